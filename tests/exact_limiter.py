"""An exact reference for the op-amp current limiter's design over the full E series, sharing no code with
handbook.design.limiter: it reads only the spec's defaults (handbook.design.schema) and the series values
(handbook.core.series), and writes the circuit out again from the node equations.

``exact_limiter(spec)`` returns (R7, (R9, R10, R11, R12, R13), worst margin): the smallest series R7 with
which some network meets the spec and, with that R7, the largest worst margin
min(I_lo/i_no_trip - 1, 1 - I_hi/i_must_trip) of any network (and one network reaching it); None when no
network meets the spec with any R7 of its range. "Meets" is tests/oracles.py:enumerate_limiter's test with
its slack (1e-12): every corner's trip current in [i_no_trip (1 + min_margin), i_must_trip (1 - min_margin)],
both inputs ``input_headroom`` below the zener node, the dividers drawing at most ``divider_current_max``.
The answer is exact (up to the rounding of the figures, ~1e-15 relative): a branch and bound whose every
bound holds for every network of its box and equals the network's own figure on a box of one network.
Nothing is sampled and no local solver is used.

The circuit (the oracle's corners: each resistor at 1 +- t, R7 at 1 +- t7, the zener V_D1 at vz0 +- dz, the
offset at +-V_os, the two bias currents (I_p, I_m) at the four vertices of their datasheet parallelogram):
with S = R9 + R10, q = 1 + R12/R13 (= 1/a, a = R13/(R12 + R13)) and R12||R13 / a = R12,

    M    = V_D1 R11/(S + R11) + I_m S||R11 = R11 (V_D1 + I_m S)/(S + R11)          (minus input above Z)
    V_cs = V_D1 - (M + V_os) q + I_p R12                                           (sense voltage at trip)
    headroom: V_D1 - M = S (V_D1 - I_m R11)/(S + R11) and R12 (V_D1 - I_p R13)/(R12 + R13)
    divider current: V_D1/(S + R11) + V_D1/(R12 + R13)

and a corner's trip current is V_cs / R7_actual, so at R7 the trip currents are (V_lo, V_hi) / R7 divided by
(1 + t7) and (1 - t7), V_lo, V_hi the extremes of V_cs over the corners. A network meets the spec with R7
iff V_lo >= cl R7, V_hi <= cu R7 (cl = i_no (1 + m)(1 + t7), cu = i_must (1 - m)(1 - t7)), its headroom and
its current hold: the R7 that suit a network are an interval.

Proofs of the properties the search rests on (``_problem`` checks their preconditions, every resistor and
both zener ends positive, 0 <= t, t7 < 1, min_margin < 1, and raises ValueError otherwise):

P1  Every figure above is monotone on every axis-parallel line of (S, R11, R12, R13), at every corner:
      dM/dS    = R11 (I_m R11 - V_D1)/(S + R11)^2 : its sign does not depend on S;
      dM/dR11  = S (V_D1 + I_m S)/(S + R11)^2     : its sign does not depend on R11;
      V_cs decreases in M (q > 0); at a fixed M it is linear in R12, and dV_cs/dR13 = (M + V_os) R12/R13^2
      keeps its sign as R13 moves; so V_cs is monotone along each axis (along S and R11 through M);
      minus headroom: d/dS ~ R11 (V_D1 - I_m R11), d/dR11 ~ -S (V_D1 + I_m S); plus headroom likewise with
      (R12, R13, I_p); the divider current falls with every resistor.
    The same holds after scaling each coordinate by a positive constant (a tolerance corner), and for any
    function of the form f(x (1 + t sigma)) with sigma fixed.
P2  A function monotone on every axis line reaches its max and min over a box at vertices (move one
    coordinate at a time to its better end; the value never gets worse).
P3  (R9, R10) enter only through S, and by P1 every corner's figure is extreme at S0 (1 - t) or S0 (1 + t)
    (S0 = R9 + R10 nominal): the corners with R9, R10 going opposite ways lie in between. So a network is
    (S0, R11, R12, R13), S0 from the sorted distinct sums of the two series; the oracle's 2^5 resistor
    corners reduce to 2^4.
P4  Vertex bounds (``_box_bounds``): over a box B of nominal values, for each fixed tolerance sign vector
    sigma, x -> V_cs(x (1 + t sigma)) is monotone on axis lines (P1), so by P2
      max_{x in B} V_lo(x) <= min_{corner, sigma} max_{v vertex of B} V_cs(v (1 + t sigma)),
    exact when B holds one network. M, the only way the minus divider enters V_cs, is bounded first
    (max_sigma min_v M from below for V_lo, min_sigma max_v M from above for V_hi): V_cs falls with M, so
    the bound stays valid and stays exact on one network. Headroom and divider current likewise.
P5  Pair bounds (``_pair_lb``): for corners i, j and beta >= 0, V_hi - beta V_lo >= V_i - beta V_j, and with
    rho = S/R11, u = R12/R13 and each corner's factors c = a_S/a_11, d = a_12/a_13,
      V = V_D1 - V_D1 (1 + u d)/(1 + rho c) - V_os (1 + u d) - I_m S||R11 q + I_p R12 a_12.
    The zener and offset terms F(rho, u) of V_i - beta V_j are linear in u and, at a fixed u, of the form
    K - P/(1 + rho c_i) + Q/(1 + rho c_j) with P, Q >= 0, whose stationary points satisfy
    sqrt(P c_i)(1 + rho c_j) = sqrt(Q c_j)(1 + rho c_i), linear in rho: one at most. F's minimum over the
    box's (rho, u) rectangle is therefore at u's ends and at rho's ends or that point, exactly. Each bias
    term is a product of non-negative factors monotone on axis lines, bounded at two vertices. The level
    V_cs changes fast across a box (by far more than the spread when the two dividers nearly balance) but
    largely cancels in V_i - beta V_j (beta ~ the two corners' V_D1 (1 + u d)/(1 + rho c) ratio), so these
    bounds prune where P4's cannot: a network feasible at R7 has V_i - beta V_j <= (cu - beta cl) R7, and
    at the chosen R7 its worst margin w has V_i - beta V_j <= B (1 - w) - beta A (1 + w)
    (A = (1 + t7) R7 i_no, B = (1 - t7) R7 i_must).
P6  Tightening (``_tighten``): a network that can improve on the incumbent has V_j >= L and V_i <= U
    (thresholds from the incumbent). Along one axis, the other three coordinates anywhere in the box,
    "some network of the box with this coordinate passes" holds iff it holds at one of the 8 vertices of
    the other three (P1, P2), and at each vertex the passing indices form a ray (P1). The ray's end is
    solved from the node equation for that one resistor and then checked by evaluating V just outside it;
    a failed check drops the ray's cut (never a network). The box keeps the union of the rays.

Search (``_search``, best first): phase 1 finds the smallest R7 (a box is dropped when no series R7 below
the best found fits its bounds, P4, P5), phase 2 the largest worst margin at that R7 (a box is dropped when
its bound is no better than the best network found). Boxes are tightened (P6), bounded (P4, P5) and split
in two along the dimension with the widest weighted log range (S and R11 weighted down: the tightening
narrows S, and the level depends on S/R11). The centre network of every box is evaluated exactly and
judged with enumerate_limiter's own formula; it supplies the incumbents. Box bounds are loosened by 1e-9
(relative, and to the zener voltage's scale where a figure may be near zero) so that rounding cannot drop a
network.
"""
import numpy as np

from handbook.core import series
from handbook.design.schema import defaults

_SIGN = np.array([-1.0, 1.0])
_LOOSE = 1e-9  # loosening of every box bound against rounding
_SPLIT_WEIGHT = np.array([0.25, 0.5, 1.0, 1.0])  # of each dimension's log range when choosing the split
_TIGHTEN_MIN = 4  # a dimension is tightened when the box holds at least this many of its values


class _Problem:
    """The spec's figures, the candidate values and every corner's parameters."""


def _problem(spec):
    s = {**defaults("current_limiter"), **spec}
    p = _Problem()
    p.s = s
    values = {n: ([float(s[n])] if s.get(n) is not None else series.values(s[n + "_series"], s[n + "_min"], s[n + "_max"]))
              for n in ("r7", "r9", "r10", "r11", "r12", "r13")}
    p.empty = any(len(v) == 0 for v in values.values())
    if p.empty:
        return p
    if min(min(v) for v in values.values()) <= 0:
        raise ValueError("exact_limiter: a resistor not above zero")
    p.r7s = np.array(values["r7"], dtype=float)
    r9, r10 = np.meshgrid(np.array(values["r9"], float), np.array(values["r10"], float), indexing="ij")
    sums, first = np.unique((r9 + r10).ravel(), return_index=True)
    p.pairs = (r9.ravel()[first], r10.ravel()[first])  # one (R9, R10) of every distinct sum
    p.vals = [sums] + [np.array(values[n], float) for n in ("r11", "r12", "r13")]
    p.t, p.t7 = float(s["resistor_tolerance"]), float(s["r7_tolerance"])
    vz0 = float(s["zener_voltage"])
    dz = vz0 * s["zener_tolerance"] + s["zener_tc"] * s["temp_span"]
    p.vz = np.array([vz0 - dz, vz0 + dz])
    ib, ios = float(s["input_bias"]), float(s["input_offset_current"])
    vert = [(avg + d / 2, avg - d / 2) for avg in (-ib, ib) for d in (-ios, ios)]  # (I_p, I_m)
    p.ip, p.im = np.array([v[0] for v in vert]), np.array([v[1] for v in vert])
    p.vos = np.array([-float(s["offset"]), float(s["offset"])])
    p.i_no, p.i_must, p.m = float(s["i_no_trip"]), float(s["i_must_trip"]), float(s["min_margin"])
    p.head, p.dmax = float(s["input_headroom"]), float(s["divider_current_max"])
    if not (p.vz[0] > 0 and 0 <= p.t < 1 and 0 <= p.t7 < 1 and p.m < 1 and p.i_no > 0 and p.i_must > 0):
        raise ValueError("exact_limiter: a precondition of its bounds fails (zener, tolerances or margin)")
    # the 256 corners of one network, in the order of _corners: tolerance signs of S, R11, R12, R13, the
    # zener end, the bias vertex, the offset's sign
    g = np.array(np.meshgrid(_SIGN, _SIGN, _SIGN, _SIGN, [0, 1], [0, 1, 2, 3], [0, 1], indexing="ij")).reshape(7, -1)
    p.cs = [1 + p.t * g[d] for d in range(4)]
    p.cvz, p.cim, p.cip = p.vz[g[4].astype(int)], p.im[g[5].astype(int)], p.ip[g[5].astype(int)]
    p.cvos = p.vos[g[6].astype(int)]
    # R7 suits a network iff V_lo >= cl R7 and V_hi <= cu R7 (enumerate_limiter's test and slack)
    p.cl = p.i_no * (1 + p.m - 1e-12) * (1 + p.t7)
    p.cu = p.i_must * (1 - p.m + 1e-12) * (1 - p.t7)
    return p


def _corners(p, S, R11, R12, R13):
    """Every corner's trip voltage at R7 = 1 (N x 256, corners ordered as in _problem) of single networks,
    their least headroom and their largest divider current; the two dividers apart, then broadcast."""
    sg = 1 + p.t * _SIGN
    vz = p.vz[:, None]
    Sa = S[:, None, None, None, None] * sg[:, None, None, None]  # (N, sign S, sign R11, vz, bias vertex)
    Ra = R11[:, None, None, None, None] * sg[:, None, None]
    M = Ra * (vz + p.im * Sa) / (Sa + Ra)
    head_m = (Sa * (vz - p.im * Ra) / (Sa + Ra)).reshape(len(S), -1).min(axis=1)
    Aa = R12[:, None, None, None, None] * sg[:, None, None, None]  # (N, sign R12, sign R13, vz, bias vertex)
    Ba = R13[:, None, None, None, None] * sg[:, None, None]
    head_p = (Aa * (vz - p.ip * Ba) / (Aa + Ba)).reshape(len(S), -1).min(axis=1)
    q = (1 + Aa / Ba)[:, None, None, :, :, :, :, None]  # (N, sS, s11, s12, s13, vz, b, vos)
    V = vz[..., None] + (p.ip * Aa)[:, None, None, :, :, :, :, None] - (M[:, :, :, None, None, :, :, None] + p.vos) * q
    i_div = p.vz[1] / ((S + R11) * (1 - p.t)) + p.vz[1] / ((R12 + R13) * (1 - p.t))
    return V.reshape(len(S), 256), np.minimum(head_m, head_p), i_div


def _corner_v(p, k, S, R, A, B):
    """Trip voltage of corner k (an index array) at nominal S, R11, R12, R13 (arrays of k's shape)."""
    Sa, Ra, Aa, Ba = S * p.cs[0][k], R * p.cs[1][k], A * p.cs[2][k], B * p.cs[3][k]
    return p.cvz[k] - (Ra * (p.cvz[k] + p.cim[k] * Sa) / (Sa + Ra) + p.cvos[k]) * (1 + Aa / Ba) + p.cip[k] * Aa


def _box_bounds(p, lo, hi):
    """P4 over boxes of indices lo..hi (N x 4: S0, R11, R12, R13): an upper bound on V_lo, a lower bound on
    V_hi, an upper bound on the headroom, a lower bound on the divider current; and the box's end values."""
    n = len(lo)
    sg = 1 + p.t * _SIGN
    ends = [np.stack([v[lo[:, d]], v[hi[:, d]]], 1) for d, v in enumerate(p.vals)]
    # minus divider: (N, end S, end R11, sign S, sign R11, vz, bias vertex)
    S = ends[0][:, :, None, None, None, None, None] * sg[:, None, None, None]
    R = ends[1][:, None, :, None, None, None, None] * sg[:, None, None]
    vz = p.vz[:, None]
    M = (R * (vz + p.im * S) / (S + R)).reshape(n, 4, 4, 8)  # (N, vertex, sign, vz x bias vertex)
    m_hi_lb = M.min(axis=1).max(axis=1)  # <= every network's largest M
    m_lo_ub = M.max(axis=1).min(axis=1)  # >= every network's smallest M
    head_m = (S * (vz - p.im * R) / (S + R)).reshape(n, 4, 32).max(axis=1).min(axis=1)
    # plus divider: (N, end R12, end R13, sign R12, sign R13, vz x bias vertex, vos)
    A = ends[2][:, :, None, None, None, None, None] * sg[:, None, None, None]
    B = ends[3][:, None, :, None, None, None, None] * sg[:, None, None]
    vz8 = np.repeat(p.vz, 4)[:, None]
    ip8 = np.tile(p.ip, 2)[:, None]
    q = 1 + A / B
    base = vz8 + ip8 * A
    v_lo = (base - (m_hi_lb[:, None, None, None, None, :, None] + p.vos) * q).reshape(n, 4, 64).max(axis=1).min(axis=1)
    v_hi = (base - (m_lo_ub[:, None, None, None, None, :, None] + p.vos) * q).reshape(n, 4, 64).min(axis=1).max(axis=1)
    head_p = (A * (vz8 - ip8 * B) / (A + B))[..., 0].reshape(n, 4, 32).max(axis=1).min(axis=1)
    top = [e[:, 1] for e in ends]
    i_div = p.vz[1] / ((top[0] + top[1]) * (1 - p.t)) + p.vz[1] / ((top[2] + top[3]) * (1 - p.t))
    return v_lo, v_hi, np.minimum(head_m, head_p), i_div, ends


def _pair_lb(p, ends, i, j, beta):
    """P5: a lower bound over each box of V_i - beta V_j (i, j: a corner index per box; beta >= 0)."""
    (S0, S1), (R0, R1), (A0, A1), (B0, B1) = ((e[:, 0], e[:, 1]) for e in ends)
    rho = (S0 / R1, S1 / R0)
    u = (A0 / B1, A1 / B0)
    ci, cj = p.cs[0][i] / p.cs[1][i], p.cs[0][j] / p.cs[1][j]
    di, dj = p.cs[2][i] / p.cs[3][i], p.cs[2][j] / p.cs[3][j]
    vzi, vzj, vosi, vosj = p.cvz[i], p.cvz[j], p.cvos[i], p.cvos[j]
    low = np.full(len(S0), np.inf)
    for ue in u:  # F is linear in u: its minimum is at an end
        P, Q = vzi * (1 + ue * di), beta * vzj * (1 + ue * dj)
        K = vzi - beta * vzj - vosi * (1 + ue * di) + beta * vosj * (1 + ue * dj)
        sp, sq = np.sqrt(P * ci), np.sqrt(Q * cj)
        den = sp * cj - sq * ci
        with np.errstate(divide="ignore", invalid="ignore"):
            star = np.where(den != 0, (sq - sp) / den, rho[0])  # the one stationary point in rho
        star = np.clip(np.nan_to_num(star, nan=rho[0], posinf=rho[1], neginf=rho[0]), rho[0], rho[1])
        for r in (rho[0], rho[1], star):
            low = np.minimum(low, K - P / (1 + r * ci) + Q / (1 + r * cj))

    # bias terms: -I_m,i (S||R11 q)_i + beta I_m,j (S||R11 q)_j + R12 (I_p,i a_12,i - beta I_p,j a_12,j);
    # S||R11 q >= 0 rises with S and R11, q rises with R12 and falls with R13: the product spans
    # [its value at (S0, R0, A0, B1), its value at (S1, R1, A1, B0)]
    def rq(k, S, R, A, B):
        Sa, Ra = S * p.cs[0][k], R * p.cs[1][k]
        return Sa * Ra / (Sa + Ra) * (1 + A * p.cs[2][k] / (B * p.cs[3][k]))
    for k, coef in ((i, -p.cim[i]), (j, beta * p.cim[j])):
        low = low + np.minimum(coef * rq(k, S0, R0, A0, B1), coef * rq(k, S1, R1, A1, B0))
    coef = p.cip[i] * p.cs[2][i] - beta * p.cip[j] * p.cs[2][j]
    low = low + np.minimum(coef * A0, coef * A1)
    return low - _LOOSE * 2 * (1 + beta) * p.vz[1] * (1 + 2 * u[1])


def _crossing(p, d, k, x, thr):
    """Where corner k's V meets thr along dimension d with the other coordinates at x (a list of four
    arrays, x[d] unused): the node equation solved for that one resistor (nominal value; may be nan)."""
    a = [c[k] for c in p.cs]
    vz, im, ip, vos = p.cvz[k], p.cim[k], p.cip[k], p.cvos[k]
    Sa, Ra, Aa, Ba = (None if e == d else x[e] * a[e] for e in range(4))
    with np.errstate(divide="ignore", invalid="ignore"):
        if d <= 1:  # V = thr  <=>  M = T
            T = (vz + ip * Aa - thr) / (1 + Aa / Ba) - vos
            if d == 0:  # R (vz + i S) = T (S + R)
                return Ra * (vz - T) / (T - Ra * im) / a[0]
            return T * Sa / (vz + im * Sa - T) / a[1]
        M = Ra * (vz + im * Sa) / (Sa + Ra) + vos
        if d == 2:  # V = vz - M - R12 (M/R13 - I_p)
            return (vz - M - thr) / (M / Ba - ip) / a[2]
        return M * Aa / (vz - M + ip * Aa - thr) / a[3]  # V = vz - M - M R12/R13 + I_p R12


def _tighten(p, lo, hi, i, j, L, U):
    """P6: shrink each box, one dimension at a time, to the indices where some network of the box could
    have V_j >= L and V_i <= U. Returns the new ranges and whether the box still holds a candidate."""
    alive = np.ones(len(lo), bool)
    lo, hi = lo.copy(), hi.copy()
    grid = np.array(np.meshgrid([0, 1], [0, 1], [0, 1], indexing="ij")).reshape(3, 8)
    for d in range(4):
        rows = np.flatnonzero(alive & (hi[:, d] - lo[:, d] >= _TIGHTEN_MIN - 1))
        if not len(rows):
            continue
        vals = p.vals[d]
        lo_r, hi_r = lo[rows], hi[rows]
        pts = [None] * 4  # the other three coordinates at the 8 vertices: (n, 8) each
        for e, g in zip([e for e in range(4) if e != d], grid):
            pts[e] = p.vals[e][np.where(g[None, :] == 0, lo_r[:, e:e + 1], hi_r[:, e:e + 1])]
        a0, b0 = np.repeat(lo_r[:, d:d + 1], 8, 1), np.repeat(hi_r[:, d:d + 1], 8, 1)
        new_lo, new_hi, ok = lo_r[:, d].copy(), hi_r[:, d].copy(), np.ones(len(rows), bool)
        for k, thr, sgn in ((j[rows], L[rows], 1.0), (i[rows], U[rows], -1.0)):  # the test: sgn V >= sgn thr
            kk, tt = np.repeat(k[:, None], 8, 1), np.repeat(thr[:, None], 8, 1)

            def passes(idx):
                x = list(pts)
                x[d] = vals[idx]
                return sgn * _corner_v(p, kk, *x) >= sgn * tt
            f_lo, f_hi = passes(a0), passes(b0)
            up, dn, full = ~f_lo & f_hi, f_lo & ~f_hi, f_lo & f_hi  # the passing indices: a ray up, down, all
            xs = _crossing(p, d, kk, pts, tt)
            xs = np.where(np.isfinite(xs), xs, vals[0])
            k_up = np.clip(np.searchsorted(vals, xs, "left"), a0 + 1, np.maximum(b0, a0 + 1))
            k_up = np.where(up & passes(np.minimum(k_up - 1, b0)), a0, k_up)  # the index below must fail
            k_dn = np.clip(np.searchsorted(vals, xs, "right") - 1, np.minimum(a0, b0 - 1), b0 - 1)
            k_dn = np.where(dn & passes(np.maximum(k_dn + 1, a0)), b0, k_dn)  # the index above must fail
            any_up, any_dn, any_full = up.any(axis=1), dn.any(axis=1), full.any(axis=1)
            only_up = any_up & ~any_dn & ~any_full
            only_dn = any_dn & ~any_up & ~any_full
            new_lo = np.where(only_up, np.maximum(new_lo, np.where(up, k_up, np.iinfo(np.int64).max).min(axis=1)), new_lo)
            new_hi = np.where(only_dn, np.minimum(new_hi, np.where(dn, k_dn, -1).max(axis=1)), new_hi)
            ok &= any_up | any_dn | any_full  # no vertex passes at either end: none passes anywhere
        ok &= new_lo <= new_hi
        alive[rows] = ok
        lo[rows, d], hi[rows, d] = np.where(ok, new_lo, lo_r[:, d]), np.where(ok, new_hi, hi_r[:, d])
    return lo, hi, alive


def _split(lo, hi, p):
    """Each box in two along the dimension of the widest weighted log range (of those with > 1 value)."""
    width = np.stack([np.log(v[hi[:, d]] / v[lo[:, d]]) for d, v in enumerate(p.vals)], 1)
    width = np.where(hi > lo, width * _SPLIT_WEIGHT + 1e-300, -1.0)
    d = np.argmax(width, axis=1)
    rows = np.arange(len(lo))
    mid = (lo[rows, d] + hi[rows, d]) // 2
    lo1, hi1, lo2, hi2 = lo.copy(), hi.copy(), lo.copy(), hi.copy()
    hi1[rows, d] = mid
    lo2[rows, d] = mid + 1
    return np.concatenate([lo1, lo2]), np.concatenate([hi1, hi2])


def _exact_ok(p, v_lo, v_hi, head, i_div, r7):
    """enumerate_limiter's test of single networks at R7, term for term: (ok, worst margin)."""
    ends = (1 - p.t7, 1 + p.t7)
    lo = np.minimum(v_lo / ends[0], v_lo / ends[1])
    hi = np.maximum(v_hi / ends[0], v_hi / ends[1])
    worst = np.minimum(lo / r7 / p.i_no - 1, 1 - hi / r7 / p.i_must)
    ok = (worst >= p.m - 1e-12) & (head >= p.head - 1e-12) & (lo > 0) & (i_div <= p.dmax * (1 + 1e-12))
    return ok, worst


def _smallest_r7(p, v_lo, v_hi, head, i_div):
    """Index of the smallest series R7 with which each single network passes (len(r7s) when none). The
    high-trip test holds from V_hi/cu up and the low-trip test up to V_lo/cl, so only the first value at or
    above V_hi/cu can be the answer (that one or the next, whichever rounding decides)."""
    k = len(p.r7s)
    j0 = np.searchsorted(p.r7s, v_hi / p.cu * (1 - _LOOSE))
    best = np.full(len(v_lo), k)
    for dj in (1, 0):  # the smaller index wins
        j = np.minimum(j0 + dj, k - 1)
        ok, _ = _exact_ok(p, v_lo, v_hi, head, i_div, p.r7s[j])
        best = np.where(ok & (j0 + dj < k), j0 + dj, best)
    return best


def _feasible_box(p, v_lo_ub, head_ub, i_div_lb):
    return ((head_ub >= p.head - 1e-12 - _LOOSE * (1 + abs(p.head))) & (i_div_lb <= p.dmax * (1 + 1e-12) * (1 + _LOOSE))
            & (v_lo_ub > 0))


def _search(p, keyfn, probefn, thrfn, chunk, max_boxes):
    """Best-first branch and bound over boxes of indices (objective: smaller is better).
    keyfn(v_lo_ub, v_hi_lb, head_ub, i_div_lb, pairs) -> (key, alive): a lower bound of the objective over
    each box and whether it can hold a feasible network; probefn(v_lo, v_hi, head, i_div) -> the exact
    objective of single networks (inf when infeasible); thrfn(parent keys, best) -> (L, U): a network that
    improves on the best has V_lo >= L and V_hi <= U. Returns (best, its indices, boxes evaluated)."""
    state = {"best": np.inf, "arg": None}
    lo = np.zeros((1, 4), dtype=np.int64)
    hi = np.array([[len(v) - 1 for v in p.vals]], dtype=np.int64)
    pkey = np.array([-np.inf])
    pool_lo, pool_hi, pool_key = lo[:0], hi[:0], np.zeros(0)
    evaluated = 0

    def probe(lo, hi):  # the centre network of each box, exactly
        ctr = (lo + hi) // 2
        V, head, i_div = _corners(p, *[v[ctr[:, d]] for d, v in enumerate(p.vals)])
        val = probefn(V.min(axis=1), V.max(axis=1), head, i_div)
        if len(val) and val.min() < state["best"]:
            k = int(np.argmin(val))
            state["best"], state["arg"] = float(val[k]), ctr[k].copy()
        return V

    while True:
        evaluated += len(lo)
        if max_boxes and evaluated > max_boxes:
            raise RuntimeError(f"exact_limiter: more than {max_boxes} boxes")
        V = probe(lo, hi)
        split = (hi > lo).any(axis=1)  # a box of one network is done: its centre was it
        lo, hi, V, pkey = lo[split], hi[split], V[split], pkey[split]
        if len(lo):
            i, j = V.argmax(axis=1), V.argmin(axis=1)  # the centre's highest and lowest corners
            L, U = thrfn(pkey, state["best"])
            lo2, hi2, alive = _tighten(p, lo, hi, i, j, L, U)
            single = alive & (lo2 == hi2).all(axis=1) & ((lo2 != lo) | (hi2 != hi)).any(axis=1)
            if single.any():
                probe(lo2[single], hi2[single])  # tightened down to one network: evaluate it
            keep = alive & (hi2 > lo2).any(axis=1)
            lo, hi, i, j, V = lo2[keep], hi2[keep], i[keep], j[keep], V[keep]
            rows = np.arange(len(lo))
            v_lo, v_hi, head_ub, i_div_lb, ends = _box_bounds(p, lo, hi)
            # beta = 1 (the spread), the zener ends' ratio, and the ratio cancelling the level's change
            # at the centre, V_D1 (1 + u d)/(1 + rho c) of corner i over corner j
            betas = [np.ones(len(lo)), p.cvz[i] / p.cvz[j]]
            with np.errstate(divide="ignore", invalid="ignore"):
                b = (p.cvz[i] - V[rows, i]) / (p.cvz[j] - V[rows, j])
            betas.append(np.where(np.isfinite(b) & (b > 0), b, 1.0))
            pairs = [(b, _pair_lb(p, ends, i, j, b)) for b in betas]
            key, ok = keyfn(v_lo, v_hi, head_ub, i_div_lb, pairs)
            keep = ok & (key < state["best"])
            pool_lo = np.concatenate([pool_lo, lo[keep]])
            pool_hi = np.concatenate([pool_hi, hi[keep]])
            pool_key = np.concatenate([pool_key, key[keep]])
        keep = pool_key < state["best"]
        pool_lo, pool_hi, pool_key = pool_lo[keep], pool_hi[keep], pool_key[keep]
        if not len(pool_key):
            return state["best"], state["arg"], evaluated
        take = np.argpartition(pool_key, chunk)[:chunk] if len(pool_key) > chunk else np.arange(len(pool_key))
        rest = np.ones(len(pool_key), bool)
        rest[take] = False
        lo, hi = _split(pool_lo[take], pool_hi[take], p)
        pkey = np.concatenate([pool_key[take], pool_key[take]])
        pool_lo, pool_hi, pool_key = pool_lo[rest], pool_hi[rest], pool_key[rest]


def exact_limiter(spec, stats=None, chunk=2048, max_boxes=None):
    """(R7, (R9, R10, R11, R12, R13), worst margin) of the smallest feasible series R7 and the best network
    with it, or None when nothing is feasible. ``stats`` (a dict) receives the boxes each phase evaluated;
    ``max_boxes`` makes it raise RuntimeError beyond that many."""
    p = _problem(spec)
    if p.empty:
        return None
    k = len(p.r7s)

    def key1(v_lo, v_hi, head, i_div, pairs):  # the smallest R7 index the box allows
        j_lo = np.searchsorted(p.r7s, np.where(v_hi > 0, v_hi * (1 - _LOOSE), v_hi * (1 + _LOOSE)) / p.cu, "left")
        j_hi = np.searchsorted(p.r7s, v_lo * (1 + _LOOSE) / p.cl, "right") - 1
        ok = np.ones(len(v_lo), bool)
        for beta, lb in pairs:  # V_i - beta V_j <= (cu - beta cl) R7
            c = p.cu - beta * p.cl
            with np.errstate(divide="ignore", invalid="ignore"):
                x = lb / c
            j_lo = np.where(c > 0, np.maximum(j_lo, np.searchsorted(p.r7s, np.where(c > 0, x, 0), "left")), j_lo)
            j_hi = np.where(c < 0, np.minimum(j_hi, np.searchsorted(p.r7s, np.where(c < 0, x, 0), "right") - 1), j_hi)
            ok &= (c != 0) | (lb <= 0)
        return j_lo.astype(float), ok & _feasible_box(p, v_lo, head, i_div) & (j_lo <= j_hi) & (j_lo < k)

    def probe1(v_lo, v_hi, head, i_div):
        j = _smallest_r7(p, v_lo, v_hi, head, i_div)
        return np.where(j < k, j, np.inf).astype(float)

    def thr1(pkey, best):  # an improving network suits some R7 index in [parent's key, best - 1]
        jl = np.clip(np.nan_to_num(pkey, neginf=0.0), 0, k - 1).astype(int)
        jh = int(min(best - 1, k - 1)) if np.isfinite(best) else k - 1
        L, U = p.cl * p.r7s[jl], np.full(len(pkey), p.cu * p.r7s[max(jh, 0)])
        return L - _LOOSE * (np.abs(L) + p.vz[1]), U + _LOOSE * (np.abs(U) + p.vz[1])

    j_best, _, n1 = _search(p, key1, probe1, thr1, chunk, max_boxes)
    if stats is not None:
        stats["phase1"] = n1
    if not np.isfinite(j_best):
        return None
    r7 = float(p.r7s[int(j_best)])
    A, B = (1 + p.t7) * r7 * p.i_no, (1 - p.t7) * r7 * p.i_must

    def key2(v_lo, v_hi, head, i_div, pairs):  # minus the largest worst margin the box allows
        w = np.minimum(v_lo / A - 1, 1 - v_hi / B)
        for beta, lb in pairs:  # V_i <= B (1 - w), V_j >= A (1 + w)
            w = np.minimum(w, (B - beta * A - lb) / (B + beta * A))
        w = w + _LOOSE * (1 + np.abs(w))
        return -w, _feasible_box(p, v_lo, head, i_div) & (w >= p.m - 1e-12)

    def probe2(v_lo, v_hi, head, i_div):
        ok, worst = _exact_ok(p, v_lo, v_hi, head, i_div, r7)
        return np.where(ok, -worst, np.inf)

    def thr2(pkey, best):  # an improving network has a larger worst margin
        w = -best if np.isfinite(best) else p.m - 1e-12
        L, U = np.full(len(pkey), A * (1 + w)), np.full(len(pkey), B * (1 - w))
        return L - _LOOSE * (np.abs(L) + p.vz[1]), U + _LOOSE * (np.abs(U) + p.vz[1])

    neg, arg, n2 = _search(p, key2, probe2, thr2, chunk, max_boxes)
    if stats is not None:
        stats["phase2"] = n2
    if not np.isfinite(neg):
        raise AssertionError("exact_limiter: phase 2 lost the network phase 1 found")
    net = (float(p.pairs[0][arg[0]]), float(p.pairs[1][arg[0]])) + tuple(float(p.vals[d][arg[d]]) for d in (1, 2, 3))
    return r7, net, -neg
