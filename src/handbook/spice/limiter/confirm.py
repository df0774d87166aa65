"""A designed current limiter confirmed by ngspice: every candidate corner of its worst case simulated in DC
(copies side by side in a few decks, run two at a time), SPICE's own lowest and highest trip current and least
input headroom kept, the design's own corner choice used only for the equation column."""
from __future__ import annotations

import itertools
import tempfile
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import numpy as np

from .. import models
from ..runner import run
from .decks import _mid, _probe, opamp_block, opamp_defaults, trip_voltage

# ----------------------------------------------------------------------------------------------
# a design confirmed: every candidate corner simulated, SPICE's own extremes kept

#: the DC sweep of the designed limiter's motor current: points from 0 to SWEEP_TOP x i_must_trip
SWEEP_POINTS, SWEEP_TOP = 50, 2.0


def design_candidates(result) -> list[dict]:
    """Every candidate corner of a current-limiter design as :func:`opamp` parameters, chosen by no equation:
    each of R7, R9..R13 at either end of its tolerance (64), the zener at either end of its tolerance and drift,
    the offset at either sign, and the two bias currents at each of the four vertices of their parallelogram
    (their average at +-I_B, their difference at +-I_os, from the spec's input_offset_current): 1024 corners."""
    from ...design.limiter import model as net

    s = result.spec
    t, ib, off = s["resistor_tolerance"], s["input_bias"], s["offset"]
    ios = s["input_offset_current"]  # the inputs' average within +-I_b, their difference within +-I_os
    biases = [(avg + d / 2, avg - d / 2) for avg in (-ib, ib) for d in (-ios, ios)]
    base = opamp_defaults()
    out = []
    for signs in itertools.product((-1, 1), repeat=6):
        r = [x * (1 + tol * g) for x, g, tol in zip((result.r7, *result.network), signs, (s["r7_tolerance"],) + (t,) * 5)]
        for vz, vos, (ibp, ibn) in itertools.product(net.zener_range(s), (-off, off), biases):
            out.append({**base, **dict(zip(("r7", "r9", "r10", "r11", "r12", "r13"), r)), "zener_voltage": vz, "vos": vos,
                        "ibp": ibp, "ibn": ibn})
    return out


def design_corners(result) -> tuple[dict, dict, dict]:
    """(lowest, highest, least-headroom) corner of :func:`design_candidates` by the equations (:func:`trip_voltage`,
    eq 11 with the bias): what the design itself reports, each with ``i_eq`` and ``head_eq``. Only the
    equation column of :func:`design_check` uses this; the simulation runs every candidate."""
    lo = hi = head = None
    for p in design_candidates(result):
        p["i_eq"] = trip_voltage(p) / p["r7"]
        s910, r11, r12, r13, vz = p["r9"] + p["r10"], p["r11"], p["r12"], p["r13"], p["zener_voltage"]
        p["head_eq"] = min(vz * r12 / (r12 + r13) - p["ibp"] * r12 * r13 / (r12 + r13),
                           vz * s910 / (s910 + r11) - p["ibn"] * s910 * r11 / (s910 + r11))
        lo = p if lo is None or p["i_eq"] < lo["i_eq"] else lo
        hi = p if hi is None or p["i_eq"] > hi["i_eq"] else hi
        head = p if head is None or p["head_eq"] < head["head_eq"] else head
    return lo, hi, head


#: vectors per wrdata command of the design deck (a command line of a few kB); copies per deck: ngspice's
#: set-up time grows faster than the copies (96 copies take 0.35 s, 768 copies 14 s), so the 1024 corners run
#: as 32 decks of 32, two ngspice processes at a time (about 1.5 s on two cores)
WRDATA_CHUNK, DECK_COPIES = 200, 32


def design_deck(corners: list[dict], i_top: float, folder) -> tuple[str, list[str]]:
    """One DC deck holding one copy of the limiter per corner, the motor currents swept together from 0 to
    ``i_top`` (a G source per copy driven by the shared sweep node ``sw``), and the files its `wrdata`
    commands write (1024 `.meas` lines would take ngspice minutes; the sweep itself takes a fraction of a
    second). Per copy ``_k`` it writes the LM358's input difference v(pd_k) = V+ - V-, the two headrooms
    v(php_k), v(phm_k) and the output v(out_k) at every point of the sweep."""
    models_, body, zeners = models.lm358(), ["VSW sw 0 0"], {}
    for k, p in enumerate(corners):
        sfx = f"_{k}"
        m, lines = opamp_block({**p, "i_max": 1.0}, sfx)
        zener = zeners.setdefault(round(p["zener_voltage"], 9), f"DZC{len(zeners)}")  # one .model per zener voltage
        if zener == f"DZC{len(zeners) - 1}" and len(zeners) > len([ln for ln in models_ if ".model DZC" in ln]):
            models_ += [ln.replace(f"DZ{sfx} ", f"{zener} ") for ln in m]
        body += [ln.replace(f" DZ{sfx} ", f" {zener} ") for ln in lines if not ln.startswith(f"IM{sfx} ")]
        body += [f"GIM{sfx} csm{sfx} 0 sw 0 {i_top:.6g}", _probe(f"d{sfx}", f"v(inp{sfx})-v(inn{sfx})")]
    vectors = [f"v({n}_{k})" for k in range(len(corners)) for n in ("pd", "php", "phm", "out")]
    files, control = [], []
    for j in range(0, len(vectors), WRDATA_CHUNK):
        files.append(str(Path(folder) / f"w{j // WRDATA_CHUNK}.txt"))
        control.append(f"wrdata {files[-1]} " + " ".join(vectors[j:j + WRDATA_CHUNK]))
    deck = "\n".join(["* designed limiter at every candidate corner", *models_, *body,
                      f".dc VSW 0 1 {1 / SWEEP_POINTS:g}", ".control", "run", *control, "quit 0", ".endc", ".end"])
    return deck + "\n", files


def _first_crossing(x, y, level) -> float:
    """The first x where y (falling or rising) passes ``level``, linearly between the sweep's points; nan if never."""
    d = np.asarray(y) - level
    k = np.nonzero(np.sign(d[:-1]) != np.sign(d[1:]))[0]
    if not len(k):
        return float("nan")
    i = k[0]
    return float(x[i] + (x[i + 1] - x[i]) * d[i] / (d[i] - d[i + 1]))


def design_check(result) -> dict:
    """A current-limiter design (handbook.design.limiter) simulated at every candidate corner
    (:func:`design_candidates`, 1024 copies in 32 DC runs of 32; the design's own corner choice is not used) and
    SPICE's own extremes kept: "i_trip_min", "i_trip_max" (A), "headroom_min" (V, the least of V_s - V+ and
    V_s - V- at no motor current), each beside the design's own figure ("*_equation"); "ok": at every corner
    the op-amp's output is high at no motor current and low at the top of the sweep (an input within the
    LM358's 2 V of the supply makes the model's output stick low: a limiter that would act on a motor drawing
    nothing shows up here, however normal its trip current looks); "meets_spec": SPICE's i_trip_min above
    i_no_trip, its i_trip_max below i_must_trip, its least headroom at least input_headroom, and ok;
    "corners": how many were simulated."""
    s = result.spec
    corners = design_candidates(result)
    i_top = SWEEP_TOP * s["i_must_trip"]
    chunks = [corners[j:j + DECK_COPIES] for j in range(0, len(corners), DECK_COPIES)]

    def simulate(chunk):
        with tempfile.TemporaryDirectory(prefix="handbook-limiter-") as tmp:
            deck, files = design_deck(chunk, i_top, tmp)
            run(deck)
            return np.hstack([np.loadtxt(f, ndmin=2) for f in files])

    with ThreadPoolExecutor(max_workers=2) as pool:  # each deck is its own ngspice process
        data = np.hstack(list(pool.map(simulate, chunks)))
    data = np.hstack([data[:, :1], data[:, 1::2]])  # wrdata writes (scale, value) pairs: keep one scale
    x = data[:, 0]
    cols = data[:, 1:].reshape(len(x), len(corners), 4)
    a0 = models.LM358["a0"]
    trips = [_first_crossing(x, cols[:, k, 0], c["vos"] + _mid(c) / a0) * i_top for k, c in enumerate(corners)]
    heads = [min(cols[0, k, 1], cols[0, k, 2]) for k in range(len(corners))]
    ok = all(cols[0, k, 3] > _mid(c) > cols[-1, k, 3] for k, c in enumerate(corners)) and not np.isnan(trips).any()
    lo, hi = float(np.nanmin(trips)), float(np.nanmax(trips))
    figures = {"i_trip_min": lo, "i_trip_min_equation": float(result.i_trip_min),
               "i_trip_max": hi, "i_trip_max_equation": float(result.i_trip_max),
               "headroom_min": float(min(heads)), "headroom_min_equation": float(result.headroom_min),
               "ok": bool(ok), "corners": len(corners)}
    figures["meets_spec"] = bool(ok and lo > s["i_no_trip"] and hi < s["i_must_trip"]
                                 and min(heads) >= s["input_headroom"])
    return figures
