"""What the converter tests share: eq 1 to 6a written out again, and PyOpenMagnetics' own figures of a core."""
import math
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
MU0 = 4e-7 * math.pi
#: E96 decade (IEC 60063), written out
E96 = (1.00, 1.02, 1.05, 1.07, 1.10, 1.13, 1.15, 1.18, 1.21, 1.24, 1.27, 1.30, 1.33, 1.37, 1.40, 1.43, 1.47, 1.50,
       1.54, 1.58, 1.62, 1.65, 1.69, 1.74, 1.78, 1.82, 1.87, 1.91, 1.96, 2.00, 2.05, 2.10, 2.15, 2.21, 2.26, 2.32,
       2.37, 2.43, 2.49, 2.55, 2.61, 2.67, 2.74, 2.80, 2.87, 2.94, 3.01, 3.09, 3.16, 3.24, 3.32, 3.40, 3.48, 3.57,
       3.65, 3.74, 3.83, 3.92, 4.02, 4.12, 4.22, 4.32, 4.42, 4.53, 4.64, 4.75, 4.87, 4.99, 5.11, 5.23, 5.36, 5.49,
       5.62, 5.76, 5.90, 6.04, 6.19, 6.34, 6.49, 6.65, 6.81, 6.98, 7.15, 7.32, 7.50, 7.68, 7.87, 8.06, 8.25, 8.45,
       8.66, 8.87, 9.09, 9.31, 9.53, 9.76)


def hand_operating_point(vcc=8.0, vout=12.0, drop=2.5, vf=0.8, vce=0.5, v12h=0.4, iout=0.05, f=20e3):
    """Eq 1 to 6a of the TCA5600 excerpt, written out again."""
    vl_plus = vout + drop + vf - vcc  # eq 1
    vl_minus = vcc - vce - v12h  # eq 2
    alpha = vl_plus / vl_minus  # eq 3
    t1 = 1 / ((1 + 1 / alpha) * f)  # eq 4
    i_peak = 2 * iout * (1 + alpha)  # eq 5
    return {"alpha": alpha, "t1": t1, "t2": 1 / f - t1, "i_peak": i_peak, "l1": vl_minus * t1 / i_peak,
            "r1": v12h / i_peak}


def hand_frequency(vcc, inductance, i_peak, vout=12.0, drop=2.5, vf=0.8, vce=0.5, v12h=0.4):
    """1 / (t1 + t2) with t1 = L I / V_L- and t2 = L I / V_L+."""
    return 1 / (inductance * i_peak / (vcc - vce - v12h) + inductance * i_peak / (vout + drop + vf - vcc))


def pom_core(pom, shape, material, gap=None):
    gapping = [] if gap is None else [{"type": "subtractive", "length": gap}]
    return pom.calculate_core_data({"functionalDescription": {"type": "two-piece set", "shape": shape,
                                                              "material": material, "gapping": gapping,
                                                              "numberStacks": 1}}, False)


def pom_inductance(pom, shape, material, gap, turns, wire="Round 0.1 - Grade 1", r=None):
    """PyOpenMagnetics' own inductance (its reluctance model: Zhang's gap with fringing, residual gaps)."""
    core = pom_core(pom, shape, material, gap)
    coil = {"bobbin": pom.create_simple_bobbin_from_core(core), "functionalDescription": [
        {"name": "Primary", "numberTurns": turns, "numberParallels": 1, "wire": wire, "isolationSide": "primary"}]}
    f, i_pk, t1 = (20e3, 0.2, 25e-6) if r is None else (r.spec["f_min"], r.i_peak_max, r.t1)
    op = {"name": "op", "conditions": {"ambientTemperature": 25}, "excitationsPerWinding": [{
        "name": "Primary", "frequency": f,
        "current": {"waveform": {"data": [0, i_pk, 0, 0], "time": [0, t1, 0.999999 / f, 1 / f]}},
        "voltage": {"waveform": {"data": [7, 7, -7, -7], "time": [0, t1, t1, 1 / f]}}}]}
    inputs = pom.process_inputs({"designRequirements": {"magnetizingInductance": {"nominal": 1e-3},
                                                        "turnsRatios": []}, "operatingPoints": [op]})
    return pom.calculate_inductance_from_number_turns_and_gapping(core, coil, inputs["operatingPoints"][0],
                                                                  {"reluctance": "ZHANG"})


def catalogue(pom, shape: str, material: str) -> dict:
    """Areas from PyOpenMagnetics' own geometry (processedDescription.columns), B_sat and mu_i from its data."""
    core = pom_core(pom, shape, material)
    proc = core["processedDescription"]
    cols = proc["columns"]
    m = pom.find_core_material_by_name(material)
    sat = {s["temperature"]: s["magneticFluxDensity"] for s in m["saturation"]}
    centre = sum(c["area"] for c in cols if c["type"] == "central")
    legs = sum(c["area"] for c in cols if c["type"] == "lateral")
    return {"centre": centre, "narrowest": min(centre, legs, proc["effectiveParameters"]["minimumArea"]),
            "ve": proc["effectiveParameters"]["effectiveVolume"],
            "window": pom.create_simple_bobbin_from_core(core)["processedDescription"]["windingWindows"][0]["area"],
            "b_sat": lambda t: sat[25] + (sat[100] - sat[25]) * (t - 25) / 75}
