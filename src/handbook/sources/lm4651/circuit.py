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
    """Eq 6 with the R_DLY correction: R_OSC = 1e9/f - 4000, plus about 2 k per 5 k of R_DLY.

    Parameters
    ----------
    f_sw : float
        Switching frequency, Hz.
    r_dly : float
        Dead-time resistor R_DLY, ohm.

    Returns
    -------
    float
        R_OSC, ohm.
    """
    return 1e9 / f_sw - 4000.0 + 0.4 * r_dly


def f_sw_for(r_osc, r_dly=0.0):
    """Eq 5 with the same correction: f = 1e9 / (4000 + R_OSC - 0.4 R_DLY).

    Parameters
    ----------
    r_osc : float
        Oscillator resistor R_OSC, ohm.
    r_dly : float
        Dead-time resistor R_DLY, ohm.

    Returns
    -------
    float
        The switching frequency, Hz.
    """
    return 1e9 / (4000.0 + r_osc - 0.4 * r_dly)


def dead_time(r_dly):
    """Eq 4: T_DLY = 1.7e-12 (500 + R_DLY) seconds.

    Parameters
    ----------
    r_dly : float
        Dead-time resistor R_DLY, ohm.

    Returns
    -------
    float
        The dead time, s.
    """
    return 1.7e-12 * (500 + r_dly)


def i_sckt(r_sckt):
    """Eq 3: I = 1e5 / (10 k || R_SCKT) amperes.

    Parameters
    ----------
    r_sckt : float
        Current-limit resistor R_SCKT, ohm.

    Returns
    -------
    float
        The current limit, A.
    """
    return 1e5 / (1e4 * r_sckt / (1e4 + r_sckt))


def gain(r1, r2, rf11, rf12):
    """Eq 12 (reconstructed): (R2/R1) (Rf11 + Rf12)/Rf12 - R2/R1 + 0.5.

    Parameters
    ----------
    r1, r2 : float
        Input resistor R1 and resistor R2, ohm.
    rf11, rf12 : float
        Feedback resistors R_f11 and R_f12, ohm.

    Returns
    -------
    float
        The closed-loop gain, a pure number (V/V).
    """
    return r2 / r1 * (rf11 + rf12) / rf12 - r2 / r1 + 0.5


def switching_loss_fraction(f_sw, t_rise=DEVICE["t_rise"], t_fall=DEVICE["t_fall"], t_overmod=DEVICE["t_overmod"]):
    """Eq 9: %LOSS = (t_r + t_f + T_overmod) f_sw.

    Parameters
    ----------
    f_sw : float
        Switching frequency, Hz.
    t_rise, t_fall : float
        LM4652 rise and fall times, s.
    t_overmod : float
        Over-modulation time T_OVERMOD, s.

    Returns
    -------
    float
        %LOSS, a fraction.
    """
    return (t_rise + t_fall + t_overmod) * f_sw


def p_switch(f_sw, p_out, **times):
    """Eq 10: P = %LOSS P_out / (1 - %LOSS).

    Parameters
    ----------
    f_sw : float
        Switching frequency, Hz.
    p_out : float
        Output power, W.
    **times : float
        ``t_rise``, ``t_fall``, ``t_overmod`` for :func:`switching_loss_fraction`, s (default: the datasheet's typical values).

    Returns
    -------
    float
        The switching dissipation, W.
    """
    x = switching_loss_fraction(f_sw, **times)
    return x * p_out / (1 - x)


def p_switch_edges(f_sw, p_out, r_load, supply=20.0, t_rise=DEVICE["t_rise"], t_fall=DEVICE["t_fall"]):
    """The textbook switching loss the datasheet does not use: V I (t_r + t_f) f_sw, with V the 2 V_s each
    half-bridge swings (the LM4652 table measures t_r and t_f at V_DS = 40 V) and I the rms output current.
    Each edge of each half-bridge dissipates about V I t / 2; two half-bridges switch every period.
    Only the edges: no term for the over-modulation pulse, during which the MOSFETs are fully on or off.

    Parameters
    ----------
    f_sw : float
        Switching frequency, Hz.
    p_out : float
        Output power, W.
    r_load : float
        Load resistance, ohm.
    supply : float
        Rail voltage V_s of the +-V_s supply, V.
    t_rise, t_fall : float
        LM4652 rise and fall times, s.

    Returns
    -------
    float
        The edges' switching loss, W.
    """
    return 2 * supply * (p_out / r_load) ** 0.5 * (t_rise + t_fall) * f_sw


def p_conduction(p_out, r_load, rds_on=DEVICE["rds_on_hot"]):
    """I_rms^2 x 2 R_DS(on): two MOSFETs of the bridge conduct at any time.

    Parameters
    ----------
    p_out : float
        Output power, W.
    r_load : float
        Load resistance, ohm.
    rds_on : float
        On-resistance R_DS(on) of one MOSFET, ohm.

    Returns
    -------
    float
        The conduction dissipation, W.
    """
    return p_out / r_load * 2 * rds_on


def p_clip(f_sw, r_load=4.0, supply=20.0):
    """Output power at 1 % THD (clipping) against switching frequency (calibrated model).

    Parameters
    ----------
    f_sw : float
        Switching frequency, Hz.
    r_load : float
        Load resistance, ohm.
    supply : float
        Rail voltage V_s of the +-V_s supply, V.

    Returns
    -------
    float
        The output power at 1 % THD, W.
    """
    v = V_EFF * supply / SUPPLY_REF * (1 - A_OM * f_sw) * r_load / (r_load + R_S)
    return v * v / (2 * r_load)


def thd_n(f_sw):
    """THD+N at the 10 W, 4 ohm test point against switching frequency (calibrated model).

    Parameters
    ----------
    f_sw : float
        Switching frequency, Hz.

    Returns
    -------
    float
        THD+N, a fraction (0.003 is 0.3 %).
    """
    return THD_REF * (F_REF / f_sw) ** THD_EXPONENT


def losses(f_sw, p_out, r_load, rds_on=DEVICE["rds_on_hot"], **times):
    """(LM4652 dissipation, total dissipation including the LM4651, efficiency).

    Parameters
    ----------
    f_sw : float
        Switching frequency, Hz.
    p_out : float
        Output power, W.
    r_load : float
        Load resistance, ohm.
    rds_on : float
        On-resistance R_DS(on) of one MOSFET, ohm.
    **times : float
        ``t_rise``, ``t_fall``, ``t_overmod``, s, as :func:`p_switch` takes them.

    Returns
    -------
    tuple of float
        (LM4652 dissipation, W; total dissipation with the LM4651's, W; efficiency, a fraction).
    """
    p_4652 = p_switch(f_sw, p_out, **times) + p_conduction(p_out, r_load, rds_on)
    total = p_4652 + DEVICE["p_driver"]
    return p_4652, total, p_out / (p_out + total)


def theta_sa_required(p_d, t_ambient, package="TF", theta_cs=0.2, tj_max=DEVICE["tj_max"]):
    """Eq 11 solved for the heat sink: theta_SA = (T_jmax - T_a) / P_D - theta_JC - theta_CS.

    Parameters
    ----------
    p_d : float
        LM4652 dissipation, W.
    t_ambient : float
        Ambient temperature, degrees C.
    package : str
        ``"TF"`` (isolated) or ``"T"`` TO-220, for theta_JC.
    theta_cs : float
        Case-to-sink thermal resistance, K/W.
    tj_max : float
        Largest junction temperature, degrees C.

    Returns
    -------
    float
        The largest sink-to-ambient thermal resistance, K/W.
    """
    return (tj_max - t_ambient) / p_d - DEVICE["theta_jc"][package] - theta_cs


def t_junction(p_d, t_ambient, theta_sa, package="TF", theta_cs=0.2):
    """Thermal Ohm's law through junction-case, case-sink and sink-ambient in series.

    Parameters
    ----------
    p_d : float
        LM4652 dissipation, W.
    t_ambient : float
        Ambient temperature, degrees C.
    theta_sa : float
        Sink-to-ambient thermal resistance, K/W.
    package : str
        ``"TF"`` (isolated) or ``"T"`` TO-220, for theta_JC.
    theta_cs : float
        Case-to-sink thermal resistance, K/W.

    Returns
    -------
    float
        The junction temperature, degrees C.
    """
    return t_ambient + p_d * (DEVICE["theta_jc"][package] + theta_cs + theta_sa)


# --- the joint design's models (f_sw, L, C, R_DLY and the heat sink) -------------------------
# Each names its assumption and the datasheet figure that calibrates it; the functions take floats,
# numpy arrays and casadi symbols alike.

#: the LM4651 table's typical frequencies against eq 5: R_OSC = 0 gives 200 kHz (eq 5: 250 kHz) and
#: 15 kOhm 65 kHz (eq 5: 52.6 kHz). The disagreement is taken as eq 5's tolerance, not fitted away.
F_TABLE = ((0.0, 200e3), (15e3, 65e3))
F_TOL_LOW = 1 - F_TABLE[0][1] / f_sw_for(F_TABLE[0][0])  # 0.20: the oscillator may run 20 % slow
F_TOL_HIGH = F_TABLE[1][1] / f_sw_for(F_TABLE[1][0]) - 1  # 0.235: or 23.5 % fast
T_DEAD_0 = 27e-9  # s: LM4651 table, dead time at R_DLY = 0 (eq 4 gives 0.85 ns there)
C_DEAD = 1.7e-12  # F: eq 4's slope, 1.7 pF per ohm of R_DLY
RDS_ON_MAX_25 = 0.300  # ohm: LM4652 table, R_DS(on) maximum at 25 C
RDS_TC = (DEVICE["rds_on_hot"] / 0.200 - 1) / (100.0 - 25.0)  # 1/K: 200 mOhm typ at 25 C -> 230 at 100 C
T_OVERMOD_MAX = 350e-9  # s: no maximum printed; the Example Design's own 350 ns (typical 310 ns)
SUPPLY_TOTAL = (22.0, 44.0)  # V: operating ratings, V+ + V- (the rails +-11 V to +-22 V)
RAILS = (SUPPLY_TOTAL[0] / 2, SUPPLY_TOTAL[1] / 2)  # V: the same as +-V_s, lowest and highest
SUPPLY_ABS_MAX = 22.0  # V: absolute maximum ratings, supply voltage +-22 V (the operating range's top too)
P_D_MAX_4652 = 32.0  # W: absolute maximum ratings, power dissipation (LM4652)
I_D_SAT_MIN = 8.0  # A: LM4652 table, saturation drain current, minimum (10 A typical; V_GS 6 V, V_DS 10 V)
I_LIMIT = 10.0  # A: "the inductor ripple current and the peak output current must be lower than 10 amps"
I_Q_4651 = 36e-3  # A: LM4651 table, quiescent current with the LM4652 not connected, |I_VCC+| + |I_VEE-| (typical)
L_REF, C_REF = 50e-6, 5e-6  # H, F: Output Stage Filtering, "a 50 uH inductor and a 5 uF Mylar capacitor"
#: idle loss at +-20 V from the system table's 55 % efficiency at 5 W (R_DLY = 5 k, 125 kHz, 4 ohm): what is
#: left of 5/0.55 - 5 W after conduction (200 mOhm typ, cold) and eq 9/10 switching, 3.35 W. The table's I_CQ of
#: 124 mA is |I_VCC+| + |I_VEE-| (the datasheet's definition), 20 V x 124 mA = 2.48 W: below it, consistent.
P_IDLE_REF = 5 / 0.55 - 5 - p_conduction(5.0, 4.0, 0.200) - p_switch(125e3, 5.0)


def dead_time_total(r_dly):
    """Dead time: the LM4651 table's 27 ns at R_DLY = 0 plus eq 4's 1.7 pF x R_DLY (eq 4's own 500 ohm
    offset gives 0.85 ns where the table says 27 ns).

    Parameters
    ----------
    r_dly : float
        Dead-time resistor R_DLY, ohm.

    Returns
    -------
    float
        The dead time, s.
    """
    return T_DEAD_0 + C_DEAD * r_dly


def rds_on_max(t_j):
    """R_DS(on) maximum at the junction temperature: 300 mOhm at 25 C (LM4652 table) rising linearly by the
    datasheet's own ratio, 200 -> 230 mOhm from 25 C to 100 C (0.2 %/K; typical, applied to the maximum).

    Parameters
    ----------
    t_j : float
        Junction temperature, degrees C.

    Returns
    -------
    float
        R_DS(on), maximum, ohm.
    """
    return RDS_ON_MAX_25 * (1 + RDS_TC * (t_j - 25.0))


def p_idle(supply):
    """Idle (no-signal) loss of the pair, calibrated on 55 % at 5 W and +-20 V; a constant supply current
    (3.35 W / 40 V = 84 mA), so it scales with the rails. Assumed independent of f_sw and of L.

    Parameters
    ----------
    supply : float
        Rail voltage V_s of the +-V_s supply, V.

    Returns
    -------
    float
        The idle loss of the LM4651 and LM4652 together, W.
    """
    return P_IDLE_REF * supply / SUPPLY_REF


def p_idle_4652(supply):
    """The LM4652's share of the idle loss: all of it but the LM4651's own, its 36 mA quiescent current x V_s (the
    table's figure is |I_VCC+| + |I_VEE-|, as the system table's I_CQ: the two rails' currents summed, so the power
    from +-V_s is V_s times it, 0.72 W at +-20 V).

    Parameters
    ----------
    supply : float
        Rail voltage V_s of the +-V_s supply, V.

    Returns
    -------
    float
        The LM4652's idle loss, W.
    """
    return p_idle(supply) - I_Q_4651 * supply


def filter_f0(l_out, c_out):
    """Bridge output filter corner, Output Stage Filtering: f_C = 1 / (2 pi sqrt(2 L C_BYP)).

    Parameters
    ----------
    l_out : float
        Inductance of each of the two filter coils, H.
    c_out : float
        Filter capacitor C_BYP across the load, F.

    Returns
    -------
    float
        The corner frequency, Hz.
    """
    return 1 / (2 * math.pi * (2 * l_out * c_out) ** 0.5)


def filter_q(l_out, c_out, r_load):
    """Q of the bridge filter loaded by R_L: 2 L in series, C_BYP across the load, Q = R_L sqrt(C / 2L).

    Parameters
    ----------
    l_out : float
        Inductance of each of the two filter coils, H.
    c_out : float
        Filter capacitor C_BYP across the load, F.
    r_load : float
        Load resistance, ohm.

    Returns
    -------
    float
        Q, a pure number.
    """
    return r_load * (c_out / (2 * l_out)) ** 0.5


def filter_gain2(f, l_out, c_out, r_load):
    """|H(j 2 pi f)|^2 of H = 1 / (1 + s 2L/R_L + s^2 2 L C) (the load is a resistor: an assumption).

    Parameters
    ----------
    f : float
        Frequency, Hz.
    l_out : float
        Inductance of each of the two filter coils, H.
    c_out : float
        Filter capacitor C_BYP across the load, F.
    r_load : float
        Load resistance, ohm.

    Returns
    -------
    float
        |H|^2, a pure number.
    """
    x = f / filter_f0(l_out, c_out)
    return 1 / ((1 - x * x) ** 2 + (x / filter_q(l_out, c_out, r_load)) ** 2)


def ripple_rms(f_sw, l_out, c_out, r_load, supply):
    """Switching residue at the load, rms: the fundamental of the idle bridge output (a +-2 V_s square wave
    at 50 % duty: amplitude 8 V_s / pi, its largest at any duty) through the filter. Harmonics ignored.

    Parameters
    ----------
    f_sw : float
        Switching frequency, Hz.
    l_out : float
        Inductance of each of the two filter coils, H.
    c_out : float
        Filter capacitor C_BYP across the load, F.
    r_load : float
        Load resistance, ohm.
    supply : float
        Rail voltage V_s of the +-V_s supply, V.

    Returns
    -------
    float
        The residue at the load, rms, V.
    """
    return 8 * supply / math.pi / 2 ** 0.5 * filter_gain2(f_sw, l_out, c_out, r_load) ** 0.5


def thd_n_joint(f_sw, l_out, c_out, p_test, r_load, supply):
    """THD+N at p_test: 0.3 % at 10 W, 4 ohm, +-20 V, 125 kHz with 50 uH / 5 uF (system table; Output Stage
    Filtering), scaled as a fixed error voltage (so as 1 / V_rms: sqrt(40 W ohm / (P R_L))) that is the
    switching residue through the second-order filter ((f_C / f_sw)^2, i.e. 1 / (f_sw^2 L C)) and grows
    with the rails (the datasheet's note on noise and supply). The exponent 2 is assumed.

    Parameters
    ----------
    f_sw : float
        Switching frequency, Hz.
    l_out : float
        Inductance of each of the two filter coils, H.
    c_out : float
        Filter capacitor C_BYP across the load, F.
    p_test : float
        Output power of the test signal, W.
    r_load : float
        Load resistance, ohm.
    supply : float
        Rail voltage V_s of the +-V_s supply, V.

    Returns
    -------
    float
        THD+N, a fraction.
    """
    return (THD_REF * (F_REF / f_sw) ** 2 * (L_REF * C_REF / (l_out * c_out)) * supply / SUPPLY_REF
            * (10.0 * 4.0 / (p_test * r_load)) ** 0.5)


def inductor_peak(f_sw, l_out, c_out, v_peak, r_load, supply, f_audio):
    """Peak inductor current (upper bound): the audio current at the peak output voltage (load and C_BYP at
    the top of the band) plus half the largest ripple, V_s / (4 L f_sw) at zero output (the bridge's
    ripple 2 V_s D (1 - D) / (L f_sw) peaks at D = 1/2).

    Parameters
    ----------
    f_sw : float
        Switching frequency, Hz.
    l_out : float
        Inductance of each of the two filter coils, H.
    c_out : float
        Filter capacitor C_BYP across the load, F.
    v_peak : float
        Peak output voltage, V.
    r_load : float
        Load resistance, ohm.
    supply : float
        Rail voltage V_s of the +-V_s supply, V.
    f_audio : float
        Top of the audio band, Hz.

    Returns
    -------
    float
        The peak coil current, A.
    """
    i_audio = v_peak * (1 / r_load ** 2 + (2 * math.pi * f_audio * c_out) ** 2) ** 0.5
    return i_audio + supply / (4 * l_out * f_sw)


def v_clip_peak(f_sw, r_load=4.0, supply=20.0):
    """Peak output voltage at the clipping point of :func:`p_clip` (the same calibrated model).

    Parameters
    ----------
    f_sw : float
        Switching frequency, Hz.
    r_load : float
        Load resistance, ohm.
    supply : float
        Rail voltage V_s of the +-V_s supply, V.

    Returns
    -------
    float
        The peak output voltage at clipping, V.
    """
    return (2 * r_load * p_clip(f_sw, r_load, supply)) ** 0.5


def coil_loss(p_out, r_load, l_out, dcr_per_henry):
    """Loss in the two filter coils: I_rms^2 x 2 DCR, with DCR proportional to L (one coil family; an
    assumption, the datasheet gives no DCR but warns the coils' loss can be significant).

    Parameters
    ----------
    p_out : float
        Output power, W.
    r_load : float
        Load resistance, ohm.
    l_out : float
        Inductance of each of the two filter coils, H.
    dcr_per_henry : float
        A coil's DC resistance per henry of inductance, ohm/H.

    Returns
    -------
    float
        The loss in both coils, W.
    """
    return p_out / r_load * 2 * dcr_per_henry * l_out


# --- what the THD+N analyser sees, and the package alone ------------------------------------------
#: the system table's THD+N (0.3 % at 10 W) is measured in 10 Hz <= BW <= 80 kHz; its 125 kHz calibration
#: point lies outside that band, so the switching residue is not in the 0.3 %
THD_BANDWIDTH = 80e3
#: LM4652 junction to ambient with no heat sink (thermal table): TO-220 'TF' 43 K/W, 'T' 37 K/W
THETA_JA = {"TF": 43.0, "T": 37.0}


def residue_fraction(f_sw, l_out, c_out, p_test, r_load, supply):
    """The switching residue at the load (:func:`ripple_rms`: the idle bridge's fundamental, an upper bound
    at any duty) as a fraction of the test signal's rms, sqrt(P R_L): 0.19 V in 6.32 V is 3 %.

    Parameters
    ----------
    f_sw : float
        Switching frequency, Hz.
    l_out : float
        Inductance of each of the two filter coils, H.
    c_out : float
        Filter capacitor C_BYP across the load, F.
    p_test : float
        Output power of the test signal, W.
    r_load : float
        Load resistance, ohm.
    supply : float
        Rail voltage V_s of the +-V_s supply, V.

    Returns
    -------
    float
        The residue, a fraction.
    """
    return ripple_rms(f_sw, l_out, c_out, r_load, supply) / (p_test * r_load) ** 0.5


def thd_n_measured(f_sw, l_out, c_out, p_test, r_load, supply, bandwidth=THD_BANDWIDTH):
    """THD+N as the analyser reads it: :func:`thd_n_joint` (the distortion, calibrated out of band) and, when
    the switching fundamental lies inside the measurement band (f_sw < bandwidth; a brick-wall filter
    assumed), the residue of :func:`residue_fraction`, root-sum-square (uncorrelated). Only the fundamental
    is counted: the square wave's next component, 3 f_sw, is at or above 150 kHz (f_sw >= 50 kHz), so
    bandwidths up to 150 kHz are covered. ``f_sw < bandwidth`` is 0 or 1 for floats, numpy and casadi.

    Parameters
    ----------
    f_sw : float
        Switching frequency, Hz.
    l_out : float
        Inductance of each of the two filter coils, H.
    c_out : float
        Filter capacitor C_BYP across the load, F.
    p_test : float
        Output power of the test signal, W.
    r_load : float
        Load resistance, ohm.
    supply : float
        Rail voltage V_s of the +-V_s supply, V.
    bandwidth : float
        Upper edge of the analyser's measurement band, Hz.

    Returns
    -------
    float
        THD+N as measured, a fraction.
    """
    distortion = thd_n_joint(f_sw, l_out, c_out, p_test, r_load, supply)
    residue = residue_fraction(f_sw, l_out, c_out, p_test, r_load, supply)
    return (distortion ** 2 + (f_sw < bandwidth) * residue ** 2) ** 0.5


def filter_worst_peak_l(f, c_out, r_load):
    """The L that maximises |H(j 2 pi f)| at fixed C_BYP: |H|^-2 = (1 - a C L)^2 + (b L)^2 with a = 2 w^2,
    b = 2 w / R_L (w = 2 pi f) is a convex parabola in L, least at L* = a C / (a^2 C^2 + b^2).

    Parameters
    ----------
    f : float
        Frequency, Hz.
    c_out : float
        Filter capacitor C_BYP across the load, F.
    r_load : float
        Load resistance, ohm.

    Returns
    -------
    float
        L*, H.
    """
    w = 2 * math.pi * f
    a, b = 2 * w * w, 2 * w / r_load
    return a * c_out / (a * a * c_out * c_out + b * b)
