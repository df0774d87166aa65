"""CAP-CD (and CAP-DC) for the TDA5143/TDA5144's adaptive commutation delay.

Problem: the smallest series capacitor whose worst-case swing at ``rpm_min`` (largest current, smallest
capacitor) fits the window, and whose worst-case swing at ``rpm_max`` (smallest current, largest
capacitor) stays above the noise floor. solve (IPOPT on the continuous relaxation) -> snap (series) ->
verify (both swings at the chosen value) -> :class:`CommutationResult`.
"""
from __future__ import annotations

from dataclasses import dataclass

import casadi as ca

from ..core import InputError, series
from ..sources.an94002 import circuit as an94002
from .common import Result, completed, ordered
from .solvers import Infeasible, minimise

TABLE = "commutation"

BINDING = {
    "window": "swing at rpm_min fits the window (largest current, smallest capacitor)",
    "noise": "swing at rpm_max stays above the noise floor (smallest current, largest capacitor)",
}


@dataclass(frozen=True)
class CommutationResult(Result):
    cap_cd: float
    cap_dc: float
    rpm_min_reliable: float
    rpm_max_reliable: float
    binding: str
    continuous_optimum: float
    noise_margin: float
    swing_at_rpm_min: float
    swing_at_rpm_max: float
    next_smaller: float
    next_smaller_fails: str

    table = TABLE


def checked(spec: dict | None) -> dict:
    s = completed(TABLE, spec)
    ordered(TABLE, "rpm_min", "rpm_max", s, "rpm")
    ordered(TABLE, "i_charge_min", "i_charge_max", s, "A", strict=False)
    if s["min_excursion"] >= s["window"]:
        raise InputError(f"commutation.min_excursion = {s['min_excursion']:g} V must be below "
                         f"commutation.window = {s['window']:g} V")
    return s


def bounds(s: dict) -> tuple[float, float]:
    """(smallest C meeting the window at rpm_min, largest C meeting the noise floor at rpm_max), in F."""
    n, tol = s["pole_pairs"], s["tolerance"]
    c_low = s["i_charge_max"] * an94002.t_com(s["rpm_min"], n) / (s["window"] * (1 - tol))
    c_high = s["i_charge_min"] * an94002.t_com(s["rpm_max"], n) / (s["min_excursion"] * (1 + tol))
    return c_low, c_high


def verify(c: float, s: dict) -> dict:
    """Independent check of one capacitor value: both worst-case swings and the speeds it supports."""
    n, tol = s["pole_pairs"], s["tolerance"]
    swing_slow = an94002.excursion(c * (1 - tol), s["rpm_min"], n, s["i_charge_max"])
    swing_fast = an94002.excursion(c * (1 + tol), s["rpm_max"], n, s["i_charge_min"])
    lo, hi = an94002.reliable_speed_range(c, tol, n, s["i_charge_min"], s["i_charge_max"], s["window"],
                                          s["min_excursion"])
    return {
        "swing_at_rpm_min": swing_slow, "swing_at_rpm_max": swing_fast,
        "window_ok": swing_slow <= s["window"] * (1 + 1e-12),
        "noise_ok": swing_fast >= s["min_excursion"] * (1 - 1e-12),
        "rpm_min_reliable": lo, "rpm_max_reliable": hi,
    }


def solve(s: dict):
    """The continuous relaxation (C in nF): minimise C subject to both swing constraints."""
    n, tol = s["pole_pairs"], s["tolerance"]
    t_slow, t_fast = an94002.t_com(s["rpm_min"], n), an94002.t_com(s["rpm_max"], n)
    c_low, _ = bounds(s)
    x = ca.SX.sym("c_nF")
    c = x * 1e-9
    return minimise(x, x, [
        ("window", s["i_charge_max"] * t_slow / (c * (1 - tol)) / s["window"], -ca.inf, 1.0),
        ("noise", s["i_charge_min"] * t_fast / (c * (1 + tol)) / s["min_excursion"], 1.0, ca.inf),
    ], x0=[max(c_low, 1e-12) * 1e9 * 1.5], lbx=[1e-3], ubx=[1e9])


def design(spec: dict | None = None) -> CommutationResult:
    """Smallest series CAP-CD whose swing fits the window at rpm_min; verified against the noise floor.

    The smallest C maximises the margin of the noise constraint. CAP-DC takes the same value.
    """
    s = checked(spec)
    n, tol = s["pole_pairs"], s["tolerance"]
    c_low, c_high = bounds(s)
    sol = solve(s)
    chosen = series.at_least(s["series"], c_low * (1 - 1e-12))
    check = verify(chosen, s)
    if not (c_low <= c_high * (1 + 1e-9) and check["window_ok"] and check["noise_ok"]):
        raise Infeasible(
            TABLE,
            f"no {s['series']} capacitor covers {s['rpm_min']:g} to {s['rpm_max']:g} rpm: the smallest that fits "
            f"the window at {s['rpm_min']:g} rpm ({chosen * 1e9:.3g} nF) keeps a swing above "
            f"{s['min_excursion']:g} V only up to {check['rpm_max_reliable']:.0f} rpm",
            {"cap_cd": chosen, "rpm_min": s["rpm_min"], "rpm_max_reliable": check["rpm_max_reliable"],
             "rpm_ratio_possible": an94002.rpm_ratio(s["window"], s["min_excursion"], s["i_charge_min"],
                                                     s["i_charge_max"]) * (1 - tol) / (1 + tol)})
    below = series.at_most(s["series"], chosen * (1 - 1e-9))
    binding = sol.binding()
    swing_below = an94002.excursion(below * (1 - tol), s["rpm_min"], n, s["i_charge_max"])
    return CommutationResult(
        spec=s, cap_cd=chosen, cap_dc=chosen,
        rpm_min_reliable=check["rpm_min_reliable"], rpm_max_reliable=check["rpm_max_reliable"],
        binding=BINDING["window"] if binding[:1] == ["window"] or not sol.success else BINDING[binding[0]],
        continuous_optimum=float(sol.x[0]) * 1e-9,
        noise_margin=check["swing_at_rpm_max"] / s["min_excursion"] - 1,
        swing_at_rpm_min=check["swing_at_rpm_min"], swing_at_rpm_max=check["swing_at_rpm_max"],
        next_smaller=below,
        next_smaller_fails=(f"{below * 1e9:.3g} nF x (1 - {tol:g}) = {below * (1 - tol) * 1e9:.3g} nF swings "
                            f"{swing_below:.3g} V at {s['rpm_min']:g} rpm, more than the {s['window']:g} V window"),
    )


def enumerate_series(spec: dict) -> float | None:
    """Exhaustive check: the smallest value of the series (1 pF..1 mF) that passes :func:`verify`."""
    s = checked(spec)
    for v in series.values(s["series"], 1e-12, 1e-3):
        chk = verify(v, s)
        if chk["window_ok"]:
            return v if chk["noise_ok"] else None
    return None
