"""The TDA5143/TDA5144 timers as the IC drives them (AN94002 2.1): CAP-ST (start oscillator), CAP-CD and
CAP-DC (adaptive commutation delay, figure 4) and CAP-TI (watchdog).

Each pin is a capacitor fed by the IC's switched current sources, which its comparators turn over at
fixed levels. Currents and levels are the TDA5144 datasheet's (Philips, June 1994);
the IC's logic is modelled, not copied, and these are the assumptions:

* a current source is an ideal behavioural source (``B ... I=``): no output resistance, no leakage;
* the CAP-ST and CAP-TI comparators are one ngspice switch with hysteresis (``SW(VT, VH)``): it turns
  on at the upper level and off at the lower one, with no delay;
* the zero crossings of the back-EMF come from two gate sources (the IC's EMF comparators, not
  modelled): CAP-CD charges from one zero crossing to the next, then sinks twice the current until it is
  back at its low level (the commutation; AN94002 2.1.2); CAP-DC does the same one interval later;
* a sink stops at the low level and a source at the high level over a 2 mV ramp (a clamp, so that the
  solver sees no step); what the IC does above the high level the datasheet does not say.
"""
from __future__ import annotations

from ..sources import an94002 as note
from ..sources.an94002.parts import PARTS
from . import schematic
from .circuit import Check, Circuit, Part, rebuildable, with_defaults
from .runner import run

TDA5144 = "TDA5144 datasheet (June 1994)"
#: CAP-CD discharge (sink) current and switching levels, min / typ / max (TDA5144 datasheet; the column
#: pairing of its scrambled table is an interpretation)
CD_SINK = (10.6e-6, 16.2e-6, 22e-6)
CD_LOW = (0.80, 0.875, 0.90)
CD_HIGH = (2.3, 2.4, 2.55)
CLAMP = 2e-3  # V: width of the soft stop of a source at a level (assumption, see the module text)
BOARD = {ref: value for ref, _, value, *_ in PARTS}
#: the TDA5144 datasheet's own start example, "t = 500 ms, thus C = 0.5/2 = 0.25 uF": a start period of 2 s
#: per uF of CAP-ST (TDA5144 datasheet). A printed rule, not this module's charge balance.
START_RULE = 2.0 / 1e-6  # s per F
#: what a check between the equation's own levels can and cannot show (the timers' sanity checks)
SANITY = ("by construction: the deck integrates the same constant current between the same levels the equation "
          "uses, so it checks the deck's switching logic and the solver's step, not the equation (the IC's timers "
          "have no independent SPICE check: their equations are this charge balance)")


def element_lines(parts, nodes: dict[str, str]) -> list[str]:
    """One netlist line per part: ``<name> <nodes> <value>`` for a part placed in ``nodes`` (ref ->
    "name nodes"), else ``.param <ref>=<value>`` for an IC figure the behavioural sources use."""
    out = []
    for p in parts:
        value = p.value if isinstance(p.value, str) else f"{p.value:.6g}"
        out.append(f"{nodes[p.ref]} {value}" if p.ref in nodes else f".param {p.ref.lower()}={value}")
    return out


def label(part: Part) -> str:
    """A part as the drawing shows it: designator (subscripts typeset) and value with its unit (Ω, µF)."""
    return schematic.label(part)


def _hysteresis(v_low: float, v_high: float) -> str:
    """ngspice's switch turns on above VT + VH and off below VT - VH: the comparator's two levels."""
    return f"SW(VT={(v_high + v_low) / 2:.6g} VH={(v_high - v_low) / 2:.6g} RON=1 ROFF=1e12)"


def _soft(expr: str) -> str:
    """0 .. 1 over the clamp width: a source's soft stop at a level."""
    return f"min(max(({expr})/{CLAMP:g},0),1)"


def _meas(*lines: str) -> list[str]:
    return [".meas tran " + line for line in lines]


# ----------------------------------------------------------------------------------------------
# CAP-ST: start oscillator

def start_defaults() -> dict:
    levels = note.FACTS["cap_st_levels"].value
    return {"cap_st": BOARD["C5"], "i_st": note.FACTS["cap_st_current"].value[1], "v_low": levels[0],
            "v_high": levels[1]}


@rebuildable
def start_oscillator(p: dict | None = None) -> Circuit:
    """CAP-ST (C5) charged and discharged at I_ST between the TDA5144's two levels (0.20 V, 2.20 V)."""
    q = with_defaults(start_defaults(), p)
    parts = (Part("C5", q["cap_st"], "F", "CAP-ST"),
             Part("I_ST", q["i_st"], "A", "CAP-ST charge = discharge current, typ (TDA5144)"),
             Part("V_LOW", q["v_low"], "V", "CAP-ST lower level (TDA5144)"),
             Part("V_HIGH", q["v_high"], "V", "CAP-ST upper level (TDA5144)"))
    period = note.start_period(q["cap_st"], q["i_st"], q["v_low"], q["v_high"])
    mid = (q["v_low"] + q["v_high"]) / 2
    lines = ["* CAP-ST start oscillator (TDA5144, AN94002 2.1.1)", *element_lines(parts, {"C5": "C5 st 0"}),
             "* comparator: a switch with hysteresis sets q = 1 (discharge) at V_HIGH, q = 0 at V_LOW",
             "VDD vdd 0 1", "SCMP vdd q st 0 swst OFF", "RQ q 0 1e6",
             f".model swst {_hysteresis(q['v_low'], q['v_high'])}",
             "BST 0 st I = i_st*(1-2*v(q))", f".ic v(st)={q['v_low']:.6g}",
             f".tran {period / 2000:.6g} {3.6 * period:.6g} 0 {period / 2000:.6g} uic",
             *_meas(f"t1 WHEN v(st)={mid:.6g} RISE=2", f"t2 WHEN v(st)={mid:.6g} RISE=3", "period PARAM='t2-t1'",
                    f"tdown WHEN v(st)={mid:.6g} FALL=2", "rise_time PARAM='tdown-t1'", "freq PARAM='1/(t2-t1)'")]
    why = ("the model switches up to a time step after the level is crossed (step = period / 2000, 0.05 % of the "
           "period); the equation switches exactly at the level")
    checks = (Check("start-period", "start period (TDA5144 levels)", "s", period, "period", 0.001,
                    f"{SANITY}; {why}: a period holds one switch at each level, two steps at most: ±0.1 %",
                    kind="sanity"),
              Check("start-ramp-up", "time from mid-window up and back to mid-window (half a period)", "s",
                    period / 2, "rise_time", 0.002, f"{SANITY}; {why}; charge and discharge at the same current: the "
                    "switch at the top, a step of this half period (0.1 %), and the two crossings' interpolation: "
                    "±0.2 %", kind="sanity"),
              Check("start-frequency", "start oscillator's frequency against the TDA5144 datasheet's rule "
                    "t = 2 s/uF x CAP-ST", "Hz", 1 / (START_RULE * q["cap_st"]), "freq", 0.001,
                    "by construction: the datasheet's printed rule (its example: 500 ms, C = 0.5/2 = 0.25 uF) is the "
                    "same charge balance the deck runs, 2 x 2 V / 2 uA = 2 s per uF at the typical current and the "
                    "0.20 V / 2.20 V levels (a part at its 1.5 or 2.5 uA moves both by 25 %), so it checks that the "
                    "rule and the datasheet's figures are one, not the oscillator. The note's eq 1, 2.15 s/uF, is for "
                    f"0.05 V to 2.2 V and would be 7.5 % slow here. Left: {why}: two steps at most, ±0.1 %",
                    kind="sanity"))
    return Circuit("cap-st", "CAP-ST start oscillator", "AN94002 2.1.1; TDA5144 datasheet", parts,
                   "\n".join(lines) + "\n", checks, draw=lambda: draw_timer(parts, "CAP-ST"))


# ----------------------------------------------------------------------------------------------
# CAP-CD / CAP-DC: adaptive commutation delay

def commutation_defaults() -> dict:
    from ..design.schema import defaults

    p = note.params()
    return {"cap_cd": BOARD["C3"], "cap_dc": BOARD["C4"], "pole_pairs": p["pole_pairs"], "rpm_min": p["rpm_min"],
            "rpm_max": defaults("commutation")["rpm_max"], "i_ch": note.FACTS["cap_cd_charge"].value[1],
            "i_dis": CD_SINK[1], "v_low": CD_LOW[1], "v_high": CD_HIGH[1], "cycles": 3}


def _pwl(times: list[float], levels: list[int], rise: float) -> str:
    pts = [(0.0, levels[0])]
    for t0, t1, lvl in zip(times[:-1], times[1:], levels):
        pts += [(t0 + rise, lvl), (t1, lvl)] if t0 > 0 else [(t1, lvl)]
    return "PWL(" + " ".join(f"{t:.9g} {v}" for t, v in pts) + ")"


def zero_crossings(segments: list[tuple[float, int]]) -> list[float]:
    """Times of the back-EMF zero crossings for [(t_com, intervals)]: one every t_com."""
    times = [0.0]
    for tc, n in segments:
        times += [times[-1] + tc * (k + 1) for k in range(n)]
    return times


def timer_source(name: str, node: str, gate: str, i_ch: str, i_dis: str, v_low: str, v_high: str) -> str:
    """One commutation timer: charge while the gate is high (stopping at v_high), sink i_dis while it is low
    (stopping at v_low, the commutation)."""
    return (f"B{name} 0 {node} I = {i_ch}*v({gate})*{_soft(f'{v_high}-v({node})')}"
            f" - {i_dis}*(1-v({gate}))*{_soft(f'v({node})-{v_low}')}")


#: where CAP-CD's and CAP-DC's capacitors sit (the SPICE netlist and lcapy's netlist both read this)
CD_NODES = {"C3": "C3 cd 0", "C4": "C4 dc 0"}


def _cd_netlist(q: dict, parts, extra: tuple = ()) -> tuple[str, dict]:
    n = q["pole_pairs"]
    tc = {"min": note.t_com(q["rpm_min"], n), "max": note.t_com(q["rpm_max"], n)}
    k = 2 * q["cycles"]
    zc = zero_crossings([(tc["min"], k), (tc["max"], k)])
    rise = tc["max"] / 1000
    levels = [(i + 1) % 2 for i in range(2 * k)]
    at = {"min": 2 * tc["min"], "max": zc[k] + 2 * tc["max"]}  # start of the second cycle of each speed
    v_hit = f"{q['v_low'] + CLAMP:.6g}"
    lines = ["* CAP-CD / CAP-DC adaptive commutation delay (TDA5144, AN94002 2.1.2, figure 4)",
             *element_lines(parts, CD_NODES),
             "* zero crossings of the back-EMF (the IC's EMF comparators, not modelled): gate high = charge",
             f"VGCD gcd 0 {_pwl(zc, levels, rise)}", f"VGDC gdc 0 {_pwl(zc, [1 - v for v in levels], rise)}",
             timer_source("CD", "cd", "gcd", "i_ch", "i_dis", "v_low", "v_high"),
             timer_source("DC", "dc", "gdc", "i_ch", "i_dis", "v_low", "v_high"),
             f".ic v(cd)={q['v_low']:.6g} v(dc)={q['v_low']:.6g}",
             f".tran {rise:.6g} {zc[-1]:.9g} 0 {tc['max'] / 400:.6g} uic"]
    for s in ("min", "max"):
        t0, t1 = at[s], at[s] + 2 * tc[s]
        lines += _meas(f"cdhi_{s} MAX v(cd) FROM={t0:.9g} TO={t1:.9g}", f"cdlo_{s} MIN v(cd) FROM={t0:.9g} TO={t1:.9g}",
                       f"swing_{s} PARAM='cdhi_{s}-cdlo_{s}'",
                       f"dchi_{s} MAX v(dc) FROM={t0:.9g} TO={t1 + tc[s]:.9g}",
                       f"dcswing_{s} PARAM='dchi_{s}-{q['v_low']:.6g}'",
                       f"tcom_{s} WHEN v(cd)={v_hit} FALL=1 FROM={t0 + tc[s]:.9g}",
                       f"delay_{s} PARAM='tcom_{s}-{t0 + tc[s]:.9g}'")
    return "\n".join([*lines, *extra]) + "\n", {"tc": tc, "zc": zc}


@rebuildable
def commutation_delay(p: dict | None = None) -> Circuit:
    """C3 (CAP-CD) and C4 (CAP-DC) driven by the TDA5144's typical currents, ``cycles`` electrical cycles at
    rpm_min and then at rpm_max."""
    q = with_defaults(commutation_defaults(), p)
    parts = (Part("C3", q["cap_cd"], "F", "CAP-CD"), Part("C4", q["cap_dc"], "F", "CAP-DC"),
             Part("I_CH", q["i_ch"], "A", "charge (source) current, typ (TDA5144)"),
             Part("I_DIS", q["i_dis"], "A", "discharge (sink) current, typ (TDA5144)"),
             Part("V_LOW", q["v_low"], "V", "low level, typ (TDA5144)"),
             Part("V_HIGH", q["v_high"], "V", "high level, typ (TDA5144)"))
    netlist, _ = _cd_netlist(q, parts)
    n = q["pole_pairs"]
    ratio = q["i_ch"] / q["i_dis"]
    swing_why = (f"{SANITY}; the gate's edges take t_com / 1000 (half of one inside the charge: 0.05 %) and the "
                 "model's time step is t_com / 400 at rpm_max (0.25 %): 0.3 % at most, ±0.5 %")
    delay_why = (f"{SANITY} (charge at I_CH for t_com, sink at I_DIS back down: t_com I_CH / I_DIS, less the "
                 f"{CLAMP * 1e3:g} mV above the low level where the simulation times the fall and its clamp begins, "
                 f"{CLAMP * 1e3:g} mV x C / I_DIS); the model's step is t_com / 400 at rpm_max, the gate's edges "
                 "t_com / 1000: ±0.5 %")
    early = q["cap_cd"] * CLAMP / q["i_dis"]  # the fall is timed at v_low + CLAMP: the sink's last 2 mV are not in it
    checks = tuple(
        Check(f"cd-swing-{s}", f"CAP-CD swing at {q[f'rpm_{s}']:g} rpm", "V",
              note.excursion(q["cap_cd"], q[f"rpm_{s}"], n, q["i_ch"]), f"swing_{s}", 0.005, swing_why, kind="sanity")
        for s in ("min", "max")) + (
        Check("dc-swing-min", f"CAP-DC swing at {q['rpm_min']:g} rpm", "V",
              note.excursion(q["cap_dc"], q["rpm_min"], n, q["i_ch"]), "dcswing_min", 0.005, swing_why, kind="sanity"),
        Check("cd-delay-min", f"commutation delay after the zero crossing at {q['rpm_min']:g} rpm", "s",
              note.t_com(q["rpm_min"], n) * ratio - early, "delay_min", 0.005, delay_why, kind="sanity"),
        Check("cd-delay-max", f"commutation delay after the zero crossing at {q['rpm_max']:g} rpm", "s",
              note.t_com(q["rpm_max"], n) * ratio - early, "delay_max", 0.005, delay_why, kind="sanity"))
    return Circuit("cap-cd", "CAP-CD / CAP-DC adaptive commutation delay", "AN94002 2.1.2, figure 4; TDA5144 datasheet",
                   parts, netlist, checks, draw=lambda: draw_timer(parts, "CAP-CD / CAP-DC"))


def commutation_waveforms(p: dict | None = None, points: int = 400) -> dict:
    """Figure 4 from the simulation: CAP-CD and CAP-DC sampled at ``points`` times (.meas FIND AT), with the
    zero crossings. {"t": [...], "cd": [...], "dc": [...], "zc": [...], "tc": {...}}."""
    q = with_defaults(commutation_defaults(), p)
    c = commutation_delay(q)
    _, info = _cd_netlist(q, c.parts)
    end = info["zc"][-1]
    times = [end * (k + 0.5) / points for k in range(points)]
    extra = _meas(*(f"w{node}{k} FIND v({node}) AT={t:.9g}" for k, t in enumerate(times) for node in ("cd", "dc")))
    netlist, _ = _cd_netlist(q, c.parts, extra)
    out = run(netlist)
    return {"t": times, "cd": [out[f"wcd{k}"] for k in range(points)], "dc": [out[f"wdc{k}"] for k in range(points)],
            "zc": info["zc"], "tc": info["tc"]}


def design_check(result) -> dict:
    """A commutation design simulated at every tolerance corner, not at the corner the design picked: CAP-CD
    at rpm_min for each capacitor end (+- tolerance), charge current (min, max) and pair of levels (low min /
    max, high min / max), 16 timers, and at rpm_max for each capacitor end and current, 4 timers; each sinks
    twice its charge current and stops at its own levels. One run; the simulation's own worst swings:
    {"swing_rpm_min": the largest at rpm_min, "swing_rpm_max": the smallest at rpm_max, "window_reached":
    whether any rpm_min corner's swing reached that corner's own window (its source stopped at the high
    level: the design does not fit), each swing beside the design's own figure ("*_equation"), "corners" (20)
    and "meets_spec" (no window reached and the smallest swing at rpm_max at least min_excursion)}. A design
    whose corner search missed a corner shows here as a larger swing than its swing_at_rpm_min; a swing beyond
    a corner's window is cut at that window. A sanity check: each timer integrates the same constant current
    between the same levels as the design's formula; what it adds is the corner search of its own."""
    import itertools

    s, c = result.spec, result.cap_cd
    caps = (c * (1 - s["tolerance"]), c * (1 + s["tolerance"]))
    currents = (s["i_charge_min"], s["i_charge_max"])
    levels = list(itertools.product((s["v_low_min"], s["v_low_max"]), (s["v_high_min"], s["v_high_max"])))
    corners = [("min", k, cap, i, lv) for k, (cap, i, lv) in enumerate(itertools.product(caps, currents, levels))]
    corners += [("max", k, cap, i, (s["v_low_max"], s["v_high_min"]))
                for k, (cap, i) in enumerate(itertools.product(caps, currents))]
    lines, end = ["* commutation design at every corner"], 0.0
    tcs = {name: note.t_com(s[f"rpm_{name}"], s["pole_pairs"]) for name in ("min", "max")}
    for speed, k, cap, i_ch, (v_lo, v_hi) in corners:
        tc, tag = tcs[speed], f"{speed}{k}"
        zc = zero_crossings([(tc, 4)])
        end = max(end, zc[-1])
        lines += [f"C{tag} n{tag} 0 {cap:.6g}", f"VG{tag} g{tag} 0 {_pwl(zc, [1, 0, 1, 0], tc / 1000)}",
                  timer_source(tag, f"n{tag}", f"g{tag}", f"{i_ch:.6g}", f"{2 * i_ch:.6g}", f"{v_lo:.6g}", f"{v_hi:.6g}"),
                  f".ic v(n{tag})={v_lo:.6g}",
                  *_meas(f"hi_{tag} MAX v(n{tag}) FROM={2 * tc:.9g} TO={4 * tc:.9g}",
                         f"lo_{tag} MIN v(n{tag}) FROM={2 * tc:.9g} TO={4 * tc:.9g}")]
    step = min(tcs.values()) / 400
    out = run("\n".join([*lines, f".tran {step:.6g} {end:.9g} 0 {step:.6g} uic"]) + "\n")
    swings = {(sp, k): out[f"hi_{sp}{k}"] - out[f"lo_{sp}{k}"] for sp, k, *_ in corners}
    reached = any(swings["min", k] >= (v_hi - v_lo) - 2 * CLAMP for sp, k, _, _, (v_lo, v_hi) in corners if sp == "min")
    hi = max(w for (sp, _), w in swings.items() if sp == "min")
    lo = min(w for (sp, _), w in swings.items() if sp == "max")
    out = {"swing_rpm_min": hi, "swing_rpm_min_equation": float(result.swing_at_rpm_min),
           "swing_rpm_max": lo, "swing_rpm_max_equation": float(result.swing_at_rpm_max),
           "window_reached": bool(reached), "corners": len(corners),
           "meets_spec": bool(not reached and lo >= s["min_excursion"])}
    return {**out, **_start_and_watchdog(result)}


def _start_and_watchdog(result) -> dict:
    """CAP-ST and CAP-TI where the design chose them, each simulated at the corner its limit is judged at (the
    chapter's decks with the design's part at its tolerance end and the spec's current): the shortest start period
    (C5 low, the largest I_ST) against the rotor's decay, the shortest watchdog time (C6 low, the largest I_WD)
    against the flyback and the longest (C6 high, the smallest I_WD) against reverse rotation. Each beside the
    design's own figure (``*_equation``); ``misses`` names a limit SPICE's figure misses, and ``meets_spec`` is
    cleared then."""
    s, tol = result.spec, result.spec["tolerance"]
    out, misses = {}, []
    if result.start is not None:
        st = result.start
        deck = start_oscillator({"cap_st": st.cap_st * (1 - tol), "i_st": s["i_st_max"], "v_low": s["v_st_low"],
                                 "v_high": s["v_st_high"]})
        out.update(start_period_min=run(deck.netlist)["period"], start_period_min_equation=float(st.period_min))
        if out["start_period_min"] < st.settle:
            misses.append(f"the shortest start period, {out['start_period_min']:.4g} s, is shorter than the rotor's "
                          f"decay, {st.settle:.4g} s")
    if result.watchdog is not None:
        wd = result.watchdog
        for key, cap, i_wd in (("t_wd_min", wd.cap_ti * (1 - tol), s["i_wd_max"]),
                               ("t_wd_max", wd.cap_ti * (1 + tol), s["i_wd_min"])):
            out[key] = run(watchdog({"cap_ti": cap, "i_wd": i_wd}).netlist)["t_wd"]
            out[f"{key}_equation"] = float(getattr(wd, key))
        if out["t_wd_min"] < s["flyback_time"]:
            misses.append(f"the shortest watchdog time, {out['t_wd_min']:.4g} s, is shorter than the flyback")
        if wd.t_reverse is not None and out["t_wd_max"] > wd.t_reverse:
            misses.append(f"the longest watchdog time, {out['t_wd_max']:.4g} s, outlasts reverse rotation's "
                          f"{wd.t_reverse:.4g} s")
    return {**out, **({"misses": misses, "meets_spec": False} if misses else {})}


# ----------------------------------------------------------------------------------------------
# CAP-TI: watchdog

def watchdog_defaults() -> dict:
    p = note.params()
    return {k: p[k] for k in ("cap_ti", "i_ti_fast", "i_wd", "i_ti_discharge", "v_ti_start", "v_ti_low", "v_ti_high")}


@rebuildable
def watchdog(p: dict | None = None) -> Circuit:
    """C6 (CAP-TI): one stalled cycle (the ramp reaches 2.2 V, the watchdog fires, 28 uA back to 0.2 V), then
    one in which the EMF recovers half-way up the ramp (the discharge starts there)."""
    q = with_defaults(watchdog_defaults(), p)
    parts = (Part("C6", q["cap_ti"], "F", "CAP-TI"),
             Part("I_FAST", q["i_ti_fast"], "A", "internal timing charge, 0.2 to 0.3 V (TDA5144)"),
             Part("I_WD", q["i_wd"], "A", "watchdog charge, 0.3 to 2.2 V (TDA5144)"),
             Part("I_TIDIS", q["i_ti_discharge"], "A", "discharge (TDA5144)"),
             Part("V_START", q["v_ti_start"], "V", "level after discharge"),
             Part("V_WDLOW", q["v_ti_low"], "V", "end of the fast step"),
             Part("V_WDHIGH", q["v_ti_high"], "V", "watchdog threshold"))
    t_s, _ = note.cap_ti_waveform(q["cap_ti"], q, stalled=True)
    t_r, _ = note.cap_ti_waveform(q["cap_ti"], q, stalled=False)
    t_emf = t_s[3] + t_r[2]  # the EMF recovers in the second cycle where the equation's ramp turns over
    charge = "(i_wd+(i_fast-i_wd)*(v(ti)<v_wdlow))"  # a comparison is 1 or 0 (no ternary: other SPICEs read it)
    dt = min(t_s[3] / 4000, t_s[1] / 40)  # the fast step needs a step well below its 18 us
    lines = ["* CAP-TI watchdog (TDA5144, AN94002 2.1.3)", *element_lines(parts, {"C6": "C6 ti 0"}),
             "* comparator with hysteresis: q = 1 (discharge) from V_WDHIGH down to V_START",
             "VDD vdd 0 1", "SCMP vdd q ti 0 swti OFF", "RQ q 0 1e6",
             f".model swti {_hysteresis(q['v_ti_start'], q['v_ti_high'])}",
             f"VEMF emf 0 PWL(0 0 {t_emf:.9g} 0 {t_emf * 1.0001:.9g} 1)",
             f"BTI 0 ti I = (1-v(q))*(1-v(emf))*{charge} - v(q)*(1-v(emf))*i_tidis"
             f" - v(emf)*i_tidis*{_soft('v(ti)-v_start')}",
             f".ic v(ti)={q['v_ti_start']:.6g}",
             f".tran {dt:.6g} {(t_s[3] + t_r[3]) * 1.05:.9g} 0 {dt:.6g} uic",
             *_meas(f"t_low WHEN v(ti)={q['v_ti_low']:.6g} RISE=1", "t_top WHEN v(q)=0.5 RISE=1",
                    "t_wd PARAM='t_top-t_low'", "t_end WHEN v(q)=0.5 FALL=1",
                    f"t_rec WHEN v(ti)={q['v_ti_start'] + CLAMP:.6g} FALL=1 FROM={t_s[3] * 1.01:.9g}",
                    "rec_cycle PARAM='t_rec-t_end'")]
    step = (f"{SANITY}; the comparator and the 57 uA / 5 uA change act within one time step (the fast step / 40), "
            "the equation switches exactly at the level")

    def share(t: float, n: int) -> str:
        return f"{n} switching{'s' * (n > 1)}, a step each: {n * dt / t:.2%} of it"

    checks = (
        Check("wd-fast", "internal timing step, 0.2 V to 0.3 V", "s", t_s[1], "t_low", 0.005,
              step + "; the crossing of 0.3 V is read on the fast slope itself (the current changes only after it), "
              ".meas interpolating between two points of that slope; the step's own share would be 2.5 %: ±0.5 %",
              kind="sanity"),
        Check("wd-time", "watchdog time, 0.3 V to 2.2 V at 5 uA", "s", note.watchdog_time(q["cap_ti"], q["i_wd"],
              q["v_ti_low"], q["v_ti_high"]), "t_wd", 0.005, f"{step} ({share(t_s[2], 2)}): ±0.5 %", kind="sanity"),
        Check("wd-stalled-cycle", "stalled cycle: up to 2.2 V and back to 0.2 V", "s", t_s[3], "t_end", 0.005,
              f"{step} ({share(t_s[3], 3)}): ±0.5 %", kind="sanity"),
        Check("wd-recovered-cycle", "cycle with the EMF recovering half-way up the ramp", "s", t_r[3], "rec_cycle",
              0.005, f"{step} ({share(t_r[3], 3)}); its discharge ends 2 mV above 0.2 V, where the clamp begins "
              "(about 0.03 % of the cycle): ±0.5 %", kind="sanity"))
    return Circuit("cap-ti", "CAP-TI watchdog", "AN94002 2.1.3, figure 5; TDA5144 datasheet", parts,
                   "\n".join(lines) + "\n", checks, draw=lambda: draw_timer(parts, "CAP-TI"))


# ----------------------------------------------------------------------------------------------
# schematic: what each netlist holds, drawn (mathtext subscripts, see :mod:`.schematic`)

def _line(part, why: str = "") -> str:
    """One line of a label: designator, value, and what it does in parentheses."""
    return label(part) + (f" ({why})" if why else "")


def _pin(d, elm, x: float, name: str, cap, sources: list[tuple[str, str]], gate: str = ""):
    """One timer pin at (x, 4): its capacitor to ground, the IC's controlled current source(s) on its left
    (("up", label) charges the pin, ("down", label) sinks), and a gate source driving them (``gate``: its
    label; none drawn if empty). Returns the pin's point."""
    pin = (x, 4.0)
    d.add(elm.Dot(open=True).at(pin).label(name, loc="right"))
    d.add(elm.Capacitor().endpoints(pin, (x, 0)).label(label(cap), loc="bottom"))
    d.add(elm.Ground().at((x, 0)))
    for k, (way, text) in enumerate(sources):
        xs = x - 5.0 * (k + 1)
        d.add(elm.Line().endpoints((xs, 4.0), (xs + 5.0, 4.0)))
        if k:
            d.add(elm.Dot().at((xs + 5.0, 4.0)))
        src = elm.SourceControlledI().endpoints((xs, 0), (xs, 4.0)).label(text, loc="top", fontsize=9)
        d.add(src if way == "up" else src.reverse())
        d.add(elm.Ground().at((xs, 0)))
    if gate:
        xg = x - 5.0 * (len(sources) + 1)
        d.add(elm.SourceSquare().endpoints((xg, 0), (xg, 3.0)).label(gate, loc="top", fontsize=9))
        d.add(elm.Ground().at((xg, 0)))
        d.add(elm.Dot(open=True).at((xg, 3.0)).label("gate", loc="top", fontsize=9))
    return pin


def _comparator(d, elm, pin, levels: str):
    """The comparator with hysteresis that turns the source over: + from the pin, − from its reference (the
    two levels, ``levels``), fed from V_P and ground; its output q is a net the source's label names."""
    x, y = pin
    d.add(elm.Line().endpoints(pin, (x, 8.0)))
    op = schematic.amplifier(d, (x + 3.0, 8.0), anchor="in2", flip=True, positive="$V_\\mathrm{P}$", stub=1.4)
    d.add(elm.Line().endpoints((x, 8.0), op.in2))
    xr = x + 1.8
    d.add(elm.Line().endpoints(op.in1, (xr, op.in1[1])))
    d.add(elm.Battery().endpoints((xr, 1.0), (xr, op.in1[1])).label(levels, loc="bottom", fontsize=9))
    d.add(elm.Ground().at((xr, 1.0)))
    d.add(elm.Line().endpoints(op.out, (op.out[0] + 1.0, op.out[1])))
    d.add(elm.Dot(open=True).at((op.out[0] + 1.0, op.out[1])).label("q", loc="right"))
    return op


def draw_timer(parts, pin: str):
    """What the deck holds: the pin's capacitor, the IC's switched current sources (controlled sources: the
    comparator's q, or the zero-crossing gate, sets their direction), and for CAP-ST and CAP-TI the comparator
    with hysteresis between its levels; CAP-CD and CAP-DC have no comparator in the deck (their sources stop
    at the two levels, a clamp)."""
    import schemdraw.elements as elm

    by = {p.ref: p for p in parts}
    d = schematic.start(unit=2.5, fontsize=10)
    if pin == "CAP-ST":
        at = _pin(d, elm, 0.0, pin, by["C5"], [("up", _line(by["I_ST"]).replace(" ", " ±", 1)
                                                     + "\n(sinks while q)")])
        _comparator(d, elm, at, f"{_line(by['V_HIGH'], 'rising')}\n{_line(by['V_LOW'], 'falling')}")
    elif pin == "CAP-TI":
        at = _pin(d, elm, 0.0, pin, by["C6"], [("up", "\n".join((
            _line(by["I_FAST"], "charge up to $V_\\mathrm{WDLOW}$"), _line(by["I_WD"], "charge above"),
            _line(by["I_TIDIS"], "sink while q or the EMF")))) ])
        _comparator(d, elm, at, "\n".join((_line(by["V_WDHIGH"], "rising"), _line(by["V_START"], "falling"),
                                             _line(by["V_WDLOW"], "fast charge below"))))
    else:
        for k, (name, cap, gate) in enumerate(zip(pin.split(" / "), ("C3", "C4"), ("VGCD", "VGDC"))):
            at = _pin(d, elm, 20.0 * k, name, by[cap],
                      [("down", _line(by["I_DIS"], "gate low")), ("up", _line(by["I_CH"], "gate high"))],
                      gate=f"{gate}\nzero crossings")
            stops = (_line(by["V_HIGH"], f"{schematic.typeset('I_CH')} stops"),
                     _line(by["V_LOW"], f"{schematic.typeset('I_DIS')} stops"))
            d.add(elm.Label().at((at[0] + 1.2, 5.1)).label("\n".join(stops), halign="left", fontsize=9))
    return d
