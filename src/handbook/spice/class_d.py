"""LM4651/LM4652 bridge output filter with its load (datasheet, "Output Stage Filtering" and figure 1).

The LM4652's two half-bridges drive the two legs in antiphase: VO1 and VO2 are each a +-V_s square
wave at f_sw (its edges the LM4652 table's t_r and t_f), L1 and L2 carry them to the load, C_BYP sits
across the load. The book's model (:mod:`handbook.sources.lm4651.circuit`) folds this into 2 L in series
with C_BYP across R_L: corner f_C = 1 / (2 pi sqrt(2 L C_BYP)), Q = R_L sqrt(C_BYP / 2L), and the
switching residue at the load as the square wave's fundamental (8 V_s / pi) through the filter. Here
the bridge is built as it is, with its two legs, and simulated twice:

* AC (:func:`circuit`): the corner where the phase is -90 deg, Q as the gain there and the gain at the top
  of the audio band (with the band past the corner, also the band's largest deviation from 0 dB);
* transient (:func:`ripple`): the idle bridge (50 % duty, every harmonic, finite edges) until the
  filter has settled, and the rms of the residue at the load over the last ten periods.

(ngspice 39 in batch mode runs only one analysis of a deck carrying .meas of two kinds, so the two are
two decks of the same parts.) Assumptions: ideal L and C (no DCR, no ESR), a resistive load, no dead
time, and the small C1 from each output to ground (0.1 to 1 uF, datasheet) left out, as in the model.
"""
from __future__ import annotations

import math
from functools import partial

import numpy as np

from ..core.units import eng
from ..design.class_d import model
from ..sources import lm4651
from ..sources.lm4651 import circuit as eqs
from . import schematic
from .circuit import Check, Circuit, Part, rebuildable, with_defaults
from .runner import run

DATASHEET = "LM4651/LM4652 datasheet"
#: the band the chapter checks: up to the top of the audio band
F_AUDIO = 20e3
#: AC points per decade; the transient's step is a hundredth of the period, its window ten periods
AC_PER_DECADE, STEPS_PER_PERIOD, RMS_PERIODS = 200, 400, 10
#: the transient runs until the filter's slowest mode has decayed by exp(-SETTLE)
SETTLE = 10.0


def defaults() -> dict:
    """The datasheet's typical circuit: 50 uH and 5 uF (Output Stage Filtering), the Example Design's 4 ohm
    and 125 kHz, +-20 V, and the LM4652's edges."""
    note = lm4651.params()
    return {"l_out": eqs.L_REF, "c_out": eqs.C_REF, "r_load": note["r_load"], "f_sw": note["f_sw"],
            "supply": eqs.SUPPLY_REF, "t_rise": note["t_rise"], "t_fall": note["t_fall"], "f_audio": F_AUDIO}


def parts(p: dict) -> tuple[Part, ...]:
    bridge = f"LM4652 half-bridge: +-V_s square at {eng(p['f_sw'], 'Hz')}"
    return (Part("VO1", p["supply"], "V", bridge), Part("VO2", p["supply"], "V", bridge + ", antiphase"),
            Part("L1", p["l_out"], "H"), Part("L2", p["l_out"], "H"),
            Part("C_BYP", p["c_out"], "F"), Part("R_L", p["r_load"], "ohm", "the loudspeaker, as a resistor"))


def label(part: Part) -> str:
    """A part as the drawing shows it: designator (subscripts typeset) and value with its unit (a half-bridge:
    ±V_s)."""
    text = schematic.label(part)
    return text.replace(" ", " ±", 1) if part.ref.startswith("VO") else text


def _pulse(p: dict, v1: float, first: float, second: float) -> str:
    """A 50 % square from v1 to -v1 and back (edges ``first`` then ``second``), starting a quarter period
    in, half way through a low phase, where the steady-state coil current crosses zero: the start-up
    transient is then small."""
    period = 1 / p["f_sw"]
    width = period / 2 - (first + second) / 2
    return f"PULSE({v1:.6g} {-v1:.6g} {period / 4:.6g} {first:.6g} {second:.6g} {width:.6g} {period:.6g})"


#: where each part sits (the SPICE netlist and lcapy's netlist both read this): the two half-bridges drive o1
#: and o2, the load is outp-outn
NODES = {"VO1": "o1 0", "VO2": "o2 0", "L1": "o1 outp", "L2": "o2 outn", "C_BYP": "outp outn", "R_L": "outp outn"}


def element_lines(p: dict, ps: tuple[Part, ...]) -> list[str]:
    """One line per part, in the parts' order, placed by :data:`NODES`."""
    v = {q.ref: q.value for q in ps}
    value = {"VO1": f"{_pulse(p, -v['VO1'], p['t_rise'], p['t_fall'])} AC 0.5",
             "VO2": f"{_pulse(p, v['VO2'], p['t_fall'], p['t_rise'])} AC 0.5 180"}
    return [f"{q.ref} {NODES[q.ref]} {value.get(q.ref, f'{q.value:.6g}')}" for q in ps] + [
        "Eprobe out 0 outp outn 1"]  # the load voltage as one node (a probe, not a part)


def _ac_lines(p: dict) -> list[str]:
    f_lo = p["f_audio"] / 1e3  # f_audio is then a grid point
    # ngspice cannot name vp()/vm()/vdb() in its save list: without an explicit .save it saves nothing
    return [".save v(out)", f".ac dec {AC_PER_DECADE} {f_lo:.6g} {p['f_audio'] * 1e3:.6g}"]


def ac_deck(p: dict, ps: tuple[Part, ...], title: str, meas: list[str]) -> str:
    return "\n".join([f"* {title}", *element_lines(p, ps), *_ac_lines(p), *meas, ".end"]) + "\n"


@rebuildable
def circuit(p: dict | None = None) -> Circuit:
    """The filter and its load in AC: corner, Q and the gain at f_audio."""
    p = with_defaults(defaults(), p)
    ps, fa = parts(p), p["f_audio"]
    args = (p["l_out"], p["c_out"], p["r_load"])
    cid = f"lm4651-filter-{p['r_load']:g}ohm"
    meas = [".meas ac f_corner WHEN vp(out)=-1.5707963",
            ".meas ac q FIND vm(out) WHEN vp(out)=-1.5707963",
            f".meas ac g_top FIND vdb(out) AT={fa:.6g}",
            f".meas ac g_max MAX vdb(out) FROM={fa / 1e3:.6g} TO={fa:.6g}",
            f".meas ac g_min MIN vdb(out) FROM={fa / 1e3:.6g} TO={fa:.6g}"]
    grid = (f"the AC grid ({AC_PER_DECADE} points a decade, {10 ** (1 / AC_PER_DECADE) - 1:.1%} apart, interpolated "
            "linearly: the phase's and |H|'s curvature over a step, below 0.01 %)")
    checks = (
        Check(f"{cid}-corner", f"corner (phase -90 deg), R_L = {p['r_load']:g} ohm", "Hz", eqs.filter_f0(*args[:2]),
              "f_corner", 5e-4, f"two coils in two legs are 2 L in series: nothing is left out but {grid}: ±0.05 %"),
        Check(f"{cid}-q", f"Q (gain at the corner), R_L = {p['r_load']:g} ohm", "1", eqs.filter_q(*args), "q", 5e-4,
              f"the same network; {grid}, read where the phase crosses -90°: ±0.05 %"),
        Check(f"{cid}-top", f"gain at {eng(fa, 'Hz')}, R_L = {p['r_load']:g} ohm", "dB",
              10 * math.log10(eqs.filter_gain2(fa, *args)), "g_top", 1e-4,
              "the same network, at a grid point: only the solver's round-off: ±0.01 %"))
    # (no row for the band's largest deviation from 0 dB: the band runs to 20 kHz, past the corner, so its
    # largest deviation is the loss at f_audio for both loads, the row above repeated)
    title = f"LM4651/LM4652 bridge output filter, R_L = {p['r_load']:g} ohm, AC"
    return Circuit(id=cid, title=title, source=f"{DATASHEET}, Output Stage Filtering; figure 1", parts=ps,
                   netlist=ac_deck(p, ps, title, meas), checks=checks, draw=partial(draw, ps))


def settle_time(l_out: float, c_out: float, r_load: float) -> float:
    """Time for the filter's slowest mode to decay by exp(-SETTLE): the poles of 2LC s^2 + (2L/R) s + 1."""
    poles = np.roots([2 * l_out * c_out, 2 * l_out / r_load, 1.0])
    return SETTLE / float(np.min(np.abs(poles.real)))


def tran_lines(p: dict, name: str = "ripple") -> list[str]:
    """Transient to the settled state, the residue's rms over the last RMS_PERIODS periods."""
    period = 1 / p["f_sw"]
    n = math.ceil(settle_time(p["l_out"], p["c_out"], p["r_load"]) / period) + RMS_PERIODS
    t_end, t_from, step = period / 4 + n * period, period / 4 + (n - RMS_PERIODS) * period, period / STEPS_PER_PERIOD
    return [f".tran {step:.6g} {t_end:.6g} {t_from:.6g} {step:.6g} uic",
            f".meas tran {name} RMS v(out) FROM={t_from:.6g} TO={t_end:.6g}"]


def residue_spectrum(p: dict, v: float, n: int = 4096) -> float:
    """What the equation's fundamental-only residue leaves out, as a ratio: the residue at the load, rms, of the
    whole bridge waveform (both PULSE sources as the deck writes them: every harmonic, the edges t_r and t_f)
    over that of an ideal square wave's fundamental alone, both by Fourier series (numpy FFT of one period, each
    harmonic through the filter's |H|, :func:`eqs.filter_gain2`). A ratio of two spectra, so it holds whatever
    the equation's own constants are: the check still sees an error in them."""
    period = 1 / p["f_sw"]
    t = np.arange(n) * period / n

    def pulse(v1, first, second):  # SPICE's PULSE(v1 -v1 td first second width period), td = period / 4
        width = period / 2 - (first + second) / 2
        x = (t - period / 4) % period
        up = np.clip(x / first, 0, 1)
        down = np.clip((x - first - width) / second, 0, 1)
        return v1 + (-2 * v1) * (up - down)

    def spectrum(wave):
        return np.abs(np.fft.rfft(wave) / n)[1:]

    k = np.arange(1, n // 2 + 1)
    gain2 = eqs.filter_gain2(k * p["f_sw"], p["l_out"], p["c_out"], p["r_load"])
    whole = spectrum(pulse(-v, p["t_rise"], p["t_fall"]) - pulse(v, p["t_fall"], p["t_rise"]))
    ideal = spectrum(pulse(-v, 1e-15, 1e-15) - pulse(v, 1e-15, 1e-15))
    return float(np.sqrt(np.sum(whole ** 2 * gain2) / (ideal[0] ** 2 * gain2[0])))


@rebuildable
def ripple(p: dict | None = None) -> Circuit:
    """The idle bridge (50 % duty) through the filter: the switching residue at the load, rms."""
    p = with_defaults(defaults(), p)
    ps = parts(p)
    cid = f"lm4651-ripple-{p['r_load']:g}ohm"
    title = f"LM4651/LM4652 bridge output filter, R_L = {p['r_load']:g} ohm, switching residue"
    eq = eqs.ripple_rms(p["f_sw"], p["l_out"], p["c_out"], p["r_load"], p["supply"])
    expected = residue_spectrum(p, ps[0].value) - 1
    why = (f"expected {expected:+.3%}: the model keeps only the square wave's fundamental (8 V_s / pi); the deck's "
           "waveform has every harmonic (the third is a third as large and filtered 9 times more) and the "
           f"{p['t_rise'] * 1e9:g}/{p['t_fall'] * 1e9:g} ns edges, summed here by Fourier series; left: "
           f"{STEPS_PER_PERIOD} steps a period (a hundred left 0.16 % at some loads) and .meas RMS over ten periods: "
           "±0.05 %")
    checks = (Check(f"{cid}-rms", f"switching residue at the load, rms, R_L = {p['r_load']:g} ohm", "V", eq,
                    "ripple", 5e-4, why, expected=expected),)
    netlist = "\n".join([f"* {title}", *element_lines(p, ps), *tran_lines(p), ".end"]) + "\n"
    return Circuit(id=cid, title=title, source=f"{DATASHEET}, Output Stage Filtering; LM4652 t_r, t_f", parts=ps,
                   netlist=netlist, checks=checks, draw=partial(draw, ps))


@rebuildable
def circuit_8ohm() -> Circuit:
    return circuit({"r_load": 8.0})


@rebuildable
def ripple_8ohm() -> Circuit:
    return ripple({"r_load": 8.0})


def response(loads=(4.0, 8.0), p: dict | None = None, points: int = 61) -> dict:
    """|H| in dB from SPICE at ``points`` frequencies (log-spaced over f_audio / 1000 .. 10 f_audio) for
    each load: {"f": array, load: array of dB}. One AC run per load."""
    p = with_defaults(defaults(), p)
    f = np.logspace(math.log10(p["f_audio"] / 1e3), math.log10(p["f_audio"] * 10), points)
    out = {"f": f}
    for r in loads:
        q = {**p, "r_load": r}
        meas = [f".meas ac g{i:03d} FIND vdb(out) AT={x:.9g}" for i, x in enumerate(f)]
        got = run(ac_deck(q, parts(q), f"LM4651 filter response, R_L = {r:g} ohm", meas))
        out[r] = np.array([got[f"g{i:03d}"] for i in range(points)])
    return out


def design_check(result) -> dict:
    """A class-D design (handbook.design.class_d) simulated: the filter's corner with the chosen L, C_BYP and
    the spec's load, and the residue at the load at the worst of the design's eight tolerance corners
    (oscillator slow/fast, L and C_BYP +- their tolerance; each corner one transient run, the largest kept).
    {"f_corner": Hz, "ripple_at_load": V rms}, each beside the design's own figure ("*_equation"), "corners"
    and "meets_spec" (SPICE's worst residue at most the spec's ripple_max)."""
    s = result.spec
    base = {"l_out": result.l_out, "c_out": result.c_out, "r_load": s["r_load"], "supply": s["supply"],
            "f_sw": result.f_sw, "f_audio": s["f_audio"]}
    f_corner = run(circuit(base).netlist)["f_corner"]
    fo, lo, co = model.corner_factors(s)
    worst = 0.0
    for kf, kl, kc in zip(fo, lo, co):
        q = {**base, "f_sw": base["f_sw"] * kf, "l_out": base["l_out"] * kl, "c_out": base["c_out"] * kc}
        worst = max(worst, run(ripple(q).netlist)["ripple"])
    return {"f_corner": f_corner, "f_corner_equation": float(eqs.filter_f0(result.l_out, result.c_out)),
            "ripple_at_load": worst, "ripple_at_load_equation": float(result.figures["ripple"]),
            "corners": len(fo), "meets_spec": bool(worst <= s["ripple_max"])}


def draw(ps: tuple[Part, ...]):
    """The bridge, the two coils, C_BYP and the load, labelled from the same parts as the netlist."""
    import schemdraw
    import schemdraw.elements as elm

    schemdraw.use("matplotlib")
    lab = {q.ref: label(q) for q in ps}
    f_sw = ps[0].note.rsplit(" at ", 1)[-1]  # the switching frequency, from the bridge's note
    with schemdraw.Drawing(show=False) as d:
        d.config(fontsize=11)
        mid = elm.Dot()
        elm.Line().left(1.0)
        elm.Ground()
        vo1 = elm.SourceSquare().at(mid.center).up().label(lab["VO1"], loc="bottom").label(f_sw, loc="top")
        l1 = elm.Inductor2().at(vo1.end).right(4).label(lab["L1"])
        vo2 = elm.SourceSquare().at(mid.center).down().label(lab["VO2"], loc="top").label(f_sw, loc="bottom")
        elm.Inductor2().at(vo2.end).right(4).label(lab["L2"], loc="bottom")
        elm.Capacitor().endpoints(l1.end, (l1.end[0], vo2.end[1])).label(lab["C_BYP"])
        elm.Line().at(l1.end).right(2.5)
        r = elm.Resistor().down(l1.end[1] - vo2.end[1]).label(lab["R_L"], loc="bottom")
        elm.Line().at(r.end).left(2.5)
        elm.Dot().at(l1.end)
        elm.Dot().at((l1.end[0], vo2.end[1]))
    return d
