"""Component choice: one package per design, each with the same public face (``checked``, ``design``,
``explain`` for a spec nothing meets, ``sensitivity`` of a result, ``enumerate`` for an exhaustive check), every
design re-verified at every tolerance corner.

* :mod:`~handbook.design.commutation`: the TDA5143/5144 timing set, CAP-CD/CAP-DC from the speed range and
  CAP-ST/CAP-TI from motor data (closed forms, exact);
* :mod:`~handbook.design.limiter`: the op-amp limiter's whole network R7, R9..R13 (an exact search by
  closed-form bounds; exact corners);
* :mod:`~handbook.design.class_d`: the LM4651/LM4652 switching frequency, R_OSC, R_DLY, output filter and
  heat sink as one design (IPOPT, then a proven series search);
* :mod:`~handbook.design.converter`: the TCA5600 dc/dc converter by eq 1 to 6a, down to a real coil (the
  smallest core of PyOpenMagnetics' database, by exact enumeration).

Shared by all four: :mod:`~handbook.design.schema` (every key's default, unit, range, meaning, and the results
each design reports), :mod:`~handbook.design.spec` (reads and runs a TOML specification),
:mod:`~handbook.design.bom` (the bill of materials), :mod:`~handbook.design.worstcase` (EVA, RSS and a seeded
Monte Carlo of any design, its yields and sensitivities), :mod:`~handbook.design.common` (a table's checks, the
result base class) and
:mod:`~handbook.design.solvers` (casadi's silent IPOPT, and :class:`~handbook.design.solvers.Infeasible`, which
a specification nothing can meet raises).
"""
from . import bom, class_d, commutation, converter, limiter, schema, spec
from .solvers import Infeasible
from .spec import DESIGNS

__all__ = ["DESIGNS", "Infeasible", "bom", "class_d", "commutation", "converter", "limiter", "schema", "spec"]
