"""TCA5600 eq 1 to 6a: printed forms and their derivations from KVL and the coil's volt-second balance."""
from __future__ import annotations

import sympy as sp
from sympy.physics import units as u

from ...core.equation import Equation
from .data import NAME


def build() -> list[Equation]:
    """The seven equations share their symbols: one short literal table (data).

    Returns
    -------
    list of Equation
        Eq 1 to 6a: V_L+, V_L- (V), alpha, t1 (s), I_peak (A), L1 (H) and R1 (ohm), in the excerpt's order.
    """
    V, A, S, H, HZ, OHM = u.volt, u.ampere, u.second, u.henry, u.hertz, u.ohm
    Vo, Vreg, VF, Vcc, Vce, V12, VLp, VLm, a, t1, t2, f, Io, Ip, L, R1 = sp.symbols(
        r"V_{out2} V_{(9-8)} V_F V_{CC2} V_{CE(sat)} V_{12(H)} V_{L+} V_{L-} \alpha t_1 t_2 f I_{out2} I_{L(peak)} L_1 R_1",
        positive=True)
    Vc2 = sp.Symbol("V_{C2}", positive=True)
    volts = {s: V for s in (Vo, Vreg, VF, Vcc, Vce, V12, VLp, VLm)}
    eqs = [
        Equation(id="tca5600-eq1", source=f"{NAME}, eq (1)", title="Coil voltage while dumping", lhs=VLp, lhs_unit=V,
                 printed=Vo + Vreg + VF - Vcc,
                 derived=sp.solve(sp.Eq(Vcc + VLp, Vc2 + VF), VLp)[0].subs(Vc2, Vo + Vreg), units=volts,
                 law="KVL while dumping: V_CC2 + V_L = V_C2 + V_F, with C2 at the regulator's input V_out2 + V(9-8)"),
        Equation(id="tca5600-eq2", source=f"{NAME}, eq (2)", title="Coil voltage while charging", lhs=VLm, lhs_unit=V,
                 printed=Vcc - Vce - V12, derived=sp.solve(sp.Eq(Vcc, VLm + Vce + V12), VLm)[0], units=volts,
                 law="KVL while charging: V_CC2 = V_L + V_CE(sat) + the drop on R1, at most V12(H)",
                 note="Taking the R1 drop at its peak value V12(H) all through t1 is the 'coil losses neglected' "
                      "simplification: the coil sees a constant voltage, so its current is a straight ramp."),
        Equation(id="tca5600-eq3", source=f"{NAME}, eq (3)", title="Charge to dump time ratio", lhs=a, lhs_unit=sp.Integer(1),
                 printed=VLp / VLm, derived=sp.solve(sp.Eq(VLm * t1, VLp * t2), t1)[0] / t2, units=volts | {t2: S},
                 law="volt-second balance on the coil: V_L- t1 = V_L+ t2 (the current starts and ends at zero)"),
        Equation(id="tca5600-eq4", source=f"{NAME}, eq (4)", title="Charging time", lhs=t1, lhs_unit=S,
                 printed=1 / ((1 + 1 / a) * f), derived=sp.solve([sp.Eq(t1 + t2, 1 / f), sp.Eq(t1, a * t2)], [t1, t2])[t1],
                 units={a: sp.Integer(1), f: HZ}, law="t1 + t2 = 1/f with t1 = alpha t2"),
        Equation(id="tca5600-eq5", source=f"{NAME}, eq (5)", title="Peak coil current", lhs=Ip, lhs_unit=A,
                 printed=2 * Io * (1 + a),
                 derived=sp.solve(sp.Eq(Io, Ip / 2 * (1 / (1 + a))), Ip)[0], units={Io: A, a: sp.Integer(1)},
                 law="the output gets the falling half of a triangle: I_out = (I_peak / 2) t2 / (t1 + t2)",
                 note="'Peak current twice the average': the triangle's average over t2 is I_peak / 2; the "
                      "current must reach zero every cycle (discontinuous operation) for this to hold."),
        Equation(id="tca5600-eq6", source=f"{NAME}, eq (6)", title="Coil inductance", lhs=L, lhs_unit=H,
                 printed=VLm * t1 / Ip, derived=sp.solve(sp.Eq(VLm, L * Ip / t1), L)[0], units={VLm: V, t1: S, Ip: A},
                 law="V = L di/dt with a constant V_L- over t1 (coil resistance neglected)"),
        Equation(id="tca5600-eq6a", source=f"{NAME}, eq (6a)", title="Current-sense resistor", lhs=R1, lhs_unit=OHM,
                 printed=V12 / Ip, derived=sp.solve(sp.Eq(Ip * R1, V12), R1)[0], units={V12: V, Ip: A},
                 law="the switch turns off when the drop on R1 reaches V12(H)"),
    ]
    return eqs + coil()


def coil() -> list[Equation]:
    """The coil the converter design winds for L1 (the excerpt prints none of it): the gap's reluctance, the peak
    flux density, the winding loss and the temperature rise, each from a magnetic or thermal law.

    Returns
    -------
    list of Equation
        The records ``tca5600-gap``, ``tca5600-b-peak``, ``tca5600-winding`` and ``tca5600-rise``.
    """
    A, H, OHM, W, K, M = u.ampere, u.henry, u.ohm, u.watt, u.kelvin, u.meter
    L, N, Rc, Rg, I, Ae, B, phi, Irms, mlt, rp, Pcu, Pfe, Rth, dT = sp.symbols(
        r"L_1 N \mathcal{R}_{core} \mathcal{R}_{gap} I_{L(peak)} A B_{peak} \Phi I_{rms} \ell_{MLT} r' P_{Cu} "
        r"P_{core} R_{th} \Delta{}T", positive=True)
    where = f"{NAME} (the design's coil; no formula printed)"
    return [
        Equation(id="tca5600-gap", source=where, title="Reluctance the gaps must add", lhs=Rg, lhs_unit=1 / H,
                 printed=N ** 2 / L - Rc, derived=sp.solve(sp.Eq(L, N ** 2 / (Rc + Rg)), Rg)[0],
                 units={N: sp.Integer(1), L: H, Rc: 1 / H},
                 law="magnetic Ohm's law: L = N^2 / (R_core + R_gap), the core and its gaps in series",
                 note="PyOpenMagnetics' gap model turns the reluctance into a gap length (fringing included)."),
        Equation(id="tca5600-b-peak", source=where, title="Peak flux density", lhs=B, lhs_unit=u.tesla,
                 printed=L * I / (N * Ae), derived=sp.solve(sp.Eq(N * phi, L * I), phi)[0] / Ae,
                 units={L: H, I: A, N: sp.Integer(1), Ae: M ** 2},
                 law="flux linkage: N Phi = L I, and B = Phi / A over the section A the flux crosses (the centre "
                     "column, the narrowest section, or the core's effective area A_e)"),
        Equation(id="tca5600-winding", source=where, title="Winding loss", lhs=Pcu, lhs_unit=W,
                 printed=Irms ** 2 * N * mlt * rp, derived=Irms ** 2 * (N * mlt * rp),
                 units={Irms: A, N: sp.Integer(1), mlt: M, rp: OHM / M},
                 law="Joule: P = I_rms^2 R_dc, with R_dc = N turns of the mean length per turn at r' per metre",
                 note="DC resistance only: at the converter's tens of kHz the skin depth in copper (0.3 mm at "
                      "50 kHz) exceeds the thin wires the bobbins take."),
        Equation(id="tca5600-rise", source=where, title="Coil temperature rise", lhs=dT, lhs_unit=K,
                 printed=Rth * (Pcu + Pfe), derived=sp.solve(sp.Eq(Pcu + Pfe, dT / Rth), dT)[0],
                 units={Rth: K / W, Pcu: W, Pfe: W},
                 law="thermal Ohm's law: the losses through the core's thermal resistance to the air"),
    ]
