"""LM4651/LM4652 equations (3 to 12, and those the text implies): each function returns one record."""
from __future__ import annotations

import functools
import math

import sympy as sp
from sympy.physics import units as u

from ...core.claim import Printed
from ...core.equation import Equation, TablePoint
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
#: the printed (number-only) symbols, written as ISO 80000-1 writes a quantity's numerical value in a unit:
#: {C_START}_F is C_START / F
Rosc, Rdly = sp.symbols("R_{OSC} R_{DLY}", positive=True)
_BASE_TEX = {Cs: r"\mathrm{F}", t: r"\mathrm{s}", Rp: r"\Omega", R: r"\Omega", f: r"\mathrm{Hz}", x: "1",
             Rosc: r"\Omega", Rdly: r"\Omega"}
n = {s: sp.Symbol(r"\{" + s.name + r"\}" + ("" if u_ == "1" else "_{" + u_ + "}"), positive=True)
     for s, u_ in _BASE_TEX.items()}


def _corner(r, c):
    """The corner of a first-order RC: omega R C = 1, as a frequency."""
    return sp.solve(sp.Eq(w * r * c, 1), w)[0] / (2 * sp.pi)


#: the label of an empirical equation's "derived" line: there is no derivation, only the source's own figures
NO_LAW = "none: the datasheet does not show the circuit; the printed form at the datasheet's own figures"
_KOHM = r"\,\mathrm{k\Omega}"


def _pt(where, at, inputs, text, unit, sig=None, through=None) -> TablePoint:
    return TablePoint(where=where, at=at, inputs=inputs, figure=Printed(text, unit, sig), through=through)


def eq1() -> Equation:
    """Eq 1: the start-up time, 8.4e4 C_START seconds.

    Returns
    -------
    Equation
        The record ``lm4651-eq1``: the start-up time (s) against C_START (F), empirical.
    """
    return Equation(
        id="lm4651-eq1", source=f"{NAME}, eq (1)", title="Start-up time", lhs=t, lhs_unit=S, lhs_scale=S,
        printed=sp.Integer(84000) * n[Cs], scales={n[Cs]: Cs / F}, units={Cs: F}, law=NO_LAW, empirical=True,
        fitted_to="an unstated figure: the datasheet gives neither the START pin's charge current nor its voltage "
                  "swing, only their ratio, 84 k (s/F)",
        table=(_pt("Start Up Sequence: C_START = 10 uF checks 'approximately every second'",
                   r"C_{START} = 10\,\mu\mathrm{F}", {Cs: 10e-6}, "1", "s"),),
        note="The component table prints T_START = 8.5e4 C_START, eq 1 8.4e4 (1.2 % apart).")


def eq2() -> Equation:
    """Eq 2: C_START for a start-up time, t / 8.5e4 farads.

    Returns
    -------
    Equation
        The record ``lm4651-eq2``: C_START (F) against the start-up time (s), empirical.
    """
    return Equation(
        id="lm4651-eq2", source=f"{NAME}, eq (2)", title="C_START for a start-up time", lhs=Cs, lhs_unit=F,
        lhs_scale=F, printed=n[t] / 85000, scales={n[t]: t / S}, units={t: S}, law=NO_LAW, empirical=True,
        fitted_to="the component table's T_START = 8.5e4 C_START, solved for C_START (eq 1 multiplies by 8.4e4)",
        table=(_pt("Start Up Sequence: 'approximately every second' with C_START = 10 uF", r"t_{START} = 1\,\mathrm{s}",
                   {t: 1.0}, "10", "uF"),),
        note="eq 2 divides by 8.5e4 where eq 1 multiplies by 8.4e4 (1.2 % apart).")


def eq3() -> Equation:
    """Eq 3: the short-circuit current limit against R_SCKT.

    Returns
    -------
    Equation
        The record ``lm4651-eq3``: the current limit (A) against R_SCKT (ohm), empirical.
    """
    return Equation(
        id="lm4651-eq3", source=f"{NAME}, eq (3)", title="Short-circuit current limit", lhs=I, lhs_unit=A,
        lhs_scale=A, printed=10 ** 5 / (10 ** 4 * n[Rp] / (10 ** 4 + n[Rp])), scales={n[Rp]: Rp / OHM}, units={Rp: OHM},
        law=NO_LAW, empirical=True,
        fitted_to="the internal 10 A minimum (pin 18: 'Minimum setting is 10A'), reached as R_SCKT grows without "
                  "bound; the form (a 10 k in parallel with R_SCKT scaling a reference, its 1e5 hiding a unit of "
                  "volts) is what the printed numbers imply, not a circuit the datasheet shows",
        table=(_pt("pin 18 and Current Limiting: 'a minimum of 10A', R_SCKT open", r"R_{SCKT} \to \infty",
                   {Rp: 1e15}, "10", "A", sig=2),
               _pt("Example Design: 'With R_SCKT equal to 100k, the current limit is 10A'", r"R_{SCKT} = 100" + _KOHM,
                   {Rp: 100e3}, "10", "A", sig=2)))


def eq4() -> Equation:
    """Eq 4: the dead time, 1.7e-12 (500 + R_DLY) seconds.

    Returns
    -------
    Equation
        The record ``lm4651-eq4``: the dead time (s) against R_DLY (ohm), empirical.
    """
    return Equation(
        id="lm4651-eq4", source=f"{NAME}, eq (4)", title="Dead time", lhs=T, lhs_unit=S, lhs_scale=S,
        printed=sp.Rational(17, 10 ** 13) * (500 + n[Rdly]), scales={n[Rdly]: Rdly / OHM}, units={Rdly: OHM},
        printed_tex=r"1.7 \times 10^{-12} (500 + \{R_{DLY}\}_{\Omega})",
        law=NO_LAW, empirical=True,
        fitted_to="an unstated figure: the only dead time the datasheet prints, 27 ns at R_DLY = 0, is 32 times the "
                  "printed form's 0.85 ns there, and the slope (1.7 ns per k) has no figure to check it against",
        table=(_pt("LM4651 table, T_dead at R_DLY = 0", r"R_{DLY} = 0", {Rdly: 0.0}, "27", "ns"),),
        note="As printed it gives 0.85 ns at R_DLY = 0 against the table's 27 ns; the design uses 27 ns plus eq 4's "
             "slope.")


def eq5() -> Equation:
    """Eq 5: the switching frequency, 1e9 / (4000 + R_OSC) hertz.

    Returns
    -------
    Equation
        The record ``lm4651-eq5``: f_SW (Hz) against R_OSC (ohm), empirical.
    """
    return Equation(
        id="lm4651-eq5", source=f"{NAME}, eq (5)", title="Switching frequency", lhs=f, lhs_unit=HZ, lhs_scale=HZ,
        printed=10 ** 9 / (4000 + n[Rosc]), scales={n[Rosc]: Rosc / OHM}, units={Rosc: OHM}, law=NO_LAW, empirical=True,
        fitted_to="125 kHz at R_OSC = 4 k (the LM4651 table's duty-cycle row), for R_DLY = 0; a period linear in "
                  "R_OSC is the form's assumption, the oscillator is not shown",
        table=(_pt("LM4651 table, f_SWerror row", r"R_{OSC} = 4" + _KOHM, {Rosc: 4e3}, "125", "kHz"),
               _pt("LM4651 table, f_SW at R_OSC = 15 k", r"R_{OSC} = 15" + _KOHM, {Rosc: 15e3}, "65", "kHz"),
               _pt("LM4651 table, f_SW at R_OSC = 0", r"R_{OSC} = 0", {Rosc: 0.0}, "200", "kHz", sig=3),
               _pt("pin 16 description, 15.5 k", r"R_{OSC} = 15.5" + _KOHM, {Rosc: 15.5e3}, "75", "kHz"),
               _pt("pin 16 description, 0 ohm", r"R_{OSC} = 0", {Rosc: 0.0}, "225", "kHz")),
        note="The table's points lie 20 % below and 23.5 % above eq 5; the design carries that spread as eq 5's "
             "tolerance.")


def eq6() -> Equation:
    """Eq 6: R_OSC for a switching frequency, 1e9 / f - 4000 ohms.

    Returns
    -------
    Equation
        The record ``lm4651-eq6``: R_OSC (ohm) against f_SW (Hz), empirical.
    """
    return Equation(
        id="lm4651-eq6", source=f"{NAME}, eq (6)", title="R_OSC for a frequency", lhs=Rosc, lhs_unit=OHM, lhs_scale=OHM,
        printed=10 ** 9 / n[f] - 4000, scales={n[f]: f / HZ}, units={f: HZ}, law=NO_LAW, empirical=True,
        fitted_to="eq 5 solved for R_OSC (R_DLY = 0; the text adds about 2 k for R_DLY = 5 k)",
        table=(_pt("LM4651 table, f_SWerror row", r"f_{SW} = 125\,\mathrm{kHz}", {f: 125e3}, "4", "kohm"),
               _pt("LM4651 table, 65 kHz at R_OSC = 15 k", r"f_{SW} = 65\,\mathrm{kHz}", {f: 65e3}, "15", "kohm"),
               _pt("LM4651 table, 200 kHz at R_OSC = 0", r"f_{SW} = 200\,\mathrm{kHz}", {f: 200e3}, "0", "kohm")))


def eq7() -> Equation:
    """Eq 7: the error amplifier's pole, 1 / (2 pi R_f C_f).

    Returns
    -------
    Equation
        The record ``lm4651-eq7``: the pole (Hz) against R_f (ohm) and C_f (F).
    """
    return Equation(
        id="lm4651-eq7", source=f"{NAME}, eq (7)", title="Error-amplifier pole", lhs=f, lhs_unit=HZ,
        printed=1 / (2 * sp.pi * Rf * Cf), derived=_corner(Rf, Cf), units={Rf: OHM, Cf: F},
        law="the parallel R_f C_f: the pole where |1/(j omega C_f)| = R_f")


def eq8() -> Equation:
    """Eq 8: the capacitance of two planes, with eps0 printed as 0.22479 pF/in.

    Returns
    -------
    Equation
        The record ``lm4651-eq8``: C (F) against epsilon_r, the area (in^2) and the spacing (in).
    """
    return Equation(
        id="lm4651-eq8", source=f"{NAME}, eq (8)", title="Plane capacitance, eps0 = 0.22479 pF/in", lhs=C,
        lhs_unit=F, printed=sp.Rational("0.22479") * F / 10 ** 12 / u.inch * epsr * Ar / d,
        derived=u.vacuum_permittivity * epsr * Ar / d, units={Ar: u.inch ** 2, d: u.inch},
        law="parallel-plate capacitor", note="0.22479 pF/in is 0.05 % below eps0 = 0.22490 pF/in.")


def _pd_system(x, p_out, f_sw):
    """LM4652 + LM4651 dissipation by the datasheet's method at (p_out, f_sw): eq 10 with the loss fraction x,
    conduction through 2 x 0.230 ohm into 4 ohm, and about 1 W in the LM4651 (Example Design)."""
    return x * p_out / (1 - x) + p_out / 4 * 2 * 0.230 + 1.0


def _decibel(g):
    """A voltage gain in dB."""
    return 20 * math.log10(g)


def eq9() -> Equation:
    """Eq 9: the switching loss fraction, (t_r + t_f + T_OVERMOD) f_SW.

    Returns
    -------
    Equation
        The record ``lm4651-eq9``: the loss fraction against t_r, t_f, T_OVERMOD (s) and f_SW (Hz), empirical.
    """
    return Equation(
        id="lm4651-eq9", source=f"{NAME}, eq (9)", title="Switching loss fraction", lhs=x, lhs_unit=sp.Integer(1),
        printed=(tr + tf + tom) * f, units={tr: S, tf: S, tom: S, f: HZ}, empirical=True,
        law="none: an estimate, not a law; checked through eq 10 against the system table's dissipation",
        fitted_to="no stated data; with the Example's 350 ns, eq 10, the conduction loss and about 1 W in the "
                  "LM4651 it gives the system table's 22 W at 125 W and 125 kHz (22.0 W), as the Example Design "
                  "points out. It is not a switching-loss law: during the "
                  "over-modulation pulse the MOSFETs are fully on or off, not lossy, so the T_OVERMOD term stands in "
                  "for losses the datasheet does not name (gate drive, ripple current, the idle loss)",
        table=(_pt("system table, P_d at 125 W, 125 kHz (typical 310 ns)", r"f_{SW} = 125\,\mathrm{kHz}",
                   {tr: 25e-9, tf: 26e-9, tom: 310e-9, f: 125e3}, "22", "W",
                   through=functools.partial(_pd_system, p_out=125.0, f_sw=125e3)),
               _pt("system table, P_d at 135 W, 75 kHz (typical 310 ns)", r"f_{SW} = 75\,\mathrm{kHz}",
                   {tr: 25e-9, tf: 26e-9, tom: 310e-9, f: 75e3}, "22", "W",
                   through=functools.partial(_pd_system, p_out=135.0, f_sw=75e3))),
        note="A switching-loss estimate from the edges alone, V I (t_r + t_f) f with 40 V, 5.59 A and the LM4652 "
             "table's 25 + 26 ns at 125 kHz, is 1.4 W against eq 9 and 10's 6.6 W.")


def eq10() -> Equation:
    """Eq 10: the switching dissipation, x P_out / (1 - x).

    Returns
    -------
    Equation
        The record ``lm4651-eq10``: the switching dissipation (W) against x and P_out (W).
    """
    return Equation(
        id="lm4651-eq10", source=f"{NAME}, eq (10)", title="Switching dissipation", lhs=P, lhs_unit=W,
        printed=x * Pout / (1 - x), derived=sp.solve(sp.Eq(P, x * (Pout + P)), P)[0], units={Pout: W},
        law="a fraction x of the input power P_out + P is lost")


def conduction() -> Equation:
    """The conduction dissipation, I_rms^2 x 2 R_DS(on) (Power Dissipation).

    Returns
    -------
    Equation
        The record ``lm4651-conduction``: the dissipation (W) against P_out (W), R_L and R_DS(on) (ohm).
    """
    return Equation(
        id="lm4651-conduction", source=f"{NAME}, Power Dissipation", title="Conduction dissipation", lhs=P,
        lhs_unit=W, printed=(sp.sqrt(Pout / RL)) ** 2 * (2 * Rds), derived=2 * Rds * Pout / RL,
        units={Pout: W, RL: OHM, Rds: OHM}, law="I_rms^2 through two on-resistances in series (the H-bridge)")


def eq11() -> Equation:
    """Eq 11: the heat sink's thermal resistance from the junction's temperature budget.

    Returns
    -------
    Equation
        The record ``lm4651-eq11``: theta_SA (K/W) against the temperatures (K), P_D (W) and theta_JC, theta_CS (K/W).
    """
    return Equation(
        id="lm4651-eq11", source=f"{NAME}, eq (11)", title="Heat sink thermal resistance", lhs=tsa, lhs_unit=K / W,
        printed=(Tj - Ta) / Pd - tjc - tcs, derived=sp.solve(sp.Eq(Tj - Ta, Pd * (tjc + tcs + tsa)), tsa)[0],
        units={Tj: K, Ta: K, Pd: W, tjc: K / W, tcs: K / W}, law="thermal Ohm's law through three series resistances")


def eq12() -> Equation:
    """Eq 12: the closed-loop gain, as the Example Design and the components table print it.

    Returns
    -------
    Equation
        The record ``lm4651-eq12``: the gain, a pure number, against R1, R2, R_f11 and R_f12 (ohm).
    """
    return Equation(
        id="lm4651-eq12", source=f"{NAME}, eq (12)", title="Closed-loop gain", lhs=sp.Symbol("G"),
        lhs_unit=sp.Integer(1), printed=(R2 / R1) * ((Rf11 + Rf12) / Rf12) - R2 / R1 + sp.Rational(1, 2),
        units={R1: OHM, R2: OHM, Rf11: OHM, Rf12: OHM}, law=NO_LAW, empirical=True,
        fitted_to="nothing the datasheet shows: the internal feedback amplifier is not described well enough to derive "
                  "the form, so it is held against the gains the datasheet prints for figure 1's values (the "
                  "Example's own R2 = 0.7 R1 follows from eq 12 and checks nothing)",
        table=(_pt("system table, THD+N condition 'A_V = 18 dB' (figure 1: R1 = 4.7 k, R2 = 3.5 k)",
                   r"R_1 = 4.7" + _KOHM + r",\ R_2 = 3.5" + _KOHM, {R1: 4.7e3, R2: 3.5e3, Rf11: 620e3, Rf12: 62e3},
                   "18", "1", through=_decibel),
               _pt("Example Design: 'R1 ... 4.7k and R2 ... 3.5k for a gain 7.5V/V'",
                   r"R_1 = 4.7" + _KOHM + r",\ R_2 = 3.5" + _KOHM, {R1: 4.7e3, R2: 3.5e3, Rf11: 620e3, Rf12: 62e3},
                   "7.5", "1")),
        note="Printed intact in the Example Design and the components table; the '(3)' after it is the Example's own "
             "equation label (the next line is 'R2 = .7R1 (4)'), which clashes with eq 3 and eq 4 "
             "(lm4651-t-eq-labels).")


def fb_pole1() -> Equation:
    """The feedback filter's first pole, 1 / (2 pi R_f12 C_fl1) (components table).

    Returns
    -------
    Equation
        The record ``lm4651-fb-pole1``: the pole (Hz) against R_f12 (ohm) and C_fl1 (F).
    """
    return Equation(
        id="lm4651-fb-pole1", source=f"{NAME}, components table, R_fl2", title="Feedback filter, first pole",
        lhs=f, lhs_unit=HZ, printed=1 / (2 * sp.pi * Rf12 * Cfl1), derived=_corner(Rf12, Cfl1),
        units={Rf12: OHM, Cfl1: F}, law="first-order RC low-pass: the corner where omega R C = 1",
        note="The capacitor values of figure 1 did not survive the OCR; R_fl1 = 10 R_fl2 keeps R_fl1 from loading it.")


def fb_pole2() -> Equation:
    """The feedback filter's second pole, 1 / (2 pi R_fl3 C_fl2) (components table).

    Returns
    -------
    Equation
        The record ``lm4651-fb-pole2``: the pole (Hz) against R_fl3 (ohm) and C_fl2 (F).
    """
    return Equation(
        id="lm4651-fb-pole2", source=f"{NAME}, components table, R_fl3", title="Feedback filter, second pole",
        lhs=f, lhs_unit=HZ, printed=1 / (2 * sp.pi * Rfl3 * Cfl2), derived=_corner(Rfl3, Cfl2),
        units={Rfl3: OHM, Cfl2: F}, law="first-order RC low-pass",
        note="Should lie above the output filter's pole (datasheet text).")


def input_hp() -> Equation:
    """The input high-pass corner of C_IN with R1 (implied by the Example Design).

    Returns
    -------
    Equation
        The record ``lm4651-input-hp``: the corner (Hz) against R1 (ohm) and C_IN (F).
    """
    return Equation(
        id="lm4651-input-hp", source=f"{NAME}, Example Design (implied; no formula printed)",
        title="Input high-pass (C_IN with R1)", lhs=f, lhs_unit=HZ, printed=1 / (2 * sp.pi * R1 * Cin),
        derived=sp.solve(sp.Eq(1 / (w * Cin), R1), w)[0] / (2 * sp.pi), units={R1: OHM, Cin: F},
        law="series C_IN into the inverting input's R1: the corner where |1/(j omega C_IN)| = R1",
        note="The text only says a lower R1 needs a larger C_IN; with R1 = 20 k a 10 Hz corner needs 0.8 uF.")


def output_filter() -> Equation:
    """The bridge output filter's corner, 1 / (2 pi sqrt(2 L1 C_BYP)) (reconstructed).

    Returns
    -------
    Equation
        The record ``lm4651-filter``: the corner (Hz) against L1 (H) and C_BYP (F).
    """
    return Equation(
        id="lm4651-filter", source=f"{NAME}, Output Stage Filtering (reconstructed)", title="Bridge output filter",
        lhs=f, lhs_unit=HZ, printed=1 / (2 * sp.pi * sp.sqrt(L1 * 2 * Cb)),
        derived=sp.solve(sp.Eq(w ** 2 * 2 * L1 * Cb, 1), w)[0] / (2 * sp.pi), units={L1: u.henry, Cb: F},
        law="series resonance of the loop L1 - C_BYP - L1 (2 L1 with C_BYP)",
        reconstructed="the OCR reads 'f_C = 1/[2 pi (L_1 2C_BYP)/_2]'; the text's 'extra factor of 2' and a square "
                      "root give this form")


# --- the design's own models of the output stage (no formula printed; each checked here) --------------------
Vs, fsw, fa, Vpk, Qf, Vr, Ipk = sp.symbols(r"V_s f_{SW} f_a V_{pk} Q V_r I_{L\,pk}", positive=True)
_s = sp.Symbol("s")


def _num(sym, unit_tex: str):
    """The number-only symbol {sym}_unit (ISO 80000-1), as eq 5 writes R_OSC."""
    return sp.Symbol(r"\{" + sym.name + r"\}_{" + unit_tex + "}", positive=True)


def _bridge_denominator():
    """(a1, a2) of the loaded bridge filter H(s) = 1 / (1 + a1 s + a2 s^2): the load R_L with C_BYP across it,
    fed through the two coils in series (2 L1), a voltage divider of impedances."""
    z_load = RL / (1 + _s * RL * Cb)
    h = sp.cancel(z_load / (z_load + 2 * _s * L1))
    a2, a1, a0 = sp.Poly(sp.expand(sp.denom(h) / sp.numer(h)), _s).all_coeffs()
    assert a0 == 1
    return a1, a2


def filter_q() -> Equation:
    """The loaded bridge filter's Q, R_L sqrt(C_BYP / (2 L1)) (the design's; the datasheet prints none).

    Returns
    -------
    Equation
        The record ``lm4651-filter-q``: Q, a pure number, against R_L (ohm), L1 (H) and C_BYP (F).
    """
    a1, a2 = _bridge_denominator()
    return Equation(
        id="lm4651-filter-q", source=f"{NAME}, Output Stage Filtering (the design's model; no formula printed)",
        title="Loaded output filter's Q", lhs=Qf, lhs_unit=sp.Integer(1), printed=RL * sp.sqrt(Cb / (2 * L1)),
        derived=sp.sqrt(a2) / a1, units={RL: OHM, L1: u.henry, Cb: F},
        law="voltage divider of 2 L1 and R_L || C_BYP: H = 1 / (1 + s 2L1/R_L + s^2 2 L1 C_BYP); Q = sqrt(a2) / a1",
        note="The load is taken as a resistor (a loudspeaker is not); the datasheet asks for no peaking, the design "
             "holds Q to q_max.")


def ripple() -> Equation:
    """The switching residue at the load, rms: the idle bridge's fundamental through the loaded filter.

    Returns
    -------
    Equation
        The record ``lm4651-ripple``: V_r (V) against V_s (V), f_SW (Hz), L1 (H), C_BYP (F) and R_L (ohm).
    """
    a1, a2 = _bridge_denominator()
    th = sp.Symbol("theta")
    b1 = 2 / sp.pi * sp.integrate(2 * Vs * sp.sin(th), (th, 0, sp.pi))  # the ±2 V_s square wave's fundamental
    wsw = 2 * sp.pi * fsw
    gain = 1 / sp.sqrt((1 - a2 * wsw ** 2) ** 2 + (a1 * wsw) ** 2)
    return Equation(
        id="lm4651-ripple", source=f"{NAME}, Output Stage Filtering (the design's model; no formula printed)",
        title="Switching residue at the load", lhs=Vr, lhs_unit=V,
        printed=8 * Vs / (sp.pi * sp.sqrt(2)) / sp.sqrt((1 - 8 * sp.pi ** 2 * fsw ** 2 * L1 * Cb) ** 2
                                                        + (4 * sp.pi * fsw * L1 / RL) ** 2),
        derived=b1 / sp.sqrt(2) * gain, units={Vs: V, fsw: HZ, L1: u.henry, Cb: F, RL: OHM},
        law="the fundamental of the idle bridge's ±2 V_s square wave (50 % duty, its largest), "
            "(2/pi) integral of 2 V_s sin over half a period = 8 V_s / pi, times |H(j 2 pi f_SW)|, rms",
        note="Harmonics ignored (3 f_SW is attenuated nine times more); an upper bound at any duty.")


def inductor_peak() -> Equation:
    """The coils' peak current: the audio current at the peak output voltage plus half the largest ripple.

    Returns
    -------
    Equation
        The record ``lm4651-inductor-peak``: I_L,pk (A) against V_pk (V), R_L (ohm), f_a (Hz), C_BYP (F), V_s (V),
        L1 (H) and f_SW (Hz).
    """
    dty = sp.Symbol("D", positive=True)
    v_out = 2 * Vs * (2 * dty - 1)  # the bridge's average output at duty D
    swing = (2 * Vs - v_out) * dty / fsw / (2 * L1)  # 2 L1 carries 2 V_s - v_out for D T
    d_star = sp.solve(sp.diff(swing, dty), dty)[0]
    wa = 2 * sp.pi * fa
    return Equation(
        id="lm4651-inductor-peak", source=f"{NAME}, Example Design, R_SCKT (the design's model; no formula printed)",
        title="Peak coil current", lhs=Ipk, lhs_unit=A,
        printed=Vpk * sp.sqrt(1 / RL ** 2 + (2 * sp.pi * fa * Cb) ** 2) + Vs / (4 * L1 * fsw),
        derived=Vpk * sp.sqrt(sp.re(1 / RL + sp.I * wa * Cb) ** 2 + sp.im(1 / RL + sp.I * wa * Cb) ** 2)
        + swing.subs(dty, d_star) / 2,
        units={Vpk: V, RL: OHM, fa: HZ, Cb: F, Vs: V, L1: u.henry, fsw: HZ},
        law="the load and C_BYP at the top of the band, |V_pk (1/R_L + j omega C_BYP)|, plus half the ripple "
            "2 V_s D (1 - D) / (L1 f_SW), largest at D = 1/2 (volt-seconds on 2 L1 while the bridge is high)",
        note="An upper bound: the audio peak and the ripple's largest half added. The datasheet: 'the inductor ripple "
             "current and the peak output current must be lower than 10 amps' (R_SCKT).")


_NV, _NF, _NR, _NL, _NC, _NP = (_num(Vs, r"\mathrm{V}"), _num(fsw, r"\mathrm{Hz}"), _num(RL, r"\Omega"),
                                _num(L1, r"\mathrm{H}"), _num(Cb, r"\mathrm{F}"), _num(Pout, r"\mathrm{W}"))
_NUMBERS = {_NV: Vs / V, _NF: fsw / HZ, _NR: RL / OHM, _NL: L1 / u.henry, _NC: Cb / F, _NP: Pout / W}


def p_clip() -> Equation:
    """The output power at 1 % THD (clipping) against f_SW, R_L and V_s: the design's calibrated model.

    Returns
    -------
    Equation
        The record ``lm4651-p-clip``: the clipping power (W) against V_s (V), f_SW (Hz) and R_L (ohm), empirical.
    """
    from .circuit import A_OM, R_S, SUPPLY_REF, V_EFF

    v_peak = sp.Float(V_EFF, 15) * _NV / SUPPLY_REF * (1 - sp.Float(A_OM, 15) * _NF) * _NR / (_NR + sp.Float(R_S, 15))
    return Equation(
        id="lm4651-p-clip", source=f"{NAME}, electrical characteristics, P_O at 1 % THD (the design's calibration)",
        title="Clipping power", lhs=P, lhs_unit=W, lhs_scale=W, printed=v_peak ** 2 / (2 * _NR), scales=_NUMBERS,
        units={Vs: V, fsw: HZ, RL: OHM}, empirical=True, law=NO_LAW,
        printed_tex=(rf"\frac{{1}}{{2 \cdot \{{R_L\}}_{{\Omega}}}} "
                     rf"\left({V_EFF:.4g} \cdot \frac{{\{{V_s\}}_{{\mathrm{{V}}}}}}{{20}}"
                     rf" (1 - {A_OM * 1e9:.4g} \times 10^{{-9}} \cdot \{{f_{{SW}}\}}_{{\mathrm{{Hz}}}}) "
                     rf"\cdot \frac{{\{{R_L\}}_{{\Omega}}}}{{\{{R_L\}}_{{\Omega}} + {R_S:.4g}}}\right)^2"),
        fitted_to="the three clipping powers of the electrical characteristics at ±20 V and 1 % THD (125 W at "
                  "125 kHz and 135 W at 75 kHz into 4 Ω, 75 W into 8 Ω): the peak output is a fixed voltage less "
                  "a fixed time lost per period (the over-modulation pulse) across R_L against a series resistance "
                  "(2 R_DS(on) and the coils); three points, three constants, so it reproduces them exactly",
        table=(_pt("electrical characteristics, P_O at R_L = 4 Ω, 1 % THD", r"f_{SW} = 125\,\mathrm{kHz},\ "
                   r"R_L = 4\,\Omega", {Vs: 20.0, fsw: 125e3, RL: 4.0}, "125", "W"),
               _pt("electrical characteristics, P_O at f_SW = 75 kHz, R_L = 4 Ω, 1 % THD",
                   r"f_{SW} = 75\,\mathrm{kHz},\ R_L = 4\,\Omega", {Vs: 20.0, fsw: 75e3, RL: 4.0}, "135", "W"),
               _pt("electrical characteristics, P_O at R_L = 8 Ω, 1 % THD", r"f_{SW} = 125\,\mathrm{kHz},\ "
                   r"R_L = 8\,\Omega", {Vs: 20.0, fsw: 125e3, RL: 8.0}, "75", "W")),
        note="Scaled with the supply as a fixed fraction of the rails (the characteristics give ±20 V only).")


def thd_distortion() -> Equation:
    """THD+N's distortion term at a test power: the system table's 0.3 % scaled as a fixed error voltage.

    Returns
    -------
    Equation
        The record ``lm4651-thd``: THD (a fraction) against f_SW (Hz), L1 (H), C_BYP (F), V_s (V), P (W) and R_L
        (ohm), empirical.
    """
    from .circuit import C_REF, F_REF, L_REF, SUPPLY_REF, THD_REF

    thd = sp.Symbol(r"\mathrm{THD}_{dist}", positive=True)
    printed = (sp.Float(THD_REF) * (sp.Float(F_REF) / _NF) ** 2 * sp.Float(L_REF * C_REF) / (_NL * _NC)
               * _NV / SUPPLY_REF * sp.sqrt(sp.Integer(40) / (_NP * _NR)))
    return Equation(
        id="lm4651-thd", source=f"{NAME}, electrical characteristics, THD+N at 10 W (the design's scaling)",
        title="THD+N, distortion term", lhs=thd, lhs_unit=sp.Integer(1), printed=printed, scales=_NUMBERS,
        units={fsw: HZ, L1: u.henry, Cb: F, Vs: V, Pout: W, RL: OHM}, empirical=True, law=NO_LAW,
        printed_tex=(r"0.003 \left(\frac{125000}{\{f_{SW}\}_{\mathrm{Hz}}}\right)^2 \cdot \frac{2.5 \times 10^{-10}}"
                     r"{\{L_1\}_{\mathrm{H}} \cdot \{C_{BYP}\}_{\mathrm{F}}} \cdot \frac{\{V_s\}_{\mathrm{V}}}{20} \cdot "
                     r"\sqrt{\frac{40}{\{P_{out}\}_{\mathrm{W}} \cdot \{R_L\}_{\Omega}}}"),
        fitted_to="one point, the characteristics' 0.3 % at 10 W into 4 Ω, ±20 V, with the Output Stage Filtering's "
                  "50 µH and 5 µF at 125 kHz; the scaling (a fixed error voltage, so 1 / V_rms; the switching residue "
                  "through the second-order filter, 1 / (f_SW^2 L1 C_BYP); in proportion to the rails) is the design's "
                  "assumption, its exponent 2 included",
        table=(_pt("electrical characteristics, THD+N at 10 W, 4 Ω, ±20 V (50 µH, 5 µF, 125 kHz)",
                   r"P = 10\,\mathrm{W},\ f_{SW} = 125\,\mathrm{kHz}",
                   {fsw: 125e3, L1: 50e-6, Cb: 5e-6, Vs: 20.0, Pout: 10.0, RL: 4.0}, "0.3", "%"),),
        note="What the analyser reads adds, root-sum-square, the switching residue (lm4651-ripple over the test "
             "signal's rms) when f_SW lies inside its 80 kHz band.")


def build() -> list[Equation]:
    """Every LM4651/LM4652 equation record.

    Returns
    -------
    list of Equation
        Equations 1 to 12 and those the text implies, in the datasheet's order.
    """
    return [eq1(), eq2(), eq3(), eq4(), eq5(), eq6(), eq7(), eq8(), eq9(), eq10(), conduction(), eq11(), eq12(),
            fb_pole1(), fb_pole2(), input_hp(), output_filter(), filter_q(), ripple(), inductor_peak(), p_clip(),
            thd_distortion()]
