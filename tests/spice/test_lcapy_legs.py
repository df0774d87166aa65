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
import json, sys
import sympy as sp
shell = sys.argv[2] == "shell"
if shell:
    from IPython.core.interactiveshell import InteractiveShell
    ip = InteractiveShell.instance()
x = sp.Symbol("x")
shown = {"float": 1.5, "list": [1, 2], "expression": x + 1}
def state():
    kinds = {name: sorted(ip.display_formatter.format(v)[0]) for name, v in shown.items()} if shell else {}
    return {"kinds": kinds, "latex": sp.latex(x / (1 - x)), "hook": repr(sys.displayhook)}
before = state()
if shell:
    ip.run_cell(sys.argv[1])
else:
    exec(sys.argv[1])
print(json.dumps({"before": before, "after": state()}))
"""
LCAPY = "from handbook.spice import lcapy_checks; _ = lcapy_checks._lcapy()"


@pytest.mark.parametrize("shell", ["shell", "script"])
@pytest.mark.parametrize("how", ["import lcapy", LCAPY])
def test_lcapy_leaves_the_display_and_printing_as_they_were(how, shell):
    """Importing lcapy calls sympy's init_printing: in a notebook's shell every float shown or glued afterwards
    becomes a LaTeX formula and a PNG, and in any process sympy's terms print in lcapy's order (x/(1 - x) becomes
    x/(-x + 1)) and, outside a shell, ``sys.displayhook`` is sympy's. The checks' import puts all of it back, so a
    chapter's outputs do not depend on whether an lcapy check ran before in the kernel."""
    import json
    import subprocess
    import sys

    out = subprocess.run([sys.executable, "-c", PROBE, how, shell], capture_output=True, text=True, timeout=120)
    assert out.returncode == 0, out.stderr[-2000:]
    got = json.loads(out.stdout.strip().splitlines()[-1])
    before, after = got["before"], got["after"]
    assert before["latex"] == r"\frac{x}{1 - x}"
    if how == LCAPY:
        assert after == before
        return
    assert after["latex"] == r"\frac{x}{- x + 1}"
    if shell == "shell":
        assert "image/png" in after["kinds"]["float"] and "image/png" not in before["kinds"]["float"]
    else:
        assert after["hook"] != before["hook"]
