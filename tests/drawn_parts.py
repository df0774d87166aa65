"""What the SPICE tests share: the parts a schematic draws against the parts its netlist simulates."""
import pytest

from handbook.spice import timers


def drawn_labels(drawing) -> list[str]:
    return [lbl.label for element in drawing.elements for lbl in element._userlabels]


def netlist_values(netlist: str) -> dict[str, str]:
    """{ref (lower case): value token} from element lines and `.param ref=value` lines."""
    out = {}
    for line in netlist.lower().splitlines():
        tokens = line.split()
        if not tokens or tokens[0].startswith("*"):
            continue
        if tokens[0] == ".param":
            out.update(tok.split("=", 1) for tok in tokens[1:])
        elif not tokens[0].startswith("."):
            out[tokens[0]] = tokens[-1]
    return out


def assert_drawn_as_netlisted(circuit):
    labels = " | ".join(drawn_labels(circuit.draw()))
    values = netlist_values(circuit.netlist)
    for part in circuit.parts:
        assert timers.label(part) in labels, f"{circuit.id}: {part.ref} not drawn as {timers.label(part)!r}"
        ref = {part.ref.lower(), part.ref.lower().replace("_", "")}
        names = [name for name in values if name in ref or name[1:] in ref]  # a SPICE letter may lead: QT1, RESR
        assert names, f"{circuit.id}: {part.ref} not in the netlist"
        token = values[names[0]]
        if isinstance(part.value, str):
            assert token == part.value.lower()
        else:
            assert float(token) == pytest.approx(part.value, rel=1e-5), part.ref
