"""TDA5341 excerpt: its example's values, and the TDA5144 datasheet's version of the same timer."""
from __future__ import annotations

from ...core import Param, ReadingNote, TextErratum

NAME = "TDA5341"
TDA5144 = "TDA5144 datasheet (Philips, June 1994)"

PARAMETERS = (
    Param(name="inertia", default=6.34e-7, unit="kg m^2", meaning="rotor inertia J (printed 'kg/m2')", low=1e-12, high=1.0),
    Param(name="torque_constant", default=4.5e-3, unit="N m/A", meaning="torque constant K_t", low=1e-6, high=10.0),
    Param(name="pole_pairs", default=6, unit="", meaning="magnetic pole pairs p", low=1, high=100),
    Param(name="start_current", default=0.48, unit="A", meaning="start current I", low=1e-4, high=100.0),
    Param(name="t_start", default=24e-3, unit="s", meaning="start period the capacitor is sized for", low=1e-5, high=100.0),
    Param(name="f_start", default=48.4, unit="Hz", meaning="start frequency the excerpt quotes", low=1e-3, high=1e5),
    Param(name="cap_st_constant", default=0.78, unit="s/uF", meaning="start-capacitor constant the excerpt divides by",
          low=1e-3, high=100.0),
    Param(name="i_charge", default=10e-6, unit="A", meaning="CAPCDM charge current (typical)", low=1e-9, high=1e-3),
    Param(name="i_discharge", default=20e-6, unit="A", meaning="CAPCDM discharge current (typical)", low=1e-9, high=1e-3),
    Param(name="v_low", default=0.87, unit="V", meaning="CAPCDM lower switching level", low=0.0, high=10.0),
    Param(name="v_high", default=2.28, unit="V", meaning="CAPCDM upper switching level", low=0.0, high=10.0),
    Param(name="f_c1", default=1600.0, unit="Hz", meaning="lowest commutation frequency of interest", low=1.0, high=1e6),
    Param(name="cap_series", default="E12", unit="", meaning="series the capacitors are chosen from",
          choices=("E3", "E6", "E12", "E24", "E48", "E96", "E192")),
    Param(name="tda5144_i_charge", default=8.1e-6, unit="A", meaning="TDA5144 CAP-CD charge current, typical",
          low=1e-9, high=1e-3, cite=TDA5144),
    Param(name="tda5144_i_discharge", default=16.2e-6, unit="A", meaning="TDA5144 CAP-CD discharge current, typical",
          low=1e-9, high=1e-3, cite=TDA5144),
    Param(name="tda5144_v_low", default=0.9, unit="V", meaning="TDA5144 CAP-CD lower level", low=0.0, high=10.0,
          cite=TDA5144),
    Param(name="tda5144_v_high", default=2.2, unit="V", meaning="TDA5144 CAP-CD upper level", low=0.0, high=10.0,
          cite=TDA5144),
    Param(name="tda5144_f_c1", default=400.0, unit="Hz", meaning="TDA5144 datasheet example's f_C1", low=1.0, high=1e6,
          cite=TDA5144),
)

ERRATA = (
    TextErratum("tda5341-t-inertia", f"{NAME}, start", "inertia printed in 'kg/m2'",
                "the unit of inertia is kg m2 (as AN94002 prints it)", "none once read as kg m2"),
)

#: what is not an error of the excerpt: how the book reads it
READING_NOTES = (
    ReadingNote("tda5341-t-typical", f"{NAME}, CAPCDM", "CAPCDM is sized with the typical 10 uA and no tolerance",
                "design advice, not a worst-case design, and the excerpt gives no current spread; the design chapter "
                "sizes the TDA5144's CAP-CD with its datasheet's spread and the capacitor's tolerance"),
)
