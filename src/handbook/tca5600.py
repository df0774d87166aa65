"""TCA5600/TCF5600 (Motorola): the flyback DC/DC converter's coil, eq 1 to 6a of the excerpt.

The converter has no time base: the switch turns on, the coil current rises until the drop across
R1 reaches V12(H), the switch turns off and the coil dumps its energy into C2 (the programmable
regulator's input) until the current is zero. Eq 1 to 6a size L1 and R1 for the worst operating
point, the lowest supply with the largest load. The excerpt prints no worked numbers and no public
copy of the electrical characteristics was found (datasheet_facts.md), so every device value in
``ASSUMED`` is an assumption, stated with its reason.
"""
from __future__ import annotations

import functools

from .examples import TextErratum
from .validate import InputError

NOTE = "TCA5600"

#: values the excerpt prints (application circuit, figure 13) and states
PRINTED = {"l1": 300e-6, "r1": 0.68, "regulator_drop": 2.5, "f_min": 20e3}

#: assumed device values and operating point, with the reason for each
ASSUMED = {
    "v12h": (0.4, "V: current-sense threshold V12(H); comparator thresholds of this kind are a few hundred mV"),
    "vce_sat": (0.5, "V: saturation of the internal switch at a few hundred mA"),
    "v_f": (0.8, "V: forward drop of a silicon rectifier at a few hundred mA"),
    "v_cc2_min": (8.0, "V: lowest converter supply (e.g. a 12 V battery at cranking)"),
    "v_out2": (12.0, "V: the programmable regulator's output"),
    "i_out2": (0.05, "A: largest load of the programmable regulator"),
}


def params(**overrides) -> dict:
    p = {k: v[0] for k, v in ASSUMED.items()}
    p.update({"regulator_drop": PRINTED["regulator_drop"], "f_min": PRINTED["f_min"]})
    p.update(overrides)
    return p


def coil_voltages(p: dict) -> tuple[float, float]:
    """Eq 1 and 2 (KVL): (V_L+ while dumping, V_L- while charging)."""
    vl_plus = p["v_out2"] + p["regulator_drop"] + p["v_f"] - p["v_cc2_min"]
    vl_minus = p["v_cc2_min"] - p["vce_sat"] - p["v12h"]
    if vl_plus <= 0 or vl_minus <= 0:
        raise InputError(f"no flyback operation: V_L+ = {vl_plus:.3g} V and V_L- = {vl_minus:.3g} V must both be "
                         f"positive (the output side must sit above the supply, the supply above the switch drops)")
    return vl_plus, vl_minus


def design(p: dict) -> dict:
    """Eq 3 to 6a at the worst operating point: alpha, t1, I_peak, L1 and R1."""
    vl_plus, vl_minus = coil_voltages(p)
    alpha = vl_plus / vl_minus
    t1 = 1 / ((1 + 1 / alpha) * p["f_min"])
    i_peak = 2 * p["i_out2"] * (1 + alpha)
    return {"vl_plus": vl_plus, "vl_minus": vl_minus, "alpha": alpha, "t1": t1, "t2": t1 / alpha,
            "i_peak": i_peak, "l1": vl_minus * t1 / i_peak, "r1": p["v12h"] / i_peak}


def operating_point(l1: float, r1: float, p: dict) -> dict:
    """What given L1 and R1 do at the operating point: the peak current is set by R1, the free-running
    frequency by L1, and the load they can carry by the triangle's average."""
    vl_plus, vl_minus = coil_voltages(p)
    alpha = vl_plus / vl_minus
    i_peak = p["v12h"] / r1
    t1 = l1 * i_peak / vl_minus
    return {"i_peak": i_peak, "t1": t1, "f": 1 / (t1 * (1 + 1 / alpha)), "i_out_max": i_peak / (2 * (1 + alpha))}


def equations() -> list:
    return list(_equations())


@functools.lru_cache(maxsize=1)
def _equations() -> tuple:
    import sympy as sp
    from sympy.physics import units as u

    from .registry import Equation

    V, A, S, H, HZ, OHM = u.volt, u.ampere, u.second, u.henry, u.hertz, u.ohm
    Vo, Vreg, VF, Vcc, Vce, V12, VLp, VLm, a, t1, t2, f, Io, Ip, L, R1 = sp.symbols(
        r"V_{out2} V_{(9-8)} V_F V_{CC2} V_{CE(sat)} V_{12(H)} V_{L+} V_{L-} \alpha t_1 t_2 f I_{out2} I_{L(peak)} L_1 R_1",
        positive=True)
    Vc2 = sp.Symbol("V_{C2}", positive=True)
    volts = {s: V for s in (Vo, Vreg, VF, Vcc, Vce, V12, VLp, VLm)}
    eqs = [
        Equation(id="tca5600-eq1", source=f"{NOTE}, eq (1)", title="Coil voltage while dumping", lhs=VLp, lhs_unit=V,
                 printed=Vo + Vreg + VF - Vcc,
                 derived=sp.solve(sp.Eq(Vcc + VLp, Vc2 + VF), VLp)[0].subs(Vc2, Vo + Vreg), units=volts,
                 law="KVL while dumping: V_CC2 + V_L = V_C2 + V_F, with C2 at the regulator's input V_out2 + V(9-8)"),
        Equation(id="tca5600-eq2", source=f"{NOTE}, eq (2)", title="Coil voltage while charging", lhs=VLm, lhs_unit=V,
                 printed=Vcc - Vce - V12, derived=sp.solve(sp.Eq(Vcc, VLm + Vce + V12), VLm)[0], units=volts,
                 law="KVL while charging: V_CC2 = V_L + V_CE(sat) + the drop on R1, at most V12(H)",
                 note="Taking the R1 drop at its peak value V12(H) all through t1 is the 'coil losses neglected' "
                      "simplification: the coil sees a constant voltage, so its current is a straight ramp."),
        Equation(id="tca5600-eq3", source=f"{NOTE}, eq (3)", title="Charge to dump time ratio", lhs=a, lhs_unit=sp.Integer(1),
                 printed=VLp / VLm, derived=sp.solve(sp.Eq(VLm * t1, VLp * t2), t1)[0] / t2, units=volts | {t2: S},
                 law="volt-second balance on the coil: V_L- t1 = V_L+ t2 (the current starts and ends at zero)"),
        Equation(id="tca5600-eq4", source=f"{NOTE}, eq (4)", title="Charging time", lhs=t1, lhs_unit=S,
                 printed=1 / ((1 + 1 / a) * f), derived=sp.solve([sp.Eq(t1 + t2, 1 / f), sp.Eq(t1, a * t2)], [t1, t2])[t1],
                 units={a: sp.Integer(1), f: HZ}, law="t1 + t2 = 1/f with t1 = alpha t2"),
        Equation(id="tca5600-eq5", source=f"{NOTE}, eq (5)", title="Peak coil current", lhs=Ip, lhs_unit=A,
                 printed=2 * Io * (1 + a),
                 derived=sp.solve(sp.Eq(Io, Ip / 2 * (1 / (1 + a))), Ip)[0], units={Io: A, a: sp.Integer(1)},
                 law="the output gets the falling half of a triangle: I_out = (I_peak / 2) t2 / (t1 + t2)",
                 note="'Peak current twice the average': the triangle's average over t2 is I_peak / 2; the "
                      "current must reach zero every cycle (discontinuous operation) for this to hold."),
        Equation(id="tca5600-eq6", source=f"{NOTE}, eq (6)", title="Coil inductance", lhs=L, lhs_unit=H,
                 printed=VLm * t1 / Ip, derived=sp.solve(sp.Eq(VLm, L * Ip / t1), L)[0], units={VLm: V, t1: S, Ip: A},
                 law="V = L di/dt with a constant V_L- over t1 (coil resistance neglected)"),
        Equation(id="tca5600-eq6a", source=f"{NOTE}, eq (6a)", title="Current-sense resistor", lhs=R1, lhs_unit=OHM,
                 printed=V12 / Ip, derived=sp.solve(sp.Eq(Ip * R1, V12), R1)[0], units={V12: V, Ip: A},
                 law="the switch turns off when the drop on R1 reaches V12(H)"),
    ]
    for e in eqs:
        e.chapter = "tca5600"
    return tuple(eqs)


def examples(p: dict | None = None, chapter: str | None = None) -> list[dict]:
    """The excerpt prints no calculated numbers: nothing to recompute."""
    return []


TEXT_ERRATA = [
    TextErratum("tca5600-t-values", f"{NOTE}, DC/DC converter", "no worked numbers, and no public electrical "
                "characteristics for V12(H), V_CE(sat) and V_F", "datasheet_facts.md: no public copy found",
                "the application values L1 = 300 uH and R1 = 0.68 ohm can only be checked against assumed device values"),
]
