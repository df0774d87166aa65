"""The generated limiter specifications the tests and tools/benchmark.py share (one generator for each
family, so the benchmark's figures and the tests' specs are drawn the same way)."""
import numpy as np


def reduced_spec(rng) -> dict:
    """The unit test's family: E12 dividers over half a decade, R9 E6/E12 over two decades, up to two pins,
    the bias, offset current and divider-current limit varied."""
    i_no = float(rng.uniform(0.1, 5))
    spec = dict(i_no_trip=i_no, i_must_trip=i_no * float(rng.uniform(1.6, 4)),
                resistor_tolerance=float(rng.choice([0.001, 0.01, 0.02])), r7_tolerance=float(rng.choice([0.01, 0.05])),
                zener_voltage=float(rng.choice([5.6, 8.2, 12.0])), zener_tolerance=float(rng.choice([0.02, 0.05])),
                offset=float(rng.uniform(0, 0.02)), input_bias=float(rng.choice([0.0, 100e-9, 500e-9])),
                min_margin=float(rng.choice([0.0, 0.02])), input_headroom=float(rng.choice([1.0, 2.0])),
                input_offset_current=float(rng.choice([0.0, 50e-9, 150e-9])),
                divider_current_max=float(rng.choice([1e-3, 3e-3, 0.1])),
                r7_series="E12", r7_min=0.01, r7_max=100.0, r9_series=str(rng.choice(["E6", "E12"])),
                r9_min=10.0 ** int(rng.integers(1, 4)))
    spec["r9_max"] = spec["r9_min"] * 100
    for n in ("r10", "r11", "r12", "r13"):
        low = float(rng.choice([1e3, 2.2e3, 4.7e3, 10e3, 22e3]))
        spec.update({f"{n}_series": "E12", f"{n}_min": low, f"{n}_max": low * 3})
    for n in rng.choice(["r10", "r11", "r12", "r13"], size=int(rng.integers(0, 3)), replace=False):
        spec[str(n)] = float(rng.choice([1e3, 2.2e3, 4.7e3, 10e3]))
    return spec


def wide_spec(rng, divider_series=("E24", "E48", "E96", "E192")) -> dict:
    """A wide specification, as an audit would draw it: every tolerance, zener, op-amp figure and limit varied,
    each divider resistor on one of ``divider_series`` over half a decade to three decades, a third of them with
    one pin."""
    i_no = float(10 ** rng.uniform(-1.3, 1))
    sp = dict(i_no_trip=i_no, i_must_trip=i_no * float(rng.uniform(1.3, 4)), min_margin=float(rng.choice([0.0, 0.02, 0.05])),
              resistor_tolerance=float(rng.choice([0.001, 0.005, 0.01, 0.02])),
              r7_tolerance=float(rng.choice([0.01, 0.02, 0.05])), zener_voltage=float(rng.uniform(3.3, 30)),
              zener_tolerance=float(rng.choice([0.02, 0.05])), zener_tc=float(rng.uniform(0, 0.02)),
              temp_span=float(rng.uniform(20, 80)), offset=float(rng.uniform(0, 0.01)),
              input_bias=float(10 ** rng.uniform(-8, -5.3)), input_offset_current=float(10 ** rng.uniform(-9, -5.3)),
              divider_current_max=float(10 ** rng.uniform(-3.3, -1.5)), input_headroom=float(rng.uniform(0.5, 2.5)),
              r7_series=str(rng.choice(["E24", "E96"])))
    for n in ("r9", "r10", "r11", "r12", "r13"):
        low = float(10 ** rng.uniform(1, 4))
        sp.update({f"{n}_series": str(rng.choice(list(divider_series))), f"{n}_min": low,
                   f"{n}_max": low * float(10 ** rng.uniform(0.5, 3))})
    if rng.uniform() < 0.3:
        sp[str(rng.choice(["r9", "r10", "r11", "r12", "r13"]))] = float(np.round(10 ** rng.uniform(2, 5), -1))
    return sp
