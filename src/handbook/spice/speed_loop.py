"""The speed loop's stability (AN94002 2.2: "The series connection of R1 and C8 is necessary to obtain a good
stability of the control loop"): the loop gain in ngspice's AC analysis, the loop broken at AMPIN+.

The break: a series AC source between the divider's midpoint (R3/R4, node ``inp``) and the OTA's AMPIN+
(``inx``). The OTA's inputs draw no current, so the source sees an infinite load on one side and the
divider's 7.96 kOhm on the other, and the voltage injection is exact (Middlebrook): T = -v(inp) / v(inx),
positive at DC for a loop with negative feedback. Phase margin at |T| = 1, gain margin where T's phase
reaches -180 degrees.

What the loop holds and where each figure comes from:

* the OTA: 0.3 S, sinking up to 40 mA down to its 1.5 V saturation (TDA5144 datasheet, as :mod:`.speed`),
  and **one pole at** :data:`OTA_POLE` (an assumption: the datasheet gives no bandwidth for the OTA);
* T1, the BD434 of :func:`.models.bd434` (all its figures assumed, as in :mod:`.speed`);
* the motor as the outputs see it while it runs: its two windings in series (``winding_resistance``,
  ``winding_inductance`` of the registry, both assumptions: the note gives no motor data) behind a back-EMF
  source that holds the DC current at V_mot / R_M (:data:`.speed.R_MOTOR`, the DC chapter's load). The back-EMF
  is a short for the loop's frequencies (the rotor's inertia makes it slow);
* no capacitor on V_mot unless ``c_mot`` is set (the note's figure 1 is lost; C2 decouples the IC, AN94002 3,
  but which pin is not said).

Two wirings of the same parts (figure 1 is lost; neither is proved):

* ``"book"`` (:mod:`.speed`'s reading): AMP OUT drives T1's base; R2 pulls the base up to V_S; R1 + C8 from
  AMP OUT to ground;
* ``"series"`` (the independent review's alternative): R2 in series from AMP OUT to T1's base, R1 + C8 from
  AMP OUT to ground: the OTA's current divides between the base (through R2) and R1 + C8, a lag-lead
  network (pole near 1 / (2 pi (R1 + R2 + r_in) C8), zero at 1 / (2 pi R1 C8)).

``rc=False`` removes R1 and C8: the margins with and without them say whether they are the compensation.
"""
from __future__ import annotations

import math
import tempfile
from pathlib import Path

import numpy as np

from ..sources import an94002 as note
from . import models, speed
from .circuit import with_defaults
from .runner import run

#: the OTA's pole, Hz: an assumption (the TDA5144 datasheet gives the OTA's transfer gain, not its bandwidth)
OTA_POLE = 1e6
WIRINGS = ("book", "series")


def defaults() -> dict:
    """The speed loop's parameters (:func:`.speed.defaults`) and the loop's own: the wiring, R1/C8 fitted or
    not, the motor's windings (registry), the OTA's pole, V_in (None: the middle of its control range), no
    capacitor on V_mot, and the AC sweep."""
    p = note.params()
    return {**speed.defaults(), "wiring": "book", "rc": True, "r_winding": p["winding_resistance"],
            "l_winding": p["winding_inductance"], "ota_pole": OTA_POLE, "v_in": None, "c_mot": 0.0,
            "f_start": 10.0, "f_stop": 1e9, "points": 100}


def operating_v_in(q: dict) -> float:
    """V_in of the operating point: ``q["v_in"]``, or the middle of eq 10's control range for ``q``'s supply and
    divider."""
    if q["v_in"] is not None:
        return q["v_in"]
    lo, hi = note.v_in_range({**note.params(), **{k: q[k] for k in ("v_supply", "supply_tolerance", "v_drop_min",
                                                                     "r3", "r4", "v_mot_min")}})
    return (lo + hi) / 2


def netlist(q: dict, analysis: list[str]) -> str:
    """The loop about its operating point at V_in = :func:`operating_v_in`, broken at AMPIN+ (VINJ), with
    ``analysis`` (the .ac line and any control block) at the end."""
    if q["wiring"] not in WIRINGS:
        raise ValueError(f"wiring {q['wiring']!r}: one of {', '.join(WIRINGS)}")
    v_s = q["v_supply"] * (1 - q["supply_tolerance"])
    v_in = operating_v_in(q)
    v_mot = speed.v_mot_loop(v_in, q)
    emf = v_mot * (1 - q["r_winding"] / q["r_motor"])  # the DC current is V_mot / R_M, as the DC chapter's load
    c_pole = 1 / (2 * math.pi * 1e3 * q["ota_pole"])
    base_drive = (["R2 vs base {:.6g}".format(q["r2"]), "* AMP OUT is the base"] if q["wiring"] == "book"
                  else ["R2 ao base {:.6g}".format(q["r2"])])
    ao = "base" if q["wiring"] == "book" else "ao"
    lines = [f"* speed loop, {q['wiring']} wiring, R1/C8 {'fitted' if q['rc'] else 'removed'} (AN94002 2.2)",
             *models.bd434(**q["t1"]), f"VS vs 0 {v_s:.6g}", "QT1 vmot base vs BD434", *base_drive,
             f"R3 vmot inp {q['r3']:.6g}", f"R4 inp 0 {q['r4']:.6g}",
             f"RW vmot nw {q['r_winding']:.6g}", f"LW nw ne {q['l_winding']:.6g}", f"VEMF ne 0 {emf:.6g}",
             f"VIN inm 0 {v_in:.6g}", "VINJ inx inp DC 0 AC 1",
             "* the OTA: g_m (AMPIN- - AMPIN+) through one pole (assumed), sunk from AMP OUT, 0 .. I_SINK, to V_SAT",
             "GP 0 pn inm inx 1m", "RP pn 0 1k", f"CP pn 0 {c_pole:.6g}",
             f"BOTA {ao} 0 I = min(max({q['gm']:g}*v(pn),0),{q['i_sink']:g})"
             f"*min(max((v({ao})-{q['v_sat']:g})/0.05,0),1)"]
    if q["rc"]:
        lines += [f"R1 {ao} n1 {q['r1']:.6g}", f"C8 n1 0 {q['c8']:.6g}"]
    if q["c_mot"]:
        lines.append(f"CMOT vmot 0 {q['c_mot']:.6g}")
    return "\n".join([*lines, *analysis]) + "\n"


def loop_gain(p: dict | None = None) -> dict:
    """T(f) from ngspice: {"f": Hz, "t": complex loop gain, "op": {"v_mot", "v_ao", "i_c"} at the operating
    point}. The sweep is ``points`` a decade from ``f_start`` to ``f_stop``."""
    q = with_defaults(defaults(), p)
    with tempfile.TemporaryDirectory(prefix="handbook-loop-") as tmp:
        out = Path(tmp) / "t.txt"
        ao = "base" if q["wiring"] == "book" else "ao"
        deck = netlist(q, [".control", "op", "print v(vmot) v(" + ao + ") i(VEMF)",
                           f"ac dec {q['points']} {q['f_start']:g} {q['f_stop']:g}",
                           "let t = -v(inp)/v(inx)", "let tr = real(t)", "let ti = imag(t)",
                           f"wrdata {out} tr ti", "quit 0", ".endc"])
        run(deck)
        data = np.loadtxt(out)
    return {"f": data[:, 0], "t": data[:, 1] + 1j * data[:, 3]}


def margins(f: np.ndarray, t: np.ndarray) -> dict:
    """Crossover and margins of a loop gain ``t`` sampled at ``f``: {"f_c": the highest frequency where |T|
    falls through 1 (Hz), "pm": 180 degrees + T's unwrapped phase there, "f_180": the first frequency above
    DC where that phase reaches -180 degrees (None if never), "gm": -20 log |T| there (dB, None if never),
    "t_dc": |T| at the lowest frequency}. Interpolated linearly in log f."""
    mag = 20 * np.log10(np.abs(t))
    ph = np.degrees(np.unwrap(np.angle(t)))
    ph -= 360 * round(ph[0] / 360)  # T is positive at DC: its phase starts at 0
    lf = np.log10(f)
    down = np.nonzero((mag[:-1] >= 0) & (mag[1:] < 0))[0]
    f_c = pm = None
    if len(down):
        k = down[-1]
        x = lf[k] + (0 - mag[k]) * (lf[k + 1] - lf[k]) / (mag[k + 1] - mag[k])
        f_c, pm = 10 ** x, 180 + float(np.interp(x, lf[k:k + 2], ph[k:k + 2]))
    cross = np.nonzero((ph[:-1] > -180) & (ph[1:] <= -180))[0]
    f_180 = gm = None
    if len(cross):
        k = cross[0]
        x = lf[k] + (-180 - ph[k]) * (lf[k + 1] - lf[k]) / (ph[k + 1] - ph[k])
        f_180, gm = 10 ** x, -float(np.interp(x, lf[k:k + 2], mag[k:k + 2]))
    return {"f_c": f_c, "pm": pm, "f_180": f_180, "gm": gm, "t_dc": float(abs(t[0]))}


def compare(p: dict | None = None) -> dict:
    """Margins in both wirings with and without R1/C8: {(wiring, rc): :func:`margins`}."""
    out = {}
    for wiring in WIRINGS:
        for rc in (True, False):
            s = loop_gain({**(p or {}), "wiring": wiring, "rc": rc})
            out[wiring, rc] = margins(s["f"], s["t"])
    return out


def drawing(wiring: str = "series", p: dict | None = None):
    """The loop's schematic in ``wiring`` (:data:`WIRINGS`) with the DC chapter's parts (:func:`.speed.draw`).

    Parameters
    ----------
    wiring : str
        "book" or "series".
    p : dict, optional
        Overrides of :func:`.speed.defaults`.

    Returns
    -------
    schemdraw.Drawing
    """
    if wiring not in WIRINGS:
        raise ValueError(f"wiring {wiring!r}: one of {', '.join(WIRINGS)}")
    return speed.draw(speed._parts(with_defaults(speed.defaults(), p)), wiring)
