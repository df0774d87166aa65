"""Text the command line prints for people: tables that fit the terminal (the last column wrapped at word
boundaries, never cut mid-word), the spec template, and plain-text help built from the one schema."""
from __future__ import annotations

import shutil
import textwrap


def width() -> int:
    """The terminal's width (80 when it cannot be told, e.g. in a pipe: then $COLUMNS or 100)."""
    return max(60, shutil.get_terminal_size((100, 24)).columns)


def fit_table(rows: list[list[str]], header: list[str], fixed: list[int]) -> str:
    """Columns of the given widths, the last one taking what is left of the terminal, wrapped."""
    total = width()
    last = max(20, total - sum(fixed) - 2 * len(fixed))

    def line(cells: list[str]) -> list[str]:
        wrapped = textwrap.wrap(cells[-1], last) or [""]
        first = "  ".join(c.ljust(w) if len(c) <= w else c[: w - 1] + "…" for c, w in zip(cells[:-1], fixed))
        pad = " " * (sum(fixed) + 2 * len(fixed))
        return [(first + "  " + wrapped[0]).rstrip()] + [(pad + w).rstrip() for w in wrapped[1:]]

    out = line(header)
    out.append("  ".join("-" * w for w in fixed) + "  " + "-" * min(last, 40))
    for r in rows:
        out.extend(line(r))
    return "\n".join(out)


def template() -> str:
    """A complete spec: every table and key, each commented with its unit, range and meaning, set to its
    default (keys without one are commented out: leaving them out is their default)."""
    from .design.schema import TABLES

    lines = ["# handbook design specification: every key at its default (SI units).",
             "# Feed it back unchanged and it designs the notes' own examples; change what differs for your board.",
             "# python -m handbook design SPEC.toml [--json] [--bom bom.csv] [--spice]", ""]
    for table, params in TABLES.items():
        lines.append(f"[{table}]")
        for p in params:
            unit = "" if p.unit in ("", "1") else f" [{p.unit}]"
            note = f"{p.meaning}{unit}; {p.range_text}" + (f"; {p.cite}" if p.cite else "")
            for i, text in enumerate(textwrap.wrap(note, 100)):
                lines.append(("# " if i == 0 else "#   ") + text)
            if p.default is None:
                lines.append(f"# {p.name} =")
            else:
                value = f'"{p.default}"' if isinstance(p.default, str) else repr(p.default)
                lines.append(f"{p.name} = {value}")
        lines.append("")
    return "\n".join(lines)


def spec_help() -> str:
    """The keys of the specification, from the one schema (plain text, no markup)."""
    from .design.schema import key_rows

    lines = ["SPEC.toml keys (SI units; a missing table or key takes the notes' value;",
             "`python -m handbook design --template` prints a complete spec with every key explained):"]
    table = None
    for t, key, default, unit, meaning in key_rows():
        if t != table:
            lines.append(f"  [{t}]")
            table = t
        lines.append(f"    {key} = {default}  ({unit + ', ' if unit not in ('', '1') else ''}{meaning})")
    lines.append("exit codes: 0 designed, 2 invalid input, 3 a valid spec nothing can meet (the other tables are "
                 "still reported), 4 --spice could not simulate (ngspice missing or a netlist it refused)")
    return "\n".join(lines)
