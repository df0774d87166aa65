"""The LM4651/LM4652 class-D stage as one design: switching frequency, R_OSC, R_DLY, output filter, heat sink.

* :mod:`.model`: every figure at every corner of the oscillator and filter tolerances (vectorised);
* :mod:`.result`: IPOPT for (f_sw, L, C), then a proven search over the series, re-verified at every corner;
* :mod:`.explain`: what binds, the warnings, and what can be met when nothing meets the spec.
"""
from ..common import explained
from .model import sensitivity as _sensitivity
from .result import ClassDResult, checked, design, r_dly_for, snap, solve
from .result import enumerate_series as _enumerate_series

TABLE = "class_d"


def enumerate(spec: dict | None = None) -> dict | None:
    """Exhaustive: the best R_OSC, L, C_BYP and R_DLY over the whole series grid, keyed as
    :class:`ClassDResult` reports them.

    Parameters
    ----------
    spec : dict or None
        The ``[class_d]`` table, {key: value} in SI units; missing keys take their defaults, None takes them all.

    Returns
    -------
    dict or None
        {"r_osc": ohm, "l_out": H, "c_out": F, "r_dly": ohm} of the best series design, or None when no series
        design meets every check.

    Raises
    ------
    InputError
        When ``spec`` is invalid.
    Infeasible
        When no series R_DLY gives ``dead_time_min``.
    """
    best = _enumerate_series(spec)
    return None if best is None else dict(zip(("r_osc", "l_out", "c_out", "r_dly"), best))


def explain(spec: dict | None = None):
    """Why ``spec`` cannot be met, and what can (an :class:`~handbook.design.solvers.Infeasible`), or None.

    Parameters
    ----------
    spec : dict or None
        The ``[class_d]`` table, {key: value} in SI units; missing keys take their defaults, None takes them all.

    Returns
    -------
    Infeasible or None
        The exception :func:`design` raises (its message, and ``achievable``: what can be met), not raised; None
        when the spec can be met.

    Raises
    ------
    InputError
        When ``spec`` itself is invalid.
    """
    return explained(design, spec)


def sensitivity(result: ClassDResult) -> list[dict]:
    """What each tolerance eats, one row per case (typical, each tolerance alone at its limit, all):
    {"source", check: margin for every check}.

    Parameters
    ----------
    result : ClassDResult
        A design (:func:`design`): its checked spec and its R_OSC, L, C_BYP and R_DLY are evaluated.

    Returns
    -------
    list of dict
        One row per case, "typical (no tolerance)" first and "all at their limits" last: ``source`` (str) and,
        for each check of :data:`~handbook.design.class_d.model.CHECKS`, its margin at the worst corner (a
        fraction of its limit; negative where it fails).
    """
    rows = _sensitivity(result.spec, result.r_osc, result.l_out, result.c_out, result.r_dly)
    return [{"source": name, **margins} for name, margins in rows.items()]


__all__ = ["TABLE", "ClassDResult", "checked", "design", "enumerate", "explain", "r_dly_for", "sensitivity", "snap", "solve"]
