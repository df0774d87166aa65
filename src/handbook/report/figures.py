"""Figures with engineering units on their axes: SI prefixes on linear and log axes alike."""
from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np
from matplotlib.ticker import EngFormatter, Formatter, FuncFormatter


class _Minor(Formatter):
    """Labels for the minor ticks of a log axis (2 and 5 of each decade) in the major ticks' style, only
    when the axis spans two decades or less: a short log axis would otherwise carry one label or none."""

    def __init__(self, major: Formatter):
        self.major = major

    def __call__(self, x, pos=None):
        lo, hi = sorted(self.axis.get_view_interval())
        if lo <= 0 or hi / lo > 100 or x <= 0:
            return ""
        mantissa = x / 10 ** np.floor(np.log10(x))
        return self.major(x, pos) if np.isclose(mantissa, (2, 5), rtol=1e-6).any() else ""


def format_axis(ax, which: str, unit: str = "", log: bool = False) -> None:
    """Scale and tick labels of one axis ("x" or "y"): values with a unit get SI prefixes (EngFormatter),
    unitless values on a log axis plain numbers (1000, not 10^3). The scale is set before the formatters:
    setting it afterwards would put matplotlib's 10^n labels back."""
    axis = ax.xaxis if which == "x" else ax.yaxis
    if log:
        (ax.set_xscale if which == "x" else ax.set_yscale)("log")
    major = EngFormatter(unit=unit) if unit else FuncFormatter(lambda x, _: f"{x:g}") if log else None
    if major is not None:
        axis.set_major_formatter(major)
        if log:
            axis.set_minor_formatter(_Minor(major))


def axes(xlabel: str, ylabel: str, xunit: str = "", yunit: str = "", *, xlog: bool = False, ylog: bool = False):
    """A figure with labelled axes, formatted by format_axis."""
    fig, ax = plt.subplots()
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    format_axis(ax, "x", xunit, xlog)
    format_axis(ax, "y", yunit, ylog)
    return fig, ax
