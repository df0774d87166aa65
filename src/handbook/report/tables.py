"""Tables a person reads: claims with their status, errata, designs; values with engineering units.

Everything shown is rounded and free of addresses or timings, so nbval can compare it exactly.
"""
from __future__ import annotations

import math

from IPython.display import Markdown

from ..core.claim import UNIT_SCALES
from ..core.units import eng, readable  # noqa: F401 (report.eng, report.readable, as the chapters call them)

#: status -> short badge used in tables
BADGE = {"exact": "exact", "rounding": "rounding", "truncated": "truncated (last digit cut off)",
         "rounded intermediate": "rounding (of a rounded intermediate)", "bound met": "bound met",
         "conservative": "conservative (rounded to the safe side)", "misprint": "**misprint**",
         "inconsistent": "**inconsistent**", "wrong method": "**wrong method**", "n/a": "n/a"}


def _cell(x) -> str:
    """Text safe inside a Markdown table cell: a '|' would end the cell, a newline the row."""
    return str(x).replace("|", "\\|").replace("\n", " ")


def _in_printed_unit(printed_text: str, value: float) -> tuple[str, str]:
    """A printed value ("0.23 uF") and a recomputed SI value, both shown in the printed unit (no unit
    shown for a pure number): ("0.23 uF", "0.25 uF")."""
    number, unit = printed_text.split(" ", 1)
    suffix = "" if unit == "1" else " " + unit
    return number + suffix, f"{value / UNIT_SCALES[unit][0]:.4g}{suffix}"


def examples_table(rows: list[dict], source: bool = False) -> Markdown:
    """The status table of a chapter: printed, recomputed, status, why (and, for the registry's table of
    every document, the source each number is printed in)."""
    head = ["source"] * source + ["quantity", "printed", "recomputed", "status", "why"]
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for r in rows:
        printed, shown = _in_printed_unit(r["printed_text"], r["computed"])
        if r["status"] == "n/a":  # the row names the note's inputs: a value for the reader's would be mislabelled
            shown = "—"
        elif r.get("relation") in (">=", "<="):  # a bound: the print is compared with it, not equated
            shown = f"{shown} (printed {'≥' if r['relation'] == '>=' else '≤'} this)"
        cells = [r["source"]] * source + [r["quantity"], printed, shown, BADGE[r["status"]], r["reason"]]
        lines.append("| " + " | ".join(_cell(readable(c)) for c in cells) + " |")
    counts: dict[str, int] = {}
    for r in rows:
        counts[r["status"]] = counts.get(r["status"], 0) + 1
    summary = (f"Status of {len(rows)} printed number{'s' * (len(rows) != 1)}: "
               + ", ".join(f"{n} {status}" for status, n in counts.items()))
    return folded(summary, Markdown("\n".join(lines)))


def _printed_and_recomputed(r: dict) -> str:
    """'printed 0.23 uF, recomputed 0.25 uF' in the printed value's own unit, or '' for non-numbers."""
    if r["recomputed"] is None or not r["printed"]:
        return ""
    printed, shown = _in_printed_unit(r["printed"], r["recomputed"])
    return f"printed {printed}, recomputed {shown}"


#: the kinds of erratum (catalog.errata()), as the book names them
ERRATA_KINDS = {"misprint": "misprint", "inconsistent": "inconsistent", "wrong method": "wrong method",
                "equation": "equation differs", "text": "text erratum"}


def folded(summary: str, body) -> Markdown:
    """A proof table (or any long body) folded away behind a one-line summary a reader can open: a MyST dropdown,
    which the book renders as a toggle and the PDF prints open."""
    text = body.data if isinstance(body, Markdown) else readable(str(body))
    return Markdown(f":::{{dropdown}} {readable(summary)}\n\n{text}\n:::")


def table(header: list[str], rows: list[list]) -> Markdown:
    """A Markdown table, every cell's units as a person reads them (:func:`readable`)."""
    lines = ["| " + " | ".join(_cell(readable(h)) for h in header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(_cell(readable(c)) for c in row) + " |" for row in rows]
    return Markdown("\n".join(lines))




def bom_table(rows: list[dict]) -> Markdown:
    """Bill-of-materials rows (:func:`handbook.design.bom.rows`) as a person reads them: designator, quantity,
    part, value, tolerance, the rating with the stress it carries, technology, package and tempco, the reason.

    Parameters
    ----------
    rows : list of dict
        The rows (keys :data:`handbook.design.bom.COLUMNS`).

    Returns
    -------
    Markdown
        The table ("nothing designed" when there are no rows).
    """
    tol = lambda x: "" if x is None else f"±{x * 100:g} %"  # noqa: E731
    return table(["designator", "qty", "part", "value", "tolerance", "rating (worst-case stress)",
                  "technology; package; tempco", "reason"],
                 [[r["designator"], r["quantity"], r["part"], r["value_text"], tol(r["tolerance"]), r["rating_text"],
                   "; ".join(x for x in (r["technology"], r["package"], r["tempco"]) if x), r["reason"]]
                  for r in rows] or [["", "", "nothing designed", "", "", "", "", ""]])


def design_table(table_name: str, result) -> Markdown:
    """One design's results as a table (values with units), or what can be met when nothing can."""
    from ..design.solvers import Infeasible
    from ..design.spec import OUTPUTS

    if isinstance(result, Infeasible):
        extra = "; ".join(achievable_text(table_name, k, v) for k, v in result.achievable.items() if v is not None)
        return Markdown(readable(f"**Cannot be met** (`{table_name}`): {result}  \nWhat can be met: {extra or 'nothing nearby'}"))
    rows = [[out.label, shown_value(getattr(result, out.key), out.unit)] for out in OUTPUTS[table_name]]
    return table(["result", "value"], rows)


#: units of the "what can be met" figures that are not design outputs, by how their key begins or ends
_ACHIEVABLE_UNITS = (("ratio", "1"), ("margin", "%"), ("rpm", "rpm"), ("cap", "F"), ("r7", "ohm"), ("i_", "A"),
                     ("f_", "Hz"), ("p_", "W"), ("theta", "K/W"), ("t_", "C"))


def achievable_text(table_name: str, key: str, value) -> str:
    """One "what can be met" figure as a person reads it: its label and its value with its unit."""
    from ..design.spec import OUTPUTS

    out = next((o for o in OUTPUTS.get(table_name, ()) if o.key == key), None)
    if out is not None:
        return f"{out.label} {shown_value(value, out.unit)}"
    label = key.replace("_", " ")
    if isinstance(value, str) or not isinstance(value, (int, float)):
        return f"{label}: {value}"
    unit = next((u for part, u in _ACHIEVABLE_UNITS if part in key), "")
    if isinstance(value, float) and unit == "1":
        return f"{label} {value:.4g}"
    return f"{label} {shown_value(value, unit)}"


#: digits and the minus sign as superscripts, for a power of ten
_SUPERSCRIPT = str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹")


def shown_value(v, unit: str) -> str:
    """A design output as a person reads it: engineering value with its unit, a percentage, '—' for a value
    not designed (None), the warnings joined ('none' when there are none)."""
    if v is None:
        return "—"
    if isinstance(v, bool):  # a proof's flag
        return "yes" if v else "no"
    if isinstance(v, (tuple, list)):  # warnings (text), or values in the unit (the R7 values left unsettled)
        return "; ".join(shown_value(x, unit) if isinstance(x, float) else readable(x) for x in v) if v else "none"
    if unit == "%":
        return f"{v:.2%}"
    if unit == "C":
        return f"{v:.4g} °C"
    if unit == "rpm" and isinstance(v, float):
        return f"{v:.0f} rpm"
    if unit == "K" and isinstance(v, float):  # a temperature rise: to a hundredth of a kelvin, as a sensor reads it
        return "< 0.01 K" if 0 <= v < 0.005 else f"{v:.3g} K" if abs(v) < 10 else f"{v:.1f} K"
    if unit in ("F", "ohm", "A", "W", "V", "Hz", "H", "s", "m", "T", "V/K", "N m/A"):  # 0.015 N m/A: 15 mN m/A
        return eng(v, unit.replace("ohm", "Ω"))
    if unit == "1/K" and isinstance(v, float):  # a temperature coefficient: 100 ppm/K, not 0.0001 1/K
        return f"{v * 1e6:.4g} ppm/K"
    if unit == "A/m^2" and isinstance(v, float):  # a current density as windings are rated: 5 A/mm²
        return f"{v / 1e6:.4g} A/mm²"
    if unit == "kg m^2" and isinstance(v, float) and v > 0:  # no prefix on kg: 72e-6 kg m^2 reads 72 × 10⁻⁶ kg m²
        r = float(f"{v:.4g}")
        power = int(math.floor(math.log10(r) / 3) * 3) if r < 1e-3 else 0
        return f"{r / 10.0 ** power:.4g}" + (f" × 10{str(power).translate(_SUPERSCRIPT)}" if power else "") + " kg m²"
    if isinstance(v, float):
        return f"{v:.4g}" + (f" {unit}" if unit not in ("", "1") else "")
    return str(v)
