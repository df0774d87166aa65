"""Shared casadi plumbing: a silent IPOPT, and naming the constraint that binds from its multiplier."""
from __future__ import annotations

from dataclasses import dataclass

import casadi as ca
import numpy as np

#: IPOPT options that keep every solve silent and deterministic in notebook output
IPOPT_OPTIONS = {"ipopt.print_level": 0, "ipopt.sb": "yes", "print_time": False,
                 "ipopt.tol": 1e-12, "ipopt.acceptable_tol": 1e-10}


class Infeasible(Exception):
    """A valid specification that no component choice meets: ``table`` names the design, ``achievable``
    says what can be met."""

    def __init__(self, table: str, message: str, achievable: dict):
        super().__init__(message)
        self.table = table
        self.achievable = achievable


@dataclass
class Solution:
    x: np.ndarray
    multipliers: np.ndarray  # one per constraint (IPOPT's lam_g)
    names: list[str]
    success: bool

    def binding(self, threshold: float = 1e-6) -> list[str]:
        """Names of the constraints whose multiplier is not zero, largest first.

        Parameters
        ----------
        threshold : float
            The smallest absolute multiplier counted as not zero (the multipliers are in the units of the
            objective per unit of each constraint's function).

        Returns
        -------
        list of str
            The names of the binding constraints, ordered by decreasing absolute multiplier (a name appears once
            per binding constraint, so a constraint taken at several corners may appear several times).
        """
        order = np.argsort(-np.abs(self.multipliers))
        return [self.names[i] for i in order if abs(self.multipliers[i]) > threshold]


def minimise(f, x, constraints: list[tuple[str, object, float, float]], x0, lbx, ubx) -> Solution:
    """Minimise ``f(x)`` subject to named constraints ``lb <= g(x) <= ub`` with a silent IPOPT.

    ``x`` is a casadi SX/MX symbol; ``constraints`` is a list of (name, g, lb, ub).

    Parameters
    ----------
    f : casadi.SX or casadi.MX
        The scalar objective, an expression in ``x`` (in whatever units the caller scales it to).
    x : casadi.SX or casadi.MX
        The decision variables, a column symbol of n entries.
    constraints : list of tuple
        One (name, g, lb, ub) per constraint: its name (str, as :meth:`Solution.binding` reports it), the
        expression g in ``x``, and its lower and upper bounds (float; ``-casadi.inf`` / ``casadi.inf`` for none),
        in the units of g.
    x0 : sequence of float
        The starting point, n values in the units of ``x``.
    lbx, ubx : sequence of float
        Lower and upper bounds on ``x``, n values each, in the units of ``x``.

    Returns
    -------
    Solution
        The optimum ``x`` (numpy array), one multiplier per constraint (IPOPT's ``lam_g``, in the order of
        ``constraints``), the constraint names, and whether IPOPT reported success.
    """
    names = [c[0] for c in constraints]
    g = ca.vertcat(*[c[1] for c in constraints])
    solver = ca.nlpsol("design", "ipopt", {"x": x, "f": f, "g": g}, IPOPT_OPTIONS)
    r = solver(x0=x0, lbx=lbx, ubx=ubx, lbg=[c[2] for c in constraints], ubg=[c[3] for c in constraints])
    stats = solver.stats()
    return Solution(np.array(r["x"]).ravel(), np.array(r["lam_g"]).ravel(), names,
                    bool(stats["success"]))
