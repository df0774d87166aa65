"""One package per source document, each split by job and each exposing one :class:`~handbook.core.Source`:

* ``circuit``: the engineering functions (SI in, SI out);
* ``data``: the parameters with their defaults, the outside facts with citations, the textual errata;
* ``equations``: the symbolic registry, one small function per equation;
* ``claims``: every number the document prints, with its recomputation.

``SOURCES`` lists them in book order.
"""
from __future__ import annotations

import importlib

#: the source packages, in book order
ORDER = ("an94002", "an93008", "tda5341", "lm4651", "tca5600")


def __getattr__(name: str):
    """``SOURCES``: every source document's :class:`~handbook.core.Source`, in book order (imported on
    first use, so that importing one source does not import them all)."""
    if name == "SOURCES":
        return tuple(importlib.import_module(f"{__name__}.{m}").SOURCE for m in ORDER)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
