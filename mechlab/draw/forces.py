"""Force plans drawn over a mechanism: reaction arrows in every pair, moved in place.

:class:`ForcePlanDrawing` draws a :class:`mechlab.kinetostatics.Kinetostatics`, so
``animate(Kinetostatics(mechanism, model, loads, omega1=…), n=36)`` plays the mechanism
with its reactions. It draws the mechanism from the mechanism's own sketch
and adds one arrow per pair (the force of link a on link b, at the pair's point, all
arrows at one scale over the cycle) and the balancing torque as text.
"""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np

from ..kinetostatics.machines import Kinetostatics
from . import drawing_class, fill_axes
from .access import CATEGORY_COLOURS

ARROW_COLOURS = CATEGORY_COLOURS[:-1]   # colour-blind safe (mechlab.draw.access); yellow is too light


def _readable(value: float) -> str:
    """Three significant figures, whole numbers from 1000 up ("2008", not "2.01e+03")."""
    return f"{value:.0f}" if abs(value) >= 1000 else f"{value:.3g}"


class ForcePlanDrawing:
    """The mechanism (its own drawing) plus reaction arrows and the balancing torque.

    ``pairs`` restricts the arrows to some pairs; ``length`` is the drawn length of the
    largest reaction over the cycle, as a fraction of the mechanism's size; ``force_unit`` names the
    forces' unit in the readout (torques in it times metres).
    """

    def __init__(self, ax, mechanism: Kinetostatics, trace: str | None = None, n: int = 361,
                 pairs=None, length: float = 0.45, *, labels: bool = True, ground: bool = True,
                 dimensions: bool = False, readout: bool = False, force_unit: str = "N"):
        self.ax = ax
        self.force_unit = force_unit   # the model's units are SI (mechlab.kinetostatics.model): N, and N·m
        self.n = n
        self.pair_names = pairs
        self.length = length
        # the crank angle is in this drawing's own text, with the torque: no second readout
        self.base = drawing_class(mechanism.mechanism)(ax, mechanism.mechanism, trace=trace, n=n, labels=labels,
                                                       ground=ground, dimensions=dimensions)
        self.quiver = None
        self.text = ax.text(0.02, 0.98, "", transform=ax.transAxes, va="top", fontsize=9, zorder=6)
        self.mechanism = None
        self.result = None
        self.set_mechanism(mechanism)

    # -- binding -------------------------------------------------------------------
    def set_mechanism(self, mechanism: Kinetostatics, phi=None):
        phi = mechanism.cycle(self.n) if phi is None else phi
        return self.set_motion(mechanism, mechanism.motion(phi))

    def set_motion(self, mechanism: Kinetostatics, motion):
        self.mechanism = mechanism
        self.motion = motion
        self.base.set_motion(mechanism.mechanism, motion)
        self.result = mechanism.forces(motion=motion)
        names = list(self.result.reactions) if self.pair_names is None else list(self.pair_names)
        self.names = names
        R = [self.result.reactions[k] for k in names]
        biggest = max(float(np.max(r.magnitude)) for r in R) or 1.0
        x0, x1, y0, y1 = self.base.bounds(margin=0.0)
        self.scale = self.length * max(x1 - x0, y1 - y0) / biggest   # drawn length per unit force
        colours = [ARROW_COLOURS[i % len(ARROW_COLOURS)] for i in range(len(R))]
        if self.quiver is not None:
            self.quiver.remove()
        self.quiver = self.ax.quiver(np.zeros(len(R)), np.zeros(len(R)), np.zeros(len(R)), np.zeros(len(R)),
                                     color=colours, angles="xy", scale_units="xy", scale=1.0, width=0.008,
                                     zorder=5)
        for old in getattr(self, "_keys", []):
            old.remove()
        self._keys = [self.ax.plot([], [], color=c, lw=3, label=f"R {k}")[0]
                      for k, c in zip(names, colours, strict=False)]
        self.ax.legend(handles=self._keys, loc="lower right", fontsize=8, framealpha=0.7)
        self.set_frame(0)
        return motion

    # -- frames --------------------------------------------------------------------
    def set_frame(self, i: int):
        self.base.set_frame(i)
        R = [self.result.reactions[k] for k in self.names]
        self.quiver.set_offsets(np.array([r.point[i] for r in R]))
        uv = np.array([r.force[i] for r in R]) * self.scale
        self.quiver.set_UVC(uv[:, 0], uv[:, 1])
        u = self.force_unit
        parts = [f"|R {k}| = {_readable(r.magnitude[i])} {u}" for k, r in zip(self.names, R, strict=False)]
        # two reactions a line: four on one line ran past the mechanism into the plots beside it
        lines = ["  ".join(parts[j:j + 2]) for j in range(0, len(parts), 2)]
        head = f"φ = {np.degrees(self.result.phi[i]):.0f}°   M_b = {_readable(self.result.torque[i])} {u}·m"
        self.text.set_text("\n".join([head, *lines]))
        return self.artists

    @property
    def artists(self):
        return [*self.base.artists, self.quiver, self.text]

    def bounds(self, margin: float = 0.15):
        x0, x1, y0, y1 = self.base.bounds(margin)
        tips = np.concatenate([r.point + r.force * self.scale
                               for r in (self.result.reactions[k] for k in self.names)])
        lo, hi = tips.min(axis=0), tips.max(axis=0)
        return min(x0, lo[0]), max(x1, hi[0]), min(y0, lo[1]), max(y1, hi[1])

    def autoscale(self):
        fill_axes(self.ax, self.bounds())


UNDEFINED_LABEL = "η undefined: loads or inertia\ndrive the crank"


def shade_undefined(ax, deg, undefined):
    """Grey the crank angles (degrees) where the efficiency is undefined; returns the spans or None.

    :meth:`mechlab.kinetostatics.solve.ForceResult.efficiency` masks η where the drive or the ideal
    loads deliver no power (the links' inertia or gravity drive the crank), so an η line has gaps
    there; the grey band and its legend entry say why.
    """
    if not np.any(undefined):
        return None
    return ax.fill_between(deg, 0.0, 1.05, where=undefined, step="mid", color="0.88", lw=0, label=UNDEFINED_LABEL)


LEVEL_STYLES = (("C1", "--"), ("C2", ":"), ("C4", "-."), ("C5", (0, (5, 1, 1, 1))))


def plot_efficiency(result, ax=None, levels=None, **style):
    """The instantaneous efficiency η(φ) of a force result, its undefined spans grey; returns the axes.

    ``levels``: name → value of cycle efficiencies (e.g. the thesis' mean and the energy ratio of
    :meth:`~mechlab.kinetostatics.solve.ForceResult.cycle_efficiency`), each drawn as a horizontal
    line labelled "name = value" in a legend.
    """
    if ax is None:
        ax = plt.subplots(figsize=(8, 3.2))[1]   # 8 in: at least 600 px in the book's column
    eta = result.efficiency()
    deg = np.degrees(result.phi)
    ax.plot(deg, eta.filled(np.nan), **{"color": "#2a7f62", "lw": 1.5, "label": "η", **style})
    shade_undefined(ax, deg, np.ma.getmaskarray(eta))
    ax.set(xlabel="crank angle φ (degrees)", ylabel="efficiency η (–)", ylim=(0.0, 1.05))
    ax.set_xticks(np.arange(0, 361, 90))
    ax.grid(True, alpha=0.3)
    if levels:
        for (name, value), (colour, dash) in zip(levels.items(), LEVEL_STYLES, strict=False):
            ax.axhline(value, color=colour, ls=dash, label=f"{name} = {value:.3f}")
        ax.legend(loc="lower left", fontsize=8)
    return ax


def _reaction_label(reaction) -> tuple[np.ndarray, str]:
    """|R| of a turning pair, |N| (the normal force) of a sliding or higher pair, with its legend."""
    if reaction.normal is None:
        return reaction.magnitude, f"|R| in {reaction.pair}"
    return np.abs(reaction.normal), f"|N| in the {reaction.pair}"


def plot_torque_and_reactions(result, power_balance=None, unit: str = "N"):
    """Left: the balancing torque M_b(φ) from the groups, with ``power_balance`` (the same from
    :func:`mechlab.kinetostatics.solve.virtual_work_torque`) dashed over it; right: the size of the
    reaction in every pair (|R| in a turning pair, |N| in a sliding or higher one). Forces in
    ``unit``, torques in ``unit``·m; returns the Figure."""
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(10, 3.2))
    deg = np.degrees(result.phi)
    ax1.plot(deg, result.torque, lw=2, label="groups")
    if power_balance is not None:
        ax1.plot(deg, power_balance, "k--", lw=1, label="power balance")
    ax1.set(xlabel="φ, degrees", ylabel=f"M_b, {unit}·m", title="balancing torque")
    ax1.legend()
    for reaction in result.reactions.values():
        size, label = _reaction_label(reaction)
        ax2.plot(deg, size, label=label)
    ax2.set(xlabel="φ, degrees", ylabel=f"reaction |R|, {unit}", title="reactions")
    ax2.legend(fontsize=8)
    for ax in (ax1, ax2):
        ax.grid(alpha=0.3)
    return fig


def plot_reaction_against_transmission(motion, results: dict, pair: str, unit: str = "N"):
    """|R| in ``pair`` against the transmission angle μ of ``motion`` (degrees), one dotted curve per
    named force result on that motion: a reaction grows as μ leaves 90°. Returns the axes."""
    ax = plt.subplots(figsize=(8, 3.6))[1]
    mu = np.degrees(motion.transmission)
    for label, result in results.items():
        ax.plot(mu, result.reactions[pair].magnitude, ".", ms=2, label=label)
    ax.set(xlabel="transmission angle μ, degrees", ylabel=f"|R_{pair}|, {unit}")
    ax.grid(alpha=0.3)
    ax.legend()
    return ax


def plot_drive(drive, unit: str = "N·m"):
    """A :class:`mechlab.kinetostatics.drive.Drive`'s crank torque M_1(φ) and, dashed, the motor's
    torque referred to the crank (M_1/η where it drives, M_1·η where the crank drives it back). Returns the axes."""
    ax = plt.subplots(figsize=(8, 3))[1]
    deg = np.degrees(drive.phi)
    ax.plot(deg, drive.torque, label="crank torque $M_1$")
    ax.plot(deg, drive.motor_torque, "--", label="motor ($M_1/\\eta$ or $M_1\\eta$)")
    ax.set(xlabel="φ, degrees", ylabel=f"torque, {unit}")
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    return ax
