"""What a drag costs in the kernel: one mouse move on the drag editor's canvas → the redrawn frame sent.

The editor (mechlab.widgets.drag.DragEditor) of the four-bar with a coupler point, on an ipympl canvas off
screen, receives the messages JupyterLab's ipympl sends while a joint is dragged (``button_press``, then
``motion_notify`` for each step, ``button_release``), through the canvas manager's ``handle_json`` as in a
kernel. Each step is timed from the message's arrival to the return of its handler, which has rebuilt the
linkage, its coupler curve over 361 crank angles, its instantaneous centres and transmission angle, blitted the
moving artists and encoded and "sent" the PNG diff (``send_binary`` records its size). A step that needs the
whole figure redrawn (the view grew, or an error replaces the drawing) asks the browser for a draw
(``draw_idle``); the browser's answer, a ``draw`` message, is handled at once and counted in that step.

Three drags: the coupler joint B (two lengths), the coupler point P (ξ, η) and the frame pivot E (every joint
moves; the last steps cannot assemble, so the error and the recovery are timed too). Medians of wall-clock
and process (CPU) time, the largest step, and the KiB sent per step. The browser's side is timed by
tests_browser/test_drag_lab.py.

Run: ``PYTHONPATH=. .venv/bin/python benchmarks/bench_drag.py``.
"""

from __future__ import annotations

import statistics
import time

import matplotlib

matplotlib.use("Agg")

import numpy as np

import mechlab as ml
from mechlab.widgets.drag import DragEditor

STEPS = 40


def editor() -> DragEditor:
    lk = (ml.Linkage({"O": (0, 0), "E": (4, 0)}, ml.Crank("O", "A", 1.0))
          .rrr("A", "E", "B", 3.0, 3.0, links=("coupler", "rocker")).point("P", "coupler", (1.5, 0.8)))
    ed = DragEditor(lk, phi=np.radians(180), live=True)
    canvas = ed.fig.canvas
    canvas.syncing_data_url = False   # as with JupyterLab connected: diffs, no data URL kept
    return ed


def drag(ed: DragEditor, joint: str, path) -> dict:
    """Drag ``joint`` along ``path`` (data points) with the browser's messages; the steps' times."""
    canvas = ed.fig.canvas
    sent, asked = [], []
    canvas.send_binary = lambda data: sent.append(len(data))
    send_event = canvas.send_event
    canvas.send_event = lambda kind, **kw: asked.append(kind) if kind == "draw" else send_event(kind, **kw)
    canvas.manager.handle_json({"type": "draw"})   # the first full drawing saves the background
    height = canvas.get_renderer().height

    def message(kind, xy, buttons):
        x, y = ed.ax.transData.transform(xy)
        # as ipympl's browser side sends it: pixels from the top left
        canvas.manager.handle_json({"type": kind, "x": float(x), "y": float(height - y), "button": 0,
                                    "buttons": buttons, "modifiers": [], "guiEvent": {}})

    message("button_press", ed._positions()[joint], 1)
    assert ed._drag is not None and ed._drag[0] == joint, "the press did not grab the handle"
    wall, cpu, kib, full = [], [], [], 0
    for xy in path:
        sent.clear()
        asked.clear()
        start, start_cpu = time.perf_counter(), time.process_time()
        message("motion_notify", xy, 1)
        if asked:   # the browser answers draw_idle with a draw request
            full += 1
            canvas.manager.handle_json({"type": "draw"})
        wall.append(1e3 * (time.perf_counter() - start))
        cpu.append(1e3 * (time.process_time() - start_cpu))
        kib.append(sum(sent) / 1024)
    message("button_release", path[-1], 0)
    canvas.send_event = send_event
    return {"median_ms": statistics.median(wall), "cpu_ms": statistics.median(cpu), "max_ms": max(wall),
            "kib": statistics.median(kib), "full": full, "errors": ed.message}


def main():
    rows = []
    ed = editor()
    B = ed._positions()["B"]
    rows.append(("B (coupler, rocker lengths)",
                 drag(ed, "B", [B + 0.02 * k * np.array([1.0, 0.6]) for k in range(1, STEPS + 1)])))
    ed = editor()
    P = ed._positions()["P"]
    rows.append(("P (ξ, η on the coupler)",
                 drag(ed, "P", [P + 0.02 * k * np.array([-0.5, 1.0]) for k in range(1, STEPS + 1)])))
    ed = editor()
    E = ed._positions()["E"]
    # to x = 5.1: |AE| > 3 + 3 at φ = 180° from x = 5 on: the last steps show the error, then the way back
    out = [E + [1.1 * k / STEPS, 0.0] for k in range(1, STEPS + 1)]
    rows.append(("E (frame pivot; out of assembly and back)", drag(ed, "E", out + out[::-1][:10])))
    print(f"{'drag':45s} {'median ms':>10s} {'CPU ms':>7s} {'max ms':>7s} {'KiB/step':>9s} {'full':>5s}")
    for name, r in rows:
        print(f"{name:45s} {r['median_ms']:10.1f} {r['cpu_ms']:7.1f} {r['max_ms']:7.1f} {r['kib']:9.1f} "
              f"{r['full']:5d}")
    every = [r["median_ms"] for _, r in rows]
    print(f"median of the drags' medians: {statistics.median(every):.1f} ms "
          f"(goal: drag event → redrawn figure ≤ 50 ms)")


if __name__ == "__main__":
    main()
