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
from .bounds import PRINTED_6, PRINTED_7, as_printed, chord, crossing, log_step, percent, round_up
from .circuit import Check, Circuit, Part, rebuildable
from .runner import run
from .timers import element_lines, label

NODES = {"C2": "C2 c2b 0", "ESR": "RESR z c2a", "ESL": "LESL c2a c2b", "C_MIN": "CMIN zc 0", "L_MAX": "LMAX zl 0"}
#: AC points per decade: the chapter's plot takes AC_PER_DECADE, the checks AC_CHECK_PER_DECADE (fine enough that the
#: grid's interpolation falls below the printed digits; 10 000 points of a few parts take hundredths of a second)
AC_PER_DECADE, AC_CHECK_PER_DECADE = 200, 2000
#: the capacitors the referee draws its operating points from (referee.SPACES): 4.7 to 22 uF, ESR 0.1 to 2 ohm, ESL
#: 5 to 20 nH (a ceramic's to an electrolytic's), the requirement 1 to 4 ohm at 1 to 4 MHz (the note's 2 ohm at 2 MHz)
SPACE = {"c2": (4.7e-6, 22e-6), "esr": (0.1, 2.0), "esl": (5e-9, 20e-9), "z_max": (1.0, 4.0), "f_decoupling": (1e6, 4e6)}
#: the largest Q of C2's series R-L-C among them, sqrt(ESL / C2) / ESR: the largest ESL, the smallest C2 and ESR
Q_MAX = math.sqrt(SPACE["esl"][1] / SPACE["c2"][0]) / SPACE["esr"][0]


def defaults() -> dict:
    p = note.params()
    return {k: p[k] for k in ("z_max", "f_decoupling", "c2", "esr", "esl")}


def _parts(q: dict) -> tuple[Part, ...]:
    """The parts, each value as the deck writes it (6 digits): the equations take these."""
    c_min, l_max = note.c_min_for_impedance(q["z_max"], q["f_decoupling"]), note.esl_max(q["z_max"], q["f_decoupling"])
    return (Part("C2", as_printed(q["c2"]), "F", "decoupling capacitor"),
            Part("ESR", as_printed(q["esr"]), "ohm", "its series resistance"),
            Part("ESL", as_printed(q["esl"]), "H", "its series inductance"),
            Part("C_MIN", as_printed(c_min), "F", "ideal, just meets 2 ohm"),
            Part("L_MAX", as_printed(l_max), "H", "inductance that alone reaches 2 ohm"))


def netlist(parts, extra: tuple = (), per_decade: int = AC_PER_DECADE) -> str:
    lines = ["* decoupling: C2 with ESR and ESL, |Z| = |V| for a 1 A AC source (AN94002 3)",
             *element_lines(parts, NODES), "I1 0 z DC 0 AC 1", "I2 0 zc DC 0 AC 1", "I3 0 zl DC 0 AC 1",
             "* a 1e15 ohm shunt on every node gives the capacitors a DC path for the operating point", ".options rshunt=1e15",
             "* vm() in .meas needs its node saved explicitly in ngspice 39", ".save v(z) v(zc) v(zl)",
             f".ac dec {per_decade} 1e3 1e8", *extra]
    return "\n".join(lines) + "\n"


@rebuildable
def circuit(p: dict | None = None) -> Circuit:
    """|Z| of C2 at 2 MHz, its minimum and its self-resonance, and the two reference branches at 2 MHz."""
    q = {**defaults(), **(p or {})}
    q["f_decoupling"] = as_printed(q["f_decoupling"])  # the frequency as the .meas lines write it
    parts = _parts(q)
    c2, esr, esl, f = parts[0].value, parts[1].value, parts[2].value, q["f_decoupling"]
    meas = (f".meas ac z_c2 FIND vm(z) AT={f:.6g}", f".meas ac z_cmin FIND vm(zc) AT={f:.6g}",
            f".meas ac z_lmax FIND vm(zl) AT={f:.6g}", ".meas ac z_c2_min MIN vm(z)",
            ".meas ac f_res WHEN vp(z)=0 CROSS=1")
    f_res = 1 / (2 * math.pi * math.sqrt(esl * c2))
    k = log_step(AC_CHECK_PER_DECADE)
    grid = (f"ngspice interpolates linearly in f between sweep points k = {k * 100:.3f} % apart ({AC_CHECK_PER_DECADE} a "
            "decade)")
    # f^2 |Z''| / |Z| of a series R-L-C is at most 2 (its capacitive asymptote, 1/f) plus 4 Q^2 (its resonance)
    z_tol = round_up(chord(k, 2 + 4 * Q_MAX ** 2) + PRINTED_7)
    cmin_tol, lmax_tol = round_up(chord(k, 2) + PRINTED_7), round_up(PRINTED_7)
    res_tol = round_up(crossing(k) + PRINTED_6)
    # the smallest |Z| over the grid: the nearest point is within half a step of the resonance in ln f, where
    # |Z| / ESR - 1 = sqrt(1 + (2 Q sinh(x))^2) - 1 <= 2 Q^2 sinh(x)^2
    miss = 2 * Q_MAX ** 2 * math.sinh(math.log1p(k) / 2) ** 2
    esr_tol = round_up(miss + PRINTED_7)
    checks = (
        Check("decoupling-z-c2", f"|Z| of C2 with its ESR and ESL at {f / 1e6:g} MHz", "ohm",
              float(note.impedance(f, c2, esr, esl)), "z_c2", z_tol,
              f"an exact series R-L-C on both sides; {grid}: the chord is off by k²/8 times f²|Z''|/|Z|, at most "
              f"2 + 4Q² (the capacitive side's 1/f, the resonance's curvature; Q = sqrt(ESL/C2)/ESR at most "
              f"{Q_MAX:.2f} at the referee's operating points): {chord(k, 2 + 4 * Q_MAX ** 2):.1e}; and the 7 printed "
              f"digits ({PRINTED_7:.0e}): {percent(z_tol)}"),
        Check("decoupling-z-cmin", f"|Z| of the smallest ideal capacitor at {f / 1e6:g} MHz", "ohm",
              float(note.impedance(f, parts[3].value)), "z_cmin", cmin_tol,
              "by construction: C_MIN is computed as 1 / (2 pi f Z_max), so its |Z| at f is Z_max again; this checks "
              f"the deck's AC source and node, not the requirement; {grid}: 1/f's chord, k²/4 "
              f"({chord(k, 2):.1e}), and the 7 printed digits: {percent(cmin_tol)}", kind="sanity"),
        Check("decoupling-z-lmax", f"|Z| of the largest series inductance at {f / 1e6:g} MHz", "ohm",
              2 * math.pi * f * parts[4].value, "z_lmax", lmax_tol, "by construction: L_MAX is computed as Z_max / "
              "(2 pi f), so its wL at f is Z_max again; wL is linear in f, so the grid's chord is exact: the 7 "
              f"printed digits alone: {percent(lmax_tol)}", kind="sanity"),
        Check("decoupling-f-res", "self-resonance of C2 with its ESL (where |Z| turns from capacitive to inductive)",
              "Hz", f_res, "f_res", res_tol,
              "1 / (2 pi sqrt(ESL C2)); ngspice finds where the phase of Z crosses zero from the series R-L-C it "
              f"solves, {grid}: the phase, atan(2Q sinh(ln(f/f_res))), is odd about the resonance in ln f, so the "
              f"crossing is off by k²/8 at most ({crossing(k):.1e}); and the 6 printed digits ({PRINTED_6:.0e}): "
              f"{percent(res_tol)}"),
        Check("decoupling-z-esr", "smallest |Z| of C2 (at its self-resonance: the ESR)", "ohm",
              float(note.impedance(1 / (2 * math.pi * math.sqrt(esl * c2)), c2, esr, esl)), "z_c2_min", esr_tol,
              "by construction: the smallest |R + jX| of a series R-L-C is R, the ESR part value measured back; it "
              f"checks the deck, not a requirement. ngspice's MIN is the smallest grid point, within half a step of "
              f"the resonance in ln f, where |Z| is at most 2Q² sinh²(step/2) above R ({miss:.1e} at Q "
              f"{Q_MAX:.2f}); and the 7 printed digits: {percent(esr_tol)}", kind="sanity"))
    return Circuit("decoupling", "Decoupling capacitor C2", "AN94002 3", parts,
                   netlist(parts, meas, AC_CHECK_PER_DECADE), checks, draw=lambda: draw(parts))


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
