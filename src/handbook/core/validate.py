"""Input checks that name the field, the value and what would work."""
from __future__ import annotations

import math
import numbers

import numpy as np


class InputError(ValueError):
    """Bad input: the message names the field, the value given and the accepted range."""


def number(name: str, value, *, low: float | None = None, high: float | None = None,
           low_open: bool = False, unit: str = "") -> float:
    """``value`` as a float, or an :class:`InputError` naming ``name`` and the accepted range.

    A numpy array is checked element by element and returned unchanged.
    """
    if isinstance(value, np.ndarray) and value.dtype.kind in "fiu":
        for x in (value.min(), value.max()) if value.size and np.isfinite(value).all() else value.ravel()[:1]:
            number(name, float(x), low=low, high=high, low_open=low_open, unit=unit)
        if value.size and not np.isfinite(value).all():
            raise InputError(f"{name}: expected finite numbers, got {value[~np.isfinite(value)][0]!r}")
        return value
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise InputError(f"{name} = {value!r}: expected a number{f' in {unit}' if unit else ''}")
    v = float(value)
    if not math.isfinite(v):
        raise InputError(f"{name} = {value!r}: expected a finite number")
    bad_low = low is not None and (v <= low if low_open else v < low)
    bad_high = high is not None and v > high
    if bad_low or bad_high:
        lo = "" if low is None else (f"> {low:g}" if low_open else f">= {low:g}")
        hi = "" if high is None else f"<= {high:g}"
        rng = " and ".join(x for x in (lo, hi) if x)
        raise InputError(f"{name} = {value!r}{(' ' + unit) if unit else ''} is out of range: use a value {rng}"
                         f"{(' ' + unit) if unit else ''}")
    return v


def positive(name: str, value, unit: str = "", high: float | None = None) -> float:
    return number(name, value, low=0.0, low_open=True, unit=unit, high=high)


def fraction(name: str, value) -> float:
    """A tolerance as a fraction: 0 <= value < 1 (5 % is 0.05)."""
    return number(name, value, low=0.0, high=0.999, unit="(fraction, 5 % = 0.05)")


def pole_pairs(name: str, value) -> int:
    if isinstance(value, bool) or not isinstance(value, numbers.Integral) or value < 1:
        raise InputError(f"{name} = {value!r}: the number of pole pairs is a whole number >= 1 (the note's motor has 6)")
    return int(value)


def ordered(name_low: str, low: float, name_high: str, high: float) -> None:
    if not low < high:
        raise InputError(f"{name_low} = {low:g} must be below {name_high} = {high:g}")
