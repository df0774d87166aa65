"""The contract of a source document: its parameters, outside facts, equations, claims and errata.

Every package under ``handbook.sources`` builds one :class:`Source`; the catalog, the errata chapter,
the command line and the chapters all go through it, so every document behaves the same way:
``params()`` refuses unknown names with the near match and checks each value against its
:class:`Param`, ``evaluate()`` recomputes every claim, ``equations()`` builds the symbolic registry
once per process and ``equation_summaries()`` once per change of the code that defines it.
"""
from __future__ import annotations

import difflib
import functools
import math
import numbers
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from typing import Any

from .claim import Case, Claim, ReadingNote, TextErratum
from .validate import InputError


@dataclass(frozen=True, kw_only=True)
class Param:
    """One input of a source's calculations: its default (the source's own value) and what it means."""

    name: str
    default: Any
    unit: str  # SI unit ("V", "F", "ohm", "1" for a ratio or fraction, "" for a name or a count)
    meaning: str
    low: float | None = None  # accepted range (inclusive, but see low_open)
    high: float | None = None
    low_open: bool = False  # the value must exceed ``low`` (a positive quantity: low=0, low_open=True)
    cite: str = ""  # where the default comes from, when not the source itself
    choices: tuple = ()  # for a name: the accepted values

    def check(self, value, prefix: str = ""):
        """``value`` if it is acceptable, else an :class:`InputError` naming the key, value and range.

        Parameters
        ----------
        value : float or int or str
            The value given, in the parameter's unit (SI; a name for a choice).
        prefix : str
            Put before the parameter's name in the message ("design.").

        Returns
        -------
        float or int or str
            ``value``, as an int where the default is an int.
        """
        name = prefix + self.name
        if self.choices:
            if value not in self.choices:
                raise InputError(f"{name} = {value!r}: use one of {', '.join(map(repr, self.choices))}")
            return value
        if isinstance(self.default, str):
            if not isinstance(value, str):
                raise InputError(f"{name} = {value!r}: expected a name in quotes, e.g. {self.default!r}")
            return value
        if isinstance(value, bool) or not isinstance(value, numbers.Real):
            raise InputError(f"{name} = {value!r}: expected a number ({self.meaning})")
        if not math.isfinite(value):
            raise InputError(f"{name} = {value!r}: expected a finite number ({self.meaning})")
        if isinstance(self.default, int) and value != int(value):
            raise InputError(f"{name} = {value!r}: expected a whole number ({self.meaning})")
        from .validate import out_of_range

        error = out_of_range(name, value, "" if self.unit == "1" else self.unit, self.low, self.high, self.low_open,
                             self.meaning)
        if error is not None:
            raise error
        return int(value) if isinstance(self.default, int) else value

    @property
    def unit_text(self) -> str:
        return "" if self.unit in ("", "1") else " " + self.unit

    @property
    def range_text(self) -> str:
        """'> 0 rpm and <= 1,000,000 rpm', 'from 0 V to 100 mV', 'from 1 kHz to 1 MHz', or the choices: the
        engineering values the error messages also use."""
        from .validate import range_text

        if self.choices:
            return "one of " + ", ".join(map(repr, self.choices))
        return range_text(self.low, self.high, self.low_open, "" if self.unit == "1" else self.unit)


@dataclass(frozen=True)
class Fact:
    """A figure a source relies on without printing it, with the datasheet it was read from."""

    value: Any
    cite: str


def unknown_key_message(kind: str, key: str, known) -> str:
    """'unknown AN94002 parameter 'rpm' (did you mean 'rpm_min'?)' or the list of known names.

    Parameters
    ----------
    kind : str
        What the key names ("AN94002 parameter").
    key : str
        The unknown name given.
    known : iterable of str
        The names accepted.

    Returns
    -------
    str
        The message, with the nearest known name or else the list of them.
    """
    near = difflib.get_close_matches(key, list(known), n=1)
    hint = f" (did you mean {near[0]!r}?)" if near else f"; known: {', '.join(known)}"
    return f"unknown {kind} {key!r}{hint}"


@dataclass(frozen=True, kw_only=True)
class Source:
    """One source document and everything the handbook records about it."""

    name: str  # "AN94002": the key of the errata and the catalog
    title: str
    parameters: tuple[Param, ...]
    facts: Mapping[str, Fact] = field(default_factory=dict)
    equations_module: str = ""  # the module whose build() makes the Equation records (imported on first use:
    # it imports sympy); its code is also the key of the on-disk check cache
    build_claims: Callable[[], list[Claim]] = lambda: []
    errata: tuple[TextErratum, ...] = ()
    reading_notes: tuple[ReadingNote, ...] = ()  # not errors of the source: lost OCR, reconstructions, assumptions
    cases: Mapping[str, Case] = field(default_factory=dict)  # erratum id -> the case against the source

    # -- parameters -------------------------------------------------------------------------
    @property
    def defaults(self) -> dict:
        return {p.name: p.default for p in self.parameters}

    def params(self, **overrides) -> dict:
        """The source's own values with ``overrides`` applied; unknown names are refused with the
        near match, and every value given is checked against its range.

        Parameters
        ----------
        **overrides : float or int or str
            Parameter name -> value, in the parameter's unit (SI).

        Returns
        -------
        dict
            Every parameter name -> value: the source's defaults with ``overrides`` applied.
        """
        by_name = {p.name: p for p in self.parameters}
        for key, value in overrides.items():
            if key not in by_name:
                raise InputError(unknown_key_message(f"{self.name} parameter", key, by_name))
            by_name[key].check(value)
        return {**self.defaults, **overrides}

    # -- claims ------------------------------------------------------------------------------
    def claims(self) -> list[Claim]:
        """Every claim of the source (built once per process, ids checked unique).

        Returns
        -------
        list of Claim
            The claims in the source's order.
        """
        return _claims(self)

    def evaluate(self, p: Mapping | None = None, chapter: str | None = None) -> list[dict]:
        """Every claim recomputed with ``p`` (default: the source's own values).

        Parameters
        ----------
        p : Mapping or None
            Parameter name -> value (SI units), as :meth:`params` returns; None for the source's own values.
        chapter : str or None
            Only the claims of this chapter; None for all.

        Returns
        -------
        list of dict
            One row per claim, as :meth:`Claim.evaluate` returns it.
        """
        defaults = self.defaults
        p = defaults if p is None else p
        return [c.evaluate(p, defaults) for c in self.claims() if chapter is None or c.chapter == chapter]

    # -- equations ---------------------------------------------------------------------------
    def equations(self) -> list:
        """Every equation record of the source (its equations module's ``build()``, once per process).

        Returns
        -------
        list of Equation
            The records in the source's order; empty when the source has no equations module.
        """
        return list(_equations(self))

    def equation(self, eq_id: str):
        """One equation record by id; an unknown id is refused with the near match.

        Parameters
        ----------
        eq_id : str
            The record's id ("an94002-eq6").

        Returns
        -------
        Equation
            The record.
        """
        for e in _equations(self):
            if e.id == eq_id:
                return e
        raise KeyError(unknown_key_message(f"{self.name} equation", eq_id, [e.id for e in _equations(self)]))

    def equation_summaries(self) -> list[dict]:
        """Every equation's summary (forms, agreement, dimensions), from the on-disk cache when the code
        that defines the equations has not changed since it was stored.

        Returns
        -------
        list of dict
            One :meth:`~handbook.core.equation.Equation.summary` per equation.
        """
        from .checks_cache import cached_summaries

        return cached_summaries(self)

    def __hash__(self):
        return hash(self.name)


@functools.cache
def _claims(source: Source) -> tuple:
    claims = tuple(source.build_claims())
    ids = [c.id for c in claims]
    if len(set(ids)) != len(ids):
        raise ValueError(f"{source.name}: duplicate claim ids")
    return claims


@functools.cache
def _equations(source: Source) -> tuple:
    if not source.equations_module:
        return ()
    from .checks_cache import cached_equations

    return cached_equations(source)
