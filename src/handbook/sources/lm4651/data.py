"""LM4651/LM4652 datasheet: the device figures (with where they are printed), the Example Design's
values and the textual errata."""
from __future__ import annotations

from ...core import Fact, Param, TextErratum

NAME = "LM4651/LM4652"
DATASHEET = "LM4651/LM4652 datasheet (National Semiconductor, 2000)"

#: the device figures the models and the Example Design rely on
FACTS = {
    "t_rise": Fact(25e-9, f"{DATASHEET}, LM4652 electrical characteristics: t_r, typical"),
    "t_fall": Fact(26e-9, f"{DATASHEET}, LM4652 electrical characteristics: t_f, typical"),
    "t_overmod": Fact(310e-9, f"{DATASHEET}, LM4651 electrical characteristics: over-modulation protection time "
                              "T_OVERMOD, typical (the Example Design uses 350 ns)"),
    "rds_on_hot": Fact(0.230, f"{DATASHEET}, Example Design: R_DS(on) 'at 100 C' (the LM4652 table gives 0.200 ohm "
                              "typical and 0.300 ohm maximum at 25 C only)"),
    "theta_jc": Fact({"TF": 2.0, "T": 1.0}, f"{DATASHEET}, LM4652 thermal resistance junction to case, K/W: "
                                            "isolated (TF) and non-isolated (T) TO-220"),
    "tj_max": Fact(150.0, f"{DATASHEET}, LM4652 absolute maximum junction temperature, C"),
    "f_min": Fact(50e3, f"{DATASHEET}, LM4651: switching frequency '50 kHz to 225 kHz'"),
    "f_max": Fact(225e3, f"{DATASHEET}, LM4651: switching frequency '50 kHz to 225 kHz'"),
    "p_driver": Fact(1.0, f"{DATASHEET}, system table: the LM4651's own dissipation, the example's 22 W system less "
                          "21 W in the LM4652"),
}


def _fact(name: str, key: str, unit: str, meaning: str, low: float, high: float) -> Param:
    """A parameter whose default is a device figure (one number, typed once, with its citation)."""
    return Param(name=name, default=FACTS[key].value, unit=unit, meaning=meaning, low=low, high=high,
                 cite=FACTS[key].cite)


#: the Example Design's values (125 W into 4 ohm, 3 V rms in, 50 C ambient)
PARAMETERS = (
    Param(name="p_out", default=125.0, unit="W", meaning="output power", low=1e-3, high=1000.0),
    Param(name="r_load", default=4.0, unit="ohm", meaning="load resistance", low=0.5, high=100.0),
    _fact("t_rise", "t_rise", "s", "LM4652 rise time t_r", 1e-10, 1e-6),
    _fact("t_fall", "t_fall", "s", "LM4652 fall time t_f", 1e-10, 1e-6),
    Param(name="t_overmod_example", default=350e-9, unit="s", meaning="over-modulation time the Example Design "
          "puts in eq 9", low=0.0, high=5e-6),
    _fact("t_overmod_table", "t_overmod", "s", "over-modulation time T_OVERMOD, LM4651 table (typical)", 0.0, 5e-6),
    _fact("rds_on_hot", "rds_on_hot", "ohm", "LM4652 on-resistance R_DS(on) when hot", 1e-3, 10.0),
    Param(name="t_ambient", default=50.0, unit="degC", meaning="ambient temperature (Celsius)", low=-55.0, high=150.0),
    Param(name="theta_cs", default=0.2, unit="K/W", meaning="case-to-sink thermal resistance (thermal grease)",
          low=0.0, high=10.0),
    _fact("tj_max", "tj_max", "degC", "largest junction temperature (Celsius)", 25.0, 200.0),
    _fact("p_driver", "p_driver", "W", "LM4651 driver's own dissipation", 0.0, 20.0),
    Param(name="f_sw", default=125e3, unit="Hz", meaning="switching frequency", low=1e3, high=1e6),
    Param(name="r_dly", default=5e3, unit="ohm", meaning="dead-time resistor R_DLY", low=0.0, high=1e6),
    Param(name="r_sckt", default=100e3, unit="ohm", meaning="current-limit resistor R_SCKT", low=1e3, high=1e8),
    Param(name="t_start", default=1.0, unit="s", meaning="start-up (mute) time", low=1e-3, high=100.0),
    Param(name="v_in_rms", default=3.0, unit="V", meaning="input voltage for full power (rms)", low=1e-3,
          high=100.0),
    Param(name="rf11", default=620e3, unit="ohm", meaning="feedback resistor R_f11", low=1.0, high=1e8),
    Param(name="rf12", default=62e3, unit="ohm", meaning="feedback resistor R_f12", low=1.0, high=1e8),
    Param(name="r1", default=20e3, unit="ohm", meaning="input resistor R1", low=1.0, high=1e8),
    Param(name="c_start", default=10e-6, unit="F", meaning="start-up capacitor C_START fitted", low=1e-9,
          high=1e-2),
)

ERRATA = (
    TextErratum("lm4651-t-50uf", f"{NAME}, Output Stage Filtering", "'a 50 uF inductor'",
                "the Example Design and figure 1 use 50 uH inductors", "none once read as uH"),
    TextErratum("lm4651-t-rds", f"{NAME}, Example Design", "R_DS(on) 'at 100 C' = 0.230 ohm is not in the table",
                "the LM4652 table gives 200 mOhm typical and 300 mOhm maximum at 25 C only",
                "0.230 ohm is optimistic against the 300 mOhm maximum: conduction loss may be 30 % higher"),
    TextErratum("lm4651-t-r1", f"{NAME}, DC offset vs Example Design vs figure 1",
                "R1 is 25 k in the DC-offset section, 20 k in the Example Design and 4.7 k in figure 1",
                "with the 1 uF input capacitor the high-pass corner is 6.4 Hz, 8.0 Hz and 33.9 Hz: the three "
                "values are three different amplifiers",
                "figure 1's 4.7 k with 1 uF cuts at 34 Hz, into a subwoofer's band: with 4.7 k use at least "
                "4.7 uF (6.8 Hz)"),
    TextErratum("lm4651-t-supply", f"{NAME}, Example Design",
                "the supply (+-20 V) comes from a graph that did not survive",
                "the electrical tables are specified at +-20 V, 4 ohm, 125 kHz, consistent with the choice",
                "none"),
)
