"""Speed of FourBar.motion (positions and both analogs) against pylinkage, and of one
widget update (compute + redraw with Agg).

Run with `make bench` (it installs pylinkage and numba into the venv for this script
only; they are not part of environment.txt). Goals (benchmarks/README.md):
≥ 200× faster than pylinkage's Linkage.step() and ≥ 3× faster than its numba
step_fast() at 360,000 crank positions; one widget update ≤ 16 ms. The same four-bar built from its
structure (ml.Linkage: a crank and an RRR dyad) is timed beside the closed form, with the ratio.
"""

from __future__ import annotations

import contextlib
import itertools
import math
import sys
import time

import matplotlib

matplotlib.use("Agg")
import numpy as np

from mechlab import Crank, FourBar, Linkage, geometry

CRANK, COUPLER, ROCKER, GROUND = 1.0, 3.0, 3.0, 4.0


@contextlib.contextmanager
def single_thread():
    """mechlab's long calls on one thread only."""
    threads, geometry.THREADS = geometry.THREADS, 1
    try:
        yield
    finally:
        geometry.THREADS = threads


def best_of(fn, repeat=9):
    """Best wall time of ``repeat`` calls (seconds) and the last result."""
    best, out = math.inf, None
    for _ in range(repeat):
        t0 = time.perf_counter()
        out = fn()
        best = min(best, time.perf_counter() - t0)
    return best, out


def pylinkage_fourbar(n):
    """The same four-bar in pylinkage; its crank turns 2π/n per step, starting at φ = 2π/n."""
    from pylinkage.actuators import Crank
    from pylinkage.components import Ground
    from pylinkage.dyads import RRRDyad
    from pylinkage.simulation import Linkage

    O = Ground(0.0, 0.0, name="O")
    E = Ground(GROUND, 0.0, name="E")
    crank = Crank(anchor=O, radius=CRANK, angular_velocity=2 * math.pi / n, name="A")
    # pylinkage's RRRDyad picks the branch nearest its current position: start B above the frame line
    B = RRRDyad(crank.output, E, distance1=COUPLER, distance2=ROCKER, name="B")
    B.x, B.y = 2.5, 2.5  # approximately the kc = +1 position at φ = 0
    return Linkage([O, E, crank, B], name="four-bar"), crank, B


def main():
    fb = FourBar(CRANK, COUPLER, ROCKER, GROUND)
    built = Linkage({"O": (0.0, 0.0), "E": (GROUND, 0.0)}, Crank("O", "A", CRANK)).rrr("A", "E", "B", COUPLER, ROCKER)
    rows = []
    try:
        import pylinkage  # noqa: F401
        have_pylinkage = True
    except ImportError:
        have_pylinkage = False
        print("pylinkage is not installed: `make bench` installs it; timing mechlab alone", file=sys.stderr)

    for n in (3_600, 360_000):
        phi = np.arange(1, n + 1) * (2 * math.pi / n)
        t_ml, mo = best_of(lambda phi=phi: fb.motion(phi))
        with single_thread():
            t_one, _ = best_of(lambda phi=phi: fb.motion(phi))
        # the joints' analogs are built when first read: time them too, for an honest total
        def with_point_analogs(phi=phi):
            m = fb.motion(phi)
            return [(m.points[k].d, m.points[k].dd) for k in "AB"]
        t_all, _ = best_of(with_point_analogs)
        t_built, mo_built = best_of(lambda phi=phi: built.motion(phi))
        err_built = max(np.abs(mo_built.psi - mo.psi).max(), np.abs(mo_built.ddpsi - mo.ddpsi).max())
        row = {"n": n, "mechlab": t_ml, "one_thread": t_one, "with_point_analogs": t_all, "built": t_built,
               "err_built": err_built}
        if have_pylinkage:
            link, _crank, B = pylinkage_fourbar(n)
            link.compile()
            link.step_fast(iterations=2)  # numba compilation, outside the timing
            link, _crank, B = pylinkage_fourbar(n)
            t_fast, traj = best_of(lambda link=link, n=n: link.step_fast(iterations=n), repeat=3)
            idx = list(link.components).index(B)
            err_fast = np.nanmax(np.abs(traj[:, idx, :] - mo.points["B"].p))

            def slow(n=n):
                lk, _, _b = pylinkage_fourbar(n)
                return np.array([pos[3] for pos in lk.step(iterations=n)])
            t_slow, pts = best_of(slow, repeat=1 if n > 10_000 else 3)
            err_slow = np.nanmax(np.abs(pts - mo.points["B"].p))
            row.update(step=t_slow, step_fast=t_fast, err_step=err_slow, err_fast=err_fast)
        rows.append(row)

    print(f"FourBar({CRANK:g}, {COUPLER:g}, {ROCKER:g}, {GROUND:g}): motion(phi) = positions + ψ, ψ', ψ''")
    print(f"mechlab with {geometry.THREADS} thread(s); [one thread; with A', A'', B', B'' read as well]")
    for r in rows:
        line = (f"n = {r['n']:>7,d}: mechlab {1e3 * r['mechlab']:6.2f} ms [{1e3 * r['one_thread']:6.2f}; "
                f"{1e3 * r['with_point_analogs']:6.2f}] | built from its structure {1e3 * r['built']:6.2f} ms "
                f"({r['built'] / r['mechlab']:.1f}× the closed form; max |Δψ|, |Δψ''| {r['err_built']:.1e})")
        if "step" in r:
            line += (f" | pylinkage step() {1e3 * r['step']:9.1f} ms ({r['step'] / r['mechlab']:6.0f}×; "
                     f"built: {r['step'] / r['built']:6.0f}×)"
                     f" | step_fast() {1e3 * r['step_fast']:7.2f} ms ({r['step_fast'] / r['mechlab']:5.1f}×)"
                     f" | max |ΔB| {max(r['err_step'], r['err_fast']):.1e}")
        print(line)

    # one widget update: new dimensions → motion over the cycle → artists moved → Agg redraw
    from mechlab.widgets import fourbar_explorer
    ex = fourbar_explorer(live=True)  # as under ipympl: its own (here Agg) canvas, blitting the crank
    ex.fig.canvas.draw()
    lengths = np.linspace(2.9, 3.1, 40)

    dims_step, angle_step = itertools.count(1), itertools.count(1)  # each update sets a new value

    def dims_update():
        ex.sliders["coupler"].value = float(lengths[next(dims_step) % len(lengths)])  # recompute, move artists, draw

    def angle_update():
        ex.angle.value = float(next(angle_step) % 360)
    t_dims, _ = best_of(lambda: [dims_update() for _ in range(20)], repeat=3)
    t_angle, _ = best_of(lambda: [angle_update() for _ in range(20)], repeat=3)
    print(f"widget update (Agg, {ex.fig.get_size_inches()[0]:.0f}×{ex.fig.get_size_inches()[1]:.0f} in at "
          f"{ex.fig.dpi:.0f} dpi): new length {1e3 * t_dims / 20:.1f} ms, crank angle {1e3 * t_angle / 20:.1f} ms")


if __name__ == "__main__":
    main()
