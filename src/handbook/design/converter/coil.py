"""The TCA5600 converter's coil: the candidate cores wound for L1 at the peak current, their flux, gap, losses
and temperature rise (see :mod:`.converter` for the method, its assumptions and the choice)."""
from __future__ import annotations

import math
from dataclasses import dataclass

from . import cores

MU0 = 4e-7 * math.pi
#: the smallest centre gap designed (PyOpenMagnetics' gap model): assumption, a ground gap holds about
#: +-5 um, so from 50 um up the gap moves A_L by at most +-10 % (the ``a_l_tolerance`` default)
GAP_MIN = 50e-6
#: the temperature of the Steinmetz coefficients' factor ct0 - ct1 T + ct2 T^2 (C): 25 C, where the MnZn
#: power ferrites of the candidate set lose most across 25..100 C (conservative)
T_LOSS = 25.0
#: copper resistivity at 20 C (ohm m) and its temperature coefficient (1/K)
RHO_CU, ALPHA_CU = 1.72e-8, 0.00393
#: the temperature of the shipped wire resistances (C)
T_WIRE_TABLE = cores.T_HOT
#: supply points over which the core loss and the audio band are evaluated
SUPPLY_POINTS = 41


@dataclass(frozen=True)
class Coil:
    """One candidate core wound for L1 at I_peak: what it takes and what it costs."""

    shape: str
    material: str
    ve: float
    turns: int
    gap: float | None
    a_l: float
    b_peak: float  # over the centre column, at the highest peak current
    b_peak_min_area: float  # at the narrowest section (the saturation figure)
    b_sat: float  # the material's saturation at t_ambient + the rise
    saturation_margin: float
    wire: str | None
    wire_diameter: float | None
    current_density: float | None
    r_dc: float | None
    core_loss: float | None
    winding_loss: float | None
    temperature_rise: float | None
    fails: str  # "" when it meets everything, else why not
    limits: tuple = ()  # the limits it fails: "saturation", "bobbin", "gap", "temperature rise"
    core_loss_at: dict | None = None  # the point of the largest core loss (core_loss_points' figures), if any

    @property
    def ok(self) -> bool:
        return not self.fails

    @property
    def loss(self) -> float:
        return (self.core_loss or 0.0) + (self.winding_loss or 0.0)


def v_top(s: dict) -> float:
    """The VCC2 at which the dump voltage V_L+ vanishes (eq 1): above it the converter need not switch.

    Parameters
    ----------
    s : dict
        The checked ``[converter]`` table or one of its corners (:func:`~.operating.corner`), SI units.

    Returns
    -------
    float
        ``v_out`` + ``v_regulator_drop`` + ``v_f``, V.
    """
    return s["v_out"] + s["v_regulator_drop"] + s["v_f"]


def coil_voltages(s: dict, vcc: float) -> tuple[float, float]:
    """Eq 1 and 2 at supply ``vcc``: (V_L+, V_L-).

    Parameters
    ----------
    s : dict
        The checked ``[converter]`` table or one of its corners (:func:`~.operating.corner`), SI units.
    vcc : float
        The supply VCC2, V.

    Returns
    -------
    tuple of float
        (V_L+, the voltage the coil dumps against; V_L-, the voltage that charges it), V; V_L+ is zero or
        negative at and above :func:`v_top`.
    """
    return v_top(s) - vcc, vcc - s["v_ce_sat"] - s["v12h"]


def frequency(s: dict, vcc: float, inductance: float, i_peak: float) -> float:
    """The full-load switching frequency 1/(t1 + t2) = 1/(L I_peak (1/V_L- + 1/V_L+)) at supply ``vcc``
    (0 where V_L+ has vanished: the dump never ends).

    Parameters
    ----------
    s : dict
        The checked ``[converter]`` table or one of its corners (:func:`~.operating.corner`), SI units.
    vcc : float
        The supply VCC2, V.
    inductance : float
        The coil's inductance, H.
    i_peak : float
        The peak coil current, A.

    Returns
    -------
    float
        The switching frequency at full load, Hz (0.0 at and above :func:`v_top`).
    """
    vl_plus, vl_minus = coil_voltages(s, vcc)
    if vl_plus <= 0:
        return 0.0
    return 1 / (inductance * i_peak * (1 / vl_minus + 1 / vl_plus))


def supplies(s: dict, n: int = SUPPLY_POINTS) -> list[float]:
    """VCC2 from v_supply_min to v_supply_max (stopping just short of where V_L+ vanishes).

    Parameters
    ----------
    s : dict
        The checked ``[converter]`` table or one of its corners (:func:`~.operating.corner`), SI units.
    n : int
        The number of points (at least 2 when the range is not a single point).

    Returns
    -------
    list of float
        ``n`` supply voltages evenly spaced, V, from ``v_supply_min`` to the smaller of ``v_supply_max`` and just
        below :func:`v_top`; the single ``[v_supply_min]`` when that range is empty.
    """
    lo, hi = s["v_supply_min"], min(s["v_supply_max"], v_top(s) * (1 - 1e-6))
    hi = max(hi, lo)
    return [lo + (hi - lo) * k / (n - 1) for k in range(n)] if hi > lo and n > 1 else [lo]


def steinmetz_range(material: dict, f: float) -> tuple[dict, bool]:
    """The Steinmetz range that covers f (else the nearest one) and whether f lies inside its span.

    Parameters
    ----------
    material : dict
        One material's row of :func:`~handbook.design.converter.cores.load` (saturation in T, Steinmetz ranges).
    f : float
        The frequency, Hz.

    Returns
    -------
    tuple
        (the range, a dict of ``f_low`` and ``f_high`` (Hz), ``k``, ``alpha``, ``beta``, ``ct0``, ``ct1``,
        ``ct2``; True when ``f`` lies in its span, False when the nearest range is extrapolated).
    """
    ranges = material["steinmetz"]
    for r in ranges:
        if r["f_low"] <= f <= r["f_high"]:
            return r, True
    return (ranges[0] if f < ranges[0]["f_low"] else ranges[-1]), False


def igse_density(material: dict, delta_b: float, f: float, duty: float) -> float:
    """Core loss per volume (W/m^3) of a triangular flux swing delta_b (peak to peak, T) at f with rise
    fraction ``duty``: the improved generalised Steinmetz equation (Venkatachalam et al., 2002)
    P_v = k_i delta_b^beta f^alpha (D^(1-alpha) + (1-D)^(1-alpha)),
    k_i = k / ((2 pi)^(alpha-1) 2^(beta-alpha) int_0^2pi |cos t|^alpha dt), with the temperature factor
    ct0 - ct1 T + ct2 T^2 at :data:`T_LOSS`.

    Parameters
    ----------
    material : dict
        One material's row of :func:`~handbook.design.converter.cores.load` (saturation in T, Steinmetz ranges).
    delta_b : float
        The flux density's swing, peak to peak, T.
    f : float
        The switching frequency, Hz.
    duty : float
        The rising part of the period, a fraction (0 < duty < 1).

    Returns
    -------
    float
        The core loss per volume, W/m^3.
    """
    k_i, a, b, temp = igse_coefficients(material, f)
    return k_i * delta_b ** b * f ** a * (duty ** (1 - a) + (1 - duty) ** (1 - a)) * temp


def igse_coefficients(material: dict, f: float) -> tuple[float, float, float, float]:
    """The iGSE's coefficients at f (:func:`igse_density`): k_i from the Steinmetz range's k, alpha, beta, and the
    temperature factor ct0 - ct1 T + ct2 T^2 at :data:`T_LOSS`.

    Parameters
    ----------
    material : dict
        One material's row of :func:`~handbook.design.converter.cores.load`.
    f : float
        The switching frequency, Hz (its Steinmetz range: :func:`steinmetz_range`).

    Returns
    -------
    tuple of float
        (k_i, alpha, beta, the temperature factor).
    """
    r, _ = steinmetz_range(material, f)
    a, b = r["alpha"], r["beta"]
    cos_integral = 2 * math.sqrt(math.pi) * math.gamma((a + 1) / 2) / math.gamma(a / 2 + 1)
    k_i = r["k"] / ((2 * math.pi) ** (a - 1) * 2 ** (b - a) * cos_integral)
    return k_i, a, b, r["ct0"] - r["ct1"] * T_LOSS + r["ct2"] * T_LOSS ** 2


def b_sat(material: dict, temperature: float) -> float:
    """The material's saturation flux density at ``temperature`` (C): linear through its 25 C and 100 C
    figures (PyOpenMagnetics gives those two), extended beyond them (never below 1 mT: far above the Curie
    temperature the figure means only "saturated").

    Parameters
    ----------
    material : dict
        One material's row of :func:`~handbook.design.converter.cores.load` (saturation in T, Steinmetz ranges).
    temperature : float
        The core's temperature, C.

    Returns
    -------
    float
        The saturation flux density, T (at least 1e-3).
    """
    t0, t1 = cores.T_ROOM, cores.T_HOT
    b0, b1 = material["b_sat_room"], material["b_sat_hot"]
    return max(b0 + (b1 - b0) * (temperature - t0) / (t1 - t0), 1e-3)


def core_reluctance(shape: dict, material: dict) -> float:
    """The ungapped core's reluctance, l_e / (mu0 mu_i A_e).

    Parameters
    ----------
    shape : dict
        One core shape's row of :func:`~handbook.design.converter.cores.load` (areas m^2, lengths m, volume m^3,
        gap table in m and A/Wb).
    material : dict
        One material's row of :func:`~handbook.design.converter.cores.load` (saturation in T, Steinmetz ranges).

    Returns
    -------
    float
        The reluctance, A/Wb (1/H).
    """
    return shape["le"] / (MU0 * material["mu_i"] * shape["ae"])


def gap_reluctance(shape: dict, gap: float) -> float:
    """PyOpenMagnetics' reluctance of the gaps with a centre gap ``gap`` (log-log interpolation of the table).

    Parameters
    ----------
    shape : dict
        One core shape's row of :func:`~handbook.design.converter.cores.load` (areas m^2, lengths m, volume m^3,
        gap table in m and A/Wb).
    gap : float
        The centre gap's length, m (outside the table, the end segment is extrapolated).

    Returns
    -------
    float
        The reluctance of all the core's gaps, A/Wb (1/H).
    """
    xs, ys = shape["gap_lengths"], shape["gap_reluctance"]
    k = min(max(1, next((i for i, x in enumerate(xs) if x >= gap), len(xs) - 1)), len(xs) - 1)
    w = math.log(gap / xs[k - 1]) / math.log(xs[k] / xs[k - 1])
    return math.exp(math.log(ys[k - 1]) + w * (math.log(ys[k]) - math.log(ys[k - 1])))


def gap_for(shape: dict, reluctance: float) -> float | None:
    """The centre gap whose gaps' reluctance is ``reluctance`` (the table inverted), None beyond the table.

    Parameters
    ----------
    shape : dict
        One core shape's row of :func:`~handbook.design.converter.cores.load` (areas m^2, lengths m, volume m^3,
        gap table in m and A/Wb).
    reluctance : float
        The gaps' reluctance wanted, A/Wb (zero or less: the ungapped core alone already has more reluctance
        than the turns allow, so they give too little inductance whatever the gap).

    Returns
    -------
    float or None
        The centre gap's length, m (below the table's shortest gap, extrapolated; 0 where ``reluctance`` is not
        positive: no gap can lower the reluctance); None above the table's largest reluctance.
    """
    xs, ys = shape["gap_lengths"], shape["gap_reluctance"]
    if reluctance <= 0:
        return 0.0
    if reluctance > ys[-1]:
        return None
    k = min(max(1, next((i for i, y in enumerate(ys) if y >= reluctance), len(ys) - 1)), len(ys) - 1)
    w = math.log(reluctance / ys[k - 1]) / math.log(ys[k] / ys[k - 1])
    return math.exp(math.log(xs[k - 1]) + w * (math.log(xs[k]) - math.log(xs[k - 1])))


def core_loss(material: dict, shape: dict, s: dict, op: dict, turns: int) -> tuple[float, list[dict]]:
    """The iGSE core loss (W) at the largest flux swing (L_max, I_peak,max), the largest over the supply range
    at full load and over V_CE(sat)'s and V_F's ends (V12(H) high: the ``hot`` corners), and the points it was
    evaluated at.

    Parameters
    ----------
    material : dict
        One material's row of :func:`~handbook.design.converter.cores.load` (saturation in T, Steinmetz ranges).
    shape : dict
        One core shape's row of :func:`~handbook.design.converter.cores.load` (areas m^2, lengths m, volume m^3,
        gap table in m and A/Wb).
    s : dict
        The checked ``[converter]`` table (SI units; temperatures in C).
    op : dict
        The operating point (:func:`~handbook.design.converter.operating.operating_point`): ``l1_max`` (H),
        ``i_peak_max`` (A) and the ``hot`` corners (the spec at each of them) are read.
    turns : int
        The coil's turns.

    Returns
    -------
    tuple
        (the core loss, W, the largest over nine supply points at each hot corner; the points it was evaluated at,
        a list of :func:`core_loss_points`' dicts: the supply points where the converter switches).
    """
    points = core_loss_points(material, shape, op, turns)
    return max((pt["loss"] for pt in points), default=0.0), points


def core_loss_points(material: dict, shape: dict, op: dict, turns: int) -> list[dict]:
    """Every point :func:`core_loss` takes its largest over: nine supply points at each hot corner where the
    converter switches, each with its figures.

    Parameters
    ----------
    material, shape : dict
        The material's and the core shape's rows of :func:`~handbook.design.converter.cores.load`.
    op : dict
        The operating point (``l1_max`` in H, ``i_peak_max`` in A and the ``hot`` corners are read).
    turns : int
        The coil's turns.

    Returns
    -------
    list of dict
        ``vcc`` (V), ``f`` (Hz), ``duty`` (the rising fraction), ``delta_b`` (T, peak to peak over A_e) and
        ``loss`` (W) of each point.
    """
    delta_b = op["l1_max"] * op["i_peak_max"] / (turns * shape["ae"])
    out = []
    for hot in op["hot"]:
        for v in supplies(hot, 9):
            vl_plus, vl_minus = coil_voltages(hot, v)
            f = frequency(hot, v, op["l1_max"], op["i_peak_max"])
            if f <= 0:
                continue
            duty = vl_plus / (vl_plus + vl_minus)  # t1 / (t1 + t2)
            out.append({"vcc": v, "f": f, "duty": duty, "delta_b": delta_b,
                        "loss": igse_density(material, delta_b, f, duty) * shape["ve"]})
    return out


def turn_bounds(shape: dict, material: dict, s: dict, op: dict, temperature: float) -> tuple[float, float]:
    """The two least turn counts (real numbers, before rounding up) of a core: the one whose gap for the nominal
    inductance is :data:`GAP_MIN` (sqrt(L1 (R_core + R_gap(GAP_MIN)))), and the one that keeps the peak flux at the
    narrowest section ``saturation_margin_min`` below saturation at ``temperature`` (L_max I_peak,max /
    ((1 - margin) B_sat A_min)).

    Parameters
    ----------
    shape, material : dict
        The core shape's and the material's rows of :func:`~handbook.design.converter.cores.load`.
    s : dict
        The checked ``[converter]`` table (``saturation_margin_min`` is read).
    op : dict
        The operating point (``l1_nominal``, ``l1_max`` in H, ``i_peak_max`` in A are read).
    temperature : float
        The core's temperature, C.

    Returns
    -------
    tuple of float
        (turns for the smallest gap, turns for the saturation margin).
    """
    n_gap = math.sqrt(op["l1_nominal"] * (core_reluctance(shape, material) + gap_reluctance(shape, GAP_MIN)))
    b_allowed = (1 - s["saturation_margin_min"]) * b_sat(material, temperature)
    return n_gap, op["l1_max"] * op["i_peak_max"] / (b_allowed * shape["a_min"])


def coil(shape_name: str, material_name: str, s: dict, op: dict, table: dict | None = None) -> Coil:
    """One candidate core, wound and costed (see the module's description).

    Parameters
    ----------
    shape_name : str
        The core shape's name, a key of the table's ``shapes`` (e.g. "RM 8").
    material_name : str
        The material's name, a key of the table's ``materials`` ("3C90", "N87").
    s : dict
        The checked ``[converter]`` table (SI units; temperatures in C).
    op : dict
        The operating point (:func:`~handbook.design.converter.operating.operating_point`): ``l1_nominal`` and
        ``l1_max`` (H), ``i_peak_max`` and ``i_rms`` (A) are read.
    table : dict or None
        The cores table (:func:`~handbook.design.converter.cores.load`); None: the shipped one.

    Returns
    -------
    Coil
        The core, material and effective volume (m^3); turns; centre gap (m, None beyond the table); A_L (H);
        peak flux densities over the centre column and the narrowest section (T); saturation flux density (T)
        and the margin left (fraction); the wire (name, copper diameter m), current density (A/m^2), R_dc
        (ohm), core and winding losses (W) and temperature rise (K), these None when no wire fits; ``fails``
        (why it fails, "" when it meets every limit) and ``limits`` (the limits it fails).
    """
    table = table or cores.load()
    shape, material = table["shapes"][shape_name], table["materials"][material_name]
    n_for = lambda t: math.ceil(max(turn_bounds(shape, material, s, op, t)) * (1 - 1e-12))  # noqa: E731
    n_hi = n_for(s["t_ambient"] + s["temperature_rise_max"])  # enough at the hottest the rise allows
    # the fewest turns that hold the margin at the coil's own temperature: from the ambient's count up, each
    # step to the count the last one's temperature asks for (the count only grows; at most n_hi)
    n = max(1, n_for(s["t_ambient"]))
    for _ in range(50):
        wound = wind(shape_name, material_name, s, op, n, table)
        if "saturation" not in wound.limits or n >= n_hi:
            return wound
        n = min(max(n + 1, n_for(s["t_ambient"] + wound.temperature_rise)), n_hi)
    return wound


def wind(shape_name: str, material_name: str, s: dict, op: dict, n: int, table: dict | None = None) -> Coil:
    """The candidate wound with ``n`` turns: gap, flux, wire, losses, rise, and the limits it fails.

    Parameters
    ----------
    shape_name : str
        The core shape's name, a key of the table's ``shapes`` (e.g. "RM 8").
    material_name : str
        The material's name, a key of the table's ``materials`` ("3C90", "N87").
    s : dict
        The checked ``[converter]`` table (SI units; temperatures in C).
    op : dict
        The operating point (:func:`~handbook.design.converter.operating.operating_point`): ``l1_nominal`` and
        ``l1_max`` (H), ``i_peak_max`` and ``i_rms`` (A) are read.
    n : int
        The turns.
    table : dict or None
        The cores table (:func:`~handbook.design.converter.cores.load`); None: the shipped one.

    Returns
    -------
    Coil
        The core, material and effective volume (m^3); turns; centre gap (m, None beyond the table); A_L (H);
        peak flux densities over the centre column and the narrowest section (T); saturation flux density (T)
        and the margin left (fraction); the wire (name, copper diameter m), current density (A/m^2), R_dc
        (ohm), core and winding losses (W) and temperature rise (K), these None when no wire fits; ``fails``
        (why it fails, "" when it meets every limit) and ``limits`` (the limits it fails).
    """
    table = table or cores.load()
    shape, material = table["shapes"][shape_name], table["materials"][material_name]
    r_core = core_reluctance(shape, material)
    t_cu = s["t_ambient"] + s["temperature_rise_max"]  # copper at the hottest the rise allows
    copper = (1 + ALPHA_CU * (t_cu - 20)) / (1 + ALPHA_CU * (T_WIRE_TABLE - 20))
    gap_reluctance = n * n / op["l1_nominal"] - r_core
    gap = gap_for(shape, gap_reluctance)
    flux = op["l1_max"] * op["i_peak_max"] / n
    b_centre, b_narrow = flux / shape["a_centre"], flux / shape["a_min"]
    fails, limits = [], []
    if gap is None:
        fails.append(f"the gap for {n} turns is longer than {shape['gap_lengths'][-1] * 1e3:.3g} mm")
        limits.append("gap")
    elif gap_reluctance <= 0:
        fails.append(f"{n} turns give less than L1 = {op['l1_nominal'] * 1e6:.3g} uH even on the ungapped core")
        limits.append("gap")
    elif gap < GAP_MIN * (1 - 1e-6):
        fails.append(f"the gap for {n} turns is {gap * 1e6:.3g} µm, below {GAP_MIN * 1e6:g} µm")
        limits.append("gap")
    fitting = [w for w in table["wires"] if n * w["d_outer"] ** 2 <= s["fill_factor"] * shape["window_area"]]
    base = dict(shape=shape_name, material=material_name, ve=shape["ve"], turns=n, gap=gap, a_l=op["l1_nominal"] / n ** 2,
                b_peak=b_centre, b_peak_min_area=b_narrow)
    if not fitting:
        sat = b_sat(material, s["t_ambient"])
        return Coil(**base, b_sat=sat, saturation_margin=1 - b_narrow / sat, wire=None, wire_diameter=None,
                    current_density=None, r_dc=None, core_loss=None, winding_loss=None, temperature_rise=None,
                    fails="; ".join([*fails, f"{n} turns of even the thinnest wire do not fit the bobbin"]),
                    limits=(*limits, "bobbin"))
    wire = fitting[-1]
    r_dc = n * shape["mlt"] * wire["r_per_m_hot"] * copper
    p_cu = op["i_rms"] ** 2 * r_dc
    p_core, points = core_loss(material, shape, s, op, n)
    rise = shape["r_th"] * (p_cu + p_core)
    sat = b_sat(material, s["t_ambient"] + rise)
    margin = 1 - b_narrow / sat
    if margin < s["saturation_margin_min"] * (1 - 1e-9):
        fails.append(f"{margin:.1%} of saturation left at {s['t_ambient'] + rise:.3g} C, below "
                     f"{s['saturation_margin_min']:.0%}")
        limits.append("saturation")
    if rise > s["temperature_rise_max"]:
        fails.append(f"it rises {rise:.3g} K, above {s['temperature_rise_max']:g} K")
        limits.append("temperature rise")
    density = op["i_rms"] / (math.pi * wire["d_cu"] ** 2 / 4)
    if density > s["current_density_max"] * (1 + 1e-9):
        fails.append(f"its thickest fitting wire ({wire['name']}) carries {density / 1e6:.3g} A/mm², above "
                     f"{s['current_density_max'] / 1e6:.3g} A/mm²")
        limits.append("current density")
    return Coil(**base, b_sat=sat, saturation_margin=margin, wire=wire["name"], wire_diameter=wire["d_cu"],
                current_density=density, r_dc=r_dc, core_loss=p_core,
                core_loss_at=max(points, key=lambda pt: pt["loss"], default=None),
                winding_loss=p_cu, temperature_rise=rise, fails="; ".join(fails), limits=tuple(limits))


def candidates(s: dict, op: dict) -> list[Coil]:
    """Every candidate core wound for this spec, smallest effective volume first (ties: least loss).

    Parameters
    ----------
    s : dict
        The checked ``[converter]`` table (SI units; temperatures in C).
    op : dict
        The operating point (:func:`~handbook.design.converter.operating.operating_point`): ``l1_nominal`` and
        ``l1_max`` (H), ``i_peak_max`` and ``i_rms`` (A) are read.

    Returns
    -------
    list of Coil
        One :func:`coil` per shape and material of the shipped table, sorted by effective volume, then (among
        those that meet every limit) total loss, then shape and material names.
    """
    table = cores.load()
    out = [coil(sh, m, s, op, table) for sh in table["shapes"] for m in table["materials"]]
    return sorted(out, key=lambda c: (c.ve, c.loss if c.ok else math.inf, c.shape, c.material))
