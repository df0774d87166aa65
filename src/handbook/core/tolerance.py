"""Tolerance analysis: exact worst case over the corners, and the app notes' percentage stack-up."""
from __future__ import annotations

import itertools
from collections.abc import Callable, Mapping
from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class WorstCase:
    nominal: float
    low: float
    high: float
    low_corner: dict  # the input values at the low end
    high_corner: dict

    @property
    def rel_low(self) -> float:
        return self.low / self.nominal - 1

    @property
    def rel_high(self) -> float:
        return self.high / self.nominal - 1


def corners(f: Callable[..., float], nominal: Mapping[str, float], spread: Mapping[str, tuple[float, float]]) -> WorstCase:
    """Extremes of ``f`` with every input in ``spread`` at one end of its range at the same time.

    ``spread`` maps an input name to its (low, high) values; inputs not named stay nominal. All
    2**k corners are evaluated, which finds the exact extremes of any ``f`` that is monotonic in each
    input over its range (true of the divider and trip-point formulas here: each resistor, the zener
    voltage and the offset enter monotonically; see the chapters for the derivative signs).

    Parameters
    ----------
    f : callable
        The quantity, called with keyword arguments (SI units); it must work elementwise on numpy arrays.
    nominal : Mapping of str to float
        Every argument of ``f`` -> its nominal value, SI units.
    spread : Mapping of str to (float, float)
        Argument name -> its (low, high) values, SI units.

    Returns
    -------
    WorstCase
        ``f`` at nominal, its lowest and highest values over the corners, and the corners (argument name ->
        value) where they occur.
    """
    names = list(spread)
    f_nom = float(f(**nominal))
    grids = np.array(list(itertools.product((0, 1), repeat=len(names))), dtype=bool)
    lo = np.array([spread[n][0] for n in names])
    hi = np.array([spread[n][1] for n in names])
    points = np.where(grids, hi, lo)
    args = {k: np.full(len(points), v, dtype=float) for k, v in nominal.items()}
    for i, n in enumerate(names):
        args[n] = points[:, i]
    vals = np.asarray(f(**args), dtype=float)
    i_lo, i_hi = int(np.argmin(vals)), int(np.argmax(vals))
    corner = lambda i: {n: float(points[i, j]) for j, n in enumerate(names)}  # noqa: E731
    return WorstCase(f_nom, float(vals[i_lo]), float(vals[i_hi]), corner(i_lo), corner(i_hi))


def symmetric(nominal: float, tol: float) -> tuple[float, float]:
    """The (low, high) ends of a value with a symmetric tolerance.

    Parameters
    ----------
    nominal : float
        The nominal value, SI units.
    tol : float
        The tolerance as a fraction (5 % is 0.05).

    Returns
    -------
    tuple of float
        (nominal (1 - tol), nominal (1 + tol)), SI units.
    """
    return nominal * (1 - tol), nominal * (1 + tol)


def stack_product(tols) -> tuple[float, float]:
    """The notes' stack-up: multiply (1 + t) for the high end; the low end is the product of (1 - t).

    Parameters
    ----------
    tols : iterable of float
        The tolerances as fractions (5 % is 0.05).

    Returns
    -------
    tuple of float
        (low, high): the relative deviations prod(1 - t) - 1 (negative) and prod(1 + t) - 1, as fractions.
    """
    tols = list(tols)
    return float(np.prod([1 - t for t in tols]) - 1), float(np.prod([1 + t for t in tols]) - 1)
