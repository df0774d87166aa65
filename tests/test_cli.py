"""`python -m handbook` from the shell, as a user runs it."""
import json
import shutil
import subprocess
import sys

import pytest

SI_UNITS = {"F", "ohm", "V", "A", "s", "Hz", "W", "K/W", "1", "1/K", "V/K", "rpm", "F*rpm"}


def run(*args):
    out = subprocess.run([sys.executable, "-m", "handbook", *args], capture_output=True, text=True, timeout=120)
    assert out.returncode == 0, out.stderr
    return out.stdout


def test_examples_json():
    rows = json.loads(run("examples", "--json"))
    assert len(rows) > 20
    for r in rows:
        assert {"id", "source", "quantity", "unit", "printed", "computed", "status"} <= set(r)
        assert isinstance(r["printed"], float) and isinstance(r["computed"], float)
        assert r["unit"] in SI_UNITS
        assert r["status"] in {"exact", "rounding", "truncated", "rounded intermediate", "bound met", "conservative",
                               "misprint", "inconsistent", "wrong method"}
    by_id = {r["id"]: r for r in rows}
    assert by_id["an94002-capcd-bound"]["printed"] == 1.48e-8  # 0.0148 uF in farads
    assert by_id["an94002-offset-tol"]["printed"] == 0.12  # a percentage as a fraction
    assert by_id["an94002-window-high"]["status"] == "misprint"


def test_equations_json_and_tables():
    rows = json.loads(run("equations", "--json"))
    assert {"id", "source", "printed_latex", "derived_latex", "agrees", "note"} <= set(rows[0])
    assert {r["id"] for r in rows if not r["agrees"]} == {"an94002-eq6", "an94002-eq9b", "an94002-eq11-num",
                                                          "an93008-eq2", "tda5341-capcdm", "tda5341-max-delay",
                                                          "lm4651-eq3", "lm4651-eq4", "lm4651-eq5", "lm4651-eq6",
                                                          "lm4651-eq8", "lm4651-eq9", "lm4651-eq12"}
    # the LM4651's internal circuits are not shown: those equations are empirical, checked against its tables
    assert {r["id"] for r in rows if r.get("empirical")} >= {f"lm4651-eq{k}" for k in (1, 2, 3, 4, 5, 6, 9)}
    text = run("examples")
    assert "an94002-c3" in text and "misprint" in text
    assert "an94002-eq13" in run("equations")


def test_unknown_command_is_a_usage_error():
    out = subprocess.run([sys.executable, "-m", "handbook", "frobnicate"], capture_output=True, text=True)
    assert out.returncode == 2 and "invalid choice" in out.stderr and "Traceback" not in out.stderr


def _run_cols(cols, *args):
    env = {**__import__("os").environ, "COLUMNS": str(cols)}
    out = subprocess.run([sys.executable, "-m", "handbook", *args], capture_output=True, text=True, timeout=120, env=env)
    assert out.returncode == 0, out.stderr
    return out.stdout


def test_examples_fit_the_terminal_in_the_printed_unit_and_filter():
    text = _run_cols(90, "examples", "--source", "AN94002", "--status", "misprint")
    lines = text.splitlines()
    assert all(len(line) <= 90 for line in lines)
    assert "an94002-window-high" in text and "an93008" not in text and " rounding " not in text
    # recomputed in the printed unit: CAP-CD's bound printed as 0.0148 uF is shown in uF, not in farads
    full = _run_cols(200, "examples", "--source", "an94002-capcd-bound")
    assert "0.0148 uF" in full and "e-08" not in full
    assert not any(w.endswith("…") and len(w) > 40 for w in full.split())  # the last column wraps, it is not cut


def test_equations_filter_by_status():
    rows = {r["id"]: r for r in json.loads(run("equations", "--json"))}
    assert rows["an94002-eq6"]["check"] == "agrees (constant rounded)" and rows["an94002-eq6"]["agrees"] is False
    text = _run_cols(100, "equations", "--status", "differs")
    assert "lm4651-eq8" in text and "an94002-eq13 " not in text
    assert all(len(line) <= 100 for line in text.splitlines())


def test_errata_command():
    rows = json.loads(run("errata", "--json"))
    assert len(rows) > 10
    for r in rows:
        assert {"id", "source", "kind", "what", "printed", "computed", "evidence", "consequence", "quote", "confidence",
                "charitable", "places"} <= set(r)
    assert {r["source"].split()[0] for r in rows} >= {"AN94002", "AN93008"}
    assert "AN94002" in run("errata", "--source", "AN94002")
    # the case against the source: the disputed passage word for word, how sure, the other places of one fact
    f15 = {r["id"]: r for r in rows}["lm4651-f-15k"]
    assert f15["confidence"] == "certain" and ["LM4651/LM4652", "Switching Frequency Range $R_{OSC} = 15k\\Omega$ 65 kHz"] \
        in f15["quote"]
    assert any("pin 16" in p for p in f15["places"]) and "lm4651-f-pin-0" not in {r["id"] for r in rows}
    notes = json.loads(run("errata", "--reading-notes", "--json"))
    assert {"an94002-eq2", "lm4651-t-standby", "tca5600-t-values"} <= {n["id"] for n in notes}
    assert not {n["id"] for n in notes} & {r["id"] for r in rows}
    assert "lm4651-t-standby" in run("errata", "--reading-notes", "--source", "LM4651")


def _run_any(cols, *args):
    """stdout, stderr and exit code of `python -m handbook ARGS` in a terminal ``cols`` columns wide."""
    env = {**__import__("os").environ, "COLUMNS": str(cols)}
    out = subprocess.run([sys.executable, "-m", "handbook", *args], capture_output=True, text=True, timeout=180, env=env)
    assert "Traceback" not in out.stderr, out.stderr
    return out.stdout, out.stderr, out.returncode


@pytest.mark.parametrize("cols", [80, 120])
@pytest.mark.parametrize("command", ["examples", "equations", "errata", "spice"])
def test_every_line_fits_the_terminal(command, cols):
    if command == "spice" and shutil.which("ngspice") is None:
        pytest.skip("ngspice is not installed")
    text, err, code = _run_any(cols, command)
    assert code in ((0, 1) if command == "spice" else (0,)), err
    too_long = [line for line in text.splitlines() if len(line) > cols]
    assert not too_long, f"{len(too_long)} lines over {cols} columns, e.g. {too_long[0]!r}"
    assert "…" not in text  # cells wrap, they are not cut
    # every id stays whole (it is one word, and a column is never narrower than its longest word here)
    rows = json.loads(_run_any(cols, command, "--json")[0])
    words = set(text.split())
    assert {r["id"] for r in rows} <= words


def test_errata_source_wraps_instead_of_being_cut():
    text, err, code = _run_any(80, "errata")
    assert code == 0, err
    words = set(text.split())
    for r in json.loads(run("errata", "--json")):
        assert set(r["source"].split()) <= words, r["source"]


@pytest.mark.parametrize("command, valid", [
    ("examples", ["exact", "rounding", "truncated", "rounded intermediate", "bound met", "conservative", "misprint",
                  "inconsistent", "wrong method"]),
    ("equations", ["agrees", "differs", "empirical"]),
    ("errata", ["misprint", "inconsistent", "wrong method", "equation", "text"]),
])
def test_an_unknown_status_is_a_usage_error(command, valid):
    text, err, code = _run_any(100, command, "--status", "bogus")
    assert code == 2 and text == ""
    assert "bogus" in err and all(v in err for v in valid), err
    text, err, code = _run_any(100, command, "--status", "bogus", "--json")
    assert code == 2 and "bogus" in err
    error = json.loads(text)["error"]
    assert error["exit"] == 2 and all(v in error["message"] for v in valid)
    # a valid status in another case still filters
    text, err, code = _run_any(100, command, "--status", valid[1].upper(), "--json")
    assert code == 0 and json.loads(text), err


def _blocks(text: str, ids) -> dict:
    """Each row's lines of a text table, joined, by the id that starts it."""
    blocks, current = {}, None
    for line in text.splitlines()[2:]:
        head = line.split(" ", 1)[0]
        if head in ids:
            current = head
            blocks[current] = ""
        blocks[current] += " " + line
    return blocks


def test_empirical_equations_say_so_and_filter():
    rows = json.loads(run("equations", "--json"))
    empirical = {r["id"] for r in rows if r["empirical"]}
    assert {"lm4651-eq3", "lm4651-eq5", "lm4651-eq9"} <= empirical
    text, err, code = _run_any(200, "equations")
    assert code == 0, err
    blocks = _blocks(text, {r["id"] for r in rows})
    for r in rows:
        block = blocks[r["id"]]
        if r["empirical"]:
            assert "empirical" in block and "DIFFERS" not in block and " agrees " not in block, block
            assert ("MISSES" in block) == (not r["agrees"]), block
        else:
            shown = "agrees" if r["agrees"] or r.get("rounded_constants") else "DIFFERS"
            assert shown in block and "empirical:" not in block, block
            assert ("DIFFERS" in block) == (not r["agrees"] and not r.get("rounded_constants")), block
    assert "DIFFERS" in blocks["lm4651-eq8"]
    only = json.loads(_run_any(100, "equations", "--status", "empirical", "--json")[0])
    assert {r["id"] for r in only} == empirical
    differs = json.loads(_run_any(100, "equations", "--status", "differs", "--json")[0])
    assert {r["id"] for r in differs} == {r["id"] for r in rows if not r["agrees"] and not r["empirical"]
                                          and not r["rounded_constants"]} == {"lm4651-eq8"}  # eps_0 misprinted


def test_a_source_matching_nothing_is_a_usage_error():
    out = subprocess.run([sys.executable, "-m", "handbook", "examples", "--source", "bogus"], capture_output=True,
                         text=True)
    assert out.returncode == 2 and "matches no entry" in out.stderr and "AN94002" in out.stderr


def _design(tmp_path, text, *extra):
    spec = tmp_path / "spec.toml"
    spec.write_text(text)
    return subprocess.run([sys.executable, "-m", "handbook", "design", str(spec), *extra], capture_output=True,
                          text=True, timeout=120)


def test_design_netlist_writes_the_tables_asked(tmp_path):
    folder = tmp_path / "new" / "decks"  # made, parents too
    out = _design(tmp_path, "[class_d]\np_out = 50.0\n[converter]\n", "--netlist", str(folder), "--json")
    assert out.returncode == 0, out.stderr
    info = json.loads(out.stdout)
    assert info["netlist"] == {"folder": str(folder), "files": ["class_d.cir", "converter.cir"], "left_out": [],
                               "not_asked": ["commutation", "current_limiter"]}
    assert sorted(p.name for p in folder.iterdir()) == ["class_d.cir", "converter.cir"]  # no temporary file left
    for name in info["netlist"]["files"]:
        text = (folder / name).read_text()
        assert f"spec sha256 {info['spec_sha256']}" in text and f"handbook {info['version']}" in text
        assert text.rstrip().endswith(".end")
    assert "--netlist DIR" in run("design", "--help")


def test_design_netlist_leaves_out_a_table_that_cannot_be_met(tmp_path):
    folder = tmp_path / "decks"
    out = _design(tmp_path, "[class_d]\np_out = 500.0\n[current_limiter]\n", "--netlist", str(folder))
    assert out.returncode == 3 and "Traceback" not in out.stderr
    assert "netlist: [class_d] not written: it cannot be met" in out.stderr
    assert [p.name for p in folder.iterdir()] == ["current_limiter.cir"]
    out = _design(tmp_path, "[class_d]\np_out = 500.0\n", "--netlist", str(tmp_path / "none"))
    assert out.returncode == 3 and "nothing designed" in out.stderr and not (tmp_path / "none").exists()


def test_design_netlist_into_an_unwritable_folder_is_a_usage_error(tmp_path):
    blocker = tmp_path / "afile"
    blocker.write_text("x")
    for folder, said in ((blocker / "decks", "cannot write the netlists into"), (blocker, "is a file, not a folder")):
        out = _design(tmp_path, "[class_d]\n", "--netlist", str(folder), "--json")
        assert out.returncode == 2 and "Traceback" not in out.stderr, out.stderr
        assert said in out.stderr and str(folder) in out.stderr
        assert json.loads(out.stdout)["error"]["exit"] == 2
    assert blocker.read_text() == "x" and sorted(p.name for p in tmp_path.iterdir()) == ["afile", "spec.toml"]


def test_design_netlist_is_written_whole_or_not_at_all(tmp_path, monkeypatch, capsys):
    """A failure at any rename (here the disk filling up at the first or the second) leaves no new file and no new
    folder behind, and a folder's old deck as it was (set aside, then put back)."""
    import shutil

    from handbook import cli
    from handbook.spice import netlist

    real, calls = netlist.os.replace, []

    def failing(src, dst):
        calls.append(dst)
        if len(calls) == calls[0]:
            raise OSError(28, "No space left on device")
        return real(src, dst)

    monkeypatch.setattr(netlist.os, "replace", failing)
    spec = tmp_path / "spec.toml"
    spec.write_text("[class_d]\n[converter]\n")
    for fail_at in (1, 2):
        for folder, before in ((tmp_path / "new", None), (tmp_path / "old", "old deck")):
            if before:
                folder.mkdir()
                (folder / "class_d.cir").write_text(before)
            calls[:] = [fail_at + 1]  # the first entry holds the call to fail at (counting itself)
            assert cli.main(["design", str(spec), "--netlist", str(folder)]) == 2
            err = capsys.readouterr().err
            assert str(folder) in err and "No space left on device" in err and "nothing written" in err
            if before is None:
                assert not folder.exists()
            else:
                assert [p.name for p in folder.iterdir()] == ["class_d.cir"]
                assert (folder / "class_d.cir").read_text() == before
                shutil.rmtree(folder)


def test_spice_figures_in_text_carry_their_own_units():
    """design --spice's text output: each figure in the unit of its check (a frequency in Hz, not V), a supply in V,
    an expected difference signed in per cent, counts and the 'misses' sentences as they are (a list once broke it)."""
    from handbook.cli import _spice_value

    assert _spice_value("f", 19843.7) == "19.84 kHz" and _spice_value("f_equation", 20000.0) == "20 kHz"
    assert _spice_value("i_out_supply", 8.0) == "8 V" and _spice_value("f_supply", 14.4) == "14.4 V"
    assert _spice_value("i_out_expected", 0.012468).startswith("+1.25 %")
    assert _spice_value("f_expected", -0.00798).startswith("\N{MINUS SIGN}0.80 %")
    assert _spice_value("corners_searched", 96) == "96 searched" and _spice_value("f_rtol", 0.001) == "±0.1 %"
    assert _spice_value("misses", ["one", "two"]) == "one; two" and _spice_value("differs", []) == "none"
    assert _spice_value("ripple_at_load", 0.02954) == "29.54 mV rms" and _spice_value("t_wd_min", 0.00237) == "2.37 ms"


def test_the_spec_hash_tells_a_partial_spec_from_the_full_one():
    """A [class_d]-only spec and one with every table at the same (default) values design different things: their
    hashes differ; the same spec read twice hashes the same."""
    from handbook.design import spec as specmod

    one = specmod.traced(specmod.parse({"class_d": {}}))["spec_sha256"]
    every = specmod.traced(specmod.parse({t: {} for t in ("commutation", "current_limiter", "class_d", "converter")}))
    assert one != every["spec_sha256"] and one == specmod.traced(specmod.parse({"class_d": {}}))["spec_sha256"]
