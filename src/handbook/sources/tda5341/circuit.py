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


def constant_k(i_charge, v_low, v_high):
    """The constant K of the excerpt's 'C = K / f_C1': K = I / dV, F Hz (the excerpt prints it in nF Hz).

    Parameters
    ----------
    i_charge : float
        CAPCDM charge current, A.
    v_low, v_high : float
        CAPCDM lower and upper switching levels, V.

    Returns
    -------
    float
        K, F Hz (A/V); times 1e9 it is the excerpt's nF Hz.
    """
    return i_charge / (v_high - v_low)


def max_delay(cap, i_discharge, v_low, v_high):
    """Longest delay (below f_C1): the capacitor discharged across the window at I_dis, C dV / I_dis.

    Parameters
    ----------
    cap : float
        CAPCDM, F (the excerpt quotes the delay for 1 nF).
    i_discharge : float
        CAPCDM discharge current, A.
    v_low, v_high : float
        CAPCDM lower and upper switching levels, V.

    Returns
    -------
    float
        The longest delay, s.
    """
    return cap * (v_high - v_low) / i_discharge
