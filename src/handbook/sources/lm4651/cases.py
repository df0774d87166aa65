"""The case against LM4651/LM4652: for each erratum, the passage it disputes word for word
(as the OCR reads it), how sure it is, and the most charitable reading of the source, answered (see
:class:`handbook.core.claim.Case`). The quotes are held against the app notes' text by a test."""
from ...core import Case

CASES = {
    'lm4651-f-15k': Case(quote=(
        'Switching Frequency Range $R_{OSC} = 15k\\Omega$ 65 kHz',
        '$f_{OSC} = 1 \\times 10^9 / (4000 + R_{OSC})$ (Hz) (5)',
        'Switching Trequency Range $R_{OSC} = 0\\Omega$ 200 kHz',
        'Adjusting the resistor from $15.5k\\Omega$ to 0Ω changes the switching frequency from 75kHz '
        'to 225kHz.',
        '50kHZ to 200kHz switching frequency range.',
    ), confidence='certain',
        charitable='Eq 5 is stated for R_DLY = 0 and the table is under Figure 1 conditions (R_DLY = '
                   "5 k), but the note's +2 k correction lowers the frequency (58.8 kHz), moving it "
                   'further from 65 kHz. Survives.'),
    'lm4651-dead-time': Case(quote=(
        'Dead Time $R_{DLY} = 0\\Omega$ 27 ns',
        '$$T_{DLY} = 1.7 \\times 10^{-12} (500 + R_{DLY})$$',
    ), confidence='certain',
        charitable='Eq 4 gives 0.85 ns at R_DLY = 0 (9.35 ns at the recommended 5 k), 32 times below '
                   "the table's 27 ns; a fixed driver delay outside eq 4 cannot plausibly close that "
                   'gap. Survives.'),
    'lm4651-rosc': Case(quote=(
        'The value of the resistor for R_{OSC} is found from Equation (6) to be 3.9 k Ω .',
        'For $R_{DLY} = 5k\\Omega$, R_{OSC} will need to be increased by about $2k\\Omega$.',
        '$R_{OSC} = 4k\\Omega$, $f_{SW} = 125kHz$',
    ), confidence='probable',
        charitable="The LM4651 table's own row 'R_OSC = 4k, f_SW = 125kHz' (figure 1's circuit) "
                   "supports the printed 3.9 k, so the Example may be right and the '+2 k' rule the "
                   'slip; either way two statements of the datasheet disagree, which survives. The '
                   'heat consequence is stated only for the case the +2 k rule holds.'),
    'lm4651-hp-corner': Case(quote=(
        'R_1 and the 1µF capacitor create a high pass filter with a 3dB point at 6.35Hz.',
    ), confidence='certain',
        charitable='6.35 Hz is what 2 pi taken as 6.3 gives (1/(6.3 x 25 k x 1 uF) = 6.349 Hz), an '
                   'intermediate the datasheet does not print; the book counts a rounded intermediate only '
                   'where the source prints it, so the print claims a third figure its constant did not '
                   'have. Survives as a trivial misprint of precision (0.25 %).'),
    'lm4651-isckt': Case(quote=(
        'With R_{SCKT} equal to 100k Ω , the current limit is 10A.',
        '$$I_{SCKT} = 1X10^{5}/(10k\\Omega \\| R_{SCKT})$$',
    ), confidence='certain',
        charitable="The writer may have treated 10 k || 100 k as 'about 10 k', but eq 3 gives 11.0 A,"
                   ' and 10 A is the limit with R_SCKT open. Survives.'),
    'lm4651-overmod': Case(quote=(
        '%Loss = (25ns+26ns+350ns) * 125kHz %Loss = 5.0%',
        'Over Modulation Protection Time Pulse Width Measured at 50% 310 ns',
        'Use the typical values given in the **Electrical Characteristics for the LM4651** and '
        '**Electrical Characteristics for the LM4652** tables',
    ), confidence='certain',
        charitable='350 ns may come from another datasheet revision or be a deliberate margin, but '
                   "the text says to use the table's typical values, which give 310 ns. Survives; the"
                   ' effect is conservative.'),
    'lm4651-l1-rating': Case(quote=(
        'L ₁ 47µH, 5A High Saturation Open Core (Vertical Mount Power Chokes)',
        'I_{OUTRMS} &= SQRT(125watts/4\\Omega) = 5.59 \\text{ amps}',
    ), confidence='probable',
        charitable='The 5 A may be a thermal rating for programme material, which rarely sustains '
                   'full sine, but the datasheet rates 125 W continuous into 4 ohm (5.59 A rms); if '
                   'it is a saturation rating all three chokes lie below the 7.9 A peak. Survives as '
                   'a minor, hedged point.'),
    'lm4651-eps0': Case(quote=(
        'where $\\epsilon o = 0.22479 p F/in and \\epsilon r = 4.1$',
    ), confidence='certain',
        charitable='0.22479 is what a three-figure epsilon_0 (8.85e-12 F/m, not printed) gives x 0.0254 '
                   'm/in; printed to five figures, its last two digits claim a precision the constant '
                   'did not have. Survives as a trivial misprint of precision (0.05 %), not as a wrong '
                   'constant.'),
    'lm4651-gain-4k7': Case(quote=(
        "with R₁'s value set to 4.7k Ω and R₂'s value set to 3.5k Ω for a gain 7.5V/V.",
        'reducing gives the equation below: $$R_2 = .7R_1$$ (4)',
        '10W, 10Hz $\\leq f_{\\text{IN}} \\leq$ 500Hz, A $_{\\rm V}$ = 18 dB',
    ), confidence='certain',
        charitable='With R_f11 = 620 k and R_f12 = 62 k, eq 12 is 10 R2/R1 + 0.5: 3.5/4.7 gives 7.95 '
                   "(18.0 dB, matching the table's A_V = 18 dB), not 7.5. Survives; the figure 1 "
                   "values are right and the '7.5' is the slip."),
    'lm4651-t-50uf': Case(quote=(
        'National has found good results with a 50µF inductor and a 5µF Mylar capacitor',
        'A typical 4 Ω load driven by a filter using 50µH inductors does not require more than 10A.',
    ), confidence='probable',
        charitable='Obviously 50 uH is meant (the Example and parts table use 50 uH chokes); an OCR '
                   'H->F confusion is unlikely, so probably a typo in the original. Survives as '
                   'trivial.'),
    'lm4651-t-rds': Case(quote=(
        'The value for $R_{DS(ON)}$ at 100°C is used since we are calculating the maximum power '
        'dissipation.',
        'Static Drain-to-Source On Resistance $VGS = 6V_{DC}, ID = 6A_{DC}$ 200 300 mΩ',
    ), confidence='certain',
        charitable='The 0.230 ohm may come from an unpublished characterisation curve, but the table '
                   'the text points to gives only 200/300 mOhm at 25 C; at 100 C R_DS(on) typically '
                   'rises 1.4-1.6 x, so 0.230 is optimistic. Survives (if anything understated).'),
    'lm4651-t-r1': Case(quote=(
        'to the input (other side of 25k, R1).',
        'The input resistance is desired to be $20k\\Omega$ so R_1 is set to $20k\\Omega$.',
        'The drawback to a lower R₁ value is a larger C_{IN} value, necessary to properly couple the '
        'lowest desired signal frequencies.',
    ), confidence='probable',
        charitable='20 k and 4.7 k are explicit alternatives in the Example, which warns that a lower'
                   ' R1 needs a larger C_IN; the 1 uF is only paired with the 25 k of the DC-offset '
                   "section and figure 1's C_IN is lost. What survives is only the 25 k, which "
                   'matches neither of the Example\'s values.'),
    'lm4651-t-170w': Case(quote=(
        '170W Class D Audio Power Amplifier Solution',
        '$f_{SW} = 75$ kHz, $R_L = 4\\Omega$, 10% THD 170 W',
        '$R_{L} = 4\\Omega$, 10% THD 155 W',
    ), confidence='probable',
        charitable='Headlining the best tabulated condition is usual marketing and 75 kHz is inside '
                   'the supported range, but the key specification drops that condition while the '
                   "table's default (125 kHz) gives 155 W. Survives as minor; the key-spec pairing of"
                   " '170W (Typ)' with its label is positional in the OCR."),
    'lm4651-t-c1-value': Case(quote=(
        'C ₁ & C _{BYP} 5µF - 10µF Metalized Polypropylene or Polyester Film',
        "Filters high frequency noise from the amplifier's output to ground. Recommended value is 0.1μ F to 1μ F.",
        'The recommended value for C₁ is 0.1µF to 1µF',
    ), confidence='probable',
        charitable="The row may be a supplier pointer for both film capacitors, its values meant for C_BYP (5 uF) "
                   "and the output-to-ground alternative (10 uF, twice C_BYP), with C1 grouped in by accident; the "
                   "same table's 'C_B1 & C_BT 0.1uF' reads '&' as both parts taking the value, and the row is "
                   "printed twice, so it is no OCR loss. Survives as a grouping slip, the text's 0.1 to 1 uF "
                   "governing; a second reader who defended the source weakened it to this."),
    'lm4651-t-torque': Case(quote=(
        'The recommended maximum torque applied to the mounting screw is 40 inch-lbs. or 3.3 foot-lbs.',
    ), confidence='probable',
        charitable="The two figures agree (40 / 12 = 3.3), so it is no one-digit slip, and no unit (inch-ounces, "
                   "another fastener) fits both; the next sentences tie the screw to warping the package. It rests "
                   "on outside mounting data (no source here gives a torque), hence 'probable'; a second reader "
                   "found no reading that clears it."),
    'lm4651-t-esd-pins': Case(quote=(
        'LM4652 (pins 2,6,10,11)',
        '11 NC No connection.',
        '14 HG₁ High-Gate #1 is the gate input to a top side MOSFET in the H-Bridge.',
    ), confidence='depends on the OCR',
        charitable="The rating block is badly damaged by the OCR, and a 4 read as 1 on an identical label printed "
                   "twice would repeat; the pin table has a slip of its own. Survives only as 'one of the two is "
                   "wrong', which is what a second reader defending the source conceded."),
    'lm4651-t-roffset': Case(quote=(
        'V_{IN} = 0V, I_O = 0mA, R_{OFFSET} = 0 Ω 0.7 V',
        'The divider should be a $1.8M\\Omega$ from the +6V output (pin 6) to the input (other side of 25k, R1).',
    ), confidence='probable',
        charitable="'0 Ω' may be house shorthand for 'not fitted', and the intent (the offset before correction) is "
                   "clear from the 1.8 M figures; but the same datasheet writes '0 Ω' literally for R_DLY and R_OSC, "
                   "so as printed the condition says something else. Survives as a mis-worded test condition of no "
                   "consequence once read as intended."),
    'lm4651-t-theta-ja': Case(quote=(
        'Thermal Resistance LM4651 N Package θJA θJC 52°C/W 22°C/W',
        'the LM4651 must be de–rated based on a 150°C maximum junction temperature and a thermal '
        'resistance of $\\theta_{JA} = 62$ °C/W',
    ), confidence='depends on the OCR',
        charitable="52 vs 62 is a classic 5/6 OCR confusion, so one figure may be the OCR's; as "
                   'printed in this text the two disagree. Survives on the text, with derating at 62 '
                   'K/W the safe choice.'),
    'lm4651-t-ilimit': Case(quote=(
        'Short circuit setting pin. Minimum setting is 10A.',
        'The current limit is set to a minimum of 10A internally but can be increased by adjusting '
        'the value of the R_{SCKT} resistor.',
        'Supply Voltage Output Current (LM4652)',
        '-40°C to + 150°C ± 22V 10A 1.5W 32W',
    ), confidence='probable',
        charitable='The trip is a fail-safe against shorts, not an operating limit, and the Example '
                   'asks to keep peak plus ripple below 10 A; but a limit that can only be set at or '
                   "above the 10 A absolute maximum (paired with 'Output Current (LM4652)' only by "
                   'position in the OCR) is odd. Survives, resting on that pairing.'),
    'lm4651-t-pin15': Case(quote=(
        '15 VO ₂ The switching output pin for one side of the H-Bridge.',
        'This must be connected to the feedback filter from V_{O1} (pin 15 on the LM4652).',
    ), confidence='depends on the OCR',
        charitable='The LM4651 pin text names pin 15 V_O1, and pin 15 sits next to HG1, so VO1 is '
                   "meant; the subscript 2 may be the OCR's misread of 1. Survives as a text/OCR "
                   'point.'),
    'lm4651-t-gain-r': Case(quote=(
        "This inverting amplifier's gain is externally configurable by resistors Rf and R1.",
        'Sets the gain and bandwidth of the system by creating a low pass filter for the Error '
        "Amplifier's feedback with C _f .",
        'The value of V_{CC} was also found as the first step in this example to be ±20V. Inserting '
        'these values into equation (12)',
    ), confidence='probable',
        charitable="The error amplifier's own stage gain is legitimately set by R_f/R1 and is not the"
                   ' system gain, so that sentence is not a fault; the real slips are the components '
                   "table's 'gain ... of the system' for R_f and the Example inserting R_f and V_CC "
                   'into eq 12, which contains neither.'),
    'lm4651-t-eq-labels': Case(quote=(
        '[(R_2/R_1) \\times ((R_{f11} + R_{f12})/R_{f12}) - (R_2/R_1) + .5].(3)$$',
        '$$R_2 = .7R_1$$ (4)',
        'Gain = $[(R_2/R_1) \\times ((R_{f11} + R_{f12})/R_{f12}) - (R_2/R_1) + .5]$.',
    ), confidence='certain',
        charitable='The formula itself is printed intact, identical to the components table; only its'
                   " labels are at fault: '(3)' and '(4)' are the Example's own numbering, which "
                   "clashes with eq 3 and eq 4 while the text calls the formula 'Equation (12)'. A "
                   'reader who follows the labels looks up the wrong equations.'),
}
