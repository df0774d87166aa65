"""The design plots, shared by the design chapters and the "Design your own" chapter."""
from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np

from ..core import series
from ..design import class_d, commutation, limiter
from ..design.class_d import model
from ..design.limiter import model as limiter_model
from ..sources.an94002 import circuit as an94002
from .figures import axes


def limiter_histogram(result, others: dict | None = None, n: int = 100_000):
    """Monte Carlo trip currents of the design (and of other limiters given as (R7, (R9, .., R13))), with
    the two limits."""
    s = result.spec
    fig, ax = axes("trip current", "boards", "A", "")
    runs = {"this design": (result.r7, result.network), **(others or {})}
    top = max(2 * s["i_must_trip"], 1.5 * result.i_trip_max)
    bins = np.linspace(0, top, 121)
    stats = {}
    for label, (r7, network) in runs.items():
        mc = limiter.monte_carlo_trip(r7, network, s, n=n, seed=1)
        stats[label] = mc
        ax.hist(mc["samples"], bins=bins, alpha=0.5, label=f"{label}: yield {mc['yield']:.1%}")
    for x in (s["i_no_trip"], s["i_must_trip"]):
        ax.axvline(x, color="k", ls="--", lw=1)
    ax.legend(fontsize=8)
    return fig, stats


def limiter_design_space(result, marks: dict | None = None):
    """Every (R7, R9) pair of the two series around the design, R10..R13 as chosen, coloured by the worst
    margin at every corner (the design's own ``min_margin`` contoured)."""
    s = result.spec
    r7s = np.array(series.values(s["r7_series"], max(s["r7_min"], result.r7 / 8), min(s["r7_max"], result.r7 * 8)))
    r9s = np.array(series.values(s["r9_series"], max(s["r9_min"], result.r9 / 30), min(s["r9_max"], result.r9 * 30)))
    R7, R9 = np.meshgrid(r7s, r9s, indexing="ij")
    others = [np.full(R9.shape, x) for x in result.network[1:]]
    v = limiter_model.verify(R7, (R9, *others), s)
    worst = np.minimum(v["margin_low"], v["margin_high"])
    fig, ax = axes("R9", "R7", "Ω", "Ω", xlog=True, ylog=True)
    pc = ax.pcolormesh(R9, R7, np.clip(worst, -1, 0.2), cmap="RdYlGn", vmin=-1, vmax=0.2, shading="nearest",
                       rasterized=True)  # one image in an SVG, not a path per cell
    if (worst > s["min_margin"]).any() and (worst < s["min_margin"]).any():
        ax.contour(R9, R7, worst, levels=[s["min_margin"]], colors="k", linewidths=1)
    ax.plot(result.r9, result.r7, "k*", ms=12, label="chosen")
    for label, (r7, r9) in (marks or {}).items():
        ax.plot(r9, r7, "kx", ms=9, label=label)
    fig.colorbar(pc, ax=ax, label="worst margin (clipped)")
    # a fixed corner: the feasible band runs diagonally (trip current ~ V_cs(R9) / R7), so the lower
    # right is always off it; loc="best" would also search the whole mesh, which under load takes more
    # than matplotlib's 1 s and then warns on stderr (the intermittent nbval failure)
    ax.legend(fontsize=8, loc="lower right")
    return fig


def limiter_sensitivity(rows):
    """Bar chart of :func:`handbook.design.limiter.sensitivity`: each source's share of the trip-current spread."""
    fig, ax = plt.subplots(figsize=(7, 3))
    names = [r["source"] for r in rows][::-1]
    ax.barh(names, [r["share"] * 100 for r in rows][::-1], color="C0")
    ax.set_xlabel("share of the worst-case spread ln(I_max / I_min) (%)")
    ax.grid(True, axis="x", alpha=0.3)
    fig.tight_layout()
    return fig


def timing_swing(result):
    """Worst-case CAP-CD swing against speed (every corner), with the narrowest window and the noise floor."""
    s, c = result.spec, result.cap_cd
    rpm = np.geomspace(result.rpm_min_reliable / 3, result.rpm_max_reliable * 2, 200)
    fig, ax = axes("speed (rpm)", "swing on CAP-CD", "", "V", xlog=True, ylog=True)
    for i, k, label in ((s["i_charge_max"], 1 - s["tolerance"], "largest current, smallest C"),
                        (s["i_charge_min"], 1 + s["tolerance"], "smallest current, largest C")):
        ax.plot(rpm, an94002.excursion(c * k, rpm, s["pole_pairs"], i), label=label)
    ax.axhline(s["v_high_min"] - s["v_low_max"], color="C3", ls="--", lw=1, label="narrowest window")
    ax.axhline(s["min_excursion"], color="C2", ls="--", lw=1, label="noise floor")
    ax.axvspan(s["rpm_min"], s["rpm_max"], color="C0", alpha=0.08, label="specified range")
    ax.legend(fontsize=8)
    return fig


def timing_ranges(result):
    """Every series CAP-CD's worst-case reliable speed range against the specified range (all corners)."""
    s = result.spec
    fig, ax = axes("capacitor", "reliable speed range (rpm)", "F", "", xlog=True, ylog=True)
    for c in series.values(s["series"], result.cap_cd / 20, result.cap_cd * 6):
        chk = commutation.verify(c, s)
        ok = chk["rpm_min_reliable"] <= s["rpm_min"] and chk["rpm_max_reliable"] >= s["rpm_max"]
        ax.plot([c, c], [chk["rpm_min_reliable"], chk["rpm_max_reliable"]], lw=5, color="C2" if ok else "0.7",
                solid_capstyle="butt")
    ax.axhspan(s["rpm_min"], s["rpm_max"], color="C0", alpha=0.12, label="specified range")
    ax.plot([result.cap_cd], [s["rpm_min"]], "kv", label="chosen")
    ax.legend(fontsize=8)
    ax.set_title("green: covers the whole specified range")
    return fig


def start_settling(result, others: dict | None = None):
    """The slowest rotor rocking's envelope against time, with the start periods of CAP-ST (and others)."""
    s, st = result.spec, result.start
    sigma = an94002.decay_rate(st.f_osc_min, s["damping_ratio"])
    t = np.linspace(0, 1.3 * max(st.period_max, st.settle), 300)
    fig, ax = axes("time after a start pulse", "rocking envelope", "s", "")
    ax.semilogy(t, np.exp(-sigma * t), color="k", label="slowest rocking, envelope")
    ax.axhline(s["residual"], color="C3", ls="--", lw=1, label="allowed at the next pulse")
    for k, (label, c) in enumerate({"chosen": result.cap_st, **(others or {})}.items()):
        chk = commutation.timers.check_start(c, s)
        ax.axvspan(chk["period_min"], chk["period_max"], color=f"C{k}", alpha=0.2,
                   label=f"{label} {c * 1e6:.3g} µF: start periods")
    ax.legend(fontsize=8)
    return fig


def class_d_margins(result, others: dict | None = None):
    """Every check's margin at its worst tolerance corner (what binds is the shortest bar); others: more
    {label: margins} to compare, e.g. the datasheet's own parts."""

    runs = {"this design": result.figures["margins"], **(others or {})}
    fig, ax = plt.subplots(figsize=(7, 4))
    y = np.arange(len(model.CHECKS))
    h = 0.8 / len(runs)
    for k, (label, m) in enumerate(runs.items()):
        ax.barh(y + k * h, [max(-1.0, min(1.0, m[c])) * 100 for c in model.CHECKS], height=h, label=label)
    ax.axvline(0, color="k", lw=1)
    ax.set_yticks(y + h * (len(runs) - 1) / 2, model.CHECKS)
    ax.invert_yaxis()
    ax.set_xlabel("margin at the worst corner (%; clipped to ±100)")
    # above the axes: inside, a fixed corner covers some check's bars
    ax.legend(fontsize=8, loc="lower center", bbox_to_anchor=(0.5, 1.0), ncol=1, frameon=False)
    fig.tight_layout()
    return fig


def class_d_design_space(result):
    """The (L, C_BYP) plane at the chosen R_OSC: which check fails first where, the choice marked."""

    s = result.spec
    _, ls, cs = model.axes(s, result.r_dly)
    ls, cs = ls[(ls >= result.l_out / 6) & (ls <= result.l_out * 6)], cs[(cs >= result.c_out / 6) & (cs <= result.c_out * 6)]
    L, C = np.meshgrid(ls, cs, indexing="ij")
    fig_ = model.figures(s, np.full(L.shape, result.r_osc), L, C, np.full(L.shape, result.r_dly))
    names = [k for k in model.CHECKS if k not in ("oscillator range", "clipping", "dead time", "heat sink")]
    first = np.full(L.shape, -1)
    for k, name in enumerate(names):
        first = np.where((first < 0) & (fig_["margins"][name] < 0), k, first)
    fig, ax = axes("L", "C_BYP", "H", "F", xlog=True, ylog=True)
    colours = ["C3", "C1", "C4", "C5", "C6"]
    ax.scatter(L[first < 0], C[first < 0], s=30, color="C2", label="meets every check")
    for k, name in enumerate(names):
        sel = first == k
        if sel.any():
            ax.scatter(L[sel], C[sel], s=18, color=colours[k % len(colours)], marker="x", label=f"fails {name}")
    ax.plot(result.l_out, result.c_out, "k*", ms=14, label="chosen")
    ax.legend(fontsize=7, loc="upper right")
    ax.set_title(f"R_OSC = {result.r_osc / 1e3:g} kΩ: f_sw {result.f_sw_min / 1e3:.0f}..{result.f_sw_max / 1e3:.0f} kHz")
    return fig


def class_d_pareto(spec: dict, thd_values, marks: dict | None = None):
    """Efficiency against THD+N: the design at each thd_max (the Pareto front), with other points marked
    ({label: (thd_n, efficiency)}). Returns the figure and the rows [(thd_max, design or None)]."""
    from ..design.solvers import Infeasible

    rows = []
    for thd in thd_values:
        try:
            rows.append((thd, class_d.design({**spec, "thd_max": float(thd)})))
        except Infeasible:
            rows.append((thd, None))
    ok = [(t, r) for t, r in rows if r is not None]
    fig, ax = axes("THD+N at the test point (worst corner)", "efficiency at p_out", "", "", xlog=True)
    ax.step([r.thd_n * 100 for _, r in ok], [r.efficiency * 100 for _, r in ok], where="post", color="C0", lw=1)
    ax.plot([r.thd_n * 100 for _, r in ok], [r.efficiency * 100 for _, r in ok], "o", color="C0",
            label="joint design at each THD+N limit")
    for k, (label, (thd, eff)) in enumerate((marks or {}).items()):
        ax.plot([thd * 100], [eff * 100], "s^Dv"[k % 4], ms=8, label=label)
    ax.set_xlabel("THD+N at the test point, worst corner (%)")
    ax.set_ylabel("efficiency at p_out (%)")
    ax.legend(fontsize=8)
    return fig, rows
