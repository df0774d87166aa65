"""What every design shares (handbook.design.common): the checked, frozen table; completing a table from the
schema; the messages for a misplaced or misspelt key; ordered limits; outputs declared on result fields."""
import copy
import pickle
from dataclasses import dataclass

import pytest

from handbook.core import InputError
from handbook.design import commutation, limiter
from handbook.design.common import Result, Table, checked_table, completed, is_checked, key_error, ordered, reported, tables_of
from handbook.design.schema import TABLES


def test_a_checked_table_is_frozen_and_keeps_its_mark_through_copy_and_pickle():
    t = checked_table("commutation", {"rpm_min": 1800.0})
    assert t["rpm_min"] == t.rpm_min == 1800.0 and is_checked("commutation", t)
    with pytest.raises(AttributeError, match="frozen"):
        t.rpm_min = 1.0
    with pytest.raises(TypeError):
        t["rpm_min"] = 1.0  # a Mapping has no item assignment
    for clone in (copy.copy(t), copy.deepcopy(t), pickle.loads(pickle.dumps(t))):
        assert is_checked("commutation", clone) and dict(clone) == {"rpm_min": 1800.0}
    assert not is_checked("class_d", t)  # a table of another name is not this one
    hand = Table("commutation", {"rpm_min": 1800.0})
    assert not is_checked("commutation", hand) and not is_checked("commutation", pickle.loads(pickle.dumps(hand)))
    assert not is_checked("commutation", {**t})  # spreading it makes a plain dict
    with pytest.raises(AttributeError, match=r"\[commutation\] has no key 'rpm'"):
        _ = t.rpm


def test_completed_fills_defaults_and_checks_each_given_value():
    s = completed("commutation", {"pole_pairs": 4})
    assert s["pole_pairs"] == 4 and s["rpm_min"] == 1800.0  # the note's 1800 rpm where none is given
    assert set(s) == {p.name for p in TABLES["commutation"]}
    with pytest.raises(InputError, match=r"commutation\.rpm_min"):
        completed("commutation", {"rpm_min": -5.0})
    with pytest.raises(InputError, match=r"did you mean commutation\.rpm_min"):
        completed("commutation", {"rpm_mni": 100.0})


def test_a_key_of_another_table_is_sent_there_and_a_near_miss_named():
    assert tables_of("i_no_trip") == ["current_limiter"]
    assert len(tables_of("t_ambient")) >= 2 and tables_of("no_such_key") == []
    assert "belongs in [current_limiter]" in str(key_error("commutation", "i_no_trip"))
    assert "did you mean current_limiter.i_no_trip" in str(key_error("current_limiter", "i_no_trp"))
    assert "known keys are" in str(key_error("current_limiter", "zzzzzz"))


def test_ordered_limits():
    s = {"a": 1.0, "b": 1.0}
    ordered("t", "a", "b", s, "A", strict=False)  # equal is allowed when not strict
    with pytest.raises(InputError, match=r"t\.a = 1 A must be below t\.b = 1 A"):
        ordered("t", "a", "b", s, "A")
    with pytest.raises(InputError, match="must not exceed"):
        ordered("t", "a", "b", {"a": 2.0, "b": 1.0}, "A", strict=False)


def test_outputs_are_the_reported_fields_with_their_units_and_labels():
    @dataclass(frozen=True)
    class Toy(Result):
        r: float = reported("ohm", "a resistor")
        hidden: float = 0.0

    assert [(o.key, o.unit, o.label) for o in Toy.outputs()] == [("r", "ohm", "a resistor")]
    assert Toy(spec={}, r=2.0, hidden=1.0).summary() == {"r": 2.0}
    keys = {o.key for o in limiter.LimiterResult.outputs()}
    assert {"r7", "i_trip_min", "i_trip_max", "p_r7"} <= keys and "spec" not in keys
    assert all(o.unit is not None and o.label for o in commutation.CommutationResult.outputs())
