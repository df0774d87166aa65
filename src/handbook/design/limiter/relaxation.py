"""The limiter's continuous relaxation (casadi and IPOPT): the figures of the message a spec nothing meets
gets (the best worst margin a continuous network reaches, the smallest continuous R7). Local optima, stated as
such; the search (:mod:`.search`) does not rest on them.
"""
from __future__ import annotations

import functools
import math

import casadi as ca
import numpy as np

from ..solvers import IPOPT_OPTIONS
from . import model as net
from .model import RESISTORS, choices

#: the spec values the relaxation takes as parameters (one NLP, built once per process, serves every spec)
RELAX_KEYS = ("zener_voltage", "zener_tolerance", "zener_tc", "temp_span", "input_bias", "input_offset_current",
              "offset", "resistor_tolerance", "r7_tolerance", "i_no_trip", "i_must_trip", "input_headroom",
              "divider_current_max")


@functools.cache
def _solvers():
    """(cold, warm) IPOPT instances of the relaxation, the spec's values as parameters."""
    x, w, q = ca.SX.sym("x", 7), ca.SX.sym("w"), ca.SX.sym("q", len(RELAX_KEYS) + 1)
    s = dict(zip(RELAX_KEYS, ca.vertsplit(q[:-1])))
    r7, r, t = ca.exp(x[0]), tuple(ca.exp(x[i]) for i in range(1, 6)), x[6]
    lows, highs = net.trip_voltage_corners(r, s, relaxed=True)
    g = ([net.margins(lo, 0.0, r7, s)[0] - t for lo in lows]
         + [net.margins(0.0, hi, r7, s)[1] - t for hi in highs]
         + [(v - s["input_headroom"]) / q[-1] for v in net.headroom_corners(r, s)]
         + [1 - net.divider_current(r, s) / s["divider_current_max"]])
    nlp = {"x": x, "p": ca.vertcat(w, q), "f": w * x[0] - (1 - w) * x[6], "g": ca.vertcat(*g)}
    base = {**IPOPT_OPTIONS, "ipopt.tol": 1e-9, "ipopt.mu_strategy": "adaptive"}
    # a child node starts from its parent's solution and multipliers: a handful of iterations, not 30
    warm = {**base, "ipopt.warm_start_init_point": "yes", "ipopt.mu_init": 1e-5, "ipopt.warm_start_bound_push": 1e-9,
            "ipopt.warm_start_mult_bound_push": 1e-9}
    return ca.nlpsol("limiter", "ipopt", nlp, base), ca.nlpsol("limiter_warm", "ipopt", nlp, warm)


class Relaxation:
    """The continuous problem in x = (ln R7, ln R9 .. ln R13, t), t the worst margin, for one spec; called
    with a node's bounds. Weight w = 1: minimise ln R7 (t >= min_margin); w = 0: maximise t."""

    def __init__(self, s: dict):
        values = dict(s)
        self.q = [float(values[k]) for k in RELAX_KEYS] + [max(s["input_headroom"], 1.0)]
        self.solver, self.warm = _solvers()

    def solve(self, lb, ub, x0, weight: float, t_min: float = -10.0, warm: dict | None = None):
        """(x, status, state) of the box lb..ub (resistor values), or None when IPOPT reports it infeasible
        (a local verdict: the callers bound such a box by :func:`vertex_bound` before dropping it).

        Parameters
        ----------
        lb, ub : array of float
            The box: lowest and highest R7, R9..R13, ohm.
        x0 : array of float
            The starting point (ln R7, ln R9 .. ln R13, t).
        weight : float
            1: minimise ln R7 (t >= ``t_min``); 0: maximise the worst margin t.
        t_min : float
            The least worst margin, fraction.
        warm : dict or None
            A parent's state (its x and multipliers) for a warm start.

        Returns
        -------
        tuple or None
            (x: ln R7, ln R9 .. ln R13 and t; IPOPT's return status; the state for a child's warm start).
        """
        solver = self.solver if warm is None else self.warm
        args = dict(x0=x0, p=[weight, *self.q], lbx=[*np.log(lb), t_min], ubx=[*np.log(ub), 10.0], lbg=0, ubg=np.inf)
        if warm is not None:
            args.update(x0=np.clip(warm["x"], args["lbx"], args["ubx"]), lam_x0=warm["lam_x"], lam_g0=warm["lam_g"])
        r = solver(**args)
        status = solver.stats()["return_status"]
        if status in ("Infeasible_Problem_Detected", "Restoration_Failed"):
            return None
        return np.array(r["x"]).ravel(), status, {"x": np.array(r["x"]).ravel(), "lam_x": r["lam_x"], "lam_g": r["lam_g"]}


def smallest_r7(s: dict) -> float | None:
    """IPOPT's smallest continuous R7 with every margin at least ``min_margin``: a figure for the message of a
    spec nothing meets (a local solver's answer, not a proof; the search does not use it).

    Parameters
    ----------
    s : Mapping
        The checked ``[current_limiter]`` table (SI units).

    Returns
    -------
    float or None
        R7, ohm; None when IPOPT finds no continuous network.
    """
    relax, lists = Relaxation(s), [choices(s, name) for name in RESISTORS]
    lb, ub = np.array([v[0] for v in lists]), np.array([v[-1] for v in lists])
    res = relax.solve(lb, ub, [*np.log(np.sqrt(lb * ub)), 0.0], 1.0, s["min_margin"])
    if res is not None and res[1] in ("Solve_Succeeded", "Solved_To_Acceptable_Level") and math.isfinite(res[0][0]):
        return math.exp(res[0][0])
    return None
