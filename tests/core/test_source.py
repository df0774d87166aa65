"""The source contract: params() for every document, claims' recorded dependencies, the check cache."""
import json
import subprocess
import sys
import time

import pytest

from handbook.core import Claim, InputError, Param, Printed, Source
from handbook.core.checks_cache import key
from handbook.sources import SOURCES


def _toy(compute, **kw):
    claim = Claim(id="toy-1", where="toy", quantity="a sum", printed=Printed("3", "V"), compute=compute,
                  reason="1 + 2", chapter="toy", **kw)
    return Source(name="TOY", title="toy", build_claims=lambda: [claim], parameters=(
        Param(name="a", default=1.0, unit="V", meaning="first", low=0.0, high=10.0),
        Param(name="b", default=2.0, unit="V", meaning="second", low=0.0, high=10.0),
        Param(name="c", default=5.0, unit="V", meaning="unused", low=0.0, high=10.0)))


def test_dependencies_are_recorded_not_declared():
    src = _toy(lambda p: p["a"] + p["b"])
    assert src.evaluate()[0]["status"] == "exact" and src.evaluate()[0]["depends"] == ["a", "b"]
    changed = src.evaluate(src.params(b=3.0))[0]
    assert changed["status"] == "n/a" and "b" in changed["reason"] and changed["computed"] == 4.0
    # a parameter the claim does not read leaves the comparison with the print
    assert src.evaluate(src.params(c=7.0))[0]["status"] == "exact"


def test_a_rounded_intermediate_is_a_dependency_too():
    src = _toy(lambda p: p["a"] + 2.0, via_rounded=lambda p: p["b"] + 1.0)
    assert src.evaluate(src.params(b=9.0))[0]["status"] == "n/a"


@pytest.mark.parametrize("source", SOURCES, ids=lambda s: s.name)
def test_every_source_refuses_unknown_names_with_the_near_match(source):
    name = source.parameters[0].name
    with pytest.raises(InputError, match=f"did you mean '{name}'"):
        source.params(**{name + "x": 1.0})
    assert source.params() == source.defaults


@pytest.mark.parametrize("source", SOURCES, ids=lambda s: s.name)
def test_every_source_checks_ranges_naming_the_key(source):
    p = next(p for p in source.parameters if p.high is not None)
    with pytest.raises(InputError, match=f"{p.name} = .* out of range"):
        source.params(**{p.name: p.high * 10 + 1})


@pytest.mark.parametrize("source", SOURCES, ids=lambda s: s.name)
def test_every_default_is_inside_its_own_range(source):
    for p in source.parameters:
        assert p.check(p.default) == p.default, p.name


@pytest.mark.parametrize("edited", ["equations.py", "data.py", "circuit.py", "units.py", "equation.py"])
def test_cache_key_changes_with_any_code_the_equations_read(monkeypatch, edited):
    """Not only the equations module: the source's data and circuit (the printed values, the constants) and
    handbook.core (checking, units) change what a summary holds, so an edit to any of them is a new key."""
    from pathlib import Path

    src = next(s for s in SOURCES if s.name == "AN94002")
    k = key(src)
    real = Path.read_bytes
    monkeypatch.setattr(Path, "read_bytes", lambda self: real(self) + (b"#" if self.name == edited else b""))
    assert key(src) != k


def test_equations_command_answers_from_the_cache_in_under_a_second(tmp_path):
    env = {"HANDBOOK_CACHE": str(tmp_path), "PATH": "/usr/bin:/bin"}
    cmd = [sys.executable, "-m", "handbook", "equations", "--json"]
    first = subprocess.run(cmd, capture_output=True, text=True, env=env, timeout=120)
    assert first.returncode == 0, first.stderr
    t0 = time.perf_counter()
    second = subprocess.run(cmd, capture_output=True, text=True, env=env, timeout=60)
    elapsed = time.perf_counter() - t0
    assert second.returncode == 0 and json.loads(second.stdout) == json.loads(first.stdout)
    assert elapsed < 1.0, f"{elapsed:.2f} s"
    assert len(list(tmp_path.glob("equations-*.json"))) == len(SOURCES)
