"""LM4651 driver + LM4652 power MOSFET bridge (National Semiconductor, 2000): 170 W class-D amplifier.

Loss, clipping, distortion and thermal models used to choose the switching frequency (``circuit``), the
datasheet's equations 1 to 12 (``equations``) and its "Example Design", number by number (``claims``).
"""
from __future__ import annotations

from ...core import Source
from . import cases, claims, data
from .circuit import (
    A_OM,
    DEVICE,
    EPS0_PF_PER_IN,
    F_REF,
    R_S,
    SUPPLY_REF,
    THD_EXPONENT,
    THD_REF,
    V_EFF,
    dead_time,
    f_sw_for,
    gain,
    i_sckt,
    losses,
    p_clip,
    p_conduction,
    p_switch,
    p_switch_edges,
    r_osc_for,
    switching_loss_fraction,
    t_junction,
    thd_n,
    theta_sa_required,
)
from .data import FACTS

SOURCE = Source(name=data.NAME, title="LM4651/LM4652 170 W class-D amplifier", parameters=data.PARAMETERS,
                facts=FACTS, equations_module=f"{__name__}.equations",
                build_claims=claims.build, errata=data.ERRATA, cases=cases.CASES,
                reading_notes=data.READING_NOTES)
params, evaluate, equation = SOURCE.params, SOURCE.evaluate, SOURCE.equation

__all__ = [
    "A_OM",
    "DEVICE",
    "EPS0_PF_PER_IN",
    "FACTS",
    "F_REF",
    "R_S",
    "SOURCE",
    "SUPPLY_REF",
    "THD_EXPONENT",
    "THD_REF",
    "V_EFF",
    "dead_time",
    "equation",
    "evaluate",
    "f_sw_for",
    "gain",
    "i_sckt",
    "losses",
    "p_clip",
    "p_conduction",
    "p_switch",
    "p_switch_edges",
    "params",
    "r_osc_for",
    "switching_loss_fraction",
    "t_junction",
    "thd_n",
    "theta_sa_required",
]
