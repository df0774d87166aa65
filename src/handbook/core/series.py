"""E-series (IEC 60063) component values, through the ``eseries`` package."""
from __future__ import annotations

import eseries

SERIES_NAMES = ("E3", "E6", "E12", "E24", "E48", "E96", "E192")


def _series(name: str):
    if name not in SERIES_NAMES:
        raise ValueError(f"series {name!r} is not an E-series; use one of {', '.join(SERIES_NAMES)}")
    return getattr(eseries, name)


def values(name: str, low: float, high: float) -> list[float]:
    """Every value of series ``name`` from ``low`` to ``high`` inclusive (SI units)."""
    return [float(v) for v in eseries.erange(_series(name), low, high)]


def nearest(name: str, x: float) -> float:
    return float(eseries.find_nearest(_series(name), x))


def at_least(name: str, x: float) -> float:
    """The smallest value of the series that is >= x."""
    return float(eseries.find_greater_than_or_equal(_series(name), x))


def at_most(name: str, x: float) -> float:
    """The largest value of the series that is <= x."""
    return float(eseries.find_less_than_or_equal(_series(name), x))


def smallest_meeting(name: str, minimum: float, tolerance: float) -> float:
    """The smallest series value whose low end, value x (1 - tolerance), still reaches ``minimum``."""
    if not 0 <= tolerance < 1:
        raise ValueError(f"tolerance {tolerance!r} must be a fraction in [0, 1)")
    return at_least(name, minimum / (1 - tolerance))
