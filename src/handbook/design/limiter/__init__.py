"""The op-amp current limiter (AN94002 figure 3) designed as a whole network: R7, R9, R10, R11, R12, R13.

* :mod:`.model`: the network at every tolerance corner (exact), the spec's checks and each resistor's choices;
* :mod:`.search`: the smallest series R7 and the network of the largest worst margin (exact, by closed-form
  bounds);
* :mod:`.relaxation`: the continuous problem (casadi, IPOPT), for the figures of an infeasible spec's message;
* :mod:`.explain`: what can be met when nothing meets the spec;
* :mod:`.result`: the result, verified at every corner, and its warnings;
* :mod:`.analysis`: which tolerance eats the window, and a Monte Carlo lot.
* :mod:`.by_yield`: ``criterion = "yield"``, the network chosen by its Monte Carlo yield (the corners reported
  beside it).
"""
from ..common import explained
from .analysis import SPREAD_SOURCES, monte_carlo_trip
from .analysis import sensitivity as _sensitivity
from .model import TABLE, checked, zener_range
from .result import IC_LIMIT_MIN, LimiterResult, design, judge, warnings
from .search import GAP
from .search import enumerate_series as _enumerate_series


def enumerate(spec: dict | None = None) -> dict | None:
    """Exhaustive, for series small enough to list (up to ``search.ENUMERATE_MAX`` networks): the smallest R7
    with a network, and the network of the largest worst margin, keyed as :class:`LimiterResult` reports them.

    Parameters
    ----------
    spec : dict or None
        The ``[current_limiter]`` table, {key: value}, SI units (None: the defaults).

    Returns
    -------
    dict or None
        {"r7", "r9", "r10", "r11", "r12", "r13": ohm; "worst_margin": that network's worst margin, a fraction},
        or None when no network of the series meets the spec.

    Raises
    ------
    InputError
        When ``spec`` is invalid, or its series hold too many networks to enumerate.
    """
    best = _enumerate_series(spec)
    if best is None:
        return None
    r7, network, margin = best
    return {"r7": r7, **dict(zip(("r9", "r10", "r11", "r12", "r13"), network)), "worst_margin": margin}


def explain(spec: dict | None = None):
    """Why ``spec`` cannot be met, and what can (an :class:`~handbook.design.solvers.Infeasible`), or None
    when a design meets it.

    Parameters
    ----------
    spec : dict or None
        The ``[current_limiter]`` table, {key: value}, SI units (None: the defaults).

    Returns
    -------
    Infeasible or None
        The exception :func:`design` raises (not raised again), or None when a design meets ``spec``.

    Raises
    ------
    InputError
        When ``spec`` is invalid.
    """
    return explained(design, spec)


def sensitivity(result: LimiterResult) -> list[dict]:
    """Which tolerance eats the trip-current window of a designed limiter, one row per source:
    {"source", "share" (of the log spread), "margin_without" (the worst margin with that source removed)}.

    Parameters
    ----------
    result : LimiterResult
        A design (:func:`design`); its R7, network and checked spec are used.

    Returns
    -------
    list of dict
        One per entry of :data:`SPREAD_SOURCES`, in its order: "source", its name (str); "share", its share of
        ln(i_trip_max / i_trip_min), a fraction (the shares add to one); "margin_without", the worst margin with
        that source set to zero, a fraction of the limits.
    """
    return [{"source": name, "share": share, "margin_without": margin}
            for name, share, margin in _sensitivity(result.r7, result.network, result.spec)]


__all__ = ["GAP", "IC_LIMIT_MIN", "SPREAD_SOURCES", "TABLE", "LimiterResult", "checked", "design",
           "enumerate", "explain", "judge", "monte_carlo_trip", "sensitivity", "warnings", "zener_range"]
