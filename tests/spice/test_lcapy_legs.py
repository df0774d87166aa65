"""The third leg for the linear parts: lcapy derives each from a netlist written from the circuit's own parts
and node maps (the ones the SPICE netlist and the schematic use), and sympy compares with the registry."""
import pytest

lc = pytest.importorskip("handbook.spice.lcapy_checks")


def test_bridge_filter_from_its_netlist_is_the_designs_second_order_form():
    out = lc.filter_from_netlist()
    assert out["same"], (out["lcapy"], out["registry"])


def test_timer_from_its_netlist_is_eq_5s_charge_balance():
    out = lc.timer_from_netlist()
    assert out["same"], (out["lcapy"], out["registry"])


def test_speed_loop_divider_is_eq_10():
    out = lc.speed_from_netlist()
    assert out["same"] and out["same_as_printed"], (out["lcapy"], out["registry"])


def test_an93008_eq_1_and_eq_6_from_the_limiters_parts():
    out = lc.an93008_from_netlist()
    assert out["eq1"]["same"], (out["eq1"]["lcapy"], out["eq1"]["registry"])
    assert out["eq6"]["same"], (out["eq6"]["lcapy"], out["eq6"]["registry"])


def test_an94002_eq_13_with_the_parts_values():
    out = lc.compare()
    assert out["same_as_derived"] and out["same_as_printed"] and out["free_of_loop_gain"]
    lcapy_value, equation = out["at_parts"]
    assert lcapy_value == pytest.approx(equation, rel=1e-12) and lcapy_value == pytest.approx(0.1, rel=2e-3)


def test_the_lcapy_netlists_are_the_spice_parts():
    from handbook.spice import class_d, speed
    from handbook.spice.limiter import decks as limiters

    text = lc.opamp_netlist()
    for p in limiters.opamp_parts(limiters.opamp_defaults()):
        assert p.ref in text.replace("VD1", "D1").replace("E_U1", "U1").replace("G_IM", "IM"), p.ref
    assert "R12 cs inp {R12}" in text and "R13 inp z {R13}" in text  # placed by OPAMP_NODES
    assert "R3 vmot inp {R3}" in lc.speed_netlist() and speed.NODES["R3"] == "R3 vmot inp"
    assert "L1 o1 outp {L1}" in lc.filter_netlist() and class_d.NODES["L1"] == "o1 outp"


def test_a_part_moved_in_the_node_map_moves_in_lcapy(monkeypatch):
    """Swap R12 and R13 in the node map the SPICE netlist is written from: lcapy's derivation no longer
    equals eq 13 (so the leg reads the circuit, not a copy of it)."""
    from handbook.spice.limiter import decks as limiters

    nodes = dict(limiters.OPAMP_NODES)
    nodes["R12"], nodes["R13"] = "cs{s} inp{s}".replace("cs", "z"), "inp{s} cs{s}"
    monkeypatch.setattr(limiters, "OPAMP_NODES", nodes)
    assert not lc.compare()["same_as_derived"]


def test_a_part_without_a_stand_in_is_an_error(monkeypatch):
    from handbook.spice.circuit import Part
    from handbook.spice.limiter import decks as limiters

    original = limiters.opamp_parts
    monkeypatch.setattr(limiters, "opamp_parts", lambda p: original(p) + (Part("Q9", "BC547"),))
    with pytest.raises(ValueError, match="Q9"):
        lc.opamp_netlist()


PROBE = """
import sys
from IPython.core.interactiveshell import InteractiveShell
import sympy as sp
ip = InteractiveShell.instance()
shown = {"float": 1.5, "list": [1, 2], "expression": sp.Symbol("x") + 1}
def kinds():
    return {name: sorted(ip.display_formatter.format(v)[0]) for name, v in shown.items()}
before = kinds()
ip.run_cell(sys.argv[1])
print(before == kinds(), kinds()["float"])
"""


@pytest.mark.parametrize("how, unchanged", [("import lcapy", False),
                                            ("from handbook.spice import lcapy_checks; _ = lcapy_checks._lcapy()", True)])
def test_lcapy_leaves_a_notebooks_display_as_it_was(how, unchanged):
    """In a notebook's shell, importing lcapy makes every float shown or glued afterwards a LaTeX formula and a PNG
    (sympy's init_printing, which lcapy calls); the checks' import puts the display back as it was, so a chapter's
    outputs do not depend on whether an lcapy check ran before in the kernel."""
    import subprocess
    import sys

    out = subprocess.run([sys.executable, "-c", PROBE, how], capture_output=True, text=True, timeout=120)
    assert out.returncode == 0, out.stderr[-2000:]
    same, float_kinds = out.stdout.split(maxsplit=1)
    assert same == str(unchanged), out.stdout
    assert ("image/png" in float_kinds) is not unchanged
