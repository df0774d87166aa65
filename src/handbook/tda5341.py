"""TDA5341 (Philips, 1997): start oscillator and adaptive commutation delay (CAPCDM, CAPCDS).

The excerpt's equations are garbled by the OCR; they are rebuilt from the numbers around them
(see the chapter). Compared with the TDA5144's treatment of the same mechanism in its datasheet
(figures from datasheet_facts.md).
"""
from __future__ import annotations

import functools

from . import an94002, series
from .examples import Example, Printed, TextErratum, evaluate_all

NOTE = "TDA5341"

DEFAULTS: dict = {
    "inertia": 6.34e-7, "torque_constant": 4.5e-3, "pole_pairs": 6, "start_current": 0.48,
    "t_start": 24e-3, "f_start": 48.4, "cap_st_constant": 0.78,  # s/uF, as the excerpt divides by it
    "i_charge": 10e-6, "i_discharge": 20e-6, "v_low": 0.87, "v_high": 2.28,
    "f_c1": 1600.0, "cap_series": "E12",
    # the TDA5144 datasheet's own version (datasheet_facts.md)
    "tda5144_i_charge": 8.1e-6, "tda5144_i_discharge": 16.2e-6, "tda5144_v_low": 0.9, "tda5144_v_high": 2.2,
    "tda5144_f_c1": 400.0,
}


def cap_cd_for(f_c1, i_charge, v_low, v_high):
    """C = I / (dV f_C1): charged at I for one commutation period 1/f_C1 across the window."""
    return i_charge / ((v_high - v_low) * f_c1)


def constant_nf_hz(i_charge, v_low, v_high):
    """The 'C = K / f_C1 (nF)' constant: K = I / dV in nF Hz."""
    return i_charge / (v_high - v_low) * 1e9


def max_delay_per_nf(i_discharge, v_low, v_high):
    """Longest delay (below f_C1): discharge across the window at I_dis, in ms per nF."""
    return (v_high - v_low) / i_discharge * 1e-9 * 1e3


def examples_list() -> list[Example]:
    S, CD, CMP = "start", "commutation", "tda5144"
    return [
        Example("tda5341-fosc", f"{NOTE} start", "rotor oscillation frequency", Printed("22.7", "Hz"),
                lambda p: an94002.oscillation_frequency(p["torque_constant"], p["start_current"], p["pole_pairs"],
                                                        p["inertia"]),
                "sqrt(4.5e-3 x 0.48 x 6 / 6.34e-7) / 2 pi = 22.755 Hz, which rounds to 22.8",
                ("torque_constant", "start_current", "pole_pairs", "inertia"), chapter=S,
                consequence="none: 22.755 Hz truncated to 22.7 instead of rounded to 22.8 (0.2 %)"),
        Example("tda5341-tstart", f"{NOTE} start", "start period for the 48.4 Hz start frequency", Printed("24", "ms"),
                lambda p: 1 / p["f_start"], "1 / 48.4 Hz = 20.7 ms; 24 ms is 1 / 41.7 Hz", ("f_start",), chapter=S,
                consequence="one of the two numbers is wrong; the capacitor that follows (33 nF) uses 24 ms, a start "
                            "frequency of 41.7 Hz"),
        Example("tda5341-capst", f"{NOTE} start", "start capacitor 0.024 / 0.78", Printed("0.031", "uF"),
                lambda p: p["t_start"] / p["cap_st_constant"] * 1e-6, "0.024 / 0.78 = 0.0308 uF",
                ("t_start", "cap_st_constant"), chapter=S),
        Example("tda5341-capst-choice", f"{NOTE} start", "start capacitor chosen", Printed("33", "nF"),
                lambda p: series.at_least(p["cap_series"], p["t_start"] / p["cap_st_constant"] * 1e-6),
                "the E12 value at or above 30.8 nF", ("t_start", "cap_st_constant", "cap_series"), chapter=S),
        Example("tda5341-window", f"{NOTE} CAPCDM", "CAPCDM voltage window 2.28 - 0.87", Printed("1.41", "V"),
                lambda p: p["v_high"] - p["v_low"], "2.28 V - 0.87 V", ("v_low", "v_high"), chapter=CD),
        Example("tda5341-constant", f"{NOTE} CAPCDM", "CAPCDM = K / f_C1 (nF), K", Printed("7092", "1"),
                lambda p: constant_nf_hz(p["i_charge"], p["v_low"], p["v_high"]),
                "10 uA / 1.41 V = 7092.2 nF Hz (typical current, no tolerance)", ("i_charge", "v_low", "v_high"),
                chapter=CD),
        Example("tda5341-capcdm", f"{NOTE} CAPCDM", "CAPCDM for f_C1 = 1600 Hz", Printed("4.43", "nF"),
                lambda p: cap_cd_for(p["f_c1"], p["i_charge"], p["v_low"], p["v_high"]), "7092 / 1600 = 4.433 nF",
                ("f_c1", "i_charge", "v_low", "v_high"), chapter=CD),
        Example("tda5341-capcdm-choice", f"{NOTE} CAPCDM", "CAPCDM chosen", Printed("4.7", "nF"),
                lambda p: series.at_least(p["cap_series"], cap_cd_for(p["f_c1"], p["i_charge"], p["v_low"], p["v_high"])),
                "the E12 value at or above 4.43 nF (no tolerance margin: 4.7 nF - 5 % = 4.47 nF still fits)",
                ("f_c1", "i_charge", "v_low", "v_high", "cap_series"), chapter=CD),
        Example("tda5341-max-delay", f"{NOTE} CAPCDM", "maximum delay per nF (discharge 1.41 V at 20 uA)",
                Printed("0.070", "ms"), lambda p: max_delay_per_nf(p["i_discharge"], p["v_low"], p["v_high"]) * 1e-3,
                "1.41 V / 20 uA = 0.0705 ms per nF", ("i_discharge", "v_low", "v_high"), chapter=CD),
        Example("tda5144-constant", "TDA5144 datasheet (datasheet_facts.md)", "TDA5144: C = K / f_C1 (nF), K",
                Printed("6231", "1"),
                lambda p: constant_nf_hz(p["tda5144_i_charge"], p["tda5144_v_low"], p["tda5144_v_high"]),
                "8.1 uA / 1.3 V = 6230.8 nF Hz", ("tda5144_i_charge", "tda5144_v_low", "tda5144_v_high"), chapter=CMP),
        Example("tda5144-cap", "TDA5144 datasheet (datasheet_facts.md)", "TDA5144 example: C for f_C1 = 400 Hz",
                Printed("15.6", "nF"),
                lambda p: cap_cd_for(p["tda5144_f_c1"], p["tda5144_i_charge"], p["tda5144_v_low"], p["tda5144_v_high"]),
                "6231 / 400 = 15.58 nF", ("tda5144_f_c1", "tda5144_i_charge", "tda5144_v_low", "tda5144_v_high"),
                chapter=CMP),
        Example("tda5144-max-delay", "TDA5144 datasheet (datasheet_facts.md)", "TDA5144: maximum delay per nF",
                Printed("0.076", "ms"),
                lambda p: max_delay_per_nf(p["tda5144_i_discharge"], p["tda5144_v_low"], p["tda5144_v_high"]) * 1e-3,
                "1.3 V / 16.2 uA = 0.0802 ms per nF; 0.076 would need 1.23 V or 17.1 uA", ("tda5144_i_discharge",
                                                                                          "tda5144_v_low", "tda5144_v_high"),
                chapter=CMP, consequence="the fixed delay below f_C1 is about 5 % longer than the datasheet's "
                                         "formula says: small, but the formula does not follow from its own numbers"),
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

    C, f, I, dV, Idis, t = sp.symbols(r"C f_{C1} I_{ch} \Delta{}V I_{dis} t_{max}", positive=True)
    f_num = sp.Symbol("f", positive=True)
    nF = u.farad / 10 ** 9
    timer = sp.solve(sp.Eq(I / f, C * dV), C)[0]
    eqs = [
        Equation(id="tda5341-capcdm", source=f"{NOTE}, CAPCDM (reconstructed)", title="CAPCDM = 7092 / f_C1 (C in nF)",
                 lhs=C, lhs_unit=u.farad, lhs_scale=nF, printed=7092 / f_num, scales={f_num: f / u.hertz},
                 derived=timer, units={I: u.ampere, dV: u.volt, f: u.hertz},
                 values={I: 10 * u.ampere / 10 ** 6, dV: sp.Rational("1.41") * u.volt},
                 law="charge balance: charged at 10 uA for one commutation period 1/f_C1 across 0.87..2.28 V",
                 reconstructed="the OCR shows 'C = 10 ... 1.41 x f ... 7092' in pieces; the form C = 10 uA / (1.41 V "
                               "f_C1) = 7092 / f_C1 nF fits the pieces and the example 7092/1600 = 4.43",
                 note="7092 is 7092.2 rounded."),
        Equation(id="tda5341-max-delay", source=f"{NOTE}, CAPCDM", title="Maximum delay = 0.070 C ms (C in nF)",
                 lhs=t, lhs_unit=u.second, lhs_scale=u.second / 1000, printed=sp.Rational("0.070") * sp.Symbol("C_nF"),
                 scales={sp.Symbol("C_nF"): C / nF}, derived=sp.solve(sp.Eq(Idis * t, C * dV), t)[0],
                 units={C: u.farad, Idis: u.ampere, dV: u.volt},
                 values={Idis: 20 * u.ampere / 10 ** 6, dV: sp.Rational("1.41") * u.volt},
                 law="charge balance: discharged at 20 uA across the window", note="0.070 is 0.0705 rounded."),
    ]
    for e in eqs:
        e.chapter = "commutation"
    return tuple(eqs)


TEXT_ERRATA = [
    TextErratum("tda5341-t-inertia", f"{NOTE}, start", "inertia printed in 'kg/m2'",
                "the unit of inertia is kg m2 (as AN94002 prints it)", "none once read as kg m2"),
    TextErratum("tda5341-t-typical", f"{NOTE}, CAPCDM", "CAPCDM is sized with the typical 10 uA and no tolerance",
                "AN94002 sizes the TDA5144's CAP-CD with the largest current and the narrowest window",
                "at the lowest frequency a part with a high charge current or a narrow window saturates: "
                "add the current spread and the capacitor tolerance as in the design chapter"),
]
