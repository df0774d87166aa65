"""LM4651/LM4652 joint design: every figure of a candidate (R_OSC, L, C, R_DLY) at every tolerance corner.

The corners are enumerated, never assumed: the oscillator at eq 5 x (1 - osc_tol_slow) and x (1 + osc_tol_fast), eq
5 taken with R_OSC and R_DLY at their own tolerance corners (``r_tolerance``), L and C each at +- their tolerance
(2 x 2 x 2 = 8 corners), and the LM4652 at its maximum R_DS(on) at the junction temperature and the Example
Design's 350 ns over-modulation time. Every constraint takes its worst corner; the filter's band check takes its
true worst over the whole L, C box (:func:`band_deviation_box_db`), since peaking can be worst between corners. The
functions broadcast over numpy arrays of candidates (a corner axis is added last), so the solver's snap, the
exhaustive enumeration and the plots share one evaluator. The models themselves are in
:mod:`handbook.sources.lm4651.circuit`.
"""
from __future__ import annotations

import itertools

import numpy as np

from ...core import series
from ...sources.lm4651 import circuit as lm4651
from .. import ratings

DEV = lm4651.DEVICE
#: the search ranges of the series parts (H, F, ohm)
L_RANGE, C_RANGE, R_OSC_RANGE, R_DLY_RANGE = (1e-6, 1e-3), (0.1e-6, 100e-6), (100.0, 1e5), (0.0, 1e6)
#: the eight corners: (oscillator sign, L sign, C sign); -1 is the slow / low end
CORNERS = np.array(list(itertools.product((-1, 1), repeat=3)), dtype=float)
#: the constraints, in the order the chapter and the binding list name them
CHECKS = ("oscillator range", "THD+N", "clipping", "ripple", "audio band", "filter Q", "inductor peak",
          "dead time", "heat sink")


def corner_factors(s: dict) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Multipliers of f, L and C at the eight corners.

    Parameters
    ----------
    s : dict
        The checked ``[class_d]`` table (SI units; temperatures in C).

    Returns
    -------
    tuple of numpy.ndarray
        (f factors, L factors, C factors), eight pure numbers each, in the order of :data:`CORNERS`: 1 -
        ``osc_tol_slow`` or 1 + ``osc_tol_fast``, 1 -+ ``l_tolerance``, 1 -+ ``c_tolerance``.
    """
    fo = np.where(CORNERS[:, 0] < 0, 1 - s["osc_tol_slow"], 1 + s["osc_tol_fast"])
    return fo, 1 + s["l_tolerance"] * CORNERS[:, 1], 1 + s["c_tolerance"] * CORNERS[:, 2]


def rails(s: dict) -> tuple[float, float]:
    """The rails' two ends: every figure the design judges is monotonic in V_s, so each is worst at one end (the
    clipping power rises with V_s squared: worst at the low rail; THD+N, the residue, the coils' peak and the
    LM4652's dissipation all grow with V_s: worst at the high one). Exact, not an assumption of the corners.

    Parameters
    ----------
    s : dict
        The checked ``[class_d]`` table (SI units); ``supply`` (V) and ``supply_tolerance`` are read.

    Returns
    -------
    tuple of float
        (low rail, high rail), V: ``supply`` x (1 -+ ``supply_tolerance``).
    """
    return s["supply"] * (1 - s["supply_tolerance"]), s["supply"] * (1 + s["supply_tolerance"])


def supply_least(s: dict, f_fast) -> float:
    """The lowest rail at which the fast oscillator corner still delivers max(p_out, the THD+N test power)
    unclipped: the clipping power goes as V_s squared (:func:`~handbook.sources.lm4651.circuit.p_clip`); never
    below the LM4651/LM4652's operating minimum, +-11 V (V+ + V- 22 V), where it stops working whatever the power.

    Parameters
    ----------
    s : dict
        The checked ``[class_d]`` table (SI units).
    f_fast : float or numpy.ndarray
        The oscillator's fast corner, Hz.

    Returns
    -------
    float or numpy.ndarray
        The least rail V_s, V.
    """
    v = s["supply"] * (p_unclipped(s) / lm4651.p_clip(f_fast, s["r_load"], s["supply"])) ** 0.5
    return np.maximum(v, lm4651.RAILS[0])


def osc_corners(f_nom, r_dly, slow, fast, r_tol):
    """The oscillator's slow and fast corners: eq 5 with R_OSC and R_DLY each at its ``r_tolerance`` corner
    (f = 1e9 / (4000 + R_OSC - 0.4 R_DLY): slowest with R_OSC high and R_DLY low), times the table's spread
    against eq 5 (1 - ``osc_tol_slow``, 1 + ``osc_tol_fast``). In terms of the nominal frequency, so the solver's
    variable f serves too: with D = 1e9 / f = 4000 + R_OSC - 0.4 R_DLY, the slow corner's denominator is
    D (1 + t) + t (0.8 R_DLY - 4000), the fast one's D (1 - t) - t (0.8 R_DLY - 4000).

    Parameters
    ----------
    f_nom : float, numpy.ndarray or casadi.SX
        The nominal frequency, eq 5 with the nominal parts, Hz.
    r_dly : float
        R_DLY, ohm.
    slow, fast : float
        ``osc_tol_slow`` and ``osc_tol_fast``, fractions.
    r_tol : float
        ``r_tolerance``, the fraction R_OSC and R_DLY may each stray.

    Returns
    -------
    tuple
        (slow corner, fast corner), Hz, broadcast as ``f_nom``.
    """
    d, k = 1e9 / f_nom, r_tol * (0.8 * r_dly - 4000.0)
    return (1 - slow) * 1e9 / (d * (1 + r_tol) + k), (1 + fast) * 1e9 / (d * (1 - r_tol) - k)


def band_deviation_db(f_audio, l_out, c_out, r_load):
    """Largest deviation of |H| from 0 dB over 0..f_audio (closed form): |H| rises to its peak at
    x_p = sqrt(1 - 1/(2 Q^2)) (when Q > 1/sqrt 2) and falls after it, so the band's extremes are |H(0)| = 1,
    |H(f_audio)| and the peak 1 / (u (2 - u)), u = 1/(2 Q^2), when it lies inside the band.

    Parameters
    ----------
    f_audio : float
        The top of the audio band, Hz.
    l_out : float or numpy.ndarray
        The filter inductors' L, H (arrays broadcast).
    c_out : float or numpy.ndarray
        C_BYP, F.
    r_load : float
        The load resistance, ohm.

    Returns
    -------
    numpy.ndarray
        The largest deviation of the loaded filter's |H| from 0 dB over 0..f_audio, dB (not negative), one per
        candidate.
    """
    x2 = (f_audio / lm4651.filter_f0(l_out, c_out)) ** 2
    g_top = lm4651.filter_gain2(f_audio, l_out, c_out, r_load)
    u = 1 / (2 * lm4651.filter_q(l_out, c_out, r_load) ** 2)
    peak_inside = (u < 1) & (x2 >= 1 - u)
    g_peak = 1 / np.maximum(u * (2 - u), 1e-300)  # only used where u < 1
    g_max = np.where(peak_inside, g_peak, np.maximum(1.0, g_top))
    g_min = np.minimum(1.0, g_top)
    return 10 * np.log10(np.maximum(g_max, 1 / g_min))


def band_deviation_box_db(s: dict, l_out, c_out):
    """Largest deviation of |H| from 0 dB over 0..f_audio and over the whole tolerance box of L and C, exact.

    Droop: |H(f)|^-2 is a convex quadratic in f^2, in L and in C separately, so its largest value over the
    band and the box is at f_audio and a corner of the box. Peaking can lie inside the box (up to 3.7 dB
    above every corner, by a brute-force sweep): |H|^-2 = (1 - 2 L p)^2 + (2 L / R_L)^2 w^2 with p = C w^2,
    so at any p the largest C (the smallest w) gives the most gain: C = C (1 + tol) always binds.
    Along that edge the in-band maximum is at L* of :func:`~handbook.sources.lm4651.circuit.filter_worst_peak_l`
    clipped to the box (below L* the gain at f_audio climbs to it; above L*, it falls, and once the peak
    enters the band the peak falls with Q). So: the four corners and that one point.

    Parameters
    ----------
    s : dict
        The checked ``[class_d]`` table (SI units; temperatures in C).
        ``r_load``, ``f_audio``, ``l_tolerance`` and ``c_tolerance`` are read.
    l_out : float or numpy.ndarray
        The filter inductors' nominal L, H (arrays broadcast).
    c_out : float or numpy.ndarray
        C_BYP, nominal, F.

    Returns
    -------
    numpy.ndarray
        The largest deviation of |H| from 0 dB over the band and the L, C tolerance box, dB, one per candidate.
    """
    rl, fa = s["r_load"], s["f_audio"]
    tl, c_hi = s["l_tolerance"], c_out * (1 + s["c_tolerance"])
    l_star = np.clip(lm4651.filter_worst_peak_l(fa, c_hi, rl), l_out * (1 - tl), l_out * (1 + tl))
    corners = [band_deviation_db(fa, l_out * (1 + sl * tl), c_out * (1 + sc * s["c_tolerance"]), rl)
               for sl in (-1, 1) for sc in (-1, 1)]
    return np.maximum(np.max(corners, axis=0), band_deviation_db(fa, l_star, c_hi, rl))


#: the share of the clipping power the heat sink is sized at, per thermal basis (IEC 62368-1 Annex E: 1/8)
CLIP_SHARE = {"iec_1_8": 1 / 8, "continuous_sine": 1.0}


def thermal_power(s: dict, f):
    """The output power the heat sink is sized at, W: 1/8 of the clipping power at f and the high rail
    (``thermal_basis`` = 'iec_1_8', IEC 62368-1 Annex E's normal operating condition), or a continuous sine at
    ``p_continuous`` (default: the clipping power at f and the high rail, all the amplifier can deliver) for
    'continuous_sine'.

    Parameters
    ----------
    s : dict
        The checked ``[class_d]`` table (SI units); ``thermal_basis``, ``p_continuous`` (W), ``r_load`` (ohm),
        ``supply`` (V) and ``supply_tolerance`` are read.
    f : float or numpy.ndarray
        The oscillator frequency, Hz (arrays broadcast).

    Returns
    -------
    float or numpy.ndarray
        The output power the LM4652's heat sink carries, W, broadcast over ``f``.
    """
    if s["thermal_basis"] == "continuous_sine" and s["p_continuous"] is not None:
        return s["p_continuous"] + 0 * f
    return CLIP_SHARE[s["thermal_basis"]] * lm4651.p_clip(f, s["r_load"], rails(s)[1])


def loss_terms(s: dict, f, t_j) -> dict:
    """The LM4652's dissipation term by term at oscillator frequency f and junction temperature t_j, carrying
    :func:`thermal_power` at the high rail: eq 9 and 10 with ``t_overmod``, conduction with R_DS(on) maximum at
    t_j (scaled to ``rds_on_25``), and the idle share.

    Parameters
    ----------
    s : dict
        The checked ``[class_d]`` table (SI units; temperatures in C).
    f : float or numpy.ndarray
        The oscillator frequency, Hz (arrays broadcast).
    t_j : float or numpy.ndarray
        The junction temperature, C.

    Returns
    -------
    dict
        ``p_out`` (W, the power carried), ``fraction`` (eq 9's x), ``rds_on`` (ohm), ``switching``,
        ``conduction``, ``idle`` and ``total`` (W), broadcast over ``f`` and ``t_j``.
    """
    p = thermal_power(s, f)
    rds = lm4651.rds_on_max(t_j) * s["rds_on_25"] / lm4651.RDS_ON_MAX_25
    out = {"p_out": p, "fraction": lm4651.switching_loss_fraction(f, t_overmod=s["t_overmod"]), "rds_on": rds,
           "switching": lm4651.p_switch(f, p, t_overmod=s["t_overmod"]),
           "conduction": lm4651.p_conduction(p, s["r_load"], rds), "idle": lm4651.p_idle_4652(rails(s)[1]) + 0 * p}
    out["total"] = out["switching"] + out["conduction"] + out["idle"]
    return out


def heat(s: dict, f, theta_sa=None, bare=False):
    """(theta_SA needed, T_j with theta_SA, LM4652 dissipation at that T_j) at oscillator frequency f.

    The LM4652's dissipation is :func:`loss_terms`' total, linear in T_j through R_DS(on):
    P(T_j) = P0 + k T_j, so T_j = (T_a + theta P0) / (1 - theta k) exactly (inf: no steady state). ``bare``: no
    heat sink, the package alone at the thermal table's theta_JA; where that steady state would pass T_jmax (or
    there is none) the shutdown trips, and T_j reads T_a + theta_JA P(T_jmax), where the junction heads at
    R_DS(on)'s T_jmax value: above T_jmax, finite.

    Parameters
    ----------
    s : dict
        The checked ``[class_d]`` table (SI units; temperatures in C).
    f : float or numpy.ndarray
        The oscillator frequency, Hz (arrays broadcast).
    theta_sa : float or numpy.ndarray or None
        The heat sink's thermal resistance, sink to air, K/W; None: the one needed.
    bare : bool
        True: no heat sink, the package's theta_JA alone (``theta_sa`` not used).

    Returns
    -------
    tuple
        (theta_SA needed to hold T_j at 150 C - ``tj_margin``, K/W; T_j with ``theta_sa``, C, inf where there is
        no steady state (``bare``: the package alone, and past T_jmax the shutdown's reading described above);
        the LM4652's dissipation at that T_j, W), each broadcast over ``f``.
    """
    def total(t):
        return loss_terms(s, f, t)["total"]

    path = DEV["theta_jc"][s["package"]] + s["theta_cs"]
    need = (DEV["tj_max"] - s["tj_margin"] - s["t_ambient"]) / total(DEV["tj_max"] - s["tj_margin"]) - path
    sink = need if theta_sa is None else theta_sa
    theta = lm4651.THETA_JA[s["package"]] if bare else path + sink
    p0, k = total(0.0), total(1.0) - total(0.0)  # exact: the total is linear in T_j
    runaway = theta * k >= 1
    tj = np.where(runaway, np.inf, (s["t_ambient"] + theta * p0) / np.where(runaway, 1.0, 1 - theta * k))
    if bare:
        tj = np.where(tj <= DEV["tj_max"], tj, s["t_ambient"] + theta * total(DEV["tj_max"]))
    return need, tj, total(tj)


def efficiency(s: dict, f_nom, l_out):
    """Efficiency at p_out, typical parts at the nominal frequency and rails: conduction with the Example Design's
    230 mOhm hot, eq 9/10 with the typical 310 ns, the idle loss and the coils (system table: 85 % at
    125 W).

    Parameters
    ----------
    s : dict
        The checked ``[class_d]`` table (SI units; temperatures in C).
    f_nom : float or numpy.ndarray
        The nominal switching frequency, Hz (arrays broadcast).
    l_out : float or numpy.ndarray
        The filter inductors' L, H (for their copper loss at ``l_dcr``).

    Returns
    -------
    float or numpy.ndarray
        The efficiency at ``p_out``, a fraction.
    """
    p = s["p_out"]
    loss = (lm4651.p_conduction(p, s["r_load"]) + lm4651.p_switch(f_nom, p) + lm4651.p_idle(s["supply"])
            + lm4651.coil_loss(p, s["r_load"], l_out, s["l_dcr"]))
    return p / (p + loss)


def i_peak_limit(s: dict) -> float:
    """The largest worst-case inductor peak the design allows: the coils' rated saturation ``i_sat`` over the
    book's saturation margin (:data:`~handbook.design.ratings.SATURATION_MARGIN`, 1.2: the BOM asks the same
    rating), and never above the LM4651's 10 A current limit (the datasheet's R_SCKT: "ripple and peak current
    must be lower than 10 amps").

    Parameters
    ----------
    s : dict
        The checked ``[class_d]`` table (SI units).

    Returns
    -------
    float
        The peak current limit, A.
    """
    return min(s["i_sat"] / ratings.SATURATION_MARGIN, lm4651.I_LIMIT)


def p_unclipped(s: dict) -> float:
    """The power that must not clip: p_out, or the THD+N test point if higher (above clipping THD+N is 1 %
    or more by the datasheet's own definition of the clipping point, so a test point there is no test).

    Parameters
    ----------
    s : dict
        The checked ``[class_d]`` table (SI units; temperatures in C).

    Returns
    -------
    float
        max(``p_out``, ``thd_test_power``), W.
    """
    return max(s["p_out"], s["thd_test_power"])


def heat_corner(s: dict, f_slow: float, f_fast: float) -> tuple[float, float]:
    """The oscillator corner that sets the heat sink (the one whose need is the smaller; the slow one on a tie) and
    the LM4652's dissipation there with T_j at 150 C - ``tj_margin``.

    Parameters
    ----------
    s : dict
        The checked ``[class_d]`` table (SI units; temperatures in C).
    f_slow, f_fast : float
        The oscillator's slow and fast corners, Hz.

    Returns
    -------
    tuple of float
        (that corner's frequency, Hz; the dissipation, W).
    """
    (need_slow, _, p_slow), (need_fast, _, p_fast) = heat(s, f_slow), heat(s, f_fast)
    return (f_slow, float(p_slow)) if need_slow <= need_fast else (f_fast, float(p_fast))


def thermal(s: dict, f_slow, f_fast):
    """(theta_SA needed, T_j, dissipation, T_j with no heat sink), the last three at the hotter oscillator
    corner. The heat sink is the one given, else the one needed: the smaller need of the two corners,
    so the corner that sets it sits at 150 C - tj_margin and the other runs cooler; that corner's
    dissipation is the one reported.

    Parameters
    ----------
    s : dict
        The checked ``[class_d]`` table (SI units; temperatures in C).
    f_slow, f_fast : float or numpy.ndarray
        The oscillator's slow and fast corners, Hz (arrays broadcast).

    Returns
    -------
    tuple
        (theta_SA needed, K/W; T_j with the heat sink, C; the LM4652's dissipation, W; T_j with no heat sink,
        C, the hotter corner's), each broadcast over the frequencies.
    """
    need = np.minimum(heat(s, f_slow)[0], heat(s, f_fast)[0])
    sink = need if s["theta_sa_available"] is None else s["theta_sa_available"]
    (_, tj_s, p_s), (_, tj_f, p_f) = heat(s, f_slow, sink), heat(s, f_fast, sink)
    slow = (tj_s > tj_f) | ((tj_s == tj_f) & (p_s >= p_f))
    bare = np.maximum(heat(s, f_slow, bare=True)[1], heat(s, f_fast, bare=True)[1])
    return need, np.where(slow, tj_s, tj_f), np.where(slow, p_s, p_f), bare


def per_corner(s: dict, f_slow, f_fast, l_out, c_out) -> dict:
    """The figures judged at the eight corners of the oscillator, L and C (last axis), before the worst is taken,
    at the high rail (:func:`rails`: each grows with V_s).

    Parameters
    ----------
    s : dict
        The checked ``[class_d]`` table (SI units).
    f_slow, f_fast : numpy.ndarray
        The oscillator's slow and fast corners of each candidate, Hz.
    l_out, c_out : numpy.ndarray
        The candidates' nominal L (H) and C_BYP (F).

    Returns
    -------
    dict
        ``f``, ``l``, ``c`` (each corner's frequency, Hz, inductance, H, and capacitance, F) and the figure at each
        corner: ``THD+N`` (fraction, as measured), ``ripple`` (V rms), ``filter Q`` and ``inductor peak`` (A), each
        of shape (candidates, 8).
    """
    _, lo, co = corner_factors(s)
    f = np.where(CORNERS[:, 0] < 0, np.asarray(f_slow)[..., None], np.asarray(f_fast)[..., None])
    l, c = np.asarray(l_out)[..., None] * lo, np.asarray(c_out)[..., None] * co
    rl, vs = s["r_load"], rails(s)[1]
    return {"f": f, "l": l, "c": c,
            "THD+N": lm4651.thd_n_measured(f, l, c, s["thd_test_power"], rl, vs, s["thd_bandwidth"]),
            "ripple": lm4651.ripple_rms(f, l, c, rl, vs), "filter Q": lm4651.filter_q(l, c, rl),
            "inductor peak": lm4651.inductor_peak(f, l, c, lm4651.v_clip_peak(f, rl, vs), rl, vs, s["f_audio"])}


def worst_corners(s: dict, r_osc: float, l_out: float, c_out: float, r_dly: float) -> dict:
    """For one design, the corner at which each corner-judged figure is worst: what the calculation sheet
    substitutes.

    Parameters
    ----------
    s : dict
        The checked ``[class_d]`` table (SI units).
    r_osc, l_out, c_out, r_dly : float
        The design's R_OSC (ohm), L (H), C_BYP (F) and R_DLY (ohm).

    Returns
    -------
    dict
        {"THD+N", "ripple", "filter Q", "inductor peak": (f, Hz; L, H; C_BYP, F) of the corner where that figure is
        largest}.
    """
    f_nom = lm4651.f_sw_for(r_osc, r_dly)
    f_slow, f_fast = osc_corners(f_nom, r_dly, s["osc_tol_slow"], s["osc_tol_fast"], s["r_tolerance"])
    per = per_corner(s, np.array([f_slow]), np.array([f_fast]), np.array([l_out]), np.array([c_out]))
    out = {}
    for k in ("THD+N", "ripple", "filter Q", "inductor peak"):
        i = int(np.argmax(per[k][0]))
        out[k] = (float(per["f"][0, i]), float(per["l"][0, i]), float(per["c"][0, i]))
    return out


def figures(s: dict, r_osc, l_out, c_out, r_dly) -> dict:
    """Every figure and margin of candidates (arrays broadcast), each at its worst corner.

    Parameters
    ----------
    s : dict
        The checked ``[class_d]`` table (SI units; temperatures in C).
    r_osc : float or numpy.ndarray
        R_OSC of each candidate, ohm.
    l_out : float or numpy.ndarray
        The filter inductors' nominal L of each candidate, H.
    c_out : float or numpy.ndarray
        C_BYP, nominal, of each candidate, F.
    r_dly : float or numpy.ndarray
        R_DLY of each candidate, ohm.

    Returns
    -------
    dict
        Arrays, one entry per candidate: ``f_sw``, ``f_sw_min``, ``f_sw_max`` (nominal and corner frequencies,
        Hz), ``thd_n`` (fraction), ``ripple`` (V rms), ``band_deviation`` (dB), ``q`` (pure number),
        ``i_peak`` (A), ``p_clip`` (W, fast corner, low rail), ``supply_least`` (V: :func:`supply_least`),
        ``theta_sa_required`` (K/W), ``t_junction`` and
        ``t_junction_no_sink`` (C), ``p_dissipation`` (W), ``dead_time`` (s), ``efficiency`` (fraction);
        ``margins`` {check of :data:`CHECKS`: margin, a fraction of its limit, negative where it fails} and
        ``ok`` (bool: every margin holds).
    """
    r_osc, l_out, c_out, r_dly = np.broadcast_arrays(*(np.asarray(v, dtype=float) for v in
                                                        (r_osc, l_out, c_out, r_dly)))
    f_nom = lm4651.f_sw_for(r_osc, r_dly)
    f_slow, f_fast = osc_corners(f_nom, r_dly, s["osc_tol_slow"], s["osc_tol_fast"], s["r_tolerance"])
    per = per_corner(s, f_slow, f_fast, l_out, c_out)
    rl, v_low = s["r_load"], rails(s)[0]
    thd, ripple, q, i_pk = (per[k].max(-1) for k in ("THD+N", "ripple", "filter Q", "inductor peak"))
    dev = band_deviation_box_db(s, l_out, c_out)
    p_clip = lm4651.p_clip(f_fast, rl, v_low)
    need, tj, p_d, tj_bare = thermal(s, f_slow, f_fast)
    t_dead = lm4651.dead_time_total(r_dly * (1 - s["r_tolerance"]))  # R_DLY at its low corner
    sink = 0.0 if s["theta_sa_available"] is None else s["theta_sa_available"]
    margins = {
        "oscillator range": np.minimum(f_slow / DEV["f_min"] - 1, 1 - f_fast / DEV["f_max"]),
        "THD+N": 1 - thd / s["thd_max"], "clipping": p_clip / p_unclipped(s) - 1,
        "ripple": 1 - ripple / s["ripple_max"], "audio band": 1 - dev / s["droop_max"],
        "filter Q": 1 - q / s["q_max"], "inductor peak": 1 - i_pk / i_peak_limit(s),
        "dead time": t_dead / s["dead_time_min"] - 1,
        "heat sink": (need - sink) / (DEV["theta_jc"][s["package"]] + s["theta_cs"] + sink)}
    ok = np.ones(f_nom.shape, dtype=bool)
    for m in margins.values():
        ok &= m >= -1e-12
    return {"f_sw": f_nom, "f_sw_min": f_slow, "f_sw_max": f_fast, "thd_n": thd, "ripple": ripple,
            "band_deviation": dev, "q": q, "i_peak": i_pk, "p_clip": p_clip, "supply_least": supply_least(s, f_fast),
            "theta_sa_required": need,
            "t_junction": tj, "p_dissipation": p_d, "t_junction_no_sink": tj_bare, "dead_time": t_dead,
            "efficiency": efficiency(s, f_nom, l_out), "margins": margins, "ok": ok}


def at(fig: dict, index) -> dict:
    """One candidate's figures as plain floats (margins included).

    Parameters
    ----------
    fig : dict
        The figures of many candidates (:func:`figures`).
    index : int
        The candidate's index in those arrays.

    Returns
    -------
    dict
        The same keys with floats (SI units as in :func:`figures`), ``margins`` {check: float} and ``ok``
        (bool).
    """
    out = {k: float(v[index]) for k, v in fig.items() if k not in ("margins", "ok")}
    out["margins"] = {k: float(v[index]) for k, v in fig["margins"].items()}
    out["ok"] = bool(fig["ok"][index])
    return out


def one(s: dict, r_osc: float, l_out: float, c_out: float, r_dly: float) -> dict:
    """The figures of one design as plain floats.

    Parameters
    ----------
    s : dict
        The checked ``[class_d]`` table (SI units; temperatures in C).
    r_osc : float
        R_OSC, ohm.
    l_out : float
        The filter inductors' nominal L, H.
    c_out : float
        C_BYP, nominal, F.
    r_dly : float
        R_DLY, ohm.

    Returns
    -------
    dict
        Its figures as :func:`at` gives them (SI units; ``margins`` {check: fraction}, ``ok`` bool).
    """
    return at(figures(s, np.array([r_osc]), np.array([l_out]), np.array([c_out]), np.array([r_dly])), 0)


#: what sensitivity() switches on one at a time, from a design with every tolerance off
TOLERANCES = {
    "oscillator (eq 5 vs table)": ("osc_tol_slow", "osc_tol_fast"),
    "R_OSC, R_DLY tolerance": ("r_tolerance",),
    "inductor tolerance": ("l_tolerance",),
    "capacitor tolerance": ("c_tolerance",),
    "R_DS(on) max vs typ": ("rds_on_25",),
    "T_overmod 350 vs 310 ns": ("t_overmod",),
}
TYPICAL = {"osc_tol_slow": 0.0, "osc_tol_fast": 0.0, "r_tolerance": 0.0, "l_tolerance": 0.0, "c_tolerance": 0.0,
           "rds_on_25": 0.200, "t_overmod": DEV["t_overmod"]}


def sensitivity(s: dict, r_osc: float, l_out: float, c_out: float, r_dly: float) -> dict:
    """Margins with every tolerance at its typical value, then with each one alone at its limit, then all:
    {case: {check: margin}}; the drop from the first row is what that tolerance eats.

    Parameters
    ----------
    s : dict
        The checked ``[class_d]`` table (SI units; temperatures in C).
    r_osc : float
        R_OSC, ohm.
    l_out : float
        The filter inductors' nominal L, H.
    c_out : float
        C_BYP, nominal, F.
    r_dly : float
        R_DLY, ohm.

    Returns
    -------
    dict
        {case: {check: margin}}: the cases "typical (no tolerance)", each of :data:`TOLERANCES` alone, and
        "all at their limits"; each margin a fraction of its check's limit (negative where it fails).
    """
    cases = {"typical (no tolerance)": {**s, **TYPICAL}}
    for name, keys in TOLERANCES.items():
        cases[name] = {**s, **TYPICAL, **{k: s[k] for k in keys}}
    cases["all at their limits"] = s
    return {name: one(spec, r_osc, l_out, c_out, r_dly)["margins"] for name, spec in cases.items()}


def axes(s: dict, r_dly: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The series values searched: R_OSC whose two oscillator corners stay inside 50..225 kHz, L and C.

    Parameters
    ----------
    s : dict
        The checked ``[class_d]`` table (SI units; temperatures in C).
    r_dly : float
        R_DLY, ohm (it shifts eq 5's frequency).

    Returns
    -------
    tuple of numpy.ndarray
        (R_OSC values in ohm, within :data:`R_OSC_RANGE`; L values in H, within :data:`L_RANGE`; C_BYP values
        in F, within :data:`C_RANGE`), each sorted, from ``r_osc_series``, ``l_series`` and ``c_series``.
    """
    r = np.array(series.values(s["r_osc_series"], *R_OSC_RANGE))
    f = lm4651.f_sw_for(r, r_dly)
    with np.errstate(divide="ignore"):
        f_slow, f_fast = osc_corners(f, r_dly, s["osc_tol_slow"], s["osc_tol_fast"], s["r_tolerance"])
    keep = (f > 0) & (f_fast > 0) & (f_slow >= DEV["f_min"] * (1 - 1e-12)) & (f_fast <= DEV["f_max"] * (1 + 1e-12))
    return r[keep], np.array(series.values(s["l_series"], *L_RANGE)), np.array(series.values(s["c_series"], *C_RANGE))


def grid(s: dict, r_dly: float, f_win=None, l_win=None, c_win=None):
    """Every combination of the series values (each optionally within a window) as flat candidate arrays.

    Parameters
    ----------
    s : dict
        The checked ``[class_d]`` table (SI units; temperatures in C).
    r_dly : float
        R_DLY, ohm.
    f_win : tuple of float or None
        (low, high) nominal switching frequency, Hz: the R_OSC values kept; None: all of :func:`axes`.
    l_win : tuple of float or None
        (low, high) L, H; None: all.
    c_win : tuple of float or None
        (low, high) C_BYP, F; None: all.

    Returns
    -------
    tuple of numpy.ndarray
        (R_OSC in ohm, L in H, C_BYP in F), three flat arrays of equal length, one entry per combination.
    """
    r, l_out, c_out = axes(s, r_dly)
    f = lm4651.f_sw_for(r, r_dly)
    pick = [np.ones(len(v), dtype=bool) if w is None else (x >= w[0]) & (x <= w[1])
            for v, x, w in ((r, f, f_win), (l_out, l_out, l_win), (c_out, c_out, c_win))]
    R, L, C = np.meshgrid(r[pick[0]], l_out[pick[1]], c_out[pick[2]], indexing="ij")
    return R.ravel(), L.ravel(), C.ravel()


def pair_keys(s: dict, r_osc, l_out, r_dly):
    """(objective, the other) of (R_OSC, L) pairs, larger better: neither depends on C_BYP. The efficiency
    at p_out, and theta_SA needed at the worse oscillator corner (a larger one is a smaller heat sink).

    Parameters
    ----------
    s : dict
        The checked ``[class_d]`` table (SI units; temperatures in C).
    r_osc : float or numpy.ndarray
        R_OSC of each pair, ohm.
    l_out : float or numpy.ndarray
        L of each pair, H.
    r_dly : float
        R_DLY, ohm.

    Returns
    -------
    tuple of numpy.ndarray
        (the objective's key, the other key), each broadcast over the pairs: the efficiency (fraction) and
        the theta_SA needed (K/W), in that order when ``objective`` is "efficiency", else swapped.
    """
    f = lm4651.f_sw_for(r_osc, r_dly)
    eff = efficiency(s, f, l_out)
    f_slow, f_fast = osc_corners(f, r_dly, s["osc_tol_slow"], s["osc_tol_fast"], s["r_tolerance"])
    theta = np.minimum(heat(s, f_slow)[0], heat(s, f_fast)[0])
    theta = np.broadcast_to(theta, np.broadcast(eff, theta).shape)
    return (eff, theta) if s["objective"] == "efficiency" else (theta, eff)


def best(s: dict, r, l_out, c_out, r_dly):
    """Index of the best feasible candidate (objective, then the other, then the smaller L and C), or None.

    Parameters
    ----------
    s : dict
        The checked ``[class_d]`` table (SI units; temperatures in C).
    r : numpy.ndarray
        R_OSC of each candidate, ohm (a flat array).
    l_out : numpy.ndarray
        L of each candidate, H.
    c_out : numpy.ndarray
        C_BYP of each candidate, F.
    r_dly : float
        R_DLY, ohm.

    Returns
    -------
    tuple
        (index of the best candidate meeting every check, or None when none does; every candidate's
        :func:`figures`).
    """
    fig = figures(s, r, l_out, c_out, r_dly)
    ok = np.flatnonzero(fig["ok"])
    if not ok.size:
        return None, fig
    first, second = pair_keys(s, r[ok], l_out[ok], r_dly)
    return ok[np.lexsort((c_out[ok], l_out[ok], -second, -first))[0]], fig
