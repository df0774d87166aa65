"""The calculation sheet's parts: :class:`Step`, the registry look-up (records, their errata), the values as
shown with their units, and the two kinds of step (from a registry record, in words).

A step from a record shows its derived form (an empirical record: its printed form), optionally solved for one
symbol, and the same with the design's own values substituted, each with its unit (:func:`equation_step`);
a number no registry equation gives is a step in words (:func:`words`). :mod:`.calcsheet` assembles them.
"""
from __future__ import annotations

import functools
import re
from dataclasses import dataclass

import sympy as sp

from ..core.units import eng, readable


@dataclass(frozen=True)
class Step:
    """One step of the calculation sheet."""

    title: str  # what the step computes; for a step in words, the sentence itself
    symbols_tex: str  # the equation in symbols (LaTeX), from the registry record; "" for a step in words
    substituted_tex: str  # the same with the design's values, each with its unit; "" for a step in words
    result_text: str  # the result as eng() writes it
    source: str  # note, section and equation number (the record's source), or what the number rests on
    errata: tuple = ()  # one line per registered erratum of the equation: "id: what is wrong"


# ----------------------------------------------------------------------------------------------
# the registry

@functools.cache
def record(eq_id: str):
    """The equation record ``eq_id`` of whichever source registers it.

    Parameters
    ----------
    eq_id : str
        The record's id ("an94002-eq6").

    Returns
    -------
    Equation
        The record.
    """
    from ..sources import SOURCES

    for src in SOURCES:
        for e in src.equations():
            if e.id == eq_id:
                return e
    raise KeyError(f"no equation record {eq_id!r}")


def _source_of(e):
    from ..sources import SOURCES

    return max((s for s in SOURCES if e.source.startswith(s.name)), key=lambda s: len(s.name))


_EQ_LIST = re.compile(r"\beqs?\.?\s*((?:\(?\d+[a-z]?\)?(?:\s*(?:,|and|to|&)\s*(?=\(?\d))?)+)", re.I)


def equation_numbers(text: str) -> set[str]:
    """The equation numbers a source reference names: "AN94002 2.1.2, eq (6) and (7)" -> {"6", "7"}.

    Parameters
    ----------
    text : str
        A reference to a source document.

    Returns
    -------
    set of str
        Every number written after "eq" (with a letter suffix kept: "6a").
    """
    return {n for m in _EQ_LIST.finditer(text) for n in re.findall(r"\d+[a-z]?", m.group(1))}


@functools.cache
def _errata_rows(src) -> tuple:
    """(id, the references it is made at, one line) of every erratum of ``src``."""
    rows = []
    places = lambda ident: tuple(src.cases[ident].places) if ident in src.cases else ()  # noqa: E731
    by_id = {c.id: c for c in src.claims()}
    for r in src.evaluate():
        if r["status"] in ("misprint", "inconsistent", "wrong method") and not by_id[r["id"]].same_fact:
            line = readable(f"{r['id']}: {r['quantity']} printed {r['printed_text']} ({r['status']}: {r['reason']})")
            rows.append((r["id"], (r["source"], *places(r["id"])), line))
    for t in src.errata:
        if not t.same_fact:
            rows.append((t.id, (t.source, *places(t.id)), readable(f"{t.id}: {t.what}")))
    return tuple(rows)


def errata_named(ids: tuple) -> tuple:
    """The registered errata of the given ids, one line each as :func:`errata_of` writes them: for a step that
    rests on a figure an erratum of its source disputes, though not at an equation number.

    Parameters
    ----------
    ids : tuple of str
        Erratum ids ("lm4651-dead-time").

    Returns
    -------
    tuple of str
        One line per id found, "id: what is wrong", in the order given.
    """
    from ..sources import SOURCES

    rows = {ident: line for s in SOURCES for ident, _where, line in _errata_rows(s)}
    return tuple(rows[i] for i in ids if i in rows)


def errata_of(e) -> tuple:
    """Every registered erratum of the record ``e``: the record itself where its printed form is wrong, and each
    erratum of its source document made at its equation number.

    Parameters
    ----------
    e : Equation
        The record.

    Returns
    -------
    tuple of str
        One line per erratum, "id: what is wrong"; empty when there is none.
    """
    src = _source_of(e)
    own = equation_numbers(e.source)
    out = []
    check = e.check()
    if (not check.agrees and check.relation == "differs" and not e.rounded_constants) or not check.dims_ok:
        out.append(f"{e.id}: the printed form differs from its derivation ({e.note or check.dims_note})")
    for _ident, where, line in _errata_rows(src):
        if own and any(p.startswith(src.name) and own & equation_numbers(p) for p in where):
            out.append(line)
    return tuple(out)


# ----------------------------------------------------------------------------------------------
# values and units

#: units written without an SI prefix (a prefix on kg or on a compound unit misleads)
_PLAIN = {"N·m/A", "kg·m²", "K/W", "°C", "K", "1", ""}


def _unit_tex(unit: str) -> str:
    out, word = [], ""
    for ch in unit:
        if ch in "µΩ":
            if word:
                out.append(r"\text{" + word + "}")
                word = ""
            out.append(r"\mu" if ch == "µ" else r"\Omega")
        else:
            word += ch
    if word:
        out.append(r"\text{" + word + "}")
    return "".join(out)


def _plain_number(value: float) -> str:
    if value != 0 and not 1e-3 <= abs(value) < 1e5:
        mantissa, exponent = f"{value:.4g}".split("e") if "e" in f"{value:.4g}" else (f"{value:.4g}", "0")
        if exponent != "0":
            return rf"{float(mantissa):g} \times 10^{{{int(exponent)}}}"
    return f"{float(f'{value:.4g}'):g}"


def _sci_text(tex: str) -> str:
    """A number as :func:`_plain_number` writes it, in plain text: "4.2 \\times 10^{6}" -> "4.2 × 10⁶"."""
    mantissa, _, exponent = tex.partition(r" \times 10^")
    return mantissa + (" × 10" + exponent.strip("{}").translate(str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹"))
                       if exponent else "")


def shown(value: float, unit: str) -> tuple[str, str]:
    """A value in SI units as the sheet shows it: (LaTeX, text).

    Parameters
    ----------
    value : float
        The value, SI (a speed in 1/s, shown in rpm; a temperature in C).
    unit : str
        Its unit symbol as people read it ("A", "F", "Ω", "rpm", "°C", "N·m/A"; "1" or "" for a pure number; "%"
        for a fraction shown in per cent; "1/H" for a reluctance; "m²" shown in mm²).

    Returns
    -------
    tuple of str
        (LaTeX with a thin space before the unit, plain text as :func:`~handbook.core.units.eng` writes it).
    """
    if unit == "rpm":  # to the revolution, as the results tables show speeds (10259 rpm, not 10260)
        number = f"{value * 60.0:.0f}"
        return rf"{number}\,\text{{rpm}}", f"{number} rpm"
    if unit == "1/H":  # a reluctance: a power of ten, not a prefix (a "MA/Wb" misleads)
        tex = _plain_number(value)
        return rf"{tex}\,\text{{H}}^{{-1}}", _sci_text(tex) + " H⁻¹"
    if unit == "m²":  # an area in mm² (a prefix on m² would square too: 11 µm² is not 11e-6 m²)
        return rf"{_plain_number(value * 1e6)}\,\text{{mm}}^2", f"{value * 1e6:.4g} mm²"
    if unit == "%":  # a fraction shown in per cent
        return rf"{_plain_number(value * 100)}\,\%", f"{value * 100:.3g} %"
    if unit in _PLAIN:
        tex = _plain_number(value)
        if unit in ("1", ""):
            return tex, eng(value)
        return rf"{tex}\,{_unit_tex(unit)}", f"{eng(value)} {unit}"
    text = eng(value, unit).replace("\N{MINUS SIGN}", "-")
    number, _, prefixed_unit = text.partition(" ")
    return rf"{number}\,{_unit_tex(prefixed_unit)}", text.replace("-", "\N{MINUS SIGN}")


# ----------------------------------------------------------------------------------------------
# steps

def _symbol(expr, lhs, name: str):
    for s in (expr.free_symbols | {lhs}):
        if s.name == name:
            return s
    raise KeyError(f"no symbol {name!r} in {expr}")


def equation_step(title: str, eq_id: str, values: dict, result: tuple, solve_for: str | None = None,
                  errata: tuple = ()) -> Step:
    """A step from the registry record ``eq_id``: its derived form (an empirical record: its printed form),
    optionally solved for one symbol, with ``values`` substituted.

    Parameters
    ----------
    title : str
        What the step computes; the form used is added ("derived form", "printed form", "solved for ...").
    eq_id : str
        The record's id.
    values : dict
        {symbol name as in the record: (value in SI units, unit as :func:`shown` takes it)}, one per free
        symbol of the form used.
    result : tuple
        (the design's value, SI; its unit): what the step gives.
    solve_for : str or None
        Solve the record for this symbol's name (the left side becomes the right's unknown).
    errata : tuple of str
        Ids of further errata the step rests on (:func:`errata_named`), beside the record's own.

    Returns
    -------
    Step
        The step, with the record's source and errata.
    """
    e = record(eq_id)
    form = "printed" if e.empirical else "derived"
    expr, lhs = (e.printed, e.lhs) if e.empirical else (e.derived, e.lhs)
    lhs_tex = e.latex_printed().split(" = ")[0] if e.empirical else _latex(lhs)
    rel = r"\ge" if e.relation == ">=" else "="
    symbols_tex = e.latex_printed() if e.empirical else e.latex_derived()
    if solve_for is not None:
        unknown = _symbol(expr, lhs, solve_for)
        expr = _solved(sp.Eq(lhs, expr), unknown)
        lhs, lhs_tex, rel = unknown, _latex(unknown), "="
        symbols_tex = f"{lhs_tex} = {_latex(expr)}"
        form += f" form solved for ${lhs_tex}$"
    else:
        form += " form"
    names = {s.name: s for s in expr.free_symbols}
    missing = set(names) - set(values)
    if missing:
        raise KeyError(f"{eq_id}: no value for {', '.join(sorted(missing))}")
    subst = {names[n]: shown(*values[n])[0] for n in names}
    if e.empirical and e.printed_tex and solve_for is None and all(n in e.printed_tex for n in names):
        # the printed form as the record writes it (sympy would multiply its constants together)
        rhs = e.printed_tex
        for n in sorted(names, key=len, reverse=True):
            rhs = rhs.replace(n, subst[names[n]])
        substituted = f"{lhs_tex} {rel} {rhs}"
    else:
        powered = {p.base for p in expr.atoms(sp.Pow) if p.base.is_Symbol and p.exp not in (-1, sp.S.Half, -sp.S.Half)}
        subst = {s: rf"\left({v}\right)" if s in powered and r"\," in v else v for s, v in subst.items()}
        fitted = expr.xreplace({c: sp.Float(c, 4) for c in expr.atoms(sp.Float)})  # a fitted constant to 4 digits
        substituted = f"{lhs_tex} {rel} {sp.latex(fitted, symbol_names=subst, mul_symbol='dot')}"
    return Step(f"{title} ({e.title}, {form})", symbols_tex, substituted, shown(*result)[1], e.source,
                tuple(dict.fromkeys(errata_of(e) + errata_named(errata))))


def _latex(expr) -> str:
    from ..core.equation import latex

    return latex(expr)


def _solved(equation, unknown):
    sols = sp.solve(equation, unknown)
    positive = [s for s in sols if not s.could_extract_minus_sign()]
    return (positive or sols)[0]


def words(title: str, result: tuple, source: str, errata: tuple = ()) -> Step:
    """A step in words: a number the design takes from no registry equation (a search, a series pick, a rating).

    Parameters
    ----------
    title : str
        The sentence ("E12 value at or above 16.4 nF: 18 nF").
    result : tuple
        (the value, SI; its unit as :func:`shown` takes it), or (text, "") for a result that is not a number.
    source : str
        What the number rests on (the design module, a datasheet).
    errata : tuple of str
        Ids of the registered errata the number rests on (:func:`errata_named`).

    Returns
    -------
    Step
        A step with no equation (``symbols_tex`` and ``substituted_tex`` empty).
    """
    value, unit = result
    text = value if isinstance(value, str) else shown(value, unit)[1]
    return Step(title, "", "", text, source, errata_named(errata))


