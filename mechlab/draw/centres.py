"""Drawings for Kozhevnikov ch. 7: the elliptic trammel, the antiparallelogram, instantaneous
centres and centrodes that move with the linkage.

Centres at infinity are never drawn as far-away points: curves are masked there
(:func:`mechlab.analysis.centres.segments` / :meth:`Centre.masked`), and a pole at infinity is
shown by an arrow along its direction with the label "P∞".
"""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np

from ..analysis.centres import centrodes
from ..analysis.centres.centrodes import Centrodes
from ..analysis.centres.instant import InstantCentres
from . import Animation, drawing_class, fill_axes

FIXED_STYLE = dict(color="#8c564b", lw=1.6, zorder=1)
MOVING_STYLE = dict(color="#9467bd", lw=1.6, ls="--", zorder=2)
POLE_STYLE = dict(ls="none", marker="*", ms=13, color="#d62728", zorder=6)
CENTRE_STYLE = dict(ls="none", marker="x", ms=8, mew=2, color="#d62728", zorder=6)


class CentrodeOverlay:
    """Fixed centrode, moving centrode (carried by its link) and the pole, frame by frame.

    ``clip`` (default: 3 × the mechanism's size) cuts the curves where they run off to
    infinity. Artists are created once; :meth:`set_frame` moves them.
    """

    def __init__(self, ax, cd: Centrodes, clip: float | None = None):
        self.ax, self.cd = ax, cd
        self.clip = 3.0 * cd.centres.structure.scale if clip is None else clip
        (self.fixed_line,) = ax.plot([], [], label=f"fixed centrode ({cd.reference})", **FIXED_STYLE)
        (self.moving_line,) = ax.plot([], [], label=f"moving centrode ({cd.link})", **MOVING_STYLE)
        (self.pole,) = ax.plot([], [], label=cd.centres.label(cd.link, cd.reference), **POLE_STYLE)
        self.arrow_text = ax.text(0.02, 0.02, "", transform=ax.transAxes, color=POLE_STYLE["color"], fontsize=9)
        self.set_frame(0)

    def _masked(self, c, centre_xy):
        xy = c.masked()
        far = np.hypot(*np.ma.filled(xy, 0.0).T) > self.clip + np.hypot(*centre_xy)
        xy[far] = np.ma.masked
        return xy

    def set_frame(self, i: int):
        cd = self.cd
        origin = np.zeros(2)
        if cd.reference != "frame":
            origin = cd.centres.structure.poses[cd.reference][0].p[i]
        f = self._masked(cd.fixed_at(i), origin)
        self.fixed_line.set_data(f[:, 0], f[:, 1])
        mv = self._masked(cd.moving_at(i), origin)
        self.moving_line.set_data(mv[:, 0], mv[:, 1])
        P = cd.centre[i]
        if P.finite[0]:
            self.pole.set_data([P.h[0, 0]], [P.h[0, 1]])
            self.arrow_text.set_text("")
        else:
            d = P.h[0, :2]
            self.pole.set_data([], [])
            self.arrow_text.set_text(f"{self.pole.get_label()} at infinity, direction ({d[0]:.2f}, {d[1]:.2f})")
        return [self.fixed_line, self.moving_line, self.pole, self.arrow_text]

    @property
    def artists(self):
        return [self.fixed_line, self.moving_line, self.pole, self.arrow_text]


def draw_centres(ic: InstantCentres, i: int = 0, ax=None, lines: bool = True):
    """All instantaneous centres at frame i with their labels P_ij; centres at infinity are
    listed with their directions. With ``lines``, the Kennedy lines of the construction."""
    if ax is None:
        _, ax = plt.subplots(figsize=(9, 6.5))
    drawing = drawing_class(ic.mechanism)(ax, ic.mechanism, n=len(ic.phi))
    drawing.set_motion(ic.mechanism, ic.motion)
    drawing.set_frame(i)
    drawing.autoscale()
    # a centre at a joint takes the side opposite the joint's letter, so that the two never overlap
    letters = [(np.asarray(t.xy, float), np.asarray(t.get_position(), float))
               for t in drawing.letters.values() if t.get_visible()]
    x0, x1 = ax.get_xlim()
    y0, y1 = ax.get_ylim()
    at_inf = []
    finite_pts = []
    for (a, b), c in sorted(ic.centres.items()):
        name = ic.label(a + 1, b + 1)
        if c.finite[i]:
            p = c.h[i, :2]
            finite_pts.append(p)
            ax.plot(*p, **CENTRE_STYLE)
            away = next((-off / max(np.hypot(*off), 1e-12) for q, off in letters
                         if np.hypot(*(q - p)) < 1e-9 * (1 + np.hypot(*q))), np.array([0.7, 0.7]))
            ax.annotate(name, p, textcoords="offset points", xytext=tuple(15 * away), fontsize=11,
                        color="#d62728", ha="center", va="center")
        else:
            at_inf.append(f"{name} → ∞ along ({c.h[i, 0]:.2f}, {c.h[i, 1]:.2f})")
    if lines:
        for (pq, used) in ic.steps:
            target = ic.centres[pq]
            for text in used:
                if text == "normal":
                    continue
                a, b = text[:3], text[3:]
                pts = [ic(int(a[1]), int(a[2])), ic(int(b[1]), int(b[2])), target]
                fin = [c.h[i, :2] for c in pts if c.finite[i]]
                if len(fin) >= 2:
                    seg = np.array(fin)
                    ax.plot(seg[:, 0], seg[:, 1], color="0.6", lw=0.8, ls=":", zorder=0)
    if finite_pts:
        allp = np.array(finite_pts + [[x0, y0], [x1, y1]])
        lo, hi = allp.min(axis=0), allp.max(axis=0)
        pad = 0.08 * max(hi - lo)
        ax.set_xlim(lo[0] - pad, hi[0] + pad)
        ax.set_ylim(lo[1] - pad, hi[1] + pad)
    if at_inf:
        ax.text(0.02, 0.02, "\n".join(at_inf), transform=ax.transAxes, fontsize=10, color="#d62728")
    ax.set_title(f"instantaneous centres at φ = {np.degrees(ic.phi[i]):.1f}°", fontsize=12)
    ax.set_axis_off()   # a diagram: the links carry Kozhevnikov's numbers, the centres P_ij use them
    return ax


def draw_centrodes(cd: Centrodes, i: int = 0, ax=None, clip: float | None = None, title: str | None = None):
    """One frame of :func:`animate_centrodes`, still: the linkage at sample ``i`` of the centrodes' crank
    angles, the fixed centrode (on the reference link), the moving one (carried by the link) touching it
    at the pole ★, the curves cut ``clip`` from the reference's origin (default: 3 × the mechanism's size)
    where they run off to infinity. Returns the axes."""
    from ..validate import check_value, count

    if not isinstance(cd, Centrodes):
        raise TypeError(f"cd must be the Centrodes of mechlab.analysis.centres.centrodes, got {type(cd).__name__}")
    i = check_value("i", i, count(0, len(cd.centres.phi) - 1))
    if ax is None:
        _, ax = plt.subplots(figsize=(6, 5))
    mechanism = cd.centres.mechanism
    drawing = drawing_class(mechanism)(ax, mechanism, n=len(cd.centres.phi))
    drawing.set_motion(mechanism, cd.centres.motion)
    drawing.set_frame(i)
    overlay = CentrodeOverlay(ax, cd, clip)
    overlay.set_frame(i)
    drawing.autoscale()
    ax.relim()
    ax.autoscale_view()
    ax.set_aspect("equal")
    ax.set_axis_off()   # a diagram, as draw_centres
    ax.legend(loc="lower right", fontsize=8)
    ax.set_title(title or f"{cd.link} about {cd.reference} at φ = {np.degrees(cd.centres.phi[i]):.1f}°", fontsize=10)
    return ax


def animate_centrodes(mechanism, link: str, reference: str = "frame", n: int = 36, interval: int = 80,
                      clip: float | None = None, figsize=(4.4, 4.0), dpi: int = 65) -> Animation:
    """An animation of the linkage with the two centrodes of ``link`` relative to
    ``reference`` rolling on each other (n frames over the cycle, the curves sampled
    about 360 times); play it with ``HTML(anim.to_jshtml())``."""
    fig, ax = plt.subplots(figsize=figsize, dpi=dpi)
    k = max(1, 360 // n)                        # the curves are sampled k times finer than the frames
    phi = mechanism.cycle(n * k + 1)[:-1] if mechanism.can_turn else mechanism.cycle(n * k)
    cd = centrodes(mechanism, link, reference, phi)
    drawing = drawing_class(mechanism)(ax, mechanism, n=len(phi), readout=True)
    drawing.set_motion(mechanism, cd.centres.motion)
    overlay = CentrodeOverlay(ax, cd, clip)
    drawing.autoscale()
    x0, x1, y0, y1 = drawing.bounds()
    if cd.reference == "frame" and cd.fixed.finite.any():
        near = np.ma.compress_rows(overlay._masked(cd.fixed, np.zeros(2)))
        if len(near):
            x0, x1 = min(x0, near[:, 0].min()), max(x1, near[:, 0].max())
            y0, y1 = min(y0, near[:, 1].min()), max(y1, near[:, 1].max())
    fill_axes(ax, (x0, x1, y0, y1))
    ax.set_axis_off()
    ax.legend(loc="lower right", fontsize=8)

    def frame(i):
        return drawing.set_frame(i * k) + overlay.set_frame(i * k)

    anim = Animation(fig, frame, frames=n, interval=interval, blit=False)
    anim.drawing, anim.overlay, anim.step = drawing, overlay, k
    plt.close(fig)
    return anim
