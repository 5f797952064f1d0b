"""Drawing of the curved-slot dwell mechanism (Zinchenko et al., 2013, §3): the crank, the link with
its slot drawn in the moving link (dwell arc highlighted, flanks for the roller), and a
"dwell" label while the link stands still."""

from __future__ import annotations

import numpy as np

from ..synthesis.dwell_slot import DwellSlotMechanism
from . import EXTRA_STYLE, LinkageDrawing, register

SLOT_STYLE = dict(color="#2a7f62", lw=2, zorder=2)
DWELL_STYLE = dict(color="#e08214", lw=3.5, zorder=2.5)
FLANK_STYLE = dict(color="#777777", lw=0.8, zorder=1.5)
ARM_STYLE = dict(EXTRA_STYLE, lw=4, alpha=0.5)


def _rotate(xy, angle, about):
    c, s = np.cos(angle), np.sin(angle)
    return about + np.stack([c * xy[:, 0] - s * xy[:, 1], s * xy[:, 0] + c * xy[:, 1]], axis=-1)


@register(DwellSlotMechanism)
class DwellDrawing(LinkageDrawing):
    """The slot is drawn in the link frame once and rotated by ψ about B each frame."""

    n_extras = 0

    def set_motion(self, mechanism, motion):
        from ..synthesis.slot_export import slot_profile

        self._centre = mechanism.slot_points(160)
        self._dwell = mechanism.dwell_points(60)
        rho = mechanism.roller_radius
        if rho > 0:
            prof = slot_profile(mechanism, n=160)
            self._flanks = [prof.left, prof.right]
        else:
            self._flanks = []
        self._in_dwell = mechanism.law.in_dwell(motion.phi)
        ax = self.ax
        if not hasattr(self, "_slot_line"):
            (self._arm,) = ax.plot([], [], **ARM_STYLE)
            (self._slot_line,) = ax.plot([], [], **SLOT_STYLE)
            (self._dwell_line,) = ax.plot([], [], **DWELL_STYLE)
            self._flank_lines = [ax.plot([], [], **FLANK_STYLE)[0] for _ in range(2)]
            (self._roller,) = ax.plot([], [], color="#1f4e79", lw=1, zorder=4)
            self._label = ax.text(0.02, 0.95, "", transform=ax.transAxes, va="top", color="#e08214",
                                  fontweight="bold")
        return super().set_motion(mechanism, motion)

    def numbered_parts(self, i):
        """The crank, then the slotted link (its arm from the slot's end through B)."""
        centre = self._world(self._centre[[0, -1]], i)
        return [*super().numbered_parts(i), np.array([centre[0], self.motion.points["B"].p[i]])]

    def _world(self, xy, i):
        B = self.motion.points["B"].p[i]
        return _rotate(xy, self.motion.psi[i], B)

    def set_frame(self, i):
        B = self.motion.points["B"].p[i]
        centre = self._world(self._centre, i)
        self._slot_line.set_data(*centre.T)
        self._dwell_line.set_data(*self._world(self._dwell, i).T)
        self._arm.set_data(*np.array([centre[0], B, centre[-1]]).T)
        for line, flank in zip(self._flank_lines, self._flanks + [None, None]):
            if flank is None:
                line.set_data([], [])
            else:
                line.set_data(*self._world(flank, i).T)
        rho = self.mechanism.roller_radius
        if rho > 0:
            A = self.motion.points["A"].p[i]
            t = np.linspace(0, 2 * np.pi, 40)
            self._roller.set_data(A[0] + rho * np.cos(t), A[1] + rho * np.sin(t))
        else:
            self._roller.set_data([], [])
        self._label.set_text("dwell" if self._in_dwell[i] else "")
        return super().set_frame(i)

    @property
    def artists(self):
        return [self._arm, self._slot_line, self._dwell_line, *self._flank_lines, self._roller, self._label,
                *super().artists]

    def bounds(self, margin: float = 0.12):
        pts = [v.p for v in self.motion.points.values()]
        step = max(1, len(self.motion) // 12)
        pts += [self._world(self._centre, j) for j in range(0, len(self.motion), step)]
        allp = np.concatenate(pts)
        lo, hi = np.nanmin(allp, axis=0), np.nanmax(allp, axis=0)
        pad = margin * max(hi - lo) + 1e-9 + self.mechanism.roller_radius
        return lo[0] - pad, hi[0] + pad, lo[1] - pad, hi[1] + pad
