"""LM4651 driver + LM4652 power MOSFET bridge (National Semiconductor, 2000): 170 W class-D amplifier.

Loss, clipping, distortion and thermal models used to choose the switching frequency. Every figure
is from the datasheet (its tables, equations 5 to 11 and its "Example Design") unless marked as a
calibration, and the calibrations are stated with their points. Functions work on floats, numpy
arrays and casadi symbols alike (plain arithmetic only), so the optimiser and the plots share them.
"""
from __future__ import annotations

import math

#: datasheet figures (LM4651/LM4652 datasheet, National Semiconductor 2000)
DATASHEET = {
    "t_rise": 25e-9,  # LM4652 t_r, typical
    "t_fall": 26e-9,  # LM4652 t_f, typical
    "t_overmod": 310e-9,  # LM4651 over-modulation protection time, typical (the example uses 350 ns)
    "rds_on_hot": 0.230,  # ohm, the example's R_DS(on) "at 100 C" (table: 0.200 typ, 0.300 max at 25 C)
    "theta_jc": {"TF": 2.0, "T": 1.0},  # K/W, LM4652 isolated (TF) and non-isolated (T) TO-220
    "theta_ja": {"TF": 43.0, "T": 37.0},  # K/W, no heat sink
    "tj_max": 150.0,  # C
    "f_min": 50e3, "f_max": 225e3,  # Hz, "50 kHz to 225 kHz"
    "p_driver": 1.0,  # W, LM4651's own dissipation: the example's 22 W system less 21 W in the LM4652
}

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


def r_osc_for(f_sw, r_dly=0.0):
    """Eq 6 with the R_DLY correction: R_OSC = 1e9/f - 4000, plus about 2 k per 5 k of R_DLY."""
    return 1e9 / f_sw - 4000.0 + 0.4 * r_dly


def f_sw_for(r_osc, r_dly=0.0):
    """Eq 5 with the same correction: f = 1e9 / (4000 + R_OSC - 0.4 R_DLY)."""
    return 1e9 / (4000.0 + r_osc - 0.4 * r_dly)


def switching_loss_fraction(f_sw, t_rise=DATASHEET["t_rise"], t_fall=DATASHEET["t_fall"],
                            t_overmod=DATASHEET["t_overmod"]):
    """Eq 9: %LOSS = (t_r + t_f + T_overmod) f_sw."""
    return (t_rise + t_fall + t_overmod) * f_sw


def p_switch(f_sw, p_out, **times):
    """Eq 10: P = %LOSS P_out / (1 - %LOSS)."""
    x = switching_loss_fraction(f_sw, **times)
    return x * p_out / (1 - x)


def p_conduction(p_out, r_load, rds_on=DATASHEET["rds_on_hot"]):
    """I_rms^2 x 2 R_DS(on): two MOSFETs of the bridge conduct at any time."""
    return p_out / r_load * 2 * rds_on


def p_clip(f_sw, r_load=4.0, supply=20.0):
    """Output power at 1 % THD (clipping) against switching frequency (calibrated model)."""
    v = V_EFF * supply / SUPPLY_REF * (1 - A_OM * f_sw) * r_load / (r_load + R_S)
    return v * v / (2 * r_load)


def thd_n(f_sw):
    """THD+N at the 10 W, 4 ohm test point against switching frequency (calibrated model)."""
    return THD_REF * (F_REF / f_sw) ** THD_EXPONENT


def losses(f_sw, p_out, r_load, rds_on=DATASHEET["rds_on_hot"], **times):
    """(LM4652 dissipation, total dissipation including the LM4651, efficiency)."""
    p_4652 = p_switch(f_sw, p_out, **times) + p_conduction(p_out, r_load, rds_on)
    total = p_4652 + DATASHEET["p_driver"]
    return p_4652, total, p_out / (p_out + total)


def theta_sa_required(p_d, t_ambient, package="TF", theta_cs=0.2, tj_max=DATASHEET["tj_max"]):
    """Eq 11 solved for the heat sink: theta_SA = (T_jmax - T_a) / P_D - theta_JC - theta_CS."""
    return (tj_max - t_ambient) / p_d - DATASHEET["theta_jc"][package] - theta_cs


def t_junction(p_d, t_ambient, theta_sa, package="TF", theta_cs=0.2):
    """Thermal Ohm's law through junction-case, case-sink and sink-ambient in series."""
    return t_ambient + p_d * (DATASHEET["theta_jc"][package] + theta_cs + theta_sa)
