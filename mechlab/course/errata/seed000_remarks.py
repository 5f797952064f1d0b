"""Four places of Zinchenko et al. (2013) found on re-reading §§1-3, each derived and recomputed."""

from __future__ import annotations

import numpy as np

from ...analysis.equivalence import equivalent_slot
from ...mechanisms.fourbar import FourBar
from ...mechanisms.slotted import SlottedLink
from ...synthesis.dwell_slot import curved_slot_dwell, slotted_link_law, two_branch_slot
from . import Claim, Erratum

NB05 = "05_dwell_curved_slot.ipynb"
NB01 = "02_equivalence.ipynb"


def _arctangent_rotating():
    # λ > 1: 1 + λ cos φ changes sign at cos φ = −1/λ, where the principal arctangent jumps by π
    lam = 1.5
    turn = np.arccos(-1 / lam)
    phi = np.linspace(turn + 0.05, np.pi - 0.05, 25)
    simulated = SlottedLink(lam, 1.0).motion(phi).psi           # the rotating link, lifted along the turn
    printed = np.arctan(lam * np.sin(phi) / (lam * np.cos(phi) + 1))
    return Claim(simulated, printed, slotted_link_law(lam, phi).psi, 1e-12,
                 f"λ = 1.5, φ from {np.degrees(turn) + 2.9:.1f}° to 177.1° (past cos φ = −1/λ, φ = "
                 f"{np.degrees(turn):.2f}°): the simulated link angle against arctg(λ sin φ/(λ cos φ + 1)) "
                 f"(off by π) and the quadrant-correct atan2(λ sin φ, 1 + λ cos φ), continued along the turn")


def _pressure_limits():
    m = curved_slot_dwell(0.5, np.radians(0.5), np.radians(179.5))
    th = np.degrees(m.motion(np.radians([0.5, 179.5])).pressure_angle)
    psi_b = m.law.psi_dwell
    assert abs(th[0] - 90) < 0.5 and abs(th[1] - 90) < 1.5
    return (f"λ = 0.5, dwell [0.5°, 179.5°]: through the slot θ(φ1) = {th[0]:.2f}°, θ(φ2) = {th[1]:.2f}°, both → 90° "
            f"as φ1 → 0 and φ2 → π (φ2 = 0 leaves no dwell); the printed θ = π/2 − (φ1 − ψ1) with ψ1 = ψ_B gives "
            f"90° at φ1 = 0 only if ψ_B = 0 (here ψ_B = {np.degrees(psi_b):.3f}°), with ψ1 = ψ_K(φ1) it does")


def _two_branch_jump():
    lam = 0.5
    tb = two_branch_slot(lam, np.radians(150))
    m = curved_slot_dwell(lam, np.radians(60), np.radians(150))
    eps = 1e-6
    cubic = m.motion(np.array([-eps, eps])).dpsi
    assert abs(tb.velocity_jump - 2 * lam / (lam + 1)) < 1e-12 and abs(cubic[1] - cubic[0]) < 1e-5
    return (f"λ = 0.5: with the dwell arc through E (φ1 = 0, ψ'(0+) = {tb.dpsi_after:.1e}) the jump is "
            f"2ψ_K'(0) − 2ψ'(0+) = {tb.velocity_jump:.4f} = 2λ/(λ+1); with the cubic law of (21), ψ'(0+) = "
            f"ψ_K'(0) = {slotted_link_law(lam, 0.0).d:.4f} and the simulated ψ' passes E without a jump "
            f"({cubic[0]:.6f} → {cubic[1]:.6f})")


def _notation():
    # l_BE ≠ l_OE, so the twin's pivot distance tells which of the two §2's l_OB is
    l_oa, l_ab, l_be, l_oe = 0.3, 0.8, 1.2, 1.0
    fb = FourBar(l_oa, l_ab, l_be, l_oe, 1)
    slot = equivalent_slot(fb).slot_mechanism
    assert slot.pivot_distance == l_oe != l_be and slot.crank == l_oa
    return (f"the four-bar O-A-B-E (l_OA, l_AB, l_BE, l_OE) = ({l_oa:g}, {l_ab:g}, {l_be:g}, {l_oe:g}): its slotted "
            f"twin has crank {slot.crank:g} and pivot distance {slot.pivot_distance:g} = l_OE (not l_BE = {l_be:g}); "
            f"so §2's B (the slotted link's pivot) is §1's E, and λ = l_OA/l_OB of (18) is l_OA/l_OE = "
            f"{slot.crank / slot.pivot_distance:g}, not l_OA over the distance to §1's joint B")


ERRATA = [
    Erratum(source="000", where="§3, β(φ) and (18) for the rotating link λ > 1",
            printed=r"$\beta = \mathrm{arctg}\,\frac{\lambda\sin\varphi}{\lambda\cos\varphi + 1} + \dots$, "
                    r"said to hold for λ > 1 too",
            correct=r"$\psi_K = \mathrm{atan2}(\lambda\sin\varphi,\ 1 + \lambda\cos\varphi)$ continued along "
                    r"the turn: the principal arctg is off by π once $\cos\varphi < -1/\lambda$",
            check=_arctangent_rotating, notebook=NB05),
    Erratum(source="000", where="§3, pressure angle: limiting cases",
            printed=r"if $\varphi_1 = 0$ (or $\varphi_2 = 0$), then $\theta = \pi/2$",
            correct=r"$\theta \to \pi/2$ as $\varphi_1 \to 0$ or $\varphi_2 \to \pi$ "
                    r"(with $\psi_1 = \psi_K(\varphi_1)$)",
            check=_pressure_limits, notebook=NB05, kind="remark"),
    Erratum(source="000", where="§3, the drawing of the two-branch slot: velocity jump",
            printed=r"the jump of $\psi'$ at φ = 0 is $2\lambda\omega_1/(\lambda+1)$",
            correct=r"$2(\psi_K'(0) - \psi'(0^+))\,\omega_1$; it is $2\lambda\omega_1/(\lambda+1)$ only when the "
                    r"link rests as the pin passes E (a dwell arc through E, φ1 = 0)",
            check=_two_branch_jump, notebook=NB05, kind="remark"),
    Erratum(source="000", where="§1 against §§2-3: the letter B",
            printed="B is the coupler-rocker joint of the four-bar OABE in §1 and the slotted link's pivot in §§2-3",
            correct="§2's B (in λ = l_OA/l_OB) is §1's E, the rocker's pivot",
            check=_notation, notebook=NB01, kind="remark"),
]
