"""Engineering values for whatever a person reads: ``eng(1.455e-8, "F")`` -> ``"14.55 nF"``.

Free of matplotlib (``design --json`` and the command line format numbers without loading a plotting
library); it writes exactly what matplotlib's ``EngFormatter(unit, places=None, sep=" ")`` writes, the
formatter the book's plot axes use, so a value reads the same in a table and on an axis.
"""
from __future__ import annotations

import math
import re

#: SI prefixes by power of ten (as matplotlib's EngFormatter.ENG_PREFIXES)
PREFIXES = {-30: "q", -27: "r", -24: "y", -21: "z", -18: "a", -15: "f", -12: "p", -9: "n", -6: "µ", -3: "m",
            0: "", 3: "k", 6: "M", 9: "G", 12: "T", 15: "P", 18: "E", 21: "Z", 24: "Y", 27: "R", 30: "Q"}


def prefixed(value: float, unit: str) -> str:
    """``value`` (as given, not rounded) with an SI prefix: ``prefixed(0.0015, "A")`` -> ``"1.5 mA"``; a
    minus sign is U+2212, as on the book's axes.

    Parameters
    ----------
    value : float
        The value in SI units.
    unit : str
        Its unit symbol ("A", "F", "Ω"); ``""`` for none.

    Returns
    -------
    str
        The mantissa (``:g``), a space, the prefix and the unit.
    """
    sign, value = (-1.0, -value) if value < 0 else (1.0, abs(float(value)))  # -0.0 shown as 0
    power = int(math.floor(math.log10(value) / 3) * 3) if value != 0 else 0
    power = min(max(power, min(PREFIXES)), max(PREFIXES))
    mantissa = sign * value / 10.0 ** power
    if abs(float(f"{mantissa:g}")) >= 1000 and power < max(PREFIXES):  # 999.9995 shown as 1 k, not 1000
        mantissa, power = mantissa / 1000, power + 3
    suffix = f" {PREFIXES[power]}{unit}" if unit or PREFIXES[power] else ""
    return f"{mantissa:g}{suffix}".replace("-", "\N{MINUS SIGN}")


def to_figures(x: float, rounding, figures: int = 4) -> float:
    """``x`` to ``figures`` significant figures, rounded one way: a limit stated so that it still holds (a largest
    allowed value rounded down, a least one up).

    Parameters
    ----------
    x : float
        The value (not zero).
    rounding : callable
        ``math.floor`` or ``math.ceil``.
    figures : int
        Significant figures kept.

    Returns
    -------
    float
        The rounded value.
    """
    scale = 10.0 ** (math.floor(math.log10(abs(x))) - figures + 1)
    return rounding(x / scale) * scale


def signed_percent(fraction: float, places: int = 2) -> str:
    """A signed share as the book writes it: "+1.21 %", "−0.78 %" (a minus sign, a space before %).

    Parameters
    ----------
    fraction : float
        The share, a fraction (0.0121 is +1.21 %).
    places : int
        Decimals of the per cent.

    Returns
    -------
    str
        The share with its sign.
    """
    return f"{fraction * 100:+.{places}f} %".replace("-", "\N{MINUS SIGN}")


def eng(value: float, unit: str = "", digits: int = 4) -> str:
    """An SI value to ``digits`` significant figures with a prefix: ``eng(1.455e-8, "F")`` -> ``"14.55 nF"``.

    Parameters
    ----------
    value : float
        The value in SI units.
    unit : str
        Its unit symbol; ``""`` or ``"1"`` for a pure number (no prefix), ``"%"`` for a fraction shown in percent.
    digits : int
        Significant figures kept.

    Returns
    -------
    str
        The value as a person reads it.
    """
    value = float(f"{float(value):.{digits}g}")
    if unit in ("1", ""):
        return f"{value:g}"
    if unit == "%":
        return f"{value * 100:g} %"
    return prefixed(value, unit)


_READABLE = ((re.compile(r"(\d)\s?u([FAHVWsm]|Ohm)\b"), "\\1 µ\\2"), (re.compile(r"(\d)\s?kohm\b"), "\\1 kΩ"),
             (re.compile(r"(\d)\s?Mohm\b"), "\\1 MΩ"), (re.compile(r"(\d)\s?mOhm\b"), "\\1 mΩ"),
             (re.compile(r"(\d)\s?ohm\b"), "\\1 Ω"), (re.compile(r"\+-\s?"), "±"), (re.compile(r"µOhm"), "µΩ"),
             (re.compile(r"([/*])u([FAH])\b"), "\\1µ\\2"), (re.compile(r"(\d)\s?deg\b"), "\\1°"),
             (re.compile(r"mm\^2"), "mm²"), (re.compile(r"mm\^3"), "mm³"), (re.compile(r"(\d) C\b(?![/ ]?\d|/)"), "\\1 °C"),
             (re.compile(r"\bm\^2\b"), "m²"))


def readable(text: str) -> str:
    """Units as a person reads them in the registries' ASCII text: 0.23 uF -> 0.23 µF, 750 ohm -> 750 Ω,
    4.7 kohm -> 4.7 kΩ, +-5 % -> ±5 %. Verbatim quotes of a source are not passed through it.

    Parameters
    ----------
    text : str
        Text written with ASCII units (anything else is taken as its ``str``).

    Returns
    -------
    str
        The same text with µ, Ω, ± and ° where a unit or a tolerance is written.
    """
    for pattern, repl in _READABLE:
        text = pattern.sub(repl, str(text))
    return text
