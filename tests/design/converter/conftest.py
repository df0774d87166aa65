"""The converter tests' fixtures: PyOpenMagnetics (once per worker; only the tests that read it ask for it)
and the design at the defaults."""
import pytest

from handbook.design.converter import result as converter


@pytest.fixture(scope="session")
def pom():
    return pytest.importorskip("PyOpenMagnetics")


@pytest.fixture(scope="module")
def result():
    """The excerpt's operating point as given (f_min = 20 kHz at the lowest supply): audible = warn."""
    return converter.design({"audible": "warn"})
