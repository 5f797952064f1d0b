"""Crank torque and motor of a Geneva drive indexing an inertia.
"""

from __future__ import annotations

import numpy as np

from ..errors import DimensionError
from ..geometry import check_length
from ..mechanisms.geneva import TWO_PI
from .drive import Drive
from .drive import drive as _drive


# ----------------------------------------------------------------------------------
# drive: crank torque from the power balance (Vainer & Shatokhina, last section)
# ----------------------------------------------------------------------------------
def crank_torque(mechanism, phi, *, inertia: float, omega1: float, resisting_torque: float = 0.0) -> np.ndarray:
    """Crank torque M1(φ) of a Geneva drive at constant crank speed ω1, from the power balance.

    Wheel side (Vainer & Shatokhina, last section): the moment of inertia J (``inertia``, reduced to
    the wheel, the seed's I_П) and a resisting torque M_r against the wheel's motion while
    it moves (the seed's M_П + M_C). With ω2 = ψ'ω1 and ε2 = ψ''ω1² from
    ``mechanism.motion``, M1·ω1 = (J ε2 + M_r sgn ω2)·ω2, so M1 = (J ψ'' ω1² + M_r sgn ψ')·ψ'
    (zero while the wheel is locked). The impulse of a velocity jump (the spherical
    Geneva's hard impact) is not included.
    """
    J = check_length("inertia", inertia, allow_zero=True)
    w1 = check_length("omega1", omega1)
    Mr = check_length("resisting_torque", resisting_torque, allow_zero=True)
    mo = mechanism.motion(phi)
    return (J * mo.ddpsi * w1**2 + Mr * np.sign(mo.dpsi)) * mo.dpsi


def drive_angles(mechanism, n: int = 7201) -> np.ndarray:
    """Crank angles over one turn [0, 2π]: n samples on the engaged interval π ± σ0, where
    the torque lives, its ends taken just inside (σ0·(1 - 1e-13)), and the dwell sampled
    at spacing ≈ 2π/(n - 1) from just outside. The torque's jumps at entry and exit then
    fall between two samples a few 1e-13 apart and the trapezoidal rule integrates each
    smooth piece on its own (error O(h²), h = 2σ0/(n - 1))."""
    n = int(n)
    if n < 16:
        raise DimensionError(f"n must be ≥ 16 samples of the engaged interval, got {n}")
    s0 = mechanism.engagement_half_angle
    k_off = max(int(np.ceil((np.pi - s0) / (TWO_PI / (n - 1)))), 1) + 1
    on = np.pi + s0 * (1.0 - 1e-13) * np.linspace(-1.0, 1.0, n)
    before = np.linspace(0.0, np.pi - s0 * (1.0 + 1e-13), k_off)
    after = np.linspace(np.pi + s0 * (1.0 + 1e-13), TWO_PI, k_off)
    return np.concatenate([before, on, after])


def geneva_drive(mechanism, *, inertia: float, omega1: float, resisting_torque: float = 0.0,
          efficiency: float = 1.0, overload: float = 2.0, n: int = 7201) -> Drive:
    """The motor of a Geneva drive: :func:`crank_torque` sampled by :func:`drive_angles`
    (n samples while the wheel moves, the engagement ends resolved), then the course's one rule,
    :func:`mechlab.kinetostatics.drive` (motor torque M1/η where it drives and M1·η where the
    wheel drives the crank back; mean power; nominal torque max(rms, peak/k))."""
    phi = drive_angles(mechanism, n)
    M1 = crank_torque(mechanism, phi, inertia=inertia, omega1=omega1, resisting_torque=resisting_torque)
    return _drive(M1, phi, omega1, overload=overload, efficiency=efficiency)


# the old name, for the geneva and geneva_spherical assignments (kinetostatics.drive.drive is the motor rule)
drive = geneva_drive
