"""Speed of the design engine, measured once and written to book/design/benchmark.json.

Usage: python tools/benchmark.py
Measures: one `python -m handbook design` run from the shell (wall time, median of 5); each design
function (median of 20); and, for each problem, the casadi route against exhaustive enumeration of
the series and against scipy.optimize (SLSQP) on the same continuous relaxation. Not a test: timings
depend on the machine. The book shows the committed results.
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
from scipy.optimize import minimize

from handbook.design import class_d, commutation, current_limiter
from handbook.design.schema import defaults
from handbook.sources.lm4651 import circuit as lm4651

ROOT = Path(__file__).resolve().parents[1]


def timed(fn, repeat=20):
    times = []
    for _ in range(repeat):
        t = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t)
    return statistics.median(times)


def scipy_commutation():
    s = defaults("commutation")
    t_slow, t_fast = 10 / (s["rpm_min"] * s["pole_pairs"]), 10 / (s["rpm_max"] * s["pole_pairs"])
    cons = [{"type": "ineq", "fun": lambda x: 1 - s["i_charge_max"] * t_slow / (x[0] * 1e-9 * 0.95) / s["window"]},
            {"type": "ineq", "fun": lambda x: s["i_charge_min"] * t_fast / (x[0] * 1e-9 * 1.05) / s["min_excursion"] - 1}]
    return minimize(lambda x: x[0], [30.0], method="SLSQP", constraints=cons, bounds=[(1e-3, 1e9)], tol=1e-12).x


def scipy_limiter():
    s = current_limiter.checked({})

    def cur(x):
        return current_limiter.trip_currents(math.exp(x[0]), math.exp(x[1]), s)
    cons = [{"type": "ineq", "fun": lambda x: cur(x)[0] / s["i_no_trip"] - 1},
            {"type": "ineq", "fun": lambda x: 1 - cur(x)[1] / s["i_must_trip"]}]
    b = [(math.log(s["r7_min"]), math.log(s["r7_max"])), (math.log(s["r9_min"]), math.log(s["r9_max"]))]
    return minimize(lambda x: x[0], [math.log(0.316), math.log(1e5)], method="SLSQP", constraints=cons, bounds=b,
                    tol=1e-12).x


def scipy_class_d():
    s = class_d.checked({})
    p = lambda x: lm4651.p_switch(x[0] * 1e3, s["p_out"]) + lm4651.p_conduction(s["p_out"], s["r_load"])  # noqa: E731
    cons = [{"type": "ineq", "fun": lambda x: 1 - lm4651.thd_n(x[0] * 1e3) / s["thd_max"]},
            {"type": "ineq", "fun": lambda x: lm4651.p_clip(x[0] * 1e3, s["r_load"], s["supply"]) / s["p_out"] - 1}]
    return minimize(p, [110.0], method="SLSQP", constraints=cons, bounds=[(50, 225)], tol=1e-12).x


def main():
    with tempfile.TemporaryDirectory() as tmp:
        spec = Path(tmp) / "empty.toml"
        spec.write_text("")
        cli = []
        for _ in range(5):
            t = time.perf_counter()
            subprocess.run([sys.executable, "-m", "handbook", "design", str(spec), "--json"], check=True,
                           capture_output=True)
            cli.append(time.perf_counter() - t)
    rows = {}
    for name, fn, enum, sp in (
            ("commutation", commutation.design, lambda: commutation.enumerate_series({}), scipy_commutation),
            ("current_limiter", current_limiter.design, lambda: current_limiter.enumerate_series({}), scipy_limiter),
            ("class_d", class_d.design, lambda: class_d.enumerate_series({}), scipy_class_d)):
        t_casadi = timed(fn)
        t_enum = timed(enum)
        t_scipy = timed(sp)
        rows[name] = {"casadi_s": t_casadi, "enumeration_s": t_enum, "scipy_relaxation_s": t_scipy,
                      "enumeration_over_casadi": t_enum / t_casadi, "scipy_over_casadi": t_scipy / t_casadi}
    out = {"machine": f"{platform.machine()}, {platform.python_implementation()} {platform.python_version()}",
           "cli_wall_s_median_of_5": statistics.median(cli), "designs": rows,
           "relaxation_agrees": {
               "commutation_nF": [float(scipy_commutation()[0]), commutation.design().continuous_optimum * 1e9],
               "limiter_r7": [float(np.exp(scipy_limiter()[0])), current_limiter.design().r7_relaxed],
               "class_d_kHz": [float(scipy_class_d()[0]), class_d.design().f_continuous / 1e3]}}
    path = ROOT / "book" / "design" / "benchmark.json"
    path.write_text(json.dumps(out, indent=1) + "\n")
    print(json.dumps(out, indent=1))


if __name__ == "__main__":
    main()
