"""The introduction quotes the book's main findings in prose (a Markdown page, no glue): each number
it quotes is recomputed here from the modules, so the prose cannot drift from the code."""
from pathlib import Path

from handbook import catalog
from handbook.sources import an93008, an94002

TEXT = " ".join((Path(__file__).resolve().parents[1] / "book" / "intro.md").read_text().split())
EX = {r["id"]: r for r in catalog.claims()}


def test_opamp_limiter_worst_case_window():
    w = an94002.trip_worst_case(an94002.params())
    assert f"between about {w.low * 1e3:.0f} mV and {w.high * 1e3:.0f} mV for a 100 mV design" in TEXT


def test_offset_window():
    lo, hi = EX["an94002-window-low"], EX["an94002-window-high"]
    assert f'"{lo["printed_text"].split()[0]} to {hi["printed_text"]}"' in TEXT
    assert f"it is {lo['computed'] * 1e3:.1f} to {hi['computed'] * 1e3:.1f} mV" in TEXT


def test_cap_cd_charge_current():
    r = EX["an94002-ich-max"]
    assert r["printed_text"] == "22 uA" and "sized with 22 µA" in TEXT
    assert f"most {r['computed'] * 1e6:.0f} µA" in TEXT


def test_an93008_supply_referenced_limiter():
    w = an93008.supply_worst_case(an93008.params())
    assert f"about {round(w.rel_low, 1):.0%}/{round(w.rel_high, 1):+.0%}".replace("%", " %") in TEXT


def test_lm4651_findings():
    assert f"gives {EX['lm4651-dead-time']['computed'] * 1e9:.2f} ns where its table says 27 ns" in TEXT
    assert f"sets {EX['lm4651-isckt']['computed']:.0f} A, not 10 A" in TEXT
