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

__all__ = ["ERRATA_REVIEW", "OUTCOMES", "REREAD", "Decision", "Review"]
