"""The design specification in one table: every key of every table, with its default, unit, range and
meaning, and every result each design reports.

Validation (:mod:`handbook.design.spec`), the command line's help, the README's key table and the design
chapters' ``parameters`` cells are all read from here; ``tests/design/test_schema.py`` fails when the
README or a parameters cell drifts from it. Values are SI (F, A, V, ohm, W, K/W; rpm for speeds;
tolerances and THD as fractions).
"""
from __future__ import annotations

from ..core import Param
from ..core.series import SERIES_NAMES

_POS = dict(low=0.0, low_open=True)
_FRACTION = dict(low=0.0, high=0.999)


def _series(name: str, default: str, what: str) -> Param:
    return Param(name=name, default=default, unit="", meaning=f"E-series for {what}", choices=SERIES_NAMES)


def _resistor(name: str, series_name: str, low: float, high: float, what: str) -> tuple[Param, ...]:
    """A resistor the limiter design chooses: its value (give it to pin the part), series and range."""
    return (
        Param(name=name, default=None, unit="ohm", high=1e9, **_POS,
              meaning=f"{what}: give a value to pin it (leave out: the design chooses it)"),
        _series(f"{name}_series", series_name, name.upper()),
        Param(name=f"{name}_min", default=low, unit="ohm", meaning=f"smallest {name.upper()}", high=1e9, **_POS),
        Param(name=f"{name}_max", default=high, unit="ohm", meaning=f"largest {name.upper()}", high=1e9, **_POS),
    )


def _limiter() -> tuple[Param, ...]:
    """The op-amp limiter (AN94002 figure 3) as a whole network: limits, tolerances, devices, resistors."""
    return (
        Param(name="i_no_trip", default=0.9, unit="A", high=100.0, **_POS,
              meaning="current at or below which the limiter must never act",
              cite="half the TDA5144's minimum internal limit"),
        Param(name="i_must_trip", default=1.8, unit="A", high=100.0, **_POS,
              meaning="current at or below which it must always have acted",
              cite="TDA5144 output current limit, minimum 1.8 A"),
        Param(name="min_margin", default=0.02, unit="1", low=0.0, high=0.5,
              meaning="margin kept inside both limits at every corner, fraction of each limit (what the corners "
                      "leave out: R7's temperature coefficient over its own rise while it holds a stalled motor, "
                      "copper in series with R7, the zener's dynamic resistance)"),
        Param(name="resistor_tolerance", default=0.01, unit="1", meaning="tolerance of R9..R13, fraction",
              **_FRACTION),
        Param(name="r7_tolerance", default=0.05, unit="1", meaning="tolerance of the sense resistor R7, fraction",
              **_FRACTION),
        Param(name="zener_voltage", default=8.2, unit="V", meaning="nominal zener voltage of D1", high=100.0,
              **_POS),
        Param(name="zener_tolerance", default=0.061, unit="1", meaning="zener tolerance, fraction", **_FRACTION,
              cite="BZX79-C8V2 datasheet: V_Z 7.7 to 8.7 V at 5 mA, +-6.1 % (the C series' nominal +-5 % is "
                   "narrower than its own limits)"),
        Param(name="zener_tc", default=6.6e-3, unit="V/K", low=0.0, high=0.1,
              meaning="largest zener temperature coefficient (drift either way)",
              cite="BZX79-C8V2 datasheet: +0.08 %/K max, 6.6 mV/K at 8.2 V (AN94002 2.4 quotes 6.2 mV/K)"),
        Param(name="temp_span", default=25.0, unit="K", low=0.0, high=200.0,
              meaning="temperature excursion either side of 25 C", cite="AN94002 2.4: 25 C +- 25 C"),
        Param(name="offset", default=9e-3, unit="V", low=0.0, high=0.1, meaning="largest op-amp input offset",
              cite="LM358 datasheet, over temperature"),
        Param(name="input_bias", default=500e-9, unit="A", low=0.0, high=1e-5,
              meaning="largest op-amp input bias current: the two inputs' average (both the same direction, either sign)",
              cite="LM358 datasheet (TI SLOS068): 250 nA max at 25 C, 500 nA over temperature; the average of the "
                   "two inputs' currents, as op-amp datasheets define it"),
        Param(name="input_offset_current", default=150e-9, unit="A", low=0.0, high=1e-5,
              meaning="largest difference of the two inputs' bias currents (one input may carry input_bias + half of it)",
              cite="LM358 datasheet (TI SLOS068): 50 nA max at 25 C, 150 nA over temperature"),
        Param(name="divider_current_max", default=1e-3, unit="A", high=1.0, **_POS,
              meaning="largest current both dividers together draw from the zener node (D1's feed must supply "
                      "it and still bias D1)",
              cite="AN94002 parts list: D1 fed by R14 = 750 ohm, 5 mA at 12 V; the BZX79's tolerance holds at "
                   "5 mA; the note's own dividers draw 0.76 mA"),
        Param(name="r7_power_rating", default=3.0, unit="W", high=1e3, **_POS,
              meaning="largest power rating the board takes for R7: the design picks the smallest class that "
                      "carries the stall loss with the derating, and warns when that is above this",
              cite="AN94002 parts list: R7 is a PR01, a 1 W resistor; 3 W: the largest leaded film class"),
        Param(name="v_supply_min", default=10.8, unit="V", low=1.0, high=60.0,
              meaning="motor supply at its lowest (feeds D1 through R14)",
              cite="AN93008: 'a supply voltage V_supply of 12 V -10%'; AN94002's board runs from 12 V"),
        Param(name="v_supply_max", default=13.2, unit="V", low=1.0, high=60.0,
              meaning="motor supply at its highest: checked against the IC's motor supply rating; sizes R14's and "
                      "D1's dissipation",
              cite="12 V +10 %, as AN93008's -10 %"),
        Param(name="v_drop_max", default=1.0, unit="V", high=10.0, **_POS,
              meaning="largest drop across R7 in the motor path, at the highest trip current",
              cite="assumption: about a tenth of the lowest 12 V - 10 % supply lost in the sense resistor; AN94002 "
                   "2.3's 1 V is the least drop it asks across R7 and T1 together for linear speed control, so "
                   "every volt R7 takes comes out of the motor's"),
        Param(name="zener_test_current", default=5e-3, unit="A", high=0.1, **_POS,
              meaning="current at which D1's tolerance is specified: R14 feeds at least this plus the dividers' "
                      "current at the lowest supply",
              cite="BZX79-C8V2 datasheet: V_Z 7.7 to 8.7 V at I_Z = 5 mA"),
        _series("r14_series", "E24", "R14 (D1's feed)"),
        Param(name="input_headroom", default=2.0, unit="V", low=0.0, high=50.0,
              meaning="least distance of both op-amp inputs below the supply",
              cite="AN94002 2.4; LM358 common-mode range to V_CC - 2 V over temperature"),
        Param(name="ic", default="TDA5144", unit="", meaning="motor IC, for its own output limit",
              choices=("TDA5144", "TDA5143")),
        Param(name="criterion", default="corners", unit="", choices=("corners", "yield"),
              meaning="'corners': every tolerance corner keeps min_margin inside the window (exact, pessimistic); "
                      "'yield': the smallest R7 whose Monte Carlo lot (100 000 boards, every part uniform in its "
                      "tolerance, each at both ends of temp_span) meets yield_min, its corner margins reported beside it"),
        Param(name="yield_min", default=0.9999, unit="1", low=0.5, high=0.999999,
              meaning="with criterion = 'yield': least fraction of boards inside the window narrowed by min_margin "
                      "with input_headroom (a 3-sigma upper bound of the lot's failures)"),
        *_resistor("r7", "E24", 0.01, 10.0, "current-sense resistor R7"),
        *_resistor("r9", "E96", 10.0, 1e6, "reference resistor R9"),
        *_resistor("r10", "E96", 1e3, 1e5, "reference divider R10"),
        *_resistor("r11", "E96", 1e3, 1e5, "reference divider R11"),
        *_resistor("r12", "E96", 1e3, 1e5, "level-shift divider R12"),
        *_resistor("r13", "E96", 1e3, 1e5, "level-shift divider R13"),
    )


def _converter() -> tuple[Param, ...]:
    """The TCA5600/TCF5600 dc/dc converter (excerpt, figures 13 and 14, eq 1 to 6a) and its coil's limits.

    No public copy of the TCA5600's electrical characteristics was found (Motorola TCA5600/TCF5600): V12(H),
    V_CE(sat) and V_F are the converter chapter's assumed figures, taken at every corner of +-device_spread, the
    operating point its assumed board."""
    return (
        Param(name="v_supply_min", default=8.0, unit="V", low=0.5, high=60.0,
              meaning="VCC2 at its lowest (the operating point that sizes the coil)",
              cite="assumption: a 12 V battery at cranking (TCA5600 chapter)"),
        Param(name="v_supply_max", default=14.4, unit="V", low=0.5, high=60.0,
              meaning="VCC2 at its highest: the switching frequency is reported (and warned about in the audio "
                      "band) over v_supply_min .. v_supply_max",
              cite="assumption: a 12 V lead-acid battery on charge, 14.4 V"),
        Param(name="v_out", default=12.0, unit="V", low=0.5, high=60.0, meaning="Vout2, the programmable "
              "regulator's output", cite="assumption (TCA5600 chapter)"),
        Param(name="i_out", default=0.05, unit="A", high=10.0, **_POS, meaning="Iout2 at its largest",
              cite="assumption (TCA5600 chapter)"),
        Param(name="f_min", default=20e3, unit="Hz", low=1e3, high=1e6,
              meaning="lowest oscillation frequency at v_supply_min and full load, at every corner of R1, A_L "
                      "and the device figures (device_spread) (eq 4; above the audio band)",
              cite="TCA5600 excerpt, eq 4: 'chosen above the audio frequency band (e.g. 20 kHz)'"),
        Param(name="v_regulator_drop", default=2.5, unit="V", low=0.0, high=20.0,
              meaning="input-output drop V(pin 9 - pin 8) of the programmable regulator",
              cite="TCA5600 excerpt, eq 1: 2.5 V typical"),
        Param(name="v_f", default=0.8, unit="V", low=0.0, high=5.0,
              meaning="forward drop V_F of the rectifier, nominal (+-device_spread)",
              cite="assumption: a silicon rectifier at a few hundred mA (no public characteristics)"),
        Param(name="v_ce_sat", default=0.5, unit="V", low=0.0, high=5.0,
              meaning="saturation voltage V_CE(sat) of the internal switch, nominal (+-device_spread)",
              cite="assumption: a bipolar switch at a few hundred mA (no public characteristics)"),
        Param(name="v12h", default=0.4, unit="V", low=0.01, high=5.0,
              meaning="current-sense threshold V12(H) across R1, nominal (+-device_spread)",
              cite="assumption: comparator thresholds of this kind are a few hundred mV (no public "
                   "characteristics)"),
        Param(name="device_spread", default=0.1, unit="1", low=0.0, high=0.5,
              meaning="spread assumed either side of v12h, v_ce_sat and v_f, fraction: part-to-part spread and "
                      "temperature drift together; the design holds at every corner of it, with R1's and A_L's "
                      "tolerances",
              cite="assumption: no public TCA5600 characteristics (TCA5600 chapter's reading note)"),
        Param(name="r1_tolerance", default=0.01, unit="1", **_FRACTION,
              meaning="tolerance of the sense resistor R1, fraction (in the worst case of the peak current)",
              cite="assumption: a 1 % thick-film or metal-film chip resistor, the tolerance E96 parts are sold with"),
        Param(name="r1_tempco", default=100e-6, unit="1/K", low=0.0, high=0.01,
              meaning="R1's temperature coefficient, at most, either sign, 1/K: the drift from 25 C to t_ambient "
                      "widens R1's ends beyond r1_tolerance (a cold start below 25 C is not in the spec)",
              cite="assumption: a metal-film or thick-film chip resistor, at most 100 ppm/K (the BOM's class)"),
        _series("r1_series", "E96", "R1 (E96: 1 % parts in 2 % steps waste at most a step of peak current)"),
        Param(name="a_l_tolerance", default=0.1, unit="1", **_FRACTION,
              meaning="tolerance of the gapped core's A_L, fraction: the coil is wound so that L at +tolerance "
                      "is eq 6's largest L1",
              cite="assumption: gapped ferrite sets are sold with A_L to +-3 % .. +-10 %; +-10 % for a gap "
                   "ground to order (about +-5 um on the 50 um smallest gap)"),
        Param(name="saturation_margin_min", default=0.2, unit="1", low=0.0, high=0.9,
              meaning="least fraction of the core's saturation flux density (at t_ambient + the coil's rise, at "
                      "its narrowest section) left at the highest peak current (R1, A_L and V12(H) at their worst "
                      "ends)",
              cite="assumption: covers the comparator's delay (no public figure; V12(H)'s spread is "
                   "device_spread's)"),
        Param(name="t_ambient", default=85.0, unit="C", low=-40.0, high=125.0,
              meaning="highest ambient temperature around the coil (saturation and copper are taken at "
                      "t_ambient + the rise)",
              cite="assumption: an enclosed automotive or industrial board, 85 C"),
        Param(name="temperature_rise_max", default=40.0, unit="K", high=200.0, **_POS,
              meaning="largest temperature rise of the coil (core and winding losses through the core's thermal "
                      "resistance)", cite="assumption: 85 C ambient + 40 K keeps the ferrite and the winding at "
                                          "or below a 125 C-class bobbin's rating"),
        Param(name="fill_factor", default=0.5, unit="1", high=1.0, **_POS,
              meaning="fraction of the bobbin's winding window the turns may fill, counted as N × (outer "
                      "diameter)²", cite="assumption: hand or machine layer winding of enamelled round wire"),
        Param(name="current_density_max", default=5e6, unit="A/m^2", high=1e8, **_POS,
              meaning="largest rms current density in the copper, a limit: a candidate whose thickest fitting wire "
                      "carries more fails, so the coil grows to meet it (5 A/mm² = 5e6 A/m²)",
              cite="assumption: the usual 3 to 5 A/mm² of small, naturally cooled windings, which also keeps the "
                   "copper loss the temperature rise counts modest"),
        Param(name="audible_margin", default=0.02, unit="1", low=0.0, high=0.5,
              meaning="with audible = 'avoid', how far above 20 kHz the full-load frequency is held by eq 1 to 5, "
                      "a fraction: room for what they leave out (D1's drop falling with its current lengthens t2 by "
                      "about 1 % where the dump voltage V_L+ is small, as the SPICE check shows)",
              cite="assumption: the converter's own SPICE check, -0.8 % at 14.4 V at the defaults; 2 % covers it "
                   "with room"),
        Param(name="audible", default="avoid", unit="", choices=("avoid", "warn"),
              meaning="'avoid': f_min is raised until the full-load frequency stays above 20 kHz at every corner "
                      "over the whole supply range (exit 3 with what would be needed when it cannot); 'warn': "
                      "f_min as given, a warning where it falls into the audio band",
              cite="TCA5600 excerpt, eq 4: the frequency 'chosen above the audio frequency band (e.g. 20 kHz)', "
                   "sized at the lowest supply only; 'avoid' holds it at every supply"),
    )


def _tables() -> dict[str, tuple[Param, ...]]:
    """The literal table (data)."""
    return {
        "commutation": (
            Param(name="pole_pairs", default=6, unit="", meaning="magnetic pole pairs n, a whole number", low=1,
                  high=100),
            Param(name="rpm_min", default=1800.0, unit="rpm", meaning="lowest speed that must commutate reliably",
                  high=1e6, **_POS),
            Param(name="rpm_max", default=3600.0, unit="rpm", high=1e6, **_POS,
                  meaning="highest speed that must commutate reliably (the note gives none: twice rpm_min)"),
            Param(name="i_charge_min", default=5.3e-6, unit="A", high=1e-3, **_POS,
                  meaning="smallest CAP-CD charge (source) current",
                  cite="TDA5144 datasheet (June 1994), CAP-CD table, charge (source) column, min"),
            Param(name="i_charge_max", default=11e-6, unit="A", high=1e-3, **_POS,
                  meaning="largest CAP-CD charge (source) current (AN94002 uses the 22 uA sink maximum)",
                  cite="TDA5144 datasheet (June 1994), CAP-CD table, charge (source) column, max"),
            Param(name="v_low_min", default=0.80, unit="V", low=0.0, high=5.0,
                  meaning="CAP-CD low switching level, smallest", cite="TDA5144 datasheet (June 1994), CAP-CD table"),
            Param(name="v_low_max", default=0.90, unit="V", low=0.0, high=5.0,
                  meaning="CAP-CD low switching level, largest", cite="TDA5144 datasheet (June 1994), CAP-CD table"),
            Param(name="v_high_min", default=2.3, unit="V", low=0.0, high=5.0,
                  meaning="CAP-CD high switching level, smallest", cite="TDA5144 datasheet (June 1994), CAP-CD table"),
            Param(name="v_high_max", default=2.55, unit="V", low=0.0, high=5.0,
                  meaning="CAP-CD high switching level, largest", cite="TDA5144 datasheet (June 1994), CAP-CD table"),
            Param(name="min_excursion", default=0.1, unit="V", high=5.0, **_POS,
                  meaning="smallest CAP-CD swing still safe from noise", cite="assumption (AN94002 gives none)"),
            Param(name="tolerance", default=0.05, unit="1", **_FRACTION,
                  meaning="capacitor tolerance of CAP-CD, CAP-ST and CAP-TI, fraction (5 % = 0.05)"),
            _series("series", "E12", "CAP-CD, CAP-ST and CAP-TI (E3 .. E192)"),
            Param(name="inertia", default=None, unit="kg m^2", high=1.0, **_POS,
                  meaning="rotor + load inertia J (motor data; leave out: no CAP-ST)"),
            Param(name="torque_constant", default=None, unit="N m/A", high=10.0, **_POS,
                  meaning="torque constant K_t (motor data; leave out: no CAP-ST)"),
            Param(name="start_current", default=None, unit="A", high=100.0, **_POS,
                  meaning="motor current while starting (motor data; leave out: no CAP-ST)"),
            Param(name="motor_tolerance", default=0.1, unit="1", **_FRACTION,
                  meaning="spread of J, K_t and the start current, fraction",
                  cite="assumption: motor data sheets give nominal values"),
            Param(name="damping_ratio", default=0.1, unit="1", high=10.0, **_POS,
                  meaning="damping ratio of the rotor rocking about a detent",
                  cite="assumption: lightly damped; AN94002 says only 'if the damping is high'; measure the decay"),
            Param(name="residual", default=0.1, unit="1", high=0.999, **_POS,
                  meaning="rocking envelope, as a fraction of its first swing, allowed at the next start pulse",
                  cite="assumption (AN94002: the amplitude 'must decrease sufficiently')"),
            Param(name="t_start_max", default=None, unit="s", high=100.0, **_POS,
                  meaning="longest start-oscillator period acceptable (leave out: no limit)"),
            Param(name="flyback_time", default=None, unit="s", high=1.0, **_POS,
                  meaning="longest flyback pulse incl. its eddy-current tail (motor data; leave out: no CAP-TI)"),
            Param(name="rpm_reverse", default=None, unit="rpm", high=1e6, **_POS,
                  meaning="fastest reverse rotation the watchdog must catch (leave out: reported, not required)"),
            Param(name="i_st_min", default=1.5e-6, unit="A", high=1e-3, **_POS,
                  meaning="smallest CAP-ST charge/discharge current", cite="TDA5144 datasheet (June 1994), CAP-ST"),
            Param(name="i_st_max", default=2.5e-6, unit="A", high=1e-3, **_POS,
                  meaning="largest CAP-ST charge/discharge current", cite="TDA5144 datasheet (June 1994), CAP-ST"),
            Param(name="v_st_low", default=0.20, unit="V", low=0.0, high=5.0, meaning="CAP-ST lower switching level",
                  cite="TDA5144 datasheet (June 1994); AN94002's 0.05 V is the TDA5141/TDA5145's"),
            Param(name="v_st_high", default=2.20, unit="V", low=0.0, high=5.0, meaning="CAP-ST upper switching level",
                  cite="TDA5144 datasheet (June 1994)"),
            Param(name="i_wd_min", default=3.75e-6, unit="A", high=1e-3, **_POS,
                  meaning="smallest CAP-TI watchdog charge current (0.3 V to 2.2 V)",
                  cite="assumption: the datasheet prints 5 uA typical only; the CAP-ST source's +-25 % assumed"),
            Param(name="i_wd_max", default=6.25e-6, unit="A", high=1e-3, **_POS,
                  meaning="largest CAP-TI watchdog charge current",
                  cite="assumption: 5 uA typical (TDA5144 datasheet, AN94002 2.1.3) + 25 %"),
        ),
        "current_limiter": _limiter(),
        "class_d": (
            Param(name="p_out", default=125.0, unit="W", meaning="output power that must not clip (1 % THD), at the "
                  "fastest oscillator corner", high=1e4, **_POS, cite="LM4651/LM4652 Example Design: 125 W"),
            Param(name="r_load", default=4.0, unit="ohm", meaning="load resistance", high=1e3, **_POS),
            Param(name="supply", default=20.0, unit="V", meaning="supply rails +-V", low=11.0, high=22.0,
                  cite="LM4651/LM4652 operating ratings: V+ + V- 22 V to 44 V"),
            Param(name="supply_tolerance", default=0.0, unit="1", low=0.0, high=0.5,
                  meaning="how far the rails may stray from supply either way, fraction: clipping is judged at the "
                          "low rail, THD+N, the residue, the coils' peak and the heat sink at the high one (0: "
                          "regulated rails held at supply; an unregulated supply's mains and load swing goes here)",
                  cite="assumption: the datasheet's figures are at +-20 V exactly; the design reports the lowest "
                       "rail that still delivers p_out"),
            Param(name="t_ambient", default=50.0, unit="C", meaning="highest ambient temperature", low=-40.0,
                  high=149.0),
            Param(name="package", default="TF", unit="", meaning="LM4652 package: 'TF' (isolated) or 'T'",
                  choices=("TF", "T")),
            Param(name="theta_cs", default=0.2, unit="K/W", meaning="case-to-sink thermal resistance", low=0.0,
                  high=10.0, cite="LM4651/LM4652 Heat Sinking: 0.2 C/W with thermal grease"),
            Param(name="theta_sa_available", default=None, unit="K/W", high=100.0, **_POS,
                  meaning="thermal resistance of the heat sink you have (leave out: report the one needed)"),
            Param(name="thermal_basis", default="iec_1_8", unit="",
                  meaning="output power the heat sink is sized at: 'iec_1_8', 1/8 of the non-clipped (clipping) "
                          "power, the normal operating condition of audio amplifiers in safety practice; "
                          "'continuous_sine', a continuous sine at p_continuous (by default the clipping power)",
                  choices=("iec_1_8", "continuous_sine"),
                  cite="IEC 62368-1 Annex E (audio amplifiers, normal operating condition: 1/8 of the non-clipped "
                       "output power), IEC 60065 4.2.4 before it"),
            Param(name="p_continuous", default=None, unit="W", high=1e4, **_POS,
                  meaning="with thermal_basis = 'continuous_sine': the continuous sine power the heat sink must carry "
                          "(leave out: all the amplifier can deliver before clipping)"),
            Param(name="thd_max", default=0.005, unit="1", high=0.1, **_POS,
                  meaning="THD+N limit at the test point, fraction (0.5 % = 0.005)"),
            Param(name="thd_test_power", default=10.0, unit="W", meaning="output power of the THD+N test point",
                  high=1e4, **_POS, cite="LM4651/LM4652 system table: THD+N 0.3 % at 10 W"),
            Param(name="thd_bandwidth", default=80e3, unit="Hz", low=20e3, high=150e3,
                  meaning="upper end of the THD+N analyser's band: an oscillator corner below it adds the switching "
                          "residue to THD+N (up to 150 kHz only the fundamental can fall inside)",
                  cite="LM4651/LM4652 system table: THD+N measured in 10 Hz <= BW <= 80 kHz"),
            Param(name="objective", default="efficiency", unit="", choices=("efficiency", "heat_sink"),
                  meaning="what to optimise: 'efficiency' (highest at p_out) or 'heat_sink' (smallest)"),
            Param(name="f_audio", default=500.0, unit="Hz", high=1e5, **_POS,
                  meaning="top of the audio band the filter must pass flat",
                  cite="LM4651/LM4652 system table: THD+N for 10 Hz <= f_IN <= 500 Hz"),
            Param(name="droop_max", default=0.5, unit="dB", high=20.0, **_POS,
                  meaning="largest deviation of the loaded filter's response from 0 dB across the audio band"),
            Param(name="q_max", default=1.0, unit="1", high=10.0, **_POS,
                  meaning="largest Q of the output filter with the load (peaking above the band)"),
            Param(name="ripple_max", default=0.5, unit="V", high=100.0, **_POS,
                  meaning="largest switching residue at the load, rms"),
            Param(name="i_sat", default=12.0, unit="A", high=1e3, **_POS,
                  meaning="rated saturation current of the filter inductors: the worst peak is held to i_sat / 1.2 "
                          "(the book's saturation margin) and to the LM4651's 10 A current limit (12 A, an "
                          "assumption: the smallest rating whose margin reaches that limit)",
                  cite="LM4651/LM4652 Example Design, R_SCKT: peak and ripple below 10 A"),
            Param(name="l_tolerance", default=0.1, unit="1", meaning="inductor tolerance, fraction", **_FRACTION),
            Param(name="c_tolerance", default=0.05, unit="1", meaning="C_BYP tolerance, fraction (film, J)",
                  **_FRACTION),
            Param(name="l_dcr", default=300.0, unit="ohm/H", low=0.0, high=1e5,
                  meaning="coil resistance per henry of inductance (300: 15 mOhm at 50 uH; an assumption)"),
            Param(name="osc_tol_slow", default=0.2, unit="1", **_FRACTION,
                  meaning="how much slower than eq 5 the oscillator may run, fraction",
                  cite="LM4651 table: R_OSC = 0 gives 200 kHz, eq 5 250 kHz (typicals; no limit is printed)"),
            Param(name="osc_tol_fast", default=0.235, unit="1", **_FRACTION,
                  meaning="how much faster than eq 5 the oscillator may run, fraction",
                  cite="LM4651 table: R_OSC = 15 k gives 65 kHz, eq 5 52.6 kHz (typicals; no limit is printed). "
                       "Pin 16's '15.5 kOhm: 75 kHz' (+46 %) contradicts the table's 65 kHz at 15 k and is not "
                       "used: set 0.46 to cover it"),
            Param(name="rds_on_25", default=0.3, unit="ohm", high=10.0, **_POS,
                  meaning="LM4652 R_DS(on) at 25 C used for the heat sink (rises 0.2 %/K)",
                  cite="LM4652 table: 300 mOhm maximum"),
            Param(name="t_overmod", default=350e-9, unit="s", low=0.0, high=5e-6,
                  meaning="over-modulation time used for the heat sink (eq 9)",
                  cite="LM4651/LM4652 Example Design: 350 ns (table typical 310 ns; no maximum printed)"),
            Param(name="tj_margin", default=10.0, unit="K", low=0.0, high=100.0,
                  meaning="margin below the 150 C junction limit, where the LM4652's thermal shutdown trips"),
            Param(name="dead_time_min", default=35.5e-9, unit="s", high=1e-6, **_POS,
                  meaning="least dead time, against shoot-through",
                  cite="LM4651/LM4652: recommended R_DLY = 5 k, 27 ns + 1.7 pF x 5 k = 35.5 ns"),
            Param(name="r_tolerance", default=0.01, unit="1", **_FRACTION,
                  meaning="R_OSC and R_DLY tolerance, fraction (metal film, F; both are in the oscillator's "
                          "corners and R_DLY's low end in the dead time's)"),
            _series("r_osc_series", "E24", "R_OSC"),
            _series("r_dly_series", "E24", "R_DLY"),
            Param(name="l_series", default="E12", unit="", meaning="E-series for the filter inductors",
                  choices=SERIES_NAMES[:4]),
            Param(name="c_series", default="E12", unit="", meaning="E-series for C_BYP", choices=SERIES_NAMES[:4]),
        ),
        "converter": _converter(),
    }


#: table -> its keys, in the order the README and the help list them
TABLES: dict[str, tuple[Param, ...]] = _tables()


def defaults(table: str) -> dict:
    """Every key of one table with its default.

    Parameters
    ----------
    table : str
        The table's name: "commutation", "current_limiter", "class_d" or "converter" (a ``KeyError`` otherwise).

    Returns
    -------
    dict
        {key: default}, in the schema's order; SI values (rpm for speeds, fractions for tolerances, C for
        temperatures), None for a key whose absence means "not given" (a pinned resistor, motor data).
    """
    return {p.name: p.default for p in TABLES[table]}


def key_rows() -> list[tuple[str, str, str, str, str]]:
    """(table, key, default, unit, meaning) for every key: the README table and the help read this.

    Returns
    -------
    list of tuple of str
        One (table, key, default, unit, meaning) per key, tables and keys in the schema's order: the default as
        its ``repr`` ("—" where there is none), the unit as the schema writes it ("ohm", "K/W", "1" for a
        fraction, "" for text).
    """
    return [(t, p.name, "—" if p.default is None else repr(p.default), p.unit, p.meaning)
            for t, params in TABLES.items() for p in params]


def markdown_table() -> str:
    """The README's table of keys, rendered from this schema (a test keeps the README in step).

    Returns
    -------
    str
        A Markdown table, header and one row per key (:func:`key_rows`), lines joined by newlines with no
        trailing newline.
    """
    lines = ["| table | key | default | unit | meaning |", "|---|---|---|---|---|"]
    for t, key, default, unit, meaning in key_rows():
        shown = default if default == "—" else f"`{default}`"
        lines.append(f"| `{t}` | `{key}` | {shown} | {unit} | {meaning} |")
    return "\n".join(lines)
