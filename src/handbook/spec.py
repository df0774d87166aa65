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
    out = run_each(spec)
    for result in out.values():
        if isinstance(result, design.Infeasible):
            raise result
    return out


def run_each(spec: dict) -> dict:
    """Each design on its own: {table: result dict, or the Infeasible saying what can be met}."""
    check(spec)
    out = {}
    for table, fn in (("commutation", design.design_commutation), ("current_limiter", design.design_current_limiter),
                      ("class_d", design.design_class_d)):
        try:
            out[table] = fn(spec[table])
        except design.Infeasible as exc:
            exc.table = table
            out[table] = exc
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


def bom(result: dict) -> list[dict]:
    """Bill of materials: reference, value (SI), tolerance, series, and why each value was chosen."""
    c, lim, cd = result["commutation"], result["current_limiter"], result["class_d"]
    sc, sl, sd = c["spec"], lim["spec"], cd["spec"]
    rows = [
        ("C3", c["cap_cd"], sc["tolerance"], sc["series"],
         f"CAP-CD: smallest value whose swing at {sc['rpm_min']:g} rpm fits the {sc['window']:g} V window at -tolerance; "
         f"reliable {c['rpm_min_reliable']:.0f} to {c['rpm_max_reliable']:.0f} rpm"),
        ("C4", c["cap_dc"], sc["tolerance"], sc["series"], "CAP-DC: the slave timer needs the same value as CAP-CD"),
        ("R7", lim["r7"], sl["r7_tolerance"], sl["r7_series"],
         f"current sense: smallest value that keeps every board's trip current in {sl['i_no_trip']:g}..{sl['i_must_trip']:g} A "
         f"({lim['i_trip_min']:.3f}..{lim['i_trip_max']:.3f} A worst case); {lim['p_r7']:.3g} W at {sl['i_no_trip']:g} A"),
        ("R9", lim["r9"], sl["resistor_tolerance"], sl["r9_series"],
         f"trip reference: largest smaller margin to the two limits with this R7 ({lim['binding']} binds)"),
        ("R10", sl["r10"], sl["resistor_tolerance"], "", "board value (AN94002 parts list), reference divider"),
        ("R11", sl["r11"], sl["resistor_tolerance"], "", "board value, reference divider"),
        ("R12", sl["r12"], sl["resistor_tolerance"], "", "board value, level shift"),
        ("R13", sl["r13"], sl["resistor_tolerance"], "", "board value, level shift"),
        ("D1", sl["zener_voltage"], sl["zener_tolerance"], "", "zener bridging the level shift (BZX79-C8V2 on the board)"),
        ("R_OSC", cd["r_osc"], 0.01, sd["r_osc_series"],
         f"sets f_sw = {cd['f_sw'] / 1e3:.1f} kHz: most efficient frequency meeting THD+N and clipping "
         f"({cd['binding']} binds); heat sink {cd['theta_sa_required']:.2f} K/W or better"),
        ("R_DLY", sd["r_dly"], 0.01, "", "dead-time resistor as specified (datasheet's recommended 5 k)"),
    ]
    return [{"reference": r, "value": v, "tolerance": t, "series": ser, "reason": why} for r, v, t, ser, why in rows]


def write_bom(rows: list[dict], path: str | Path) -> None:
    """Write the BOM as CSV atomically: a complete file or none at all."""
    import csv
    import os
    import tempfile

    path = Path(path)
    fd, tmp = tempfile.mkstemp(prefix=".bom-", suffix=".csv", dir=path.parent if str(path.parent) else ".")
    try:
        with os.fdopen(fd, "w", newline="") as fh:
            w = csv.DictWriter(fh, fieldnames=["reference", "value", "tolerance", "series", "reason"])
            w.writeheader()
            w.writerows(rows)
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise
