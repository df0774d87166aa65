"""Speed and proof of the design engine, measured once and written to book/design/benchmark.json.

Usage: python tools/benchmark.py [--wide-only | --report]
Measures: one `python -m handbook design` run from the shell (wall time, median of 5); each design against
its exhaustive enumeration; the limiter network's exact search against exhaustive enumeration
(tests/oracles.py: every network, every corner from the node equations) on 200 generated specifications with
reduced series; the search on 520 wide generated specifications (E24..E192, every figure varied: time of
every answer, each design held at every corner of the oracle and against the exact reference of
tests/exact_limiter.py, the proof flags counted); and the full-E96
default with the enumeration's time extrapolated from a measured sample. Not a test (timings depend on the
machine); the book shows the committed results. ``--report`` only times `python -m handbook report` on the
template spec (HTML with SPICE, PDF, HTML without SPICE; one run each) and prints it, writing nothing.
"""
import json
import math
import platform
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tests"))

from exact_limiter import exact_limiter  # noqa: E402
from limiter_specs import reduced_spec, wide_spec  # noqa: E402

from handbook.core import InputError  # noqa: E402
from handbook.design import class_d, commutation, limiter  # noqa: E402
from handbook.design.solvers import Infeasible  # noqa: E402

from oracles import enumerate_limiter, limiter_corners  # noqa: E402


def timed(fn, repeat=5):
    times = []
    for _ in range(repeat):
        t = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t)
    return statistics.median(times)


def limiter_reduced(cases: int = 200) -> dict:
    """The search against exhaustive enumeration (tests/oracles.py) on reduced series."""
    rng = np.random.default_rng(2026)
    same = same_net = feasible = feasible_same = 0
    t_search, t_enum = [], []
    for _ in range(cases):
        spec = reduced_spec(rng)
        t = time.perf_counter()
        expected = enumerate_limiter(spec)
        t_enum.append(time.perf_counter() - t)
        t = time.perf_counter()
        try:
            got = limiter.design(spec, board=False)
        except Infeasible:
            got = None
        t_search.append(time.perf_counter() - t)
        if got is None or expected is None:
            same += got is None and expected is None
            same_net += got is None and expected is None
            continue
        feasible += 1
        worst = min(got.margin_low, got.margin_high)
        ok = got.r7 == expected[0] and expected[2] - limiter.GAP - 1e-9 <= worst <= expected[2] + 1e-9
        same += ok
        feasible_same += ok
        same_net += got.r7 == expected[0] and got.network == expected[1]
    return {"cases": cases, "feasible": feasible, "same_optimum": int(same), "feasible_same_optimum": int(feasible_same),
            "same_network": int(same_net), "search_s": statistics.mean(t_search), "enumeration_s": statistics.mean(t_enum)}


def limiter_wide(cases: int = 520) -> dict:
    """Every answer to wide specs timed (a design, or the Infeasible with what can be met), each design held
    at every corner of the oracle, and the proof flags counted."""
    rng = np.random.default_rng(18)
    times, designs, infeasible, unproven, sound, invalid = [], 0, 0, 0, 0, 0
    exact = {"checked": 0, "same": 0, "budget": 0, "differ": []}
    for _ in range(cases):
        spec = wide_spec(rng)
        try:
            limiter.checked(spec)
        except InputError:
            invalid += 1
            continue
        t = time.perf_counter()
        try:
            r = limiter.design(spec, board=False)
        except Infeasible:
            r = None
        times.append(time.perf_counter() - t)
        _against_exact(spec, r, exact)
        if r is None:
            infeasible += 1
            continue
        designs += 1
        unproven += not (r.r7_proven and r.best_proven)
        lo, hi, head, i_div = limiter_corners(r.r7, r.network, r.spec)
        s = r.spec
        sound += bool(lo >= s["i_no_trip"] * (1 + s["min_margin"]) * (1 - 1e-9)
                      and hi <= s["i_must_trip"] * (1 - s["min_margin"]) * (1 + 1e-9)
                      and head >= s["input_headroom"] - 1e-9 and i_div <= s["divider_current_max"] * (1 + 1e-9))
    q = np.percentile(times, [50, 90, 99])
    return {"cases": len(times), "invalid_skipped": invalid, "designs": designs, "infeasible": infeasible,
            "unproven": int(unproven), "sound_at_every_corner": int(sound), "median_s": float(q[0]),
            "p90_s": float(q[1]), "p99_s": float(q[2]), "max_s": float(max(times)),
            "over_2_s": int(sum(t > 2 for t in times)), "over_10_s": int(sum(t > 10 for t in times)),
            "exact_reference": exact}


def _against_exact(spec, r, exact, budget=2_000_000):
    """The design's answer against tests/exact_limiter.py (sharing no code with it): the same smallest R7 (or
    both none), the worst margin within GAP of the reference's best and not above it, the bound above it."""
    try:
        ref = exact_limiter(spec, max_boxes=budget)
    except RuntimeError:
        exact["budget"] += 1
        return
    exact["checked"] += 1
    if r is None or ref is None:
        ok = r is None and ref is None
    else:
        worst = min(r.margin_low, r.margin_high)
        ok = (r.r7 == ref[0] and ref[2] - limiter.GAP - 1e-9 <= worst <= ref[2] + 1e-9
              and r.margin_bound >= ref[2] - 1e-9)
    exact["same"] += ok
    if not ok:
        exact["differ"].append(spec)


def limiter_network() -> dict:
    """The reduced-series comparison, the wide specs, and the full E96 default (the enumeration's time
    extrapolated from a measured sample)."""
    out = {**limiter_reduced(), "wide": limiter_wide()}
    rng = np.random.default_rng(7)
    s = limiter.checked({})
    lists = [limiter.model.choices(s, n) for n in limiter.model.RESISTORS]
    networks = math.prod(len(v) for v in lists[1:])
    sample = [rng.choice(v, 20_000) for v in lists[1:]]
    t = time.perf_counter()
    limiter_corners(1.0, sample, s)
    per_network = (time.perf_counter() - t) / 20_000
    return {**out, "full_search_s": timed(lambda: limiter.design({}), 3), "full_networks": float(networks),
            "full_enumeration_s_extrapolated": per_network * networks}


def report_times() -> dict:
    """Wall time of `python -m handbook report` on `design --template`'s spec: HTML, PDF, HTML with --no-spice."""
    out = {}
    with tempfile.TemporaryDirectory() as tmp:
        spec = Path(tmp) / "template.toml"
        spec.write_text(subprocess.run([sys.executable, "-m", "handbook", "design", "--template"], check=True,
                                       capture_output=True, text=True).stdout)
        for name, extra in (("html_s", ["-o", "r.html"]), ("pdf_s", ["-o", "r.pdf"]),
                            ("html_no_spice_s", ["-o", "n.html", "--no-spice"])):
            t = time.perf_counter()
            subprocess.run([sys.executable, "-m", "handbook", "report", str(spec), *extra], check=True,
                           capture_output=True, cwd=tmp)
            out[name] = round(time.perf_counter() - t, 1)
    return out


def main():
    if "--report" in sys.argv:
        print(json.dumps(report_times(), indent=1))
        return
    if "--wide-only" in sys.argv:  # only the wide specs again, written into the JSON beside the rest
        path = ROOT / "book" / "design" / "benchmark.json"
        out = json.loads(path.read_text())
        out["limiter_network"]["wide"] = limiter_wide()
        path.write_text(json.dumps(out, indent=1) + "\n")
        print(json.dumps(out["limiter_network"]["wide"], indent=1))
        return
    with tempfile.TemporaryDirectory() as tmp:
        spec = Path(tmp) / "empty.toml"
        spec.write_text("")
        cli = []
        for _ in range(5):
            t = time.perf_counter()
            subprocess.run([sys.executable, "-m", "handbook", "design", str(spec), "--json"], check=True,
                           capture_output=True)
            cli.append(time.perf_counter() - t)
    rows = {name: {"design_s": timed(fn), "enumeration_s": timed(enum)} for name, fn, enum in (
        ("commutation", commutation.design, lambda: commutation.enumerate({})),
        ("class_d", class_d.design, lambda: class_d.enumerate({})))}
    out = {"machine": f"{platform.machine()}, {platform.python_implementation()} {platform.python_version()}",
           "cli_wall_s_median_of_5": statistics.median(cli), "designs": rows, "limiter_network": limiter_network()}
    path = ROOT / "book" / "design" / "benchmark.json"
    path.write_text(json.dumps(out, indent=1) + "\n")
    print(json.dumps(out, indent=1))


if __name__ == "__main__":
    main()
