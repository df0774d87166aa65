"""Everything a person reads: tables, figures and the notebook helpers the chapters call.

Chapters use ``from handbook import report`` and call ``report.setup()``, ``report.table(...)``,
``report.examples_table(...)``, ``report.axes(...)``, ``report.eng(...)`` and so on; the design
figures are in :mod:`handbook.report.design_plots`. The names load on first use, so the command line's
text output (which needs only :mod:`.tables`) does not import pyplot.
"""
from importlib import import_module

_HOME = {"axes": "figures", "format_axis": "figures", "glue_all": "notebook", "is_note": "notebook",
         "note_only": "notebook", "sentence": "notebook", "setup": "notebook",
         "show_equation": "notebook", "BADGE": "tables", "ERRATA_KINDS": "tables", "design_table": "tables",
         "bom_table": "tables", "readable": "tables",
         "eng": "tables", "errata_counts": "errata", "errata_md": "errata", "reading_notes_md": "errata",
         "review_table": "errata", "examples_table": "tables",
         "table": "tables", "folded": "tables", "chapter_table": "spice_tables", "rows_table": "spice_tables",
         "confirm_table": "spice_tables"}

__all__ = sorted(_HOME)


def __getattr__(name: str):
    if name not in _HOME:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    return getattr(import_module(f".{_HOME[name]}", __name__), name)
