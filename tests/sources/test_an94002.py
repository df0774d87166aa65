"""AN94002: every equation's check, and every example against numbers worked out independently here."""
import dataclasses
import itertools
import math

import numpy as np
import pytest

from handbook.core import UNIT_SCALES, InputError, Printed, series
from handbook.sources import an94002 as note

EQS = {e.id: e for e in note.SOURCE.equations()}
EXAMPLES = {r["id"]: r for r in note.evaluate()}
DEFAULTS = note.SOURCE.defaults


# ---------------------------------------------------------------------------------------------
# equations

EXPECTED_DIFFERENT = {
    "an94002-eq6": 56 / 55,  # 160 against 10 x 22 uA / 1.4 V = 157.14
    "an94002-eq9b": 0.9994,  # 2.63 against 5 / 1.9
    "an94002-eq11-num": None,  # 2.02 and 0.741 rounded: differs by a small affine term
}


@pytest.mark.parametrize("eq_id", sorted(EQS))
def test_equation_printed_against_derived(eq_id):
    c = EQS[eq_id].check()
    assert c.dims_ok, c.dims_note
    if eq_id in EXPECTED_DIFFERENT:
        assert not c.agrees
        if EXPECTED_DIFFERENT[eq_id] is not None:
            assert float(c.factor) == pytest.approx(EXPECTED_DIFFERENT[eq_id], rel=1e-12)
    else:
        assert c.agrees, EQS[eq_id].summary()["note"]


def test_every_numbered_equation_of_the_note_is_registered():
    numbered = {e.source.split("eq (")[1].split(")")[0] for e in EQS.values() if "eq (" in e.source}
    assert numbered >= {str(i) for i in range(1, 15)}


def test_eq2_ocr_text_is_dimensionally_wrong_and_the_reconstruction_right():
    eq = EQS["an94002-eq2"]
    assert eq.ocr_dims_ok() is False
    assert eq.check().dims_ok and eq.reconstructed


def test_eq11_numeric_form_differs_only_by_rounding():
    eq = EQS["an94002-eq11-num"]
    diff = eq.check().difference
    vcs = [s for s in diff.free_symbols if "cs" in s.name][0]
    # printed - derived = (0.741 - 16/21.6) V_cs ... tiny coefficients: rounding of 2.0196 and 0.74074
    assert abs(float(diff.subs(vcs, 0))) == pytest.approx(2.02 - 7.79 * 5.6 / 21.6, abs=1e-12)
    assert abs(float(diff.coeff(vcs))) == pytest.approx(abs(0.741 - 16 / 21.6), rel=1e-9)


def test_derived_trip_point_matches_a_hand_solution_of_the_two_dividers():
    # independent: solve the two KCL equations numerically for one set of values
    vs, vd1, r9, r10, r11, r12, r13 = 12.0, 8.0, 300.0, 5.5e3, 16.5e3, 5.7e3, 15.8e3
    ref = vs - vd1 + vd1 * r11 / (r9 + r10 + r11)
    # V+ = ref: (vs - vcs - ref)/r12 = (ref - (vs - vd1))/r13
    vcs = vs - ref - r12 * (ref - (vs - vd1)) / r13
    eq = EQS["an94002-eq13"]
    sub = {s: v for s in eq.derived.free_symbols for name, v in
           (("V_{D1}", vd1), ("R_9", r9), ("R_{10}", r10), ("R_{11}", r11), ("R_{12}", r12), ("R_{13}", r13))
           if s.name == name}
    assert float(eq.derived.subs(sub)) == pytest.approx(vcs, rel=1e-12)
    assert note.v_cs_trip(vd1, r9, r10, r11, r12, r13) == pytest.approx(vcs, rel=1e-12)


# ---------------------------------------------------------------------------------------------
# examples: recomputed values against numbers worked out here by hand

HAND = {
    "an94002-fosc": math.sqrt(25e-3 * 0.5 * 6 / 72e-6) / (2 * math.pi),
    "an94002-tstart": 0.5,
    "an94002-capst": 0.5 * 2e-6 / (2 * 2.15),
    "an94002-capst-choice": 0.22e-6,
    "an94002-capst-datasheet": 0.25e-6,
    "an94002-window": 1.4,
    "an94002-eq6-constant": 10 * 22e-6 / 1.4,
    "an94002-capcd-bound": 22e-6 * (10 / (1800 * 6)) / 1.4,
    "an94002-c3": 18e-9,
    "an94002-c4": 18e-9,
    "an94002-ich-max": 11e-6,
    "an94002-eq9-constant": 5e-6 / 1.9,
    "an94002-eq9-window": 1.9,
    "an94002-vmot-max": 9.8,
    "an94002-vin": 2.0,
    "an94002-vmot-min": 1.7,
    "an94002-vbe-tc": -0.0025,
    "an94002-vbe": 0.82,  # V_BE(on) up to 0.82 V at 10 mA (BC556-558 sheets): 'about 0.8 V' is inside
    "an94002-offset-generic": 0.10,
    "an94002-vd1-min": 7.79,
    "an94002-factor-a": 16 / 21.6,
    "an94002-a-vd1": 16 / 21.6 * 7.79,
    "an94002-level-shift": 7.79 * 5.6 / 21.6,
    "an94002-vcs-at-opamp": 0.1 * 16 / 21.6,
    "an94002-window-high": 0.1 * 16 / 21.6 + 0.009,
    "an94002-window-low": 0.1 * 16 / 21.6 - 0.009,
    "an94002-offset-tol": 0.009 / (0.1 * 16 / 21.6),
    "an94002-zener-tol": 0.05,
    "an94002-zener-drift": 0.155,
    "an94002-zener-drift-pct": 0.155 / 7.79,
    "an94002-zener-tc": 0.00085 * 8.2,  # '+0.08 %/K' printed to one figure: up to 0.085 %/K
    "an94002-zener-spread": 0.5 / 8.2,  # BZX79-C8V2: 7.7 to 8.7 V, both 0.5 V from 8.2 V
    "an94002-shift-7v7": 7.7 * 5.6 / (5.6 + 16),  # V_s - V_+ at V_Z = 7.7 V, V_cs = 0
    "an94002-total-tol": 1.12 * 1.05 * 1.05 - 1,
    "an94002-c2": 1 / (2 * math.pi * 2e6 * 2.0),
    "an94002-r3": 39e3,
    "an94002-r13": 16e3,
    "an94002-c5": 220e-9,
    "an94002-c6": 2e-9,
}

STATUS = {
    "exact": {"an94002-tstart", "an94002-capst-choice", "an94002-window", "an94002-c3", "an94002-c4",
              "an94002-eq9-window", "an94002-vmot-max", "an94002-vin", "an94002-vmot-min", "an94002-vbe-tc",
              "an94002-offset-generic", "an94002-vd1-min", "an94002-zener-tol", "an94002-r3",
              "an94002-r13", "an94002-c5"},
    # C2 >= 39.8 nF (10 uF chosen), C6 >= 2000 pF; 0.8 V and 6.2 mV/K inside the datasheets' ranges
    "bound met": {"an94002-c2", "an94002-c6", "an94002-vbe", "an94002-zener-tc"},
    "conservative": {"an94002-capcd-bound"},  # a lower bound printed 1.7 % high, through the constant 160
    "rounding": {"an94002-fosc", "an94002-capst", "an94002-eq6-constant",
                 "an94002-eq9-constant", "an94002-factor-a", "an94002-a-vd1", "an94002-level-shift",
                 "an94002-vcs-at-opamp", "an94002-offset-tol", "an94002-zener-drift-pct",
                 "an94002-total-tol"},
    "truncated": {"an94002-zener-drift"},  # 155 mV printed 150: cut off, not rounded by either rule
    "misprint": {"an94002-window-high", "an94002-window-low"},
    "wrong method": {"an94002-resistor-tol", "an94002-total-exact"},  # percentages multiplied, matching assumed
    "inconsistent": {"an94002-capst-datasheet", "an94002-ich-max", "an94002-zener-spread", "an94002-shift-7v7"},
}


def test_more_than_twenty_examples_all_classified():
    assert len(EXAMPLES) > 20
    assert set(EXAMPLES) == set().union(*STATUS.values())


@pytest.mark.parametrize("ex_id", sorted(HAND))
def test_example_recomputed_value(ex_id):
    assert EXAMPLES[ex_id]["computed"] == pytest.approx(HAND[ex_id], rel=1e-9)


@pytest.mark.parametrize("status", sorted(STATUS))
def test_example_statuses(status):
    got = {k for k, r in EXAMPLES.items() if r["status"] == status}
    assert got == STATUS[status]


def test_a_deliberately_wrong_printed_value_is_flagged():
    for ex in note.SOURCE.claims():
        if ex.relation != "=" or ex.method_wrong:  # a wrong method's status does not depend on the print
            continue
        good = ex.evaluate(DEFAULTS, DEFAULTS)["computed"]
        wrong = Printed(repr(good * 1.5 / UNIT_SCALES[ex.printed.unit][0]), ex.printed.unit)
        r = dataclasses.replace(ex, printed=wrong).evaluate(DEFAULTS, DEFAULTS)
        assert r["status"] == ("misprint" if ex.basis == "note" else "inconsistent"), ex.id


def test_changed_inputs_make_the_comparison_not_applicable():
    rows = {r["id"]: r for r in note.evaluate(note.params(rpm_min=900.0))}
    assert rows["an94002-capcd-bound"]["status"] == "n/a"
    assert rows["an94002-capcd-bound"]["computed"] == pytest.approx(22e-6 * 10 / (900 * 6 * 1.4), rel=1e-12)
    assert rows["an94002-fosc"]["status"] == "rounding"  # does not depend on rpm_min


def test_claims_record_the_parameters_they_read():
    rows = {r["id"]: r for r in note.evaluate(note.params(cap_series="E6"))}
    # C3 is picked from the series: no printed value to compare with another series
    assert rows["an94002-c3"]["status"] == "n/a" and "cap_series" in rows["an94002-c3"]["reason"]
    assert rows["an94002-c3"]["computed"] == pytest.approx(22e-9)  # E6: 15 nF x 0.95 < 14.55 nF <= 22 nF
    # the window does not read the series: still compared with the print
    assert rows["an94002-window"]["status"] == "exact"
    assert rows["an94002-window"]["depends"] == ["v_cd_high_min", "v_cd_low_max"]
    assert rows["an94002-c3"]["depends"] == ["cap_series", "cap_tolerance", "i_charge_max", "pole_pairs", "rpm_min",
                                             "v_cd_high_min", "v_cd_low_max"]
    # a claim resting on a datasheet figure reads no parameter at all
    assert rows["an94002-ich-max"]["depends"] == [] and rows["an94002-ich-max"]["status"] == "inconsistent"


# ---------------------------------------------------------------------------------------------
# the op-amp limiter's worst case, against a brute-force search done here

def test_worst_case_corners_bound_a_dense_random_sample():
    p = note.params()
    wc = note.trip_worst_case(p)
    rng = np.random.default_rng(1)
    k = 200_000
    r9 = note.r9_for(0.1, 8.2, 5.6e3, 16e3)

    def vary(x, t):
        return x * (1 + rng.uniform(-t, t, k))

    r9_, r10, r11, r12, r13 = (vary(x, .01) for x in (r9, 5.6e3, 16e3, 5.6e3, 16e3))
    a = r13 / (r12 + r13)
    b = r11 / (r9_ + r10 + r11)
    v = vary(8.2, .05) * (1 - b / a) - rng.uniform(-9e-3, 9e-3, k) / a
    assert wc.low <= v.min() and v.max() <= wc.high
    # and the corners are reached: brute force over the 2^7 corners written out here
    vals = []
    for s in itertools.product((-1, 1), repeat=7):
        r9_, r10, r11, r12, r13 = (x * (1 + 0.01 * si) for x, si in zip((r9, 5.6e3, 16e3, 5.6e3, 16e3), s[:5]))
        vd1, vos = 8.2 * (1 + 0.05 * s[5]), 9e-3 * s[6]
        aa, bb = r13 / (r12 + r13), r11 / (r9_ + r10 + r11)
        vals.append(vd1 * (1 - bb / aa) - vos / aa)
    assert wc.low == pytest.approx(min(vals), rel=1e-12) and wc.high == pytest.approx(max(vals), rel=1e-12)
    assert 1.0e-3 < wc.low < 1.5e-3 and 0.205 < wc.high < 0.208


def test_cap_cd_choice_rejects_15nF_for_its_tolerance():
    chosen, bound, rejected = note.choose_cap_cd(1800, 6, 22e-6, 1.4, 0.05, "E12")
    assert chosen == pytest.approx(18e-9)
    assert bound == pytest.approx(14.55e-9, rel=1e-3)
    assert "not at -5%" in rejected[15e-9]
    # with the datasheet's 11 uA charge current the bound halves and 8.2 nF suffices
    assert note.choose_cap_cd(1800, 6, 11e-6, 1.4, 0.05, "E12")[0] == pytest.approx(8.2e-9)


def test_speed_range_of_the_board_capacitor():
    # 18 nF at -5 %: lowest speed with 22 uA over 1.4 V; at +5 % highest with 10.6 uA over 0.1 V
    assert note.rpm_min_for(18e-9 * 0.95, 6, 22e-6, 1.4) == pytest.approx(10 * 22e-6 / (1.4 * 6 * 17.1e-9))
    assert note.rpm_max_for(18e-9 * 1.05, 6, 10.6e-6, 0.1) == pytest.approx(10 * 10.6e-6 / (0.1 * 6 * 18.9e-9))
    assert note.rpm_ratio(1.4, 0.1, 10.6e-6, 22e-6) == pytest.approx(14 * 10.6 / 22)
    lo, hi = note.reliable_speed_range(18e-9, 0.05, 6, 10.6e-6, 22e-6, 1.4, 0.1)
    assert lo == pytest.approx(1531.6, abs=0.1) and hi == pytest.approx(9347.4, abs=0.1)  # by hand, as above


def test_cap_ti_waveform_times():
    t, v = note.cap_ti_waveform(10e-9, DEFAULTS)
    assert t[1] == pytest.approx(10e-9 * 0.1 / 57e-6)
    assert t[2] - t[1] == pytest.approx(3.8e-3)
    assert t[3] - t[2] == pytest.approx(10e-9 * 2.0 / 28e-6)
    assert list(v) == [0.2, 0.3, 2.2, 0.2]


def test_12nc_codes_that_disagree_with_the_printed_values():
    bad = {ref for ref, _, value, _, _, _, nc in note.PARTS
           if value and note.decode_12nc(nc) is not None and abs(note.decode_12nc(nc) - value) > 1e-6 * value}
    assert bad == {"R14", "C6"}
    # the decade rule by hand: two digits, then 8 = x 0.1, 9 = x 1, n = x 10^n of the family's base unit
    assert note.decode_12nc("2322 181 53229") == 22.0 and note.decode_12nc("2322 181 53681") == 680.0
    assert note.decode_12nc("2322 181 53108") == pytest.approx(1.0) and note.decode_12nc("2322 181 53393") == 39e3
    assert note.decode_12nc("2222 037 68109") == pytest.approx(10e-6)  # the electrolytics' base unit is the µF
    assert note.decode_12nc("2222 370 21183") == pytest.approx(18e-9) and note.decode_12nc("2322 181 53") is None


def test_parts_rows_compare_print_code_and_calculation():
    rows = {r[0]: r for r in note.parts_rows(note.params())}
    assert list(rows) == [ref for ref, *_ in note.PARTS]
    assert all(len(r) == len(note.PARTS_HEADER) for r in rows.values())
    differs = {ref for ref, r in rows.items() if "**differs**" in r[6]}
    assert differs == {"R14", "C6"}
    # decoded by hand: ...53229 = 22 x 1 ohm, ...53701 = 70 x 10 ohm, ...17224 = 22 x 10^4 pF, ...68109 = 10 x 1 µF
    assert rows["R1"][6] == "22 Ω" and rows["R14"][6].startswith("700 Ω")
    assert rows["C6"][6].startswith("220 nF") and rows["C5"][6] == "220 nF"
    assert rows["C1"][6] == "10 µF" and rows["R7"][6] == ""  # TBD value
    assert rows["R1"][2] == "22 Ω" and rows["C1"][2] == "10 µF" and rows["R10"][3] == "1%"
    # R7: 0.8 V / 1 A and 0.1 V / 1 A; R9: 0.1 V x 21.6 k / 8.1 V = 266.7 ohm, nearest E96 267 ohm
    assert rows["R7"][8] == "800 mΩ (O1, 0.8 V) or 100 mΩ (O2, 100 mV)"
    assert rows["R9"][8] == "267 Ω (E96, eq 14)"
    assert rows["R3"][8] == "39 kΩ: exact" and rows["C3"][8] == "18 nF: exact" and rows["C6"][8] == "2 nF: bound met"
    assert rows["R2"][7] == rows["R2"][8] == ""
    # another limit current: R7 follows, the claims it shows are then not comparable
    other = {r[0]: r for r in note.parts_rows(note.params(i_limit=2.0, v_cs=0.2))}
    assert other["R7"][8] == "400 mΩ (O1, 0.8 V) or 100 mΩ (O2, 200 mV)"
    assert other["R9"][8].endswith("(E96, eq 14)") and other["R9"][8] != rows["R9"][8]


# ---------------------------------------------------------------------------------------------
# bad input

@pytest.mark.parametrize("call,field", [
    (lambda: note.t_com(1800, -2), "pole_pairs"),
    (lambda: note.t_com(1800, 2.5), "pole_pairs"),
    (lambda: note.t_com(0, 6), "rpm"),
    (lambda: note.cap_cd_min(1800, 6, 22e-6, float("nan")), "window"),
    (lambda: note.choose_cap_cd(1800, 6, 22e-6, 1.4, tolerance=1.5), "cap_tolerance"),
    (lambda: note.start_period(1e-7, 2e-6, 2.2, 0.05), "v_st_low"),
    (lambda: note.r9_for(9.0, 8.2, 5.6e3, 16e3), "v_cs"),
    (lambda: note.params(rpm_mni=900), "rpm_min"),
    (lambda: note.excursion(18e-9, np.array([1000.0, -5.0]), 6, 22e-6), "rpm"),
])
def test_bad_input_names_the_field(call, field):
    with pytest.raises(InputError, match=field):
        call()


def test_params_refuse_unknown_names_with_the_near_match():
    with pytest.raises(InputError, match="rpm_min") as exc:
        note.params(rpm_mni=1)
    assert "rpm_mni" in str(exc.value)


@pytest.mark.parametrize("key,value", [("rpm_min", -5.0), ("cap_tolerance", 1.5), ("pole_pairs", 2.5),
                                       ("i_charge_max", float("nan")), ("cap_series", "E7"), ("zener_voltage", "8.2")])
def test_params_refuse_values_out_of_range_naming_the_key(key, value):
    with pytest.raises(InputError, match=key):
        note.params(**{key: value})


def test_every_parameter_default_is_in_its_own_range():
    for par in note.SOURCE.parameters:
        assert par.check(par.default) == par.default, par.name


def test_bzx79_spread_and_the_level_shift_at_its_minimum_by_hand():
    """The datasheet's 7.7 to 8.7 V is -6.1 %/+6.1 % about 8.2 V (the note says +-5 %); at 7.7 V the 5.6 k / 16 k
    divider shifts 1.996 V, under the 2 V the note requires, and the note's R13 rule picks 15 k, not 16 k."""
    assert (8.2 - 7.7) / 8.2 == pytest.approx(0.0610, abs=5e-5) and (8.7 - 8.2) / 8.2 == pytest.approx(0.0610, abs=5e-5)
    assert EXAMPLES["an94002-zener-spread"]["printed"] == 0.05
    shift = 7.7 * 5.6e3 / 21.6e3
    assert shift == pytest.approx(1.99630, abs=1e-5) and shift < 2.0
    assert EXAMPLES["an94002-shift-7v7"]["relation"] == "<="  # 2 V required <= the shift: not met
    assert 5.6e3 * (7.7 - 2) / 2 == pytest.approx(15.96e3) and series.at_most("E24", 15.96e3) == 15e3
    assert 2 * 21.6 / 5.6 == pytest.approx(7.714, abs=5e-4)  # the V_Z 16 k needs
    assert (7.7 - 0.0062 * 25) * 5.6 / 21.6 == pytest.approx(1.956, abs=5e-4)  # at 0 C, the note's 6.2 mV/K
    consequence = EXAMPLES["an94002-shift-7v7"]["consequence"]
    assert "15 k" in consequence and "7.71 V" in consequence and "1.96 V" in consequence and "2.07 V" in consequence
    assert (7.7 - 16 / 21.6 * (7.7 - 0.1)) == pytest.approx(2.07, abs=5e-3)  # V_s - V_+ at V_cs = 100 mV
