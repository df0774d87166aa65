"""Input checks that name the field, the value and what would work."""
from __future__ import annotations

import math
import numbers

import numpy as np

from .units import eng


class InputError(ValueError):
    """Bad input: the message names the field, the value given and the accepted range."""


#: SI units shown with an engineering prefix in messages (others as plain numbers: rpm, K, C, A/m^2, ...)
_PREFIXED = {"F": "F", "A": "A", "V": "V", "Hz": "Hz", "H": "H", "s": "s", "m": "m", "T": "T", "W": "W",
             "ohm": "Ω", "Ω": "Ω", "J": "J"}


def quantity(value, unit: str = "") -> str:
    """A value as a message shows it: '50 MHz', '1 kHz', '-1 A', '12 µH' for SI units, '0.05' for a fraction,
    '1,000,000 rpm' for others (the number to 4 significant figures).

    Parameters
    ----------
    value : float
        The value, in ``unit``.
    unit : str
        Its unit: an SI unit ("Hz", "ohm", ...) gets an engineering prefix, ``""`` or ``"1"`` none, anything
        else ("rpm") is written after the plain number.

    Returns
    -------
    str
        The value as the message shows it.
    """
    v = float(value)
    if unit in _PREFIXED and v != 0 and math.isfinite(v):  # the one formatter (core.units), with a plain minus
        return eng(v, _PREFIXED[unit]).replace("\N{MINUS SIGN}", "-")
    text = f"{v:,.0f}" if 1e4 <= abs(v) < 1e15 and v == round(v) else f"{v:.4g}"  # 1,000,000 rpm, not 1e+06
    return text + ("" if unit in ("", "1") else f" {_PREFIXED.get(unit, unit)}")


def range_text(low: float | None, high: float | None, low_open: bool = False, unit: str = "") -> str:
    """'from 1 kHz to 1 MHz', '> 0 A and <= 10 A', '<= 5 V': the accepted range with its unit.

    Parameters
    ----------
    low, high : float or None
        The ends of the range, in ``unit``; None for no limit on that side.
    low_open : bool
        ``low`` itself is excluded (a positive quantity: low = 0, low_open = True).
    unit : str
        The unit of the range (as :func:`quantity` takes it).

    Returns
    -------
    str
        The range in words, "(any)" when neither end is given.
    """
    if low is not None and high is not None and not low_open:
        return f"from {quantity(low, unit)} to {quantity(high, unit)}"
    lo = None if low is None else ("> " if low_open else ">= ") + quantity(low, unit)
    hi = None if high is None else "<= " + quantity(high, unit)
    return " and ".join(x for x in (lo, hi) if x) or "(any)"


def out_of_range(name: str, value, unit: str, low: float | None, high: float | None, low_open: bool = False,
                 meaning: str = "") -> InputError | None:
    """The error for ``value`` outside [low, high] (``low`` excluded with ``low_open``), else None.

    Parameters
    ----------
    name : str
        The field's name, as the message shows it.
    value : float
        The value given, in ``unit``.
    unit : str
        Its unit (as :func:`quantity` takes it), or an annotation in parentheses shown once after the range.
    low, high : float or None
        The accepted range, in ``unit``; None for no limit on that side.
    low_open : bool
        ``low`` itself is excluded.
    meaning : str
        What the field is, added in parentheses to the message.

    Returns
    -------
    InputError or None
        The error to raise, or None when ``value`` is in range.
    """
    v = float(value)
    if not ((low is not None and (v <= low if low_open else v < low)) or (high is not None and v > high)):
        return None
    if unit.startswith("("):  # an annotation, e.g. '(fraction, 5 % = 0.05)': once, after the range
        meaning, unit = meaning or unit.strip("()"), ""
    return InputError(f"{name} = {quantity(v, unit)} is out of range: use a value "
                      f"{range_text(low, high, low_open, unit)}" + (f" ({meaning})" if meaning else ""))


def number(name: str, value, *, low: float | None = None, high: float | None = None,
           low_open: bool = False, unit: str = "") -> float:
    """``value`` as a float, or an :class:`InputError` naming ``name`` and the accepted range.

    A numpy array is checked element by element and returned unchanged.

    Parameters
    ----------
    name : str
        The field's name, as the message shows it.
    value : float or numpy.ndarray
        The value given, in ``unit``.
    low, high : float or None
        The accepted range, in ``unit``; None for no limit on that side.
    low_open : bool
        ``low`` itself is excluded.
    unit : str
        The unit of ``value`` (SI: "V", "ohm", ...), for the message.

    Returns
    -------
    float or numpy.ndarray
        ``value`` as a float, or the array unchanged.
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
    error = out_of_range(name, v, unit, low, high, low_open)
    if error is not None:
        raise error
    return v


def positive(name: str, value, unit: str = "", high: float | None = None) -> float:
    """``value`` as a float if it is > 0 (and <= ``high`` where given), else an :class:`InputError`.

    Parameters
    ----------
    name : str
        The field's name, as the message shows it.
    value : float or numpy.ndarray
        The value given, in ``unit``.
    unit : str
        The unit of ``value`` (SI: "V", "ohm", ...), for the message.
    high : float or None
        The largest value accepted, in ``unit``; None for no upper limit.

    Returns
    -------
    float or numpy.ndarray
        ``value`` as a float, or the array unchanged.
    """
    return number(name, value, low=0.0, low_open=True, unit=unit, high=high)


def fraction(name: str, value) -> float:
    """A tolerance as a fraction: 0 <= value <= 0.999 (5 % is 0.05; a tolerance of 100 % or more would let a
    part's value reach zero or below).

    Parameters
    ----------
    name : str
        The field's name, as the message shows it.
    value : float
        The tolerance given, as a fraction.

    Returns
    -------
    float
        ``value`` as a float.
    """
    return number(name, value, low=0.0, high=0.999, unit="(fraction, 5 % = 0.05)")


def pole_pairs(name: str, value) -> int:
    """``value`` as an int if it is a whole number of pole pairs >= 1, else an :class:`InputError`.

    Parameters
    ----------
    name : str
        The field's name, as the message shows it.
    value : int
        The number of magnetic pole pairs given.

    Returns
    -------
    int
        ``value`` as an int.
    """
    if isinstance(value, bool) or not isinstance(value, numbers.Integral) or value < 1:
        raise InputError(f"{name} = {value!r}: the number of pole pairs is a whole number >= 1 (the note's motor has 6)")
    return int(value)


def ordered(name_low: str, low: float, name_high: str, high: float) -> None:
    """An :class:`InputError` unless ``low < high`` (two levels of one window).

    Parameters
    ----------
    name_low, name_high : str
        The two fields' names, as the message shows them.
    low, high : float
        Their values, one unit for both (SI: V for switching levels).
    """
    if not low < high:
        raise InputError(f"{name_low} = {low:g} must be below {name_high} = {high:g}")
