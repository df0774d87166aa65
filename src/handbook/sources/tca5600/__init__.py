"""TCA5600/TCF5600 (Motorola): the DC/DC converter's coil, eq 1 to 6a of the excerpt.

Eq 1 to 6a size L1 and R1 for the worst operating point, the lowest supply with the largest load.
The excerpt prints no calculated numbers, so there are no claims to recompute.
"""
from __future__ import annotations

from ...core import Source
from . import data
from .circuit import coil_voltages, design, operating_point
from .data import APPLICATION

SOURCE = Source(name=data.NAME, title="TCA5600/TCF5600 DC/DC converter (excerpt)", parameters=data.PARAMETERS,
                equations_module=f"{__name__}.equations", errata=data.ERRATA,
                reading_notes=data.READING_NOTES)
params, evaluate, equation = SOURCE.params, SOURCE.evaluate, SOURCE.equation

__all__ = ["APPLICATION", "SOURCE", "coil_voltages", "design", "equation", "evaluate", "operating_point", "params"]
