"""``python -m handbook``: the command-line face of the handbook's registries."""
from __future__ import annotations

import argparse
import json
import sys

from . import catalog


def _table(rows: list[dict], cols: list[tuple[str, str, int]]) -> str:
    out = ["  ".join(title.ljust(w) for _, title, w in cols).rstrip()]
    out.append("  ".join("-" * w for _, _, w in cols))
    for r in rows:
        cells = []
        for key, _, w in cols:
            v = r[key]
            v = f"{v:.6g}" if isinstance(v, float) else str(v)
            cells.append(v[:w].ljust(w))
        out.append("  ".join(cells).rstrip())
    return "\n".join(out)


def cmd_examples(args) -> int:
    rows = catalog.claims()
    if args.json:
        keys = ("id", "source", "quantity", "unit", "printed", "computed", "status", "reason", "relation", "basis")
        print(json.dumps([{k: r[k] for k in keys} for r in rows], indent=1))
    else:
        print(_table(rows, [("id", "id", 26), ("printed_text", "printed", 12), ("computed", "computed (SI)", 13),
                            ("unit", "unit", 6), ("status", "status", 12), ("reason", "reason", 90)]))
    return 0


def cmd_equations(args) -> int:
    rows = catalog.equation_summaries()
    if args.json:
        keys = ("id", "source", "title", "printed_latex", "derived_latex", "agrees", "dimensions_ok", "law", "note")
        print(json.dumps([{k: r[k] for k in keys} for r in rows], indent=1))
    else:
        print(_table(rows, [("id", "id", 24), ("source", "source", 34), ("agrees", "agrees", 6),
                            ("dimensions_ok", "dims", 5), ("note", "note", 100)]))
    return 0


def cmd_design(args) -> int:
    from .core import InputError
    from .design import bom
    from .design import spec as specmod
    from .design.solvers import Infeasible

    try:
        spec = specmod.load(args.spec)
        if args.spice:
            from .spice import runner

            if runner.available() is None:
                print(f"error: --spice: {runner.why_unavailable()}", file=sys.stderr)
                return 4
        result = specmod.run(spec)
    except InputError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    except Infeasible as exc:
        table = exc.table
        print(f"cannot be met [{table}]: {exc}", file=sys.stderr)
        if args.json:
            print(json.dumps({"infeasible": {"table": table, "message": str(exc), "achievable": exc.achievable}},
                             indent=1, default=float))
        return 3
    out = specmod.summary(result)
    if args.spice:
        from .spice import checks as spice

        try:
            for table, figures in spice.confirm(result).items():
                out[table]["spice"] = figures
        except (spice.SpiceUnavailable, spice.SpiceError) as exc:
            print(f"error: --spice: {exc}", file=sys.stderr)
            return 4
    if args.bom:
        try:
            bom.write(bom.rows(result), args.bom)
        except OSError as exc:
            print(f"error: cannot write {args.bom}: {exc.strerror}", file=sys.stderr)
            return 2
    if args.json:
        print(json.dumps(out, indent=1))
    else:
        from .design.schema import OUTPUTS
        from .report.tables import shown_value

        for table, values in out.items():
            print(f"[{table}]")
            for o in OUTPUTS[table]:
                print(f"  {o.label:45s} {shown_value(values[o.key], o.unit)}")
    return 0


def cmd_spice(args) -> int:
    from .spice import checks as spice

    try:
        rows = spice.rows()
    except (spice.SpiceUnavailable, spice.SpiceError) as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 4
    keys = ("id", "circuit", "quantity", "unit", "equation", "spice", "rel_diff", "agrees")
    if args.json:
        print(json.dumps([{k: r[k] for k in keys} for r in rows], indent=1))
    else:
        from .report.tables import eng

        for r in rows:
            print(f"{r['id']:34s} {r['quantity'][:38]:38s} {eng(r['equation'], r['unit']):>12s} "
                  f"{eng(r['spice'], r['unit']):>12s} {r['rel_diff']:8.2%}  {'agrees' if r['agrees'] else 'DIFFERS'}")
    return 0 if all(r["agrees"] for r in rows) else 1


def _spec_help() -> str:
    """The specification's keys, from the one schema (handbook.design.schema)."""
    from .design.schema import key_rows

    lines = ["SPEC.toml keys (SI units; a missing table or key takes the notes' value):"]
    table = None
    for t, key, default, unit, meaning in key_rows():
        if t != table:
            lines.append(f"  [{t}]")
            table = t
        lines.append(f"    {key} = {default}  ({unit + ', ' if unit not in ('', '1') else ''}{meaning})")
    lines.append("exit codes: 0 designed, 2 invalid input, 3 a valid spec nothing can meet, 4 --spice could not simulate "
                 "(ngspice missing or a netlist it refused)")
    return "\n".join(lines)


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(prog="python -m handbook", description=__doc__)
    sub = parser.add_subparsers(dest="command", required=True)
    p = sub.add_parser("examples", help="every numeric example: printed, recomputed, status")
    p.add_argument("--json", action="store_true", help="a JSON list; values in SI base units")
    p.set_defaults(func=cmd_examples)
    p = sub.add_parser("equations", help="every equation: printed and derived forms, agreement")
    p.add_argument("--json", action="store_true")
    p.set_defaults(func=cmd_equations)
    p = sub.add_parser("design", help="choose CAP-CD, R7/R9 and the class-D switching frequency for a spec",
                       epilog=_spec_help(), formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("spec", help="TOML file with optional [commutation], [current_limiter], [class_d] tables")
    p.add_argument("--json", action="store_true", help="one JSON object, SI units")
    p.add_argument("--bom", metavar="FILE.csv", help="also write a bill of materials (written only on success)")
    p.add_argument("--spice", action="store_true",
                   help="also simulate the chosen parts at their worst-case corners with ngspice (adds 'spice' to each table)")
    p.set_defaults(func=cmd_design)
    p = sub.add_parser("spice", help="every circuit's SPICE checks: equation against ngspice")
    p.add_argument("--json", action="store_true", help="a JSON list of id, circuit, quantity, equation, spice, rel_diff, agrees")
    p.set_defaults(func=cmd_spice)
    args = parser.parse_args(argv)
    return args.func(args)


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
