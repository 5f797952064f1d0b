"""Mistakes in the force sections of the SibSIU proceedings (kinetostatics by groups) and of
Vainer & Shatokhina (drive torque).

Each check recomputes the evidence with :mod:`mechlab.kinetostatics` on a slider-crank (the
SibSIU mechanism without its additional link: crank 1 = O-A here, rod 2 = A-B,
slider 4 at B; the source's pins B and C are A and B here).
"""

from __future__ import annotations

import numpy as np

from ...geometry import cross
from ...kinetostatics.model import Force, model_for
from ...kinetostatics.solve import solve
from ...mechanisms.slider_crank import SliderCrank
from . import Claim, Erratum

NOTEBOOK = "11_forces.ipynb"

# A press-sized slider-crank in metres and kilograms (notebook 11 uses the same numbers).
_SC = SliderCrank(0.10, 0.40, 0.0)
_PHI = np.radians(60.0)


def _rod_group(eps1: float = 0.0):
    model = (model_for(_SC).with_body("crank", mass=2.0, inertia=0.002, com=(0.05, 0.0))
             .with_body("rod", mass=3.0, com=(0.16, 0.0)).with_body("slider", mass=4.0))
    mo = _SC.motion(np.array([_PHI]))
    return model, mo, solve(model, mo, [Force("slider", "B", (-500.0, 0.0))], omega1=30.0, eps1=eps1)


def _check_rod_tangential() -> str:
    """Formula (1): the rod's moment equation about C uses the arm h_И2 of the rod's own
    inertia force; the printed solution divides F_И2·h_И4 (the slider's arm) instead."""
    model, mo, res = _rod_group()
    A, B = mo.points["A"].p, mo.points["B"].p
    l2 = _SC.rod
    t = np.stack([-(A - B)[:, 1], (A - B)[:, 0]], axis=1) / l2   # unit normal to the rod, C→B turned by +90°
    R_t = float(np.sum(res.reactions["A"].force * t))            # tangential reaction of the crank on the rod
    rod = model.body("rod")
    u = (B - A) / l2
    S = A + rod.com[0] * u                                        # rod's centre of mass
    aS = (mo.points["A"].dd + rod.com[0] / l2 * (mo.points["B"].dd - mo.points["A"].dd)) * 30.0**2
    G2 = rod.mass * np.array([[0.0, -9.81]])
    F_in2 = -rod.mass * aS
    # rod's angular acceleration from the same analogs: θ'' of the vector B - A
    v = mo.points["B"].p - mo.points["A"].p
    vd = mo.points["B"].d - mo.points["A"].d
    vdd = mo.points["B"].dd - mo.points["A"].dd
    r2 = float(np.sum(v * v))
    ddth = float(cross(v, vdd)[0]) / r2 - 2 * float(cross(v, vd)[0]) * float(np.sum(v * vd)) / r2**2
    M_in2 = -rod.inertia * ddth * 30.0**2
    m_G = float(cross(S - B, G2)[0])
    m_F2 = float(cross(S - B, F_in2)[0])                          # F_И2·h_И2 with its sign
    # the slider's inertia force acts along the guide through C: no moment about B
    m_F4 = 0.0
    correct = -(m_G + m_F2 + M_in2) / l2
    printed = -(m_G + m_F4 + M_in2) / l2
    return Claim(R_t, printed, correct, 1e-9 * abs(R_t),
                 text=(f"slider-crank 0.10/0.40 m, rod 3 kg, ω1 = 30 rad/s, φ = 60°: group solution R_B^t = {R_t:.3f} "
                       f"N; (1) with h_И2: {correct:.3f} N; with h_И4 (= 0, slider force through C): {printed:.3f} N"))


def _check_crank_moment() -> str:
    """The crank's moment equation about B leaves out the crank's inertia force F_И1 (and couple
    M_И1) that its force equation includes: exact under the source's uniform rotation (ε1 = 0,
    centre of mass on OB), a remark; shown wrong only for an accelerating crank."""
    out = []
    for eps1 in (0.0, 400.0):
        model, mo, res = _rod_group(eps1)
        crank = model.body("crank")
        O, A = mo.points["O"].p, mo.points["A"].p
        u = (A - O) / _SC.crank
        S = O + crank.com[0] * u
        G1 = crank.mass * np.array([[0.0, -9.81]])
        R_A = res.reactions["O"].force                            # frame on crank (the source's R_A)
        printed = -float(cross(O - A, R_A)[0] + cross(S - A, G1)[0])
        # the crank's inertia force and couple at ω1 = 30 rad/s, ε1: a_S = S''·ω1² + S'·ε1
        k = crank.com[0] / _SC.crank
        F_in1 = -crank.mass * k * (mo.points["A"].dd * 30.0**2 + mo.points["A"].d * eps1)
        correct = printed - float(cross(S - A, F_in1)[0]) + crank.inertia * eps1
        out.append((eps1, float(res.torque[0]), printed, correct))
    (_e0, t0, p0, _c0), (e1, t1, p1, c1) = out
    assert abs(p0 - t0) <= 1e-9 * abs(t0)  # harmless at ε1 = 0 with S on OA
    return Claim(t1, p1, c1, 1e-9 * abs(t1),
                 f"ε1 = 0: printed M_ур = {p0:.3f} N·m = power balance {t0:.3f} N·m; start-up ε1 = {e1:g} rad/s²: "
                 f"printed {p1:.3f} N·m, with F_И1, M_И1 {c1:.3f} N·m, power balance {t1:.3f} N·m")


def _check_mean_torque() -> str:
    """Seed 004: M_cp = Σ(R_i ρ_i / n) is the mean of n sampled torques; the version "with
    losses" is printed as n·η⁻¹·Σ(...) — n must divide, not multiply."""
    model = (model_for(_SC).with_body("crank", mass=2.0, inertia=0.002, com=(0.05, 0.0))
             .with_body("rod", mass=3.0, com=(0.16, 0.0)).with_body("slider", mass=4.0))
    def load(m):
        return np.stack([np.where(m.ds < 0, 2000.0, 0.0), 0.0 * m.s], axis=1)  # pressing on the return stroke
    fine = _SC.turn(7201)
    M_fine = solve(model, _SC.motion(fine), [Force("slider", "B", load)], omega1=30.0).torque
    exact = float(np.trapezoid(M_fine, fine) / (2 * np.pi))
    n, eta = 12, 0.9
    phi = np.arange(n) * 2 * np.pi / n + np.pi / n
    M = solve(model, _SC.motion(phi), [Force("slider", "B", load)], omega1=30.0).torque
    correct = float(np.sum(M) / (n * eta))
    printed = float(n / eta * np.sum(M))
    assert abs(printed / correct - n * n) < 1e-9 * n * n
    return Claim(exact / eta, printed, correct, 0.05 * abs(exact / eta),
                 text=(f"press torque at n = {n} positions, η = {eta}: Σ M_i/(nη) = {correct:.3f} N·m (cycle mean/η "
            f"{exact / eta:.3f}); printed n·η⁻¹·Σ M_i = {printed:.1f} N·m, n² = {n * n} times too large; tolerance "
            f"5 % for sampling {n} positions"))


ERRATA = [
    Erratum(source="003", where="slider-crank with an additional link, formula (1)",
            printed=r"$R_B^t = (G_2 h_2 \mu_l - F_{\text{И}2} h_{\text{И}4} \mu_l - M_{\text{И}2})/l_2$",
            correct=r"$R_B^t = (G_2 h_2 \mu_l - F_{\text{И}2} h_{\text{И}2} \mu_l - M_{\text{И}2})/l_2$ (the arm of "
                    r"the rod's own inertia force, as in the moment equation above it)",
            check=_check_rod_tangential, notebook=NOTEBOOK),
    Erratum(source="003", where="slider-crank with an additional link, the drawing of the leading link, moment "
                                "equation about B",
            printed=r"$M_{\text{ур}} = G_1 h_G \mu_l - R_A h_A \mu_l$",
            correct=r"exact under the source's uniform rotation (ε1 = 0, centre of mass on OB); in general "
                    r"$M_{\text{ур}} = G_1 h_G \mu_l - R_A h_A \mu_l \pm F_{\text{И}1} h_{\text{И}1} \mu_l \pm "
                    r"M_{\text{И}1}$: with a crank acceleration (a start-up) the crank's inertia force, which the "
                    r"force equation includes, also has a moment about B",
            check=_check_crank_moment, notebook=NOTEBOOK, kind="remark"),
    Erratum(source="004", where="last section, mean crank torque with friction losses",
            printed=r"$M_{cp} \approx n\,\eta^{-1} \sum P_i \rho_i \omega/\omega_{KP}$",
            correct=r"$M_{cp} \approx (n\,\eta)^{-1} \sum P_i \rho_i \omega/\omega_{KP}$ (the mean of the n sampled "
                    r"torques, as in $M_{cp} = \sum R_i\rho_i/n$ above it)",
            check=_check_mean_torque, notebook=NOTEBOOK),
]
