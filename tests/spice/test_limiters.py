"""The current limiters in SPICE: drawing and netlist hold the same parts, every check agrees within its
stated tolerance, the corner shows the LM358's input-range failure, a design is confirmed at its worst
corners, and lcapy's derivation of the trip point equals the registry's."""
import functools
import re

import pytest

from handbook.spice import limiters, runner
from handbook.spice.circuit import evaluate
from handbook.spice.limiter_drawings import label, labels

BUILDERS = (limiters.one_transistor, limiters.opamp, limiters.opamp_corner, limiters.supply_referenced)



@functools.cache
def simulated(builder):
    c = builder()
    return c, runner.run(c.netlist)


@pytest.mark.parametrize("builder", BUILDERS, ids=lambda b: b.__name__)
def test_drawing_and_netlist_hold_the_same_parts(builder):
    c = builder()
    drawn = labels(c.draw())
    parts = {p.ref: label(p).partition("\n")[2] for p in c.parts}
    assert {k: drawn.get(k) for k in parts} == parts
    names = {line.split()[0].upper(): line for line in c.netlist.splitlines() if line and line[0] not in "*."}
    for p in c.parts:
        line = names[limiters.NAMES.get(p.ref, p.ref).upper()]
        value = p.value if isinstance(p.value, str) else f"{p.value:.6g}"
        assert value in re.split(r"[\s()]+", line), (p.ref, line)


@pytest.mark.parametrize("builder", BUILDERS, ids=lambda b: b.__name__)
def test_every_check_agrees_within_its_tolerance(ngspice, builder):
    c, out = simulated(builder)
    rows = evaluate(c, run=lambda _: out)
    assert len(rows) >= 2
    bad = [f"{r['id']}: {r['equation']:.6g} vs {r['spice']:.6g} ({r['rel_diff']:.2%} > {r['rtol']:.1%})"
           for r in rows if not r["agrees"]]
    assert not bad, bad


def test_the_corner_shows_the_input_range_failure(ngspice):
    _, nominal = simulated(limiters.opamp)
    _, corner = simulated(limiters.opamp_corner)
    assert nominal["head_p"] > 2.0 and nominal["out0"] > 10.0  # in range: the output high, no limiting
    assert corner["head_p"] < 2.0 and corner["out0"] < 0.1  # V+ within 2 V of the supply: the output stuck low
    assert corner["i_back"] < corner["i_trip"]  # it comes back, then trips where the node equation says


def test_a_design_is_confirmed_at_its_two_worst_corners(ngspice):
    from handbook.design import current_limiter

    r = current_limiter.design({})
    lo, hi, head = limiters.design_corners(r)
    assert lo["i_eq"] == pytest.approx(r.i_trip_min, rel=1e-9) and hi["i_eq"] == pytest.approx(r.i_trip_max, rel=1e-9)
    assert head["head_eq"] == pytest.approx(r.headroom_min, rel=1e-9)
    out = limiters.design_check(r)
    assert out["i_trip_min"] == pytest.approx(r.i_trip_min, rel=0.01)
    assert out["i_trip_max"] == pytest.approx(r.i_trip_max, rel=0.01)
    assert out["ok"] and out["headroom_min"] == pytest.approx(r.headroom_min, abs=5e-3)


def test_a_network_that_leaves_the_op_amp_latched_is_not_confirmed(ngspice):
    """R12 7 % low puts V+ within 2 V of the supply at the least-headroom corner: the trip currents still look
    normal afterwards, but at no motor current the output is already low; design_check must say so."""
    import dataclasses

    from handbook.design import current_limiter

    r = current_limiter.design({})
    bad = dataclasses.replace(r, r12=r.r12 * 0.93)
    out = limiters.design_check(bad)
    assert not out["ok"] and out["headroom_min"] < 2.0


def test_lcapy_derives_eq_13_from_the_netlist():
    out = pytest.importorskip("handbook.spice.lcapy_checks").compare()
    assert out["same_as_derived"] and out["same_as_printed"] and out["free_of_loop_gain"]
