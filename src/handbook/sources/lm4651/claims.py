"""Every number the LM4651/LM4652 datasheet prints in its tables, equations and Example Design, recomputed."""
from __future__ import annotations

import math

from ...core import Claim, Printed
from .circuit import (
    EPS0_PF_PER_IN,
    dead_time,
    f_sw_for,
    gain,
    i_sckt,
    p_conduction,
    p_switch,
    r_osc_for,
    switching_loss_fraction,
    theta_sa_required,
)
from .data import NAME

OSC, EX, TH = "oscillator", "example", "thermal"

# printed numbers the Example Design goes on to use
VOUT = Printed("22.4", "V")  # output voltage for 125 W into 4 ohm
GAIN = Printed("7.5", "1")  # closed-loop gain
R2_RATIO = Printed("0.7", "1")  # R2 / R1
P_TOTAL = Printed("21", "W")  # LM4652 dissipation, used in eq 11
P_SYSTEM = Printed("22", "W")  # LM4652 + LM4651, used for the efficiency
R1_OFFSET, C_IN_OFFSET = 25e3, 1e-6  # the DC-offset section's R1 ("the other side of 25k, R1") and its 1 uF


def _times(p):
    """The Example Design's edge and over-modulation times (its own 350 ns, not the table's 310 ns)."""
    return {"t_rise": p["t_rise"], "t_fall": p["t_fall"], "t_overmod": p["t_overmod_example"]}


def _loss_fraction(p):
    return switching_loss_fraction(p["f_sw"], **_times(p))


def _p_switch(p):
    return p_switch(p["f_sw"], p["p_out"], **_times(p))


def _p_conduction(p):
    return p_conduction(p["p_out"], p["r_load"], p["rds_on_hot"])


def _p_4652(p):
    return _p_switch(p) + _p_conduction(p)


def _theta_sa(p, package, p_d):
    return theta_sa_required(p_d, p["t_ambient"], package, p["theta_cs"], p["tj_max"])


def _v_out(p):
    return (p["p_out"] * p["r_load"]) ** 0.5


def _p_system_at(p, p_out, f_sw):
    """The datasheet's own loss method (eq 9, eq 10, conduction, about 1 W in the LM4651) at another operating
    point of its system table (4 ohm, as the table), with the Example's times and R_DS(on)."""
    return p_switch(f_sw, p_out, **_times(p)) + p_conduction(p_out, 4.0, p["rds_on_hot"]) + p["p_driver"]


#: the system table's total quiescent current: two values whose conditions did not survive the OCR (237 and
#: 124 mA); the smaller is used
I_CQ_SYSTEM = 124e-3


def build() -> list[Claim]:
    """Every LM4651/LM4652 claim: oscillator, Example Design and thermal numbers.

    Returns
    -------
    list of Claim
        The claims, in the datasheet's order.
    """
    return [
        Claim(id="lm4651-f-4k", where=f"{NAME} table, R_OSC = 4 k",
              quantity="switching frequency at R_OSC = 4 k (eq 5)",
              printed=Printed("125", "kHz"), compute=lambda p: f_sw_for(4e3), reason="1e9 / 8000 = 125 kHz",
              chapter=OSC),
        Claim(id="lm4651-f-15k", where=f"{NAME} table, R_OSC = 15 k", quantity="switching frequency at R_OSC = 15 k",
              printed=Printed("65", "kHz"), compute=lambda p: f_sw_for(15e3),
              reason="eq 5 gives 1e9 / 19000 = 52.6 kHz; eq 5, the table and the pin 16 text are three different "
                     "relations between R_OSC and f_sw (200 / 250 / 225 kHz at 0, 65 kHz at 15 k, 75 kHz at 15.5 k)",
              basis="eq 5", chapter=OSC,
              consequence="eq 5 and the table disagree by 20 % at low frequencies and 25 % at the top: measure f_sw on "
                          "the board, and stay below 200 kHz unless it is measured"),
        Claim(id="lm4651-f-0", where=f"{NAME} table, R_OSC = 0", quantity="switching frequency at R_OSC = 0",
              printed=Printed("200", "kHz", sig=3), compute=lambda p: f_sw_for(0.0),
              reason="eq 5 gives 1e9 / 4000 = 250 kHz, above the 225 kHz limit", basis="eq 5", chapter=OSC,
              same_fact="lm4651-f-15k",
              consequence="eq 5 overstates the top of the range; stay below 225 kHz"),
        Claim(id="lm4651-f-pin-15k5", where=f"{NAME} pin 16 (OSC) description",
              quantity="switching frequency at R_OSC = 15.5 k ('from 75kHz')", printed=Printed("75", "kHz"),
              compute=lambda p: f_sw_for(15.5e3), basis="eq 5", chapter=OSC, same_fact="lm4651-f-15k",
              reason="eq 5 gives 1e9 / 19500 = 51.3 kHz; the LM4651 table gives 65 kHz at the smaller 15 k, so 75 kHz "
                     "at 15.5 k contradicts the table as well",
              consequence="the pin description overstates the bottom of the range by 46 % against eq 5; design with "
                          "eq 5 and its table spread (-20 %/+23.5 %), not with the pin description"),
        Claim(id="lm4651-f-pin-0", where=f"{NAME} pin 16 (OSC) description",
              quantity="switching frequency at R_OSC = 0 ('to 225kHz')", printed=Printed("225", "kHz"),
              compute=lambda p: f_sw_for(0.0), basis="eq 5", chapter=OSC, same_fact="lm4651-f-15k",
              reason="eq 5 gives 1e9 / 4000 = 250 kHz; the LM4651 table gives 200 kHz at R_OSC = 0",
              consequence="three tops for one resistor (200, 225, 250 kHz): above 200 kHz measure f_sw on the board"),
        Claim(id="lm4651-dead-time", where=f"{NAME} table T_dead and eq 4", quantity="dead time at R_DLY = 0",
              printed=Printed("27", "ns"), compute=lambda p: dead_time(0.0),
              reason="eq 4 gives 1.7e-12 x 500 = 0.85 ns at R_DLY = 0", basis="eq 4", chapter=OSC,
              consequence="eq 4 cannot be used as printed (its constant is probably off by a factor of about 30); "
                          "take the dead time from measurement"),
        Claim(id="lm4651-rosc", where=f"{NAME} Example Design", quantity="R_OSC for 125 kHz with R_DLY = 5 k",
              printed=Printed("3.9", "kohm"), compute=lambda p: r_osc_for(p["f_sw"], p["r_dly"]),
              reason="eq 6 gives 4.0 k for R_DLY = 0, and the same datasheet says R_OSC must rise by about 2 k for "
                     "R_DLY = 5 k: 6.0 k. The LM4651 table's own row 'R_OSC = 4k, f_SW = 125kHz' (figure 1's circuit, "
                     "R_DLY not stated) supports the printed 3.9 k instead, so two statements of the datasheet disagree",
              basis="the datasheet's +2 k rule for R_DLY = 5 k", chapter=OSC,
              consequence="which one holds decides the frequency: if the +2 k rule does, 3.9 k runs at 169.5 kHz and, "
                          "by the Example's own loss method, the LM4652 dissipates 23.5 W instead of 21.0 W, with the "
                          "junction near 160 C on the example's heat sink; if the table row does, 3.9 k is right. "
                          "Measure f_sw on the board before sizing the heat sink"),
        Claim(id="lm4651-hp-corner", where=f"{NAME} DC offset", quantity="input high-pass corner, R1 = 25 k and 1 uF",
              printed=Printed("6.35", "Hz"), compute=lambda p: 1 / (2 * math.pi * R1_OFFSET * C_IN_OFFSET),
              reason="1 / (2 pi x 25 k x 1 uF) = 6.366 Hz: rounded 6.37, truncated 6.36; 6.35 is neither "
                     "(0.25 % low)", chapter=EX,
              consequence="negligible by itself (0.25 %); the 25 k beside it matches neither of the Example "
                          "Design's R1 values (see lm4651-t-r1)"),
        Claim(id="lm4651-isckt", where=f"{NAME} Example Design", quantity="current limit with R_SCKT = 100 k",
              printed=Printed("10", "A", sig=2), compute=lambda p: i_sckt(p["r_sckt"]),
              reason="1e5 / (10 k || 100 k) = 1e5 / 9.09 k = 11 A", chapter=EX,
              consequence="the limit is 11 A, not 10 A; 10 A is the limit with no R_SCKT at all"),
        Claim(id="lm4651-cstart", where=f"{NAME} Example Design, eq (2)", quantity="C_START for 1 s",
              printed=Printed("11.7", "uF"), compute=lambda p: p["t_start"] / 8.5e4,
              reason="1 / 8.5e4 = 11.76 uF, truncated to 11.7 instead of rounded to 11.8 (eq 1's 8.4e4 would give "
                     "11.9 uF); the 10 uF fitted starts in 0.84 s", chapter=EX, truncated=True),
        Claim(id="lm4651-vout-rms", where=f"{NAME} Example Design", quantity="output voltage for 125 W into 4 ohm",
              printed=VOUT, compute=_v_out, reason="sqrt(125 x 4) = 22.36 V", chapter=EX),
        Claim(id="lm4651-gain", where=f"{NAME} Example Design", quantity="closed-loop gain 22.4 / 3", printed=GAIN,
              compute=lambda p: _v_out(p) / p["v_in_rms"], reason="22.36 / 3 = 7.45",
              via_rounded=lambda p: VOUT.si / p["v_in_rms"], chapter=EX),
        Claim(id="lm4651-gain-db", where=f"{NAME} Example Design", quantity="closed-loop gain in dB",
              printed=Printed("17.5", "1"), compute=lambda p: 20 * math.log10(_v_out(p) / p["v_in_rms"]),
              reason="20 log10(7.454) = 17.45 dB; from the rounded 7.5, 17.50 dB",
              via_rounded=lambda p: 20 * math.log10(GAIN.si), chapter=EX),
        Claim(id="lm4651-r2-ratio", where=f"{NAME} Example Design, eq (12)", quantity="R2 / R1 for a gain of 7.5",
              printed=R2_RATIO, compute=lambda p: (GAIN.si - 0.5) / ((p["rf11"] + p["rf12"]) / p["rf12"] - 1),
              reason="(7.5 - 0.5) / (682 k / 62 k - 1) = 0.7", chapter=EX),
        Claim(id="lm4651-r2", where=f"{NAME} Example Design", quantity="R2 with R1 = 20 k",
              printed=Printed("14", "kohm"), compute=lambda p: R2_RATIO.si * p["r1"], reason="0.7 x 20 k",
              chapter=EX),
        Claim(id="lm4651-overmod", where=f"{NAME} Example Design vs LM4651 table",
              quantity="over-modulation time used in eq 9", printed=Printed("350", "ns"),
              compute=lambda p: p["t_overmod_table"], reason="the LM4651 table gives 310 ns typical",
              basis="LM4651 table", chapter=TH,
              consequence="the example's switching loss is 0.7 W (11 %) higher than the table's typical gives: "
                          "conservative"),
        Claim(id="lm4651-loss-pct", where=f"{NAME} Example Design, eq (9)", quantity="switching loss fraction",
              printed=Printed("5.0", "%"), compute=_loss_fraction, reason="(25 + 26 + 350) ns x 125 kHz = 5.01 %",
              chapter=TH),
        Claim(id="lm4651-p-switch", where=f"{NAME} Example Design, eq (10)", quantity="switching dissipation",
              printed=Printed("6.6", "W"), compute=_p_switch, reason="5.01 % x 125 W / 0.95 = 6.60 W", chapter=TH),
        Claim(id="lm4651-i-rms", where=f"{NAME} Example Design", quantity="RMS output current",
              printed=Printed("5.59", "A"), compute=lambda p: (p["p_out"] / p["r_load"]) ** 0.5,
              reason="sqrt(125 / 4) = 5.590 A", chapter=TH),
        Claim(id="lm4651-p-rds", where=f"{NAME} Example Design", quantity="conduction dissipation",
              printed=Printed("14.4", "W"), compute=_p_conduction, reason="31.25 A^2 x 0.46 ohm = 14.38 W",
              chapter=TH),
        Claim(id="lm4651-p-total", where=f"{NAME} Example Design", quantity="LM4652 dissipation", printed=P_TOTAL,
              compute=_p_4652, reason="6.60 + 14.38 = 20.97 W", chapter=TH),
        Claim(id="lm4651-theta-tf", where=f"{NAME} Example Design, eq (11)", quantity="heat sink for the TF package",
              printed=Printed("2.5", "K/W"), compute=lambda p: _theta_sa(p, "TF", _p_4652(p)),
              via_rounded=lambda p: _theta_sa(p, "TF", P_TOTAL.si),
              reason="100 / 20.97 - 2 - 0.2 = 2.57 K/W (2.56 with the example's rounded 21 W), rounded down",
              chapter=TH,
              consequence="conservative: the heat sink asked for is 2 % better than needed", safe_side="below"),
        Claim(id="lm4651-theta-t", where=f"{NAME} Example Design, eq (11)", quantity="heat sink for the T package",
              printed=Printed("3.5", "K/W"), compute=lambda p: _theta_sa(p, "T", _p_4652(p)),
              via_rounded=lambda p: _theta_sa(p, "T", P_TOTAL.si),
              reason="100 / 20.97 - 1 - 0.2 = 3.57 K/W (3.56 with the example's rounded 21 W), rounded down",
              chapter=TH,
              consequence="conservative, as for the TF package", safe_side="below"),
        Claim(id="lm4651-efficiency", where=f"{NAME} system table", quantity="efficiency at 125 W with 22 W dissipated",
              printed=Printed("85", "%"), compute=lambda p: p["p_out"] / (p["p_out"] + P_SYSTEM.si),
              reason="125 / (125 + 22) = 85.0 %", chapter=TH),
        Claim(id="lm4651-system-pd", where=f"{NAME} system table", quantity="system dissipation: LM4652 + LM4651",
              printed=P_SYSTEM, compute=lambda p: _p_4652(p) + p["p_driver"],
              reason="20.97 W + about 1 W in the LM4651", chapter=TH),
        Claim(id="lm4651-eta-5w", where=f"{NAME} system table, efficiency at P_O = 5 W vs I_CQ",
              quantity="efficiency at 5 W if the quiescent current still flows (upper bound)",
              printed=Printed("55", "%"), relation="<=",
              compute=lambda p: 5.0 / (5.0 + I_CQ_SYSTEM * 20.0),  # |I_VCC+| + |I_VEE-| from +-20 V rails
              basis="system table, I_CQ", chapter=TH,
              reason="the datasheet defines the total quiescent current as |I_VCC+| + |I_VEE-| (LM4651 table), so "
                     "124 mA (the smaller of the row's two values) from +-20 V rails costs 20 V x 124 mA = 2.48 W: "
                     "at 5 W out the efficiency is at most 5 / 7.48 = 66.8 %, and the printed 55 % is below it (the row's other "
                     "value, 237 mA, whose conditions the OCR lost, would bound it at 51 %)"),
        Claim(id="lm4651-l1-rating", where=f"{NAME} recommended components, L1 (CoilCraft PCV-0-473-05, 47 uH, 5 A)",
              quantity="current rating of the recommended 47 uH choke against the Example's rms current",
              printed=Printed("5", "A"), relation=">=", compute=lambda p: (p["p_out"] / p["r_load"]) ** 0.5,
              basis="Example Design's output current", chapter=TH,
              reason="125 W into 4 ohm is 5.59 A rms (7.91 A peak); the CoilCraft choke is rated 5 A, the J.W. Miller "
                     "50 uH 5.6 A (0.2 % above the rms current) and 68 uH 7.3 A",
              consequence="at full continuous power the 5 A choke carries 25 % more I^2 than its rating; if the "
                          "ratings are saturation currents, all three lie below the 7.9 A peak: choose L1 for the "
                          "peak of the output current plus half the ripple"),
        Claim(id="lm4651-eps0", where=f"{NAME} eq (8)", quantity="vacuum permittivity in pF/in",
              printed=Printed("0.22479", "1"), compute=lambda p: EPS0_PF_PER_IN,
              reason="a misprinted constant: 8.8542e-12 F/m (CODATA) x 0.0254 m/in = 0.22490 pF/in", chapter=OSC,
              consequence="negligible (0.05 %)"),
        Claim(id="lm4651-gain-4k7", where=f"{NAME} Example Design",
              quantity="gain with R1 = 4.7 k, R2 = 3.5 k (figure 1 values)", printed=GAIN,
              compute=lambda p: gain(4.7e3, 3.5e3, p["rf11"], p["rf12"]),
              reason="eq 12: 10 x 3.5/4.7 + 0.5 = 7.95; 7.5 needs R2 = 3.29 k with R1 = 4.7 k", chapter=EX,
              consequence="the figure 1 values give 6 % more gain (0.5 dB) than stated: clipping comes at a 6 % "
                          "lower input"),
        Claim(id="lm4651-rf-ratio", where=f"{NAME} Example Design", quantity="Rf11 / Rf12", printed=Printed("10", "1"),
              compute=lambda p: p["rf11"] / p["rf12"], reason="620 k / 62 k", chapter=EX),
    ]
