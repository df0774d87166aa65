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
import random
import sys
from importlib import import_module
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path[:0] = [str(ROOT / "tests"), str(ROOT / "src")]

import papermill as pm  # noqa: E402
import test_rerun as tr  # noqa: E402

from handbook.core import parameters  # noqa: E402

SETS = 3


def registry(chapter: str) -> dict:
    """name -> Param of the chapter's inputs (the source document's parameters, or the design schema's table)."""
    doc, name = chapter.split("/")
    if doc == "design":
        from handbook.design import schema
        table = {"cap_cd": "commutation", "class_d": "class_d", "current_limiter": "current_limiter",
                 "converter": "converter"}.get(name)
        return {p.name: p for p in schema.TABLES.get(table, ())}
    return {p.name: p for p in import_module(f"handbook.sources.{doc}").SOURCE.parameters}


def generated(chapter: str, k: int) -> dict:
    """The k-th generated parameter set of a chapter (only the values that differ from its parameters cell)."""
    nb = json.loads((tr.BOOK / f"{chapter}.ipynb").read_text())
    cell = next(c for c in nb["cells"] if "parameters" in c.get("metadata", {}).get("tags", []))
    values, reg = parameters.assignments("".join(cell["source"])), registry(chapter)
    rng, factors, out = random.Random(f"{chapter}-{k}"), {}, {}
    for key, v in values.items():
        p = reg.get(key)
        if p is None or isinstance(v, bool) or not isinstance(v, (int, float)):
            continue
        if isinstance(v, int):
            new = max(int(p.low or 1), min(int(p.high or 100), v + rng.choice([-2, -1, 1, 2])))
        else:
            stem = key.removesuffix("_min").removesuffix("_max")  # a range moves as one
            factor = factors.setdefault(stem, rng.uniform(0.85, 1.2))
            new = v * factor
            new = min(new, p.high) if p.high is not None else new
            new = max(new, p.low * 1.0001 if p.low_open else p.low) if p.low is not None else new
        if new != v:
            out[key] = new
    return out


def main(chapters: list[str]) -> int:
    km, bad = tr._shared_kernel(), 0
    for chapter in chapters or sorted(c for c in tr.RERUNS if c != "design/your_own"):
        note_nb = json.loads((tr.BOOK / f"{chapter}.ipynb").read_text())
        for k in range(SETS):
            params = generated(chapter, k)
            out = ROOT / "_build" / "rerun_generated" / f"{chapter.replace('/', '_')}_{k}.ipynb"
            out.parent.mkdir(parents=True, exist_ok=True)
            try:
                tr._fresh(km, (tr.BOOK / chapter).parent)
                pm.execute_notebook(str(tr.BOOK / f"{chapter}.ipynb"), str(out), parameters=params,
                                    kernel_name="python3", progress_bar=False, km=km)
            except Exception as exc:  # the chapter stopped: its last line says why
                bad += 1
                print(f"{chapter} set {k}: STOPPED: {str(exc).strip().splitlines()[-1][:200]}")
                continue
            saved, tr.RERUNS[chapter] = tr.RERUNS[chapter], params
            try:
                found = tr.problems(chapter, note_nb, json.loads(out.read_text()))
            finally:
                tr.RERUNS[chapter] = saved
            bad += bool(found)
            print(f"{chapter} set {k}: {len(params)} parameters changed, {len(found)} finding(s)")
            for f in found[:3]:
                print("    " + f[:240])
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
