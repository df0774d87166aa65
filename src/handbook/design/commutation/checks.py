"""Device-aware sanity of a commutation timing set: a valid design that the TDA5144 will not run as
intended still designs, and says why in ``warnings`` (each naming the limit and where it is read)."""
from __future__ import annotations

from ...sources.an94002 import circuit as an94002
from ...sources.an94002 import params as an94002_params
from .timers import CAP_TI_MIN

#: CAP-TI internal-timing charge (0.2 V -> 0.3 V) and discharge currents, typical (TDA5144 datasheet;
#: AN94002 2.1.3: 57 uA and 28 uA): the source's own parameters, not typed again
_NOTE = an94002_params()
I_TI_FAST, I_TI_DISCHARGE = _NOTE["i_ti_fast"], _NOTE["i_ti_discharge"]
V_TI_STEP = round(_NOTE["v_ti_low"] - _NOTE["v_ti_start"], 12)  # 0.1 V, not 0.0999...9
#: pin + board stray capacitance (assumption: a few pF for an SO20/SO28 pin and its track)
STRAY = 5e-12
#: above this a timing capacitor is in practice an electrolytic (assumption: film/ceramic end about here)
FILM_MAX = 1e-6
#: rated leakage floor of common aluminium electrolytics, '0.01 C V or 3 uA' (assumption; check the part)
LEAK_FLOOR = 3e-6


def capacitor_range(name: str, c: float, i_pin: float) -> list[str]:
    """A capacitor outside what a timing pin is meant for.

    Parameters
    ----------
    name : str
        The capacitor's name as the warning shows it ("CAP-CD", "CAP-ST", "CAP-TI").
    c : float
        Its value, F.
    i_pin : float
        The pin's smallest charge current, A (what an electrolytic's leakage would rival).

    Returns
    -------
    list of str
        Zero, one or two warnings: the stray capacitance (:data:`STRAY`) shifts the timing by more than 1 %, and
        the value is beyond film and ceramic parts (above :data:`FILM_MAX`).
    """
    out = []
    if STRAY / c > 0.01:
        out.append(f"{name} = {c * 1e12:.3g} pF: the pin and board stray capacitance (a few pF; {STRAY * 1e12:g} pF "
                   f"assumed) shifts its timing by {STRAY / c:.0%}: choose slower timing or check on the board")
    if c > FILM_MAX:
        out.append(f"{name} = {c * 1e6:.3g} µF is beyond film and ceramic values: an electrolytic's rated leakage "
                   f"(commonly 0.01 C V or {LEAK_FLOOR * 1e6:g} µA, whichever is larger; an assumption, check the part) "
                   f"rivals the pin's smallest current {i_pin * 1e6:.3g} µA (TDA5144 datasheet)")
    return out


def ti_cycle(cap_ti: float, tol: float) -> float:
    """The least time CAP-TI's internal timing takes per commutation at its largest value: the step
    0.2 -> 0.3 V at 57 uA and the discharge back at 28 uA, with no watchdog ramp at all (AN94002 2.1.3).
    A flyback adds its own length and a ramp to discharge, so the real cycle is longer.

    Parameters
    ----------
    cap_ti : float
        CAP-TI, nominal, F.
    tol : float
        Its tolerance, a fraction (the cycle is taken at ``cap_ti (1 + tol)``).

    Returns
    -------
    float
        The least internal-timing time per commutation, s.
    """
    c = cap_ti * (1 + tol)
    return c * V_TI_STEP / I_TI_FAST + c * V_TI_STEP / I_TI_DISCHARGE


def speed_limits(s: dict, start, watchdog) -> list[str]:
    """Speeds the IC cannot commutate with this timing set.

    Parameters
    ----------
    s : dict
        The checked ``[commutation]`` table (SI units, speeds in rpm).
    start : StartResult or None
        The CAP-ST design (:func:`~handbook.design.commutation.timers.design_start`), None when there is none.
    watchdog : WatchdogResult or None
        The CAP-TI design (:func:`~handbook.design.commutation.timers.design_watchdog`), None when there is
        none (the smallest allowed CAP-TI, 2000 pF, is then assumed).

    Returns
    -------
    list of str
        Zero to two warnings: the commutation interval at ``rpm_max`` is shorter than CAP-TI's internal timing
        (:func:`ti_cycle`), and the shortest start period is not longer than the commutation interval at
        ``rpm_min``.
    """
    out = []
    n = s["pole_pairs"]
    fast, slow = an94002.t_com(s["rpm_max"], n), an94002.t_com(s["rpm_min"], n)
    cap_ti = CAP_TI_MIN if watchdog is None else watchdog.cap_ti
    cycle = ti_cycle(cap_ti, s["tolerance"])
    if cycle >= fast:
        which = "the chosen" if watchdog else "even the smallest allowed (2000 pF, AN94002 2.1.3)"
        out.append(f"rpm_max = {s['rpm_max']:g} rpm: the commutation interval {fast * 1e6:.3g} µs is shorter than "
                   f"the {cycle * 1e6:.3g} µs CAP-TI needs at least for its internal timing with {which} CAP-TI "
                   f"(0.2 -> 0.3 V at 57 µA, back at 28 µA: TDA5144 datasheet, AN94002 2.1.3): the IC cannot "
                   f"commutate this fast")
    if start is not None and start.period_min <= slow:
        out.append(f"the shortest start period {start.period_min * 1e3:.3g} ms is not longer than the commutation "
                   f"interval at rpm_min ({slow * 1e3:.3g} ms): the start oscillator, reset only by commutations "
                   f"(AN94002 2.1.1), would fire while the motor runs")
    return out


def warnings(s: dict, cap_cd: float, start, watchdog) -> list[str]:
    """Every device warning of a timing set: each capacitor's range, then the speed limits.

    Parameters
    ----------
    s : dict
        The checked ``[commutation]`` table (SI units, speeds in rpm).
    cap_cd : float
        The chosen CAP-CD, F.
    start : StartResult or None
        The CAP-ST design, None when there is none.
    watchdog : WatchdogResult or None
        The CAP-TI design, None when there is none.

    Returns
    -------
    list of str
        The warnings of :func:`capacitor_range` for CAP-CD, CAP-ST and CAP-TI (those designed), then those of
        :func:`speed_limits`.
    """
    out = capacitor_range("CAP-CD", cap_cd, s["i_charge_min"])
    if start is not None:
        out += capacitor_range("CAP-ST", start.cap_st, s["i_st_min"])
    if watchdog is not None:
        out += capacitor_range("CAP-TI", watchdog.cap_ti, s["i_wd_min"])
    return out + speed_limits(s, start, watchdog)
