"""The case against AN94002: for each erratum, the passage it disputes word for word
(as the OCR reads it), how sure it is, and the most charitable reading of the source, answered (see
:class:`handbook.core.claim.Case`). The quotes are held against the app notes' text by a test."""
from ...core import Case

CASES = {
    'an94002-capst-datasheet': Case(quote=(
        'with a current of 2 $\\mu$ A, from 0.05 V to 2.2 V and back to 0.05 V.',
        'According to equation (1) CAP-ST $\\approx 0.23 \\mu F$ .',
        ('datasheet facts', 'CAP-ST: charge and discharge current 2.0 uA typ (1.5 to 2.5 uA); switching'
                          ' levels 0.20 V and 2.20 V.'),
    ), confidence='probable',
        charitable='The note is self-consistent (0.5 s / 2.15 = 0.233 uF); its 0.05 V level and 2.15 '
                   'factor come from the TDA5141/TDA5145 datasheets, while the TDA5144 datasheet (as'
                   ' read for this book) switches at 0.20/2.20 V and gets 0.25 uF. The erratum '
                   'survives, though the +-25 % spread of the 2 uA current is larger than the 7 % '
                   'difference.'),
    'an94002-ich-max': Case(quote=(
        'With $\\Delta V_{\\text{capmin}} = 2.3 - 0.9 = 1.4 \\text{ V}$ and $I_{\\text{chmax}} = 22 \\ '
        '\\mu\\text{A}$ the CAP-CD is determined as follows:',
        'The discharge of CAP-CD is done with a current twice the charge current',
        ('datasheet facts', 'discharge (sink) current 10.6 / 16.2 / 22 uA; charge (source) current 5.3 '
                          '/ 8.1 / 11 uA;'),
    ), confidence='probable',
        charitable='The note may have taken 22 uA as a deliberate safety margin, but it calls it the '
                   'maximum charging current while saying itself that discharge is twice the charge '
                   "current, so 22 uA can only be the sink maximum. Survives, resting on the book's "
                   "pairing of the datasheet's scrambled columns (stated as an interpretation)."),
    'an94002-window-high': Case(quote=(
        'This means a voltage 74.1 mV on the op-amp input at $V_{cs} = 100$ mV.',
        'the output of the op-amp will become active at input voltages varying between 90.5 and 72.5 '
        'mV, which means an initial tolerance $\\pm 12\\%$ .',
        ('AN93008', 'This gives a voltage 81.5 mV on op-amp input at $V_{\\text{cs}} = 100$ mV.'),
    ), confidence='certain',
        charitable="The +-12 % (9/74.1) is right; only the two window figures are AN93008's 81.5 +- 9"
                   ' mV copied unchanged (AN93008 prints the same 90.5/72.5 sentence). Survives: 74.1'
                   ' + 9 = 83.1 mV.'),
    'an94002-zener-spread': Case(quote=(
        'For the calculations a zener diode is taken with a tolerance of $\\pm$ 5 %.',
        ('datasheet facts', 'BZX79-C8V2: V_Z 7.7 to 8.7 V at 5 mA;'),
        'have been calculated for a level shift of 2 V at a V<sub>D1</sub> of 8.2 V - 5% (7.79 V) and'
        ' V<sub>cs</sub> = 0 V.',
    ), confidence='probable',
        charitable="+-5 % is the maker's nominal C-series band ('about +-5 %'), so the note repeats "
                   "Philips' own label; the datasheet limits 7.7/8.7 V are -6.1/+6.1 %. Survives as a"
                   ' minor point: a worst-case budget should use the limits.'),
    'an94002-resistor-tol': Case(quote=(
        'Resistors tolerance: $\\pm$ 5 %',
        'R10 O2 5.6 K $\\Omega \\pm 1\\%$ SFR25 2322 181 53562',
        'By choosing R11 = R13 and R10 = R12 for $V_{cs}$ the following applies:',
        'Total initial tolerance : ± 23 % (1.12 x 1.05 x 1.05)',
    ), confidence='certain',
        charitable="The note asserts +-5 % without derivation and only asks for 'low-tolerance "
                   "resistors'; it may have meant matched pairs. Even so, V_cs = V_D1(1 - B/A) is a "
                   '~1 % difference of two ratios, and independent 1 % parts move it about -86/+85 %:'
                   ' survives.'),
    'an94002-t-dvcapmin': Case(quote=(
        'With $\\Delta V_{\\text{capmin}} = 2.3 - 0.9 = 1.4 \\text{ V}$',
        'calculated with a minimum allowable voltage excursion ( $\\Delta V_{capmin}$ ) and the '
        'minimum charge current ( $I_{chmin}$ ) for CAP-CD.',
        'the minimum value of the maximum possible voltage excursion $(\\Delta V_{capmax})$ on CAP-CD',
    ), confidence='certain',
        charitable="The note's intent is readable (eq 5's text and eq 8 call the window dV_capmax), "
                   'but eq 6 prints dV_capmin = 1.4 V for the window and eq 7 uses the same name for '
                   "the noise floor. Survives as a text fault; the '14 times too low' in the "
                   'consequence rests on an assumed 0.1 V floor that the note never gives.'),
    'an94002-t-160': Case(quote=(
        'CAP-CD $\\geq$ 160 / 1800 x 6 = 0.0148 $\\mu F$ : Take C3 = 18 nF.',
    ), confidence='certain',
        charitable='Informal notation: 160/(1800 x 6) = 0.014815 matches the printed 0.0148, so the '
                   'intent is unambiguous. Survives only as a trivial notation slip.'),
    'an94002-t-1v': Case(quote=(
        'The one-transistor current needs a voltage drop of about 1 V before the limiter becomes '
        'active.',
        'that is based upon the voltage drop of about 0.8 V across a current sense resistor R7.',
    ), confidence='certain',
        charitable="Both are rough figures ('about'), and the take-over voltage does depend on T2's "
                   'current; but the same note gives two figures 25 % apart for the same V_be of the '
                   'same circuit without saying why. Survives as a minor inconsistency, not as a '
                   'claim about which is right.'),
    'an94002-t-12nc': Case(quote=(
        'R14 O2 $750 \\pm 5\\%$ SFR25 2322 181 53701',
        '220 nF 10 nF 220 nF 220 nF 10 μF 10 μF',
        '2222 370 17224 2222 370 17224 2222 370 17224 2222 370 17224 2222 370 17224',
    ), confidence='depends on the OCR',
        charitable='By the decade rule seen in the same list (53681 = 680, 53229 = 22, 21183 = 18 nF)'
                   " R14's ...701 is 700 ohm, not 750 (...751), possibly a 5->0 OCR slip; C6's code "
                   'cannot be aligned for sure because the code column holds 11 codes (5 x 17224) for'
                   ' 10 capacitors (and 5 codes for R16..R19). Survives as hedged, depending on the '
                   'OCR; the text itself confirms C6 = 0.010 uF.'),
    'an94002-t-mosfet': Case(quote=(
        'the transistor T2 turns-on and decreases the drive for the MOSFET that determines the voltage',
        'is regulated in an analogue way by a series regulator transistor T1 (BD434).',
        ('AN93008', 'the transistor T1 turns-on and decreases the drive for the MOSFET that determines the voltage'),
    ), confidence='certain',
        charitable="'MOSFET' could be a loose word for the pass transistor, but the note names its device (the "
                   "BD434) and the word is spelled out in a clean paragraph, so no OCR reading explains it: the "
                   "sentence was carried over from AN93008, which covers either device. Survives as a wording slip "
                   "of small consequence; a second reader, asked only to defend the note, found no reading that "
                   "clears it."),
    'an94002-t-cadcd': Case(quote=(
        'With the signal on CAD-CD only three of the 6 commutations per cycle can be done.',
        'CAD-DC has been connected to a similar timer circuit and needs the same capacitor value as '
        'used for CAD-CD.',
    ), confidence='probable',
        charitable='Three consistent occurrences suggest a typo in the original rather than OCR; the '
                   'meaning (CAP-CD, CAP-DC) is obvious. Survives as a trivial typo.'),
}
