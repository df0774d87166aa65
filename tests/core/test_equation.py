"""Printed-number parsing, the status logic, and the equation record's symbolic check."""
import dataclasses
import math

import pytest
import sympy as sp
from sympy.physics import units as u

from handbook.core import Printed, classify
from handbook.core.equation import Equation, latex


@pytest.mark.parametrize("text,unit,si,half", [
    ("160", "uF*rpm", 160e-6, 5e-6),  # trailing zero of an integer: not significant
    ("0.0148", "uF", 1.48e-8, 0.5e-10),
    ("5", "Hz", 5.0, 0.5),
    ("-0.25", "%/K", -0.0025, 0.5e-4),
    ("74.1", "mV", 0.0741, 0.5e-4),
    ("2.02", "V", 2.02, 0.005),
])
def test_printed_parses_value_and_precision(text, unit, si, half):
    p = Printed(text, unit)
    assert p.si == pytest.approx(si, rel=1e-12)
    assert p.half_unit == pytest.approx(half, rel=1e-12)


def test_printed_with_stated_significant_figures():
    assert Printed("200", "kHz").half_unit == pytest.approx(50e3)  # trailing zeros: not significant by default
    assert Printed("200", "kHz", sig=3).half_unit == pytest.approx(500.0)
    assert Printed("10", "A", sig=2).half_unit == pytest.approx(0.5)


def test_classify_exact_rounding_misprint():
    assert classify(9.8, 0.05, 9.8) == "exact"
    assert classify(5.0, 0.5, 5.1367) == "rounding"
    assert classify(5.0, 0.5, 5.6) == "misprint"
    # the boundary: half a unit is still rounding, a hair more is not
    assert classify(150e-3, 5e-3, 155e-3) == "rounding"
    assert classify(150e-3, 5e-3, 155.1e-3) == "misprint"


def test_classify_names_the_basis_of_a_mismatch():
    assert classify(22e-6, 0.5e-6, 11e-6, basis="TDA5144 datasheet") == "inconsistent"
    assert classify(22e-6, 0.5e-6, 11e-6, basis="note") == "misprint"


def test_classify_accepts_a_value_that_follows_from_the_notes_rounded_intermediate():
    # 0.0148 uF is 160/(1800*6) although 22 uA and 1.4 V give 0.01455 uF directly
    assert classify(1.48e-8, 0.5e-10, 1.455e-8) == "misprint"
    assert classify(1.48e-8, 0.5e-10, 1.455e-8, via_rounded=160e-6 / 10800) == "rounding"


def test_classify_bounds():
    # C2: 10 uF chosen against a 39.8 nF minimum meets the bound; it is not "exact" beside two unequal numbers
    assert classify(10e-6, 0.5e-6, 39.8e-9, relation=">=") == "bound met"
    assert classify(10e-9, 0.5e-9, 39.8e-9, relation=">=") == "misprint"
    assert classify(1.0, 0.05, 2.0, relation="<=") == "bound met"


def test_rounded_to_the_safe_side_and_wrong_method_are_statuses_of_their_own():
    from handbook import catalog

    status = {r["id"]: r["status"] for r in catalog.claims()}
    # theta_SA printed 2.5 and 3.5 K/W against 2.57 and 3.57: a heat sink rounded down to the better one
    assert status["lm4651-theta-tf"] == status["lm4651-theta-t"] == "conservative"
    # multiplying tolerance percentages (and carrying eq 14's matching into them) is a method, not a misprint
    assert status["an94002-total-exact"] == status["an94002-resistor-tol"] == status["an93008-resistor-tol"] == "wrong method"
    assert status["an94002-c2"] == "bound met"


def test_a_truncated_last_digit_is_rounding_only_where_the_print_is_the_truncation():
    from handbook.core import Claim

    def claim(text, value, **kw):
        return Claim(id="t", where="w", quantity="q", printed=Printed(text, "Hz"), compute=lambda p: value,
                     reason="22.755 truncated to 22.7", chapter="c", **kw)

    assert claim("22.7", 22.755).evaluate({}, {})["status"] == "misprint"
    assert claim("22.7", 22.755, truncated=True).evaluate({}, {})["status"] == "truncated"
    assert claim("22.8", 22.755, truncated=True).evaluate({}, {})["status"] == "rounding"  # rounded anyway
    # 6.366 truncates to 6.36, not 6.35; 22.755 never truncates to 22.6: still misprints
    assert claim("6.35", 6.366, truncated=True).evaluate({}, {})["status"] == "misprint"
    assert claim("22.6", 22.755, truncated=True).evaluate({}, {})["status"] == "misprint"
    with pytest.raises(ValueError, match="truncated"):
        Claim(id="t", where="w", quantity="q", printed=Printed("22.7", "Hz"), compute=lambda p: 22.755,
              reason="22.755 Hz", chapter="c", truncated=True)


@pytest.mark.parametrize("bad", [math.nan, math.inf])
def test_classify_refuses_non_finite(bad):
    with pytest.raises(ValueError, match="finite"):
        classify(bad, 0.1, 1.0)


def _divider_equation(printed, lhs_scale=None, scales=None):
    vin, r1, r2, vout = sp.symbols("V_in R_1 R_2 V_out", positive=True)
    return Equation(
        id="t", source="test", title="divider", lhs=vout, lhs_unit=u.volt,
        printed=printed(vin, r1, r2), derived=vin * r2 / (r1 + r2),
        units={vin: u.volt, r1: u.ohm, r2: u.ohm}, law="KCL", lhs_scale=lhs_scale, scales=scales or {})


def test_equation_check_identical_constant_and_structural():
    same = _divider_equation(lambda v, a, b: v / (1 + a / b)).check()
    assert same.agrees and same.relation == "identical" and same.dims_ok
    scaled = _divider_equation(lambda v, a, b: sp.Rational(101, 100) * v * b / (a + b)).check()
    assert not scaled.agrees and scaled.relation == "constant factor" and scaled.factor == sp.Rational(101, 100)
    wrong = _divider_equation(lambda v, a, b: v * a / (a + b)).check()
    assert not wrong.agrees and wrong.relation == "differs"


def test_equation_check_finds_a_dimension_error():
    bad = _divider_equation(lambda v, a, b: v * b).check()  # volt x ohm is not a voltage
    assert not bad.dims_ok


def test_hidden_unit_constant_is_made_explicit():
    # t [s] = 2.15 x C [uF] for 2 uA over 2.15 V twice: agrees only once the uF is explicit
    c, c_uf, t, i, dv = sp.symbols("C C_uF t I dV", positive=True)
    uF = u.farad / 10 ** 6
    eq = Equation(id="t", source="test", title="timer", lhs=t, lhs_unit=u.second, lhs_scale=u.second,
                  printed=sp.Rational("2.15") * c_uf, scales={c_uf: c / uF}, derived=2 * c * dv / i,
                  units={c: u.farad, i: u.ampere, dv: u.volt},
                  values={i: 2 * u.ampere / 10 ** 6, dv: sp.Rational("2.15") * u.volt}, law="I t = C dV")
    assert eq.check().agrees
    per_farad = dataclasses.replace(eq, scales={c_uf: c / u.farad})  # as if the constant were per farad
    assert per_farad.check().factor == sp.Integer(10) ** -6


def test_latex_shows_decimal_constants_as_printed():
    x = sp.Symbol("x")
    assert latex(sp.Rational("2.15") * x) == "2.15 x"
    assert latex(sp.sqrt(x) / 2) == r"\frac{\sqrt{x}}{2}"


def test_an_equation_is_frozen_and_checks_once():
    eq = _divider_equation(lambda v, a, b: v / (1 + a / b))
    with pytest.raises(dataclasses.FrozenInstanceError):
        eq.law = "other"
    assert eq.check() is eq.check()  # computed once, then remembered


def test_an_empirical_equation_is_checked_against_figures_not_a_derivation():
    import sympy as sp
    from sympy.physics import units as u

    from handbook.core import Printed
    from handbook.core.equation import Equation, TablePoint

    r, rn = sp.symbols("R R_n", positive=True)
    pts = (TablePoint("table a", "R = 4", {r: 4e3}, Printed("125", "kHz")),
           TablePoint("table b", "R = 0", {r: 0.0}, Printed("200", "kHz", sig=3)))
    eq = Equation(id="x-eq", source="x", title="f", lhs=sp.Symbol("f"), lhs_unit=u.hertz, lhs_scale=u.hertz,
                  printed=10 ** 9 / (4000 + rn), scales={rn: r / u.ohm}, units={r: u.ohm}, empirical=True,
                  fitted_to="the 4 k row", table=pts)
    c = eq.check()
    assert c.relation == "empirical" and not c.agrees and c.dims_ok
    assert [p[-1] for p in c.points] == [True, False]
    assert c.points[1][3] == pytest.approx(250.0) and c.points[1][4] == pytest.approx(0.25)  # kHz, +25 %
    s = eq.summary()
    assert s["empirical"] and s["fitted_to"] == "the 4 k row" and "(+25.0 %)" in s["note"]
    assert r"\checkmark" in s["derived_latex"] and r"+25.0\,\%" in s["derived_latex"]
    with pytest.raises(ValueError, match="fitted to"):
        Equation(id="y", source="y", title="y", lhs=sp.Symbol("f"), lhs_unit=u.hertz, printed=rn,
                 units={}, empirical=True)
    with pytest.raises(ValueError, match="derived form is required"):
        Equation(id="z", source="z", title="z", lhs=sp.Symbol("f"), lhs_unit=u.hertz, printed=rn, units={})


@pytest.mark.parametrize("text, exact, rounds", [("160", 1100 / 7, True), ("2.63", 50 / 19, True), ("0.741", 20 / 27, True),
                                                 ("0.070", 0.0705, True), ("7092", 1e6 / 141, True),
                                                 ("0.0148", 0.01455, False), ("7.7", 7.79, False), ("2.63", 2.64, False)])
def test_a_printed_constant_rounds_its_exact_value_by_its_own_figures(text, exact, rounds):
    from handbook.core.equation import rounds_to

    assert rounds_to(text, exact) is rounds


def test_rounded_constants_agree_once_the_exact_values_are_put_back():
    """The six printed forms that differ from their derivations only by a rounded constant read 'agrees
    (constant rounded)'; a constant that rounds right but is not the one the printed form lost does not."""
    from dataclasses import replace

    import sympy as sp

    from handbook.sources import SOURCES

    eqs = {e.id: e for src in SOURCES for e in src.equations()}
    ids = ("an94002-eq6", "an94002-eq9b", "an94002-eq11-num", "an93008-eq2", "tda5341-capcdm", "tda5341-max-delay")
    assert all(not eqs[i].check().agrees and eqs[i].rounded_constants for i in ids)
    assert all(eqs[i].summary()["rounded_constants"] for i in ids)
    wrong = replace(eqs["an94002-eq9b"], rounded=(("2.63", sp.Rational(26301, 10000)),))  # rounds to 2.63, not 5/1.9
    assert not wrong.rounded_constants
    assert not any(e.rounded_constants for e in eqs.values() if e.id not in ids)
