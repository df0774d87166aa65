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
