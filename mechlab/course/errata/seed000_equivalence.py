"""Printed mistakes in Zinchenko et al. (2013) §2 (half-turn relations, base mechanism), found while
deriving Tables 1-2 and formulas (12)-(20) anew (notebook 03_base_mechanism).

Evidence on the seed's own example [4]: l_OA = 0.3, l_AB = 0.8, l_BE = 1, l_OE = 1,
kc = +1, as its curved-slot twin in the seed's frame (ψ = ψ_K - β, formula (12)),
at φ = 60°, φ* = 2π - φ = 300°.
"""

from __future__ import annotations

import numpy as np

from ...analysis.equivalence import equivalent_slot
from ...analysis.half_turn import base_peaks, formula_18
from ...geometry import wrap
from ...mechanisms.fourbar import FourBar
from . import Claim, Erratum

NOTEBOOK = "03_base_mechanism.ipynb"


def _twin_at(phi_deg: float):
    slot = equivalent_slot(FourBar(0.3, 0.8, 1.0, 1.0, 1)).slot_mechanism   # seed frame
    phi = np.radians([phi_deg, 360.0 - phi_deg])
    mo, base, beta = slot.motion(phi), slot.base().motion(phi), slot.beta(phi)
    return mo, base, beta


def _check_13() -> str:
    mo, base, beta = _twin_at(60.0)
    actual = mo.psi[1]
    printed = base.psi[1] + beta.theta[0]            # ψ_K(φ*) + β
    correct = base.psi[1] - beta.theta[0]            # ψ_K(φ*) - β = -ψ_K(φ) - β
    other = -base.psi[0] - beta.theta[0]
    assert abs(wrap(other - actual)) < 1e-12
    return Claim(0.0, wrap(printed - actual), wrap(correct - actual), 1e-12,
                 text=(f"φ = 60°: ψ(φ*) = {np.degrees(actual):.4f}°, ψ_K(φ*) - β = {np.degrees(correct):.4f}°, "
            f"printed ψ_K(φ*) + β = {np.degrees(printed):.4f}° (off by 2β = {np.degrees(2 * beta.theta[0]):.4f}°); "
            f"compared: the wrapped difference from the simulated ψ(φ*)"))


def _check_15() -> str:
    mo, base, beta = _twin_at(60.0)
    actual = mo.dpsi[1]
    printed = -base.dpsi[0] + beta.d[0]
    correct = base.dpsi[0] + beta.d[0]
    return Claim(actual, printed, correct, 1e-12, f"φ = 60°: ψ'(φ*) = {actual:.6f}, ψ'_K(φ) + β' = {correct:.6f}, "
                                                  f"printed -ψ'_K(φ) + β' = {printed:.6f}")


def _check_peak() -> str:
    # the source means the peak of the modulus |ψ'_K| (the base mechanism's largest speed ratio)
    lam = 0.3
    phi = np.linspace(0, 2 * np.pi, 100001)
    d1 = formula_18(lam, phi).d
    printed = lam / (lam - 1)
    peak, _ = base_peaks(lam)
    measured = np.max(np.abs(d1))
    assert abs(measured - peak) < 1e-12 and abs(np.max(d1) - lam / (lam + 1)) < 1e-9
    return Claim(measured, printed, lam / (1 - lam), 1e-9, text=(
        f"λ = 0.3: peak |ψ'_K| = {measured:.4f} on 100001 points = λ/(1-λ); the printed λ/(λ-1) = {printed:.4f} "
        f"is ψ'_K's most negative value (at φ = π), not a peak of the modulus; the signed maximum is "
        f"λ/(λ+1) = {np.max(d1):.4f}"))


ERRATA = [
    Erratum(source="000", where="formula (13)",
            printed=r"$\psi(\varphi^*) = \psi_K(\varphi^*) + \beta = -\psi_K(\varphi) - \beta$",
            correct=r"$\psi(\varphi^*) = \psi_K(\varphi^*) - \beta = -\psi_K(\varphi) - \beta$ (the middle sign; Table "
                    r"2 is right)",
            check=_check_13, notebook=NOTEBOOK),
    Erratum(source="000", where="formula (15), final expression",
            printed=r"$\psi'(\varphi^*) = -\psi'_K(\varphi) + \beta'(\varphi)$",
            correct=r"$\psi'(\varphi^*) = \psi'_K(\varphi) + \beta'(\varphi)$ (as in Table 2)",
            check=_check_15, notebook=NOTEBOOK),
    Erratum(source="000", where="§3, after (25): peak of the base mechanism's velocity analog",
            printed=r"the maximum of the base mechanism's $\psi'_K$ is $\lambda/(\lambda-1)$",
            correct=r"the peak of $|\psi'_K|$ is $\lambda/|1-\lambda|$; for $\lambda<1$, $\lambda/(\lambda-1)<0$ is "
                    r"the minimum and the maximum is $\lambda/(\lambda+1)$",
            check=_check_peak, notebook=NOTEBOOK),
]
