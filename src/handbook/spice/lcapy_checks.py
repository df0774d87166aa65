"""A third leg for the op-amp limiter's linear part: lcapy derives the trip point from a netlist and sympy
compares it with the registry's derivation (AN94002 eq 13 as :mod:`handbook.sources.an94002.equations`
derives it from KCL, and as the note prints it).

The netlist is the limiter holding the current (the loop closed): the zener D1 is a voltage source V_D1
(its dynamic resistance left out, as eq 11 and 12 leave it out), the LM358 an ideal op-amp (lcapy's
``opamp`` with gain A, then A -> oo), and the regulator it throttles a voltage-controlled source that sets
the sense voltage from the op-amp's output (gain K; any K > 0 gives the same limit). With infinite gain the
loop holds V+ = V-, so the sense voltage it holds is the trip voltage. lcapy takes about 2 s to import:
it is imported inside the function.
"""
from __future__ import annotations

import math

NETLIST = """
Vs s 0 dc {V_s}
Vz s z dc {V_D1}
E1 s cs o 0 {K}
R12 cs p {R12}
R13 p z {R13}
R9 s a {R9}
R10 a m {R10}
R11 m z {R11}
E2 o 0 opamp p m {A}
"""


def trip_from_netlist():
    """V_cs held by the closed loop, derived by lcapy from :data:`NETLIST` with A -> oo (a sympy expression
    in the registry's symbols)."""
    import lcapy
    import sympy as sp

    from ..sources.an94002 import equations as eqs

    cct = lcapy.Circuit(NETLIST)
    v_cs = (cct.s.V - cct.cs.V).dc.expr
    free = {s.name: s for s in v_cs.free_symbols}
    held = sp.limit(v_cs, free["A"], sp.oo)
    ours = {"V_D1": eqs.V_D1, "V_s": eqs.V_s, "R9": eqs.R9, "R10": eqs.R10, "R11": eqs.R11, "R12": eqs.R12,
            "R13": eqs.R13}
    return held.subs({free[k]: v for k, v in ours.items() if k in free})


def compare() -> dict:
    """{"lcapy": its V_cs, "derived": the registry's derivation, "printed": eq 13 as printed,
    "same_as_derived", "same_as_printed"} (sympy simplify of each difference == 0; K must drop out)."""
    import sympy as sp

    from ..sources.an94002 import equations as eqs

    held = trip_from_netlist()
    derived = eqs.v_cs_at_trip()
    printed = eqs.eq13().printed
    return {"lcapy": held, "derived": derived, "printed": printed,
            "same_as_derived": sp.simplify(held - derived) == 0, "same_as_printed": sp.simplify(held - printed) == 0,
            "free_of_loop_gain": not any(s.name in ("K", "A") for s in held.free_symbols)}


#: the LM4651/LM4652 bridge output filter: L1 in each leg, C_BYP and the load across the two outputs (driven
#: from node "in" against ground: lcapy's transfer function needs no source)
FILTER_NETLIST = """
L1 in a L
C1 a b C
RL a b R
L2 b 0 L
"""


def filter_from_netlist() -> dict:
    """The bridge filter's transfer function (load voltage over bridge voltage) derived by lcapy from
    :data:`FILTER_NETLIST`, against the second-order form the class-D design uses: corner f_C = 1 / (2 pi
    sqrt(2 L C)) and Q = R sqrt(C / 2L) (:func:`handbook.sources.lm4651.circuit.filter_f0`, ``filter_q``,
    fed sympy symbols). {"lcapy", "registry", "same"}."""
    import lcapy
    import sympy as sp

    from ..sources.lm4651 import circuit as lm4651

    cct = lcapy.Circuit(FILTER_NETLIST)
    h = cct.transfer("in", 0, "a", "b").expr
    free = {x.name: x for x in h.free_symbols}
    s, l_, c_, r_ = free["s"], free["L"], free["C"], free["R"]
    def exact(expr):  # the functions compute with floats (math.pi, ** 0.5): each float back to its exact value
        return expr.xreplace({x: sp.nsimplify(float(x), tolerance=1e-12) for x in expr.atoms(sp.Float)})

    w0, q = exact(2 * math.pi * lm4651.filter_f0(l_, c_)), exact(lm4651.filter_q(l_, c_, r_))
    registry = 1 / ((s / w0) ** 2 + s / (w0 * q) + 1)
    return {"lcapy": sp.simplify(h), "registry": registry, "same": sp.simplify(h - registry) == 0}


def timer_from_netlist() -> dict:
    """A timer pin: the IC's constant current I into the capacitor C, from rest. lcapy's v(t), set equal to
    the swing dV after one commutation interval t_com = 1 / (6 n N), solved for C, against the registry's
    derivation of AN94002 eq 5 (charge balance). {"lcapy", "registry", "same"}."""
    import lcapy
    import sympy as sp

    from ..sources.an94002 import equations as eqs

    cct = lcapy.Circuit("I1 a 0 step I_ch\nC1 a 0 C")  # SPICE's sense: the source drives I_ch into node a
    v = cct.a.V(lcapy.t).expr
    free = {x.name: x for x in v.free_symbols}
    at = v.subs(sp.Heaviside(free["t"]), 1).subs({free["t"]: 1 / (6 * eqs.n * eqs.N), free["I_ch"]: eqs.I})
    c_needed = sp.solve(sp.Eq(at, eqs.dV), free["C"])[0]
    registry = eqs.eq5().derived
    return {"lcapy": c_needed, "registry": registry, "same": sp.simplify(c_needed - registry) == 0}
