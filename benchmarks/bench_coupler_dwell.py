"""Speed of the coupler-curve arc and run search (mechlab.synthesis.coupler_dwell), which the chapter on coupler
curve dwells calls live while a student drags a joint.

Goal: `coupler_arcs(linkage, dwell=…)` at n = 720 samples ≤ 30 ms (the drag editor's budget is 50 ms for the
whole redraw); the longest-arc search (`dwell=None`) well under a second. Timed on the course's example
crank-rocker (wall and CPU time, best of 7) and on 20 random crank-rockers (wall, best of 3 each; median and
maximum over the designs). Measured 2026-12-02 on the shared 2-core VM at load 8-11: arcs with a 90° dwell
14 ms CPU (19-30 ms wall), runs 11 ms CPU, the longest arcs 66 ms CPU (150-230 ms wall).

Run: `python benchmarks/bench_coupler_dwell.py` (PYTHONPATH at the repository for a worktree).
"""

from __future__ import annotations

import math
import time

import numpy as np

import mechlab as ml


def best_of(fn, repeat=7, clock=time.perf_counter):
    """Best time of ``repeat`` calls (seconds) on ``clock``."""
    best = math.inf
    for _ in range(repeat):
        t0 = clock()
        fn()
        best = min(best, clock() - t0)
    return best


def random_crank_rockers(count, seed=0):
    """Crank-rockers with the crank 1 and a coupler point near the coupler."""
    rng = np.random.default_rng(seed)
    out = []
    while len(out) < count:
        c, r, f = rng.uniform(1.5, 5.0, 3)
        if 1 + max(c, r, f) < sum(sorted((c, r, f))[:2]) - 0.2:
            out.append(ml.coupler_fourbar(1.0, c, r, f, (rng.uniform(-1, 2) * c, rng.uniform(-1.5, 1.5) * c)))
    return out


def main():
    example = ml.coupler_fourbar(1.0, 3.0, 3.0, 3.5, (2.0, 1.2))
    rows = [
        ("arcs, dwell 90°, n = 720", lambda lk: ml.coupler_arcs(lk, dwell=np.radians(90))),
        ("arcs, dwell 90°, n = 720, count 1", lambda lk: ml.coupler_arcs(lk, dwell=np.radians(90), count=1)),
        ("runs, dwell 90°, n = 720", lambda lk: ml.coupler_runs(lk, dwell=np.radians(90))),
        ("longest arcs (ripple ≤ 0.1 % R)", lambda lk: ml.coupler_arcs(lk)),
        ("longest runs (ripple ≤ 0.1 % length)", lambda lk: ml.coupler_runs(lk)),
    ]
    designs = random_crank_rockers(20)
    # CPU time beside wall time: the machine is shared, and the wall time grows with the others' load
    print(f"{'call':40s} {'example':>10s} {'(CPU)':>10s} {'random median':>14s} {'random max':>11s}")
    for name, call in rows:
        ex = best_of(lambda call=call: call(example))
        cpu = best_of(lambda call=call: call(example), clock=time.process_time)
        times = [best_of(lambda lk=lk, call=call: call(lk), 3) for lk in designs]
        print(f"{name:40s} {ex * 1e3:8.1f} ms {cpu * 1e3:7.1f} ms {np.median(times) * 1e3:11.1f} ms "
              f"{max(times) * 1e3:8.1f} ms")
    arc = ml.coupler_arcs(example, dwell=np.radians(90), count=1)[0]
    six = ml.arc_dwell_sixbar(example, "P", arc)
    build = best_of(lambda: ml.arc_dwell_sixbar(example, "P", arc))
    print(f"{'arc_dwell_sixbar (default pivot)':40s} {build * 1e3:8.1f} ms")
    print(f"{'check_dwell':40s} {best_of(lambda: ml.check_dwell(six, arc.crank_interval)) * 1e3:8.1f} ms")


if __name__ == "__main__":
    main()
