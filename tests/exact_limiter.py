import numpy as np

from handbook.core import series
from handbook.design.schema import defaults

_SIGN = np.array([-1.0, 1.0])
_LOOSE = 1e-9
_FIELDS = ("a11", "b11", "sl", "sh", "r1", "r2", "a13", "b13", "pl", "ph", "u1", "u2")


class _Problem:
    pass


def _problem(spec):
    s = {**defaults("current_limiter"), **spec}
    p = _Problem()
    p.s = s
    values = {n: ([float(s[n])] if s.get(n) is not None else series.values(s[n + "_series"], s[n + "_min"], s[n + "_max"]))
              for n in ("r7", "r9", "r10", "r11", "r12", "r13")}
    if any(len(v) == 0 for v in values.values()) or min(min(v) for v in values.values()) <= 0:
        raise ValueError("exact_limiter: an empty range or a resistor not above zero")
    p.r7s = np.array(values["r7"], dtype=float)
    r9, r10 = np.meshgrid(np.array(values["r9"], float), np.array(values["r10"], float), indexing="ij")
    p.sums, first = np.unique((r9 + r10).ravel(), return_index=True)
    p.pairs = (r9.ravel()[first], r10.ravel()[first])
    p.r11, p.r12, p.r13 = (np.array(values[n], float) for n in ("r11", "r12", "r13"))
    gap = lambda v: float(np.log(v[1:] / v[:-1]).max()) if len(v) > 1 else np.inf  # noqa: E731
    p.gap_s, p.gap_12 = gap(p.sums), gap(p.r12)
    p.t, p.t7 = float(s["resistor_tolerance"]), float(s["r7_tolerance"])
    vz0 = float(s["zener_voltage"])
    dz = vz0 * s["zener_tolerance"] + s["zener_tc"] * s["temp_span"]
    p.vz0, p.vz = vz0, np.array([vz0 - dz, vz0 + dz])
    ib, ios = float(s["input_bias"]), float(s["input_offset_current"])
    vert = [(avg + d / 2, avg - d / 2) for avg in (-ib, ib) for d in (-ios, ios)]
    p.ip, p.im = np.array([v[0] for v in vert]), np.array([v[1] for v in vert])
    p.imax = abs(ib) + abs(ios) / 2
    p.vos = np.array([-float(s["offset"]), float(s["offset"])])
    p.i_no, p.i_must, p.m = float(s["i_no_trip"]), float(s["i_must_trip"]), float(s["min_margin"])
    p.head, p.dmax = float(s["input_headroom"]), float(s["divider_current_max"])
    if not (p.vz[0] > 0 and 0 <= p.t < 1 and 0 <= p.t7 < 1 and p.m < 1 and p.i_no > 0 and p.i_must > 0):
        raise ValueError("exact_limiter: a precondition of its bounds fails (zener, tolerances or margin)")
    return p


def _figures(p, Sv, Rv, Av, Bv):
    """Bounds over boxes given by their vertices (N x 4 each: S, R11 of the minus side's four vertices, R12,
    R13 of the plus side's): (V_lo upper, V_hi lower, headroom upper, divider current lower)."""
    t, n = p.t, len(Sv)
    sg = 1 + t * _SIGN
    # minus side: (N, vertex, sign S, sign R11, vz, bias vertex)
    S = Sv[:, :, None, None, None, None] * sg[:, None, None, None]
    R = Rv[:, :, None, None, None, None] * sg[:, None, None]
    vz = p.vz[:, None]
    M = (R * (vz + p.im * S) / (S + R)).reshape(n, 4, 4, 8)
    m_hi_lb = M.min(axis=1).max(axis=1)  # (N, 8) <= every network's largest M
    m_lo_ub = M.max(axis=1).min(axis=1)  # (N, 8) >= every network's smallest M
    head_m = (S * (vz - p.im * R) / (S + R)).reshape(n, 4, 32).max(axis=1).min(axis=1)
    # plus side: (N, vertex, sign R12, sign R13, vz x bias vertex, vos)
    A = Av[:, :, None, None, None, None] * sg[:, None, None, None]
    B = Bv[:, :, None, None, None, None] * sg[:, None, None]
    vz8 = np.repeat(p.vz, 4)[:, None]
    ip8 = np.tile(p.ip, 2)[:, None]
    q = 1 + A / B
    base = vz8 + ip8 * A
    v_lo = (base - (m_hi_lb[:, None, None, None, :, None] + p.vos) * q).reshape(n, 4, 64).max(axis=1).min(axis=1)
    v_hi = (base - (m_lo_ub[:, None, None, None, :, None] + p.vos) * q).reshape(n, 4, 64).min(axis=1).max(axis=1)
    head_p = (A * (vz8 - ip8 * B) / (A + B))[..., 0].reshape(n, 4, 32).max(axis=1).min(axis=1)
    i_div = (p.vz[1] / ((Sv + Rv) * (1 - t))).min(axis=1) + (p.vz[1] / ((Av + Bv) * (1 - t))).min(axis=1)
    return v_lo, v_hi, np.minimum(head_m, head_p), i_div


class _Boxes(dict):
    def take(self, sel):
        return _Boxes({k: v[sel] for k, v in self.items()})

    def __len__(self):
        return len(self["a11"])

    @staticmethod
    def cat(parts):
        return _Boxes({k: np.concatenate([b[k] for b in parts]) for k in _FIELDS})


def _index_ranges(b, p):
    """Single-R11 (single-R13) boxes: the indices of the sums (R12) their ratio range holds, sums in
    [fl(r1 R11), fl(r2 R11)] (the membership rule, monotone in r, so that splits lose nothing); the ratio
    range shrunk to what they hold. Returns the boxes without the empty ones."""
    keep = np.ones(len(b), bool)
    for a, z, lo, hi, r1, r2, mag, vals in (("a11", "b11", "sl", "sh", "r1", "r2", p.r11, p.sums),
                                            ("a13", "b13", "pl", "ph", "u1", "u2", p.r13, p.r12)):
        new = (b[a] == b[z]) & (b[lo] < 0)
        if new.any():
            R = mag[b[a][new]]
            i = np.searchsorted(vals, b[r1][new] * R, "left")
            j = np.searchsorted(vals, b[r2][new] * R, "right") - 1
            b[lo][new], b[hi][new] = i, j
            keep[np.flatnonzero(new)[i > j]] = False
        single = (b[a] == b[z]) & (b[lo] >= 0) & (b[lo] <= b[hi])
        R = mag[b[a][single]]
        b[r1][single] = vals[b[lo][single]] / R
        b[r2][single] = vals[b[hi][single]] / R
    return b.take(keep)


def _vertices(b, p):
    single_m = b["a11"] == b["b11"]
    Ra, Rb = p.r11[b["a11"]], p.r11[b["b11"]]
    Sv = np.stack([b["r1"] * Ra, b["r1"] * Rb, b["r2"] * Ra, b["r2"] * Rb], 1)
    Rv = np.stack([Ra, Rb, Ra, Rb], 1)
    sl, sh = np.maximum(b["sl"], 0), np.maximum(b["sh"], 0)
    Sv = np.where(single_m[:, None], np.stack([p.sums[sl], p.sums[sl], p.sums[sh], p.sums[sh]], 1), Sv)
    single_p = b["a13"] == b["b13"]
    Ta, Tb = p.r13[b["a13"]], p.r13[b["b13"]]
    Av = np.stack([b["u1"] * Ta, b["u1"] * Tb, b["u2"] * Ta, b["u2"] * Tb], 1)
    Bv = np.stack([Ta, Tb, Ta, Tb], 1)
    pl, ph = np.maximum(b["pl"], 0), np.maximum(b["ph"], 0)
    Av = np.where(single_p[:, None], np.stack([p.r12[pl], p.r12[pl], p.r12[ph], p.r12[ph]], 1), Av)
    return Sv, Rv, Av, Bv


def _probe(b, p):
    """A real network in each box (its indices: sum, R11, R12, R13) and whether there is one."""
    out, ok = [], np.ones(len(b), bool)
    for a, z, lo, hi, r1, r2, mag, vals in (("a11", "b11", "sl", "sh", "r1", "r2", p.r11, p.sums),
                                            ("a13", "b13", "pl", "ph", "u1", "u2", p.r13, p.r12)):
        m = (b[a] + b[z]) // 2
        R = mag[m]
        single = b[a] == b[z]
        i = np.where(single, b[lo], np.searchsorted(vals, b[r1] * R, "left"))
        j = np.where(single, b[hi], np.searchsorted(vals, b[r2] * R, "right") - 1)
        k = np.clip(np.searchsorted(vals, np.sqrt(b[r1] * b[r2]) * R), i, j)
        k = np.where(single, (i + j) // 2, k)
        ok &= i <= j
        out += [np.clip(k, 0, len(vals) - 1), m]
    return np.stack(out, 1), ok


def _probe_figures(p, idx):
    S, R, A, B = p.sums[idx[:, 0]], p.r11[idx[:, 1]], p.r12[idx[:, 2]], p.r13[idx[:, 3]]
    rep = lambda x: np.repeat(x[:, None], 4, 1)  # noqa: E731
    return _figures(p, rep(S), rep(R), rep(A), rep(B))


def _effects(b, p):
    """How much each dimension (minus ratio, R11, plus ratio, R13) moves the nominal figures across the box."""
    c = [np.sqrt(b["r1"] * b["r2"]), np.sqrt(p.r11[b["a11"]] * p.r11[b["b11"]]), np.sqrt(b["u1"] * b["u2"]),
         np.sqrt(p.r13[b["a13"]] * p.r13[b["b13"]])]
    ends = [(b["r1"], b["r2"]), (p.r11[b["a11"]], p.r11[b["b11"]]), (b["u1"], b["u2"]), (p.r13[b["a13"]], p.r13[b["b13"]])]
    vz, i = p.vz0, p.imax

    def nominal(rho, R, u, T):
        M = (vz + i * rho * R) / (1 + rho)
        return (vz - M * (1 + u) + i * u * T, rho * (vz - i * R) / (1 + rho), u * (vz - i * T) / (1 + u),
                vz / (R * (1 + rho)) + vz / (T * (1 + u)))

    v0 = nominal(*c)
    vs = np.maximum(np.abs(v0[0]), 0.01 * vz)
    eff = []
    for d in range(4):
        x1, x2 = list(c), list(c)
        x1[d], x2[d] = ends[d]
        f1, f2 = nominal(*x1), nominal(*x2)
        eff.append(np.abs(f1[0] - f2[0]) / vs + (np.abs(f1[1] - f2[1]) + np.abs(f1[2] - f2[2])) / max(p.head, 1e-3)
                   + np.abs(f1[3] - f2[3]) / p.dmax)
    eff = np.stack(eff, 1)
    # a ratio range narrower than the largest step of its list is not split while its magnitude can be (it
    # would hold no network for most magnitudes)
    can = np.stack([np.where(b["a11"] == b["b11"], b["sh"] > b["sl"], np.log(b["r2"] / b["r1"]) > p.gap_s),
                    b["b11"] > b["a11"],
                    np.where(b["a13"] == b["b13"], b["ph"] > b["pl"], np.log(b["u2"] / b["u1"]) > p.gap_12),
                    b["b13"] > b["a13"]], 1)
    return np.where(can, eff + 1e-300, -1.0), can.any(axis=1)


def _split(b, p):
    eff, _ = _effects(b, p)
    d = np.argmax(eff, axis=1)
    kids = []
    for dim, (a, z, lo, hi, r1, r2) in ((0, ("a11", "b11", "sl", "sh", "r1", "r2")), (2, ("a13", "b13", "pl", "ph", "u1", "u2"))):
        sel = d == dim
        if sel.any():
            x = b.take(sel)
            single = x[a] == x[z]
            c1, c2 = x.take(slice(None)), x.take(slice(None))
            mid_i = (x[lo] + x[hi]) // 2
            mid_r = np.sqrt(x[r1] * x[r2])
            c1[hi] = np.where(single, mid_i, x[hi])
            c2[lo] = np.where(single, mid_i + 1, x[lo])
            c1[r2] = np.where(single, x[r2], mid_r)
            c2[r1] = np.where(single, x[r1], mid_r)
            kids += [c1, c2]
    for dim, (a, z, lo, hi) in ((1, ("a11", "b11", "sl", "sh")), (3, ("a13", "b13", "pl", "ph"))):
        sel = d == dim
        if sel.any():
            x = b.take(sel)
            mid = (x[a] + x[z]) // 2
            c1, c2 = x.take(slice(None)), x.take(slice(None))
            c1[z], c2[a] = mid, mid + 1
            kids += [c1, c2]
    kids = _Boxes.cat(kids)
    # children of single-ratio-index boxes: their ratio ranges follow their index ranges
    return _index_ranges(kids, p)


def _root(p):
    b = _Boxes(a11=np.array([0]), b11=np.array([len(p.r11) - 1]), sl=np.array([-1]), sh=np.array([-1]),
               r1=np.array([p.sums[0] / p.r11[-1] * (1 - 1e-12)]), r2=np.array([p.sums[-1] / p.r11[0] * (1 + 1e-12)]),
               a13=np.array([0]), b13=np.array([len(p.r13) - 1]), pl=np.array([-1]), ph=np.array([-1]),
               u1=np.array([p.r12[0] / p.r13[-1] * (1 - 1e-12)]), u2=np.array([p.r12[-1] / p.r13[0] * (1 + 1e-12)]))
    return _index_ranges(b, p)


def _exact_ok(p, v_lo, v_hi, head, i_div, r7):
    ends = (1 - p.t7, 1 + p.t7)
    lo = np.minimum(v_lo / ends[0], v_lo / ends[1])
    hi = np.maximum(v_hi / ends[0], v_hi / ends[1])
    worst = np.minimum(lo / r7 / p.i_no - 1, 1 - hi / r7 / p.i_must)
    ok = (worst >= p.m - 1e-12) & (head >= p.head - 1e-12) & (lo > 0) & (i_div <= p.dmax * (1 + 1e-12))
    return ok, worst


def _smallest_r7(p, fig):
    v_lo, v_hi, head, i_div = fig
    k = len(p.r7s)
    thr = v_hi / (p.i_must * (1 - p.m + 1e-12) * (1 - p.t7))
    j0 = np.searchsorted(p.r7s, thr * (1 - _LOOSE))
    best = np.full(len(v_lo), k)
    for dj in (1, 0):
        j = np.minimum(j0 + dj, k - 1)
        ok, _ = _exact_ok(p, v_lo, v_hi, head, i_div, p.r7s[j])
        best = np.where(ok & (j0 + dj < k), j0 + dj, best)
    return best


def _box_feasible(p, fig):
    v_lo, _, head, i_div = fig
    return (head >= (p.head - 1e-12) - _LOOSE * (1 + abs(p.head))) & (i_div <= p.dmax * (1 + 1e-12) * (1 + _LOOSE)) & (v_lo > 0)


def _r7_window(p, fig):
    v_lo, v_hi = fig[0], fig[1]
    r_lo = v_hi / (p.i_must * (1 - p.m + 1e-12) * (1 - p.t7))
    r_lo = np.where(r_lo > 0, r_lo * (1 - _LOOSE), r_lo * (1 + _LOOSE))
    r_hi = v_lo / (p.i_no * (1 + p.m - 1e-12) * (1 + p.t7)) * (1 + _LOOSE)
    return np.searchsorted(p.r7s, r_lo, "left"), np.searchsorted(p.r7s, r_hi, "right") - 1


def _margin_ub(p, fig, r7):
    v_lo, v_hi = fig[0], fig[1]
    up = v_lo / ((1 + p.t7) * r7 * p.i_no) - 1
    dn = 1 - v_hi / ((1 - p.t7) * r7 * p.i_must)
    w = np.minimum(up, dn)
    w = w + _LOOSE * (1 + np.abs(w))
    return w, _box_feasible(p, fig) & (w >= p.m - 1e-12)


def _search(p, keyfn, probefn, chunk, best=np.inf, arg=None):
    boxes = _root(p)
    pool = boxes.take(slice(0, 0))
    pool_key = np.zeros(0)
    evaluated = 0
    while True:
        evaluated += len(boxes)
        idx, has = _probe(boxes, p)
        val = np.where(has, probefn(_probe_figures(p, idx)), np.inf) if len(boxes) else np.zeros(0)
        if len(val) and val.min() < best:
            j = int(np.argmin(val))
            best, arg = float(val[j]), idx[j].copy()
            keep = pool_key < best
            pool, pool_key = pool.take(keep), pool_key[keep]
        key, alive = keyfn(_figures(p, *_vertices(boxes, p)))
        _, can = _effects(boxes, p)
        keep = alive & (key < best) & can
        pool = _Boxes.cat([pool, boxes.take(keep)])
        pool_key = np.concatenate([pool_key, key[keep]])
        if not len(pool_key):
            return best, arg, evaluated
        if len(pool_key) > chunk:
            take = np.argpartition(pool_key, chunk)[:chunk]
        else:
            take = np.arange(len(pool_key))
        rest = np.ones(len(pool_key), bool)
        rest[take] = False
        boxes = _split(pool.take(take), p)
        pool, pool_key = pool.take(rest), pool_key[rest]


def exact_limiter(spec, chunk=2048, stats=None):
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
    net = (float(p.pairs[0][arg[0]]), float(p.pairs[1][arg[0]]), float(p.r11[arg[1]]), float(p.r12[arg[2]]),
           float(p.r13[arg[3]]))
    return r7, net, -neg
