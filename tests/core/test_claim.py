"""Printed numbers, their status rules and the claim record (handbook.core.claim), on hand-made numbers:
the edges of each rule (just inside and just outside), the statuses only a Claim can give, and evaluate's
record of the parameters a recomputation reads."""
import math

import pytest

from handbook.core.claim import UNIT_SCALES, Claim, Printed, Recorder, classify

# --- Printed -----------------------------------------------------------------------------------------------


@pytest.mark.parametrize("text,unit,si,half", [
    ("4.7", "kohm", 4700.0, 50.0),
    ("1.50", "V", 1.5, 0.005),  # a trailing zero after the point is significant
    ("1500", "ohm", 1500.0, 50.0),  # trailing zeros of an integer are not
    ("1e3", "V", 1000.0, 500.0),
    ("0.00", "V", 0.0, 0.005),
    ("0", "mA", 0.0, 0.5e-3),
    ("-0.25", "%/K", -0.0025, 0.5e-4),
    ("5", "%", 0.05, 0.5e-2),
    ("33", "nF", 33e-9, 0.5e-9),
    ("2.2", "uF*rpm", 2.2e-6, 0.05e-6),
])
def test_printed_value_and_half_unit_by_hand(text, unit, si, half):
    p = Printed(text, unit)
    assert p.si == pytest.approx(si, rel=1e-12, abs=1e-300)
    assert p.half_unit == pytest.approx(half, rel=1e-12)
    assert str(p) == f"{text} {unit}"


@pytest.mark.parametrize("text,unit,sig,half", [
    ("200", "kHz", 3, 500.0),  # 200 kHz to 3 figures: +-0.5 kHz
    ("200", "kHz", 1, 50e3),
    ("0.0470", "uF", 2, 0.5e-9),  # 47 nF to 2 figures: +-0.5 nF, whatever the printed zero says
    ("-12", "V", 3, 0.05),
    ("9.99", "V", 2, 0.05),
])
def test_printed_with_significant_figures_by_hand(text, unit, sig, half):
    assert Printed(text, unit, sig=sig).half_unit == pytest.approx(half, rel=1e-12)


def test_printed_refuses_an_unknown_unit_and_names_the_known_ones():
    with pytest.raises(ValueError, match=r"Printed\('1', 'kV'\): unknown unit; known: F, uF, nF"):
        Printed("1", "kV")


def test_unit_scales_are_the_si_prefixes():
    expected = {"uF": 1e-6, "nF": 1e-9, "pF": 1e-12, "kohm": 1e3, "Mohm": 1e6, "mV": 1e-3, "mA": 1e-3, "uA": 1e-6,
                "ms": 1e-3, "us": 1e-6, "ns": 1e-9, "kHz": 1e3, "MHz": 1e6, "%": 1e-2, "%/K": 1e-2, "mV/K": 1e-3}
    for unit, scale in expected.items():
        assert UNIT_SCALES[unit][0] == scale, unit
    assert {UNIT_SCALES[u][1] for u in ("F", "uF", "nF", "pF")} == {"F"}
    assert UNIT_SCALES["%"][1] == "1" and UNIT_SCALES["uF*rpm"] == (1e-6, "F*rpm")


# --- classify ----------------------------------------------------------------------------------------------


def test_exact_within_one_part_in_a_billion():
    assert classify(1000.0, 0.0, 1000.0 * (1 + 5e-10)) == "exact"
    assert classify(1000.0, 0.0, 1000.0 * (1 - 5e-10)) == "exact"
    assert classify(1000.0, 0.0, 1000.0 * (1 + 2e-9)) == "misprint"  # no rounding room when half_unit is 0
    assert classify(0.0, 0.5, 0.0) == "exact"
    assert classify(-3.3, 0.05, -3.3) == "exact"


def test_rounding_up_to_half_a_unit_on_either_side():
    # 2.02 printed: anything from 2.015 to 2.025 rounds to it
    for computed in (2.0151, 2.0249, 2.0150001, 2.0249999, 2.02 + 0.005 * (1 + 1e-10), 2.02 - 0.005 * (1 + 1e-10)):
        assert classify(2.02, 0.005, computed) == "rounding", computed
    for computed in (2.0149999, 2.0250001, 2.02 + 0.005 * (1 + 1e-8), 2.02 - 0.005 * (1 + 1e-8), 2.1):
        assert classify(2.02, 0.005, computed) == "misprint", computed
    # the same in another scale: 150 mV printed holds 145 to 155 mV
    assert classify(0.150, 0.005, 0.1549) == "rounding" and classify(0.150, 0.005, 0.1551) == "misprint"
    assert classify(-0.150, 0.005, -0.1549) == "rounding" and classify(-0.150, 0.005, -0.1551) == "misprint"


def test_rounding_via_the_notes_rounded_intermediate():
    assert classify(2.02, 0.005, 2.05) == "misprint"
    assert classify(2.02, 0.005, 2.05, via_rounded=2.0249) == "rounding"
    assert classify(2.02, 0.005, 2.05, via_rounded=2.0251) == "misprint"
    assert classify(2.02, 0.005, 2.0201, via_rounded=9.0) == "rounding"  # either one suffices


def test_a_mismatch_is_a_misprint_on_the_notes_inputs_and_inconsistent_on_another_source():
    assert classify(22.0, 0.5, 11.0) == "misprint"
    assert classify(22.0, 0.5, 11.0, basis="note") == "misprint"
    assert classify(22.0, 0.5, 11.0, basis="LM358 datasheet") == "inconsistent"
    assert classify(22.0, 0.5, 22.3, basis="LM358 datasheet") == "rounding"


def test_lower_bound():
    assert classify(5.0, 0.05, 4.9, relation=">=") == "bound met"
    assert classify(4.9, 0.05, 4.9, relation=">=") == "bound met"  # equal meets it, and is not "exact"
    assert classify(4.9 * (1 - 1e-13), 0.05, 4.9, relation=">=") == "bound met"
    assert classify(4.9 * (1 - 1e-11), 0.05, 4.9, relation=">=") == "misprint"
    assert classify(4.89, 0.05, 4.9, relation=">=") == "misprint"  # within half a unit, but a bound has no rounding
    assert classify(4.89, 0.05, 4.9, relation=">=", basis="datasheet") == "inconsistent"


def test_upper_bound():
    assert classify(1.0, 0.05, 2.0, relation="<=") == "bound met"
    assert classify(2.0, 0.05, 2.0, relation="<=") == "bound met"
    assert classify(2.0 * (1 + 1e-13), 0.05, 2.0, relation="<=") == "bound met"
    assert classify(2.0 * (1 + 1e-11), 0.05, 2.0, relation="<=") == "misprint"
    assert classify(2.01, 0.05, 2.0, relation="<=") == "misprint"


def test_negative_bounds():
    """-0.5 >= -1 and -2 <= -1 are met, -2 >= -1 and -0.5 <= -1 are not."""
    assert classify(-0.5, 0.05, -1.0, relation=">=") == "bound met"
    assert classify(-2.0, 0.05, -1.0, relation=">=") == "misprint"
    assert classify(-2.0, 0.05, -1.0, relation="<=") == "bound met"
    assert classify(-0.5, 0.05, -1.0, relation="<=") == "misprint"


def test_a_print_equal_to_a_negative_bound_meets_it():
    """As 4.9 >= 4.9 is met, so is -1 >= -1 (a -1 V threshold printed as 'at least -1 V'), and -1 <= -1."""
    assert classify(-1.0, 0.05, -1.0, relation=">=") == "bound met"
    assert classify(-1.0, 0.05, -1.0, relation="<=") == "bound met"


@pytest.mark.parametrize("printed,computed", [(math.nan, 1.0), (1.0, math.nan), (math.inf, 1.0), (1.0, -math.inf)])
def test_classify_refuses_non_finite_numbers(printed, computed):
    with pytest.raises(ValueError, match="must both be finite numbers"):
        classify(printed, 0.1, computed)


# --- Claim -------------------------------------------------------------------------------------------------

NOTE = {"vin": 12.0, "r1": 30e3, "r2": 10e3, "unused": 1.0}


def divider(p):
    """12 V x 10k / (30k + 10k) = 3 V."""
    return p["vin"] * p["r2"] / (p["r1"] + p["r2"])


def claim(text="3.00", unit="V", compute=divider, **kw):
    fields = dict(id="c1", where="AN 1, eq 2", quantity="V_out", printed=Printed(text, unit), compute=compute,
                  reason="why", chapter="ch1")
    return Claim(**(fields | kw))


def test_evaluate_on_the_notes_inputs():
    out = claim().evaluate(NOTE, NOTE)
    assert out["status"] == "exact" and out["computed"] == pytest.approx(3.0, rel=1e-15)
    assert out["depends"] == ["r1", "r2", "vin"]  # "unused" was never read
    assert out["printed"] == 3.0 and out["printed_text"] == "3.00 V" and out["unit"] == "V"
    assert (out["id"], out["source"], out["chapter"], out["quantity"]) == ("c1", "AN 1, eq 2", "ch1", "V_out")
    assert (out["relation"], out["basis"], out["reason"], out["consequence"]) == ("=", "note", "why", "")


def test_evaluate_statuses_from_the_printed_digits():
    assert claim("3.004").evaluate(NOTE, NOTE)["status"] == "misprint"  # 3.0035..3.0045 does not hold 3
    assert claim("3.0").evaluate(NOTE, NOTE)["status"] == "exact"
    assert claim("2.96").evaluate(NOTE, NOTE)["status"] == "misprint"
    assert claim("2.96", basis="other note").evaluate(NOTE, NOTE)["status"] == "inconsistent"
    # printed in another unit: 3000 mV holds 2500..3500 mV, 3001 mV only 3000.5..3001.5 mV
    assert claim("3000", "mV").evaluate(NOTE, NOTE)["status"] == "exact"
    assert claim("3001", "mV").evaluate(NOTE, NOTE)["status"] == "misprint"
    assert claim("3.2", "V").evaluate(NOTE, NOTE)["status"] == "misprint"
    assert claim("3", "V", compute=lambda p: divider(p) + 0.4).evaluate(NOTE, NOTE)["status"] == "rounding"


def test_evaluate_compares_only_where_the_inputs_read_are_the_notes():
    changed = NOTE | {"r2": 20e3}  # 12 x 20k / 50k = 4.8 V
    out = claim().evaluate(changed, NOTE)
    assert out["status"] == "n/a" and out["computed"] == pytest.approx(4.8, rel=1e-15)
    assert out["reason"] == "inputs differ from the note's (r2): no printed value to compare"
    assert claim().evaluate(NOTE | {"unused": 2.0}, NOTE)["status"] == "exact"  # a change it does not read
    two = claim().evaluate(NOTE | {"vin": 5.0, "r1": 1.0}, NOTE)
    assert two["reason"].startswith("inputs differ from the note's (r1, vin)")
    missing = {k: v for k, v in NOTE.items() if k != "vin"}  # a key the defaults lack differs from them
    assert claim().evaluate(NOTE, missing)["status"] == "n/a"


def test_evaluate_reads_via_rounded_too():
    c = claim("3.1", compute=lambda p: 3.2, via_rounded=lambda p: p["vin"] / 4 + 0.06)  # 3.06: within 0.05 of 3.1
    out = c.evaluate(NOTE, NOTE)
    assert out["status"] == "rounded intermediate" and out["depends"] == ["vin"]  # 3.2 itself is not 3.1
    assert c.evaluate(NOTE | {"vin": 12.5}, NOTE)["status"] == "n/a"


def test_claim_unit_is_the_si_unit():
    assert claim("4.7", "kohm", compute=lambda p: 4.7e3).unit == "ohm"
    assert claim("4.7", "kohm", compute=lambda p: 4.7e3).evaluate(NOTE, NOTE)["status"] == "exact"
    assert claim("4.7", "kohm", compute=lambda p: 4.76e3).evaluate(NOTE, NOTE)["status"] == "misprint"  # 60 > 50 ohm
    out = claim("5", "%", compute=lambda p: 0.05).evaluate(NOTE, NOTE)
    assert out["unit"] == "1" and out["printed"] == pytest.approx(0.05) and out["status"] == "exact"


def test_a_wrong_method_is_its_own_status_even_when_the_arithmetic_holds():
    assert claim(method_wrong=True).evaluate(NOTE, NOTE)["status"] == "wrong method"
    assert claim("3.5", method_wrong=True).evaluate(NOTE, NOTE)["status"] == "wrong method"
    assert claim(method_wrong=True).evaluate(NOTE | {"r1": 1.0}, NOTE)["status"] == "n/a"


def test_a_truncated_last_digit():
    t = dict(truncated=True, reason="last digit truncated")
    assert claim("22.7", compute=lambda p: 22.755).evaluate(NOTE, NOTE)["status"] == "misprint"  # 0.055 off
    assert claim("22.7", compute=lambda p: 22.755, **t).evaluate(NOTE, NOTE)["status"] == "truncated"
    assert claim("22.7", compute=lambda p: 22.799, **t).evaluate(NOTE, NOTE)["status"] == "truncated"
    assert claim("22.7", compute=lambda p: 22.74, **t).evaluate(NOTE, NOTE)["status"] == "rounding"  # rounds anyway
    assert claim("22.7", compute=lambda p: 22.8001, **t).evaluate(NOTE, NOTE)["status"] == "misprint"  # cut: 22.8
    assert claim("-22.7", compute=lambda p: -22.755, **t).evaluate(NOTE, NOTE)["status"] == "truncated"
    assert claim("6.35", compute=lambda p: 6.366, **t).evaluate(NOTE, NOTE)["status"] == "misprint"  # cut: 6.36
    assert claim("11.7", compute=lambda p: 11.76, basis="datasheet", **t).evaluate(NOTE, NOTE)["status"] == "truncated"
    via = claim("22.7", compute=lambda p: 30.0, via_rounded=lambda p: 22.78, **t)
    assert via.evaluate(NOTE, NOTE)["status"] == "truncated"
    with pytest.raises(ValueError, match="c1: a claim marked truncated=True must say 'truncated'"):
        claim(truncated=True, reason="cut off")


@pytest.mark.parametrize("computed,status", [
    (1.26, "conservative"),  # 0.06 above the print: more than half a unit, within one
    (1.3, "conservative"),  # exactly one unit (0.1 K/W) above
    (1.3001, "misprint"),  # more than one unit
    (1.24, "rounding"),  # within half a unit: plain rounding
    (1.14, "misprint"),  # 0.06 below the print: the unsafe side
])
def test_rounded_to_the_safe_side_below(computed, status):
    c = claim("1.2", "K/W", compute=lambda p: computed, safe_side="below")
    assert c.evaluate(NOTE, NOTE)["status"] == status


@pytest.mark.parametrize("computed,status", [(1.14, "conservative"), (1.1, "conservative"), (1.0999, "misprint"),
                                             (1.26, "misprint"), (1.16, "rounding")])
def test_rounded_to_the_safe_side_above(computed, status):
    c = claim("1.2", "K/W", compute=lambda p: computed, safe_side="above")
    assert c.evaluate(NOTE, NOTE)["status"] == status


def test_bounds_on_a_claim():
    assert claim("2.9", relation=">=").evaluate(NOTE, NOTE)["status"] == "misprint"
    assert claim("3.1", relation=">=").evaluate(NOTE, NOTE)["status"] == "bound met"
    assert claim("2.9", relation="<=").evaluate(NOTE, NOTE)["status"] == "bound met"
    assert claim("3.1", relation="<=", basis="datasheet").evaluate(NOTE, NOTE)["status"] == "inconsistent"


# --- Recorder ----------------------------------------------------------------------------------------------


def test_recorder_remembers_what_is_read():
    r = Recorder({"a": 1, "b": 2, "c": 3})
    assert len(r) == 3 and list(r) == ["a", "b", "c"] and r.read == set()  # length and keys read no value
    assert r["a"] == 1 and r.get("b") == 2 and r.get("zz", 9) == 9
    assert r.read == {"a", "b"}
    with pytest.raises(KeyError):
        r["zz"]
    assert r.read == {"a", "b"}


def test_recorder_spread_reads_every_key():
    r = Recorder({"a": 1, "b": 2})
    assert {**r} == {"a": 1, "b": 2} and r.read == {"a", "b"}


@pytest.mark.parametrize("computed, safe_side, status", [
    (0.01455, "above", "conservative"),  # the note's CAP-CD bound: 0.0148 from the constant 160, 0.01455 exact
    (0.01455, "", "rounded intermediate"),  # no safe side declared: the rounded intermediate explains it, nothing more
    (0.01505, "above", "rounded intermediate"),  # the print below the exact value is not the safe side of a lower bound
    (0.01479, "above", "rounding"),  # the exact value itself rounds to the print: plain rounding
])
def test_a_rounded_intermediate_that_moves_a_bound_to_the_safe_side_is_conservative(computed, safe_side, status):
    c = claim("0.0148", "uF", compute=lambda p: computed * 1e-6, via_rounded=lambda p: 160e-6 / 10800,
              safe_side=safe_side)
    assert c.evaluate(NOTE, NOTE)["status"] == status


def test_every_claim_called_truncated_is_its_value_cut_off():
    """A reason that says 'truncated' must be true of the numbers: the print is the recomputed value (or the
    note's rounded intermediate) with its digits past the last printed one cut off, and rounding would not give
    the print (else the claim is plain rounding)."""
    from handbook.core.claim import _is_truncation
    from handbook.sources import SOURCES

    checked = 0
    for src in SOURCES:
        for c in src.claims():
            if not c.truncated:
                continue
            p = src.defaults
            computed = float(c.compute(p))
            via = None if c.via_rounded is None else float(c.via_rounded(p))
            assert _is_truncation(c.printed, computed) or (via is not None and _is_truncation(c.printed, via)), c.id
            checked += 1
    assert checked >= 3  # an93008-vz-min and both zener drifts at least
