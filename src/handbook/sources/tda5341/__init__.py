"""TDA5341 (Philips, 1997): start oscillator and adaptive commutation delay (CAPCDM, CAPCDS).

The excerpt's equations are garbled by the OCR; they are rebuilt from the numbers around them (see the
chapter) and compared with the TDA5144 datasheet's treatment of the same mechanism.
"""
from __future__ import annotations

from ...core import Source
from . import cases, claims, data
from .circuit import cap_cd_for, constant_k, max_delay

SOURCE = Source(name=data.NAME, title="TDA5341 start and commutation (excerpt)", parameters=data.PARAMETERS,
                equations_module=f"{__name__}.equations",
                build_claims=claims.build, errata=data.ERRATA, cases=cases.CASES,
                reading_notes=data.READING_NOTES)
params, evaluate, equation = SOURCE.params, SOURCE.evaluate, SOURCE.equation

__all__ = ["SOURCE", "cap_cd_for", "constant_k", "equation", "evaluate", "max_delay", "params"]
