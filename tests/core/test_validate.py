"""Input checks (handbook.core.validate): what passes, what is refused, and the message a user reads (the
field, the value given and the accepted range, with units)."""
import decimal
import fractions
import math
import re

import numpy as np
import pytest

from handbook.core.validate import InputError, fraction, number, ordered, out_of_range, pole_pairs, positive, quantity, range_text


def message(fn, *args, **kw) -> str:
    with pytest.raises(InputError) as info:
        fn(*args, **kw)
    return str(info.value)


def test_input_error_is_a_value_error():
    assert issubclass(InputError, ValueError)
    with pytest.raises(ValueError):
        number("x", -1.0, low=0.0)


@pytest.mark.parametrize("value,unit,text", [
    (50e6, "Hz", "50 MHz"),
    (1e3, "Hz", "1 kHz"),
    (-1, "A", "-1 A"),
    (12e-6, "H", "12 µH"),
    (2.2e-9, "F", "2.2 nF"),
    (4700, "ohm", "4.7 kΩ"),
    (3.3, "Ω", "3.3 Ω"),
    (1e-3, "s", "1 ms"),
    (15e12, "Hz", "15 THz"),
    (1e-16, "F", "100 aF"),  # atto, as core.units (and the book's axes) write it
    (999.99, "Hz", "1 kHz"),  # rounds up to 1.000 kHz at 4 figures: shown as 1 kHz, not 1000 Hz
    (999.9, "Hz", "999.9 Hz"),
    (123456, "V", "123.5 kV"),  # 4 significant figures
    (0, "V", "0 V"),
    (0.05, "", "0.05"),
    (0.5, "1", "0.5"),
    (1e6, "rpm", "1,000,000 rpm"),
    (12345.0, "", "12,345"),
    (12345.5, "", "1.235e+04"),  # not whole: 4 significant figures
    (300, "K", "300 K"),
    (math.inf, "V", "inf V"),
])
def test_quantity(value, unit, text):
    assert quantity(value, unit) == text


@pytest.mark.parametrize("args,text", [
    ((1e3, 1e6, False, "Hz"), "from 1 kHz to 1 MHz"),
    ((0, 10, True, "A"), "> 0 A and <= 10 A"),
    ((None, 5, False, "V"), "<= 5 V"),
    ((1, None, False, ""), ">= 1"),
    ((0, None, True, "ohm"), "> 0 Ω"),
    ((None, None, False, "V"), "(any)"),
])
def test_range_text(args, text):
    assert range_text(*args) == text


def test_out_of_range_edges():
    # closed range 1 kHz .. 1 MHz: both ends accepted, just outside refused
    for inside in (1e3, 1e6, 500e3):
        assert out_of_range("f", inside, "Hz", 1e3, 1e6) is None
    for outside in (999.0, 1e6 * (1 + 1e-12), -1.0):
        assert isinstance(out_of_range("f", outside, "Hz", 1e3, 1e6), InputError)
    # an open low end refuses the end itself
    assert isinstance(out_of_range("i", 0.0, "A", 0.0, None, low_open=True), InputError)
    assert out_of_range("i", 1e-12, "A", 0.0, None, low_open=True) is None
    assert out_of_range("i", -5.0, "A", None, None) is None


def test_out_of_range_message_names_the_field_the_value_and_the_range():
    e = out_of_range("f_switch", 2e6, "Hz", 1e3, 1e6)
    assert str(e) == "f_switch = 2 MHz is out of range: use a value from 1 kHz to 1 MHz"
    e = out_of_range("v_supply", 11, "V", 1, 10, meaning="the LM358's supply")
    assert str(e) == "v_supply = 11 V is out of range: use a value from 1 V to 10 V (the LM358's supply)"
    # a unit in parentheses is an annotation, shown once after the range
    e = out_of_range("tol", 1.0, "(fraction, 5 % = 0.05)", 0.0, 0.999)
    assert str(e) == "tol = 1 is out of range: use a value from 0 to 0.999 (fraction, 5 % = 0.05)"


def test_number_accepts_real_numbers_in_range():
    assert number("x", 5) == 5.0 and type(number("x", 5)) is float
    assert number("x", np.float32(2.5), low=0, high=10) == 2.5
    assert number("x", np.int64(3), low=3, high=3) == 3.0  # both ends of a closed range
    assert number("x", fractions.Fraction(1, 4)) == 0.25
    assert number("x", -1e300) == -1e300  # no range: any finite number


@pytest.mark.parametrize("value,text", [
    (-0.1, "x = -100 mV is out of range: use a value from 0 V to 10 V"),
    (10.5, "x = 10.5 V is out of range: use a value from 0 V to 10 V"),
])
def test_number_out_of_range(value, text):
    assert message(number, "x", value, low=0.0, high=10.0, unit="V") == text


@pytest.mark.parametrize("value", [True, False, np.True_, "5", None, 1 + 0j, [1.0], decimal.Decimal("1.5")])
def test_number_refuses_what_is_not_a_real_number(value):
    text = message(number, "r_load", value, unit="ohm")
    assert text == f"r_load = {value!r}: expected a number in ohm"
    assert message(number, "gain", value) == f"gain = {value!r}: expected a number"


@pytest.mark.parametrize("value", [math.nan, math.inf, -math.inf])
def test_number_refuses_non_finite(value):
    assert message(number, "c_out", value, low=0.0) == f"c_out = {value!r}: expected a finite number"


def test_positive():
    assert positive("r", 1e-9, "ohm") == 1e-9
    assert message(positive, "r", 0.0, "ohm") == "r = 0 Ω is out of range: use a value > 0 Ω"
    assert message(positive, "r", -4.7e3, "ohm") == "r = -4.7 kΩ is out of range: use a value > 0 Ω"
    assert positive("r", 1e6, "ohm", high=1e6) == 1e6
    assert message(positive, "r", 2e6, "ohm", high=1e6) == "r = 2 MΩ is out of range: use a value > 0 Ω and <= 1 MΩ"


def test_fraction():
    assert fraction("tol", 0.0) == 0.0 and fraction("tol", 0.05) == 0.05 and fraction("tol", 0.999) == 0.999
    assert message(fraction, "tol", 5) == "tol = 5 is out of range: use a value from 0 to 0.999 (fraction, 5 % = 0.05)"
    assert message(fraction, "tol", 0.9991).startswith("tol = 0.9991 is out of range")
    assert message(fraction, "tol", -0.01).startswith("tol = -0.01 is out of range")


def test_pole_pairs():
    assert pole_pairs("n", 6) == 6 and pole_pairs("n", 1) == 1 and pole_pairs("n", np.int64(3)) == 3
    assert type(pole_pairs("n", np.int64(3))) is int
    for bad in (0, -1, 3.0, 2.5, True, "6", None):
        assert message(pole_pairs, "n", bad) == f"n = {bad!r}: the number of pole pairs is a whole number >= 1 " \
                                                "(the note's motor has 6)"


def test_ordered():
    assert ordered("v_low", 1.0, "v_high", 2.0) is None
    assert message(ordered, "v_low", 2.0, "v_high", 2.0) == "v_low = 2 must be below v_high = 2"
    assert message(ordered, "v_low", 3.5, "v_high", 2.0) == "v_low = 3.5 must be below v_high = 2"
    assert message(ordered, "v_low", math.nan, "v_high", 2.0) == "v_low = nan must be below v_high = 2"


# --- numpy arrays ------------------------------------------------------------------------------------------


def test_an_array_in_range_is_returned_unchanged():
    a = np.array([1.0, 2.0, 3.0])
    assert number("x", a, low=1.0, high=3.0, unit="V") is a
    ints = np.array([[1, 2], [3, 4]])
    assert number("x", ints, low=0) is ints
    empty = np.array([])
    assert number("x", empty, low=0) is empty


@pytest.mark.parametrize("values,text", [
    ([1.0, -2.0, 3.0], "x = -2 V is out of range: use a value from 0 V to 10 V"),  # the minimum is named
    ([1.0, 12.0, 3.0], "x = 12 V is out of range: use a value from 0 V to 10 V"),  # the maximum is named
])
def test_an_array_out_of_range_names_its_worst_element(values, text):
    assert message(number, "x", np.array(values), low=0.0, high=10.0, unit="V") == text


@pytest.mark.parametrize("values", [[1.0, np.nan], [np.nan, 1.0], [2.0, np.inf], [-np.inf]])
def test_an_array_with_a_non_finite_element_is_refused(values):
    text = message(number, "x", np.array(values), low=0.0)
    assert text.startswith("x") and re.search(r"expected (a )?finite numbers?", text)
    assert ("nan" in text) if any(np.isnan(values)) else ("inf" in text)


@pytest.mark.parametrize("values", [np.array([True, False]), np.array([1 + 1j]), np.array(["1"])])
def test_an_array_of_booleans_complex_or_text_is_refused(values):
    assert message(number, "x", values).endswith(": expected a number")
