"""E-series (IEC 60063) component values, through the ``eseries`` package."""
from __future__ import annotations

import eseries

SERIES_NAMES = ("E3", "E6", "E12", "E24", "E48", "E96", "E192")


def _series(name: str):
    if name not in SERIES_NAMES:
        raise ValueError(f"series {name!r} is not an E-series; use one of {', '.join(SERIES_NAMES)}")
    return getattr(eseries, name)


def values(name: str, low: float, high: float) -> list[float]:
    """Every value of series ``name`` from ``low`` to ``high`` inclusive (SI units).

    Parameters
    ----------
    name : str
        The series, one of :data:`SERIES_NAMES` ("E12").
    low, high : float
        The range, SI units (ohm, F, ...); both ends included.

    Returns
    -------
    list of float
        The series values in the range, ascending.
    """
    return [float(v) for v in eseries.erange(_series(name), low, high)]


def nearest(name: str, x: float) -> float:
    """The value of series ``name`` nearest ``x``.

    Parameters
    ----------
    name : str
        The series, one of :data:`SERIES_NAMES`.
    x : float
        The value wanted, SI units.

    Returns
    -------
    float
        The nearest series value, SI units.
    """
    return float(eseries.find_nearest(_series(name), x))


def at_least(name: str, x: float) -> float:
    """The smallest value of the series that is >= x.

    Parameters
    ----------
    name : str
        The series, one of :data:`SERIES_NAMES`.
    x : float
        The lower bound, SI units.

    Returns
    -------
    float
        The series value, SI units.
    """
    return float(eseries.find_greater_than_or_equal(_series(name), x))


def at_most(name: str, x: float) -> float:
    """The largest value of the series that is <= x.

    Parameters
    ----------
    name : str
        The series, one of :data:`SERIES_NAMES`.
    x : float
        The upper bound, SI units.

    Returns
    -------
    float
        The series value, SI units.
    """
    return float(eseries.find_less_than_or_equal(_series(name), x))


def smallest_meeting(name: str, minimum: float, tolerance: float) -> float:
    """The smallest series value whose low end, value x (1 - tolerance), still reaches ``minimum``.

    Parameters
    ----------
    name : str
        The series, one of :data:`SERIES_NAMES`.
    minimum : float
        The value the part must reach at its low tolerance end, SI units.
    tolerance : float
        The part's tolerance as a fraction (5 % is 0.05), 0 <= tolerance < 1.

    Returns
    -------
    float
        The series value, SI units.
    """
    if not 0 <= tolerance < 1:
        raise ValueError(f"tolerance {tolerance!r} must be a fraction in [0, 1)")
    return at_least(name, minimum / (1 - tolerance))
