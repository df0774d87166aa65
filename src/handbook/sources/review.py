"""The decisions an independent review of the errata led to (the errata chapter shows them).

The review (2026-11-25) read each of the 56 errata registered then against the passage it disputes and
recomputed the numbers. Each of its points was checked against the source before anything changed; where the
book disagrees with the review, ``why`` says so. Outcomes:

* ``kept``: the erratum holds as registered (its evidence may be corrected);
* ``tempered``: the error is real, but the entry claimed more than can be shown, and now claims less;
* ``merged into <id>``: the same fact as another entry, now listed there as another place;
* ``reading note``: not an error of the source (lost OCR, a reconstruction, missing public data, a lower bound
  read as a contradiction): moved to the reading notes;
* ``removed``: not an error; the number stays in the examples registry with the status its numbers earn;
* ``rewritten as <id>``: the entry misdescribed the source; the real slip is registered under the new id.

A later sentence-by-sentence re-read of every source proposed new errata; a second reader whose only job was to
defend the sources tried to knock each down (:data:`REREAD`): ``registered`` (with the hedge the defence left)
or ``not registered``.
"""
from __future__ import annotations

from dataclasses import dataclass

OUTCOMES = ("kept", "tempered", "merged into", "reading note", "removed", "rewritten as", "registered", "not registered")


@dataclass(frozen=True)
class Decision:
    """What was decided about one erratum the review read."""

    id: str
    verdict: str  # what the review said: real, false, overstated, OCR note
    outcome: str  # one of OUTCOMES, "merged into" and "rewritten as" followed by the id
    why: str

    def __post_init__(self):
        if not any(self.outcome == o or self.outcome.startswith(o + " ") for o in OUTCOMES):
            raise ValueError(f"{self.id}: outcome {self.outcome!r} is not one of {', '.join(OUTCOMES)}")

    @property
    def target(self) -> str:
        """The id an entry was merged into or rewritten as ('' otherwise)."""
        for o in ("merged into ", "rewritten as "):
            if self.outcome.startswith(o):
                return self.outcome[len(o):]
        return ""


@dataclass(frozen=True)
class Review:
    """One review of the errata and the decision on every id it read."""

    date: str
    scope: str
    decisions: tuple[Decision, ...]


def _d(id_, verdict, outcome, why) -> Decision:
    return Decision(id=id_, verdict=verdict, outcome=outcome, why=why)


ERRATA_REVIEW = Review(date="2026-11-25", scope="the 56 errata registered then, each against its passage", decisions=(
    # AN94002
    _d("an94002-capst-datasheet", "real", "kept", "the TDA5144's own levels (0.20/2.20 V) and example (0.25 uF)"),
    _d("an94002-ich-max", "real", "kept", "22 uA is the sink maximum; rests on the book's pairing of the datasheet's "
       "scrambled columns, "
       "so 'probable'"),
    _d("an94002-vbe", "false", "removed", "agreed: T2 runs at milliamps to tens of milliamps, where BC556-558 sheets "
       "give up to 0.82 V (10 mA); the 2 mA column does not bound it. Now 'bound met' against 0.82 V"),
    _d("an94002-window-high", "real", "kept", "74.07 + 9 mV = 83.07 mV; 90.5 mV is AN93008's window, copied"),
    _d("an94002-window-low", "real", "merged into an94002-window-high", "the same copied sentence: one fact"),
    _d("an94002-zener-spread", "real (minor)", "kept", "the C8V2's 7.7 to 8.7 V is +-6.1 %; the charitable reading "
       "(the maker's own 'approx. +-5 %') is stated"),
    _d("an94002-shift-7v7", "real (minor)", "merged into an94002-zener-spread",
       "a consequence of the same +-5 % reading (the shift computed at 7.79 V, not 7.7 V: 4 mV short)"),
    _d("an94002-zener-tc", "false", "removed", "agreed: 6.2 mV/K at 8.2 V is 0.076 %/K, inside a column printed to "
       "one figure (+0.08 %/K holds up to 0.085 %/K). Now 'bound met'"),
    _d("an94002-resistor-tol", "real", "kept", "recomputed: -86 %/+85 % at the corners of 1 % parts"),
    _d("an94002-total-exact", "real", "merged into an94002-resistor-tol", "recomputed (-98.8 %/+106 %), but the same "
       "fact as the resistor term it follows from; its consequence ('not guaranteed to limit at all') was "
       "overstated and now gives the range"),
    _d("an94002-eq2", "OCR note", "reading note", "a reconstruction of garbled OCR, not an error of the note"),
    _d("an94002-t-dvcapmin", "real", "tempered", "one name for two quantities holds; the '14 times' rests on the "
       "book's assumed 0.1 V noise floor, which the entry now says"),
    _d("an94002-t-160", "real (trivial)", "kept", "notation only, and registered as such"),
    _d("an94002-t-1v", "real (minor)", "tempered", "the two figures are printed; the evidence no longer leans on the 2 mA "
       "V_BE column"),
    _d("an94002-t-12nc", "overstated", "tempered", "agreed: R1 '...53229' is 22 ohm by the decade rule (the decoder "
       "already used it); R14 and C6 stay, each marked as possibly the OCR's"),
    _d("an94002-t-cadcd", "real (trivial)", "kept", "a typing slip"),
    # AN93008
    _d("an93008-resistor-tol", "real", "kept", "recomputed: -422 %/+407 % with 5 % R8..R11"),
    _d("an93008-zener-spread", "real (minor)", "kept", "as AN94002; the note itself uses the 7.7 V minimum next"),
    _d("an93008-zener-tc", "false", "removed", "as an94002-zener-tc"),
    _d("an93008-zener-share", "real (minor)", "merged into an93008-zener-spread", "the same +-5 % reading carried "
       "into the +-7 % share; its aside with 6.56 mV/K is gone with the false TC"),
    _d("an93008-t-unit", "real (low confidence)", "reading note", "the review's own caveat decides it: the math OCR "
       "left an empty '\\text{ }' exactly where '%/' belongs ('%' starts a LaTeX comment), and AN94002 prints the "
       "same sentence with '%/°C'; the charitable reading (an OCR loss) is the likely one"),
    _d("an93008-t-gnd", "real", "kept", "a literal contradiction between the two notes"),
    _d("an93008-t-fig4", "false (not an erratum)", "reading note", "agreed: an OCR gap, and the text is consistent"),
    # TDA5341 / TDA5144
    _d("tda5341-tstart", "real", "kept", "1/48.4 Hz = 20.7 ms, not 24 ms"),
    _d("tda5144-max-delay", "real (unverifiable here)", "kept", "rests on the book's reading of the TDA5144 "
       "datasheet, so 'probable'"),
    _d("tda5341-capcdm", "OCR note", "reading note", "a reconstruction of garbled OCR"),
    _d("tda5341-t-inertia", "real (trivial)", "kept", "kg/m2 for kg m2"),
    _d("tda5341-t-typical", "overstated", "reading note", "agreed: design advice with typical currents, not a "
       "claim of a worst-case design, and no spread is published here"),
    # LM4651/LM4652
    _d("lm4651-f-15k", "real", "kept", "now the one entry for eq 5 against the table and pin 16, listing the other "
       "places"),
    _d("lm4651-f-0", "real", "merged into lm4651-f-15k", "the same fact: eq 5 disagrees with the table"),
    _d("lm4651-f-pin-15k5", "real", "merged into lm4651-f-15k", "the same fact, in the pin 16 text"),
    _d("lm4651-f-pin-0", "real", "merged into lm4651-f-15k", "the same fact, in the pin 16 text"),
    _d("lm4651-t-frange", "real (duplicate)", "merged into lm4651-f-15k", "the four printed ranges are the same fact"),
    _d("lm4651-dead-time", "real", "kept", "0.85 ns by eq 4 against the table's 27 ns"),
    _d("lm4651-rosc", "overstated", "tempered", "agreed: the table's own 'R_OSC = 4k, f_SW = 125kHz' row supports "
       "3.9 k; the clash with the '+2 k for R_DLY = 5 k' rule stays (inconsistent, not misprint), and the "
       "heat consequence is now conditional on the board running at 169.5 kHz"),
    _d("lm4651-hp-corner", "real (trivial)", "kept", "6.366 Hz printed 6.35: neither rounded nor truncated"),
    _d("lm4651-isckt", "real", "kept", "eq 3 gives 11.0 A at 100 k"),
    _d("lm4651-overmod", "real", "kept", "the text says it uses the table's typical values; the table says 310 ns"),
    _d("lm4651-pd-75k", "overstated", "reading note", "agreed: the datasheet never says eq 9 reproduces that row; a "
       "6 % miss of an empirical estimate is a note on the model"),
    _d("lm4651-eta-5w", "false", "removed", "agreed: the total quiescent current is |I_VCC+| + |I_VEE-| (LM4651 table), "
       "so 124 mA costs 20 V x 124 mA = 2.48 W and 55 % is below the 66.8 % bound. Now 'bound met'"),
    _d("lm4651-l1-rating", "real (minor)", "kept", "5.59 A rms at the rated 125 W against a 5 A part; hedged on the "
       "kind of rating"),
    _d("lm4651-eps0", "real (trivial)", "kept", "now 'misprint' (a misprinted constant), not 'inconsistent'"),
    _d("lm4651-gain-4k7", "real", "kept", "strengthened as the review found: 7.947 is 18.0 dB, the system table's "
       "A_V = 18 dB, so figure 1's values are right and the text's 7.5 is the slip"),
    _d("lm4651-eq12", "false (misdescribed)", "rewritten as lm4651-t-eq-labels", "agreed: printed intact; '(3)' is "
       "the Example's own label, which clashes with eq 3. The record is now empirical (the Example's 7.5 with "
       "R2 = 0.7 R1), not 'agrees' on a simplification of itself"),
    _d("lm4651-filter", "OCR note", "reading note", "a reconstruction of garbled OCR"),
    _d("lm4651-t-50uf", "real (trivial)", "kept", "'50uF' inductor"),
    _d("lm4651-t-rds", "real", "kept", "the 100 C figure is not in the 25 C table"),
    _d("lm4651-t-r1", "overstated", "tempered", "agreed: 20 k and 4.7 k are an explicit alternative; only the DC-offset "
       "section's 25 k is odd, and figure 1's C_IN is unknown"),
    _d("lm4651-t-170w", "real (minor)", "kept", "the headline drops the 75 kHz condition"),
    _d("lm4651-t-standby", "false", "reading note", "agreed: three compatible lower bounds; the note says to design "
       "with the guaranteed 100 dB"),
    _d("lm4651-t-theta-ja", "real", "kept", "52 against 62 K/W in one datasheet"),
    _d("lm4651-t-ilimit", "real (moderate)", "kept", "marked 'depends on the OCR' (the abs-max block's pairing)"),
    _d("lm4651-t-pin15", "real", "kept", "marked 'depends on the OCR'"),
    _d("lm4651-t-gain-r", "real (minor; partly overstated)", "tempered", "the error amplifier's own gain is set by "
       "R_f/R1; the slip is the components table calling it the system's and the Example inserting R_f and V_CC"),
    _d("lm4651-t-supply", "false (not an erratum)", "reading note", "agreed: consistent; the OCR lost the graph"),
    # TCA5600
    _d("tca5600-t-values", "false (not an erratum)", "reading note", "agreed: missing public data is not an error of "
       "the source"),
))

REREAD = Review(date="2026-11-25", scope="new errata from a sentence-by-sentence re-read, each defended by a second "
                "reader", decisions=(
    _d("an94002-t-mosfet", "stands", "registered", "the defence ('MOSFET' as a loose word for the pass transistor) "
       "fails: the note names its BD434 and has no MOSFET; the sentence is AN93008's"),
    _d("lm4651-t-c1-value", "weakened", "registered", "as a grouping slip in the table, the text's 0.1 to 1 uF "
       "governing; the proposal's 'the common mistake' was dropped (the datasheet limits that warning to "
       "single-ended use)"),
    _d("lm4651-t-torque", "stands", "registered", "no unit or fastener fits both printed figures; 'probable', since it "
       "rests on makers' mounting notes outside the sources"),
    _d("lm4651-t-esd-pins", "weakened", "registered", "only as 'one of the two tables is wrong' (OCR or print), not as "
       "a claim about which"),
    _d("lm4651-t-roffset", "weakened", "registered", "as a mis-worded test condition with no consequence once read as "
       "'not fitted'"),
    _d("an93008-t-onchip", "knocked down", "not registered", "'the IC with external output driver' need not be one of "
       "the three ICs named: the note covers the whole TDA514x family, and its limiters act on the supply path, "
       "which serves either output stage"),
))

#: what the same re-read considered and rejected itself, each with its reason (checked, not worth an accusation)
REREAD_REJECTED = Review(date="2026-11-25", scope="candidates the re-read rejected before any defence", decisions=(
    _d('reread-r1', 'LM4651 abs. max \'1.5W\' / \'32W\' (P_D of LM4651 / LM4652) vs Note 3 derating "based on a 150°C maximum'
       ' junction temperature and ... θ_JA = 62 °C/W" / "θ_JC = 2.0 °C/W"',
       "not registered", '(150−25)/62 = 2.0 W (2.4 W with 52 K/W) and (150−25)/2.0 = 62.5 W (125 W for T) do not give 1.5 W / '
       '32 W. But a flat P_D cap that meets the θ line at T = 57 °C / 86 °C is a legitimate way to rate a '
       'part, and the OCR scrambles the label-to-value pairing of this block. Not provable.'),
    _d('reread-r2', 'LM4651 "is the $R_{DS_{(ON)}}$ of the FET times the RMS output current" and "multiplying the output '
       'current times the $R_{DS(ON)}$"',
       "not registered", 'Strictly I·R is a voltage, not a power. But both sentences stand next to the correct '
       '(I_rms)²·2R_DS(on) formula, and the example computes with it. This is wording, with no numerical '
       'effect.'),
    _d('reread-r3', "LM4652 'Maximum Saturation Drain Current' min 8 A (V_GS = 6 V) vs 125 W peak 7.91 A plus ripple, and"
       ' the 10 A limit',
       "not registered", 'It suggests that a minimum-spec part saturates before the 10 A limit trips. But the real gate drive '
       "in figure 1 is unknown (lost), and the 10 A theme is registered as 'lm4651-t-ilimit'. This is "
       'inference, not a contradiction.'),
    _d('reread-r4', 'TDA5341 "Without damping, a start frequency of 48.4 Hz can be chosen" (above f_osc = 22.7 Hz, '
       'whereas AN94002 goes *below* f_osc for high damping)',
       "not registered", "1/(2·22.75 Hz) = 22.0 ms. Pulsing at about half the oscillation period, at the rotor's forward "
       'overshoot, is a physically sensible choice without damping, so the two notes describe two different '
       "strategies. The 48.4 Hz ↔ 24 ms arithmetic is already 'tda5341-tstart'."),
    _d('reread-r5', 'the TDA5144 datasheet (as read for this book): CAP-CD text range "0.9 to 2.2 V" vs table high '
       'level 2.3 / 2.4 / 2.55 V',
       "not registered", "A real mismatch (the 1.3 V text window is below the table's 1.4 V minimum window), but it errs on "
       "the safe side (it gives a larger C) and depends on the book's stated column-pairing "
       'interpretation. The remark that "the typical values agree with the text" holds for the '
       "currents, not for the high level (2.4 V typical vs 2.2 V). Worth a note beside the datasheet's figures, not an "
       'erratum of a source.'),
    _d('reread-r6', 'LM4651 "The squarewave has a duty cycle proportional to the audio signal level."',
       "not registered", 'The duty cycle is affine (50 % at no signal, as the DC-offset section says). "Proportional" is '
       'colloquial here.'),
    _d('reread-r7', "LM4651 'Standby High Input Voltage' Min 2.5, Typical 2.0",
       "not registered", 'A guaranteed V_IH above the typical switching point is the normal convention, not a min > typ error.'),
    _d('reread-r8', 'AN94002 "BZX 79-family are available with tolerances of 1, 2, 3 and 5%" (AN93008: "5, 3, 2 and 1%")',
       "not registered", "The two notes agree with each other. The datasheet figures read for this book name only the B "
       "(2 %) and C (5 %) series, "
       'so the 3 % claim cannot be refuted from the sources.'),
    _d('reread-r9', 'LM4652 \'I _{DSS}\' "1.0 mA" at 44 V',
       "not registered", 'Unusually high for a MOSFET, and possibly an OCR µ→m. Unverifiable.'),
    _d('reread-r10', "LM4651 Example: heat sink sized for T_J = T_JMAX = 150 °C, which is also the LM4652's TSD threshold "
       '("goes high (6V) once the temperature ... reaches 150°C")',
       "not registered", 'With 2.5 K/W: 50 + 21·4.7 = 148.7 °C, 1.3 K below the trip point. This is a zero-margin design, not '
       "an error. The margin problem is already in 'lm4651-rosc''s consequence."),
    _d('reread-r11', "LM4651 eq (8) 'C = εo εr A/d (Farads)' with ε0 in pF/in",
       "not registered", 'With ε0 in pF/in the number comes out in pF. The unit label is loose, not wrong. The constant itself'
       " is 'lm4651-eps0'."),
    _d('reread-r12', 'AN93008 "R10 becomes 7.87 KΩ" (an E96, 1 %-only value) budgeted at "Resistor tolerances of ±5%"',
       "not registered", "A real oddity, but it is absorbed by 'an93008-resistor-tol', which already shows the 5 % budget is "
       'wrong.'),
    _d('reread-r13', 'AN94002 §2.2 "minimum allowed voltage drop across R7 and T1 of 1 V" while the one-transistor R7 '
       'drops up to 0.8 V',
       "not registered", 'R7 approaches 0.8 V only at the limit, where control has passed to T2 anyway. Not an error.'),
    _d('reread-r14', 'AN94002 parts list R7 "PR01" for option O12 (one-transistor too)',
       "not registered", '0.8 V × I_lim exceeds a ~1 W PR01 above about 1.25 A (1.6 W at the TDA5144\'s 2 A). But R7 is "TBD", '
       'the PR01 rating comes from outside the sources, and the user may pick another series. Too weak.'),
    _d('reread-r15', 'LM4651 Note 3 "For operating at case temperatures above 25°C, the LM4651 must be de–rated based on '
       '... θ_JA"',
       "not registered", 'Case temperature with a junction-to-ambient resistance is mismatched wording. The θ_JA value itself '
       "is 'lm4651-t-theta-ja'."),
    _d('reread-r16', 'LM4651 Features "15 Lead TO-220 isolated package." vs Note 8 \'LM4652TA ... is a non-isolated '
       'package\', and "T" vs "TA" for the same non-isolated package',
       "not registered", 'Marketing shorthand and a naming slip. Nothing for a designer to get wrong.'),
    _d('reread-r17', 'LM4651 eq (1) 8.4×10⁴ vs eq (2)/table 8.5×10⁴; "10µF ... check approximately every second" (0.84 s)',
       "not registered", "Already carried by the 'lm4651-cstart' row's reason and the 'lm4651-eq1'/'eq2' equation notes."),
    _d('reread-r18', 'LM4651 "In bridge operation, each output sees $C_{\\rm BYP}.$ This causes the extra factor of 2"',
       "not registered", 'Each half sees 2·C_BYP to the virtual midpoint. The wording is loose, but the formula and the "twice'
       ' C_BYP\'s value" alternative are right. Covered by \'lm4651-filter\'.'),
    _d('reread-r19', 'TCA5600 figure values (R4 "85K", not an E-series value) and LM4651 "R₂ ... 3.5kΩ" (not E24/E96)',
       "not registered", "Non-standard values, possibly OCR. No arithmetic depends on them beyond what 'lm4651-gain-4k7' "
       'covers.'),
))

__all__ = ["ERRATA_REVIEW", "OUTCOMES", "REREAD", "REREAD_REJECTED", "Decision", "Review"]
