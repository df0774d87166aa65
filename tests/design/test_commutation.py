"""CAP-CD: the design against an exhaustive enumeration written out in tests/oracles.py."""
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from handbook.design import commutation
from handbook.design.solvers import Infeasible

from oracles import enumerate_cap

SETTINGS = settings(max_examples=60, deadline=None, derandomize=True,
                    suppress_health_check=[HealthCheck.too_slow])


def test_note_motor_gives_18nF_and_15nF_fails_for_its_tolerance():
    r = commutation.design()
    assert r.cap_cd == pytest.approx(18e-9) and r.cap_dc == r.cap_cd
    assert r.next_smaller == pytest.approx(15e-9)
    # 15 nF at -5 %: 22 uA for 10/(1800*6) s over 14.25 nF is more than the 1.4 V window
    assert 22e-6 * (10 / 10800) / 14.25e-9 > 1.4
    assert 22e-6 * (10 / 10800) / 17.1e-9 < 1.4
    assert "window" in r.binding
    assert r.rpm_max_reliable == pytest.approx(10 * 10.6e-6 / (0.1 * 6 * 18.9e-9))


@SETTINGS
@given(n=st.integers(1, 12), rpm_min=st.floats(100, 20000), span=st.floats(1.05, 20),
       i_max=st.floats(2e-6, 50e-6), spread=st.floats(0.2, 1.0), window=st.floats(0.5, 2.5),
       floor=st.floats(0.02, 0.4), tol=st.sampled_from([0.01, 0.05, 0.1, 0.2]),
       ser=st.sampled_from(["E6", "E12", "E24"]))
def test_cap_cd_equals_enumeration(n, rpm_min, span, i_max, spread, window, floor, tol, ser):
    spec = dict(pole_pairs=n, rpm_min=rpm_min, rpm_max=rpm_min * span, i_charge_max=i_max,
                i_charge_min=i_max * spread, window=window, min_excursion=min(floor, window / 2), tolerance=tol,
                series=ser)
    expected = enumerate_cap(spec)
    try:
        got = commutation.design(spec)
    except Infeasible as exc:
        assert expected is None
        assert exc.achievable["rpm_max_reliable"] < spec["rpm_max"]
        return
    assert got.cap_cd == pytest.approx(expected, rel=1e-12)
    chk = commutation.verify(got.cap_cd, got.spec)
    assert chk["window_ok"] and chk["noise_ok"]
