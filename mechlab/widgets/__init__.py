"""ipywidgets controls bound to :mod:`mechlab.draw`.

Sliders are in degrees and mm (or the mechanism's length unit); the explorer builds
the mechanism from the slider values, computes its whole cycle once, and moves the
existing artists (no new figure per slider move). A geometry that cannot be built
shows its :class:`~mechlab.errors.MechanismError` message in place of the drawing,
and the widget stays usable. Works with the inline backend (the figure is
re-shown in an Output widget) and with ipympl (``%matplotlib widget``: the canvas
itself is the widget and redraws in place).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Callable

import ipywidgets as W
import matplotlib
import matplotlib.pyplot as plt
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure
import numpy as np
from IPython.display import display

from ..draw import drawing_class
from ..errors import MechanismError
from ..mechanisms.fourbar import FourBar


@dataclass(frozen=True)
class Control:
    """A slider: label, range, step, initial value and unit ("mm", "deg", "" …).

    Values of a "deg" control reach the factory in radians.
    """

    label: str
    min: float
    max: float
    step: float
    value: float
    unit: str = ""


@dataclass(frozen=True)
class Choice:
    """A choice among a few options (toggle buttons for ≤ 3, else a drop-down).

    ``options`` are the values handed to the factory, or (label, value) pairs.
    """

    label: str
    options: tuple
    value: object

    def widget(self):
        kind = W.ToggleButtons if len(self.options) <= 3 else W.Dropdown
        return kind(options=list(self.options), value=self.value, description=self.label)


def _control_widget(c):
    if isinstance(c, Choice):
        return c.widget()
    return W.FloatSlider(value=c.value, min=c.min, max=c.max, step=c.step,
                         description=f"{c.label} ({c.unit})" if c.unit else c.label,
                         continuous_update=True, style={"description_width": "110px"},
                         layout=W.Layout(width="380px"))


def _fit(ax, bounds) -> bool:
    """Set the axes limits to ``bounds`` (x0, x1, y0, y1), with 10 % to spare so that small
    changes fit without a full redraw, unless the current limits already hold them without
    wasting more than half the view; True if the limits changed."""
    x0, x1, y0, y1 = bounds
    (cx0, cx1), (cy0, cy1) = ax.get_xlim(), ax.get_ylim()
    inside = cx0 <= x0 and x1 <= cx1 and cy0 <= y0 and y1 <= cy1
    snug = (x1 - x0) > 0.5 * (cx1 - cx0) and (y1 - y0) > 0.5 * (cy1 - cy0)
    if inside and snug:
        return False
    mx, my = 0.1 * (x1 - x0), 0.1 * (y1 - y0)
    ax.set_xlim(x0 - mx, x1 + mx)
    ax.set_ylim(y0 - my, y1 + my)
    return True


def _uses_ipympl() -> bool:
    return "ipympl" in matplotlib.get_backend() or "widget" in matplotlib.get_backend().lower()


class Explorer:
    """What every explorer shares: controls → ``factory(**values)``, a crank-angle slider,
    one figure shown on the right canvas, a MechanismError shown in place of the plots.

    ``controls`` maps the factory's keyword names to :class:`Control` (a slider) or
    :class:`Choice` (buttons or a drop-down). ``live`` (default: whether the ipympl
    backend is active) draws on the figure's own canvas and blits the moving artists
    (:meth:`_moving_artists`) over a saved background; otherwise the figure is re-shown in
    an Output widget (inline backend, static pages). A subclass makes its axes and
    artists after ``super().__init__``, then calls :meth:`_finish` with the widgets to show
    beside the angle slider; it defines :meth:`rebuild`, :meth:`_select_frame`,
    :meth:`_axes` and :meth:`_forget`; ``blit = False`` redraws the whole figure on a live canvas.
    """

    blit = True

    def __init__(self, factory: Callable, controls: dict, *, n: int, title: str = "", live: bool | None = None,
                 figsize=(9, 4), dpi: int = 80, angle: float = 0.0):
        self.factory = factory
        self.controls = controls
        self.n = n
        self.message = ""
        self.frame = 0
        self.sliders = {name: _control_widget(c) for name, c in controls.items()}
        self.angle = W.FloatSlider(value=angle, min=0.0, max=360.0, step=1.0, description="crank φ (deg)",
                                   continuous_update=True, style={"description_width": "110px"},
                                   layout=W.Layout(width="380px"))
        self.status = W.HTML()
        ipympl = _uses_ipympl()
        self.live = ipympl if live is None else live
        self._background = None
        if ipympl:
            with plt.ioff():
                self.fig = plt.figure(figsize=figsize)
        else:
            # not managed by pyplot (so the inline backend shows it only through the Output
            # widget), with an Agg canvas so that it renders
            self.fig = Figure(figsize=figsize, dpi=dpi)
            FigureCanvasAgg(self.fig)
        if title:
            self.fig.suptitle(title)
        self.error_text = self.fig.text(0.5, 0.5, "", ha="center", va="center", wrap=True, color="#b00020",
                                        fontsize=12, bbox=dict(fc="#fff0f0", ec="#b00020"))
        self.output = None if self.live else W.Output()
        # live without ipympl (benchmarks, tests) renders off screen: nothing to place in the layout
        self._canvas_widget = self.fig.canvas if ipympl else (self.output or W.HTML())
        if self.live and self.blit:
            self.fig.canvas.mpl_connect("draw_event", self._capture_background)

    def _finish(self, side_widgets=()):
        """Lay the widgets out, connect them, and build the first mechanism."""
        for w in self.sliders.values():
            w.observe(self._on_dimensions, names="value")
        self.angle.observe(self._on_angle, names="value")
        self.widget = W.VBox([W.HBox([W.VBox(list(self.sliders.values())),
                                      W.VBox([self.angle, *side_widgets, self.status])]), self._canvas_widget])
        self.rebuild()

    def values(self) -> dict:
        """Current control values as the factory receives them (radians for "deg")."""
        out = {}
        for name, w in self.sliders.items():
            c = self.controls.get(name)
            out[name] = np.radians(w.value) if isinstance(c, Control) and c.unit == "deg" else w.value
        return out

    def nearest_frame(self, phi) -> int:
        """Index of the sample of ``phi`` (radians, a full turn) nearest the angle slider."""
        deg = np.degrees(phi)
        return int(np.argmin(np.abs((deg - self.angle.value + 180.0) % 360.0 - 180.0)))

    # -- to define in a subclass --------------------------------------------------------
    def rebuild(self):  # pragma: no cover - abstract
        raise NotImplementedError

    def _select_frame(self):  # pragma: no cover - abstract
        raise NotImplementedError

    def _axes(self):
        return self.fig.axes

    def _forget(self):
        """Drop the state of the last good mechanism (after a MechanismError)."""

    def _ready(self) -> bool:
        return not self.message

    def _moving_artists(self):
        return []

    # -- shared machinery ---------------------------------------------------------------
    def _show_error(self, text: str):
        self.message = text
        self._forget()
        self._set_visible(False)
        self.error_text.set_text(text)
        self.status.value = f"<span style='color:#b00020'>{text}</span>"
        self._redraw()

    def _set_visible(self, ok: bool):
        for ax in self._axes():
            ax.set_visible(ok)
        self.error_text.set_visible(not ok)
        if ok:
            self.error_text.set_text("")

    def _on_dimensions(self, change):
        self.rebuild()

    def _on_angle(self, change=None):
        if not self._ready():
            return
        self._select_frame()
        self._blit_or_redraw()

    def _blit_or_redraw(self):
        """Redraw only the moving artists over the saved background when live, else everything."""
        if self.live and self._background is not None:
            self.fig.canvas.restore_region(self._background)
            self._draw_moving()
            self.fig.canvas.blit(self.fig.bbox)
        else:
            self._redraw()

    def _capture_background(self, event):
        """After a full draw (which skips the animated artists): save it, then draw them."""
        self._background = self.fig.canvas.copy_from_bbox(self.fig.bbox)
        if self._ready():
            self._draw_moving()

    def _draw_moving(self):
        for artist in self._moving_artists():
            artist.axes.draw_artist(artist)

    def _redraw(self):
        if self.output is None:
            self.fig.canvas.draw_idle()
        else:
            with self.output:
                self.output.clear_output(wait=True)
                display(self.fig)

    def _ipython_display_(self):
        display(self.widget)


class MechanismExplorer(Explorer):
    """Sliders → ``factory(**values)`` → drawing, output law and transmission angle.

    ``controls`` maps the factory's keyword names to :class:`Control` (a slider) or
    :class:`Choice` (buttons or a drop-down); ``assembly=True`` adds a ±1 toggle; the
    crank angle slider (degrees) and a play button are added by the explorer. ``trace``
    names a joint whose path is drawn. ``live``: see :class:`Explorer`.
    """

    def __init__(self, factory: Callable, controls: dict, *, assembly: bool = False,
                 trace: str | None = None, n: int = 181, title: str = "", live: bool | None = None):
        super().__init__(factory, controls, n=n, title=title, live=live)
        self.mechanism = None
        self.motion = None
        if assembly:
            self.sliders["assembly"] = W.ToggleButtons(options=[("kc = +1", 1), ("kc = -1", -1)], value=1,
                                                       description="assembly")
        self.play = W.Play(value=0, min=0, max=359, step=4, interval=40, description="play")
        W.jslink((self.play, "value"), (self.angle, "value"))
        self.ax_mech, self.ax_law = self.fig.subplots(1, 2, gridspec_kw={"width_ratios": [1.1, 1]})
        self.law_lines = {k: self.ax_law.plot([], [], label=k)[0] for k in ("law", "first", "second")}
        (self.law_marker,) = self.ax_law.plot([], [], "ko", ms=5)
        self.ax_law.axhline(0.0, color="0.6", lw=0.8)
        self.ax_law.set_xlabel("φ, degrees")
        self.ax_law.set_xlim(0, 360)
        self.ax_law.grid(True, alpha=0.3)
        self.drawing = None
        self.trace = trace
        self._finish([self.play])

    def rebuild(self):
        """Build the mechanism from the sliders and redraw (message on a MechanismError)."""
        try:
            mechanism = self.factory(**self.values())
            phi = mechanism.cycle(self.n)
            motion = mechanism.motion(phi)
        except MechanismError as err:
            self._show_error(str(err))
            return
        self.mechanism, self.motion = mechanism, motion
        self.message = ""
        if self.drawing is None or type(self.drawing) is not drawing_class(mechanism):
            self.ax_mech.clear()
            self.drawing = drawing_class(mechanism)(self.ax_mech, mechanism, trace=self.trace, n=self.n)
            for artist in self._moving_artists():
                artist.set_animated(self.live)
        was_hidden = not self.ax_mech.get_visible()
        self.drawing.set_motion(mechanism, motion)
        deg = np.degrees(phi)
        law = (motion.output.value, motion.output.d, motion.output.dd)
        names = ("ψ (rad)", "ψ′", "ψ″") if mechanism.output == "angle" else ("s", "s′", "s″")
        relabel = False
        for line, y, name in zip(self.law_lines.values(), law, names):
            line.set_data(deg, y)
            relabel |= line.get_label() != name
            line.set_label(name)
        lo = min(float(np.min(y)) for y in law)
        hi = max(float(np.max(y)) for y in law)
        pad = 0.05 * (hi - lo) + 1e-9
        rescaled = _fit(self.ax_mech, self.drawing.bounds())
        rescaled |= _fit(self.ax_law, (deg[0], deg[-1], lo - pad, hi + pad))
        if relabel:
            self.ax_law.legend(loc="upper right", fontsize=8)
        mu = np.degrees(motion.transmission)
        self.status.value = (f"transmission angle μ: {mu.min():.1f}° … {mu.max():.1f}°"
                             + ("" if mechanism.can_turn else " · crank rocks: range limited"))
        self._set_visible(True)
        self._select_frame()
        if rescaled or relabel or was_hidden:
            self._redraw()
        else:
            self._blit_or_redraw()

    def _select_frame(self):
        phi = np.degrees(self.motion.phi)
        target = self.angle.value
        if self.mechanism.can_turn:
            self.frame = self.nearest_frame(self.motion.phi)
        else:
            self.frame = int(np.clip(np.searchsorted(phi, target), 0, len(phi) - 1))
        self.drawing.set_frame(self.frame)
        law = self.motion.output.value
        self.law_marker.set_data([phi[self.frame]], [law[self.frame]])

    def _moving_artists(self):
        """Everything that changes with the crank angle or the dimensions (axes limits aside)."""
        return [*self.drawing.artists, *self.law_lines.values(), self.law_marker]

    def _axes(self):
        return (self.ax_mech, self.ax_law)

    def _forget(self):
        self.mechanism = self.motion = None

    def _ready(self) -> bool:
        return self.motion is not None


def fourbar_explorer(crank=1.0, coupler=3.0, rocker=3.0, ground=4.0, *, max_length=10.0, trace="B",
                     live: bool | None = None):
    """Sliders for a four-bar's four lengths (mm) and its assembly, with its animation."""
    def ctl(label, v):
        return Control(label, 0.1, max_length, 0.05, v, "mm")
    controls = {"crank": ctl("crank OA", crank), "coupler": ctl("coupler AB", coupler),
                "rocker": ctl("rocker BE", rocker), "ground": ctl("ground OE", ground)}
    return MechanismExplorer(FourBar, controls, assembly=True, trace=trace, title="Four-bar O-A-B-E", live=live)
