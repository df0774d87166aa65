"""What a chosen limiter is worth beyond its corners: which tolerance eats the window, and a production lot."""
from __future__ import annotations

import math

import numpy as np

from . import model as net
from .model import checked

#: what spreads the trip current, and the spec keys that set each (zeroed one at a time by sensitivity)
SPREAD_SOURCES = {"R9..R13 tolerance": ("resistor_tolerance",), "R7 tolerance": ("r7_tolerance",),
                  "zener tolerance": ("zener_tolerance",), "zener drift": ("zener_tc",), "op-amp offset": ("offset",),
                  "op-amp bias current": ("input_bias", "input_offset_current")}


def sensitivity(r7: float, network, s: dict) -> list[tuple[str, float, float]]:
    """Which tolerance eats the window: for each source, (name, share of ln(i_trip_max / i_trip_min), the
    worst margin with that source removed). The shares are of the log spread at every corner, each
    source removed alone; they need not add to one (the sources interact), so they are normalised.

    Parameters
    ----------
    r7 : float
        The sense resistor R7, nominal, ohm.
    network : tuple of float
        (R9, R10, R11, R12, R13), nominal, ohm.
    s : Mapping
        The checked ``[current_limiter]`` table (SI units).

    Returns
    -------
    list of tuple
        One (source, share, margin) per entry of :data:`SPREAD_SOURCES`, in its order: the source's name (str);
        its share of ln(i_trip_max / i_trip_min), a fraction (the shares add to one); the worst margin with that
        source's keys set to zero, a fraction of the limits.
    """
    base = net.verify(r7, network, s)
    spread = math.log(float(base["i_trip_max"] / base["i_trip_min"]))
    rows = []
    for name, keys in SPREAD_SOURCES.items():
        v = net.verify(r7, network, {**s, **{k: 0.0 for k in keys}})
        rows.append((name, spread - math.log(float(v["i_trip_max"] / v["i_trip_min"])),
                     float(min(v["margin_low"], v["margin_high"]))))
    total = sum(r[1] for r in rows) or 1.0
    return [(name, gain / total, margin) for name, gain, margin in rows]


def monte_carlo_trip(r7: float, network, s: dict, n: int = 100_000, seed: int = 1) -> dict:
    """A production lot of ``n`` boards (fixed seed, vectorised): the design report's own lot
    (:mod:`handbook.design.worstcase.limiter`: every part uniform within its tolerance, the zener's tempco within
    the BZX79's range, each board at both ends of ``temp_span``), so the chapters' histograms and the report's
    yields are of one lot.

    Parameters
    ----------
    r7 : float
        The sense resistor R7, nominal, ohm.
    network : tuple of float
        (R9, R10, R11, R12, R13), nominal, ohm.
    s : Mapping or None
        The ``[current_limiter]`` table, {key: value}, SI units (checked here; None: the defaults).
    n : int
        The number of boards.
    seed : int
        The random generator's seed.

    Returns
    -------
    dict
        "yield": the fraction of boards whose trip current lies within ``i_no_trip`` .. ``i_must_trip`` at both
        ends of the temperature span (no margin); "i_p001": the 0.1 % quantile of the boards' lowest trip currents,
        "i_p999": the 99.9 % quantile of their highest, A; "i_min" and "i_max": the lot's lowest and highest, A
        (floats); "samples": every board's trip current at both ends of the span, A (numpy.ndarray, shape (2 n,)).

    Raises
    ------
    InputError
        When ``s`` is invalid (:func:`~handbook.design.limiter.model.checked`).
    """
    from ..worstcase import engine
    from ..worstcase import limiter as board

    s = checked(s)
    m = board.model(r7, network, s)
    lot = engine.evaluate(m, engine.draw(m, n, seed))
    low, high = lot["i_trip_low"], lot["i_trip_high"]
    ok = (low >= s["i_no_trip"]) & (high <= s["i_must_trip"])
    return {"yield": float(ok.mean()), "i_p001": float(np.quantile(low, 0.001)),
            "i_p999": float(np.quantile(high, 0.999)), "i_min": float(low.min()), "i_max": float(high.max()),
            "samples": np.concatenate([low, high])}
