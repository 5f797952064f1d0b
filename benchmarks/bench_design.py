"""Speed goal: ``mechlab.design.candidates(spec)`` for one specification, all families, under 2 s on a
2-core machine, so that the choosing explorer stays interactive. Prints the best of five per motion
kind and the share of each family's synthesis and evaluation (what dominates).

Run: ``make bench`` (or ``python benchmarks/bench_design.py``).
"""

import time

import numpy as np

from mechlab import design as D
from mechlab.design.criteria import evaluate

SPECS = {
    "index (6 stations, dwell 2/3)": D.Specification("index", 2 / 3, stations=6, inertia=2.4, rpm=40),
    "swing (40°, dwell 40°)": D.Specification("swing", 40 / 360, amplitude=np.radians(40),
                                              max_pressure_angle=np.radians(60), inertia=0.2),
    "stroke (120 mm, dwell 1/3)": D.Specification("stroke", 1 / 3, amplitude=120.0, mass=6.0,
                                                  max_pressure_angle=np.radians(60)),
}


def best(f, repeat=5):
    times = []
    for _ in range(repeat):
        t = time.perf_counter()
        f()
        times.append(time.perf_counter() - t)
    return min(times)


def main():
    print(f"{'specification':32s} {'candidates(spec)':>17s}   per family: synthesis + evaluation (s)")
    for name, spec in SPECS.items():
        total = best(lambda spec=spec: D.candidates(spec))
        parts = []
        for family, designer in D.FAMILIES.items():
            t0 = time.perf_counter()
            try:
                d = designer(spec)
            except (D.Unsuitable, Exception):
                parts.append((time.perf_counter() - t0, 0.0, family))
                continue
            t1 = time.perf_counter()
            evaluate(d.mechanism, spec, scale=d.scale, structure=d.structure, circles=d.circles,
                     pressure_angle=d.pressure_angle, phase=d.phase)
            parts.append((t1 - t0, time.perf_counter() - t1, family))
        heavy = ", ".join(f"{f} {s:.2f}+{e:.2f}" for s, e, f in sorted(parts, key=lambda p: -(p[0] + p[1]))[:3])
        print(f"{name:32s} {total:15.2f} s   {heavy}")


if __name__ == "__main__":
    main()
