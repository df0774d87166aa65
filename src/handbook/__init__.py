"""Design handbook for driver ICs: app-note equations re-derived, examples recomputed, parts chosen."""
__version__ = "0.1.0"
