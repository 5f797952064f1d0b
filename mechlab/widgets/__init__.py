"""ipywidgets controls bound to :mod:`mechlab.draw`.

Sliders are in degrees and in the mechanism's length unit (mm, or dimensionless); the
explorer builds the mechanism from the slider values, computes its whole cycle once, and
moves the existing artists (no new figure per slider move). A geometry that cannot be
built shows its :class:`~mechlab.errors.MechanismError` message in place of the drawing,
and the widget stays usable. Every explorer may carry a ``question`` to investigate,
shown above its controls.

Where it is drawn: in JupyterLab (an IPython kernel with ipympl installed) the figure's
canvas is an ipympl widget and a crank-angle move redraws only the moving artists over a
saved background (blitting), whatever ``%matplotlib`` backend the notebook uses; in the
book (``MECHLAB_WIDGETS=static``, set by the book's kernels) and outside a kernel the
figure is re-shown as an image in an Output widget.
"""

from __future__ import annotations

import html
import os
import struct
import zlib
from collections.abc import Callable
from dataclasses import dataclass

import ipywidgets as W
import matplotlib
import matplotlib.pyplot as plt
import numpy as np
from IPython import get_ipython
from IPython.display import display
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure
from traitlets import CFloat

from ..draw import drawing_class, fill_axes
from ..errors import MechanismError
from ..mechanisms.fourbar import FourBar
from .access import announce_controls, describe_live_figure, status_line

UNIT_TEXT = {"deg": "°"}   # how a unit reads in a slider's description
SLIDER_STYLE = dict(style={"description_width": "165px"}, layout=W.Layout(width="445px"))
# the sliders' column keeps its width (a long status line beside it must not clip the readouts)
SLIDER_COLUMN = dict(layout=W.Layout(flex="0 0 auto", width="455px"))
SIDE_COLUMN = dict(layout=W.Layout(flex="1 1 auto", min_width="300px"))


@dataclass(frozen=True)
class Control:
    """A slider: label, range, step, initial value and unit ("mm", "deg", "" …).

    Values of a "deg" control reach the factory in radians. A control whose range, step
    and value are whole numbers is an integer slider (z = 4, not 4.00); a float slider
    shows as many decimals as its step has.
    """

    label: str
    min: float
    max: float
    step: float
    value: float
    unit: str = ""

    @property
    def integer(self) -> bool:
        return all(float(v).is_integer() for v in (self.min, self.max, self.step, self.value))

    def widget(self):
        unit = UNIT_TEXT.get(self.unit, self.unit)
        common = dict(description=f"{self.label} ({unit})" if unit else self.label, continuous_update=True,
                      **SLIDER_STYLE)
        if self.integer:
            return W.IntSlider(value=int(self.value), min=int(self.min), max=int(self.max), step=int(self.step),
                               **common)
        decimals = max(0, int(np.ceil(-np.log10(self.step) - 1e-9)))
        return W.FloatSlider(value=self.value, min=self.min, max=self.max, step=self.step,
                             readout_format=f".{decimals}f", **common)


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


def _fit(ax, bounds, fill: bool = False) -> bool:
    """Set the axes limits to ``bounds`` (x0, x1, y0, y1), with 10 % to spare so that small
    changes fit without a full redraw (5 % with ``fill``), unless the current limits already hold them without
    wasting more than half the view; True if the limits changed. ``fill``: equal-aspect
    limits that fill the axes' box (:func:`mechlab.draw.fill_axes`)."""
    x0, x1, y0, y1 = bounds
    (cx0, cx1), (cy0, cy1) = ax.get_xlim(), ax.get_ylim()
    inside = cx0 <= x0 and x1 <= cx1 and cy0 <= y0 and y1 <= cy1
    snug = (x1 - x0) > 0.5 * (cx1 - cx0) or (y1 - y0) > 0.5 * (cy1 - cy0) if fill else \
        (x1 - x0) > 0.5 * (cx1 - cx0) and (y1 - y0) > 0.5 * (cy1 - cy0)
    if inside and snug:
        return False
    spare = 0.05 if fill else 0.1
    mx, my = spare * (x1 - x0), spare * (y1 - y0)
    if fill:
        fill_axes(ax, (x0 - mx, x1 + mx, y0 - my, y1 + my))
    else:
        ax.set_xlim(x0 - mx, x1 + mx)
        ax.set_ylim(y0 - my, y1 + my)
    return True


def _uses_ipympl() -> bool:
    return "ipympl" in matplotlib.get_backend() or "widget" in matplotlib.get_backend().lower()


def _ipympl_canvas(fig):
    """An ipympl canvas for ``fig`` (a widget JupyterLab draws), or None without ipympl."""
    try:
        from ipympl.backend_nbagg import Canvas, FigureManager
    except ImportError:
        return None
    canvas = Canvas(fig)
    FigureManager(canvas, 0)
    bare_canvas(canvas)
    return canvas


def bare_canvas(canvas) -> None:
    """An ipympl canvas without its "Figure 1" header, status footer, toolbar and resize handle: the
    explorer's own title and status line say what it shows. Any other canvas is left as it is."""
    for trait in ("header_visible", "footer_visible", "toolbar_visible", "resizable"):
        if hasattr(canvas, trait):
            setattr(canvas, trait, False)


def png_rgba(rgba) -> bytes:
    """An RGBA array (rows × columns × 4, uint8) as a PNG: no row filter and zlib level 1, so
    that a frame's diff, mostly transparent zeros, is encoded 2-3× faster than by Pillow's
    defaults (adaptive filters, level 6) for a few KiB more (PNG, ISO/IEC 15948:2004)."""
    h, w, _ = rgba.shape
    rows = np.zeros((h, 4 * w + 1), np.uint8)   # each row: filter type 0, then its pixels
    rows[:, 1:] = rgba.reshape(h, 4 * w)

    def chunk(kind: bytes, data: bytes) -> bytes:
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))

    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 6, 0, 0, 0))
            + chunk(b"IDAT", zlib.compress(rows.tobytes(), 1)) + chunk(b"IEND", b""))


def diff_image(canvas):
    """What a web canvas (ipympl's) sends after a draw or a blit: the whole image, or only the
    pixels that changed since the last one, in an image cropped below and right of the last
    changed pixel (the browser draws it at the top-left corner over the old image); None if
    nothing new was drawn. Replaces ``FigureCanvasWebAggCore.get_diff_image``, same protocol."""
    if not canvas._png_is_old:
        return None
    pixels = np.asarray(canvas.get_renderer().buffer_rgba())
    buff = pixels.view(np.uint32).squeeze(2)   # one uint32 per pixel: compared in one pass
    # whole images until a browser has said it shows the canvas (ipympl then stops syncing the data URL): a
    # frame sent before its view existed may be lost, and a diff over nothing leaves holes in the plot
    unseen = getattr(canvas, "syncing_data_url", False)
    if canvas._force_full or unseen or buff.shape != canvas._last_buff.shape or (pixels[:, :, 3] != 255).any():
        canvas.set_image_mode("full")   # a diff cannot make a pixel transparent again
        output = buff
    else:
        canvas.set_image_mode("diff")
        changed = buff != canvas._last_buff
        rows, cols = np.flatnonzero(changed.any(axis=1)), np.flatnonzero(changed.any(axis=0))
        h, w = (rows[-1] + 1, cols[-1] + 1) if len(rows) else (1, 1)
        output = np.where(changed[:h, :w], buff[:h, :w], 0)
    canvas._last_buff = buff.copy()
    canvas._force_full = canvas._png_is_old = False
    return png_rgba(output.view(np.uint8).reshape(*output.shape, 4))


def live_by_default() -> bool:
    """Live (ipympl canvas, blitting) in a Jupyter kernel, static in the book and outside a kernel."""
    if os.environ.get("MECHLAB_WIDGETS") == "static":
        return False
    shell = get_ipython()
    return _uses_ipympl() or (shell is not None and hasattr(shell, "kernel"))


class AngleSlider(W.FloatSlider):
    """The crank-angle slider: the kernel does not echo its value back to the browser (one
    message fewer per key press; the browser set the value, and ipywidgets needs the echo only
    when several browsers show the same widget)."""

    value = CFloat(0.0, help="Float value").tag(sync=True, echo_update=False)


class Explorer:
    """What every explorer shares: controls → ``factory(**values)``, a crank-angle slider,
    one figure shown on the right canvas, a MechanismError shown in place of the plots, and
    an optional ``question`` (shown as "Investigate: …" above the controls).

    ``controls`` maps the factory's keyword names to :class:`Control` (a slider) or
    :class:`Choice` (buttons or a drop-down). ``live`` (default: :func:`live_by_default`)
    draws on the figure's own canvas and blits the moving artists (:meth:`_moving_artists`)
    over a saved background; otherwise the figure is re-shown in an Output widget. The
    crank-angle slider steps by the sampling step of the cycle (n samples over 360°), so
    every key press shows a new position. A subclass makes its axes and artists after
    ``super().__init__``, then calls :meth:`_finish` with the widgets to show beside the
    angle slider; it defines :meth:`rebuild`, :meth:`_select_frame`, :meth:`_axes` and
    :meth:`_forget`; ``blit = False`` redraws the whole figure on a live canvas.
    """

    blit = True

    def __init__(self, factory: Callable, controls: dict, *, n: int, title: str = "", live: bool | None = None,
                 figsize=(9.5, 4.4), dpi: int = 80, angle: float = 0.0, question: str | None = None):
        self.factory = factory
        self.controls = controls
        self.n = n
        self.message = ""
        self.frame = 0
        self.sliders = {name: c.widget() for name, c in controls.items()}
        self.angle_step = 360.0 / (n - 1)
        self.angle = AngleSlider(value=self.angle_step * round(angle / self.angle_step), min=0.0, max=360.0,
                                   step=self.angle_step, description="crank angle φ (°)", continuous_update=True,
                                   readout_format=".0f", **SLIDER_STYLE)
        self.status = status_line()   # announced by a screen reader when it changes
        self.question = W.HTML(f"<b>Investigate:</b> {html.escape(question)}" if question else "")
        self.live = live_by_default() if live is None else live
        self._background = None
        self._player = None
        canvas = None
        # whole pixels: a web canvas is sized in them, and the browser's size sent back must not resize the figure
        figsize = tuple(round(v * dpi) / dpi for v in figsize)
        if _uses_ipympl():
            with plt.ioff():
                self.fig = plt.figure(figsize=figsize, dpi=dpi)
            canvas = self.fig.canvas
            bare_canvas(canvas)
        else:
            # not managed by pyplot (so the inline backend shows it only through the Output widget)
            self.fig = Figure(figsize=figsize, dpi=dpi)
            canvas = _ipympl_canvas(self.fig) if self.live else None
            if canvas is None:
                FigureCanvasAgg(self.fig)
        if title:
            self.fig.suptitle(title)
        self.error_text = self.fig.text(0.5, 0.5, "", ha="center", va="center", wrap=True, color="#b00020",
                                        fontsize=12, bbox=dict(fc="#fff0f0", ec="#b00020"))
        if hasattr(canvas, "get_diff_image"):   # a web canvas: its frames encoded faster
            canvas.get_diff_image = lambda: diff_image(canvas)
        self.output = None if self.live else W.Output()
        # live without ipympl (benchmarks, tests) renders off screen: nothing to place in the layout
        self._canvas_widget = canvas if isinstance(canvas, W.Widget) else (self.output or W.HTML())
        describe_live_figure(self.fig)   # a live canvas is named by the figure's alt text
        if self.live and self.blit:
            self.fig.canvas.mpl_connect("draw_event", self._capture_background)

    def _finish(self, side_widgets=()):
        """Lay the widgets out, connect them, and build the first mechanism."""
        for w in self.sliders.values():
            w.observe(self._on_dimensions, names="value")
        self.angle.observe(self._on_angle, names="value")
        self.widget = W.VBox([self.question,
                              W.HBox([W.VBox(list(self.sliders.values()), **SLIDER_COLUMN),
                                      W.VBox([self.angle, *side_widgets, self.status], **SIDE_COLUMN)]),
                              self._canvas_widget])
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

    def _play(self, interval: int = 60) -> W.Play:
        """A play button moving the crank slider by one sample per tick (linked in the browser),
        starting from the slider's angle."""
        step = max(1, round(self.angle_step))
        play = W.Play(value=0, min=0, max=int(360 - step), step=step, interval=interval, description="play")
        # play → slider in the browser; slider → play from the kernel, after the redraw: a two-way
        # link would send the play's value to the kernel with each key press, a second request
        # (and its echo and busy/idle messages) ahead of the slider's own
        W.jsdlink((play, "value"), (self.angle, "value"))
        self._player = play
        return play

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
        self.status.value = f"<span style='color:#b00020'>{html.escape(text)}</span>"
        self._redraw()

    def _set_visible(self, ok: bool):
        for ax in self._axes():
            ax.set_visible(ok)
        self.error_text.set_visible(not ok)
        if ok:
            self.error_text.set_text("")

    def _animate_moving(self):
        """Mark the moving artists animated when live (a full draw skips them; blitting draws them)."""
        for artist in self._moving_artists():
            artist.set_animated(self.live and self.blit)

    def _on_dimensions(self, change):
        self.rebuild()

    def _on_angle(self, change=None):
        if self._ready():
            self._select_frame()
            self._blit_or_redraw()
        if self._player is not None:
            self._player.value = min(self._player.max, round(self.angle.value))

    def _blit_or_redraw(self):
        """Redraw only the moving artists over the saved background when live, else everything."""
        if self.live and self.blit and self._background is not None:
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
            if artist.axes is not None and artist.get_visible():
                artist.axes.draw_artist(artist)

    def _redraw(self):
        if self.output is None:
            self.fig.canvas.draw_idle()
        else:
            with self.output:
                self.output.clear_output(wait=True)
                display(self.fig)

    def _ipython_display_(self):
        announce_controls()
        display(self.widget)


def legend_above(ax, handles=None, **kwargs):
    """The legend of ``ax`` in one row just above its top edge, right-aligned and frameless: outside
    the data, so that no curve hides under it whatever the sliders make of the curves."""
    extra = {} if handles is None else {"handles": handles}
    return ax.legend(**extra, **{"loc": "lower right", "bbox_to_anchor": (1.0, 1.0), "ncols": 4,
                                 "frameon": False, "borderaxespad": 0.1, "fontsize": 8, **kwargs})


def law_labels(output: str, length_unit: str) -> tuple[str, str, tuple[str, str]]:
    """Axis labels of an output law and its analogs: angles in degrees, ψ′ dimensionless,
    ψ″ per radian; a translating output s in the mechanism's length unit ("mm", or
    "dimensionless": then its analogs are per radian)."""
    if output == "angle":
        return "output ψ (degrees)", "ψ′ (–), ψ″ (1/rad)", ("ψ′ = dψ/dφ", "ψ″ = d²ψ/dφ²")
    per = "1" if length_unit == "dimensionless" else length_unit
    return f"output s ({length_unit})", f"s′ ({per}/rad), s″ ({per}/rad²)", ("s′ = ds/dφ", "s″ = d²s/dφ²")


class MechanismExplorer(Explorer):
    """Sliders → ``factory(**values)`` → the labelled drawing (filling its axes), the output
    law ψ(φ) in degrees (or s(φ)) with a marker at the crank angle, its analogs ψ′, ψ″ below
    it, and the transmission angle in the status line.

    ``controls`` maps the factory's keyword names to :class:`Control` (a slider) or
    :class:`Choice` (buttons or a drop-down); ``assembly=True`` adds a ±1 toggle; the
    crank angle slider (degrees) and a play button are added by the explorer. ``trace``
    names a joint whose path is drawn; ``length_unit`` names the lengths' unit on the axes
    ("dimensionless" or "mm"). ``live``, ``question``: see :class:`Explorer`. ``figsize`` (inches) and
    ``mechanism_width`` (the drawing's column over the plots' column) lay the figure out for the family's
    proportions over its turn.
    """

    def __init__(self, factory: Callable, controls: dict, *, assembly: bool = False,
                 trace: str | None = None, n: int = 181, title: str = "", live: bool | None = None,
                 question: str | None = None, length_unit: str = "dimensionless", figsize=(9.5, 4.4),
                 mechanism_width: float = 1.25):
        super().__init__(factory, controls, n=n, title=title, live=live, question=question, figsize=figsize)
        self.mechanism = None
        self.motion = None
        self.length_unit = length_unit
        if assembly:
            self.sliders["assembly"] = W.ToggleButtons(options=[("kc = +1", 1), ("kc = -1", -1)], value=1,
                                                       description="assembly")
        self.play = self._play()
        grid = self.fig.add_gridspec(2, 2, width_ratios=[mechanism_width, 1], left=0.01, right=0.98,
                                     bottom=0.12 * 4.4 / figsize[1],
                                     top=1 - (0.1 if title else 0.03) * 4.4 / figsize[1],
                                     wspace=0.28, hspace=0.2)
        self.ax_mech = self.fig.add_subplot(grid[:, 0])
        self.ax_law = self.fig.add_subplot(grid[0, 1])
        self.ax_rate = self.fig.add_subplot(grid[1, 1], sharex=self.ax_law)
        (law_line,) = self.ax_law.plot([], [], color="#1f4e79", lw=1.8)
        self.law_lines = {"law": law_line, "first": self.ax_rate.plot([], [], color="#2a7f62", label="′")[0],
                          "second": self.ax_rate.plot([], [], color="#e08214", label="″")[0]}
        self.law_markers = [ax.plot([], [], "o", color="#d62728", ms=6, zorder=5)[0]
                            for ax in (self.ax_law, self.ax_rate, self.ax_rate)]
        self.law_marker = self.law_markers[0]
        self.ax_rate.axhline(0.0, color="0.6", lw=0.8)
        self.ax_rate.set_xlabel("crank angle φ (degrees)")
        self.ax_law.set_xlim(0, 360)
        self.ax_law.tick_params(labelbottom=False)
        for ax in (self.ax_law, self.ax_rate):
            ax.grid(True, alpha=0.3)
            ax.set_xticks(np.arange(0, 361, 90))
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
            self.ax_mech.set_axis_off()
        was_hidden = not self.ax_mech.get_visible()
        self.drawing.set_motion(mechanism, motion)
        self._animate_moving()
        deg = np.degrees(phi)
        out = motion.output
        law = (out.value, out.d, out.dd)
        angular = out.kind == "angle"
        y0 = np.degrees(np.unwrap(law[0])) if angular else law[0]
        self._law = (y0, law[1], law[2])
        for line, y in zip(self.law_lines.values(), self._law, strict=False):
            line.set_data(deg, y)
        law_label, rate_label, names = law_labels(out.kind, self.length_unit)
        relabel = self.ax_law.get_ylabel() != law_label
        if relabel:
            self.ax_law.set_ylabel(law_label)
            self.ax_rate.set_ylabel(rate_label)
            for line, name in zip((self.law_lines["first"], self.law_lines["second"]), names, strict=False):
                line.set_label(name)
            legend_above(self.ax_rate, fontsize=8)
        pad = 0.05 * float(np.ptp(y0)) + 1e-9
        lo = min(float(np.min(law[1])), float(np.min(law[2])))
        hi = max(float(np.max(law[1])), float(np.max(law[2])))
        rpad = 0.05 * (hi - lo) + 1e-9
        rescaled = self._fit_mechanism()
        rescaled |= _fit(self.ax_law, (deg[0], deg[-1], float(np.min(y0)) - pad, float(np.max(y0)) + pad))
        rescaled |= _fit(self.ax_rate, (deg[0], deg[-1], lo - rpad, hi + rpad))
        self.status.value = self._status()
        self._set_visible(True)
        self._select_frame()
        if rescaled or relabel or was_hidden:
            self._redraw()
        else:
            self._blit_or_redraw()

    def _fit_mechanism(self) -> bool:
        if getattr(self.drawing.ax, "name", "") == "3d":
            return False
        return _fit(self.ax_mech, self.drawing.bounds(), fill=True)

    def _status(self) -> str:
        mu = np.degrees(self.motion.transmission)
        return (f"transmission angle μ: {mu.min():.1f}° … {mu.max():.1f}°"
                + ("" if self.mechanism.can_turn else " · crank rocks: range limited"))

    def _select_frame(self):
        phi = np.degrees(self.motion.phi)
        target = self.angle.value
        if self.mechanism.can_turn:
            self.frame = self.nearest_frame(self.motion.phi)
        else:
            self.frame = int(np.clip(np.searchsorted(phi, target), 0, len(phi) - 1))
        self.drawing.set_frame(self.frame)
        for marker, y in zip(self.law_markers, self._law, strict=False):
            marker.set_data([phi[self.frame]], [y[self.frame]])

    def _moving_artists(self):
        """Everything that changes with the crank angle or the dimensions (axes limits aside)."""
        return [*self.drawing.artists, *self.law_lines.values(), *self.law_markers]

    def _axes(self):
        return (self.ax_mech, self.ax_law, self.ax_rate)

    def _forget(self):
        self.mechanism = self.motion = None

    def _ready(self) -> bool:
        return self.motion is not None


def fourbar_explorer(crank=1.0, coupler=3.0, rocker=3.0, ground=4.0, *, max_length=10.0, trace="B",
                     live: bool | None = None, question: str | None = None):
    """Sliders for a four-bar's four lengths (dimensionless) and its assembly, with its animation."""
    def ctl(label, v):
        return Control(label, 0.1, max_length, 0.05, v)
    controls = {"crank": ctl("crank OA", crank), "coupler": ctl("coupler AB", coupler),
                "rocker": ctl("rocker BE", rocker), "ground": ctl("ground OE", ground)}
    return MechanismExplorer(FourBar, controls, assembly=True, trace=trace, title="Four-bar O-A-B-E", live=live,
                             question=question)


from .drag import DragEditor, as_linkage, linkage_code  # noqa: E402, F401  (re-exported; built on the Explorer above)
