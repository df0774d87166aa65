"""ngspice in batch mode, run by the project's own small runner: write the netlist, run `ngspice -b`,
read the `.meas` results from its output. No wrapper library (see the notes on tools): a subprocess is
the least fragile way to drive Debian's ngspice.

Errors are messages, not tracebacks: :class:`SpiceUnavailable` when ngspice is not installed (the tests
and the book then report the SPICE checks as skipped, saying why), :class:`SpiceError` when a netlist
does not parse or a measurement fails (naming the netlist's title, the offending line of the deck with its
number, and ngspice's own words). ngspice accepts some malformed element lines without a word (``R1 a``
becomes a 1 mOhm resistor to a node named by its value), so the deck is read first: an element line with
fewer fields than its kind needs is refused before ngspice runs, naming the line.

For the chapters' plots, :func:`waveform_or_reason` runs a simulation and returns (data, None), or (None,
a sentence) when ngspice is missing or refused the deck: a page shows the sentence instead of a traceback.
"""
from __future__ import annotations

import re
import shutil
import subprocess
import tempfile
from pathlib import Path

#: ngspice prints each measurement as `name = value` (some with `at= ...` or `targ= ...` after it)
_MEAS = re.compile(r"^\s*([a-z_][a-z0-9_]*)\s*=\s*([-+0-9.eE]+)(?:\s|$)", re.IGNORECASE)
_FAILED = re.compile(r"^\s*\.meas(?:ure)?\s+\S+\s+(\S+).*failed", re.IGNORECASE | re.MULTILINE)
#: a `.meas` line, or a `meas` command inside a .control block (it measures vectors made with `let`)
_DECLARED = re.compile(r"^\s*\.?meas(?:ure)?\s+\S+\s+(\S+)", re.IGNORECASE | re.MULTILINE)
#: where ngspice names a line of the deck: "Error on line 3 ...", "Netlist line no. 8:", "... from line N"
_LINE_NO = re.compile(r"(?:error on line|netlist line no\.?|line no\.?)\s*(\d+)", re.IGNORECASE)
#: ngspice quoting an element line after "... from line" / "Error on line N ...:" (indented on the next line)
_QUOTED = re.compile(r"(?:from line|or its substitute:)\s*\n\s+(\S.*)", re.IGNORECASE)
#: fewest fields (name and nodes and value/model) of an element line, by its first letter
_FIELDS = {"r": (4, "two nodes and a value"), "c": (4, "two nodes and a value"), "l": (4, "two nodes and a value"),
           "d": (4, "two nodes and a model"), "q": (5, "three nodes and a model"), "v": (3, "two nodes"),
           "i": (3, "two nodes"), "e": (5, "two nodes and a control"), "g": (5, "two nodes and a control"),
           "h": (4, "two nodes and a control"), "f": (4, "two nodes and a control"), "x": (3, "nodes and a subcircuit"),
           "s": (6, "four nodes and a model"), "b": (4, "two nodes and V= or I=")}


class SpiceUnavailable(RuntimeError):
    """ngspice is not installed here."""


class SpiceError(RuntimeError):
    """A netlist ngspice refused, or a measurement it could not make."""


def available() -> str | None:
    """The path of ngspice, or None."""
    return shutil.which("ngspice")


def why_unavailable() -> str:
    return ("ngspice is not installed: `make test` installs Debian's ngspice where apt-get runs as root "
            "(apt-get install ngspice); without it the SPICE checks are skipped")


def malformed(netlist: str) -> list[tuple[int, str, str]]:
    """Element lines with fewer fields than their kind needs: [(line number in the deck, the line, what it
    lacks)]. Comments, dot lines, continuations and .control blocks are not element lines."""
    out, control = [], False
    lines = netlist.splitlines()
    for k, line in enumerate(lines, start=1):
        text = line.split(";")[0].split("$ ")[0].strip()
        low = text.lower()
        if k == 1 or not text or text[0] in "*+":
            continue
        if low.startswith(".control"):
            control = True
        elif low.startswith(".endc"):
            control = False
        if control or text[0] == ".":
            continue
        need = _FIELDS.get(low[0])
        fields = len(text.split())
        nxt = lines[k].lstrip()[:1] if k < len(lines) else ""  # a continuation line adds fields
        if need and fields < need[0] and nxt != "+":
            out.append((k, line.strip(), f"a {low[0].upper()} element needs {need[1]}"))
        elif low[0] == "b" and "=" not in text and nxt != "+":
            out.append((k, line.strip(), _FIELDS["b"][1]))
    return out


#: a vector a measurement reads: v(node), v(a,b), i(source)
_VECTOR = re.compile(r"\b([vi])\(\s*([^\s(),]+)\s*(?:,\s*([^\s(),]+)\s*)?\)", re.IGNORECASE)


def unknown_vectors(netlist: str) -> list[tuple[int, str, str]]:
    """`.meas` lines that read a node or a source no top-level element line names: [(line number, line,
    "v(name)" or "i(name)")]. Asked only after ngspice has failed (its own words are "no data saved" or
    "not found", naming nothing)."""
    lines = netlist.splitlines()
    names, nodes, control = set(), {"0", "gnd"}, False
    for k, line in enumerate(lines, start=1):
        text = line.split(";")[0].strip().lower()
        if k == 1 or not text or text[0] in "*+":
            continue
        if text.startswith((".control", ".subckt")):
            control = True
        elif text.startswith((".endc", ".ends")):
            control = False
        elif not control and text[0] != ".":
            name, *fields = text.split()
            names.add(name)
            nodes.update(re.split(r"[\s(),=]+", " ".join(fields)))
    out = []
    for k, line in enumerate(lines, start=1):
        if not re.match(r"\s*\.?meas", line, re.IGNORECASE):
            continue
        for kind, a, b in _VECTOR.findall(line):
            missing = [x for x in (a, b) if x and x.lower() not in (nodes if kind.lower() == "v" else names)]
            if missing:
                out.append((k, line.strip(), f"{kind.lower()}({', '.join(missing)})"))
    return out


def _named(netlist: str, said: str) -> str:
    """The deck's element line whose name ngspice puts before a colon ("this: transmission line z0 must be
    given"), as "line N: `text`", or ""."""
    heads = {m.lower() for m in re.findall(r"([A-Za-z_][\w.]*)\s*:", said)}
    for n, line in enumerate(netlist.splitlines(), start=1):
        first = line.split()[0].lower() if line.split() else ""
        if n > 1 and first and first[0] not in "*.+" and first in heads:
            return f"line {n}: `{line.strip()}`"
    return ""


def _where(netlist: str, said: str) -> str:
    """The deck's line ngspice complains about, as "line N: `text`" (from its line number, else from the
    element line it quotes), or ""."""
    lines = netlist.splitlines()
    for m in _LINE_NO.finditer(said):
        n = int(m.group(1))
        if 1 <= n <= len(lines):
            return f"line {n}: `{lines[n - 1].strip()}`"
    for m in _QUOTED.finditer(said):
        quoted = m.group(1).strip().lower()
        for n, line in enumerate(lines, start=1):
            if line.strip().lower() == quoted or (quoted and line.strip().lower().startswith(quoted)):
                return f"line {n}: `{line.strip()}`"
    return _named(netlist, said)


def run(netlist: str, timeout: float = 30.0) -> dict[str, float]:
    """Run one netlist in batch mode; {measurement name (lower case): value}.

    The netlist's first line is its title (SPICE's rule); its `.meas` lines name what is returned.
    """
    title = netlist.strip().splitlines()[0].lstrip("* ").strip() if netlist.strip() else "(empty netlist)"
    bad = malformed(netlist)  # read before ngspice is looked for: a bad deck is reported where ngspice is missing too
    if bad:
        raise SpiceError(f"{title}: malformed element line(s), not run: "
                         + "; ".join(f"line {n}: `{line}` ({why})" for n, line, why in bad))
    exe = available()
    if exe is None:
        raise SpiceUnavailable(why_unavailable())
    with tempfile.TemporaryDirectory(prefix="handbook-spice-") as tmp:
        deck = Path(tmp) / "deck.cir"
        deck.write_text(netlist if netlist.rstrip().lower().endswith(".end") else netlist.rstrip() + "\n.end\n")
        try:
            proc = subprocess.run([exe, "-b", str(deck)], capture_output=True, text=True, timeout=timeout, cwd=tmp)
        except subprocess.TimeoutExpired:
            raise SpiceError(f"{title}: ngspice did not finish within {timeout:g} s") from None
    text = proc.stdout + "\n" + proc.stderr
    failed = _FAILED.findall(text)
    # ngspice can say "Error" and still exit 0 (a model it could not find, an analysis it skipped); a failed
    # measurement also prints "Error: measure ...", which is reported as such below
    errors = [line for line in text.splitlines() if re.match(r"\s*(error\b|.*simulation interrupted due to error)",
                                                             line, re.IGNORECASE) and "measure" not in line.lower()]
    if proc.returncode != 0 or (errors and not failed):
        said = [line.strip() for line in proc.stderr.splitlines()
                if line.strip() and not line.lower().startswith(("note: no compatibility", "warning"))]
        where = _where(netlist, proc.stderr + "\n" + proc.stdout)
        unread = unknown_vectors(netlist)
        raise SpiceError(f"{title}: ngspice refused the netlist (exit {proc.returncode})"
                         + (f" at {where}" if where else "") + ": " + "; ".join(said[:4] or ["no message"])
                         + "".join(f"; line {n}: `{line}` reads {vec}, a node or source no element line names"
                                   for n, line, vec in unread))
    if failed:
        raise SpiceError(f"{title}: measurement {', '.join(sorted(set(failed)))} failed (the event it waits for "
                         "never happened in the simulated time)")
    wanted = {name.lower() for name in _DECLARED.findall(netlist)}
    out = {}
    for line in proc.stdout.splitlines():
        m = _MEAS.match(line)
        if m and m.group(1).lower() in wanted:
            out[m.group(1).lower()] = float(m.group(2))
    missing = wanted - set(out)
    if missing:
        raise SpiceError(f"{title}: ngspice printed no value for {', '.join(sorted(missing))}")
    return out


def waveform_or_reason(fn, *args, **kwargs):
    """``fn(*args, **kwargs)`` for a chapter's plot: (its result, None), or (None, a sentence saying why there
    is no plot) when ngspice is not installed (:class:`SpiceUnavailable`) or refused the deck or a
    measurement failed (:class:`SpiceError`). Any other exception is a bug and is raised."""
    try:
        return fn(*args, **kwargs), None
    except SpiceUnavailable as exc:
        return None, f"SPICE plot skipped: {exc}."
    except SpiceError as exc:
        return None, f"SPICE plot not drawn: {exc}."
