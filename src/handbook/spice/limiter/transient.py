"""The op-amp limiter of AN94002 figure 3 closed through the speed loop, in time: the motor current at start-up
into a stalled winding and when a running motor stalls (a step in the current it asks for).

The note's figure 3 is lost, so how the LM358's output throttles T1 is an assumption, read from the parts list:
T2 (BC557) is an O12 part, fitted with either limiter, and the O2 option holds R5 (1 kOhm) and R15 (3.9 kOhm)
whose roles the text does not state. Here R15 runs from the LM358's output to T2's base and R5 from T2's base to
V_S (its emitter); T2's collector feeds T1's base (AMP OUT), so when it conducts it takes over the current the
OTA sinks and T1 turns down, as T2 does in the one-transistor limiter (AN94002 2.3). With the LM358's output
high (V_S - 1.5 V) R5/R15 hold T2's V_EB at 1.5 V x R5 / (R5 + R15) = 0.31 V (off); T2 turns on once the output
has fallen to about V_S - V_EB (R5 + R15) / R5 = V_S - 3 V. C10 (10 uF, O2) is left out unless ``c10`` is set, then
across R5 (T2's base-emitter, as C9 would sit in the one-transistor option): an 8 ms filter that lets the start-up
current through before the limiter acts.

The rest: the speed loop of :mod:`..speed_loop` in the book's wiring (R2 pulling T1's base up, R1/C8 from AMP
OUT to ground), T1's emitter on R7 (the sense resistor in series with T1, AN94002 2.2 and 2.4), C2 (10 uF, the
board's decoupling) on V_mot (an assumption: without a capacitor there the speed loop oscillates with the
OTA's assumed 1 MHz pole, see :mod:`..speed_loop`), the motor's two windings (registry, assumed) in series with
a back-EMF source. The limiter network (R9..R14, D1, the LM358) is :func:`.decks.opamp_block`'s.
"""
from __future__ import annotations

import math
import tempfile
from pathlib import Path

import numpy as np

from ...sources import an94002
from .. import models, speed, speed_loop
from ..runner import run
from . import decks

#: settling band: within this fraction of the final current
BAND = 0.05
RIPPLE_WINDOW = 0.2  # the last fraction of the run, where the final current and any ripple are read


def defaults() -> dict:
    """The nominal op-amp limiter (:func:`.decks.opamp_defaults`), the speed loop (:func:`..speed.defaults`) at the
    nominal supply, the windings, and the closure's parts from the parts list (R5, R15, T2; C2 on V_mot)."""
    p = an94002.params()
    return {**speed.defaults(), **decks.opamp_defaults(), "supply_tolerance": 0.0, "r5": decks.BOARD["R5"],
            "r15": decks.BOARD["R15"], "c10": 0.0, "ota_pole": speed_loop.OTA_POLE, "c_mot": decks.BOARD["C2"],
            "r_winding": p["winding_resistance"], "l_winding": p["winding_inductance"], "t_step": 1e-3,
            "t_stop": 10e-3, "step": 2e-6}


def netlist(q: dict, emf: str, v_in: str, tail: list[str]) -> str:
    """The closed loop: the limiter (:func:`.decks.opamp_block` without its ramp), T2 and R5/R15, the speed loop
    around T1 (emitter on R7), C_mot, the windings and the back-EMF source ``emf`` (a SPICE source value),
    V_in ``v_in`` (one too); ``tail`` closes the deck."""
    lim_models, lim = decks.opamp_block(q)
    lim = [ln for ln in lim if not ln.startswith(("IM", "VAM"))]
    lines = ["* AN94002 figure 3 closed through the speed loop (closure assumed, see handbook.spice.limiter.transient)",
             ".options temp=25 tnom=25", *models.lm358(), *lim_models, *models.bc557(), *models.bd434(**q["t1"]), *lim,
             f"R15 out b2 {q['r15']:.6g}", f"R5 vs b2 {q['r5']:.6g}", "QT2 base b2 vs BC557",
             "QT1 vmot base cs BD434", f"R2 vs base {q['r2']:.6g}", f"R1 base n1 {q['r1']:.6g}",
             f"C8 n1 0 {q['c8']:.6g}", f"R3 vmot fbk {q['r3']:.6g}", f"R4 fbk 0 {q['r4']:.6g}",
             f"CMOT vmot 0 {q['c_mot']:.6g}", f"RW vmot nw {q['r_winding']:.6g}", f"LW nw ne {q['l_winding']:.6g}",
             f"VEMF ne 0 {emf}", f"VIN vin 0 {v_in}",
             "GP 0 pn vin fbk 1m", "RP pn 0 1k", f"CP pn 0 {1 / (2 * math.pi * 1e3 * q['ota_pole']):.6g}",
             f"BOTA base 0 I = min(max({q['gm']:g}*v(pn),0),{q['i_sink']:g})*min(max((v(base)-{q['v_sat']:g})/0.05,0),1)"]
    if q["c10"]:
        lines.append(f"C10 vs b2 {q['c10']:.6g}")
    return "\n".join([*lines, *tail]) + "\n"


def _run(q: dict, emf: str, v_in: str) -> dict[str, np.ndarray]:
    with tempfile.TemporaryDirectory(prefix="handbook-limtr-") as tmp:
        out = Path(tmp) / "w.txt"
        deck = netlist(q, emf, v_in, [f".tran {q['step']:g} {q['t_stop']:g} 0 {q['step']:g}",
                                      ".control", "run", "linearize",
                                      "let vr7 = v(vs)-v(cs)",
                                      f"wrdata {out} i(VEMF) v(vmot) v(out) v(base) vr7", "quit 0", ".endc"])
        run(deck)
        d = np.loadtxt(out)
    return {"t": d[:, 0], "i": d[:, 1], "v_mot": d[:, 3], "out": d[:, 5], "base": d[:, 7], "i_r7": d[:, 9] / q["r7"]}


def response(w: dict, t0: float, i_limit: float) -> dict:
    """Figures of a current waveform ``w`` (from :func:`startup` or :func:`stall`) after ``t0``: the peak and its
    time, the overshoot over ``i_limit`` (A and relative), the final current (mean of the last
    RIPPLE_WINDOW of the run) and its ripple (peak to peak there), the time the current first exceeds
    ``i_limit`` and the settling time: from ``t0`` until it stays within BAND of the final current (None where
    the run ends before it does, and the first time None where the current never exceeds the limit)."""
    t, i = w["t"], w["i"]
    after = t >= t0
    k = int(np.argmax(np.where(after, i, -np.inf)))
    tail = t >= t[-1] - RIPPLE_WINDOW * (t[-1] - t0)
    final = float(np.mean(i[tail]))
    outside = np.nonzero(after & (np.abs(i - final) > BAND * final))[0]
    if not len(outside):
        settled = t0  # within the band from the start
    elif outside[-1] + 1 < len(t):
        settled = t[outside[-1] + 1]
    else:  # still outside at the end of the run: it has not settled (None, not a settling time of zero)
        settled = None
    over = np.nonzero(after & (i > i_limit))[0]
    return {"peak": float(i[k]), "t_peak": float(t[k] - t0), "overshoot": float(i[k] - i_limit),
            "overshoot_rel": float(i[k] / i_limit - 1), "final": final,
            "ripple": float(np.ptp(i[tail])), "t_over": float(t[over[0]] - t0) if len(over) else None,
            "settling": None if settled is None else float(settled - t0)}


def startup(p: dict | None = None) -> dict:
    """Start-up into a stalled winding (no back-EMF): V_in steps at ``t_step`` from 0 to the top of its range.
    The waveforms ({"t", "i" (motor current), "v_mot", "out" (LM358), "base" (T1's)}) and :func:`response`
    against the limit eq 13 gives with R7 ("limit")."""
    q = {**defaults(), **(p or {})}
    _, hi = an94002.v_in_range({**an94002.params(), **{k: q[k] for k in ("r3", "r4")}})
    w = _run(q, "0", f"PWL(0 0 {q['t_step']:g} 0 {q['t_step'] + 1e-6:g} {hi:.6g})")
    limit = decks.trip_voltage(q) / q["r7"]
    return {**w, "limit": limit, "v_in": hi, **response(w, q["t_step"], limit)}


def stall(p: dict | None = None, i_run: float | None = None) -> dict:
    """A running motor that stalls: V_in at the top of its range from the start, a back-EMF that holds the
    current at ``i_run`` (default half the limit) while running, falling to 0 in 1 us at ``t_step``. As
    :func:`startup`."""
    q = {**defaults(), **(p or {})}
    _, hi = an94002.v_in_range({**an94002.params(), **{k: q[k] for k in ("r3", "r4")}})
    limit = decks.trip_voltage(q) / q["r7"]
    i_run = limit / 2 if i_run is None else i_run
    k = (q["r3"] + q["r4"]) / q["r4"]
    v_mot = speed.v_mot_loop(hi, {**q, "r_motor": k * hi / i_run})  # the loop's V_mot at that load (DC analysis)
    emf = v_mot - i_run * q["r_winding"]
    t1 = q["t_step"]
    w = _run(q, f"PWL(0 {emf:.6g} {t1:g} {emf:.6g} {t1 + 1e-6:g} 0)", f"{hi:.6g}")
    return {**w, "limit": limit, "v_in": hi, "i_run": i_run, **response(w, t1, limit)}


def trip_temperatures(p: dict | None = None, temps: tuple | None = None) -> dict:
    """The nominal op-amp limiter's trip current (the slow ramp of :func:`.decks.opamp`) at ``temps`` (default the
    registry's low end, 25 C and its high end), D1 drifting by the note's 6.2 mV/K (``zener_tc``, AN94002 2.4). Only
    D1 has a temperature coefficient in the deck (the LM358 model and the resistors have none), so the trip follows
    V_D1 (eq 13). {temperature (C): trip current (A)}."""
    reg = an94002.params()
    q = {**decks.opamp_defaults(), "zener_tc": reg["zener_tc"], **(p or {})}
    temps = temps or (reg["t_low"], 25.0, reg["t_high"])
    deck = decks._opamp_deck("AN94002 figure 3, temperature", [q])
    out = {}
    for t in temps:
        res = run(deck.replace(".options temp=25 tnom=25", f".options temp={t:g} tnom=25"))
        out[float(t)] = res["i_trip"]
    return out
