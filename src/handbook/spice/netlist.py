"""The designed circuits as plain SPICE decks to take away (`python -m handbook design SPEC.toml --netlist DIR`).

One deck per designed table, each the circuit at its nominal values with the designed parts, built by the same
code as the book's own decks (:mod:`.timers`, :mod:`.limiter`, :mod:`.class_d`, :mod:`.converter`), with a
comment header (the design, the handbook's version, the spec's SHA-256 as the JSON output gives it, and what
each part is), one analysis and the `.meas` lines that reproduce the design's figures at that nominal point:

* ``commutation.cir``: CAP-CD / CAP-DC over three electrical cycles at rpm_min, then at rpm_max (transient):
  the swings and the commutation delays. When the design chose them, ``commutation_cap_st.cir`` (the start
  oscillator) and ``commutation_cap_ti.cir`` (the watchdog) beside it: CAP-ST's period is a second or so where
  CAP-CD's commutation lasts a millisecond, and one transient holding both would take millions of steps;
* ``current_limiter.cir``: the op-amp limiter in DC, the motor current swept from 0 to twice i_must_trip: the
  trip current and sense voltage, both inputs' headroom and the output at no current and at the top;
* ``class_d.cir``: the bridge filter with its load in AC: corner, Q, the gain at f_audio, and the switching
  residue at the load from the square wave's odd harmonics up to the 15th (the idle bridge's transient is in
  the deck as comment lines: ngspice runs one analysis per deck in batch mode with `.meas` of one kind);
* ``converter.cir``: the TCA5600 power stage's switching transient: t1, t2, the frequency, the peak current and
  the current into C2.

Plain SPICE: no `.control` block, no ``params:`` (the LM358's figures are written into its `.subckt`), no
brace expressions, no `.include`; behavioural B sources use arithmetic, ``min``/``max``/``sqrt`` and
comparisons only; `.meas` lines in the HSPICE / LTspice form (``.meas <analysis> name ...``).
:func:`nonportable` scans a deck for what other SPICEs would not read; :func:`Deck.checks` holds the design's
figures at the nominal point, which the tests hold each exported deck against in ngspice.
"""
from __future__ import annotations

import math
import os
import re
import tempfile
import textwrap
from dataclasses import dataclass
from pathlib import Path

from ..core.units import eng
from ..sources import an94002 as note
from ..sources.lm4651 import circuit as eqs
from . import class_d as cd
from . import converter as conv
from . import models, timers
from .circuit import Check, Circuit, Part
from .limiter import decks as lim
from .limiter import left_out

#: odd harmonics of the idle bridge's square wave summed for the residue (the 17th adds under 1e-7 of its rms)
HARMONICS = tuple(range(1, 16, 2))
#: DC sweep points of the limiter's motor current
SWEEP_POINTS = 2000
#: the units' signs a deck writes in ASCII
ASCII = str.maketrans({"µ": "u", "Ω": "ohm", "±": "+-", "°": " deg", "−": "-", "×": "x"})
#: columns of a deck's line (longer element lines continue on `+` lines, the header wraps)
LINE = 110


@dataclass(frozen=True)
class Deck:
    """One exported netlist: its file ``name``, the ``parts`` its header lists, the deck's ``body`` (models,
    elements, analysis, `.meas`), what the analysis is, and the design's figures it reproduces (``checks``:
    equation value at the nominal point, `.meas` name, tolerance and why)."""

    table: str
    name: str
    title: str
    parts: tuple[Part, ...]
    body: tuple[str, ...]
    analysis: str
    checks: tuple[Check, ...]
    nominal: str = ""  # how the nominal point was chosen

    def text(self, meta: dict) -> str:
        """The deck with its comment header; ``meta``: ``version`` and ``spec_sha256`` (spec.traced)."""
        head = [f"* {self.title}",
                f"* handbook {meta['version']}: the [{self.table}] design, `python -m handbook design --netlist`",
                f"* spec sha256 {meta['spec_sha256']}",
                *_comment("the circuit at its nominal values: " + (self.nominal or "every part at its designed value")),
                "*", "* parts:", *(f"*   {p.ref:<8} {_value(p):<14} {p.note}".rstrip() for p in self.parts), "*",
                *_comment(f"analysis: {self.analysis}"), "* measurements (the design's figure at this nominal point):",
                *(line for c in self.checks for line in _comment(
                    f"{c.measure:<10} {c.quantity}: {eng(c.equation, _unit(c.unit))} expected, within {c.rtol:.2%}",
                    "*   ", "*" + " " * 16)), "*"]
        text = "\n".join([*head, *_wrapped(self.body), ".end"]) + "\n"
        return text.translate(ASCII)  # a deck in ASCII: not every SPICE reads UTF-8, even in a comment

    def circuit(self, meta: dict | None = None) -> Circuit:
        """The deck as a :class:`~.circuit.Circuit` whose checks are the design's figures (for :func:`evaluate`)."""
        text = self.text(meta or {"version": "", "spec_sha256": ""})
        return Circuit(self.name, self.title, f"[{self.table}] design", self.parts, text, self.checks)


def _comment(text: str, first: str = "* ", then: str = "*   ") -> list[str]:
    """A comment wrapped at LINE columns."""
    return textwrap.wrap(text, LINE, initial_indent=first, subsequent_indent=then, break_on_hyphens=False)


def _wrapped(lines) -> list[str]:
    """Element lines longer than LINE columns continued on `+` lines (HSPICE reads at most 1024 columns a line);
    comment and dot lines as they are (a `.meas` stays one line, which a reader can comment out whole)."""
    out = []
    for line in lines:
        if line.startswith(("*", ".")) or len(line) <= LINE:
            out.append(line)
        else:
            out += textwrap.wrap(line, LINE, subsequent_indent="+ ", break_long_words=False, break_on_hyphens=False)
    return out


def _unit(unit: str) -> str:
    return {"1": "", "ohm": "Ω"}.get(unit, unit)


def _value(p: Part) -> str:
    return (p.value if isinstance(p.value, str) else eng(p.value, _unit(p.unit))).translate(ASCII)


def plain(lines) -> list[str]:
    """A deck's lines made plain: the title and `.end` dropped, inline ``$`` comments cut (HSPICE's and
    ngspice's, not LTspice's), ngspice's ``.options temp=`` written as `.temp`."""
    out = []
    for line in lines:
        low = line.strip().lower()
        if low == ".end":
            continue
        if low.startswith(".options") and "temp=" in low:
            temp = re.search(r"\btemp=(\S+)", line, re.IGNORECASE).group(1)
            rest = re.sub(r"\s*\btemp=\S+", "", line, flags=re.IGNORECASE)
            out += [f".temp {temp}"] + ([rest] if rest.strip().lower() != ".options" else [])
            continue
        out.append(line.split(" $ ")[0].rstrip() if not line.startswith("*") else line)
    return out


def _from(circuit: Circuit, table: str, name: str, analysis: str, nominal: str, keep=None) -> Deck:
    """A deck from one of the book's circuits, as it is (its checks kept, or those whose id is in ``keep``)."""
    checks = tuple(c for c in circuit.checks if keep is None or c.id in keep)
    return Deck(table, name, circuit.title + " (designed)", circuit.parts,
                tuple(plain(circuit.netlist.strip().splitlines()[1:])), analysis, checks, nominal)


def _typical(typ: float, lo: float, hi: float) -> float:
    """The datasheet's typical figure where the spec's range holds it, else the middle of that range."""
    return typ if lo <= typ <= hi else (lo + hi) / 2


# ----------------------------------------------------------------------------------------------
# the four designs

def commutation(result) -> list[Deck]:
    """CAP-CD / CAP-DC (and CAP-ST, CAP-TI when designed) at the IC's typical currents and levels."""
    s = result.spec
    i_ch = _typical(note.FACTS["cap_cd_charge"].value[1], s["i_charge_min"], s["i_charge_max"])
    q = {"cap_cd": result.cap_cd, "cap_dc": result.cap_dc, "pole_pairs": s["pole_pairs"], "rpm_min": s["rpm_min"],
         "rpm_max": s["rpm_max"], "i_ch": i_ch, "i_dis": 2 * i_ch,
         "v_low": _typical(timers.CD_LOW[1], s["v_low_min"], s["v_low_max"]),
         "v_high": _typical(timers.CD_HIGH[1], s["v_high_min"], s["v_high_max"])}
    typical = "the TDA5144's typical currents and levels (the middle of the spec's range where it excludes them)"
    out = [_from(timers.commutation_delay(q), "commutation", "commutation.cir",
                 f"transient, three electrical cycles at {s['rpm_min']:g} rpm then at {s['rpm_max']:g} rpm (the "
                 "back-EMF zero crossings as gate sources)",
                 f"{typical}, the sink twice the charge current as the --spice confirmation takes it; the corners are "
                 "in --spice")]
    if result.cap_st is not None:
        st = {"cap_st": result.cap_st, "v_low": s["v_st_low"], "v_high": s["v_st_high"],
              "i_st": _typical(note.FACTS["cap_st_current"].value[1], s["i_st_min"], s["i_st_max"])}
        out.append(_from(timers.start_oscillator(st), "commutation", "commutation_cap_st.cir",
                         "transient, 3.6 periods of the start oscillator", typical,
                         keep=("start-period", "start-ramp-up")))
    if result.cap_ti is not None:
        wd = {"cap_ti": result.cap_ti, "i_wd": _typical(note.params()["i_wd"], s["i_wd_min"], s["i_wd_max"])}
        out.append(_from(timers.watchdog(wd), "commutation", "commutation_cap_ti.cir",
                         "transient, a stalled cycle then one where the back-EMF recovers", typical))
    return out


def current_limiter(result) -> list[Deck]:
    """The op-amp limiter (AN94002 figure 3) with the designed network, the motor current swept in DC."""
    s = result.spec
    i_top = 2 * s["i_must_trip"]
    p = {**lim.opamp_defaults(), "v_supply": s["v_supply_min"], "zener_voltage": s["zener_voltage"], "r7": result.r7,
         "r9": result.r9, "r10": result.r10, "r11": result.r11, "r12": result.r12, "r13": result.r13,
         "r14": result.r14, "vos": 0.0, "ibp": 0.0, "ibn": 0.0, "i_max": i_top}
    nodes = {**lim.OPAMP_NODES, "U1": "inp{s} inn{s} vs{s} 0 out{s} {v}"}  # the LM358's figures in its subckt
    zener, lines = lim.opamp_block(p, nodes=nodes)
    parts = tuple(Part(x.ref, x.value, x.unit, "motor current, swept in DC from 0 to this value") if x.ref == "IM"
                  else x for x in lim.opamp_parts(p))
    a0, mid = models.LM358["a0"], lim._mid(p)
    body = [*models.lm358(values=p), *zener, *plain(ln for ln in lines if not ln.startswith("IM ")),
            "IM csm 0 DC 0", lim._probe("d", "v(inp)-v(inn)"), ".temp 25", ".options tnom=25",
            f".dc IM 0 {i_top:.6g} {i_top / SWEEP_POINTS:.6g}",
            "* the trip: the LM358's input difference where its output passes mid-swing (out = A0 (V+ - V-))",
            f".meas dc i_trip WHEN v(pd)={mid / a0:.6g} FALL=1", f".meas dc vcs_trip FIND v(pcs) WHEN v(pd)={mid / a0:.6g} "
            "FALL=1", ".meas dc head_p FIND v(php) AT=0", ".meas dc head_m FIND v(phm) AT=0",
            ".meas dc out_idle FIND v(out) AT=0", f".meas dc out_top FIND v(out) AT={i_top * (1 - 1 / SWEEP_POINTS):.6g}"]
    vz, s910 = s["zener_voltage"], result.r9 + result.r10
    # the design takes V_Z at D1's 5 mA test current; here D1 carries R14's current less the dividers' (more at a
    # nominal V_Z than the design's least, i_zener_min): its 15 ohm lift V_Z, and eq 13 and eq 11 scale with V_Z
    i_d1 = left_out.divider_currents(p, 0.0)["zener"]
    k = 1 + models.BZX79_C8V2_RZ * (i_d1 - models.BZX79_C8V2_IZT) / vz
    lift = (f"the design's figure with V_Z at the {i_d1 * 1e3:.3g} mA D1 carries here (x {k:.5f}: its 15 ohm "
            "above the 5 mA test current)")
    checks = (
        Check("netlist-limiter-trip", "nominal trip current (eq 13 / R7)", "A", result.i_trip_nominal * k, "i_trip",
              0.005, f"{lift}; R12's current also flows in R7 and the zener's exponential bends its 15 ohm (0.1 % "
              "seen): ±0.5 %, as the --spice confirmation"),
        Check("netlist-limiter-vcs", "nominal sense voltage at the trip (eq 13)", "V", result.v_cs_nominal * k,
              "vcs_trip", 0.005, f"{lift}; as the trip current: ±0.5 %"),
        Check("netlist-limiter-head-p", "V_s - V+ at no motor current (eq 11)", "V",
              k * vz * result.r12 / (result.r12 + result.r13), "head_p", 0.002,
              f"{lift}; the zener's exponential bends its 15 ohm (0.05 % seen): ±0.2 %, as the --spice confirmation"),
        Check("netlist-limiter-head-m", "V_s - V- at no motor current (R9 + R10 against R11)", "V",
              k * vz * s910 / (s910 + result.r11), "head_m", 0.002, f"{lift}; as V+: ±0.2 %"),
        Check("netlist-limiter-idle", "op-amp output at no motor current (high)", "V",
              s["v_supply_min"] - models.LM358["v_oh_drop"], "out_idle", 1e-3,
              "the model's output clamp, reached with the input 2 V inside its range", kind="sanity"),
        Check("netlist-limiter-top", "op-amp output at the top of the sweep (low)", "V", models.LM358["v_ol"], "out_top",
              0.01, "the model's lower output clamp", kind="sanity"))
    return [Deck("current_limiter", "current_limiter.cir", "AN94002 figure 3: op-amp current limiter (designed)",
                 parts, tuple(body), f"DC sweep of the motor current IM, 0 to {eng(i_top, 'A')} in "
                 f"{SWEEP_POINTS} steps", checks,
                 "offset and bias currents zero, as the design's nominal trip (eq 13) takes them, D1 at its "
                 "nominal V_Z, the supply at v_supply_min (D1's current there is the nearest to its 5 mA test "
                 "current); the corners are in --spice")]


def class_d(result) -> list[Deck]:
    """The bridge filter with the designed L and C_BYP, the spec's load and supply, at the design's f_sw, in AC."""
    s = result.spec
    p = {**cd.defaults(), "l_out": result.l_out, "c_out": result.c_out, "r_load": s["r_load"], "supply": s["supply"],
         "f_sw": result.f_sw, "f_audio": s["f_audio"]}
    ps, fa, f_sw = cd.parts(p), s["f_audio"], result.f_sw
    f_lo = fa / 1e3  # f_audio is then a point of the grid
    f_hi = f_lo * 10 ** math.ceil(math.log10(1.2 * HARMONICS[-1] * f_sw / f_lo))
    amp = 8 * s["supply"] / math.pi / math.sqrt(2)  # the +-2 V_s square's fundamental, rms
    total = "+".join(f"h{k}*h{k}" + (f"/{k * k}" if k > 1 else "") for k in HARMONICS)
    body = [*cd.element_lines(p, ps), "* the AC drive is 1 V across the bridge: v(out) is the filter's response",
            ".save v(out)", f".ac dec {cd.AC_PER_DECADE} {f_lo:.6g} {f_hi:.6g}",
            "* the corner: phase -90 deg, where the response's real part is zero",
            ".meas ac f_corner WHEN vr(out)=0", ".meas ac q FIND vm(out) WHEN vr(out)=0",
            f".meas ac g_audio FIND vdb(out) AT={fa:.6g}",
            "* the residue at the load: the idle bridge's odd harmonics (8 V_s / (pi k)) through the filter",
            *(f".meas ac h{k} FIND vm(out) AT={k * f_sw:.9g}" for k in HARMONICS),
            f".meas ac ripple PARAM='{amp:.9g}*sqrt({total})'",
            "* the idle bridge in the time domain instead (every harmonic, the LM4652's edges): comment out the"
            " .ac and .meas ac lines above and use these", *("* " + ln for ln in cd.tran_lines(p, "ripple_tran"))]
    grid = f"the AC grid ({cd.AC_PER_DECADE} points a decade, interpolated)"
    checks = (
        Check("netlist-class-d-corner", "filter corner with the load, phase -90 deg", "Hz",
              result.f_corner, "f_corner", 1e-3,
              f"2 L in series with C_BYP across R_L is the bridge's network: only {grid} (0.01 % seen): ±0.1 %"),
        Check("netlist-class-d-q", "filter Q with the load (gain at the corner)", "1",
              eqs.filter_q(result.l_out, result.c_out, s["r_load"]), "q", 1e-3, f"the same network, {grid}: ±0.1 %"),
        Check("netlist-class-d-ripple", "switching residue at the load, rms", "V",
              eqs.ripple_rms(f_sw, result.l_out, result.c_out, s["r_load"], s["supply"]), "ripple", 0.002,
              "the design keeps only the fundamental; the harmonics up to the 15th add about 0.07 % rms and the "
              "grid's interpolation of |H| between its points at most 0.04 %: ±0.2 %, as --spice"))
    return [Deck("class_d", "class_d.cir", "LM4651/LM4652 bridge output filter with its load (designed)", ps,
                 tuple(body), f"AC, {eng(f_lo, 'Hz')} to {eng(f_hi, 'Hz')}, {cd.AC_PER_DECADE} points a decade", checks,
                 "L1, L2 and C_BYP at their designed values, the oscillator at its nominal f_sw, the spec's load "
                 "and supply; the eight tolerance corners are in --spice")]


def converter(result) -> list[Deck]:
    """The TCA5600 power stage with the wound L1 (nominal) and the fitted R1, at the lowest supply."""
    from ..design.converter.result import source_params

    p = {**source_params(result.spec), "l1": result.l1_nominal, "r1": result.r1_part}
    return [_from(conv.circuit(p), "converter", "converter.cir",
                  "transient, seven switching cycles at v_supply_min; the figures are read in the third",
                  "L1 as wound (nominal A_L), R1 the fitted series value, the converter's supply at v_supply_min, C2 "
                  "held at v_out + v_regulator_drop")]


#: design table -> its decks
BUILDERS = {"commutation": commutation, "current_limiter": current_limiter, "class_d": class_d,
            "converter": converter}


def decks(results: dict) -> list[Deck]:
    """The decks of every design result given ({table: result}; tables without a builder are skipped)."""
    return [d for table, result in results.items() if table in BUILDERS for d in BUILDERS[table](result)]


# ----------------------------------------------------------------------------------------------
# what other SPICEs would not read

#: (pattern, why) of what a plain deck must not hold: ngspice's own constructs, or what only it reads
NGSPICE_ONLY = (
    (r"^\s*\.(control|endc)\b", "a .control block (ngspice's scripting)"),
    (r"\bparams:", "params: on a .subckt or instance line (ngspice / HSPICE-style subcircuit parameters)"),
    (r"[{}]", "a brace expression"),
    (r"\?", "a ternary (cond ? a : b) in an expression"),
    (r"^\s*\.(include|inc|lib)\b", "an .include or .lib of a file that is not written"),
    (r"^\s*(let|wrdata|write|print|plot|run|quit|linearize|alter|altermod)\b", "an ngspice command"),
    (r"@\w+\[", "an ngspice internal vector (@dev[param])"),
    (r"\bsavecurrents\b", "ngspice's savecurrents option"),
    (r"\b(u|uramp|ternary_fcn|nint)\(", "an ngspice-only function"),
    (r"\s\$\s|;", "an inline comment ($ and ; are not read alike by every SPICE)"),
)


def nonportable(text: str) -> list[tuple[int, str, str]]:
    """[(line number, line, what is wrong)] for every line of a deck another SPICE may not read
    (:data:`NGSPICE_ONLY`), a `.meas` without its analysis (.meas tran|ac|dc name ...), more or fewer than one
    analysis, or no `.end` at the end. Comment lines are not read (the title is the first line)."""
    out, lines, logical = [], text.splitlines(), []
    for n, line in enumerate(lines[1:], start=2):  # continuation lines joined to the line they continue
        if line.startswith("+") and logical:
            logical[-1] = (logical[-1][0], logical[-1][1] + " " + line[1:].strip())
        elif line.strip() and not line.lstrip().startswith("*"):
            logical.append((n, line))
    for n, line in logical:
        out += [(n, line, why) for pattern, why in NGSPICE_ONLY if re.search(pattern, line, re.IGNORECASE)]
        if re.match(r"\s*\.meas(ure)?\b", line, re.IGNORECASE) and not re.match(
                r"\s*\.meas(ure)?\s+(tran|ac|dc)\s+\w+\s", line, re.IGNORECASE):
            out.append((n, line, ".meas without its analysis (.meas tran|ac|dc name ...)"))
    analyses = [n for n, line in enumerate(lines, start=1) if re.match(r"\s*\.(tran|ac|dc|op|noise|tf)\b", line, re.I)]
    if len(analyses) != 1:
        out.append((analyses[1] if analyses[1:] else len(lines), "", f"{len(analyses)} analyses: one per deck"))
    if not lines or lines[-1].strip().lower() != ".end":
        out.append((len(lines), lines[-1] if lines else "", "the deck does not end with .end"))
    return out


def write(texts: dict[str, str], folder) -> list[Path]:
    """Write {file name: deck} into ``folder`` (made if missing): every file or none. Each deck goes to a
    temporary file in the folder first; only when all are written are they renamed into place, a file they
    replace set aside until the last is in. On an error the folder is put back as it was (the files set aside
    restored, the temporary files removed, the folder removed if this call made it) and the OSError is raised."""
    folder = Path(folder)
    made = not folder.exists()
    temps: dict[str, Path] = {}
    placed: list[Path] = []
    aside: dict[Path, Path] = {}  # a file replaced -> where it waits
    umask = os.umask(0)
    os.umask(umask)
    try:
        folder.mkdir(parents=True, exist_ok=True)
        for name, text in texts.items():
            fd, tmp = tempfile.mkstemp(prefix=f".{name}-", suffix=".tmp", dir=folder)
            temps[name] = Path(tmp)
            with os.fdopen(fd, "w", encoding="utf-8") as fh:
                fh.write(text)
            os.chmod(tmp, 0o666 & ~umask)  # a plain file's mode, not mkstemp's private one
        for name, tmp in list(temps.items()):
            target = folder / name
            if target.exists():
                fd, old = tempfile.mkstemp(prefix=f".{name}-", suffix=".old", dir=folder)
                os.close(fd)
                temps[f"{name}.old"] = Path(old)  # removed on an error until the old file is in it
                os.replace(target, old)
                aside[target] = temps.pop(f"{name}.old")
            os.replace(tmp, target)
            placed.append(target)
    except BaseException:
        _put_back(placed, aside, temps.values())
        if made and folder.is_dir() and not any(folder.iterdir()):
            folder.rmdir()
        raise
    for old in aside.values():
        old.unlink(missing_ok=True)
    return [folder / name for name in texts]


def _put_back(placed, aside: dict, temps) -> None:
    """Undo a :func:`write` that failed: the new files removed, the old ones back, the temporary files gone."""
    for target in placed:
        target.unlink(missing_ok=True)
    for target, old in aside.items():
        if old.exists():
            os.replace(old, target)
    for tmp in temps:
        tmp.unlink(missing_ok=True)
