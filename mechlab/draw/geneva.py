"""The spherical Geneva of Vainer & Shatokhina in 3-D (the drawing of a ``spatial`` mechanism: the
planar wheels are drawn from their ``sketch()`` like any linkage), and the Geneva drives' laws compared.

The 3-D drawing follows the protocol of :class:`mechlab.draw.LinkageDrawing`
(``__init__(ax, mechanism, trace=None, n=...)``, ``set_motion``, ``set_frame(i)`` →
artists, ``autoscale()``, ``artists``), so :func:`mechlab.draw.animate` plays it.
"""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np

from ..analysis.intermittency import DWELL_TOL, compare
from ..mechanisms.geneva import wheel_outline  # noqa: F401 - where the course's readers look for it
from ..mechanisms.spherical_geneva import SphericalGeneva
from . import JOINT_STYLE, LETTER_STYLE, LINK_STYLE, NUMBER_STYLE, READOUT_STYLE, TRACE_STYLE


# ----------------------------------------------------------------------------------
# spherical Geneva in 3-D
# ----------------------------------------------------------------------------------
class SphericalGenevaDrawing:
    """The hemisphere (equator and two parallels), its z meridian slots turning with the
    wheel, the crank axis, the crank arm and the pin on its cone, and the contact point
    A while the pin is in a slot, with the letters of the points (O, O1, P, B, and A while
    engaged), the links' numbers of its structure (crank, wheel, frame, circled as in the planar
    drawings) and, with ``readout``, the crank angle. A 2-D ``ax`` is replaced by a 3-D one in
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
        # circled link numbers (crank, wheel, frame), numbered as the mechanism's structure numbers them
        self.numbers = {link: ax.text(0.0, 0.0, 0.0, "", **NUMBER_STYLE) for link in ("crank", "wheel", "frame")} \
            if labels else {}
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
        numbers = mechanism.structure().numbers()
        for link, text in self.numbers.items():
            text.set_text(str(numbers[link]))
        if self.numbers:   # the wheel's on its rim facing the viewer, the frame's beside the wheel's bearing
            front = np.radians(-75.0)
            self.numbers["wheel"].set_position_3d((1.12 * R * np.cos(front), 1.12 * R * np.sin(front), 0.0))
            self.numbers["frame"].set_position_3d((0.12 * R, -0.12 * R, -e - 0.3 * R))
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
        if self.numbers:   # the crank's number beside the middle of its arm
            self.numbers["crank"].set_position_3d((foot + base) / 2 + np.array([0.0, -0.1 * R, 0.0]))
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
                *self.letters.values(), *self.numbers.values(), *([self.readout] if self.readout is not None else [])]

    def autoscale(self):
        R = self.mechanism.R
        self.ax.set_xlim(-R, R)
        self.ax.set_ylim(-R, R)
        self.ax.set_zlim(-1.0 * R, 1.1 * R)
        self.ax.set_box_aspect((1, 1, 1), zoom=1.15)   # the sphere and the pin's path fill the axes
        self.ax.view_init(elev=22, azim=-60)
        self.ax.set_axis_off()


def plot_comparison(mechanisms: dict, axes=None, n: int = 721, phase: float = 0.0,
                    dwell_tol: float | dict | None = None, clip: float | None = 2.0):
    """ψ' and ψ'' over one crank turn (from ``phase``) for each named mechanism, in the
    sense of its index (the external Geneva's negative turn shown positive), with
    :func:`mechlab.analysis.intermittency.compare` in the legend (``dwell_tol`` as there: one, or per name, for
    approximate dwells; names it does not plot are left out).

    A curve whose peak is more than ``clip`` times the largest peak of the (at least two) others would squash
    them: its axis is cut at 1.2 times the others' peak and the curve's own peak is written at the cut (``None``:
    never cut)."""
    if axes is None:
        _, axes = plt.subplots(2, 1, sharex=True, figsize=(7, 5))
    phi = phase + np.linspace(0, 2 * np.pi, n)
    if isinstance(dwell_tol, dict):   # one dict serves a table of all and a plot of some
        dwell_tol = {k: v for k, v in dwell_tol.items() if k in mechanisms}
    rows = compare(mechanisms, n=2 * n, phase=phase, dwell_tol=DWELL_TOL if dwell_tol is None else dwell_tol).by("name")
    curves = ([], [])
    for name, m in mechanisms.items():
        mo = m.motion(phi)
        sense = np.sign(mo.psi[-1] - mo.psi[0])
        inv = rows[name]
        still = (f"dwell {inv.dwell_fraction:.2f}" if inv.dwell_fraction > 0
                 else f"near-standstill {inv.standstill_fraction:.2f}")
        label = f"{name}: {still}, impact: {inv.impact}"
        for ax, y, lab, kept in zip(axes, (sense * mo.dpsi, sense * mo.ddpsi), (label, name), curves, strict=False):
            kept.append((ax.plot(np.degrees(phi), y, label=lab)[0], name, y))
    axes[0].set_ylabel("ψ′ = dψ/dφ (–)")
    axes[1].set_ylabel("ψ″ = d²ψ/dφ² (1/rad)")
    axes[1].set_xlabel("crank angle φ (degrees)")
    for ax, kept in zip(axes, curves, strict=False):
        ax.grid(True, alpha=0.3)
        if clip is not None and len(kept) > 2:   # with two curves neither is the odd one out
            _clip_outlier(ax, kept, clip)
    axes[0].legend(fontsize=7, loc="upper left")
    return axes


def _clip_outlier(ax, kept, clip: float) -> None:
    """Cut ``ax`` at 1.2 × the others' peak when one curve's peak exceeds ``clip`` × theirs; label its peak."""
    peaks = [float(np.max(np.abs(y))) for _, _, y in kept]
    worst = int(np.argmax(peaks))
    others = max(p for i, p in enumerate(peaks) if i != worst)
    if peaks[worst] <= clip * others:
        return
    line, name, y = kept[worst]
    top = 1.2 * others
    lo = -top if np.min(y) < -others else min(ax.get_ylim()[0], -0.1 * top)
    ax.set_ylim(lo, top)
    for k in {int(np.argmax(y)), int(np.argmin(y))}:
        if abs(y[k]) > top:
            x = line.get_xdata()[k]
            ax.annotate(f"{name}: {y[k]:+.1f} (cut)", (x, np.sign(y[k]) * top), xytext=(0, -4 if y[k] > 0 else 4),
                        textcoords="offset points", ha="right" if x > 180 else "left",
                        va="top" if y[k] > 0 else "bottom", fontsize=7, color=line.get_color())
