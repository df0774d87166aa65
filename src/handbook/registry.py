"""Equation and numeric-example registries shared by every chapter.

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

An :class:`Example` is one number the note prints as the result of a calculation, with the value
recomputed here, and a status from :func:`classify`.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from decimal import Decimal
from typing import Callable

import sympy as sp
from sympy.physics import units as u
from sympy.printing.latex import LatexPrinter
from sympy.physics.units.systems.si import SI, dimsys_SI

# ----------------------------------------------------------------------------------------------
# units

#: printed unit names -> (SI scale factor, SI unit name used in the JSON output)
UNIT_SCALES: dict[str, tuple[float, str]] = {
    "F": (1.0, "F"), "uF": (1e-6, "F"), "nF": (1e-9, "F"), "pF": (1e-12, "F"),
    "ohm": (1.0, "ohm"), "kohm": (1e3, "ohm"), "Mohm": (1e6, "ohm"),
    "V": (1.0, "V"), "mV": (1e-3, "V"),
    "A": (1.0, "A"), "mA": (1e-3, "A"), "uA": (1e-6, "A"),
    "s": (1.0, "s"), "ms": (1e-3, "s"), "us": (1e-6, "s"),
    "Hz": (1.0, "Hz"), "kHz": (1e3, "Hz"), "MHz": (1e6, "Hz"),
    "W": (1.0, "W"), "K/W": (1.0, "K/W"),
    "%": (1e-2, "1"), "1": (1.0, "1"), "%/K": (1e-2, "1/K"), "1/K": (1.0, "1/K"),
    "V/K": (1.0, "V/K"), "mV/K": (1e-3, "V/K"),
    "rpm": (1.0, "rpm"), "uF*rpm": (1e-6, "F*rpm"),
}


def dimension_of(expr: sp.Expr):
    """The SI dimension of an expression built from sympy unit quantities.

    Raises ``ValueError`` (from sympy) when a sum adds unlike dimensions.
    """
    _, dim = SI._collect_factor_and_dimension(expr)
    return dim


def same_dimension(a, b) -> bool:
    return dimsys_SI.equivalent_dims(a, b)


def to_si_number(expr: sp.Expr) -> sp.Expr:
    """Convert a dimensionless expression of unit quantities to a plain number (exact where possible)."""
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
    """LaTeX of ``expr`` with decimal constants shown as printed in the note."""
    expr = sp.sympify(expr)
    exponents = {a for pw in expr.atoms(sp.Pow) for a in pw.exp.atoms(sp.Rational)}
    swap = {r: _decimal(r) for r in expr.atoms(sp.Rational) - exponents if r.q not in (1, 2, 4)}
    return sp.latex(expr.xreplace(swap))


_UNIT_TEX = {"second": r"\mathrm{s}", "farad/1000000": r"\mu\mathrm{F}", "farad": r"\mathrm{F}",
             "volt": r"\mathrm{V}", "1/minute": r"\mathrm{rpm}"}


# ----------------------------------------------------------------------------------------------
# equations

@dataclass
class Check:
    """Outcome of comparing a printed form with its derivation."""

    agrees: bool
    relation: str  # "identical", "constant factor", "differs"
    factor: sp.Expr | None  # printed / derived when it is a pure number
    difference: sp.Expr | None  # printed - derived (physical), simplified
    dims_ok: bool  # printed and derived forms are dimensionally consistent with the left side
    dims_note: str


@dataclass
class Equation:
    id: str
    source: str  # note, section, equation number
    title: str
    lhs: sp.Symbol  # physical quantity on the left
    lhs_unit: sp.Expr  # its SI unit (a sympy quantity expression)
    printed: sp.Expr  # right-hand side as printed, in the printed symbols
    derived: sp.Expr  # right-hand side from circuit laws, physical symbols
    units: dict  # physical symbol -> sympy unit
    law: str  # which circuit law the derivation uses
    scales: dict = field(default_factory=dict)  # printed symbol -> physical expression it stands for
    lhs_scale: sp.Expr | None = None  # the printed left side is lhs / lhs_scale (e.g. C / uF)
    values: dict = field(default_factory=dict)  # physical symbol -> value with units (note's numbers)
    relation: str = "="  # "=" or ">=" (bounds are recorded by their limiting expression)
    note: str = ""  # how they differ, what was reconstructed, what a symbol means
    reconstructed: str = ""  # what the OCR garbled and how the form was rebuilt
    ocr_form: sp.Expr | None = None  # the OCR text taken literally, where it differs
    chapter: str = ""
    printed_tex: str = ""  # the printed right side as LaTeX, where sympy would re-arrange it

    # -- forms -------------------------------------------------------------------------------
    def printed_physical(self) -> sp.Expr:
        """The printed right side with every hidden unit made explicit (a physical quantity)."""
        rhs = self.printed.subs(self.scales)
        if self.lhs_scale is not None:
            rhs = rhs * self.lhs_scale
        return rhs

    def derived_at_values(self) -> sp.Expr:
        return self.derived.subs(self.values)

    def _with_units(self, expr: sp.Expr) -> sp.Expr:
        # symbol -> symbol x unit (not the bare unit: V_s - V_D1 must not cancel to zero)
        return expr.subs({s: s * unit for s, unit in self.units.items()}, simultaneous=True)

    def check(self) -> Check:
        printed = self.printed_physical()
        derived = self.derived_at_values()
        # Dimensions: both sides must carry the left side's dimension.
        lhs_dim = dimension_of(self.lhs_unit)
        notes = []
        dims_ok = True
        for name, form in (("printed", printed), ("derived", derived)):
            try:
                d = dimension_of(self._with_units(form))
            except ValueError as exc:  # a sum of unlike dimensions
                dims_ok = False
                notes.append(f"{name}: {exc}")
                continue
            if not same_dimension(d, lhs_dim):
                dims_ok = False
                notes.append(f"{name} form has dimension {d}, left side {lhs_dim}")
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

    def ocr_dims_ok(self) -> bool | None:
        """Whether the OCR text taken literally is dimensionally consistent (None if no OCR form)."""
        if self.ocr_form is None:
            return None
        try:
            d = dimension_of(self._with_units(self.ocr_form.subs(self.scales)))
        except ValueError:
            return False
        return same_dimension(d, dimension_of(self.lhs_unit))

    # -- display -----------------------------------------------------------------------------
    def latex_printed(self) -> str:
        lhs = latex(self.lhs)
        if self.lhs_scale is not None:
            lhs += r"\,[" + _UNIT_TEX.get(str(self.lhs_scale), latex(self.lhs_scale)) + "]"
        rel = r"\ge" if self.relation == ">=" else "="
        return f"{lhs} {rel} {self.printed_tex or latex(self.printed)}"

    def latex_derived(self) -> str:
        rel = r"\ge" if self.relation == ">=" else "="
        return f"{latex(self.lhs)} {rel} {latex(self.derived)}"

    def summary(self) -> dict:
        c = self.check()
        if c.agrees:
            verdict = "printed form = derived form (symbolic difference simplifies to 0)"
        elif c.relation == "constant factor":
            verdict = f"printed = derived x {float(c.factor):.6g} (ratio simplifies to {sp.nsimplify(c.factor)})"
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
        }


# ----------------------------------------------------------------------------------------------
# numeric examples

STATUSES = ("exact", "rounding", "misprint", "inconsistent", "n/a")


@dataclass(frozen=True)
class Printed:
    """A number as the note prints it: the digits (as text) and the unit it is printed in."""

    text: str
    unit: str

    @property
    def si(self) -> float:
        return float(Decimal(self.text)) * UNIT_SCALES[self.unit][0]

    @property
    def half_unit(self) -> float:
        """Half a unit in the last printed digit, in SI.

        Trailing zeros of an integer without a decimal point are taken as not significant
        ("160" holds 155 to 165), as is usual when nothing says otherwise.
        """
        d = Decimal(self.text).normalize() if "." not in self.text else Decimal(self.text)
        exponent = d.as_tuple().exponent
        return 0.5 * 10.0 ** exponent * UNIT_SCALES[self.unit][0]

    def __str__(self) -> str:
        return f"{self.text} {self.unit}"


def classify(printed: float, half_unit: float, computed: float, *, relation: str = "=",
             basis: str = "note", via_rounded: float | None = None) -> str:
    """Status of a printed number against its recomputation.

    * ``exact``: equal to floating-point precision (for a bound: the printed value meets it);
    * ``rounding``: within half a unit of the last printed digit, of the recomputed value or of the
      value the note's own rounded intermediate gives (``via_rounded``);
    * otherwise ``misprint`` when the recomputation uses the note's own inputs (``basis="note"``),
      and ``inconsistent`` when it uses another source (a device datasheet, another note).
    """
    if not (math.isfinite(printed) and math.isfinite(computed)):
        raise ValueError(f"printed={printed!r} and computed={computed!r} must both be finite numbers")
    if relation == ">=":
        ok = printed >= computed * (1 - 1e-12)
    elif relation == "<=":
        ok = printed <= computed * (1 + 1e-12)
    else:
        scale = max(abs(printed), abs(computed), 1e-300)
        if abs(printed - computed) <= 1e-9 * scale:
            return "exact"
        tol = half_unit * (1 + 1e-9) + 1e-12 * scale
        ok = abs(printed - computed) <= tol or (via_rounded is not None and abs(printed - via_rounded) <= tol)
        if ok:
            return "rounding"
    if relation != "=" and ok:
        return "exact"
    return "misprint" if basis == "note" else "inconsistent"


@dataclass
class Example:
    id: str
    source: str
    quantity: str
    printed: Printed
    compute: Callable[[dict], float]  # params -> computed value in SI
    reason: str  # one line: why the status is what it is
    depends: tuple[str, ...] = ()  # parameter names the computation reads
    relation: str = "="
    basis: str = "note"  # "note" or the other source the recomputation rests on
    via_rounded: Callable[[dict], float] | None = None
    chapter: str = ""
    printed_tex: str = ""  # the printed right side as LaTeX, where sympy would re-arrange it

    @property
    def unit(self) -> str:
        return UNIT_SCALES[self.printed.unit][1]

    def evaluate(self, params: dict, defaults: dict) -> dict:
        """Recompute with ``params``; compare with the print only where the inputs are the note's."""
        computed = float(self.compute(params))
        changed = [k for k in self.depends if params.get(k) != defaults.get(k)]
        if changed:
            status = "n/a"
            reason = "inputs differ from the note's (" + ", ".join(changed) + "): no printed value to compare"
        else:
            via = None if self.via_rounded is None else float(self.via_rounded(params))
            status = classify(self.printed.si, self.printed.half_unit, computed, relation=self.relation,
                              basis=self.basis, via_rounded=via)
            reason = self.reason
        return {
            "id": self.id,
            "source": self.source,
            "chapter": self.chapter,
            "quantity": self.quantity,
            "unit": self.unit,
            "printed": self.printed.si,
            "printed_text": str(self.printed),
            "computed": computed,
            "relation": self.relation,
            "basis": self.basis,
            "status": status,
            "reason": reason,
        }
