"""The design specification in one table: every key of every table, with its default, unit, range and
meaning, and every result each design reports.

Validation (:mod:`handbook.design.spec`), the command line's help, the README's key table and the design
chapters' ``parameters`` cells are all read from here; ``tests/design/test_schema.py`` fails when the
README or a parameters cell drifts from it. Values are SI (F, A, V, ohm, W, K/W; rpm for speeds;
tolerances and THD as fractions).
"""
from __future__ import annotations

from dataclasses import dataclass

from ..core import Param
from ..core.series import SERIES_NAMES

_POS = dict(low=0.0, low_open=True)
_FRACTION = dict(low=0.0, high=0.999)


def _series(name: str, default: str, what: str) -> Param:
    return Param(name=name, default=default, unit="", meaning=f"E-series for {what}", choices=SERIES_NAMES)


def _tables() -> dict[str, tuple[Param, ...]]:
    """The literal table (data)."""
    return {
        "commutation": (
            Param(name="pole_pairs", default=6, unit="", meaning="magnetic pole pairs n (whole number)", low=1,
                  high=100),
            Param(name="rpm_min", default=1800.0, unit="rpm", meaning="lowest speed that must commutate reliably",
                  high=1e6, **_POS),
            Param(name="rpm_max", default=3600.0, unit="rpm", high=1e6, **_POS,
                  meaning="highest speed that must commutate reliably (the note gives none: twice rpm_min)"),
            Param(name="i_charge_min", default=10.6e-6, unit="A", high=1e-3, **_POS,
                  meaning="smallest CAP-CD charge current", cite="TDA5144 datasheet, the column AN94002 reads 22 uA from"),
            Param(name="i_charge_max", default=22e-6, unit="A", high=1e-3, **_POS,
                  meaning="largest CAP-CD charge current", cite="AN94002 2.1.2"),
            Param(name="window", default=1.4, unit="V", high=5.0, **_POS,
                  meaning="CAP-CD voltage window (lowest upper level less highest lower level)",
                  cite="TDA5144 datasheet: 2.3 V - 0.9 V"),
            Param(name="min_excursion", default=0.1, unit="V", high=5.0, **_POS,
                  meaning="smallest swing still safe from noise (an assumption)"),
            Param(name="tolerance", default=0.05, unit="1", meaning="capacitor tolerance, fraction (5 % = 0.05)",
                  **_FRACTION),
            _series("series", "E12", "CAP-CD (E3 .. E192)"),
        ),
        "current_limiter": (
            Param(name="i_no_trip", default=0.9, unit="A", high=100.0, **_POS,
                  meaning="current at or below which the limiter must never act",
                  cite="half the TDA5144's minimum internal limit"),
            Param(name="i_must_trip", default=1.8, unit="A", high=100.0, **_POS,
                  meaning="current at or below which it must always have acted",
                  cite="TDA5144 output current limit, minimum 1.8 A"),
            Param(name="resistor_tolerance", default=0.01, unit="1", meaning="tolerance of R9..R13, fraction",
                  **_FRACTION),
            Param(name="r7_tolerance", default=0.05, unit="1", meaning="tolerance of the sense resistor R7, fraction",
                  **_FRACTION),
            Param(name="zener_voltage", default=8.2, unit="V", meaning="nominal zener voltage of D1", high=100.0,
                  **_POS),
            Param(name="zener_tolerance", default=0.05, unit="1", meaning="zener tolerance, fraction", **_FRACTION),
            Param(name="zener_tc", default=0.0, unit="V/K", low=0.0, high=0.1,
                  meaning="largest zener temperature coefficient (0: no drift)"),
            Param(name="temp_span", default=0.0, unit="K", low=0.0, high=200.0,
                  meaning="temperature excursion either side of 25 C for the drift"),
            Param(name="offset", default=9e-3, unit="V", low=0.0, high=0.1, meaning="largest op-amp input offset",
                  cite="LM358 datasheet, over temperature"),
            Param(name="r10", default=5.6e3, unit="ohm", meaning="R10", high=1e9, **_POS),
            Param(name="r11", default=16e3, unit="ohm", meaning="R11", high=1e9, **_POS),
            Param(name="r12", default=5.6e3, unit="ohm", meaning="R12", high=1e9, **_POS),
            Param(name="r13", default=16e3, unit="ohm", meaning="R13", high=1e9, **_POS),
            _series("r7_series", "E24", "R7"),
            Param(name="r7_min", default=0.01, unit="ohm", meaning="smallest R7", high=1e9, **_POS),
            Param(name="r7_max", default=10.0, unit="ohm", meaning="largest R7", high=1e9, **_POS),
            _series("r9_series", "E96", "R9"),
            Param(name="r9_min", default=10.0, unit="ohm", meaning="smallest R9", high=1e9, **_POS),
            Param(name="r9_max", default=1e6, unit="ohm", meaning="largest R9", high=1e9, **_POS),
        ),
        "class_d": (
            Param(name="p_out", default=125.0, unit="W", meaning="output power that must not clip (1 % THD)",
                  high=1e4, **_POS),
            Param(name="r_load", default=4.0, unit="ohm", meaning="load resistance", high=1e3, **_POS),
            Param(name="supply", default=20.0, unit="V", meaning="supply rails +-V", high=22.0, **_POS),
            Param(name="t_ambient", default=50.0, unit="C", meaning="highest ambient temperature", low=-40.0,
                  high=149.0),
            Param(name="package", default="TF", unit="", meaning="LM4652 package: 'TF' (isolated) or 'T'",
                  choices=("TF", "T")),
            Param(name="theta_cs", default=0.2, unit="K/W", meaning="case-to-sink thermal resistance", low=0.0,
                  high=10.0),
            Param(name="theta_sa_available", default=None, unit="K/W", high=100.0, **_POS,
                  meaning="thermal resistance of the heat sink you have (leave out: report the one needed)"),
            Param(name="thd_max", default=0.005, unit="1", high=0.1, **_POS,
                  meaning="THD+N limit at the test point, fraction (0.5 % = 0.005)"),
            Param(name="thd_test_power", default=10.0, unit="W", meaning="output power of the THD+N test point",
                  high=1e4, **_POS),
            Param(name="r_dly", default=5e3, unit="ohm", meaning="dead-time resistor R_DLY", low=0.0, high=1e5),
            _series("r_osc_series", "E24", "R_OSC"),
        ),
    }


#: table -> its keys, in the order the README and the help list them
TABLES: dict[str, tuple[Param, ...]] = _tables()


@dataclass(frozen=True)
class Output:
    """One result a design reports: its key in the JSON (SI), the unit, and a label for people."""

    key: str
    unit: str  # "F", "ohm", "A", ...; "%" for a fraction shown as a percentage; "" for text or plain numbers
    label: str


#: table -> the results it reports, in order
OUTPUTS: dict[str, tuple[Output, ...]] = {
    "commutation": (
        Output("cap_cd", "F", "CAP-CD"), Output("cap_dc", "F", "CAP-DC"),
        Output("rpm_min_reliable", "rpm", "lowest reliable speed"),
        Output("rpm_max_reliable", "rpm", "highest reliable speed"),
        Output("noise_margin", "%", "margin above the noise floor at rpm_max"), Output("binding", "", "binding"),
    ),
    "current_limiter": (
        Output("r7", "ohm", "R7"), Output("r9", "ohm", "R9"), Output("i_trip_min", "A", "lowest trip current"),
        Output("i_trip_max", "A", "highest trip current"), Output("i_trip_nominal", "A", "nominal trip current"),
        Output("p_r7", "W", "loss in R7 at i_no_trip"), Output("v_cs_nominal", "V", "nominal sense voltage"),
        Output("margin_low", "%", "margin above i_no_trip"), Output("margin_high", "%", "margin below i_must_trip"),
        Output("binding", "", "binding"),
    ),
    "class_d": (
        Output("f_sw", "Hz", "switching frequency"), Output("r_osc", "ohm", "R_OSC"),
        Output("efficiency", "%", "efficiency at p_out"), Output("p_dissipation", "W", "LM4652 dissipation"),
        Output("theta_sa_required", "K/W", "heat sink needed"), Output("t_junction", "C", "junction temperature"),
        Output("thd_n", "%", "THD+N at the test point"), Output("p_clip", "W", "clipping power"),
        Output("binding", "", "binding"),
    ),
}


def defaults(table: str) -> dict:
    return {p.name: p.default for p in TABLES[table]}


def key_rows() -> list[tuple[str, str, str, str, str]]:
    """(table, key, default, unit, meaning) for every key: the README table and the help read this."""
    return [(t, p.name, "—" if p.default is None else repr(p.default), p.unit, p.meaning)
            for t, params in TABLES.items() for p in params]


def markdown_table() -> str:
    """The README's table of keys, rendered from this schema (a test keeps the README in step)."""
    lines = ["| table | key | default | unit | meaning |", "|---|---|---|---|---|"]
    for t, key, default, unit, meaning in key_rows():
        shown = default if default == "—" else f"`{default}`"
        lines.append(f"| `{t}` | `{key}` | {shown} | {unit} | {meaning} |")
    return "\n".join(lines)
