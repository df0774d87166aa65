"""LM4651/LM4652 class-D amplifier as a joint design: R_OSC, R_DLY, the output filter's L and C_BYP and the
heat sink, chosen together.

Problem. Choose R_OSC (``r_osc_series``), L (``l_series``) and C_BYP (``c_series``) to maximise the
efficiency at p_out (``objective = "efficiency"``) or the heat sink's allowed theta_SA (``"heat_sink"``),
subject at the worst of eight tolerance corners (oscillator slow/fast from eq 5 against the datasheet
table, L and C each +-tolerance; :mod:`~handbook.design.class_d.model`) and at the worse rail end (low for
clipping, high for the rest: each figure is monotonic in V_s) to: THD+N at ``thd_test_power`` as
the analyser reads it (the switching residue added when an oscillator corner lies inside its
``thd_bandwidth``); no clipping at p_out (nor at the test point); the switching residue at the load; the
loaded filter flat across the audio band over the whole L, C tolerance box (exact, not only its corners)
and its Q; the inductor's peak current below its saturation and the 10 A limit; the oscillator inside
50..225 kHz; and the junction at T_jmax - tj_margin with R_DS(on) maximum at temperature, carrying
p_continuous. R_DLY is closed form and exact: the smallest series value whose dead time meets
``dead_time_min`` (the datasheet: more dead time only costs THD).

Method. f_sw, L and C trade ripple and THD (both want f^2 L C large) against the audio band and Q (which
bound L C and C / L) and against the losses (switching grows with f, the coils' loss with L): IPOPT
solves that continuous problem (:func:`solve`, every constraint at every corner). :func:`snap` takes the
best series design near its optimum and then certifies it exactly: both objectives depend on R_OSC and L
alone, so every (R_OSC, L) pair at least as good is searched with every C_BYP, and nothing outside can
win. THD+N jumps where the slow corner crosses the analyser's band, so IPOPT solves each side (two
smooth NLPs) and both seed the snap; the certificate does not depend on them. :func:`enumerate_series`
is the exhaustive check over the whole grid (the tests carry their own, written independently). The
oscillator corners, L and C corners are enumerated (8), never assumed.
"""
from __future__ import annotations

import functools
import math
from collections.abc import Mapping
from dataclasses import dataclass

import casadi as ca
import numpy as np

from ...core import InputError, series
from ...sources.lm4651 import circuit as lm4651
from ..common import Result, Table, checked_table, completed, is_checked, reported
from ..solvers import IPOPT_OPTIONS, Infeasible, Solution
from . import model
from .explain import binding_text, infeasible, warnings
from .model import best, grid

TABLE = "class_d"
DEV = lm4651.DEVICE
L_RANGE, C_RANGE, R_DLY_RANGE = model.L_RANGE, model.C_RANGE, model.R_DLY_RANGE
#: the incumbent's window around IPOPT's optimum, a factor either way on f, L and C
SPREAD = 1.5
#: scales of the solver's variables: f in 100 kHz, L in 100 uH, C in 10 uF
F_S, L_S, C_S = 1e5, 1e-4, 1e-5


@dataclass(frozen=True)
class ClassDResult(Result):
    f_sw: float = reported('Hz', 'switching frequency (eq 5, nominal)')
    f_sw_min: float = reported('Hz', 'slowest oscillator corner')
    f_sw_max: float = reported('Hz', 'fastest oscillator corner')
    r_osc: float = reported('ohm', 'R_OSC')
    r_dly: float = reported('ohm', 'R_DLY')
    l_out: float = reported('H', 'filter inductors L')
    c_out: float = reported('F', 'C_BYP')
    efficiency: float = reported('%', 'efficiency at p_out')
    thermal_basis: str = reported('', 'heat sink sized at')
    p_thermal: float = reported('W', 'output power the heat sink carries (its thermal basis)')
    p_dissipation: float = reported('W', 'LM4652 dissipation at the hotter oscillator corner, with the heat sink used')
    theta_sa_required: float = reported('K/W', 'heat sink needed')
    t_junction: float = reported('C', 'T_j with the heat sink used (the one given, else the one needed: then 150 °C '
                                      '- tj_margin by construction)')
    needs_heat_sink: bool = reported('', 'needs a heat sink (theta_JA alone passes the 150 C shutdown)')
    t_junction_no_sink: float | None = reported('C', 'T_j with no heat sink, theta_JA alone (none: past the shutdown)')
    audio_band: str = reported('', 'audio band')
    f_corner: float = reported('Hz', "output filter's corner, 1/(2 pi sqrt(2 L C_BYP))")
    thd_n: float = reported('%', "THD+N at the test point (in the analyser's band)")
    p_clip: float = reported('W', 'clipping power (fastest oscillator corner, low rail)')
    i_peak: float = reported('A', "coils' worst peak (audio at clipping plus half the ripple)")
    ripple: float = reported('V', 'switching residue at the load, rms, worst corner')
    q: float = reported('1', 'loaded filter Q, worst corner')
    band_deviation: float = reported('dB', "filter's largest deviation across the audio band, whole tolerance box")
    dead_time: float = reported('s', 'dead time, R_DLY at its low end')
    supply_least: float = reported('V', 'lowest rail that still delivers p_out and the THD+N test power unclipped '
                                        '(fastest corner; the LM4651/LM4652 works from +-11 V)')
    binding: str = reported('', 'binding')
    warnings: list = reported('', 'warnings')
    figures: dict
    continuous: tuple  # IPOPT's (f_sw, L, C) before the snap
    band: tuple  # the f_sw corners (slow, fast)

    table = TABLE


def checked(spec: Mapping | None) -> Table:
    """The ``[class_d]`` table completed with its defaults, each value checked against the schema.

    Parameters
    ----------
    spec : Mapping or None
        The ``[class_d]`` table, {key: value} in SI units (temperatures in C): missing keys take their defaults,
        None takes them all; a checked :class:`~handbook.design.common.Table` is taken as it is.

    Returns
    -------
    Table
        Every key of the table, checked (SI units; temperatures in C).

    Raises
    ------
    InputError
        When a key is unknown or a value is of the wrong type or out of range.
    """
    if is_checked(TABLE, spec):  # checked once, where it was read
        return spec
    s = completed(TABLE, spec)
    if s["p_continuous"] is not None and s["thermal_basis"] != "continuous_sine":
        raise InputError(f"{TABLE}.p_continuous = {s['p_continuous']:g} W is a continuous sine power: give it with "
                         f"{TABLE}.thermal_basis = \"continuous_sine\" (the basis is {s['thermal_basis']!r}, 1/8 of the "
                         "clipping power by IEC 62368-1 Annex E)")
    low, high = model.rails(s)
    if low < lm4651.RAILS[0] or high > lm4651.RAILS[1]:
        raise InputError(f"{TABLE}.supply = {s['supply']:g} V with {TABLE}.supply_tolerance = {s['supply_tolerance']:g} "
                         f"puts the rails at +-{low:.4g} V to +-{high:.4g} V, outside the LM4651/LM4652's operating "
                         f"+-{lm4651.RAILS[0]:g} V to +-{lm4651.RAILS[1]:g} V (V+ + V- 22 V to 44 V): a tolerance of at most "
                         f"{min(1 - lm4651.RAILS[0] / s['supply'], lm4651.RAILS[1] / s['supply'] - 1):.3g} fits this supply")
    return checked_table(TABLE, s)


def _basis_text(s: dict) -> str:
    """The heat sink's thermal basis in words."""
    if s["thermal_basis"] == "iec_1_8":
        return "1/8 of the clipping power (IEC 62368-1 Annex E, normal operating condition)"
    if s["p_continuous"] is None:
        return "a continuous sine at the clipping power (all the amplifier delivers)"
    return f"a continuous sine at p_continuous = {s['p_continuous']:g} W"


#: the LM4651/LM4652 datasheet's own use: "designed for low frequency audio applications" (Input Pre-Amplifier
#: with Subwoofer Filter), a subwoofer's low pass "normally set within the range of 60Hz - 180Hz"
SUBWOOFER_BAND = 1e3


def _band_text(s: dict) -> str:
    """The audio band the filter keeps flat, named as the datasheet's subwoofer use when it is one."""
    top = s["f_audio"]
    text = f"up to {top / 1e3:.3g} kHz" if top >= 1e3 else f"up to {top:.3g} Hz"
    if top <= SUBWOOFER_BAND:
        text += " (a subwoofer band: the datasheet's low-frequency use)"
    return text


def r_dly_for(s: dict) -> float:
    """Closed form: the smallest series R_DLY whose dead time 27 ns + 1.7 ns/kΩ x R_DLY meets dead_time_min at
    R_DLY's low tolerance corner, R_DLY (1 - r_tolerance) (0 if the 27 ns at R_DLY = 0 already does: pin 17 to
    ground).

    Parameters
    ----------
    s : dict
        The checked ``[class_d]`` table (SI units; temperatures in C).

    Returns
    -------
    float
        R_DLY, ohm: the smallest ``r_dly_series`` value whose dead time is at least ``dead_time_min``, or 0.0.

    Raises
    ------
    Infeasible
        When ``dead_time_min`` needs more than 1 Mohm (``achievable``: ``dead_time_max``, s).
    """
    need = (s["dead_time_min"] - lm4651.T_DEAD_0) / lm4651.C_DEAD / (1 - s["r_tolerance"])
    if need <= 0:
        return 0.0
    if need > R_DLY_RANGE[1]:
        raise Infeasible(TABLE, f"a dead time of {s['dead_time_min'] * 1e9:.0f} ns needs R_DLY = {need:.0f} ohm, "
                         f"above {R_DLY_RANGE[1]:g} ohm", {"dead_time_max": float(lm4651.dead_time_total(1e6))})
    return series.at_least(s["r_dly_series"], need * (1 - 1e-12))


def _params(s: dict, r_dly: float) -> list[float]:
    """The spec and R_DLY as the NLP's parameter vector (in the order of NAMES)."""
    p = {"p_out": s["p_out"], "r_load": s["r_load"], "v_low": model.rails(s)[0],
         "v_high": model.rails(s)[1], "t_a": s["t_ambient"],
         "path": s["theta_cs"] + DEV["theta_jc"][s["package"]], "sink": s["theta_sa_available"] or 0.0,
         "thd_max": s["thd_max"], "p_test": s["thd_test_power"], "w_cont": float(s["p_continuous"] is not None),
         "clip_share": model.CLIP_SHARE[s["thermal_basis"]],
         "p_cont": s["p_continuous"] or 0.0, "tol_slow": s["osc_tol_slow"], "tol_fast": s["osc_tol_fast"],
         "tol_r": s["r_tolerance"], "r_dly": r_dly,
         "tol_l": s["l_tolerance"], "tol_c": s["c_tolerance"], "f_audio": s["f_audio"],
         "g_band": 10 ** (s["droop_max"] / 10), "q_max": s["q_max"], "ripple_max": s["ripple_max"],
         "i_max": model.i_peak_limit(s), "dcr": s["l_dcr"], "t_target": DEV["tj_max"] - s["tj_margin"],
         "rds25": s["rds_on_25"], "t_om": s["t_overmod"], "band": s["thd_bandwidth"],
         "p_need": model.p_unclipped(s)}
    return [p[n] for n in NAMES]


def _theta_needed(f, P):
    """theta_SA needed at oscillator frequency f (symbolic twin of model.heat)."""
    pc = P["w_cont"] * P["p_cont"] + (1 - P["w_cont"]) * P["clip_share"] * lm4651.p_clip(f, P["r_load"], P["v_high"])
    watts = (lm4651.p_switch(f, pc, t_overmod=P["t_om"]) + lm4651.p_idle_4652(P["v_high"])
             + 2 * pc / P["r_load"] * P["rds25"] * (1 + lm4651.RDS_TC * (P["t_target"] - 25.0)))
    return (P["t_target"] - P["t_a"]) / watts - P["path"]


def _constraints(f, l_out, c_out, P, above: bool) -> list[tuple[str, object, float, float]]:
    """Every constraint at every corner, scaled to order one (the symbolic twin of model.figures).

    THD+N jumps where an oscillator corner crosses the analyser's band, so the NLP is solved on each side
    of it, both smooth: ``above`` holds the slowest corner above the band (distortion alone), else the
    residue is counted at every corner (at a corner above the band that is conservative)."""
    slow, fast = _corners(f, P)
    out = [("oscillator range", slow / DEV["f_min"], 1.0, ca.inf),
           ("oscillator range", fast / DEV["f_max"], -ca.inf, 1.0)]
    if above:
        out.append(("analyser band", slow / P["band"], 1.0, ca.inf))
    rl, vs = P["r_load"], P["v_high"]  # each figure below grows with the rails (model.rails)
    for so, sl, sc in model.CORNERS:
        fc = slow if so < 0 else fast
        lc, cc = l_out * (1 + sl * P["tol_l"]), c_out * (1 + sc * P["tol_c"])
        thd = lm4651.thd_n_joint(fc, lc, cc, P["p_test"], rl, vs)
        if not above:
            thd = (thd ** 2 + lm4651.residue_fraction(fc, lc, cc, P["p_test"], rl, vs) ** 2) ** 0.5
        out += [("THD+N", thd / P["thd_max"], -ca.inf, 1.0),
                ("ripple", lm4651.ripple_rms(fc, lc, cc, rl, vs) / P["ripple_max"], -ca.inf, 1.0),
                ("audio band", lm4651.filter_gain2(P["f_audio"], lc, cc, rl) / P["g_band"], -ca.inf, 1.0),
                ("audio band", lm4651.filter_gain2(P["f_audio"], lc, cc, rl) * P["g_band"], 1.0, ca.inf),
                ("filter Q", lm4651.filter_q(lc, cc, rl) / P["q_max"], -ca.inf, 1.0),
                ("inductor peak", lm4651.inductor_peak(fc, lc, cc, lm4651.v_clip_peak(fc, rl, vs), rl, vs,
                                                       P["f_audio"]) / P["i_max"], -ca.inf, 1.0)]
    c_hi = c_out * (1 + P["tol_c"])  # the box's worst in-band peaking (model.band_deviation_box_db)
    l_star = ca.fmin(ca.fmax(lm4651.filter_worst_peak_l(P["f_audio"], c_hi, rl), l_out * (1 - P["tol_l"])),
                     l_out * (1 + P["tol_l"]))
    out.append(("audio band", lm4651.filter_gain2(P["f_audio"], l_star, c_hi, rl) / P["g_band"], -ca.inf, 1.0))
    out.append(("clipping", lm4651.p_clip(fast, rl, P["v_low"]) / P["p_need"], 1.0, ca.inf))
    return out


def _corners(f, P):
    """The oscillator's slow and fast corners of the solver's f (:func:`~handbook.design.class_d.model.osc_corners`)."""
    return model.osc_corners(f, P["r_dly"], P["tol_slow"], P["tol_fast"], P["tol_r"])


NAMES = ("p_out", "r_load", "v_low", "v_high", "t_a", "path", "sink", "thd_max", "p_test", "w_cont", "clip_share", "p_cont",
         "tol_slow", "tol_fast", "tol_r", "r_dly", "tol_l", "tol_c", "f_audio", "g_band", "q_max", "ripple_max", "i_max", "dcr",
         "t_target", "rds25", "t_om", "band", "p_need")


@functools.lru_cache(maxsize=4)
def _nlp(objective: str, above: bool):
    """The NLP, built once per objective and side of the analyser's band with the spec as parameters (x: f, L,
    C scaled; t: theta_SA)."""
    x = ca.SX.sym("x", 4)
    p = ca.SX.sym("p", len(NAMES))
    P = {n: p[i] for i, n in enumerate(NAMES)}
    f, l_out, c_out, t = x[0] * F_S, x[1] * L_S, x[2] * C_S, x[3]
    cons = _constraints(f, l_out, c_out, P, above)
    for fc in _corners(f, P):
        theta = _theta_needed(fc, P)
        cons += [("heat sink", theta - P["sink"], 0.0, ca.inf), ("heat sink objective", theta - t, 0.0, ca.inf)]
    loss = (lm4651.p_switch(f, P["p_out"]) + lm4651.coil_loss(P["p_out"], P["r_load"], l_out, P["dcr"])) / P["p_out"]
    obj = loss if objective == "efficiency" else -t + 1e-3 * loss
    g = ca.vertcat(*[c[1] for c in cons])
    solver = ca.nlpsol(f"class_d_{objective}_{above}", "ipopt", {"x": x, "p": p, "f": obj, "g": g},
                       {**IPOPT_OPTIONS, "ipopt.max_iter": 300})
    return solver, [c[0] for c in cons], [c[2] for c in cons], [c[3] for c in cons]


def solve(s: dict, r_dly: float) -> list[Solution]:
    """IPOPT on the continuous problem: (f_sw, L, C) as reals, every constraint at every corner, on each side
    of the analyser's band: both solutions, the better solved one first.

    Parameters
    ----------
    s : dict
        The checked ``[class_d]`` table (SI units; temperatures in C).
    r_dly : float
        R_DLY, ohm (:func:`r_dly_for`): it moves eq 5 and its tolerance the oscillator's corners.

    Returns
    -------
    list of Solution
        Two solutions, one per side of the analyser's band (the one above it has an "analyser band"
        constraint); solved ones first, then the lower objective. Each ``x`` is (f_sw in Hz, L in H, C_BYP in F,
        theta_SA bound in K/W); the multipliers name the binding constraints.
    """
    f_lo = DEV["f_min"] / (1 - s["osc_tol_slow"])
    f_hi = DEV["f_max"] / (1 + s["osc_tol_fast"])
    x0 = [math.sqrt(f_lo * max(f_hi, f_lo)) / F_S, 50e-6 / L_S, 5e-6 / C_S, 0.0]
    lbx = [DEV["f_min"] / F_S, L_RANGE[0] / L_S, C_RANGE[0] / C_S, -100.0]
    ubx = [DEV["f_max"] / F_S, L_RANGE[1] / L_S, C_RANGE[1] / C_S, 100.0]
    found = []
    for above in (False, True):
        solver, names, lbg, ubg = _nlp(s["objective"], above)
        r = solver(x0=x0, p=_params(s, r_dly), lbx=lbx, ubx=ubx, lbg=lbg, ubg=ubg)
        x = np.array(r["x"]).ravel() * [F_S, L_S, C_S, 1.0]
        sol = Solution(x, np.array(r["lam_g"]).ravel(), names, bool(solver.stats()["success"]))
        found.append((not sol.success, float(r["f"]), above, sol))
    return [c[3] for c in sorted(found, key=lambda c: c[:3])]


def snap(s: dict, seeds, r_dly: float):
    """The best series (R_OSC, L, C_BYP), exactly, from IPOPT's (f, L, C) on each side of the band (seeds).

    First the best within a factor SPREAD of either optimum (the incumbent); then every (R_OSC, L) pair
    whose objective is at least the incumbent's (both objectives are set by R_OSC and L alone) with every
    C_BYP: nothing outside that set can beat the incumbent, so the best inside it is the optimum. IPOPT only
    makes the set small. Returns (parts or None, their figures, the figures of the last set searched).

    Parameters
    ----------
    s : dict
        The checked ``[class_d]`` table (SI units; temperatures in C).
    seeds : iterable of sequence of float
        IPOPT's optima, each starting (f_sw in Hz, L in H, C_BYP in F) (:attr:`Solution.x`).
    r_dly : float
        R_DLY, ohm (:func:`r_dly_for`).

    Returns
    -------
    tuple
        (parts: (R_OSC in ohm, L in H, C_BYP in F) of the best series design, or None when nothing in the
        last set meets every check; its figures as plain floats (:func:`~handbook.design.class_d.model.at`), or
        None; searched: (R_OSC, L, C_BYP) flat arrays of the last set searched and their
        :func:`~handbook.design.class_d.model.figures`, None when that set was empty).
    """
    near = [grid(s, r_dly, *[(v / SPREAD, v * SPREAD) for v in x[:3]]) for x in seeds]
    r, l_out, c_out = (np.concatenate(a) for a in zip(*near))
    i, fig = best(s, r, l_out, c_out, r_dly) if r.size else (None, None)
    rs, ls, cs = model.axes(s, r_dly)
    R, L = (a.ravel() for a in np.meshgrid(rs, ls, indexing="ij"))
    first, _ = model.pair_keys(s, R, L, r_dly)
    if i is not None:
        incumbent = model.pair_keys(s, r[i], l_out[i], r_dly)[0]
        keep = first >= incumbent - 1e-12 * abs(incumbent)
        R, L = R[keep], L[keep]
    r, c_out = (a.ravel() for a in np.meshgrid(R, cs, indexing="ij"))
    l_out = np.repeat(L, len(cs))
    i, fig = best(s, r, l_out, c_out, r_dly) if r.size else (None, None)
    if i is None:
        return None, None, (r, l_out, c_out, fig)
    return (r[i], l_out[i], c_out[i]), model.at(fig, i), (r, l_out, c_out, fig)


def enumerate_series(s: dict):
    """Exhaustive: the best (R_OSC, L, C_BYP, R_DLY) over the whole grid, or None (the chapter's check).

    Parameters
    ----------
    s : Mapping or None
        The ``[class_d]`` table, {key: value} in SI units (checked here; a checked
        :class:`~handbook.design.common.Table` is taken as it is).

    Returns
    -------
    tuple of float or None
        (R_OSC in ohm, L in H, C_BYP in F, R_DLY in ohm) of the best series design, or None when none meets every
        check.

    Raises
    ------
    InputError
        When the spec is invalid.
    Infeasible
        When no series R_DLY gives ``dead_time_min``.
    """
    s = checked(s)
    r_dly = r_dly_for(s)
    r, l_out, c_out = grid(s, r_dly)
    i, _ = best(s, r, l_out, c_out, r_dly) if r.size else (None, None)
    return None if i is None else (float(r[i]), float(l_out[i]), float(c_out[i]), r_dly)


def design(spec: dict | None = None) -> ClassDResult:
    """The joint design: IPOPT for (f_sw, L, C), snapped to the series and re-verified at every corner.

    Parameters
    ----------
    spec : Mapping or None
        The ``[class_d]`` table, {key: value} in SI units (temperatures in C): missing keys take their defaults,
        None takes them all; a checked :class:`~handbook.design.common.Table` is taken as it is.

    Returns
    -------
    ClassDResult
        The checked spec; the switching frequency, nominal and at both oscillator corners (Hz); R_OSC and
        R_DLY (ohm), L (H), C_BYP (F); efficiency and THD+N (fractions); the LM4652's dissipation and the
        clipping power (W); the heat sink needed (K/W); T_j with it and with none (C); what binds; the
        warnings; every figure and margin (``figures``); IPOPT's continuous (f_sw, L, C); the band (Hz, Hz).

    Raises
    ------
    InputError
        When the spec is invalid.
    Infeasible
        When no series design meets every check at every tolerance corner (``achievable``: what each failed
        check can reach while the others hold), or no series R_DLY gives ``dead_time_min``.
    """
    s = checked(spec)
    r_dly = r_dly_for(s)
    sols = solve(s, r_dly)
    parts, fig, searched = snap(s, [sol.x for sol in sols], r_dly)
    if parts is None:
        infeasible(s, r_dly, searched)  # with no incumbent the set searched was the whole grid
    r_osc, l_out, c_out = (float(v) for v in parts)
    # the binding constraints of the continuous optimum on the series design's side of the band
    above = fig["f_sw_min"] >= s["thd_bandwidth"]
    sol = next((x for x in sols if ("analyser band" in x.names) == above), sols[0])
    f_slow, f_fast = fig["f_sw_min"], fig["f_sw_max"]
    f_set, _ = model.heat_corner(s, f_slow, f_fast)
    p_thermal = float(model.thermal_power(s, f_set))
    hot = bool(fig["t_junction_no_sink"] > DEV["tj_max"])
    return ClassDResult(
        spec=s, f_sw=fig["f_sw"], f_sw_min=fig["f_sw_min"], f_sw_max=fig["f_sw_max"], r_osc=r_osc, r_dly=r_dly,
        l_out=l_out, c_out=c_out, efficiency=fig["efficiency"], p_dissipation=fig["p_dissipation"],
        theta_sa_required=fig["theta_sa_required"], t_junction=fig["t_junction"],
        thermal_basis=_basis_text(s), p_thermal=p_thermal, needs_heat_sink=hot,
        t_junction_no_sink=None if hot else fig["t_junction_no_sink"], audio_band=_band_text(s),
        f_corner=float(lm4651.filter_f0(l_out, c_out)),
        thd_n=fig["thd_n"], p_clip=fig["p_clip"], supply_least=fig["supply_least"], i_peak=fig["i_peak"],
        ripple=fig["ripple"], q=fig["q"], band_deviation=fig["band_deviation"], dead_time=fig["dead_time"],
        binding=binding_text(sol, fig),
        warnings=warnings(s, fig, l_out, c_out),
        figures=fig, continuous=(float(sol.x[0]), float(sol.x[1]), float(sol.x[2])),
        band=(fig["f_sw_min"], fig["f_sw_max"]))
