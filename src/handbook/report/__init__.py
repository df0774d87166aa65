"""Everything a person reads: tables, figures and the notebook helpers the chapters call.

Chapters use ``from handbook import report`` and call ``report.setup()``, ``report.table(...)``,
``report.examples_table(...)``, ``report.axes(...)``, ``report.eng(...)`` and so on; the design
figures are in :mod:`handbook.report.design_plots`.
"""
from .figures import axes, format_axis
from .notebook import glue_all, setup, show_equation
from .tables import BADGE, ERRATA_KINDS, design_table, eng, errata_counts, errata_md, examples_table, table

__all__ = ["BADGE", "ERRATA_KINDS", "axes", "design_table", "eng", "errata_counts", "errata_md", "examples_table",
           "format_axis", "glue_all", "setup", "show_equation", "table"]
