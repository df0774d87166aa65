"""Schematics of the current limiters (schemdraw, matplotlib backend, no LaTeX), drawn from the same parts
as their netlists (:mod:`.limiters`): every part is labelled with its designator and value, and
:func:`labels` reads them back for the test that the drawing and the netlist hold the same set."""
from __future__ import annotations

from .. import schematic


def label(part) -> str:
    return schematic.label(part, sep="\n")


def labels(drawing) -> dict[str, str]:
    """{designator: value as drawn} of every labelled element of a drawing."""
    out = {}
    for el in drawing.elements:
        for lab in getattr(el, "_userlabels", []):
            ref, _, value = str(lab.label).partition("\n")
            out[ref] = value
    return out


def _start():
    return schematic.start(unit=3, fontsize=10)


def _two(d, kind, part, a, b, loc="bottom"):
    """A two-terminal part from a to b, labelled."""
    return d.add(kind().endpoints(a, b).label(label(part), loc=loc))


def _supply_and_sense(d, elm, by, top: float, x_sense: float, y_cs: float, right: float):
    """V_s from ground to the rail, the rail, R7 from the rail down to the sense point, the motor below it."""
    _two(d, elm.SourceV, by["VS"], (0, 0), (0, top), loc="top")
    d.add(elm.Line().endpoints((0, top), (right, top)))
    d.add(elm.Label().at((right / 2, top + 0.6)).label("$V_\\mathrm{s}$"))
    _two(d, elm.Resistor, by["R7"], (x_sense, top), (x_sense, y_cs), loc="top")
    _two(d, elm.SourceI, by["IM"], (x_sense, y_cs), (x_sense, 0), loc="top")
    d.add(elm.Label().at((x_sense + 1.4, y_cs / 2)).label("motor"))
    d.add(elm.Dot().at((x_sense, y_cs)))
    for x in (0, x_sense):
        d.add(elm.Ground().at((x, 0)))


def _opamp_down(d, elm, by, inp, inn, x: float, y: float):
    """U1 pointing down between the two divider columns, inputs on top ("+" on the left, from the sense side),
    fed from V_s (its V+ pin, right) and ground (its V- pin, left); the output labelled."""
    op = schematic.amplifier(d, (x, y), theta=-90, text=label(by["U1"]), text_at=(x + 0.4, y - 1.5))
    d.add(elm.Line().endpoints(inp, (op.in2[0], inp[1])))
    d.add(elm.Line().endpoints((op.in2[0], inp[1]), op.in2))
    d.add(elm.Line().endpoints(inn, (op.in1[0], inn[1])))
    d.add(elm.Line().endpoints((op.in1[0], inn[1]), op.in1))
    d.add(elm.Line().at(op.out).down(0.6))
    d.add(elm.Dot(open=True).at((op.out[0], op.out[1] - 0.6)).label("out: to the regulator", loc="bottom"))
    return op


def opamp(parts):
    """AN94002 figure 3: R7 and the motor, R12/R13 to V+, R9/R10/R11 to V-, D1 over both, R14 feeding D1."""
    import schemdraw.elements as elm

    by = {p.ref: p for p in parts}
    d = _start()
    top, y_cs, y_z, xr = 14.0, 9.0, 2.5, 14.0
    _supply_and_sense(d, elm, by, top, 3.0, y_cs, 18.0)
    inp, inn = (7.0, y_cs), (xr, y_cs)
    _two(d, elm.Resistor, by["R12"], (3.0, y_cs), inp)
    _two(d, elm.Resistor, by["R13"], inp, (7.0, y_z), loc="top")
    _two(d, elm.Resistor, by["R9"], (xr, top), (xr, top - 2.5), loc="top")
    _two(d, elm.Resistor, by["R10"], (xr, top - 2.5), inn, loc="top")
    _two(d, elm.Resistor, by["R11"], inn, (xr, y_z), loc="top")
    d.add(elm.Line().endpoints((7.0, y_z), (18.0, y_z)))
    d.add(elm.Label().at((12.5, y_z - 0.6)).label("$V_\\mathrm{s} − V_\\mathrm{D1}$"))
    _two(d, elm.Zener, by["D1"], (18.0, y_z), (18.0, top), loc="bottom")
    _two(d, elm.Resistor, by["R14"], (18.0, y_z), (18.0, 0), loc="bottom")
    d.add(elm.Ground().at((18.0, 0)))
    for pt in (inp, inn, (7.0, y_z), (xr, y_z), (18.0, y_z), (18.0, top), (3.0, top), (xr, top)):
        d.add(elm.Dot().at(pt))
    _opamp_down(d, elm, by, inp, inn, 10.5, 6.6)
    return d


def supply(parts):
    """AN93008 figure 3: R8/R9 divide the sensed supply to V+, R10/R11 the supply to V-."""
    import schemdraw.elements as elm

    by = {p.ref: p for p in parts}
    d = _start()
    top, y_cs, xr = 12.0, 8.0, 14.0
    _supply_and_sense(d, elm, by, top, 3.0, y_cs, xr)
    inp, inn = (7.0, y_cs), (xr, y_cs)
    _two(d, elm.Resistor, by["R8"], (3.0, y_cs), inp)
    _two(d, elm.Resistor, by["R9"], inp, (7.0, 0))
    _two(d, elm.Resistor, by["R10"], (xr, top), inn, loc="top")
    _two(d, elm.Resistor, by["R11"], inn, (xr, 0), loc="top")
    for x in (7.0, xr):
        d.add(elm.Ground().at((x, 0)))
    for pt in (inp, inn, (3.0, top), (xr, top)):
        d.add(elm.Dot().at(pt))
    _opamp_down(d, elm, by, inp, inn, 10.5, 5.6)
    return d


def one_transistor(parts):
    """AN94002 figure 2: R7 in the supply, T2's emitter at V_s and base at the sense point; its collector
    pulls the regulator's drive (a stand-in load RL here)."""
    import schemdraw.elements as elm

    by = {p.ref: p for p in parts}
    d = _start()
    top, y_cs = 11.0, 6.0
    _supply_and_sense(d, elm, by, top, 3.0, y_cs, 3.0)
    q = d.add(elm.BjtPnp(circle=True).theta(0).anchor("base").at((6.5, y_cs)).label(label(by["T2"]), loc="right"))
    d.add(elm.Line().endpoints((3.0, y_cs), q.base))
    d.add(elm.Line().endpoints(q.emitter, (q.emitter[0], top)))
    d.add(elm.Line().endpoints((3.0, top), (q.emitter[0], top)))
    d.add(elm.Dot().at((q.emitter[0], top)))
    _two(d, elm.Resistor, by["RL"], q.collector, (q.collector[0], 0), loc="bottom")
    d.add(elm.Ground().at((q.collector[0], 0)))
    # the drive the collector pulls: led off to the right, clear of T2's symbol and its label
    tap = (q.collector[0] + 3.0, q.collector[1] - 1.0)
    d.add(elm.Dot().at((q.collector[0], tap[1])))
    d.add(elm.Line().endpoints((q.collector[0], tap[1]), tap))
    d.add(elm.Dot(open=True).at(tap).label("to the regulator's\ndrive", loc="right"))
    return d
