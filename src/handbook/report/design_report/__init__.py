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
    gather on the way (section 7 lists them); ``unmet`` holds {table: why} for a table nothing can meet (the book's
    form of the report shows what can be met; the command writes no report then)."""

    spec: object
    trace: dict
    designed: dict
    bom: list
    no_spice: bool = False
    spice_warnings: list = field(default_factory=list)
    unmet: dict = field(default_factory=dict)


def calc_section(ctx) -> str:
    """Section 3: the calculation sheet of each design (``handbook.report.calcsheet``)."""
    from .. import calcsheet

    return "".join(f"<h3>{page.esc(sections.title(t))}</h3>{calcsheet.html(calcsheet.steps(t, r))}"
                   for t, r in ctx.designed.items())


def context(spec, results: dict, spec_file: str, no_spice: bool = False) -> Context:
    """The report's context from a read spec and its designs.

    Parameters
    ----------
    spec : Spec
        The read specification (:func:`handbook.design.spec.load`).
    results : dict
        {table: Result or Infeasible} as :func:`handbook.design.spec.run_each` gives it; a table that cannot be met
        goes to ``unmet`` with its message (what can be met), section 7 lists it.
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
    from ...design.solvers import Infeasible
    from ...design.spec import traced

    designed = {t: results[t] for t in spec.asked if not isinstance(results[t], Infeasible)}
    unmet = {t: str(results[t]) for t in spec.asked if t not in designed}
    tr = traced(spec)
    return Context(spec, {"version": tr["version"], "spec_sha256": tr["spec_sha256"], "spec_file": spec_file},
                   designed, bom.rows(designed), no_spice, unmet=unmet)


def for_book(spec_file: str = "", no_spice: bool = False) -> Context:
    """The context of the book's form of the report (the chapter "Design your own" and the worked examples): the
    spec file read and designed, or, with none, the notes' own examples (every table at its default).

    Parameters
    ----------
    spec_file : str
        The TOML file (absolute, or relative to the working folder); empty: no file.
    no_spice : bool
        Leave SPICE out.

    Returns
    -------
    Context
        As :func:`context` gives it (a table nothing can meet in ``unmet``).
    """
    from pathlib import Path

    from ...design import spec as specmod

    s = specmod.load(spec_file) if spec_file else specmod.parse({})
    name = Path(spec_file).name if spec_file else "none (the notes' examples)"
    return context(s, specmod.run_each(s), name, no_spice)


def _worst(ctx, analyse=None) -> str:
    return worst.section(ctx, analyse)


#: the report's sections in order: (anchor, heading, the function of the context that writes the body); a section's
#: function may add to ``ctx.spice_warnings``, which section 7 lists, so they run in this order
SECTIONS = (("spec", "1. The spec", sections.spec_section),
            ("circuits", "2. The designed circuits", sections.circuits_section),
            ("calculations", "3. Calculation sheet", calc_section),
            ("worst-case", "4. Worst-case analysis", _worst),
            ("spice", "5. SPICE at the worst corners", simulated.section),
            ("losses", "6. Losses, temperatures and the BOM", sections.losses_section),
            ("notes", "7. Warnings, assumptions and trace", sections.notes_section))


def body(ctx: Context, sid: str, analyse=None) -> str:
    """One section's body HTML.

    Parameters
    ----------
    ctx : Context
        :func:`context`'s.
    sid : str
        The section's anchor (:data:`SECTIONS`).
    analyse : callable, optional
        The worst-case analysis for section 4 (default ``handbook.design.worstcase.analyse``).

    Returns
    -------
    str
        HTML.
    """
    fn = dict((a, f) for a, _, f in SECTIONS)[sid]
    return fn(ctx, analyse) if fn is _worst else fn(ctx)


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
    parts = [(sid, head, body(ctx, sid, analyse)) for sid, head, _ in SECTIONS]
    tables = ", ".join(f"[{t}]" for t in ctx.designed)
    return page.document(f"Design report: {ctx.trace['spec_file']} ({tables})", ctx.trace, parts)


def show(ctx: Context, sid: str):
    """One section as the book shows it (``IPython.display.HTML``): the report's own HTML, in a box carrying the
    report's styles for tables, figures and math (:func:`.page.fragment`).

    Parameters
    ----------
    ctx : Context
        :func:`for_book`'s.
    sid : str
        The section's anchor (:data:`SECTIONS`).

    Returns
    -------
    IPython.display.HTML
    """
    from IPython.display import HTML

    return HTML(page.fragment(body(ctx, sid)))


__all__ = ["SECTIONS", "Context", "body", "build", "context", "for_book", "show"]
