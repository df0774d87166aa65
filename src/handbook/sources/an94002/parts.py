"""AN94002 parts list (section 4): the OCR of the note's table, what the text says each part does, the
value each 12NC code decodes to, and the comparison of all three that the parts-list chapter shows."""
from __future__ import annotations

from ...core import series
from .circuit import r7_for_limit, r9_for

# the option column O1/O2/O12 is from the note

#: (reference, value as printed, value in SI or None for TBD/type, tolerance, option, type, 12NC)
PARTS = [
    ("R1", "22 ohm", 22.0, 0.05, "", "SFR25", "2322 181 53229"),
    ("R2", "680 ohm", 680.0, 0.05, "", "SFR25", "2322 181 53681"),
    ("R3", "39 kohm", 39e3, 0.05, "", "SFR25", "2322 181 53393"),
    ("R4", "10 kohm", 10e3, 0.05, "", "SFR25", "2322 181 53103"),
    ("R5", "1 kohm", 1e3, 0.05, "O2", "SFR25", "2322 181 53102"),
    ("R6", "1 kohm", 1e3, 0.05, "O1", "SFR25", "2322 181 53102"),
    ("R7", "TBD", None, None, "O12", "PR01", "2322 193"),
    ("R8", "TBD", None, None, "O2", "PR01", "2322 193"),
    ("R9", "TBD", None, None, "O2", "SFR25", "2322 181 53"),
    ("R10", "5.6 kohm", 5.6e3, 0.01, "O2", "SFR25", "2322 181 53562"),
    ("R11", "16 kohm", 16e3, 0.01, "O2", "SFR25", "2322 181 53163"),
    ("R12", "5.6 kohm", 5.6e3, 0.01, "O2", "SFR25", "2322 181 53562"),
    ("R13", "16 kohm", 16e3, 0.01, "O2", "SFR25", "2322 181 53163"),
    ("R14", "750 ohm", 750.0, 0.05, "O2", "SFR25", "2322 181 53701"),
    ("R15", "3.9 kohm", 3.9e3, 0.05, "O2", "SFR25", "2322 181 53392"),
    ("R16", "10 kohm", 10e3, 0.05, "", "SFR25", "2322 181 53103"),
    ("R17", "1 kohm", 1e3, 0.05, "", "SFR25", "2322 181 53102"),
    ("R18", "1 kohm", 1e3, 0.05, "", "SFR25", "2322 181 53102"),
    ("R19", "1 kohm", 1e3, 0.05, "", "SFR25", "2322 181 53102"),
    ("C1", "10 uF", 10e-6, None, "", "RSM 037", "2222 037 68109"),
    ("C2", "10 uF", 10e-6, None, "", "RSM 037", "2222 037 68109"),
    ("C3", "18 nF", 18e-9, None, "", "MKT 370", "2222 370 21183"),
    ("C4", "18 nF", 18e-9, None, "", "MKT 370", "2222 370 21183"),
    ("C5", "220 nF", 220e-9, None, "", "MKT 370", "2222 370 17224"),
    ("C6", "10 nF", 10e-9, None, "", "MKT 370", "2222 370 17224"),
    ("C7", "220 nF", 220e-9, None, "", "MKT 370", "2222 370 17224"),
    ("C8", "220 nF", 220e-9, None, "", "MKT 370", "2222 370 17224"),
    ("C9", "10 uF", 10e-6, None, "O1", "RSM 037", "2222 037 68109"),
    ("C10", "10 uF", 10e-6, None, "O2", "RSM 037", "2222 037 68109"),
]

#: what the text says each part does, and which claim checks its value
PART_ROLES = {
    "R1": ("series with C8: stability of the V_mot loop", None),
    "R3": ("V_mot divider, top (eq 10)", "an94002-r3"),
    "R4": ("V_mot divider, bottom (eq 10)", None),
    "R7": ("current sense (user's limit current)", None),
    "R9": ("sets the trip voltage (eq 14, figure 7)", None),
    "R10": ("reference divider, = R12 (eq 14)", None),
    "R11": ("reference divider, = R13 (eq 14)", "an94002-r13"),
    "R12": ("level shift, top (eq 11)", None),
    "R13": ("level shift, bottom (eq 11)", "an94002-r13"),
    "R17": ("artificial centre tap (1 k)", None), "R18": ("artificial centre tap (1 k)", None),
    "R19": ("artificial centre tap (1 k)", None),
    "C2": ("supply decoupling: |Z| < 2 ohm at 2 MHz", "an94002-c2"),
    "C3": ("CAP-CD (eq 6)", "an94002-c3"),
    "C4": ("CAP-DC = CAP-CD", "an94002-c4"),
    "C5": ("CAP-ST (eq 1; inferred from the value)", "an94002-c5"),
    "C6": ("CAP-TI (eq 9)", "an94002-c6"),
    "C8": ("with R1: stability of the V_mot loop", None),
}

#: the columns of :func:`parts_rows`
PARTS_HEADER = ["ref", "option", "value", "tol.", "type", "12NC", "12NC decodes to", "role in the text",
                "text's calculation"]


def decode_12nc(code: str) -> float | None:
    """Value encoded in the last three digits of a Philips 12NC: two digits and a decade digit.

    The decade digit counts in the family's base unit (ohm for the SFR25 resistors, pF for the MKT 370
    capacitors, µF for the RSM 037 electrolytics): 8 means 1 to 9.9 (the two digits x 0.1), 9 means 10 to 99
    (x 1), 1 means 100 to 990 (x 10), 2 x 100 and so on. One rule decodes the whole list: R1 "...53229" is
    22 ohm and the electrolytics' "...68109" 10 µF, as printed; the list itself proves the rule.

    Parameters
    ----------
    code : str
        The 12NC as printed, spaces allowed ("2322 181 53229").

    Returns
    -------
    float or None
        The value, ohm for a resistor and F for a capacitor; None for a code that is not 12 digits long.
    """
    digits = code.replace(" ", "")
    if len(digits) != 12:
        return None
    mant, dec = int(digits[-3:-1]), int(digits[-1])
    value = mant * {9: 1.0, 8: 0.1}.get(dec, 10.0 ** dec)
    base = 1e-12 if digits.startswith("2222370") else 1e-6 if digits.startswith("2222037") else 1.0
    return value * base


def _symbol(unit: str) -> str:
    return unit.replace("ohm", "Ω")


def _calculation(ref: str, claim_id: str | None, p: dict, checks: dict) -> str:
    """The text's calculation for one part: R7 and R9 designed from ``p``, else the claim that checks it."""
    from ...core.units import eng

    if ref == "R7":
        return (f"{eng(r7_for_limit(p['i_limit'], p['v_be']), 'Ω')} (O1, 0.8 V) or "
                f"{eng(p['v_cs'] / p['i_limit'], 'Ω')} (O2, {eng(p['v_cs'], 'V')})")
    if ref == "R9":
        return eng(series.nearest("E96", r9_for(p["v_cs"], p["zener_voltage"], p["r10"], p["r11"])), "Ω") + " (E96, eq 14)"
    if claim_id:
        r = checks[claim_id]
        return f"{eng(r['computed'], _symbol(r['unit']))}: {r['status']}"
    return ""


def _decoded(ref: str, value: float | None, nc: str) -> str:
    """What the 12NC code decodes to, marked where it differs from the printed value."""
    from ...core.units import eng

    code_value = decode_12nc(nc)
    if code_value is None or value is None:
        return ""
    differs = abs(code_value - value) > 1e-6 * value
    return eng(code_value, "F" if ref.startswith("C") else "Ω") + (" **differs**" if differs else "")


def parts_rows(p: dict, checks: list[dict]) -> list[list[str]]:
    """One row per part (columns :data:`PARTS_HEADER`): the printed value, its 12NC decoded, the part's role
    and the text's calculation of it. ``checks`` are the evaluated claims at ``p``.

    Parameters
    ----------
    p : Mapping
        The AN94002 parameters (names as in :mod:`.data`, SI units); R7 and R9 are designed from ``i_limit``
        (A), ``v_be``, ``v_cs``, ``zener_voltage`` (V) and ``r10``, ``r11`` (ohm).
    checks : list of dict
        The evaluated claims at ``p``, as :meth:`~handbook.core.Source.evaluate` returns them.

    Returns
    -------
    list of list of str
        One row of text per part, in the columns of :data:`PARTS_HEADER`.
    """
    by_id = {r["id"]: r for r in checks}
    rows = []
    for ref, printed, value, tol, option, kind, nc in PARTS:
        role, claim_id = PART_ROLES.get(ref, ("", None))
        rows.append([ref, option, printed.replace("ohm", "Ω").replace("uF", "µF"),
                     "" if tol is None else f"{tol:.0%}", kind, nc, _decoded(ref, value, nc), role,
                     _calculation(ref, claim_id, p, by_id)])
    return rows
