"""The numerics every design's worst-case analysis shares: a model (its varying inputs and its vectorised
equations), evaluated at every corner (extreme-value analysis), one input at a time (root-sum-square) and on a
seeded Monte Carlo lot; yields, and what halving each tolerance buys.
"""
from __future__ import annotations

import dataclasses
import itertools
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

#: the Monte Carlo's reported quantiles: 0.005 % and 99.995 % (five boards in 100 000 at either end)
QUANTILES = (0.00005, 0.99995)


@dataclass(frozen=True)
class Source:
    """One input that varies from board to board: its argument name in the model's equations, the part or figure
    it belongs to, its range (uniform inside it), the value taken as nominal, the sensitivity group it is counted
    in and where the range comes from."""

    name: str
    part: str
    low: float
    high: float
    nominal: float
    group: str
    cite: str
    kind: str = "uniform"
    unit: str = ""  # of low, high and nominal (the results' units: "ohm", "F", "V"...; "" a plain factor)


@dataclass(frozen=True)
class Measure:
    """One quantity the analysis reports: its key (of the model's output), label, unit and limits (None: none),
    and the name its limit is reported under in the yields."""

    key: str
    label: str
    unit: str
    limit_low: float | None = None
    limit_high: float | None = None
    limit_name: str = ""


@dataclass(frozen=True)
class Model:
    """A design's analysis: its varying inputs, its quantities, and ``f(**inputs) -> {key: array}``, the design's
    own equations applied elementwise (every input an array of the same shape); ``drift`` sentences."""

    sources: tuple[Source, ...]
    measures: tuple[Measure, ...]
    f: Callable[..., dict]
    drift: tuple[str, ...] = ()


def evaluate(model: Model, args: dict) -> dict:
    """The model's quantities on arrays of inputs, as float arrays.

    Parameters
    ----------
    model : Model
        The design's analysis model.
    args : dict
        {source name: numpy.ndarray}, every source, arrays of one shape (SI units).

    Returns
    -------
    dict
        {quantity key: numpy.ndarray of float}, the arrays' shape.
    """
    out = model.f(**args)
    return {m.key: np.asarray(out[m.key], dtype=float) for m in model.measures}


def nominal(model: Model) -> dict:
    """The quantities with every input at its nominal value.

    Parameters
    ----------
    model : Model
        The design's analysis model.

    Returns
    -------
    dict
        {quantity key: float}.
    """
    vals = evaluate(model, {src.name: np.array([src.nominal]) for src in model.sources})
    return {k: float(v[0]) for k, v in vals.items()}


def corners(model: Model, sources: tuple[Source, ...] | None = None) -> dict:
    """Every quantity at every corner of the inputs' box (2^k points, k inputs): the extreme-value analysis.

    Parameters
    ----------
    model : Model
        The design's analysis model.
    sources : tuple of Source or None
        The inputs' ranges to use (the model's own when None: a sensitivity case passes a narrowed copy).

    Returns
    -------
    dict
        {quantity key: numpy.ndarray of its value at each corner}.
    """
    sources = model.sources if sources is None else sources
    grid = np.array(list(itertools.product((0, 1), repeat=len(sources))), dtype=bool)
    args = {src.name: np.where(grid[:, j], src.high, src.low) for j, src in enumerate(sources)}
    return evaluate(model, args)


def effects(model: Model) -> dict:
    """Each input's first-order effect on each quantity: half the change from its low to its high end, every
    other input nominal (the derivative times the half-range, for a linear quantity exactly).

    Parameters
    ----------
    model : Model
        The design's analysis model.

    Returns
    -------
    dict
        {source name: {quantity key: float}}, in the quantity's unit.
    """
    k = len(model.sources)
    args = {src.name: np.full(2 * k, src.nominal) for src in model.sources}
    for j, src in enumerate(model.sources):
        args[src.name][2 * j], args[src.name][2 * j + 1] = src.low, src.high
    vals = evaluate(model, args)
    return {src.name: {key: float((v[2 * j + 1] - v[2 * j]) / 2) for key, v in vals.items()}
            for j, src in enumerate(model.sources)}


def sided(model: Model, nominal_values: dict) -> dict:
    """Each input's largest move of each quantity below and above its nominal, over the input's two ends, every
    other input nominal: what the one-sided root-sum-square adds up (an input whose range is not symmetric, or a
    quantity that bends, moves it further one way than the other).

    Parameters
    ----------
    model : Model
        The design's analysis model.
    nominal_values : dict
        {quantity key: nominal value}, as :func:`nominal` gives them.

    Returns
    -------
    dict
        {quantity key: (down, up)}: the root-sum-squares of the moves below and above nominal (both >= 0).
    """
    k = len(model.sources)
    args = {src.name: np.full(2 * k, src.nominal) for src in model.sources}
    for j, src in enumerate(model.sources):
        args[src.name][2 * j], args[src.name][2 * j + 1] = src.low, src.high
    out = {}
    for key, v in evaluate(model, args).items():
        d = np.asarray(v, dtype=float).reshape(k, 2) - nominal_values[key]
        out[key] = (float(np.sqrt(np.sum(np.minimum(d.min(axis=1), 0.0) ** 2))),
                    float(np.sqrt(np.sum(np.maximum(d.max(axis=1), 0.0) ** 2))))
    return out


def draw(model: Model, n: int, seed: int) -> dict:
    """``n`` boards: every input uniform in its range, drawn in the model's order from
    ``numpy.random.default_rng(seed)``.

    Parameters
    ----------
    model : Model
        The design's analysis model.
    n : int
        The number of boards.
    seed : int
        The generator's seed.

    Returns
    -------
    dict
        {source name: numpy.ndarray, shape (n,)}.
    """
    rng = np.random.default_rng(seed)
    return {src.name: rng.uniform(src.low, src.high, n) for src in model.sources}


def inside(measure: Measure, values: np.ndarray) -> np.ndarray:
    """Which values meet the quantity's limits (all of them when it has none).

    Parameters
    ----------
    measure : Measure
        The quantity.
    values : numpy.ndarray
        Its values.

    Returns
    -------
    numpy.ndarray
        bool, the shape of ``values``.
    """
    ok = np.ones(values.shape, dtype=bool)
    if measure.limit_low is not None:
        ok &= values >= measure.limit_low
    if measure.limit_high is not None:
        ok &= values <= measure.limit_high
    return ok


def margin(measure: Measure, low: float, high: float) -> float | None:
    """The worst margin of a quantity whose range is ``low`` .. ``high``: a fraction of the limit it is nearest
    (positive inside), None when it has no limit.

    Parameters
    ----------
    measure : Measure
        The quantity.
    low, high : float
        Its lowest and highest value.

    Returns
    -------
    float or None
        min(low / limit_low - 1, 1 - high / limit_high) over the limits it has.
    """
    out = []
    if measure.limit_low is not None:
        out.append(low / measure.limit_low - 1)
    if measure.limit_high is not None:
        out.append(1 - high / measure.limit_high)
    return min(out) if out else None


def worst_margin(model: Model, values: dict) -> float:
    """The least margin over every limited quantity, each at its extremes in ``values``.

    Parameters
    ----------
    model : Model
        The design's analysis model.
    values : dict
        {quantity key: numpy.ndarray} (corners, or samples).

    Returns
    -------
    float
        The least :func:`margin`, a fraction (inf when no quantity has a limit).
    """
    ms = [margin(m, float(values[m.key].min()), float(values[m.key].max())) for m in model.measures]
    return min((x for x in ms if x is not None), default=float("inf"))


def yields(model: Model, samples: dict) -> tuple[dict, float]:
    """Per limit, the fraction of boards inside it, and the fraction inside every limit.

    Parameters
    ----------
    model : Model
        The design's analysis model.
    samples : dict
        {quantity key: numpy.ndarray, shape (n,)}.

    Returns
    -------
    tuple
        ({limit name: fraction}, fraction inside all of them).
    """
    every = None
    out = {}
    for m in model.measures:
        if m.limit_low is None and m.limit_high is None:
            continue
        ok = inside(m, samples[m.key])
        out[m.limit_name] = float(ok.mean())
        every = ok if every is None else every & ok
    return out, (1.0 if every is None else float(every.mean()))


def halved(src: Source) -> Source:
    """The input with its range halved about its nominal value (each side's distance from it halved).

    Parameters
    ----------
    src : Source
        The input.

    Returns
    -------
    Source
        The same input, range nominal - (nominal - low) / 2 .. nominal + (high - nominal) / 2.
    """
    return dataclasses.replace(src, low=src.nominal - (src.nominal - src.low) / 2,
                               high=src.nominal + (src.high - src.nominal) / 2)


def binding(model: Model, eva: dict) -> Measure | None:
    """The limited quantity of the least worst-case margin: the one the sensitivity ranks the tolerances for.

    Parameters
    ----------
    model : Model
        The design's analysis model.
    eva : dict
        {quantity key: values at every corner} (:func:`corners`).

    Returns
    -------
    Measure or None
        That quantity; None when none has a limit.
    """
    limited = [(mg, i, m) for i, (m, mg) in enumerate(_limited(model, eva))]
    return min(limited)[2] if limited else None


def _limited(model: Model, eva: dict) -> list[tuple[Measure, float]]:
    """Every limited quantity with its worst-case margin (a fraction of its limit), in the model's order."""
    return [(m, margin(m, float(eva[m.key].min()), float(eva[m.key].max()))) for m in model.measures
            if m.limit_low is not None or m.limit_high is not None]


def _group_variance(model: Model, eff: dict, key: str) -> dict:
    """{tolerance group: its first-order variance of quantity ``key``} (``eff``: :func:`effects`), groups in the
    model's order."""
    groups = dict.fromkeys(src.group for src in model.sources)
    return {g: sum(eff[src.name][key] ** 2 for src in model.sources if src.group == g) for g in groups}


def per_limit(model: Model, eva: dict) -> list[tuple[str, float, str, float]]:
    """For every limited quantity: its worst-case margin and the tolerance group with the largest share of its
    first-order variance (:func:`effects`), least margin first.

    Parameters
    ----------
    model : Model
        The design's analysis model.
    eva : dict
        {quantity key: values at every corner} (:func:`corners`).

    Returns
    -------
    list of tuple
        (quantity key, its EVA margin as a fraction of its limit, the group, its share), least margin first; a
        quantity no tolerance moves has the group "" and share 0.
    """
    eff = effects(model)
    rows = []
    for m, mg in _limited(model, eva):
        var = _group_variance(model, eff, m.key)
        total = sum(var.values())
        top = max(var, key=var.get) if total > 0 else ""
        rows.append((m.key, mg, top, var[top] / total if total > 0 else 0.0))
    return sorted(rows, key=lambda r: r[1])


def sensitivity(model: Model, eva: dict, draws: dict) -> list[tuple[str, float, float, float]]:
    """Per tolerance group: its share of the binding quantity's first-order variance, the worst-case margin and
    the Monte Carlo yield with that group's ranges halved (the same random numbers, scaled towards nominal).

    Parameters
    ----------
    model : Model
        The design's analysis model.
    eva : dict
        {quantity key: values at every corner}.
    draws : dict
        {source name: the Monte Carlo's inputs}.

    Returns
    -------
    list of tuple
        (group, share, margin_if_halved, yield_if_halved), ranked by share, largest first.
    """
    key = getattr(binding(model, eva), "key", model.measures[0].key)
    var = _group_variance(model, effects(model), key)
    total = sum(var.values()) or 1.0
    rows = []
    for g in var:
        narrowed = tuple(halved(src) if src.group == g else src for src in model.sources)
        m_half = worst_margin(model, corners(model, narrowed))
        args = {src.name: (src.nominal + (draws[src.name] - src.nominal) / 2 if src.group == g else draws[src.name])
                for src in model.sources}
        _, y_half = yields(model, evaluate(model, args))
        rows.append((g, var[g] / total, m_half, y_half))
    return sorted(rows, key=lambda r: -r[1])


def combine(*models: Model) -> Model:
    """Several models as one: their inputs, quantities and drift sentences in the order given, each part's
    equations fed its own inputs (one model is returned as it is).

    Parameters
    ----------
    *models : Model
        The parts, their inputs' names and quantities' keys unique across them.

    Returns
    -------
    Model
        The parts together.

    Raises
    ------
    ValueError
        When two parts share an input's name or a quantity's key.
    """
    if len(models) == 1:
        return models[0]
    names = [src.name for m in models for src in m.sources]
    keys = [q.key for m in models for q in m.measures]
    if len(set(names)) < len(names) or len(set(keys)) < len(keys):
        raise ValueError(f"models to combine share an input or a quantity: {names}, {keys}")

    def f(**args):
        out = {}
        for m in models:
            out.update(m.f(**{src.name: args[src.name] for src in m.sources}))
        return out

    return Model(tuple(src for m in models for src in m.sources), tuple(q for m in models for q in m.measures), f,
                 tuple(s for m in models for s in m.drift))
