"""An exact reference for the op-amp current limiter's design, over the full series, sharing no code with
handbook.design.limiter (it reads the spec's defaults and the E-series values only).

``exact_limiter(spec)`` returns (R7, (R9, R10, R11, R12, R13), worst margin) for the smallest feasible R7 of
the spec and, with that R7, the largest worst margin min(I_lo/i_no_trip - 1, 1 - I_hi/i_must_trip) of any
network, or None when no network meets the spec with any R7 of its range. Feasible means what
tests/oracles.py:enumerate_limiter means, with the same slack (1e-12): every corner's trip current inside
[i_no_trip (1 + min_margin), i_must_trip (1 - min_margin)], both inputs ``input_headroom`` below the zener
node, the dividers drawing at most ``divider_current_max``.

Method: branch and bound over boxes of series indices, with bounds that are valid for every network of a box
and exact on a box of one network; nothing is sampled and no local solver is used, so the answer is the true
optimum (up to the floating-point rounding of the figures themselves, ~1e-15 relative).

1. R9 and R10 enter only through their sum. Every corner figure is monotone in S = R9 + R10 (point 3), so
   its extremes over the tolerance corners of R9 and R10 are at S0 (1 - t) and S0 (1 + t), S0 the nominal
   sum: the corners where R9 and R10 go opposite ways lie in between. A network is (S0, R11, R12, R13) with
   S0 from the sorted distinct sums of the two series.

2. The node equations, with q = 1 + R12/R13 (= 1/a, a = R13/(R12 + R13)) and R12||R13 / a = R12:
       M   = V_D1 R11/(S + R11) + I_m S||R11 = R11 (V_D1 + I_m S)/(S + R11)          (minus input - Z)
       V_cs = V_D1 - (M + V_os) q + I_p R12                                          (trip voltage at R7)
       headroom, minus input: V_D1 - M = S (V_D1 - I_m R11)/(S + R11)
       headroom, plus input:  V_D1 (1 - a) - I_p R12||R13 = R12 (V_D1 - I_p R13)/(R12 + R13)
       divider current: V_D1/(S + R11) + V_D1/(R12 + R13)
   Trip currents are V_cs / R7_actual, so (I_lo, I_hi) at R7 are (V_lo, V_hi)/R7 (the oracle's
   limiter_corners(1, ...) divided by R7): the feasible R7 of a network are an interval.

3. Monotonicity on every axis-parallel line (each variable alone, the others fixed), for every corner
   (V_D1 > 0, (I_p, I_m) a bias vertex, V_os = +-offset):
       dM/dS   = R11 (I_m R11 - V_D1)/(S + R11)^2 : the sign of (I_m R11 - V_D1) does not depend on S;
       dM/dR11 = S (V_D1 + I_m S)/(S + R11)^2    : the sign of (V_D1 + I_m S) does not depend on R11;
       V_cs at a fixed M: linear in R12; d/dR13 = (M + V_os) R12/R13^2, sign independent of R13;
       V_cs decreases in M (q > 0);
       minus headroom: d/dS ~ R11 (V_D1 - I_m R11), d/dR11 ~ -S (I_m S + V_D1): signs free of the variable;
       plus headroom: d/dR12 ~ R13 (V_D1 - I_p R13), d/dR13 ~ -R12 (I_p R12 + V_D1): likewise;
       divider current decreases in every resistor.
   A function monotone on every axis-parallel line reaches its max and min over a box at a vertex (move
   each coordinate in turn to the better end: the value never gets worse). These hold for any spec with
   positive resistors, 0 <= t < 1 and a positive zener at both ends; ``_problem`` checks those and raises
   otherwise. Nothing else (no sign of I_m R11 - V_D1 etc.) is assumed.

4. Bounds over a box B of nominal values (sigma: a tolerance sign vector, x * (1 + t sigma) its corner):
   the network's V_lo = min over corner, sigma of V_cs. For each fixed sigma, x -> f(x (1 + t sigma)) is
   still monotone on axis lines, so max over x in B of f(x (1 + t sigma)) is at a vertex of B, and
       max_{x in B} V_lo(x) <= min_{corner, sigma} max_{vertices v} V_cs(v (1 + t sigma)),
   which is exact when B is one network (its vertices coincide). The minus side enters V_cs only through
   M, and V_cs falls with M, so the plus side is bounded with M at its own box bound (max_sigma min_v M for
   V_lo, min_sigma max_v M for V_hi): still valid, still exact on one network. Likewise V_hi from below,
   either input's headroom from above, the divider current from below (all resistors at the box's top).

5. Search: phase 1 finds the smallest R7 (a box is dropped when no series R7 below the best found fits its
   bounds: R7 >= V_hi/(i_must (1 - m)(1 - t7)) and R7 <= V_lo/(i_no (1 + m)(1 + t7)), or its headroom or
   current bound fails); phase 2, at that R7, the largest worst margin (a box is dropped when its bound
   is no better than the best network found, or it cannot be feasible). Boxes are split in two along the
   dimension of the widest log range; the centre network of every box is evaluated exactly (it is a real
   network), which provides the incumbents. Box bounds are loosened by 1e-9 relative so that rounding
   cannot drop a network; single networks are judged with enumerate_limiter's own formula and slack.
"""
import numpy as np

from handbook.core import series
from handbook.design.schema import defaults

_SIGN = np.array([-1.0, 1.0])
_LOOSE = 1e-9  # relative loosening of the box bounds (a box is never dropped on rounding)


class _Problem:
    pass


def _problem(spec):
    s = {**defaults("current_limiter"), **spec}
    p = _Problem()
    p.s = s
    values = {n: ([float(s[n])] if s.get(n) is not None else series.values(s[n + "_series"], s[n + "_min"], s[n + "_max"]))
              for n in ("r7", "r9", "r10", "r11", "r12", "r13")}
    p.r7s = np.array(values["r7"], dtype=float)
    r9, r10 = np.meshgrid(np.array(values["r9"], dtype=float), np.array(values["r10"], dtype=float), indexing="ij")
    sums, first = np.unique((r9 + r10).ravel(), return_index=True)
    p.pairs = (r9.ravel()[first], r10.ravel()[first])  # one (R9, R10) for every distinct sum
    p.vals = [sums, np.array(values["r11"], float), np.array(values["r12"], float), np.array(values["r13"], float)]
    p.t, p.t7 = float(s["resistor_tolerance"]), float(s["r7_tolerance"])
    vz0 = float(s["zener_voltage"])
    dz = vz0 * s["zener_tolerance"] + s["zener_tc"] * s["temp_span"]
    p.vz = np.array([vz0 - dz, vz0 + dz])
    ib, ios = float(s["input_bias"]), float(s["input_offset_current"])
    vert = [(avg + d / 2, avg - d / 2) for avg in (-ib, ib) for d in (-ios, ios)]  # the datasheet parallelogram
    p.ip = np.array([v[0] for v in vert])
    p.im = np.array([v[1] for v in vert])
    p.vos = np.array([-float(s["offset"]), float(s["offset"])])
    p.i_no, p.i_must, p.m = float(s["i_no_trip"]), float(s["i_must_trip"]), float(s["min_margin"])
    p.head, p.dmax = float(s["input_headroom"]), float(s["divider_current_max"])
    # the preconditions of the monotonicity claims (module docstring, point 3)
    if not (p.vz[0] > 0 and 0 <= p.t < 1 and 0 <= p.t7 < 1 and 1 - p.m > 0 and p.i_no > 0 and p.i_must > 0):
        raise ValueError("exact_limiter: a precondition of its bounds fails (zener, tolerances or margin)")
    if any(len(v) == 0 for v in p.vals) or len(p.r7s) == 0 or min(v.min() for v in p.vals) <= 0 or p.r7s.min() <= 0:
        raise ValueError("exact_limiter: an empty range or a resistor not above zero")
    return p


def _figures(p, lo, hi):
    """For boxes of indices lo..hi (N x 4: S0, R11, R12, R13): an upper bound on V_lo, a lower bound on V_hi
    (trip voltages at R7 = 1 ohm nominal), an upper bound on the headroom, a lower bound on the divider
    current, over every network of the box; exact for a box of one network (module docstring, point 4)."""
    t = p.t
    ends = [np.stack([v[lo[:, d]], v[hi[:, d]]], 1)[:, :, None] * (1 + t * _SIGN) for d, v in enumerate(p.vals)]
    sa, r11a, r12a, r13a = ends  # each (N, end, sign)
    n = len(lo)
    vz = p.vz.reshape(2, 1)
    # minus side: axes (N, end S, end R11, sign S, sign R11, vz, vertex)
    S = sa[:, :, None, :, None, None, None]
    R = r11a[:, None, :, None, :, None, None]
    im = p.im.reshape(1, 1, 1, 1, 1, 1, 4)
    vzm = vz.reshape(1, 1, 1, 1, 1, 2, 1)
    M = (R * (vzm + im * S) / (S + R)).reshape(n, 4, 4, 8)  # (N, vertex of the box, sign, corner)
    m_hi_lb = M.min(axis=1).max(axis=1)  # (N, 8): <= the largest M of every network in the box
    m_lo_ub = M.max(axis=1).min(axis=1)  # (N, 8): >= the smallest M of every network
    head_m = (S * (vzm - im * R) / (S + R)).reshape(n, 4, 4 * 8).max(axis=1).min(axis=1)
    # plus side: axes (N, end R12, end R13, sign R12, sign R13, vz x vertex = 8, vos)
    A = r12a[:, :, None, :, None, None, None]
    B = r13a[:, None, :, None, :, None, None]
    q = 1 + A / B
    ip8 = np.tile(p.ip, 2).reshape(1, 1, 1, 1, 1, 8, 1)
    vz8 = np.repeat(p.vz, 4).reshape(1, 1, 1, 1, 1, 8, 1)
    vos = p.vos.reshape(1, 1, 1, 1, 1, 1, 2)
    base = vz8 + ip8 * A
    v_lo_ub = (base - (m_hi_lb[:, None, None, None, None, :, None] + vos) * q).reshape(n, 4, 4 * 16)
    v_lo_ub = v_lo_ub.max(axis=1).min(axis=1)
    v_hi_lb = (base - (m_lo_ub[:, None, None, None, None, :, None] + vos) * q).reshape(n, 4, 4 * 16)
    v_hi_lb = v_hi_lb.min(axis=1).max(axis=1)
    head_p = (A * (vz8 - ip8 * B) / (A + B)).reshape(n, 4, 4 * 8).max(axis=1).min(axis=1)
    top = [v[hi[:, d]] for d, v in enumerate(p.vals)]
    i_div = p.vz[1] / ((top[0] + top[1]) * (1 - t)) + p.vz[1] / ((top[2] + top[3]) * (1 - t))
    return v_lo_ub, v_hi_lb, np.minimum(head_m, head_p), i_div


def _exact_ok(p, v_lo, v_hi, head, i_div, r7):
    """enumerate_limiter's test, term for term, of single networks at R7 (arrays); (ok, worst margin)."""
    ends = (1 - p.t7, 1 + p.t7)
    lo = np.minimum(v_lo / ends[0], v_lo / ends[1])
    hi = np.maximum(v_hi / ends[0], v_hi / ends[1])
    worst = np.minimum(lo / r7 / p.i_no - 1, 1 - hi / r7 / p.i_must)
    ok = (worst >= p.m - 1e-12) & (head >= p.head - 1e-12) & (lo > 0) & (i_div <= p.dmax * (1 + 1e-12))
    return ok, worst


def _smallest_r7(p, fig):
    """Index of the smallest feasible series R7 of each single network (len(r7s) when none). The high-trip
    test holds from V_hi/(i_must (1 - m)(1 - t7)) up, the low-trip test up to a limit: the feasible R7 are an
    interval, and its first series value is within one index of the threshold's (values are > 1e-9 apart)."""
    v_lo, v_hi, head, i_div = fig
    k = len(p.r7s)
    thr = v_hi / (p.i_must * (1 - p.m + 1e-12) * (1 - p.t7))
    j0 = np.searchsorted(p.r7s, thr * (1 - _LOOSE))
    best = np.full(len(v_lo), k)
    for dj in (1, 0):  # the smaller index wins
        j = np.minimum(j0 + dj, k - 1)
        ok, _ = _exact_ok(p, v_lo, v_hi, head, i_div, p.r7s[j])
        best = np.where(ok & (j0 + dj < k), j0 + dj, best)
    return best


def _box_feasible(p, fig):
    """Headroom and divider-current bounds allow a feasible network in the box; V_lo can be positive."""
    v_lo, _, head, i_div = fig
    return (head >= (p.head - 1e-12) - _LOOSE * abs(p.head)) & (i_div <= p.dmax * (1 + 1e-12) * (1 + _LOOSE)) & (v_lo > 0)


def _r7_window(p, fig):
    """Series indices [j_lo, j_hi] of R7 allowed by the bounds of each box (empty when j_lo > j_hi)."""
    v_lo, v_hi = fig[0], fig[1]
    r_lo = v_hi / (p.i_must * (1 - p.m + 1e-12) * (1 - p.t7))
    r_lo = np.where(r_lo > 0, r_lo * (1 - _LOOSE), r_lo * (1 + _LOOSE))
    r_hi = v_lo / (p.i_no * (1 + p.m - 1e-12) * (1 + p.t7)) * (1 + _LOOSE)
    return np.searchsorted(p.r7s, r_lo, "left"), np.searchsorted(p.r7s, r_hi, "right") - 1


def _margin_ub(p, fig, r7):
    """Upper bound of the worst margin of every network of each box at R7 (and whether one can be feasible)."""
    v_lo, v_hi = fig[0], fig[1]
    up = v_lo / ((1 + p.t7) * r7 * p.i_no) - 1
    dn = 1 - v_hi / ((1 - p.t7) * r7 * p.i_must)
    w = np.minimum(up, dn) + _LOOSE * (1 + np.abs(np.minimum(up, dn)))
    return w, _box_feasible(p, fig) & (w >= p.m - 1e-12)


def _split(p, lo, hi):
    """Each box in two along the dimension of the widest log range (only dimensions with > 1 value)."""
    width = np.stack([np.log(v[hi[:, d]] / v[lo[:, d]]) for d, v in enumerate(p.vals)], 1)
    width = np.where(hi > lo, width + 1e-300, -1.0)
    d = np.argmax(width, axis=1)
    rows = np.arange(len(lo))
    mid = (lo[rows, d] + hi[rows, d]) // 2
    lo1, hi1, lo2, hi2 = lo.copy(), hi.copy(), lo.copy(), hi.copy()
    hi1[rows, d] = mid
    lo2[rows, d] = mid + 1
    return np.concatenate([lo1, lo2]), np.concatenate([hi1, hi2])


def _search(p, keyfn, probefn, chunk):
    """Best-first branch and bound. keyfn(lo, hi, fig) -> (key, alive): a lower bound of the objective over
    the box (smaller is better); probefn(fig of centre networks) -> exact objective of each (inf when
    infeasible). Returns the best objective (inf when none) and the centre indices that reach it."""
    best, arg = np.inf, None
    lo = np.zeros((1, 4), dtype=np.int64)
    hi = np.array([[len(v) - 1 for v in p.vals]], dtype=np.int64)
    pool_lo, pool_hi, pool_key = lo[:0], hi[:0], np.zeros(0)
    boxes = (lo, hi)
    evaluated = 0
    while True:
        lo, hi = boxes
        evaluated += len(lo)
        ctr = (lo + hi) // 2
        val = probefn(_figures(p, ctr, ctr))
        j = int(np.argmin(val)) if len(val) else 0
        if len(val) and val[j] < best:
            best, arg = float(val[j]), ctr[j].copy()
            keep = pool_key < best
            pool_lo, pool_hi, pool_key = pool_lo[keep], pool_hi[keep], pool_key[keep]
        key, alive = keyfn(_figures(p, lo, hi))
        keep = alive & (key < best) & (hi > lo).any(axis=1)
        pool_lo = np.concatenate([pool_lo, lo[keep]])
        pool_hi = np.concatenate([pool_hi, hi[keep]])
        pool_key = np.concatenate([pool_key, key[keep]])
        if not len(pool_key):
            return best, arg, evaluated
        if len(pool_key) > chunk:
            take = np.argpartition(pool_key, chunk)[:chunk]
            rest = np.ones(len(pool_key), bool)
            rest[take] = False
        else:
            take, rest = np.arange(len(pool_key)), np.zeros(len(pool_key), bool)
        boxes = _split(p, pool_lo[take], pool_hi[take])
        pool_lo, pool_hi, pool_key = pool_lo[rest], pool_hi[rest], pool_key[rest]


def exact_limiter(spec, chunk=2048, stats=None):
    """(R7, (R9, R10, R11, R12, R13), worst margin) of the smallest feasible R7 and its best network, or None.
    ``stats``, a dict, receives the number of boxes each phase evaluated."""
    p = _problem(spec)
    k = len(p.r7s)

    def key1(fig):
        j_lo, j_hi = _r7_window(p, fig)
        return j_lo.astype(float), _box_feasible(p, fig) & (j_lo <= j_hi) & (j_lo < k)

    def probe1(fig):
        j = _smallest_r7(p, fig)
        return np.where(j < k, j, np.inf).astype(float)

    j_best, _, n1 = _search(p, key1, probe1, chunk)
    if stats is not None:
        stats["phase1"] = n1
    if not np.isfinite(j_best):
        return None
    r7 = float(p.r7s[int(j_best)])

    def key2(fig):
        w, alive = _margin_ub(p, fig, r7)
        return -w, alive

    def probe2(fig):
        ok, worst = _exact_ok(p, *fig, r7)
        return np.where(ok, -worst, np.inf)

    neg, arg, n2 = _search(p, key2, probe2, chunk)
    if stats is not None:
        stats["phase2"] = n2
    assert np.isfinite(neg), "phase 2 lost the network phase 1 found"
    r9, r10 = p.pairs[0][arg[0]], p.pairs[1][arg[0]]
    net = (float(r9), float(r10), float(p.vals[1][arg[1]]), float(p.vals[2][arg[2]]), float(p.vals[3][arg[3]]))
    return r7, net, -neg
