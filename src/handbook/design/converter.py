"""The TCA5600 converter designed down to a real coil: eq 1 to 6a, then the smallest core that holds L1.

The converter is a boost stage: the switch (pin 9 to R1) charges L1 from VCC2 for t1 until the drop
across R1 reaches V12(H); then the coil dumps into C2, the regulator's input, for t2 until its current
is zero, and the next charge starts (TCA5600 excerpt, figures 13 and 14). Eq 4's t1 + t2 = 1/f puts the
worst operating point (VCC2 lowest, Iout2 largest) at the boundary between continuous and discontinuous
conduction; every lighter load lets the regulator's feedback stop the converter between cycles.

Operating point: eq 1 to 6a by the source's own functions (:mod:`handbook.sources.tca5600.circuit`):
alpha, t1, t2, I_peak, L1 and R1.

Coil. For every candidate core (shape and material from PyOpenMagnetics' database, shipped as
:mod:`.converter_cores`): the fewest whole turns that keep the peak flux density at the core's narrowest
section ``saturation_margin_min`` below the material's saturation at 100 C (N >= L1 I_peak / (B_max
A_min)) and leave a centre-leg gap of at least :data:`GAP_MIN`; the gap for L1 without fringing, lg =
mu0 N^2 A_e / L1 - l_e / mu_i (fringing adds inductance: the gap is ground to the A_L = L1 / N^2 reported);
the thickest wire that fits the bobbin with ``fill_factor`` (least copper loss) and carries the rms
current within ``current_density_max``; the core loss by the improved generalised Steinmetz equation
(iGSE) for the triangular flux of figure 14 with the material's coefficients; the copper loss I_rms^2
R_dc at 100 C; and the temperature rise from the core's thermal resistance. The choice is the candidate
of least effective volume that meets the saturation margin, the fit and ``temperature_rise_max`` (ties:
the least loss). The candidate set is finite and every candidate is evaluated exactly, so enumeration
is the exact optimum: no solver is needed and none is used. The frequency trade-off (higher f_min: a
smaller L1 and core, more core loss per volume) is shown as a sweep over f_min in the design chapter.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

from ..core import InputError
from ..sources.tca5600 import circuit as tca5600
from . import converter_cores
from .common import Result, completed
from .solvers import Infeasible

TABLE = "converter"
MU0 = 4e-7 * math.pi
#: the smallest centre-leg gap designed: assumption, a ground gap holds about +-10 um, so 50 um keeps
#: A_L within about +-20 %
GAP_MIN = 50e-6
#: the temperature of the Steinmetz coefficients' factor ct0 - ct1 T + ct2 T^2 (C): 25 C, where the MnZn
#: power ferrites of the candidate set lose most across 25..100 C (conservative)
T_LOSS = 25.0
#: copper resistivity (ohm m) and its temperature coefficient (1/K), for the skin depth only
RHO_CU, ALPHA_CU = 1.72e-8, 0.00393


@dataclass(frozen=True)
class Coil:
    """One candidate core wound for L1 at I_peak: what it takes and what it costs."""

    shape: str
    material: str
    ve: float
    turns: int
    gap: float
    a_l: float
    b_peak: float  # at the effective area (the loss figure)
    b_peak_min_area: float  # at the narrowest section (the saturation figure)
    saturation_margin: float
    wire: str | None
    wire_diameter: float | None
    r_dc: float | None
    core_loss: float | None
    winding_loss: float | None
    temperature_rise: float | None
    fails: str  # "" when it meets everything, else why not

    @property
    def ok(self) -> bool:
        return not self.fails

    @property
    def loss(self) -> float:
        return (self.core_loss or 0.0) + (self.winding_loss or 0.0)


@dataclass(frozen=True)
class ConverterResult(Result):
    alpha: float
    t1: float
    t2: float
    i_peak: float
    l1: float
    r1: float
    vl_plus: float
    vl_minus: float
    i_rms: float
    core_shape: str
    core_material: str
    turns: int
    gap: float
    a_l: float
    wire: str
    b_peak: float
    core_loss: float
    winding_loss: float
    temperature_rise: float
    saturation_margin: float
    coil: Coil
    candidates: tuple  # every candidate Coil, in the order of the choice (smallest first)
    next_smaller: Coil | None  # the largest candidate smaller than the choice, and why it fails
    warnings: tuple

    table = TABLE


def source_params(s: dict) -> dict:
    """The spec in the source functions' names (handbook.sources.tca5600.circuit)."""
    return {"v_cc2_min": s["v_supply_min"], "v_out2": s["v_out"], "i_out2": s["i_out"], "f_min": s["f_min"],
            "regulator_drop": s["v_regulator_drop"], "v_f": s["v_f"], "vce_sat": s["v_ce_sat"], "v12h": s["v12h"]}


def checked(spec: dict | None) -> dict:
    s = completed(TABLE, spec)
    above = s["v_supply_min"] - s["v_regulator_drop"] - s["v_f"]
    if s["v_out"] <= above:
        raise InputError(f"converter.v_out = {s['v_out']:g} V must be above v_supply_min - v_regulator_drop - v_f = "
                         f"{above:g} V: the coil must dump upwards into the regulator's input (eq 1, V_L+ > 0)")
    drops = s["v_ce_sat"] + s["v12h"]
    if s["v_supply_min"] <= drops:
        raise InputError(f"converter.v_supply_min = {s['v_supply_min']:g} V must be above v_ce_sat + v12h = "
                         f"{drops:g} V: the coil needs a voltage to charge (eq 2, V_L- > 0)")
    return s


def operating_point(s: dict) -> dict:
    """Eq 1 to 6a (the source's functions) and the triangle's rms current I_peak / sqrt(3)."""
    op = tca5600.design(source_params(s))
    return {**op, "i_rms": op["i_peak"] / math.sqrt(3), "duty": op["t1"] * s["f_min"]}


def steinmetz_range(material: dict, f: float) -> tuple[dict, bool]:
    """The Steinmetz range that covers f (else the nearest one) and whether f lies inside its span."""
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
    ct0 - ct1 T + ct2 T^2 at :data:`T_LOSS`."""
    r, _ = steinmetz_range(material, f)
    a, b = r["alpha"], r["beta"]
    cos_integral = 2 * math.sqrt(math.pi) * math.gamma((a + 1) / 2) / math.gamma(a / 2 + 1)
    k_i = r["k"] / ((2 * math.pi) ** (a - 1) * 2 ** (b - a) * cos_integral)
    temp = r["ct0"] - r["ct1"] * T_LOSS + r["ct2"] * T_LOSS ** 2
    return k_i * delta_b ** b * f ** a * (duty ** (1 - a) + (1 - duty) ** (1 - a)) * temp


def wind(shape: dict, material: dict, s: dict, op: dict) -> tuple[int, float, float]:
    """(turns, gap, A_L): the fewest whole turns that keep B at the narrowest section below the margin and
    leave a gap of at least GAP_MIN; the gap for L1 without fringing."""
    l1, i_pk = op["l1"], op["i_peak"]
    b_max = (1 - s["saturation_margin_min"]) * material["b_sat_hot"]
    n_sat = l1 * i_pk / (b_max * shape["a_min"])
    n_gap = math.sqrt(l1 * (GAP_MIN + shape["le"] / material["mu_i"]) / (MU0 * shape["ae"]))
    n = max(1, math.ceil(max(n_sat, n_gap) * (1 - 1e-12)))
    gap = MU0 * n * n * shape["ae"] / l1 - shape["le"] / material["mu_i"]
    return n, gap, l1 / (n * n)


def coil(shape_name: str, material_name: str, s: dict, op: dict, table: dict | None = None) -> Coil:
    """One candidate core, wound and costed (see the module's description)."""
    table = table or converter_cores.load()
    shape, material = table["shapes"][shape_name], table["materials"][material_name]
    n, gap, a_l = wind(shape, material, s, op)
    flux = op["l1"] * op["i_peak"] / n
    b_eff, b_min_area = flux / shape["ae"], flux / shape["a_min"]
    margin = 1 - b_min_area / material["b_sat_hot"]
    base = dict(shape=shape_name, material=material_name, ve=shape["ve"], turns=n, gap=gap, a_l=a_l, b_peak=b_eff,
                b_peak_min_area=b_min_area, saturation_margin=margin)
    a_cu_min = op["i_rms"] / s["current_density_max"]
    fitting = [w for w in table["wires"] if n * w["d_outer"] ** 2 <= s["fill_factor"] * shape["window_area"]]
    if not fitting:
        return Coil(**base, wire=None, wire_diameter=None, r_dc=None, core_loss=None, winding_loss=None,
                    temperature_rise=None, fails=f"{n} turns of even the thinnest wire do not fit the bobbin")
    wire = fitting[-1]
    r_dc = n * shape["mlt"] * wire["r_per_m_hot"]
    p_cu = op["i_rms"] ** 2 * r_dc
    p_core = igse_density(material, b_eff, s["f_min"], op["duty"]) * shape["ve"]
    rise = shape["r_th"] * (p_cu + p_core)
    fails = []
    if math.pi * wire["d_cu"] ** 2 / 4 < a_cu_min:
        fails.append(f"the thickest wire that fits ({wire['d_cu'] * 1e3:g} mm) carries "
                     f"{op['i_rms'] / (math.pi * wire['d_cu'] ** 2 / 4) / 1e6:.3g} A/mm^2, above "
                     f"{s['current_density_max'] / 1e6:g} A/mm^2")
    if rise > s["temperature_rise_max"]:
        fails.append(f"it rises {rise:.3g} K, above {s['temperature_rise_max']:g} K")
    return Coil(**base, wire=wire["name"], wire_diameter=wire["d_cu"], r_dc=r_dc, core_loss=p_core,
                winding_loss=p_cu, temperature_rise=rise, fails="; ".join(fails))


def candidates(s: dict, op: dict) -> list[Coil]:
    """Every candidate core wound for this spec, smallest effective volume first (ties: least loss)."""
    table = converter_cores.load()
    out = [coil(sh, m, s, op, table) for sh in table["shapes"] for m in table["materials"]]
    return sorted(out, key=lambda c: (c.ve, c.loss if c.ok else math.inf, c.shape, c.material))


def choose(s: dict) -> tuple[dict, list[Coil], Coil | None]:
    op = operating_point(s)
    every = candidates(s, op)
    return op, every, next((c for c in every if c.ok), None)


def _feasible(s: dict) -> bool:
    return choose(s)[2] is not None


def _largest_true(pred, low: float, high: float, steps: int = 40) -> float | None:
    """Largest x in [low, high] with pred(x) true, for a pred true below a threshold (bisection)."""
    if not pred(low):
        return None
    if pred(high):
        return high
    for _ in range(steps):
        mid = math.sqrt(low * high)
        low, high = (mid, high) if pred(mid) else (low, mid)
    return low


def infeasible(s: dict, every: list[Coil]) -> Infeasible:
    """Nothing in the candidate set meets the spec: what would (a lower current, a higher frequency),
    and which candidate comes nearest (the way to a larger core family)."""
    from ..report.tables import eng

    i_ok = _largest_true(lambda i: _feasible({**s, "i_out": i}), 1e-6, s["i_out"])
    f_ok = None
    for f in (s["f_min"] * 1.25 ** k for k in range(1, 41)):
        if f <= 1e7 and _feasible({**s, "f_min": f}):
            f_ok = f
            break
    largest = max(every, key=lambda c: (c.ve, -c.loss))
    why = largest.fails
    parts = [f"no core of the candidate set (P 9/5 .. P 26/16, RM 4 .. RM 10, EP 7 .. EP 20, E 13 .. E 25, "
             f"EFD 10 .. EFD 25 in 3C90 and N87) holds L1 at the peak current with a "
             f"{s['saturation_margin_min']:.0%} saturation margin within {s['temperature_rise_max']:g} K: "
             f"the largest, {largest.shape} in {largest.material}, fails: {why}"]
    if i_ok is not None:
        parts.append(f"i_out up to {eng(i_ok, 'A')} can be met at f_min = {eng(s['f_min'], 'Hz')}")
    if f_ok is not None:
        parts.append(f"f_min = {eng(f_ok, 'Hz')} meets i_out = {eng(s['i_out'], 'A')}")
    parts.append("a larger core family (RM 12/14, P 30/19 and up, ETD, PQ) is outside the candidate set")
    return Infeasible(TABLE, "; ".join(parts), {"i_out": i_ok, "f_min": f_ok, "largest_core": largest.shape,
                                                 "largest_core_fails": why})


def warnings(s: dict, op: dict, c: Coil) -> list[str]:
    table = converter_cores.load()
    out = []
    if s["f_min"] < 20e3:
        out.append(f"f_min = {s['f_min'] / 1e3:g} kHz lies in the audio band: the coil may be heard (the excerpt: "
                   "above the audio band, e.g. 20 kHz)")
    _, inside = steinmetz_range(table["materials"][c.material], s["f_min"])
    if not inside:
        rng = table["materials"][c.material]["steinmetz"]
        out.append(f"core loss extrapolated: {c.material}'s Steinmetz fit spans {rng[0]['f_low'] / 1e3:g} to "
                   f"{rng[-1]['f_high'] / 1e3:g} kHz, f_min = {s['f_min'] / 1e3:g} kHz")
    skin = math.sqrt(RHO_CU * (1 + ALPHA_CU * 80) / (math.pi * s["f_min"] * MU0))
    if c.wire_diameter is not None and c.wire_diameter > 2 * skin:
        out.append(f"wire {c.wire_diameter * 1e3:g} mm is thicker than twice the skin depth at f_min "
                   f"({skin * 1e3:.3g} mm): the copper loss (I_rms^2 R_dc) is underestimated")
    return out


def design(spec: dict | None = None) -> ConverterResult:
    """Eq 1 to 6a, then the smallest candidate core meeting the saturation margin, the bobbin and the
    temperature rise (exact enumeration). Raises Infeasible when no candidate does."""
    s = checked(spec)
    op, every, chosen = choose(s)
    if chosen is None:
        raise infeasible(s, every)
    smaller = [c for c in every if c.ve < chosen.ve * (1 - 1e-9)]
    return ConverterResult(
        spec=s, alpha=op["alpha"], t1=op["t1"], t2=op["t2"], i_peak=op["i_peak"], l1=op["l1"], r1=op["r1"],
        vl_plus=op["vl_plus"], vl_minus=op["vl_minus"], i_rms=op["i_rms"],
        core_shape=chosen.shape, core_material=chosen.material, turns=chosen.turns, gap=chosen.gap, a_l=chosen.a_l,
        wire=chosen.wire, b_peak=chosen.b_peak, core_loss=chosen.core_loss, winding_loss=chosen.winding_loss,
        temperature_rise=chosen.temperature_rise, saturation_margin=chosen.saturation_margin, coil=chosen,
        candidates=tuple(every), next_smaller=smaller[-1] if smaller else None,
        warnings=tuple(warnings(s, op, chosen)))


def sweep(s: dict, frequencies) -> list[dict]:
    """The chosen coil at each f_min (the rest of the spec unchanged): the trade-off of the chapter's plot."""
    rows = []
    for f in frequencies:
        try:
            r = design({**s, "f_min": float(f)})
        except Infeasible:
            rows.append({"f_min": float(f), "core": None})
            continue
        rows.append({"f_min": float(f), "core": f"{r.core_shape} {r.core_material}", "ve": r.coil.ve, "l1": r.l1,
                     "turns": r.turns, "core_loss": r.core_loss, "winding_loss": r.winding_loss,
                     "temperature_rise": r.temperature_rise})
    return rows
