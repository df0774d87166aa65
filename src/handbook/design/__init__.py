"""Component choice: one module per design, each ``checked -> solve -> snap -> verify -> Result``, every
design re-verified at every tolerance corner.

* :mod:`~handbook.design.commutation`: the TDA5143/5144 timing set, CAP-CD/CAP-DC from the speed range and
  CAP-ST/CAP-TI from motor data (closed forms, exact; :mod:`.commutation_timers`, :mod:`.commutation_checks`);
* :mod:`~handbook.design.current_limiter`: the op-amp limiter's whole network R7, R9..R13 (branch and
  bound over IPOPT relaxations, :mod:`.branch_bound`; exact corners in :mod:`.limiter_network`);
* :mod:`~handbook.design.class_d`: the LM4651/LM4652 switching frequency, R_OSC, R_DLY, output filter and
  heat sink as one design (IPOPT, then a proven series search; :mod:`.class_d_model`, :mod:`.class_d_report`);
* :mod:`~handbook.design.converter`: the TCA5600 dc/dc converter by eq 1 to 6a, down to a real coil (the
  smallest core of PyOpenMagnetics' database, :mod:`.converter_cores`, by exact enumeration).

:mod:`~handbook.design.schema` holds the specification (every key's default, unit, range, meaning) and
the results each design reports; :mod:`~handbook.design.spec` reads and runs a TOML specification;
:mod:`~handbook.design.bom` writes the bill of materials; :mod:`~handbook.design.solvers` is the casadi
plumbing. A specification nothing can meet raises :class:`~handbook.design.solvers.Infeasible`.
"""
from . import bom, class_d, commutation, converter, current_limiter, schema, spec
from .solvers import Infeasible

__all__ = ["Infeasible", "bom", "class_d", "commutation", "converter", "current_limiter", "schema", "spec"]
