"""AN94002 (Philips, R. Galema, 1995): evaluation board for the TDA5143/TDA5144.

Start oscillator, adaptive commutation delay, watchdog, speed control, the two current limiters,
decoupling and the parts list: the circuit functions (SI in, SI out; speed in rpm as the note states
it), the note's values, the equations with their derivations and every number the note prints.
"""
from __future__ import annotations

from ...core import Source
from . import cases, claims, data
from .circuit import (
    c_min_for_impedance,
    cap_cd_min,
    cap_st_for,
    cap_ti_for,
    cap_ti_waveform,
    choose_cap_cd,
    esl_max,
    excursion,
    factor_a,
    factor_b,
    impedance,
    level_shift,
    limit_current,
    limit_tc,
    note_stack_up,
    oscillation_frequency,
    ota_input_max,
    r3_for,
    r7_for_limit,
    r9_for,
    reliable_speed_range,
    rpm_max_for,
    rpm_min_for,
    rpm_ratio,
    start_period,
    t_com,
    t_cycle,
    trip_worst_case,
    v_cs_matched,
    v_cs_trip,
    v_in_for,
    v_in_range,
    v_mot_max,
    watchdog_time,
)
from .data import FACTS, NAME
from .parts import PART_ROLES, PARTS, PARTS_HEADER, decode_12nc
from .parts import parts_rows as _parts_rows

SOURCE = Source(name=NAME, title="TDA5143/TDA5144 evaluation board", parameters=data.PARAMETERS,
                facts=FACTS, equations_module=f"{__name__}.equations",
                build_claims=claims.build, errata=data.ERRATA, cases=cases.CASES)
params, evaluate, equation = SOURCE.params, SOURCE.evaluate, SOURCE.equation


def parts_rows(p: dict, checks: list[dict] | None = None) -> list[list[str]]:
    """The parts list for the board of ``p``: see :func:`.parts.parts_rows` (``checks`` default: the source's own
    evaluation at ``p``).

    Parameters
    ----------
    p : dict
        The board's parameters (:func:`params`).
    checks : list of dict or None
        Rows of :func:`evaluate` at ``p``, if already computed.

    Returns
    -------
    list of list of str
        One row of text per part.
    """
    return _parts_rows(p, evaluate(p) if checks is None else checks)

__all__ = [
    "FACTS", "NAME", "PARTS", "PARTS_HEADER", "PART_ROLES", "SOURCE", "c_min_for_impedance", "cap_cd_min",
    "cap_st_for", "cap_ti_for", "cap_ti_waveform", "choose_cap_cd", "decode_12nc", "equation", "esl_max",
    "evaluate", "excursion", "factor_a", "factor_b", "impedance", "level_shift", "limit_current", "limit_tc",
    "note_stack_up", "oscillation_frequency", "ota_input_max", "params", "parts_rows", "r3_for", "r7_for_limit",
    "r9_for", "reliable_speed_range", "rpm_max_for", "rpm_min_for", "rpm_ratio", "start_period", "t_com", "t_cycle",
    "trip_worst_case", "v_cs_matched", "v_cs_trip", "v_in_for", "v_in_range", "v_mot_max", "watchdog_time",
]
