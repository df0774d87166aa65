"""The design report (``python -m handbook report SPEC.toml -o my-board.html`` or ``-o my-board.pdf``): one
self-contained file a reviewer can sign, built from a spec. Sections, for the tables the spec asks for
(:attr:`~handbook.design.spec.Spec.asked`):

1. the spec: what the reader changed against the defaults, then every other key (folded);
2. each designed circuit: its schematic with the chosen values, its parts with ratings, what binds, the margins;
3. the calculation sheet (``handbook.report.calcsheet``);
4. the worst-case analysis (``handbook.design.worstcase``; :mod:`.worst`);
5. SPICE's confirmation at the worst corners with this circuit's waveforms (:mod:`.simulated`);
6. losses and temperatures, and the BOM;
7. warnings, assumptions, and what the report was made from.

Every number is the design's own (``design --json``'s), each in a ``<data value=...>`` element carrying it
exactly. The handbook's version and the spec's SHA-256 are in the page's header and footer and in the running
footer of every printed page.
"""
from __future__ import annotations

from dataclasses import dataclass, field

from . import page, sections, simulated, worst


@dataclass
class Context:
    """What the sections read: the spec, its trace (``version``, ``spec_sha256``, ``spec_file``), the designed
    tables the spec asked for ({table: Result}), their BOM rows, and the warnings SPICE and the worst-case analysis
    gather on the way (section 7 lists them)."""

    spec: object
    trace: dict
    designed: dict
    bom: list
    no_spice: bool = False
    spice_warnings: list = field(default_factory=list)


def calc_section(ctx) -> str:
    """Section 3: the calculation sheet of each design (``handbook.report.calcsheet``)."""
    from .. import calcsheet

    return "".join(f"<h3>{page.esc(sections.title(t))}</h3>{calcsheet.html(calcsheet.steps(t, r))}"
                   for t, r in ctx.designed.items())


def context(spec, results: dict, spec_file: str, no_spice: bool = False) -> Context:
    """The report's context from a read spec and its designs (none of them infeasible).

    Parameters
    ----------
    spec : Spec
        The read specification (:func:`handbook.design.spec.load`).
    results : dict
        {table: Result} as :func:`handbook.design.spec.run_each` gives it, every table designed.
    spec_file : str
        The spec's file name, as the report names it.
    no_spice : bool
        Leave SPICE out (section 5 says so).

    Returns
    -------
    Context
        The tables the spec asked for, their BOM, the trace.
    """
    from ...design import bom
    from ...design.spec import traced

    designed = {t: results[t] for t in spec.asked}
    tr = traced(spec)
    return Context(spec, {"version": tr["version"], "spec_sha256": tr["spec_sha256"], "spec_file": spec_file},
                   designed, bom.rows(designed), no_spice)


def build(ctx: Context, analyse=None) -> str:
    """The report as one HTML document.

    Parameters
    ----------
    ctx : Context
        :func:`context`'s.
    analyse : callable, optional
        The worst-case analysis to use (default ``handbook.design.worstcase.analyse``).

    Returns
    -------
    str
        The self-contained HTML page.
    """
    spice_html = simulated.section(ctx)  # before section 7, which lists SPICE's warnings
    parts = [("spec", "1. The spec", sections.spec_section(ctx)),
             ("circuits", "2. The designed circuits", sections.circuits_section(ctx)),
             ("calculations", "3. Calculation sheet", calc_section(ctx)),
             ("worst-case", "4. Worst-case analysis", worst.section(ctx, analyse)),
             ("spice", "5. SPICE at the worst corners", spice_html),
             ("losses", "6. Losses, temperatures and the BOM", sections.losses_section(ctx)),
             ("notes", "7. Warnings, assumptions and trace", sections.notes_section(ctx))]
    tables = ", ".join(f"[{t}]" for t in ctx.designed)
    return page.document(f"Design report: {ctx.trace['spec_file']} ({tables})", ctx.trace, parts)


__all__ = ["Context", "build", "context"]
