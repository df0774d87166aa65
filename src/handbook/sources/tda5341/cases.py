"""The case against TDA5341: for each erratum, the passage it disputes word for word
(as the OCR reads it), how sure it is, and the most charitable reading of the source, answered (see
:class:`handbook.core.claim.Case`). The quotes are held against the app notes' text by a test."""
from ...core import Case

CASES = {
    'tda5341-tstart': Case(quote=(
        'a start frequency of 48.4 Hz can be chosen or t = 24 ms, thus C = 0.024/0.78 = 0.031',
    ), confidence='certain',
        charitable='No reading reconciles them: 1/48.4 Hz = 20.7 ms and 24 ms = 41.7 Hz; one of the '
                   'two numbers is wrong (the capacitor uses 24 ms). Survives.'),
    'tda5341-t-inertia': Case(quote=(
        'J = inertia J (kg/m 2 ).',
        'Example: J = 6.34 × 10 7 kg/m 2 , K = 4.5 × 10 3 N.m/A,',
        ('AN94002', 'J = inertia (kg.m<sup>2</sup>)'),
    ), confidence='probable',
        charitable="kg m2 is meant (AN94002 prints kg.m2, and the example's numbers give the printed "
                   '22.7 Hz with kg m2); the slash appears twice, so it is probably in the original '
                   'rather than an OCR slip. (The OCR lost the exponents\' minus signs: 6.34e-7 kg m2 '
                   'and 4.5e-3 N m/A are meant, which the book reads so.) Survives as trivial.'),
    'tda5144-max-delay': Case(quote=(
        ('datasheet facts', 'C = 6231 / f_C1 (nF), maximum delay 0.076 C ms;'),
        ('datasheet facts', 'CAP-CD datasheet text: charge 8.1 uA, discharge 16.2 uA, range "0.9 to 2.2'
                          ' V",'),
    ), confidence='probable',
        charitable="The text's own 8.1 uA / 1.3 V gives its 6231 exactly, so the same 1.3 V / 16.2 uA"
                   ' should give 0.0802 ms/nF; only an odd mix of table columns (2.55 V max high '
                   'minus 0.875 V typ low, at 22 uA max) comes near 0.076. Survives, but rests on the'
                   " book's reading of a datasheet that is not among the sources."),
}
