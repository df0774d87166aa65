"""CAP-CD and CAP-DC driven by a running motor's back-EMF through whole electrical cycles (AN94002 2.1.2,
figure 4): the commutations the two timers produce, where they fall between the zero crossings, and how many
there are per cycle.

:mod:`.timers` drives the timers from a gate it is given (zero crossings every t_com by construction). Here the
gate comes from the motor: three back-EMF phases 120 electrical degrees apart at ``rpm`` and ``pole_pairs``,
and the IC's zero-crossing detection modelled as the sign of their product, which flips at every zero crossing
of any phase (six a cycle). CAP-CD charges while that sign is positive and sinks its discharge current while it is
negative, CAP-DC the other way round (the same timer source as :mod:`.timers`). A
commutation is where a capacitor's discharge reaches its low level (the note: "a commutation is effectuated
when the capacitor voltage is again on its starting (low) level"). ngspice writes the waveforms; the
commutation times are read from them (the fall through the low level plus the clamp's 2 mV).

Assumptions beyond :mod:`.timers`': sinusoidal back-EMF (its shape does not matter, only its zero crossings);
a constant speed; no fly-back pulse (the note: the charge "is interrupted during the fly-back pulse", not
modelled, as in :mod:`.timers`).
"""
from __future__ import annotations

import math
import tempfile
from pathlib import Path

import numpy as np

from ..sources import an94002 as note
from .circuit import with_defaults
from .runner import run
from .timers import CD_HIGH, CD_LOW, CD_SINK, CLAMP, timer_source


def defaults() -> dict:
    """The board's C3 and C4 (18 nF), the note's motor (6 pole pairs) at its lowest speed (1800 rpm), the TDA5144's
    typical CAP-CD currents and levels, and the number of electrical cycles simulated."""
    from .timers import BOARD

    p = note.params()
    return {"cap_cd": BOARD["C3"], "cap_dc": BOARD["C4"], "pole_pairs": p["pole_pairs"], "rpm": p["rpm_min"],
            "i_ch": note.FACTS["cap_cd_charge"].value[1], "i_dis": CD_SINK[1], "v_low": CD_LOW[1],
            "v_high": CD_HIGH[1], "cycles": 4}


def cycle(p: dict | None = None) -> dict:
    """The timers through ``cycles`` electrical cycles: {"t", "cd", "dc", "emf" (3 x n, the phases, V), "zc" (the
    zero crossings, s), "commutations" (s), "t_com" (eq 4, s), "t_cycle" (eq 3, s)}."""
    q = with_defaults(defaults(), p)
    t_cyc = note.t_cycle(q["rpm"], q["pole_pairs"])
    w = 2 * math.pi / t_cyc
    end = q["cycles"] * t_cyc
    step = t_cyc / 3000
    # a small phase offset keeps t = 0 off a zero crossing
    phases = [f"BE{k} e{k} 0 V=sin({w:.9g}*time+{0.3 - 2 * math.pi * k / 3:.9g})" for k in range(3)]
    lines = ["* CAP-CD / CAP-DC driven by a running motor's back-EMF (AN94002 2.1.2, figure 4)",
             f"C3 cd 0 {q['cap_cd']:.6g}", f"C4 dc 0 {q['cap_dc']:.6g}",
             *phases, "* zero-crossing detection: the sign of the three phases' product (edges of 1/1000 cycle)",
             "BG gcd 0 V=0.5+0.5*tanh(1e4*v(e0)*v(e1)*v(e2))", "BH gdc 0 V=1-v(gcd)",
             f".param i_ch={q['i_ch']:.6g} i_dis={q['i_dis']:.6g} v_low={q['v_low']:.6g} v_high={q['v_high']:.6g}",
             timer_source("CD", "cd", "gcd", "i_ch", "i_dis", "v_low", "v_high"),
             timer_source("DC", "dc", "gdc", "i_ch", "i_dis", "v_low", "v_high"),
             f".ic v(cd)={q['v_low']:.6g} v(dc)={q['v_low']:.6g}"]
    with tempfile.TemporaryDirectory(prefix="handbook-cycle-") as tmp:
        out = Path(tmp) / "c.txt"
        lines += [f".tran {step:.6g} {end:.9g} 0 {step:.6g} uic", ".control", "run", "linearize",
                  f"wrdata {out} v(cd) v(dc) v(e0) v(e1) v(e2)", "quit 0", ".endc"]
        run("\n".join(lines) + "\n")
        d = np.loadtxt(out)
    t, emf = d[:, 0], d[:, [5, 7, 9]].T
    prod = np.prod(emf, axis=0)
    k = np.nonzero(np.sign(prod[1:]) != np.sign(prod[:-1]))[0]
    zc = t[k] + prod[k] / (prod[k] - prod[k + 1]) * (t[k + 1] - t[k])
    hit = q["v_low"] + CLAMP
    comm = []
    for v in (d[:, 1], d[:, 3]):
        k = np.nonzero((v[:-1] > hit) & (v[1:] <= hit))[0]
        comm += list(t[k] + (v[k] - hit) / (v[k] - v[k + 1]) * (t[k + 1] - t[k]))
    return {"t": t, "cd": d[:, 1], "dc": d[:, 3], "emf": emf, "zc": zc, "commutations": np.sort(comm),
            "t_com": note.t_com(q["rpm"], q["pole_pairs"]), "t_cycle": t_cyc, "q": q}


def figures(c: dict) -> dict:
    """From :func:`cycle` after its first electrical cycle (the timers start empty): the mean interval between
    commutations (s), the commutations per electrical cycle, the mean delay from a zero crossing to the next
    commutation in electrical degrees, and where each zero crossing falls between its two commutations (0 to 1;
    the note's "half-way" is 0.5)."""
    t0 = c["t_cycle"]
    comm = c["commutations"][c["commutations"] > t0]
    zc = c["zc"][(c["zc"] > t0) & (c["zc"] < comm[-1])]
    delays, place = [], []
    for z in zc:
        after = comm[comm > z]
        before = comm[comm < z]
        if len(after) and len(before):
            delays.append(after[0] - z)
            place.append((z - before[-1]) / (after[0] - before[-1]))
    span = comm[-1] - comm[0]
    return {"interval": float(np.mean(np.diff(comm))), "per_cycle": (len(comm) - 1) / span * c["t_cycle"],
            "delay_deg": float(np.mean(delays)) / c["t_cycle"] * 360, "zc_place": float(np.mean(place)),
            "zc_place_spread": float(np.ptp(place))}
