"""Plot conventions the book relies on: SI-prefixed log axes, and figures whose output does not depend on
the machine's load (nbval compares every cell's stderr)."""
import io
import itertools
import warnings

import matplotlib

matplotlib.use("Agg")
import matplotlib.legend  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import pytest  # noqa: E402
from matplotlib.ticker import EngFormatter  # noqa: E402

from handbook import report  # noqa: E402
from handbook.design import current_limiter  # noqa: E402
from handbook.report import design_plots  # noqa: E402


class _SlowClock:
    """Stands in for matplotlib.legend's `time`: every reading is 10 s after the last, as if the machine
    were so busy that the search for the "best" legend spot took longer than matplotlib's 1 s."""

    def __init__(self):
        self._t = itertools.count(0.0, 10.0)

    def perf_counter(self):
        return next(self._t)


def _render(fig):
    fig.savefig(io.BytesIO(), format="png")
    plt.close(fig)


def test_design_space_plot_is_silent_on_a_busy_machine(monkeypatch):
    """The intermittent nbval failure: loc="best" searched the whole R7-R9 mesh and, under load, took
    over 1 s, so matplotlib warned on stderr. The plot now puts its legend in a fixed corner."""
    monkeypatch.setattr(matplotlib.legend, "time", _SlowClock())
    fig = design_plots.limiter_design_space(current_limiter.design({}), {"the note's method": (0.075, 267.0)})
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        _render(fig)


def test_the_clock_does_make_a_best_legend_warn(monkeypatch):
    """The check above can fail: with loc="best" the same clock raises the warning, unless report.setup's
    filter (the guard for every other plot) is in place."""
    monkeypatch.setattr(matplotlib.legend, "time", _SlowClock())
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        fig, ax = plt.subplots()
        ax.plot([1, 2, 3], label="a")
        ax.legend()
        with pytest.raises(UserWarning, match="can be slow"):
            _render(fig)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        report.setup()
        fig, ax = plt.subplots()
        ax.plot([1, 2, 3], label="a")
        ax.legend()
        _render(fig)


def test_log_axes_keep_si_prefixes():
    fig, ax = report.axes("R9", "R7", "Ω", "Ω", xlog=True, ylog=True)
    ax.plot([100, 10e3], [0.05, 2.0])
    fig.canvas.draw()
    assert ax.get_xscale() == ax.get_yscale() == "log"
    assert isinstance(ax.xaxis.get_major_formatter(), EngFormatter)
    labels = [t.get_text() for t in ax.get_xticklabels() if t.get_text()]
    assert "1 kΩ" in labels and "10 kΩ" in labels
    # under two decades the minor ticks at 2 and 5 carry the labels the few major ticks cannot
    minor = [t.get_text() for t in ax.yaxis.get_minorticklabels() if t.get_text()]
    assert minor and all(lbl.endswith("Ω") for lbl in minor)
    assert "200 mΩ" in minor and "500 mΩ" in minor
    plt.close(fig)


def test_unitless_log_axes_show_plain_numbers():
    fig, ax = report.axes("speed (rpm)", "swing", "", "V", xlog=True, ylog=True)
    ax.plot([100, 50000], [0.05, 3.0])
    fig.canvas.draw()
    labels = [t.get_text() for t in ax.get_xticklabels() if t.get_text()]
    assert "1000" in labels and "10000" in labels
    assert not [t.get_text() for t in ax.xaxis.get_minorticklabels() if t.get_text()]  # over two decades
    plt.close(fig)
