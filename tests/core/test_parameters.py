"""A chapter's parameters, and what a reader injects, checked before the chapter computes anything."""
import pytest

from handbook.core import InputError
from handbook.core import parameters as P

CELL = 'pole_pairs = 6          # n\nrpm_min = 1800.0\nseries = "E12"\ninertia = None\nflag = True\nx = 2 * rpm_min\n'


def test_assignments_reads_the_cells_names_and_literals():
    assert P.assignments(CELL) == {"pole_pairs": 6, "rpm_min": 1800.0, "series": "E12", "inertia": None,
                                   "flag": True, "x": ...}


@pytest.mark.parametrize("given, message", [
    ({"pole_pair": 4}, "unknown parameter 'pole_pair' (did you mean 'pole_pairs'?)"),
    ({"pole_pairs": "four"}, "parameter 'pole_pairs' = 'four' is not a whole number (its default is 6)"),
    ({"pole_pairs": 4.5}, "is not a whole number"),
    ({"rpm_min": "fast"}, "parameter 'rpm_min' = 'fast' is not a number (its default is 1800.0)"),
    ({"series": 12}, "is not text"),
    ({"flag": 1}, "is not true or false"),
])
def test_a_bad_injected_parameter_is_refused_naming_it(given, message):
    with pytest.raises(InputError, match="^ch: ") as exc:
        P.check(P.assignments(CELL), given, chapter="ch")
    assert message in str(exc.value) and "\n" not in str(exc.value)


def test_good_values_pass_and_a_default_of_none_takes_anything():
    P.check(P.assignments(CELL), {"pole_pairs": 4, "rpm_min": 1500, "series": "E24", "inertia": 2e-5, "flag": False,
                                  "x": "anything"})
    P.check(P.assignments(CELL), {"pole_pairs": 4.0})  # a whole number written as a float


def test_the_history_is_checked_only_after_papermills_injected_cell():
    injected = "# Parameters\npole_pair = 4\n"
    with pytest.raises(InputError, match="did you mean 'pole_pairs'"):
        P.check_history(["", CELL, injected, "from handbook import report\nreport.setup()"])
    P.check_history(["", CELL, "from handbook import report\nreport.setup()"])  # run as written: nothing to check
    P.check_history(["report.setup()"])
