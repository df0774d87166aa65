"""AN93008: the values of its figure 3 and figure 4 limiters and its tolerance budget, and its textual errata."""
from __future__ import annotations

from ...core import Param, ReadingNote, TextErratum
from ..an94002.data import FACTS as _AN94002_FACTS

NAME = "AN93008"

#: the outside figures AN93008 relies on: the same BZX79-C8V2 as AN94002's figure 3 (BZX79 datasheet)
FACTS = {k: _AN94002_FACTS[k] for k in ("bzx79_vz", "bzx79_tc")}

PARAMETERS = (
    Param(name="v_supply", default=12.0, unit="V", meaning="supply the limiter is referenced to", low=0.5,
          high=60.0),
    Param(name="supply_tolerance", default=0.10, unit="1", meaning="supply tolerance (fraction)", low=0.0, high=0.5),
    Param(name="r8", default=7.5e3, unit="ohm", meaning="level shift, top resistor R8", low=1.0, high=1e8),
    Param(name="r9", default=33e3, unit="ohm", meaning="level shift, bottom resistor R9", low=1.0, high=1e8),
    Param(name="r10", default=7.87e3, unit="ohm", meaning="reference, top resistor R10", low=1.0, high=1e8),
    Param(name="r11", default=33e3, unit="ohm", meaning="reference, bottom resistor R11", low=1.0, high=1e8),
    Param(name="v_cs", default=0.1, unit="V", meaning="sense voltage at the current limit", low=1e-3, high=10.0),
    Param(name="offset", default=9e-3, unit="V", meaning="op-amp input offset, largest (LM358)", low=0.0, high=0.1),
    Param(name="offset_generic", default=10e-3, unit="V", meaning="the note's round-figure op-amp offset", low=0.0,
          high=0.1),
    Param(name="resistor_tolerance", default=0.05, unit="1", meaning="tolerance of R8 to R11 (fraction)", low=0.0,
          high=0.5),
    Param(name="zener_voltage", default=8.2, unit="V", meaning="zener voltage of the figure 4 limiter", low=0.5, high=100.0),
    Param(name="zener_tolerance", default=0.05, unit="1", meaning="zener tolerance (fraction)", low=0.0, high=0.5),
    Param(name="zener_tolerance_a", default=0.01, unit="1", meaning="zener tolerance of the BZX79-A (fraction)",
          low=0.0, high=0.5),
    Param(name="zener_tc", default=6.2e-3, unit="V/K", meaning="zener temperature coefficient", low=-0.1, high=0.1),
    Param(name="temp_span", default=25.0, unit="K", meaning="temperature excursion (25 C +- 25 C)", low=0.0,
          high=200.0),
    Param(name="level_shift", default=2.0, unit="V", meaning="level shift the figure 4 divider is designed for",
          low=0.0, high=50.0),
    Param(name="v_be", default=0.8, unit="V", meaning="base-emitter voltage of the one-transistor limiter", low=0.1,
          high=2.0),
    Param(name="v_be_tc", default=-2e-3, unit="V/K", meaning="temperature coefficient of V_be", low=-0.01, high=0.0),
)

ERRATA = (
    TextErratum("an93008-t-gnd", f"{NAME} 2 vs AN94002 3",
                "'all GND pins are internally interconnected', the reason given for keeping the sense resistor out "
                "of the ground return",
                "AN94002 section 3, on the same TDA5143/TDA5144: 'GND3 is on the chip not connected to the ground "
                "line and has externally to be connected to GND2'",
                "connect GND3 to GND2 on the board, as AN94002 says; whether GND1 and GND2 are joined on the chip "
                "(AN93008's reason for a supply-side sense resistor) neither note shows"),
)

#: what is not an error of the note: how the book reads it
READING_NOTES = (
    ReadingNote("an93008-t-unit", f"{NAME} 2.1", "the one-transistor limit's drift reads '-0.25 °C'",
                "the math OCR left an empty '\\text{ }' where '%/' belongs ('%' starts a comment in LaTeX), and AN94002 "
                "2.3 prints the same sentence with '%/°C': -2 mV/K over 800 mV is -0.25 %/K"),
    ReadingNote("an93008-t-fig4", f"{NAME} 2.2, figure 4", "figure 4's resistor values did not survive the OCR",
                "the text gives A = 0.74 and a 2 V level shift; AN94002 figure 3 is the same circuit with 5.6 k / "
                "16 k, which give the note's A, so the book evaluates figure 4 with those values"),
)
