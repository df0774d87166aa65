"""LM4651/LM4652 loss, clipping, distortion and thermal models used to choose the switching frequency.

Every figure is from the datasheet (its tables, equations 3 to 12 and its "Example Design", see
:data:`~handbook.sources.lm4651.data.FACTS`) unless marked as a calibration, and the calibrations are
stated with their points. Functions work on floats, numpy arrays and casadi symbols alike (plain
arithmetic only), so the optimiser and the plots share them.
"""
from __future__ import annotations

import math

from .data import FACTS

#: the device figures by name (values only; their citations are in FACTS)
DEVICE = {k: f.value for k, f in FACTS.items()}

# --- calibrations (stated in the chapter) ---------------------------------------------------
# Clipping power at 1 % THD: the bridge's peak output is V_EFF (1 - A_OM f) R_L / (R_L + R_S), with
# the over-modulation pulse taking a fixed time out of every period. Three datasheet points fix the
# three constants: 125 W at 125 kHz and 135 W at 75 kHz (4 ohm), 75 W at 125 kHz (8 ohm), all +-20 V.
_S = math.sqrt(135 / 125)
A_OM = (_S - 1) / (_S * 125e3 - 75e3)  # s: time lost per period (about 2.3 x T_overmod)
R_S = (4 - 8 * math.sqrt(0.3)) / (math.sqrt(0.3) - 1)  # ohm: series resistance (2 R_DS(on) + filter)
V_EFF = math.sqrt(2 * 4 * 125) * (4 + R_S) / 4 / (1 - A_OM * 125e3)  # V at +-20 V supply
SUPPLY_REF = 20.0
# THD+N at the 10 W test point: 0.3 % at 125 kHz (datasheet), rising as the switching residue that
# the second-order output filter lets through, i.e. as (125 kHz / f)^2 (an assumed exponent).
THD_REF, F_REF, THD_EXPONENT = 0.003, 125e3, 2.0
EPS0_PF_PER_IN = 8.8541878128e-12 * 0.0254 * 1e12  # vacuum permittivity in pF/in (CODATA)


def r_osc_for(f_sw, r_dly=0.0):
    """Eq 6 with the R_DLY correction: R_OSC = 1e9/f - 4000, plus about 2 k per 5 k of R_DLY."""
    return 1e9 / f_sw - 4000.0 + 0.4 * r_dly


def f_sw_for(r_osc, r_dly=0.0):
    """Eq 5 with the same correction: f = 1e9 / (4000 + R_OSC - 0.4 R_DLY)."""
    return 1e9 / (4000.0 + r_osc - 0.4 * r_dly)


def dead_time(r_dly):
    """Eq 4: T_DLY = 1.7e-12 (500 + R_DLY) seconds."""
    return 1.7e-12 * (500 + r_dly)


def i_sckt(r_sckt):
    """Eq 3: I = 1e5 / (10 k || R_SCKT) amperes."""
    return 1e5 / (1e4 * r_sckt / (1e4 + r_sckt))


def gain(r1, r2, rf11, rf12):
    """Eq 12 (reconstructed): (R2/R1) (Rf11 + Rf12)/Rf12 - R2/R1 + 0.5."""
    return r2 / r1 * (rf11 + rf12) / rf12 - r2 / r1 + 0.5


def switching_loss_fraction(f_sw, t_rise=DEVICE["t_rise"], t_fall=DEVICE["t_fall"], t_overmod=DEVICE["t_overmod"]):
    """Eq 9: %LOSS = (t_r + t_f + T_overmod) f_sw."""
    return (t_rise + t_fall + t_overmod) * f_sw


def p_switch(f_sw, p_out, **times):
    """Eq 10: P = %LOSS P_out / (1 - %LOSS)."""
    x = switching_loss_fraction(f_sw, **times)
    return x * p_out / (1 - x)


def p_conduction(p_out, r_load, rds_on=DEVICE["rds_on_hot"]):
    """I_rms^2 x 2 R_DS(on): two MOSFETs of the bridge conduct at any time."""
    return p_out / r_load * 2 * rds_on


def p_clip(f_sw, r_load=4.0, supply=20.0):
    """Output power at 1 % THD (clipping) against switching frequency (calibrated model)."""
    v = V_EFF * supply / SUPPLY_REF * (1 - A_OM * f_sw) * r_load / (r_load + R_S)
    return v * v / (2 * r_load)


def thd_n(f_sw):
    """THD+N at the 10 W, 4 ohm test point against switching frequency (calibrated model)."""
    return THD_REF * (F_REF / f_sw) ** THD_EXPONENT


def losses(f_sw, p_out, r_load, rds_on=DEVICE["rds_on_hot"], **times):
    """(LM4652 dissipation, total dissipation including the LM4651, efficiency)."""
    p_4652 = p_switch(f_sw, p_out, **times) + p_conduction(p_out, r_load, rds_on)
    total = p_4652 + DEVICE["p_driver"]
    return p_4652, total, p_out / (p_out + total)


def theta_sa_required(p_d, t_ambient, package="TF", theta_cs=0.2, tj_max=DEVICE["tj_max"]):
    """Eq 11 solved for the heat sink: theta_SA = (T_jmax - T_a) / P_D - theta_JC - theta_CS."""
    return (tj_max - t_ambient) / p_d - DEVICE["theta_jc"][package] - theta_cs


def t_junction(p_d, t_ambient, theta_sa, package="TF", theta_cs=0.2):
    """Thermal Ohm's law through junction-case, case-sink and sink-ambient in series."""
    return t_ambient + p_d * (DEVICE["theta_jc"][package] + theta_cs + theta_sa)
