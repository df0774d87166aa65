"""The third leg for the linear parts: lcapy derives each from its netlist, sympy compares with the registry."""
import pytest

lc = pytest.importorskip("handbook.spice.lcapy_checks")


def test_bridge_filter_from_its_netlist_is_the_designs_second_order_form():
    out = lc.filter_from_netlist()
    assert out["same"], (out["lcapy"], out["registry"])


def test_timer_from_its_netlist_is_eq_5s_charge_balance():
    out = lc.timer_from_netlist()
    assert out["same"], (out["lcapy"], out["registry"])
