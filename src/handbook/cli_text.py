"""Text the command line prints for people: tables that fit the terminal (the last column wrapped at word
boundaries, never cut mid-word), the spec template, and plain-text help built from the one schema."""
from __future__ import annotations

import re
import shutil
import textwrap


def width() -> int:
    """The terminal's width: $COLUMNS, else the terminal's own, else 100 (e.g. in a pipe); at least 40."""
    return max(40, shutil.get_terminal_size((100, 24)).columns)


_GLUE = "\x1f"  # stands for a space that must not break (between a number and its unit) while wrapping
_NUMBER_UNIT = re.compile(r"(?<=\d) (?=[A-Za-zµΩ%°][A-Za-z/Ω]{0,3}(?![\w/]))")


def wrap(text: str, w: int) -> list[str]:
    """``text`` in lines of at most ``w`` characters, broken at spaces (a number stays with its unit); a
    word is cut only when it alone is longer than ``w``."""
    words = _NUMBER_UNIT.sub(_GLUE, str(text)).split(" ")
    # a number with its unit wider than the column: let them part rather than cut one of them
    glued = " ".join(word.replace(_GLUE, " ") if len(word) > w else word for word in words)
    lines = textwrap.wrap(glued, w, break_on_hyphens=False) or [""]
    return [line.replace(_GLUE, " ") for line in lines]


def _widths(columns: list[list[str]], fixed: list[int], total: int) -> list[int]:
    """Each column's width: the fixed ones at most their given width and no wider than their content, the
    last one taking what is left. When the terminal is too narrow for that, the widest fixed columns shrink
    (wrapping at spaces, their longest word still whole) until the last column has a readable width; only a
    terminal too narrow even for that cuts words."""
    gap = 2 * (len(columns) - 1)
    longest_word = [max((len(word) for c in col for word in str(c).split()), default=1) for col in columns]
    widths = [max(1, min(f, max(len(str(c)) for c in col))) for col, f in zip(columns[:-1], fixed)]
    floor = [min(w, word) for w, word in zip(widths, longest_word)]
    last_natural = max(len(str(c)) for c in columns[-1])
    last = min(last_natural, max(20, total // 3))

    def shrink(lowest: list[int], last_min: int) -> None:
        while sum(widths) + gap + last_min > total:
            i = max((i for i in range(len(widths)) if widths[i] > lowest[i]), key=lambda i: widths[i], default=None)
            if i is None:
                return
            widths[i] -= 1

    shrink(floor, last)  # 1. wrap the fixed columns at spaces
    last = max(min(last_natural, 10), min(last, total - sum(widths) - gap))  # 2. a narrower last column
    shrink([min(w, 4) for w in floor], last)  # 3. cut long words (ids) as a last resort
    return widths + [max(1, total - sum(widths) - gap)]


def fit_table(rows: list[list[str]], header: list[str], fixed: list[int]) -> str:
    """A table no wider than the terminal: the columns but the last at most the given widths, the last one
    taking what is left; every cell wrapped at word boundaries (see ``_widths`` for a narrow terminal)."""
    rows = [[str(c) for c in r] for r in rows]
    widths = _widths([list(col) for col in zip(header, *rows)], fixed, width())

    def lines(cells: list[str]) -> list[str]:
        wrapped = [wrap(c, w) for c, w in zip(cells, widths)]
        height = max(len(w) for w in wrapped)
        return ["  ".join((w[k] if k < len(w) else "").ljust(n) for w, n in zip(wrapped, widths)).rstrip()
                for k in range(height)]

    out = lines(header)
    out.append("  ".join("-" * w for w in widths[:-1]) + "  " + "-" * min(widths[-1], 40))
    for r in rows:
        out.extend(lines(r))
    return "\n".join(out)


def template() -> str:
    """A complete spec: every table and key, each commented with its unit, range and meaning, set to its
    default (keys without one are commented out: leaving them out is their default)."""
    from .design.schema import TABLES

    lines = ["# handbook design specification: every key at its default (SI units).",
             "# Feed it back unchanged and it designs the notes' own examples; change what differs for your board.",
             "# python -m handbook design SPEC.toml [--json] [--bom bom.csv] [--netlist DIR] [--spice]", ""]
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
