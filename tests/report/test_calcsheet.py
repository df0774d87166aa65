"""The calculation sheet (handbook.report.calcsheet): each equation step, evaluated here from its registry record
with lambdify at the design's own numbers, gives what the design reports; every step has a source; a known
erratum of an equation the designs use shows beside it; the HTML parses and carries MathML.

The oracle below is written apart from the sheet's code: for each design, the registry record each equation
step must show, the values (read from the result and its checked spec) and the number the design reports.
"""
from __future__ import annotations

import math
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
import sympy as sp

from handbook import catalog
from handbook.core.units import eng
from handbook.design import spec as specmod
from handbook.design.class_d import model
from handbook.report import calcsheet
from handbook.sources.lm4651.circuit import DEVICE

BOOK = Path(__file__).resolve().parents[2] / "book" / "examples"
SPECS = {"default": None, "fan_motor": BOOK / "fan_motor.toml", "amplifier_8ohm": BOOK / "amplifier_8ohm.toml"}
RPM = 60.0  # rpm per 1/s


def _commutation(r):
    s, t, n = r.spec, r.spec["tolerance"], r.spec["pole_pairs"]
    window = s["v_high_min"] - s["v_low_max"]
    rows = [("an94002-eq6", None, {"I_{ch,max}": s["i_charge_max"], "N_{min}": s["rpm_min"] / RPM,
                                   r"\Delta{}V_{win}": window, "n": n}, r.continuous_optimum * (1 - t), 1),
            ("an94002-eq7", None, {"I_{ch,min}": s["i_charge_min"], "C_{CD}": r.cap_cd * (1 + t),
                                   r"\Delta{}V_{noise}": s["min_excursion"], "n": n},
             r.summary()["rpm_max_reliable"], RPM),
            ("an94002-eq5", "N", {"I": s["i_charge_max"], "C_{CD}": r.cap_cd * (1 - t), r"\Delta{}V": window, "n": n},
             r.summary()["rpm_min_reliable"], RPM)]
    if r.start is not None:
        m = s["motor_tolerance"]
        levels = {"I_{ST}": s["i_st_max"], "V_{high}": s["v_st_high"], "V_{low}": s["v_st_low"]}
        rows += [("an94002-eq2", None, {"K_t": s["torque_constant"] * (1 - m), "I": s["start_current"] * (1 - m),
                                        "p": n, "J": s["inertia"] * (1 + m)}, r.start.f_osc_min, 1),
                 ("an94002-eq1", "C_{ST}", {"t_{start}": r.start.settle, **levels}, r.start.bound * (1 - t), 1),
                 ("an94002-eq1", None, {"C_{ST}": r.summary()["cap_st"] * (1 - t), **levels}, r.start.period_min, 1)]
    if r.watchdog is not None:
        levels = {"V_{high}": 2.2, "V_{low}": 0.3}  # the TDA5144's watchdog ramp (datasheet; AN94002 2.1.3)
        cap = r.summary()["cap_ti"]
        rows += [("an94002-eq9", "t_{wd}", {"C_{TI}": cap * (1 - t), "I_{wd}": s["i_wd_max"], **levels},
                  r.watchdog.t_wd_min, 1),
                 ("an94002-eq9", "t_{wd}", {"C_{TI}": cap * (1 + t), "I_{wd}": s["i_wd_min"], **levels},
                  r.watchdog.t_wd_max, 1)]
    return rows


def _limiter(r):
    j = r.summary()
    return [("an94002-eq13", None, {"V_{D1}": r.spec["zener_voltage"], "R_9": j["r9"], "R_{10}": j["r10"],
                                    "R_{11}": j["r11"], "R_{12}": j["r12"], "R_{13}": j["r13"]}, j["v_cs_nominal"], 1)]


def _class_d(r):
    s, j = r.spec, r.summary()
    # the dissipation at the oscillator corner of the smaller need, T_j at 150 C - tj_margin (model.thermal)
    p_d = min((model.heat(s, f)[0], float(model.heat(s, f)[2])) for f in (j["f_sw_min"], j["f_sw_max"]))[1]
    if s["theta_sa_available"] is None:  # the heat sink is the one needed: that is the dissipation reported
        assert math.isclose(p_d, j["p_dissipation"], rel_tol=1e-9)
    return [("lm4651-eq5", None, {r"\{R_{OSC}\}_{\Omega}": j["r_osc"] - 0.4 * j["r_dly"]}, j["f_sw"], 1),
            ("lm4651-filter", None, {"L_1": j["l_out"], "C_{BYP}": j["c_out"]}, j["f_corner"], 1),
            ("lm4651-eq11", None, {"T_{jmax}": DEVICE["tj_max"] - s["tj_margin"], "T_{a}": s["t_ambient"],
                                   "P_D": p_d, r"\theta_{JC}": DEVICE["theta_jc"][s["package"]],
                                   r"\theta_{CS}": s["theta_cs"]}, j["theta_sa_required"], 1)]


def _converter(r):
    s, j = r.spec, r.summary()
    return [("tca5600-eq1", None, {"V_F": s["v_f"], "V_{(9-8)}": s["v_regulator_drop"], "V_{CC2}": s["v_supply_min"],
                                   "V_{out2}": s["v_out"]}, r.vl_plus, 1),
            ("tca5600-eq2", None, {"V_{12(H)}": s["v12h"], "V_{CC2}": s["v_supply_min"], "V_{CE(sat)}": s["v_ce_sat"]},
             r.vl_minus, 1),
            ("tca5600-eq3", None, {"V_{L+}": r.vl_plus, "V_{L-}": r.vl_minus}, j["alpha"], 1),
            ("tca5600-eq4", None, {r"\alpha": j["alpha"], "f": j["f_min_design"]}, j["t1"], 1),
            ("tca5600-eq5", None, {"I_{out2}": s["i_out"], r"\alpha": j["alpha"]}, j["i_peak"], 1),
            ("tca5600-eq6", None, {"V_{L-}": r.vl_minus, "t_1": j["t1"], "I_{L(peak)}": j["i_peak"]}, j["l1"], 1),
            ("tca5600-eq6a", None, {"V_{12(H)}": s["v12h"], "I_{L(peak)}": j["i_peak"]}, j["r1"], 1)]


ORACLE = {"commutation": _commutation, "current_limiter": _limiter, "class_d": _class_d, "converter": _converter}


@pytest.fixture(scope="module")
def designed():
    """{spec name: {table: result}} for the default spec and the two examples (each designed once)."""
    out = {}
    for name, path in SPECS.items():
        spec = specmod.parse({}) if path is None else specmod.load(path)
        out[name] = specmod.run(spec)
    return out


def _record(eq_id):
    for src in catalog.sources():
        for e in src.equations():
            if e.id == eq_id:
                return e
    raise KeyError(eq_id)


def _evaluate(eq_id: str, solve_for: str | None, inputs: dict) -> float:
    """The registry record's expression (derived form; an empirical record's printed form, in its own units) at
    ``inputs``, by lambdify: no code of the sheet is used."""
    e = _record(eq_id)
    lhs, expr = e.lhs, (e.printed if e.empirical else e.derived)
    if solve_for is not None:
        unknown = next(s for s in expr.free_symbols | {lhs} if s.name == solve_for)
        expr = [x for x in sp.solve(sp.Eq(lhs, expr), unknown) if not x.could_extract_minus_sign()][0]
    symbols = sorted(expr.free_symbols, key=lambda s: s.name)
    assert {s.name for s in symbols} == set(inputs), (eq_id, symbols, sorted(inputs))
    value = float(sp.lambdify(symbols, expr, "math")(*(inputs[s.name] for s in symbols)))
    if e.empirical:
        assert e.lhs_scale is not None and float(e.lhs_scale / e.lhs_unit) == 1.0  # printed in the SI unit (Hz)
    return value


def _number_shown(value: float) -> set[str]:
    """How a value's number may read in the sheet: with an SI prefix, plain, or as a power of ten."""
    prefixed = eng(value, "X").split(" ")[0].replace("\N{MINUS SIGN}", "-")
    plain = f"{float(f'{value:.4g}'):g}"
    mantissa, _, exp = f"{value:.4g}".partition("e")
    return {prefixed, plain, rf"{float(mantissa):g} \times 10^{{{int(exp)}}}" if exp else plain}


@pytest.mark.parametrize("spec_name", list(SPECS))
@pytest.mark.parametrize("table", list(ORACLE))
def test_each_equation_step_evaluates_to_the_designs_number(designed, spec_name, table):
    result = designed[spec_name][table]
    rows = ORACLE[table](result)
    shown = [st for st in calcsheet.steps(table, result) if st.symbols_tex]
    assert len(shown) == len(rows), [st.title for st in shown]
    for st, (eq_id, solve_for, inputs, expected, per_si) in zip(shown, rows):
        e = _record(eq_id)
        assert st.source == e.source, (st.title, eq_id)
        value = _evaluate(eq_id, solve_for, inputs)
        assert math.isclose(value * per_si, expected, rel_tol=1e-6), (spec_name, table, eq_id, value * per_si, expected)
        text = st.result_text.replace("\N{MINUS SIGN}", "-")
        if text.endswith(" rpm"):  # speeds to the revolution, as the results tables show them
            assert text == f"{round(expected)} rpm", (text, expected)
        else:
            assert eng(expected) in text or eng(expected, "X").split(" ")[0] in text, (text, expected)
        for name, v in inputs.items():  # every value the record takes is shown substituted
            v_shown = v * RPM if name in ("N_{min}",) else v
            assert any(text in st.substituted_tex for text in _number_shown(v_shown)), (eq_id, name, v_shown,
                                                                                          st.substituted_tex)


@pytest.mark.parametrize("table", list(ORACLE))
def test_every_step_has_a_source_and_a_result(designed, table):
    for st in calcsheet.steps(table, designed["fan_motor"][table]):
        assert st.source.strip(), st.title
        assert st.result_text.strip(), st.title
        assert bool(st.symbols_tex) == bool(st.substituted_tex), st.title


def test_known_errata_of_an_equation_the_designs_use_are_beside_it(designed):
    # errata --json: the AN94002 errata made at eq (6) (the commutation design's CAP-CD bound)
    known = {r["id"] for r in catalog.errata("AN94002") if "eq (6)" in r["source"]}
    assert known, "no registered erratum at AN94002 eq (6): pick another equation"
    steps = calcsheet.steps("commutation", designed["default"]["commutation"])
    eq6 = [st for st in steps if st.source == _record("an94002-eq6").source]
    assert len(eq6) == 1
    assert {line.split(":")[0] for line in eq6[0].errata} >= known, eq6[0].errata
    eq5 = [st for st in steps if st.source == _record("an94002-eq5").source]
    assert eq5 and eq5[0].errata == ()  # no erratum is registered at eq (5)


@pytest.mark.parametrize("table", list(ORACLE))
def test_html_parses_and_carries_mathml(designed, table):
    steps = calcsheet.steps(table, designed["default"][table])
    fragment = calcsheet.html(steps)
    root = ET.fromstring(fragment)
    assert root.tag == "section"
    assert "<math" in fragment and "mathjax" not in fragment.lower() and "http" not in fragment.replace(
        "http://www.w3.org/1998/Math/MathML", "")
    blocks = root.findall("div")
    assert len(blocks) == len(steps)
    for block, st in zip(blocks, steps):
        text = "".join(block.itertext())
        assert st.source in text and st.result_text in text
        assert all(line in text for line in st.errata)
        maths = block.findall("{http://www.w3.org/1998/Math/MathML}math", ) + block.findall(".//math")
        assert len(block.findall(".//{http://www.w3.org/1998/Math/MathML}math")) >= (2 if st.symbols_tex else 0), \
            (st.title, maths)
