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
  filter has settled, and the rms of the residue at the load about its mean over the last ten periods.

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
from .bounds import PRINTED_6, PRINTED_7, as_printed, crossing, log_step, percent, round_up
from .circuit import Check, Circuit, Part, rebuildable, with_defaults
from .runner import run

DATASHEET = "LM4651/LM4652 datasheet"
#: the band the chapter checks: up to the top of the audio band
F_AUDIO = 20e3
#: AC points per decade: the chapter's plots and the designed decks take AC_PER_DECADE; the referee's rows
#: (:func:`circuit`) AC_CHECK_PER_DECADE, where the grid's interpolation falls below the printed digits (an AC run of
#: a few parts is cheap: 12 000 points in a few hundredths of a second)
AC_PER_DECADE, AC_CHECK_PER_DECADE = 200, 2000
#: the transient's largest step: a STEPS_PER_PERIOD-th of the period and a STEPS_PER_EDGE-th of the shorter edge
#: (:func:`tran_step`); the residue is read over RMS_PERIODS periods
STEPS_PER_PERIOD, STEPS_PER_EDGE, RMS_PERIODS = 400, 4, 10
#: the transient runs until the filter's slowest mode has decayed by exp(-SETTLE)
SETTLE = 10.0
#: the filters the referee draws its operating points from (referee.SPACES): each coil 22 to 100 uH, C_BYP 1 to
#: 10 uF, the load 4 to 8 ohm (the datasheet's 50 uH, 5 uF and its two loads inside)
FILTER_SPACE = {"l_out": (22e-6, 100e-6), "c_out": (1e-6, 10e-6), "r_load": (4.0, 8.0)}
#: the largest Q among them, R_L sqrt(C_BYP / 2L): the highest load across the largest C_BYP and the smallest coils
Q_MAX = FILTER_SPACE["r_load"][1] * math.sqrt(FILTER_SPACE["c_out"][1] / (2 * FILTER_SPACE["l_out"][0]))


def defaults() -> dict:
    """The datasheet's typical circuit: 50 uH and 5 uF (Output Stage Filtering), the Example Design's 4 ohm
    and 125 kHz, +-20 V, and the LM4652's edges."""
    note = lm4651.params()
    return {"l_out": eqs.L_REF, "c_out": eqs.C_REF, "r_load": note["r_load"], "f_sw": note["f_sw"],
            "supply": eqs.SUPPLY_REF, "t_rise": note["t_rise"], "t_fall": note["t_fall"], "f_audio": F_AUDIO,
            "steps_per_edge": STEPS_PER_EDGE}


def as_deck(p: dict) -> dict:
    """The parameters as the deck writes them (6 significant digits; f_sw as the inverse of its printed period):
    what the equations take, so that they see the deck's parts and not a rounding of them."""
    q = {**p, **{k: as_printed(p[k]) for k in ("l_out", "c_out", "r_load", "supply", "f_audio")}}
    return {**q, "f_sw": 1 / as_printed(1 / p["f_sw"])}


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


def _ac_lines(p: dict, per_decade: int = AC_PER_DECADE) -> list[str]:
    f_lo = p["f_audio"] / 1e3  # f_audio is then a grid point
    # ngspice cannot name vp()/vm()/vdb() in its save list: without an explicit .save it saves nothing
    return [".save v(out)", f".ac dec {per_decade} {f_lo:.6g} {p['f_audio'] * 1e3:.6g}"]


def ac_deck(p: dict, ps: tuple[Part, ...], title: str, meas: list[str], per_decade: int = AC_PER_DECADE) -> str:
    return "\n".join([f"* {title}", *element_lines(p, ps), *_ac_lines(p, per_decade), *meas, ".end"]) + "\n"


@rebuildable
def circuit(p: dict | None = None) -> Circuit:
    """The filter and its load in AC: corner, Q and the gain at f_audio."""
    p = as_deck(with_defaults(defaults(), p))
    ps, fa = parts(p), p["f_audio"]
    args = (p["l_out"], p["c_out"], p["r_load"])
    cid = f"lm4651-filter-{p['r_load']:g}ohm"
    meas = [".meas ac f_corner WHEN vp(out)=-1.57079632679",
            ".meas ac q FIND vm(out) WHEN vp(out)=-1.57079632679",
            f".meas ac g_top FIND vdb(out) AT={fa:.6g}",
            f".meas ac g_max MAX vdb(out) FROM={fa / 1e3:.6g} TO={fa:.6g}",
            f".meas ac g_min MIN vdb(out) FROM={fa / 1e3:.6g} TO={fa:.6g}"]
    k = log_step(AC_CHECK_PER_DECADE)
    corner_tol = round_up(crossing(k) + PRINTED_6)
    peak = k * k * Q_MAX ** 2 / 2  # the chord's error where |H| peaks, at the largest Q of the operating points
    q_tol = round_up(peak + PRINTED_7)
    grid = (f"the AC grid, {AC_CHECK_PER_DECADE} points a decade (k = {k * 100:.3f} % apart), read by linear interpolation "
            "in f")
    checks = (
        Check(f"{cid}-corner", f"corner (phase -90 deg), R_L = {p['r_load']:g} ohm", "Hz", eqs.filter_f0(*args[:2]),
              "f_corner", corner_tol,
              f"two coils in two legs are 2 L in series: nothing is left out but {grid}: the phase is odd about the "
              f"corner in ln f, so the crossing is off by k²/8 at most ({crossing(k):.1e}), and the 6 digits "
              f"ngspice prints ({PRINTED_6:.0e}): {percent(corner_tol)}"),
        Check(f"{cid}-q", f"Q (gain at the corner), R_L = {p['r_load']:g} ohm", "1", eqs.filter_q(*args), "q", q_tol,
              f"the same network; |H| read where the phase crosses -90°, {grid}: the chord's error at the peak, "
              f"|H|'s curvature and the crossing's k²/8 on its slope, is k²(|4Q² - 2| + 1)/8 at most, below k²Q²/2: "
              f"{peak:.1e} at the largest Q of the operating points the referee draws ({Q_MAX:.2f}: "
              f"{FILTER_SPACE['r_load'][1]:g} Ω across {FILTER_SPACE['c_out'][1] * 1e6:g} µF, 2 × "
              f"{FILTER_SPACE['l_out'][0] * 1e6:g} µH); and the 7 printed digits ({PRINTED_7:.0e}): {percent(q_tol)}"),
        Check(f"{cid}-top", f"gain at {eng(fa, 'Hz')}, R_L = {p['r_load']:g} ohm", "dB",
              10 * math.log10(eqs.filter_gain2(fa, *args)), "g_top", PRINTED_7 + 1e-9,
              f"the same network, read at a grid point (no interpolation): the 7 digits ngspice prints the dB value "
              f"with ({PRINTED_7:.0e} of it) and the linear solve's round-off on a four-node network (below 1e-9): "
              f"{percent(PRINTED_7 + 1e-9)}"))
    # (no row for the band's largest deviation from 0 dB: the band runs to 20 kHz, past the corner, so its
    # largest deviation is the loss at f_audio for both loads, the row above repeated)
    title = f"LM4651/LM4652 bridge output filter, R_L = {p['r_load']:g} ohm, AC"
    return Circuit(id=cid, title=title, source=f"{DATASHEET}, Output Stage Filtering; figure 1", parts=ps,
                   netlist=ac_deck(p, ps, title, meas, AC_CHECK_PER_DECADE), checks=checks, draw=partial(draw, ps))


def settle_time(l_out: float, c_out: float, r_load: float) -> float:
    """Time for the filter's slowest mode to decay by exp(-SETTLE): the poles of 2LC s^2 + (2L/R) s + 1."""
    poles = np.roots([2 * l_out * c_out, 2 * l_out / r_load, 1.0])
    return SETTLE / float(np.min(np.abs(poles.real)))


def tran_step(p: dict) -> float:
    """The transient's largest step h: a STEPS_PER_PERIOD-th of the period and a ``steps_per_edge``-th of the shorter
    edge (STEPS_PER_EDGE), so that each edge of the PULSE sources takes several steps (:func:`ripple_bound` says why
    the referee's rows need it); ``steps_per_edge`` 0: the period's alone (the design check's ±0.2 % needs no more)."""
    step = 1 / p["f_sw"] / STEPS_PER_PERIOD
    return min(step, min(p["t_rise"], p["t_fall"]) / p["steps_per_edge"]) if p["steps_per_edge"] else step


def tran_lines(p: dict, name: str = "ripple") -> list[str]:
    """Transient to the settled state; the residue's rms about its mean over the last RMS_PERIODS periods (``name``;
    ``name``_rms and ``name``_avg are the raw rms and mean). The residue is AC: ngspice's first-order step after
    each corner of the edges builds a small DC at the load that is not the bridge's (:func:`ripple_bound`), and the
    Fourier sum the row is held against has no DC either."""
    period = 1 / p["f_sw"]
    n = math.ceil(settle_time(p["l_out"], p["c_out"], p["r_load"]) / period) + RMS_PERIODS
    t_end, t_from, step = period / 4 + n * period, period / 4 + (n - RMS_PERIODS) * period, tran_step(p)
    window = f"FROM={t_from:.12g} TO={t_end:.12g}"  # whole periods: 12 digits, not the deck's 6
    # the run goes an eighth of a period past the window: its stop time is then no corner of the PULSE edges (a
    # corner picoseconds before the stop, from the edges' 6-digit times, can stall ngspice's step at 1e-20 s)
    return [f".tran {step:.6g} {t_end + period / 8:.12g} {t_from:.12g} {step:.6g} uic",
            f".meas tran {name}_rms RMS v(out) {window}", f".meas tran {name}_avg AVG v(out) {window}",
            f".meas tran {name} PARAM='sqrt({name}_rms*{name}_rms-{name}_avg*{name}_avg)'"]


def _pulse_wave(p: dict, t: np.ndarray, v1: float, first: float, second: float) -> np.ndarray:
    """SPICE's PULSE(v1 -v1 td first second width period) at times ``t``, td = period / 4, as :func:`_pulse`."""
    period = 1 / p["f_sw"]
    width = period / 2 - (first + second) / 2
    x = (t - period / 4) % period
    return v1 + (-2 * v1) * (np.clip(x / first, 0, 1) - np.clip((x - first - width) / second, 0, 1))


def _harmonics(p: dict, v: float, n: int = 4096) -> tuple[np.ndarray, np.ndarray, float]:
    """The residue at the load by Fourier series: (k, the power |c_k H_k|^2 of each harmonic k of the whole bridge
    waveform as the deck writes it, that of an ideal square wave's fundamental), numpy FFT of one period, each
    harmonic through the filter's |H| (:func:`eqs.filter_gain2`)."""
    period = 1 / p["f_sw"]
    t = np.arange(n) * period / n

    def spectrum(wave):
        return np.abs(np.fft.rfft(wave) / n)[1:]

    k = np.arange(1, n // 2 + 1)
    gain2 = eqs.filter_gain2(k * p["f_sw"], p["l_out"], p["c_out"], p["r_load"])
    whole = spectrum(_pulse_wave(p, t, -v, p["t_rise"], p["t_fall"]) - _pulse_wave(p, t, v, p["t_fall"], p["t_rise"]))
    ideal = spectrum(_pulse_wave(p, t, -v, 1e-15, 1e-15) - _pulse_wave(p, t, v, 1e-15, 1e-15))
    return k, whole ** 2 * gain2, float(ideal[0] ** 2 * gain2[0])


def residue_spectrum(p: dict, v: float, n: int = 4096) -> float:
    """What the equation's fundamental-only residue leaves out, as a ratio: the residue at the load, rms, of the
    whole bridge waveform (both PULSE sources as the deck writes them: every harmonic, the edges t_r and t_f)
    over that of an ideal square wave's fundamental alone, both by Fourier series (:func:`_harmonics`). A ratio of
    two spectra, so it holds whatever the equation's own constants are: the check still sees an error in them."""
    _, whole, ideal = _harmonics(p, v, n)
    return float(np.sqrt(np.sum(whole) / ideal))


def ripple_bound(p: dict) -> dict:
    """How far the transient's rms of the residue can be from the network's, relative, from the method alone (the
    step h = :func:`tran_step`, ngspice's integration and .meas, the printout): each term and their sum, "total".

    * "first_order": after each breakpoint (every corner of the PULSE edges) ngspice takes one backward-Euler step,
      at most a tenth of the step before it (dctran.c), which misses s h_1^2 / 2 of the drive's volt-seconds, s the
      drive's slope after the corner. Its DC is taken out (the rms about the mean); its harmonics, at most
      2 sum(s h_1^2 / 2) / T each, pass the filter like the drive's: relative to the fundamental's 8 V_s / pi,
      times sqrt(sum |H_m|^2) / |H_1|.
    * "trapezoid": the trapezoidal rule integrates the piecewise-linear drive exactly, but C's charge from the coil
      current, which bends as the drive ramps, with an error of h^2 / 12 of the current's swing in slope: at most
      h^2 (8 V_s + 4 v_peak) / (24 L) a period (the drive's 4 V_s swing twice, the residue's own), a current into the
      load node whose harmonics pass its impedance Z_out.
    * "quadrature": .meas RMS and AVG integrate by Simpson's or the trapezoidal rule between the saved points
      (com_measure2.c): the mean square is off by at most h^2 / 12 of the mean |(v^2)''|, the rms by half that.
    * "printed": the 6 digits ngspice prints.
    """
    period, v, h = 1 / p["f_sw"], p["supply"], tran_step(p)
    l2, c, r = 2 * p["l_out"], p["c_out"], p["r_load"]
    k, power, _ = _harmonics(p, v)
    w = 2 * np.pi * p["f_sw"] * k
    gain = np.sqrt(eqs.filter_gain2(k * p["f_sw"], p["l_out"], c, r))  # |H| at each harmonic
    z_out = np.abs(1 / (1j * w * c + 1 / r + 1 / (1j * w * l2)))  # the load node's impedance, the coils to the bridge
    amplitude = 2 * np.sqrt(power)  # each harmonic of the residue
    fundamental = float(amplitude[0])  # the residue's rms is at least its fundamental's
    # the drive's slope just after each corner of the two PULSE sources (VO1 - VO2), over one period
    tr, tf = p["t_rise"], p["t_fall"]
    width = period / 2 - (tr + tf) / 2
    corners = sorted({round(x, 15) for x in (0.0, tr, tr + width, tr + width + tf, tf, tf + width, tf + width + tr)})
    after = np.array(corners) + min(tr, tf) * 1e-6
    t = after + period / 4
    slope = np.abs(_pulse_wave(p, t + 1e-12, -v, tr, tf) - _pulse_wave(p, t, -v, tr, tf)
                   - _pulse_wave(p, t + 1e-12, v, tf, tr) + _pulse_wave(p, t, v, tf, tr)) / 1e-12
    missed = float(np.sum(slope * (h / 10) ** 2 / 2))  # V s a period
    first_order = 2 * missed / period * float(np.sqrt(np.sum(gain ** 2))) / fundamental
    v_peak = float(np.sum(amplitude))  # at most: every harmonic in phase
    charge = h ** 2 * (8 * v + 4 * v_peak) / (12 * l2)  # C s a period
    trapezoid = 2 * charge / period * float(np.sqrt(np.sum(z_out ** 2))) / fundamental
    mean2 = float(np.sum(power))
    w1 = float(np.sum(w ** 2 * power)) / mean2  # mean(v'^2) / mean(v^2)
    w2 = math.sqrt(float(np.sum(w ** 4 * power)) / mean2)  # sqrt(mean(v''^2) / mean(v^2))
    quadrature = h ** 2 / 24 * (2 * w1 + 2 * w2)
    terms = {"first_order": first_order, "trapezoid": trapezoid, "quadrature": quadrature, "printed": PRINTED_6}
    return {**terms, "total": sum(terms.values()), "step": h}


@rebuildable
def ripple(p: dict | None = None) -> Circuit:
    """The idle bridge (50 % duty) through the filter: the switching residue at the load, rms (about its mean)."""
    p = as_deck(with_defaults(defaults(), p))
    ps = parts(p)
    cid = f"lm4651-ripple-{p['r_load']:g}ohm"
    title = f"LM4651/LM4652 bridge output filter, R_L = {p['r_load']:g} ohm, switching residue"
    eq = eqs.ripple_rms(p["f_sw"], p["l_out"], p["c_out"], p["r_load"], p["supply"])
    expected = residue_spectrum(p, ps[0].value) - 1
    b = ripple_bound(p)
    tol = round_up(b["total"])
    why = (f"expected {expected:+.3%}: the model keeps only the square wave's fundamental (8 V_s / pi); the deck's "
           "waveform has every harmonic (the third is a third as large and filtered 9 times more) and the "
           f"{p['t_rise'] * 1e9:g}/{p['t_fall'] * 1e9:g} ns edges, summed here by Fourier series; left, the method's "
           f"own (class_d.ripple_bound), with steps of at most {b['step'] * 1e9:.3g} ns ("
           + (f"1/{p['steps_per_edge']:g} of the shorter edge, at most " if p["steps_per_edge"] else "")
           + f"1/{STEPS_PER_PERIOD} of the period): ngspice's first-order step after each corner "
           f"of the edges, {b['first_order']:.1e} (the DC it builds is taken out: the rms is about the mean, as the "
           f"Fourier sum's), the trapezoidal rule over the ramps {b['trapezoid']:.1e}, .meas's quadrature "
           f"{b['quadrature']:.1e} and the 6 printed digits {b['printed']:.0e}: {percent(tol)}")
    checks = (Check(f"{cid}-rms", f"switching residue at the load, rms, R_L = {p['r_load']:g} ohm", "V", eq,
                    "ripple", tol, why, expected=expected),)
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
    (oscillator slow/fast, L and C_BYP +- their tolerance; each corner one transient run, the largest kept), at
    the high rail (the residue grows with V_s).
    {"f_corner": Hz, "ripple_at_load": V rms}, each beside the design's own figure ("*_equation"), "corners"
    and "meets_spec" (SPICE's worst residue at most the spec's ripple_max)."""
    s = result.spec
    # the design's ±0.2 % needs no edge-resolving step: a 400th of the period, the rms about its mean (ripple_bound)
    base = {"l_out": result.l_out, "c_out": result.c_out, "r_load": s["r_load"], "supply": model.rails(s)[1],
            "f_sw": result.f_sw, "f_audio": s["f_audio"], "steps_per_edge": 0}
    f_corner = run(circuit(base).netlist)["f_corner"]
    fo, lo, co = model.corner_factors(s)
    worst = 0.0
    for kf, kl, kc in zip(fo, lo, co):  # the design's own oscillator corners (R_OSC, R_DLY at theirs too)
        q = {**base, "f_sw": result.f_sw_min if kf < 1 else result.f_sw_max, "l_out": base["l_out"] * kl,
             "c_out": base["c_out"] * kc}
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
