"""An explorer for chapters 01-03: a linkage and its curved-slot twin side by side, the
pin's relative path in the output link's frame, and ψ′, ψ″ against the base mechanism.

Sliders (mm and degrees) build the linkage; the twin, the relative path and the
base law are recomputed once per change; the crank-angle slider only moves artists.
A geometry that cannot be built (or whose crank cannot turn) shows its
:class:`~mechlab.errors.MechanismError` message instead of the plots.
"""

from __future__ import annotations

from typing import Callable

import ipywidgets as W
import matplotlib
import numpy as np
from IPython.display import display

from ..draw import drawing_class
from ..draw.curved_slot import SLOT_STYLE
from ..analysis.equivalence import base_law, equivalent_slot, law_difference, relative_path
from ..errors import MechanismError
from ..analysis.half_turn import limit_theorem
from ..mechanisms.fourbar import FourBar
from ..mechanisms.slider_crank import SliderCrank
from . import Control


class EquivalenceExplorer:
    """``factory(**values)`` → linkage; shows it, its twin, the relative path and the analogs."""

    def __init__(self, factory: Callable, controls: dict[str, Control], *, assembly: bool = True, n: int = 181):
        self.factory, self.controls, self.n = factory, controls, n
        self.mechanism = self.twin = self.motion = None
        self.message = ""
        self.limit = None
        self.error = None
        self.sliders = {k: W.FloatSlider(value=c.value, min=c.min, max=c.max, step=c.step,
                                         description=f"{c.label} ({c.unit})" if c.unit else c.label,
                                         style={"description_width": "110px"}, layout=W.Layout(width="360px"))
                        for k, c in controls.items()}
        if assembly:
            self.sliders["assembly"] = W.ToggleButtons(options=[("kc = +1", 1), ("kc = -1", -1)], value=1,
                                                       description="assembly")
        self.angle = W.FloatSlider(value=30.0, min=0.0, max=360.0, step=2.0, description="crank φ (deg)",
                                   style={"description_width": "110px"}, layout=W.Layout(width="360px"))
        self.play = W.Play(value=30, min=0, max=358, step=6, interval=120, description="play")
        W.jslink((self.play, "value"), (self.angle, "value"))
        self.status = W.HTML()
        self.fig = matplotlib.figure.Figure(figsize=(10, 6), dpi=60)
        grid = self.fig.add_gridspec(2, 3, height_ratios=[1.2, 1])
        self.ax_link, self.ax_twin, self.ax_rel = (self.fig.add_subplot(grid[0, j]) for j in range(3))
        self.ax_d0, self.ax_d1, self.ax_d2 = (self.fig.add_subplot(grid[1, j]) for j in range(3))
        self.output = W.Output()
        for w in self.sliders.values():
            w.observe(lambda ch: self.rebuild(), names="value")
        self.angle.observe(lambda ch: self._frame(), names="value")
        self.widget = W.VBox([W.HBox([W.VBox(list(self.sliders.values())), W.VBox([self.angle, self.play, self.status])]),
                              self.output])
        self.rebuild()

    def values(self) -> dict:
        out = {}
        for k, w in self.sliders.items():
            c = self.controls.get(k)
            out[k] = np.radians(w.value) if c is not None and c.unit == "deg" else w.value
        return out

    def rebuild(self):
        try:
            mech = self.factory(**self.values())
            phi = mech.turn(self.n)
            twin = equivalent_slot(mech)
            mo, tm = mech.motion(phi), twin.motion(phi)
            rel = relative_path(mech, phi)
            base = base_law(mech, phi)
            self.limit = limit_theorem(mech, 361)
        except MechanismError as err:
            self.mechanism = self.motion = None
            self.message = str(err)
            self.status.value = f"<span style='color:#b00020'>{err}</span>"
            self._show()
            return
        self.message = ""
        self.mechanism, self.twin, self.motion, self.twin_motion = mech, twin, mo, tm
        self.error = max(law_difference(mo, tm))
        for ax in (self.ax_link, self.ax_twin, self.ax_rel, self.ax_d0, self.ax_d1, self.ax_d2):
            ax.clear()
        self.d_link = drawing_class(mech)(self.ax_link, mech, trace="A", n=self.n)
        self.d_link.set_motion(mech, mo)
        self.d_twin = drawing_class(twin)(self.ax_twin, twin, trace="A", n=self.n)
        self.d_twin.set_motion(twin, tm)
        for d, title in ((self.d_link, type(mech).__name__), (self.d_twin, "curved-slot twin")):
            d.autoscale()
            d.ax.set_title(title, fontsize=10)
        self.ax_rel.set_aspect("equal")
        slot = twin.slot_mechanism.slot
        if slot.periodic:
            self.ax_rel.plot(*slot.points(np.linspace(slot.t0, slot.t1, 300)).T, color="0.6", lw=0.8, ls="--")
        self.ax_rel.plot(*twin.slot_samples(200).T, **SLOT_STYLE)
        self.ax_rel.plot(*rel.p.T, color="#d62728", lw=1)
        self.ax_rel.plot([0], [0], "^", color="#555555", ms=9)
        (self.rel_pin,) = self.ax_rel.plot([], [], "o", mfc="white", mec="#1f4e79", ms=7)
        self.rel = rel.p
        self.ax_rel.set_title("pin in the output link's frame", fontsize=10)
        deg = np.degrees(phi)
        angular = mech.output == "angle"
        d0, d1, d2 = mo.output.value, mo.output.d, mo.output.dd
        k0 = base.theta
        if angular:   # continuous angles, the base law on the linkage's branch
            d0, k0 = np.unwrap(d0), np.unwrap(k0)
            k0 = k0 + 2 * np.pi * np.round((d0[0] - k0[0]) / (2 * np.pi))
        sym = "ψ" if angular else "s"
        for ax, y, yk, name in ((self.ax_d0, d0, k0, ""), (self.ax_d1, d1, base.d, "′"), (self.ax_d2, d2, base.dd, "″")):
            ax.plot(deg, y, label=sym + name)
            ax.plot(deg, yk, "--", label="base " + ("ψ_K" if angular else "x_K") + name)
            ax.grid(True, alpha=0.3)
            ax.legend(fontsize=7, loc="upper right")
            ax.set_xlabel("φ, degrees")
        self.law = (d0, d1, d2)
        (self.m0,) = self.ax_d0.plot([], [], "ko", ms=4)
        (self.m1,) = self.ax_d1.plot([], [], "ko", ms=4)
        (self.m2,) = self.ax_d2.plot([], [], "ko", ms=4)
        lim = self.limit
        lam = f"λ = l_OA/l_OE = {mech.crank / mech.ground:.3f} · " if angular else ""
        self.status.value = lam + (f"twin error {self.error:.1e} · peak |{'ψ' if angular else 's'}′| {lim.peak_velocity:.4f} ≥ "
                             f"base {lim.base_peak_velocity:.4f} · peak |″| {lim.peak_acceleration:.4f} ≥ "
                             f"base {lim.base_peak_acceleration:.4f}")
        self._frame()

    def _frame(self):
        if self.motion is None:
            return
        phi = np.degrees(self.motion.phi)
        i = int(np.argmin(np.abs((phi - self.angle.value + 180.0) % 360.0 - 180.0)))
        self.d_link.set_frame(i)
        self.d_twin.set_frame(i)
        self.rel_pin.set_data([self.rel[i, 0]], [self.rel[i, 1]])
        for marker, y in zip((self.m0, self.m1, self.m2), self.law):
            marker.set_data([phi[i]], [y[i]])
        self._show()

    def _show(self):
        with self.output:
            self.output.clear_output(wait=True)
            if self.motion is None:
                print(self.message)
            else:
                display(self.fig)

    def _ipython_display_(self):
        display(self.widget)


def fourbar_equivalence(crank=0.3, coupler=0.8, rocker=1.0, ground=1.0, max_length=3.0):
    """Four-bar (seed 000's example by default) and its circular-slot twin."""
    def ctl(label, v):
        return Control(label, 0.05, max_length, 0.01, v, "mm")
    return EquivalenceExplorer(FourBar, {"crank": ctl("crank OA", crank), "coupler": ctl("coupler AB", coupler),
                                         "rocker": ctl("rocker BE", rocker), "ground": ctl("ground OE", ground)})


def slider_crank_equivalence(crank=1.0, rod=3.0, offset=0.5):
    """Offset slider-crank and its translating circular-slot twin."""
    return EquivalenceExplorer(SliderCrank, {"crank": Control("crank OA", 0.1, 3.0, 0.05, crank, "mm"),
                                             "rod": Control("rod AB", 0.5, 6.0, 0.05, rod, "mm"),
                                             "offset": Control("offset e", -2.0, 2.0, 0.05, offset, "mm")})
