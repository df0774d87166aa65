"""The TDA5143/5144 timing set: CAP-CD from the speed range, CAP-ST and CAP-TI from motor data.

* :mod:`.result`: CAP-CD (closed form, exact) and the result, verified at every corner;
* :mod:`.timers`: CAP-ST (start oscillator) and CAP-TI (watchdog) from the motor's data;
* :mod:`.checks`: each capacitor's range, the speed limits the timers set, the warnings.
"""
from ..common import explained
from .result import CommutationResult, bounds, checked, design, verify
from .result import enumerate_series as _enumerate_series
from .result import sensitivity as _sensitivity

TABLE = "commutation"


def enumerate(spec: dict | None = None) -> dict | None:
    """Exhaustive: the first series CAP-CD, from 1 pF up, that meets the spec at every corner, keyed as
    :class:`CommutationResult` reports it (every design's ``enumerate`` has this shape).

    Parameters
    ----------
    spec : dict or None
        The ``[commutation]`` table, {key: value} in SI units (speeds in rpm); None takes the defaults.

    Returns
    -------
    dict or None
        {"cap_cd": F}, or None when no series value meets the spec.

    Raises
    ------
    InputError
        When ``spec`` is invalid.
    """
    c = _enumerate_series(spec)
    return None if c is None else {"cap_cd": c}


def explain(spec: dict | None = None):
    """Why ``spec`` cannot be met, and what can (an :class:`~handbook.design.solvers.Infeasible`), or None.

    Parameters
    ----------
    spec : dict or None
        The ``[commutation]`` table, {key: value} in SI units (speeds in rpm); missing keys take their defaults,
        None takes them all.

    Returns
    -------
    Infeasible or None
        The exception :func:`design` raises (its message, and ``achievable``: what can be met), not raised; None
        when the spec can be met.

    Raises
    ------
    InputError
        When ``spec`` itself is invalid (an unknown key, a value out of range, contradicting limits).
    """
    return explained(design, spec)


def sensitivity(result: CommutationResult) -> list[dict]:
    """Which tolerance eats most of the speed range of a designed CAP-CD, one row per group:
    {"source", "share", "range_gain" (what pinning that group to the middle of its range gains), "cap_cd_bound"}.

    Parameters
    ----------
    result : CommutationResult
        A designed timing set (:func:`design`); its checked spec is what is varied.

    Returns
    -------
    list of dict
        One row per tolerance group ("capacitor tolerance", "charge current", "low level", "high level"):
        ``source`` (str), ``share`` (the fraction of the log of the lost speed range that pinning this group
        recovers), ``range_gain`` (the factor by which pinning it widens rpm_max_reliable / rpm_min_reliable) and
        ``cap_cd_bound`` (the smallest continuous CAP-CD with it pinned, F).
    """
    return [{"source": r["group"], **{k: v for k, v in r.items() if k != "group"}} for r in _sensitivity(result.spec)]


__all__ = ["TABLE", "CommutationResult", "bounds", "checked", "design", "enumerate", "explain", "sensitivity",
           "verify"]
