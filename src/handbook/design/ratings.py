"""Part ratings: the rating and package class each chosen part needs to carry its worst-case stress.

One convention for the whole handbook, stated here and in every BOM row that uses it:

* **Power** (resistors, the zener): the worst-case dissipation at most :data:`DERATING` (50 %) of the part's
  rating *at the highest ambient*; the rating itself falls linearly from full at :data:`KNEE` (70 °C) to zero
  at :data:`ZERO` (155 °C), the curve chip- and film-resistor datasheets draw. The zener's is the DO-35 glass
  diode's own curve (:data:`ZENER`).
* **Voltage** (capacitors): the largest voltage at most :data:`DERATING` of the rated voltage.
* **Current** (inductors): saturation current at least :data:`SATURATION_MARGIN` times the worst-case peak.

These are this book's convention, chosen to be conservative, not a standard's numbers: a reader with a
stricter derating policy changes them here. Package classes are what the rating needs, never a part number.
"""
from __future__ import annotations

#: fraction of a rating a part may use at its highest ambient (power of resistors and the zener, voltage of
#: capacitors): this book's convention
DERATING = 0.5
#: resistor power derating curve: full rating up to KNEE, zero at ZERO (C), linear between (chip and film
#: resistor datasheets)
KNEE, ZERO = 70.0, 155.0
#: saturation current of an inductor at least this times its worst-case peak current
SATURATION_MARGIN = 1.2
#: the limiter's divider resistors' temperature coefficient the BOM asks for, 1/K: thin film's usual class (the
#: worst-case analysis states their drift with it)
DIVIDER_TC = 25e-6

#: resistor power classes, W, and the package class that carries each (surface mount up to 1 W, then leaded)
RESISTOR_CLASSES = ((0.1, "0603 chip"), (0.125, "0805 chip"), (0.25, "1206 chip"), (0.5, "2010 chip"),
                    (1.0, "2512 chip"), (2.0, "2 W leaded film"), (3.0, "3 W leaded film"),
                    (5.0, "5 W wirewound"), (10.0, "10 W wirewound"), (25.0, "25 W chassis-mount wirewound"))
#: capacitor rated voltages, V (the usual ladder of ceramic and film parts)
CAPACITOR_VOLTAGES = (16.0, 25.0, 50.0, 63.0, 100.0, 250.0, 400.0, 630.0)
#: the lowest rated voltage film capacitors are commonly sold at, V
FILM_MIN_VOLTAGE = 63.0
#: the BZX79's power rating, W, and where its derating ends (C): "500 mW" is the series' name; a DO-35 glass
#: diode's rating falls from 50 C to zero at its 200 C junction limit (an assumption: the series' curve, not a
#: figure the notes print)
ZENER = {"rating": 0.5, "knee": 50.0, "zero": 200.0}
#: the next zener power class, W (1.3 W axial DO-41 parts), taken with the same derating curve
ZENER_LARGE = 1.3


def available(t_ambient: float, knee: float = KNEE, zero: float = ZERO) -> float:
    """The fraction of a part's rating left at ``t_ambient`` by a linear derating curve.

    Parameters
    ----------
    t_ambient : float
        The highest ambient temperature, C.
    knee, zero : float
        Full rating up to ``knee``, none at ``zero`` (C).

    Returns
    -------
    float
        1 up to the knee, falling linearly to 0 at ``zero`` (0 beyond).
    """
    return max(0.0, min(1.0, (zero - t_ambient) / (zero - knee)))


def power_needed(p_worst: float, t_ambient: float, knee: float = KNEE, zero: float = ZERO) -> float:
    """The power rating a part needs to carry ``p_worst`` at ``t_ambient`` under :data:`DERATING`.

    Parameters
    ----------
    p_worst : float
        The part's worst-case dissipation, W.
    t_ambient : float
        The highest ambient, C.
    knee, zero : float
        The derating curve (:func:`available`).

    Returns
    -------
    float
        ``p_worst / (DERATING * available(t_ambient))``, W (inf where nothing is left of the rating).
    """
    left = DERATING * available(t_ambient, knee, zero)
    return float("inf") if left <= 0 else p_worst / left


def resistor(p_worst: float, t_ambient: float) -> tuple[float, str]:
    """The smallest resistor power class, and its package, that carries ``p_worst`` at ``t_ambient``.

    Parameters
    ----------
    p_worst : float
        The resistor's worst-case dissipation, W.
    t_ambient : float
        The highest ambient, C.

    Returns
    -------
    tuple
        (rating, W; package class), or (the rating needed, "no standard class: split it or use a heat-sunk
        part") above the largest class.
    """
    need = power_needed(p_worst, t_ambient)
    for rating, package in RESISTOR_CLASSES:
        if rating >= need * (1 - 1e-12):
            return rating, package
    return need, "no standard class: split it or use a heat-sunk part"


def capacitor_voltage(v_worst: float, film: bool = False) -> float:
    """The smallest rated voltage of the ladder with ``v_worst`` at most :data:`DERATING` of it.

    Parameters
    ----------
    v_worst : float
        The largest voltage across the capacitor, V.
    film : bool
        A film capacitor: its ladder starts at :data:`FILM_MIN_VOLTAGE` (film parts are rarely sold lower).

    Returns
    -------
    float
        The rated voltage, V (the voltage needed itself above the ladder's top).
    """
    need = max(v_worst / DERATING, FILM_MIN_VOLTAGE if film else 0.0)
    return next((v for v in CAPACITOR_VOLTAGES if v >= need * (1 - 1e-12)), need)
