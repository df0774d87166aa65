"""The records every source document and design is built from (none of them imports sympy).

* :class:`~handbook.core.source.Param`, :class:`~handbook.core.source.Fact` and
  :class:`~handbook.core.source.Source`: a document's inputs, outside figures and registries;
* :class:`~handbook.core.claim.Claim` and :class:`~handbook.core.claim.Printed`: a printed number and
  its recomputation; :class:`~handbook.core.claim.TextErratum`: an erratum that is not a number;
* :class:`handbook.core.equation.Equation` (imported from its module: it needs sympy): a printed
  equation, its derivation and their symbolic check.
"""
from .claim import CONFIDENCE, UNIT_SCALES, Case, Claim, Printed, ReadingNote, TextErratum, classify
from .source import Fact, Param, Source
from .validate import InputError

__all__ = ["CONFIDENCE", "UNIT_SCALES", "Case", "Claim",
           "Fact", "InputError", "Param", "Printed", "ReadingNote", "Source", "TextErratum", "classify"]
