"""Sliders for kinetostatics: speed, masses, load, friction → force plan, torque and efficiency.

:class:`ForceExplorer` builds a :class:`mechlab.kinetostatics.Kinetostatics` from its sliders
(``factory(**values)``), solves it over the cycle once, and shows the mechanism with its
reaction arrows (:mod:`mechlab.draw.forces`), the balancing torque from the groups and
from the power balance, and the instantaneous efficiency; the crank-angle slider moves
the arrows in place. A MechanismError (bad dimensions, self-locking) is shown in place
of the plots and the widget stays usable. Like :class:`mechlab.widgets.MechanismExplorer`
it re-shows the figure in an Output widget with the inline backend (and in static
pages) and redraws the canvas itself under ipympl.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from ..draw import drawing_class
from ..draw.forces import shade_undefined
from ..errors import MechanismError
from ..kinetostatics.drive import drive
from ..kinetostatics.machines import press, rocker_drive
from . import Control, Explorer, legend_above


class ForceExplorer(Explorer):
    """Sliders → ``factory(**values)`` (a Kinetostatics) → force plan, M_b(φ), η(φ).

    ``controls`` maps the factory's keyword names to :class:`~mechlab.widgets.Control`
    ("deg" controls reach the factory in radians). ``pairs`` restricts the arrows.
    """

    def __init__(self, factory: Callable, controls: dict[str, Control], *, n: int = 121, title: str = "",
                 pairs=None, live: bool | None = None, question: str | None = None):
        super().__init__(factory, controls, n=n, title=title, figsize=(10, 4.4), dpi=76, angle=30.0, live=live,
                         question=question)
        self.pairs = pairs
        self.system = None
        self.result = None
        grid = self.fig.add_gridspec(2, 2, width_ratios=[1.2, 1])
        self.ax_mech = self.fig.add_subplot(grid[:, 0])
        self.ax_torque = self.fig.add_subplot(grid[0, 1])
        self.ax_eta = self.fig.add_subplot(grid[1, 1], sharex=self.ax_torque)
        self.lines = {"groups": self.ax_torque.plot([], [], lw=2, label="M_b, groups")[0],
                      "power": self.ax_torque.plot([], [], "k--", lw=1, label="M_b, power balance")[0],
                      "ideal": self.ax_torque.plot([], [], ":", color="0.4", lw=1, label="M_b, no friction")[0],
                      "eta": self.ax_eta.plot([], [], color="#2a7f62", lw=1.5)[0]}
        (self.m_marker,) = self.ax_torque.plot([], [], "ko", ms=5)
        (self.e_marker,) = self.ax_eta.plot([], [], "ko", ms=5)
        self.ax_torque.axhline(0.0, color="0.6", lw=0.8)
        self.ax_torque.set_ylabel("balancing torque M_b (N·m)")
        legend_above(self.ax_torque, fontsize=7)
        self.ax_eta.set_ylabel("efficiency η (–)")
        self.ax_eta.set_xlabel("crank angle φ (degrees)")
        self.ax_eta.set_xticks(np.arange(0, 361, 90))
        self._undefined = None   # the grey spans where η is undefined, redrawn with each rebuild
        for ax in (self.ax_torque, self.ax_eta):
            ax.grid(True, alpha=0.3)
        self.drawing = None
        self._finish()

    def rebuild(self):
        """Build and solve from the sliders; show a MechanismError's message instead of plots
        (a bad dimension, self-locking, a crank speed of zero for the drive's figures …)."""
        try:
            system = self.factory(**self.values())
            phi = system.cycle(self.n)
            motion = system.motion(phi)
            if self.drawing is None:
                self.ax_mech.clear()
                self.drawing = drawing_class(system)(self.ax_mech, system, n=self.n, pairs=self.pairs)
                self.ax_mech.set_axis_off()
            else:
                self.drawing.set_motion(system, motion)
            result = self.drawing.result
            d = drive(result.torque, result.phi, system.omega1)
        except MechanismError as err:
            self._show_error(str(err))
            return
        self.system, self.result, self.message = system, result, ""
        self.drawing.autoscale()
        deg = np.degrees(result.phi)
        for key, y in (("groups", result.torque), ("power", result.torque_power), ("ideal", result.ideal_torque)):
            self.lines[key].set_data(deg, y)
        self._eta = result.efficiency().filled(np.nan)
        self.lines["eta"].set_data(deg, self._eta)
        self._shade_undefined(deg, np.isnan(self._eta))
        lo, hi = float(np.min(result.torque)), float(np.max(result.torque))
        pad = 0.08 * (hi - lo) + 1e-9
        self.ax_torque.set_xlim(deg[0], deg[-1])
        self.ax_torque.set_ylim(min(lo, 0) - pad, hi + pad)
        self.ax_eta.set_ylim(0.0, 1.05)
        try:
            cyc = f"{result.cycle_efficiency():.3f} (mean), {result.cycle_efficiency(how='work'):.3f} (work)"
        except MechanismError:
            cyc = "undefined"
        # the student reads mechanics; the solver's own check is a verdict, its residuals stay in the library
        gap = float(np.max(np.abs(result.torque - result.torque_power)))
        agree = gap <= 1e-9 * max(1.0, float(np.max(np.abs(result.torque))))
        check = ("group by group and by the power balance: the same M_b ✓" if agree else
                 f"✗ group by group and by the power balance M_b differs by up to {gap:.3g} N·m")
        self.status.value = (f"M_b mean {d.mean_torque:.4g} N·m, peak {d.peak_torque:.4g} N·m, "
                             f"rms {d.rms_torque:.4g} N·m; mean power {d.mean_power:.4g} W<br>"
                             f"cycle efficiency {cyc}<br>{check}")
        self._set_visible(True)
        self._animate_moving()   # the arrows are new artists after each rebuild
        self._select_frame()
        self._redraw()

    def _shade_undefined(self, deg, undefined):
        """Grey where η is undefined (:func:`mechlab.draw.forces.shade_undefined`), replacing the last rebuild's."""
        if self._undefined is not None:
            self._undefined.remove()
        legend = self.ax_eta.get_legend()
        if legend is not None:
            legend.remove()
        self._undefined = shade_undefined(self.ax_eta, deg, undefined)
        if self._undefined is not None:
            self.ax_eta.legend(loc="lower left", fontsize=7)

    def _select_frame(self):
        phi = np.degrees(self.result.phi)
        self.frame = self.nearest_frame(self.result.phi)
        self.drawing.set_frame(self.frame)
        self.m_marker.set_data([phi[self.frame]], [self.result.torque[self.frame]])
        self.e_marker.set_data([phi[self.frame]], [self._eta[self.frame]])

    def _moving_artists(self):
        return [*self.drawing.artists, self.m_marker, self.e_marker] if self.drawing is not None else []

    def _axes(self):
        return (self.ax_mech, self.ax_torque, self.ax_eta)

    def _forget(self):
        self.system = self.result = None

    def _ready(self) -> bool:
        return self.result is not None


def press_explorer(*, live: bool | None = None, question: str | None = None, **initial) -> ForceExplorer:
    """Sliders for the chapter's press (:func:`mechlab.kinetostatics.press`): speed, masses, load, friction."""
    v = dict(rpm=120.0, P=2000.0, m_rod=3.0, m_slider=4.0, f=0.0, rod=0.40)
    v.update(initial)
    controls = {"rpm": Control("crank speed", 0.0, 400.0, 5.0, v["rpm"], "rpm"),
                "P": Control("press force P", 0.0, 10000.0, 100.0, v["P"], "N"),
                "m_rod": Control("rod mass", 0.0, 20.0, 0.5, v["m_rod"], "kg"),
                "m_slider": Control("slider mass", 0.0, 40.0, 0.5, v["m_slider"], "kg"),
                "f": Control("friction f", 0.0, 0.5, 0.01, v["f"]),
                "rod": Control("rod AB", 0.05, 0.8, 0.01, v["rod"], "m")}
    return ForceExplorer(press, controls, title="Crank press: reactions and balancing torque", live=live,
                         question=question)


def rocker_explorer(*, live: bool | None = None, question: str | None = None, **initial) -> ForceExplorer:
    """Sliders for the chapter's four-bar (:func:`mechlab.kinetostatics.rocker_drive`)."""
    v = dict(rpm=120.0, T=40.0, m_coupler=2.0, m_rocker=2.0, f=0.0, ground=0.35)
    v.update(initial)
    controls = {"rpm": Control("crank speed", 0.0, 400.0, 5.0, v["rpm"], "rpm"),
                "T": Control("rocker torque T", 0.0, 200.0, 1.0, v["T"], "N·m"),
                "m_coupler": Control("coupler mass", 0.0, 20.0, 0.5, v["m_coupler"], "kg"),
                "m_rocker": Control("rocker mass", 0.0, 20.0, 0.5, v["m_rocker"], "kg"),
                "f": Control("friction f", 0.0, 0.5, 0.01, v["f"]),
                "ground": Control("ground OE", 0.2, 0.55, 0.005, v["ground"], "m")}
    return ForceExplorer(rocker_drive, controls, title="Four-bar: reactions and balancing torque", live=live,
                         question=question)
