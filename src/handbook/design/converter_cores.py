"""The TCA5600 converter coil's candidate cores, materials and wires, read from PyOpenMagnetics' database.

PyOpenMagnetics (PyPI, MIT, version pinned in requirements.txt) ships the OpenMagnetics database of core
shapes, materials and wires in its wheel. Its adviser takes tens of seconds per design, so the few
figures the coil design needs are read from that database once, for a narrowed candidate set, and
shipped as ``converter_cores.json`` beside this module: :func:`load` reads it (no PyOpenMagnetics at design
time), :func:`build` rebuilds it (``python -m handbook.design.converter_cores`` writes it), and
``tests/design/test_converter.py`` rebuilds a sample of rows from PyOpenMagnetics to prove the file current.

Candidates: gapped two-piece ferrite sets of the families a small board coil uses (pot cores P, RM, EP,
E and EFD, from about 5 mm to 26 mm), each in two MnZn power ferrites made for 25 to 200 kHz (Ferroxcube
3C90, TDK N87), wound with IEC 60317 grade-1 enamelled round copper of 0.05 to 1 mm. Per shape: the
effective area, length and volume, the narrowest cross-section, the bobbin's winding window, the mean
length of a turn at the middle of that window, and the thermal resistance PyOpenMagnetics gives the core
(Maniktala's empirical 53 K/W x (V_e / cm^3)^-0.54). Per material: the saturation flux density at 25 and
100 C, the initial permeability at 25 C, and the Steinmetz ranges (k, alpha, beta, temperature factors
ct0, ct1, ct2). Per wire: copper and outer diameter (the largest, else the nominal) and the resistance per metre at
100 C.
"""
from __future__ import annotations

import functools
import json
import math
from pathlib import Path

#: the shipped table
PATH = Path(__file__).with_name("converter_cores.json")

#: shape families a small board coil of a few hundred uH at a few hundred mA uses, smallest to largest
SHAPES = ("P 9/5", "P 11/7", "P 14/8", "P 18/11", "P 22/13", "P 26/16",
          "RM 4", "RM 5", "RM 6", "RM 7", "RM 8", "RM 10",
          "EP 7", "EP 10", "EP 13", "EP 17", "EP 20",
          "E 13/7/4", "E 16/8/5", "E 20/10/6", "E 25/13/7",
          "EFD 10/5/3", "EFD 15/8/5", "EFD 20/10/7", "EFD 25/13/9")
#: MnZn power ferrites for 25..200 kHz, one from each of two makers
MATERIALS = ("3C90", "N87")
#: enamelled round copper, IEC 60317 grade 1, this range of copper diameters (m)
WIRE_RANGE = (0.05e-3, 1.0e-3)
#: temperatures (C) of the figures read: saturation hot, permeability and copper as stated
T_HOT, T_ROOM = 100.0, 25.0


def _shape_row(pom, name: str) -> dict:
    core = pom.calculate_core_data({"functionalDescription": {
        "type": "two-piece set", "shape": name, "material": MATERIALS[0], "gapping": [], "numberStacks": 1}}, False)
    proc = core["processedDescription"]
    eff = proc["effectiveParameters"]
    bobbin = pom.create_simple_bobbin_from_core(core)["processedDescription"]
    window = bobbin["windingWindows"][0]
    # mean turn at the middle of the bobbin's window; the bobbin's column width/depth are half-dimensions
    a, b, w = bobbin["columnWidth"], bobbin["columnDepth"], window["width"]
    if bobbin["columnShape"] == "round":
        mlt = 2 * math.pi * (a + w / 2)
    else:
        mlt = 4 * (a + b) + math.pi * w
    ambient = 25.0
    r_th = pom.calculate_temperature_from_core_thermal_resistance(core, 1.0) - ambient
    return {"family": name.split()[0], "ae": eff["effectiveArea"], "le": eff["effectiveLength"],
            "ve": eff["effectiveVolume"], "a_min": eff["minimumArea"],
            "column_shape": bobbin["columnShape"], "column_half_width": a, "column_half_depth": b,
            "window_area": window["area"], "window_width": w, "window_height": window["height"],
            "mlt": mlt, "r_th": r_th, "width": proc["width"], "height": proc["height"], "depth": proc["depth"]}


def _material_row(pom, name: str) -> dict:
    m = pom.find_core_material_by_name(name)
    sat = {float(s["temperature"]): s["magneticFluxDensity"] for s in m["saturation"]}
    ranges = [{"f_low": r["minimumFrequency"], "f_high": r["maximumFrequency"], "k": r["k"], "alpha": r["alpha"],
               "beta": r["beta"], "ct0": r["ct0"], "ct1": r["ct1"], "ct2": r["ct2"]}
              for method in m["volumetricLosses"]["default"] if method.get("method") == "steinmetz"
              for r in method["ranges"]]
    return {"manufacturer": m["manufacturerInfo"]["name"], "datasheet": m["manufacturerInfo"]["datasheetUrl"],
            "b_sat_hot": sat[T_HOT], "b_sat_room": sat[T_ROOM],
            "mu_i": pom.get_material_permeability(name, T_ROOM, 0.0, 25e3),
            "steinmetz": sorted(ranges, key=lambda r: r["f_low"])}


def _wire_rows(pom) -> list[dict]:
    rows = []
    for name in pom.get_wire_names():
        if not (name.startswith("Round ") and name.endswith("- Grade 1")):
            continue
        w = pom.find_wire_by_name(name)
        if w.get("standard") != "IEC 60317":
            continue
        d = w["conductingDiameter"]["nominal"]
        if not WIRE_RANGE[0] <= d <= WIRE_RANGE[1] * (1 + 1e-9):
            continue
        outer = w["outerDiameter"]
        rows.append({"name": name, "d_cu": d, "d_outer": outer["maximum"] or outer["nominal"],
                     "r_per_m_hot": pom.calculate_dc_resistance_per_meter(w, T_HOT)})
    return sorted(rows, key=lambda r: r["d_cu"])


def build(shapes=SHAPES, materials=MATERIALS, wires: bool = True) -> dict:
    """The table, read from PyOpenMagnetics' database (needs the PyOpenMagnetics package: a few seconds)."""
    from importlib.metadata import version

    import PyOpenMagnetics as pom

    out = {"source": f"PyOpenMagnetics {version('PyOpenMagnetics')} database (OpenMagnetics MAS)",
           "shapes": {s: _shape_row(pom, s) for s in shapes},
           "materials": {m: _material_row(pom, m) for m in materials}}
    if wires:
        out["wires"] = _wire_rows(pom)
    return out


@functools.cache
def load() -> dict:
    """The shipped table (read once)."""
    return json.loads(PATH.read_text())


def write(path: Path = PATH) -> None:
    path.write_text(json.dumps(build(), indent=1, sort_keys=True) + "\n")


if __name__ == "__main__":  # pragma: no cover
    write()
    print(f"wrote {PATH}")
