"""The TCA5600 converter coil's candidate cores, materials and wires, read from PyOpenMagnetics' database.

PyOpenMagnetics (PyPI, MIT, version pinned in requirements.txt) ships the OpenMagnetics database of core
shapes, materials and wires in its wheel. Its adviser takes tens of seconds per design, so the few
figures the coil design needs are read from that database once, for a narrowed candidate set, and
shipped as ``cores.json`` beside this module: :func:`load` reads it (no PyOpenMagnetics at design
time), :func:`build` rebuilds it (``python -m handbook.design.converter.cores`` writes it), and
``tests/design/converter/test_converter_cores.py`` rebuilds a sample of rows from PyOpenMagnetics to prove the file current.

Candidates: gapped two-piece ferrite sets of the families a small board coil uses (pot cores P, RM, EP,
E and EFD, from about 5 mm to 26 mm), each in two MnZn power ferrites made for 25 to 200 kHz (Ferroxcube
3C90, TDK N87), wound with IEC 60317 grade-1 enamelled round copper of 0.05 to 1 mm. Per shape: the
effective area, length and volume; the cross-sections the flux passes (PyOpenMagnetics'
``processedDescription.columns``: the centre column, which carries all the flux and holds the gap, the outer
legs together, and the database's ``minimumArea``) and the narrowest of them, ``a_min``; PyOpenMagnetics' own
gap model tabulated over the centre gap's length (``gap_lengths``, ``gap_reluctance``: Zhang's reluctance
of the ground centre gap, with fringing, in series with the outer legs' 5 um residual gaps in parallel, the
model ``calculate_inductance_from_number_turns_and_gapping`` uses); the bobbin's winding window, the mean
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
from importlib import resources
from pathlib import Path

#: the shipped table's name inside the package (pyproject's package-data ships it in the wheel)
RESOURCE = "cores.json"
#: the file in a source tree (what :func:`write` rewrites)
PATH = Path(__file__).with_name(RESOURCE)
#: the centre gaps tabulated (m): 10 um (twice the 5 um residual gap) to 5 mm, 61 points evenly in log, each
#: shape's up to half its centre column's height (a longer gap is no small board coil's)
GAP_GRID = tuple(10e-6 * (5e-3 / 10e-6) ** (k / 60) for k in range(61))
#: PyOpenMagnetics' gap reluctance model (the one its inductance calculation uses by default)
GAP_MODEL = "ZHANG"

#: shape families a small board coil of a few hundred uH at a few hundred mA uses, smallest to largest
SHAPES = ("P 7.4/4.0", "P 9/5", "P 11/7", "P 14/8", "P 18/11", "P 22/13", "P 26/16",
          "RM 4", "RM 5", "RM 6", "RM 7", "RM 8", "RM 10",
          "EP 7", "EP 10", "EP 13", "EP 17", "EP 20",
          "E 8.3/4", "E 13/7/4", "E 16/8/5", "E 20/10/6", "E 25/13/7",
          "EFD 10/5/3", "EFD 15/8/5", "EFD 20/10/7", "EFD 25/13/9")
#: MnZn power ferrites for 25..200 kHz, one from each of two makers
MATERIALS = ("3C90", "N87")
#: enamelled round copper, IEC 60317 grade 1, this range of copper diameters (m)
WIRE_RANGE = (0.05e-3, 1.0e-3)
#: temperatures (C) of the figures read: saturation hot, permeability and copper as stated
T_HOT, T_ROOM = 100.0, 25.0


def _core(pom, name: str, gap: float | None = None) -> dict:
    gapping = [] if gap is None else [{"type": "subtractive", "length": gap}]
    return pom.calculate_core_data({"functionalDescription": {
        "type": "two-piece set", "shape": name, "material": MATERIALS[0], "gapping": gapping, "numberStacks": 1}}, False)


def gap_reluctance(pom, name: str, gap: float) -> float:
    """PyOpenMagnetics' reluctance of every gap of the core with a centre gap ground to ``gap`` (A/Wb):
    the centre gap in series with the outer legs' residual gaps, those in parallel (Zhang's model).

    Parameters
    ----------
    pom : module
        The PyOpenMagnetics module.
    name : str
        The core shape's name in its database (e.g. "RM 8").
    gap : float
        The centre gap's length, m.

    Returns
    -------
    float
        The reluctance of all the core's gaps, A/Wb (1/H).
    """
    gaps = _core(pom, name, gap)["functionalDescription"]["gapping"]
    centre = sum(pom.calculate_gap_reluctance(g, GAP_MODEL)["reluctance"] for g in gaps if g["type"] != "residual")
    legs = [pom.calculate_gap_reluctance(g, GAP_MODEL)["reluctance"] for g in gaps if g["type"] == "residual"]
    return centre + (1 / sum(1 / x for x in legs) if legs else 0.0)


def _shape_row(pom, name: str) -> dict:
    core = _core(pom, name)
    proc = core["processedDescription"]
    eff = proc["effectiveParameters"]
    columns = proc["columns"]
    a_centre = sum(c["area"] for c in columns if c["type"] == "central")
    a_legs = sum(c["area"] for c in columns if c["type"] == "lateral")
    column_height = max(c["height"] for c in columns if c["type"] == "central")
    gaps = [g for g in GAP_GRID if g <= column_height / 2]
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
            "ve": eff["effectiveVolume"], "a_min": min(eff["minimumArea"], a_centre, a_legs),
            "a_min_database": eff["minimumArea"], "a_centre": a_centre, "a_legs": a_legs,
            "gap_lengths": gaps, "gap_reluctance": [gap_reluctance(pom, name, g) for g in gaps],
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
    """The table, read from PyOpenMagnetics' database (needs the PyOpenMagnetics package: a few seconds).

    Parameters
    ----------
    shapes : sequence of str
        The core shapes to read (names in PyOpenMagnetics' database).
    materials : sequence of str
        The core materials to read.
    wires : bool
        Read the wires too (False: the table has no ``wires``).

    Returns
    -------
    dict
        ``source`` (str: PyOpenMagnetics' version), ``shapes`` {name: row}, ``materials`` {name: row} and
        ``wires`` (a list of rows, thinnest first), in SI units as the module's description lists them (m, m^2,
        m^3, A/Wb, K/W, T, ohm/m; Steinmetz coefficients for W/m^3 with f in Hz and B in T).
    """
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
    """The shipped table (read once, as package data: it works from an installed wheel too).

    Returns
    -------
    dict
        The table as :func:`build` makes it (``source``, ``shapes``, ``materials``, ``wires``), cached: the same
        object on every call, not to be modified.
    """
    return json.loads(resources.files(__package__).joinpath(RESOURCE).read_text(encoding="utf-8"))


def write(path: Path = PATH) -> None:
    """Rebuild the table from PyOpenMagnetics (:func:`build`) and write it as JSON.

    Parameters
    ----------
    path : pathlib.Path
        The file to write (default: the shipped ``cores.json`` of a source tree).
    """
    path.write_text(json.dumps(build(), indent=1, sort_keys=True) + "\n")


if __name__ == "__main__":  # pragma: no cover
    write()
    print(f"wrote {PATH}")
