"""What the SPICE tests share: the parts a schematic draws against the parts its netlist simulates, both ways.

Three sets must be one: the circuit's ``parts``, the designators its drawing labels (read back from the
drawing's label text, value and all), and the netlist's elements and ``.param`` lines (read back from the
netlist text). Every part is drawn and simulated with its value; nothing is drawn that is not a part; every
netlist element is a part or is declared by the test as not one (an ammeter, a probe, the IC's logic), with
the reason beside it.
"""
from __future__ import annotations

import re

import pytest

PREFIX = {"p": 1e-12, "n": 1e-9, "µ": 1e-6, "μ": 1e-6, "u": 1e-6, "m": 1e-3, "": 1.0, "k": 1e3, "M": 1e6, "G": 1e9}
UNITS = ("Ω", "ohm", "V", "A", "F", "H", "S", "Hz")
REF = re.compile(r"^[A-Za-z][A-Za-z0-9_]*$")  # a designator: R7, C_BYP, I_ST, VO1 (g_m read as GM)
DEVICE = re.compile(r"^[A-Z0-9][A-Z0-9-]*$")  # a device name: BC557, BZX79-C8V2
NUMBER = re.compile(r"^([-+]?\d+(?:\.\d*)?(?:e[-+]?\d+)?)\s*(\S*)$")
COPY = re.compile(r"_\d+$")  # a copy of a part in the same deck: R7_1 (another temperature, another supply)


def drawn_labels(drawing) -> list[str]:
    """Every label of the drawing as read: mathtext undone ("$C_\\mathrm{BYP}$ 5 µF" -> "C_BYP 5 µF")."""
    from drawn_layout import plain

    return [plain(lbl.label) for element in drawing.elements for lbl in element._userlabels]


def bare(ref: str) -> str:
    """A designator as compared: a typeset subscript and a written underscore read the same (V_CC2, VCC2; the
    transconductance g_m, GM)."""
    return ref.replace("_", "").upper()


def parse_value(text: str):
    """A drawn value back to SI ("775 mΩ" -> 0.775, "±20 V" -> 20.0, "BC557" -> "BC557"), or None."""
    text = re.sub(r"\s*\([^()]*\)$", "", text.strip()).lstrip("±")  # "2.4 V (I_CH stops)": what it does, said
    if "= " in text:  # "V_CE(sat) = 500 mV"
        text = text.rsplit("= ", 1)[1]
    m = NUMBER.match(text)
    if m:
        number, unit = float(m.group(1)), m.group(2)
        if unit in UNITS or unit == "":
            return number
        if unit[:1] in PREFIX and unit[1:] in UNITS:
            return number * PREFIX[unit[:1]]
        return None
    return text if DEVICE.match(text) else None


def drawn_parts(drawing) -> dict[str, float | str]:
    """{designator (:func:`bare`): value} of every part the drawing labels: "REF value" on one line of a
    label, or "REF" then its value on the next (the limiters' style). A designator drawn twice with two values
    is an error."""
    return parts_in(drawn_labels(drawing))


def parts_in(labels: list[str]) -> dict[str, float | str]:
    """{designator (:func:`bare`): value} read from label texts (see :func:`drawn_parts`)."""
    out: dict[str, float | str] = {}

    def put(ref, value):
        if ref in out and out[ref] != value:
            raise AssertionError(f"{ref} drawn twice: {out[ref]!r} and {value!r}")
        out[ref] = value

    for label in labels:
        lines = [ln.strip() for ln in str(label).split("\n")]
        for k, line in enumerate(lines):
            head, _, rest = line.partition(" ")
            if REF.match(head) and rest and parse_value(rest) is not None:
                put(bare(head), parse_value(rest))
            elif REF.match(line) and k + 1 < len(lines) and parse_value(lines[k + 1]) is not None:
                put(bare(line), parse_value(lines[k + 1]))
    return out


def netlist_elements(netlist: str) -> tuple[dict[str, list[str]], dict[str, str]]:
    """({element name (upper case): its fields after the name}, {.param name (lower case): value}) of the
    top level of a deck: comments, dot lines, subcircuit bodies and .control blocks are not elements."""
    elements, params, skip = {}, {}, None
    for line in netlist.splitlines():
        text = line.strip()  # an inline "$ BZX79-C8V2" names the device the model stands for: kept
        low = text.lower()
        if skip:
            skip = None if low.startswith(skip) else skip
            continue
        if not text or text[0] in "*+":
            continue
        if low.startswith(".subckt"):
            skip = ".ends"
        elif low.startswith(".control"):
            skip = ".endc"
        elif low.startswith(".param"):
            params.update(tok.split("=", 1) for tok in text.split()[1:])
        elif text[0] != ".":
            name, *fields = text.split()
            assert name.upper() not in elements, f"element {name} twice in the netlist"
            elements[name.upper()] = fields
    return elements, {k.lower(): v for k, v in params.items()}


def _names(ref: str) -> set[str]:
    """The element names a part may go by: its designator, without underscores, after a SPICE letter."""
    bare = {ref.upper(), ref.upper().replace("_", "")}
    return bare | {letter + b for b in bare for letter in "BCDEFGHIJKLMQRSVWXY"}


def _holds(fields: list[str], value) -> bool:
    """Whether an element's fields carry ``value``: a plain element (two nodes and a value) in its last
    field; any other (a device name among nodes and parameters, a level inside PULSE(...) or PWL(...)) in
    any of its fields."""
    tokens = [t for t in re.split(r"[\s()=]+", " ".join(fields)) if t]
    if isinstance(value, str):
        return value.lower() in (t.lower() for t in tokens)
    if len(fields) == 3 and _float(fields[-1]) is not None:
        return _float(fields[-1]) == pytest.approx(value, rel=1e-5)
    return any(_float(t) is not None and _float(t) == pytest.approx(value, rel=1e-5) for t in tokens)


def _float(token: str):
    try:
        return float(token)
    except ValueError:
        return None


def assert_same_parts(circuit, aux: dict[str, str] = None, copies: dict[str, object] = None, rel: float = 1e-3):
    """The drawing, the netlist and ``circuit.parts`` hold one set of parts with one set of values.

    ``aux``: {regular expression on element names: why such an element is not a part}; ``copies``: {element
    name of a copy: its value, where a copy runs at another value than the part (a second supply)}. Drawn
    values are compared to ``rel`` (the drawing prints four significant figures), netlist values to 1e-5."""
    aux, copies = aux or {}, {k.upper(): v for k, v in (copies or {}).items()}
    parts = {p.ref: p.value for p in circuit.parts}

    drawn = drawn_parts(circuit.draw())
    want = {bare(ref) for ref in parts}
    assert set(drawn) == want, (f"{circuit.id}: drawn but not a part {sorted(set(drawn) - want)}, "
                                f"a part not drawn {sorted(want - set(drawn))}")
    for ref, value in parts.items():
        got = drawn[bare(ref)]
        if isinstance(value, str):
            assert got == value, f"{circuit.id}: {ref} drawn as {got!r}, is {value!r}"
        else:
            assert got == pytest.approx(value, rel=rel), f"{circuit.id}: {ref} drawn as {got}, is {value}"

    elements, params = netlist_elements(circuit.netlist)
    owner = {}  # element name -> the part it is (or a copy of)
    for name in elements:
        base = COPY.sub("", name) if COPY.search(name) else name
        refs = [r for r in parts if name in _names(r)] or [r for r in parts if base in _names(r)]
        if refs:
            owner[name] = refs[0]
        else:
            why = [reason for pattern, reason in aux.items() if re.fullmatch(pattern, name, re.IGNORECASE)]
            assert why, f"{circuit.id}: netlist element {name} is neither a part nor declared as not one"
    for ref, value in parts.items():
        mine = [n for n, r in owner.items() if r == ref]
        if not mine:
            key = ref.lower()
            assert key in params, f"{circuit.id}: {ref} is neither an element nor a .param of the netlist"
            got = params[key]
            assert (got.lower() == value.lower() if isinstance(value, str)
                    else float(got) == pytest.approx(value, rel=1e-5)), f"{circuit.id}: .param {key}={got}, is {value}"
            continue
        for name in mine:
            want = copies.get(name, value)
            assert _holds(elements[name], want), f"{circuit.id}: {name} {' '.join(elements[name])} does not hold {want}"


def assert_drawn_as_netlisted(circuit, aux: dict[str, str] = None, copies: dict[str, object] = None):
    """The older name of :func:`assert_same_parts`."""
    assert_same_parts(circuit, aux, copies)


def assert_edit_caught(circuit, aux: dict[str, str], old: str, new: str, match: str, copies: dict | None = None) -> None:
    """The netlist with ``old`` replaced by ``new`` (a changed value, a stray element) fails
    :func:`assert_same_parts` with ``match``: the part-set test sees the edit."""
    import dataclasses

    edited = dataclasses.replace(circuit, netlist=circuit.netlist.replace(old, new))
    assert edited.netlist != circuit.netlist, f"{old!r} is not in the netlist: the edit would test nothing"
    with pytest.raises(AssertionError, match=match):
        assert_same_parts(edited, aux, copies)
