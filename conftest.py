"""Both cores busy to the end (pytest-xdist, ``make test`` runs ``pytest -n 2 --dist loadscope``): the
scheduler below sends every test on its own, except what must stay together on one worker:

* a notebook's cells (nbval runs them in order in one kernel): one unit per notebook;
* a test file (or folder) whose fixture is expensive (the converter tests import PyOpenMagnetics once): one
  unit, so the fixture is built once;
* the browser check and the PDF: one unit, the browser check first (its HTML build leaves Sphinx's environment,
  which the PDF's single-page build then reads instead of every chapter again).

The longest units go out first, so that neither worker is left with a long one at the end.
(xdist's own ``--dist loadgroup`` marks do not take under pytest 9.2, whose node ids moved from
``_nodeid`` to ``_id``; a scheduler of our own does not depend on that.)
"""
import pytest

#: test files kept on one worker because their module-scoped fixture is expensive to build twice
TOGETHER = ("tests/test_browser.py", "tests/design/converter/", "tests/report/test_plots.py",
            "tests/design/limiter/test_limiter_exact_wide.py",  # its last test counts what the others found
            "tests/report/test_design_report.py")  # its reports (template, [class_d]) are built once
#: units sent first, longest first (measured on the 2-core machine); the rest follow in collection order
FIRST = ("tests/test_browser.py", "tests/design/limiter/test_limiter_exact_wide.py",
         "tests/report/test_design_report.py",
         "tests/design/limiter/test_limiter_search.py::test_the_search",
         "tests/design/converter/", "tests/design/limiter/test_limiter_search.py::test_every_design",
         "tests/design/test_fuzz_specs.py")


#: test files that are one unit with another (file -> the unit)
WITH = {"tests/test_pdf.py": "tests/test_browser.py"}


def _unit(nodeid: str) -> str:
    path = nodeid.split("::", 1)[0]
    path = WITH.get(path, path)
    if path.endswith(".ipynb"):
        return path
    return next((unit for unit in TOGETHER if path.startswith(unit)), nodeid)


def _rank(unit: str) -> int:
    """``FIRST`` in its order, then the notebooks (ten to twenty seconds each), then every other test (mostly
    short: they fill in at the end, so neither worker waits long for the other)."""
    first = next((i for i, prefix in enumerate(FIRST) if unit.startswith(prefix)), None)
    if first is not None:
        return first
    return len(FIRST) + (0 if unit.endswith(".ipynb") else 1)


@pytest.hookimpl(optionalhook=True)  # a run without xdist (-p no:xdist) does not know the hook
def pytest_xdist_make_scheduler(config, log):
    from xdist.scheduler import LoadScopeScheduling

    class Scheduling(LoadScopeScheduling):
        def _split_scope(self, nodeid: str) -> str:
            return _unit(nodeid)

    config.option.loadscopereorder = False
    return Scheduling(config, log)


def pytest_collection_modifyitems(items):
    """The order units are sent in: ``FIRST``, then collection order (stable, so a notebook's cells keep theirs;
    every worker collects, and sorts, the same way)."""
    items.sort(key=lambda item: _rank(_unit(item.nodeid)))
