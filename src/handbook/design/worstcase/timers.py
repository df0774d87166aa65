"""The worst-case models of the TDA5144's start oscillator (CAP-ST) and watchdog (CAP-TI), the parts of the
commutation model :func:`.models.commutation` adds when the design chose them: the design's own equations
(:mod:`handbook.design.commutation.timers`, which call AN94002's eq 1, eq 2 with the rocking's decay, and eq 9
solved for the time), elementwise on numpy arrays, over the ranges its corners take.

* start: the start period (limit ``t_start_max`` when given), the slowest rocking's settle time, and the period
  over the settle time (limit 1: the rocking has decayed to ``residual`` before the next start pulse), over
  CAP-ST at +- ``tolerance``, the CAP-ST current at ``i_st_min`` .. ``i_st_max`` and the motor's K_t, start
  current and J at +- ``motor_tolerance`` (:func:`~handbook.design.commutation.timers.start_box`,
  :func:`~handbook.design.commutation.timers.rocking_box`);
* watchdog: the watchdog time (limit ``flyback_time``) and, with ``rpm_reverse``, the reverse-catch time over
  the watchdog time (limit 1, the design's margin_reverse + 1), over CAP-TI at +- ``tolerance`` and the
  watchdog current at ``i_wd_min`` .. ``i_wd_max``.

Each input's sensitivity group is the spec key that sets its range: the three timing capacitors share
``tolerance`` ("capacitor tolerance", CAP-CD's group), the motor's three figures ``motor_tolerance``.
"""
from __future__ import annotations

from ...core import tolerance
from ...sources.an94002 import circuit as an94002
from ..commutation import timers as design
from ..schema import TABLES
from .engine import Measure, Model, Source
from .limiter import UNIFORM

#: the commutation table's keys, for their defaults and cites
_PARAMS = {p.name: p for p in TABLES["commutation"]}
#: where the TDA5144's CAP-ST and CAP-TI currents' default ranges (the schema's) come from
PIN_SOURCES = {"i_st_min": "TDA5144 datasheet (June 1994), CAP-ST: min and max",
               "i_wd_min": "assumption: the TDA5144 datasheet and AN94002 2.1.3 print 5 uA typical only; +-25 % "
                           "about it, as CAP-ST's min and max lie about their typical"}


def capacitor_drift(name: str, c: float, s: dict) -> str:
    """The drift sentence of one timing capacitor: its class (the BOM's: C0G up to 100 nF, film above).

    Parameters
    ----------
    name : str
        "CAP-CD", "CAP-ST" or "CAP-TI".
    c : float
        Its nominal value, F.
    s : dict
        The checked ``[commutation]`` table (``tolerance`` is read).

    Returns
    -------
    str
        The sentence (ASCII units; the report makes them readable).
    """
    tech, tc = ("C0G/NP0, 0 +- 30 ppm/K", 30e-6) if c <= 100e-9 else ("polypropylene film, -200 ppm/K", 200e-6)
    return (f"{name} ({c * 1e9:.3g} nF) is {tech} (the BOM's timing-capacitor class): {tc * 100:.1%} per 100 K, "
            f"beside tolerance = {s['tolerance']:.0%}; the spec gives no temperature span for the timers, so it is "
            "not in the analysis.")


def pin_cite(s: dict, low: str, high: str) -> str:
    """Where a TDA5144 pin current's range comes from: :data:`PIN_SOURCES` for the defaults, else the spec.

    Parameters
    ----------
    s : dict
        The checked ``[commutation]`` table.
    low, high : str
        The keys of the smallest and largest current ("i_st_min", "i_st_max").

    Returns
    -------
    str
        The cite, ending with the distribution's reason.
    """
    default = (s[low], s[high]) == (_PARAMS[low].default, _PARAMS[high].default)
    where = PIN_SOURCES[low] if default else "the spec's own values"
    return f"commutation.{low} .. {high}: {where}; {UNIFORM}"


def capacitor(name: str, part: str, c: float, s: dict) -> Source:
    """A timing capacitor as a varying input: uniform within +- ``tolerance`` (CAP-CD, CAP-ST and CAP-TI alike).

    Parameters
    ----------
    name : str
        Its argument name in the model's equations ("cap", "cap_st").
    part : str
        The part as the report names it ("CAP-CD").
    c : float
        The chosen capacitance, F.
    s : dict
        The checked ``[commutation]`` table.

    Returns
    -------
    Source
    """
    lo, hi = tolerance.symmetric(c, s["tolerance"])
    return Source(name, part, lo, hi, c, "capacitor tolerance",
                  f"commutation.tolerance = {s['tolerance']:g} (the capacitor's tolerance class); " + UNIFORM, unit="F")


def start(c: float, s: dict) -> Model:
    """The CAP-ST part of the commutation model.

    Parameters
    ----------
    c : float
        The chosen CAP-ST, F.
    s : dict
        The checked ``[commutation]`` table, with the motor data.

    Returns
    -------
    Model
        Inputs ``cap_st``, ``i_st``, ``k_t``, ``i_start``, ``inertia``; quantities ``start_period`` (s, limit
        ``t_start_max`` when given), ``rocking_settle`` (s, no limit) and ``start_settles`` (the period over the
        settle time, limit 1); its drift sentences.
    """
    box, rock = design.start_box(c, s), design.rocking_box(s)
    motor = (f"commutation.motor_tolerance = {s['motor_tolerance']:g} ({_PARAMS['motor_tolerance'].cite}), as "
             "the design's rocking box takes it; " + UNIFORM)
    srcs = (capacitor("cap_st", "CAP-ST", c, s),
            Source("i_st", "TDA5144 CAP-ST current", *box["i_cap"], sum(box["i_cap"]) / 2, "CAP-ST current",
                   pin_cite(s, "i_st_min", "i_st_max"), unit="A"),
            Source("k_t", "motor torque constant K_t", *rock["torque_constant"], s["torque_constant"], "motor data",
                   motor, unit="N m/A"),
            Source("i_start", "motor start current", *rock["current"], s["start_current"], "motor data", motor,
                   unit="A"),
            Source("inertia", "rotor and load inertia J", *rock["inertia"], s["inertia"], "motor data", motor,
                   unit="kg m^2"))
    period, rocking = design.start_period(s), design.f_osc(s)

    def f(cap_st, i_st, k_t, i_start, inertia):
        p = period(cap_st, i_st)
        settle = an94002.settle_time(rocking(k_t, i_start, inertia), s["damping_ratio"], s["residual"])
        return {"start_period": p, "rocking_settle": settle, "start_settles": p / settle}

    t_max = s["t_start_max"]
    measures = (Measure("start_period", "CAP-ST start period", "s", None, t_max, "" if t_max is None else "t_start_max"),
                Measure("rocking_settle", "rotor rocking's decay time to the residual (eq 2)", "s"),
                Measure("start_settles", "start period over the rocking's decay time", "1", 1.0, None, "rocking settles"))
    drift = (capacitor_drift("CAP-ST", c, s),
             f"J, K_t and the start current are taken at +-{s['motor_tolerance']:.0%} (motor_tolerance, an "
             "assumption) with their drift inside it: the project holds no figure for K_t's fall as the magnets warm "
             "nor the start current's with the winding's resistance.",
             f"The damping ratio ({s['damping_ratio']:g}) and residual ({s['residual']:g}) are taken as given, not "
             "varied: the decay time is ln(1/residual) over the decay rate, which is the damping ratio times "
             "2π f for light damping, so a damping ratio half as large doubles it; a measured decay is the check.")
    return Model(srcs, measures, f, drift)


def watchdog(c: float, s: dict) -> Model:
    """The CAP-TI part of the commutation model.

    Parameters
    ----------
    c : float
        The chosen CAP-TI, F.
    s : dict
        The checked ``[commutation]`` table, with ``flyback_time``.

    Returns
    -------
    Model
        Inputs ``cap_ti``, ``i_wd``; quantities ``watchdog_time`` (s, limit ``flyback_time``) and, with
        ``rpm_reverse``, ``reverse_over_watchdog`` (the time a rotor reversing at ``rpm_reverse`` takes for 150
        electrical degrees over the watchdog time, limit 1); its drift sentence.
    """
    srcs = (capacitor("cap_ti", "CAP-TI", c, s),
            Source("i_wd", "TDA5144 CAP-TI watchdog current", s["i_wd_min"], s["i_wd_max"],
                   (s["i_wd_min"] + s["i_wd_max"]) / 2, "CAP-TI current", pin_cite(s, "i_wd_min", "i_wd_max"),
                   unit="A"))
    time = design.watchdog_time(s)
    t_rev = None if s["rpm_reverse"] is None else an94002.reverse_catch_time(s["rpm_reverse"], s["pole_pairs"])

    def f(cap_ti, i_wd):
        t = time(cap_ti, i_wd)
        return {"watchdog_time": t} if t_rev is None else {"watchdog_time": t, "reverse_over_watchdog": t_rev / t}

    measures = (Measure("watchdog_time", "CAP-TI watchdog time", "s", s["flyback_time"], None, "flyback_time"),)
    if t_rev is not None:
        measures += (Measure("reverse_over_watchdog", "reverse-catch time at rpm_reverse over the watchdog time", "1",
                             1.0, None, "rpm_reverse"),)
    return Model(srcs, measures, f, (capacitor_drift("CAP-TI", c, s),))


def pin_drift(s: dict, started: bool, watched: bool) -> str:
    """The drift sentence of the TDA5144's CAP-ST and CAP-TI currents.

    Parameters
    ----------
    s : dict
        The checked ``[commutation]`` table.
    started, watched : bool
        Whether CAP-ST, CAP-TI was chosen.

    Returns
    -------
    str
        The sentence ("" when neither was).
    """
    pins = [p for p, there in (("CAP-ST", started), ("CAP-TI", watched)) if there]
    if not pins:
        return ""
    return (f"The TDA5144's {' and '.join(pins)} current{'s are' if len(pins) > 1 else ' is'} taken at the spec's "
            "min and max (where those come from: the distributions' sources); the project holds no figure for "
            f"{'their' if len(pins) > 1 else 'its'} temperature drift beyond them.")
