"""The one motor-sizing rule: mean, rms and peak crank torque, overload and efficiency.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Annotated, Sequence

import numpy as np

from ..errors import DimensionError, DriveError, MechanismError
from ..validate import MAX_SAMPLES, Real, Spec, number, validated

__all__ = ["Drive", "DriveError", "drive", "motor_torque", "cycle_mean"]


# --------------------------------------------------------------------------- drive
Efficiency = Annotated[float, Spec("number", 0.0, 1.0, open_lo=True, error=DriveError, why="the efficiency 0 < η ≤ 1")]
Sampled = Annotated[np.ndarray, Spec("samples", lo=2, hi=MAX_SAMPLES)]


@dataclass(frozen=True, eq=False)
class Drive:
    """A crank's torque over one cycle at constant ω1 and the motor it needs without a flywheel.

    ``phi``, ``torque``: the crank angles and the crank torque M(φ) as given;
    ``motor_torque``: M_m(φ), the motor's torque referred to the crank (M/η where the
    motor drives, M·η where the mechanism drives it back, see :func:`drive`). Every
    statistic below is of M_m: ``mean_torque`` ⟨M_m⟩, ``rms_torque`` √⟨M_m²⟩ (thermal),
    ``peak_torque`` max|M_m|; ``mean_power`` = ⟨M_m⟩·ω1 (Vainer & Shatokhina's N_cp),
    ``peak_power`` = peak·|ω1|; ``nominal_torque`` = max(rms, peak/overload),
    ``nominal_power`` = nominal_torque·|ω1|; ``governing`` = "rms" or "peak", the
    term that decided.
    """

    phi: np.ndarray
    torque: np.ndarray
    motor_torque: np.ndarray
    mean_torque: float
    peak_torque: float
    rms_torque: float
    mean_power: float
    peak_power: float
    nominal_torque: float
    nominal_power: float
    overload: float
    efficiency: float
    governing: str

    def choose(self, catalogue: Sequence[float]) -> float:
        """The smallest motor power in ``catalogue`` (same unit as the powers here) ≥ nominal_power."""
        ok = sorted(p for p in catalogue if p >= self.nominal_power)
        if not ok:
            raise MechanismError(f"no motor in the catalogue reaches the nominal power {self.nominal_power:.4g} "
                                 f"(largest: {max(catalogue):.4g})")
        return ok[0]


@validated
def cycle_mean(y: Sampled, phi: Sampled) -> float:
    """Mean of y(φ) over the sampled interval (trapezoidal rule, any spacing)."""
    if len(y) != len(phi) or phi[-1] == phi[0]:
        raise DimensionError(f"y and phi must be samples of one interval, as many y as phi, got {len(y)} y over "
                             f"{len(phi)} phi from {phi[0]:g} to {phi[-1]:g}")
    return float(np.trapezoid(y, phi) / (phi[-1] - phi[0]))


@validated
def motor_torque(torque: Annotated[np.ndarray, Spec("samples", lo=1, hi=MAX_SAMPLES)], omega1: Real,
                 efficiency: Efficiency = 1.0) -> np.ndarray:
    """The motor's torque referred to the crank: M/η where the motor drives (M·ω1 > 0), M·η
    where the mechanism drives the motor back (M·ω1 < 0) through the same transmission."""
    M = np.asarray(torque, dtype=float)
    driving = M * np.sign(omega1) > 0
    return np.where(driving, M / efficiency, M * efficiency)


@validated
def drive(torque: Annotated[np.ndarray, Spec("samples", lo=2, error=DriveError)],
          phi: Annotated[np.ndarray, Spec("samples", lo=2, error=DriveError)],
          omega1: Annotated[float, number(error=DriveError)], *,
          overload: Annotated[float, number(1.0, error=DriveError, why="the overload factor k ≥ 1")] = 2.0,
          efficiency: Efficiency = 1.0) -> Drive:
    """The one rule of the course for sizing a motor that drives a crank without a flywheel.

    ``torque`` is the crank torque M(φ) at the crank angles ``phi`` over one cycle (e.g.
    ``ForceResult.torque``; :func:`mechlab.kinetostatics.geneva.geneva_drive` builds the Geneva's); ``omega1``
    the constant crank speed (either sign); ``efficiency`` η of the transmission between
    motor and crank (0 < η ≤ 1); ``overload`` the motor's admissible ratio k of peak to
    nominal torque (k ≥ 1). Returns a :class:`Drive`.

    Derivation. *Motor side.* Where the motor drives (M·ω1 > 0) it must supply M/η; where
    the mechanism drives the motor back (M·ω1 < 0: kinetic energy of the links returned,
    gravity) only M·η reaches it (a transmission that does not lock backwards, with the
    same η both ways). So M_m = M/η or M·η, and every figure below is of M_m. At constant
    ω1 time is proportional to φ, so a mean over the cycle is ⟨x⟩ = ∫x dφ / Φ.

    1. *Energy: the mean power* N̄ = ⟨M_m⟩·ω1 — Vainer & Shatokhina's N_cp = M_cp·ω_KP with M_cp the
       mean of the torques in n positions (its formula printed with n multiplying instead
       of dividing; see the errata). It is what the motor draws on average, and the size of
       the motor when a flywheel makes its torque nearly constant.
    2. *Heating: the equivalent (rms) torque* M_eq = √⟨M_m²⟩. A motor's losses are a
       constant part (iron, bearings, fan) plus the copper losses I²R; at constant flux
       (a DC shunt motor, an induction motor in its working range) the current is
       proportional to the torque, so the heat of one cycle — short against the motor's
       thermal time constant of minutes — grows as ⟨M_m²⟩, and the constant torque that
       heats the motor as much is M_eq: the *method of equivalent torque* of the
       electric-drive texts (M. G. Chilikin, A. S. Sandler, Общий курс электропривода,
       the chapter on choosing the motor's power; A. Hughes, B. Drury, Electric Motors
       and Drives, on rating for intermittent loads). The mean power is **not** a thermal
       measure: by Cauchy–Schwarz M_eq ≥ |⟨M_m⟩|, with equality only for a constant
       torque, so sizing by the mean power understates the heating whenever the torque
       fluctuates — a Geneva wheel with inertia alone and η = 1 has ⟨M⟩ = 0 and still
       heats the motor. The nominal torque must be ≥ M_eq.
    3. *Overload*: the motor must also deliver the peak |M_m| within its overload factor
       k = M_max/M_nom (Vainer & Shatokhina: "the overload factor must be taken into account"), so
       M_nom ≥ M_peak/k.

    Hence M_nom = max(M_eq, M_peak/k), N_nom = M_nom·|ω1| (the motor's torque and power
    referred to the crank shaft: a gear of ratio u multiplies the speed and divides the
    torque by u and leaves the power), and ``governing`` names the larger term.

    Integration: the trapezoidal rule over the samples (any spacing). Where the torque
    jumps (a hard impact, a load switching on), give both one-sided values at the same
    or nearly the same φ: each smooth piece is then integrated on its own to the
    accuracy of its sampling, as :func:`mechlab.kinetostatics.geneva.geneva_drive` does at the engagement
    ends. The peak is the largest sample.
    """
    M = torque
    if M.shape != phi.shape:
        raise DriveError(f"torque and phi must be 1-D arrays of the same length ≥ 2, got {M.shape}, {phi.shape}")
    if not np.all(np.diff(phi) >= 0) or phi[-1] <= phi[0]:
        raise DriveError(f"phi must increase over the cycle, got φ from {phi[0]:g} to {phi[-1]:g}")
    if omega1 == 0:
        raise DriveError(f"crank speed ω1 must be finite and non-zero: omega1 = {omega1}")
    Mm = motor_torque(M, omega1, efficiency)
    mean = cycle_mean(Mm, phi)
    peak = float(np.max(np.abs(Mm)))
    # scaled by the peak, so that M² neither underflows nor overflows
    rms = peak * float(np.sqrt(cycle_mean((Mm / peak) ** 2, phi))) if peak > 0 else 0.0
    w = abs(omega1)
    by_peak = peak / overload
    nominal = max(rms, by_peak)
    return Drive(phi, M, Mm, mean, peak, rms, mean * omega1, peak * w, nominal, nominal * w,
                 float(overload), float(efficiency), "peak" if by_peak > rms else "rms")

