"""The case against AN93008: for each erratum, the passage it disputes word for word
(as the OCR reads it), how sure it is, and the most charitable reading of the source, answered (see
:class:`handbook.core.claim.Case`). The quotes are held against the app notes' text by a test."""
from ...core import Case

CASES = {
    'an93008-resistor-tol': Case(quote=(
        'Resistor tolerances of $\\pm 5\\%$ result in a tolerance on current limiting value of $\\pm '
        '5\\%$.',
        '$$V_{\\text{cs}} = V_{\\text{supply}} - B/A \\cdot V_{\\text{supply}} \\quad (6)$$',
    ), confidence='certain',
        charitable='No charitable reading rescues it: V_cs = V_supply(1 - B/A) with B/A = 0.991 is a '
                   '~1 % difference of two ratios of 5 % parts, so the resistors alone move the ~98 '
                   'mV trip from about -0.31 V to +0.50 V. Survives.'),
    'an93008-zener-spread': Case(quote=(
        'Assume a zener diode of $8.2 \\text{ V} \\pm 5\\%$ (BZX79 C 8V2).',
        'The minimum zener voltage is $0.95 \\times 8.2 = 7.7 \\text{ V}$.',
        ('datasheet facts', 'BZX79-C8V2: V_Z 7.7 to 8.7 V at 5 mA;'),
        'Together with a zener diode tolerance of $\\pm 5\\%$ the overall tolerance of the zener diode '
        'voltage is then $\\pm 7\\%$.',
    ), confidence='probable',
        charitable="+-5 % is the maker's nominal C-series band and the note does use the datasheet's "
                   '7.7 V minimum right after (though 0.95 x 8.2 is 7.79); the datasheet limits are '
                   '+-6.1 %. Survives as minor.'),
    'an93008-t-gnd': Case(quote=(
        'Because of the fact all GND pins are internally interconnected, it is not possible to have a'
        ' current sense resistor',
        ('AN94002', 'GND3 is on the chip not connected to the ground line and has externally to be '
                  'connected to GND2.'),
    ), confidence='probable',
        charitable='AN93008 speaks for the whole family (incl. TDA5145) and its practical point may '
                   'rest on GND1/GND2 being joined on chip, which neither note shows; but for the '
                   'TDA5143/5144 the literal statement contradicts AN94002. Survives as a text '
                   "contradiction; the erratum's consequence is suitably hedged."),
}
