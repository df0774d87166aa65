"""Engineering values (handbook.core.units): by hand, and the same text as matplotlib's EngFormatter, which the
book's axes use (matplotlib is imported here, in the test, never by the module)."""
import numpy as np
import pytest
from matplotlib.ticker import EngFormatter

from handbook.core.units import eng, prefixed, to_figures


@pytest.mark.parametrize("value,unit,text", [
    (1.455e-8, "F", "14.55 nF"), (18e-9, "F", "18 nF"), (1210.0, "Ω", "1.21 kΩ"), (0.0, "V", "0 V"),
    (-0.0, "V", "0 V"), (999.95, "Hz", "1 kHz"), (999.9, "Hz", "999.9 Hz"), (-3.3e3, "ohm", "\u22123.3 kohm"),
    (1e-31, "F", "0.1 qF"), (0.5, "", "0.5"), (2.0, "1", "2"), (0.0255, "%", "2.55 %"), (5e6, "A/m^2", "5 MA/m^2"),
])
def test_by_hand(value, unit, text):
    assert eng(value, unit) == text


def test_digits_are_significant_figures():
    assert eng(1.23456e-6, "A", digits=3) == "1.23 µA" and eng(1.23456e-6, "A", digits=6) == "1.23456 µA"


def test_to_figures_rounds_one_way():
    """A limit kept on its safe side: 0.123456 A to four figures is 0.1234 down and 0.1235 up; 98765 Hz is 98760
    down and 98770 up."""
    import math

    assert to_figures(0.123456, math.floor) == pytest.approx(0.1234, rel=1e-12)
    assert to_figures(0.123456, math.ceil) == pytest.approx(0.1235, rel=1e-12)
    assert to_figures(98765.0, math.floor) == pytest.approx(98760.0) and to_figures(98765.0, math.ceil) == pytest.approx(98770.0)
    assert to_figures(22.75, math.floor, 3) == pytest.approx(22.7)


def test_same_text_as_matplotlibs_formatter():
    rng = np.random.default_rng(7)
    values = list(10 ** rng.uniform(-33, 33, 3000) * rng.choice([-1, 1], 3000)) + [0.0, 999.9995, 1e33]
    formatter = EngFormatter(unit="F", places=None, sep=" ")
    for v in values:
        rounded = float(f"{v:.4g}")
        assert eng(v, "F") == formatter(rounded), v
        assert prefixed(rounded, "F") == formatter(rounded), v


def test_loads_no_plotting_library():
    import subprocess
    import sys

    out = subprocess.run([sys.executable, "-c", "import sys, handbook.core.units as u; u.eng(1e-9, 'F'); "
                          "print('matplotlib' in sys.modules)"], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "False"
