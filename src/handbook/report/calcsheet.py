"""The design report's calculation sheet: every equation a design uses, as symbols, with the reader's numbers,
and its result, in the order the design uses them.

:func:`steps` gives one :class:`Step` per equation of the registry a design uses (its symbols from the record:
the derived form, or an empirical equation's printed form, as the title says; then the same with the design's
own values substituted, each with its unit) and one step in words where the design uses a number no registry
equation gives (a search, an E-series pick, a tolerance, a rating rule). :func:`html` writes them as a
``<section>`` with the math as presentation MathML (:mod:`.mathml`), which Chromium renders offline (no MathJax,
no network). The steps of each design are in :mod:`.calcsheet_designs`, their parts in :mod:`.calcsheet_steps`.
"""
from __future__ import annotations

from html import escape

from .calcsheet_designs import BUILDERS
from .calcsheet_steps import Step
from .mathml import to_mathml

__all__ = ["Step", "html", "steps"]


def steps(table: str, result) -> list[Step]:
    """The calculation sheet of one design: its steps in the order the design takes them.

    Parameters
    ----------
    table : str
        The spec table ("commutation", "current_limiter", "class_d", "converter").
    result : Result
        That design's result (its ``spec`` the checked table it was designed from).

    Returns
    -------
    list of Step
        One step per registry equation the design uses, and one in words per number it takes elsewhere.
    """
    if table not in BUILDERS:
        raise KeyError(f"no calculation sheet for [{table}]; known: {', '.join(BUILDERS)}")
    return BUILDERS[table](result)


def html(steps: list[Step]) -> str:
    """The steps as an HTML fragment: a ``<section>`` with one block per step, the math as MathML.

    Parameters
    ----------
    steps : list of Step
        The calculation sheet (:func:`steps`).

    Returns
    -------
    str
        ``<section class="calcsheet">`` with one ``<div class="calc-step">`` per step: its title, the equation in
        symbols and with the values (MathML), the result, the source and the errata beside it.
    """
    blocks = []
    for i, st in enumerate(steps, 1):
        math = "".join(f'<div class="calc-math">{to_mathml(t)}</div>' for t in (st.symbols_tex, st.substituted_tex)
                       if t)
        errata = "".join(f"<li>{escape(line)}</li>" for line in st.errata)
        aside = (f'<aside class="calc-aside"><p class="calc-source">{escape(st.source)}</p>'
                 + (f'<ul class="calc-errata">{errata}</ul>' if errata else "") + "</aside>")
        blocks.append(f'<div class="calc-step{" calc-words" if not st.symbols_tex else ""}">'
                      f'<h4><span class="calc-n">{i}.</span> {_title_html(st.title)}</h4>{math}'
                      f'<p class="calc-result">{escape(st.result_text)}</p>{aside}</div>')
    return '<section class="calcsheet">' + "".join(blocks) + "</section>"


def _title_html(title: str) -> str:
    """A title with inline math ($...$) as inline MathML."""
    parts = title.split("$")
    return "".join(to_mathml(p, display=False) if i % 2 else escape(p) for i, p in enumerate(parts))
