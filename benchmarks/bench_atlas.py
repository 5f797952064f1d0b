"""The coupler-curve atlas: designs screened per second, how the build's cost grows with the grid, the local
process pool against a local Dask cluster, the shipped file's size and load time, and a query's time.

Run: ``python benchmarks/bench_atlas.py`` (the full grid is built once per route: several minutes on two
cores); ``--quick`` skips the full grid.
"""

import os
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

from mechlab.synthesis import atlas as A


def timed(f):
    t = time.perf_counter()
    out = f()
    return out, time.perf_counter() - t


def cpu_timed(f):
    """(result, wall s, CPU s of this process and of the worker processes it reaped)."""
    before = os.times()
    out, wall = timed(f)
    after = os.times()
    cpu = sum(getattr(after, k) - getattr(before, k) for k in ("user", "system", "children_user", "children_system"))
    return out, wall, cpu


def grid(step: int) -> dict:
    """Every ``step``-th coupler point in u and in v: the grid's size grows as 1/step²."""
    return {"u": A.U[::step], "v": A.V[::step]}


def main(quick: bool = False) -> None:
    cores = os.cpu_count()
    print(f"{cores} cores; chunks of {A.CHUNK} designs; {A.SAMPLES} crank angles per curve, "
          f"{len(A.ARC_WIDTHS)} arc and {len(A.RUN_WIDTHS)} run widths")
    # the wall time depends on what else the machine runs; the CPU time (this process and its pool's workers)
    # gives the designs per CPU-second whatever the load
    print(f"{'grid':>10s} {'designs':>8s} {'route':>22s} {'time (s)':>9s} {'designs/s':>10s} {'CPU s':>7s} "
          f"{'per CPU-s':>9s}")
    steps = (8, 4, 2) if quick else (8, 4, 2, 1)
    for step in steps:
        g = grid(step)
        routes = {f"{cores} processes": {}}
        if step > 1:  # one process on the whole grid only repeats the largest size's figure, at twice the time
            routes = {"1 process": {"workers": 1}, **routes}
        for name, kw in routes.items():
            atlas, dt, cpu = cpu_timed(lambda g=g, kw=kw: A.build_atlas(**g, **kw))
            print(f"{'1/' + str(step * step):>10s} {len(atlas):8d} {name:>22s} {dt:9.1f} {len(atlas) / dt:10.0f} "
                  f"{cpu:7.1f} {len(atlas) / cpu:9.0f}")
    from dask.distributed import Client, LocalCluster
    with LocalCluster(n_workers=cores, threads_per_worker=1, processes=True, dashboard_address=None) as cluster, \
            Client(cluster) as client:
        for step in steps[-2:]:
            g = grid(step)
            atlas, dt = timed(lambda g=g: A.build_atlas(**g, client=client))
            print(f"{'1/' + str(step * step):>10s} {len(atlas):8d} {'Dask, ' + str(cores) + ' workers':>22s} "
                  f"{dt:9.1f} {len(atlas) / dt:10.0f}")
    size = A.DATA.stat().st_size / 1e6
    A._load.cache_clear()
    atlas, dt = timed(A.load_atlas)
    print(f"shipped atlas: {len(atlas)} designs, {size:.2f} MB, loaded in {dt:.3f} s")
    with tempfile.TemporaryDirectory() as tmp:
        raw = Path(tmp) / "raw.npz"
        np.savez(raw, **atlas.columns)
        print(f"  uncompressed columns: {raw.stat().st_size / 1e6:.2f} MB")
    for args, kw in (((np.radians(120), 0.002), {"transmission": np.radians(40), "size": 8.0}),
                     ((np.radians(60), 0.0005), {}), ((np.radians(90), 0.003), {"kind": "run"})):
        best = min(timed(lambda a=args, k=kw: atlas.query(*a, **k))[1] for _ in range(5))
        found = atlas.query(*args, **kw)
        print(f"query dwell {np.degrees(args[0]):.0f}°, ripple {args[1]:g}, {kw}: {len(found)} designs, "
              f"best of 5 {best * 1e3:.1f} ms")


if __name__ == "__main__":
    main(quick="--quick" in sys.argv)
