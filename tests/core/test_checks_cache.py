"""The equation records stored on disk (handbook.core.checks_cache): what is read back is what a fresh build gives,
a file that cannot be read is built again, and a record that cannot be stored leaves no file."""
import importlib
import pickle
from types import SimpleNamespace

import pytest

from handbook.core import checks_cache
from handbook.core.equation import TablePoint
from handbook.sources import SOURCES


@pytest.fixture
def cache(tmp_path, monkeypatch):
    monkeypatch.setenv("HANDBOOK_CACHE", str(tmp_path))
    return tmp_path


@pytest.mark.parametrize("source", [s for s in SOURCES if s.equations_module], ids=lambda s: s.name)
def test_records_read_back_equal_a_fresh_build(cache, source):
    fresh = importlib.import_module(source.equations_module).build()
    stored = checks_cache.cached_equations(source)
    assert len(list(cache.glob("records-*.pickle"))) == 1
    read = checks_cache.cached_equations(source)  # from the file this time
    assert read is not stored and [e.id for e in read] == [e.id for e in fresh]
    for a, b in zip(read, fresh):
        assert a.printed == b.printed and a.derived == b.derived and a.check() == b.check()
        assert a.latex_printed() == b.latex_printed() and a.summary() == b.summary()


def test_units_read_back_with_their_latex(cache):
    """sympy pickles a unit without the LaTeX it was made with; the cache keeps the unit itself (R_OSC in Ω)."""
    lm = next(s for s in SOURCES if s.name.startswith("LM4651"))
    checks_cache.cached_equations(lm)
    eq6 = next(e for e in checks_cache.cached_equations(lm) if e.id == "lm4651-eq6")
    assert r"R_{OSC}\,[\Omega]" in eq6.latex_printed()


def test_an_unreadable_file_is_built_again(cache):
    src = next(s for s in SOURCES if s.name == "TDA5341")
    checks_cache.cached_equations(src)
    (path,) = cache.glob("records-*.pickle")
    path.write_bytes(b"not a pickle")
    assert [e.id for e in checks_cache.cached_equations(src)] == ["tda5341-capcdm", "tda5341-max-delay"]
    assert pickle.loads(path.read_bytes())[0].id == "tda5341-capcdm"  # stored again


def test_a_record_that_cannot_be_stored_leaves_no_file(cache, monkeypatch):
    src = next(s for s in SOURCES if s.name == "TDA5341")
    module = importlib.import_module(src.equations_module)
    real = module.build

    def build():  # a table point whose chain is a lambda: pickle refuses it
        first, *rest = real()
        point = TablePoint(where="x", at="x", inputs={}, figure=first.table[0].figure if first.table else None,
                           through=lambda v: v)
        object.__setattr__(first, "table", (point,))
        return [first, *rest]

    monkeypatch.setattr(module, "build", build)
    records = checks_cache.cached_equations(SimpleNamespace(name=src.name, equations_module=src.equations_module))
    assert len(records) == 2 and not list(cache.glob("records-*"))
