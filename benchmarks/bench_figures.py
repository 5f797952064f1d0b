"""What the larger figures cost: an explorer's crank-angle move in the kernel, and an animation's frames.

For every explorer of the course, the median time of one crank-angle step (the slider moved by
its step) in the kernel, two ways: live (an ipympl canvas, the moving artists blitted over the
saved background and sent as a PNG diff: what JupyterLab gets) and inline (the whole figure
rendered and encoded as a PNG, as the inline backend re-shows it in an Output widget: what
JupyterLab got before). Then, for an animation of the four-bar, the width of its frames, the
bytes per frame in the page and the time to render and encode a frame. The browser's side (the
key press travelling to the kernel, the image to the page) is timed by tests_browser/test_lab.py.

Run: ``PYTHONPATH=. .venv/bin/python benchmarks/bench_figures.py``.
"""

from __future__ import annotations

import io
import statistics
import time

import matplotlib

matplotlib.use("Agg")

from mechlab import FourBar  # noqa: E402
from mechlab.draw import animate, frame_dpi  # noqa: E402
from mechlab.widgets import fourbar_explorer  # noqa: E402
from mechlab.widgets.centres import fourbar_centrode_explorer  # noqa: E402
from mechlab.widgets.chebyshev import mchv1_explorer  # noqa: E402
from mechlab.widgets.dwell import dwell_explorer  # noqa: E402
from mechlab.widgets.equivalence import fourbar_equivalence  # noqa: E402
from mechlab.widgets.forces import press_explorer  # noqa: E402
from mechlab.widgets.geneva import planar_geneva_explorer, spherical_geneva_explorer  # noqa: E402

EXPLORERS = (fourbar_explorer, fourbar_equivalence, fourbar_centrode_explorer, dwell_explorer, mchv1_explorer,
             planar_geneva_explorer, spherical_geneva_explorer, press_explorer)
STEPS = 30


def crank_steps_ms(make, live: bool) -> float:
    """Median milliseconds of one crank-angle step: live blitting, or the inline figure's PNG."""
    ex = make(live=live)
    if live:
        # as with JupyterLab connected: the canvas sends its diffs and stops keeping a PNG copy of itself
        ex.fig.canvas.syncing_data_url = False
        ex.fig.canvas.draw()   # the first full drawing saves the background
    times = []
    for _ in range(STEPS):
        start = time.perf_counter()
        ex.angle.value = (ex.angle.value + ex.angle.step) % 360.0
        if not live:   # what the inline backend does to re-show the figure
            ex.fig.savefig(io.BytesIO(), format="png", bbox_inches="tight")
        times.append(time.perf_counter() - start)
    return 1000 * statistics.median(times)


def animation_figures(n: int = 24) -> tuple[int, float, float]:
    """(frame width px, bytes per frame in the page, ms to render and encode a frame)."""
    anim = animate(FourBar(1, 3, 3, 4), n=n, trace="B")
    start = time.perf_counter()
    html = anim.to_jshtml()
    per_frame = 1000 * (time.perf_counter() - start) / n
    width = round(anim._fig.get_figwidth() * frame_dpi(anim._fig))
    return width, len(html.encode()) / n, per_frame


def main():
    print(f"{'explorer':32s} {'live (ms)':>10s} {'inline (ms)':>12s}")
    for make in EXPLORERS:
        print(f"{make.__name__:32s} {crank_steps_ms(make, True):10.1f} {crank_steps_ms(make, False):12.1f}")
    width, size, ms = animation_figures()
    print(f"animation: frames {width} px wide, {size / 1024:.1f} KiB per frame in the page, {ms:.0f} ms per frame")


if __name__ == "__main__":
    main()
