"""A third leg for the linear parts: lcapy derives each circuit's relation from a netlist and sympy compares
it with the registry's derivation (:mod:`handbook.sources.an94002.equations`, ``an93008.equations``, the
class-D filter functions).

The lcapy netlists are not typed here: :func:`netlist` writes them from the same ``Circuit.parts`` and the
same node maps the SPICE netlist is written from (``limiter.decks.OPAMP_NODES``, ``limiter.supply.SUPPLY_NODES``,
``speed.NODES``, ``class_d.NODES``, ``timers.CD_NODES``), each part under a symbol named by its designator.
A part that is not a resistor, capacitor or inductor needs a stated linear stand-in, and every part needs
one or an explicit reason to be left out: a part added to a circuit without a decision here is an error,
and a part moved in a node map moves in all three (schematic, SPICE, lcapy).

The stand-ins: a zener in breakdown is a voltage source V_D1 (its dynamic resistance left out, as eq 11
and 12 leave it out); the LM358 an ideal op-amp (lcapy's ``opamp`` with gain A, then A -> oo); the motor
of a limiter a current the op-amp's output sets (a transconductance K > 0: the regulator it throttles,
so the loop holds V+ = V-; any K gives the same limit), or an independent current I_M where the loop is
open; the speed loop's T1 a voltage source V_mot at its collector (the divider sees a source); the OTA's
and the op-amp's inputs draw no current (the equations' law), so they are left out where the loop is open.
lcapy takes about 2 s to import: it is imported inside the functions, by :func:`_lcapy`.
"""
from __future__ import annotations

import functools
import math
import sys


def _lcapy():
    """lcapy, imported without its printing side effects. Importing lcapy calls sympy's ``init_printing``, which
    in a notebook makes IPython render every float, int, list and dict shown or glued after it as LaTeX and as a
    PNG (mathtext, about 50 ms each: a chapter's glued numbers cost seconds and carried images nobody reads), and
    which outlives the chapter in a kernel that runs several: a chapter's outputs depended on whether an lcapy
    check had run before it. IPython's display formatters, sympy's ``Printable`` display methods, sympy's global
    printer settings and ``sys.displayhook`` are put back as they were; lcapy's own LaTeX display of its containers
    (``ExprList``, ``ExprDict``), registered with them, goes too (no chapter shows one). An lcapy imported before,
    other than through here (a reader's own ``import lcapy``), is left with the printing it set up."""
    if "lcapy" in sys.modules:
        return sys.modules["lcapy"]
    from sympy.core._print_helpers import Printable
    from sympy.printing.printer import Printer

    shell = None
    if "IPython" in sys.modules:
        from IPython import get_ipython

        shell = get_ipython()
    formatters = shell.display_formatter.formatters.values() if shell is not None else ()
    saved = [(f, dict(f.type_printers), dict(f.deferred_printers)) for f in formatters]
    methods = {name: Printable.__dict__[name] for name in ("_repr_latex_", "_repr_png_", "_repr_svg_")}
    settings, hook = dict(Printer._global_settings), sys.displayhook
    try:
        import lcapy
    finally:
        for f, types, deferred in saved:
            f.type_printers, f.deferred_printers = types, deferred
        for name, method in methods.items():
            setattr(Printable, name, method)
        Printer._global_settings.clear()
        Printer._global_settings.update(settings)
        sys.displayhook = hook
    return lcapy


def _nodes(spec: str, count: int, named: bool = False) -> list[str]:
    """The first ``count`` node names of a SPICE node map entry ("R3 vmot inp" when ``named``, else
    "vs{s} cs{s}"), without the copy suffix."""
    tokens = spec.replace("{s}", "").split()
    return tokens[1:count + 1] if named else tokens[:count]


def netlist(parts, nodes: dict[str, str], stand_ins: dict, named: bool = False, wires=()) -> str:
    """lcapy's netlist of ``parts`` placed by the SPICE node map ``nodes``: a resistor, capacitor or inductor
    as itself with its designator as its symbol; any other part by ``stand_ins[ref]`` (a function of its
    node list returning lcapy lines, or a string saying why it is left out). ``wires``: (a, b) node pairs
    the SPICE netlist joins through an ammeter (a 0 V source, not a part)."""
    letters = {"ohm": "R", "F": "C", "H": "L"}
    lines = []
    for p in parts:
        rule = stand_ins.get(p.ref)
        if isinstance(rule, str):  # left out, and why
            continue
        if rule is not None:
            lines += rule(_nodes(nodes.get(p.ref, ""), 6, named))  # an IC figure may have no nodes
        elif p.unit in letters:
            a, b = _nodes(nodes[p.ref], 2, named)
            name = p.ref if p.ref[0] == letters[p.unit] else letters[p.unit] + p.ref
            lines.append(f"{name} {a} {b} {{{p.ref}}}")
        else:
            raise ValueError(f"{p.ref} ({p.value}) has no linear stand-in for lcapy and no reason to be left out")
    lines += [f"W{k} {a} {b}" for k, (a, b) in enumerate(wires)]
    return "\n".join(lines) + "\n"


def _names(expr) -> dict:
    """{name: symbol} of an lcapy expression's own symbols (they carry lcapy's assumptions)."""
    return {s.name: s for s in expr.free_symbols}


def _to(expr, mapping: dict):
    """``expr`` with lcapy's symbols replaced by the registry's (``mapping``: lcapy name -> registry symbol)."""
    free = _names(expr)
    return expr.subs({free[k]: v for k, v in mapping.items() if k in free})


@functools.lru_cache(maxsize=64)
def _circuit(text: str):
    """lcapy's circuit of a netlist, one per netlist text in a process: lcapy keeps what it has solved in the
    circuit, so a chapter re-run in the same kernel does not solve the same netlist again (a changed netlist is
    a new circuit)."""
    return _lcapy().Circuit(text)


@functools.lru_cache(maxsize=256)
def _same(a, b) -> bool:
    import sympy as sp

    return sp.simplify(a - b) == 0


@functools.lru_cache(maxsize=64)
def _held(text: str, top: str, bottom: str):
    """V(top) - V(bottom) at DC with the op-amp's gain A -> oo, of the circuit of netlist ``text`` (once per netlist
    in a process, as :func:`_circuit`)."""
    import sympy as sp

    cct = _circuit(text)
    v = (cct[top].V - cct[bottom].V).dc.expr
    return sp.limit(v, _names(v)["A"], sp.oo)


# ----------------------------------------------------------------------------------------------
# AN94002 figure 3: the op-amp limiter, eq 13

def opamp_netlist(p: dict | None = None) -> str:
    """The op-amp limiter (AN94002 figure 3) for lcapy, from :func:`limiters.opamp_parts` and
    :data:`limiters.OPAMP_NODES`: the loop closed through the motor."""
    from .limiter import decks as limiters

    q = {**limiters.opamp_defaults(), **(p or {})}
    u1 = _nodes(limiters.OPAMP_NODES["U1"], 5)  # inp inn vcc vee out
    stand = {
        "VS": lambda n: [f"VS {n[0]} {n[1]} dc {{V_s}}"],
        "D1": lambda n: [f"VD1 {n[1]} {n[0]} dc {{V_D1}}"],  # anode n0, cathode n1: V(cathode) - V(anode) = V_D1
        "U1": lambda n: [f"E_U1 {n[4]} 0 opamp {n[0]} {n[1]} {{A}}"],
        "IM": lambda n: [f"G_IM {n[0]} {n[1]} {u1[4]} 0 {{K}}"],
    }
    return netlist(limiters.opamp_parts(q), limiters.OPAMP_NODES, stand, wires=[("cs", "csm")])


def trip_from_netlist(p: dict | None = None):
    """V_cs held by the closed loop, derived by lcapy from :func:`opamp_netlist` with A -> oo (a sympy
    expression in the registry's symbols)."""
    from ..sources.an94002 import equations as eqs

    held = _held(opamp_netlist(p), "vs", "cs")
    return _to(held, {"V_D1": eqs.V_D1, "V_s": eqs.V_s, "R9": eqs.R9, "R10": eqs.R10, "R11": eqs.R11,
                      "R12": eqs.R12, "R13": eqs.R13})


def compare() -> dict:
    """{"lcapy": its V_cs, "derived": the registry's derivation, "printed": eq 13 as printed,
    "same_as_derived", "same_as_printed", "free_of_loop_gain", "at_parts": (lcapy's V_cs with the netlist's
    part values, an94002.v_cs_trip of the same values)}."""
    from ..sources import an94002
    from ..sources.an94002 import circuit as note
    from ..sources.an94002 import equations as eqs
    from .limiter import decks as limiters

    held, eq13 = trip_from_netlist(), an94002.equation("an94002-eq13")
    q = limiters.opamp_defaults()
    values = {eqs.V_D1: q["zener_voltage"], eqs.R9: q["r9"], eqs.R10: q["r10"], eqs.R11: q["r11"], eqs.R12: q["r12"],
              eqs.R13: q["r13"]}
    return {"lcapy": held, "derived": eq13.derived, "printed": eq13.printed,
            "same_as_derived": _same(held, eq13.derived), "same_as_printed": _same(held, eq13.printed),
            "free_of_loop_gain": not any(s.name in ("K", "A") for s in held.free_symbols),
            "at_parts": (float(held.subs(values)),
                         float(note.v_cs_trip(q["zener_voltage"], q["r9"], q["r10"], q["r11"], q["r12"], q["r13"])))}


# ----------------------------------------------------------------------------------------------
# AN93008 figure 3: the supply-referenced limiter, eq 1 and eq 6

def supply_netlist(closed: bool = True) -> str:
    """AN93008's limiter for lcapy from :func:`.limiter.supply.supply_parts` and :data:`.limiter.supply.SUPPLY_NODES`:
    closed (the op-amp and the motor's loop) or open (no op-amp: its inputs draw nothing; the motor an
    independent current I_M)."""
    from .limiter import supply as limiters

    out = _nodes(limiters.SUPPLY_NODES["U1"], 5)[4]
    stand = {"VS": lambda n: [f"VS {n[0]} {n[1]} dc {{V_s}}"]}
    if closed:
        stand.update({"U1": lambda n: [f"E_U1 {n[4]} 0 opamp {n[0]} {n[1]} {{A}}"],
                      "IM": lambda n: [f"G_IM {n[0]} {n[1]} {out} 0 {{K}}"]})
    else:
        stand.update({"U1": "an op-amp's inputs draw no current (the law of eq 1): left out with the loop open",
                      "IM": lambda n: [f"I_M {n[0]} {n[1]} dc {{I_M}}"]})
    return netlist(limiters.supply_parts(limiters.supply_defaults()), limiters.SUPPLY_NODES, stand,
                   wires=[("cs", "csm")])


def an93008_from_netlist() -> dict:
    """AN93008 eq 1 (V+ from the level-shifting divider R8/R9) and eq 6 (V_cs at the trip) derived by lcapy
    from the limiter's parts, against the registry's derivations (an93008.equations eq1().derived with its
    V_cs set to lcapy's V_s - V(cs), eq6().derived). {"eq1": {...}, "eq6": {...}}, each with "lcapy",
    "registry", "same"."""
    from ..sources import an93008
    from ..sources.an93008 import equations as eqs

    names = {"V_s": eqs.Vs, "R8": eqs.R8, "R9": eqs.R9, "R10": eqs.R10, "R11": eqs.R11}
    opened = _circuit(supply_netlist(closed=False))
    v_plus = _to(opened["inp"].V.dc.expr, names)
    v_cs = _to((opened["vs"].V - opened["cs"].V).dc.expr, names)
    eq1 = an93008.equation("an93008-eq1").derived.subs(eqs.Vcs, v_cs)
    held = _to(_held(supply_netlist(closed=True), "vs", "cs"), names)
    eq6 = an93008.equation("an93008-eq6").derived
    return {"eq1": {"lcapy": v_plus, "registry": eq1, "same": _same(v_plus, eq1)},
            "eq6": {"lcapy": held, "registry": eq6, "same": _same(held, eq6)}}


# ----------------------------------------------------------------------------------------------
# AN94002 2.2: the speed loop's divider, eq 10

def speed_netlist() -> str:
    """The speed loop for lcapy from :func:`speed._parts` and :data:`speed.NODES`: T1 a source V_mot at its
    collector, the OTA's inputs drawing nothing (its figures left out)."""
    from . import speed

    q = speed.defaults()
    why = "an OTA figure: the OTA's inputs draw no current (eq 10's law), its output is not part of the divider"
    stand = {"V_S": lambda n: [f"V_S {n[0]} {n[1]} dc {{V_s}}"],
             "T1": lambda n: [f"VT1 {n[0]} 0 dc {{V_mot}}"],  # collector, base, emitter: T1 holds V_mot
             "GM": why, "I_SINK": why, "V_SAT": why}
    return netlist(speed._parts(q), speed.NODES, stand, named=True)


def speed_from_netlist() -> dict:
    """AMPIN+ of the speed loop derived by lcapy from its parts, against the registry's derivation of eq 10
    (KCL at AMPIN+). {"lcapy", "registry", "printed", "same", "same_as_printed"}."""
    from ..sources import an94002
    from ..sources.an94002 import equations as eqs
    from . import speed

    e10 = an94002.equation("an94002-eq10")
    names = {"R3": eqs.R3, "R4": eqs.R4, "V_mot": eqs.V_mot}
    ampin = _nodes(speed.NODES["R4"], 1, named=True)[0]  # AMPIN+: R4's top
    node = _to(_circuit(speed_netlist())[ampin].V.dc.expr, names)
    return {"lcapy": node, "registry": e10.derived, "printed": e10.printed, "same": _same(node, e10.derived),
            "same_as_printed": _same(node, e10.printed)}


# ----------------------------------------------------------------------------------------------
# LM4651/LM4652 bridge output filter

def filter_netlist() -> str:
    """The bridge filter for lcapy from :func:`class_d.parts` and :data:`class_d.NODES`: VO1's nodes are the
    input port; VO2 a wire (nothing of the network goes to ground but the two half-bridges, so only VO1 - VO2
    drives the load: tying o2 to ground and driving o1 is the same)."""
    from . import class_d

    stand = {"VO1": "the input port: the transfer is taken from its nodes",
             "VO2": lambda n: [f"W_VO2 {n[0]} {n[1]}"]}
    return netlist(class_d.parts(class_d.defaults()), class_d.NODES, stand)


def filter_from_netlist() -> dict:
    """The bridge filter's transfer function (load voltage over bridge voltage) derived by lcapy from
    :func:`filter_netlist` with L1 = L2 = L, against the second-order form the class-D design uses: corner
    f_C = 1 / (2 pi sqrt(2 L C)) and Q = R sqrt(C / 2L) (:func:`handbook.sources.lm4651.circuit.filter_f0`,
    ``filter_q``, fed sympy symbols). {"lcapy", "registry", "same"}."""
    import sympy as sp

    from ..sources.lm4651 import circuit as lm4651
    from . import class_d

    o1, o2 = class_d.NODES["VO1"].split()
    outp, outn = class_d.NODES["R_L"].split()
    h = _circuit(filter_netlist()).transfer(o1, o2, outp, outn).expr
    free = _names(h)
    l_, c_, r_ = sp.symbols("L C R", positive=True)
    h = h.subs({free["L1"]: l_, free["L2"]: l_, free["C_BYP"]: c_, free["R_L"]: r_})
    s = free["s"]

    def exact(expr):  # the functions compute with floats (math.pi, ** 0.5): each float back to its exact value
        return expr.xreplace({x: sp.nsimplify(float(x), tolerance=1e-12) for x in expr.atoms(sp.Float)})

    w0, q = exact(2 * math.pi * lm4651.filter_f0(l_, c_)), exact(lm4651.filter_q(l_, c_, r_))
    registry = 1 / ((s / w0) ** 2 + s / (w0 * q) + 1)
    return {"lcapy": sp.simplify(h), "registry": registry, "same": _same(h, registry)}


# ----------------------------------------------------------------------------------------------
# CAP-CD: a timer pin

def timer_netlist() -> str:
    """CAP-CD in its charge phase for lcapy from :func:`timers.commutation_delay`'s parts and
    :data:`timers.CD_NODES`: the IC's charge current I_CH into C3 from rest."""
    from . import timers

    c = timers.commutation_delay()
    pin = _nodes(timers.CD_NODES["C3"], 1, named=True)[0]
    stand = {"I_CH": lambda n: [f"I_CH {pin} 0 step {{I_CH}}"],  # lcapy's sense: I_CH into the pin
             "C4": "CAP-DC: the same timer one interval later", "I_DIS": "the sink acts after the interval",
             "V_LOW": "a comparator level: it ends the interval, it is not in it",
             "V_HIGH": "a comparator level: it ends the interval, it is not in it"}
    return netlist(c.parts, timers.CD_NODES, stand, named=True)


def timer_from_netlist() -> dict:
    """lcapy's v(t) of :func:`timer_netlist`, set equal to the swing dV after one commutation interval
    t_com = 1 / (6 n N), solved for C, against the registry's derivation of AN94002 eq 5 (charge balance).
    {"lcapy", "registry", "same"}."""
    import sympy as sp

    from ..sources import an94002
    from ..sources.an94002 import equations as eqs
    from . import timers

    lcapy = _lcapy()

    pin = _nodes(timers.CD_NODES["C3"], 1, named=True)[0]
    v = _circuit(timer_netlist())[pin].V(lcapy.t).expr
    free = _names(v)
    at = v.subs(sp.Heaviside(free["t"]), 1).subs({free["t"]: 1 / (6 * eqs.n * eqs.N), free["I_CH"]: eqs.I})
    c_needed = sp.solve(sp.Eq(at, eqs.dV), free["C3"])[0]
    registry = an94002.equation("an94002-eq5").derived
    return {"lcapy": c_needed, "registry": registry, "same": _same(c_needed, registry)}
