"""The one motor-sizing rule: mean, rms and peak crank torque, overload and efficiency.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import Annotated

import numpy as np

from ..errors import DimensionError, DriveError, MechanismError
from ..validate import MAX_SAMPLES, Real, Spec, number, validated

__all__ = ["Drive", "DriveError", "cycle_mean", "drive", "motor_torque"]


# --------------------------------------------------------------------------- drive
Efficiency = Annotated[float, Spec("number", 0.0, 1.0, open_lo=True, error=DriveError, why="the efficiency 0 < η ≤ 1")]
Sampled = Annotated[np.ndarray, Spec("samples", lo=2, hi=MAX_SAMPLES)]


@dataclass(frozen=True, eq=False)
class Drive:
    """A crank's torque over one cycle at constant ω1 and the motor it needs without a flywheel (from :func:`drive`).

    Every statistic is of the motor torque M_m referred to the crank.

    Parameters
    ----------
    phi : numpy.ndarray
        Crank angles (radians), as given.
    torque : numpy.ndarray
        The crank torque M(φ) (N·m), as given.
    motor_torque : numpy.ndarray
        M_m(φ): M/η where the motor drives, M·η where the mechanism drives it back (N·m).
    mean_torque : float
        ⟨M_m⟩ (N·m).
    peak_torque : float
        max|M_m| (N·m).
    rms_torque : float
        √⟨M_m²⟩, the thermal equivalent torque (N·m).
    mean_power : float
        ⟨M_m⟩·ω1 (W; Vainer & Shatokhina's N_cp).
    peak_power : float
        peak·|ω1| (W).
    nominal_torque : float
        max(rms, peak/overload) (N·m).
    nominal_power : float
        nominal_torque·|ω1| (W).
    overload : float
        The motor's admissible ratio k of peak to nominal torque.
    efficiency : float
        η of the transmission between motor and crank.
    governing : {"rms", "peak"}
        The term that decided the nominal torque.

    Examples
    --------
    >>> from mechlab.kinetostatics import drive, press
    >>> k = press()
    >>> phi = k.turn(73)
    >>> d = drive(k.forces(phi).torque, phi, k.omega1)
    >>> d.governing, round(d.nominal_power, 2)
    ('peak', 1210.03)
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
        """The smallest motor power in ``catalogue`` that reaches ``nominal_power``.

        Parameters
        ----------
        catalogue : sequence of float
            Available motor powers (W, the unit of the powers here).

        Returns
        -------
        float
            The chosen power.

        Raises
        ------
        MechanismError
            If no motor in the catalogue reaches the nominal power.

        Examples
        --------
        >>> from mechlab.kinetostatics import drive, press
        >>> k = press()
        >>> phi = k.turn(73)
        >>> drive(k.forces(phi).torque, phi, k.omega1).choose([250, 550, 750, 1100, 1500])
        1500
        """
        ok = sorted(p for p in catalogue if p >= self.nominal_power)
        if not ok:
            raise MechanismError(f"no motor in the catalogue reaches the nominal power {self.nominal_power:.4g} "
                                 f"(largest: {max(catalogue):.4g})")
        return ok[0]


@validated
def cycle_mean(y: Sampled, phi: Sampled) -> float:
    """Mean of y(φ) over the sampled interval (trapezoidal rule, any spacing).

    Parameters
    ----------
    y : array_like
        Samples of y.
    phi : array_like
        The angles (radians) at which y is sampled, as many as ``y``.

    Returns
    -------
    float
        ∫y dφ / (φ_end − φ_start).

    Raises
    ------
    DimensionError
        If ``y`` and ``phi`` differ in length, or ``phi`` spans no interval.

    Examples
    --------
    >>> import numpy as np
    >>> from mechlab.kinetostatics import cycle_mean
    >>> phi = np.linspace(0, 2 * np.pi, 73)
    >>> round(cycle_mean(np.sin(phi) ** 2, phi), 12)
    0.5
    """
    if len(y) != len(phi) or phi[-1] == phi[0]:
        raise DimensionError(f"y and phi must be samples of one interval, as many y as phi, got {len(y)} y over "
                             f"{len(phi)} phi from {phi[0]:g} to {phi[-1]:g}")
    return float(np.trapezoid(y, phi) / (phi[-1] - phi[0]))


@validated
def motor_torque(torque: Annotated[np.ndarray, Spec("samples", lo=1, hi=MAX_SAMPLES)], omega1: Real,
                 efficiency: Efficiency = 1.0) -> np.ndarray:
    """The motor's torque referred to the crank.

    M/η where the motor drives (M·ω1 > 0), M·η where the mechanism drives the motor back (M·ω1 < 0)
    through the same transmission.

    Parameters
    ----------
    torque : array_like
        The crank torque M (N·m), one or more samples.
    omega1 : float
        Crank speed ω1 (rad/s; only its sign matters).
    efficiency : float, optional
        η of the transmission (0 < η ≤ 1).

    Returns
    -------
    numpy.ndarray
        M_m (N·m), one per sample.

    Raises
    ------
    DimensionError
        For torques that are not finite, or η outside (0, 1].

    Examples
    --------
    >>> import numpy as np
    >>> from mechlab.kinetostatics import motor_torque
    >>> motor_torque(np.array([10.0, -10.0]), 1.0, 0.8)
    array([12.5, -8. ])
    """
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

    Parameters
    ----------
    torque : array_like
        The crank torque M(φ) (N·m) at the crank angles ``phi`` over one cycle (e.g.
        ``ForceResult.torque``; :func:`mechlab.kinetostatics.geneva.geneva_drive` builds the Geneva's).
    phi : array_like
        The crank angles (radians), increasing, as many as ``torque``.
    omega1 : float
        The constant crank speed ω1 (rad/s, either sign, not 0).
    overload : float, optional
        The motor's admissible ratio k of peak to nominal torque (k ≥ 1).
    efficiency : float, optional
        η of the transmission between motor and crank (0 < η ≤ 1).

    Returns
    -------
    Drive
        The motor torque, its mean, rms and peak, the nominal torque and power and what governs them.

    Raises
    ------
    DriveError
        For torque and angles of different shapes, angles that do not increase, ω1 = 0, k < 1 or η
        outside (0, 1].

    Notes
    -----
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

    Examples
    --------
    >>> from mechlab.kinetostatics import drive, press
    >>> k = press()
    >>> phi = k.turn(73)
    >>> d = drive(k.forces(phi).torque, phi, k.omega1)
    >>> round(d.rms_torque, 3), round(d.peak_torque, 3), d.governing
    (53.391, 192.582, 'peak')
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

