"""What the limiters' equations leave out and the decks keep, computed: each check's expected difference.

A check's tolerance is then the numerical method's alone (:mod:`.numerics`: the ramp's step, .meas interpolation,
the solver's tolerance), and a change in the equation as small as the tolerance shows (the mutation test). Each
term is physics of the circuit, written here from the parts' figures, not fitted to the simulation, and each is
an amount added to the equation's figure (never a prediction that replaces it: a fault put into the equation
still shows):

* **lag**: the LM358 model has one pole (A0 and GBW of :data:`models.LM358`). While the motor current ramps,
  its differential input falls at ``k`` V/s through the offset; the output, held at its high swing until the
  pole's drive A0 v_d comes down to that swing (117 uV of input before the crossing), then follows
  x' = w (A0 v_d - x), w = 2 pi GBW / A0, and crosses mid-swing ``tau`` after the crossing (:class:`OnePole`, the
  exact solution). The sense voltage has risen by dV_cs/dt x tau by then.
* **bias**: the LM358's 500 nA out of each input, through the dividers' source resistances (the node
  equation's terms, :func:`.decks.trip_voltage`).
* **zener**: D1 is specified at 5 mA; the model's breakdown (:func:`models.bzx79_c8v2`: IBV = 5 mA at BV, RS
  in series) puts V_Z(I) = V_Z(5 mA) + V_T ln(I / 5 mA) + RS (I - 5 mA), 15 ohm of slope at 5 mA; I_Z is R14's
  current less what the two dividers and the LM358's bias currents feed into D1's anode, each at the voltage D1
  then has (:func:`zener_current`).
* **R12 in R7**: R7 carries the level-shift divider's current too, so the motor current at a given V_cs is
  lower by it, and at no motor current V_cs is R7 times it, not 0.
* **change-over**: at the least-headroom corner the model ignores its inputs while V+ is within 2 V of the supply
  and blends them in over the last 1 mV (:func:`back_terms`).
"""
from __future__ import annotations

import math

from ...sources import an94002
from .. import models

W = 2 * math.pi * models.LM358["gbw"] / models.LM358["a0"]  # rad/s: the LM358 model's pole
A0 = models.LM358["a0"]


class OnePole:
    """The LM358 model's output once its clamp lets go at ``t0`` from ``x0``: x' = w (A0 u(t) - x), the drive u (V
    of input: v_d less the offset, or the change-over's blend) a polynomial of degree <= 2 in each piece, solved
    exactly: x = A0 (u - u'/w + u''/w^2) + C e^(-w (t - t_from)), C from x's continuity. ``pieces``: [(t_from,
    (c0, c1, c2))], u = c0 + c1 s + c2 s^2 with s = t - t_from, the first t_from = ``t0``, ascending."""

    def __init__(self, t0: float, x0: float, pieces: list[tuple[float, tuple]]):
        if not pieces or pieces[0][0] != t0:
            raise ValueError("the first piece starts at the release")
        self.t0, self.pieces, x_s = t0, [], x0
        for k, (ts, c) in enumerate(pieces):
            te = pieces[k + 1][0] if k + 1 < len(pieces) else math.inf
            cst = x_s - self._xp(c, 0.0)
            self.pieces.append((ts, te, c, cst))
            if te < math.inf:
                x_s = self._xp(c, te - ts) + cst * math.exp(-W * (te - ts))

    @staticmethod
    def _u(c, s):
        return c[0] + c[1] * s + c[2] * s * s, c[1] + 2 * c[2] * s, 2 * c[2]

    @classmethod
    def _xp(cls, c, s):
        u, du, ddu = cls._u(c, s)
        return A0 * (u - du / W + ddu / W ** 2)

    def _at(self, t):
        for ts, te, c, cst in self.pieces:
            if t < te:
                return c, cst, t - ts
        raise ValueError(t)

    def x(self, t: float) -> float:
        c, cst, s = self._at(t)
        return self._xp(c, s) + cst * math.exp(-W * s)

    def dx(self, t: float) -> float:
        c, cst, s = self._at(t)
        _, du, ddu = self._u(c, s)
        return A0 * (du - ddu / W) - W * cst * math.exp(-W * s)

    def ddx(self, t: float) -> float:
        c, cst, s = self._at(t)
        return A0 * self._u(c, s)[2] + W * W * cst * math.exp(-W * s)

    def kinks(self) -> list[tuple[float, float]]:
        """[(t, |jump of x''|)]: the release (x'' from 0, the clamp holding x) and each change of piece (x' is
        continuous, x'' = w (A0 u' - x') jumps with u')."""
        out = [(self.t0, abs(self.ddx(self.t0)))]
        for (ts_prev, _, c_prev, _), (ts, _, c, _) in zip(self.pieces, self.pieces[1:]):
            out.append((ts, abs(W * A0 * (c[1] - self._u(c_prev, ts - ts_prev)[1]))))
        return out

    def time_at(self, level: float) -> float:
        """When x reaches ``level`` (x moves towards it monotonically from the release)."""
        x0 = self.x(self.t0)
        up = level > x0

        def past(t):
            return self.x(t) >= level if up else self.x(t) <= level

        lo, step = self.t0, 1e-6
        while not past(lo + step):
            step *= 2
            if step > 1e3:
                raise ValueError(f"the output never reaches {level:.3g} V from {x0:.3g} V")
        hi = lo + step
        for _ in range(200):
            mid = (lo + hi) / 2
            lo, hi = (lo, mid) if past(mid) else (mid, hi)
            if hi - lo <= 1e-15 * max(1.0, abs(hi)):
                break
        return (lo + hi) / 2

    @classmethod
    def fall(cls, v_start: float, k: float) -> OnePole:
        """The trip: the input falling (``k`` < 0, V/s) through the offset at t = 0, the output held at its high
        clamp ``v_start`` until A0 k t comes down to it, at t0 = v_start / (A0 k) (or rising, ``k`` > 0, from the
        low clamp, let go just after the crossing)."""
        t0 = v_start / (A0 * k)
        return cls(t0, v_start, [(t0, (k * t0, k, 0.0))])


def lag(v_start: float, v_mid: float, k: float) -> float:
    """Seconds from the differential input crossing the offset to the output reaching ``v_mid``, the input
    moving at ``k`` V/s (negative: falling) and the output held at its clamp ``v_start`` until the pole's drive
    reaches it (:meth:`OnePole.fall`)."""
    return OnePole.fall(v_start, k).time_at(v_mid)


def zener_shift(i_z: float) -> float:
    """How far the BZX79 model's V_Z at ``i_z`` lies from its figure at the 5 mA test current (V)."""
    v_t = models.K_Q * models.T25
    rs = models.BZX79_C8V2_RZ - v_t / models.BZX79_C8V2_IZT
    return v_t * math.log(i_z / models.BZX79_C8V2_IZT) + rs * (i_z - models.BZX79_C8V2_IZT)


def divider_currents(p: dict, v_cs: float) -> dict:
    """At the trip (V+ = V-): the reference divider's current (R9 + R10 + R11, across D1), the level shift's
    (R12 + R13, across D1 less V_cs), R14's, and D1's: R14's less the two (A)."""
    v_z = p["zener_voltage"]
    i_ref = v_z / (p["r9"] + p["r10"] + p["r11"])
    i_shift = (v_z - v_cs) / (p["r12"] + p["r13"])
    i_r14 = (p["v_supply"] - v_z) / p["r14"]
    return {"ref": i_ref, "shift": i_shift, "r14": i_r14, "zener": i_r14 - i_ref - i_shift}


def zener_current(p: dict, v_cs: float) -> tuple[float, float]:
    """D1's current and its voltage's shift from the 5 mA figure, (A, V), at sense voltage ``v_cs``, each from the
    other: D1 carries R14's current less the dividers' (:func:`divider_currents`) and less the bias currents the
    LM358's inputs push towards its anode (I_+ R12 / (R12 + R13), I_- (R9 + R10) / (R9 + R10 + R11)), and those
    currents are taken at D1's own voltage V_Z + dV_Z(I) (:func:`zener_shift`), not at its 5 mA figure: the shift
    lowers R14's current and raises the dividers', which pulls the shift back by some per cent of itself."""
    r_ref, r_shift = p["r9"] + p["r10"] + p["r11"], p["r12"] + p["r13"]
    into_anode = (p.get("ibp", 0.0) * p["r12"] / r_shift + p.get("ibn", 0.0) * (p["r9"] + p["r10"]) / r_ref)

    def excess(i):  # the current the network leaves for D1 at the voltage D1 has at i, less i
        v_z = p["zener_voltage"] + zener_shift(i)
        return (p["v_supply"] - v_z) / p["r14"] - v_z / r_ref - (v_z - v_cs) / r_shift - into_anode - i

    lo, hi = 1e-9, p["v_supply"] / p["r14"]
    if excess(hi) > 0 or excess(lo) < 0:
        raise ValueError(f"D1 carries no current in the op-amp limiter here (V_s {p['v_supply']:.3g} V, R14 "
                         f"{p['r14']:.3g} ohm)")
    for _ in range(100):
        mid = (lo + hi) / 2
        lo, hi = (mid, hi) if excess(mid) > 0 else (lo, mid)
    i = (lo + hi) / 2
    return i, zener_shift(i)


def bias_shift(p: dict) -> float:
    """How far the LM358's bias currents move AN94002 figure 3's trip V_cs (V): the node equation's terms
    I_+ R12 - I_- ((R9 + R10) || R11) / A (handbook.design.limiter.model), what eq 13 leaves out."""
    a = an94002.factor_a(p["r12"], p["r13"])
    r_m = (p["r9"] + p["r10"]) * p["r11"] / (p["r9"] + p["r10"] + p["r11"])
    return p["ibp"] * p["r12"] - p["ibn"] * r_m / a


def _shift_moved(p: dict, dvz: float) -> float:
    """How far eq 11's level shift moves when D1's voltage moves by ``dvz`` (V)."""
    return (an94002.level_shift(p["zener_voltage"] + dvz, p["r12"], p["r13"])
            - an94002.level_shift(p["zener_voltage"], p["r12"], p["r13"]))


def opamp_terms(p: dict, v_cs: float, ramp: float, v_mid: float, with_bias: bool) -> dict:
    """Relative terms (fractions of ``v_cs``, the equation's trip) for AN94002 figure 3 ramped from 0 to
    ``p["i_max"]`` in ``ramp`` seconds: lag, bias (when the equation has none), zener, and r12 (the motor
    current's share only: add it to an "i_trip" row, not a "vcs" row)."""
    a = an94002.factor_a(p["r12"], p["r13"])
    slope = p["r7"] * p["i_max"] / ramp  # dV_cs/dt
    response = OnePole.fall(p["v_supply"] - models.LM358["v_oh_drop"], -a * slope)
    tau = response.time_at(v_mid)
    i_z, dvz = zener_current(p, v_cs)
    network = (p["r9"], p["r10"], p["r11"], p["r12"], p["r13"])
    dvcs_dvz = (an94002.v_cs_trip(p["zener_voltage"] + 1e-3, *network, p["vos"])
                - an94002.v_cs_trip(p["zener_voltage"], *network, p["vos"])) / 1e-3
    bias = bias_shift(p) if with_bias else 0.0
    return {"lag": slope * tau / v_cs, "bias": bias / v_cs, "zener": dvcs_dvz * dvz / v_cs,
            "r12": -r12_current(p, v_cs, dvz) * p["r7"] / v_cs, "tau": tau, "dvz": dvz, "i_zener": i_z,
            "response": response, "slope": slope, "a": a}


def r12_current(p: dict, v_cs: float, dvz: float) -> float:
    """The level shift's current out of the sense point through R12 (A), which R7 carries besides the motor's:
    D1's voltage less V_cs over R12 + R13, less the share of the LM358's bias current out of V+ that returns
    through R12 (I_+ R13 / (R12 + R13))."""
    r_shift = p["r12"] + p["r13"]
    return (p["zener_voltage"] + dvz - v_cs) / r_shift - p.get("ibp", 0.0) * p["r13"] / r_shift


def supply_terms(p: dict, v_supply: float, v_cs: float, ramp: float, v_mid: float) -> dict:
    """The same for AN93008 figure 3 (no zener): lag and bias, fractions of ``v_cs``."""
    from ...sources import an93008

    a = an93008.factor_a(p["r8"], p["r9"])
    slope = p["r7"] * p["i_max"] / ramp
    response = OnePole.fall(v_supply - models.LM358["v_oh_drop"], -a * slope)
    tau = response.time_at(v_mid)
    r_p, r_m = p["r8"] * p["r9"] / (p["r8"] + p["r9"]), p["r10"] * p["r11"] / (p["r10"] + p["r11"])
    # the bias currents flow out of the pins: V+ rises by I_bp (R8 || R9), V- by I_bn (R10 || R11), so the
    # trip's V_cs moves by (I_bp R_p - I_bn R_m) / A
    bias = (p["ibp"] * r_p - p["ibn"] * r_m) / a
    return {"lag": slope * tau / v_cs, "bias": bias / v_cs, "tau": tau, "response": response, "slope": slope, "a": a}


def shift_terms(p: dict, shift: float, with_bias: bool) -> dict:
    """At no motor current, fractions of ``shift`` (V_s - V+, eq 11): the bias current out of V+ through
    R12 || R13 (when the equation has none) and the zener's 15 ohm at the current it carries there."""
    i_z, dvz = zener_current(p, 0.0)
    r_p = p["r12"] * p["r13"] / (p["r12"] + p["r13"])
    # with no motor current R7 still carries R12's current: V_cs = R7 I_12, of which V+ follows A
    v_r7 = p["r7"] * r12_current(p, 0.0, dvz) * an94002.factor_a(p["r12"], p["r13"])
    return {"bias": (-p["ibp"] * r_p / shift) if with_bias else 0.0, "zener": _shift_moved(p, dvz) / shift,
            "r7": v_r7 / shift, "dvz": dvz, "i_zener": i_z}


def back_terms(p: dict, v_back: float, ramp: float, v_mid: float) -> dict:
    """Where the output of AN94002 figure 3 at its least-headroom corner comes back up (V+ back 2 V below the
    supply as the current rises), against ``v_back``, the equation's V_cs for 2 V of headroom (eq 11 with the
    bias). Fractions of ``|v_back|``:

    * zener: D1's 15 ohm at its current there lifts the headroom by dV, so 2 V comes dV / A earlier;
    * change_over: the model (:func:`models.lm358`) blends its inputs in over the last 1 mV below the limit, its
      drive u = ok (v_d + 10 mV) - 10 mV with ok rising from 0 to 1 over that 1 mV of headroom (v_d: V+ - V- less
      the offset, from the two dividers across D1 at its voltage there, with the bias currents); u turns positive
      before 2 V is reached;
    * lag: the output, held at its low clamp until A0 u reaches it, then rises as x' = w (A0 u - x) with u
      quadratic in time while ok rises and linear after (:class:`OnePole`, exact) to mid-swing;
    * r12: the motor current there is V_cs / R7 less R12's current.

    "held" is False when the output is not held low at no motor current (V+ already in range: D1's lift or the
    network's own headroom): then the deck reads 0 A (its probe), and "reading" is 0. "never": the output, held low,
    would not come back before the trip (the drive peaks at 2 V of headroom): no reading ("reading" NaN; the deck's
    measurement then fails too, unless ``v_back`` is an equation's wrong figure)."""
    m, a = models.LM358, an94002.factor_a(p["r12"], p["r13"])
    slope, r_ref = p["r7"] * p["i_max"] / ramp, p["r9"] + p["r10"] + p["r11"]
    v_h2 = v_back
    for _ in range(4):  # D1's current at the V_cs where the headroom is 2 V, which its lift moves
        i_z, dvz = zener_current(p, v_h2)
        v_h2 = v_back - _shift_moved(p, dvz) / a  # V_cs where V+ is 2 V below the supply
    head_m = ((p["zener_voltage"] + dvz) * (p["r9"] + p["r10"]) / r_ref
              - p["ibn"] * (p["r9"] + p["r10"]) * p["r11"] / r_ref)
    if head_m < m["cm_headroom"] + 1e-3:
        raise ValueError(f"V- is {head_m:.4g} V below the supply, inside the LM358's {m['cm_headroom']:g} V (and its "
                         "1 mV change-over): the output never comes back, whatever the motor current")
    d_head = _shift_moved(p, dvz)
    # the drive at 2 V of headroom (ok = 1): V+ - V- less the offset, that is V- 's headroom less V+'s (2 V there)
    d_h = head_m - m["cm_headroom"] - p["vos"]
    # as V_cs rises D1 carries the current R12 no longer draws: V_Z rises by g per volt, which V+ and V- follow
    g = (zener_current(p, v_h2 + 1e-4)[1] - zener_current(p, v_h2 - 1e-4)[1]) / 2e-4
    b = p["r11"] / r_ref
    s_head, s_d = a + (1 - a) * g, -a + (a - b) * g  # d(headroom)/dV_cs, d(v_d)/dV_cs
    span = 1e-3 / (s_head * slope)  # s: the change-over's 1 mV of headroom, while V_cs ramps
    beta, stuck = 1 / span, 0.01
    quad = (d_h, beta * (d_h + stuck) + s_d * slope, beta * s_d * slope)  # u(t), t from V_h2, over -span..0

    def u(t):
        if t >= 0:
            return d_h + s_d * slope * t
        if t <= -span:
            return -stuck
        return quad[0] + quad[1] * t + quad[2] * t * t

    v_cs0 = p["r7"] * r12_current(p, 0.0, zener_current(p, 0.0)[1])  # V_cs at no motor current
    t_start = (v_cs0 - v_h2) / slope
    release = m["v_ol"] / A0  # the drive at which the output leaves its low clamp
    terms = {"zener": -d_head / a / abs(v_back), "dvz": dvz, "i_zener": i_z, "head_m": head_m, "slope": slope,
             "a": a, "v_h2": v_h2}
    if u(t_start) >= release:  # in range at no motor current: the output sits at A0 u, no lower than its clamp
        x_s = min(A0 * u(t_start), p["v_supply"] - m["v_oh_drop"])
        if x_s >= v_mid:
            return {**terms, "held": False, "reading": 0.0}
        t0, x0 = t_start, x_s
    else:
        if d_h <= release or t_start >= 0:  # the drive peaks at 2 V of headroom (then falls towards the trip)
            return {**terms, "held": True, "reading": math.nan, "never": True}
        lo, hi = max(t_start, -span), 0.0  # u rises monotonically over the change-over
        for _ in range(200):
            mid = (lo + hi) / 2
            lo, hi = (mid, hi) if u(mid) < release else (lo, mid)
        t0, x0 = (lo + hi) / 2, m["v_ol"]
    if t0 < 0:
        c = (u(t0), quad[1] + 2 * quad[2] * t0, quad[2])
        pieces = [(t0, c), (0.0, (d_h, s_d * slope, 0.0))]
    else:
        pieces = [(t0, (u(t0), s_d * slope, 0.0))]
    response = OnePole(t0, x0, pieces)
    try:
        t_c = response.time_at(v_mid)
    except ValueError:  # the drive turns down again before the output gets there
        return {**terms, "held": True, "reading": math.nan, "never": True}
    # the static point where the drive turns positive (for the text's split of the terms)
    lo, hi = -span, 0.0
    for _ in range(200):
        mid = (lo + hi) / 2
        lo, hi = (mid, hi) if u(mid) < 0 else (lo, mid)
    t_z = max((lo + hi) / 2, t_start)
    v_c = v_h2 + slope * t_c
    r12 = -r12_current(p, v_c, dvz) * p["r7"] / abs(v_back)
    return {**terms, "held": True, "change_over": slope * t_z / abs(v_back), "lag": slope * (t_c - t_z) / abs(v_back),
            "r12": r12, "response": response, "t_cross": t_c, "v_cross": v_c, "tau": t_c - t_z,
            "reading": v_c / p["r7"] - r12_current(p, v_c, dvz), "early": -s_head * slope * t_z}


def bc557_vbe(v_be25: float, i_c: float, temperature: float) -> float:
    """V_BE of the BC557 model (:func:`models.bc557`: IS from ``v_be25`` at 2 mA and 25 C, NF = 1, EG = 1.11 eV,
    XTI = 3) at ``i_c`` and ``temperature`` (C): SPICE's saturation current law IS(T) = IS (T/T0)^XTI
    exp(EG (T - T0) / (V_T(T) T0)) solved for V_BE = V_T(T) ln(I_C / IS(T))."""
    t0, t = models.T25, temperature + 273.15
    is25 = models.BC557_IC / math.exp(v_be25 / (models.K_Q * t0))
    v_t = models.K_Q * t
    is_t = is25 * (t / t0) ** 3 * math.exp(1.11 * (t - t0) / (v_t * t0))
    return v_t * math.log(i_c / is_t)


def one_transistor_terms(p: dict, r7: float, temperature: float, equation: float) -> dict:
    """The one-transistor limiter at ``temperature``: the motor current where T2's collector carries 2 mA is
    V_BE(T) / R7 plus T2's base current I_C / h_FE. As fractions of ``equation`` (the book's figure): "base", that
    base current, and "silicon", how far the model's V_BE(T) (silicon's law, :func:`bc557_vbe`) lies from the rule of
    thumb's V_BE + TC (T - 25 C) (``p["v_be_tc"]``, -2 mV/K), over R7: the difference the rule is known to make,
    computed from the rule as the chapter states it, not from the equation's code (a fault there still shows). "tc":
    the model's own mean drift from 25 C (V/K)."""
    v_be = bc557_vbe(p["v_be_bc557"], models.BC557_IC, temperature)
    rule = p["v_be_bc557"] + p["v_be_tc"] * (temperature - 25.0)
    return {"silicon": (v_be - rule) / r7 / equation, "base": models.BC557_IC / models.BC557_BF / equation,
            "tc": (v_be - p["v_be_bc557"]) / (temperature - 25.0) if temperature != 25.0 else float("nan")}
