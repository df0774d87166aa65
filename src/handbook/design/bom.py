"""Bill of materials: the chosen parts with the reason for each value, written atomically as CSV."""
from __future__ import annotations

import csv
import os
import tempfile
from pathlib import Path


def rows(result: dict) -> list[dict]:
    """Reference, value (SI), tolerance, series, and why each value was chosen."""
    c, lim, cd = result["commutation"], result["current_limiter"], result["class_d"]
    sc, sl, sd = c.spec, lim.spec, cd.spec
    table = [
        ("C3", c.cap_cd, sc["tolerance"], sc["series"],
         f"CAP-CD: smallest value whose swing at {sc['rpm_min']:g} rpm fits the {sc['window']:g} V window at "
         f"-tolerance; reliable {c.rpm_min_reliable:.0f} to {c.rpm_max_reliable:.0f} rpm"),
        ("C4", c.cap_dc, sc["tolerance"], sc["series"], "CAP-DC: the slave timer needs the same value as CAP-CD"),
        ("R7", lim.r7, sl["r7_tolerance"], sl["r7_series"],
         f"current sense: smallest value that keeps every board's trip current in {sl['i_no_trip']:g}.."
         f"{sl['i_must_trip']:g} A ({lim.i_trip_min:.3f}..{lim.i_trip_max:.3f} A worst case); "
         f"{lim.p_r7:.3g} W at {sl['i_no_trip']:g} A"),
        ("R9", lim.r9, sl["resistor_tolerance"], sl["r9_series"],
         f"trip reference: largest smaller margin to the two limits with this R7 ({lim.binding} binds)"),
        ("R10", sl["r10"], sl["resistor_tolerance"], "", "board value (AN94002 parts list), reference divider"),
        ("R11", sl["r11"], sl["resistor_tolerance"], "", "board value, reference divider"),
        ("R12", sl["r12"], sl["resistor_tolerance"], "", "board value, level shift"),
        ("R13", sl["r13"], sl["resistor_tolerance"], "", "board value, level shift"),
        ("D1", sl["zener_voltage"], sl["zener_tolerance"], "", "zener bridging the level shift (BZX79-C8V2 on the board)"),
        ("R_OSC", cd.r_osc, 0.01, sd["r_osc_series"],
         f"sets f_sw = {cd.f_sw / 1e3:.1f} kHz: most efficient frequency meeting THD+N and clipping "
         f"({cd.binding} binds); heat sink {cd.theta_sa_required:.2f} K/W or better"),
        ("R_DLY", sd["r_dly"], 0.01, "", "dead-time resistor as specified (datasheet's recommended 5 k)"),
    ]
    return [{"reference": r, "value": v, "tolerance": t, "series": ser, "reason": why} for r, v, t, ser, why in table]


def write(table: list[dict], path: str | Path) -> None:
    """Write the BOM as CSV atomically: a complete file or none at all."""
    path = Path(path)
    fd, tmp = tempfile.mkstemp(prefix=".bom-", suffix=".csv", dir=path.parent if str(path.parent) else ".")
    try:
        with os.fdopen(fd, "w", newline="") as fh:
            w = csv.DictWriter(fh, fieldnames=["reference", "value", "tolerance", "series", "reason"])
            w.writeheader()
            w.writerows(table)
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise
