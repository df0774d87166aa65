"""TCA5600 flyback coil: eq 1 to 6a derived, the worked example and the application check by hand."""
import pytest

from handbook.core import InputError
from handbook.sources import tca5600


def test_every_equation_agrees_with_its_derivation():
    for e in tca5600.SOURCE.equations():
        c = e.check()
        assert c.agrees and c.dims_ok, e.id


def test_worked_example_by_hand():
    d = tca5600.design(tca5600.params())
    vlp, vlm = 12 + 2.5 + 0.8 - 8, 8 - 0.5 - 0.4
    a = vlp / vlm
    t1 = a / (1 + a) / 20e3
    ipk = 2 * 0.05 * (1 + a)
    assert (d["alpha"], d["t1"], d["i_peak"]) == pytest.approx((a, t1, ipk), rel=1e-12)
    assert d["l1"] == pytest.approx(vlm * t1 / ipk, rel=1e-12)
    assert d["r1"] == pytest.approx(0.4 / ipk, rel=1e-12)


def test_application_values_at_the_assumed_point():
    op = tca5600.operating_point(300e-6, 0.68, tca5600.params())
    ipk = 0.4 / 0.68
    a = 7.3 / 7.1
    t1 = 300e-6 * ipk / 7.1
    assert op["f"] == pytest.approx(1 / (t1 + t1 / a), rel=1e-12)
    assert op["i_out_max"] == pytest.approx(ipk / (2 * (1 + a)), rel=1e-12)
    assert 20e3 < op["f"] < 21e3  # just above the excerpt's 20 kHz


def test_no_flyback_when_the_output_side_is_below_the_supply():
    with pytest.raises(InputError, match="V_L"):
        tca5600.design(tca5600.params(v_out2=3.0, v_cc2_min=14.0))
