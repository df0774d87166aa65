"""R7 and R9 of the op-amp current limiter (AN94002 figure 3): every board's trip current between two limits.

Problem (x = ln R7, ln R9): minimise ln R7 (the least loss) subject to
  I_trip,min = V_cs,min(R9) / (R7 (1 + t7)) >= i_no_trip
  I_trip,max = V_cs,max(R9) / (R7 (1 - t7)) <= i_must_trip
with V_cs,min/max the tolerance corners (:func:`vcs_extremes`). solve (IPOPT on the relaxation) -> snap
(walk the R7 series up from the relaxed optimum, the best series R9 for each) -> verify -> Result.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import casadi as ca
import numpy as np

from ..core import series
from ..sources.an94002 import circuit as an94002
from .common import Result, completed, ordered
from .solvers import Infeasible, minimise

TABLE = "current_limiter"


@dataclass(frozen=True)
class LimiterResult(Result):
    r7: float
    r9: float
    i_trip_min: float
    i_trip_max: float
    i_trip_nominal: float
    p_r7: float
    binding: str
    relaxed_binding: tuple
    margin_low: float
    margin_high: float
    r7_relaxed: float
    r9_relaxed: float
    v_cs_nominal: float

    table = TABLE


def checked(spec: dict | None) -> dict:
    s = completed(TABLE, spec)
    ordered(TABLE, "i_no_trip", "i_must_trip", s, "A")
    ordered(TABLE, "r7_min", "r7_max", s, "ohm")
    ordered(TABLE, "r9_min", "r9_max", s, "ohm")
    return s


def zener_range(s: dict) -> tuple[float, float]:
    drift = s["zener_tc"] * s["temp_span"]
    return s["zener_voltage"] * (1 - s["zener_tolerance"]) - drift, s["zener_voltage"] * (1 + s["zener_tolerance"]) + drift


def vcs_extremes(r9, s: dict):
    """Lowest and highest trip voltage over every tolerance corner, in closed form.

    V_cs = V_D1 - (1 + R12/R13) (V_D1 B + V_os), B = R11 / (R9 + R10 + R11). Whatever V_D1 is, V_cs
    rises with R9, R10 and R13 and falls with R11, R12 and V_os (because V_D1 B + V_os > 0), so the
    high corner of the resistors and offset is (R9+, R10+, R11-, R12-, R13+, V_os-) and the low corner
    its mirror image. V_cs is linear in V_D1 with slope 1 - B/A, whose sign depends on the design, so
    both zener ends are evaluated. The unit tests check this against all 128 corners. Works on numpy
    arrays and casadi symbols.
    """
    t = s["resistor_tolerance"]
    vz_lo, vz_hi = zener_range(s)
    lo_, hi_ = 1 - t, 1 + t

    def vcs(vz, r9_, r10, r11, r12, r13, vos):
        return vz - (1 + r12 / r13) * (vz * r11 / (r9_ + r10 + r11) + vos)

    high_r = (r9 * hi_, s["r10"] * hi_, s["r11"] * lo_, s["r12"] * lo_, s["r13"] * hi_, -s["offset"])
    low_r = (r9 * lo_, s["r10"] * lo_, s["r11"] * hi_, s["r12"] * hi_, s["r13"] * lo_, s["offset"])
    symbolic = isinstance(r9, (ca.SX, ca.MX))
    fmax, fmin = (ca.fmax, ca.fmin) if symbolic else (np.maximum, np.minimum)
    high = fmax(vcs(vz_hi, *high_r), vcs(vz_lo, *high_r))
    low = fmin(vcs(vz_lo, *low_r), vcs(vz_hi, *low_r))
    return low, high


def trip_currents(r7, r9, s: dict):
    """(lowest, highest) trip current with R7's tolerance too."""
    low, high = vcs_extremes(r9, s)
    return low / (r7 * (1 + s["r7_tolerance"])), high / (r7 * (1 - s["r7_tolerance"]))


def limiter_margins(r7, r9, s: dict):
    """Relative margins to the two limits (both >= 0 when the design meets the spec)."""
    i_lo, i_hi = trip_currents(r7, r9, s)
    return i_lo / s["i_no_trip"] - 1, 1 - i_hi / s["i_must_trip"]


def _best_r9(r7: float, r9s: np.ndarray, s: dict):
    m_lo, m_hi = limiter_margins(r7, r9s, s)
    worst = np.minimum(m_lo, m_hi)
    ok = worst >= -1e-12
    if not ok.any():
        return None
    i = int(np.argmax(np.where(ok, worst, -np.inf)))
    return float(r9s[i]), float(worst[i])


def enumerate_series(spec: dict):
    """Exhaustive search over both series: (r7, r9) or None. Used by the tests and the benchmark."""
    s = checked(spec)
    r9s = np.array(series.values(s["r9_series"], s["r9_min"], s["r9_max"]))
    for r7 in series.values(s["r7_series"], s["r7_min"], s["r7_max"]):
        best = _best_r9(r7, r9s, s)
        if best:
            return r7, best[0]
    return None


def narrowest_window(s: dict) -> float:
    """The smallest i_must_trip / i_no_trip any R9 of the range allows (at the largest R9)."""
    low, high = vcs_extremes(np.array([s["r9_max"]]), s)
    return float(high[0] / low[0] * (1 + s["r7_tolerance"]) / (1 - s["r7_tolerance"]))


def _snap(s: dict, r7_relaxed: float, r9s: np.ndarray, ratio_needed: float):
    """The smallest series R7 from the relaxed optimum up that has a feasible series R9, with that R9."""
    start = series.at_most(s["r7_series"], max(r7_relaxed * (1 - 1e-6), s["r7_min"]))
    for r7_c in series.values(s["r7_series"], start, s["r7_max"]):
        if r7_c < s["r7_min"]:
            continue
        best = _best_r9(r7_c, r9s, s)
        if best:
            return r7_c, best[0]
    raise Infeasible(TABLE, f"no {s['r7_series']} R7 in {s['r7_min']:g}..{s['r7_max']:g} ohm with an "
                     f"{s['r9_series']} R9 meets {s['i_no_trip']:g}..{s['i_must_trip']:g} A",
                     {"narrowest_ratio": ratio_needed, "r7_relaxed": r7_relaxed})


def design(spec: dict | None = None) -> LimiterResult:
    """Smallest R7 (least loss), then the R9 with the largest smaller margin to the two limits.

    The relaxation's R7 is a lower bound on every series design; the series search starts there and walks
    up, taking for each R7 the best series R9 (all of them are checked: the line search is exact).
    """
    s = checked(spec)
    ratio_needed = narrowest_window(s)
    if s["i_must_trip"] / s["i_no_trip"] < ratio_needed:
        raise Infeasible(
            TABLE,
            f"no R7/R9 keeps the trip current between {s['i_no_trip']:g} A and {s['i_must_trip']:g} A at every "
            f"tolerance corner: the narrowest window these tolerances allow is i_must_trip / i_no_trip >= "
            f"{ratio_needed:.3g} (for i_no_trip = {s['i_no_trip']:g} A, i_must_trip >= "
            f"{ratio_needed * s['i_no_trip']:.3g} A)",
            {"narrowest_ratio": ratio_needed, "i_must_trip_min": ratio_needed * s["i_no_trip"]})
    x = ca.SX.sym("x", 2)
    i_lo, i_hi = trip_currents(ca.exp(x[0]), ca.exp(x[1]), s)
    x0 = [math.log(math.sqrt(s["r7_min"] * s["r7_max"])), math.log(s["r9_max"] / 10)]
    sol = minimise(x[0], x, [
        ("i_no_trip", i_lo / s["i_no_trip"], 1.0, ca.inf),
        ("i_must_trip", i_hi / s["i_must_trip"], -ca.inf, 1.0),
    ], x0=x0, lbx=[math.log(s["r7_min"]), math.log(s["r9_min"])], ubx=[math.log(s["r7_max"]), math.log(s["r9_max"])])
    r7_relaxed = math.exp(sol.x[0]) if sol.success else s["r7_min"]
    r9s = np.array(series.values(s["r9_series"], s["r9_min"], s["r9_max"]))
    r7_c, r9_c = _snap(s, r7_relaxed, r9s, ratio_needed)
    i_lo_c, i_hi_c = trip_currents(r7_c, r9_c, s)
    m_lo, m_hi = limiter_margins(r7_c, r9_c, s)
    v_nominal = an94002.v_cs_trip(s["zener_voltage"], r9_c, s["r10"], s["r11"], s["r12"], s["r13"])
    return LimiterResult(
        spec=s, r7=r7_c, r9=r9_c, i_trip_min=float(i_lo_c), i_trip_max=float(i_hi_c),
        i_trip_nominal=float(v_nominal / r7_c), p_r7=s["i_no_trip"] ** 2 * r7_c,
        binding="i_no_trip (lowest trip current)" if m_lo <= m_hi else "i_must_trip (highest trip current)",
        relaxed_binding=tuple(sol.binding()), margin_low=float(m_lo), margin_high=float(m_hi),
        r7_relaxed=r7_relaxed, r9_relaxed=math.exp(sol.x[1]), v_cs_nominal=float(v_nominal))


def monte_carlo_trip(r7: float, r9: float, s: dict, n: int = 100_000, seed: int = 1) -> dict:
    """Trip currents of ``n`` boards, every part uniform within its tolerance (fixed seed, vectorised)."""
    s = checked(s)
    rng = np.random.default_rng(seed)
    t = s["resistor_tolerance"]

    def u(x, tol):
        return x * (1 + rng.uniform(-tol, tol, n))

    vz_lo, vz_hi = zener_range(s)
    vz = rng.uniform(vz_lo, vz_hi, n)
    v = an94002.v_cs_trip(vz, u(r9, t), u(s["r10"], t), u(s["r11"], t), u(s["r12"], t), u(s["r13"], t),
                          rng.uniform(-s["offset"], s["offset"], n))
    i = v / u(r7, s["r7_tolerance"])
    ok = (i >= s["i_no_trip"]) & (i <= s["i_must_trip"])
    return {"yield": float(ok.mean()), "i_p001": float(np.quantile(i, 0.001)),
            "i_p999": float(np.quantile(i, 0.999)), "i_min": float(i.min()), "i_max": float(i.max()), "samples": i}
