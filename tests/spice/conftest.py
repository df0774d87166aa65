"""The fixture every SPICE test file uses: skip, saying why, where Debian's ngspice is not installed."""
import pytest

from handbook.spice import runner


@pytest.fixture(scope="module")
def ngspice():
    if runner.available() is None:
        pytest.skip(runner.why_unavailable())
