"""The limiter's search, exact by construction: every pruning decision rests on a bound that holds for every
network it discards, never on a local solver's verdict.

The network splits in two: the level shift P = (R12, R13) and the reference Q = (R9 + R10, R11). At every
corner, with A = R13 / (R12 + R13), B = R11 / (R9 + R10 + R11) and the bias error E (:func:`.model.bias_error`
times A), the trip voltage is (:mod:`.model`)

    V_cs = V_D1 (1 - B / A) -+ (V_os + E) / A,      E = |R_p - R_m| I_b + (R_p + R_m) I_os / 2 >= R_p min(I_os, I_b + I_os / 2)

(R_p = R12 || R13, R_m = (R9 + R10) || R11). Q enters the bias-free part only through B, whose extremes over
Q's tolerances are 1 / (1 + y (1 -+ t) / (1 +- t)), y = (R9 + R10) / R11: so for one P, "both margins at least
theta" can hold only for y inside an interval [y1, y2] written in closed form (with E at its lower bound, which
only widens it). Every P gets the best theta its interval allows (an upper bound on any network with that P);
the P are taken best bound first, and for each the reference networks inside its interval (every R11, the
sums R9 + R10 in a sorted array) are evaluated exactly (:func:`.model.scores`). The search stops when no P
left can beat the best network found by more than :data:`GAP` (or, for the smallest R7, reach ``min_margin``):
the smallest R7 and the tie-break are then proven, up to :data:`MAX_EVALUATIONS` exact evaluations.
"""
from __future__ import annotations

import math

import numpy as np

from ...core import InputError
from .model import DIVIDER, RESISTORS, checked, choices, headroom_corners, scores, zener_range

#: the most divider networks :func:`enumerate_series` evaluates (a few hundred MB of numpy arrays)
ENUMERATE_MAX = 2_000_000
#: the tie-break is settled to within this worst margin (0.25 percentage point)
GAP = 2.5e-3
#: exact network evaluations one R7 may spend before its search is reported unsettled
MAX_EVALUATIONS = 5_000_000
#: networks evaluated at a time while looking for the first that meets the spec
CHUNK = 20_000
#: relative widening of every closed-form interval (rounding may not cost a network)
SLACK = 1e-9


class Split:
    """The two halves of every network of the spec's series: level shifts P and references Q."""

    def __init__(self, s: dict):
        self.s = s
        t, ib, ios = s["resistor_tolerance"], s["input_bias"], s["input_offset_current"]
        self.vz = np.array(zener_range(s))
        r = {n: choices(s, n) for n in DIVIDER}
        r12, r13 = (x.ravel() for x in np.meshgrid(r["r12"], r["r13"], indexing="ij"))
        a12 = r12[:, None] * (1 + t * np.array([-1, -1, 1, 1]))
        a13 = r13[:, None] * (1 + t * np.array([-1, 1, -1, 1]))
        head_p = np.min(headroom_corners((1.0, 1.0, 1.0, r12, r13), s)[:4], axis=0)  # V_+'s four corners
        i_p = self.vz[1] / ((r12 + r13) * (1 - t))
        keep = (head_p >= s["input_headroom"] - 1e-12) & (i_p < s["divider_current_max"] * (1 + 1e-12))
        self.r12, self.r13 = r12[keep], r13[keep]
        # the least S + R11 the references may have, per level shift: the divider current it leaves them
        self.least_total = self.vz[1] / ((1 - t) * (s["divider_current_max"] * (1 + 1e-12) - i_p[keep]))
        a = (a13 / (a12 + a13))[keep]  # (nP, 4): A at each corner of (R12, R13)
        eps = (a12 * a13 / (a12 + a13))[keep] * min(ios, ib + ios / 2)  # the least bias error there
        sums = (r["r9"][:, None] + r["r10"][None, :]).ravel()
        order = np.argsort(sums, kind="stable")
        self.sums = sums[order]
        self.i9, self.i10 = np.unravel_index(order, (len(r["r9"]), len(r["r10"])))
        self.r9, self.r10, self.r11 = r["r9"], r["r10"], r["r11"]
        self.rho = (1 - t) / (1 + t)
        # at each zener end j and corner c of each level shift: A_c / V_z,j and A_c -+ (V_os + eps_c) / V_z,j, so that
        # ((V_z,j - L) A_c -+ (V_os + eps_c)) / V_z,j is one product and one difference (:meth:`interval`); shape
        # (kind, j and c, level shift), so that the reduction over the eight (j, c) runs along whole rows
        a8 = np.concatenate([a.T, a.T])
        k8 = np.concatenate([(s["offset"] + eps.T) / vz for vz in self.vz])
        # made C-ordered: the transposes above leave the (j, c) axis innermost, and a reduction over it striding
        # across memory took five times as long (a yield design 2.9 s, now 1.5 s; same answers)
        self.terms = np.ascontiguousarray(np.stack([np.concatenate([a.T / vz for vz in self.vz]), a8 - k8, a8 + k8]))
        self.head_sum = self._head_sums(t, ib + ios / 2)
        self.y_lo, self.y_hi = self._reach()

    def _reach(self) -> tuple[np.ndarray, np.ndarray]:
        """For each level shift, the y = (R9 + R10) / R11 its references can reach at all: every R11 whose sums
        meet the headroom and the divider current the level shift leaves them. The least total S + R11 rises
        with the level shift's own current; it is taken at 512 breakpoints, each level shift at the breakpoint
        just below its own (less demanding: the range only widens)."""
        least = self.least_total
        points = np.sort(least)[np.linspace(0, len(least) - 1, min(512, len(least))).astype(int)]
        lower = np.maximum(np.maximum(self.head_sum, points[:, None] - self.r11), self.sums[0]) * (1 - SLACK)
        ok = lower <= self.sums[-1]
        y_lo = np.where(ok, lower / self.r11, np.inf).min(axis=1)
        y_hi = np.where(ok, self.sums[-1] / self.r11, -np.inf).max(axis=1)
        k = np.searchsorted(points, least, side="right") - 1
        return y_lo[k], y_hi[k]

    def _head_sums(self, t: float, ib: float) -> np.ndarray:
        """For each R11, the least R9 + R10 whose V_- headroom, (S (V_D1,lo - I_b R11)) / (S + R11) at every
        corner, reaches input_headroom (increasing in S where V_D1,lo - I_b R11 > input_headroom); +inf where
        none can, -inf where the form gives no bound."""
        h, out = self.s["input_headroom"] - 1e-12, np.full(len(self.r11), -np.inf)  # verify's tolerance
        for g11 in (-1, 1):
            a11 = self.r11 * (1 + t * g11)
            c = self.vz[0] - ib * a11
            with np.errstate(divide="ignore", invalid="ignore"):
                need = np.where(c > h, h * a11 / (c - h), np.where(h > 0, np.inf, -np.inf))
            out = np.maximum(out, need / (1 - t))  # the sum at its low end must still reach it
        return out

    def interval(self, theta, r7: float, p=slice(None), r7_high: float | None = None):
        """[y1, y2]: where y = (R9 + R10) / R11 must lie for both margins to reach ``theta`` with level shift(s)
        ``p`` (a necessary condition: the bias error at its least); empty when y1 > y2.

        Parameters
        ----------
        theta : float or numpy.ndarray
            The worst margin asked for, a fraction (one, or one per level shift of ``p``).
        r7 : float
            The sense resistor, nominal, ohm.
        p : slice or numpy.ndarray
            The level shifts (indices of the arrays of this split).
        r7_high : float or None
            For a range of R7 at once: its largest value (``r7`` its smallest). The interval then holds every
            y any R7 of the range could use (each margin's limit taken at the R7 most lenient for it).

        Returns
        -------
        tuple of numpy.ndarray
            (y1, y2), one each per level shift, clipped to the y its references can reach (:meth:`_reach`).
        """
        s = self.s
        theta = np.asarray(theta) - 1e-12  # the margin a design accepts (verify's tolerance)
        big_l = (1 + theta) * s["i_no_trip"] * r7 * (1 + s["r7_tolerance"])
        big_u = (1 - theta) * s["i_must_trip"] * (r7 if r7_high is None else r7_high) * (1 - s["r7_tolerance"])
        per_a, low, high = self.terms[:, :, p]  # V_z positive wherever a level shift passed the headroom
        with np.errstate(divide="ignore", invalid="ignore"):
            beta_low = (low - big_l * per_a).min(axis=0)  # ((V_z - L) A - V_os - eps) / V_z, least
            beta_high = (high - big_u * per_a).max(axis=0)  # ((V_z - U) A + V_os + eps) / V_z, most
            y1 = np.where(beta_low > 0, (1 / beta_low - 1) / self.rho, np.inf)
            y2 = np.where(beta_high > 0, (1 / beta_high - 1) * self.rho, np.inf)
        # both ends widened by SLACK after clipping: y_hi R11 may round below the sum it came from
        return np.maximum(y1, self.y_lo[p]) * (1 - SLACK), np.minimum(y2, self.y_hi[p]) * (1 + SLACK)

    def bounds(self, r7: float) -> np.ndarray:
        """For every P, a bound on the worst margin any network with it can reach (bisection on the interval).

        Parameters
        ----------
        r7 : float
            The sense resistor, nominal, ohm.

        Returns
        -------
        numpy.ndarray
            One bound per level shift, a fraction (-inf where no margin above -100 % is possible).
        """
        lo, hi = np.full(len(self.r12), -1.0), np.full(len(self.r12), 1.0)
        for _ in range(16):  # to 3e-5 of a margin: an upper end stays an upper bound, only a little looser
            mid = (lo + hi) / 2
            y1, y2 = self.interval(mid, r7)
            ok = y1 <= y2
            lo, hi = np.where(ok, mid, lo), np.where(ok, hi, mid)
        y1, y2 = self.interval(lo, r7)
        return np.where(y1 <= y2, hi, -np.inf)  # hi: above every theta the bisection found possible

    def candidates(self, ps: np.ndarray, theta, r7: float, size: int):
        """Every network (rows R9..R13) with a level shift of ``ps`` whose y lies in that shift's interval for
        ``theta`` and whose reference meets the headroom and its share of the divider current, ``size`` rows at
        a time (a generator: the next rows are made only when asked for).

        Parameters
        ----------
        ps : numpy.ndarray
            The level shifts, indices of this split's arrays.
        theta : float
            The worst margin asked for, a fraction.
        r7 : float
            The sense resistor, nominal, ohm.
        size : int
            The most networks per array yielded.

        Yields
        ------
        numpy.ndarray
            Networks, shape (n, 5): R9, R10, R11, R12, R13 in ohm.
        """
        y1, y2 = self.interval(theta, r7, ps)
        ps, y1, y2 = ps[y1 <= y2], y1[y1 <= y2], y2[y1 <= y2]
        if not len(ps):
            return
        least_total = self.least_total[ps][:, None]  # S + R11 at least this for the divider current
        lo = np.maximum(np.maximum(y1[:, None] * self.r11, self.head_sum), least_total - self.r11) * (1 - SLACK)
        start = np.searchsorted(self.sums, lo.ravel(), side="left")
        hi = (y2[:, None] * self.r11).ravel() * (1 + SLACK)
        count = np.maximum(np.searchsorted(self.sums, hi, side="right") - start, 0)
        ends = np.cumsum(count)
        for first in range(0, int(ends[-1]), size):
            rows = np.arange(first, min(first + size, int(ends[-1])))
            cell = np.searchsorted(ends, rows, side="right")
            k = start[cell] + rows - (ends[cell] - count[cell])
            p, j11 = ps[cell // len(self.r11)], cell % len(self.r11)
            yield np.column_stack([self.r9[self.i9[k]], self.r10[self.i10[k]], self.r11[j11], self.r12[p], self.r13[p]])


class _Limit(Exception):
    """The search spent :data:`MAX_EVALUATIONS` exact evaluations on one R7 before it settled."""


class _Budget:
    """The exact evaluations one R7's search has spent, across its calls of :func:`_scored`."""

    def __init__(self):
        self.spent = 0


def _scored(split: Split, order: np.ndarray, theta: float, r7: float, size: int, budget: _Budget):
    """Every candidate network of the level shifts ``order`` for ``theta`` (:meth:`Split.candidates`), in
    batches of about 200 000 (level shift, R11) cells and arrays of ``size`` networks, each array with its
    exact worst margins (:func:`.model.scores`); raises :class:`_Limit` once ``budget`` has passed
    :data:`MAX_EVALUATIONS`."""
    step = max(1, 200_000 // max(len(split.r11), 1))
    for i in range(0, len(order), step):
        if budget.spent > MAX_EVALUATIONS:
            raise _Limit
        for nets in split.candidates(order[i:i + step], theta, r7, size):
            if budget.spent > MAX_EVALUATIONS:
                raise _Limit
            budget.spent += len(nets)
            yield nets, scores(r7, nets, split.s)


def first_network(split: Split, r7: float, threshold: float) -> dict:
    """Any network with this R7 whose worst margin reaches ``threshold``.

    Parameters
    ----------
    split : Split
        The spec's level shifts and references.
    r7 : float
        The sense resistor, nominal, ohm.
    threshold : float
        The worst margin asked for (``min_margin``), a fraction.

    Returns
    -------
    dict
        "network" (R9..R13, ohm, or None: there is none, proven when "proven"), "score" (its worst margin),
        "proven" (False: the evaluation limit stopped the search first), "evaluated" (networks evaluated).
    """
    y1, y2 = split.interval(threshold, r7)
    open_ = np.flatnonzero(y1 <= y2)
    order = open_[np.argsort(-(y2[open_] / y1[open_]), kind="stable")]  # the widest intervals first
    budget = _Budget()
    try:
        for part, sc in _scored(split, order, threshold, r7, CHUNK, budget):  # stop at the first that reaches it
            j = int(np.argmax(sc))
            if sc[j] >= threshold - 1e-12:
                return {"network": tuple(float(x) for x in part[j]), "score": float(sc[j]), "proven": True,
                        "evaluated": budget.spent}
    except _Limit:
        return {"network": None, "score": -np.inf, "proven": False, "evaluated": budget.spent}
    return {"network": None, "score": -np.inf, "proven": True, "evaluated": budget.spent}


def best_network(split: Split, r7: float, threshold: float, start: tuple) -> dict:
    """The network of the largest worst margin with this R7, within :data:`GAP`; ``start`` is a network known to
    reach ``threshold``. Levels theta from the best bound down: every network
    that could exceed theta (its level shift's interval for theta) is evaluated; once the best found is within
    GAP of theta, no network left out can beat it by more. The first level is GAP / 8 under the bound, each next
    one twice as far.

    Parameters
    ----------
    split : Split
        The spec's level shifts and references.
    r7 : float
        The sense resistor, nominal, ohm.
    threshold : float
        The worst margin asked for (``min_margin``), a fraction.
    start : tuple of float
        A network known to reach ``threshold``, R9..R13 in ohm.

    Returns
    -------
    dict
        "network" (R9..R13, ohm), "score" (its worst margin), "bound" (no network with this R7 has a worst
        margin above it), "proven" (False: the evaluation limit stopped the search first), "evaluated".
    """
    ub = split.bounds(r7)
    best, score = start, float(scores(r7, np.array([start]), split.s)[0])
    top = float(ub.max())
    budget, step = _Budget(), GAP / 8  # the first level close under the best bound: the best network is often there
    theta = top - step
    while True:
        theta = max(theta, threshold, score)
        order = np.flatnonzero(ub > theta)
        order = order[np.argsort(-ub[order], kind="stable")]
        try:
            for nets, sc in _scored(split, order, theta, r7, 10 * CHUNK, budget):
                j = int(np.argmax(sc))
                if sc[j] > score:
                    best, score = tuple(float(x) for x in nets[j]), float(sc[j])
        except _Limit:
            return {"network": best, "score": score, "bound": top, "proven": False, "evaluated": budget.spent}
        # every network above theta has been evaluated: the best is the best, or within GAP of theta
        if score >= theta - GAP or theta <= max(threshold, score):
            return {"network": best, "score": score, "bound": score if score >= theta else min(theta, top),
                    "proven": True, "evaluated": budget.spent}
        step *= 2
        theta -= step


def _first_open(split: Split, r7s: np.ndarray, lo: int, hi: int) -> int | None:
    """The first index of ``r7s[lo..hi]`` at which some level shift leaves room for ``min_margin`` (None: none
    does; every R7 before it is proven to have no network). A whole range is ruled out at once by its most
    lenient limits, and split in two where it is not."""
    if lo > hi:
        return None
    y1, y2 = split.interval(split.s["min_margin"], float(r7s[lo]), r7_high=float(r7s[hi]))
    if not (y1 <= y2).any():
        return None
    if lo == hi:
        return lo
    mid = (lo + hi) // 2
    first = _first_open(split, r7s, lo, mid)
    return first if first is not None else _first_open(split, r7s, mid + 1, hi)


def solve(s: dict) -> dict:
    """The smallest series R7 with a network meeting the spec, and its network of the largest worst margin.

    Parameters
    ----------
    s : Mapping
        The checked ``[current_limiter]`` table (SI units).

    Returns
    -------
    dict
        "r7" (ohm, or None when no network of the series meets the spec), "network" (R9..R13, ohm), "score"
        (its worst margin), "bound" (no network with this R7 has a worst margin above it), "proven" (bool: the
        tie-break settled within GAP), "unproven" (smaller R7 values, ohm, whose search hit its evaluation limit
        without a network), "tried" (R7 values searched), "evaluated" (exact network evaluations).
    """
    split = Split(s)
    out = {"r7": None, "network": None, "score": -np.inf, "bound": -np.inf, "proven": True, "unproven": (),
           "tried": 0, "evaluated": 0}
    if not len(split.r12) or not len(split.sums):
        return out
    r7s = choices(s, "r7")
    first = _first_open(split, r7s, 0, len(r7s) - 1)
    for r7 in r7s[len(r7s) if first is None else first:]:
        r7 = float(r7)
        y1, y2 = split.interval(s["min_margin"], r7)
        if not (y1 <= y2).any():  # no level shift leaves room: proven without a network evaluated
            continue
        out["tried"] += 1
        found = first_network(split, r7, s["min_margin"])
        out["evaluated"] += found["evaluated"]
        if found["network"] is None:
            if not found["proven"]:
                out["unproven"] += (r7,)
            continue
        best = best_network(split, r7, s["min_margin"], found["network"])
        out["evaluated"] += best["evaluated"]
        return {**out, "r7": r7, "network": best["network"], "score": best["score"], "bound": best["bound"],
                "proven": best["proven"]}
    return out


def enumerate_series(spec: dict):
    """Exhaustive search (every network and every R7; for reduced series only): (r7, network, worst margin)
    or None. Used by the benchmark beside :func:`design`.

    Parameters
    ----------
    spec : Mapping
        The ``[current_limiter]`` table.

    Returns
    -------
    tuple or None
        (the smallest R7 with a network, ohm; the network of the largest worst margin, R9..R13 in ohm; that margin,
        fraction), or None when no network of the series meets the spec.

    Raises
    ------
    InputError
        When the series hold more than :data:`ENUMERATE_MAX` divider networks.
    """
    s = checked(spec)
    lists = [choices(s, name) for name in RESISTORS]
    networks = math.prod(len(v) for v in lists[1:])
    if networks > ENUMERATE_MAX:
        raise InputError(f"{networks:,} divider networks are too many to enumerate (at most {ENUMERATE_MAX:,}): pin "
                         "resistors or narrow their ranges or series (limiter.design searches any size)")
    grid = np.array(np.meshgrid(*lists[1:], indexing="ij")).reshape(5, -1).T
    for r7 in lists[0]:
        sc = scores(float(r7), grid, s)
        ok = sc >= s["min_margin"] - 1e-12
        if ok.any():
            j = int(np.argmax(np.where(ok, sc, -np.inf)))
            return float(r7), tuple(float(x) for x in grid[j]), float(sc[j])
    return None
