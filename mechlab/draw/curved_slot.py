"""A side-by-side animation of a linkage, its curved-slot twin and the relative path, a law
plotted against its base mechanism's (each mechanism drawn from its own ``sketch()``), and the
four-bar's two assemblies as the pin's two arcs in the rocker's frame."""

from __future__ import annotations

import textwrap
from dataclasses import replace

import matplotlib.pyplot as plt
import numpy as np

from ..analysis.equivalence import base_law, equivalent_slot, relative_path
from . import ROLE_STYLES, Animation, drawing_class, fill_axes, mechanism_name

SLOT_STYLE = ROLE_STYLES["slot"]


def animate_equivalence(mechanism, n: int = 30, interval: int = 100, figsize=(9, 3.2), dpi: int = 55) -> Animation:
    """Three panels moving together: the linkage, its curved-slot twin (Zinchenko et al., 2013, §1),
    and the pin's relative path in the output link's frame with the pin on it."""
    twin = equivalent_slot(mechanism)
    fig, axes = plt.subplots(1, 3, figsize=figsize, dpi=dpi)
    fig.subplots_adjust(left=0.02, right=0.98, top=0.8, bottom=0.08, wspace=0.1)   # room for two-line titles
    left = drawing_class(mechanism)(axes[0], mechanism, trace="A", n=n, readout=True)
    right = drawing_class(twin)(axes[1], twin, trace="A", n=n)
    for d, title in ((left, mechanism_name(mechanism)), (right, "its curved-slot twin")):
        d.autoscale()
        # a long name on two lines, from the left edge: legible in a frame, clear of the φ readout at the right
        d.ax.set_title(textwrap.fill(title, 24), fontsize=12, loc="left")
    x0, x1, y0, y1 = left.bounds()
    x2, x3, y2, y3 = right.bounds()
    for d in (left, right):   # one scale for both, each filling its panel
        fill_axes(d.ax, (min(x0, x2), max(x1, x3), min(y0, y2), max(y1, y3)))
    # the crank angle in the figure's lower right corner, clear of the titles
    left.readout.set_transform(fig.transFigure)
    left.readout.set_position((0.99, 0.02))
    phi = mechanism.cycle(n)
    rel = relative_path(mechanism, phi).p
    dense = relative_path(mechanism, mechanism.cycle(361)).p
    ax = axes[2]
    ax.set_aspect("equal")
    slot = twin.slot_mechanism.slot
    if slot.periodic:   # the whole closed curve: both branches (α1–α1 and α2–α2 for a circle)
        ax.plot(*slot.points(np.linspace(slot.t0, slot.t1, 300)).T, color="0.6", lw=0.8, ls="--")
    ax.plot(*twin.slot_samples(200).T, **SLOT_STYLE)
    ax.plot(*dense.T, color="#d62728", lw=1)
    ax.plot([0], [0], marker="o", ms=7, mfc="white", mec="#333333", ls="none")
    (pin,) = ax.plot([], [], "o", mfc="white", mec="#1f4e79", ms=7)
    ax.set_title("pin A in the output\nlink's frame", fontsize=12)
    for a in axes:   # diagrams: no ticks (they cost most of each frame's rendering)
        a.set_axis_off()

    def frame(i):
        pin.set_data([rel[i, 0]], [rel[i, 1]])
        return [*left.set_frame(i), *right.set_frame(i), pin]

    anim = Animation(fig, frame, frames=n, interval=interval, blit=False)
    anim.drawings = (left, right)
    plt.close(fig)
    return anim


def plot_against_base(mechanism, phi=None, axes=None):
    """ψ (degrees), ψ′, ψ″ (or s, s′, s″) of a mechanism with its base mechanism's law dashed,
    each axis naming its quantity and unit."""
    phi = mechanism.cycle(361) if phi is None else phi
    mo = mechanism.motion(phi)
    k = base_law(mechanism, phi)
    out = mo.output
    angular = out.kind == "angle"
    law = (out.value, out.d, out.dd)
    names = ("ψ (degrees)", "ψ′ (–)", "ψ″ (1/rad)") if angular else \
        ("s (length)", "s′ (length/rad)", "s″ (length/rad²)")
    if axes is None:
        _, axes = plt.subplots(1, 3, figsize=(10, 2.8))
    deg = np.degrees(phi)
    for ax, y, yk, name in zip(axes, law, (k.theta, k.d, k.dd), names, strict=False):
        if angular and name.startswith("ψ "):   # continuous, in degrees, the base law on the same branch
            y, yk = np.unwrap(y), np.unwrap(yk)
            y, yk = np.degrees(y), np.degrees(yk + 2 * np.pi * np.round((y[0] - yk[0]) / (2 * np.pi)))
        ax.plot(deg, y, label=mechanism_name(mechanism))
        ax.plot(deg, yk, "--", label="base mechanism")
        ax.set_ylabel(name)
        ax.set_xlabel("crank angle φ (degrees)")
        ax.grid(True, alpha=0.3)
    # above the first panel, outside it: the two laws end where a legend in a corner would sit
    axes[0].legend(fontsize=8, loc="lower left", bbox_to_anchor=(0.0, 1.01), ncols=2, frameon=False,
                   borderaxespad=0.1)
    return axes


# Zinchenko et al. (2013) name the two arcs of the circle about B by their end points
ARC_NAMES = {1: "kc = +1 (α1–α1)", -1: "kc = −1 (α2–α2)"}


def plot_assembly_arcs(fourbar, n: int = 721, ax=None):
    """The pin A of a four-bar in the rocker's frame (E at the origin, B on the x axis), for both assemblies
    k_c = ±1: two arcs of the circle of radius l_AB about B (dashed), mirror images in the rocker's axis E→B
    (after Zinchenko et al., 2013, Fig. 2). Lengths in units of the frame OE; returns the Figure."""
    from ..mechanisms.fourbar import FourBar
    from ..validate import check_value, count, mechanism

    fourbar = check_value("fourbar", fourbar, mechanism(FourBar))
    n = check_value("n", n, count(2))
    if ax is None:
        _, ax = plt.subplots(figsize=(7, 5))
    phi = fourbar.cycle(n)
    g, b, r = fourbar.ground, fourbar.rocker, fourbar.coupler
    t = np.linspace(0, 2 * np.pi, 200)
    ax.plot((b + r * np.cos(t)) / g, r * np.sin(t) / g, "--", color="0.6", lw=0.8)
    for k, name in ARC_NAMES.items():
        ax.plot(*relative_path(replace(fourbar, assembly=k), phi).p.T / g, lw=3, label=name)
    ax.plot([0, b / g], [0, 0], "k-", lw=1)
    ax.plot([0], [0], "k^", ms=9)
    ax.set(xlabel="x along E→B (units of the frame OE)", ylabel="y (units of OE)", aspect="equal")
    ax.set_title("pin A in the rocker's frame (after Zinchenko et al., 2013, Fig. 2)", fontsize=10)
    ax.legend(fontsize=8)
    return ax.figure
