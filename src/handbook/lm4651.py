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


# ============================================================================================
# registry: the datasheet's equations and its "Example Design", number by number

import functools  # noqa: E402

from .examples import Example, Printed, TextErratum, evaluate_all  # noqa: E402

NOTE = "LM4651/LM4652"
EPS0_PF_PER_IN = 8.8541878128e-12 * 0.0254 * 1e12  # vacuum permittivity in pF/in (CODATA)

DEFAULTS: dict = {
    "p_out": 125.0, "r_load": 4.0, "t_rise": 25e-9, "t_fall": 26e-9, "t_overmod_example": 350e-9,
    "t_overmod_table": 310e-9, "rds_on_hot": 0.230, "t_ambient": 50.0, "theta_cs": 0.2, "tj_max": 150.0,
    "p_driver": 1.0, "f_sw": 125e3, "r_dly": 5e3, "r_sckt": 100e3, "t_start": 1.0, "v_in_rms": 3.0,
    "rf11": 620e3, "rf12": 62e3, "r1": 20e3, "c_start": 10e-6,
}


def dead_time(r_dly):
    """Eq 4: T_DLY = 1.7e-12 (500 + R_DLY) seconds."""
    return 1.7e-12 * (500 + r_dly)


def i_sckt(r_sckt):
    """Eq 3: I = 1e5 / (10 k || R_SCKT) amperes."""
    return 1e5 / (1e4 * r_sckt / (1e4 + r_sckt))


def gain(r1, r2, rf11, rf12):
    """Eq 12 (reconstructed): (R2/R1) (Rf11 + Rf12)/Rf12 - R2/R1 + 0.5."""
    return r2 / r1 * (rf11 + rf12) / rf12 - r2 / r1 + 0.5


def _ex(p):  # the example's dissipation, with its own 350 ns
    x = (p["t_rise"] + p["t_fall"] + p["t_overmod_example"]) * p["f_sw"]
    p_sw = x * p["p_out"] / (1 - x)
    p_c = p["p_out"] / p["r_load"] * 2 * p["rds_on_hot"]
    return x, p_sw, p_c


def examples_list() -> list[Example]:
    OSC, EX, TH = "oscillator", "example", "thermal"
    dl = ("t_rise", "t_fall", "t_overmod_example", "f_sw", "p_out", "r_load", "rds_on_hot")
    return [
        Example("lm4651-f-4k", f"{NOTE} table, R_OSC = 4 k", "switching frequency at R_OSC = 4 k (eq 5)",
                Printed("125", "kHz"), lambda p: f_sw_for(4e3), "1e9 / 8000 = 125 kHz", (), chapter=OSC),
        Example("lm4651-f-15k", f"{NOTE} table, R_OSC = 15 k", "switching frequency at R_OSC = 15 k",
                Printed("65", "kHz"), lambda p: f_sw_for(15e3), "eq 5 gives 1e9 / 19000 = 52.6 kHz", (),
                basis="eq 5", chapter=OSC,
                consequence="eq 5 and the table disagree by 20 % at low frequencies: measure f_sw on the board"),
        Example("lm4651-f-0", f"{NOTE} table, R_OSC = 0", "switching frequency at R_OSC = 0", Printed("200", "kHz", sig=3),
                lambda p: f_sw_for(0.0), "eq 5 gives 1e9 / 4000 = 250 kHz, above the 225 kHz limit", (),
                basis="eq 5", chapter=OSC, consequence="eq 5 overstates the top of the range; stay below 225 kHz"),
        Example("lm4651-dead-time", f"{NOTE} table T_dead and eq 4", "dead time at R_DLY = 0", Printed("27", "ns"),
                lambda p: dead_time(0.0), "eq 4 gives 1.7e-12 x 500 = 0.85 ns at R_DLY = 0", (), basis="eq 4",
                chapter=OSC, consequence="eq 4 cannot be used as printed (its constant is probably off by a factor "
                                         "of about 30); take the dead time from measurement"),
        Example("lm4651-rosc", f"{NOTE} Example Design", "R_OSC for 125 kHz with R_DLY = 5 k", Printed("3.9", "kohm"),
                lambda p: r_osc_for(p["f_sw"], p["r_dly"]),
                "eq 6 gives 4.0 k for R_DLY = 0, and the text adds about 2 k for R_DLY = 5 k: 6.0 k", ("f_sw", "r_dly"),
                chapter=OSC, consequence="with R_DLY = 5 k, 3.9 k runs at about 170 kHz by eq 5 and the stated "
                                         "correction: about 2 % more switching loss than designed"),
        Example("lm4651-isckt", f"{NOTE} Example Design", "current limit with R_SCKT = 100 k", Printed("10", "A", sig=2),
                lambda p: i_sckt(p["r_sckt"]), "1e5 / (10 k || 100 k) = 1e5 / 9.09 k = 11 A", ("r_sckt",),
                chapter=EX, consequence="the limit is 11 A, not 10 A; 10 A is the limit with no R_SCKT at all"),
        Example("lm4651-cstart", f"{NOTE} Example Design, eq (2)", "C_START for 1 s", Printed("11.7", "uF"),
                lambda p: p["t_start"] / 8.5e4, "1 / 8.5e4 = 11.76 uF (eq 1's 8.4e4 would give 11.9 uF)",
                ("t_start",), chapter=EX, consequence="none: 11.76 truncated to 11.7; the 10 uF fitted starts in 0.84 s"),
        Example("lm4651-vout-rms", f"{NOTE} Example Design", "output voltage for 125 W into 4 ohm", Printed("22.4", "V"),
                lambda p: (p["p_out"] * p["r_load"]) ** 0.5, "sqrt(125 x 4) = 22.36 V", ("p_out", "r_load"), chapter=EX),
        Example("lm4651-gain", f"{NOTE} Example Design", "closed-loop gain 22.4 / 3", Printed("7.5", "1"),
                lambda p: (p["p_out"] * p["r_load"]) ** 0.5 / p["v_in_rms"], "22.36 / 3 = 7.45",
                ("p_out", "r_load", "v_in_rms"), via_rounded=lambda p: 22.4 / p["v_in_rms"], chapter=EX),
        Example("lm4651-gain-db", f"{NOTE} Example Design", "closed-loop gain in dB", Printed("17.5", "1"),
                lambda p: 20 * math.log10((p["p_out"] * p["r_load"]) ** 0.5 / p["v_in_rms"]),
                "20 log10(7.454) = 17.45 dB; from the rounded 7.5, 17.50 dB",
                ("p_out", "r_load", "v_in_rms"), via_rounded=lambda p: 20 * math.log10(7.5), chapter=EX),
        Example("lm4651-r2-ratio", f"{NOTE} Example Design, eq (12)", "R2 / R1 for a gain of 7.5", Printed("0.7", "1"),
                lambda p: (7.5 - 0.5) / ((p["rf11"] + p["rf12"]) / p["rf12"] - 1), "(7.5 - 0.5) / (682 k / 62 k - 1) = 0.7",
                ("rf11", "rf12"), chapter=EX),
        Example("lm4651-r2", f"{NOTE} Example Design", "R2 with R1 = 20 k", Printed("14", "kohm"),
                lambda p: 0.7 * p["r1"], "0.7 x 20 k", ("r1",), chapter=EX),
        Example("lm4651-overmod", f"{NOTE} Example Design vs LM4651 table", "over-modulation time used in eq 9",
                Printed("350", "ns"), lambda p: p["t_overmod_table"], "the LM4651 table gives 310 ns typical",
                (), basis="LM4651 table", chapter=TH,
                consequence="the example's switching loss is 0.7 W (11 %) higher than the table's typical gives: "
                            "conservative"),
        Example("lm4651-loss-pct", f"{NOTE} Example Design, eq (9)", "switching loss fraction", Printed("5.0", "%"),
                lambda p: _ex(p)[0], "(25 + 26 + 350) ns x 125 kHz = 5.01 %", dl, chapter=TH),
        Example("lm4651-p-switch", f"{NOTE} Example Design, eq (10)", "switching dissipation", Printed("6.6", "W"),
                lambda p: _ex(p)[1], "5.01 % x 125 W / 0.95 = 6.60 W", dl, chapter=TH),
        Example("lm4651-i-rms", f"{NOTE} Example Design", "RMS output current", Printed("5.59", "A"),
                lambda p: (p["p_out"] / p["r_load"]) ** 0.5, "sqrt(125 / 4) = 5.590 A", ("p_out", "r_load"), chapter=TH),
        Example("lm4651-p-rds", f"{NOTE} Example Design", "conduction dissipation", Printed("14.4", "W"),
                lambda p: _ex(p)[2], "31.25 A^2 x 0.46 ohm = 14.38 W", dl, chapter=TH),
        Example("lm4651-p-total", f"{NOTE} Example Design", "LM4652 dissipation", Printed("21", "W"),
                lambda p: _ex(p)[1] + _ex(p)[2], "6.60 + 14.38 = 20.97 W", dl, chapter=TH),
        Example("lm4651-theta-tf", f"{NOTE} Example Design, eq (11)", "heat sink for the TF package", Printed("2.5", "K/W"),
                lambda p: (p["tj_max"] - p["t_ambient"]) / 21.0 - DATASHEET["theta_jc"]["TF"] - p["theta_cs"],
                "100 / 21 - 2 - 0.2 = 2.56 K/W, rounded down", ("tj_max", "t_ambient", "theta_cs"), chapter=TH,
                consequence="conservative: the heat sink asked for is 2 % better than needed"),
        Example("lm4651-theta-t", f"{NOTE} Example Design, eq (11)", "heat sink for the T package", Printed("3.5", "K/W"),
                lambda p: (p["tj_max"] - p["t_ambient"]) / 21.0 - DATASHEET["theta_jc"]["T"] - p["theta_cs"],
                "100 / 21 - 1 - 0.2 = 3.56 K/W, rounded down", ("tj_max", "t_ambient", "theta_cs"), chapter=TH,
                consequence="conservative, as for the TF package"),
        Example("lm4651-efficiency", f"{NOTE} system table", "efficiency at 125 W with 22 W dissipated", Printed("85", "%"),
                lambda p: p["p_out"] / (p["p_out"] + 22.0), "125 / (125 + 22) = 85.0 %", ("p_out",), chapter=TH),
        Example("lm4651-system-pd", f"{NOTE} system table", "system dissipation: LM4652 + LM4651", Printed("22", "W"),
                lambda p: _ex(p)[1] + _ex(p)[2] + p["p_driver"], "20.97 W + about 1 W in the LM4651", dl + ("p_driver",),
                chapter=TH),
        Example("lm4651-eps0", f"{NOTE} eq (8)", "vacuum permittivity in pF/in", Printed("0.22479", "1"),
                lambda p: EPS0_PF_PER_IN, "8.8542e-12 F/m x 0.0254 m/in = 0.22490 pF/in", (), basis="CODATA",
                chapter=OSC, consequence="negligible (0.05 %)"),
        Example("lm4651-gain-4k7", f"{NOTE} Example Design", "gain with R1 = 4.7 k, R2 = 3.5 k (figure 1 values)",
                Printed("7.5", "1"), lambda p: gain(4.7e3, 3.5e3, p["rf11"], p["rf12"]),
                "eq 12: 10 x 3.5/4.7 + 0.5 = 7.95; 7.5 needs R2 = 3.29 k with R1 = 4.7 k", ("rf11", "rf12"), chapter=EX,
                consequence="the figure 1 values give 6 % more gain (0.5 dB) than stated: clipping comes at a 6 % "
                            "lower input"),
        Example("lm4651-rf-ratio", f"{NOTE} Example Design", "Rf11 / Rf12", Printed("10", "1"),
                lambda p: p["rf11"] / p["rf12"], "620 k / 62 k", ("rf11", "rf12"), chapter=EX),
    ]


def examples(p: dict | None = None, chapter: str | None = None) -> list[dict]:
    return evaluate_all(examples_list(), p, DEFAULTS, chapter)


def equations() -> list:
    return list(_equations())


@functools.lru_cache(maxsize=1)
def _equations() -> tuple:
    import sympy as sp
    from sympy.physics import units as u

    from .registry import Equation

    V, A, F, S, OHM, W, K = u.volt, u.ampere, u.farad, u.second, u.ohm, u.watt, u.kelvin
    t, C, R, Rint, Cint, f, T, x, P, Pout, RL, Rds, I = sp.symbols(
        r"t C R R_{int} C_{int} f T x P P_{out} R_L R_{DS(on)} I", positive=True)
    Rf, Cf, L1, Cb, Tj, Ta, Pd, tjc, tcs, tsa = sp.symbols(
        r"R_f C_f L_1 C_{BYP} T_{jmax} T_{a} P_D \theta_{JC} \theta_{CS} \theta_{SA}", positive=True)
    R1, R2, Rf11, Rf12 = sp.symbols("R_1 R_2 R_{f11} R_{f12}", positive=True)
    tr, tf, tom, Cs, Rp, epsr, Ar, d = sp.symbols(r"t_r t_f T_{OVERMOD} C_{START} R_{SCKT} \epsilon_r A d", positive=True)
    n = {s: sp.Symbol(s.name + "_n", positive=True) for s in (Cs, t, Rp, R, f, x)}
    w = sp.Symbol("omega", positive=True)
    in_ = u.inch
    eqs = [
        Equation(id="lm4651-eq1", source=f"{NOTE}, eq (1)", title="Start-up time", lhs=t, lhs_unit=S, lhs_scale=S,
                 printed=sp.Integer(84000) * n[Cs], scales={n[Cs]: Cs / F},
                 derived=sp.solve(sp.Eq(I * t, Cs * sp.Symbol("dV", positive=True)), t)[0].subs(
                     sp.Symbol("dV", positive=True), sp.Symbol("dV", positive=True)),
                 units={Cs: F, I: A, sp.Symbol("dV", positive=True): V},
                 values={I: A / 84000, sp.Symbol("dV", positive=True): V},
                 law="charge balance on C_START; the datasheet gives only dV / I = 84 k (taken as 1 V / 11.9 uA)",
                 note="The component table prints T_START = 8.5e4 C_START, eq 1 8.4e4."),
        Equation(id="lm4651-eq2", source=f"{NOTE}, eq (2)", title="C_START for a start-up time", lhs=Cs, lhs_unit=F,
                 lhs_scale=F, printed=n[t] / 85000, scales={n[t]: t / S}, derived=t * I / sp.Symbol("dV", positive=True),
                 units={t: S, I: A, sp.Symbol("dV", positive=True): V},
                 values={I: A / 84000, sp.Symbol("dV", positive=True): V},
                 law="eq 1 solved for C_START", note="eq 2 divides by 8.5e4 where eq 1 multiplies by 8.4e4 (1.2 % apart)."),
        Equation(id="lm4651-eq3", source=f"{NOTE}, eq (3)", title="Short-circuit current limit", lhs=I, lhs_unit=A,
                 lhs_scale=A, printed=10 ** 5 / (10 ** 4 * n[Rp] / (10 ** 4 + n[Rp])), scales={n[Rp]: Rp / OHM},
                 derived=sp.Symbol("V_k", positive=True) * (1 / Rint + 1 / Rp),
                 units={Rp: OHM, Rint: OHM, sp.Symbol("V_k", positive=True): V},
                 values={Rint: 10 ** 4 * OHM, sp.Symbol("V_k", positive=True): 10 ** 5 * V},
                 law="an internal 10 k in parallel with R_SCKT (conductances add) scales a fixed reference",
                 note="The 1e5 hides a unit of volts (an internal reference times a current gain)."),
        Equation(id="lm4651-eq4", source=f"{NOTE}, eq (4)", title="Dead time", lhs=T, lhs_unit=S, lhs_scale=S,
                 printed=sp.Rational(17, 10 ** 13) * (500 + n[R]), scales={n[R]: R / OHM}, derived=Cint * (Rint + R),
                 units={R: OHM, Rint: OHM, Cint: F}, values={Cint: sp.Rational(17, 10 ** 13) * F, Rint: 500 * OHM},
                 printed_tex=r"1.7 \times 10^{-12} (500 + R_{DLY})",
                 law="an RC delay: 1.7 pF charged through 500 ohm + R_DLY",
                 note="As printed it gives 0.85 ns at R_DLY = 0 against the table's 27 ns."),
        Equation(id="lm4651-eq5", source=f"{NOTE}, eq (5)", title="Switching frequency", lhs=f, lhs_unit=u.hertz,
                 lhs_scale=u.hertz, printed=10 ** 9 / (4000 + n[R]), scales={n[R]: R / OHM}, derived=1 / (Cint * (Rint + R)),
                 units={R: OHM, Rint: OHM, Cint: F}, values={Cint: F / 10 ** 9, Rint: 4000 * OHM},
                 law="an RC oscillator: period proportional to 1 nF x (4 k + R_OSC)"),
        Equation(id="lm4651-eq6", source=f"{NOTE}, eq (6)", title="R_OSC for a frequency", lhs=R, lhs_unit=OHM,
                 lhs_scale=OHM, printed=10 ** 9 / n[f] - 4000, scales={n[f]: f / u.hertz},
                 derived=sp.solve(sp.Eq(f, 1 / (Cint * (Rint + R))), R)[0], units={f: u.hertz, Rint: OHM, Cint: F},
                 values={Cint: F / 10 ** 9, Rint: 4000 * OHM}, law="eq 5 solved for R_OSC"),
        Equation(id="lm4651-eq7", source=f"{NOTE}, eq (7)", title="Error-amplifier pole", lhs=f, lhs_unit=u.hertz,
                 printed=1 / (2 * sp.pi * Rf * Cf),
                 derived=sp.solve(sp.Eq(w * Rf * Cf, 1), w)[0] / (2 * sp.pi), units={Rf: OHM, Cf: F},
                 law="the parallel R_f C_f: the pole where |1/(j omega C_f)| = R_f"),
        Equation(id="lm4651-eq8", source=f"{NOTE}, eq (8)", title="Plane capacitance, eps0 = 0.22479 pF/in",
                 lhs=C, lhs_unit=F, printed=sp.Rational("0.22479") * F / 10 ** 12 / in_ * epsr * Ar / d,
                 derived=u.vacuum_permittivity * epsr * Ar / d, units={Ar: in_ ** 2, d: in_},
                 law="parallel-plate capacitor", note="0.22479 pF/in is 0.05 % below eps0 = 0.22490 pF/in."),
        Equation(id="lm4651-eq9", source=f"{NOTE}, eq (9)", title="Switching loss fraction", lhs=x, lhs_unit=sp.Integer(1),
                 printed=(tr + tf + tom) * f, derived=(tr + tf + tom) / (1 / f), units={tr: S, tf: S, tom: S, f: u.hertz},
                 law="the fraction of each period spent in the edges and the over-modulation pulse"),
        Equation(id="lm4651-eq10", source=f"{NOTE}, eq (10)", title="Switching dissipation", lhs=P, lhs_unit=W,
                 printed=x * Pout / (1 - x), derived=sp.solve(sp.Eq(P, x * (Pout + P)), P)[0], units={Pout: W},
                 law="a fraction x of the input power P_out + P is lost"),
        Equation(id="lm4651-conduction", source=f"{NOTE}, Power Dissipation", title="Conduction dissipation", lhs=P,
                 lhs_unit=W, printed=(sp.sqrt(Pout / RL)) ** 2 * (2 * Rds), derived=2 * Rds * Pout / RL,
                 units={Pout: W, RL: OHM, Rds: OHM}, law="I_rms^2 through two on-resistances in series (the H-bridge)"),
        Equation(id="lm4651-eq11", source=f"{NOTE}, eq (11)", title="Heat sink thermal resistance", lhs=tsa,
                 lhs_unit=K / W, printed=(Tj - Ta) / Pd - tjc - tcs, derived=sp.solve(sp.Eq(Tj - Ta, Pd * (tjc + tcs + tsa)), tsa)[0],
                 units={Tj: K, Ta: K, Pd: W, tjc: K / W, tcs: K / W}, law="thermal Ohm's law through three series resistances"),
        Equation(id="lm4651-eq12", source=f"{NOTE}, eq (12) (reconstructed)", title="Closed-loop gain", lhs=sp.Symbol("G"),
                 lhs_unit=sp.Integer(1), printed=(R2 / R1) * ((Rf11 + Rf12) / Rf12) - R2 / R1 + sp.Rational(1, 2),
                 derived=R2 * Rf11 / (R1 * Rf12) + sp.Rational(1, 2), units={R1: OHM, R2: OHM, Rf11: OHM, Rf12: OHM},
                 law="algebra only: the internal feedback amplifier is not described well enough to derive it",
                 reconstructed="the OCR of the Example Design reads '[...] + .5].(3)'; the component table prints the same "
                               "formula without the '(3)', and it gives 10 R2/R1 + 0.5 = 7.5 for the printed R2 = 0.7 R1"),
        Equation(id="lm4651-fb-pole1", source=f"{NOTE}, components table, R_fl2", title="Feedback filter, first pole",
                 lhs=f, lhs_unit=u.hertz, printed=1 / (2 * sp.pi * Rf12 * sp.Symbol("C_{fl1}", positive=True)),
                 derived=sp.solve(sp.Eq(w * Rf12 * sp.Symbol("C_{fl1}", positive=True), 1), w)[0] / (2 * sp.pi),
                 units={Rf12: OHM, sp.Symbol("C_{fl1}", positive=True): F},
                 law="first-order RC low-pass: the corner where omega R C = 1",
                 note="The capacitor values of figure 1 did not survive the OCR; R_fl1 = 10 R_fl2 keeps R_fl1 from loading it."),
        Equation(id="lm4651-fb-pole2", source=f"{NOTE}, components table, R_fl3", title="Feedback filter, second pole",
                 lhs=f, lhs_unit=u.hertz,
                 printed=1 / (2 * sp.pi * sp.Symbol("R_{fl3}", positive=True) * sp.Symbol("C_{fl2}", positive=True)),
                 derived=sp.solve(sp.Eq(w * sp.Symbol("R_{fl3}", positive=True) * sp.Symbol("C_{fl2}", positive=True), 1),
                                  w)[0] / (2 * sp.pi),
                 units={sp.Symbol("R_{fl3}", positive=True): OHM, sp.Symbol("C_{fl2}", positive=True): F},
                 law="first-order RC low-pass", note="Should lie above the output filter's pole (datasheet text)."),
        Equation(id="lm4651-input-hp", source=f"{NOTE}, Example Design (implied; no formula printed)",
                 title="Input high-pass (C_IN with R1)", lhs=f, lhs_unit=u.hertz,
                 printed=1 / (2 * sp.pi * R1 * sp.Symbol("C_{IN}", positive=True)),
                 derived=sp.solve(sp.Eq(1 / (w * sp.Symbol("C_{IN}", positive=True)), R1), w)[0] / (2 * sp.pi),
                 units={R1: OHM, sp.Symbol("C_{IN}", positive=True): F},
                 law="series C_IN into the inverting input's R1: the corner where |1/(j omega C_IN)| = R1",
                 note="The text only says a lower R1 needs a larger C_IN; with R1 = 20 k a 10 Hz corner needs 0.8 uF."),
        Equation(id="lm4651-filter", source=f"{NOTE}, Output Stage Filtering (reconstructed)", title="Bridge output filter",
                 lhs=f, lhs_unit=u.hertz, printed=1 / (2 * sp.pi * sp.sqrt(L1 * 2 * Cb)),
                 derived=sp.solve(sp.Eq(w ** 2 * 2 * L1 * Cb, 1), w)[0] / (2 * sp.pi), units={L1: u.henry, Cb: F},
                 law="series resonance of the loop L1 - C_BYP - L1 (2 L1 with C_BYP)",
                 reconstructed="the OCR reads 'f_C = 1/[2 pi (L_1 2C_BYP)/_2]'; the text's 'extra factor of 2' and a square "
                               "root give this form"),
    ]
    for e in eqs:
        e.chapter = "lm4651"
    return tuple(eqs)


TEXT_ERRATA = [
    TextErratum("lm4651-t-50uf", f"{NOTE}, Output Stage Filtering", "'a 50 uF inductor'",
                "the Example Design and figure 1 use 50 uH inductors", "none once read as uH"),
    TextErratum("lm4651-t-rds", f"{NOTE}, Example Design", "R_DS(on) 'at 100 C' = 0.230 ohm is not in the table",
                "the LM4652 table gives 200 mOhm typical and 300 mOhm maximum at 25 C only",
                "0.230 ohm is optimistic against the 300 mOhm maximum: conduction loss may be 30 % higher"),
    TextErratum("lm4651-t-supply", f"{NOTE}, Example Design", "the supply (+-20 V) comes from a graph that did not survive",
                "the electrical tables are specified at +-20 V, 4 ohm, 125 kHz, consistent with the choice",
                "none"),
]
