"""LM4651/LM4652 equations (3 to 12, and those the text implies): each function returns one record."""
from __future__ import annotations

import sympy as sp
from sympy.physics import units as u

from ...core.equation import Equation
from .data import NAME

V, A, F, S, OHM, W, K, HZ = u.volt, u.ampere, u.farad, u.second, u.ohm, u.watt, u.kelvin, u.hertz
t, C, R, Rint, Cint, f, T, x, P, Pout, RL, Rds, I = sp.symbols(
    r"t C R R_{int} C_{int} f T x P P_{out} R_L R_{DS(on)} I", positive=True)
Rf, Cf, L1, Cb, Tj, Ta, Pd, tjc, tcs, tsa = sp.symbols(
    r"R_f C_f L_1 C_{BYP} T_{jmax} T_{a} P_D \theta_{JC} \theta_{CS} \theta_{SA}", positive=True)
R1, R2, Rf11, Rf12 = sp.symbols("R_1 R_2 R_{f11} R_{f12}", positive=True)
tr, tf, tom, Cs, Rp, epsr, Ar, d = sp.symbols(r"t_r t_f T_{OVERMOD} C_{START} R_{SCKT} \epsilon_r A d", positive=True)
dV, Vk, Cfl1, Cfl2, Rfl3, Cin = sp.symbols("dV V_k C_{fl1} C_{fl2} R_{fl3} C_{IN}", positive=True)
w = sp.Symbol("omega", positive=True)
#: the printed (number-only) symbols: C_START_n is C_START / F, and so on
n = {s: sp.Symbol("{" + s.name + "}_{n}", positive=True) for s in (Cs, t, Rp, R, f, x)}  # braced: no double subscript


def _corner(r, c):
    """The corner of a first-order RC: omega R C = 1, as a frequency."""
    return sp.solve(sp.Eq(w * r * c, 1), w)[0] / (2 * sp.pi)


def eq1() -> Equation:
    return Equation(
        id="lm4651-eq1", source=f"{NAME}, eq (1)", title="Start-up time", lhs=t, lhs_unit=S, lhs_scale=S,
        printed=sp.Integer(84000) * n[Cs], scales={n[Cs]: Cs / F}, derived=sp.solve(sp.Eq(I * t, Cs * dV), t)[0],
        units={Cs: F, I: A, dV: V}, values={I: A / 84000, dV: V},
        law="charge balance on C_START; the datasheet gives only dV / I = 84 k (taken as 1 V / 11.9 uA)",
        note="The component table prints T_START = 8.5e4 C_START, eq 1 8.4e4.")


def eq2() -> Equation:
    return Equation(
        id="lm4651-eq2", source=f"{NAME}, eq (2)", title="C_START for a start-up time", lhs=Cs, lhs_unit=F,
        lhs_scale=F, printed=n[t] / 85000, scales={n[t]: t / S}, derived=t * I / dV, units={t: S, I: A, dV: V},
        values={I: A / 84000, dV: V}, law="eq 1 solved for C_START",
        note="eq 2 divides by 8.5e4 where eq 1 multiplies by 8.4e4 (1.2 % apart).")


def eq3() -> Equation:
    return Equation(
        id="lm4651-eq3", source=f"{NAME}, eq (3)", title="Short-circuit current limit", lhs=I, lhs_unit=A,
        lhs_scale=A, printed=10 ** 5 / (10 ** 4 * n[Rp] / (10 ** 4 + n[Rp])), scales={n[Rp]: Rp / OHM},
        derived=Vk * (1 / Rint + 1 / Rp), units={Rp: OHM, Rint: OHM, Vk: V},
        values={Rint: 10 ** 4 * OHM, Vk: 10 ** 5 * V},
        law="an internal 10 k in parallel with R_SCKT (conductances add) scales a fixed reference",
        note="The 1e5 hides a unit of volts (an internal reference times a current gain).")


def eq4() -> Equation:
    return Equation(
        id="lm4651-eq4", source=f"{NAME}, eq (4)", title="Dead time", lhs=T, lhs_unit=S, lhs_scale=S,
        printed=sp.Rational(17, 10 ** 13) * (500 + n[R]), scales={n[R]: R / OHM}, derived=Cint * (Rint + R),
        units={R: OHM, Rint: OHM, Cint: F}, values={Cint: sp.Rational(17, 10 ** 13) * F, Rint: 500 * OHM},
        printed_tex=r"1.7 \times 10^{-12} (500 + R_{DLY})", law="an RC delay: 1.7 pF charged through 500 ohm + R_DLY",
        note="As printed it gives 0.85 ns at R_DLY = 0 against the table's 27 ns.")


def eq5() -> Equation:
    return Equation(
        id="lm4651-eq5", source=f"{NAME}, eq (5)", title="Switching frequency", lhs=f, lhs_unit=HZ, lhs_scale=HZ,
        printed=10 ** 9 / (4000 + n[R]), scales={n[R]: R / OHM}, derived=1 / (Cint * (Rint + R)),
        units={R: OHM, Rint: OHM, Cint: F}, values={Cint: F / 10 ** 9, Rint: 4000 * OHM},
        law="an RC oscillator: period proportional to 1 nF x (4 k + R_OSC)")


def eq6() -> Equation:
    return Equation(
        id="lm4651-eq6", source=f"{NAME}, eq (6)", title="R_OSC for a frequency", lhs=R, lhs_unit=OHM, lhs_scale=OHM,
        printed=10 ** 9 / n[f] - 4000, scales={n[f]: f / HZ}, derived=sp.solve(sp.Eq(f, 1 / (Cint * (Rint + R))), R)[0],
        units={f: HZ, Rint: OHM, Cint: F}, values={Cint: F / 10 ** 9, Rint: 4000 * OHM}, law="eq 5 solved for R_OSC")


def eq7() -> Equation:
    return Equation(
        id="lm4651-eq7", source=f"{NAME}, eq (7)", title="Error-amplifier pole", lhs=f, lhs_unit=HZ,
        printed=1 / (2 * sp.pi * Rf * Cf), derived=_corner(Rf, Cf), units={Rf: OHM, Cf: F},
        law="the parallel R_f C_f: the pole where |1/(j omega C_f)| = R_f")


def eq8() -> Equation:
    return Equation(
        id="lm4651-eq8", source=f"{NAME}, eq (8)", title="Plane capacitance, eps0 = 0.22479 pF/in", lhs=C,
        lhs_unit=F, printed=sp.Rational("0.22479") * F / 10 ** 12 / u.inch * epsr * Ar / d,
        derived=u.vacuum_permittivity * epsr * Ar / d, units={Ar: u.inch ** 2, d: u.inch},
        law="parallel-plate capacitor", note="0.22479 pF/in is 0.05 % below eps0 = 0.22490 pF/in.")


def eq9() -> Equation:
    return Equation(
        id="lm4651-eq9", source=f"{NAME}, eq (9)", title="Switching loss fraction", lhs=x, lhs_unit=sp.Integer(1),
        printed=(tr + tf + tom) * f, derived=(tr + tf + tom) / (1 / f), units={tr: S, tf: S, tom: S, f: HZ},
        law="the fraction of each period spent in the edges and the over-modulation pulse")


def eq10() -> Equation:
    return Equation(
        id="lm4651-eq10", source=f"{NAME}, eq (10)", title="Switching dissipation", lhs=P, lhs_unit=W,
        printed=x * Pout / (1 - x), derived=sp.solve(sp.Eq(P, x * (Pout + P)), P)[0], units={Pout: W},
        law="a fraction x of the input power P_out + P is lost")


def conduction() -> Equation:
    return Equation(
        id="lm4651-conduction", source=f"{NAME}, Power Dissipation", title="Conduction dissipation", lhs=P,
        lhs_unit=W, printed=(sp.sqrt(Pout / RL)) ** 2 * (2 * Rds), derived=2 * Rds * Pout / RL,
        units={Pout: W, RL: OHM, Rds: OHM}, law="I_rms^2 through two on-resistances in series (the H-bridge)")


def eq11() -> Equation:
    return Equation(
        id="lm4651-eq11", source=f"{NAME}, eq (11)", title="Heat sink thermal resistance", lhs=tsa, lhs_unit=K / W,
        printed=(Tj - Ta) / Pd - tjc - tcs, derived=sp.solve(sp.Eq(Tj - Ta, Pd * (tjc + tcs + tsa)), tsa)[0],
        units={Tj: K, Ta: K, Pd: W, tjc: K / W, tcs: K / W}, law="thermal Ohm's law through three series resistances")


def eq12() -> Equation:
    return Equation(
        id="lm4651-eq12", source=f"{NAME}, eq (12) (reconstructed)", title="Closed-loop gain", lhs=sp.Symbol("G"),
        lhs_unit=sp.Integer(1), printed=(R2 / R1) * ((Rf11 + Rf12) / Rf12) - R2 / R1 + sp.Rational(1, 2),
        derived=R2 * Rf11 / (R1 * Rf12) + sp.Rational(1, 2), units={R1: OHM, R2: OHM, Rf11: OHM, Rf12: OHM},
        law="algebra only: the internal feedback amplifier is not described well enough to derive it",
        reconstructed="the OCR of the Example Design reads '[...] + .5].(3)'; the component table prints the same "
                      "formula without the '(3)', and it gives 10 R2/R1 + 0.5 = 7.5 for the printed R2 = 0.7 R1")


def fb_pole1() -> Equation:
    return Equation(
        id="lm4651-fb-pole1", source=f"{NAME}, components table, R_fl2", title="Feedback filter, first pole",
        lhs=f, lhs_unit=HZ, printed=1 / (2 * sp.pi * Rf12 * Cfl1), derived=_corner(Rf12, Cfl1),
        units={Rf12: OHM, Cfl1: F}, law="first-order RC low-pass: the corner where omega R C = 1",
        note="The capacitor values of figure 1 did not survive the OCR; R_fl1 = 10 R_fl2 keeps R_fl1 from loading it.")


def fb_pole2() -> Equation:
    return Equation(
        id="lm4651-fb-pole2", source=f"{NAME}, components table, R_fl3", title="Feedback filter, second pole",
        lhs=f, lhs_unit=HZ, printed=1 / (2 * sp.pi * Rfl3 * Cfl2), derived=_corner(Rfl3, Cfl2),
        units={Rfl3: OHM, Cfl2: F}, law="first-order RC low-pass",
        note="Should lie above the output filter's pole (datasheet text).")


def input_hp() -> Equation:
    return Equation(
        id="lm4651-input-hp", source=f"{NAME}, Example Design (implied; no formula printed)",
        title="Input high-pass (C_IN with R1)", lhs=f, lhs_unit=HZ, printed=1 / (2 * sp.pi * R1 * Cin),
        derived=sp.solve(sp.Eq(1 / (w * Cin), R1), w)[0] / (2 * sp.pi), units={R1: OHM, Cin: F},
        law="series C_IN into the inverting input's R1: the corner where |1/(j omega C_IN)| = R1",
        note="The text only says a lower R1 needs a larger C_IN; with R1 = 20 k a 10 Hz corner needs 0.8 uF.")


def output_filter() -> Equation:
    return Equation(
        id="lm4651-filter", source=f"{NAME}, Output Stage Filtering (reconstructed)", title="Bridge output filter",
        lhs=f, lhs_unit=HZ, printed=1 / (2 * sp.pi * sp.sqrt(L1 * 2 * Cb)),
        derived=sp.solve(sp.Eq(w ** 2 * 2 * L1 * Cb, 1), w)[0] / (2 * sp.pi), units={L1: u.henry, Cb: F},
        law="series resonance of the loop L1 - C_BYP - L1 (2 L1 with C_BYP)",
        reconstructed="the OCR reads 'f_C = 1/[2 pi (L_1 2C_BYP)/_2]'; the text's 'extra factor of 2' and a square "
                      "root give this form")


def build() -> list[Equation]:
    return [eq1(), eq2(), eq3(), eq4(), eq5(), eq6(), eq7(), eq8(), eq9(), eq10(), conduction(), eq11(), eq12(),
            fb_pole1(), fb_pole2(), input_hp(), output_filter()]
