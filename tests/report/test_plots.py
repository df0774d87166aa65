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
from handbook.design import class_d, commutation, limiter  # noqa: E402
from handbook.design.class_d.explain import datasheet_application  # noqa: E402
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
    fig = design_plots.limiter_design_space(limiter.design({}), {"the note's method": (0.075, 267.0)})
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        _render(fig)


NOTE_NETWORK = (267.0, 5.6e3, 16e3, 5.6e3, 16e3)  # AN94002's R9..R13
#: every design plot the book draws, as the chapters and "Design your own" call it
PLOTS = {
    "timing_ranges": lambda d: design_plots.timing_ranges(d["commutation"]),
    "timing_swing": lambda d: design_plots.timing_swing(d["commutation"]),
    "start_settling": lambda d: design_plots.start_settling(d["commutation"], {"AN94002": 0.22e-6}),
    "limiter_histogram": lambda d: design_plots.limiter_histogram(
        d["current_limiter"], {"the note's method": (0.075, NOTE_NETWORK)}, n=10_000)[0],
    "limiter_design_space": lambda d: design_plots.limiter_design_space(d["current_limiter"],
                                                                        {"the note's method": (0.075, 267.0)}),
    "limiter_sensitivity": lambda d: design_plots.limiter_sensitivity(limiter.sensitivity(d["current_limiter"])),
    "class_d_margins": lambda d: design_plots.class_d_margins(
        d["class_d"], {"datasheet's parts": datasheet_application(d["class_d"].spec)["margins"]}),
    "class_d_design_space": lambda d: design_plots.class_d_design_space(d["class_d"]),
    "class_d_pareto": lambda d: design_plots.class_d_pareto(d["class_d"].spec, [0.003, 0.01], {"x": (0.004, 0.85)})[0],
}


@pytest.fixture(scope="module")
def designs():
    motor = dict(inertia=72e-6, torque_constant=25e-3, start_current=0.5, flyback_time=1e-3)
    return {"commutation": commutation.design(motor), "current_limiter": limiter.design({}),
            "class_d": class_d.design({})}


@pytest.mark.parametrize("name", sorted(PLOTS))
def test_every_design_plot_draws_silently_on_a_busy_machine(name, designs, monkeypatch):
    """Each plot with the new results, as the book calls it after report.setup(): no exception and nothing
    on stderr (a warning would be a difference in nbval), even when the legend search is slow."""
    monkeypatch.setattr(matplotlib.legend, "time", _SlowClock())
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        report.setup()
        _render(PLOTS[name](designs))


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
