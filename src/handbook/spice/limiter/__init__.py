"""The limiters of AN94002 and AN93008 in SPICE: the notes' decks (:mod:`.decks`), a designed limiter confirmed at
every corner (:mod:`.confirm`) and the drawings (:mod:`.drawings`); AN93008's supply-referenced limiter is
:mod:`.supply`."""
from .confirm import design_candidates, design_check, design_corners
from .decks import (
    corner_defaults,
    one_transistor,
    one_transistor_defaults,
    one_transistor_parts,
    opamp,
    opamp_corner,
    opamp_defaults,
    opamp_parts,
    waveforms,
)
from .supply import supply_defaults, supply_parts, supply_referenced

__all__ = ["corner_defaults", "design_candidates", "design_check", "design_corners", "one_transistor",
           "one_transistor_defaults", "one_transistor_parts", "opamp", "opamp_corner", "opamp_defaults", "opamp_parts",
           "supply_defaults", "supply_parts", "supply_referenced", "waveforms"]
