"""The designed circuits drawn with their chosen values: each design table (``python -m handbook design``) on the
SPICE circuit it designs, so that the schematic is the simulated circuit's own drawing with the chosen parts in
it (the same circuits :data:`.checks.DESIGN_CHECKS` simulates):

* ``commutation``: CAP-CD / CAP-DC (:func:`.timers.commutation_delay`) with the chosen C3 and C4, at the spec's
  speeds, the TDA5144's typical currents and levels;
* ``current_limiter``: AN94002 figure 3 (:func:`.limiter.opamp`) with the chosen R7, R9 to R13, R14 (the
  parts list's 750 Ω where the design has none: a network designed alone) and D1 named as the BOM names it;
* ``class_d``: the LM4652 bridge and its filter (:func:`.class_d.circuit`) with the chosen L and C_BYP, the
  spec's load and supply, at the designed switching frequency;
* ``converter``: the TCA5600 power stage (:func:`.converter.circuit`) at the spec's operating point (its lowest
  VCC2, V_CE(sat), V_F, V12(H) and output) with the coil as wound (L1 nominal) and R1 as bought (the series
  value), the BOM's two values.

:func:`write_svgs` writes them, one SVG per table, all or none.
"""
from __future__ import annotations

import dataclasses
import io
import os
import tempfile
from pathlib import Path

#: SVG output that reads back as text (values searchable) and is the same bytes for the same drawing
SVG_RC = {"svg.fonttype": "none", "svg.hashsalt": "handbook-schematic"}


def _commutation(result):
    from . import timers

    s = result.spec
    return timers.commutation_delay({"cap_cd": result.cap_cd, "cap_dc": result.cap_dc, "rpm_min": s["rpm_min"],
                                     "rpm_max": s["rpm_max"], "pole_pairs": s["pole_pairs"]})


def limiter_params(result) -> dict:
    """The op-amp limiter decks' parameters a designed limiter sets: R7, R9 to R13, D1's voltage and R14 (when the
    design chose it; else the decks keep the parts list's).

    Parameters
    ----------
    result : LimiterResult
        A designed limiter.

    Returns
    -------
    dict
        {"r7", "r9" .. "r13", "zener_voltage"[, "r14"]}, ohm and V.
    """
    p = {"r7": result.r7, **dict(zip(("r9", "r10", "r11", "r12", "r13"), result.network)),
         "zener_voltage": result.spec["zener_voltage"]}
    if result.r14 is not None:
        p["r14"] = result.r14
    return p


def _limiter(result):
    from ..design.bom import _zener_name
    from . import limiter
    from .limiter.decks import draw_opamp

    s = result.spec
    circuit = limiter.opamp(limiter_params(result))
    d1 = dataclasses.replace(circuit.part("D1"), value=_zener_name(s["zener_voltage"]))
    parts = _as_bom(tuple(d1 if q.ref == "D1" else q for q in circuit.parts), "current_limiter")
    return dataclasses.replace(circuit, parts=parts, draw=lambda: draw_opamp(parts))


#: the BOM's designators (handbook.design.bom, within the table's sheet) of parts the SPICE deck names otherwise
BOM_NAMES = {"current_limiter": {"U1": "IC2"}, "class_d": {"C_BYP": "C1"}}


def _as_bom(parts: tuple, table: str) -> tuple:
    """The parts with the BOM's designators drawn (the deck's own names stay its element names)."""
    names = BOM_NAMES.get(table, {})
    return tuple(dataclasses.replace(q, drawn=names[q.ref]) if q.ref in names else q for q in parts)


def _class_d(result):
    from . import class_d

    s = result.spec
    circuit = class_d.circuit({"l_out": result.l_out, "c_out": result.c_out, "r_load": s["r_load"],
                               "supply": s["supply"], "f_sw": result.f_sw, "f_audio": s["f_audio"]})
    parts = _as_bom(circuit.parts, "class_d")
    return dataclasses.replace(circuit, parts=parts, draw=lambda: class_d.draw(parts))


def _converter(result):
    from ..design.converter import source_params
    from . import converter

    return converter.circuit({**converter.defaults(), **source_params(result.spec), "l1": result.l1_nominal,
                              "r1": result.r1_part})


#: design table -> the function taking that design's result, returning the circuit it designs
CIRCUITS = {"commutation": _commutation, "current_limiter": _limiter, "class_d": _class_d, "converter": _converter}


def circuit(table: str, result):
    """The SPICE circuit (:class:`.circuit.Circuit`) a design table's result designs, with its chosen values."""
    return CIRCUITS[table](result)


def drawing(table: str, result):
    """The schematic of the circuit a design table's result designs, labelled with the chosen values."""
    return circuit(table, result).draw()


def svg(d) -> bytes:
    """A drawing as SVG: text kept as text, no date, the same bytes each time."""
    import matplotlib
    import matplotlib.pyplot as plt

    with matplotlib.rc_context(SVG_RC):
        fig = d.draw(show=False).getfig()
        buf = io.BytesIO()
        fig.savefig(buf, format="svg", bbox_inches="tight", pad_inches=0.1, metadata={"Date": None})
        plt.close(fig)
    return buf.getvalue()


def png(d) -> bytes:
    """A drawing as PNG (for a notebook: nbval does not compare images)."""
    import matplotlib.pyplot as plt

    fig = d.draw(show=False).getfig()
    buf = io.BytesIO()
    fig.savefig(buf, format="png", bbox_inches="tight", pad_inches=0.1, dpi=90)
    plt.close(fig)
    return buf.getvalue()


def _umask() -> int:
    mask = os.umask(0o022)
    os.umask(mask)
    return mask


def write_svgs(results: dict, folder) -> list[Path]:
    """One SVG per design result, ``<table>.svg`` in ``folder`` (made if missing): every drawing is rendered
    before anything is written, each file is written whole (a temporary file, then renamed), and on an error
    none of this call's files is left. Returns the paths; raises OSError."""
    images = {table: svg(drawing(table, result)) for table, result in results.items()}
    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    written: list[Path] = []
    try:
        for table, data in images.items():
            fd, tmp = tempfile.mkstemp(prefix=f".{table}-", suffix=".svg", dir=folder)
            try:
                with os.fdopen(fd, "wb") as fh:
                    fh.write(data)
                os.chmod(tmp, 0o666 & ~_umask())  # as an ordinary new file (mkstemp makes it private)
                os.replace(tmp, folder / f"{table}.svg")
            except BaseException:
                Path(tmp).unlink(missing_ok=True)
                raise
            written.append(folder / f"{table}.svg")
    except BaseException:
        for path in written:
            path.unlink(missing_ok=True)
        raise
    return written
