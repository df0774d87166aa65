"""How far the limiter decks' readings can be from the circuit's exact solution, bounded from the numerical method
alone: each check's tolerance about its expected difference (:mod:`.left_out`).

Three sources, each bounded from the method's own figures, none from a simulation's result:

* **the ramp's step**. ngspice takes no step longer than ``h`` (``RAMP / steps``) and `.meas` interpolates linearly
  between the points it keeps. A crossing of a signal x(t) read that way is off by at most |x - chord| / |x'|,
  and |x - chord| <= h^2 / 8 max|x''| over the step; where the LM358's output leaves its clamp inside a step
  (x'' jumps from 0), the trapezoidal rule is off by at most h^2 / 8 times the jump, and over the rest of the
  output's swing by h^2 / 12 times the integral of |x'''| (its local error h^3 / 12 |x'''| per step). The
  output's x(t) is known exactly (:class:`.left_out.OnePole`), so these are computed, per operating point.
* **the solver**. Newton stops when no node moves more than RELTOL |v| + VNTOL between iterations (no branch
  current more than RELTOL |i| + ABSTOL); the decks set RELTOL = 1e-9, VNTOL = 1e-12 V, ABSTOL = 1e-15 A
  (:data:`.decks.SOLVER`), so each node voltage is that close to its solution: a difference of two nodes within
  twice it, a few nV.
* **the printed digits**. ngspice prints each `.meas` result to seven significant digits: half a unit in the
  seventh, at most 5e-7 of the value.

The bounds take every step at its longest. ngspice's own truncation-error control (TRTOL 7 times RELTOL) only
shortens steps where the output bends, so the readings are usually far closer; it also keeps the LM358 model's
clamp (10 S against the pole's capacitor: a 23 ns mode) from ringing under the trapezoidal rule once the output
has run into it, which these bounds do not cover: with that control switched off (every step at its longest), the
rows whose output idles low and comes back into its high clamp before the trip miss by up to three times their
bound, the others stay inside it (the one-transistor rows' interpolation reaches nine tenths of it, as a tight
bound should where the crossing falls mid-step).
"""
from __future__ import annotations

import math

import numpy as np

from .. import models
from .left_out import A0, OnePole, W

#: ngspice's .meas results carry seven significant digits: at most half a unit in the seventh of the value
PRINTED = 5e-7
#: ngspice (39) computes V_T from CODATA 2014's k and q, the models (:data:`models.K_Q`) from 2019's exact ones: its
#: V_T is this fraction lower, and a V_BE set from a datasheet figure through the models' V_T with it
KQ_SPREAD = abs(1 - (1.38064852e-23 / 1.6021766208e-19) / models.K_Q)


def pct(x: float) -> str:
    """A fraction as a percentage with three significant figures, never in exponent form (0.000123 %)."""
    return np.format_float_positional(100 * x, precision=3, unique=False, fractional=False, trim="-")


def node(solver: dict, v: float) -> float:
    """How far one node at about ``v`` volts can be from its solution (V): RELTOL |v| + VNTOL."""
    return solver["reltol"] * abs(v) + solver["vntol"]


def crossing_time(response: OnePole, t_cross: float, h: float) -> float:
    """Bound on how far `.meas` puts the LM358 model's output crossing a level, at ``t_cross`` of ``response``,
    from the exact time (s), with time steps no longer than ``h`` (module text: interpolation, the release and
    other kinks of x'', the trapezoidal rule over the swing); ``h`` itself where the output leaves its clamp less
    than a step before the crossing (a ramp too fast for its steps: the crossing is then only known to its step)."""
    t0 = response.t0
    if t_cross - t0 < h:  # the clamp lets go within the crossing's own step: .meas puts the crossing in that step
        return h
    near = np.linspace(t_cross - h, t_cross + h, 129)
    curve = max(abs(response.ddx(t)) for t in near)
    jumps = sum(j for t, j in response.kinks() if t <= t_cross)
    grid = np.linspace(t0, t_cross, 4001)
    ddx = np.array([response.ddx(t) for t in grid])
    # x''' = w (A0 u'' - x''); u'' is constant within a piece: take it from the piece each point lies in
    dddx = np.array([W * (A0 * response._at(t)[0][2] * 2 - d) for t, d in zip(grid, ddx)])
    swing = float(np.sum((np.abs(dddx[1:]) + np.abs(dddx[:-1])) / 2 * np.diff(grid)))
    err_x = h * h / 8 * (curve + jumps) + h * h / 12 * swing
    slope = abs(response.dx(t_cross))
    dt = err_x / slope
    slope = min(abs(response.dx(t)) for t in np.linspace(t_cross - dt, t_cross, 9))  # the slowest x' within it
    return err_x / slope


def ramp_row(response: OnePole, t_cross: float, h: float, solver: dict, *, rate: float, v_rate: float,
             value: float, v_node: float, a: float, reads_nodes: bool) -> dict:
    """A trip read on the ramp, as a fraction of ``value`` (the row's equation, V or A): the crossing's time bound
    times ``rate`` (the reading's rate, V/s or A/s); the solver's: the input difference V+ - V- (two nodes at about
    ``v_node``) moves the crossing by 2 (RELTOL |v| + VNTOL) / A of V_cs (``a``: V+'s share of V_cs; ``v_rate``:
    dV_cs/dt, to turn it into the reading's unit), and where the reading is itself a node difference
    (``reads_nodes``: V_cs) two more nodes; and the printed digits."""
    dt = crossing_time(response, t_cross, h)
    per_volt = abs(rate / v_rate)  # the reading's unit per volt of V_cs
    solver_v = (2 * node(solver, v_node) / a + (2 * node(solver, v_node) if reads_nodes else 0.0)) * per_volt
    step = abs(rate) * dt / abs(value)
    how = (".meas interpolating the output's crossing, h²/8 of its curvature over one step, the clamp's release "
           "within a step as much again, the trapezoidal rule's h²/12 over the swing, over the output's slope"
           if dt < h else "the output leaves its clamp within the crossing's step, known to that step")
    return {"step": step, "solver": solver_v / abs(value), "printed": PRINTED, "dt": dt, "how": how,
            "total": step + solver_v / abs(value) + PRINTED}


def dc_row(solver: dict, v_node: float, value: float) -> dict:
    """A reading at no motor current (the pause before the ramp, a DC operating point): a difference of two nodes
    at about ``v_node``, as a fraction of ``value``; no step (nothing moves during the pause)."""
    solver_v = 2 * node(solver, v_node) / abs(value)
    return {"step": 0.0, "solver": solver_v, "printed": PRINTED, "total": solver_v + PRINTED}


def exponential_row(h: float, solver: dict, *, v_rate: float, v_t: float, v_be: float, v_t_part: float, rate: float,
                    value: float, v_node: float) -> dict:
    """T2 taking over: its collector current I_C = I_S e^(V_BE / V_T) crosses a level while V_BE rises at
    ``v_rate`` V/s; `.meas` interpolates I_C over a step, so the crossing is off by at most h^2 / 8 max I_C'' /
    min I_C' = h^2 v_rate e^(h v_rate / V_T) / (8 V_T) seconds, times ``rate`` (the motor current's A/s), as a
    fraction of ``value``; the solver's V_BE (two nodes at about ``v_node``, and the collector current's RELTOL:
    V_T RELTOL) over ``v_be``; ngspice's V_T (:data:`KQ_SPREAD`) of ``v_t_part``, the part of V_BE that scales
    with V_T; the printed digits. T2's model has no charge: no integration error."""
    dt = h * h * v_rate * math.exp(h * v_rate / v_t) / (8 * v_t)
    step = rate * dt / abs(value)
    solver_v = (2 * node(solver, v_node) + v_t * solver["reltol"]) / v_be + KQ_SPREAD * abs(v_t_part) / v_be
    return {"step": step, "solver": solver_v, "printed": PRINTED, "dt": dt, "total": step + solver_v + PRINTED,
            "how": ".meas interpolating the collector current's exponential, h²/8 of its curvature over its slope",
            "also": "; and ngspice's k/q, CODATA 2014's, against the models' 2019 values"}


def words(b: dict, h: float) -> str:
    """The bound's reason, ending in the tolerance (the chapters' "why")."""
    parts = []
    if b["step"]:
        parts.append(f"the ramp's step ({h * 1e3:.2g} ms at most; {b['how']}: {b['dt'] * 1e6:.3g} µs) "
                     f"{pct(b['step'])} %")
    parts.append(f"the solver's tolerance (RELTOL 1e-9 of each node{b.get('also', '')}) {pct(b['solver'])} %")
    parts.append(f"the seven printed digits {pct(b['printed'])} %")
    return "left, the numerical method's: " + ", ".join(parts) + f": ±{pct(b['total'])} %"


