"""Drawings of the Geneva drives: the planar wheel with its slots and locking arcs
(animated like any linkage), and the spherical Geneva of Vainer & Shatokhina in 3-D.

Both follow the protocol of :class:`mechlab.draw.LinkageDrawing`
(``__init__(ax, mechanism, trace=None, n=...)``, ``set_motion``, ``set_frame(i)`` →
artists, ``autoscale()``, ``artists``), so :func:`mechlab.draw.animate` plays them.
"""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np

from ..mechanisms.geneva import ExternalGeneva, PlanarGeneva
from ..mechanisms.spherical_geneva import SphericalGeneva
from ..analysis.intermittency import intermittency
from . import JOINT_STYLE, LETTER_STYLE, LINK_STYLE, READOUT_STYLE, TRACE_STYLE, LinkageDrawing, register

WHEEL_STYLE = dict(color="#2a7f62", lw=1.6, zorder=2)
LOCK_STYLE = dict(color="#b8860b", lw=2.2, zorder=2)


def _arc(centre, radius, a0, a1, n=40):
    t = np.linspace(a0, a1, n)
    return np.asarray(centre) + radius * np.stack([np.cos(t), np.sin(t)], axis=-1)


def wheel_outline(g: PlanarGeneva, n_arc: int = 24) -> tuple[np.ndarray, np.ndarray]:
    """The wheel's outlines in its own frame (W at the origin, ψ = 0), as two polylines.

    External: the slotted rim with the concave locking arcs (radius a - 1.5 r, centred
    at distance C on the bisectors between slots), and nothing else. Internal: the inner
    rim with the slots running outwards, and the outer rim.
    """
    z, C, r = g.z, g.centre_distance, g.roller_radius
    w = 1.08 * r  # the slot's half-width, with a little clearance
    pts = []
    rim = g.outer_radius if g.kappa < 0 else g.inner_radius
    top = np.sqrt(max(rim**2 - w**2, 0.0))
    gap = np.arcsin(w / rim)
    for k in range(z):
        th = np.pi - g.kappa * np.pi / z + 2 * np.pi * k / z  # slot k's direction at ψ = 0
        u = np.array([np.cos(th), np.sin(th)])
        v = np.array([-u[1], u[0]])
        # the slot from its -v wall round the bottom (towards W outside, away from W inside)
        end = th - 1.5 * np.pi if g.kappa < 0 else th + 0.5 * np.pi
        pts += [top * u - w * v, *_arc(g.slot_bottom * u, w, th - 0.5 * np.pi, end, n_arc), top * u + w * v]
        t = np.linspace(th + gap, th + 2 * np.pi / z - gap, 3 * n_arc)
        radius = np.full_like(t, rim)
        if g.kappa < 0:  # the concave locking arc in the gap after this slot
            dlt = t - (th + np.pi / z)
            disc = g.locking_radius**2 - (C * np.sin(dlt)) ** 2
            near = np.where(disc >= 0, C * np.cos(dlt) - np.sqrt(np.maximum(disc, 0.0)), np.inf)
            radius = np.minimum(radius, near)
        pts += list(radius[:, None] * np.stack([np.cos(t), np.sin(t)], axis=-1))
    outline = np.array(pts + [pts[0]])
    if g.kappa < 0:
        return outline, np.empty((0, 2))
    return outline, _arc((0.0, 0.0), g.outer_radius, 0.0, 2 * np.pi, 120)


def _rotate(xy: np.ndarray, angle: float, centre) -> np.ndarray:
    c, s = np.cos(angle), np.sin(angle)
    return np.asarray(centre) + xy @ np.array([[c, s], [-s, c]])


@register(PlanarGeneva)
class PlanarGenevaDrawing(LinkageDrawing):
    """Crank O-A with its roller, the slotted wheel turning about W, and (external
    drive) the crank's locking disc whose relief lets the wheel turn."""

    n_extras = 3

    def set_motion(self, mechanism, motion):
        self.ax.set_axis_off()  # tick labels cost most of an animation's rendering time
        self._outline = wheel_outline(mechanism)
        for line, style in zip(self.extra_lines, (WHEEL_STYLE, WHEEL_STYLE, LOCK_STYLE)):
            line.set(**style)
        return super().set_motion(mechanism, motion)

    def numbered_parts(self, i):
        """The crank, then the wheel (a radius of it, turning with it, carries its number)."""
        W, psi = self.motion.points["W"].p[i], self.motion.psi[i]
        rim = W + 0.7 * self.mechanism.outer_radius * np.array([np.cos(psi), np.sin(psi)])
        return [*super().numbered_parts(i), np.array([W, rim])]

    def extras(self, i):
        g, mo = self.mechanism, self.motion
        W = mo.points["W"].p[i]
        psi = mo.psi[i]
        inner, outer = (_rotate(p, psi, W) if len(p) else p for p in self._outline)
        if isinstance(g, ExternalGeneva):
            A = mo.points["A"].p[i]
            pin = np.arctan2(A[1], A[0])
            s0 = g.engagement_half_angle
            lock = _arc((0.0, 0.0), g.locking_radius, pin + s0, pin + 2 * np.pi - s0, 60)
        else:
            lock = np.empty((0, 2))
        return [inner, outer, lock]


# ----------------------------------------------------------------------------------
# spherical Geneva in 3-D
# ----------------------------------------------------------------------------------
@register(SphericalGeneva)
class SphericalGenevaDrawing:
    """The hemisphere (equator and two parallels), its z meridian slots turning with the
    wheel, the crank axis, the crank arm and the pin on its cone, and the contact point
    A while the pin is in a slot, with the letters of the points (O, O1, P, B, and A while
    engaged) and, with ``readout``, the crank angle. A 2-D ``ax`` is replaced by a 3-D one in
    its place."""

    def __init__(self, ax, mechanism: SphericalGeneva, trace: str | None = None, n: int = 73, *,
                 labels: bool = True, ground: bool = True, dimensions: bool = False, readout: bool = False):
        if getattr(ax, "name", "") != "3d":
            fig, pos = ax.figure, ax.get_position()
            ax.remove()
            ax = fig.add_axes(pos, projection="3d")
        self.ax = ax
        self.n = n
        self.trace_name = trace
        self.mechanism = self.motion = None
        self._static = []
        self.slot_lines = []
        (self.pin_line,) = ax.plot([], [], [], color="#1f4e79", lw=4, solid_capstyle="round")
        (self.arm_line,) = ax.plot([], [], [], **LINK_STYLE)
        (self.contact,) = ax.plot([], [], [], ls="none", marker="o", ms=7, mfc="#d62728", mec="k")
        (self.trace_line,) = ax.plot([], [], [], **TRACE_STYLE)
        (self.joints,) = ax.plot([], [], [], **JOINT_STYLE)
        self.letters = {}
        if labels:
            self.letters = {name: ax.text(0.0, 0.0, 0.0, f" {name}", **LETTER_STYLE)
                            for name in ("O", "O1", "P", "B", "A")}
            for text in self.letters.values():
                text.set_ha("left")
        self.readout = ax.text2D(0.98, 0.98, "", transform=ax.transAxes, **READOUT_STYLE) if readout else None
        self.set_mechanism(mechanism)

    def set_mechanism(self, mechanism, phi=None):
        phi = mechanism.cycle(self.n) if phi is None else phi
        return self.set_motion(mechanism, mechanism.motion(phi))

    def set_motion(self, mechanism: SphericalGeneva, motion):
        ax, R, e = self.ax, mechanism.R, mechanism.e
        for art in self._static:
            art.remove()
        self._static = []
        t = np.linspace(0, 2 * np.pi, 97)
        for lat, style in ((0.0, dict(color="#2a7f62", lw=1.6)), (np.pi / 6, dict(color="0.75", lw=0.8)),
                           (np.pi / 3, dict(color="0.75", lw=0.8))):
            rr = R * np.cos(lat)
            self._static += ax.plot(rr * np.cos(t), rr * np.sin(t), np.full_like(t, R * np.sin(lat)), **style)
        self._static += ax.plot([-0.2 * R, 1.25 * R], [0, 0], [-e, -e], color="0.35", ls="-.", lw=1)  # crank axis
        self._static += ax.plot([0, 0], [0, 0], [-e - 0.3 * R, 1.2 * R], color="0.35", ls="-.", lw=1)  # wheel axis
        while len(self.slot_lines) < mechanism.z:
            self.slot_lines += ax.plot([], [], [], color="#2a7f62", lw=3, alpha=0.85)
        for line in self.slot_lines[mechanism.z:]:
            line.set_data_3d([], [], [])
        self.mechanism, self.motion = mechanism, motion
        g = mechanism
        self._elev = np.linspace(0.0, np.arccos(g.r_H / R) + 0.5 * g.pin_diameter / R, 16)
        self._engaged = g.engaged(motion.phi)
        if self.trace_name:
            p = motion.points[self.trace_name].p
            self.trace_line.set_data_3d(p[:, 0], p[:, 1], p[:, 2])
        self.autoscale()
        self.set_frame(0)
        return motion

    def set_frame(self, i: int):
        g, mo = self.mechanism, self.motion
        R = g.R
        for k, line in enumerate(self.slot_lines[:g.z]):
            az = mo.psi[i] - g.beta0 + 2 * np.pi * k / g.z
            el = self._elev
            line.set_data_3d(R * np.cos(el) * np.cos(az), R * np.cos(el) * np.sin(az), R * np.sin(el))
        o1 = mo.points["O1"].p[i]
        d = (mo.points["P"].p[i] - o1) / g.u0
        base = o1 + (g.u0 - 0.15 * R) * d
        tip = o1 + (g.u_H + 0.1 * R) * d
        self.pin_line.set_data_3d(*np.array([base, tip]).T)
        foot = np.array([base[0], 0.0, -g.e])
        self.arm_line.set_data_3d(*np.array([foot, base]).T)
        if self._engaged[i]:
            A = mo.points["A"].p[i]
            self.contact.set_data_3d([A[0]], [A[1]], [A[2]])
        else:
            self.contact.set_data_3d([], [], [])
        self.joints.set_data_3d([foot[0], 0.0], [foot[1], 0.0], [foot[2], 0.0])
        for name, text in self.letters.items():
            text.set_position_3d(mo.points[name].p[i])
            text.set_visible(name != "A" or bool(self._engaged[i]))
        if self.readout is not None:
            self.readout.set_text(f"φ = {np.degrees(mo.phi[i]):.0f}°")
        return self.artists

    def bounds(self, margin: float = 0.0):
        """(xmin, xmax, ymin, ymax) of the view (the sphere's extent), for the explorer."""
        R = self.mechanism.R
        return -R, R, -R, R

    @property
    def artists(self):
        return [*self.slot_lines, self.pin_line, self.arm_line, self.contact, self.trace_line, self.joints,
                *self.letters.values(), *([self.readout] if self.readout is not None else [])]

    def autoscale(self):
        R = self.mechanism.R
        self.ax.set_xlim(-R, R)
        self.ax.set_ylim(-R, R)
        self.ax.set_zlim(-1.0 * R, 1.1 * R)
        self.ax.set_box_aspect((1, 1, 1), zoom=1.15)   # the sphere and the pin's path fill the axes
        self.ax.view_init(elev=22, azim=-60)
        self.ax.set_axis_off()


def plot_comparison(mechanisms: dict, axes=None, n: int = 721, phase: float = 0.0, dwell_tol: dict | None = None):
    """ψ' and ψ'' over one crank turn (from ``phase``) for each named mechanism, in the
    sense of its index (the external Geneva's negative turn shown positive), with
    :func:`mechlab.analysis.intermittency.intermittency` in the legend (``dwell_tol`` per name, for
    approximate dwells)."""
    if axes is None:
        _, axes = plt.subplots(2, 1, sharex=True, figsize=(7, 5))
    phi = phase + np.linspace(0, 2 * np.pi, n)
    for name, m in mechanisms.items():
        mo = m.motion(phi)
        sense = np.sign(mo.psi[-1] - mo.psi[0])
        inv = intermittency(m, n=2 * n, phase=phase, dwell_tol=(dwell_tol or {}).get(name, 1e-9))
        label = f"{name}: dwell {inv.dwell_fraction:.2f}, impact: {inv.impact}"
        axes[0].plot(np.degrees(phi), sense * mo.dpsi, label=label)
        axes[1].plot(np.degrees(phi), sense * mo.ddpsi, label=name)
    axes[0].set_ylabel("ψ′ = dψ/dφ (–)")
    axes[1].set_ylabel("ψ″ = d²ψ/dφ² (1/rad)")
    axes[1].set_xlabel("crank angle φ (degrees)")
    for ax in axes:
        ax.grid(True, alpha=0.3)
    axes[0].legend(fontsize=7, loc="upper left")
    return axes
