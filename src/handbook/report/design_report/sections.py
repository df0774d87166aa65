"""The design report's sections read straight from the spec, the results and the BOM: the spec (what the reader
changed first), each designed circuit (schematic, parts, what binds, margins), losses and temperatures with the
BOM, and the warnings and assumptions."""
from __future__ import annotations

from ...core.units import readable, signed_percent
from ...design.bom import SHEETS
from ...design.ratings import SATURATION_MARGIN
from ...design.schema import TABLES
from ...design.spec import OUTPUTS
from .page import esc, inline_svg, note, table, value

#: per design table: the results that are losses, temperatures and thermal ratings (section 6)
LOSSES = {"current_limiter": ("p_r7", "r7_rating", "r7_package", "v_drop", "p_r14", "p_zener", "i_zener_min"),
          "class_d": ("efficiency", "thermal_basis", "p_thermal", "p_dissipation", "theta_sa_required", "t_junction",
                      "needs_heat_sink", "t_junction_no_sink"),
          "converter": ("core_loss", "winding_loss", "temperature_rise", "saturation_margin", "b_peak_min_area")}
#: how the section reads its margins and ratings, as MathML (no script typesets it: the browser does)
MARGIN_MATH = ('<p>A margin is how far the worst corner stays inside its limit, as a fraction of the limit, negative '
               'where it fails (s = +1 below an upper limit, −1 above a lower one); a part\'s rating is used by its '
               'worst-case stress:</p><math display="block"><mi>m</mi><mo>=</mo><mi>s</mi><mfrac><mrow>'
               '<mtext>limit</mtext><mo>&#x2212;</mo><mtext>worst</mtext></mrow><mtext>limit</mtext></mfrac><mo>,</mo>'
               '<mspace width="2em"/><mi>u</mi><mo>=</mo><mfrac><msub><mi>S</mi><mtext>worst</mtext></msub>'
               '<msub><mi>R</mi><mtext>rated</mtext></msub></mfrac></math>')
#: results shown apart from the results table (what binds, in its own line; warnings in section 7)
APART = ("binding", "warnings")


def title(table_name: str) -> str:
    """A design table's heading: its BOM sheet and circuit ("A3 LM4651/LM4652 class-D amplifier [class_d]")."""
    sheet, circuit = SHEETS[table_name]
    return f"{sheet} {circuit} [{table_name}]"


def _param_row(t: str, p, used, given: dict) -> list[str]:
    mine = value(f"spec.{t}.{p.name}", used, p.unit)
    default = "—" if p.default is None else value(f"default.{t}.{p.name}", p.default, p.unit)
    return [f"<code>{esc(p.name)}</code>", mine, default, esc(readable(p.meaning)), "yes" if p.name in given else ""]


def spec_section(ctx) -> str:
    """Section 1: per table the spec asked for, the keys whose value differs from the schema's default (what the
    reader changed), then every key with the value used, folded."""
    out = [f"<p>Tables designed: {', '.join(f'<code>[{esc(t)}]</code>' for t in ctx.designed) or 'none'}"
           + ("" if ctx.spec.written else " (the spec wrote none: all four, at the notes' defaults)")
           + "".join(f"; <code>[{esc(t)}]</code> cannot be met (section 7 says what can)" for t in ctx.unmet) + ". "
           "Values in SI units (speeds in rpm, temperatures in °C, tolerances as fractions).</p>"]
    header = ["key", "value used", "default", "meaning", "written"]
    for t in ctx.spec.asked:
        given, used = ctx.spec[t], ctx.spec.tables[t]
        changed = [p for p in TABLES[t] if p.name in given and used[p.name] != p.default]
        out.append(f"<h3>[{esc(t)}]</h3>")
        if changed:
            out.append(f"<p>What you changed ({len(changed)} of {len(TABLES[t])} keys):</p>")
            out.append(table(header, [_param_row(t, p, used[p.name], given) for p in changed], (1, 2)))
        else:
            out.append("<p>Nothing changed: every key at the handbook's default"
                       + (f" ({len(given)} written with the default value)" if given else "") + ".</p>")
        rest = [_param_row(t, p, used[p.name], given) for p in TABLES[t] if p not in changed]
        out.append(f"<details><summary>The other {len(rest)} keys of [{esc(t)}], as used</summary>"
                   f"{table(header, rest, (1, 2))}</details>")
    return "".join(out)


def _rating_use(r: dict) -> str:
    rating = next((r[k] for k in ("power_rating", "voltage_rating", "current_rating") if r[k]), None)
    if rating is None or r["stress"] is None:
        return ""
    share = f"{r['stress'] / rating:.1%}".replace("%", " %")
    if r["current_rating"] and abs(r["stress"] * SATURATION_MARGIN / rating - 1) < 1e-9:  # the rule, not a part
        return f"{share} (the 1.2 saturation margin: the rating asked is the peak × 1.2)"
    return share


def parts_table(rows: list[dict]) -> str:
    """The BOM rows of one circuit as a table: designator, part, value, tolerance, rating and the worst-case
    stress it carries, the share of the rating that stress uses."""
    tol = lambda x: "" if x is None else f"±{x * 100:g} %"  # noqa: E731
    return table(["designator", "part", "value", "tolerance", "rating (worst-case stress)", "stress / rating"],
                 [[esc(r["designator"]), esc(r["part"]), esc(r["value_text"]), tol(r["tolerance"]),
                   esc(readable(r["rating_text"])), _rating_use(r)] for r in rows], (2, 5))


#: per design table: what its drawing shows that is not a part to fit (the simulation's stimulus, a device's inside)
NOT_FITTED = {
    "current_limiter": "VS is the supply and IM the motor current, ramped from zero to the value shown: the "
                       "simulation's stimulus, not parts to fit; IC2 is the LM358 (A2-IC2), drawn with the offset and "
                       "bias currents the design's corners take. Designators are the BOM's, on sheet A2.",
    "class_d": "VO1 and VO2 stand for the LM4652's two half-bridges (U2, a ±V_s square wave at the switching "
               "frequency, which the LM4651 U1 sets with R_OSC, R1, and R_DLY, R2: not drawn); R_L is the loudspeaker. "
               "Designators are the BOM's, on sheet A3.",
    "converter": "VCC2 is the supply; S1 (the switch, with its V_CE(sat)) and U1 (its comparator, at V12(H)) are "
                 "inside the TCA5600, U1 of the BOM; VC2 stands for C2 held at the regulator's input. Designators "
                 "are the BOM's, on sheet A4.",
    "commutation": "I_CH, I_DIS, V_LOW and V_HIGH are the TDA5144's pin currents and switching levels (typical), not "
                   "parts to fit. Designators are the BOM's, on sheet A1.",
}


def _schematic(t: str, result, warned: list | None = None) -> str:
    from ...spice import designed

    try:
        svg = designed.svg(designed.drawing(t, result))
    except Exception as exc:  # a drawing that fails must not lose the report: say so in its place
        if warned is not None:  # and among the warnings (section 7)
            warned.append((t, f"schematic not drawn: {type(exc).__name__}: {exc}"))
        return note(f"schematic not drawn: {type(exc).__name__}: {exc}")
    return (f'<figure class="schematic">{inline_svg(svg, f"sch-{t}")}<figcaption>The designed circuit with the chosen '
            f"values (the circuit SPICE simulates). {esc(NOT_FITTED.get(t, ''))}</figcaption></figure>")


def results_table(t: str, result) -> str:
    """Every result the design reports (label, value with unit), :data:`~handbook.design.spec.OUTPUTS`' order."""
    return table(["result", "value"], [[esc(readable(o.label)), value(f"{t}.{o.key}", getattr(result, o.key), o.unit)]
                                       for o in OUTPUTS[t] if o.key not in APART], (1,))


def _eva_margins(t: str, result) -> list[tuple[str, str, float, str]]:
    """Every limited quantity of the design's worst-case model at its worst corner (EVA, section 4's): (label, key,
    the margin as a fraction of the limit it is nearest, negative where it fails, that limit's name)."""
    from ...design.worstcase import engine, model

    m = model(t, result)
    eva = engine.corners(m)
    out = []
    for q in m.measures:
        mg = engine.margin(q, float(eva[q.key].min()), float(eva[q.key].max()))
        if mg is not None:
            out.append((q.label, f"eva_margin.{q.key}", mg, q.limit_name))
    return out


def margins_table(t: str, result) -> str:
    """The design's margins (:func:`margins`) as a table: label, value, what each is held to."""
    rows = [[esc(readable(label)), value(f"{t}.{key}", mg, "%"), esc(held_to)] for label, key, mg, held_to in margins(t, result)]
    return table(["margin (at the worst corner)", "value", "held to"], rows, (1,)) if rows else ""


def margins(t: str, result) -> list[tuple[str, str, float, str]]:
    """The design's margins: every limited quantity's at its worst corner (EVA over the worst-case model, the
    inputs section 4 lists), then the margins the design itself states that are not among them; the class-D
    stage's are its own checks (:data:`~handbook.design.class_d.model.CHECKS`, each at its worst corner, which
    section 4's model follows; the heat sink's only where one is given: else it is sized, with no margin).

    Parameters
    ----------
    t : str
        The design table.
    result : Result
        Its design.

    Returns
    -------
    list of tuple
        (label, data key, margin as a fraction of its limit, what it is held to), in the table's order.
    """
    if t == "class_d":
        from ...design.class_d.explain import SHOW
        from ...design.class_d.model import CHECKS

        held = {"oscillator range": "the LM4651's 50 kHz .. 225 kHz", "dead time": "dead_time_min",
                "inductor peak": "i_sat / 1.2 and the LM4651's 10 A limit", "clipping": "p_out",
                "audio band": "droop_max"}
        m = result.figures["margins"]
        given = result.spec["theta_sa_available"] is not None  # else the heat sink is sized: no margin to state
        found = [(k, f"margin.{k}", float(m[k]), held.get(k) or SHOW.get(k, ("", "", "", ""))[3] or "")
                 for k in CHECKS if k != "heat sink" or given]
    else:
        found = _eva_margins(t, result)
        found += [(o.label, o.key, getattr(result, o.key), "the design's own") for o in OUTPUTS[t]
                  if "margin" in o.key and o.unit == "%" and getattr(result, o.key) is not None
                  and not any(abs(getattr(result, o.key) - mg) < 1e-9 for _, _, mg, _ in found)]
    return found


def _figures(t: str, result) -> list[tuple[object, str]]:
    """The figures that show how a design's choice was made (the design chapters' own plots), with captions."""
    from .. import design_plots as plots

    if t == "commutation":
        out = [(plots.timing_ranges(result), "Each capacitor of the series: the speeds it serves at every tolerance "
                                             "corner; the chosen one marked."),
               (plots.timing_swing(result), "The chosen CAP-CD's worst-case swing against speed, inside the window "
                                            "between the switching levels.")]
        if result.cap_st is not None:
            out.append((plots.start_settling(result), "The rotor's rocking after a start pulse against the start "
                                                      "periods CAP-ST gives."))
        return out
    if t == "current_limiter":
        return [(plots.limiter_design_space(result), "Every (R7, R9) pair of the series with R10..R13 as chosen, "
                                                     "coloured by its worst margin at every corner; the chosen "
                                                     "pair starred, the design's min_margin contoured.")]
    if t == "class_d":
        from ...design.class_d.explain import datasheet_application

        ds = datasheet_application(result.spec)
        failed = [k for k, m in ds["margins"].items() if m < -1e-12]
        label = "datasheet's parts" + (f" (fail: {', '.join(failed)})" if failed else " (meet every check)")
        return [(plots.class_d_margins(result, {label: ds["margins"]}),
                 "Each check's margin at its worst corner, beside the datasheet's typical parts judged by the same "
                 "checks on this spec."),
                (plots.class_d_design_space(result), "Around the chosen L and C_BYP: which check fails first.")]
    return []


def choice_figures(t: str, result, warned: list | None = None) -> str:
    """How the choice was made, as inline SVG figures (a plot that fails is named in its place)."""
    import matplotlib.pyplot as plt

    from .page import figure_svg

    try:
        figs = _figures(t, result)
    except Exception as exc:  # a plot that fails must not lose the report: say so in its place
        if warned is not None:  # and among the warnings (section 7)
            warned.append((t, f"figures of how the choice was made not drawn: {type(exc).__name__}: {exc}"))
        return note(f"figures not drawn: {type(exc).__name__}: {exc}")
    out = []
    for k, (fig, caption) in enumerate(figs):
        out.append(figure_svg(fig, f"choice-{t}-{k}", caption))
        plt.close(fig)
    return "".join(out)


def circuits_section(ctx) -> str:
    """Section 2: for each designed circuit its schematic, its parts with ratings, what binds and the margins."""
    out = [MARGIN_MATH]
    for t, result in ctx.designed.items():
        sheet = SHEETS[t][0]
        out += [f'<h3 id="circuit-{t}">{esc(title(t))}</h3>', _schematic(t, result, ctx.spice_warnings),
                f"<p><b>What binds:</b> {esc(str(result.binding))}</p>" + _least(t, result),
                "<h4>Chosen parts and their ratings</h4>", parts_table([r for r in ctx.bom if r["sheet"] == sheet]),
                "<h4>Margins</h4>", margins_table(t, result) or note("this design states no margin as a fraction"),
                "<h4>How the choice was made</h4>",
                choice_figures(t, result, ctx.spice_warnings) or note("every candidate core is evaluated: the table "
                                                                      "above is the choice"),
                f"<details open><summary>Every result of [{esc(t)}]</summary>{results_table(t, result)}</details>"]
    return "".join(out)


def _least(t: str, result) -> str:
    """The least margin at its worst corner, named beside what binds the choice (they need not be the same: a
    series pick can leave a check closer to its limit than the one that decided)."""
    found = margins(t, result)
    if not found:
        return ""
    label, _key, mg, held_to = min(found, key=lambda f: f[2])
    return (f"<p><b>Least margin:</b> {esc(readable(label))}, {esc(signed_percent(mg))} at its worst corner"
            + (f" (held to {esc(held_to)})" if held_to else "") + "</p>")


def losses_section(ctx) -> str:
    """Section 6: losses, temperatures and thermal ratings of each design (R7 in a stall, the LM4652 at its
    thermal basis, the converter's coil), the ambient each is taken at, then the BOM."""
    out = []
    for t, result in ctx.designed.items():
        out.append(f"<h3>{esc(title(t))}</h3>")
        keys = LOSSES.get(t)
        if not keys:
            out.append(note("the timing capacitors carry no loss worth stating (pin currents of microamps)"))
            continue
        units = {o.key: o for o in OUTPUTS[t]}
        rows = [[esc(readable(units[k].label)), value(f"{t}.{k}", getattr(result, k), units[k].unit)] for k in keys]
        if "t_ambient" in result.spec:
            rows.insert(0, ["ambient (spec)", value(f"spec.{t}.t_ambient", result.spec["t_ambient"], "C")])
        out.append(table(["loss or temperature", "value"], rows, (1,)))
    out.append("<h3>Bill of materials</h3>")
    out.append(_bom_html(ctx.bom) if ctx.bom else note("nothing designed"))
    return "".join(out)


def _bom_html(rows: list[dict]) -> str:
    tol = lambda x: "" if x is None else f"±{x * 100:g} %"  # noqa: E731
    return table(["designator", "qty", "part", "value", "tolerance", "rating (worst-case stress)",
                  "technology; package; tempco", "reason"],
                 [[esc(r["designator"]), str(r["quantity"]), esc(r["part"]), esc(r["value_text"]), tol(r["tolerance"]),
                   esc(r["rating_text"]), esc("; ".join(x for x in (r["technology"], r["package"], r["tempco"]) if x)),
                   esc(r["reason"])] for r in rows], (1, 3))


def assumptions(ctx) -> list[tuple[str, str, str]]:
    """(table.key, value used, why) of every key of the asked tables whose default is an assumption of the
    handbook's (the schema says so), with the value this spec used."""
    out = []
    for t in ctx.spec.asked:
        for p in TABLES[t]:
            why = p.cite if "assumption" in p.cite else p.meaning if "assumption" in p.meaning else ""
            if why:
                out.append((f"{t}.{p.name}", value(f"spec.{t}.{p.name}", ctx.spec.tables[t][p.name], p.unit), why))
    return out


def notes_section(ctx) -> str:
    """Section 7: every design's warnings, SPICE's, the assumptions made, and what the report was made from."""
    out = ["<h3>Warnings</h3>"]
    warned = [(t, f"cannot be met, so not designed: {why}") for t, why in ctx.unmet.items()]
    warned += [(t, w) for t, r in ctx.designed.items() for w in r.warnings]
    warned += list(dict.fromkeys(ctx.spice_warnings))  # once each, though a section be written twice
    out.append("<ul>" + "".join(f'<li class="warn"><code>[{esc(t)}]</code> {esc(w)}</li>' for t, w in warned) + "</ul>"
               if warned else "<p>None: no design warned.</p>")
    out.append("<h3>Assumptions made</h3><p>Keys whose default is the handbook's assumption, not a datasheet's "
               "figure (check them against your parts), with the value this report used:</p>")
    out.append(table(["key", "value used", "why"],
                     [[f"<code>{esc(k)}</code>", v, esc(readable(w))] for k, v, w in assumptions(ctx)], (1,)))
    out.append("<p>Further: the designs take every part at its tolerance corners and the datasheets' limits; "
               "SPICE models are written from the datasheets' figures (no vendor macro-model).</p>")
    tr = ctx.trace
    out.append(table(["made from", ""], [["handbook version", esc(tr["version"])], ["spec file", esc(tr["spec_file"])],
                                         ["spec SHA-256 (the spec as read, defaults filled in)", esc(tr["spec_sha256"])],
                                         ["tables asked", esc(", ".join(ctx.spec.asked))]]))
    return "".join(out)
