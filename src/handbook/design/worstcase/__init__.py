"""Worst-case analysis of a design: extreme values over every tolerance corner (EVA), root-sum-square (RSS), a
seeded Monte Carlo lot with its yields, the distributions assumed, which tolerance eats the margin, and drift.

:func:`analyse` takes any of the four designs' results. The Monte Carlo runs the design's own equations on
numpy arrays (never SPICE): every varying input uniform inside its range (no source the project cites gives a
better distribution; each :class:`Distribution` says so), drawn in a fixed order from
``numpy.random.default_rng(seed)``. EVA evaluates the same equations at every corner of the inputs' box, the
corners the design's own enumeration takes (the tests check they give the design's reported extremes); every
quantity here is monotonic in each input, so EVA bounds every sample. RSS is one-sided: below nominal the
root-sum-square of each input's largest move down (over its two ends, the others nominal), above it of each
one's largest move up, so an input whose range is not symmetric about nominal (the class-D oscillator's
0.8 .. 1.235) moves each side by what it really does; it stays inside EVA. What each design's quantities and
limits are: :mod:`.limiter`, :mod:`.models` and :mod:`.timers` (the TDA5144's CAP-ST and CAP-TI).
"""
from __future__ import annotations

import dataclasses
from dataclasses import dataclass

import numpy as np

from . import engine
from . import limiter as _limiter
from . import models as _models


@dataclass(frozen=True)
class Quantity:
    """One analysed quantity: nominal, EVA, RSS and Monte Carlo ranges (its unit), its limits (None: none)."""

    key: str
    label: str
    unit: str
    nominal: float
    eva_low: float
    eva_high: float
    rss_low: float
    rss_high: float
    mc_low: float
    mc_high: float
    limit_low: float | None
    limit_high: float | None


@dataclass(frozen=True)
class Distribution:
    """How one part or figure varies: the distribution's kind, its range (the part's unit) and its source."""

    part: str
    kind: str
    low: float
    high: float
    cite: str
    unit: str = ""  # of low and high ("" a plain factor)


@dataclass(frozen=True)
class LimitSource:
    """One limited quantity: its worst-case margin and the tolerance that moves it most."""

    key: str
    margin: float  # EVA, a fraction of its limit
    source: str  # the tolerance group with the largest share of its first-order variance ("" if none moves it)
    share: float


@dataclass(frozen=True)
class Sensitivity:
    """One tolerance: its share of the binding quantity's first-order variance, and the worst-case margin and
    Monte Carlo yield with its range halved."""

    source: str
    share: float
    margin_if_halved: float
    yield_if_halved: float


@dataclass(frozen=True)
class WorstCase:
    """A design's worst-case analysis (:func:`analyse`)."""

    table: str
    quantities: tuple[Quantity, ...]
    yields: dict
    yield_all: float
    samples: dict
    distributions: tuple[Distribution, ...]
    sensitivity: tuple[Sensitivity, ...]
    drift: tuple[str, ...]
    n: int
    seed: int
    binding: str = ""  # the quantity the sensitivity's shares are of: the limited one of least EVA margin
    by_limit: tuple = ()  # LimitSource per limited quantity, least margin first

    def quantity(self, key: str) -> Quantity:
        """The quantity of that key.

        Parameters
        ----------
        key : str
            A quantity's key.

        Returns
        -------
        Quantity
            The analysed quantity (a ``KeyError`` when there is none of that key).
        """
        for q in self.quantities:
            if q.key == key:
                return q
        raise KeyError(key)


#: the Monte Carlo lot the report and ``design --worstcase`` run: boards and seed (the same numbers in both)
N, SEED = 100_000, 1


def as_json(wc: WorstCase) -> dict:
    """An analysis as ``design --worstcase --json`` writes it: everything but the samples, SI units.

    Parameters
    ----------
    wc : WorstCase
        The analysis (:func:`analyse`).

    Returns
    -------
    dict
        ``n``, ``seed``, ``yield_all`` and ``yields`` ({limit: fraction}), ``binding``, ``quantities`` (one dict
        each: key, label, unit (a fraction's "1", where the report shows per cent), nominal, eva_low/high, rss_low/high,
        mc_low/high, limit_low/high), ``distributions``,
        ``sensitivity`` (source, share, margin_if_halved, yield_if_halved), ``drift`` (sentences) and ``by_limit``
        (key, margin, source, share: every limited quantity's worst-case margin and the tolerance moving it most).
    """
    return {"n": wc.n, "seed": wc.seed, "yield_all": wc.yield_all, "yields": dict(wc.yields), "binding": wc.binding,
            "quantities": [{**dataclasses.asdict(q), "unit": "1" if q.unit == "%" else q.unit} for q in wc.quantities],
            "distributions": [dataclasses.asdict(d) for d in wc.distributions],
            "sensitivity": [dataclasses.asdict(x) for x in wc.sensitivity], "drift": list(wc.drift),
            "by_limit": [dataclasses.asdict(x) for x in wc.by_limit]}


#: table -> its model builder, from a design's result
MODELS = {"commutation": _models.commutation,
          "current_limiter": lambda r: _limiter.model(r.r7, r.network, r.spec),
          "class_d": _models.class_d, "converter": _models.converter}


def model(table: str, result) -> engine.Model:
    """The worst-case model of a design.

    Parameters
    ----------
    table : str
        "commutation", "current_limiter", "class_d" or "converter".
    result : Result
        That design's result (its ``design(spec)``).

    Returns
    -------
    engine.Model
        Its varying inputs, quantities, equations and drift sentences.

    Raises
    ------
    KeyError
        For an unknown table.
    """
    return MODELS[table](result)


def analyse(table: str, result, n: int = N, seed: int = SEED) -> WorstCase:
    """EVA, RSS and a seeded Monte Carlo of ``n`` boards of one design, with yields and sensitivities.

    Parameters
    ----------
    table : str
        "commutation", "current_limiter", "class_d" or "converter".
    result : Result
        That design's result.
    n : int
        Boards in the Monte Carlo lot.
    seed : int
        Seed of ``numpy.random.default_rng``.

    Returns
    -------
    WorstCase
        Every quantity's ranges (SI units), the yields per limit and overall (fractions), the samples
        ({key: numpy.ndarray, shape (n,)}), the distributions, the tolerances ranked by their share of the
        first-order variance of ``binding`` (the limited quantity of the least worst-case margin, each margin a
        fraction of its limit), each with the least worst-case margin over every limit and the yield of every
        limit together when that tolerance's range is halved; the drift sentences, ``n`` and ``seed``.
    """
    m = model(table, result)
    nom, eva = engine.nominal(m), engine.corners(m)
    rss = engine.sided(m, nom)
    draws = engine.draw(m, n, seed)
    samples = engine.evaluate(m, draws)
    quantities = []
    for q in m.measures:
        down, up = rss[q.key]
        lo, hi = np.quantile(samples[q.key], engine.QUANTILES)
        quantities.append(Quantity(q.key, q.label, q.unit, nom[q.key], float(eva[q.key].min()),
                                   float(eva[q.key].max()), nom[q.key] - down, nom[q.key] + up, float(lo), float(hi),
                                   q.limit_low, q.limit_high))
    per_limit, overall = engine.yields(m, samples)
    return WorstCase(
        table=table, quantities=tuple(quantities), yields=per_limit, yield_all=overall, samples=samples,
        distributions=tuple(Distribution(src.part, src.kind, src.low, src.high, src.cite, src.unit) for src in m.sources),
        sensitivity=tuple(Sensitivity(*row) for row in engine.sensitivity(m, eva, draws)), drift=m.drift, n=n,
        seed=seed, binding=getattr(engine.binding(m, eva), "key", ""),
        by_limit=tuple(LimitSource(*row) for row in engine.per_limit(m, eva)))


__all__ = ["MODELS", "Distribution", "LimitSource", "Quantity", "Sensitivity", "WorstCase", "analyse", "model"]
