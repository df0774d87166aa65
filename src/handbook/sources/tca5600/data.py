"""TCA5600/TCF5600 excerpt: the application circuit's values and the assumed device figures.

The excerpt prints no worked numbers and no public copy of the electrical characteristics was found,
so every device value is an assumption, stated with its reason.
"""
from __future__ import annotations

from ...core import Param, ReadingNote

NAME = "TCA5600"

#: values the excerpt prints on its application circuit (figure 13)
APPLICATION = {"l1": 300e-6, "r1": 0.68}

PARAMETERS = (
    Param(name="v12h", default=0.4, unit="V", low=0.01, high=5.0, meaning="current-sense threshold V12(H)",
          cite="assumption: comparator thresholds of this kind are a few hundred mV"),
    Param(name="vce_sat", default=0.5, unit="V", low=0.0, high=5.0, meaning="saturation of the internal switch",
          cite="assumption: a few hundred mA through a bipolar switch"),
    Param(name="v_f", default=0.8, unit="V", low=0.0, high=5.0, meaning="rectifier forward drop",
          cite="assumption: a silicon rectifier at a few hundred mA"),
    Param(name="v_cc2_min", default=8.0, unit="V", low=0.5, high=60.0, meaning="lowest converter supply VCC2",
          cite="assumption: a 12 V battery at cranking"),
    Param(name="v_out2", default=12.0, unit="V", low=0.5, high=60.0, meaning="the programmable regulator's output",
          cite="assumption"),
    Param(name="i_out2", default=0.05, unit="A", low=1e-6, high=10.0, meaning="largest load of the regulator",
          cite="assumption"),
    Param(name="regulator_drop", default=2.5, unit="V", low=0.0, high=20.0,
          meaning="regulator input-output drop V(9-8), 2.5 V typical per the excerpt"),
    Param(name="f_min", default=20e3, unit="Hz", low=1.0, high=1e7,
          meaning="lowest oscillation frequency, above the audio band (the excerpt's 20 kHz)"),
)

ERRATA = ()

#: what is not an error of the excerpt: what the public record lacks
READING_NOTES = (
    ReadingNote("tca5600-t-values", f"{NAME}, DC/DC converter", "no worked numbers, and no public electrical "
                "characteristics for V12(H), V_CE(sat) and V_F",
                "no public copy of the electrical characteristics was found, so the application values L1 = 300 uH "
                "and R1 = 0.68 ohm are checked against device values the chapter assumes and states"),
)
