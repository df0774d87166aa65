"""What every schematic shares (schemdraw, matplotlib backend, no LaTeX): labels with typeset subscripts and
the units a person reads (Ω, kΩ, µF), and amplifiers whose input signs stay upright in any orientation, with
their supply pins drawn.

A designator with an underscore, or a quantity's name, is set in matplotlib's mathtext: ``C_BYP`` as
:math:`C_\\mathrm{BYP}`, ``VCC2`` as :math:`V_\\mathrm{CC2}`; a plain designator (R7, U1, D1) stays plain.
The tests read the labels back (``tests/drawn_parts.py``), so every label is built here.
"""
from __future__ import annotations

import math

from ..core.units import eng

#: a part's unit as the drawing shows it
UNITS = {"ohm": "Ω", "Ohm": "Ω"}
#: designators that name a quantity with a subscript, though written without an underscore
SUBSCRIPTED = {"VCC2": ("V", "CC2"), "VS": ("V", "s"), "VC2": ("V", "C2"), "GM": ("g", "m")}


def typeset(name: str) -> str:
    """``name`` typeset: ``"V_LOW"`` -> ``"$V_\\mathrm{LOW}$"``, ``"V12(H)"`` -> ``"$V_\\mathrm{12(H)}$"``,
    ``"R7"`` -> ``"R7"`` (a plain designator stays plain)."""
    if name in SUBSCRIPTED:
        head, sub = SUBSCRIPTED[name]
    elif "_" in name:
        head, sub = name.split("_", 1)
    elif name[:1] in "VI" and name[1:2].isdigit():  # V12(H): the level at pin 12
        head, sub = name[0], name[1:]
    else:
        return name
    return f"${head}_\\mathrm{{{sub}}}$"


def value(part) -> str:
    """A part's value as drawn: a device name as it is, a number with its SI prefix and unit (Ω, not ohm)."""
    if isinstance(part.value, str):
        return part.value
    return eng(part.value, UNITS.get(part.unit, part.unit))


def label(part, sep: str = " ", what: str = "") -> str:
    """Designator and value: ``"R7 100 mΩ"`` (``sep="\\n"``: on two lines); ``what`` names a device's figure
    (``"V_F"`` -> ``"D1 $V_\\mathrm{F}$ = 800 mV"``)."""
    figure = f"{typeset(what)} = " if what else ""
    return f"{typeset(part.drawn or part.ref)}{sep}{figure}{value(part)}"


def start(unit: float = 3.0, fontsize: float = 10):
    """A drawing that is not shown as it is built."""
    import schemdraw

    schemdraw.use("matplotlib")
    return schemdraw.Drawing(show=False, fontsize=fontsize, unit=unit)


def _local(op, x: float, y: float):
    """A point given in the amplifier's own frame (before its rotation), in the drawing's frame."""
    return op.transform.transform((x, y))


def amplifier(d, at, theta: float = 0, anchor: str = "center", text: str = "", text_at=None,
              positive: str | None = "$V_\\mathrm{s}$", negative: str | None = "ground", fontsize: float = 10,
              flip: bool = False, stub: float = 1.4):
    """An op-amp, comparator or OTA: schemdraw's triangle without its drawn signs (they would turn with the
    symbol), the signs as upright text ("−" at ``in1``, "+" at ``in2``: the inputs of schemdraw's Opamp),
    ``text`` at ``text_at`` (its left edge; a drawing point), and its supply pins: ``positive`` (a rail's name)
    on the upper one (or the right one, the symbol turned), ``negative`` ("ground", a rail's name, or None for
    none drawn) on the other. ``flip`` swaps the inputs (+ at ``in1``) so that the
    inverting input can face either way; ``stub``: the supply pins' length. Returns the Opamp element."""
    import schemdraw.elements as elm
    from schemdraw.elements.opamp import oa_back, oa_xlen

    lead, up = oa_back / 4, -1 if flip else 1
    op = elm.Opamp(leads=True, sign=False).theta(theta).anchor(anchor).at(at)
    # the supply pins half-way along the sides, clear of the signs (schemdraw puts them a third of the way)
    op.anchors["vd"], op.anchors["vs"] = (lead + oa_xlen / 2, oa_back / 4), (lead + oa_xlen / 2, -oa_back / 4)
    op = d.add(op.flip() if flip else op)
    for sign, y in (("−", up * 0.5), ("+", -up * 0.5)):
        d.add(elm.Label().at(_local(op, lead + 0.4, y)).label(sign, fontsize=fontsize))
    if text:
        d.add(elm.Label().at(text_at).label(text, halign="left", fontsize=fontsize))
    pins = sorted(((getattr(op, name), axis(op, sign * up)) for name, sign in (("vd", 1), ("vs", -1))),
                  key=lambda pa: (-round(pa[1][1], 6), -round(pa[1][0], 6)))  # the upper (or right) pin first
    for (pin, a), rail in zip(pins, (positive, negative)):  # the positive rail on the upper pin
        if rail is None:
            continue
        end = (pin[0] + stub * a[0], pin[1] + stub * a[1])
        d.add(elm.Line().endpoints(pin, end))
        if rail == "ground":
            d.add(elm.Ground().at(end))
        else:
            d.add(elm.Vdd().theta(180 if a[1] < -0.5 else 0).at(end).label(rail, fontsize=fontsize))
    return op


def axis(op, sign: int) -> tuple[float, float]:
    """The unit vector of the amplifier's own +y axis (``sign`` 1) or -y axis (-1), in the drawing's frame."""
    origin, tip = _local(op, 0, 0), _local(op, 0, sign)
    dx, dy = tip[0] - origin[0], tip[1] - origin[1]
    norm = math.hypot(dx, dy)
    return dx / norm, dy / norm
