"""python -m handbook: the command-line face of the handbook's registries, designs and circuits."""
from __future__ import annotations

import argparse
import json
import sys

from . import catalog
from .cli_text import fit_table, spec_help, template

_spec_help = spec_help  # the schema test reads the help through this name


class _BadStatus(ValueError):
    """--status names no status the command knows."""


def _filtered(rows: list[dict], args, status_of, statuses) -> list[dict]:
    """Rows whose source contains --source (any case) and whose status is --status (any case); a --status
    that is none of ``statuses`` (nor of the rows' own) raises _BadStatus naming the valid ones."""
    if args.source:
        every = rows
        rows = [r for r in rows if args.source.lower() in (r["source"] + " " + r["id"]).lower()]
        if not rows:
            docs = sorted({r["source"].split()[0].rstrip(",") for r in every})
            raise _BadStatus(f"--source {args.source!r} matches no entry of `{args.command}`; "
                             f"the documents are {', '.join(docs)}")
    if args.status:
        valid = list(dict.fromkeys([*statuses, *(status_of(r) for r in rows)]))
        if args.status.lower() not in valid:
            raise _BadStatus(f"--status {args.status!r} is not a status of `{args.command}`; "
                             f"valid: {', '.join(valid)}")
        rows = [r for r in rows if status_of(r) == args.status.lower()]
    return rows


def _usage_error(args, message: str) -> int:
    """Exit 2 with ``message`` on stderr and, with --json, a JSON error object on stdout (as `design` does)."""
    print(f"error: {message}", file=sys.stderr)
    if args.json:
        print(json.dumps({"error": {"exit": 2, "message": message}}, indent=1))
    return 2


def _equation_status(r: dict) -> str:
    """'empirical' for a fitted equation (no symbolic check behind it), else 'agrees' (a printed constant rounded
    counts: :attr:`~handbook.core.equation.Equation.rounded_constants`) or 'differs'."""
    return "empirical" if r.get("empirical") else "agrees" if r["agrees"] or r.get("rounded_constants") else "differs"


def _equation_check(r: dict) -> str:
    """The equations table's check column: the symbolic check, or for an empirical equation how it fares
    against the datasheet's own figures."""
    if r.get("empirical"):
        return "empirical: reproduces figures" if r["agrees"] else "empirical: MISSES figures"
    return "agrees" if r["agrees"] else "agrees (constant rounded)" if r.get("rounded_constants") else "DIFFERS"


def cmd_examples(args) -> int:
    from .report.tables import BADGE

    try:
        rows = _filtered(catalog.claims(), args, lambda r: r["status"], BADGE)
    except _BadStatus as exc:
        return _usage_error(args, str(exc))
    if args.json:
        keys = ("id", "source", "quantity", "unit", "printed", "computed", "status", "reason", "relation", "basis")
        print(json.dumps([{k: r[k] for k in keys} for r in rows], indent=1))
        return 0
    from .report.tables import _in_printed_unit

    table = []
    for r in rows:
        printed, computed = _in_printed_unit(r["printed_text"], r["computed"]) if r["printed_text"] else ("", "")
        table.append([r["id"], printed, computed, r["status"], r["reason"]])
    print(fit_table(table, ["id", "printed", "recomputed", "status", "why"], [24, 12, 12, 12]))
    return 0


def cmd_equations(args) -> int:
    try:
        rows = _filtered(catalog.equation_summaries(), args, _equation_status, ("agrees", "differs", "empirical"))
    except _BadStatus as exc:
        return _usage_error(args, str(exc))
    if args.json:
        keys = ("id", "source", "title", "printed_latex", "derived_latex", "agrees", "rounded_constants", "dimensions_ok",
                "law", "note", "empirical", "fitted_to")
        # "check" is the text's check column ("agrees (constant rounded)" where only rounded constants differ;
        # "agrees" stays the strict symbolic verdict)
        print(json.dumps([{**{k: r[k] for k in keys}, "check": _equation_check(r)} for r in rows], indent=1))
        return 0
    table = [[r["id"], r["source"], _equation_check(r), "ok" if r["dimensions_ok"] else "ERROR",
              r["note"] or r["title"]] for r in rows]
    print(fit_table(table, ["id", "source", "check", "dims", "note"], [22, 22, 12, 5]))
    return 0


def cmd_errata(args) -> int:
    from .report.tables import ERRATA_KINDS

    if args.reading_notes:
        try:
            notes = _filtered(catalog.reading_notes(), args, lambda r: "reading note", ("reading note",))
        except _BadStatus as exc:
            return _usage_error(args, str(exc))
        if args.json:
            print(json.dumps(notes, indent=1))
        else:
            print(fit_table([[r["id"], r["source"], f"{r['what']}: {r['note_text']}"] for r in notes],
                            ["id", "source", "reading note"], [22, 22]))
        return 0
    try:
        rows = _filtered([{**r, "status": r["kind"]} for r in catalog.errata()], args, lambda r: r["kind"],
                         ERRATA_KINDS)
    except _BadStatus as exc:
        return _usage_error(args, str(exc))
    keys = ("id", "source", "kind", "confidence", "what", "printed", "computed", "evidence", "consequence", "quote",
            "charitable", "places")
    out = [{**{k: r.get(k) for k in keys}, "computed": r.get("recomputed"), "unit": r.get("unit")} for r in rows]
    if args.json:
        print(json.dumps(out, indent=1, default=str))
        return 0
    table = [[r["id"], r["source"], f"{r['kind']}, {r['confidence']}",
              r["what"] + (f": {r['consequence']}" if r["consequence"] else "")] for r in rows]
    print(fit_table(table, ["id", "source", "kind, confidence", "what, and what it costs"], [24, 20, 16]))
    return 0


def _design_error(args, code: int, message: str, extra: dict | None = None) -> int:
    print(f"error: {message}", file=sys.stderr)
    if args.json:
        print(json.dumps({"error": {"exit": code, "message": message, **(extra or {})}}, indent=1, default=float))
    return code


def cmd_design(args) -> int:
    from .core import InputError
    from .design import spec as specmod
    from .design.solvers import Infeasible

    if args.template:
        print(template())
        return 0
    if args.spec is None:
        return _design_error(args, 2, "give a SPEC.toml (or --template to print one with every key)")
    try:
        spec = specmod.load(args.spec)
        if args.spice:
            from .spice import runner

            if runner.available() is None:
                return _design_error(args, 4, f"--spice: {runner.why_unavailable()}")
        results = specmod.run_each(spec)
    except InputError as exc:
        return _design_error(args, 2, str(exc))
    failed = {t: r for t, r in results.items() if isinstance(r, Infeasible)}
    designed = {t: r for t, r in results.items() if t not in failed}
    out = specmod.summary(designed)
    for table, exc in failed.items():
        print(f"cannot be met [{table}]: {exc}", file=sys.stderr)
        out[table] = {"infeasible": {"table": table, "message": str(exc), "achievable": exc.achievable}}
    if failed:  # the first table that cannot be met, where scripts written for one look for it
        out = {"infeasible": next(iter(out[t]["infeasible"] for t in failed)), **out}
    if args.spice:
        from .spice import checks as spice

        try:
            for table, figures in spice.confirm(designed).items():
                out[table]["spice"] = figures
                for warning in spice.warnings(table, figures):
                    print(f"warning: --spice: [{table}] {warning}", file=sys.stderr)
        except (spice.SpiceUnavailable, spice.SpiceError) as exc:
            return _design_error(args, 4, f"--spice: {exc}")
    if args.worstcase:  # the report's section 4, as numbers: the same lot (N boards, SEED)
        from .design import worstcase

        for table, result in designed.items():
            out[table]["worstcase"] = worstcase.as_json(worstcase.analyse(table, result))
    for option, write in (("bom", _write_bom), ("netlist", _write_netlists), ("schematic", _schematics)):
        if getattr(args, option):  # the tables the spec asked for that designed; what was left out is said
            code = write(args, spec, designed, failed, out)
            if code:
                return code
    if args.json:
        print(json.dumps({**out, **specmod.traced(spec)}, indent=1, default=float))
    else:
        _print_designs(out, failed, spec.asked)
    return 3 if failed else 0


def _write_bom(args, spec, designed: dict, failed: dict, out: dict) -> int:
    """--bom: the BOM of the tables the spec asked for that designed, written atomically; 0, or 2 (unwritable)."""
    from .design import bom
    from .design.spec import TABLES

    asked = spec.asked
    rows = bom.rows({t: r for t, r in designed.items() if t in asked})
    left = [t for t in asked if t in failed]
    for t in left:
        print(f"bom: [{t}] left out: it cannot be met (above)", file=sys.stderr)
    if rows:
        try:
            bom.write(rows, args.bom)
        except OSError as exc:
            return _design_error(args, 2, f"cannot write {args.bom}: {exc.strerror}")
    else:
        print(f"bom: nothing designed, {args.bom} not written", file=sys.stderr)
    out["bom"] = {"rows": rows, "units": bom.UNITS, "left_out": left, "not_asked": [t for t in TABLES if t not in asked]}
    return 0


def _write_netlists(args, spec, designed: dict, failed: dict, out: dict) -> int:
    """--netlist DIR: one plain SPICE deck per table the spec asked for that designed (the folder made if
    missing), every file or none; 0, or 2 when DIR cannot be written (naming it; nothing is left behind)."""
    from pathlib import Path

    from .design.spec import TABLES, traced
    from .spice import netlist

    folder, asked = Path(args.netlist), spec.asked
    left = [t for t in asked if t in failed]
    for t in left:
        print(f"netlist: [{t}] not written: it cannot be met (above)", file=sys.stderr)
    decks = netlist.decks({t: r for t, r in designed.items() if t in asked})
    meta = traced(spec)
    texts = {d.name: d.text(meta) for d in decks}
    if texts and folder.exists() and not folder.is_dir():
        return _design_error(args, 2, f"--netlist: {folder} is a file, not a folder; nothing written")
    if texts:
        try:
            netlist.write(texts, folder)
        except OSError as exc:
            return _design_error(args, 2, f"--netlist: cannot write the netlists into {folder}: "
                                 f"{exc.strerror or exc}; nothing written")
    else:
        print(f"netlist: nothing designed, {folder} not written", file=sys.stderr)
    out["netlist"] = {"folder": str(folder), "files": list(texts), "left_out": left,
                      "not_asked": [t for t in TABLES if t not in asked]}
    return 0


def _schematics(args, spec, designed: dict, failed: dict, out: dict) -> int:
    """--schematic DIR: one SVG per designed table the spec asked for (all or none written); 0, or 2 on a
    folder that cannot be written."""
    from .spice import designed as drawings

    tables = {t: r for t, r in designed.items() if t in spec.asked}
    for t in (t for t in spec.asked if t in failed):
        print(f"schematic: [{t}] left out: it cannot be met (above)", file=sys.stderr)
    try:
        paths = drawings.write_svgs(tables, args.schematic) if tables else []
    except OSError as exc:
        return _design_error(args, 2, f"cannot write the schematics to {args.schematic}: {exc.strerror or exc}")
    out["schematic"] = {"folder": str(args.schematic), "files": [str(p) for p in paths]}
    return 0


def _print_designs(out: dict, failed: dict, asked: tuple = ()) -> None:
    from .cli_text import width, wrap
    from .design.spec import OUTPUTS
    from .report.tables import shown_value

    total = width()
    lw = min(60, total // 2 - 4, max(len(o.label) for outs in OUTPUTS.values() for o in outs))
    vw = max(16, total - lw - 4)

    def line(label: str, value: str) -> None:
        """A label and its value, both wrapped at words to fit the terminal (the value in its column)."""
        labels, values = wrap(label, lw), wrap(value, vw)
        for k in range(max(len(labels), len(values))):
            left = labels[k] if k < len(labels) else ""
            print(f"  {left.ljust(lw)}  {values[k] if k < len(values) else ''}".rstrip())

    for table in OUTPUTS:
        print(f"[{table}]" + ("" if not asked or table in asked else "  (not in your spec: the notes' defaults)"))
        if table in failed:
            for text in wrap(f"cannot be met: {failed[table]}", total - 2):
                print(f"  {text}")
            continue
        for o in OUTPUTS[table]:
            line(o.label, shown_value(out[table][o.key], o.unit))
        for key, value in out[table].get("spice", {}).items():
            line(f"SPICE: {key}", _spice_value(key, value))
        if "worstcase" in out[table]:
            wc = out[table]["worstcase"]
            line(f"worst case: Monte Carlo yield, {wc['n']} boards (seed {wc['seed']})",
                 ", ".join([f"all limits {wc['yield_all']:.4%}"] + [f"{k} {v:.4%}" for k, v in wc["yields"].items()]))


def _spice_value(key: str, value) -> str:
    """A --spice figure as a person reads it: its unit from the check it belongs to (:data:`~.spice.checks.CONFIRM`),
    a supply in V, an expected difference signed in per cent, a step bound as ± per cent, counts, yes/no, lists."""
    from .core.units import eng, signed_percent
    from .spice.checks import CONFIRM

    units = {k: unit for rows in CONFIRM.values() for _q, unit, k, *_ in rows}
    if isinstance(value, bool) or key in ("ok", "window_reached", "meets_spec", "agrees"):
        return "yes" if value else "no"
    if isinstance(value, (list, tuple)):  # differs, misses: the keys or the sentences
        return "; ".join(map(str, value)) or "none"
    if key.startswith("corners"):
        return f"{int(value):d}" + (" simulated" if key == "corners" else " searched")
    if key.endswith("_expected"):
        return signed_percent(value) + " (what the circuit's physics predicts against the equations)"
    if key.endswith("_rtol"):
        return f"±{value * 100:.2g} %"
    if key.endswith("_supply"):
        return eng(value, "V")
    base = key.removesuffix("_equation")
    unit = units.get(base) or ("A" if base.startswith("i_") else "Hz" if base.startswith("f_") else "V")
    return eng(value, unit) + (" rms" if base.startswith("ripple") else "")


def cmd_report(args) -> int:
    from .report.design_report.command import run

    return run(args)


def cmd_spice(args) -> int:
    from .spice import checks as spice

    try:
        rows = spice.rows()
    except (spice.SpiceUnavailable, spice.SpiceError) as exc:
        print(f"error: {exc}", file=sys.stderr)
        if args.json:  # a script reading stdout gets the reason too, as design --spice --json gives it
            print(json.dumps({"error": {"exit": 4, "message": str(exc),
                                        "skipped": isinstance(exc, spice.SpiceUnavailable)}}, indent=1))
        return 4
    keys = ("id", "circuit", "quantity", "unit", "equation", "spice", "rel_diff", "expected_difference", "residual",
            "agrees", "rtol", "why", "kind", "verdict", "faults_seen")
    for r in rows:
        if "error" in r:
            print(f"error: {r['error']}", file=sys.stderr)
    if args.json:
        print(json.dumps([{k: (None if isinstance(r.get(k), float) and r[k] != r[k] else r.get(k)) for k in keys}
                          | ({"error": r["error"]} if "error" in r else {}) for r in rows], indent=1))
    else:
        from .core.units import eng, signed_percent

        unit = {r["unit"]: r["unit"].replace("ohm", "Ω") for r in rows}
        print(fit_table([[r["id"], eng(r["equation"], unit[r["unit"]]) if "error" not in r else "—",
                          eng(r["spice"], unit[r["unit"]]) if "error" not in r else "—",
                          signed_percent((r["spice"] - r["equation"]) / r["equation"]) if "error" not in r else "—",
                          signed_percent(r["expected_difference"]) if "error" not in r else "—",
                          r.get("error") or (r["verdict"] if r["agrees"] else "DIFFERS") + ": " + r["quantity"]]
                         for r in rows],
                        ["id", "equation", "SPICE", "diff", "expected", "verdict: quantity"], [30, 12, 12, 8, 8]))
    return 0 if all(r["agrees"] for r in rows) else 1


def cmd_render(args) -> int:
    from . import render
    from .core import InputError

    if bool(args.notebook) == bool(args.spec):
        print("render: give either a notebook or --spec SPEC.toml (one of them)", file=sys.stderr)
        return 2
    warned: list[str] = []
    try:
        page = render.render(args.notebook, args.out, warned) if args.notebook else render.render_spec(args.spec, args.out)
    except InputError as exc:
        print(exc, file=sys.stderr)
        return 2
    for line in warned:
        print("warning:", line, file=sys.stderr)
    print(page)
    return 0


def cmd_rerun(args) -> int:
    from . import render
    from .core import InputError

    try:
        page = render.rerun(args.chapter, [tuple(p) for p in args.param or []], args.out)
    except render.CannotBeMet as exc:
        print(exc, file=sys.stderr)
        return 3
    except InputError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    print(page)
    return 0


def _filters(p, statuses: str) -> None:
    p.add_argument("--json", action="store_true", help="a JSON list; values in SI base units")
    p.add_argument("--source", metavar="TEXT", help="only entries whose source or id contains TEXT (e.g. AN94002)")
    p.add_argument("--status", metavar="STATUS", help=f"only entries with this status, any case: {statuses} "
                   "(another exits 2, listing the valid ones)")


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(prog="python -m handbook", description=__doc__.split(":", 1)[1].strip())
    sub = parser.add_subparsers(dest="command", required=True)
    p = sub.add_parser("examples", help="every printed number: printed, recomputed (in the printed unit), status")
    _filters(p, "exact, rounding, truncated, 'rounded intermediate', 'bound met', conservative, misprint, inconsistent, "
             "'wrong method', n/a")
    p.set_defaults(func=cmd_examples)
    p = sub.add_parser("equations", help="every equation: printed and derived forms, agreement")
    _filters(p, "agrees, differs (derived equations), empirical (fitted to a datasheet's figures)")
    p.set_defaults(func=cmd_equations)
    p = sub.add_parser("errata", help="every erratum: what the source says, what holds, the evidence")
    _filters(p, "the kind: misprint, inconsistent, 'wrong method', equation, text")
    p.add_argument("--reading-notes", action="store_true",
                   help="list the reading notes instead: what is not an error of the source (lost OCR, reconstructions, "
                   "missing public data, the book's assumptions)")
    p.set_defaults(func=cmd_errata)
    p = sub.add_parser("design", help="choose the timing capacitors, the limiter network, the class-D parts and "
                       "the TCA5600 converter's coil",
                       epilog=spec_help(), formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("spec", nargs="?", help="TOML file with optional [commutation], [current_limiter], [class_d], "
                   "[converter] tables")
    p.add_argument("--json", action="store_true", help="one JSON object, SI units")
    p.add_argument("--bom", metavar="FILE.csv",
                   help="also write a bill of materials (CSV; the same rows in --json): the tables the spec wrote (all "
                   "four if none), each part with its rating; a table that cannot be met is left out and named")
    p.add_argument("--netlist", metavar="DIR",
                   help="also write each designed circuit as a plain SPICE deck into DIR (made if missing): one .cir "
                   "per table the spec wrote (all four if none; CAP-ST and CAP-TI in decks of their own), the "
                   "designed parts at their nominal values, a header naming the design, the handbook's version, the "
                   "spec's SHA-256 and every part, one analysis and .meas lines giving the design's figures; no "
                   "ngspice-only syntax, every model in the file. A table that cannot be met is not written and "
                   "named; an unwritable DIR exits 2 with nothing written")
    p.add_argument("--schematic", metavar="DIR",
                   help="also draw each designed circuit with its chosen values, one SVG per table in DIR (made if "
                   "missing): the tables the spec wrote (all four if none), as --bom")
    p.add_argument("--worstcase", action="store_true",
                   help="also run the worst-case analysis the report's section 4 shows (extreme value, root-sum-square, "
                        "a seeded Monte Carlo of 100 000 boards: yields, sensitivities; adds 'worstcase' to each table)")
    p.add_argument("--spice", action="store_true",
                   help="also simulate the chosen parts at their worst-case corners with ngspice (adds 'spice' to each table)")
    p.add_argument("--template", action="store_true", help="print a complete spec, every key commented, and stop")
    p.set_defaults(func=cmd_design)
    p = sub.add_parser("report", help="one self-contained file a reviewer can sign (HTML or PDF): the spec, each "
                       "designed circuit, its calculations, worst cases, SPICE, losses, BOM, warnings")
    p.add_argument("spec", help="the TOML spec, as `design` reads it (exit 2 on a bad key or value, 3 when a table "
                   "cannot be met; nothing is written then)")
    p.add_argument("-o", "--out", required=True, metavar="FILE.html|FILE.pdf",
                   help="the report: .html (opens offline) or .pdf (printed by Chromium; exit 4 without it)")
    p.add_argument("--no-spice", action="store_true", help="leave out the SPICE confirmation (faster)")
    p.set_defaults(func=cmd_report)
    p = sub.add_parser("spice", help="every circuit's SPICE checks: equation against ngspice")
    p.add_argument("--json", action="store_true",
                   help="a JSON list of id, circuit, quantity, equation, spice, rel_diff, expected_difference, residual, "
                        "agrees, rtol, why, kind, verdict, faults_seen")
    p.set_defaults(func=cmd_spice)
    p = sub.add_parser("render", help="render a re-run chapter (or 'Design your own' on a spec) to a web page with "
                       "the book's look, offline")
    p.add_argument("notebook", nargs="?", help="an executed notebook, e.g. what papermill wrote")
    p.add_argument("--spec", metavar="SPEC.toml", help="run 'Design your own' on this spec, then render it")
    p.add_argument("-o", "--out", metavar="DIR", help="where the page goes (default: beside the input, NAME_html)")
    p.set_defaults(func=cmd_render)
    p = sub.add_parser("rerun", help="re-run a chapter with other values (checked before anything runs) and render it")
    p.add_argument("chapter", help="the chapter, e.g. design/cap_cd or cap_cd (every chapter with a parameters cell)")
    p.add_argument("-p", "--param", nargs=2, action="append", metavar=("NAME", "VALUE"),
                   help="a parameter and its value (a number, None, or text), as often as needed")
    p.add_argument("-o", "--out", metavar="DIR", help="folder for the page (default: <chapter>_html here)")
    p.set_defaults(func=cmd_rerun)
    args = parser.parse_args(argv)
    return args.func(args)


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
