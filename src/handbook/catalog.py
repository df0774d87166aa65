"""Every source module's equations and numeric examples, in book order."""
from __future__ import annotations

from . import an94002

#: source modules in book order; each offers equations() and examples()
SOURCES = (an94002,)


def equations():
    return [e for m in SOURCES for e in m.equations()]


def examples():
    return [r for m in SOURCES for r in m.examples()]
