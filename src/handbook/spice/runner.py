"""ngspice in batch mode, run by the project's own small runner: write the netlist, run `ngspice -b`,
read the `.meas` results from its output. No wrapper library (see the notes on tools): a subprocess is
the least fragile way to drive Debian's ngspice.

Errors are messages, not tracebacks: :class:`SpiceUnavailable` when ngspice is not installed (the tests
and the book then report the SPICE checks as skipped, saying why), :class:`SpiceError` when a netlist
does not parse or a measurement fails (naming the netlist's title and ngspice's own words).
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
_DECLARED = re.compile(r"^\s*\.meas(?:ure)?\s+\S+\s+(\S+)", re.IGNORECASE | re.MULTILINE)


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


def run(netlist: str, timeout: float = 30.0) -> dict[str, float]:
    """Run one netlist in batch mode; {measurement name (lower case): value}.

    The netlist's first line is its title (SPICE's rule); its `.meas` lines name what is returned.
    """
    exe = available()
    if exe is None:
        raise SpiceUnavailable(why_unavailable())
    title = netlist.strip().splitlines()[0].lstrip("* ").strip() if netlist.strip() else "(empty netlist)"
    with tempfile.TemporaryDirectory(prefix="handbook-spice-") as tmp:
        deck = Path(tmp) / "deck.cir"
        deck.write_text(netlist if netlist.rstrip().lower().endswith(".end") else netlist.rstrip() + "\n.end\n")
        try:
            proc = subprocess.run([exe, "-b", str(deck)], capture_output=True, text=True, timeout=timeout, cwd=tmp)
        except subprocess.TimeoutExpired:
            raise SpiceError(f"{title}: ngspice did not finish within {timeout:g} s") from None
    text = proc.stdout + "\n" + proc.stderr
    failed = _FAILED.findall(text)
    if proc.returncode != 0:
        said = [line.strip() for line in proc.stderr.splitlines() if line.strip()]
        raise SpiceError(f"{title}: ngspice refused the netlist (exit {proc.returncode}): "
                         + "; ".join(said[:3] or ["no message"]))
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
