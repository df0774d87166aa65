"""The decoupling capacitor C2 (AN94002 3: "lower than 2 ohm at 2 MHz") as a real part: capacitance, ESR
and ESL in series, driven by a 1 A AC current source so that |V| reads |Z| in ohms. Beside it two
reference branches from the note's requirement: the smallest ideal capacitor that meets it (C_MIN, no
ESR or ESL) and the largest inductance that meets it alone (L_MAX).

The ESR and ESL are the project's illustrative values (an94002.params: not from a datasheet); a
series R-L-C is the usual first model of a capacitor and leaves out the frequency dependence of the ESR
and the dielectric's losses.
"""
from __future__ import annotations

import math

from ..sources import an94002 as note
from . import schematic
from .circuit import Check, Circuit, Part, rebuildable
from .runner import run
from .timers import element_lines, label

NODES = {"C2": "C2 c2b 0", "ESR": "RESR z c2a", "ESL": "LESL c2a c2b", "C_MIN": "CMIN zc 0", "L_MAX": "LMAX zl 0"}


def defaults() -> dict:
    p = note.params()
    return {k: p[k] for k in ("z_max", "f_decoupling", "c2", "esr", "esl")}


def _parts(q: dict) -> tuple[Part, ...]:
    return (Part("C2", q["c2"], "F", "decoupling capacitor"), Part("ESR", q["esr"], "ohm", "its series resistance"),
            Part("ESL", q["esl"], "H", "its series inductance"),
            Part("C_MIN", note.c_min_for_impedance(q["z_max"], q["f_decoupling"]), "F", "ideal, just meets 2 ohm"),
            Part("L_MAX", note.esl_max(q["z_max"], q["f_decoupling"]), "H", "inductance that alone reaches 2 ohm"))


def netlist(parts, extra: tuple = ()) -> str:
    lines = ["* decoupling: C2 with ESR and ESL, |Z| = |V| for a 1 A AC source (AN94002 3)",
             *element_lines(parts, NODES), "I1 0 z DC 0 AC 1", "I2 0 zc DC 0 AC 1", "I3 0 zl DC 0 AC 1",
             "* a 1e15 ohm shunt on every node gives the capacitors a DC path for the operating point", ".options rshunt=1e15",
             "* vm() in .meas needs its node saved explicitly in ngspice 39", ".save v(z) v(zc) v(zl)",
             ".ac dec 200 1e3 1e8", *extra]
    return "\n".join(lines) + "\n"


@rebuildable
def circuit(p: dict | None = None) -> Circuit:
    """|Z| of C2 at 2 MHz, its minimum and its self-resonance, and the two reference branches at 2 MHz."""
    q = {**defaults(), **(p or {})}
    parts = _parts(q)
    f = q["f_decoupling"]
    meas = (f".meas ac z_c2 FIND vm(z) AT={f:.6g}", f".meas ac z_cmin FIND vm(zc) AT={f:.6g}",
            f".meas ac z_lmax FIND vm(zl) AT={f:.6g}", ".meas ac z_c2_min MIN vm(z)",
            ".meas ac f_res WHEN vp(z)=0 CROSS=1")
    f_res = 1 / (2 * math.pi * math.sqrt(q["esl"] * q["c2"]))
    half = 10 ** (1 / 400) - 1  # half a grid step of 200 points a decade, relative
    x_miss = math.sqrt(q["esl"] / q["c2"]) * 2 * half  # X = Z0 (f/f0 - f0/f) that far from the resonance
    miss = math.sqrt(1 + (x_miss / q["esr"]) ** 2) - 1
    interp = ("an exact series R-L-C on both sides; ngspice interpolates |Z| linearly between sweep points 1.2 % "
              "apart (200 a decade), and |Z|'s curvature over that step is below 0.01 %: ±0.05 %")
    checks = (
        Check("decoupling-z-c2", f"|Z| of C2 with its ESR and ESL at {f / 1e6:g} MHz", "ohm",
              float(note.impedance(f, q["c2"], q["esr"], q["esl"])), "z_c2", 5e-4, interp),
        Check("decoupling-z-cmin", f"|Z| of the smallest ideal capacitor at {f / 1e6:g} MHz", "ohm",
              float(note.impedance(f, parts[3].value)), "z_cmin", 5e-4,
              "by construction: C_MIN is computed as 1 / (2 pi f Z_max), so its |Z| at f is Z_max again; this checks "
              "the deck's AC source and node, not the requirement; " + interp, kind="sanity"),
        Check("decoupling-z-lmax", f"|Z| of the largest series inductance at {f / 1e6:g} MHz", "ohm",
              q["z_max"], "z_lmax", 5e-4, "by construction: L_MAX is computed as Z_max / (2 pi f), so its wL at f "
              "is Z_max again; " + interp, kind="sanity"),
        Check("decoupling-f-res", "self-resonance of C2 with its ESL (where |Z| turns from capacitive to inductive)",
              "Hz", f_res, "f_res", 5e-4,
              "1 / (2 pi sqrt(ESL C2)); ngspice finds where the phase of |Z| crosses zero from the series R-L-C it "
              "solves, between two of its 200 points a decade (1.2 % apart; the phase's curvature over a step is "
              "below 0.01 %): ±0.05 %"),
        Check("decoupling-z-esr", "smallest |Z| of C2 (at its self-resonance: the ESR)", "ohm",
              float(note.impedance((q["esl"] * q["c2"]) ** -0.5 / (2 * 3.141592653589793), q["c2"], q["esr"], q["esl"])),
              "z_c2_min", 1e-4,
              "by construction: the smallest |R + jX| of a series R-L-C is R, the ESR part value measured back; it "
              f"checks the deck, not a requirement. The minimum falls between two points of the grid (200 a decade): "
              f"there X is at most {x_miss:.2g} ohm, |Z| {miss:.1g} above R; ±0.01 % for the solver's round-off",
              kind="sanity"))
    return Circuit("decoupling", "Decoupling capacitor C2", "AN94002 3", parts, netlist(parts, meas), checks,
                   draw=lambda: draw(parts))


def sweep(p: dict | None = None, points: int = 41) -> dict:
    """|Z| of the three branches at ``points`` frequencies, 1 kHz to 100 MHz, for the chapter's plot."""
    q = {**defaults(), **(p or {})}
    freqs = [1e3 * 10 ** (5 * k / (points - 1)) for k in range(points)]
    meas = tuple(f".meas ac {n}{k} FIND vm({node}) AT={f:.6g}" for k, f in enumerate(freqs)
                 for n, node in (("a", "z"), ("b", "zc"), ("c", "zl")))
    out = run(netlist(_parts(q), meas))
    return {"f": freqs, **{key: [out[f"{n}{k}"] for k in range(points)] for key, n in (("c2", "a"), ("c_min", "b"),
                                                                                           ("l_max", "c"))}}


def _branch(d, elm, x: float, top: float, node: str, parts: list):
    """One branch as the deck has it: a 1 A AC current source from ground into ``node`` (so |V| reads |Z|),
    the node, and ``parts`` ((element, label)) in series from the node down to ground."""
    d.add(elm.SourceI().endpoints((x, 0), (x, top)).label("1 A AC", loc="top", fontsize=9))
    d.add(elm.Ground().at((x, 0)))
    d.add(elm.Line().endpoints((x, top), (x + 2.5, top)))
    d.add(elm.Dot().at((x + 2.5, top)).label(node, loc="top", fontsize=9))
    step = top / len(parts)
    for k, (kind, text) in enumerate(parts):
        d.add(kind().endpoints((x + 2.5, top - k * step), (x + 2.5, top - (k + 1) * step)).label(text, loc="bottom"))
    d.add(elm.Ground().at((x + 2.5, 0)))


def draw(parts):
    """Three branches, each driven by its own 1 A AC source as in the deck: C2 as a real part (ESR, ESL, C2 in
    series, at the V_P pin), the smallest ideal capacitor C_MIN and the largest inductance L_MAX that meet
    the note's 2 Ω at 2 MHz."""
    import schemdraw.elements as elm

    by = {p.ref: label(p) for p in parts}
    d = schematic.start(unit=2.2, fontsize=10)
    _branch(d, elm, 0.0, 6.6, "$V_\\mathrm{P}$ pin: C2 as a real part",
            [(elm.Resistor, by["ESR"]), (elm.Inductor2, by["ESL"]), (elm.Capacitor, by["C2"])])
    _branch(d, elm, 9.0, 6.6, "ideal capacitor", [(elm.Capacitor, by["C_MIN"])])
    _branch(d, elm, 18.0, 6.6, "inductance alone", [(elm.Inductor2, by["L_MAX"])])
    return d
