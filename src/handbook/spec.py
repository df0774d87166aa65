"""Design specifications: a TOML file with optional tables [commutation], [current_limiter], [class_d].

Everything is checked before any computation: unknown tables and keys (with the near match), types,
finiteness and ranges (a charge current of 22 instead of 22e-6 is out of range), and limits that
contradict each other. A missing table or key takes the notes' values (``design.*_DEFAULTS``), so an
empty file designs the notes' own examples. All values are in SI units.
"""
from __future__ import annotations

import difflib
import math
import numbers
import tomllib
from pathlib import Path

from . import design
from .validate import InputError

TABLES = {
    "commutation": design.COMMUTATION_DEFAULTS,
    "current_limiter": design.LIMITER_DEFAULTS,
    "class_d": design.CLASS_D_DEFAULTS,
}

#: keys whose value is a name, not a number
TEXT_KEYS = {"series", "r7_series", "r9_series", "r_osc_series", "package"}
#: keys that must be whole numbers
INT_KEYS = {"pole_pairs"}

#: what each key means (for the README, the book and error messages)
DOCS = {
    "commutation": {
        "pole_pairs": "magnetic pole pairs n (whole number)",
        "rpm_min": "lowest speed that must commutate reliably, rpm",
        "rpm_max": "highest speed that must commutate reliably, rpm",
        "i_charge_min": "smallest CAP-CD charge current, A",
        "i_charge_max": "largest CAP-CD charge current, A",
        "window": "CAP-CD voltage window (lowest upper level less highest lower level), V",
        "min_excursion": "smallest swing still safe from noise, V",
        "tolerance": "capacitor tolerance, fraction (5 % = 0.05)",
        "series": "E-series to choose from (E3 .. E192)",
    },
    "current_limiter": {
        "i_no_trip": "current at or below which the limiter must never act, A",
        "i_must_trip": "current at or below which it must always have acted, A",
        "resistor_tolerance": "tolerance of R9..R13, fraction",
        "r7_tolerance": "tolerance of the sense resistor R7, fraction",
        "zener_voltage": "nominal zener voltage of D1, V",
        "zener_tolerance": "zener tolerance, fraction",
        "zener_tc": "largest zener temperature coefficient, V/K (0: no drift)",
        "temp_span": "temperature excursion either side of 25 C for the drift, K",
        "offset": "largest op-amp input offset, V",
        "r10": "R10, ohm", "r11": "R11, ohm", "r12": "R12, ohm", "r13": "R13, ohm",
        "r7_series": "series for R7", "r7_min": "smallest R7, ohm", "r7_max": "largest R7, ohm",
        "r9_series": "series for R9", "r9_min": "smallest R9, ohm", "r9_max": "largest R9, ohm",
    },
    "class_d": {
        "p_out": "output power that must not clip (1 % THD), W",
        "r_load": "load resistance, ohm",
        "supply": "supply rails +-V, V",
        "t_ambient": "highest ambient temperature, C",
        "package": "LM4652 package: 'TF' (isolated) or 'T'",
        "theta_cs": "case-to-sink thermal resistance, K/W",
        "theta_sa_available": "thermal resistance of the heat sink you have, K/W (leave out: report the one needed)",
        "thd_max": "THD+N limit at the test point, fraction (0.5 % = 0.005)",
        "thd_test_power": "output power of the THD+N test point, W",
        "r_dly": "dead-time resistor R_DLY, ohm",
        "r_osc_series": "series for R_OSC",
    },
}


def _check_value(table: str, key: str, value):
    name = f"{table}.{key}"
    if key in TEXT_KEYS:
        if not isinstance(value, str):
            raise InputError(f"{name} = {value!r}: expected a name in quotes, e.g. {TABLES[table][key]!r}")
        return value
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise InputError(f"{name} = {value!r}: expected a number ({DOCS[table][key]})")
    if not math.isfinite(value):
        raise InputError(f"{name} = {value!r}: expected a finite number ({DOCS[table][key]})")
    if key in INT_KEYS and value != int(value):
        raise InputError(f"{name} = {value!r}: expected a whole number ({DOCS[table][key]})")
    return int(value) if key in INT_KEYS else float(value)


def parse(data: dict) -> dict:
    """Checked spec: {table: {key: value}} with every table present (missing keys left to the defaults)."""
    if not isinstance(data, dict):
        raise InputError("the specification must be a TOML document with tables")
    out = {t: {} for t in TABLES}
    for table, body in data.items():
        if table not in TABLES:
            near = difflib.get_close_matches(table, TABLES, n=1)
            raise InputError(f"unknown table [{table}]" + (f": did you mean [{near[0]}]?" if near else
                                                            f": use {', '.join('[' + t + ']' for t in TABLES)}"))
        if not isinstance(body, dict):
            raise InputError(f"{table} must be a table ([{table}]), not a value")
        for key, value in body.items():
            if key not in TABLES[table]:
                near = difflib.get_close_matches(key, TABLES[table], n=1)
                raise InputError(f"unknown key {table}.{key}" + (f": did you mean {table}.{near[0]}?" if near else
                                                                 f": known keys are {', '.join(TABLES[table])}"))
            out[table][key] = _check_value(table, key, value)
    return out


def load(path: str | Path) -> dict:
    try:
        text = Path(path).read_bytes()
    except OSError as exc:
        raise InputError(f"cannot read {path}: {exc.strerror}") from None
    try:
        data = tomllib.loads(text.decode("utf-8"))
    except (tomllib.TOMLDecodeError, UnicodeDecodeError) as exc:
        raise InputError(f"{path} is not valid TOML: {exc}") from None
    return parse(data)


def check(spec: dict) -> dict:
    """Every range and contradiction check of every table, before any solver runs."""
    design._commutation_checked(spec["commutation"])
    design._limiter_checked(spec["current_limiter"])
    design._class_d_checked(spec["class_d"])
    return spec


def run(spec: dict) -> dict:
    """All three designs. Raises InputError for bad input, Infeasible (with .table) for unmeetable specs."""
    check(spec)
    out = {}
    for table, fn in (("commutation", design.design_commutation), ("current_limiter", design.design_current_limiter),
                      ("class_d", design.design_class_d)):
        try:
            out[table] = fn(spec[table])
        except design.Infeasible as exc:
            exc.table = table
            raise
    return out


#: the keys each design reports in the JSON output (SI units)
OUTPUT_KEYS = {
    "commutation": ("cap_cd", "cap_dc", "rpm_min_reliable", "rpm_max_reliable", "noise_margin", "binding"),
    "current_limiter": ("r7", "r9", "i_trip_min", "i_trip_max", "i_trip_nominal", "p_r7", "v_cs_nominal",
                        "margin_low", "margin_high", "binding"),
    "class_d": ("f_sw", "r_osc", "efficiency", "p_dissipation", "theta_sa_required", "t_junction", "thd_n",
                "p_clip", "binding"),
}


def summary(result: dict) -> dict:
    return {t: {k: result[t][k] for k in OUTPUT_KEYS[t]} for t in OUTPUT_KEYS}
