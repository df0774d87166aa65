"""Every number the TDA5341 excerpt prints, and the TDA5144 datasheet's version, recomputed."""
from __future__ import annotations

from ...core import Claim, Printed, series
from ..an94002.circuit import oscillation_frequency
from .circuit import cap_cd_for, constant_k, max_delay
from .data import NAME, TDA5144

START, CD, CMP = "start", "commutation", "tda5144"


def _cap_st(p):
    return p["t_start"] / p["cap_st_constant"] * 1e-6


def _capcdm(p):
    return cap_cd_for(p["f_c1"], p["i_charge"], p["v_low"], p["v_high"])


def build() -> list[Claim]:
    """Every TDA5341 claim (start, CAPCDM) and the TDA5144 datasheet's version of the timer.

    Returns
    -------
    list of Claim
        The claims, in the excerpt's order.
    """
    return [
        Claim(id="tda5341-fosc", where=f"{NAME} start", quantity="rotor oscillation frequency",
              printed=Printed("22.7", "Hz"), chapter=START,
              compute=lambda p: oscillation_frequency(p["torque_constant"], p["start_current"], p["pole_pairs"],
                                                      p["inertia"]),
              reason="sqrt(4.5e-3 x 0.48 x 6 / 6.34e-7) / 2 pi = 22.755 Hz, truncated to 22.7 instead of rounded "
                     "to 22.8 (0.2 % low)", truncated=True),
        Claim(id="tda5341-tstart", where=f"{NAME} start", quantity="start period for the 48.4 Hz start frequency",
              printed=Printed("24", "ms"), chapter=START, compute=lambda p: 1 / p["f_start"],
              reason="1 / 48.4 Hz = 20.7 ms; 24 ms is 1 / 41.7 Hz",
              consequence="one of the two numbers is wrong; the capacitor that follows (33 nF) uses 24 ms, a start "
                          "frequency of 41.7 Hz"),
        Claim(id="tda5341-capst", where=f"{NAME} start", quantity="start capacitor 0.024 / 0.78",
              printed=Printed("0.031", "uF"), chapter=START, compute=_cap_st, reason="0.024 / 0.78 = 0.0308 uF"),
        Claim(id="tda5341-capst-choice", where=f"{NAME} start", quantity="start capacitor chosen",
              printed=Printed("33", "nF"), chapter=START,
              compute=lambda p: series.at_least(p["cap_series"], _cap_st(p)),
              reason="the E12 value at or above 30.8 nF"),
        Claim(id="tda5341-window", where=f"{NAME} CAPCDM", quantity="CAPCDM voltage window 2.28 - 0.87",
              printed=Printed("1.41", "V"), chapter=CD, compute=lambda p: p["v_high"] - p["v_low"],
              reason="2.28 V - 0.87 V"),
        Claim(id="tda5341-constant", where=f"{NAME} CAPCDM", quantity="CAPCDM = K / f_C1 (nF), K",
              printed=Printed("7092", "1"), chapter=CD,
              compute=lambda p: constant_k(p["i_charge"], p["v_low"], p["v_high"]) * 1e9,  # F Hz -> nF Hz
              reason="10 uA / 1.41 V = 7092.2 nF Hz (typical current, no tolerance)"),
        Claim(id="tda5341-capcdm", where=f"{NAME} CAPCDM", quantity="CAPCDM for f_C1 = 1600 Hz",
              printed=Printed("4.43", "nF"), chapter=CD, compute=_capcdm, reason="7092 / 1600 = 4.433 nF"),
        Claim(id="tda5341-capcdm-choice", where=f"{NAME} CAPCDM", quantity="CAPCDM chosen",
              printed=Printed("4.7", "nF"), chapter=CD, compute=lambda p: series.at_least(p["cap_series"], _capcdm(p)),
              reason="the E12 value at or above 4.43 nF (no tolerance margin: 4.7 nF - 5 % = 4.47 nF still fits)"),
        Claim(id="tda5341-max-delay", where=f"{NAME} CAPCDM", quantity="maximum delay per nF (discharge 1.41 V at 20 uA)",
              printed=Printed("0.070", "ms"), chapter=CD,
              compute=lambda p: max_delay(1e-9, p["i_discharge"], p["v_low"], p["v_high"]),  # for 1 nF
              reason="1.41 V / 20 uA = 0.0705 ms per nF"),
        Claim(id="tda5144-constant", where=TDA5144, quantity="TDA5144: C = K / f_C1 (nF), K",
              printed=Printed("6231", "1"), chapter=CMP,
              compute=lambda p: constant_k(p["tda5144_i_charge"], p["tda5144_v_low"], p["tda5144_v_high"]) * 1e9,
              reason="8.1 uA / 1.3 V = 6230.8 nF Hz"),
        Claim(id="tda5144-cap", where=TDA5144, quantity="TDA5144 example: C for f_C1 = 400 Hz",
              printed=Printed("15.6", "nF"), chapter=CMP,
              compute=lambda p: cap_cd_for(p["tda5144_f_c1"], p["tda5144_i_charge"], p["tda5144_v_low"],
                                           p["tda5144_v_high"]),
              reason="6231 / 400 = 15.58 nF"),
        Claim(id="tda5144-max-delay", where=TDA5144, quantity="TDA5144: maximum delay per nF",
              printed=Printed("0.076", "ms"), chapter=CMP,
              compute=lambda p: max_delay(1e-9, p["tda5144_i_discharge"], p["tda5144_v_low"], p["tda5144_v_high"]),
              reason="1.3 V / 16.2 uA = 0.0802 ms per nF; 0.076 would need 1.23 V or 17.1 uA",
              consequence="the fixed delay below f_C1 is about 5 % longer than the datasheet's formula says: small, "
                          "but the formula does not follow from its own numbers"),
    ]
