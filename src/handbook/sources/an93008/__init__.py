"""AN93008: current limiter for the motor-control ICs of the TDA514x family (Philips, R. Galema, 1995).

The one-transistor limiter (as in AN94002 2.3), the op-amp limiter with a supply-referenced level
shift (figure 3, eq 1 to 8) and the improved one bridged by a zener (figure 4, as AN94002 figure 3).
"""
from __future__ import annotations

from ...core import Source
from . import cases, claims, data
from .circuit import b_for, factor_a, factor_b, r10_for, supply_worst_case, v_cs_trip

SOURCE = Source(name=data.NAME, title="AN93008 current limiters", parameters=data.PARAMETERS, facts=data.FACTS,
                equations_module=f"{__name__}.equations",
                build_claims=claims.build, errata=data.ERRATA, cases=cases.CASES,
                reading_notes=data.READING_NOTES)
params, evaluate, equation = SOURCE.params, SOURCE.evaluate, SOURCE.equation

__all__ = ["SOURCE", "b_for", "equation", "evaluate", "factor_a", "factor_b", "params", "r10_for",
           "supply_worst_case", "v_cs_trip"]
