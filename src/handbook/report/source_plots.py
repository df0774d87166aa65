"""Figures of the source chapters that are more than a few lines (the LM4651/LM4652 loss and heat-sink curves)."""
from __future__ import annotations

import numpy as np

from ..sources.lm4651 import circuit as lm4651
from .figures import axes


def lm4651_losses(p_out=125.0, r_load=4.0, t_overmod=lm4651.DEVICE["t_overmod"]):
    """Switching, conduction and total LM4652 dissipation against switching frequency (eq 9, 10)."""
    f = np.linspace(lm4651.DEVICE["f_min"], lm4651.DEVICE["f_max"], 300)
    p_sw = lm4651.p_switch(f, p_out, t_overmod=t_overmod)
    p_c = np.full_like(f, lm4651.p_conduction(p_out, r_load))
    fig, ax = axes("switching frequency", "LM4652 dissipation", "Hz", "W")
    ax.plot(f, p_sw, label="switching (eq 9, 10)")
    ax.plot(f, p_c, label="conduction (2 R_DS(on) I_rms²)")
    ax.plot(f, p_sw + p_c, "k", label="total")
    ax.axvline(125e3, color="0.5", ls=":", lw=1)
    ax.set_ylim(0, None)
    ax.legend(fontsize=8)
    ax.set_title(f"{p_out:g} W into {r_load:g} Ω, T_OVERMOD = {t_overmod * 1e9:.0f} ns")
    return fig


def lm4651_heatsink(p_out=125.0, r_load=4.0, package="TF", theta_cs=0.2, ambients=(25.0, 40.0, 50.0, 60.0, 70.0)):
    """Heat sink needed (eq 11) against switching frequency, one line per ambient temperature."""
    f = np.linspace(lm4651.DEVICE["f_min"], lm4651.DEVICE["f_max"], 300)
    pd = lm4651.losses(f, p_out, r_load)[0]
    fig, ax = axes("switching frequency", "θ_SA needed (K/W)", "Hz", "")
    for t_a in ambients:
        ax.plot(f, lm4651.theta_sa_required(pd, t_a, package, theta_cs), label=f"T_a = {t_a:.0f} °C")
    ax.axvline(125e3, color="0.5", ls=":", lw=1)
    ax.legend(fontsize=8, ncol=2)
    ax.set_title(f"LM4652{package}, θ_CS = {theta_cs:g} K/W")
    return fig
