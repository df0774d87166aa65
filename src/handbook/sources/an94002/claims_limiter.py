"""AN94002 section 2.4, the op-amp limiter: every number it prints, recomputed."""
from __future__ import annotations

from ...core import Claim, Printed
from .circuit import factor_a, level_shift, trip_worst_case
from .data import FACTS, NAME

WHERE = f"{NAME} 2.4"


def a(p):
    """The level-shift factor A = R13 / (R12 + R13).

    Parameters
    ----------
    p : Mapping
        The AN94002 parameters (names as in :mod:`.data`, SI units); reads ``r12`` and ``r13``, ohm.

    Returns
    -------
    float
        A, a pure number.
    """
    return factor_a(p["r12"], p["r13"])


def vd1_min(p):
    """The lowest zener voltage.

    Parameters
    ----------
    p : Mapping
        The AN94002 parameters (names as in :mod:`.data`, SI units); reads ``zener_voltage`` (V) and ``zener_tolerance``.

    Returns
    -------
    float
        V_D1 at the low end of its tolerance, V.
    """
    return p["zener_voltage"] * (1 - p["zener_tolerance"])


def seen(p):
    """The sense signal at the op-amp input, A V_cs.

    Parameters
    ----------
    p : Mapping
        The AN94002 parameters (names as in :mod:`.data`, SI units); reads ``r12``, ``r13`` (ohm) and ``v_cs`` (V).

    Returns
    -------
    float
        A V_cs, V.
    """
    return a(p) * p["v_cs"]


def zener_drift(p):
    """The zener's drift over the temperature excursion: TC x temperature span.

    Parameters
    ----------
    p : Mapping
        The AN94002 parameters (names as in :mod:`.data`, SI units); reads ``zener_tc`` (V/K) and ``temp_span`` (K).

    Returns
    -------
    float
        The drift, V.
    """
    return p["zener_tc"] * p["temp_span"]


def largest_excursion(p, include=("resistors", "zener", "offset")):
    """The exact worst case of the trip voltage over the tolerances in ``include``, as a fraction.

    Parameters
    ----------
    p : Mapping
        The AN94002 parameters (names as in :mod:`.data`, SI units); as
        :func:`~handbook.sources.an94002.circuit.trip_worst_case` reads them.
    include : tuple of str
        The spreads taken: ``"resistors"``, ``"zener"``, ``"offset"``.

    Returns
    -------
    float
        The larger of the relative deviations of the trip voltage below and above nominal, a fraction.
    """
    wc = trip_worst_case(p, include=include)
    return max(abs(wc.rel_low), abs(wc.rel_high))


def zener_spread(p):
    """The BZX79-C8V2's datasheet spread about the nominal V_Z: the larger of its two sides, as a fraction.

    Parameters
    ----------
    p : Mapping
        The AN94002 parameters (names as in :mod:`.data`, SI units); reads ``zener_voltage``, V.

    Returns
    -------
    float
        The spread, a fraction of ``zener_voltage``.
    """
    low, high = FACTS["bzx79_vz"].value
    return max(p["zener_voltage"] - low, high - p["zener_voltage"]) / p["zener_voltage"]


def tc_column_top(v_zener: float) -> float:
    """The largest temperature coefficient the BZX79 datasheet's column allows at ``v_zener``.

    Parameters
    ----------
    v_zener : float
        The zener voltage (V).

    Returns
    -------
    float
        The column's top, +0.08 %/K printed to one figure, so up to 0.085 %/K, times ``v_zener`` (V/K).
    """
    return (FACTS["bzx79_tc"].value[1] + 0.5e-4) * v_zener


def build() -> list[Claim]:
    """Every claim of section 2.4, the op-amp limiter.

    Returns
    -------
    list of Claim
        The inputs' claims, then the tolerance budget's.
    """
    return _inputs("opamp") + _budget("opamp")


def _inputs(ch: str) -> list[Claim]:
    """The op-amp's inputs: the level shift, the sense signal it sees, the offset's window."""
    return [
        Claim(id="an94002-offset-generic", where=WHERE, quantity="tolerance from a 10 mV offset at V_cs = 100 mV",
              printed=Printed("10", "%"), chapter=ch, compute=lambda p: p["offset_generic"] / p["v_cs"],
              reason="10 mV / 100 mV, before any level shift"),
        Claim(id="an94002-vd1-min", where=WHERE, quantity="lowest zener voltage 8.2 V - 5 %",
              printed=Printed("7.79", "V"), chapter=ch, compute=vd1_min, reason="0.95 x 8.2 V"),
        Claim(id="an94002-factor-a", where=WHERE, quantity="level-shift factor A = R13/(R12+R13)",
              printed=Printed("0.741", "1"), chapter=ch, compute=a, reason="16 k / 21.6 k = 0.74074"),
        Claim(id="an94002-a-vd1", where=WHERE, quantity="A x V_D1 in eq 11", printed=Printed("5.77", "V"), chapter=ch,
              compute=lambda p: a(p) * vd1_min(p), reason="0.74074 x 7.79 V = 5.770 V"),
        Claim(id="an94002-level-shift", where=WHERE, quantity="level shift at V_D1 = 7.79 V, V_cs = 0",
              printed=Printed("2.02", "V"), chapter=ch, compute=lambda p: level_shift(vd1_min(p), p["r12"], p["r13"]),
              reason="7.79 V x 5.6 k / 21.6 k = 2.0196 V"),
        Claim(id="an94002-vcs-at-opamp", where=WHERE, quantity="sense signal at the op-amp input for V_cs = 100 mV",
              printed=Printed("74.1", "mV"), chapter=ch, compute=seen, reason="0.74074 x 100 mV = 74.07 mV"),
        Claim(id="an94002-window-high", where=WHERE, quantity="op-amp input at trip, offset -9 mV side (upper)",
              printed=Printed("90.5", "mV"), chapter=ch, compute=lambda p: seen(p) + p["offset"],
              reason="74.07 + 9 = 83.07 mV; 90.5 mV is AN93008's 81.5 + 9 (A = 0.815) copied unchanged",
              consequence="none for the tolerance (the +-12 % is right), but a reader checking the window against "
                          "74.1 mV is misled"),
        Claim(id="an94002-window-low", where=WHERE, quantity="op-amp input at trip, offset +9 mV side (lower)",
              printed=Printed("72.5", "mV"), chapter=ch, compute=lambda p: seen(p) - p["offset"],
              reason="74.07 - 9 = 65.07 mV; 72.5 mV is AN93008's 81.5 - 9 (A = 0.815) copied unchanged",
              same_fact="an94002-window-high",
              consequence="as for the upper end: the printed window belongs to AN93008's supply-referenced circuit"),
        Claim(id="an94002-offset-tol", where=WHERE, quantity="offset-related tolerance of the limit",
              printed=Printed("12", "%"), chapter=ch, compute=lambda p: p["offset"] / seen(p),
              reason="9 mV / 74.07 mV = 12.15 % (consistent with A = 0.741, not with the printed 90.5/72.5 mV "
                     "window)")]


def _budget(ch: str) -> list[Claim]:
    """The tolerance budget: the zener, its drift, the resistors, the total."""
    return [
        Claim(id="an94002-zener-tol", where=f"{NAME} 2.4, eq (13)", quantity="zener-related tolerance of the limit",
              printed=Printed("5", "%"), chapter=ch, compute=lambda p: p["zener_tolerance"],
              reason="V_cs is proportional to V_D1 (eq 13)"),
        Claim(id="an94002-zener-spread", where=f"{NAME} 2.4 vs BZX79 datasheet",
              quantity="zener tolerance of the BZX79-C8V2 ('a tolerance of +-5 %')", printed=Printed("5", "%"),
              chapter=ch, compute=zener_spread, basis="BZX79 datasheet",
              reason="the datasheet's V_Z limits, 7.7 and 8.7 V at 5 mA, are 8.2 V -6.1 % and +6.1 %; +-5 % is the "
                     "C series' nominal band, not the part's limits",
              consequence="the zener's share of the trip tolerance is +-6.1 %, not +-5 % (eq 13: V_cs is "
                          "proportional to V_D1); the note's 5 % also sizes the level shift (7.79 V, see "
                          "an94002-shift-7v7) and the drift's reference (0.95 x 8.2 V)"),
        Claim(id="an94002-shift-7v7", where=f"{NAME} 2.4 vs BZX79 datasheet",
              quantity="level shift at the datasheet's lowest V_Z (7.7 V), V_cs = 0: at least 2 V required",
              printed=Printed("2", "V"), relation="<=", chapter=ch, basis="BZX79 datasheet",
              same_fact="an94002-zener-spread",
              compute=lambda p: level_shift(FACTS["bzx79_vz"].value[0], p["r12"], p["r13"]),
              reason="7.7 V x 5.6 k / 21.6 k = 1.996 V, 4 mV short of the 2 V the note sizes R12 and R13 for (it "
                     "used 8.2 V - 5 % = 7.79 V: 2.02 V)",
              consequence="harmless at 25 C, where the LM358 needs 1.5 V, and at the trip point (V_cs = 100 mV) the "
                          "inputs sit 2.07 V down; but the note's own rule then picks R13 = 15 k, not 16 k (16 k needs "
                          "V_Z >= 7.71 V), and at 0 C the zener's drift (-155 mV) leaves 1.96 V where the LM358 needs "
                          "2 V over temperature"),
        Claim(id="an94002-zener-drift", where=WHERE, quantity="zener drift over 25 C +- 25 C",
              printed=Printed("150", "mV"), chapter=ch, compute=zener_drift,
              reason="6.2 mV/K x 25 K = 155 mV, truncated to two figures (rounding would give 160 mV)",
              truncated=True),
        Claim(id="an94002-zener-drift-pct", where=WHERE, quantity="zener drift as a tolerance",
              printed=Printed("2", "%"), chapter=ch, compute=lambda p: zener_drift(p) / vd1_min(p),
              reason="155 mV / 7.79 V = 1.99 %"),
        Claim(id="an94002-zener-tc", where=f"{NAME} 2.4 vs BZX79 datasheet",
              quantity="largest zener temperature coefficient ('max. 6.2 mV/°C')", printed=Printed("6.2", "mV/K"),
              chapter=ch, relation="<=", compute=lambda p: tc_column_top(p["zener_voltage"]),
              reason="6.2 mV/K at 8.2 V is 0.076 %/K, inside the datasheet's +0.03 to +0.08 %/K column, which is "
                     "printed to one figure (0.08 holds up to 0.085 %/K, 6.97 mV/K at 8.2 V)",
              basis="BZX79 datasheet"),
        Claim(id="an94002-resistor-tol", where=WHERE, quantity="resistor-related tolerance of the limit (1 % R9..R13)",
              printed=Printed("5", "%"), chapter=ch, compute=lambda p: largest_excursion(p, ("resistors",)),
              reason="eq 14's matching (R10 = R12, R11 = R13) carried into the tolerance; with each 1 % resistor "
                     "varying on its own V_cs = V_D1 (1 - B/A) moves -86 %/+85 % (a 100 mV difference of two 8 V "
                     "dividers)",
              consequence="the limiter can trip anywhere from almost no current to twice the design value on a real "
                          "board; design it with the exact worst case (chapter 'Choosing R7 and R9')", method_wrong=True),
        Claim(id="an94002-total-tol", where=WHERE, quantity="total initial tolerance, note's method 1.12 x 1.05 x 1.05",
              printed=Printed("23", "%"), chapter=ch, compute=lambda p: 1.12 * 1.05 * 1.05 - 1,
              reason="1.12 x 1.05 x 1.05 = 1.2348; the method's lower end is 0.88 x 0.95 x 0.95 = 0.794 (-20.6 %)"),
        Claim(id="an94002-total-exact", where=WHERE, quantity="total initial tolerance, exact worst case of eq 13",
              printed=Printed("23", "%"), chapter=ch, compute=largest_excursion,
              reason="every corner of 1 % R9..R13, 5 % zener and +-9 mV offset: the trip voltage spans 1.2 to 206 mV "
                     "(-99 %/+106 %), not +-23 %",
              consequence="a board built as the note says may limit at anywhere from about 1 % to about twice the "
                          "design current; see the design chapter for a limiter that holds its window",
              method_wrong=True, same_fact="an94002-resistor-tol"),
    ]
