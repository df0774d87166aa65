"""The TDA5143/5144 timing set: CAP-CD from the speed range, CAP-ST and CAP-TI from motor data.

* :mod:`.result`: CAP-CD (closed form, exact) and the result, verified at every corner;
* :mod:`.timers`: CAP-ST (start oscillator) and CAP-TI (watchdog) from the motor's data;
* :mod:`.checks`: each capacitor's range, the speed limits the timers set, the warnings.
"""
from ..common import explained
from .result import CommutationResult, bounds, checked, design, verify
from .result import enumerate_series as enumerate
from .result import sensitivity as _sensitivity

TABLE = "commutation"


def explain(spec: dict | None = None):
    """Why ``spec`` cannot be met, and what can (an :class:`~handbook.design.solvers.Infeasible`), or None."""
    return explained(design, spec)


def sensitivity(result: CommutationResult) -> list[dict]:
    """Which tolerance eats most of the speed range of a designed CAP-CD, one row per group:
    {"source", "share", "range_gain" (what pinning that group to the middle of its range gains), "cap_cd_bound"}."""
    return [{"source": r["group"], **{k: v for k, v in r.items() if k != "group"}} for r in _sensitivity(result.spec)]


__all__ = ["TABLE", "CommutationResult", "bounds", "checked", "design", "enumerate", "explain", "sensitivity",
           "verify"]
