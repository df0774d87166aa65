"""The four designs' common face (handbook.design.<name>: checked, design, explain, sensitivity, enumerate), each
called the same way; every enumeration is an exhaustive search of its own, held against the design's answer."""
import pytest

from handbook.design import class_d, commutation, converter, limiter
from handbook.design.common import Table
from handbook.design.solvers import Infeasible

#: a spec each design cannot meet (from the designs' own tests)
UNMEETABLE = {commutation: {"flyback_time": 5e-3, "rpm_reverse": 3000.0}, limiter: {"i_no_trip": 1.0, "i_must_trip": 1.25},
              class_d: {"thermal_basis": "continuous_sine", "p_continuous": 1000.0}, converter: {"i_out": 5.0}}
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


#: a spec small enough for each design's enumeration (the limiter's E96 dividers pinned but R9)
ENUMERABLE = {commutation: {}, class_d: {}, converter: {}, limiter: dict(zip(("r10", "r11", "r12", "r13"),
                                                                       (4320.0, 11800.0, 5110.0, 13700.0)))}


@pytest.mark.parametrize("design", list(TABLES), ids=list(TABLES.values()))
def test_every_enumeration_answers_in_the_results_keys_and_agrees(design):
    found = design.enumerate(ENUMERABLE[design])
    got = design.design(ENUMERABLE[design]).summary()
    margin = found.pop("worst_margin", None)
    assert found and set(found) <= set(got) and found == {k: got[k] for k in found}
    if margin is not None:  # the limiter's tie-break: the design's worst margin within GAP of the best
        assert min(got["margin_low"], got["margin_high"]) >= margin - limiter.GAP - 1e-9
    none = {commutation: {"rpm_min": 100.0, "rpm_max": 20000.0}, limiter: {**ENUMERABLE[limiter], "i_must_trip": 1.1},
            class_d: UNMEETABLE[class_d], converter: UNMEETABLE[converter]}[design]
    assert design.enumerate(none) is None and isinstance(design.explain(none), Infeasible)


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
