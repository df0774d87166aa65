"""Design handbook for driver ICs: app-note equations re-derived, examples recomputed, parts chosen."""
from .core.version import VERSION as __version__  # noqa: F401
