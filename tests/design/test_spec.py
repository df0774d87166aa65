"""Reading a specification (handbook.design.spec): every table checked once, at reading, with one message
style; a read Spec cannot be changed afterwards; the designs take its tables as they are."""
import pytest

from handbook.core import InputError
from handbook.design import spec as spec_mod
from handbook.design.common import is_checked
from handbook.design.schema import TABLES


def test_an_empty_document_is_every_table_at_its_defaults():
    s = spec_mod.parse({})
    assert set(s) == set(TABLES) and all(dict(s[t]) == {} for t in s)  # nothing given
    assert all(is_checked(t, s.tables[t]) for t in TABLES)
    assert s.tables["commutation"]["rpm_min"] == 1800.0 and s.tables["current_limiter"]["i_no_trip"] == 0.9


@pytest.mark.parametrize("data, words", [
    ({"i_no_trip": 1.0}, "written outside any table: put it under [current_limiter]"),
    ({"comutation": {}}, "did you mean [commutation]?"),
    ({"zzz": {}}, "use [commutation], [current_limiter], [class_d], [converter]"),
    ({"commutation": 3}, "commutation must be a table ([commutation]), not a value"),
    ({"commutation": {"i_no_trip": 1.0}}, "it belongs in [current_limiter]"),
    ({"current_limiter": {"i_no_trip": 2.0, "i_must_trip": 1.0}}, "current_limiter.i_no_trip"),
    ([1, 2], "must be a TOML document with tables"),
])
def test_bad_documents_name_the_key_and_what_would_work(data, words):
    with pytest.raises(InputError) as exc:
        spec_mod.parse(data)
    assert words in str(exc.value)


def test_a_read_spec_is_read_only():
    s = spec_mod.parse({"commutation": {"pole_pairs": 4}})
    with pytest.raises(TypeError):
        s["commutation"]["pole_pairs"] = 2
    with pytest.raises(TypeError):
        s.tables["commutation"] = {}
    assert s.tables["commutation"]["pole_pairs"] == 4 and spec_mod.check(s) is s.tables


def test_load_reports_unreadable_and_invalid_files(tmp_path):
    with pytest.raises(InputError, match="cannot read"):
        spec_mod.load(tmp_path / "missing.toml")
    bad = tmp_path / "bad.toml"
    bad.write_text("[commutation\npole_pairs = 4\n")
    with pytest.raises(InputError, match="is not valid TOML"):
        spec_mod.load(bad)
    bad.write_bytes(b"[commutation]\nseries = \"\xff\"\n")
    with pytest.raises(InputError, match="is not valid TOML"):
        spec_mod.load(bad)
    good = tmp_path / "good.toml"
    good.write_text("[commutation]\npole_pairs = 4\n")
    assert spec_mod.load(good).tables["commutation"]["pole_pairs"] == 4


def test_run_each_reports_an_unmeetable_table_beside_the_others():
    out = spec_mod.run_each({"current_limiter": {"i_no_trip": 1.0, "i_must_trip": 1.1}})
    assert isinstance(out["current_limiter"], spec_mod.Infeasible) and out["current_limiter"].achievable
    assert out["commutation"].cap_cd == pytest.approx(8.2e-9)  # 8.2 nF at the defaults (test_commutation_result)
    with pytest.raises(spec_mod.Infeasible):
        spec_mod.run({"current_limiter": {"i_no_trip": 1.0, "i_must_trip": 1.1}})
