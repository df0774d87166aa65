"""The four designs' common face (handbook.design.<name>: checked, design, explain, sensitivity, enumerate), each
called the same way; every enumeration is an exhaustive search of its own, held against the design's answer."""
import pytest

from handbook.design import class_d, commutation, converter, limiter
from handbook.design.common import Table
from handbook.design.solvers import Infeasible

#: a spec each design cannot meet (from the designs' own tests)
UNMEETABLE = {commutation: {"flyback_time": 5e-3, "rpm_reverse": 3000.0}, limiter: {"i_no_trip": 1.0, "i_must_trip": 1.25},
              class_d: {"p_continuous": 1000.0}, converter: {"i_out": 5.0}}
TABLES = {commutation: "commutation", limiter: "current_limiter", class_d: "class_d", converter: "converter"}


@pytest.mark.parametrize("design", list(TABLES), ids=list(TABLES.values()))
def test_one_face(design):
    s = design.checked(None)
    assert isinstance(s, Table) and s.name == TABLES[design] and design.checked(s) is s  # checked once
    result = design.design(s)
    assert result.table == TABLES[design] and result.spec is s
    assert design.explain({}) is None
    why = design.explain(UNMEETABLE[design])
    assert isinstance(why, Infeasible) and why.table == TABLES[design] and why.achievable
    rows = design.sensitivity(result)
    assert rows and all(isinstance(r, dict) and isinstance(r["source"], str) for r in rows)


def test_enumerations_agree_with_the_designs():
    assert commutation.enumerate({}) == commutation.design({}).cap_cd
    r_osc, l_out, c_out, r_dly = class_d.enumerate({})
    amp = class_d.design({})
    assert (r_osc, l_out, c_out, r_dly) == (amp.r_osc, amp.l_out, amp.c_out, amp.r_dly)
    _, every, chosen = converter.enumerate({})
    coil = converter.design({})
    assert (chosen.shape, chosen.material) == (coil.core_shape, coil.core_material) and len(every) > 10
    reduced = {n: v for n, v in zip(("r10", "r11", "r12", "r13"), (4320.0, 11800.0, 5110.0, 13700.0))}
    r7, network, margin = limiter.enumerate(reduced)
    got = limiter.design(reduced)
    assert r7 == got.r7 and min(got.margin_low, got.margin_high) >= margin - limiter.GAP - 1e-9


def test_enumerating_a_full_series_is_refused_not_attempted():
    from handbook.core import InputError

    with pytest.raises(InputError, match="too many to enumerate"):
        limiter.enumerate({})


def test_a_hand_made_table_is_checked_again():
    """Only a design's ``checked`` marks a Table as checked: one made by hand (here with a tolerance of 500 %) is
    validated like any spec, and copies and pickles keep the mark of a checked one."""
    import copy
    import pickle

    from handbook.core import InputError

    good = commutation.checked(None)
    assert commutation.checked(copy.deepcopy(good)) == good and pickle.loads(pickle.dumps(good))._checked
    with pytest.raises(InputError, match="commutation.tolerance = 5"):
        commutation.design(Table("commutation", {**good, "tolerance": 5.0}))
