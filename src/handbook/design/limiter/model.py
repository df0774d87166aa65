"""The op-amp current limiter (AN94002 figure 3) as a network: trip voltage and input headroom at every
tolerance corner, exactly, for numpy arrays and casadi symbols alike.

Node equations (AN94002 eq 11 and 12, with the op-amp's offset V_os and input bias currents I_+, I_- added;
Z = V_s - V_D1 is the zener's low end, the sense point sits at V_s - V_cs):

    V_+ = Z + (V_D1 - V_cs) R13 / (R12 + R13) + I_+ (R12 || R13)
    V_- = Z + V_D1 R11 / (R9 + R10 + R11)     + I_- ((R9 + R10) || R11)

and the op-amp trips at V_+ - V_- = V_os, so with 1/A = 1 + R12/R13 and B = R11 / (R9 + R10 + R11):

    V_cs = V_D1 (1 - B/A) + I_+ R12 - (I_- R_m + V_os) / A,    R_m = (R9 + R10) || R11

The bias currents of an op-amp's two inputs flow the same way (out of the LM358's PNP inputs). As op-amp
datasheets define them, the input bias current is the average of the two inputs' currents and the input
offset current their difference: (I_+ + I_-)/2 in [-I_b, I_b] and |I_+ - I_-| <= I_os (either sign, so other
input stages are covered too), so either input alone may carry up to I_b + I_os/2. The extremes of
a I_+ - b I_- (a = R12, b = R_m/A, both positive) over that parallelogram lie at its vertices:
+-(|a - b| I_b + (a + b) I_os / 2). Treating the two currents as independent instead (+-(a + b) I_b) would
charge a design for an error that cancels when the two inputs see equal resistances, and push every divider
to its smallest resistance.

Why the corners are exact (:func:`corner_proof` checks it with sympy): V_cs, both headrooms and the trip
current V_cs / R7 are, in each quantity separately, a ratio of two polynomials of degree at most one whose
denominator is a sum of positive resistances. Such a function is monotone in that quantity over any
interval, so its extremes over the whole tolerance box lie at a vertex of the box, and enumerating every
vertex finds them (for the two bias currents, the vertices of their parallelogram). Here V_D1 takes both ends;
V_os and the bias currents enter linearly, so their worst values are written directly (above); the five
resistors take all their combinations. No direction of any resistor is assumed: the earlier closed form fixed the high corner at
(R12-, R13+), which is wrong once V_D1 B + V_os < 0 and let an unsafe design through.
"""
from __future__ import annotations

import functools
import itertools
from collections.abc import Mapping

import numpy as np

from ...core import InputError, series
from ..common import Table, checked_table, completed, is_checked, ordered

#: the divider resistors, in the order of every tuple here
DIVIDER = ("r9", "r10", "r11", "r12", "r13")
#: R9 and R10 enter every expression only through their sum S = R9 + R10, whose extremes over the two
#: parts' tolerances are S (1 +- t) (both at the same end); so the resistor corners are those of
#: (S, R11, R12, R13): 2^4, not 2^5 (the oracle in the tests still enumerates all of them)
CORNERS = tuple(itertools.product((-1, 1), repeat=4))
TABLE = "current_limiter"
#: every resistor the design chooses, R7 first
RESISTORS = ("r7",) + DIVIDER


def zener_range(s: dict) -> tuple[float, float]:
    """Lowest and highest zener voltage: tolerance plus drift over the temperature span.

    Parameters
    ----------
    s : Mapping
        The checked ``[current_limiter]`` table (SI units); ``zener_voltage`` (V), ``zener_tolerance`` (fraction),
        ``zener_tc`` (V/K) and ``temp_span`` (K) are read (casadi symbols in the search's relaxation).

    Returns
    -------
    tuple of float
        (lowest, highest) V_D1, V: ``zener_voltage`` (1 -+ ``zener_tolerance``) -+ ``zener_tc`` ``temp_span``.
    """
    drift = s["zener_tc"] * s["temp_span"]
    vz = s["zener_voltage"]
    return vz * (1 - s["zener_tolerance"]) - drift, vz * (1 + s["zener_tolerance"]) + drift


def _corner(r, signs, t):
    """(S, R11, R12, R13) at one corner, S = R9 + R10."""
    return tuple(x * (1 + t * g) for x, g in zip((r[0] + r[1], *r[2:]), signs))


def trip_voltage_corners(r, s: dict, relaxed: bool = False) -> tuple[list, list]:
    """(lows, highs): V_cs at its lowest and highest for each of the 16 resistor corners and both zener
    ends (32 each), the offset and both bias currents at their worst. ``r`` = (R9, R10, R11, R12, R13),
    floats, numpy arrays or casadi symbols. The lowest trip voltage is min(lows), the highest max(highs).

    ``relaxed`` (the smooth form the solver gets, the same feasible set): only the lowest zener voltage in
    ``lows`` and the highest in ``highs`` (the others matter only where 1 - B/A <= 0, where V_cs is negative
    at that corner, which the lower trip limit refuses anyway), and the bias error's |a - b| I_b +
    (a + b) I_os / 2 written as the larger of its two smooth branches, a (I_b + I_os/2) - b (I_b - I_os/2) and
    b (I_b + I_os/2) - a (I_b - I_os/2), each its own entry (a bound on a maximum is a bound on each branch).

    Parameters
    ----------
    r : tuple
        (R9, R10, R11, R12, R13), ohm: floats, numpy arrays (broadcast together) or casadi symbols.
    s : Mapping
        The checked ``[current_limiter]`` table (SI units): the zener's, the op-amp's (``offset``, V;
        ``input_bias``, ``input_offset_current``, A) and ``resistor_tolerance`` (fraction) are read. The
        search's relaxation passes a mapping of casadi symbols instead.
    relaxed : bool
        False: every corner exactly, both zener ends. True: the solver's smooth form described above.

    Returns
    -------
    tuple of list
        (lows, highs): the trip voltage V_cs at its lowest and at its highest, V, 32 entries each, each entry a
        float, numpy array or casadi expression like ``r``. Not relaxed: for each of the 16 corners of :data:`CORNERS`,
        the lowest then the highest zener voltage; relaxed: for each corner, the two branches of the bias error.
    """
    vz_lo, vz_hi = zener_range(s)
    ib, off, t = s["input_bias"], s["offset"], s["resistor_tolerance"]
    ios = s["input_offset_current"]
    lows, highs = [], []
    for signs in CORNERS:
        s910, r11, r12, r13 = _corner(r, signs, t)
        inv_a = 1 + r12 / r13
        b = r11 / (s910 + r11)
        r_m = s910 * b
        k = 1 - b * inv_a
        a_p, a_m = r12, r_m * inv_a
        if relaxed:
            for err in (a_p * (ib + ios / 2) - a_m * (ib - ios / 2), a_m * (ib + ios / 2) - a_p * (ib - ios / 2)):
                lows.append(vz_lo * k - off * inv_a - err)
                highs.append(vz_hi * k + off * inv_a + err)
            continue
        err = off * inv_a + bias_error(a_p, a_m, ib, ios)
        for vz in (vz_lo, vz_hi):
            lows.append(vz * k - err)
            highs.append(vz * k + err)
    return lows, highs


def bias_error(a, b, ib: float, ios: float):
    """The largest |a I_+ - b I_-| over the bias currents' parallelogram (a, b > 0; average within +-I_b, difference
    within +-I_os): |a - b| I_b + (a + b) I_os / 2.
    Floats, numpy arrays or casadi symbols (abs is casadi's fabs).

    Parameters
    ----------
    a : float or numpy.ndarray or casadi.SX
        The factor of I_+ in the trip voltage, ohm (R12), positive.
    b : float or numpy.ndarray or casadi.SX
        The factor of I_- in the trip voltage, ohm (R_m / A = ((R9 + R10) || R11) (1 + R12 / R13)), positive.
    ib : float
        The largest input bias current I_b (the two inputs' average), A.
    ios : float
        The largest input offset current I_os (their difference), A.

    Returns
    -------
    float or numpy.ndarray or casadi.SX
        The largest |a I_+ - b I_-|, V, broadcast over ``a`` and ``b``.
    """
    return abs(a - b) * ib + (a + b) / 2 * ios


def divider_current(r, s: dict):
    """The most current both dividers draw from the zener node: the highest zener voltage over the smallest
    resistances (R9 + R10 + R11 and R12 + R13 at their lower tolerance ends; decreasing in each).

    Parameters
    ----------
    r : tuple
        (R9, R10, R11, R12, R13), ohm: floats, numpy arrays (broadcast together) or casadi symbols.
    s : Mapping
        The checked ``[current_limiter]`` table (SI units); the zener's keys and ``resistor_tolerance``
        (fraction) are read.

    Returns
    -------
    float or numpy.ndarray or casadi.SX
        The two dividers' current together, A: V_D1,max / ((R9 + R10 + R11) (1 - t)) + V_D1,max / ((R12 + R13)
        (1 - t)), t = ``resistor_tolerance``.
    """
    _, vz_hi = zener_range(s)
    r9, r10, r11, r12, r13 = r
    return vz_hi / ((r9 + r10 + r11) * (1 - s["resistor_tolerance"])) + vz_hi / ((r12 + r13) * (1 - s["resistor_tolerance"]))


def headroom_corners(r, s: dict) -> list:
    """How far each op-amp input sits below the supply, at every corner (V_cs = 0 for V_+, where it is
    nearest the supply; V_- does not depend on V_cs): 4 corners of (R12, R13), 4 of (R9 + R10, R11), the
    lowest zener voltage and the bias current pushing each input up (one input's current is at most
    I_b + I_os / 2: the average within I_b, the difference within I_os).

    Parameters
    ----------
    r : tuple
        (R9, R10, R11, R12, R13), ohm: floats, numpy arrays (broadcast together) or casadi symbols.
    s : Mapping
        The checked ``[current_limiter]`` table (SI units); the zener's keys, ``input_bias`` and
        ``input_offset_current`` (A) and ``resistor_tolerance`` (fraction) are read.

    Returns
    -------
    list
        Eight headrooms, V (floats, numpy arrays or casadi expressions like ``r``): the first four of V_+ at the
        (R12, R13) corners (-, -), (-, +), (+, -), (+, +), the last four of V_- at the (R9 + R10, R11) corners
        in the same order. The least headroom is their minimum.
    """
    vz_lo, _ = zener_range(s)
    ib, t = s["input_bias"] + s["input_offset_current"] / 2, s["resistor_tolerance"]  # one input's most
    r9, r10, r11, r12, r13 = r
    out = []
    for g12, g13 in itertools.product((-1, 1), repeat=2):
        a12, a13 = r12 * (1 + t * g12), r13 * (1 + t * g13)
        out.append((vz_lo * a12 - ib * a12 * a13) / (a12 + a13))
    for g9, g11 in itertools.product((-1, 1), repeat=2):  # R9 + R10 as one (see CORNERS)
        upper, a11 = (r9 + r10) * (1 + t * g9), r11 * (1 + t * g11)
        out.append(upper * (vz_lo - ib * a11) / (upper + a11))
    return out


def margins(low, high, r7, s: dict) -> tuple:
    """The margins of trip voltages ``low`` and ``high`` (one corner's, or arrays of them) against the window:
    (low / (R7 (1 + t7)) / i_no_trip - 1, 1 - high / (R7 (1 - t7)) / i_must_trip), R7 at the end of its
    tolerance that is worst for a positive voltage (:func:`current_margins` of those currents: the one place the
    margin is written; :func:`verify` takes it at the worst corners, the search's bounds and relaxation corner by
    corner; numpy, floats or casadi).

    Parameters
    ----------
    low : float or numpy.ndarray or casadi.SX
        The lowest trip voltage V_cs (of one corner, or of many), V.
    high : float or numpy.ndarray or casadi.SX
        The highest trip voltage V_cs (of one corner, or of many), V.
    r7 : float or numpy.ndarray or casadi.SX
        The sense resistor R7, nominal, ohm.
    s : Mapping
        The checked ``[current_limiter]`` table (SI units); ``r7_tolerance`` (fraction), ``i_no_trip`` and
        ``i_must_trip`` (A) are read.

    Returns
    -------
    tuple
        (margin above ``i_no_trip``, margin below ``i_must_trip``), fractions of each limit (positive: inside the
        window), broadcast over the arguments.
    """
    # current_margins(low / (R7 (1 + t7)), high / (R7 (1 - t7))), with R7 folded into one divisor: the form the
    # search's relaxation and bounds have always used (a reordered division moves IPOPT's path)
    return (low / (r7 * (1 + s["r7_tolerance"]) * s["i_no_trip"]) - 1,
            1 - high / (r7 * (1 - s["r7_tolerance"]) * s["i_must_trip"]))


def current_margins(i_low, i_high, s: dict) -> tuple:
    """The margins of trip currents against the window: (i_low / i_no_trip - 1, 1 - i_high / i_must_trip).

    Parameters
    ----------
    i_low, i_high : float or numpy.ndarray or casadi.SX
        The lowest and highest trip current, A.
    s : Mapping
        The checked ``[current_limiter]`` table; ``i_no_trip`` and ``i_must_trip`` (A) are read.

    Returns
    -------
    tuple
        (margin above ``i_no_trip``, margin below ``i_must_trip``), fractions of each limit.
    """
    return i_low / s["i_no_trip"] - 1, 1 - i_high / s["i_must_trip"]


def trip_currents(r7, r, s: dict):
    """(lowest, highest) trip current over every corner, R7's tolerance included (numpy or floats); a
    negative trip voltage (a network that trips with no current) divides by the smallest R7.

    Parameters
    ----------
    r7 : float or numpy.ndarray
        The sense resistor R7, nominal, ohm.
    r : tuple
        (R9, R10, R11, R12, R13), ohm: floats or numpy arrays (broadcast together with ``r7``).
    s : Mapping
        The checked ``[current_limiter]`` table (SI units).

    Returns
    -------
    tuple of numpy.ndarray
        (lowest, highest) trip current over every corner, A (0-d arrays for one network).
    """
    import numpy as np
    lows, highs = trip_voltage_corners(r, s)
    low, high = np.min(np.stack(lows), axis=0), np.max(np.stack(highs), axis=0)
    r_lo, r_hi = r7 * (1 - s["r7_tolerance"]), r7 * (1 + s["r7_tolerance"])
    return np.where(low > 0, low / r_hi, low / r_lo), np.where(high > 0, high / r_lo, high / r_hi)


def verify(r7, r, s: dict) -> dict:
    """Every figure of one network (or of arrays of networks) at its exact worst corners.

    Parameters
    ----------
    r7 : float or numpy.ndarray
        The sense resistor R7, nominal, ohm.
    r : tuple
        (R9, R10, R11, R12, R13), ohm: floats or numpy arrays (broadcast together with ``r7``).
    s : Mapping
        The checked ``[current_limiter]`` table (SI units).

    Returns
    -------
    dict
        numpy arrays (0-d for one network): "i_trip_min" and "i_trip_max", the lowest and highest trip current
        over every corner, A; "margin_low" and "margin_high", the margins above ``i_no_trip`` and below
        ``i_must_trip``, fractions; "headroom_min", the least headroom of either op-amp input, V;
        "divider_current", the most current the dividers draw from the zener node, A; "ok", bool: both margins
        at least ``min_margin``, the headroom at least ``input_headroom``, a positive lowest trip current and the
        divider current at most ``divider_current_max``.
    """
    import numpy as np
    i_lo, i_hi = trip_currents(r7, r, s)
    m_lo, m_hi = current_margins(i_lo, i_hi, s)  # the worst trip currents (a negative V_cs takes R7's other end)
    headroom = np.min(np.stack(headroom_corners(r, s)), axis=0)
    i_div = divider_current(r, s)
    ok = ((np.minimum(m_lo, m_hi) >= s["min_margin"] - 1e-12) & (headroom >= s["input_headroom"] - 1e-12) & (i_lo > 0)
          & (i_div <= s["divider_current_max"] * (1 + 1e-12)))
    return {"i_trip_min": i_lo, "i_trip_max": i_hi, "margin_low": m_lo, "margin_high": m_hi,
            "headroom_min": headroom, "divider_current": i_div, "ok": ok}


def corner_proof() -> dict:
    """sympy, once per process: {(expression, quantity): (degree of the numerator, of the denominator, denominator a
    sum of positive terms)} for V_cs, the trip current and both headrooms. All degrees at most 1 and positive
    denominators: each is monotone in each quantity over the tolerance box, so the extremes lie at its vertices
    (the module's docstring).

    Returns
    -------
    dict
        {(expression, quantity): (int, int, bool)}: the expression ("V_cs", "I_trip", "headroom_plus" or
        "headroom_minus"), a quantity it contains ("R7", "R9" .. "R13", "V_D1", "V_os", "I_p" or "I_m"), and
        the degree in that quantity of the expression's numerator and of its denominator, and whether the
        denominator's coefficients (as a polynomial in R7, R9 .. R13) are all positive.
    """
    return dict(_corner_proof())


@functools.cache
def _corner_proof() -> dict:
    import sympy as sp

    r7, r9, r10, r11, r12, r13 = sp.symbols("R7 R9 R10 R11 R12 R13", positive=True)
    vd1, vcs, vos, ip, im, z = sp.symbols("V_D1 V_cs V_os I_p I_m Z", real=True)
    v_plus = z + (vd1 - vcs) * r13 / (r12 + r13) + ip * r12 * r13 / (r12 + r13)
    v_minus = z + vd1 * r11 / (r9 + r10 + r11) + im * (r9 + r10) * r11 / (r9 + r10 + r11)
    trip = sp.solve(sp.Eq(v_plus - v_minus, vos), vcs)[0]
    exprs = {"V_cs": trip, "I_trip": trip / r7,
             "headroom_plus": sp.together((z + vd1) - v_plus.subs(vcs, 0)),
             "headroom_minus": sp.together((z + vd1) - v_minus)}
    out = {}
    for name, e in exprs.items():
        num, den = sp.fraction(sp.together(sp.expand(e)))
        positive = all(c > 0 for c in sp.Poly(sp.expand(den), r7, r9, r10, r11, r12, r13).coeffs())
        for q in (r7, r9, r10, r11, r12, r13, vd1, vos, ip, im):
            if e.has(q):
                out[(name, str(q))] = (sp.degree(num, q), sp.degree(den, q), positive)
    return out


def checked(spec: Mapping | None) -> Table:
    """The ``[current_limiter]`` table checked: defaults filled in, every value in range, and the table's own
    contradictions ruled out (the trip window, each resistor's range, room for ``min_margin``).

    Parameters
    ----------
    spec : Mapping or None
        The keys given, {key: value}, SI units (A, V, ohm, fractions); None: every default. A checked
        ``[current_limiter]`` :class:`~handbook.design.common.Table` is returned as it is.

    Returns
    -------
    Table
        Every key of the table, checked, SI units.

    Raises
    ------
    InputError
        For an unknown key or a value of the wrong type or out of range; when ``i_no_trip`` is not below
        ``i_must_trip``, a resistor's ``_min`` is above its ``_max`` or a free resistor's range holds no value of
        its series; and when ``i_no_trip`` (1 + ``min_margin``) is not below ``i_must_trip`` (1 - ``min_margin``).
    """
    if is_checked(TABLE, spec):  # checked once, where it was read
        return spec
    s = completed(TABLE, spec)
    ordered(TABLE, "i_no_trip", "i_must_trip", s, "A")
    for name in RESISTORS:
        ordered(TABLE, f"{name}_min", f"{name}_max", s, "ohm", strict=False)
    for name in RESISTORS:  # a range holding no series value is bad input, found before any solver
        choices(s, name)
    if s["i_no_trip"] * (1 + s["min_margin"]) >= s["i_must_trip"] * (1 - s["min_margin"]):
        raise InputError(f"{TABLE}.min_margin = {s['min_margin']:g} leaves no room between i_no_trip = "
                         f"{s['i_no_trip']:g} A and i_must_trip = {s['i_must_trip']:g} A: use a smaller margin")
    return checked_table(TABLE, s)


def choices(s: dict, name: str) -> np.ndarray:
    """The values a resistor may take: its pinned value, or its series within its range.

    Parameters
    ----------
    s : Mapping
        The ``[current_limiter]`` table (SI units); ``name``, ``name_series``, ``name_min`` and ``name_max``
        are read.
    name : str
        The resistor: "r7", "r9", "r10", "r11", "r12" or "r13".

    Returns
    -------
    numpy.ndarray
        Its values, ohm, ascending: the pinned value alone, or every value of its series in its range.

    Raises
    ------
    InputError
        When the resistor is not pinned and its range holds no value of its series.
    """
    if s[name] is not None:
        return np.array([float(s[name])])
    values = series.values(s[f"{name}_series"], s[f"{name}_min"], s[f"{name}_max"])
    if not values:
        name_series = s[f"{name}_series"]
        below, above = series.at_most(name_series, s[f"{name}_min"]), series.at_least(name_series, s[f"{name}_max"])
        raise InputError(f"{TABLE}.{name}_min = {s[name + '_min']:g} ohm .. {TABLE}.{name}_max = {s[name + '_max']:g} ohm "
                         f"holds no {s[name + '_series']} value: widen it to include {below:g} or {above:g} ohm")
    return np.array(values)


def scores(r7: float, r: np.ndarray, s: dict) -> np.ndarray:
    """Exact worst margin of each network (rows of R9..R13) with this R7; -inf where a headroom fails.

    Parameters
    ----------
    r7 : float
        The sense resistor R7, nominal, ohm.
    r : numpy.ndarray
        Networks, shape (n, 5): one row (R9, R10, R11, R12, R13) per network, ohm.
    s : Mapping
        The checked ``[current_limiter]`` table (SI units).

    Returns
    -------
    numpy.ndarray
        Shape (n,): each network's worst margin, min(margin above ``i_no_trip``, margin below ``i_must_trip``),
        a fraction (``min_margin`` is not applied); -inf where the least headroom is below ``input_headroom``,
        the lowest trip current is not positive or the divider current is above ``divider_current_max``.
    """
    v = verify(r7, tuple(r.T), s)
    worst = np.minimum(v["margin_low"], v["margin_high"])
    ok = ((v["headroom_min"] >= s["input_headroom"] - 1e-12) & (v["i_trip_min"] > 0)
          & (v["divider_current"] <= s["divider_current_max"] * (1 + 1e-12)))
    return np.where(ok, worst, -np.inf)


def best_headroom(s: dict) -> float:
    """The largest least headroom any network of the ranges (or pins) allows: both inputs, worst corner.

    Parameters
    ----------
    s : Mapping
        The ``[current_limiter]`` table (SI units); each divider resistor's pin or series range is used.

    Returns
    -------
    float
        The largest least headroom, V: the smaller of the two inputs' best, each the best over its resistors'
        range ends (or pins).

    Raises
    ------
    InputError
        When a free divider resistor's range holds no value of its series (:func:`choices`).
    """
    ends = [(v[0], v[-1]) for v in (choices(s, n) for n in DIVIDER)]
    best_plus = max(min(headroom_corners((1, 1, 1, r12, r13), s)[:4]) for r12, r13 in itertools.product(*ends[3:]))
    best_minus = max(min(headroom_corners((r9, r10, r11, 1, 1), s)[4:])
                     for r9, r10, r11 in itertools.product(*ends[:3]))
    return float(min(best_plus, best_minus))
