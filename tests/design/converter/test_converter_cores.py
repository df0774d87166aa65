"""The shipped table of cores, materials and wires: rebuilt from PyOpenMagnetics, shipped in the wheel, held
against the makers' figures (handbook.design.converter.cores)."""
import fnmatch
import json
import shutil
import subprocess
import sys
import tomllib
import zipfile

import pytest
from converter_oracle import ROOT

from handbook.design.converter import cores as converter_cores
from handbook.design.converter import result as converter


def test_shipped_table_is_current(pom):
    """The shipped table is what PyOpenMagnetics' database gives today (every shape, material, wire and gap)."""
    built = json.loads(json.dumps(converter_cores.build()))
    shipped = converter_cores.load()
    assert built["source"] == shipped["source"]
    assert set(built["shapes"]) == set(shipped["shapes"]) == set(converter_cores.SHAPES)
    for section in ("shapes", "materials"):
        for name, row in built[section].items():
            assert set(row) == set(shipped[section][name]), name
            for key, value in row.items():
                if isinstance(value, float) or (isinstance(value, list) and value and isinstance(value[0], float)):
                    assert shipped[section][name][key] == pytest.approx(value, rel=1e-9), (name, key)
                else:
                    assert shipped[section][name][key] == value, (name, key)
    assert [w["name"] for w in built["wires"]] == [w["name"] for w in shipped["wires"]]
    assert all(b["r_per_m_hot"] == pytest.approx(s["r_per_m_hot"], rel=1e-9)
               for b, s in zip(built["wires"], shipped["wires"]))


def test_narrowest_section_is_the_least_of_the_columns_and_the_minimum_area():
    """EP cores: the centre post (about 0.74 A_e) carries all the flux and is narrower than the database's
    minimumArea; the gap table's reluctance grows with the gap."""
    for name, row in converter_cores.load()["shapes"].items():
        assert row["a_min"] == min(row["a_centre"], row["a_legs"], row["a_min_database"]), name
        assert all(b > a for a, b in zip(row["gap_reluctance"], row["gap_reluctance"][1:])), name
        assert row["gap_lengths"][0] <= converter.GAP_MIN
    ep10 = converter_cores.load()["shapes"]["EP 10"]
    assert ep10["a_min"] == ep10["a_centre"] == pytest.approx(8.553e-6, rel=1e-6)


def test_package_data_ships_the_table(tmp_path):
    """pyproject's package-data covers every non-Python file of the package, and a wheel built from the
    sources holds the table (the package reads it through importlib.resources)."""
    patterns = tomllib.loads((ROOT / "pyproject.toml").read_text())["tool"]["setuptools"]["package-data"]["handbook"]
    package = ROOT / "src" / "handbook"
    data = [p.relative_to(package).as_posix() for p in package.rglob("*")
            if p.is_file() and p.suffix not in (".py", ".pyc") and "__pycache__" not in p.parts]
    assert "design/converter/cores.json" in data
    for name in data:
        assert any(fnmatch.fnmatch(name, pat) for pat in patterns), name
    if shutil.which("git") is None:
        pytest.skip("no git to list the sources")
    # a wheel from a copy of the tracked sources (the work tree is left alone)
    files = subprocess.run(["git", "ls-files", "pyproject.toml", "src/handbook"], cwd=ROOT, capture_output=True,
                           text=True, check=True).stdout.split()
    for f in files:
        (tmp_path / "src" / f).parent.mkdir(parents=True, exist_ok=True)
        shutil.copy(ROOT / f, tmp_path / "src" / f)
    built = subprocess.run([sys.executable, "-m", "pip", "wheel", "--no-deps", "--no-build-isolation", "-q", "-w",
                            str(tmp_path / "dist"), str(tmp_path / "src")], capture_output=True, text=True, timeout=120)
    if built.returncode != 0 and "No module named" in built.stderr:
        pytest.skip(f"cannot build a wheel here: {built.stderr.strip()[-200:]}")
    assert built.returncode == 0, built.stderr
    wheel = next((tmp_path / "dist").glob("handbook-*.whl"))
    assert "handbook/design/converter/cores.json" in zipfile.ZipFile(wheel).namelist()


def test_catalogue_against_the_makers_figures():
    """PyOpenMagnetics' effective parameters of two cores against the makers' catalogues (within 5 %):
    EP 10 (TDK: Ae 11.3 mm^2, le 19.2 mm) and P 14/8 (Ferroxcube: Ae 25.1 mm^2, le 19.8 mm)."""
    ep10, p14 = converter_cores.load()["shapes"]["EP 10"], converter_cores.load()["shapes"]["P 14/8"]
    assert ep10["ae"] == pytest.approx(11.3e-6, rel=0.05) and ep10["le"] == pytest.approx(19.2e-3, rel=0.05)
    assert p14["ae"] == pytest.approx(25.1e-6, rel=0.05) and p14["le"] == pytest.approx(19.8e-3, rel=0.05)
