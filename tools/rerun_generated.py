"""Re-run every chapter that has a parameters cell with generated parameter sets (issue 20's re-run check, not yet
a test): three sets per chapter, each numeric parameter the chapter's registry knows (the source's parameters or
the design schema's table) moved by a seeded factor of 0.85 to 1.2 (a whole number by up to two), clipped to its
accepted range, a key_min / key_max pair moved together. Each run is checked as tests/test_rerun.py checks its
hand-written re-runs (a note's value stated in the static prose as the reader's) and for a chapter that stops
with an error.

Usage: ``python tools/rerun_generated.py [CHAPTER ...]`` (default every chapter of tests/test_rerun.py's
RERUNS except "Design your own"). Prints one line per run and the first findings; exit 1 when any run found
something. About 3 minutes for every chapter on one core.
"""
from __future__ import annotations

import json
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path[:0] = [str(ROOT / "tests"), str(ROOT / "src")]

import test_rerun as tr  # noqa: E402

SETS = tr.SETS
#: findings printed per run
SHOW = 3


def main(chapters: list[str]) -> int:
    bad = 0
    for chapter in chapters or sorted(c for c in tr.RERUNS if c != "design/your_own"):
        note_nb = json.loads((tr.BOOK / f"{chapter}.ipynb").read_text())
        for k in range(SETS):
            params = tr.generated(chapter, k)
            out = ROOT / "_build" / "rerun_generated" / f"{chapter.replace('/', '_')}_{k}.ipynb"
            out.parent.mkdir(parents=True, exist_ok=True)
            try:
                tr.execute(chapter, params, out)
            except Exception as exc:  # the chapter stopped: its last line says why
                bad += 1
                print(f"{chapter} set {k}: STOPPED: {str(exc).strip().splitlines()[-1][:200]}")
                continue
            found = tr.problems(chapter, note_nb, json.loads(out.read_text()), params)
            bad += bool(found)
            print(f"{chapter} set {k}: {len(params)} parameters changed, {len(found)} finding(s)")
            for f in found[:SHOW]:
                print("    " + f[:240])
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
