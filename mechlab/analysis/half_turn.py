"""Half-turn relations (Zinchenko et al. (2013), Tables 1-2, formulas (1)-(17)) and the limit theorem.

They hold where the pin runs back and forth along one piece of the slot, so that its place on the
slot depends only on its distance S(φ) from the pivot or its height l_OA·sin φ: every linkage with
one second-order group (:mod:`mechlab.analysis.equivalence`) and every curved-slot link. With
ψ = ψ_K - β (formula (12)) and φ* = 2π - φ (Table 2; φ* = π - φ and s = x_K - x_α, Table 1):
ψ(φ*) = ψ(φ) - 2ψ_K(φ), ψ'(φ*) = 2ψ_K'(φ) - ψ'(φ), ψ''(φ*) = ψ''(φ) - 2ψ_K''(φ)
(:func:`other_half`), so a law can be chosen on [0, π] only.

Limit theorem (§2, conclusions before §3), :func:`limit_theorem`: ψ'(φ) + ψ'(φ*) = 2ψ_K'(φ) gives
max|ψ'| ≥ max|ψ_K'| = λ/|1 - λ| (at φ = π, (19)), and likewise max|ψ''| ≥ max|ψ_K''| (the peak of
(20), :func:`base_peaks`); equality only for the base mechanism itself. The book's chapter on the base
mechanism derives both.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Annotated

import numpy as np

from ..errors import DimensionError
from ..geometry import AnglePath, as_angles, wrap
from ..mechanisms.base import AnyMechanism
from ..mechanisms.slotted import SineMechanism
from ..motion import scalar_law
from ..validate import Angles, count, number, validated
from .equivalence import base_law, base_mechanism

# λ = l_OA / l_OB of the base mechanism
Ratio = Annotated[float, number(1e-6, 1e6, why="λ = l_OA / l_OB, positive")]


def _not_one(lam: float) -> None:
    if lam == 1:
        raise DimensionError("lam must be ≠ 1 (λ must be positive and ≠ 1), got 1: "
                             "ψ_K' = λ/|1 - λ| is unbounded at φ = 180°")


@scalar_law
@validated
def formula_18(lam: Ratio, phi) -> AnglePath:
    """The base mechanism's law from Zinchenko et al. (2013) (18)-(20) (the printed formulas, verified correct):
    tan ψ_K = λ sin φ/(λ cos φ + 1), ψ_K' = λ(λ + cos φ)/D, ψ_K'' = λ(λ² - 1) sin φ/D², D = λ² + 1 + 2λ cos φ.
    ψ_K is the continuous branch (atan2; lifted by φ when λ > 1).

    Parameters
    ----------
    lam : float
        λ = l_OA / l_OB of the base mechanism, positive and ≠ 1.
    phi : float or array_like
        Crank angles (rad).

    Returns
    -------
    AnglePath
        ψ_K (rad), ψ_K′ and ψ_K″ at ``phi`` (scalars for a scalar ``phi``).

    Raises
    ------
    DimensionError
        ``lam`` is not in [1e-6, 1e6] or equals 1, or ``phi`` is not finite.

    Examples
    --------
    >>> import numpy as np
    >>> from mechlab.analysis.half_turn import formula_18
    >>> law = formula_18(0.5, np.pi / 2)
    >>> round(float(law.theta), 4), round(float(law.d), 4), round(float(law.dd), 4)
    (0.4636, 0.2, -0.24)
    """
    phi = as_angles(phi)
    _not_one(lam)
    s, c = np.sin(phi), np.cos(phi)
    D = lam * lam + 1 + 2 * lam * c
    psi = np.arctan2(lam * s, lam * c + 1)
    if lam > 1:
        psi = phi + wrap(psi - phi)
    return AnglePath(psi, lam * (lam + c) / D, lam * (lam * lam - 1) * s / D**2)


@validated
def base_peaks(lam: Ratio) -> tuple[float, float]:
    """Peaks of |ψ_K'| and |ψ_K''| of the base mechanism over a turn, in closed form.

    |ψ_K'| peaks at φ = π: λ/|1 - λ| (seed (25)). ψ_K'' ∝ sin φ/D² peaks where
    2λ cos²φ - (1 + λ²) cos φ - 4λ = 0, i.e. cos φ = [(1 + λ²) - √((1 + λ²)² + 32λ²)]/(4λ).

    Parameters
    ----------
    lam : float
        λ = l_OA / l_OB, positive and ≠ 1.

    Returns
    -------
    tuple of float
        (max |ψ_K′|, max |ψ_K″|) over a crank turn.

    Raises
    ------
    DimensionError
        ``lam`` is not in [1e-6, 1e6] or equals 1.

    Examples
    --------
    >>> from mechlab.analysis.half_turn import base_peaks
    >>> [round(v, 4) for v in base_peaks(0.5)]
    [1.0, 1.3496]
    """
    _not_one(lam)
    v = lam / abs(1 - lam)
    c = ((1 + lam * lam) - np.sqrt((1 + lam * lam) ** 2 + 32 * lam * lam)) / (4 * lam)
    s = np.sqrt(1 - c * c)
    D = lam * lam + 1 + 2 * lam * c
    return float(v), float(lam * abs(lam * lam - 1) * s / D**2)


def _is_translating(mechanism) -> bool:
    return isinstance(base_mechanism(mechanism), SineMechanism)


def mirror_angle(mechanism, phi) -> np.ndarray:
    """φ* of Tables 1-2: 2π - φ for a turning output, π - φ for a translating one."""
    phi = as_angles(phi)
    return (np.pi - phi) if _is_translating(mechanism) else (2 * np.pi - phi)


@dataclass(frozen=True)
class HalfTurn:
    """The law at φ* predicted from the law at φ (Tables 1-2) and the law actually found there."""

    phi: np.ndarray
    phi_star: np.ndarray
    predicted: AnglePath
    actual: AnglePath
    angular: bool

    def residual(self) -> float:
        d0 = self.predicted.theta - self.actual.theta
        if self.angular:
            d0 = wrap(d0)
        return float(max(np.max(np.abs(d0)), np.max(np.abs(self.predicted.d - self.actual.d)),
                         np.max(np.abs(self.predicted.dd - self.actual.dd))))


def _law(mo) -> AnglePath:
    out = mo.output
    return AnglePath(out.value, out.d, out.dd)


@scalar_law
@validated
def other_half(mechanism: AnyMechanism, phi: Angles) -> HalfTurn:
    """Predict the law at φ* = 2π - φ (or π - φ) from the law at φ and the base mechanism.

    Parameters
    ----------
    mechanism : Mechanism
        A linkage with one second-order group or a curved-slot link (its output turns about a
        pivot or slides).
    phi : float or array_like
        Crank angles (rad).

    Returns
    -------
    HalfTurn
        φ, φ*, the law predicted at φ* and the law found there; ``residual()`` is their largest
        difference.

    Raises
    ------
    TypeError
        ``mechanism`` is not a Mechanism.
    DimensionError
        ``phi`` is not finite, or the output does not turn about one fixed pivot.
    AssemblyError
        The linkage cannot be assembled at φ or φ*.

    Examples
    --------
    >>> import numpy as np
    >>> import mechlab as ml
    >>> from mechlab.analysis.half_turn import other_half
    >>> other_half(ml.FourBar(1, 3, 3, 4), np.linspace(0.1, 3.0, 5)).residual() < 1e-12
    True
    """
    phi = as_angles(phi)
    star = mirror_angle(mechanism, phi)
    law = _law(mechanism.motion(phi))
    k = base_law(mechanism, phi)
    predicted = AnglePath(law.theta - 2 * k.theta, 2 * k.d - law.d, law.dd - 2 * k.dd)
    actual = _law(mechanism.motion(star))
    return HalfTurn(phi, star, predicted, actual, not _is_translating(mechanism))


@dataclass(frozen=True)
class LimitCheck:
    """Peaks of the output's analogs and of its base mechanism's, over one symmetric grid."""

    peak_velocity: float
    base_peak_velocity: float
    peak_acceleration: float
    base_peak_acceleration: float
    pointwise_velocity_gap: float       # min over φ of max(|ψ'(φ)|, |ψ'(φ*)|) - |ψ_K'(φ)| (≥ 0)
    pointwise_acceleration_gap: float   # min over φ of max(|ψ''(φ)|, |ψ''(φ*)|) - |ψ_K''(φ)| (≥ 0)

    def holds(self, tol: float = 1e-12) -> bool:
        return (self.peak_velocity >= self.base_peak_velocity - tol
                and self.peak_acceleration >= self.base_peak_acceleration - tol
                and self.pointwise_velocity_gap >= -tol and self.pointwise_acceleration_gap >= -tol)


@validated
def limit_theorem(mechanism: AnyMechanism, n: Annotated[int, count(3)] = 721) -> LimitCheck:
    """Check Zinchenko et al.'s (2013) limit theorem on a grid of n crank angles symmetric under φ ↦ φ*.

    The crank must turn fully. The grid is φ_k = 2πk/(n-1) (for a translating link
    shifted to -π/2 + …, symmetric under φ ↦ π - φ), so φ* of every sample is a sample.

    Parameters
    ----------
    mechanism : Mechanism
        A linkage with one second-order group or a curved-slot link, with a crank that turns fully.
    n : int
        Odd number of crank angles, ≥ 3 (default 721).

    Returns
    -------
    LimitCheck
        Peaks of |ψ′| and |ψ″| against the base mechanism's, and the pointwise gaps;
        ``holds()`` says whether the theorem holds.

    Raises
    ------
    TypeError
        ``mechanism`` is not a Mechanism.
    DimensionError
        ``n`` is even or < 3, or the output does not turn about one fixed pivot.
    RotationError
        The crank does not turn fully.

    Examples
    --------
    >>> import mechlab as ml
    >>> from mechlab.analysis.half_turn import limit_theorem
    >>> check = limit_theorem(ml.FourBar(1, 3, 3, 4))
    >>> check.holds(), round(check.peak_velocity, 4), round(check.base_peak_velocity, 4)
    (True, 0.3772, 0.3333)
    """
    if n < 3 or n % 2 == 0:
        raise DimensionError(f"n must be odd and ≥ 3 (so that φ = π is a sample), got {n}")
    phi = mechanism.turn(n)
    if _is_translating(mechanism):
        phi = phi - np.pi / 2
    law = _law(mechanism.motion(phi))
    k = base_law(mechanism, phi)
    star = law.d[::-1], law.dd[::-1]   # on this grid φ* of φ_k is φ_{n-1-k} (mod 2π)
    gap_v = np.maximum(np.abs(law.d), np.abs(star[0])) - np.abs(k.d)
    gap_a = np.maximum(np.abs(law.dd), np.abs(star[1])) - np.abs(k.dd)
    return LimitCheck(float(np.max(np.abs(law.d))), float(np.max(np.abs(k.d))),
                      float(np.max(np.abs(law.dd))), float(np.max(np.abs(k.dd))),
                      float(np.min(gap_v)), float(np.min(gap_a)))
