"""The design plots, shared by the design chapters and the "Design your own" chapter."""
from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np
from matplotlib.ticker import EngFormatter

from ..core import series
from ..design import class_d, commutation, current_limiter
from ..sources.an94002 import circuit as an94002
from ..sources.lm4651 import circuit as lm4651
from .figures import axes, format_axis


def commutation_ranges(result):
    """Every series capacitor's reliable speed range against the specified range."""
    s = result.spec
    caps = np.array(series.values(s["series"], result.cap_cd / 20, result.cap_cd * 6))
    fig, ax = axes("capacitor", "reliable speed range (rpm)", "F", "", xlog=True, ylog=True)
    for c in caps:
        chk = commutation.verify(c, s)
        ok = chk["rpm_min_reliable"] <= s["rpm_min"] and chk["rpm_max_reliable"] >= s["rpm_max"]
        ax.plot([c, c], [chk["rpm_min_reliable"], chk["rpm_max_reliable"]], lw=5, color="C2" if ok else "0.7",
                solid_capstyle="butt")
    ax.axhspan(s["rpm_min"], s["rpm_max"], color="C0", alpha=0.12, label="specified range")
    ax.plot([result.cap_cd], [s["rpm_min"]], "kv", label="chosen")
    ax.legend(fontsize=8)
    ax.set_title("green: covers the whole specified range")
    return fig


def commutation_swing(result):
    """Worst-case swing on the chosen capacitor against speed, with the window and the noise floor."""
    s, c = result.spec, result.cap_cd
    rpm = np.geomspace(result.rpm_min_reliable / 3, result.rpm_max_reliable * 2, 300)
    fig, ax = axes("speed (rpm)", "swing on CAP-CD", "", "V", xlog=True, ylog=True)
    ax.plot(rpm, [an94002.excursion(c * (1 - s["tolerance"]), x, s["pole_pairs"], s["i_charge_max"]) for x in rpm],
            label="largest current, smallest C")
    ax.plot(rpm, [an94002.excursion(c * (1 + s["tolerance"]), x, s["pole_pairs"], s["i_charge_min"]) for x in rpm],
            label="smallest current, largest C")
    ax.axhline(s["window"], color="C3", ls="--", lw=1, label="window")
    ax.axhline(s["min_excursion"], color="C2", ls="--", lw=1, label="noise floor")
    ax.axvspan(s["rpm_min"], s["rpm_max"], color="C0", alpha=0.08, label="specified range")
    ax.legend(fontsize=8)
    return fig


def limiter_histogram(result, others: dict | None = None, n: int = 100_000):
    """Monte Carlo trip currents of the design (and of any other (R7, R9) pairs), with the two limits."""
    s = result.spec
    fig, ax = axes("trip current", "boards", "A", "")
    runs = {"this design": (result.r7, result.r9), **(others or {})}
    top = max(2 * s["i_must_trip"], 1.5 * result.i_trip_max)
    bins = np.linspace(0, top, 121)
    stats = {}
    for label, (r7, r9) in runs.items():
        mc = current_limiter.monte_carlo_trip(r7, r9, s, n=n, seed=1)
        stats[label] = mc
        ax.hist(mc["samples"], bins=bins, alpha=0.5, label=f"{label}: yield {mc['yield']:.1%}")
    for x in (s["i_no_trip"], s["i_must_trip"]):
        ax.axvline(x, color="k", ls="--", lw=1)
    ax.legend(fontsize=8)
    return fig, stats


def limiter_design_space(result, marks: dict | None = None):
    """Every (R7, R9) pair of the two series around the design, coloured by the smaller margin."""
    s = result.spec
    r7s = np.array(series.values(s["r7_series"], max(s["r7_min"], result.r7 / 8), min(s["r7_max"], result.r7 * 8)))
    r9s = np.array(series.values(s["r9_series"], max(s["r9_min"], result.r9 / 30), min(s["r9_max"], result.r9 * 30)))
    R7, R9 = np.meshgrid(r7s, r9s, indexing="ij")
    worst = np.minimum(*current_limiter.limiter_margins(R7, R9, s))
    fig, ax = axes("R9", "R7", "Ω", "Ω", xlog=True, ylog=True)
    pc = ax.pcolormesh(R9, R7, np.clip(worst, -1, 0.2), cmap="RdYlGn", vmin=-1, vmax=0.2, shading="nearest")
    if (worst > 0).any() and (worst < 0).any():
        ax.contour(R9, R7, worst, levels=[0.0], colors="k", linewidths=1)
    ax.plot(result.r9, result.r7, "k*", ms=12, label="chosen")
    for label, (r7, r9) in (marks or {}).items():
        ax.plot(r9, r7, "kx", ms=9, label=label)
    fig.colorbar(pc, ax=ax, label="smaller relative margin (clipped)")
    # a fixed corner: the feasible band runs diagonally (trip current ~ V_cs(R9) / R7), so the lower
    # right is always off it; loc="best" would also search the whole mesh, which under load takes more
    # than matplotlib's 1 s and then warns on stderr (the intermittent nbval failure)
    ax.legend(fontsize=8, loc="lower right")
    return fig


def class_d_sweep(result, ambients=(25.0, 40.0, 50.0, 60.0)):
    """Efficiency, THD+N and the heat sink needed against switching frequency, band and choice marked."""
    s = result.spec
    f = np.linspace(lm4651.DEVICE["f_min"], lm4651.DEVICE["f_max"], 351)
    ev = [class_d.evaluate(x, s) for x in f]
    fig, axs = plt.subplots(3, 1, figsize=(7, 8), sharex=True)
    axs[0].plot(f, [e["efficiency"] * 100 for e in ev])
    axs[0].set_ylabel("efficiency (%)")
    axs[1].plot(f, [e["thd_n"] * 100 for e in ev])
    axs[1].axhline(s["thd_max"] * 100, color="C3", ls="--", lw=1, label="limit")
    axs[1].set_ylabel("THD+N at 10 W (%)")
    format_axis(axs[1], "y", log=True)
    axs[1].legend(fontsize=8)
    for t_a in ambients:
        need = [lm4651.theta_sa_required(lm4651.losses(x, s["p_out"], s["r_load"])[0], t_a, s["package"], s["theta_cs"])
                for x in f]
        axs[2].plot(f, need, label=f"T_a = {t_a:.0f} °C")
    if s["theta_sa_available"] is not None:
        axs[2].axhline(s["theta_sa_available"], color="k", ls="--", lw=1, label="your heat sink")
    axs[2].set_ylabel("θ_SA needed (K/W)")
    axs[2].legend(fontsize=8, ncol=2)
    for ax in axs:
        ax.axvspan(result.band[0], result.band[1], color="C2", alpha=0.12)
        ax.axvline(result.f_sw, color="k", lw=1)
        ax.axvline(125e3, color="0.5", ls=":", lw=1)
    axs[2].set_xlabel("switching frequency")
    axs[2].xaxis.set_major_formatter(EngFormatter(unit="Hz"))
    axs[0].set_title("green: feasible band; black: chosen; dotted: the datasheet's 125 kHz")
    return fig
