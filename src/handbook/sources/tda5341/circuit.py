"""TDA5341 commutation-delay timer (CAPCDM): capacitor, constant and longest delay (SI units)."""
from __future__ import annotations


def cap_cd_for(f_c1, i_charge, v_low, v_high):
    """C = I / (dV f_C1): charged at I for one commutation period 1/f_C1 across the window.

    Parameters
    ----------
    f_c1 : float
        Lowest commutation frequency of interest f_C1, Hz.
    i_charge : float
        CAPCDM charge current, A.
    v_low, v_high : float
        CAPCDM lower and upper switching levels, V.

    Returns
    -------
    float
        CAPCDM, F.
    """
    return i_charge / ((v_high - v_low) * f_c1)


def constant_nf_hz(i_charge, v_low, v_high):
    """The 'C = K / f_C1 (nF)' constant: K = I / dV in nF Hz.

    Parameters
    ----------
    i_charge : float
        CAPCDM charge current, A.
    v_low, v_high : float
        CAPCDM lower and upper switching levels, V.

    Returns
    -------
    float
        K, nF Hz (not SI: the excerpt's constant, C in nF = K / f_C1 in Hz).
    """
    return i_charge / (v_high - v_low) * 1e9


def max_delay_per_nf(i_discharge, v_low, v_high):
    """Longest delay (below f_C1): discharge across the window at I_dis, in ms per nF.

    Parameters
    ----------
    i_discharge : float
        CAPCDM discharge current, A.
    v_low, v_high : float
        CAPCDM lower and upper switching levels, V.

    Returns
    -------
    float
        The longest delay per nF of CAPCDM, ms/nF (not SI: as the excerpt prints it).
    """
    return (v_high - v_low) / i_discharge * 1e-9 * 1e3
