"""Drawing of the disc cams: the profile turning with the cam, its base circle, the roller on the
follower (a stem in its guide, or an arm about its pivot) and the contact normal; "dwell" shows
while the follower stands still. The profile is sampled once and rotated by φ each frame."""

from __future__ import annotations

import numpy as np

from ..mechanisms.cam import OscillatingRollerCam, RollerCam, TranslatingRollerCam
from . import GUIDE_STYLE, LINK_STYLE, LinkageDrawing, register

PROFILE_STYLE = dict(color="#2a7f62", lw=2, zorder=2)
CAM_FILL = dict(color="#2a7f62", alpha=0.15, lw=0, zorder=1)
BASE_STYLE = dict(color="#2a7f62", lw=0.8, ls="--", zorder=1.5)
ROLLER_STYLE = dict(color="#1f4e79", lw=1.5, zorder=4)
NORMAL_STYLE = dict(color="#d62728", lw=1, ls=":", zorder=3.5)
_CIRCLE = np.stack([np.cos(np.linspace(0, 2 * np.pi, 60)), np.sin(np.linspace(0, 2 * np.pi, 60))], axis=-1)


def _rotate(xy, angle):
    c, s = np.cos(angle), np.sin(angle)
    return xy @ np.array([[c, s], [-s, c]])


@register(TranslatingRollerCam)
@register(OscillatingRollerCam)
class CamDrawing(LinkageDrawing):
    """The cam (profile and base circle, in the cam frame, turned by φ), the roller, the follower
    and the common normal at the contact (the line of the force without friction)."""

    def set_motion(self, mechanism: RollerCam, motion):
        self._profile = mechanism.profile(240, check=False).surface
        self._base = mechanism.base_radius * _CIRCLE
        self._in_dwell = mechanism.in_dwell(motion.phi)
        ax = self.ax
        if not hasattr(self, "_cam_line"):
            (self._fill,) = ax.fill([], [], **CAM_FILL)
            (self._cam_line,) = ax.plot([], [], **PROFILE_STYLE)
            (self._base_line,) = ax.plot([], [], **BASE_STYLE)
            (self._roller,) = ax.plot([], [], **ROLLER_STYLE)
            (self._follower,) = ax.plot([], [], **LINK_STYLE)
            (self._guide,) = ax.plot([], [], **GUIDE_STYLE)
            (self._normal,) = ax.plot([], [], **NORMAL_STYLE)
            self._label = ax.text(0.02, 0.95, "", transform=ax.transAxes, va="top", color="#e08214",
                                  fontweight="bold")
        return super().set_motion(mechanism, motion)

    def _stem(self, i):
        """The follower beyond the roller: a stem up its guide, or nothing (the arm is a link)."""
        m = self.mechanism
        if not isinstance(m, TranslatingRollerCam):
            return np.empty((0, 2)), np.empty((0, 2))
        C = self.motion.points["C"].p[i]
        top = m.s0 + m.programme.stroke + 0.9 * m.prime_radius
        stem = np.array([C, [m.offset, top]])
        w = 0.35 * max(m.roller_radius, 0.1 * m.base_radius)
        y0 = m.s0 + m.programme.stroke + 0.3 * m.prime_radius
        guide = np.array([[m.offset - w, y0], [m.offset - w, top], [np.nan, np.nan],
                          [m.offset + w, y0], [m.offset + w, top]])
        return stem, guide

    def set_frame(self, i):
        phi = self.motion.phi[i]
        cam = _rotate(self._profile, phi)
        self._fill.set_xy(cam)
        self._cam_line.set_data(*cam.T)
        self._base_line.set_data(*_rotate(self._base, phi).T)
        C, K = self.motion.points["C"].p[i], self.motion.points["K"].p[i]
        r = self.mechanism.roller_radius
        self._roller.set_data(*(C + r * _CIRCLE).T)
        stem, guide = self._stem(i)
        self._follower.set_data(*stem.T)
        self._guide.set_data(*guide.T)
        n = C - K if r > 0 else np.zeros(2)
        n = n / (np.hypot(*n) or 1.0)
        reach = 0.6 * self.mechanism.prime_radius
        self._normal.set_data(*np.array([K - reach * n, K + reach * n]).T)
        self._label.set_text("dwell" if self._in_dwell[i] else "")
        return super().set_frame(i)

    @property
    def artists(self):
        return [self._fill, self._cam_line, self._base_line, self._roller, self._follower, self._guide,
                self._normal, self._label, *super().artists]

    def bounds(self, margin: float = 0.08):
        reach = np.max(np.hypot(*self._profile.T))
        pts = [np.array([[-reach, -reach], [reach, reach]])] + [v.p for v in self.motion.points.values()]
        pts += [seg for seg in self._stem(0) if len(seg)]
        allp = np.concatenate(pts)
        lo, hi = np.nanmin(allp, axis=0), np.nanmax(allp, axis=0)
        pad = margin * max(hi - lo) + self.mechanism.roller_radius
        return lo[0] - pad, hi[0] + pad, lo[1] - pad, hi[1] + pad
