"""Numeric claims: a number a source prints, its recomputation, and a status (no sympy needed).

A :class:`Claim` records where a number is printed, the number as printed (:class:`Printed`), how to
recompute it from the source's parameters, and why its status is what it is. The parameters a claim
depends on are not written by hand: :meth:`Claim.evaluate` runs the recomputation on a mapping that
records every key it reads, and compares with the printed number only when none of those differs
from the source's own value.
"""
from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from decimal import ROUND_HALF_EVEN, ROUND_HALF_UP, Decimal

#: printed unit names -> (SI scale factor, SI unit name used in the JSON output)
UNIT_SCALES: dict[str, tuple[float, str]] = {
    "F": (1.0, "F"), "uF": (1e-6, "F"), "nF": (1e-9, "F"), "pF": (1e-12, "F"),
    "ohm": (1.0, "ohm"), "kohm": (1e3, "ohm"), "Mohm": (1e6, "ohm"),
    "V": (1.0, "V"), "mV": (1e-3, "V"),
    "A": (1.0, "A"), "mA": (1e-3, "A"), "uA": (1e-6, "A"),
    "s": (1.0, "s"), "ms": (1e-3, "s"), "us": (1e-6, "s"), "ns": (1e-9, "s"),
    "Hz": (1.0, "Hz"), "kHz": (1e3, "Hz"), "MHz": (1e6, "Hz"),
    "W": (1.0, "W"), "K/W": (1.0, "K/W"),
    "%": (1e-2, "1"), "1": (1.0, "1"), "%/K": (1e-2, "1/K"), "1/K": (1.0, "1/K"),
    "V/K": (1.0, "V/K"), "mV/K": (1e-3, "V/K"),
    "rpm": (1.0, "rpm"), "uF*rpm": (1e-6, "F*rpm"),
}


@dataclass(frozen=True)
class Printed:
    """A number as the note prints it: the digits (as text) and the unit it is printed in."""

    text: str
    unit: str
    sig: int | None = None  # significant figures, where the context fixes them ("200 kHz" in a table: 3)

    def __post_init__(self):
        if self.unit not in UNIT_SCALES:
            raise ValueError(f"Printed({self.text!r}, {self.unit!r}): unknown unit; known: {', '.join(UNIT_SCALES)}")

    @property
    def si(self) -> float:
        return float(Decimal(self.text)) * UNIT_SCALES[self.unit][0]

    @property
    def half_unit(self) -> float:
        """Half a unit in the last printed digit, in SI.

        Trailing zeros of an integer without a decimal point are taken as not significant
        ("160" holds 155 to 165), as is usual when nothing says otherwise.
        """
        if self.sig is not None:
            v = abs(float(Decimal(self.text)))
            exponent = math.floor(math.log10(v)) - self.sig + 1 if v else 0
            return 0.5 * 10.0 ** exponent * UNIT_SCALES[self.unit][0]
        d = Decimal(self.text).normalize() if "." not in self.text else Decimal(self.text)
        exponent = d.as_tuple().exponent
        return 0.5 * 10.0 ** exponent * UNIT_SCALES[self.unit][0]

    def __str__(self) -> str:
        return f"{self.text} {self.unit}"


def classify(printed: float, half_unit: float, computed: float, *, relation: str = "=",
             basis: str = "note", via_rounded: float | None = None) -> str:
    """Status of a printed number against its recomputation.

    * ``exact``: equal to floating-point precision;
    * ``bound met``: for a bound (relation ">=" or "<="), the printed value meets it;
    * ``rounding``: within half a unit of the last printed digit, of the recomputed value or of the
      value the note's own rounded intermediate gives (``via_rounded``);
    * otherwise ``misprint`` when the recomputation uses the note's own inputs (``basis="note"``),
      and ``inconsistent`` when it uses another source (a device datasheet, another note).

    Parameters
    ----------
    printed : float
        The printed number in SI units.
    half_unit : float
        Half a unit in its last printed digit, SI units (:attr:`Printed.half_unit`).
    computed : float
        The recomputed value, SI units.
    relation : str
        ``"="`` for a value, ``">="`` or ``"<="`` for a bound the printed number must meet.
    basis : str
        ``"note"`` when the recomputation uses the note's own inputs, else the other document it rests on.
    via_rounded : float or None
        The value the note's own rounded intermediate gives, SI units (None: no such intermediate).

    Returns
    -------
    str
        ``"exact"``, ``"rounding"``, ``"bound met"``, ``"misprint"`` or ``"inconsistent"``.
    """
    if not (math.isfinite(printed) and math.isfinite(computed)):
        raise ValueError(f"printed={printed!r} and computed={computed!r} must both be finite numbers")
    if relation == ">=":
        ok = printed >= computed - 1e-12 * abs(computed)  # the slack loosens, whatever the sign
    elif relation == "<=":
        ok = printed <= computed + 1e-12 * abs(computed)
    else:
        scale = max(abs(printed), abs(computed), 1e-300)
        if abs(printed - computed) <= 1e-9 * scale:
            return "exact"
        tol = half_unit * (1 + 1e-9) + 1e-12 * scale
        ok = abs(printed - computed) <= tol or (via_rounded is not None and abs(printed - via_rounded) <= tol)
        if ok:
            return "rounding"
    if relation != "=" and ok:
        return "bound met"
    return "misprint" if basis == "note" else "inconsistent"


class Recorder(Mapping):
    """A read-only view of the parameters that remembers every key read through it.

    Spreading it (``{**p}``) or copying it reads every key: a conservative record.
    """

    def __init__(self, params: Mapping):
        self._params = params
        self.read: set[str] = set()

    def __getitem__(self, key):
        value = self._params[key]
        self.read.add(key)
        return value

    def __iter__(self):
        return iter(self._params)

    def __len__(self):
        return len(self._params)


@dataclass(frozen=True, kw_only=True)
class Claim:
    """A number printed in a source, with its recomputation from the source's parameters."""

    id: str
    where: str  # document, section, equation or table
    quantity: str
    printed: Printed
    compute: Callable[[Mapping], float]  # parameters -> recomputed value in SI
    reason: str  # one line: why the status is what it is
    chapter: str
    relation: str = "="
    basis: str = "note"  # "note", or the other document the recomputation rests on
    via_rounded: Callable[[Mapping], float] | None = None
    consequence: str = ""  # for a misprint or an inconsistency: what it means for a designer
    safe_side: str = ""  # "below" or "above": the side a designer may round to on purpose (a heat sink's K/W)
    method_wrong: bool = False  # the number follows the note's arithmetic but the method itself is wrong
    truncated: bool = False  # the last printed digit is cut off, not rounded (22.755 printed 22.7): status "truncated"
    same_fact: str = ""  # the id of the erratum that carries this fact (listed there as another place, not counted twice)

    def __post_init__(self):
        if self.truncated and "truncated" not in self.reason:
            raise ValueError(f"{self.id}: a claim marked truncated=True must say 'truncated' in its reason")

    @property
    def unit(self) -> str:
        return UNIT_SCALES[self.printed.unit][1]

    def _status(self, computed: float, via: float | None) -> str:
        """classify, then what a number's arithmetic alone cannot tell: a wrong method; a last digit cut off
        instead of rounded ("truncated", when the print is exactly the value cut off); a value rounded to the safe
        side on purpose ("conservative": within one unit of its last digit, or the print of a rounded intermediate
        that moved it to the safe side, where the exact value does not round to it); and a print that follows from
        the note's own rounded intermediate but not from the exact value ("rounded intermediate"). "rounding" is
        kept for a print the exact value itself rounds to."""
        status = classify(self.printed.si, self.printed.half_unit, computed, relation=self.relation, basis=self.basis,
                          via_rounded=via)
        if self.method_wrong:
            return "wrong method"
        if status in ("misprint", "inconsistent", "rounding") and self.truncated and not any(
                _rounds_to_print(self.printed, v) for v in (computed, via) if v is not None) and (
                _is_truncation(self.printed, computed) or (via is not None and _is_truncation(self.printed, via))):
            return "truncated"  # a tie at half a unit (155 printed 150) is a cut, not a rounding, by either rule
        if status in ("misprint", "inconsistent") and self.safe_side and _safe_rounding(self, computed):
            return "conservative"
        if status == "rounding" and via is not None:
            direct = classify(self.printed.si, self.printed.half_unit, computed, relation=self.relation, basis=self.basis)
            if direct in ("misprint", "inconsistent"):
                on_safe_side = (computed > self.printed.si) if self.safe_side == "below" else (self.printed.si > computed)
                return "conservative" if self.safe_side and on_safe_side else "rounded intermediate"
        return status

    def evaluate(self, params: Mapping, defaults: Mapping) -> dict:
        """Recompute with ``params``; compare with the print only where the inputs read are the note's.

        Parameters
        ----------
        params : Mapping
            Parameter name -> value (SI units) to recompute with.
        defaults : Mapping
            The source's own values, parameter name -> value: a parameter read that differs from its default
            makes the comparison with the print "n/a".

        Returns
        -------
        dict
            The claim's row: ``id``, ``source`` (where it is printed), ``chapter``, ``quantity``, ``unit`` (SI),
            ``printed`` (SI value), ``printed_text``, ``computed`` (SI value), ``relation``, ``basis``, ``status``,
            ``reason``, ``consequence`` and ``depends`` (the sorted parameter names read).
        """
        seen = Recorder(params)
        computed = float(self.compute(seen))
        via = None if self.via_rounded is None else float(self.via_rounded(seen))
        changed = sorted(k for k in seen.read if params[k] != defaults.get(k))
        if changed:
            status = "n/a"
            reason = "inputs differ from the note's (" + ", ".join(changed) + "): no printed value to compare"
        else:
            status = self._status(computed, via)
            reason = self.reason
        return {
            "id": self.id, "source": self.where, "chapter": self.chapter, "quantity": self.quantity,
            "unit": self.unit, "printed": self.printed.si, "printed_text": str(self.printed),
            "computed": computed, "relation": self.relation, "basis": self.basis, "status": status,
            "reason": reason, "consequence": self.consequence, "depends": sorted(seen.read),
        }


def _is_truncation(printed: Printed, computed: float) -> bool:
    """The print is ``computed`` with the digits after its last printed one cut off (toward zero):
    22.755 -> 22.7 and 11.76 -> 11.7 are; 6.366 -> 6.35 (truncation gives 6.36) and 11 -> 10 are not."""
    step = 2 * printed.half_unit
    if step <= 0:
        return False
    cut = math.copysign(math.floor(abs(computed) / step + 1e-9) * step, computed)
    return abs(printed.si - cut) <= 1e-9 * max(step, abs(printed.si))


def _rounds_to_print(printed: Printed, value: float) -> bool:
    """``value`` rounded half up or half even at the print's last digit is the print (155 -> 160, so "150" is not)."""
    step = Decimal(repr(2 * printed.half_unit / UNIT_SCALES[printed.unit][0])).normalize()
    v = Decimal(repr(value / UNIT_SCALES[printed.unit][0]))
    exact = Decimal(printed.text)
    return any(abs((v / step).quantize(Decimal(1), rounding=m) * step - exact) <= step * Decimal("1e-9")
               for m in (ROUND_HALF_UP, ROUND_HALF_EVEN))


def _safe_rounding(claim: Claim, computed: float) -> bool:
    """The print is on the claim's safe side and within one unit of its last digit: rounded on purpose."""
    gap = computed - claim.printed.si if claim.safe_side == "below" else claim.printed.si - computed
    return 0 < gap <= 2 * claim.printed.half_unit * (1 + 1e-9)


#: how sure an erratum is: the printed numbers settle it; it rests on a reading (which datasheet, which column);
#: or the OCR may have lost what would clear the source
CONFIDENCE = ("certain", "probable", "depends on the OCR")


@dataclass(frozen=True)
class Case:
    """The case an erratum makes against its source: the passage it disputes, word for word, and how sure it is.

    ``quote`` holds verbatim passages, the disputed one first; a passage of another document is a
    ``(document, text)`` pair ("AN94002", "datasheet facts"). ``charitable`` is the most charitable reading
    of the source (a rounded column, a definition elsewhere, an explicit alternative, an OCR loss) and why
    the erratum survives it. ``places`` lists other places the same fact shows that are not records of their
    own (a record marked ``same_fact`` is listed there by the catalog). A source's cases live in its
    ``cases`` module, keyed by erratum id.
    """

    quote: tuple
    confidence: str
    charitable: str
    places: tuple[str, ...] = ()

    def __post_init__(self):
        if not self.quote or not all(isinstance(q, str) or (isinstance(q, tuple) and len(q) == 2) for q in self.quote):
            raise ValueError(f"Case.quote must be passages (text, or (document, text)), got {self.quote!r}")
        if self.confidence not in CONFIDENCE:
            raise ValueError(f"Case.confidence {self.confidence!r}: use one of {', '.join(CONFIDENCE)}")
        if not self.charitable.strip():
            raise ValueError("Case.charitable: state the most charitable reading of the source and answer it")

    def passages(self, own: str) -> list[tuple[str, str]]:
        """Every quoted passage as (document, text).

        Parameters
        ----------
        own : str
            The erratum's own document ("AN94002"), which a bare passage belongs to.

        Returns
        -------
        list of tuple
            (document, verbatim text) per passage, the disputed one first.
        """
        return [(own, q) if isinstance(q, str) else q for q in self.quote]


@dataclass(frozen=True)
class TextErratum:
    """A misprint or inconsistency that is not a number: a wrong unit, a name used twice, a copied text."""

    id: str
    source: str
    what: str
    evidence: str
    consequence: str
    same_fact: str = ""  # the id of the erratum that carries this fact (listed there as another place)


@dataclass(frozen=True)
class ReadingNote:
    """Not an error of the source: how the book reads it where the OCR lost a figure, what it reconstructs,
    what the public record lacks, or what it assumes. Kept apart from the errata and out of their count."""

    id: str
    source: str
    what: str
    note: str
