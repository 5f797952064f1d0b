"""Controls for the curved-slot dwell mechanism (Zinchenko et al., 2013, §3): λ, the pivot distance, the dwell
[φ1, φ2] (degrees), the transition law and the roller radius, driving the drawing (slot in the
moving link, dwell arc highlighted) and the law ψ, ψ′, ψ″; the status line gives the dwell
angle and the largest pressure angle."""

from __future__ import annotations

import numpy as np

from ..synthesis.dwell_slot import TRANSITIONS, curved_slot_dwell
from . import Choice, Control, MechanismExplorer


class DwellExplorer(MechanismExplorer):
    """Sliders → :func:`mechlab.synthesis.dwell_slot.curved_slot_dwell` → drawing and law; a bad design
    (φ1 ≥ φ2, λ = 1, a roller too large for the slot's curvature) shows its message instead."""

    def __init__(self, lam=0.5, phi1_deg=60.0, phi2_deg=150.0, pivot_distance=1.0, transition="quintic",
                 roller_radius=0.0, n: int = 121, *, live: bool | None = None, question: str | None = None):
        controls = {
            "lam": Control("λ = l_OA/l_OB", 0.1, 3.0, 0.05, lam),
            "pivot_distance": Control("pivot distance OB", 0.5, 3.0, 0.1, pivot_distance),
            "phi1": Control("dwell from φ1", 1.0, 179.0, 1.0, phi1_deg, "deg"),
            "phi2": Control("dwell to φ2", 1.0, 179.0, 1.0, phi2_deg, "deg"),
            "roller_radius": Control("roller radius ρ", 0.0, 0.5, 0.01, roller_radius),
            "transition": Choice("transition", TRANSITIONS, transition),
        }
        # the slotted link swings through its whole law over the turn: a drawing about as tall as it is wide,
        # given a column of its own proportions (and the figure the height for it)
        super().__init__(self._build, controls, n=n, live=live, question=question,
                         title="Curved-slot dwell mechanism (Zinchenko et al., 2013, §3), lengths dimensionless",
                         figsize=(9.5, 5.4), mechanism_width=1.1)

    @staticmethod
    def _build(lam, pivot_distance, phi1, phi2, roller_radius, transition):
        return curved_slot_dwell(lam, phi1, phi2, pivot_distance, transition, roller_radius=roller_radius)

    def _status(self) -> str:
        """The dwell and the largest pressure angle only: a roller in a curved slot has no transmission angle."""
        th = np.degrees(self.motion.pressure_angle)
        i = int(np.argmax(th))
        return (f"dwell ψ_B = {np.degrees(self.mechanism.law.psi_dwell):.2f}°, largest pressure angle {th[i]:.1f}° "
                f"at φ = {np.degrees(self.motion.phi[i]):.0f}°")


def dwell_explorer(**kwargs) -> DwellExplorer:
    """The dwell explorer with its defaults (λ = 0.5, [60°, 150°], quintic)."""
    return DwellExplorer(**kwargs)
