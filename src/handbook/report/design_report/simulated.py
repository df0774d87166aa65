"""The design report's SPICE section (section 5): each design confirmed by ngspice at its worst corners
(:func:`handbook.spice.checks.confirm_rows`), and where a run is cheap the waveform or response of this very
circuit: the class-D filter's response with the spec's load (one AC run), the converter's coil current with the
designed L1 and R1 (one transient), the limiter's output as the motor current ramps through the trip and the motor
current when a running motor stalls (two transients), CAP-CD and CAP-DC through a commutation cycle (one
transient). Skipped with the reason when ngspice is missing."""
from __future__ import annotations

from ...core.units import eng, signed_percent
from .page import esc, figure_svg, note, table
from .sections import title


def _unit(u: str) -> str:
    return u.replace("ohm", "Ω")


def _difference(r: dict) -> str:
    """The difference as a person reads it: its size, or signed beside the one the circuit's physics predicts."""
    if not r.get("expected_difference"):
        return f"{r['rel_diff']:.3%}".replace("%", " %")
    signed = r["spice"] / r["equation"] - 1
    return f"{signed_percent(signed, 3)} (expected {signed_percent(r['expected_difference'], 3)})"


def confirm_table(rows: list[dict]) -> str:
    """SPICE's figures beside the design's own: quantity, design, SPICE, difference, tolerance, verdict."""
    return table(["quantity", "design (worst corner)", "SPICE (worst corner)", "difference", "tolerance", "verdict"],
                 [[esc(r["quantity"]), esc(eng(r["equation"], _unit(r["unit"]))), esc(eng(r["spice"], _unit(r["unit"]))),
                   _difference(r), f"±{r['rtol']:.2%}".replace("%", " %"),
                   f'<span class="{"ok" if r["agrees"] else "warn"}">{esc(r["verdict"])}</span>'] for r in rows],
                 (1, 2, 3, 4))


def _axes(xlabel: str, ylabel: str, xunit: str, yunit: str, xlog: bool = False):
    from matplotlib.figure import Figure

    from ..figures import format_axis

    fig = Figure(figsize=(6.4, 2.8))
    ax = fig.add_subplot()
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    format_axis(ax, "x", xunit, xlog)
    format_axis(ax, "y", yunit)
    ax.grid(True, which="both", lw=0.3)
    return fig, ax


def _class_d(result, warned: list | None = None) -> str:
    from ...spice import class_d

    s = result.spec
    p = {"l_out": result.l_out, "c_out": result.c_out, "supply": s["supply"], "f_sw": result.f_sw, "f_audio": s["f_audio"]}
    got = class_d.response((s["r_load"],), p)
    fig, ax = _axes("frequency", "|H| (dB)", "Hz", "", xlog=True)
    ax.plot(got["f"], got[s["r_load"]], color="C0", lw=1.6, label=f"nominal, R_L = {eng(s['r_load'], 'Ω')}")
    tl, tc = s["l_tolerance"], s["c_tolerance"]
    for (kl, kc), color in zip(((-1, 1), (-1, -1), (1, 1), (1, -1)), ("C1", "C2", "C3", "C4")):  # L and C_BYP corners
        corner = class_d.response((s["r_load"],), {**p, "l_out": result.l_out * (1 + kl * tl),
                                                    "c_out": result.c_out * (1 + kc * tc)})
        ax.plot(corner["f"], corner[s["r_load"]], color=color, lw=0.8,
                label=f"L {kl * tl * 100:+g} %, C_BYP {kc * tc * 100:+g} %".replace("-", "\N{MINUS SIGN}"))
    ax.axvline(result.f_corner, color="0.4", ls=":", label=f"corner {eng(result.f_corner, 'Hz')}")
    ax.axvline(s["f_audio"], color="#c0392b", ls="--", label=f"audio band {eng(s['f_audio'], 'Hz')}")
    ax.legend(fontsize=6, ncol=2)
    return figure_svg(fig, "sim-class_d", "The output filter's response with the designed L and C_BYP and the spec's "
                      "load, nominal and at the four corners of L's and C_BYP's tolerances (ngspice AC runs): the "
                      "low-L, high-C corner peaks most (the largest Q), the high-L, high-C one droops first.")


def _converter(result, warned: list | None = None) -> str:
    from ...design.converter import source_params
    from ...spice import converter

    w = converter.waveform({**converter.defaults(), **source_params(result.spec), "l1": result.l1_nominal,
                            "r1": result.r1_part})
    fig, ax = _axes("time from a switch-on", "coil current", "s", "A")
    ax.plot(w["t"], w["i"], label="i(L1)")
    ax.axhline(result.i_peak, color="0.4", ls=":", label=f"eq 5 peak {eng(result.i_peak, 'A')}")
    ax.axhline(result.i_peak_max, color="#c0392b", ls="--", label=f"highest peak {eng(result.i_peak_max, 'A')}")
    ax.legend(fontsize=7)
    return figure_svg(fig, "sim-converter", "The coil current over two cycles with the coil as wound (L1 nominal) and "
                      "R1 as bought, at the spec's lowest supply (ngspice transient).")


def _limiter(result, warned: list | None = None) -> str:
    from ...spice import designed, limiter

    w = limiter.waveforms(designed.circuit("current_limiter", result), {"i": "i(VAM)", "out": "v(out)"})
    s = result.spec
    fig, ax = _axes("motor current", "op-amp output", "A", "V")
    ax.plot(w["i"], w["out"], label="output, nominal parts")
    ax.axvspan(result.i_trip_min, result.i_trip_max, color="#4878a8", alpha=0.15, label="trip over every corner")
    for x, lab in ((s["i_no_trip"], "i_no_trip"), (s["i_must_trip"], "i_must_trip")):
        ax.axvline(x, color="#c0392b", ls="--", lw=1)
        ax.annotate(lab, (x, 0.5), rotation=90, fontsize=7, xytext=(2, 0), textcoords="offset points")
    ax.legend(fontsize=7)
    return figure_svg(fig, "sim-current_limiter", "The limiter's output as the motor current ramps through the trip, "
                      "nominal parts (ngspice transient); the band is the design's trip over every corner.")


def _limiter_step(result, warned: list | None = None) -> str:
    from ...spice import designed
    from ...spice.limiter import transient

    s = result.spec
    w = transient.stall({**designed.limiter_params(result), "v_supply": s["v_supply_min"]})
    fig, ax = _axes("time after the stall", "motor current", "s", "A")
    t = w["t"] - transient.defaults()["t_step"]
    ax.plot(t, w["i"], label="motor current")
    ax.axhline(w["limit"], color="0.4", ls=":", label=f"trip, nominal parts: {eng(w['limit'], 'A')}")
    for x, lab in ((s["i_no_trip"], "i_no_trip"), (s["i_must_trip"], "i_must_trip")):
        ax.axhline(x, color="#c0392b", ls="--", lw=1)
        ax.annotate(lab, (t[-1], x), fontsize=7, xytext=(-2, -9), textcoords="offset points", ha="right")
    ax.legend(fontsize=7, loc="lower center", bbox_to_anchor=(0.5, 1.0), ncol=2, frameon=False)
    settle = "does not settle within the run" if w["settling"] is None else f"settles within 5 % in {eng(w['settling'], 's')}"
    if w["peak"] > s["i_must_trip"] and warned is not None:
        warned.append(("current_limiter", f"SPICE: a running motor that stalls peaks at {eng(w['peak'], 'A')} before the "
                       f"limiter settles, above i_must_trip = {eng(s['i_must_trip'], 'A')} "
                       f"({w['overshoot_rel'] * 100:+.0f} % over the nominal trip): check the driver's and the "
                       "motor's peak ratings, or slow the loop (section 5)"))
    return figure_svg(fig, "sim-limiter-step", "A running motor that stalls (its back-EMF falls to zero in 1 µs) at the "
                      f"lowest supply, nominal parts, the limiter closed through the speed loop as AN94002's chapter "
                      f"reads figure 3: the current peaks at {eng(w['peak'], 'A')} ({w['overshoot_rel'] * 100:+.0f} % over the "
                      f"trip) and {settle} (ngspice transient; the closure, T2 and the windings as the book assumes).")


def _commutation(result, warned: list | None = None) -> str:
    from ...spice import commutation_cycle

    s = result.spec
    c = commutation_cycle.cycle({"cap_cd": result.cap_cd, "cap_dc": result.cap_dc, "pole_pairs": s["pole_pairs"],
                                 "rpm": s["rpm_min"]})
    fig, ax = _axes("time", "timer voltage", "s", "V")
    ax.plot(c["t"], c["cd"], label="CAP-CD")
    ax.plot(c["t"], c["dc"], label="CAP-DC")
    for k, z in enumerate(c["zc"]):
        ax.axvline(z, color="0.6", ls=":", lw=0.8, label="back-EMF zero crossing" if k == 0 else None)
    ax.plot(c["commutations"], [c["q"]["v_low"]] * len(c["commutations"]), "kv", ms=5, label="commutation")
    ax.legend(fontsize=7, loc="lower center", bbox_to_anchor=(0.5, 1.0), ncol=4, frameon=False)
    f = commutation_cycle.figures(c)
    return figure_svg(fig, "sim-commutation", f"The designed CAP-CD and CAP-DC driven through {c['q']['cycles']} electrical "
                      f"cycles by a motor's back-EMF at rpm_min ({s['rpm_min']:g} rpm, {s['pole_pairs']} pole pairs), the "
                      f"TDA5144's typical currents and levels: {f['per_cycle']:.3g} commutations a cycle, each "
                      f"{f['delay_deg']:.3g}° after its zero crossing (ngspice transient).")


#: table -> the waveforms and responses of its circuit
WAVES = {"commutation": (_commutation,), "class_d": (_class_d,), "converter": (_converter,),
         "current_limiter": (_limiter, _limiter_step)}


def section(ctx) -> str:
    """Section 5 (and the SPICE warnings, appended to ``ctx.spice_warnings``)."""
    from ...spice import checks, runner

    if ctx.no_spice:
        return note("SPICE confirmation skipped: --no-spice was given")
    if runner.available() is None:
        return note(f"SPICE confirmation skipped: {runner.why_unavailable()}")
    out = ["<p>Each verdict: <b>agrees</b>, an independent check (SPICE computes the figure by its own means) "
           "within its tolerance; <b>consistent (by construction)</b>, a figure SPICE reaches by the same arithmetic "
           "as the design (it checks the corner search and the deck, not the formula); <b>differs</b>, outside its "
           "tolerance. Where the circuit's physics predicts a difference from the design's equations, the table "
           "shows it beside the difference, and the tolerance is about it.</p>"]
    for t, result in ctx.designed.items():
        out.append(f"<h3>{esc(title(t))}</h3>")
        try:
            if t in checks.DESIGN_CHECKS:
                figures = checks.confirm({t: result})[t]
                out.append(confirm_table(checks.confirm_rows(t, result, figures)))
                if "meets_spec" in figures:
                    said = ([f"{figures['corners']} corners simulated"] if "corners" in figures else []) + (
                        [f"the worst of {figures['corners_searched']} by the circuit's own exact figures"]
                        if "corners_searched" in figures else [])
                    corners = f" ({', '.join(said)})" if said else ""
                    out.append(f"<p>SPICE's worst corners meet the spec in the figures above: "
                               f"<b>{'yes' if figures['meets_spec'] else 'no'}"
                               f"</b>{corners}.</p>")
                ctx.spice_warnings.extend((t, f"SPICE: {w}") for w in checks.warnings(t, figures))
            else:
                out.append(note("no corner confirmation for this circuit (SPICE checks its equations in the book); "
                                "its waveform below is simulated with the designed parts"))
            out += [wave(result, ctx.spice_warnings) for wave in WAVES.get(t, ())]
        except (checks.SpiceError, checks.SpiceUnavailable) as exc:
            out.append(note(f"SPICE run failed: {exc}"))
            ctx.spice_warnings.append((t, f"SPICE run failed, the design is not confirmed by simulation: {exc}"))
    return "".join(out)
