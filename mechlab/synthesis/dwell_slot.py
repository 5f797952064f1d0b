"""Dwell synthesis with a curved slot (Zinchenko et al. (2013), §3, Figs. 9-10, formulas (21)-(25)).

Frame of §2 (as :class:`~mechlab.mechanisms.slotted.SlottedLink`): O at the origin, the link's pivot
B at (-d, 0), crank r = λd, φ = 0 where A is farthest from B. The base mechanism's law
ψ_K = atan2(λ sin φ, 1 + λ cos φ) and its analogs are formulas (18)-(20) (:func:`slotted_link_law`).
In the link's frame the pin sits at (S, β) with S(φ) = d·sqrt(1 + λ² + 2λ cos φ) and β = ψ_K - ψ
(formula (12); the printed S has a wrong sign, :mod:`mechlab.course.errata.seed000_dwell`).
S(-φ) = S(φ) gives the half-turn relation (Table 2): a law chosen on [0, π] fixes the slot and
the other half of the turn (:meth:`DwellLaw.__call__`).

:class:`DwellLaw` holds the designed law (a dwell ψ_B on [φ1, φ2], transitions of
:data:`TRANSITIONS`, formulas (21)-(25) with corrected signs) and the slot it fixes;
:func:`curved_slot_dwell` returns a :class:`DwellSlotMechanism` whose ``motion(phi)`` solves the
pin in the designed slot through :class:`~mechlab.mechanisms.curved_slot.CurvedSlotLink` (not by
evaluating the law). The book's chapter on the curved-slot dwell derives it.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from functools import cached_property
from math import comb
from typing import Annotated

import numpy as np
from numpy.polynomial import Polynomial

from ..errors import DwellError, DwellIntervalError, DwellRatioError, renamed
from ..geometry import as_angles, wrap
from ..mechanisms.base import Mechanism, Part, Sketch
from ..motion import Table, scalar_law
from ..validate import MAX_GRID, Checked, Distance, Length, Spec, angle, check_value, choice, count, number, validated

TRANSITIONS = ("cubic", "quintic", "sextic")


# |λ - 1| at least this: closer, ψ_K'(π) = λ/(λ - 1) outgrows what the slot solver can follow.
LAMBDA_TOL = 1e-4
# λ within these: outside, the slot's curvature over- or underflows.
LAMBDA_RANGE = (1e-6, 1e6)
# The shortest transition (radians) from φ = 0 to φ1 and from φ2 to π (best_placement keeps 1e-3).
MIN_TRANSITION = 5e-4


# λ = l_OA / l_OB
Ratio = Annotated[float, number(*LAMBDA_RANGE, error=DwellRatioError, why="λ = l_OA / l_OB, positive")]
# a crank angle of the dwell's design, radians
DwellAngle = Annotated[float, angle(0.0, np.pi, error=DwellIntervalError, why="the dwell lies within [0°, 180°]")]
Transition = Annotated[str, choice(*TRANSITIONS, error=DwellError)]
# the crank angles of the designed half turn, which DwellLaw.half() takes
_HALF_TURN = Spec("radians", 0.0, np.pi, error=DwellError, why="half() takes the designed half; use __call__ for any φ")


def check_lambda(lam) -> float:
    """λ as a float; DwellRatioError unless 1e-6 ≤ λ ≤ 1e6 and |λ - 1| > 1e-4."""
    lam = check_value("lam", lam, Ratio.__metadata__[0])
    if abs(lam - 1.0) <= LAMBDA_TOL:
        raise DwellRatioError(
            f"λ = l_OA / l_OB = {lam:g}, but λ ≠ 1 is needed (|λ - 1| > {LAMBDA_TOL:g}): the pin passes through "
            f"the pivot B at φ = 180°, where the slot direction is undefined and ψ_K'(π) = λ/(λ - 1) "
            + ("is infinite" if lam == 1 else f"= {lam / (lam - 1):.3g}"))
    return lam


@dataclass(frozen=True)
class BaseLaw:
    """ψ_K and its first three analogs (base mechanism, Zinchenko et al. (2013) (18)-(20))."""

    psi: np.ndarray
    d: np.ndarray
    dd: np.ndarray
    ddd: np.ndarray


@scalar_law
def slotted_link_law(lam: float, phi) -> BaseLaw:
    """The base mechanism's law ψ_K(φ) with ψ_K', ψ_K'', ψ_K''' (Zinchenko et al. (2013), (18)-(20)).

    ψ_K is continuous in φ: principal for λ < 1, ψ_K - φ ∈ (-π/2, π/2) for λ > 1 (the link turns).

    Parameters
    ----------
    lam : float
        λ = l_OA / l_OB, the crank over the pivot distance (dimensionless, λ ≠ 1).
    phi : float or array_like
        Crank angles (rad).

    Returns
    -------
    BaseLaw
        ψ_K (rad) and its analogs ψ_K′, ψ_K″, ψ_K‴ (``psi``, ``d``, ``dd``, ``ddd``).

    Raises
    ------
    DwellRatioError
        λ = 1 (within 1e-4) or outside [1e-6, 1e6].

    Examples
    --------
    >>> import numpy as np
    >>> from mechlab.synthesis.dwell_slot import slotted_link_law
    >>> k = slotted_link_law(0.5, np.pi / 2)
    >>> round(float(k.psi), 4), round(float(k.d), 4)    # atan(λ) and λ²/(1 + λ²)
    (0.4636, 0.2)
    """
    lam = check_lambda(lam)
    phi = as_angles(phi)
    s, c = np.sin(phi), np.cos(phi)
    D = 1.0 + lam * lam + 2.0 * lam * c
    psi = np.arctan2(lam * s, 1.0 + lam * c)
    if lam > 1.0:
        psi = phi + wrap(psi - phi)
    d1 = lam * (lam + c) / D
    d2 = lam * (lam * lam - 1.0) * s / D**2
    d3 = lam * (lam * lam - 1.0) * (c * D + 4.0 * lam * s * s) / D**3
    return BaseLaw(psi, d1, d2, d3)


def arc_pressure_angle(lam, phi) -> np.ndarray:
    """Pressure angle where the pin runs on a dwell arc (radius l_OA about O): the slot's normal
    is along OA, the link point moves perpendicular to BA, so θ = |π/2 - (φ - ψ_K(φ))|.

    Its smallest value over φ is 0 for λ < 1 (at cos φ = -λ, OA ⊥ BA) and π/2 - arcsin(1/λ) for
    λ > 1 (the angle OAB never exceeds arcsin(1/λ)): a dwell of the rotating link always works
    at a pressure angle of at least that much.
    """
    phi = as_angles(phi)
    return np.abs(np.pi / 2 - (phi - slotted_link_law(lam, phi).psi))


def _end_values(lam: float):
    """(ψ_K'(0), ψ_K'''(0), ψ_K'(π), ψ_K'''(π)) in closed form."""
    return (lam / (lam + 1.0), lam * (lam - 1.0) / (lam + 1.0) ** 3,
            lam / (lam - 1.0), -lam * (lam + 1.0) / (lam - 1.0) ** 3)


def _fit(powers, at: float, sign: float, conditions) -> np.ndarray:
    """Coefficients of Σ c_k x^k (k in ``powers``) with (sign)^m p^(m)(at) = value for (m, value)."""
    M = np.zeros((len(conditions), len(powers)))
    rhs = np.zeros(len(conditions))
    for i, (m, value) in enumerate(conditions):
        for j, k in enumerate(powers):
            if k >= m:
                M[i, j] = sign**m * np.prod(np.arange(k - m + 1, k + 1)) * at ** (k - m)
        rhs[i] = value
    coef = np.zeros(max(powers) + 1)
    coef[list(powers)] = np.linalg.solve(M, rhs)
    return coef


def _deriv(coef: np.ndarray, m: int = 1) -> np.ndarray:
    for _ in range(m):
        coef = coef[1:] * np.arange(1, len(coef)) if len(coef) > 1 else np.zeros(1)
    return coef


def _reflect(coef: np.ndarray, a: float) -> np.ndarray:
    """Coefficients in x of p(a - x)."""
    out = np.zeros(len(coef))
    for k, c in enumerate(coef):
        for j in range(k + 1):
            out[j] += c * comb(k, j) * a ** (k - j) * (-1.0) ** j
    return out


def _horner(coef, x):
    """Σ coef[k] x^k by Horner's rule (numpy's Polynomial call is slow for small arrays)."""
    out = np.full(np.shape(x), float(coef[-1]))
    for c in coef[-2::-1]:
        out = out * x + c
    return out


def _x_over_sin(x: np.ndarray):
    """x/sin x and its derivative, without cancellation near x = 0 (series for |x| < 0.1)."""
    x = np.asarray(x, dtype=float)
    small = np.abs(x) < 0.1
    xs = np.where(small, 0.5, x)
    s = xs / np.sin(xs)
    ds = (np.sin(xs) - xs * np.cos(xs)) / np.sin(xs) ** 2
    z = x * x
    s_ser = 1 + z * (1 / 6 + z * (7 / 360 + z * (31 / 15120 + z * (127 / 604800 + z * 73 / 3421440))))
    ds_ser = x * (1 / 3 + z * (28 / 360 + z * (186 / 15120 + z * (1016 / 604800 + z * 730 / 3421440))))
    return np.where(small, s_ser, s), np.where(small, ds_ser, ds)


def check_interval(phi1, phi2) -> tuple[float, float]:
    """(φ1, φ2) as floats; DwellIntervalError unless 0 < φ1 < φ2 < π with transitions ≥ MIN_TRANSITION."""
    phi1, phi2 = (check_value(k, v, DwellAngle.__metadata__[0]) for k, v in (("phi1", phi1), ("phi2", phi2)))
    deg = f"[φ1, φ2] = [{np.degrees(phi1):.2f}°, {np.degrees(phi2):.2f}°]"
    if phi1 >= phi2:
        raise DwellIntervalError(f"the dwell needs φ1 < φ2, got {deg}")
    if phi1 == 0.0 or phi2 == np.pi:
        raise DwellIntervalError(
            f"a dwell starting at φ = 0° or ending at 180° leaves no room for a transition that matches the "
            f"base mechanism's ψ' there, got {deg}: this is the two-branch slot (see two_branch_slot)")
    if min(phi1, np.pi - phi2) < MIN_TRANSITION:
        raise DwellIntervalError(
            f"each transition needs at least {MIN_TRANSITION:g} rad ({np.degrees(MIN_TRANSITION):.3f}°): φ1 = "
            f"{phi1:.3g} rad, π - φ2 = {np.pi - phi2:.3g} rad (ψ'' grows as 1/width), got {deg}")
    return phi1, phi2


@dataclass(frozen=True)
class DwellLaw(Checked):
    """The designed law ψ(φ) (Zinchenko et al. (2013) (21)-(25), corrected) and the slot it fixes.

    ψ = ψ_B on the dwell (the slot an arc of radius l_OA), ψ = ψ_B + p(φ1 - φ) on [0, φ1] and
    ψ_B + q(φ - φ2) on [φ2, π], starting with ψ' = ψ'' = 0 at the joins, reaching ψ_K' at 0 and π
    (odd derivatives must match the base mechanism's there), and ψ(0) = 0. ``"cubic"`` ((21),
    (23)): p = a1 u³, q = a2 v³, a1 = -λ/(3(λ + 1)φ1²), a2 = λ/(3(λ - 1)(π - φ2)²),
    ψ_B = λφ1/(3(λ + 1)); its jerk jumps and the slot's curvature grows like 1/φ at the ends.
    ``"quintic"``: p = c4 u⁴ + c5 u⁵ (q alike), also matching ψ_K‴ at 0 and π
    (λ(λ - 1)/(λ + 1)³ and -λ(λ + 1)/(λ - 1)³) with ψ‴ = 0 at the joins: bounded curvature.
    Calling the law at any crank angles gives ψ and its three analogs (a ``BaseLaw``).

    Parameters
    ----------
    lam : float
        λ = l_OA / l_OB, in [1e-6, 1e6] with |λ − 1| > 1e-4.
    phi1, phi2 : float
        The dwell (rad), 0 < φ1 < φ2 < π, each transition ≥ MIN_TRANSITION.
    transition : {"cubic", "quintic", "sextic"}
        The transitions' law (:data:`TRANSITIONS`).
    pivot_distance : float
        d = l_OB (length units, default 1).

    Attributes
    ----------
    psi_dwell : float
        ψ_B, the link's angle during the dwell (rad).

    Raises
    ------
    DwellRatioError
        λ out of range or too near 1.
    DwellIntervalError
        The dwell is empty, reversed, outside (0, π) or leaves a transition too short.
    DwellError
        An unknown transition.
    DimensionError
        ``pivot_distance`` is not a positive length.

    Examples
    --------
    >>> import numpy as np
    >>> import mechlab as ml
    >>> law = ml.DwellLaw(0.5, np.radians(60), np.radians(150), "quintic")
    >>> round(law.psi_dwell, 6), round(float(law(np.radians(90)).d), 6)  # still in the dwell
    (0.105429, 0.0)
    """

    lam: float
    phi1: float
    phi2: float
    transition: Transition = "cubic"
    pivot_distance: Length = 1.0
    left_coef: np.ndarray = field(init=False, repr=False, compare=False)
    right_coef: np.ndarray = field(init=False, repr=False, compare=False)
    psi_dwell: float = field(init=False, compare=False)

    def __post_init__(self):
        super().__post_init__()
        lam = check_lambda(self.lam)
        phi1, phi2 = check_interval(self.phi1, self.phi2)
        for k, v in (("lam", lam), ("phi1", phi1), ("phi2", phi2)):
            object.__setattr__(self, k, v)
        k0, j0, k1, j1 = _end_values(lam)
        W = np.pi - phi2
        if self.transition == "cubic":
            # (21)/(24): ψ'(0) = -3 a1 φ1² = λ/(λ+1);  (23)/(25): ψ'(π) = 3 a2 (π-φ2)² = λ/(λ-1)
            left = _fit((3,), phi1, -1.0, [(1, k0)])
            right = _fit((3,), W, 1.0, [(1, k1)])
        elif self.transition == "quintic":
            left = _fit((4, 5), phi1, -1.0, [(1, k0), (3, j0)])
            right = _fit((4, 5), W, 1.0, [(1, k1), (3, j1)])
        else:  # ψ'' = ψ_K'' = 0 at the ends as well
            left = _fit((4, 5, 6), phi1, -1.0, [(1, k0), (2, 0.0), (3, j0)])
            right = _fit((4, 5, 6), W, 1.0, [(1, k1), (2, 0.0), (3, j1)])
        object.__setattr__(self, "left_coef", left)
        object.__setattr__(self, "right_coef", right)
        # coefficient arrays used in the hot paths: derivatives of p and q, and the polynomials
        # (ψ'(φ) - k0)/φ (left, in φ) and (ψ'(π - w) - k1)/w (right, in w) with their derivatives
        q = -_reflect(_deriv(left), phi1)          # ψ'(φ) on the left, in powers of φ
        rq = _reflect(_deriv(right), W)            # ψ'(π - w) on the right, in powers of w
        P = q[1:] if len(q) > 1 else np.zeros(1)
        Pr = rq[1:] if len(rq) > 1 else np.zeros(1)
        object.__setattr__(self, "_coefs", dict(
            left=[_deriv(left, m) for m in range(4)], right=[_deriv(right, m) for m in range(4)],
            P=(P, _deriv(P)), Pr=(Pr, _deriv(Pr))))
        object.__setattr__(self, "psi_dwell", float(-_horner(left, phi1)))  # ψ(0) = 0

    @property
    def left(self) -> Polynomial:
        """p(u) on [0, φ1], u = φ1 - φ: ψ = ψ_B + p(φ1 - φ).

        Returns
        -------
        numpy.polynomial.Polynomial
            The left transition's polynomial in u.

        Examples
        --------
        >>> import numpy as np
        >>> import mechlab as ml
        >>> law = ml.DwellLaw(0.5, np.radians(60), np.radians(150), "quintic")
        >>> law.left.degree()
        5
        """
        return Polynomial(self.left_coef)

    @property
    def right(self) -> Polynomial:
        """q(v) on [φ2, π], v = φ - φ2: ψ = ψ_B + q(φ - φ2).

        Returns
        -------
        numpy.polynomial.Polynomial
            The right transition's polynomial in v.

        Examples
        --------
        >>> import numpy as np
        >>> import mechlab as ml
        >>> law = ml.DwellLaw(0.5, np.radians(60), np.radians(150), "quintic")
        >>> round(float(law.right(np.pi - law.phi2)) + law.psi_dwell, 6)  # ψ(π)
        -0.058828
        """
        return Polynomial(self.right_coef)

    # -- dimensions ----------------------------------------------------------------------
    @property
    def crank(self) -> float:
        """The crank's length l_OA = λ·l_OB.

        Returns
        -------
        float
            l_OA (length units).

        Examples
        --------
        >>> import numpy as np
        >>> import mechlab as ml
        >>> law = ml.DwellLaw(0.5, np.radians(60), np.radians(150), "quintic")
        >>> law.crank
        0.5
        """
        return self.lam * self.pivot_distance

    @property
    def dwell_angle(self) -> float:
        """The dwell's crank angle φ_B = φ2 - φ1.

        Returns
        -------
        float
            φ_B (rad).

        Examples
        --------
        >>> import numpy as np
        >>> import mechlab as ml
        >>> law = ml.DwellLaw(0.5, np.radians(60), np.radians(150), "quintic")
        >>> round(float(np.degrees(law.dwell_angle)), 6)
        90.0
        """
        return self.phi2 - self.phi1

    @property
    def rotates(self) -> bool:
        """Whether the slotted link turns fully, one dwell per turn (intermittent rotation): λ > 1.

        Returns
        -------
        bool
            True for λ > 1, False for a rocking link (λ < 1).

        Examples
        --------
        >>> import numpy as np
        >>> import mechlab as ml
        >>> law = ml.DwellLaw(0.5, np.radians(60), np.radians(150), "quintic")
        >>> law.rotates
        False
        """
        return self.lam > 1.0

    # -- the law on the half turn [0, π] -------------------------------------------------
    def _pieces(self, phi):
        return phi < self.phi1, phi > self.phi2

    @scalar_law
    def half(self, phi) -> BaseLaw:
        """ψ, ψ′, ψ″, ψ‴ for φ in [0, π] (the designed half).

        Parameters
        ----------
        phi : float or array_like
            Crank angles (rad) in [0, π], the designed half.

        Returns
        -------
        BaseLaw
            ψ (rad) and its first three analogs.

        Raises
        ------
        DwellError
            An angle outside [0, π] (use the law itself for any φ).

        Examples
        --------
        >>> import numpy as np
        >>> import mechlab as ml
        >>> law = ml.DwellLaw(0.5, np.radians(60), np.radians(150), "quintic")
        >>> np.round(law.half(np.array([0.0, np.pi])).d, 6).tolist()  # ψ_K' at the slot's ends
        [0.333333, -1.0]
        """
        phi = check_value("phi", as_angles(phi), _HALF_TURN)
        L, R = self._pieces(phi)
        out = [np.zeros_like(phi) for _ in range(4)]
        out[0][:] = self.psi_dwell
        u, v = self.phi1 - phi[L], phi[R] - self.phi2
        cl, cr = self._coefs["left"], self._coefs["right"]
        for m in range(4):
            out[m][L] += (-1.0) ** m * _horner(cl[m], u)
            out[m][R] += _horner(cr[m], v)
        return BaseLaw(*out)

    @scalar_law
    def __call__(self, phi) -> BaseLaw:
        """ψ(φ) and its analogs over any crank angles: the designed half on [0, π], the
        half-turn relation (Table 2) on (-π, 0), and ψ(φ + 2π) = ψ(φ) + 2π·[λ > 1]."""
        phi = as_angles(phi)
        red = wrap(phi)
        turns = np.round((phi - red) / (2 * np.pi))
        neg = red < 0
        a = np.abs(red)
        h = self.half(a)
        K = slotted_link_law(self.lam, a)
        sign = np.where(neg, -1.0, 1.0)
        psi = h.psi - 2.0 * neg * K.psi
        d1 = np.where(neg, 2.0 * K.d - h.d, h.d)
        d2 = h.dd - 2.0 * neg * K.dd
        d3 = sign * (h.ddd - 2.0 * neg * K.ddd)
        if self.rotates:
            psi = psi + 2 * np.pi * turns
        return BaseLaw(psi, d1, d2, d3)

    @scalar_law
    def in_dwell(self, phi) -> np.ndarray:
        """True where wrap(φ) lies in [φ1, φ2].

        Parameters
        ----------
        phi : float or array_like
            Crank angles (rad).

        Returns
        -------
        numpy.ndarray of bool
            Whether the link dwells there.

        Examples
        --------
        >>> import numpy as np
        >>> import mechlab as ml
        >>> law = ml.DwellLaw(0.5, np.radians(60), np.radians(150), "quintic")
        >>> law.in_dwell(np.radians([30.0, 90.0])).tolist()
        [False, True]
        """
        red = wrap(as_angles(phi))
        return (red >= self.phi1) & (red <= self.phi2)

    # -- the slot --------------------------------------------------------------------------
    @scalar_law
    def S(self, phi) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """|A - B| and its two analogs (Zinchenko et al. (2013) §3, S(φ) corrected to the §2 frame).

        Parameters
        ----------
        phi : float or array_like
            Crank angles (rad).

        Returns
        -------
        S, dS, ddS : numpy.ndarray
            The pin's distance from B (length units) and its first and second φ-analogs.

        Examples
        --------
        >>> import numpy as np
        >>> import mechlab as ml
        >>> law = ml.DwellLaw(0.5, np.radians(60), np.radians(150), "quintic")
        >>> round(float(law.S(0.0)[0]), 6)  # d + r at φ = 0
        1.5
        """
        phi = as_angles(phi)
        d, r = self.pivot_distance, self.crank
        S = np.sqrt(d * d + r * r + 2 * r * d * np.cos(phi))
        dS = -r * d * np.sin(phi) / S
        ddS = (-r * d * np.cos(phi) - dS**2) / S
        return S, dS, ddS

    @scalar_law
    def beta(self, phi) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """β = ψ_K - ψ (polar angle of the pin in the link's frame) and β', β'' for φ in [0, π].

        Parameters
        ----------
        phi : float or array_like
            Crank angles (rad) in [0, π], the designed half.

        Returns
        -------
        beta, dbeta, ddbeta : numpy.ndarray
            β (rad) and its first and second φ-analogs.

        Raises
        ------
        DwellError
            An angle outside [0, π].

        Examples
        --------
        >>> import numpy as np
        >>> import mechlab as ml
        >>> law = ml.DwellLaw(0.5, np.radians(60), np.radians(150), "quintic")
        >>> round(float(law.beta(np.radians(30))[0]), 6)
        0.07615
        """
        h, K = self.half(phi), slotted_link_law(self.lam, phi)
        return K.psi - h.psi, K.d - h.d, K.dd - h.dd

    @scalar_law
    def slot_points(self, phi) -> np.ndarray:
        """Points of the slot's centre line in the link's frame (origin B), φ in [0, π].

        Parameters
        ----------
        phi : float or array_like
            Crank angles (rad) in [0, π], the designed half.

        Returns
        -------
        numpy.ndarray
            (n, 2) points (length units), where the pin is at those crank angles.

        Raises
        ------
        DwellError
            An angle outside [0, π].

        Examples
        --------
        >>> import numpy as np
        >>> import mechlab as ml
        >>> law = ml.DwellLaw(0.5, np.radians(60), np.radians(150), "quintic")
        >>> np.round(law.slot_points(np.array([0.0, np.pi / 2])), 4).tolist()
        [[1.5, 0.0], [1.0471, 0.392]]
        """
        S, _, _ = self.S(phi)
        b, _, _ = self.beta(phi)
        return S[:, None] * np.stack([np.cos(b), np.sin(b)], axis=-1)

    def centre_in_link(self) -> np.ndarray:
        """Where the crank pivot O sits in the link's frame during the dwell: the dwell arc's centre.

        Returns
        -------
        numpy.ndarray
            (x, y) in the link's frame (origin B, length units).

        Examples
        --------
        >>> import numpy as np
        >>> import mechlab as ml
        >>> law = ml.DwellLaw(0.5, np.radians(60), np.radians(150), "quintic")
        >>> np.round(law.centre_in_link(), 4).tolist()
        [0.9944, -0.1052]
        """
        c, s = np.cos(self.psi_dwell), np.sin(self.psi_dwell)
        return np.array([c * self.pivot_distance, -s * self.pivot_distance])

    def _g(self, phi: np.ndarray, with_derivative: bool = False):
        """g = β'(φ)/sin φ on [0, π], exact also at φ = 0 and π (where β' = 0), and, if asked,
        G = g'(φ)/sin φ (finite at the ends only when β‴ vanishes there; taken 1e-6 inside them).

        Each piece is written so that nothing cancels at the ends: on the left transition
        (ψ_K' - k0)/sin φ = λ(λ-1) tan(φ/2)/((λ+1)D) and (ψ' - k0)/φ is a polynomial; on the
        right one, with w = π - φ, (ψ_K' - k1)/sin φ = -λ(λ+1) tan(w/2)/((λ-1)D).
        """
        lam = self.lam
        g = np.empty_like(phi)
        G = np.empty_like(phi)
        L, R = self._pieces(phi)
        M = ~(L | R)
        x = phi[M]
        K = slotted_link_law(lam, x)
        sx, cx = np.sin(x), np.cos(x)
        g[M] = K.d / sx
        G[M] = (K.dd * sx - K.d * cx) / sx**3
        # left transition, x = φ
        x = phi[L]
        C = lam * (lam - 1.0) / (lam + 1.0)
        g[L], G[L] = self._piece(x, C, 1.0, self._coefs["P"])
        # right transition, w = π - φ
        w = np.pi - phi[R]
        C2 = -lam * (lam + 1.0) / (lam - 1.0)
        gr, Gr = self._piece(w, C2, -1.0, self._coefs["Pr"])
        g[R], G[R] = gr, -Gr   # d/dφ = -d/dw
        return (g, G) if with_derivative else g

    def _piece(self, x, C, sign, P):
        """g = C tan(x/2)/D - P(x)·x/sin x with D = 1 + λ² + 2λ·sign·cos x, and (dg/dx)/sin x
        (P = (coefficients of P, of P'))."""
        lam = self.lam
        D = 1.0 + lam * lam + 2.0 * lam * sign * np.cos(x)
        Dx = -2.0 * lam * sign * np.sin(x)
        P, dP = P
        s, _ = _x_over_sin(x)
        g = C * np.tan(x / 2) / D - _horner(P, x) * s
        # G = g'/sin x: g' = O(x) cancels at the ends, so G is taken at x ≥ 1e-6 (relative error
        # ~1e-10 there; it only enters the solver multiplied by t'² = O(x²))
        x = np.clip(x, 1e-6, None)
        D = 1.0 + lam * lam + 2.0 * lam * sign * np.cos(x)
        Dx = -2.0 * lam * sign * np.sin(x)
        s, ds = _x_over_sin(x)
        t = np.tan(x / 2)
        dg = C * ((1.0 + t * t) / (2.0 * D) - t * Dx / D**2) - _horner(dP, x) * s - _horner(P, x) * ds
        return g, dg / np.sin(x)

    @scalar_law
    def pressure_angle(self, phi) -> np.ndarray:
        """Pressure angle θ (radians) at the pin for any φ, from the slot's geometry:
        tan θ = S²|β'|/(r d |sin φ|) (exact limit at the slot's ends φ = 0, π).

        Parameters
        ----------
        phi : float or array_like
            Crank angles (rad).

        Returns
        -------
        numpy.ndarray
            θ (rad) at each angle.

        Examples
        --------
        >>> import numpy as np
        >>> import mechlab as ml
        >>> law = ml.DwellLaw(0.5, np.radians(60), np.radians(150), "quintic")
        >>> np.round(law.pressure_angle(np.radians([30.0, 90.0])), 4).tolist()
        [1.1435, 0.4636]
        """
        phi = np.abs(wrap(as_angles(phi)))
        S, _, _ = self.S(phi)
        g = self._g(phi)
        return np.arctan(S * S * np.abs(g) / (self.crank * self.pivot_distance))

    @scalar_law
    def curvature(self, phi) -> np.ndarray:
        """Signed curvature of the slot's centre line where the pin is at crank angle φ ∈ [0, π]
        (sign taken along increasing distance from B), from the slot parametrised by S:
        κ = (2β_S + Sβ_SS + S²β_S³)/(1 + S²β_S²)^{3/2}. On the dwell |κ| = 1/l_OA. For the
        cubic law κ grows like 1/φ towards the ends (it is evaluated 1e-6 inside them).

        Parameters
        ----------
        phi : float or array_like
            Crank angles (rad).

        Returns
        -------
        numpy.ndarray
            κ (1/length) at each angle.

        Examples
        --------
        >>> import numpy as np
        >>> import mechlab as ml
        >>> law = ml.DwellLaw(0.5, np.radians(60), np.radians(150), "quintic")
        >>> np.round(law.curvature(np.radians([90.0])), 6).tolist()  # on the dwell arc: |κ| = 1/l_OA
        [-2.0]
        """
        phi = np.abs(wrap(as_angles(phi)))
        S = self.S(phi)[0]
        _, bS, bSS = self._polar(S)
        return (2 * bS + S * bSS + S * S * bS**3) / (1 + (S * bS) ** 2) ** 1.5

    # -- the slot as a curve in the link's frame, parameter = distance from B ----------------
    def phi_of_distance(self, S) -> np.ndarray:
        """The crank angle φ ∈ [0, π] at which the pin is S from B (stable at both ends).

        Parameters
        ----------
        S : float or array_like
            Distances from B (length units), in [|r − d|, r + d] (clipped there).

        Returns
        -------
        numpy.ndarray
            φ (rad).

        Examples
        --------
        >>> import numpy as np
        >>> import mechlab as ml
        >>> law = ml.DwellLaw(0.5, np.radians(60), np.radians(150), "quintic")
        >>> np.round(law.phi_of_distance([1.5, 0.5]), 6).tolist()
        [0.0, 3.141593]
        """
        S = np.asarray(S, dtype=float)
        r, d = self.crank, self.pivot_distance
        smax, smin = r + d, abs(r - d)
        a = np.clip((smax - S) * (smax + S) / (4 * r * d), 0.0, 1.0)   # sin²(φ/2)
        b = np.clip((S - smin) * (S + smin) / (4 * r * d), 0.0, 1.0)   # cos²(φ/2)
        return np.where(a <= 0.5, 2 * np.arcsin(np.sqrt(a)), np.pi - 2 * np.arcsin(np.sqrt(b)))

    def slot_curve(self):
        """The slot's centre line as a :class:`~mechlab.mechanisms.curved_slot.ParametricSlot`
        in the link's frame with parameter t = distance from B.

        On the dwell it is the circle of radius l_OA about the link-frame image of O
        (computed from that geometry, not from the law); on the transitions
        c = S·(cos β, sin β) with β from the law, β_S = -S g/(r d), β_SS = -g/(r d) + S² G/(r d)².
        Beyond [|r - d|, r + d] (never reached by the pin) the curve goes on with constant β_S,
        so that the solver's root brackets see both ends.

        Returns
        -------
        ParametricSlot
            The curve with its first and second derivatives in t.

        Examples
        --------
        >>> import numpy as np
        >>> import mechlab as ml
        >>> law = ml.DwellLaw(0.5, np.radians(60), np.radians(150), "quintic")
        >>> np.round(law.slot_curve().evaluate(np.array([1.5])).p, 4).tolist()  # the far end, φ = 0
        [[1.5, 0.0]]
        """
        from ..mechanisms.curved_slot import ParametricSlot

        r, d = self.crank, self.pivot_distance
        smax, smin = r + d, abs(r - d)
        ends = np.array([smin, smax])
        _, bS_end, _ = self._polar(ends)
        b_end = self.beta(self.phi_of_distance(ends))[0]
        pad = 0.05 * (smax - smin)

        def polar(t):
            t = np.asarray(t, dtype=float)
            inside = (t >= smin) & (t <= smax)
            beta, bS, bSS = (np.empty_like(t) for _ in range(3))
            beta[inside], bS[inside], bSS[inside] = self._polar(t[inside])
            for k, end in enumerate(ends):
                out = (t > smax) if k else (t < smin)
                beta[out] = b_end[k] + bS_end[k] * (t[out] - end)
                bS[out] = bS_end[k]
                bSS[out] = 0.0
            return t, beta, bS, bSS

        memo = {}

        def frames(t):
            # f, df, ddf are called one after the other with the same t: compute once
            t = np.asarray(t, dtype=float)
            key = (t.shape, t.tobytes())
            if memo.get("key") != key:
                S, beta, bS, bSS = polar(t)
                er = np.stack([np.cos(beta), np.sin(beta)], axis=-1)
                et = np.stack([-er[:, 1], er[:, 0]], axis=-1)
                memo.update(key=key, value=(S, er, et, bS, bSS))
            return memo["value"]

        def f(t):
            S, er, _, _, _ = frames(t)
            c = S[:, None] * er   # a new array: the memo is not modified
            dw = self._dwell_mask(S)
            c[dw] = self._arc_point(S[dw])
            return c

        def df(t):
            S, er, et, bS, _ = frames(t)
            return er + (S * bS)[:, None] * et

        def ddf(t):
            S, er, et, bS, bSS = frames(t)
            return (-S * bS**2)[:, None] * er + (2 * bS + S * bSS)[:, None] * et

        return ParametricSlot(f, df, ddf, smin - pad, smax + pad)

    def _dwell_mask(self, S):
        phi = self.phi_of_distance(S)
        return (phi >= self.phi1) & (phi <= self.phi2)

    def _arc_point(self, S):
        """Pin positions on the dwell arc at distance S from B, from the geometry of the dwell:
        the link stands at ψ_B, so the pin is R(-ψ_B)·(A(φ) - B) with A on the crank circle."""
        phi = self.phi_of_distance(S)
        r, d = self.crank, self.pivot_distance
        v = np.stack([r * np.cos(phi) + d, r * np.sin(phi)], axis=-1)
        c, s = np.cos(self.psi_dwell), np.sin(self.psi_dwell)
        return np.stack([c * v[:, 0] + s * v[:, 1], -s * v[:, 0] + c * v[:, 1]], axis=-1)

    def _polar(self, S):
        """β, dβ/dS, d²β/dS² of the slot at distances S ∈ [|r - d|, r + d] from B."""
        rd = self.crank * self.pivot_distance
        phi = self.phi_of_distance(S)
        beta = self.beta(phi)[0]
        g, G = self._g(phi, with_derivative=True)
        return beta, -S * g / rd, -g / rd + S * S * G / rd**2


@dataclass(frozen=True, eq=False)
class DwellSlotMechanism(Mechanism):
    """The curved-slot mechanism designed for a dwell (Zinchenko et al. (2013) §3, Fig. 9).

    ``motion(phi)`` is solved through :class:`~mechlab.mechanisms.curved_slot.CurvedSlotLink`
    with the designed slot (:meth:`DwellLaw.slot_curve`); ``law`` is the design it was
    made from. Build one with :func:`curved_slot_dwell`.

    Parameters
    ----------
    lam : float
        λ = l_OA / l_OB (≠ 1; λ > 1 gives intermittent rotation).
    phi1, phi2 : float
        The dwell (rad), strictly inside (0, π).
    pivot_distance : float
        d = l_OB (length units, default 1).
    transition : {"cubic", "quintic", "sextic"}
        The transitions' law.
    roller_radius : float
        ρ ≥ 0, below the slot's smallest radius of curvature on its concave side: sets the slot's
        flanks for drawing and export.

    Attributes
    ----------
    law : DwellLaw
        The design.

    Raises
    ------
    DwellRatioError, DwellIntervalError, DwellError
        As :class:`DwellLaw`.
    SlotUndercutError
        ρ not below the slot's smallest radius of curvature.
    DimensionError
        ``roller_radius`` negative or not finite.

    Examples
    --------
    >>> import numpy as np
    >>> import mechlab as ml
    >>> mech = ml.DwellSlotMechanism(0.5, np.radians(60), np.radians(150), transition="quintic")
    >>> round(mech.law.psi_dwell, 6), mech.crank
    (0.105429, 0.5)
    """

    rollers = 1   # the roller in the slot

    @classmethod
    def example(cls) -> DwellSlotMechanism:
        """λ = 0.5, a dwell from φ = 60° to 150° (``curved_slot_dwell``).

        Returns
        -------
        DwellSlotMechanism
            A valid instance of the family, the one the services that find the families use.
        """
        return curved_slot_dwell(0.5, np.pi / 3, 5 * np.pi / 6)

    lam: float
    phi1: float
    phi2: float
    pivot_distance: float = 1.0
    transition: str = "cubic"
    roller_radius: Distance = 0.0

    pivots = ("O", "B")
    output = "angle"

    def __post_init__(self):
        super().__post_init__()
        law = DwellLaw(self.lam, self.phi1, self.phi2, self.transition, self.pivot_distance)
        for k in ("lam", "phi1", "phi2", "pivot_distance"):
            object.__setattr__(self, k, getattr(law, k))
        object.__setattr__(self, "law", law)
        if self.roller_radius > 0:
            from .slot_export import check_roller
            check_roller(self, self.roller_radius)

    @property
    def crank(self) -> float:
        """The crank's length l_OA.

        Returns
        -------
        float
            l_OA = λ·l_OB (length units).

        Examples
        --------
        >>> import numpy as np
        >>> import mechlab as ml
        >>> mech = ml.curved_slot_dwell(0.5, np.radians(60), np.radians(150), transition="quintic")
        >>> mech.crank
        0.5
        """
        return self.law.crank

    @cached_property
    def link(self):
        """The :class:`~mechlab.mechanisms.curved_slot.CurvedSlotLink` with the designed slot."""
        from ..mechanisms.curved_slot import CurvedSlotLink

        link = CurvedSlotLink(self.crank, self.pivot_distance, self.law.slot_curve())
        if not link.can_turn:  # pragma: no cover - the design covers the whole distance range
            raise DwellError(f"the designed slot does not let the crank turn: {link.rotation_failure()}")
        return link

    def base(self):
        """The base mechanism (straight slot through B).

        Returns
        -------
        SlottedLink
            The same crank and pivot distance with a straight slot.

        Examples
        --------
        >>> import numpy as np
        >>> import mechlab as ml
        >>> mech = ml.curved_slot_dwell(0.5, np.radians(60), np.radians(150), transition="quintic")
        >>> mech.base()
        SlottedLink(crank=0.5, pivot_distance=1.0)
        """
        return self.link.base()

    def motion(self, phi):
        """ψ, ψ', ψ'' and the pressure angle through the slot (the curved-slot solver).

        Parameters
        ----------
        phi : float or array_like
            Crank angles (rad).

        Returns
        -------
        AngularMotion
            The joints O, A, B, the link's angle ψ (rad), ψ′, ψ″ and the pressure angle (rad).

        Raises
        ------
        DimensionError
            ``phi`` is not finite.

        Examples
        --------
        >>> import numpy as np
        >>> import mechlab as ml
        >>> mech = ml.curved_slot_dwell(0.5, np.radians(60), np.radians(150), transition="quintic")
        >>> mo = mech.motion(np.radians([90.0, 120.0]))  # inside the dwell
        >>> np.round(mo.psi, 6).tolist(), bool(np.allclose(mo.dpsi, 0.0))
        ([0.105429, 0.105429], True)
        """
        return self.link.motion(phi)

    def structure(self):
        """The curved-slot link's: crank, slotted link, the slot's higher pair at A.

        Returns
        -------
        Structure
            The links and pairs, from which drawing, centres and forces are derived.

        Examples
        --------
        >>> import numpy as np
        >>> import mechlab as ml
        >>> mech = ml.curved_slot_dwell(0.5, np.radians(60), np.radians(150), transition="quintic")
        >>> st = mech.structure()
        >>> [link.name for link in st.links], [pair.kind for pair in st.pairs]
        (['crank', 'link'], ['revolute', 'higher', 'revolute'])
        """
        return self.link.structure()

    def sketch(self, motion) -> Sketch:
        """The crank; the link's slot (centre line, the dwell arc highlighted, the roller's flanks) drawn
        in the link frame once and turned by ψ about B; the arm holding it (numbered); the roller; and
        "dwell" while the link stands still.

        Parameters
        ----------
        motion : AngularMotion
            The mechanism's motion, the frames drawn.

        Returns
        -------
        Sketch
            The parts in drawing order and the fixed pivots.

        Examples
        --------
        >>> import numpy as np
        >>> import mechlab as ml
        >>> mech = ml.curved_slot_dwell(0.5, np.radians(60), np.radians(150), transition="quintic")
        >>> sketch = mech.sketch(mech.motion(mech.turn(5)))
        >>> [part.role for part in sketch.parts][:3], sketch.pivots
        (['link', 'arm', 'anchor'], ('O', 'B'))
        """
        from .slot_export import slot_profile

        centre, arc, rho = self.slot_points(160), self.dwell_points(60), self.roller_radius
        flanks = []
        if rho > 0:
            prof = slot_profile(self, n=160)
            flanks = [prof.left, prof.right]
        B, psi, A = motion.points["B"].p, motion.psi, motion.points["A"].p
        still = self.law.in_dwell(motion.phi)
        ring = rho * np.stack([np.cos(np.linspace(0, 2 * np.pi, 40)), np.sin(np.linspace(0, 2 * np.pi, 40))], -1)

        def world(xy, i):
            c, s = np.cos(psi[i]), np.sin(psi[i])
            return B[i] + xy @ np.array([[c, s], [-s, c]])

        parts = (Part("link", ("O", "A"), "crank"),
                 Part("arm", lambda i: np.array([world(centre[:1], i)[0], B[i], world(centre[-1:], i)[0]])),
                 Part("anchor", lambda i: np.array([world(centre[:1], i)[0], B[i]]), "link"),
                 Part("slot centre", lambda i: world(centre, i)), Part("dwell", lambda i: world(arc, i)),
                 *(Part("flank", lambda i, f=f: world(f, i)) for f in flanks),
                 *((Part("roller", lambda i: A[i] + ring),) if rho > 0 else ()),
                 Part("note", lambda i: "dwell" if still[i] else ""))
        return Sketch(parts, self.pivots)

    @validated
    def slot_points(self, n: Annotated[int, count(2)] = 401) -> np.ndarray:
        """(n, 2) points of the slot's centre line in the link frame, from the far end E
        (φ = 0) to the near end (φ = π), as the solver's curve gives them.

        Parameters
        ----------
        n : int
            Points, ≥ 2 (default 401).

        Returns
        -------
        numpy.ndarray
            (n, 2) points (length units).

        Raises
        ------
        DimensionError
            ``n`` is not an integer ≥ 2.

        Examples
        --------
        >>> import numpy as np
        >>> import mechlab as ml
        >>> mech = ml.curved_slot_dwell(0.5, np.radians(60), np.radians(150), transition="quintic")
        >>> np.round(mech.slot_points(3), 4).tolist()
        [[1.5, 0.0], [0.9211, 0.3894], [0.4991, 0.0294]]
        """
        S = np.linspace(self.crank + self.pivot_distance, abs(self.crank - self.pivot_distance), n)
        return self.link.slot.points(S)

    @validated
    def dwell_points(self, n: Annotated[int, count(2)] = 101) -> np.ndarray:
        """(n, 2) points of the dwell arc (link frame).

        Parameters
        ----------
        n : int
            Points, ≥ 2 (default 101).

        Returns
        -------
        numpy.ndarray
            (n, 2) points on the arc of radius l_OA about :meth:`DwellLaw.centre_in_link`.

        Raises
        ------
        DimensionError
            ``n`` is not an integer ≥ 2.

        Examples
        --------
        >>> import numpy as np
        >>> import mechlab as ml
        >>> mech = ml.curved_slot_dwell(0.5, np.radians(60), np.radians(150), transition="quintic")
        >>> arc = mech.dwell_points(3)
        >>> np.round(np.hypot(*(arc - mech.law.centre_in_link()).T), 12).tolist()
        [0.5, 0.5, 0.5]
        """
        phi = np.linspace(self.phi1, self.phi2, n)
        return self.law._arc_point(self.law.S(phi)[0])

    @validated
    def max_pressure_angle(self, n: Annotated[int, count(2)] = 721) -> tuple[float, float]:
        """(θ_max, φ at θ_max) over the whole turn from the solver's motion: a grid over [0, π]
        (θ(-φ) = θ(φ): the pin is at the same slot point), the peak refined on the closed form
        :meth:`DwellLaw.pressure_angle`, and θ re-evaluated there through the solver.

        Parameters
        ----------
        n : int
            Grid points over [0, π], ≥ 2 (default 721).

        Returns
        -------
        theta, phi : float
            The largest pressure angle and the crank angle where it occurs (rad).

        Raises
        ------
        DimensionError
            ``n`` is not an integer ≥ 2.

        Examples
        --------
        >>> import numpy as np
        >>> import mechlab as ml
        >>> mech = ml.curved_slot_dwell(0.5, np.radians(60), np.radians(150), transition="quintic")
        >>> theta, where = mech.max_pressure_angle()
        >>> round(float(np.degrees(theta)), 2), float(where)
        (70.39, 0.0)
        """
        from scipy.optimize import minimize_scalar

        phi = np.linspace(0.0, np.pi, n)
        th = self.motion(phi).pressure_angle
        i = int(np.argmax(th))
        best_phi, best = float(phi[i]), float(th[i])
        lo, hi = phi[max(i - 1, 0)], phi[min(i + 1, n - 1)]
        res = minimize_scalar(lambda x: -self.law.pressure_angle(x), bounds=(lo, hi), method="bounded",
                              options={"xatol": 1e-10})
        refined = float(self.motion(res.x).pressure_angle)
        if refined > best:
            best_phi, best = float(res.x), refined
        return best, best_phi


def curved_slot_dwell(lam, phi1, phi2, pivot_distance=1.0, transition="cubic", *,
                      roller_radius=0.0) -> DwellSlotMechanism:
    """Design the curved-slot dwell mechanism of Zinchenko et al. (2013) §3 (angles in radians, seed-000 frame).

    Parameters
    ----------
    lam : float
        λ = l_OA / l_OB (≠ 1; λ > 1 gives intermittent rotation).
    phi1, phi2 : float
        The dwell (rad), strictly inside (0, π).
    pivot_distance : float
        d = l_OB (length units, default 1).
    transition : {"cubic", "quintic", "sextic"}
        The transitions' law (:data:`TRANSITIONS`).
    roller_radius : float
        ρ ≥ 0 of the roller on the pin, for the slot's flanks.

    Returns
    -------
    DwellSlotMechanism
        The mechanism, its motion solved through the designed slot.

    Raises
    ------
    DwellRatioError
        λ out of range or too near 1.
    DwellIntervalError
        φ1 ≥ φ2, outside [0, π], touching 0 or π.
    DwellError
        An unknown transition.
    SlotUndercutError
        ρ not below the slot's smallest radius of curvature.

    Examples
    --------
    >>> import numpy as np
    >>> import mechlab as ml
    >>> mech = ml.curved_slot_dwell(0.5, np.radians(60), np.radians(150), transition="quintic")
    >>> np.round(mech.motion(np.radians([90.0, 120.0])).psi, 6).tolist()  # the link stands still
    [0.105429, 0.105429]
    """
    return DwellSlotMechanism(lam, phi1, phi2, pivot_distance, transition, roller_radius)


# ---------------------------------------------------------------------------------------------
# comparisons and limits
# ---------------------------------------------------------------------------------------------
def _jerk_jump(law: DwellLaw) -> float:
    e = 1e-9
    x = np.array([0.0, law.phi1, law.phi2, np.pi])
    return float(np.abs(law(x + e).ddd - law(x - e).ddd).max())


@dataclass(frozen=True)
class TransitionRow:
    """One transition law of a dwell slot (a row of :func:`compare_transitions`); angles in degrees
    where the name says ``_deg``, curvatures in 1/length, the radius in length."""

    transition: str
    psi_dwell_deg: float     # ψ_B, the dwell's output angle
    peak_dpsi: float         # max |ψ'| over the turn, through the slot
    peak_ddpsi: float        # max |ψ''|
    peak_jerk: float         # max |ψ'''| of the law
    jerk_jump: float         # largest jump of ψ''' at 0, φ1, φ2, π
    max_pressure_deg: float  # largest pressure angle
    where_deg: float         # the crank angle where it occurs
    curvature_max: float     # largest |κ| of the slot for φ ∈ [1°, 179°]
    curvature_end: float     # |κ| at the slot's ends
    min_radius: float        # smallest radius of curvature


@dataclass(frozen=True)
class DwellLimit:
    """The longest dwell under a pressure-angle bound (:func:`dwell_limit`): its length and place
    (φ1, φ2 in radians), the largest pressure angle reached and where, named."""

    max_dwell_deg: float
    phi1: float
    phi2: float
    theta_deg: float
    where_deg: float
    where: str


@dataclass(frozen=True)
class TwoBranchSlot:
    """The two-branch slot (:func:`two_branch_slot`): the pressure angle at the far point E
    (radians), ψ' just after and just before φ = 0, their difference, and ``link()`` building
    the curved-slot mechanism."""

    pressure_angle_at_E: float
    dpsi_after: float
    dpsi_before: float
    velocity_jump: float
    link: Callable = field(repr=False)


@validated
def compare_transitions(lam, phi1, phi2, pivot_distance=1.0, n: Annotated[int, count(2)] = 721) -> Table:
    """One :class:`TransitionRow` per transition law: ψ_B, peak |ψ'|, |ψ''| (through the slot,
    whole turn), peak |ψ'''| and its largest jump at 0, φ1, φ2, π (from the law), the largest
    pressure angle and where it occurs, the largest |κ| of the slot for φ ∈ [1°, 179°] and |κ|
    at its ends (1e-6 rad inside them), and the smallest radius of curvature.

    Parameters
    ----------
    lam : float
        λ = l_OA / l_OB.
    phi1, phi2 : float
        The dwell (rad), strictly inside (0, π).
    pivot_distance : float
        d = l_OB (length units, default 1).
    n : int
        Crank angles over the turn, ≥ 2 (default 721).

    Returns
    -------
    Table
        One ``TransitionRow`` per law of :data:`TRANSITIONS`.

    Raises
    ------
    DwellRatioError, DwellIntervalError
        As :func:`curved_slot_dwell`.
    DimensionError
        ``n`` is not an integer ≥ 2.

    Examples
    --------
    >>> import numpy as np
    >>> import mechlab as ml
    >>> table = ml.compare_transitions(0.5, np.radians(60), np.radians(150))
    >>> [(row.transition, round(row.min_radius, 4)) for row in table]
    [('cubic', 0.0), ('quintic', 0.5), ('sextic', 0.0132)]
    """
    from .slot_export import min_radius_of_curvature

    rows = []
    for tr in TRANSITIONS:
        m = curved_slot_dwell(lam, phi1, phi2, pivot_distance, tr)
        phi = m.turn(n)
        mo = m.motion(phi)
        law = m.law(phi)
        th, where = m.max_pressure_angle()
        inner = np.linspace(np.radians(1.0), np.radians(179.0), 1001)
        rows.append(TransitionRow(
            transition=tr,
            psi_dwell_deg=float(np.degrees(m.law.psi_dwell)),
            peak_dpsi=float(np.abs(mo.dpsi).max()),
            peak_ddpsi=float(np.abs(mo.ddpsi).max()),
            peak_jerk=float(np.abs(law.ddd).max()),
            jerk_jump=_jerk_jump(m.law),
            max_pressure_deg=float(np.degrees(th)),
            where_deg=float(np.degrees(where)),
            curvature_max=float(np.abs(m.law.curvature(inner)).max()),
            curvature_end=float(np.abs(m.law.curvature(np.array([0.0, np.pi]))).max()),
            min_radius=min_radius_of_curvature(m)[0],
        ))
    return Table(rows)


def _worst(law: DwellLaw, n: int = 361):
    phi = np.linspace(0.0, np.pi, n)
    th = law.pressure_angle(phi)
    i = int(np.argmax(th))
    return float(th[i]), float(phi[i])


def where_kind(law: DwellLaw, phi: float, tol: float = np.radians(0.5)) -> str:
    """Name the place of a crank angle in the design: slot end, dwell end, transition, dwell."""
    phi = abs(float(wrap(phi)))
    if phi <= tol:
        return "far slot end (φ = 0)"
    if phi >= np.pi - tol:
        return "near slot end (φ = 180°)"
    if abs(phi - law.phi1) <= tol or abs(phi - law.phi2) <= tol:
        return "dwell end"
    if law.phi1 < phi < law.phi2:
        return "dwell"
    return "transition"


@validated
def best_placement(lam: Ratio, length: Annotated[float, angle(0.0, np.pi, open=True)], transition: Transition = "cubic",
                   pivot_distance: Length = 1.0, n_grid: Annotated[int, count(2, MAX_GRID)] = 19):
    """The dwell [φ1, φ1 + length] that minimises the largest pressure angle (law-based, closed form).

    A grid over φ1, then a bounded refinement.

    Parameters
    ----------
    lam : float
        λ = l_OA / l_OB.
    length : float
        The dwell's crank angle (rad), in (0, π).
    transition : {"cubic", "quintic", "sextic"}
        The transitions' law.
    pivot_distance : float
        d = l_OB (length units, default 1).
    n_grid : int
        Grid points over φ1, ≥ 2 (default 19).

    Returns
    -------
    theta_max, phi1 : float
        The least largest pressure angle and the dwell's start (rad).

    Raises
    ------
    DwellRatioError
        λ out of range or too near 1.
    DwellIntervalError
        The dwell leaves no room for both transitions.
    DwellError
        An unknown transition.

    Examples
    --------
    >>> import numpy as np
    >>> import mechlab as ml
    >>> theta, phi1 = ml.best_placement(0.5, np.radians(90))
    >>> round(float(np.degrees(theta)), 2), round(float(np.degrees(phi1)), 2)
    (68.56, 67.5)
    """
    from scipy.optimize import minimize_scalar

    margin = 1e-3
    lo, hi = margin, np.pi - length - margin
    if hi <= lo:
        raise DwellIntervalError(f"a dwell of {np.degrees(length):.2f}° leaves no room for both transitions")

    def cost(p1):
        return _worst(DwellLaw(lam, p1, p1 + length, transition, pivot_distance))[0]

    grid = np.linspace(lo, hi, n_grid)
    vals = np.array([cost(p) for p in grid])
    i = int(np.argmin(vals))
    a, b = grid[max(i - 1, 0)], grid[min(i + 1, n_grid - 1)]
    res = minimize_scalar(cost, bounds=(a, b), method="bounded", options={"xatol": 1e-5})
    return (float(res.fun), float(res.x)) if res.fun < vals[i] else (float(vals[i]), float(grid[i]))


@validated
def dwell_limit(lam: Ratio, theta_max: Annotated[float, angle(0.0, np.pi / 2)], transition: Transition = "cubic",
                pivot_distance: Length = 1.0) -> DwellLimit:
    """The longest dwell whose largest pressure angle stays ≤ ``theta_max`` (radians) with the
    best placement, by bisection on the dwell length. Zinchenko et al. (2013) §3 says a dwell over 120°
    makes the pressure angle large; this computes the actual limit and where θ is worst.

    Parameters
    ----------
    lam : float
        λ = l_OA / l_OB.
    theta_max : float
        The pressure angle bound (rad), in [0, π/2].
    transition : {"cubic", "quintic", "sextic"}
        The transitions' law.
    pivot_distance : float
        d = l_OB (length units, default 1).

    Returns
    -------
    DwellLimit
        The longest dwell (deg), its φ1, φ2 (rad), the largest pressure angle (deg) and where.

    Raises
    ------
    DwellError
        No dwell keeps the pressure angle within the bound, or an unknown transition.
    DwellRatioError
        λ out of range or too near 1.

    Examples
    --------
    >>> import numpy as np
    >>> import mechlab as ml
    >>> limit = ml.dwell_limit(0.5, np.radians(75), "quintic")
    >>> round(limit.max_dwell_deg, 1), limit.where
    (119.6, 'far slot end (φ = 0)')
    """
    lo, hi = np.radians(1.0), np.pi - np.radians(1.0)
    if best_placement(lam, lo, transition, pivot_distance)[0] > theta_max:
        raise DwellError(f"no dwell keeps the pressure angle ≤ {np.degrees(theta_max):.1f}° for λ = {lam:g} "
                         f"with the {transition} transition")
    for _ in range(30):
        mid = 0.5 * (lo + hi)
        if best_placement(lam, mid, transition, pivot_distance)[0] <= theta_max:
            lo = mid
        else:
            hi = mid
        if hi - lo < 2e-4:
            break
    th, p1 = best_placement(lam, lo, transition, pivot_distance)
    law = DwellLaw(lam, p1, p1 + lo, transition, pivot_distance)
    _, where = _worst(law, 3601)
    return DwellLimit(max_dwell_deg=float(np.degrees(lo)), phi1=p1, phi2=float(p1 + lo),
                      theta_deg=float(np.degrees(th)), where_deg=float(np.degrees(where)), where=where_kind(law, where))


@validated
def cubic_dwell_window(lam: Ratio,
                       theta_max: Annotated[float, angle(0.0, np.pi / 2, open=True)]) -> tuple[float, float]:
    """The longest dwell [φ1, φ2] (radians) of the cubic transition whose pressure angle stays ≤ ``theta_max``
    at both slot ends, where the cubic's is largest (chapter 5, from Zinchenko et al. (2013) (21), (23)):
    tan θ(0) = 2(1 + λ)/φ1 and tan θ(π) = 2|1 - λ|/(π - φ2), so φ1 = 2(1 + λ)/tan θ_max and
    φ2 = π - 2|1 - λ|/tan θ_max. :func:`dwell_limit` finds the same window numerically.

    Parameters
    ----------
    lam : float
        λ = l_OA / l_OB.
    theta_max : float
        The pressure angle bound (rad), in (0, π/2].

    Returns
    -------
    phi1, phi2 : float
        The window's ends (rad).

    Raises
    ------
    DwellIntervalError
        The two transitions leave no dwell.
    DwellRatioError
        λ out of range or too near 1.

    Examples
    --------
    >>> import numpy as np
    >>> import mechlab as ml
    >>> [round(float(np.degrees(p)), 2) for p in ml.cubic_dwell_window(0.5, np.radians(60))]
    [99.24, 146.92]
    """
    lam = check_lambda(lam)
    phi1 = 2.0 * (1.0 + lam) / np.tan(theta_max)
    phi2 = np.pi - 2.0 * abs(1.0 - lam) / np.tan(theta_max)
    if phi2 - phi1 <= 0.0:
        raise DwellIntervalError(
            f"θ ≤ {np.degrees(theta_max):.2f}° at both slot ends needs φ1 ≥ {np.degrees(phi1):.2f}° and "
            f"φ2 ≤ {np.degrees(phi2):.2f}°: no dwell is left for λ = {lam:g} with the cubic transition")
    return float(phi1), float(phi2)


@validated
def two_branch_slot(lam: Ratio, phi2: Annotated[float, angle(0.0, np.pi, open=True, error=DwellIntervalError)],
                    pivot_distance: Length = 1.0) -> TwoBranchSlot:
    """The two-branch slot of Zinchenko et al. (2013) Fig. 10: the dwell starts at φ1 = 0, so the dwell arc
    (radius l_OA about O, link at ψ_B = 0) passes through the slot's far point E.

    Returns a :class:`TwoBranchSlot`: ``pressure_angle_at_E`` (π/2: the arc is tangent to the circle about B there),
    ``dpsi_after`` = ψ'(0+) through the solver (the link dwells), ``dpsi_before`` = ψ'(0-) when
    the pin comes back along the same branch (Table 2: 2ψ_K'(0) - ψ'(0+)), their difference
    ``velocity_jump`` (= 2λ/(λ+1), times ω1), and ``link``: a factory of the curved-slot
    mechanism with that arc, which raises SingularityError at φ = 0.

    Parameters
    ----------
    lam : float
        λ = l_OA / l_OB.
    phi2 : float
        The dwell's end (rad), in (0, π).
    pivot_distance : float
        d = l_OB (length units, default 1).

    Returns
    -------
    TwoBranchSlot
        The pressure angle at E, ψ′ after and before φ = 0, their jump, and ``link()``.

    Raises
    ------
    DwellRatioError
        λ out of range or too near 1.
    DwellIntervalError
        ``phi2`` outside (0, π).

    Examples
    --------
    >>> import numpy as np
    >>> import mechlab as ml
    >>> slot = ml.two_branch_slot(0.5, np.radians(120))
    >>> round(slot.velocity_jump, 6), round(slot.pressure_angle_at_E, 6)  # 2λ/(λ + 1), π/2
    (0.666667, 1.570796)
    """
    from ..mechanisms.curved_slot import CircleSlot, CurvedSlotLink

    lam = check_lambda(lam)
    d = pivot_distance
    r = lam * d

    def link():
        return CurvedSlotLink(r, d, CircleSlot((d, 0.0), r), start=0.0)

    after = float(link().motion(np.array([0.5 * phi2])).dpsi[0])   # the link dwells on (0, φ2)
    before = float(2 * slotted_link_law(lam, 0.0).d - after)
    # at E the slot point is c(0) = (d + r, 0) in the link frame (= B→E); θ = angle(tangent, radius)
    E = link().slot.evaluate(np.array([0.0]))
    cos_t = abs(float(E.p[0] @ E.d[0])) / (np.hypot(*E.p[0]) * np.hypot(*E.d[0]))
    return TwoBranchSlot(pressure_angle_at_E=float(np.arccos(cos_t)), dpsi_after=after,
                         dpsi_before=before, velocity_jump=before - after, link=link)


# the old name (analysis.equivalence.base_law is the law of any mechanism's base mechanism)
__getattr__ = renamed(__name__, base_law=(slotted_link_law, "mechlab.synthesis.dwell_slot.slotted_link_law"))
