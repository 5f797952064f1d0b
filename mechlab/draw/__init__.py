"""Matplotlib drawings of mechanisms whose artists are created once and moved in place.

A drawing is bound to an axes and a mechanism; :meth:`LinkageDrawing.set_motion`
hands it the arrays of a whole cycle (computed once by ``mechanism.motion``), and
:meth:`LinkageDrawing.set_frame` moves every artist to frame i without creating
any new artist. A drawing is a labelled kinematic diagram: joint letters (the names
of the mechanism's points: O, A, B, …), link numbers (1, 2, … for the moving links,
the next number for the frame, as Kozhevnikov numbers them for the instantaneous
centres), fixed pivots on hatched supports, and, on request, link lengths; all of
them move in place with the frame. :func:`animate` turns a drawing into a
``FuncAnimation`` whose ``to_jshtml()`` plays in a static page: at least
:data:`MIN_WIDTH_PX` wide, with palette-quantised PNG frames so that a page stays
small. What is drawn comes from the mechanism's ``sketch()`` (its links, pairs and the parts a
family adds); no family registers a drawing.
"""

from __future__ import annotations

import base64
import html
import io
import re
from pathlib import Path
from tempfile import TemporaryDirectory

import matplotlib as mpl
import matplotlib.pyplot as plt
import numpy as np
from matplotlib.animation import FuncAnimation, HTMLWriter
from matplotlib.backends.backend_agg import FigureCanvasAgg
from PIL import Image

from ..errors import MechanismError
from ..mechanisms.base import FRAME, Mechanism
from ..motion import Motion
from .access import CATEGORY_COLOURS, OKABE_ITO, alt_text, category_style, set_alt

# Okabe and Ito's colour-blind-safe colours for every "C0", "C1", ... and every default line colour
mpl.rcParams["axes.prop_cycle"] = mpl.cycler(color=list(CATEGORY_COLOURS))

LINK_STYLE = dict(color="#1f4e79", lw=3, solid_capstyle="round", zorder=3)
JOINT_STYLE = dict(ls="none", marker="o", ms=6, mfc="white", mec="#1f4e79", mew=1.5, zorder=4)
PIVOT_STYLE = dict(ls="none", marker="o", ms=7, mfc="white", mec="#333333", mew=1.5, zorder=4)
GROUND_STYLE = dict(color="#333333", lw=1.2, solid_capstyle="butt", zorder=1.5)
LETTER_STYLE = dict(fontsize=12, fontweight="bold", fontstyle="italic", color="#111111", ha="center",
                    va="center", zorder=7)
NUMBER_STYLE = dict(fontsize=9, color="#1f4e79", ha="center", va="center", zorder=7,
                    bbox=dict(boxstyle="circle,pad=0.2", fc="white", ec="#1f4e79", lw=0.8))
DIMENSION_STYLE = dict(fontsize=8, color="#555555", ha="center", va="center", zorder=6)
READOUT_STYLE = dict(fontsize=11, ha="right", va="bottom", zorder=7,
                     bbox=dict(boxstyle="round,pad=0.25", fc="white", ec="0.7", alpha=0.85))
LETTER_OFFSET = 11.0   # points from the joint to the centre of its letter
NUMBER_OFFSET = 10.0   # points from a link's middle to its number
LABEL_GAP = 14.0       # points between the centres of two labels at least (a circled number is about 13 wide)
TRACE_STYLE = dict(color=OKABE_ITO["vermillion"], lw=1, alpha=0.8, zorder=1)
EXTRA_STYLE = dict(color="#2a7f62", lw=2.5, zorder=2)
# a moving output drawn as an extra (a slotted bar, a block), a fixed guide, and the output
# re-drawn over itself while it dwells: green then means "standing still"
OUTPUT_STYLE = dict(color="#1f4e79", lw=2, solid_capstyle="round", zorder=3)
GUIDE_STYLE = dict(color="#555555", lw=1.5, zorder=2)
HIGHLIGHT_STYLE = dict(color="#2a7f62", lw=4.5, alpha=0.9, solid_capstyle="round", zorder=5)

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


# the frame slider has no label of its own: a screen reader would announce a bare "slider"
_UNLABELLED_SLIDER = re.compile(r'<input (?![^>]*aria-label)([^>]*class="anim-slider")')


def local_animation_controls(html: str) -> str:
    """matplotlib's animation HTML without the remote Font Awesome stylesheet: the buttons'
    icons become ``mechlab-icon mechlab-<name>`` classes drawn by an inline style, and the
    frame slider gets an accessible name."""
    html = _UNLABELLED_SLIDER.sub(r'<input aria-label="Frame of the animation" \1', html)
    if not _REMOTE_FONT_AWESOME.search(html) and not _FA_CLASS.search(html):
        return html

    def rename(match: re.Match) -> str:
        name = "play-backwards" if "fa-flip-horizontal" in match.group(0) else match.group(1)
        return f'class="mechlab-icon mechlab-{name}"'

    return _ICON_STYLE + _FA_CLASS.sub(rename, _REMOTE_FONT_AWESOME.sub("", html))


MIN_WIDTH_PX = 640   # an animation's frames are at least this wide (pixels) …
MAX_WIDTH_PX = 784   # … and at most the book's column, whatever the figure's size and dpi
PALETTE = 64         # colours of a frame: line drawings lose nothing visible, a frame shrinks 3-5×


def frame_dpi(fig) -> float:
    """The dpi at which ``fig`` is MIN_WIDTH_PX to MAX_WIDTH_PX wide (its own dpi if it already is);
    a figure of several panels takes the whole column."""
    width = fig.get_figwidth()
    if len(fig.axes) > 1:
        return MAX_WIDTH_PX / width
    return float(np.clip(width * fig.dpi, MIN_WIDTH_PX, MAX_WIDTH_PX)) / width


def quantised_png(rgba) -> bytes:
    """An RGBA buffer as a PNG of :data:`PALETTE` colours (line drawings lose nothing visible)."""
    image = Image.fromarray(np.asarray(rgba)[..., :3])
    frame = io.BytesIO()
    image.quantize(PALETTE, method=Image.Quantize.FASTOCTREE, dither=Image.Dither.NONE).save(frame, format="png")
    return frame.getvalue()


class PaletteHTMLWriter(HTMLWriter):
    """matplotlib's HTMLWriter, embedding frames handed to :meth:`add_frame` as quantised PNGs."""

    def add_frame(self, rgba):
        self._saved_frames.append(base64.encodebytes(quantised_png(rgba)).decode("ascii"))


class Animation(FuncAnimation):
    """A FuncAnimation whose ``to_jshtml()`` loads nothing from another host and embeds
    quantised frames between :data:`MIN_WIDTH_PX` and :data:`MAX_WIDTH_PX` wide.

    The frames are blitted: what does not move (the axes of a law, the guides, the titles)
    is drawn once, then each frame restores it and draws only the artists its frame
    function returns, so a larger frame is not a slower one.
    """

    def to_jshtml(self, fps=None, embed_frames=True, default_mode=None) -> str:
        if not hasattr(self, "_html_representation"):
            fps = 1000 / self._interval if fps is None else fps
            default_mode = default_mode or ("loop" if getattr(self, "_repeat", False) else "once")
            writer = PaletteHTMLWriter(fps=fps, embed_frames=True, default_mode=default_mode)
            with TemporaryDirectory() as tmp:
                path = Path(tmp, "animation.html")
                writer.setup(self._fig, path, dpi=frame_dpi(self._fig))
                self._blit_frames(writer)
                writer.finish()
                text = local_animation_controls(path.read_text())
                # the figure's alternative text on the frames' <img>: the book's pages and the PDF carry it
                described = alt_text(self._fig)
                alt = html.escape(f"{described} Animation of {self._n_frames} frames; the buttons "
                                  "below it play, pause and step it.".strip(), quote=True)
                text = text.replace('<img id="_anim_img', f'<img alt="{alt}" id="_anim_img', 1)
                # matplotlib names every animation's mode form "Repetition mode": two on a page would be landmarks
                # of one name; each is named after its figure's subject (the first sentence of the alt text)
                subject = described.split(". ")[0].split(", moving")[0].removesuffix(".") or "the animation"
                subject = html.escape(subject if len(subject) <= 90 else subject[:90].rsplit(" ", 1)[0] + " …",
                                      quote=True)
                self._html_representation = text.replace('aria-label="Repetition mode"',
                                                         f'aria-label="Repetition mode of: {subject}"', 1)
        return self._html_representation

    def _blit_frames(self, writer: PaletteHTMLWriter):
        fig = self._fig
        own_canvas, own_dpi = fig.canvas, fig.dpi
        canvas = FigureCanvasAgg(fig)   # off screen, whatever the backend (an ipympl canvas would send it)
        fig.set_dpi(writer.dpi)
        frames = list(self.new_saved_frame_seq())
        self._n_frames = len(frames)
        moving = list(dict.fromkeys(self._func(frames[0], *self._args)))
        animated = [artist.get_animated() for artist in moving]
        try:
            for artist in moving:
                artist.set_animated(True)
            canvas.draw()   # the background: everything that does not move
            background = canvas.copy_from_bbox(fig.bbox)
            for frame in frames:
                canvas.restore_region(background)
                for artist in self._func(frame, *self._args):
                    if artist.get_visible() and artist.axes is not None:
                        artist.axes.draw_artist(artist)
                    elif artist.get_visible():
                        fig.draw_artist(artist)
                writer.add_frame(canvas.buffer_rgba())
        finally:
            for artist, was in zip(moving, animated, strict=False):
                artist.set_animated(was)
            fig.set_dpi(own_dpi)
            fig.set_canvas(own_canvas)


def drawing_class(mechanism) -> type:
    """The drawing of an object: a force plan for a :class:`mechlab.kinetostatics.Kinetostatics`, a 3-D
    view for a ``spatial`` mechanism, else the one :class:`LinkageDrawing`, which draws what the
    mechanism's ``sketch()`` describes (no family is registered anywhere)."""
    from ..kinetostatics.machines import Kinetostatics

    if isinstance(mechanism, Kinetostatics):
        from .forces import ForcePlanDrawing
        return ForcePlanDrawing
    if getattr(mechanism, "spatial", False):   # the one spatial family, the spherical Geneva
        from .geneva import SphericalGenevaDrawing
        return SphericalGenevaDrawing
    return LinkageDrawing


# the style of each role a mechanism's sketch names (mechlab.mechanisms.base.Part)
ROLE_STYLES = {
    "link": LINK_STYLE, "extra": EXTRA_STYLE, "output": OUTPUT_STYLE, "guide": GUIDE_STYLE,
    "highlight": HIGHLIGHT_STYLE, "anchor": dict(visible=False),
    "slot": dict(color="#2a7f62", lw=5, alpha=0.45, solid_capstyle="round", zorder=2),
    "slot centre": dict(color="#2a7f62", lw=2, zorder=2), "dwell": dict(color="#e08214", lw=3.5, zorder=2.5),
    "flank": dict(color="#777777", lw=0.8, zorder=1.5), "arm": dict(EXTRA_STYLE, lw=4, alpha=0.5),
    "wheel": dict(color="#2a7f62", lw=1.6, zorder=2), "lock": dict(color="#b8860b", lw=2.2, zorder=2),
    "profile": dict(color="#2a7f62", lw=2, zorder=2), "fill": dict(color="#2a7f62", alpha=0.15, lw=0, zorder=1),
    "base circle": dict(color="#2a7f62", lw=0.8, ls="--", zorder=1.5),
    "roller": dict(color="#1f4e79", lw=1.5, zorder=4), "normal": dict(color="#d62728", lw=1, ls=":", zorder=3.5),
}
NOTE_STYLE = dict(va="top", color="#e08214", fontweight="bold")


class LinkageDrawing:
    """A labelled kinematic diagram of what ``mechanism.sketch(motion)`` describes: bars, the parts a
    family adds (guides, blocks, slots, wheels, cam profiles, each styled by its role), joints, hatched
    fixed pivots, joint letters, link numbers, an optional traced point and optional link lengths.

    Parameters: ``ax`` the axes; ``mechanism`` a mechanism; ``trace`` the name of a joint whose path
    over the cycle is drawn; ``labels`` joint letters and link numbers (on by default); ``ground`` the
    hatched supports of the fixed pivots (on by default); ``dimensions`` each bar's length beside it;
    ``readout`` the crank angle φ in degrees above the axes. Every artist is made once and moved by
    :meth:`set_frame`; a mechanism of another family re-uses and re-styles them.
    """

    def __init__(self, ax, mechanism: Mechanism, trace: str | None = None, n: int = 361, *, labels: bool = True,
                 ground: bool = True, dimensions: bool = False, readout: bool = False):
        self.ax = ax
        self.trace_name = trace
        self.n = n
        self.show_labels, self.show_ground, self.show_dimensions = labels, ground, dimensions
        ax.set_aspect("equal")
        self.link_lines = []     # one per bar of the sketch
        self.extra_lines = []    # one per other polyline part, styled by its role
        self.fills = []          # filled outlines (a cam's body)
        self.note = None         # a text in the corner ("dwell")
        self._roles = {}         # the role each line is styled for
        (self.trace_line,) = ax.plot([], [], **TRACE_STYLE)
        (self.ground_line,) = ax.plot([], [], **GROUND_STYLE)
        (self.pivot_marks,) = ax.plot([], [], **PIVOT_STYLE)
        (self.joint_marks,) = ax.plot([], [], **JOINT_STYLE)
        self.letters: dict[str, plt.Annotation] = {}
        self.numbers: list[plt.Annotation] = []
        self.lengths: list[plt.Annotation] = []
        # above the axes, at the right: out of the drawing's way
        self.readout = ax.text(1.0, 1.01, "", transform=ax.transAxes, **READOUT_STYLE) if readout else None
        self.mechanism = None
        self.motion = None
        self.sketch = None
        self.set_mechanism(mechanism)

    # -- binding -------------------------------------------------------------------
    def set_mechanism(self, mechanism: Mechanism, phi=None) -> Motion:
        """Bind a (new) mechanism, compute its cycle once, and show frame 0."""
        phi = mechanism.cycle(self.n) if phi is None else phi
        return self.set_motion(mechanism, mechanism.motion(phi))

    def set_motion(self, mechanism: Mechanism, motion: Motion) -> Motion:
        self.mechanism, self.motion = mechanism, motion
        self.sketch = mechanism.sketch(motion)
        parts = self.sketch.parts
        self.bars = [p for p in parts if isinstance(p.at, tuple)]
        self.drawn = [p for p in parts if not isinstance(p.at, tuple) and p.role not in ("fill", "note")]
        self.filled = [p for p in parts if p.role == "fill"]
        self.noted = [p for p in parts if p.role == "note"]
        self._make_artists()
        if self.trace_name:
            p = motion.points[self.trace_name].p
            self.trace_line.set_data(p[:, 0], p[:, 1])
        self._ground_size = 0.045 * float(np.nanmax(np.ptp(np.concatenate([v.p for v in motion.points.values()]),
                                                           axis=0)) or 1.0)
        self._make_labels()
        self.set_frame(0)
        return motion

    def _make_artists(self):
        """Lines for the bars and parts (made when a sketch brings more than the last one, hidden when
        it brings fewer), each styled by its part's role."""
        ax = self.ax
        while len(self.link_lines) < len(self.bars):
            self.link_lines.append(ax.plot([], [], **LINK_STYLE)[0])
        while len(self.extra_lines) < len(self.drawn):
            self.extra_lines.append(ax.plot([], [])[0])
        while len(self.fills) < len(self.filled):
            self.fills.append(ax.fill([], [])[0])
        if self.noted and self.note is None:
            self.note = ax.text(0.02, 0.95, "", transform=ax.transAxes, **NOTE_STYLE)
        roles = [*(("link", p.role) for p in self.bars), *(("extra", p.role) for p in self.drawn),
                 *(("fill", "fill") for _ in self.filled)]
        artists = [*self.link_lines[:len(self.bars)], *self.extra_lines[:len(self.drawn)],
                   *self.fills[:len(self.filled)]]
        for artist, (kind, role) in zip(artists, roles, strict=False):
            if self._roles.get(artist) != role:   # restyled only when its role changes
                default = LINK_STYLE if kind == "link" else EXTRA_STYLE
                artist.set(**{"visible": True, **ROLE_STYLES.get(role, default)})
                self._roles[artist] = role
        for spare in (*self.link_lines[len(self.bars):], *self.extra_lines[len(self.drawn):],
                      *self.fills[len(self.filled):]):
            spare.set_visible(False)
            self._roles[spare] = None
        if self.note is not None:
            self.note.set_visible(bool(self.noted))

    def _make_labels(self):
        """Letters for every point, numbers for every moving link and the frame: made when a
        mechanism brings more of them than the last one, hidden when it brings fewer."""
        names = list(self.motion.points) if self.show_labels else []
        for name in names:
            if name not in self.letters:
                self.letters[name] = self.ax.annotate(name, (0, 0), xytext=(0, 0), textcoords="offset points",
                                                      **LETTER_STYLE)
        for name, text in self.letters.items():
            text.set_visible(name in names)
        self.numbered = [p for p in self.sketch.parts if p.number is not None]
        # the structure's numbering, which the centres and the force model share
        self.link_numbers = self.mechanism.structure().numbers() if self.numbered else {}
        unknown = [p.number for p in self.numbered if p.number not in self.link_numbers]
        if unknown:
            raise MechanismError(f"the sketch of {type(self.mechanism).__name__} numbers {unknown}, not links of its "
                                 f"structure ({', '.join(k for k in self.link_numbers if k != FRAME)})")
        parts = len(self.numbered)
        count = parts + 1 if self.show_labels and parts else 0   # no moving link numbered: no frame number
        while len(self.numbers) < count:
            self.numbers.append(self.ax.annotate("", (0, 0), xytext=(0, 0), textcoords="offset points",
                                                 **NUMBER_STYLE))
        for k, text in enumerate(self.numbers):
            text.set_visible(k < count)
        count = len(self.bars) if self.show_dimensions else 0
        while len(self.lengths) < count:
            self.lengths.append(self.ax.annotate("", (0, 0), xytext=(0, 0), textcoords="offset points",
                                                 **DIMENSION_STYLE))
        for k, text in enumerate(self.lengths):
            text.set_visible(k < count)

    # -- frames --------------------------------------------------------------------
    def set_frame(self, i: int):
        """Move every artist to frame i of the bound motion; returns the artists."""
        points = self.motion.points
        pts = {k: v.p[i] for k, v in points.items()}
        for line, part in zip(self.link_lines, self.bars, strict=False):
            xy = part.points(points, i)
            line.set_data(xy[:, 0], xy[:, 1])
        pivots = self.sketch.pivots
        piv = np.array([pts[k] for k in pivots if k in pts]).reshape(-1, 2)
        self.pivot_marks.set_data(piv[:, 0], piv[:, 1])
        if self.show_ground:
            self.ground_line.set_data(*ground_symbols(piv, self._ground_size).T)
        moving = np.array([v for k, v in pts.items() if k not in pivots] or [[np.nan, np.nan]])
        self.joint_marks.set_data(moving[:, 0], moving[:, 1])
        for line, seg in zip(self.extra_lines, self.extras(i), strict=False):
            line.set_data(seg[:, 0], seg[:, 1])
        for patch, part in zip(self.fills, self.filled, strict=False):
            patch.set_xy(part.at(i))
        if self.noted:
            self.note.set_text(self.noted[0].at(i))
        if self.show_labels:
            self._place_labels(i, pts, piv)
        if self.show_dimensions:
            self._place_lengths(pts)
        if self.readout is not None:
            self.readout.set_text(f"φ = {np.degrees(self.motion.phi[i]):.0f}°")
        return self.artists

    def _place_labels(self, i, pts, piv):
        finite = np.array([p for p in pts.values() if np.all(np.isfinite(p))] or [[0.0, 0.0]])
        centre = finite.mean(axis=0)
        for name, p in pts.items():
            away = _unit(p - centre, fallback=(-0.7, 0.7))
            if name in self.sketch.pivots:   # the support is below a pivot: its letter above it
                away = _unit(np.array([away[0], max(away[1], 0.6)]))
            text = self.letters[name]
            text.xy = p
            text.set_position(LETTER_OFFSET * away)
        parts = self.numbered_parts(i)
        for text, part, spec in zip(self.numbers, parts, self.numbered, strict=False):
            where, normal = _label_anchor(part, centre)
            text.set_text(str(self.link_numbers[spec.number]))
            text.xy = where
            text.set_position(NUMBER_OFFSET * normal)
        if not parts:
            return
        frame = self.numbers[len(parts)]
        frame.set_text(str(self.link_numbers[FRAME]))
        if len(piv):   # beside the hatching of the fixed pivot farthest out: clear of the crank's numbers at O
            far = piv[np.argmax(np.hypot(*(piv - centre).T))]
            frame.xy = far + np.array([-1.9, -1.7]) * self._ground_size
            frame.set_position((0.0, 0.0))
        frame.set_visible(bool(len(piv)))
        self._separate_numbers()

    def _separate_numbers(self):
        """Move each link number that would sit on a joint letter or on a number placed before it further
        out, along its own side of its link (the frame's number: down and left, away from its pivot), so
        that the frame's and the crank's numbers at O, or the numbers of a small drawing, stay apart."""
        to_px, scale = self.ax.transData.transform, self.ax.figure.dpi / 72.0
        taken = [to_px(t.xy) + scale * np.asarray(t.get_position(), float)
                 for t in self.letters.values() if t.get_visible() and np.all(np.isfinite(t.xy))]
        for text in self.numbers:
            if not text.get_visible() or not np.all(np.isfinite(text.xy)):
                continue
            anchor, offset = to_px(text.xy), np.asarray(text.get_position(), float)
            step = 0.5 * LABEL_GAP * _unit(offset, fallback=(-0.7, -0.7))
            for _ in range(8):   # a few steps out at most: a label never wanders far from its link
                where = anchor + scale * offset
                if all(np.hypot(*(where - other)) >= scale * LABEL_GAP for other in taken):
                    break
                offset = offset + step
            text.set_position(tuple(offset))
            taken.append(anchor + scale * offset)

    def _place_lengths(self, pts):
        for text, bar in zip(self.lengths, self.bars, strict=False):
            names = bar.at
            a, b = pts[names[0]], pts[names[1]]
            where, normal = _label_anchor(np.array([a, b]), None)
            text.set_text(f"{names[0]}{names[1]} = {np.hypot(*(b - a)):.3g}")
            text.xy = where
            text.set_position(-NUMBER_OFFSET * normal)

    def numbered_parts(self, i: int) -> list[np.ndarray]:
        """The numbered parts of the sketch (bars, blocks, …) in the order of their numbers, each as a
        polyline at frame i."""
        return [part.points(self.motion.points, i) for part in self.numbered]

    def extras(self, i: int) -> list[np.ndarray]:
        """The polylines of the sketch's parts beyond the bars (guides, slots, sliders) at frame i."""
        return [np.asarray(part.at(i), dtype=float).reshape(-1, 2) for part in self.drawn]

    def lines_of(self, role: str) -> list:
        """The lines drawing the parts of one role (e.g. "slot"), in the sketch's order."""
        return [line for line, part in zip(self.extra_lines, self.drawn, strict=False) if part.role == role]

    @property
    def label_artists(self):
        return [*self.letters.values(), *self.numbers, *self.lengths]

    @property
    def artists(self):
        return [*self.fills, *self.link_lines, *self.extra_lines, self.trace_line, self.ground_line,
                self.pivot_marks, self.joint_marks, *self.label_artists,
                *([self.note] if self.note is not None else []), *([self.readout] if self.readout is not None else [])]

    def bounds(self, margin: float = 0.15):
        """(xmin, xmax, ymin, ymax) enclosing every joint over the cycle and the parts at nine frames
        along it, with a margin."""
        frames = np.unique(np.linspace(0, len(self.motion) - 1, 9).astype(int))
        allp = np.concatenate([v.p for v in self.motion.points.values()]
                              + [seg for j in frames for seg in self.extras(j)]
                              + [np.asarray(part.at(j)) for j in frames for part in self.filled])
        lo, hi = np.nanmin(allp, axis=0), np.nanmax(allp, axis=0)
        pad = margin * max(hi - lo) + 1e-9
        return lo[0] - pad, hi[0] + pad, lo[1] - pad, hi[1] + pad

    def autoscale(self):
        fill_axes(self.ax, self.bounds())


def fill_axes(ax, bounds):
    """Set equal-aspect limits that hold ``bounds`` (x0, x1, y0, y1) and fill the axes' box: the
    shorter side of the bounds is widened to the box's proportions, so that the drawing is as
    large as the axes allow instead of the box shrinking to a band."""
    x0, x1, y0, y1 = bounds
    box = ax.get_position(original=True)   # the box before an equal aspect shrank it
    fig_w, fig_h = ax.figure.get_size_inches()
    ratio = (box.height * fig_h) / (box.width * fig_w)   # height / width of the box
    w, h = x1 - x0, y1 - y0
    if h < ratio * w:
        y0, y1 = (y0 + y1) / 2 - ratio * w / 2, (y0 + y1) / 2 + ratio * w / 2
    else:
        x0, x1 = (x0 + x1) / 2 - h / ratio / 2, (x0 + x1) / 2 + h / ratio / 2
    ax.set_xlim(x0, x1)
    ax.set_ylim(y0, y1)


def _unit(v, fallback=(0.0, 1.0)) -> np.ndarray:
    norm = float(np.hypot(*v))
    return np.asarray(fallback, dtype=float) / np.hypot(*fallback) if not norm > 1e-12 else np.asarray(v) / norm


def _label_anchor(part: np.ndarray, centre) -> tuple[np.ndarray, np.ndarray]:
    """Where a link's number goes: the middle of a bar (then the unit normal pointing away from
    ``centre``) or the centroid of a closed polyline (a block, a triangle: no offset)."""
    part = part[np.all(np.isfinite(part), axis=1)]
    if len(part) == 0:
        return np.array([np.nan, np.nan]), np.zeros(2)
    if len(part) > 2 and np.allclose(part[0], part[-1]):
        return part[:-1].mean(axis=0), np.zeros(2)
    a, b = part[0], part[1] if len(part) > 1 else part[0]
    mid = (a + b) / 2
    normal = _unit(np.array([a[1] - b[1], b[0] - a[0]]))
    if centre is not None and np.dot(mid - centre, normal) < 0:
        normal = -normal
    return mid, normal


def ground_symbols(pivots: np.ndarray, size: float) -> np.ndarray:
    """Polylines (NaN-separated) of the frame's symbol under each fixed pivot: a support
    triangle with its apex at the pivot, a base line and five hatch strokes below it."""
    pieces = []
    for x, y in np.asarray(pivots, dtype=float).reshape(-1, 2):
        base = y - 1.4 * size
        pieces += [[x, y], [x - 0.8 * size, base], [x + 0.8 * size, base], [x, y], [np.nan, np.nan],
                   [x - 1.3 * size, base], [x + 1.3 * size, base], [np.nan, np.nan]]
        for t in np.linspace(-1.1, 1.3, 5) * size:
            pieces += [[x + t, base], [x + t - 0.5 * size, base - 0.5 * size], [np.nan, np.nan]]
    return np.array(pieces or [[np.nan, np.nan]])


def _diagram_axes(ax):
    """A kinematic diagram has no axes frame or ticks (the letters, numbers and lengths say
    what it shows), and tick labels cost most of an animation frame's rendering."""
    ax.set_axis_off()


def draw(mechanism, phi: float = 0.0, ax=None, trace: str | None = None, *, labels: bool = True,
         ground: bool = True, dimensions: bool = False):
    """Draw a mechanism at crank angle φ (radians) as a labelled kinematic diagram: joint
    letters and link numbers (``labels``), hatched fixed pivots (``ground``), and with
    ``dimensions`` the links' lengths; ``trace`` names a joint whose whole path is drawn.
    Returns the drawing."""
    own = ax is None
    if own:
        _, ax = plt.subplots(figsize=(6.5, 5))
    drawing = drawing_class(mechanism)(ax, mechanism, trace=trace, labels=labels, ground=ground,
                                       dimensions=dimensions)
    drawing.autoscale()
    motion = mechanism.motion(np.atleast_1d(phi))
    drawing.set_motion(mechanism, motion)
    if own:   # a figure of the caller's may hold more than this diagram: its caller describes it
        set_alt(ax.figure, diagram_alt(mechanism, motion)
                + (f" The path of joint {trace} over the cycle is traced." if trace else ""))
    if trace:   # the path over the whole cycle, not just the one position drawn
        drawing.trace_line.set_data(*mechanism.motion(mechanism.cycle(361)).points[trace].p.T)
    _diagram_axes(ax)
    return drawing


def _kind_words(mechanism) -> str:
    """A mechanism's class name as words: ``RollerCam`` → "roller cam"."""
    return re.sub(r"(?<=[a-z])(?=[A-Z])", " ", type(mechanism).__name__).lower()


# what a student reads above a mechanism's drawing, by the name of its class (the course's words, its sources cited)
MECHANISM_NAMES = {
    "FourBar": "Four-bar linkage",
    "SliderCrank": "Slider-crank",
    "SixBarIV": "Six-bar of type IV (Zinchenko et al., 2013)",
    "SineMechanism": "Sine mechanism (slotted yoke)",
    "SlottedLink": "Slotted link",
    "EllipticTrammel": "Elliptic trammel",
    "Antiparallelogram": "Crossed antiparallelogram",
    "CurvedSlotLink": "Curved-slot link",
    "TranslatingCurvedSlot": "Translating curved slot",
    "DwellSlotMechanism": "Curved-slot dwell mechanism",
    "ExternalGeneva": "External Geneva drive",
    "InternalGeneva": "Internal Geneva drive",
    "SphericalGeneva": "Spherical Geneva drive",
    "GuidedLambda": "Chebyshev lambda mechanism",
    "LambdaRockerSixBar": "Lambda six-bar with rocker output",
    "LambdaSlottedSixBar": "Lambda six-bar with slotted output",
    "LambdaSliderSixBar": "Lambda six-bar with slider output",
    "LambdaTranslatingSlot": "Lambda six-bar with translating slot",
}


def mechanism_name(mechanism) -> str:
    """What to call ``mechanism`` above its drawing or in a legend, in words ("Four-bar linkage"): its own
    ``display_name`` if it has one, else the course's name of its family (:data:`MECHANISM_NAMES`), else its
    class name as words, capitalised — never a bare class name such as ``SixBarIV``.

    Examples
    --------
    >>> from mechlab.mechanisms.fourbar import FourBar
    >>> mechanism_name(FourBar(0.3, 0.8, 1.0, 1.0))
    'Four-bar linkage'
    """
    own = getattr(mechanism, "display_name", None)
    if isinstance(own, str) and own:
        return own
    name = MECHANISM_NAMES.get(type(mechanism).__name__)
    if name is None:
        words = _kind_words(mechanism)
        name = words[:1].upper() + words[1:]
    return name


def diagram_alt(mechanism, motion, law: bool = False) -> str:
    """The alternative text of a kinematic diagram of ``mechanism`` drawn over ``motion``: what it is,
    its joints, the crank angle (or the cycle) and the output's range (the law beside it with ``law``)."""
    deg = np.degrees(np.atleast_1d(np.asarray(motion.phi, float)))
    points = getattr(motion, "points", None)
    joints = f" with joints {', '.join(points)}" if points else ""
    kind = _kind_words(mechanism)
    text = f"Kinematic diagram of {'an' if kind[:1] in 'aeiou' else 'a'} {kind}{joints}"
    text += (f", drawn at crank angle φ = {deg[0]:.0f}°." if deg.size == 1
             else f", moving over one cycle, crank angle φ from {deg[0]:.0f}° to {deg[-1]:.0f}°.")
    if getattr(motion, "output", None) is not None and deg.size > 1:
        y, label = law_of(motion)
        text += (f"{' Beside it, the' if law else ' The'} {label} against φ: from {np.min(y):.3g} to {np.max(y):.3g},"
                 f" a stroke of {np.ptp(y):.3g}.")
    return text


def law_of(motion: Motion) -> tuple[np.ndarray, str]:
    """The output law for a plot: ψ in degrees (continuous) or s, with its axis label."""
    out = motion.output
    if out.kind == "angle":
        return np.degrees(np.unwrap(out.value)), f"output {out.name} (degrees)"
    return out.value, f"output {out.name} (length units of the mechanism)"


def animate(mechanism, n: int = 48, interval: int = 80, trace: str | None = None, ax=None,
            figsize=(6.5, 4.5), *, law: bool = False, labels: bool = True, dimensions: bool = False) -> Animation:
    """A FuncAnimation of one cycle in n frames, a labelled diagram with the crank angle φ in
    a corner; with ``law`` the output law ψ(φ) (or s(φ)) beside it, a marker running along
    it in step. The figure is closed, so only the animation is shown: play it in a page with
    ``HTML(anim.to_jshtml())`` (frames 640-784 px wide whatever ``figsize``)."""
    own = ax is None
    if own:
        if law:
            fig, (ax, ax_law) = plt.subplots(1, 2, figsize=(max(figsize[0], 9.0), figsize[1]),
                                             gridspec_kw={"width_ratios": [1.2, 1]})
        else:
            fig, ax = plt.subplots(figsize=figsize)
    else:
        fig = ax.figure
        ax_law = ax.inset_axes([1.08, 0.1, 0.8, 0.8]) if law else None
    drawing = drawing_class(mechanism)(ax, mechanism, trace=trace, n=n, labels=labels, dimensions=dimensions,
                                       readout=True)
    drawing.autoscale()
    _diagram_axes(ax)
    step, marker = drawing.set_frame, None
    if law:
        y, label = law_of(drawing.motion)
        deg = np.degrees(drawing.motion.phi)
        dense, _ = law_of(mechanism.motion(mechanism.cycle(361)))   # the curve smooth, the marker on it
        ax_law.plot(np.degrees(mechanism.cycle(361)), dense + (y[0] - dense[0]), color="#1f4e79", lw=1.8)
        (marker,) = ax_law.plot([], [], "o", ms=8, color=OKABE_ITO["vermillion"], zorder=5)
        ax_law.set_xlabel("crank angle φ (degrees)")
        ax_law.set_ylabel(label)
        ax_law.grid(True, alpha=0.3)
        fig.tight_layout()

        def step(i):
            marker.set_data([deg[i]], [y[i]])
            return [*drawing.set_frame(i), marker]
    if own:
        set_alt(fig, diagram_alt(mechanism, drawing.motion, law=law))
    anim = Animation(fig, step, frames=n, interval=interval, blit=False)
    anim.drawing = drawing
    anim.marker = marker
    plt.close(fig)
    return anim


def animate_together(mechanisms, titles=(), n: int = 24, interval: int = 150, trace: str | None = None,
                     figsize=None, dpi: int = 80, *, labels: bool = True, same_scale: bool = True) -> Animation:
    """One animation of several mechanisms side by side, frame i of each at the same fraction
    of its cycle (the same crank angle for mechanisms whose crank turns fully), so that their
    motions can be compared; one panel per mechanism, ``titles`` above them, each with its
    crank angle. With ``same_scale`` every panel draws at one scale, each as wide as its mechanism
    sweeps: a mechanism whose output swings far gets the room it needs instead of shrinking in a
    panel of the others' width."""
    mechanisms = list(mechanisms)
    fig, axes = plt.subplots(1, len(mechanisms), figsize=figsize or (3.2 * len(mechanisms), 3.2), dpi=dpi,
                             squeeze=False)
    drawings = []
    for ax, mech, title in zip(axes[0], mechanisms, list(titles) + [None] * len(mechanisms), strict=False):
        drawing = drawing_class(mech)(ax, mech, trace=trace, n=n, labels=labels, readout=True)
        _diagram_axes(ax)
        if title:
            ax.set_title(title, fontsize=11)
        drawings.append(drawing)
    boxes = np.array([d.bounds() for d in drawings])
    if same_scale and len(drawings) > 1 and np.all(np.isfinite(boxes)):
        # one height for all (the tallest), each panel's width in proportion to its mechanism's
        half = (boxes[:, 3] - boxes[:, 2]).max() / 2
        middle = (boxes[:, 2] + boxes[:, 3]) / 2
        boxes[:, 2], boxes[:, 3] = middle - half, middle + half
        grid = axes[0, 0].get_subplotspec().get_gridspec()
        grid.set_width_ratios(boxes[:, 1] - boxes[:, 0])
        for ax in axes[0]:
            ax.set_position(ax.get_subplotspec().get_position(fig))
    for drawing, box in zip(drawings, boxes, strict=False):
        fill_axes(drawing.ax, box)

    def frame(i):
        return [artist for drawing in drawings for artist in drawing.set_frame(i)]

    names = [title or _kind_words(mech)
             for mech, title in zip(mechanisms, list(titles) + [None] * len(mechanisms), strict=False)]
    set_alt(fig, f"{len(mechanisms)} kinematic diagrams side by side, moving in step over one cycle: "
            + "; ".join(names) + ".")
    anim = Animation(fig, frame, frames=n, interval=interval, blit=False)
    anim.drawings = drawings
    plt.close(fig)
    return anim


def plot_law(motion: Motion, axes=None, label: str | None = None, **style):
    """Plot the output law and its two analogs against φ in degrees on three axes: ψ in
    degrees, ψ′ = dψ/dφ (dimensionless) and ψ″ = d²ψ/dφ² (per radian); for a translating
    output s, s′ and s″ in the mechanism's length unit (per radian, per radian²)."""
    own = axes is None
    if own:
        _, axes = plt.subplots(3, 1, sharex=True, figsize=(7, 6))
    out = motion.output
    sym = out.name
    if out.kind == "angle":
        law = (np.degrees(np.unwrap(out.value)), out.d, out.dd)
        names = (f"{sym} (degrees)", f"{sym}′ = d{sym}/dφ (–)", f"{sym}″ = d²{sym}/dφ² (1/rad)")
    else:
        law = (out.value, out.d, out.dd)
        names = (f"{sym} (length)", f"{sym}′ = d{sym}/dφ (length/rad)", f"{sym}″ (length/rad²)")
    deg = np.degrees(motion.phi)
    lines = []
    for ax, y, name in zip(axes, law, names, strict=False):
        lines.append(ax.plot(deg, y, label=label, **style)[0])
        ax.set_ylabel(name)
        ax.grid(True, alpha=0.3)
    axes[-1].set_xlabel("crank angle φ (degrees)")
    if own:
        set_alt(axes[0].figure, f"Output law and its two analogs against crank angle φ, three panels: {names[0]} from "
                f"{np.min(law[0]):.3g} to {np.max(law[0]):.3g}; {names[1]} from {np.min(law[1]):.3g} to "
                f"{np.max(law[1]):.3g}; {names[2]} from {np.min(law[2]):.3g} to {np.max(law[2]):.3g}.")
    return lines


def plot_pressure_angles(lam, phi1, phi2, pivot_distance=1.0, n: int = 721, ax=None):
    """The pressure angle θ (degrees) of the curved-slot dwell mechanism (Zinchenko et al., 2013, §3) over
    a turn of the crank (φ in degrees), one line per transition law of
    :data:`~mechlab.synthesis.dwell_slot.TRANSITIONS`; the dwell [φ1, φ2] (radians) shaded, and lighter its
    mirror [360° - φ2, 360° - φ1], where the pin passes the same slot points. Returns the Figure."""
    from ..synthesis.dwell_slot import TRANSITIONS, curved_slot_dwell

    designs = [curved_slot_dwell(lam, phi1, phi2, pivot_distance, tr) for tr in TRANSITIONS]
    phi = designs[0].turn(n)
    if ax is None:
        _, ax = plt.subplots(figsize=(7, 2.8))
    for tr, m in zip(TRANSITIONS, designs, strict=False):
        ax.plot(np.degrees(phi), np.degrees(m.motion(phi).pressure_angle), label=tr)
    a, b = np.degrees(designs[0].phi1), np.degrees(designs[0].phi2)
    ax.axvspan(a, b, color="#e08214", alpha=0.12)
    ax.axvspan(360 - b, 360 - a, color="0.5", alpha=0.08)
    ax.set(xlabel="φ, degrees", ylabel="θ, degrees")
    ax.legend(fontsize=8)
    return ax.figure


def plot_slot(mechanism, ax=None):
    """The slot of a curved-slot dwell mechanism to cut, in the link's frame (B at the origin, lengths in
    units of l_OB): its centre line, the dwell arc (radius l_OA about O) and the flanks at ± the roller
    radius (:func:`mechlab.synthesis.slot_export.slot_profile`). Returns the Figure."""
    from ..synthesis.slot_export import slot_profile

    prof = slot_profile(mechanism)
    unit = mechanism.pivot_distance
    if ax is None:
        _, ax = plt.subplots(figsize=(8, 4.2))
    ax.plot(*prof.centre.T / unit, color="#2a7f62", lw=1)
    ax.plot(*mechanism.dwell_points().T / unit, color="#e08214", lw=3)
    for flank in (prof.left, prof.right):
        ax.plot(*flank.T / unit, "0.4", lw=0.8)
    ax.plot([0], [0], "^", color="0.3")
    ax.set_aspect("equal")
    ax.set_title("slot in the link's frame (B at the origin)", fontsize=10)
    ax.set(xlabel="x (units of $l_{OB}$)", ylabel="y (units of $l_{OB}$)")
    return ax.figure


def plot_cam_laws(names=None, n: int = 401):
    """Plot cam motion laws side by side, normalised (rise h = 1 over the interval Φ = 1):
    lift Y(x), velocity analog Y′(x) and acceleration analog Y″(x), x = φ/Φ; returns the Figure.

    Parameters
    ----------
    names : law names of :data:`mechlab.analysis.motion_laws.LAWS` (all of them when None).
    n : samples over the rise, at least 2.
    """
    from ..analysis.motion_laws import LAWS
    from ..errors import MechanismError
    from ..validate import check_value, count

    names = list(LAWS) if names is None else list(names)
    unknown = [name for name in names if name not in LAWS]
    if unknown or not names:
        raise MechanismError(f"law names = {unknown or names!r}: not among {', '.join(LAWS)}")
    x = np.linspace(0.0, 1.0, check_value("n", n, count(2)))
    fig, axes = plt.subplots(1, 3, figsize=(13, 3.9), layout="constrained")
    for name in names:
        for ax, y in zip(axes, LAWS[name](x), strict=False):
            ax.plot(x, y, label=name)
    labels = ("lift Y (fraction of h)", "velocity analog Y′", "acceleration analog Y″")
    for ax, label in zip(axes, labels, strict=False):
        ax.set_xlabel("x = φ / Φ (fraction of the rise)")
        ax.set_ylabel(label)
        ax.grid(alpha=0.3)
    # one legend for the three panels, above them: no curve of any panel under it
    fig.legend(handles=axes[0].lines, loc="outside upper center", ncols=min(len(names), 6), fontsize=9,
               frameon=False)
    return fig


def plot_cam_undercut(cams: dict, folded, n: int = 1441):
    """Why a roller cam undercuts: left, the convex radius of curvature ρ of each named cam's pitch
    curve against the cam angle, its roller radius r_r dotted (the roller fits where ρ > r_r); right,
    the pitch curve of ``folded`` and its offset by r_r, which folds over where ρ < r_r, the fold zoomed
    (the offset is the profile, ρ_profile = ρ − r_r; Kinitsky, 1994). Returns the Figure.

    Parameters
    ----------
    cams : name → roller cam, each drawn on the left.
    folded : the roller cam drawn on the right; it must undercut (its :meth:`undercut` is not None).
    n : design angles over the turn, at least 3.
    """
    from ..errors import MechanismError
    from ..mechanisms.cam import RollerCam
    from ..validate import check_value, count, mechanism

    n = check_value("n", n, count(3))
    folded = check_value("folded", folded, mechanism(RollerCam))
    if not isinstance(cams, dict) or not cams:
        raise MechanismError(f"cams must be a non-empty dict of name → roller cam, got {cams!r}")
    for name, cam in cams.items():
        check_value(f"cams[{name!r}]", cam, mechanism(RollerCam))
    cut = folded.undercut()
    if cut is None:
        raise MechanismError("folded: its roller fits the pitch curve everywhere, there is no fold to show")
    phi = np.linspace(0.0, 2 * np.pi, n)
    fig, axes = plt.subplots(1, 2, figsize=(12, 4.6))
    for name, cam in cams.items():
        k = cam.curvature(phi)
        axes[0].plot(np.degrees(phi), np.where(k > 0, 1 / np.maximum(k, 1e-9), np.nan), label=f"{name}: pitch ρ")
        axes[0].axhline(cam.roller_radius, ls=":", color=axes[0].lines[-1].get_color(), label=f"{name}: roller r_r")
    # from 0 to past every cam's sharpest convex part and its roller, leaving out the flat arcs
    sharpest = max(1 / np.max(cam.curvature(phi)) for cam in cams.values())
    top = max(1.5 * sharpest, 3 * max(cam.roller_radius for cam in cams.values()))
    axes[0].set(ylim=(0, top), xticks=range(0, 361, 60), xlabel="cam angle φ (degrees)",
                ylabel="radius of curvature, convex (length of the cam)")
    axes[0].legend(fontsize=8)
    axes[0].grid(alpha=0.3)
    bad = folded.profile(n, check=False)
    axes[1].plot(*bad.pitch.T, "--", color="#1f4e79", lw=1, label="pitch curve")
    axes[1].plot(*bad.surface.T, color="#d62728", lw=1.5, label="its offset by r_r: folds over")
    axes[1].set(aspect="equal", xlabel="x (length of the cam)", ylabel="y (length of the cam)")
    axes[1].legend(fontsize=8)
    # the zoom frames the profile over the fold's cam angles
    near = (bad.theta >= cut.where.min()) & (bad.theta <= cut.where.max())
    (x0, y0), (x1, y1) = bad.surface[near].min(axis=0), bad.surface[near].max(axis=0)
    pad = 0.25 * max(x1 - x0, y1 - y0)
    zoom = axes[1].inset_axes([0.62, 0.04, 0.36, 0.36])
    zoom.plot(*bad.surface.T, color="#d62728", lw=1.5)
    zoom.set(xlim=(x0 - pad, x1 + pad), ylim=(y0 - pad, y1 + pad), xticks=[], yticks=[], aspect="equal")
    zoom.set_title("the fold, zoomed", fontsize=8)
    fig.tight_layout()
    return fig


# kind → (marker, colour, legend): a marker shape per kind, so that no reader depends on the colour alone
OUTCOME_STYLE = {
    "design": ("o", OKABE_ITO["bluish green"], "equal-ripple design"), "frame": ("s", "0.75", "outside the span of a"),
    "resolution": ("v", OKABE_ITO["sky blue"], "ripple below resolution (< 10⁻⁹ l)"),
    "rotation": ("^", OKABE_ITO["orange"], "beyond the rotation limit"),
    "fold": ("D", OKABE_ITO["reddish purple"], "shorter than the fold"),
    "whole turn": ("P", OKABE_ITO["black"], "2α = 360° off the whole-turn line"),
    "unresolved": ("x", OKABE_ITO["vermillion"], "unresolved")}
SPAN_STYLE = dict(color=OKABE_ITO["vermillion"], ls="--", lw=1)


def plot_design_outcomes(maps):
    """Where :func:`mechlab.synthesis.lambda_guiding.circle_guiding` designs, one panel per
    :class:`~mechlab.synthesis.lambda_guiding.DesignOutcomes`: frame a against dwell 2α, a filled dot per design,
    an open marker per refusal kind, the span's ends dashed; returns the Figure.
    """
    from ..errors import MechanismError
    from ..synthesis.lambda_guiding import DesignOutcomes
    from ..validate import check_value, mechanism

    maps = list(maps) if isinstance(maps, list | tuple) else [maps]
    if not maps:
        raise MechanismError("maps must hold at least one DesignOutcomes")
    for i, m in enumerate(maps):
        check_value(f"maps[{i}]", m, mechanism(DesignOutcomes))
    # two panels a row and the legend in the next free cell, so each panel keeps half the column's width
    cols = 1 if len(maps) == 1 else 2
    rows = -(-(len(maps) + (cols == 2)) // cols)
    fig, grid = plt.subplots(rows, cols, figsize=(6.5 if cols == 1 else 9.5, 4.2 * rows), squeeze=False)
    axes, spare = grid.ravel()[:len(maps)], grid.ravel()[len(maps):]
    for ax in spare:
        ax.axis("off")
    for ax, m in zip(axes, maps, strict=False):
        for i, a in enumerate(m.a):
            for j, dw in enumerate(np.degrees(m.dwell)):
                marker, colour, _ = OUTCOME_STYLE[m.kind[i, j]]
                ax.plot(a, dw, marker, color=colour, ms=5, mfc=colour if m.kind[i, j] == "design" else "none")
        for edge in m.span:
            ax.axvline(edge, **SPAN_STYLE)
        ax.set_title(f"δ = {np.degrees(m.delta):.0f}°")
        ax.set_xlabel("frame a (units of l)")
        ax.set_ylabel("dwell 2α (degrees)")
        ax.set_ylim(-15, 375)
        ax.set_yticks(range(0, 361, 60))
    handles = [plt.Line2D([], [], marker=marker, ls="", color=colour, mfc=colour if kind == "design" else "none",
                          label=label) for kind, (marker, colour, label) in OUTCOME_STYLE.items()]
    handles.append(plt.Line2D([], [], **SPAN_STYLE, label="ends of the span of a"))
    if spare.size:
        spare[0].legend(handles=handles, loc="center", fontsize=10, title="each marker: one request")
    else:
        axes[-1].legend(handles=handles, fontsize=8, loc="center left", bbox_to_anchor=(1.02, 0.5))
    fig.tight_layout()
    panels = []
    for m in maps:
        kinds, counts = np.unique(m.kind, return_counts=True)
        tally = ", ".join(f"{c} {OUTCOME_STYLE[k][2]}"
                          for k, c in sorted(zip(kinds, counts, strict=False), key=lambda kc: -kc[1]))
        panels.append(f"δ = {np.degrees(m.delta):.0f}°: {tally}")
    return set_alt(fig, f"Outcome map of {m.kind.size} design requests per panel, frame a against dwell 2α, each "
                   f"marked by what the design returned (a marker shape per kind). {'; '.join(panels)}.")


ISO_DWELL_STYLES = tuple(category_style(i) for i in (0, 2, 3, 5, 6, 4, 7))   # vermillion, orange: the lines
COURSE_TRANSMISSION = (np.radians(40), np.radians(140))   # the course's limits of μ (chapter 0)


def plot_existence_map(em, delta: float, course=COURSE_TRANSMISSION):
    """Kinitsky's (1994) Fig. 2a redrawn from an :class:`~mechlab.synthesis.lambda_guiding.ExistenceMap`
    for break angle δ (radians): the existence region shaded, the rotation limits, the whole-turn and
    fifth-order lines, one curve per dwell, the thesis' transmission lines μ = 30°, 150° dotted and
    ``course`` = (μ_min, μ_max) (radians; None: left out) dashed, in the (r, a) plane (units of l).
    Returns the Figure."""
    from ..synthesis.lambda_guiding import transmission_lines

    fig, ax = plt.subplots(figsize=(9, 6.5))
    ax.fill(*em.region, color="#2a7f62", alpha=0.12, label="existence region")
    ax.plot(*em.rotation, "k", label="r = a, r + a = 2")
    ax.plot(*em.whole, color=OKABE_ITO["vermillion"], lw=2.5, label="2α = 360° (whole curve)")
    ax.plot(*em.fifth, color=OKABE_ITO["orange"], lw=1.5, ls=(0, (6, 2)), label="fifth-order contact")
    for (key, curve), style in zip(em.iso_dwell.items(), ISO_DWELL_STYLES, strict=False):
        ax.plot(*curve, **{**style, "ls": "-"}, ms=4, lw=1, label=f"2α = {key}°")
    ax.plot(*em.mu_min, "0.5", ls=":", label="μ = 30°, 150°")
    ax.plot(*em.mu_max, "0.5", ls=":")
    if course is not None:
        lines = transmission_lines(*course)
        label = f"μ = {np.degrees(course[0]):.0f}°, {np.degrees(course[1]):.0f}° (course)"
        ax.plot(*lines.mu_min, "0.6", ls="--", lw=1, label=label)
        ax.plot(*lines.mu_max, "0.6", ls="--", lw=1)
    ax.set(xlim=(0, 1), ylim=(0, 2), xlabel="r = l_OA / l", ylabel="a = l_OC / l",
           title=f"existence map, δ = {np.degrees(delta):.0f}° (after Kinitsky, 1994, Fig. 2a)")
    ax.legend(fontsize=9)
    return set_alt(fig, f"Existence map for break angle δ = {np.degrees(delta):.0f}° in the plane of crank r against "
                   f"frame a (units of l): the shaded existence region bounded by the rotation limits, the whole-turn "
                   f"line and the fifth-order-contact line, with curves of equal dwell 2α = "
                   f"{', '.join(f'{k}°' for k in em.iso_dwell)} inside it and the transmission-angle limits dotted.")
