"""Seed 000 §3 (dwell with a curved slot): the printed mistakes, each recomputed.

Example used throughout: λ = 0.5, l_OB = 1, dwell [φ1, φ2] = [60°, 150°], the seed's cubic
transitions (21)-(23), frame of §2 (φ = 0 where A is farthest from B).
"""

from __future__ import annotations

import numpy as np

from ...synthesis.dwell_slot import DwellLaw, curved_slot_dwell, slotted_link_law
from . import Claim, Erratum

NB = "05_dwell_curved_slot.ipynb"
LAM, P1, P2 = 0.5, np.radians(60.0), np.radians(150.0)


def _law():
    return DwellLaw(LAM, P1, P2, "cubic")


def _psi_b():
    law = _law()
    a1 = -LAM / (3 * (LAM + 1) * P1**2)                     # printed (and correct) a1
    printed = -LAM * P1 / (3 * (LAM + 1))
    correct = LAM * P1 / (3 * (LAM + 1))
    psi0_printed = printed + a1 * P1**3                      # ψ(0) from (21) with the printed ψ_B
    assert abs(correct - law.psi_dwell) < 1e-15
    return Claim(0.0, psi0_printed, correct + a1 * P1**3, 1e-12,
                 f"λ = 0.5, φ1 = 60°: ψ(0) must be 0; (21) gives ψ(0) = ψ_B + a1 φ1³ = {np.degrees(psi0_printed):.3f}° "
                 f"with the printed ψ_B = {np.degrees(printed):.3f}°, 0 with ψ_B = +{np.degrees(correct):.3f}°")


def _a2():
    W = np.pi - P2
    printed = LAM / (3 * (1 - LAM) * W**2)
    correct = LAM / (3 * (LAM - 1) * W**2)
    target = slotted_link_law(LAM, np.pi).d                     # (25): ψ_K'(π) = λ/(λ - 1)
    assert abs(_law().right.coef[3] - correct) < 1e-12
    return Claim(target, 3 * printed * W**2, 3 * correct * W**2, 1e-12,
                 f"λ = 0.5, φ2 = 150°: ψ'(π) = 3a2(π - φ2)² is {3 * printed * W**2:+.3f} with the printed a2 = "
                 f"{printed:.4f}, but (25) requires λ/(λ - 1) = {target:+.3f}: a2 = {correct:.4f}")


def _beta_left():
    law = _law()
    K0 = slotted_link_law(LAM, np.array([0.0, P1]))
    c = LAM * P1 / (3 * (LAM + 1))
    k = LAM / (3 * (LAM + 1) * P1**2)
    # printed: β = atan(...) + c + k (φ1 - φ)        correct: β = atan(...) - c + k (φ1 - φ)³
    printed0 = K0.psi[0] + c + k * P1
    printed_d1 = K0.d[1] - k                                # β'(φ1) printed; the dwell needs β' = ψ_K'(φ1)
    b = law.beta(np.array([0.0, P1]))
    corrected = [K0.psi[0] - c + k * P1**3, K0.d[1] - 3 * k * (P1 - P1) ** 2]
    return Claim([0.0, K0.d[1]], [printed0, printed_d1], corrected, 1e-12,
                 text=(f"λ = 0.5, φ1 = 60°: the printed β(0) = {np.degrees(printed0):.3f}° (must be ψ_K(0) - ψ(0) = 0) "
                       f"and "
            f"β'(φ1) = {printed_d1:.4f} ≠ ψ_K'(φ1) = {K0.d[1]:.4f} (the slot would not join the dwell arc "
            f"smoothly); the corrected β gives β(0) = {b[0][0]:.1e}, β'(φ1) = {b[1][1]:.4f}"))


def _beta_right():
    law = _law()
    W = np.pi - P2
    Kpi = slotted_link_law(LAM, np.pi)
    printed_dbeta_pi = Kpi.d - LAM / ((1 - LAM) * W**2) * W**2   # derivative of the printed cubic term at π
    psi_d_printed = Kpi.d - printed_dbeta_pi
    correct = law.beta(np.pi)[1]
    return Claim(Kpi.d, psi_d_printed, Kpi.d - correct, 1e-12,
                 text=(f"λ = 0.5, φ2 = 150°: with the printed β, β'(π) = {printed_dbeta_pi:+.3f} and ψ'(π) = ψ_K'(π) - "
                       f"β'(π) = {psi_d_printed:+.3f} instead of ψ_K'(π) = {Kpi.d:+.3f} (a velocity jump of "
            f"{abs(2 * printed_dbeta_pi):.3f}·ω1 at φ = π); corrected β'(π) = {correct:.1e}"))


def _beta_middle():
    # on the dwell [φ1, φ2] the link stands at ψ_B, so β = ψ_K − ψ_B; truth: ψ_K − the simulated ψ
    m = curved_slot_dwell(LAM, P1, P2)
    phi = np.linspace(P1, P2, 7)
    K = slotted_link_law(LAM, phi).psi
    c = LAM * P1 / (3 * (LAM + 1))
    truth = K - m.motion(phi).psi
    return Claim(truth, K + c, K - c, 1e-12, text=(
        f"λ = 0.5, dwell [60°, 150°] at 7 angles: ψ_K − ψ(simulated) = β; the printed constant +λφ1/(3(λ+1)) = "
        f"+{np.degrees(c):.3f}° (the end pieces' wrong sign) puts the slot {np.degrees(2 * c):.3f}° off; with "
        f"−λφ1/(3(λ+1)) = −ψ_B it is exact"))


def _distance():
    m = curved_slot_dwell(LAM, P1, P2)
    lOA, lOB = m.crank, m.pivot_distance
    printed = np.sqrt((lOA * np.cos(0.0) - lOB) ** 2 + (lOA * np.sin(0.0)) ** 2)
    A = m.motion(0.0).points["A"].p
    true = float(np.hypot(*(A - np.array([-lOB, 0.0]))))
    correct = np.sqrt((lOA * np.cos(0.0) + lOB) ** 2 + (lOA * np.sin(0.0)) ** 2)
    return Claim(true, printed, correct, 1e-12,
                 text=(f"l_OA = 0.5, l_OB = 1, φ = 0: the printed S(0) = {printed:.3f} is the pin's nearest distance, "
                       f"but in the frame of (18) (B at (-l_OB, 0)) A is farthest from B at φ = 0: |AB| = {true:.3f}"))


def _pressure_at_phi1():
    m = curved_slot_dwell(LAM, P1, P2)
    theta = m.motion(P1).pressure_angle
    psiK = slotted_link_law(LAM, P1).psi
    printed = np.pi / 2 - (P1 - m.law.psi_dwell)
    correct = abs(np.pi / 2 - (P1 - psiK))
    return Claim(theta, printed, correct, 1e-12,
                 text=(f"λ = 0.5, [60°, 150°]: through the slot θ(φ1) = {np.degrees(theta):.3f}°; the printed formula "
                       f"with "
            f"ψ1 = ψ_B = {np.degrees(m.law.psi_dwell):.3f}° gives {np.degrees(printed):.3f}°; with the angle of the "
            f"line BA, ψ_K(φ1) = {np.degrees(psiK):.3f}°, it gives {np.degrees(correct):.3f}°"))


def _limit_120():
    m = curved_slot_dwell(LAM, P1, P2)
    th, where = m.max_pressure_angle()
    far = np.arctan(2 * (1 + LAM) / P1)
    assert abs(where) < 1e-5 and abs(th - far) < 1e-7
    # θ ≤ 60° at both slot ends needs φ1 ≥ 2(1 + λ)/tan 60° and π - φ2 ≥ 2(1 - λ)/tan 60°
    t60 = np.tan(np.radians(60.0))
    q1, q2 = 2 * (1 + LAM) / t60, np.pi - 2 * (1 - LAM) / t60
    edge = curved_slot_dwell(LAM, q1, q2)
    assert abs(edge.max_pressure_angle()[0] - np.radians(60.0)) < 1e-6 and np.degrees(q2 - q1) < 60.0
    return (f"λ = 0.5, [60°, 150°] (a 90° dwell): the worst pressure angle is {np.degrees(th):.2f}° at the slot's "
            f"far end φ = 0, tan θ = 2(1 + λ)/φ1, whatever the dwell length; keeping θ ≤ 60° at both ends allows "
            f"at most [{np.degrees(q1):.1f}°, {np.degrees(q2):.1f}°], a {np.degrees(q2 - q1):.1f}° dwell, with the "
            f"cubic")


ERRATA = [
    Erratum(source="000", where="§3, after (24)-(25): ψ_B from ψ(0) = 0",
            printed=r"$\psi_B = -\lambda\varphi_1/[3(\lambda+1)]$",
            correct=r"$\psi_B = +\lambda\varphi_1/[3(\lambda+1)]$",
            check=_psi_b, notebook=NB),
    Erratum(source="000", where="§3, coefficient a2 from (23), (25)",
            printed=r"$a_2 = \lambda/[3(1-\lambda)(\pi-\varphi_2)^2]$",
            correct=r"$a_2 = \lambda/[3(\lambda-1)(\pi-\varphi_2)^2]$",
            check=_a2, notebook=NB),
    Erratum(source="000", where="§3, slot profile β(φ) on [0, φ1]",
            printed=r"$\beta = \mathrm{arctg}(\dots) + \frac{\lambda\varphi_1}{3(\lambda+1)} + "
                    r"\frac{\lambda(\varphi_1-\varphi)}{3(\lambda+1)\varphi_1^2}$",
            correct=r"$\beta = \mathrm{arctg}(\dots) - \frac{\lambda\varphi_1}{3(\lambda+1)} + "
                    r"\frac{\lambda(\varphi_1-\varphi)^3}{3(\lambda+1)\varphi_1^2}$ (β = ψ_K - ψ)",
            check=_beta_left, notebook=NB),
    Erratum(source="000", where="§3, slot profile β(φ) on [φ2, π]",
            printed=r"$\beta = \mathrm{arctg}(\dots) + \frac{\lambda\varphi_1}{3(\lambda+1)} - "
                    r"\frac{\lambda(\varphi-\varphi_2)^3}{3(1-\lambda)(\pi-\varphi_2)^2}$",
            correct=r"$\beta = \mathrm{arctg}(\dots) - \frac{\lambda\varphi_1}{3(\lambda+1)} + "
                    r"\frac{\lambda(\varphi-\varphi_2)^3}{3(1-\lambda)(\pi-\varphi_2)^2}$",
            check=_beta_right, notebook=NB),
    Erratum(source="000", where="§3, slot profile β(φ) on [φ1, φ2] (the source's (23))",
            printed=r"$\beta = \mathrm{arctg}(\dots) + \frac{\lambda\varphi_1}{3(\lambda+1)}$",
            correct=r"$\beta = \mathrm{arctg}(\dots) - \frac{\lambda\varphi_1}{3(\lambda+1)} = \psi_K - \psi_B$ "
                    r"(the link dwells at ψ_B)",
            check=_beta_middle, notebook=NB),
    Erratum(source="000", where="§3, distance S(φ) from A to B",
            printed=r"$S = \sqrt{(l_{OA}\cos\varphi - l_{OB})^2 + (l_{OA}\sin\varphi)^2}$",
            correct=r"$S = \sqrt{(l_{OA}\cos\varphi + l_{OB})^2 + (l_{OA}\sin\varphi)^2}$ (φ = 0 farthest from B)",
            check=_distance, notebook=NB),
    Erratum(source="000", where="§3, pressure angle at φ = φ1",
            printed=r"$\theta = \pi/2 - (\varphi_1 - \psi_1)$ with $\psi_1 = \psi_B$ the link's dwell angle",
            correct=r"$\theta = |\pi/2 - (\varphi_1 - \psi_K(\varphi_1))|$, ψ_K the angle of the line BA",
            check=_pressure_at_phi1, notebook=NB),
    Erratum(source="000", where="§3, practical dwell limit",
            printed="a dwell over 120° makes the pressure angle large (the danger is on the dwell, θ at φ1)",
            correct="with the cubic law the worst pressure angle is at the slot's ends, set by φ1 and π - φ2, not "
                    "by the dwell's length",
            check=_limit_120, notebook=NB, kind="remark"),
]
