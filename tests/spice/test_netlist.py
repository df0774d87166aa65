"""The exported netlists (`design --netlist`): each deck run in ngspice gives the design's own figures at its
nominal point (within the tolerance each check states and justifies: handbook.spice.netlist), fails when a part is
changed, holds nothing another SPICE would not read, carries every model it uses, and names its design."""
import re
from pathlib import Path

import pytest

from handbook.design import spec as specmod
from handbook.spice import class_d as cd
from handbook.spice import netlist
from handbook.spice.circuit import evaluate
from handbook.spice.limiter import decks as lim
from handbook.spice.runner import run

EXAMPLES = Path(__file__).resolve().parents[2] / "book" / "examples"
#: the notes' defaults (all four tables), and the book's two example specs (CAP-ST and CAP-TI designed, 8 ohm)
SPECS = {"defaults": {}, "fan_motor": EXAMPLES / "fan_motor.toml", "amplifier_8ohm": EXAMPLES / "amplifier_8ohm.toml"}


def _designed(name):
    source = SPECS[name]
    spec = specmod.load(source) if isinstance(source, Path) else specmod.parse(source)
    results = {t: r for t, r in specmod.run_each(spec).items() if hasattr(r, "spec")}
    return spec, results


@pytest.fixture(scope="module", params=list(SPECS))
def exported(request):
    spec, results = _designed(request.param)
    meta = specmod.traced(spec)
    return meta, results, netlist.decks(results)


def test_every_deck_reproduces_the_design_in_ngspice(ngspice, exported):
    meta, _, decks = exported
    names = [d.name for d in decks]
    assert {"commutation.cir", "current_limiter.cir", "class_d.cir", "converter.cir"} <= set(names)
    for deck in decks:
        rows = evaluate(deck.circuit(meta))
        assert rows, deck.name
        bad = [f"{r['id']}: deck {r['spice']:.6g} against {r['equation']:.6g} ({r['rel_diff']:.3%} > {r['rtol']:.2%})"
               for r in rows if not r["agrees"]]
        assert not bad, f"{deck.name}: {bad}"


def test_the_start_oscillator_and_watchdog_come_when_designed():
    spec, results = _designed("fan_motor")
    names = [d.name for d in netlist.decks(results)]
    assert {"commutation_cap_st.cir", "commutation_cap_ti.cir"} <= set(names)
    spec, results = _designed("defaults")  # no motor data: no CAP-ST, no CAP-TI
    assert not {"commutation_cap_st.cir", "commutation_cap_ti.cir"} & {d.name for d in netlist.decks(results)}


#: a designed part of each deck, changed by MUTATION: the deck must then miss the design's figures
BROKEN = {"commutation.cir": "C3", "commutation_cap_st.cir": "C5", "commutation_cap_ti.cir": "C6",
          "current_limiter.cir": "R13", "class_d.cir": "C_BYP", "converter.cir": "L1"}
MUTATION = 1.03


def _scaled(text: str, ref: str, factor: float) -> str:
    """The deck with the value ending the element line of ``ref`` multiplied by ``factor``."""
    def scale(m):
        return f"{m.group(1)}{float(m.group(2)) * factor:.6g}"

    out, n = re.subn(rf"^({re.escape(ref)} \S+ \S+ )(\S+)$", scale, text, count=1, flags=re.MULTILINE)
    assert n == 1, f"no element line {ref} with a plain value"
    return out


def test_a_broken_deck_misses_the_design(ngspice, exported):
    """The checks are not vacuous: 3 % on one designed part moves a figure past its tolerance in every deck."""
    meta, _, decks = exported
    for deck in decks:
        circuit = deck.circuit(meta)
        broken = circuit.__class__(**{**circuit.__dict__, "netlist": _scaled(circuit.netlist, BROKEN[deck.name],
                                                                             MUTATION)})
        assert not all(r["agrees"] for r in evaluate(broken)), f"{deck.name} passes with {BROKEN[deck.name]} changed"


def test_class_d_deck_against_the_spice_confirmations_transient(ngspice):
    """The deck's AC residue (odd harmonics to the 15th) against the --spice confirmation's own transient of the
    idle bridge at the nominal corner (handbook.spice.class_d.ripple), and the deck's commented transient lines,
    switched on, against the same: the harmonics past the 15th and the LM4652's 25 ns edges are all that differ
    (under 0.05 % at these figures) beside the transient's step (a hundredth of a period, 0.1 % seen): ±0.2 %."""
    _, results = _designed("defaults")
    r, s = results["class_d"], results["class_d"].spec
    deck = next(d for d in netlist.decks({"class_d": r}))
    text = deck.text({"version": "", "spec_sha256": ""})
    base = {"l_out": r.l_out, "c_out": r.c_out, "r_load": s["r_load"], "supply": s["supply"], "f_sw": r.f_sw,
            "f_audio": s["f_audio"]}
    confirmation = run(cd.ripple(base).netlist)["ripple"]
    assert run(text)["ripple"] == pytest.approx(confirmation, rel=0.002)
    lines = [("* " + ln if re.match(r"\.(ac|meas ac|save)\b", ln) else ln[2:] if ln.startswith("* .") else ln)
             for ln in text.splitlines()]
    switched = "\n".join(lines) + "\n"
    assert not netlist.nonportable(switched)
    assert run(switched)["ripple_tran"] == pytest.approx(confirmation, rel=1e-4)  # the confirmation's own lines


def test_decks_are_plain_spice_and_name_their_design(exported):
    meta, results, decks = exported
    for deck in decks:
        text = deck.text(meta)
        assert netlist.nonportable(text) == [], deck.name
        assert text.isascii(), deck.name
        head = [ln for ln in text.splitlines() if ln.startswith("*")][:4]
        assert f"handbook {meta['version']}" in head[1] and f"[{deck.table}]" in head[1]
        assert head[2] == f"* spec sha256 {meta['spec_sha256']}"
        for part in deck.parts:  # every part listed in the header, and its designed value in the deck
            assert re.search(rf"^\*\s+{re.escape(part.ref)}\s", text, re.MULTILINE), (deck.name, part.ref)
        # every model and subcircuit used is defined in the file (no .include)
        used = set(re.findall(r"^D\w*\s+\S+\s+\S+\s+(\w+)", text, re.MULTILINE | re.IGNORECASE))
        used |= set(re.findall(r"^S\w*\s+(?:\S+\s+){4}(\w+)", text, re.MULTILINE | re.IGNORECASE))
        used |= set(re.findall(r"^X\w*\s+.*\s(\w+)\s*$", text, re.MULTILINE | re.IGNORECASE))
        defined = set(re.findall(r"^\.(?:model|subckt)\s+(\w+)", text, re.MULTILINE | re.IGNORECASE))
        assert used <= defined, (deck.name, used - defined)
    limiter = next(d for d in decks if d.table == "current_limiter").text(meta)
    r = results["current_limiter"]
    for ref, value in (("R7", r.r7), ("R9", r.r9), ("R13", r.r13), ("R14", r.r14)):
        assert re.search(rf"^{ref} \S+ \S+ {value:.6g}$", limiter, re.MULTILINE)


def test_the_scan_finds_what_other_spices_would_not_read():
    """The book's own decks use ngspice's conveniences: the scan names them (and passes the exported forms)."""
    said = {why for _, _, why in netlist.nonportable(lim.opamp().netlist)}
    assert any("params:" in w for w in said) and any("brace" in w for w in said) and any("inline" in w for w in said)
    control = "* t\nR1 a 0 1\n.control\nrun\n.endc\n.op\n.end\n"
    assert any(".control" in why for _, _, why in netlist.nonportable(control))
    for bad, what in (("B1 a 0 V=v(b)>1 ? 1 : 0", "ternary"), (".include models.lib", ".include"),
                      (".meas f1 WHEN v(a)=0", "without its analysis"), ("B1 a 0 V=u(v(b))", "ngspice-only function")):
        text = f"* t\nR1 a 0 1\n{bad}\n.tran 1u 1m\n.end\n"
        assert any(what in why for _, _, why in netlist.nonportable(text)), bad
    two = "* t\nR1 a 0 1\n.tran 1u 1m\n.ac dec 10 1 1k\n.end\n"
    assert any("analyses" in why for _, _, why in netlist.nonportable(two))
    assert any(".end" in why for _, _, why in netlist.nonportable("* t\nR1 a 0 1\n.op\n"))
