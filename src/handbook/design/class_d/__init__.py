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


def enumerate(spec: dict | None = None):
    """Exhaustive: the best (R_OSC, L, C_BYP, R_DLY) over the whole series grid, or None."""
    return _enumerate_series(spec)


def explain(spec: dict | None = None):
    """Why ``spec`` cannot be met, and what can (an :class:`~handbook.design.solvers.Infeasible`), or None."""
    return explained(design, spec)


def sensitivity(result: ClassDResult) -> list[dict]:
    """What each tolerance eats, one row per case (typical, each tolerance alone at its limit, all):
    {"source", check: margin for every check}."""
    rows = _sensitivity(result.spec, result.r_osc, result.l_out, result.c_out, result.r_dly)
    return [{"source": name, **margins} for name, margins in rows.items()]


__all__ = ["TABLE", "ClassDResult", "checked", "design", "enumerate", "explain", "r_dly_for", "sensitivity", "snap", "solve"]
