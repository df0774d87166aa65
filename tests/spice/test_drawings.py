"""Every schematic of every SPICE circuit, rendered and read back as an engineer reads it (tests/drawn_layout.py):
no text on another text or on a stroke of ink, no part on another or crowded by a wire it is not wired to, no
pin left unconnected (an amplifier's supply pins included), every part's designator and value on the figure,
Ω and µ rather than ASCII, subscripts typeset, and each amplifier's "+" and "−" upright, at the input the
netlist wires as that input. Each check is shown to fail on a drawing with the fault put in."""
from __future__ import annotations

import functools
import re

import pytest
from drawn_layout import amplifier_signs, faults, net, plain, render, style_faults, texts
from drawn_parts import bare, netlist_elements, parts_in

from handbook.spice import schematic
from handbook.spice.checks import BUILDERS

IDS = [b().id for b in BUILDERS]


@functools.cache
def drawn(k: int):
    """(circuit, drawing, (axes, renderer)) of BUILDERS[k], rendered once for every test below."""
    circuit = BUILDERS[k]()
    drawing = circuit.draw()
    return circuit, drawing, render(drawing)


def figure_texts(k: int) -> list[str]:
    _, _, (ax, renderer) = drawn(k)
    return [t for t, _, _ in texts(ax, renderer)]


@pytest.mark.parametrize("k", range(len(BUILDERS)), ids=IDS)
def test_no_text_or_part_on_another_and_no_pin_unconnected(k):
    _, drawing, rendered = drawn(k)
    assert faults(drawing, rendered) == []


@pytest.mark.parametrize("k", range(len(BUILDERS)), ids=IDS)
def test_every_part_is_on_the_figure_with_its_designator_and_value(k):
    """Read from the rendered figure's texts (not from the labels the code meant to add): each part's
    designator with its value, to the four figures the drawing prints."""
    circuit = drawn(k)[0]
    on_figure = parts_in([plain(t) for t in figure_texts(k)])
    for p in circuit.parts:
        assert bare(p.ref) in on_figure, f"{circuit.id}: {p.ref} is not on the figure"
        got = on_figure[bare(p.ref)]
        assert got == p.value if isinstance(p.value, str) else got == pytest.approx(p.value, rel=1e-3), (
            f"{circuit.id}: {p.ref} reads {got!r}, is {p.value!r}")


@pytest.mark.parametrize("k", range(len(BUILDERS)), ids=IDS)
def test_units_are_typeset_and_subscripts_are_not_raw_text(k):
    strings = figure_texts(k)
    assert style_faults(strings) == []
    assert not [t for t in strings if re.search(r"ohm|\buF\b", plain(t), re.IGNORECASE)]


#: which parts' pins (designators as :func:`bare` reads them) each amplifier's inputs meet, from the netlist's
#: own wiring: {circuit: ("+" meets, "−" meets)}
POLARITY = {
    "limiter-opamp": ({"R12", "R13"}, {"R10", "R11"}),  # U1 inp inn ...: R12 cs inp, R13 inp z; R10 a inn, R11 inn z
    "limiter-opamp-corner": ({"R12", "R13"}, {"R10", "R11"}),
    "limiter-supply": ({"R8", "R9"}, {"R10", "R11"}),
    "cap-st": ({"C5"}, {"VHIGH"}),  # the switch closes (q = 1) as v(st) rises past V_HIGH: st on +
    "cap-ti": ({"C6"}, {"VWDHIGH"}),
    "speed": ({"R3", "R4"}, set()),  # I_sink = gm (v(inm) - v(inp)): inp, R3/R4's junction, is +
    "speed-loop-filter": ({"R3", "R4"}, set()),
    "tca5600-converter": (set(), {"R1", "S1"}),  # U1 opens S1 when v(e), R1's drop, passes V12(H): e is −
}


@pytest.mark.parametrize("k", range(len(BUILDERS)), ids=IDS)
def test_amplifier_signs_are_upright_and_at_the_inputs_the_netlist_wires(k):
    circuit, drawing, rendered = drawn(k)
    for row in amplifier_signs(drawing, rendered):
        assert not row["strokes"], f"{circuit.id}: schemdraw's own signs turn with the symbol"
        assert (row["in1"], row["in2"]) == ("−", "+"), f"{circuit.id}: the inputs read {row['in1']}, {row['in2']}"
        plus, minus = POLARITY[circuit.id]
        op = row["element"]
        assert plus <= {bare(n) for n, _ in net(drawing, op.in2)}, f"{circuit.id}: + does not meet {plus}"
        assert minus <= {bare(n) for n, _ in net(drawing, op.in1)}, f"{circuit.id}: − does not meet {minus}"
        assert not plus & {bare(n) for n, _ in net(drawing, op.in1)}, f"{circuit.id}: − meets the + side"


def test_the_speed_loops_alternative_wiring_is_drawn_as_an_engineer_accepts_it():
    """The speed loop with R2 in series from AMP OUT to T1's base (speed_loop's "series" wiring): the same checks
    as every circuit's drawing, and R2 wired between the OTA's output and T1's base instead of from V_S."""
    from handbook.spice import speed, speed_loop

    drawing = speed_loop.drawing("series")
    rendered = render(drawing)
    assert faults(drawing, rendered) == []
    strings = [t for t, _, _ in texts(*rendered)]
    assert style_faults(strings) == []
    on_figure = parts_in([plain(t) for t in strings])
    for p in speed._parts(speed.defaults()):
        assert bare(p.ref) in on_figure and (on_figure[bare(p.ref)] == p.value if isinstance(p.value, str)
                                             else on_figure[bare(p.ref)] == pytest.approx(p.value, rel=1e-3))
    r2 = _element(drawing, "R2")
    ends = [net(drawing, pt) for pt in (r2.start, r2.end)]  # AMP OUT (the OTA's output) and T1's base
    assert {("Opamp", "out"), ("T1", "base")} <= ends[0] | ends[1] and not any(n == "V_S" for e in ends for n, _ in e)
    book = speed.circuit().draw()
    r2_book = _element(book, "R2")
    assert ("V_S", "end") in net(book, r2_book.start) and ("T1", "base") in net(book, r2_book.end)  # the pull-up


def test_the_limiter_polarity_table_is_the_netlists_own():
    """POLARITY's limiter rows from the deck itself: U1's first node is + (the LM358 subcircuit's pin order),
    and the resistors on that node are the ones + must meet."""
    circuit = drawn(IDS.index("limiter-opamp"))[0]
    elements, _ = netlist_elements(circuit.netlist)
    plus_node, minus_node = elements["XU1"][:2] if "XU1" in elements else elements["U1"][:2]
    on = {node: {name for name, f in elements.items() if name.startswith("R") and node in f[:2]}
          for node in (plus_node, minus_node)}
    assert (on[plus_node], on[minus_node]) == POLARITY["limiter-opamp"]


# ----------------------------------------------------------------------------------------------
# each check fails when the fault is put in


def _converter():
    from handbook.spice import converter

    return converter.circuit().draw()


def _element(drawing, ref: str):
    return next(el for el in drawing.elements
                if any(plain(lab.label).split()[:1] == [ref] for lab in getattr(el, "_userlabels", [])))


def test_a_part_moved_onto_another_is_caught():
    import schemdraw.elements as elm

    d = _converter()
    assert faults(d) == []
    d1 = _element(d, "D1")
    d.add(elm.Opamp(leads=True, sign=False).anchor("center").at(d1.center))  # the TCA5600 fault, made worse
    found = faults(d)
    assert "Diode 'D1 V_F = 800 mV' overlaps Opamp" in found, found


def test_a_label_on_a_part_or_on_another_label_is_caught():
    import schemdraw.elements as elm

    d = _converter()
    r1 = _element(d, "R1")
    d.add(elm.Label().at(r1.center).label("R99 1 kΩ"))
    d.add(elm.Label().at(_element(d, "L1").absanchors["label"] if "label" in _element(d, "L1").absanchors
                         else (_element(d, "L1").center[0], _element(d, "L1").center[1] + 0.6)).label("L9 1 µH"))
    found = faults(d)
    assert any(f.startswith("text 'R99 1 kΩ' lies on Resistor") for f in found), found
    assert any("overlaps text" in f and "L9 1 µH" in f for f in found), found


def test_a_wire_through_a_part_and_an_unconnected_pin_are_caught():
    import schemdraw.elements as elm

    d = _converter()
    s1 = _element(d, "S1")
    d.add(elm.Line().endpoints((s1.center[0] - 2, s1.center[1]), (s1.center[0] + 0.2, s1.center[1])))
    d.add(elm.Resistor().endpoints((30, 0), (30, 3)).label("R98 1 Ω"))
    found = faults(d)
    assert any(f.startswith("Line runs into Switch 'S1") for f in found), found
    assert "ResistorIEEE 'R98 1 Ω': pin start meets no wire" in found and "ResistorIEEE 'R98 1 Ω': pin end meets no wire" in found


def test_an_amplifier_without_its_supply_pins_is_caught():
    d = schematic.start()
    op = schematic.amplifier(d, (0, 0), positive=None, negative=None)
    import schemdraw.elements as elm

    for pin in (op.in1, op.in2, op.out):
        d.add(elm.Line().endpoints(pin, (pin[0] + (1 if pin is op.out else -1), pin[1])))
    found = faults(d)
    assert any("pin vd meets no wire" in f for f in found) and any("pin vs meets no wire" in f for f in found), found


def test_turned_or_swapped_signs_are_caught():
    import schemdraw.elements as elm

    d = schematic.start()
    d.add(elm.Opamp(leads=True).theta(-90))  # schemdraw's signs: the "−" turns into "|"
    assert amplifier_signs(d)[0]["strokes"]
    d = schematic.start()
    op = d.add(elm.Opamp(leads=True, sign=False))
    d.add(elm.Label().at((op.in1[0] + 1.0, op.in1[1])).label("+"))  # + written at the inverting input
    d.add(elm.Label().at((op.in2[0] + 1.0, op.in2[1])).label("−"))
    row = amplifier_signs(d)[0]
    assert (row["in1"], row["in2"]) == ("+", "−")
    d = schematic.start()
    op = schematic.amplifier(d, (0, 0), theta=-90)  # the library's own, turned as the limiters turn it
    row = amplifier_signs(d)[0]
    assert (row["strokes"], row["in1"], row["in2"]) == (False, "−", "+")


def test_a_missing_value_or_designator_is_caught():
    k = IDS.index("limiter-opamp")
    strings = [plain(t) for t in figure_texts(k)]
    assert "R9" in parts_in(strings)
    assert "R9" not in parts_in([s for s in strings if not s.startswith("R9")])
    assert "R9" not in parts_in([s.replace("267 Ω", "") if s.startswith("R9") else s for s in strings])


def test_ascii_units_and_raw_subscripts_are_caught():
    assert style_faults(["R2 680 ohm", "R3 39 kohm", "C2 10 uF", "V_CE(sat) = 500 mV", "V12(H)", "V_s"]) == [
        "'R2 680 ohm': units in ASCII", "'R3 39 kohm': units in ASCII", "'C2 10 uF': units in ASCII",
        "'V_CE(sat) = 500 mV': a subscript as raw text", "'V12(H)': a subscript as raw text",
        "'V_s': a subscript as raw text"]
    assert style_faults(["R2 680 Ω", "$V_\\mathrm{CE(sat)}$ = 500 mV", "C2 10 µF", "motor"]) == []
