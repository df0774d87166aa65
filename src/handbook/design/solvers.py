"""Shared casadi plumbing: a silent IPOPT, naming the constraint that binds from its multiplier, and the error a
specification nothing can meet raises."""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..core.units import readable

#: IPOPT options that keep every solve silent and deterministic in notebook output
IPOPT_OPTIONS = {"ipopt.print_level": 0, "ipopt.sb": "yes", "print_time": False,
                 "ipopt.tol": 1e-12, "ipopt.acceptable_tol": 1e-10}


class Infeasible(Exception):
    """A valid specification that no component choice meets: ``table`` names the design, ``achievable``
    says what can be met."""

    def __init__(self, table: str, message: str, achievable: dict):
        super().__init__(readable(message))
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
