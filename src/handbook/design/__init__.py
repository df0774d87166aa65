"""Component choice: one module per design, each ``checked -> solve -> snap -> verify -> Result``.

* :mod:`~handbook.design.commutation`: CAP-CD/CAP-DC for the TDA5143/5144;
* :mod:`~handbook.design.current_limiter`: R7 and R9 of the op-amp current limiter;
* :mod:`~handbook.design.class_d`: the LM4651/LM4652 switching frequency and R_OSC.

:mod:`~handbook.design.schema` holds the specification (every key's default, unit, range, meaning) and
the results each design reports; :mod:`~handbook.design.spec` reads and runs a TOML specification;
:mod:`~handbook.design.bom` writes the bill of materials; :mod:`~handbook.design.solvers` is the casadi
plumbing. A specification nothing can meet raises :class:`~handbook.design.solvers.Infeasible`.
"""
from . import bom, class_d, commutation, current_limiter, schema, spec
from .solvers import Infeasible

__all__ = ["Infeasible", "bom", "class_d", "commutation", "current_limiter", "schema", "spec"]
