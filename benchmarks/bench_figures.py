"""What the larger figures cost: an explorer's crank-angle move in the kernel, and an animation's frames.

For every explorer of the course, the median time of one crank-angle step (the slider moved by
its step) in the kernel, wall-clock and process (CPU) time (the latter barely blurred by other
processes sharing the machine), two ways: live (an ipympl canvas, the moving artists blitted over the
saved background and sent as a PNG diff: what JupyterLab gets) and inline (the whole figure
rendered and encoded as a PNG, as the inline backend re-shows it in an Output widget: what
JupyterLab got before). Then, for an animation of the four-bar, the width of its frames, the
bytes per frame in the page and the time to render and encode a frame. The browser's side (the
key press travelling to the kernel, the image to the page) is timed by tests_browser/test_lab.py.

Run: ``PYTHONPATH=. .venv/bin/python benchmarks/bench_figures.py``.
"""

from __future__ import annotations

import contextlib
import io
import statistics
import time

import matplotlib

matplotlib.use("Agg")

from mechlab import FourBar
from mechlab.draw import animate, frame_dpi
from mechlab.widgets import fourbar_explorer
from mechlab.widgets.centres import fourbar_centrode_explorer
from mechlab.widgets.chebyshev import mchv1_explorer
from mechlab.widgets.dwell import dwell_explorer
from mechlab.widgets.equivalence import fourbar_equivalence
from mechlab.widgets.forces import press_explorer
from mechlab.widgets.geneva import planar_geneva_explorer, spherical_geneva_explorer

EXPLORERS = (fourbar_explorer, fourbar_equivalence, fourbar_centrode_explorer, dwell_explorer, mchv1_explorer,
             planar_geneva_explorer, spherical_geneva_explorer, press_explorer)
STEPS = 30


def crank_steps_ms(make, live: bool) -> tuple[float, float, float]:
    """Medians of one crank-angle step: (wall ms, CPU ms, KiB sent); live blitting (the PNG
    diff the canvas sends), or the inline figure's PNG."""
    with contextlib.redirect_stdout(io.StringIO()):   # outside a kernel, the Output widget prints a repr
        ex = make(live=live)
    sent = [0]
    if live:
        # as with JupyterLab connected: the canvas sends its diffs and stops keeping a PNG copy of itself
        ex.fig.canvas.syncing_data_url = False
        ex.fig.canvas.send_binary = lambda data: sent.append(len(data))
        ex.fig.canvas.draw()   # the first full drawing saves the background
    wall, cpu, size = [], [], []
    for _ in range(STEPS):
        start, start_cpu = time.perf_counter(), time.process_time()
        with contextlib.redirect_stdout(io.StringIO()):   # outside a kernel, the Output widget prints a repr
            ex.angle.value = (ex.angle.value + ex.angle.step) % 360.0
        if not live:   # what the inline backend does to re-show the figure
            png = io.BytesIO()
            ex.fig.savefig(png, format="png", bbox_inches="tight")
            sent.append(len(png.getvalue()))
        wall.append(time.perf_counter() - start)
        cpu.append(time.process_time() - start_cpu)
        size.append(sent[-1])
    return 1000 * statistics.median(wall), 1000 * statistics.median(cpu), statistics.median(size) / 1024


def animation_figures(n: int = 24) -> tuple[int, float, float]:
    """(frame width px, bytes per frame in the page, ms to render and encode a frame)."""
    anim = animate(FourBar(1, 3, 3, 4), n=n, trace="B")
    start = time.perf_counter()
    html = anim.to_jshtml()
    per_frame = 1000 * (time.perf_counter() - start) / n
    width = round(anim._fig.get_figwidth() * frame_dpi(anim._fig))
    return width, len(html.encode()) / n, per_frame


def main():
    print(f"{'explorer':28s} {'live: wall ms':>13s} {'CPU ms':>7s} {'KiB':>5s}   {'inline: wall ms':>15s} "
          f"{'CPU ms':>7s}")
    for make in EXPLORERS:
        (lw, lc, lk), (iw, ic, _) = crank_steps_ms(make, True), crank_steps_ms(make, False)
        print(f"{make.__name__:28s} {lw:13.1f} {lc:7.1f} {lk:5.1f}   {iw:15.1f} {ic:7.1f}")
    width, size, ms = animation_figures()
    print(f"animation: frames {width} px wide, {size / 1024:.1f} KiB per frame in the page, {ms:.0f} ms per frame")


if __name__ == "__main__":
    main()
