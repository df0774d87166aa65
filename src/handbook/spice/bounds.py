"""The numerical method's own bounds, that a check's tolerance (``Check.rtol``) is built from: never a difference
seen in a run, always a figure of the grid, the step or the printout that the deck itself fixes.

* An AC sweep ``.ac dec N`` puts its points a factor ``1 + k`` apart, k = 10^(1/N) - 1 (:func:`log_step`);
  ``.meas`` interpolates linearly in f between two of them. The chord's error is at most k^2 / 8 times
  f^2 |y''| / |y| of the quantity y, relative (:func:`chord`); a crossing (WHEN) of a quantity that is odd about
  the crossing in ln f (a phase through -90 deg or 0 deg of a second-order network) is off by at most k^2 / 8,
  relative in f (the curvature that ln f itself puts in, :func:`crossing`).
* ngspice 39 prints a ``.meas`` result with 6 significant digits (WHEN, RMS, PARAM) or 7 (FIND, AT, MIN, MAX,
  AVG): half a unit of the last digit, relative, is at most :data:`PRINTED_6` or :data:`PRINTED_7`. A part value
  written into a deck is rounded the same way: :func:`as_printed` gives the equation the value the deck has.
"""
from __future__ import annotations

import math

#: half a unit of the 6th, of the 7th significant digit, relative to the printed value (its mantissa is >= 1)
PRINTED_6, PRINTED_7 = 5e-6, 5e-7


def log_step(per_decade: int) -> float:
    """Relative spacing k of an ``.ac dec per_decade`` grid's points."""
    return 10 ** (1 / per_decade) - 1


def chord(k: float, curvature: float) -> float:
    """Largest relative error of a linear interpolation in f between points k apart (relative) of a quantity y whose
    f^2 |y''| / |y| is at most ``curvature`` over the step."""
    return k * k / 8 * curvature


def crossing(k: float) -> float:
    """Largest relative error in f of a WHEN between points k apart of a quantity odd about its crossing in ln f:
    linear in ln f, so in f its curvature is its slope's, and the chord's root is off by k^2 / 8 at most."""
    return k * k / 8


def round_up(x: float, digits: int = 2) -> float:
    """``x`` rounded up to ``digits`` significant digits: the tolerance a reason prints, never below its bound."""
    if x <= 0:
        return x
    unit = 10 ** (math.floor(math.log10(x)) - digits + 1)
    return float(f"{math.ceil(x / unit * (1 - 1e-12)) * unit:.{digits}g}")


def as_printed(x: float) -> float:
    """A part value as a deck writes it (6 significant digits): what the equation must take to see the deck's part."""
    return float(f"{x:.6g}")


def percent(x: float) -> str:
    """A tolerance as a reason prints it, two significant digits and no exponent: "±0.0011 %"."""
    v = x * 100
    text = f"{v:.{max(0, 1 - math.floor(math.log10(v)))}f}"
    return f"±{text.rstrip('0').rstrip('.') if '.' in text else text} %"
