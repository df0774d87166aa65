"""What a chosen limiter is worth beyond its corners: which tolerance eats the window, and a production lot."""
from __future__ import annotations

import math

import numpy as np

from ...sources.an94002 import circuit as an94002
from . import model as net
from .model import checked, zener_range

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
    """Trip currents of ``n`` boards, every part uniform within its tolerance (fixed seed, vectorised).

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
        "yield": the fraction of boards whose trip current lies within ``i_no_trip`` .. ``i_must_trip`` (no
        margin); "i_p001" and "i_p999": the 0.1 % and 99.9 % quantiles of the trip current, A; "i_min" and
        "i_max": its lowest and highest, A (floats); "samples": every board's trip current, A (numpy.ndarray,
        shape (n,)).

    Raises
    ------
    InputError
        When ``s`` is invalid (:func:`~handbook.design.limiter.model.checked`).
    """
    s = checked(s)
    rng = np.random.default_rng(seed)
    t = s["resistor_tolerance"]

    def u(x, tol):
        return x * (1 + rng.uniform(-tol, tol, n))

    vz_lo, vz_hi = zener_range(s)
    r9, r10, r11, r12, r13 = (u(x, t) for x in network)
    ios = min(s["input_offset_current"], 2 * s["input_bias"])
    common = rng.uniform(-1, 1, n) * (s["input_bias"] - ios / 2)  # both inputs the same way, differing by <= I_os
    half = rng.uniform(-ios / 2, ios / 2, n)
    v = (an94002.v_cs_trip(rng.uniform(vz_lo, vz_hi, n), r9, r10, r11, r12, r13, rng.uniform(-s["offset"], s["offset"], n))
         + (common + half) * r12 - (common - half) * (r9 + r10) * r11 / (r9 + r10 + r11) * (1 + r12 / r13))
    i = v / u(r7, s["r7_tolerance"])
    ok = (i >= s["i_no_trip"]) & (i <= s["i_must_trip"])
    return {"yield": float(ok.mean()), "i_p001": float(np.quantile(i, 0.001)),
            "i_p999": float(np.quantile(i, 0.999)), "i_min": float(i.min()), "i_max": float(i.max()), "samples": i}
