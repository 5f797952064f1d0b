"""The trade-offs of :func:`mechlab.design.candidates` at a glance: a radar of the criteria and the laws overlaid.

The figure is made once with a line for every family; :meth:`ComparisonFigure.update` moves
those lines to a new comparison (hidden where a family was refused), so an explorer redraws
in place.
"""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np
from matplotlib.figure import Figure

from ..design import FAMILIES, Comparison
from .access import category_style, set_alt

# radar spokes: (criterion, label); each is scaled by the largest among the candidates (smaller is better)
# (the invariants in the glossary's symbols: the library's B and C are C_v and C_a)
SPOKES = (("B", "peak velocity\n$C_v$"), ("C", "peak\nacceleration $C_a$"), ("pressure_angle", "pressure\nangle"),
          ("size", "size"), ("motor_power", "motor\npower"), ("parts", "parts and\npairs"))
FIGSIZE = (8.8, 4.4)   # inches: 880 px at 100 dpi, inside a notebook's output area (about 912 px)
# a family's colour (Okabe-Ito), dash on the laws and marker on the radar's spokes: told apart without colour too
STYLES = {f: category_style(i) for i, f in enumerate(FAMILIES)}
COLOURS = {f: style["color"] for f, style in STYLES.items()}


def _spoke(c, key):
    if key == "parts":
        s = c.criteria.structure
        return s.parts + s.lower_pairs + 2 * s.higher_pairs  # a higher pair wears: it counts twice
    return getattr(c.criteria, key)


class ComparisonFigure:
    """A radar of the criteria (left) and every candidate's output law over the crank turn (right)."""

    def __init__(self, comparison: Comparison, fig: Figure | None = None):
        self.fig = fig if fig is not None else plt.figure(figsize=FIGSIZE, layout="constrained")
        self.radar = self.fig.add_subplot(1, 2, 1, projection="polar")
        self.laws = self.fig.add_subplot(1, 2, 2)
        angles = np.linspace(0.0, 2 * np.pi, len(SPOKES), endpoint=False)
        self._angles = np.append(angles, angles[0])
        self.radar.set_xticks(angles, [label for _, label in SPOKES], fontsize=9)
        self.radar.tick_params(axis="x", pad=10)
        # each label outward of its spoke's end
        for text, angle in zip(self.radar.get_xticklabels(), angles, strict=False):
            c = np.cos(angle)
            text.set_horizontalalignment("left" if c > 0.2 else "right" if c < -0.2 else "center")
        self.radar.set_ylim(0.0, 1.05)
        self.radar.set_yticks([0.25, 0.5, 0.75, 1.0], ["", "0.5", "", "1"], fontsize=8)
        self.radar.set_rlabel_position(120.0)
        self.radar.set_title("criteria, each ÷ the largest (smaller is better)", fontsize=10)
        self.laws.set_xlabel("crank angle φ (deg)")
        self.laws.set_ylabel("output ÷ amplitude (–)")
        self.laws.set_xlim(0.0, 360.0)
        self.laws.set_xticks(np.arange(0, 361, 60))
        self.laws.grid(True, alpha=0.3)
        self.laws.set_title("output laws over one crank turn", fontsize=10)
        self.spokes = {f: self.radar.plot([], [], color=COLOURS[f], ls=STYLES[f]["ls"], marker=STYLES[f]["marker"],
                                          ms=6, lw=2, label=f)[0] for f in FAMILIES}
        self.curves = {f: self.laws.plot([], [], color=COLOURS[f], ls=STYLES[f]["ls"], marker=STYLES[f]["marker"],
                                         markevery=60, ms=6, lw=2, label=f)[0] for f in FAMILIES}
        self.update(comparison)

    def update(self, comparison: Comparison) -> None:
        """Show ``comparison``: its candidates' lines move, the refused families' lines hide."""
        shown = {c.family: c for c in comparison.candidates}
        worst = {k: max((_spoke(c, k) for c in shown.values()), default=1.0) or 1.0 for k, _ in SPOKES}
        phi = np.linspace(0.0, 2 * np.pi, 721)
        for family in FAMILIES:
            spoke, curve = self.spokes[family], self.curves[family]
            c = shown.get(family)
            spoke.set_visible(c is not None)
            curve.set_visible(c is not None)
            if c is None:
                continue
            r = [_spoke(c, k) / worst[k] for k, _ in SPOKES]
            spoke.set_data(self._angles, r + r[:1])
            x = np.asarray(c.design.mechanism.motion(c.design.phase + phi).output.value, float)
            scale = 1.0 if comparison.spec.rotary else c.design.scale
            x = (x - x[0]) * scale / comparison.spec.amplitude
            # a table indexing clockwise rises too
            x = x * np.sign(x[-1]) if comparison.spec.motion == "index" else x - x.min()
            curve.set_data(np.degrees(phi), x)
        self.laws.relim()
        self.laws.autoscale_view(scalex=False)
        handles = [self.curves[f] for f in shown]
        legend = self.laws.get_legend()
        if legend is not None:
            legend.remove()
        if handles:
            self.laws.legend(handles=handles, loc="best", fontsize=8)
        set_alt(self.fig, self.describe(shown))

    @staticmethod
    def describe(shown: dict) -> str:
        """The alternative text for candidates ``shown`` (family → candidate): who is best on each criterion."""
        if not shown:
            return "Comparison of candidate mechanisms: no family meets the specification, nothing is drawn."
        best = [f"{label}: {min(shown, key=lambda f, k=key: _spoke(shown[f], k))}" for key, label in SPOKES]
        return (f"Comparison of {len(shown)} candidate mechanisms ({', '.join(shown)}). Left, a radar of six criteria, "
                f"each divided by the largest, smaller is better; right, each candidate's output law over one crank "
                f"turn. Smallest on each criterion: {'; '.join(best)}.")


def comparison_figure(comparison: Comparison, fig: Figure | None = None) -> Figure:
    """The trade-off figure of ``comparison`` (see :class:`ComparisonFigure`)."""
    return ComparisonFigure(comparison, fig).fig
