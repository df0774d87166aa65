"""The speed-control loop of the TDA5144 board (AN94002 2.2): T1 (BD434) regulates V_mot, the IC's OTA
compares the divided V_mot (R3, R4 on AMPIN+) with V_in (AMPIN-) and sinks T1's base current; R1 and C8
stabilise the loop.

The note's figure 1 was lost with the OCR, so the wiring around T1 is an assumption, stated here and in
the chapter: AMP OUT drives T1's base directly; R2 (680 ohm, a part the text gives no role) pulls the
base up to the emitter so that T1 is off when the OTA sinks nothing; R1 + C8 go from AMP OUT to ground;
the jumper R7 of figure 1 is a wire; T1 is :func:`models.bd434` (assumed figures: no datasheet figure for
the BD434 is in the project's sources); the motor is a resistor R_M (10 ohm, about 1 A at 10 V; a running
motor is a back-EMF behind its winding resistance, which moves the operating point, not the divider).

Eq 10 takes AMPIN+ = AMPIN- (an OTA of infinite gain). The real OTA must sink T1's base current and R2's
current, and needs I_sink / g_m of input difference to do it, so V_mot falls short of eq 10 by (R3 + R4) /
R4 x I_sink / g_m. With I_C = V_mot (1 / R_M + 1 / (R3 + R4)) and I_sink = V_EB / R2 + I_C / h_FE, V_mot =
(R3 + R4) / R4 (V_in - I_sink / g_m) solves to (:func:`v_mot_loop`)

    V_mot = (R3 + R4) / R4 x (V_in - V_EB / (g_m R2)) / (1 + (R3 + R4) / R4 x G / (g_m h_FE)),

G = 1 / R_M + 1 / (R3 + R4). The checks put that shortfall into the equation column, with h_FE and V_EB of
the BD434 at its operating point (:func:`models.bd434_dc`: the model's Gummel-Poon equations; assumed figures):
the model and the equation take the same figures, so no verdict rests on them; the tests vary them.

At DC C8 carries no current: the DC checks do not see R1 and C8. :func:`loop_filter` is the same loop in
AC: R1 and C8 in series from AMP OUT to ground make C8's voltage follow AMP OUT through a first-order
low-pass, -45 degrees at f_z = 1 / (2 pi R1 C8). That checks the branch as wired in the loop, not the
loop's stability: the note gives no criterion for it and figure 1, which would show where R1 and C8 sit,
is lost.

The OTA (TDA5144 datasheet, June 1994): transfer gain 0.3 S, sinks at most
40 mA, cannot pull its output below its saturation voltage (1.5 V typ, 2.1 V max); its inputs draw no
current. A behavioural current source: I_sink = g_m (V_AMPIN- - V_AMPIN+), clipped to 0 .. 40 mA.
"""
from __future__ import annotations

import math

from ..sources import an94002 as note
from . import models, schematic
from .bounds import PRINTED_6, PRINTED_7, as_printed, percent, round_up
from .circuit import Check, Circuit, Part, rebuildable, with_defaults
from .runner import run
from .timers import BOARD, element_lines, label

#: OTA figures: transfer gain, largest sink current, output saturation typ and max (TDA5144 datasheet)
OTA_GM, OTA_SINK, OTA_SAT = 0.3, 40e-3, (1.5, 2.1)
R_MOTOR = 10.0  # ohm: the motor as a resistor (assumption: about 1 A at 10 V)
#: the DC sweep's step (V of V_in) and its end: 3 V, or further when the sweep must reach 1.25 times the top of the
#: control range (vmot_sat)
DC_STEP, DC_END = 0.005, 3.0
#: ngspice's DC tolerances, written into the deck: a point is accepted when each node's last Newton correction is
#: below RELTOL |v| + VNTOL (each branch current's RELTOL |i| + ABSTOL), and Newton's quadratic convergence leaves the
#: solution that close at most; ngspice's defaults (RELTOL 1e-3, VNTOL 1 uV) would allow 0.1 %
RELTOL, VNTOL, ABSTOL = 1e-7, 1e-9, 1e-12


def defaults() -> dict:
    p = note.params()
    return {**{k: p[k] for k in ("v_supply", "supply_tolerance", "v_drop_min", "r3", "r4", "v_mot_min")},
            "r1": BOARD["R1"], "r2": BOARD["R2"], "c8": BOARD["C8"], "r_motor": R_MOTOR, "gm": OTA_GM,
            "i_sink": OTA_SINK, "v_sat": OTA_SAT[0], "t1": {}}


def t1_figures(v_mot: float, q: dict) -> tuple[float, float, float]:
    """(I_C, h_FE, V_EB) of T1 at the operating point where the loop holds ``v_mot`` at the lowest supply."""
    i_c = v_mot / q["r_motor"] + v_mot / (q["r3"] + q["r4"])
    hfe, v_eb = models.bd434_dc(i_c, q["v_supply"] * (1 - q["supply_tolerance"]) - v_mot, **q["t1"])
    return i_c, hfe, v_eb


def i_sink(v_mot: float, q: dict) -> float:
    """The OTA's sink current: R2's current and T1's base current, V_EB / R2 + I_C / h_FE."""
    i_c, hfe, v_eb = t1_figures(v_mot, q)
    return v_eb / q["r2"] + i_c / hfe


def v_mot_loop(v_in: float, q: dict) -> float:
    """V_mot the loop holds for ``v_in``: eq 10 less the OTA's input difference (module text), h_FE and V_EB
    of T1 at its operating point (fixed-point iteration; the shortfall is a few per cent)."""
    k = 1 / note.v_in_for(1.0, q["r3"], q["r4"])  # eq 10's gain, (R3 + R4) / R4
    g = 1 / q["r_motor"] + 1 / (q["r3"] + q["r4"])
    v = 0.9 * k * v_in  # below eq 10's figure: T1 starts with room across it (the fixed point is the same)
    for _ in range(100):
        _, hfe, v_eb = t1_figures(v, q)
        v, last = k * (v_in - v_eb / (q["gm"] * q["r2"])) / (1 + k * g / (q["gm"] * hfe)), v
        if v == last:  # the fixed point, to the last bit (about 8 rounds)
            break
    return v


def shortfall(v_in: float, q: dict) -> dict:
    """The OTA's sink current and input difference at ``v_in``, and V_mot's shortfall from eq 10 (V)."""
    v = v_mot_loop(v_in, q)
    k = 1 / note.v_in_for(1.0, q["r3"], q["r4"])
    return {"v_mot": v, "i_sink": i_sink(v, q), "v_diff": i_sink(v, q) / q["gm"], "dv_mot": k * v_in - v}


def v_in_loop(v_mot: float, q: dict) -> float:
    """V_in that gives ``v_mot``: eq 10 plus the OTA's input difference at that operating point."""
    return note.v_in_for(v_mot, q["r3"], q["r4"]) + i_sink(v_mot, q) / q["gm"]


def as_deck(q: dict) -> dict:
    """The parameters as the deck writes them (6 significant digits; the supply so that its lowest value, the part
    V_S, is a 6-digit figure): what the equations take, so that they see the deck's parts, not a rounding of them."""
    low = 1 - q["supply_tolerance"]
    out = {**q, **{k: as_printed(q[k]) for k in ("r3", "r4", "r2", "r1", "c8", "r_motor", "gm", "i_sink", "v_sat")}}
    return {**out, "v_supply": as_printed(q["v_supply"] * low) / low}


def _parts(q: dict) -> tuple[Part, ...]:
    v_s = q["v_supply"] * (1 - q["supply_tolerance"])
    return (Part("V_S", v_s, "V", "the lowest supply, 12 V - 10 %"), Part("T1", "BD434", "", "series regulator"),
            Part("R3", q["r3"], "ohm"), Part("R4", q["r4"], "ohm"), Part("R2", q["r2"], "ohm", "T1 base pull-up (assumed role)"),
            Part("R1", q["r1"], "ohm"), Part("C8", q["c8"], "F"), Part("R_M", q["r_motor"], "ohm", "motor (assumed)"),
            Part("GM", q["gm"], "S", "OTA transfer gain (TDA5144)"), Part("I_SINK", q["i_sink"], "A", "OTA sink limit"),
            Part("V_SAT", q["v_sat"], "V", "OTA output saturation, typ"))


NODES = {"V_S": "VS vs 0", "T1": "QT1 vmot base vs", "R3": "R3 vmot inp", "R4": "R4 inp 0", "R2": "R2 vs base",
         "R1": "R1 base n1", "C8": "C8 n1 0", "R_M": "RM vmot 0"}


def sweep_end(q: dict) -> float:
    """Where the DC sweep of V_in ends: DC_END, or past 1.25 times the top of the control range (vmot_sat reads
    there), on the DC_STEP grid."""
    _, hi_in = note.v_in_range({**note.params(), **q})
    return max(DC_END, DC_STEP * math.ceil(1.3 * hi_in / DC_STEP))


def netlist(q: dict, parts, extra: tuple = (), analysis: str | None = None) -> str:
    """The loop's deck: the DC sweep of V_in (or ``analysis``) with ngspice's tolerances set (RELTOL ...)."""
    lines = ["* speed control: T1, the OTA, R3/R4, R1/C8 (AN94002 2.2)", *models.bd434(**q["t1"]),
             *element_lines(parts, NODES), "VIN inm 0 0",
             "* the OTA: sinks g_m (AMPIN- - AMPIN+) from AMP OUT, 0 .. I_SINK, down to V_SAT",
             "BOTA base 0 I = min(max(gm*(v(inm)-v(inp)),0),i_sink)*min(max((v(base)-v_sat)/0.05,0),1)",
             f".options reltol={RELTOL:g} vntol={VNTOL:g} abstol={ABSTOL:g}",
             analysis or f".dc VIN 0 {sweep_end(q):.6g} {DC_STEP:g}", *extra]
    return "\n".join(lines) + "\n"


def curvature(v_in: float, q: dict) -> tuple[float, float]:
    """(|V_mot''| at most, V_mot') of :func:`v_mot_loop` about ``v_in``: the second differences over DC_STEP centred
    on the grid step's ends and middle, the largest kept, and the central first difference."""
    f = [v_mot_loop(v_in + j * DC_STEP, q) for j in (-2, -1, 0, 1, 2)]
    second = max(abs(f[j - 1] - 2 * f[j] + f[j + 1]) for j in (1, 2, 3)) / DC_STEP ** 2
    return second, (f[3] - f[1]) / (2 * DC_STEP)


def dc_bounds(v_in: float, q: dict) -> dict:
    """What the method leaves in the DC rows at ``v_in``, relative, by row (module text of :func:`circuit`): the
    sweep's linear interpolation (DC_STEP^2 / 8 of the curvature of V_mot(V_in), :func:`curvature`), the solver's
    convergence (RELTOL, VNTOL) and the digits ngspice prints."""
    sf = shortfall(v_in, q)
    v, k = sf["v_mot"], 1 / note.v_in_for(1.0, q["r3"], q["r4"])
    bend, slope = curvature(v_in, q)
    chord = DC_STEP ** 2 / 8 * bend  # V of V_mot: the chord's largest miss over one step
    solve = RELTOL * v + VNTOL  # V: a node's converged error at most
    return {"v_mot": (chord + solve) / v + PRINTED_7,
            "v_in": (chord + solve) / slope / v_in + PRINTED_6,  # V_in where V_mot crosses a level
            "v_diff": (chord / k + RELTOL * v_in + VNTOL) / sf["v_diff"] + PRINTED_7,  # AMPIN- is the source: exact
            "shortfall": (chord + solve) / sf["dv_mot"] + PRINTED_6,
            "chord": chord / v, "solve": solve / v}


@rebuildable
def circuit(p: dict | None = None) -> Circuit:
    """The loop at the lowest supply, V_in swept 0 to 3 V (further if the control range needs it): V_mot at the two
    ends of the control range.

    The DC rows' tolerances are the method's (:func:`dc_bounds`): the 5 mV sweep interpolated linearly, off by at
    most DC_STEP^2 / 8 times V_mot's curvature in V_in (computed from :func:`v_mot_loop`, 1e-7 of V_mot or less),
    the solver's RELTOL and VNTOL, and the 6 or 7 digits ngspice prints. Where the OTA would have to sink more than
    its I_SINK to hold the top of the range (a heavy motor at a high supply: T1's base current I_C / h_FE), the loop
    cannot get there: SPICE falls short, the rows say so and differ (a finding, not an error), and V_in for the
    top reads the sweep's end, where a probe (Breach) forces the crossing the loop never makes."""
    q = as_deck(with_defaults(defaults(), p))
    parts = _parts(q)
    lo_in, hi_in = note.v_in_range({**note.params(), **q})
    v_top = note.v_mot_max(q["v_supply"], q["supply_tolerance"], q["v_drop_min"])
    end = sweep_end(q)
    meas = [f".meas dc vmot_top FIND v(vmot) AT={hi_in:.9g}", f".meas dc vmot_low FIND v(vmot) AT={lo_in:.9g}",
            f".meas dc vin_top WHEN v(reach)={v_top:.9g} RISE=1",
            f".meas dc vce_top FIND par('v(vs)-v(vmot)') AT={hi_in:.9g}",
            f".meas dc vmot_sat FIND v(vmot) AT={1.25 * hi_in:.9g}",
            f".meas dc vdiff_top FIND par('v(inm)-v(inp)') AT={hi_in:.9g}"]
    top, low = shortfall(hi_in, q), shortfall(lo_in, q)
    k10 = 1 / note.v_in_for(1.0, q["r3"], q["r4"])  # eq 10: V_mot = (R3 + R4) / R4 x V_in
    meas += [f".meas dc short_top PARAM='{k10 * hi_in:.12g}-vmot_top'",
             f".meas dc short_low PARAM='{k10 * lo_in:.12g}-vmot_low'",
             "* a probe, not a part: V_mot, forced up over the sweep's last step, so that vin_top reads the sweep's "
             "end where the loop never brings V_mot to the top",
             f"Breach reach 0 V=v(vmot)+1e4*max(v(inm)-{end - DC_STEP:.9g},0)"]
    bt, bl = dc_bounds(hi_in, q), dc_bounds(lo_in, q)

    def left(b: dict, key: str, v_mot: float) -> str:
        """The method's share, and where the OTA cannot sink what holding ``v_mot`` takes, that finding."""
        need = i_sink(v_mot, q)
        short = (f" Here, though, the OTA would have to sink {need * 1e3:.1f} mA to hold {v_mot:.3g} V, more than its "
                 f"{q['i_sink'] * 1e3:g} mA (T1's base current at {t1_figures(v_mot, q)[0]:.2g} A): the loop cannot, "
                 "SPICE falls short and the row differs, a limit of the circuit, not of the method"
                 if need > q["i_sink"] else "")
        return (f"Left, the method's own: the {DC_STEP * 1e3:g} mV sweep interpolated linearly (V_mot's curvature in "
                f"V_in, from the loop's equations, misses {b['chord']:.1e} of V_mot over a step), ngspice's converged "
                f"solution (RELTOL {RELTOL:g}, VNTOL {VNTOL:g} V: {b['solve']:.1e}) and its printed digits: "
                f"{percent(round_up(b[key]))}.{short}")

    gain = ("the equation is eq 10 less the OTA's input difference I_sink / g_m times (R3 + R4) / R4 "
            f"({top['dv_mot']:.3g} V at the top, {low['dv_mot'] * 1e3:.3g} mV at the low end), with T1's h_FE and V_EB "
            "at its operating point from the model's own Gummel-Poon equations (base charge, Early effect, high "
            "injection, RB, RE, RC: models.bd434_dc), so the verdict does not rest on the assumed BD434 figures (the "
            "tests vary them). ")
    vin_why = ("eq 10 plus I_sink / g_m at that operating point (the same terms as the V_mot rows); if the loop never "
               f"gets V_mot there, SPICE reads the sweep's end, {end:g} V. ")
    checks = (
        Check("speed-vmot-top", "V_mot at the top of the V_in range (lowest supply)", "V", top["v_mot"], "vmot_top",
              round_up(bt["v_mot"]), gain + left(bt, "v_mot", top["v_mot"])),
        Check("speed-vmot-low", "V_mot at the lowest running V_in", "V", low["v_mot"], "vmot_low",
              round_up(bl["v_mot"]), gain + left(bl, "v_mot", low["v_mot"])),
        Check("speed-vin-top", "V_in that gives the highest controllable V_mot (eq 10 plus the OTA's difference)",
              "V", v_in_loop(v_top, q), "vin_top", round_up(dc_bounds(v_in_loop(v_top, q), q)["v_in"]),
              vin_why + left(dc_bounds(v_in_loop(v_top, q), q), "v_in", v_top)),
        Check("speed-vdiff-top", "OTA input difference at the top of the V_in range (I_sink / g_m)", "V",
              top["v_diff"], "vdiff_top", round_up(bt["v_diff"]),
              "I_sink = V_EB / R2 + I_C / h_FE, h_FE and V_EB by the model's Gummel-Poon equations at T1's operating "
              "point; AMPIN+ carries the solver's error, AMPIN- is the source. " + left(bt, "v_diff", top["v_mot"])),
        *(Check(f"speed-eq10-{tag}", f"eq 10 as printed ({eq10:.4g} V) minus SPICE's V_mot, {where}: the OTA's "
                "shortfall", "V", sf["dv_mot"], f"short_{tag}", round_up(b["shortfall"]),
                f"the V_mot row above restated as the shortfall from eq 10 as printed (an OTA of infinite gain), "
                f"{sf['dv_mot'] / eq10:.1%} of V_mot: the same residual, rescaled, and the same faults, so it adds no "
                "verdict of its own; it shows how far eq 10 alone is off. " + left(b, "shortfall", sf["v_mot"]),
                kind="sanity")
          for tag, where, sf, eq10, b in (("top", "top of the V_in range", top, k10 * hi_in, bt),
                                          ("low", "lowest running V_in", low, k10 * lo_in, bl))))
    return Circuit("speed", "Speed-control loop", "AN94002 2.2, figure 1 (wiring assumed: the figure is lost)", parts,
                   netlist(q, parts, tuple(meas)), checks, draw=lambda: draw(parts))


@rebuildable
def loop_filter(p: dict | None = None) -> Circuit:
    """The same loop in AC about its top operating point (V_in = the top of its range, AC 1 V on V_in): C8's
    voltage over AMP OUT's, a first-order low-pass whose -45 degree frequency is 1 / (2 pi R1 C8)."""
    q = with_defaults(defaults(), p)
    parts = _parts(q)
    _, hi_in = note.v_in_range({**note.params(), **q})
    f_z = 1 / (2 * math.pi * q["r1"] * q["c8"])
    body = netlist(q, parts, analysis=".ac dec 200 10 10e6").replace("VIN inm 0 0", f"VIN inm 0 DC {hi_in:.6g} AC 1")
    deck = body + "\n".join([
        "* C8's voltage over AMP OUT's: a ratio of two node voltages, so measured in a .control block",
        ".control", "run", "let h = v(n1)/v(base)", "meas ac f_rc WHEN vp(h)=-0.785398163",
        f"meas ac g_10 FIND vm(h) AT={10 * f_z:.6g}", "quit 0", ".endc"]) + "\n"
    grid = ("the AC sweep's 200 points a decade (1.2 % apart, interpolated linearly: the phase's curvature over a "
            "step is below 0.01 %): ±0.05 %")
    checks = (
        Check("speed-rc-corner", "frequency where C8 lags AMP OUT by 45 degrees, 1 / (2 pi R1 C8)", "Hz", f_z,
              "f_rc", 5e-4, "by construction: R1 in series with C8 is the whole path from AMP OUT to C8 in the "
              "netlist, so the ratio of their voltages is that RC divider's whatever T1, the OTA and the loop do (it "
              "would agree with C8 moved to V_s); it checks the branch as the deck wires it, not the loop's "
              f"stability, which the loop-gain analysis (handbook.spice.speed_loop) takes up; {grid}", kind="sanity"),
        Check("speed-rc-rolloff", "C8's voltage over AMP OUT's a decade above, 1 / sqrt(1 + 100)", "1",
              1 / math.sqrt(101), "g_10", 5e-4, f"by construction: a first-order low-pass, the same branch; {grid}",
              kind="sanity"))
    return Circuit("speed-loop-filter", "Speed-control loop, R1/C8 in AC", "AN94002 2.2 (R1, C8: 'necessary to "
                   "obtain a good stability'); wiring assumed", parts, deck, checks, draw=lambda: draw(parts))


def sweep(p: dict | None = None, points: int = 31) -> dict:
    """V_mot and the OTA's input difference against V_in from the simulation, for the chapter's plot."""
    q = with_defaults(defaults(), p)
    parts = _parts(q)
    v_in = [2.99 * k / (points - 1) for k in range(points)]
    meas = [f".meas dc m{k} FIND v(vmot) AT={v:.6g}" for k, v in enumerate(v_in)]
    out = run(netlist(q, parts, tuple(meas)))
    return {"v_in": v_in, "v_mot": [out[f"m{k}"] for k in range(points)]}


def draw(parts, wiring: str = "book"):
    """V_S, T1 from V_S to V_mot, R3/R4 to AMPIN+, the OTA (a current output: it sinks from AMP OUT) with V_in on
    AMPIN-, fed from V_P and ground, R1 + C8, the motor R_M; R2 from V_S to T1's base, which is AMP OUT (``wiring``
    "book", this module's reading), or R2 in series from AMP OUT to T1's base ("series", :mod:`.speed_loop`'s
    alternative)."""
    import schemdraw.elements as elm

    by = {p.ref: label(p) for p in parts}
    d = schematic.start(unit=2.5, fontsize=10)
    series = wiring == "series"
    top, base_x, out_y, xd = 11.0, 6.0, 3.0, 15.0 if series else 13.0  # R2 in series takes 2 units more
    d.add(elm.SourceV().endpoints((-2, 0), (-2, top)).label(by["V_S"], loc="top"))
    d.add(elm.Ground().at((-2, 0)))
    t1_x = base_x + (3.5 if series else 1.5)
    t1 = d.add(elm.BjtPnp(circle=True).theta(0).anchor("base").at((t1_x, 8.0)).label(by["T1"], loc="right"))
    d.add(elm.Line().endpoints((-2, top), (t1.emitter[0], top)))
    d.add(elm.Line().endpoints(t1.emitter, (t1.emitter[0], top)))
    if series:  # AMP OUT, R2, T1's base
        d.add(elm.Resistor().endpoints((base_x, 8.0), t1.base).label(by["R2"], loc="top"))
        dots = ((base_x, 5.5),)
    else:  # R2 pulls the base, which is AMP OUT, up to V_S
        d.add(elm.Resistor().endpoints((base_x, top), (base_x, 8.0)).label(by["R2"], loc="top"))
        d.add(elm.Line().endpoints((base_x, 8.0), t1.base))
        dots = ((base_x, top), (base_x, 8.0), (base_x, 5.5))
    for pt in dots:
        d.add(elm.Dot().at(pt))
    vmot = (t1.collector[0], 6.0)
    d.add(elm.Line().endpoints(t1.collector, vmot))
    d.add(elm.Line().endpoints(vmot, (xd + 3.5, 6.0)))
    d.add(elm.Dot().at(vmot).label("$V_\\mathrm{mot}$", loc="bottom"))
    d.add(elm.Resistor().endpoints((xd + 3.5, 6.0), (xd + 3.5, 0)).label(by["R_M"], loc="bottom"))
    inp = (xd, out_y + 0.625)
    d.add(elm.Resistor().endpoints((xd, 6.0), inp).label(by["R3"], loc="bottom"))
    d.add(elm.Resistor().endpoints(inp, (xd, 0)).label(by["R4"], loc="bottom"))
    for x in (xd, xd + 3.5):
        d.add(elm.Dot().at((x, 6.0)) if x == xd else elm.Ground().at((x, 0)))
    d.add(elm.Ground().at((xd, 0)))
    d.add(elm.Dot().at(inp))
    d.add(elm.Line().endpoints(inp, (xd - 1.5, inp[1])))
    # the OTA points left: AMPIN+ from the divider above, AMPIN- (V_in) below, AMP OUT into T1's base
    ota = schematic.amplifier(d, (xd - 1.5, inp[1]), theta=180, anchor="in2", positive="$V_\\mathrm{P}$",
                              text="OTA\n" + "\n".join(by[k] for k in ("GM", "I_SINK", "V_SAT")),
                              text_at=(base_x + 0.6, 0.9), fontsize=9)
    d.add(elm.Label().at((inp[0] - 0.6, inp[1] + 0.35)).label("AMPIN+", fontsize=8))
    d.add(elm.Line().endpoints(ota.in1, (ota.in1[0], ota.in1[1] - 1.0)))
    d.add(elm.Dot(open=True).at((ota.in1[0], ota.in1[1] - 1.0)).label("AMPIN− = $V_\\mathrm{in}$", loc="bottom",
                                                                      fontsize=8))
    d.add(elm.Line().endpoints(ota.out, (base_x, out_y)))
    d.add(elm.Line().endpoints((base_x, out_y), (base_x, 8.0)).label("pin AMP OUT", loc="bottom", fontsize=8))
    d.add(elm.Line().endpoints((base_x, 5.5), (3.0, 5.5)))
    d.add(elm.Resistor().endpoints((3.0, 5.5), (3.0, 3.0)).label(by["R1"], loc="top"))
    d.add(elm.Capacitor().endpoints((3.0, 3.0), (3.0, 0.5)).label(by["C8"], loc="top"))
    d.add(elm.Ground().at((3.0, 0.5)))
    return d
