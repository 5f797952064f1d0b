"""Matplotlib drawings of mechanisms whose artists are created once and moved in place.

A drawing is bound to an axes and a mechanism; :meth:`LinkageDrawing.set_motion`
hands it the arrays of a whole cycle (computed once by ``mechanism.motion``), and
:meth:`LinkageDrawing.set_frame` moves every artist to frame i without creating
any new artist. :func:`animate` turns a drawing into a ``FuncAnimation`` whose
``to_jshtml()`` plays in a static page. Other mechanism families register their
own drawing classes in modules of this package with :func:`register`.
"""

from __future__ import annotations

import importlib
import pkgutil
import re

import matplotlib.pyplot as plt
import numpy as np
from matplotlib.animation import FuncAnimation

from ..mechanisms.fourbar import FourBar
from ..mechanisms.base import Mechanism
from ..mechanisms.slotted import SineMechanism, SlottedLink
from ..mechanisms.slider_crank import SliderCrank
from ..motion import Motion

LINK_STYLE = dict(color="#1f4e79", lw=3, solid_capstyle="round", zorder=3)
JOINT_STYLE = dict(ls="none", marker="o", ms=6, mfc="white", mec="#1f4e79", mew=1.5, zorder=4)
PIVOT_STYLE = dict(ls="none", marker="^", ms=11, color="#555555", zorder=2)
TRACE_STYLE = dict(color="#d62728", lw=1, alpha=0.8, zorder=1)
EXTRA_STYLE = dict(color="#2a7f62", lw=2.5, zorder=2)
# a moving output drawn as an extra (a slotted bar, a block), a fixed guide, and the output
# re-drawn over itself while it dwells: green then means "standing still"
OUTPUT_STYLE = dict(color="#1f4e79", lw=2, solid_capstyle="round", zorder=3)
GUIDE_STYLE = dict(color="#555555", lw=1.5, zorder=2)
HIGHLIGHT_STYLE = dict(color="#2a7f62", lw=4.5, alpha=0.9, solid_capstyle="round", zorder=5)

_REGISTRY: dict[type, type] = {}

# matplotlib's to_jshtml() links Font Awesome from a CDN for its buttons; the course loads
# nothing from another host, so the link goes and the icons become Unicode glyphs.
_REMOTE_FONT_AWESOME = re.compile(r'<link[^>]*href="(?:https?:)?//[^"]*font-awesome[^"]*"[^>]*>\s*', re.I)
_FA_CLASS = re.compile(r'class="fa fa-([a-z-]+)(?: fa-flip-horizontal)?"')
ICON_GLYPHS = {"minus": "\u2212", "fast-backward": "\u21e4", "step-backward": "\u2759\u25c0",
               "play-backwards": "\u25c0", "pause": "\u2759\u2759", "play": "\u25b6",
               "step-forward": "\u25b6\u2759", "fast-forward": "\u21e5", "plus": "+"}
_ICON_STYLE = ("<style>.animation .mechlab-icon{font-style:normal;font-family:'DejaVu Sans',system-ui,sans-serif}"
               ".animation button{min-width:2.2em}"
               + "".join(f'.animation .mechlab-{k}::before{{content:"{v}"}}' for k, v in ICON_GLYPHS.items())
               + "</style>\n")


def local_animation_controls(html: str) -> str:
    """matplotlib's animation HTML without the remote Font Awesome stylesheet: the buttons'
    icons become ``mechlab-icon mechlab-<name>`` classes drawn by an inline style."""
    if not _REMOTE_FONT_AWESOME.search(html) and not _FA_CLASS.search(html):
        return html

    def rename(match: re.Match) -> str:
        name = "play-backwards" if "fa-flip-horizontal" in match.group(0) else match.group(1)
        return f'class="mechlab-icon mechlab-{name}"'

    return _ICON_STYLE + _FA_CLASS.sub(rename, _REMOTE_FONT_AWESOME.sub("", html))


class Animation(FuncAnimation):
    """A FuncAnimation whose ``to_jshtml()`` (and HTML display) loads nothing from another host."""

    def to_jshtml(self, *args, **kwargs) -> str:
        return local_animation_controls(super().to_jshtml(*args, **kwargs))


def register(mechanism_type: type):
    """Class decorator: use this drawing class for ``mechanism_type``."""
    def deco(cls):
        _REGISTRY[mechanism_type] = cls
        return cls
    return deco


def drawing_class(mechanism) -> type:
    """The drawing class registered for a mechanism (searching this package's modules)."""
    def registered():
        return next((_REGISTRY[k] for k in type(mechanism).__mro__ if k in _REGISTRY), None)

    found = registered()
    # the family modules register on import: load them one by one until one serves
    for info in pkgutil.iter_modules(__path__):
        if found is not None:
            return found
        importlib.import_module(f"{__name__}.{info.name}")
        found = registered()
    if found is None:
        raise TypeError(f"no drawing registered for {type(mechanism).__name__}")
    return found


class LinkageDrawing:
    """Links, joints, pivots, an optional traced point and per-family extras.

    Parameters: ``ax`` the axes; ``mechanism`` a single-loop mechanism;
    ``trace`` the name of a joint whose path over the cycle is drawn.
    """

    n_extras = 0
    extra_styles: dict[int, dict] = {}  # the style of extra k when it is not EXTRA_STYLE

    def __init__(self, ax, mechanism: Mechanism, trace: str | None = None, n: int = 361):
        self.ax = ax
        self.trace_name = trace
        self.n = n
        ax.set_aspect("equal")
        self.link_lines = []
        self.extra_lines = [ax.plot([], [], **self.extra_styles.get(k, EXTRA_STYLE))[0] for k in range(self.n_extras)]
        (self.trace_line,) = ax.plot([], [], **TRACE_STYLE)
        (self.pivot_marks,) = ax.plot([], [], **PIVOT_STYLE)
        (self.joint_marks,) = ax.plot([], [], **JOINT_STYLE)
        self.labels = {}
        self.mechanism = None
        self.motion = None
        self.set_mechanism(mechanism)

    # -- binding -------------------------------------------------------------------
    def set_mechanism(self, mechanism: Mechanism, phi=None) -> Motion:
        """Bind a (new) mechanism, compute its cycle once, and show frame 0."""
        phi = mechanism.cycle(self.n) if phi is None else phi
        return self.set_motion(mechanism, mechanism.motion(phi))

    def set_motion(self, mechanism: Mechanism, motion: Motion) -> Motion:
        self.mechanism, self.motion = mechanism, motion
        links = mechanism.links
        while len(self.link_lines) < len(links):
            self.link_lines.append(self.ax.plot([], [], **LINK_STYLE)[0])
        for extra in self.link_lines[len(links):]:
            extra.set_data([], [])
        if self.trace_name:
            p = motion.points[self.trace_name].p
            self.trace_line.set_data(p[:, 0], p[:, 1])
        self.set_frame(0)
        return motion

    # -- frames --------------------------------------------------------------------
    def set_frame(self, i: int):
        """Move every artist to frame i of the bound motion; returns the artists."""
        pts = {k: v.p[i] for k, v in self.motion.points.items()}
        for line, names in zip(self.link_lines, self.mechanism.links):
            xy = np.array([pts[k] for k in names])
            line.set_data(xy[:, 0], xy[:, 1])
        piv = np.array([pts[k] for k in self.mechanism.pivots if k in pts])
        self.pivot_marks.set_data(piv[:, 0], piv[:, 1])
        moving = np.array([v for k, v in pts.items() if k not in self.mechanism.pivots] or [[np.nan, np.nan]])
        self.joint_marks.set_data(moving[:, 0], moving[:, 1])
        for line, seg in zip(self.extra_lines, self.extras(i)):
            line.set_data(seg[:, 0], seg[:, 1])
        return self.artists

    def extras(self, i: int) -> list[np.ndarray]:
        """Polylines beyond the links (guides, slots, sliders) at frame i."""
        return []

    @property
    def artists(self):
        return [*self.link_lines, *self.extra_lines, self.trace_line, self.pivot_marks, self.joint_marks]

    def bounds(self, margin: float = 0.15):
        """(xmin, xmax, ymin, ymax) enclosing every joint over the cycle, with a margin."""
        allp = np.concatenate([v.p for v in self.motion.points.values()]
                              + [seg for j in (0, len(self.motion) // 2) for seg in self.extras(j)])
        lo, hi = np.nanmin(allp, axis=0), np.nanmax(allp, axis=0)
        pad = margin * max(hi - lo) + 1e-9
        return lo[0] - pad, hi[0] + pad, lo[1] - pad, hi[1] + pad

    def autoscale(self):
        x0, x1, y0, y1 = self.bounds()
        self.ax.set_xlim(x0, x1)
        self.ax.set_ylim(y0, y1)


@register(FourBar)
class FourBarDrawing(LinkageDrawing):
    pass


@register(SliderCrank)
class SliderCrankDrawing(LinkageDrawing):
    """Adds the guide line and the slider block."""

    n_extras = 2

    def extras(self, i):
        m, mo = self.mechanism, self.motion
        s = mo.s
        h = 0.08 * (m.crank + m.rod)
        guide = np.array([[s.min() - 2 * h, m.offset], [s.max() + 2 * h, m.offset]])
        x = s[i]
        block = np.array([[x - h, m.offset - h / 2], [x + h, m.offset - h / 2], [x + h, m.offset + h / 2],
                          [x - h, m.offset + h / 2], [x - h, m.offset - h / 2]])
        return [guide, block]


@register(SlottedLink)
class SlottedLinkDrawing(LinkageDrawing):
    """Adds the slotted link: a bar from the pivot B through the pin A."""

    n_extras = 1

    def extras(self, i):
        m = self.mechanism
        B = self.motion.points["B"].p[i]
        reach = 1.15 * (m.pivot_distance + m.crank)
        psi = self.motion.psi[i]
        return [np.array([B, B + reach * np.array([np.cos(psi), np.sin(psi)])])]


@register(SineMechanism)
class SineMechanismDrawing(LinkageDrawing):
    """Adds the yoke: the slot (perpendicular to the guide) and its rod along the guide."""

    n_extras = 1

    def extras(self, i):
        r = self.mechanism.crank
        x = self.motion.s[i]
        return [np.array([[x, 1.3 * r], [x, -1.3 * r], [x, 0.0], [x + 1.6 * r, 0.0]])]


def draw(mechanism, phi: float = 0.0, ax=None, trace: str | None = None):
    """Draw a mechanism at crank angle φ (radians); returns the drawing."""
    if ax is None:
        _, ax = plt.subplots(figsize=(5, 4))
    drawing = drawing_class(mechanism)(ax, mechanism, trace=trace)
    drawing.autoscale()
    drawing.set_motion(mechanism, mechanism.motion(np.atleast_1d(phi)))
    return drawing


def animate(mechanism, n: int = 72, interval: int = 50, trace: str | None = None, ax=None,
            figsize=(5, 4)) -> Animation:
    """A FuncAnimation of one cycle in n frames (its figure is closed, so only the
    animation is shown); play it in a page with ``HTML(anim.to_jshtml())``."""
    if ax is None:
        fig, ax = plt.subplots(figsize=figsize)
    else:
        fig = ax.figure
    drawing = drawing_class(mechanism)(ax, mechanism, trace=trace, n=n)
    drawing.autoscale()
    anim = Animation(fig, drawing.set_frame, frames=n, interval=interval, blit=False)
    anim.drawing = drawing
    plt.close(fig)
    return anim


def animate_together(mechanisms, titles=(), n: int = 24, interval: int = 150, trace: str | None = None,
                     figsize=None, dpi: int = 50) -> Animation:
    """One animation of several mechanisms side by side, frame i of each at the same fraction
    of its cycle (the same crank angle for mechanisms whose crank turns fully), so that their
    motions can be compared; one panel per mechanism, ``titles`` above them."""
    mechanisms = list(mechanisms)
    fig, axes = plt.subplots(1, len(mechanisms), figsize=figsize or (3.2 * len(mechanisms), 3.0), dpi=dpi,
                             squeeze=False)
    drawings = []
    for ax, mech, title in zip(axes[0], mechanisms, list(titles) + [None] * len(mechanisms)):
        drawing = drawing_class(mech)(ax, mech, trace=trace, n=n)
        drawing.autoscale()
        if title:
            ax.set_title(title, fontsize=9)
        drawings.append(drawing)

    def frame(i):
        return [artist for drawing in drawings for artist in drawing.set_frame(i)]

    anim = Animation(fig, frame, frames=n, interval=interval, blit=False)
    anim.drawings = drawings
    plt.close(fig)
    return anim


def plot_law(motion: Motion, axes=None, label: str | None = None, **style):
    """Plot the output law and its two analogs against φ in degrees on three axes."""
    if axes is None:
        _, axes = plt.subplots(3, 1, sharex=True, figsize=(6, 6))
    out = motion.output
    law = (out.value, out.d, out.dd)
    names = (out.name, out.name + "′", out.name + "″")
    deg = np.degrees(motion.phi)
    lines = []
    for ax, y, name in zip(axes, law, names):
        lines.append(ax.plot(deg, y, label=label, **style)[0])
        ax.set_ylabel(name)
        ax.grid(True, alpha=0.3)
    axes[-1].set_xlabel("φ, degrees")
    return lines
