"""Mistakes in Vainer & Shatokhina (the offset spherical Geneva), kinematics
and Table 1. Each check recomputes the evidence with :mod:`mechlab.mechanisms.geneva` (the exact
3-D model and the closed forms). The mean-torque formula's n-vs-1/n slip is recorded
with the force chapter (``seed003_forces.py``); its ρ_i-vs-r_i slip is recorded here.
"""

from __future__ import annotations

import numpy as np

from ...mechanisms.spherical_geneva import SphericalGeneva
from ...synthesis.geneva import table1_comparison
from . import Claim, Erratum

NOTEBOOK = "10_geneva_spherical.ipynb"
_G = SphericalGeneva(40.0, 15.0, 4)  # Table 1's R, e with z = 4


def _check_c1() -> str:
    cells = []
    for z in (3, 4, 5, 6, 8):
        g = SphericalGeneva(40.0, 15.0, z)
        al = np.linspace(-g.alpha0, g.alpha0, 201)
        m = g.model(al)
        dev = float(np.max(np.abs(np.cos(m.gamma) - np.cos(al) * np.sin(g.cone_angle))))
        assert abs(g.seed_c1()) < 1e-14 and dev < 1e-15
        cells.append(abs(g.seed_c1()))
    return (f"R = 40, e = 15, z = 3…8: C1 = (cot²ψ - R² cos²β0/ρ0²)·ρ0/(2e) ≤ {max(cells):.0e} (zero by (3)); "
            f"the 3-D model gives cos γ = cos α sin ψ to 1e-15, so (11) is exact, not an approximation")


def _check_21() -> str:
    al = np.linspace(-_G.alpha0, _G.alpha0, 2001)
    p = _G.position(al)
    i = int(np.argmax(p.d))
    assert al[i] == 0.0 and abs(p.d[i] - 1 / np.sqrt(_G.a2 - 1)) < 1e-14
    return Claim(p.dd[i], 1 / np.sqrt(_G.a2 - 1), 0.0, 1e-12,
                 text=(f"z = 4: at α = 0, ω/ω1 = {p.d[i]:.4f} = 1/sqrt(a² - 1) = tan ψ (its maximum) while ε/ω1² = "
            f"{abs(p.dd[i]):.1g}: (21) is the velocity, not the acceleration (compared: ε/ω1² at α = 0)"))


def _check_deps() -> str:
    a2 = _G.a2
    s = np.sqrt(a2 - 1)
    h = 1e-6
    al = 0.3
    num = (_G.position(al + h).dd - _G.position(al - h).dd) / (2 * h)
    x2 = np.sin(al) ** 2
    bracket = x2**2 - 6 * a2 * x2 + a2**2 - 1
    correct = -s * np.cos(al) * bracket / (a2 - 1 + x2) ** 3
    printed = np.sqrt((a2 - 1) ** 3) * bracket
    u2 = 3 * a2 - np.sqrt(8 * a2**2 + 1)
    assert abs(np.sin(_G.acceleration_extreme_alpha()) ** 2 - u2) < 1e-14
    return Claim(num, printed, correct, 1e-7,
                 text=(f"z = 4, α = 0.3 rad: dε/dα (central difference) = {num:.6f}; corrected formula {correct:.6f}; "
            f"printed {printed:.6f}. The root u = {u2:.5f} of u² - 6a²u + a⁴ - 1 = 0 is sin²α1, not sin 2α1"))


def _check_impact() -> str:
    imp = _G.impacts()
    g0 = SphericalGeneva(40.0, 0.0, 4)
    assert imp.kind == "hard" and imp.entry_velocity_jump > 0.2 and g0.impacts().kind == "soft"
    return (f"R = 40, e = 15, z = 4: the wheel's ψ' jumps from 0 to {imp.entry_velocity_jump:.4f} at entry "
            f"(α0 = {np.degrees(_G.alpha0):.2f}° < 90°) — a velocity jump, i.e. a hard impact; only e = 0 "
            f"(α0 = 90°, ψ' = {abs(g0.impacts().entry_velocity_jump):.0e}) gives a soft one")


def _cells():
    return {(c.z, c.column): c for c in table1_comparison()}


def _check_table_z8() -> str:
    g = SphericalGeneva(40.0, 15.0, 8)
    a1 = g.acceleration_extreme_alpha()
    p1 = g.position(a1)
    eps_move, at = g.max_acceleration()
    assert a1 > g.alpha0 and p1.theta > g.beta0 and at == g.alpha0
    truth = [abs(eps_move), np.degrees(g.alpha0), np.degrees(g.beta0)]
    # the corrections to their stated digits; the printed values are rounded to two decimals
    return Claim(truth, [0.46, 52.93, 24.85], [0.453, 45.58, 22.5], [0.0005, 0.005, 1e-12], printed_tol=0.005,
                 text=(f"z = 8: the stationary point of (22) is α = {np.degrees(a1):.2f}°, β = "
                       f"{np.degrees(p1.theta):.2f}° "
            f"(|ε| = {abs(p1.dd):.4f}), beyond α0 = {np.degrees(g.alpha0):.2f}°, β0 = 22.5°: the pin has left the "
            f"slot. While the wheel moves |ε| is largest at entry: {eps_move:.4f} at α = {np.degrees(at):.2f}°"))


def _check_table_z3() -> str:
    c = _cells()
    g = SphericalGeneva(40.0, 15.0, 3)
    at_printed = abs(g.position(np.radians(16.40)).dd)
    assert at_printed > 2.53
    keys = ("eps_max", "alpha1", "beta1")
    return Claim([c[3, k].computed for k in keys], [c[3, k].printed for k in keys], [2.536, 16.872, 28.714],
                 [0.0005, 0.0005, 0.0005], printed_tol=0.005,
                 text=(f"z = 3: ε_max/ω1² = {c[3, 'eps_max'].computed:.4f} (printed 2.51) at α1 = "
                       f"{c[3, 'alpha1'].computed:.2f}° "
            f"(16.40), β1 = {c[3, 'beta1'].computed:.2f}° (27.80); even at the printed α1, |ε| = {at_printed:.4f}"))


def _check_table_angles() -> str:
    c = _cells()
    parts = []
    for z in (4, 5, 6):
        g = SphericalGeneva(40.0, 15.0, z)
        b_at_printed = np.degrees(g.position(np.radians(c[z, "alpha1"].printed)).theta)
        assert abs(b_at_printed - c[z, "beta1"].printed) > 0.05
        parts.append(f"z = {z}: α1 {c[z, 'alpha1'].printed:.2f}→{c[z, 'alpha1'].computed:.2f}°, β1 "
                     f"{c[z, 'beta1'].printed:.2f}→{c[z, 'beta1'].computed:.2f}° (β at the printed α1: "
                     f"{b_at_printed:.2f}°)")
    g6 = SphericalGeneva(40.0, 15.0, 6)
    assert abs(g6.rho0 - 25.0) < 1e-12
    parts.append(f"z = 6: ρ0 = 25 mm exactly, α0 = arccos 0.6 = {np.degrees(g6.alpha0):.2f}° (printed 53.15°)")
    keys = [(4, "alpha1"), (5, "alpha1"), (6, "alpha1"), (4, "beta1"), (5, "beta1"), (6, "beta1"), (6, "alpha0")]
    return Claim([c[k].computed for k in keys], [c[k].printed for k in keys],
                 [27.074, 34.919, 41.593, 27.257, 26.258, 25.598, 53.130], 0.0005, "; ".join(parts),
                 printed_tol=0.005)


def _check_drive_arm() -> str:
    al = np.linspace(-_G.alpha0, _G.alpha0, 9)
    wheel, crank = _G.force_arms(al)
    m = _G.model(al)
    assert np.allclose(wheel, m.r)
    i = 4  # α = 0
    return Claim(crank, m.rho * m.beta.d, m.r * m.beta.d, 1e-12 * np.max(crank),
                 text=(f"z = 4, α = 0, unit force on the slot: crank torque arm (3-D cross product) {crank[i]:.3f} mm "
                       f"= "
            f"r·ω/ω_KP = {m.r[i]:.3f}·{m.beta.d[i]:.4f}; printed ρ·ω/ω_KP = {m.rho[i] * m.beta.d[i]:.3f} mm "
            f"(compared at 9 positions over the motion)"))


ERRATA = [
    Erratum(source="004", where="formulas (10)-(11), the term C1",
            printed=r"$\cos\gamma = ((\mathrm{tg}^{-2}\psi - R^2\rho_0^{-2}\cos^2\beta_0)\,\rho_0/(2e + "
                    r"\cos\alpha))\sin\psi$; "
                    r"C1 'of 3rd-4th order of smallness, neglected'",
            correct=r"$\cos\gamma = (C_1 + \cos\alpha)\sin\psi$ with $C_1 \equiv 0$ by (3): (11) $\cos\gamma = "
                    r"\cos\alpha\sin\psi$ is exact",
            check=_check_c1, notebook=NOTEBOOK, kind="remark"),
    Erratum(source="004", where="formula (21)",
            printed=r"$\varepsilon_{MX} = \omega_{KP}/\sqrt{a^2-1}$",
            correct=r"$\omega_{MX,\max} = \omega_{KP}/\sqrt{a^2-1} = \omega_{KP}\tan\psi$ (a velocity; ε = 0 there)",
            check=_check_21, notebook=NOTEBOOK),
    Erratum(source="004", where="derivative of (20) before (22), and its substitution",
            printed=r"$d\varepsilon/d\alpha = \sqrt{(a^2-1)^3}\,(\sin^4\alpha - 6a^2\sin^2\alpha + a^4 - 1)$; $u = "
                    r"\sin 2\alpha$",
            correct=r"$d\varepsilon/d\alpha = -\omega^2\sqrt{a^2-1}\cos\alpha\,(\sin^4\alpha - 6a^2\sin^2\alpha + a^4 "
                    r"- 1)/(a^2-1+\sin^2\alpha)^3$; $u = \sin^2\alpha$ ((22) itself is right)",
            check=_check_deps, notebook=NOTEBOOK),
    Erratum(source="004", where="text after (21): impacts at the start and end of the motion",
            printed="the angular velocity and acceleration are not zero at the start and end, hence soft impacts",
            correct="a non-zero velocity at the start is a velocity jump: a hard impact (soft only for e = 0)",
            check=_check_impact, notebook=NOTEBOOK, kind="remark"),
    Erratum(source="004", where="Table 1, row z = 8",
            printed=r"$\varepsilon_{\max}/\omega_1^2 = 0.46$ at $\alpha^1 = 52.93°$, $\beta^1 = 24.85°$",
            correct=r"0.453 at $\alpha^1 = \alpha_0 = 45.58°$, $\beta^1 = \beta_0 = 22.5°$ (entry): the printed point "
                    r"lies outside the motion",
            check=_check_table_z8, notebook=NOTEBOOK),
    Erratum(source="004", where="Table 1, row z = 3",
            printed=r"$\varepsilon_{\max}/\omega_1^2 = 2.51$, $\alpha^1 = 16.40°$, $\beta^1 = 27.80°$",
            correct=r"2.536, $\alpha^1 = 16.87°$, $\beta^1 = 28.71°$",
            check=_check_table_z3, notebook=NOTEBOOK),
    Erratum(source="004", where=r"Table 1, columns $\alpha^1$, $\beta^1$ (z = 4, 5, 6) and $\alpha_0$ (z = 6)",
            printed=r"$\alpha^1$ = 27.26, 34.96, 41.60°; $\beta^1$ = 27.56, 26.22, 25.38°; $\alpha_0$(z=6) = 53.15°",
            correct=r"$\alpha^1$ = 27.07, 34.92, 41.59°; $\beta^1$ = 27.26, 26.26, 25.60°; $\alpha_0$ = 53.13°",
            check=_check_table_angles, notebook=NOTEBOOK),
    Erratum(source="004", where="last section, crank torque summed with friction losses",
            printed=r"$\sum P_i\,\rho_i\,\omega/\omega_{KP}$",
            correct=r"$\sum P_i\,r_i\,\omega/\omega_{KP}$ ($P_i r_i$ is the wheel torque; by the power balance it "
                    r"times ω/ω_KP is the crank torque, $= P_i\rho_i\cos\alpha_i\cos\beta_i$)",
            check=_check_drive_arm, notebook=NOTEBOOK),
]
