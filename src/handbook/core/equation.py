"""Equation records: a printed equation, its derivation from circuit laws, and their symbolic check.

An :class:`Equation` holds an app note's equation three ways:

* ``printed``: the right-hand side *as printed*, in the note's own symbols. Where the note hides a
  unit in its constants ("C in uF") the printed symbols stand for plain numbers in those units, and
  ``scales`` says which physical quantity each one is (``C_uF = C / uF``).
* ``derived``: the same quantity derived here from a circuit law (charge balance, KCL, the op-amp
  virtual short, ...), in physical symbols carrying SI units.
* ``values``: the note's numbers for constants (charge currents, voltage levels), with units, so a
  printed form with the numbers folded into one constant can be compared with the derived one.

:meth:`Equation.check` makes the printed form physical (every hidden unit made explicit), then
compares it with the derived form symbolically: the difference simplifies to zero, or the ratio
simplifies to a pure number (a rounded constant), or the two differ structurally, and each case is
recorded. The dimensions of both sides are checked with ``sympy.physics.units``.

An *empirical* equation (``empirical=True``) is a number-only formula for a circuit the source does
not show (an internal oscillator, a reference, a timer): no circuit law can be written for it, so it has
no ``derived`` form. ``fitted_to`` says what its constants reproduce, and its check is the printed form
evaluated at the figures the source prints elsewhere (``table``: its tables, typical values, worked
text), each within half a unit of the figure's last digit.

The check is computed once per record (the record is frozen) and, through
:mod:`handbook.core.checks_cache`, stored on disk keyed on the code that defines it.
"""
from __future__ import annotations

import functools
from dataclasses import dataclass, field, replace
from decimal import ROUND_HALF_EVEN, ROUND_HALF_UP, Decimal

import sympy as sp
from sympy.physics import units as u
from sympy.physics.units.systems.si import SI, dimsys_SI

from .claim import UNIT_SCALES, Printed

# ----------------------------------------------------------------------------------------------
# units

def dimension_of(expr: sp.Expr):
    """The SI dimension of an expression built from sympy unit quantities.

    Raises ``ValueError`` (from sympy) when a sum adds unlike dimensions.

    Parameters
    ----------
    expr : sympy.Expr
        An expression of symbols and sympy unit quantities.

    Returns
    -------
    sympy.physics.units.Dimension
        Its dimension in the SI system.
    """
    _, dim = SI._collect_factor_and_dimension(expr)
    return dim


def same_dimension(a, b) -> bool:
    """Whether two SI dimensions are equivalent (``dimsys_SI.equivalent_dims``).

    Parameters
    ----------
    a, b : sympy.physics.units.Dimension
        The dimensions compared.

    Returns
    -------
    bool
        True when they reduce to the same base dimensions.
    """
    return dimsys_SI.equivalent_dims(a, b)


def to_si_number(expr: sp.Expr) -> sp.Expr:
    """Convert a dimensionless expression of unit quantities to a plain number (exact where possible).

    Parameters
    ----------
    expr : sympy.Expr
        A dimensionless expression of sympy unit quantities (a ratio of two quantities of one dimension).

    Returns
    -------
    sympy.Expr
        The expression in base SI units, simplified: a plain number where it is one.
    """
    base = [u.kilogram, u.meter, u.second, u.ampere, u.kelvin]
    return sp.simplify(u.convert_to(expr, base))


def _decimal(r: sp.Rational) -> sp.Expr:
    """A rational whose denominator is 2^a 5^b as the Float the note printed (2.15, not 43/20)."""
    q = int(r.q)
    for k in (2, 5):
        while q % k == 0:
            q //= k
    if q != 1 or r.q == 1:
        return r
    text = format(Decimal(int(r.p)) / Decimal(int(r.q)), "f")
    return sp.Float(text, len(text.replace("-", "").replace(".", "").lstrip("0")) or 1)


def latex(expr) -> str:
    """LaTeX of ``expr`` with decimal constants shown as printed in the note.

    Parameters
    ----------
    expr : sympy.Expr or object
        The expression (anything ``sympy.sympify`` takes).

    Returns
    -------
    str
        Its LaTeX, rationals with a decimal expansion written as decimals (2.15, not 43/20) and the vacuum
        permittivity and permeability as their symbols.
    """
    expr = sp.sympify(expr)
    exponents = {a for pw in expr.atoms(sp.Pow) for a in pw.exp.atoms(sp.Rational)}
    swap = {r: _decimal(r) for r in expr.atoms(sp.Rational) - exponents if r.q not in (1, 2, 4)}
    # a physical constant of sympy.physics.units prints as its name (\text{vacuum_permittivity}): its symbol
    swap.update({q: sp.Symbol(_CONSTANT_TEX[q.name.name]) for q in expr.atoms(u.Quantity)
                 if q.name.name in _CONSTANT_TEX})
    return sp.latex(expr.xreplace(swap))


_CONSTANT_TEX = {"vacuum_permittivity": r"\varepsilon_0", "vacuum_permeability": r"\mu_0"}


_FIGURE_UNIT_TEX = {"kohm": r"\mathrm{k\Omega}", "ohm": r"\Omega", "uF": r"\mu\mathrm{F}", "us": r"\mu\mathrm{s}",
                    "%": r"\%"}

_UNIT_TEX = {"second": r"\mathrm{s}", "farad/1000000": r"\mu\mathrm{F}", "farad": r"\mathrm{F}",
             "volt": r"\mathrm{V}", "1/minute": r"\mathrm{rpm}"}


# ----------------------------------------------------------------------------------------------
# equations

@dataclass(frozen=True)
class Check:
    """Outcome of comparing a printed form with its derivation."""

    agrees: bool
    relation: str  # "identical", "constant factor", "differs"
    factor: sp.Expr | None  # printed / derived when it is a pure number
    difference: sp.Expr | None  # printed - derived (physical), simplified
    dims_ok: bool  # printed and derived forms are dimensionally consistent with the left side
    dims_note: str
    points: tuple = ()  # empirical equations: one (where, at, printed text, value in its unit, deviation, ok) each


def rounds_to(text: str, exact: float) -> bool:
    """``exact`` rounded to the significant figures of the printed ``text`` (half up or half even) is ``text``.

    Parameters
    ----------
    text : str
        The number as printed ("160", "0.070", "2.63"): an integer's trailing zeros are not significant, a
        decimal's are.
    exact : float
        The value it stands for.

    Returns
    -------
    bool
        True when either rounding rule gives the printed number.
    """
    digits = text.lstrip("+-")
    figures = len(digits.replace(".", "").lstrip("0")) if "." in digits else len(digits.rstrip("0")) or 1
    value = Decimal(repr(exact))
    if value == 0:
        return Decimal(text) == 0
    step = Decimal(1).scaleb(value.adjusted() - figures + 1)
    return any(value.quantize(step, rounding=mode) == Decimal(text) for mode in (ROUND_HALF_UP, ROUND_HALF_EVEN))


@dataclass(frozen=True)
class TablePoint:
    """A figure the source itself prints, which an empirical equation's printed form must reproduce."""

    where: str  # where the source prints it ("LM4651 table, R_OSC = 15 k")
    at: str  # the inputs as LaTeX ("R_{OSC} = 15\\,\\mathrm{k\\Omega}")
    inputs: dict  # physical symbol -> SI value
    figure: Printed  # the figure as printed (its unit and last digit give the comparison's tolerance)
    through: object = None  # optional: maps the printed form's SI value to the figure's quantity (a chain)


@dataclass(frozen=True, kw_only=True, eq=False)
class Equation:
    id: str
    source: str  # note, section, equation number
    title: str
    lhs: sp.Symbol  # physical quantity on the left
    lhs_unit: sp.Expr  # its SI unit (a sympy quantity expression)
    printed: sp.Expr  # right-hand side as printed, in the printed symbols
    derived: sp.Expr | None = None  # right-hand side from circuit laws, physical symbols (None: empirical)
    units: dict  # physical symbol -> sympy unit
    law: str = ""  # which circuit law the derivation uses
    scales: dict = field(default_factory=dict)  # printed symbol -> physical expression it stands for
    lhs_scale: sp.Expr | None = None  # the printed left side is lhs / lhs_scale (e.g. C / uF)
    values: dict = field(default_factory=dict)  # physical symbol -> value with units (note's numbers)
    relation: str = "="  # "=" or ">=" (bounds are recorded by their limiting expression)
    note: str = ""  # how they differ, what was reconstructed, what a symbol means
    reconstructed: str = ""  # what the OCR garbled and how the form was rebuilt
    ocr_form: sp.Expr | None = None  # the OCR text taken literally, where it differs
    printed_tex: str = ""  # the printed right side as LaTeX, where sympy would re-arrange it
    rounded: tuple = ()  # (printed constant as text, its exact value): the source rounded these, nothing else
    empirical: bool = False  # fitted to figures, not derivable: the source does not show the circuit
    fitted_to: str = ""  # what the printed constants reproduce (empirical equations)
    table: tuple = ()  # TablePoint: the source's own figures the printed form is checked against

    def __post_init__(self):
        if self.empirical and (self.derived is not None or not self.fitted_to):
            raise ValueError(f"{self.id}: an empirical equation has no derived form and says what it is fitted to")
        if not self.empirical and self.derived is None:
            raise ValueError(f"{self.id}: a derived form is required (or empirical=True with fitted_to)")

    # -- forms -------------------------------------------------------------------------------
    def printed_physical(self) -> sp.Expr:
        """The printed right side with every hidden unit made explicit (a physical quantity).

        Returns
        -------
        sympy.Expr
            The printed right side with ``scales`` substituted and multiplied by ``lhs_scale``, in the physical
            symbols (SI units of the left side).
        """
        rhs = self.printed.subs(self.scales)
        if self.lhs_scale is not None:
            rhs = rhs * self.lhs_scale
        return rhs

    def derived_at_values(self) -> sp.Expr:
        """The derived right side with the note's constants (``values``) substituted.

        Returns
        -------
        sympy.Expr
            ``derived`` with each symbol of ``values`` replaced by its value with units (not defined for an
            empirical equation, which has no derived form).
        """
        return self.derived.subs(self.values)

    def value_at(self, inputs: dict) -> float:
        """The printed form at ``inputs`` (physical symbol -> SI value), in SI units of the left side.

        Parameters
        ----------
        inputs : dict
            Physical symbol -> its value in SI units, for every free symbol of the printed form.

        Returns
        -------
        float
            The printed form's value, in the SI unit of the left side (``lhs_unit``).
        """
        expr = self._with_units(self.printed_physical()).subs(inputs, simultaneous=True) / self.lhs_unit
        return float(to_si_number(expr))

    def _with_units(self, expr: sp.Expr) -> sp.Expr:
        # symbol -> symbol x unit (not the bare unit: V_s - V_D1 must not cancel to zero)
        return expr.subs({s: s * unit for s, unit in self.units.items()}, simultaneous=True)

    def check(self) -> Check:
        """The comparison of the printed and derived forms (computed once, then remembered).

        Returns
        -------
        Check
            Agreement, relation (``"identical"``, ``"constant factor"``, ``"differs"`` or ``"empirical"``),
            the ratio and difference where they apply, the dimension check and, for an empirical equation, its
            points against the source's own figures.
        """
        return self._check

    @functools.cached_property
    def _check(self) -> Check:
        printed = self.printed_physical()
        derived = None if self.empirical else self.derived_at_values()
        # Dimensions: both sides must carry the left side's dimension.
        lhs_dim = dimension_of(self.lhs_unit)
        notes = []
        dims_ok = True
        for name, form in (("printed", printed), ("derived", derived)):
            if form is None:
                continue
            try:
                d = dimension_of(self._with_units(form))
            except ValueError as exc:  # a sum of unlike dimensions
                dims_ok = False
                notes.append(f"{name}: {exc}")
                continue
            if not same_dimension(d, lhs_dim):
                dims_ok = False
                notes.append(f"{name} form has dimension {d}, left side {lhs_dim}")
        if self.empirical:
            return self._table_check(dims_ok, "; ".join(notes))
        # Agreement: difference zero, or a pure-number ratio, else structural.
        diff = to_si_number(self._with_units(printed - derived) / self.lhs_unit)
        if diff == 0:
            return Check(True, "identical", sp.Integer(1), sp.Integer(0), dims_ok, "; ".join(notes))
        ratio = to_si_number(self._with_units(printed) / self._with_units(derived))
        if ratio.is_number:
            same = sp.simplify(ratio - 1) == 0
            return Check(bool(same), "identical" if same else "constant factor", ratio,
                         None if same else diff, dims_ok, "; ".join(notes))
        return Check(False, "differs", None, diff, dims_ok, "; ".join(notes))

    def _table_check(self, dims_ok: bool, dims_note: str) -> Check:
        """An empirical equation: the printed form at each of the source's own figures, within half a unit of
        the figure's last printed digit."""
        points = []
        for pt in self.table:
            value = self.value_at(pt.inputs)
            if pt.through is not None:
                value = float(pt.through(value))
            scale = UNIT_SCALES[pt.figure.unit][0]
            ok = abs(value - pt.figure.si) <= pt.figure.half_unit * (1 + 1e-9)
            dev = value / pt.figure.si - 1 if pt.figure.si else None  # None: a zero figure, no ratio
            points.append((pt.where, pt.at, str(pt.figure), value / scale, dev, bool(ok)))
        return Check(all(p[-1] for p in points), "empirical", None, None, dims_ok, dims_note, tuple(points))

    def ocr_dims_ok(self) -> bool | None:
        """Whether the OCR text taken literally is dimensionally consistent (None if no OCR form).

        Returns
        -------
        bool or None
            True if the OCR form has the left side's dimension, False if not (or if it adds unlike dimensions),
            None when there is no OCR form.
        """
        if self.ocr_form is None:
            return None
        try:
            d = dimension_of(self._with_units(self.ocr_form.subs(self.scales)))
        except ValueError:
            return False
        return same_dimension(d, dimension_of(self.lhs_unit))

    # -- display -----------------------------------------------------------------------------
    def latex_printed(self) -> str:
        """The printed equation as LaTeX: left side (with its hidden unit), relation, printed form.

        Returns
        -------
        str
            LaTeX of the whole equation, using ``printed_tex`` where it is given.
        """
        lhs = latex(self.lhs)
        if self.lhs_scale is not None:
            lhs += r"\,[" + _UNIT_TEX.get(str(self.lhs_scale), latex(self.lhs_scale)) + "]"
        rel = r"\ge" if self.relation == ">=" else "="
        return f"{lhs} {rel} {self.printed_tex or latex(self.printed)}"

    def latex_derived(self) -> str:
        """The derived form, or for an empirical equation the printed form at the source's own figures.

        Returns
        -------
        str
            LaTeX of the derived equation, or for an empirical equation an ``array`` with one row per figure
            (inputs, printed form's value, datasheet figure, check mark or deviation).
        """
        if self.empirical:
            return self._latex_table()
        rel = r"\ge" if self.relation == ">=" else "="
        return f"{latex(self.lhs)} {rel} {latex(self.derived)}"

    def _latex_table(self) -> str:
        rows = []
        for _where, at, figure, value, dev, ok in self.check().points:
            number, unit = figure.split(" ", 1)
            u_tex = "" if unit == "1" else r"\," + _FIGURE_UNIT_TEX.get(unit, r"\mathrm{" + unit + "}")
            off = rf"{100 * dev:+.1f}\,\%" if dev is not None else rf"{value - float(number):+.4g}{u_tex}"
            mark = r"\checkmark" if ok else off
            rows.append(rf"{at} & \text{{printed form: }} {value:.4g}{u_tex} & \text{{datasheet: }} {number}{u_tex}"
                        rf" & {mark}")
        return r"\begin{array}{llll}" + r" \\ ".join(rows) + r"\end{array}" if rows else r"\text{(no figure to check)}"

    @functools.cached_property
    def rounded_constants(self) -> bool:
        """The printed form differs from the derived one by rounded constants only: each printed constant of
        ``rounded`` is its exact value rounded to the figures printed (half up or half even), and with the exact
        values put back the printed form agrees with the derivation."""
        if not self.rounded or self.empirical or self.check().agrees:
            return False
        if not all(rounds_to(text, float(exact)) for text, exact in self.rounded):
            return False
        swap = {}
        for text, exact in self.rounded:
            swap.update({sp.Rational(text): sp.sympify(exact), -sp.Rational(text): -sp.sympify(exact)})
        return replace(self, printed=self.printed.xreplace(swap), rounded=()).check().agrees

    def summary(self) -> dict:
        """The equation's summary for the chapters, the errata and the command line (JSON-ready).

        Returns
        -------
        dict
            ``id``, ``source``, ``title``, ``printed_latex``, ``derived_latex``, ``agrees``, ``relation``,
            ``factor`` (printed / derived as a float, or None), ``dimensions_ok``, ``law``, ``note`` (the verdict
            and the record's notes), ``reconstructed``, ``rounded_constants``, ``empirical`` and ``fitted_to``.
        """
        c = self.check()
        if self.empirical:
            return self._summary_empirical(c)
        if c.agrees:
            verdict = "printed form = derived form (symbolic difference simplifies to 0)"
        elif c.relation == "constant factor":
            exact = sp.nsimplify(c.factor, [sp.pi], tolerance=1e-12)  # shown only when it is short: 4/pi, not a float's digits
            verdict = f"printed = derived x {float(c.factor):.6g}" + (f" (ratio {exact})" if len(str(exact)) <= 16 else "")
        else:
            verdict = f"printed - derived = {sp.N(c.difference, 4)}"
        note = verdict + (". " + self.note if self.note else "")
        if self.reconstructed:
            note += " Reconstructed: " + self.reconstructed
        if not c.dims_ok:
            note += " Dimension problem: " + c.dims_note
        return {
            "id": self.id,
            "source": self.source,
            "title": self.title,
            "printed_latex": self.latex_printed(),
            "derived_latex": self.latex_derived(),
            "agrees": bool(c.agrees),
            "relation": c.relation,
            "factor": None if c.factor is None else float(c.factor),
            "dimensions_ok": bool(c.dims_ok),
            "law": self.law,
            "note": note,
            "reconstructed": self.reconstructed,
            "rounded_constants": self.rounded_constants,
            "empirical": False,
            "fitted_to": "",
        }

    def _summary_empirical(self, c: Check) -> dict:
        """An empirical equation's summary: what it is fitted to and how it fares against the source's figures."""
        def off(figure, value, dev):
            number, unit = figure.split(" ", 1)
            return f"{100 * dev:+.1f} %" if dev is not None else f"{value - float(number):+.4g} {unit} off"

        checks = [f"{where}: {value:.4g} {figure.split(' ', 1)[1]} against {figure}"
                  + ("" if ok else f" ({off(figure, value, dev)})") for where, _, figure, value, dev, ok in c.points]
        verdict = ("reproduces every figure the datasheet prints for it" if c.agrees else
                   "does not reproduce every figure the datasheet prints for it")
        note = (f"Empirical, not derived: fitted to {self.fitted_to}. "
                f"Printed form against the datasheet's own figures: {verdict}: " + "; ".join(checks) + ".")
        if self.note:
            note += " " + self.note
        if not c.dims_ok:
            note += " Dimension problem: " + c.dims_note
        return {
            "id": self.id, "source": self.source, "title": self.title,
            "printed_latex": self.latex_printed(), "derived_latex": self.latex_derived(),
            "agrees": bool(c.agrees), "relation": c.relation, "factor": None, "dimensions_ok": bool(c.dims_ok),
            "law": "empirical: " + self.law if self.law else "empirical (no circuit law: the circuit is not shown)",
            "note": note, "reconstructed": self.reconstructed, "rounded_constants": self.rounded_constants,
            "empirical": True, "fitted_to": self.fitted_to,
        }
