"""An explorer for chapters 02-04: a linkage and its curved-slot twin side by side, the
pin's relative path in the output link's frame, and ψ′, ψ″ against the base mechanism.

Sliders (dimensionless lengths, degrees) build the linkage; the twin, the relative path and the
base law are recomputed once per change; the crank-angle slider only moves artists.
A geometry that cannot be built (or whose crank cannot turn) shows its
:class:`~mechlab.errors.MechanismError` message instead of the plots.
"""

from __future__ import annotations

from collections.abc import Callable

import ipywidgets as W
import numpy as np

from ..analysis.equivalence import base_law, equivalent_slot, law_difference, relative_path
from ..analysis.half_turn import limit_theorem
from ..draw import drawing_class, fill_axes, mechanism_name
from ..draw.curved_slot import SLOT_STYLE
from ..errors import MechanismError
from ..mechanisms.fourbar import FourBar
from ..mechanisms.slider_crank import SliderCrank
from . import Control, Explorer, legend_above


class EquivalenceExplorer(Explorer):
    """``factory(**values)`` → linkage; shows it, its twin, the relative path and the analogs
    against the base mechanism's, with markers at the crank angle. A dimension change
    recomputes and redraws everything; a crank-angle move only moves artists (blitted on a
    live canvas). ``live``, ``question``: see :class:`mechlab.widgets.Explorer`."""

    def __init__(self, factory: Callable, controls: dict[str, Control], *, assembly: bool = True, n: int = 181,
                 live: bool | None = None, question: str | None = None, title: str = ""):
        super().__init__(factory, controls, n=n, title=title, live=live, question=question, figsize=(10, 6.2),
                         dpi=76, angle=30.0)
        self.mechanism = self.twin = self.motion = None
        self.limit = None
        self.error = None
        self._artists = []
        if assembly:
            self.sliders["assembly"] = W.ToggleButtons(options=[("kc = +1", 1), ("kc = -1", -1)], value=1,
                                                       description="assembly")
        self.play = self._play(interval=120)
        grid = self.fig.add_gridspec(2, 3, height_ratios=[1.2, 1], left=0.06, right=0.99, bottom=0.09,
                                     top=0.93 if title else 0.96, wspace=0.32, hspace=0.3)
        self.ax_link, self.ax_twin, self.ax_rel = (self.fig.add_subplot(grid[0, j]) for j in range(3))
        self.ax_d0, self.ax_d1, self.ax_d2 = (self.fig.add_subplot(grid[1, j]) for j in range(3))
        self._finish([self.play])

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
            self._show_error(str(err))
            return
        self.message = ""
        self.mechanism, self.twin, self.motion, self.twin_motion = mech, twin, mo, tm
        self.error = max(law_difference(mo, tm))
        for ax in self._axes():
            ax.clear()
        self.d_link = drawing_class(mech)(self.ax_link, mech, trace="A", n=self.n)
        self.d_link.set_motion(mech, mo)
        self.d_twin = drawing_class(twin)(self.ax_twin, twin, trace="A", n=self.n)
        self.d_twin.set_motion(twin, tm)
        boxes = np.array([self.d_link.bounds(), self.d_twin.bounds()])
        common = (boxes[:, 0].min(), boxes[:, 1].max(), boxes[:, 2].min(), boxes[:, 3].max())
        for d, title in ((self.d_link, mechanism_name(mech)), (self.d_twin, "its curved-slot twin")):
            fill_axes(d.ax, common)
            d.ax.set_axis_off()
            d.ax.set_title(title, fontsize=10)
        self.ax_rel.set_aspect("equal")
        slot = twin.slot_mechanism.slot
        if slot.periodic:
            self.ax_rel.plot(*slot.points(np.linspace(slot.t0, slot.t1, 300)).T, color="0.6", lw=0.8, ls="--")
        self.ax_rel.plot(*twin.slot_samples(200).T, **SLOT_STYLE)
        self.ax_rel.plot(*rel.p.T, color="#d62728", lw=1)
        self.ax_rel.plot([0], [0], "o", mfc="white", mec="#333333", ms=7)
        (self.rel_pin,) = self.ax_rel.plot([], [], "o", mfc="white", mec="#1f4e79", ms=7)
        self.rel = rel.p
        self.ax_rel.set_title("pin A in the output link's frame", fontsize=10)
        self.ax_rel.set_axis_off()
        deg = np.degrees(phi)
        angular = mech.output == "angle"
        d0, d1, d2 = mo.output.value, mo.output.d, mo.output.dd
        k0 = base.theta
        if angular:   # continuous angles in degrees, the base law on the linkage's branch
            d0, k0 = np.unwrap(d0), np.unwrap(k0)
            k0 = np.degrees(k0 + 2 * np.pi * np.round((d0[0] - k0[0]) / (2 * np.pi)))
            d0 = np.degrees(d0)
        sym, base_sym = ("ψ", "ψ_K") if angular else ("s", "x_K")
        units = ("degrees", "–", "1/rad") if angular else ("dimensionless", "1/rad", "1/rad²")
        for ax, y, yk, mark, unit in ((self.ax_d0, d0, k0, "", units[0]), (self.ax_d1, d1, base.d, "′", units[1]),
                                      (self.ax_d2, d2, base.dd, "″", units[2])):
            ax.plot(deg, y, label=sym + mark)
            ax.plot(deg, yk, "--", label="base " + base_sym + mark)
            ax.grid(True, alpha=0.3)
            legend_above(ax, fontsize=8)
            ax.set_xlabel("crank angle φ (degrees)")
            ax.set_ylabel(f"{sym}{mark} ({unit})")
            ax.set_xticks(np.arange(0, 361, 90))
        self.law = (d0, d1, d2)
        self.markers = [ax.plot([], [], "o", color="#d62728", ms=5, zorder=5)[0]
                        for ax in (self.ax_d0, self.ax_d1, self.ax_d2)]
        lim = self.limit
        lam = f"λ = l_OA/l_OE = {mech.crank / mech.ground:.3f} · " if angular else ""
        self.status.value = (f"{lam}twin error {self.error:.1e} · "
                             f"peak |{sym}′| {lim.peak_velocity:.4f} ≥ base {lim.base_peak_velocity:.4f} · "
                             f"peak |{sym}″| {lim.peak_acceleration:.4f} ≥ base {lim.base_peak_acceleration:.4f}")
        self._set_visible(True)
        self._animate_moving()
        self._select_frame()
        self._redraw()

    def _select_frame(self):
        phi = np.degrees(self.motion.phi)
        self.frame = i = self.nearest_frame(self.motion.phi)
        self.d_link.set_frame(i)
        self.d_twin.set_frame(i)
        self.rel_pin.set_data([self.rel[i, 0]], [self.rel[i, 1]])
        for marker, y in zip(self.markers, self.law, strict=False):
            marker.set_data([phi[i]], [y[i]])

    def _moving_artists(self):
        if self.motion is None:
            return []
        return [*self.d_link.artists, *self.d_twin.artists, self.rel_pin, *self.markers]

    def _axes(self):
        return (self.ax_link, self.ax_twin, self.ax_rel, self.ax_d0, self.ax_d1, self.ax_d2)

    def _forget(self):
        self.mechanism = self.motion = None

    def _ready(self) -> bool:
        return self.motion is not None


def fourbar_equivalence(crank=0.3, coupler=0.8, rocker=1.0, ground=1.0, max_length=3.0, *,
                        live: bool | None = None, question: str | None = None):
    """Four-bar (the example of Zinchenko et al., 2013, by default) and its circular-slot twin;
    lengths dimensionless."""
    def ctl(label, v):
        return Control(label, 0.05, max_length, 0.01, v)
    return EquivalenceExplorer(FourBar, {"crank": ctl("crank OA", crank), "coupler": ctl("coupler AB", coupler),
                                         "rocker": ctl("rocker BE", rocker), "ground": ctl("ground OE", ground)},
                               live=live, question=question)


def slider_crank_equivalence(crank=1.0, rod=3.0, offset=0.5, *, live: bool | None = None,
                             question: str | None = None):
    """Offset slider-crank and its translating circular-slot twin; lengths dimensionless."""
    return EquivalenceExplorer(SliderCrank, {"crank": Control("crank OA", 0.1, 3.0, 0.05, crank),
                                             "rod": Control("rod AB", 0.5, 6.0, 0.05, rod),
                                             "offset": Control("offset e", -2.0, 2.0, 0.05, offset)},
                               live=live, question=question)
