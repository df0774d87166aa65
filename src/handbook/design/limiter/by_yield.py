"""``criterion = "yield"``: the limiter chosen by its production yield instead of its corners.

The corners put every tolerance at its end at once, which a lot of boards almost never does (the default design
keeps 2.7 % inside the window at its corners; its 100 000 boards keep about 11 %). The search here is the exact
corner search (:func:`.search.solve`) on a box shrunk by a factor k on every tolerance (R9..R13, R7, D1's
tolerance and tempco, the op-amp's offset and bias currents), k bisected from 1 down: the smallest k whose design
keeps the Monte Carlo yield (:mod:`handbook.design.worstcase`: every part uniform in its full tolerance, each board
at both ends of the temperature span) at ``yield_min``, judged against the window narrowed by ``min_margin``
(what neither the corners nor the lot hold: R7's self-heating, copper, the zener's dynamic resistance) and
``input_headroom``. A lot's failures are a count: the yield is accepted when a 3-sigma upper bound of the failure
rate (Wilson's, one-sided) is at most 1 - ``yield_min``, so a fresh lot meets it too. The op-amp's input range
(``input_headroom``) stays a limit at the full corners: a board whose input sits inside it at no motor current
leaves the output undefined, a failure mode, not a margin.

It is a heuristic over k, not an exact optimum: a smaller box gives a smaller or equal R7, and the bisection
finds the smallest box whose design passes; a design of a box between two tried ones is not tried.
"""
from __future__ import annotations

import math

from ..common import checked_table
from . import model as net
from .model import TABLE
from .search import solve

#: the tolerances the box is shrunk on
SCALED = ("resistor_tolerance", "r7_tolerance", "zener_tolerance", "zener_tc", "offset", "input_bias",
          "input_offset_current")
#: the search's lot: boards and seed
N, SEED = 100_000, 1
#: bisection steps on k (k settled to 1/128)
STEPS = 7
#: sigmas of the failure rate's upper bound
Z = 3.0
#: searches of one box that may raise its input headroom to what the full corners lack
HEADROOM_TRIES = 4


def lot_yield(r7: float, network, s: dict, n: int = N, seed: int = SEED) -> float:
    """The fraction of ``n`` boards (seeded) whose trip current stays inside the window narrowed by
    ``min_margin`` at both ends of the temperature span and whose op-amp inputs keep ``input_headroom``.

    Parameters
    ----------
    r7 : float
        The sense resistor R7, nominal, ohm.
    network : tuple of float
        (R9, R10, R11, R12, R13), nominal, ohm.
    s : Mapping
        The checked ``[current_limiter]`` table (SI units), its full tolerances.
    n : int
        Boards.
    seed : int
        Seed of ``numpy.random.default_rng``.

    Returns
    -------
    float
        The yield, a fraction.
    """
    from ..worstcase import engine
    from ..worstcase import limiter as board

    m = s["min_margin"]
    narrowed = {**s, "i_no_trip": s["i_no_trip"] * (1 + m), "i_must_trip": s["i_must_trip"] * (1 - m)}
    model = board.model(r7, network, narrowed)
    return engine.yields(model, engine.evaluate(model, engine.draw(model, n, seed)))[1]


def meets(y: float, n: int, target: float) -> bool:
    """Whether a lot of ``n`` boards with yield ``y`` shows, at :data:`Z` sigma, a yield of at least ``target``.

    Parameters
    ----------
    y : float
        The lot's yield, a fraction.
    n : int
        Its boards.
    target : float
        ``yield_min``, a fraction.

    Returns
    -------
    bool
        True when Wilson's upper bound of the failure rate, (f + z^2/2 + z sqrt(f + z^2/4)) / n for f failures,
        is at most 1 - ``target``.
    """
    fails = (1 - y) * n
    return (fails + Z * Z / 2 + Z * math.sqrt(fails + Z * Z / 4)) / n <= 1 - target


def shrunk(s: dict, k: float):
    """The table with every tolerance of :data:`SCALED` times ``k`` (the box the corner search is run on).

    Parameters
    ----------
    s : Mapping
        The checked ``[current_limiter]`` table.
    k : float
        The factor, 0 .. 1.

    Returns
    -------
    Table
        A checked table, the tolerances scaled, ``criterion`` "corners".
    """
    return checked_table(TABLE, {**dict(s), **{key: s[key] * k for key in SCALED}, "criterion": "corners"})


def attempt(s: dict, k: float) -> tuple[dict, float | None]:
    """The corner search on the box shrunk by ``k``, and its design's lot yield.

    Parameters
    ----------
    s : Mapping
        The checked ``[current_limiter]`` table, its full tolerances.
    k : float
        The factor on every tolerance of :data:`SCALED` (1: the full corners, searched on ``s`` itself).

    Returns
    -------
    tuple
        (:func:`.search.solve`'s dict, the yield of its design's lot by :func:`lot_yield`, None when the search
        found no network). A network whose input headroom at the full corners falls short is searched again on
        the box with ``input_headroom`` raised by the shortfall (up to :data:`HEADROOM_TRIES` searches).
    """
    box = s if k == 1.0 else shrunk(s, k)
    for _ in range(HEADROOM_TRIES):
        found = solve(box)
        if found["r7"] is None:
            return found, None
        # the op-amp's input range is held at the full corners: an input inside it leaves the output undefined at
        # no motor current (the limiter may act on a motor drawing nothing), a failure no lot statistic should trade
        short = s["input_headroom"] - float(net.verify(found["r7"], found["network"], s)["headroom_min"])
        if short <= s["input_headroom"] * 1e-12:
            return found, lot_yield(found["r7"], found["network"], s)
        # the box's search sat at its own headroom limit: ask it for what the full corners lack, and search again
        box = checked_table(TABLE, {**dict(box), "input_headroom": box["input_headroom"] + short * (1 + 1e-6)})
    return found, None


def solve_yield(s: dict) -> dict:
    """The search's answer by yield: :func:`.search.solve`'s dict for the smallest accepted box, with "scale" (its
    k) and "yield" (its lot's yield). The first box tried is the full one, then 3/4, 1/2 and 1/4 of it until one
    passes; then k is bisected between the smallest that passed and 0.

    Parameters
    ----------
    s : Mapping
        The checked ``[current_limiter]`` table, ``criterion`` "yield".

    Returns
    -------
    dict
        :func:`.search.solve`'s keys ("r7", "network", "evaluated", "tried", "bound", "proven", "unproven") for the
        design chosen, plus "scale" (float) and "yield" (float; None, with "r7" None, when no box tried passes).
    """
    first = None
    for k in (1.0, 0.75, 0.5, 0.25):
        found, y = attempt(s, k)
        first = first or found
        if y is not None and meets(y, N, s["yield_min"]):
            best, best_yield, k_ok = found, y, k
            break
    else:
        return {**first, "scale": 1.0, "yield": None}
    k_bad = 0.0
    for _ in range(STEPS):
        k = (k_ok + k_bad) / 2
        found, y = attempt(s, k)
        if y is not None and meets(y, N, s["yield_min"]):
            k_ok, best, best_yield = k, found, y
        else:
            k_bad = k
    return {**best, "scale": k_ok, "yield": best_yield}
