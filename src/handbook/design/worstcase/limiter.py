"""The op-amp current limiter's worst-case model: each board's trip current at both ends of the temperature span
and its op-amp input headroom, from the design's own node equations (AN94002 eq 11 and 12 with the offset and
bias currents of :mod:`handbook.design.limiter.model`) applied to arrays.

Quantities: ``i_trip_low`` (each board's lowest trip current over 25 C +- ``temp_span``; limit ``i_no_trip``),
``i_trip_high`` (its highest; limit ``i_must_trip``) and ``headroom`` (the least distance of either op-amp input
below the supply, D1 at its coldest-or-hottest low end; limit ``input_headroom``). The design's corners hold the
margins ``min_margin`` inside the window; the yields here are against the window itself (no margin).
:func:`handbook.design.limiter.monte_carlo_trip` (the chapters' histograms) draws this same lot.

Each board is judged at its worst temperature: its zener's drift is its own tempco times +-``temp_span``, so the
board's zener spans V_Z -+ |tc| ``temp_span``, and |tc| (uniform in 0.375 x ``zener_tc`` .. ``zener_tc``, the
BZX79's +0.03..+0.08 %/K) is the varying input. The bias currents vary as the corners take them: the two inputs'
average within +-``input_bias``, their difference within +-``input_offset_current`` (the parallelogram of
:func:`~handbook.design.limiter.model.bias_error`).
"""
from __future__ import annotations

import numpy as np

from ...sources.an94002 import circuit as an94002
from ..ratings import DIVIDER_TC
from .engine import Measure, Model, Source

#: no resistor, zener or op-amp datasheet the project cites gives a distribution inside its limits
UNIFORM = "no distribution inside the limits is published for it: uniform (every value in the range equally likely)"


#: the BZX79-C8V2's smallest temperature coefficient over its largest (+0.03 and +0.08 %/K, datasheet)
TC_LOW = 0.03 / 0.08


def equations(s: dict):
    """The limiter's board equations as one vectorised function of the varying inputs.

    Parameters
    ----------
    s : Mapping
        The checked ``[current_limiter]`` table (SI units); ``temp_span`` (K) is read.

    Returns
    -------
    callable
        ``f(r7, r9, r10, r11, r12, r13, vz, tc, vos, i_avg, i_diff) -> {"i_trip_low", "i_trip_high",
        "headroom"}`` (A, A, V), elementwise over arrays.
    """
    span = s["temp_span"]

    def f(r7, r9, r10, r11, r12, r13, vz, tc, vos, i_avg, i_diff):
        i_plus, i_minus = i_avg + i_diff / 2, i_avg - i_diff / 2
        s910 = r9 + r10
        r_m, inv_a = s910 * r11 / (s910 + r11), 1 + r12 / r13
        cold, hot = vz - tc * span, vz + tc * span  # the board's zener at the two ends of its drift
        trips = [(an94002.v_cs_trip(v, r9, r10, r11, r12, r13, vos) + i_plus * r12 - i_minus * r_m * inv_a) / r7
                 for v in (cold, hot)]
        head_plus = (cold * r12 - i_plus * r12 * r13) / (r12 + r13)
        head_minus = s910 * (cold - i_minus * r11) / (s910 + r11)
        return {"i_trip_low": np.minimum(*trips), "i_trip_high": np.maximum(*trips),
                "headroom": np.minimum(head_plus, head_minus)}

    return f


def sources(r7: float, network, s: dict) -> tuple[Source, ...]:
    """The limiter's varying inputs, each uniform in the range the design's corners take.

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
    tuple of Source
        R7, R9..R13, D1's tolerance and tempco, the LM358's offset, bias average and offset current.
    """
    t, t7 = s["resistor_tolerance"], s["r7_tolerance"]
    vz, tz = s["zener_voltage"], s["zener_tolerance"]
    rows = [Source("r7", "R7", r7 * (1 - t7), r7 * (1 + t7), r7, "R7 tolerance",
                   f"current_limiter.r7_tolerance = {t7:g}; {UNIFORM}", unit="ohm")]
    for name, value in zip(("r9", "r10", "r11", "r12", "r13"), network):
        rows.append(Source(name, name.upper(), value * (1 - t), value * (1 + t), value, "R9..R13 tolerance",
                           f"current_limiter.resistor_tolerance = {t:g}; {UNIFORM}", unit="ohm"))
    rows += [
        Source("vz", "D1 V_Z", vz * (1 - tz), vz * (1 + tz), vz, "zener tolerance",
               f"BZX79-C8V2 datasheet: 7.7 to 8.7 V at 5 mA (zener_tolerance = {tz:g}); {UNIFORM}", unit="V"),
        Source("tc", "D1 |tempco|", s["zener_tc"] * TC_LOW, s["zener_tc"], s["zener_tc"] * (1 + TC_LOW) / 2,
               "zener drift",
               "BZX79-C8V2 datasheet: +0.03 to +0.08 %/K (zener_tc the top): |tc| uniform in "
               f"{TC_LOW:.3g} x zener_tc .. zener_tc, each board at both ends of 25 C +- temp_span (AN94002 2.4)",
               unit="V/K"),
        Source("vos", "LM358 V_os", -s["offset"], s["offset"], 0.0, "op-amp offset",
               f"LM358 datasheet, over temperature: |V_os| <= {s['offset'] * 1e3:g} mV; {UNIFORM}", unit="V"),
        Source("i_avg", "LM358 I_b (average)", -s["input_bias"], s["input_bias"], 0.0, "op-amp bias current",
               f"LM358 datasheet (TI SLOS068), over temperature: {s['input_bias'] * 1e9:g} nA; either sign, as the "
               f"design's corners; {UNIFORM}", unit="A"),
        Source("i_diff", "LM358 I_os", -s["input_offset_current"], s["input_offset_current"], 0.0,
               "op-amp bias current", f"LM358 datasheet (TI SLOS068), over temperature: "
               f"{s['input_offset_current'] * 1e9:g} nA; {UNIFORM}", unit="A"),
    ]
    return tuple(rows)


def drift(s: dict) -> tuple[str, ...]:
    """Temperature and ageing drift of the limiter, each with its source.

    Parameters
    ----------
    s : Mapping
        The checked ``[current_limiter]`` table.

    Returns
    -------
    tuple of str
        Sentences: D1's drift (in the analysis), the dividers' and R7's tempco (outside it), ageing.
    """
    span, tc, vz = s["temp_span"], s["zener_tc"], s["zener_voltage"]
    return (
        f"D1 drifts by up to +-{tc * span * 1e3:.3g} mV ({tc * 1e3:g} mV/K over 25 C +- {span:g} K; BZX79-C8V2 "
        f"datasheet, +0.08 %/K max; AN94002 2.4's span), +-{tc * span / vz:.2%} of V_Z: inside the analysis, each "
        "board at both ends of the span.",
        f"R9..R13 at {DIVIDER_TC * 1e6:g} ppm/K (the BOM's thin-film class) drift {DIVIDER_TC * span:.2%} over "
        f"+-{span:g} K, inside resistor_tolerance = {s['resistor_tolerance']:.2%} when bought in the BOM's tolerance "
        "class (a tracking network where no stocked class leaves room); they share one type, so their drift largely "
        "cancels in the divider ratios.",
        "R7 (<= 100 ppm/K, the BOM's current-sense class) warms while it holds a stalled motor: about 1 % of the "
        "trip current, outside the analysis and covered by min_margin "
        f"= {s['min_margin']:.0%} (the schema's meaning of min_margin).",
        "The LM358's offset and bias figures are its over-temperature maxima (LM358 datasheet, TI SLOS068): "
        "their drift is inside the ranges sampled.",
        "Ageing: no source here prints it for these parts; min_margin is what is left for it.",
    )


def model(r7: float, network, s: dict) -> Model:
    """The limiter's worst-case model for one network (a design's, or a candidate of the yield search).

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
    Model
        Inputs, the three quantities with their limits, the equations and the drift sentences.
    """
    measures = (
        Measure("i_trip_low", "lowest trip current over the temperature span", "A", s["i_no_trip"], None, "i_no_trip"),
        Measure("i_trip_high", "highest trip current over the temperature span", "A", None, s["i_must_trip"],
                "i_must_trip"),
        Measure("headroom", "least op-amp input headroom below the supply", "V", s["input_headroom"], None,
                "input_headroom"),
    )
    return Model(sources(r7, network, s), measures, equations(s), drift(s))
