"""The offset spherical Geneva drive (Vainer & Shatokhina): design and exact 3-D model.

Sphere of radius R about O, wheel axis z, slots in the meridian planes; the crank axis is the line
{y = 0, z = -e}, its point O1 = (0, 0, -e) on the wheel axis. The pin axis is a generatrix of the
cone with apex O1, axis x and half-angle ψ (formula (3)): d(α) = (cos ψ, sin ψ sin α, sin ψ cos α),
α = 0 at the crank's lowest position (Fig. 2). As O1 is on the wheel axis, the pin axis lies in the
meridian plane of its contact point, so the wheel angle is the azimuth of d: tan β = tan ψ·sin α,
exact for any e (equivalent to formula (18)); cos γ = cos α·sin ψ (11) is exact too, the
"neglected" term C1 of (10) being identically zero by (3).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Annotated

import numpy as np

from ..errors import DimensionError, MechanismError, SpatialMechanismError  # noqa: F401 (re-exported)
from ..geometry import AnglePath, PointPath, as_angles, vector_angle
from ..motion import AngularMotion, Quantity, Table, scalar_law
from ..validate import Length, check_value, choice, length, number, validated
from .base import FRAME, Link, Mechanism, Pair, Structure
from .geneva import LENGTH_UNITS, TWO_PI, Impact, OffsetError, Slots, mid_motion_angle


# ----------------------------------------------------------------------------------
# spherical offset Geneva (Vainer & Shatokhina)
# ----------------------------------------------------------------------------------
@dataclass(frozen=True)
class SphericalModel:
    """The exact 3-D model at crank angles α: contact point A (3-D PointPath), pin axis
    direction d, distance u = |O1A|, wheel angle β (azimuth of A), γ (angle between
    O1A and the wheel axis), ρ (A's distance from the crank axis), r (from the wheel axis)."""

    A: PointPath
    d: np.ndarray
    u: np.ndarray
    beta: AnglePath
    gamma: np.ndarray
    rho: np.ndarray
    r: np.ndarray


# the pin's allowance beyond the slot wall, mm (seed formula (9))
Allowance = Annotated[float, number(5.0, 8.0, why="within [5, 8] mm, seed formula (9)")]


@dataclass(frozen=True)
class SphericalGeneva(Mechanism):
    """Hemispherical Geneva with perpendicular axes and offset e (Vainer & Shatokhina).

    A spatial mechanism: its motion's points are 3-D; the planar methods refuse it with
    SpatialMechanismError.

    Parameters
    ----------
    R : float
        Sphere radius (mm).
    e : float
        Offset of the crank axis from the sphere's centre (mm, 0 ≤ e < R).
    z : int
        Number of slots (≥ 3).
    pin_diameter : float, optional
        d, the pin's diameter (mm; seed Table 1: R = 40, e = 15, d = 10 mm).

    Raises
    ------
    OffsetError
        For e < 0 or e ≥ R.
    SlotCountError
        For z that is not a whole number ≥ 3.
    DimensionError
        For a bad radius, or a pin too thick for the slot's working length.

    Examples
    --------
    >>> from mechlab import SphericalGeneva
    >>> g = SphericalGeneva(100, 20, 4)
    >>> round(g.dwell_fraction, 4), round(g.max_velocity(), 4)
    (0.5877, 1.0392)
    """

    title = "spherical Geneva"

    locks = 1   # the crank's locking disc on the wheel's arcs

    @classmethod
    def example(cls) -> SphericalGeneva:
        """Sphere 40 mm, offset 15 mm, four slots.

        Returns
        -------
        SphericalGeneva
            A valid instance of the family, the one the services that find the families use.
        """
        return cls(40.0, 15.0, 4, pin_diameter=10.0)

    R: Length
    e: Annotated[float, length(zero=True, error=OffsetError)]
    z: Slots
    pin_diameter: Length = 10.0

    spatial = True   # drawn in 3-D
    pivots = ("O", "O1")
    output = "angle"

    def structure(self) -> Structure:
        """The crank B→P turning about the crank axis, the wheel about its axis through O, the pin P in a slot.

        The pin in a slot is a higher pair; one group, the wheel. Spatial: the axes are perpendicular and the
        contact lies on the sphere, so the planar methods (instantaneous centres, planar kinetostatics) refuse
        it with SpatialMechanismError; its links and pairs still give the design layer's counts (a spherical
        linkage's mobility has the planar formula, 3n − 2p₅ − p₄).

        Returns
        -------
        Structure
            Links, pairs and structural groups, from which the drawing, centres, force model and counts derive.

        Examples
        --------
        >>> from mechlab import SphericalGeneva
        >>> g = SphericalGeneva(100, 20, 4)
        >>> g.structure().numbers()
        {'crank': 1, 'wheel': 2, 'frame': 3}
        """
        return Structure(
            (Link("crank", "O1", ("B", "P"), self.R, joints=("B", "P")), Link("wheel", "O", 0.0)),
            (Pair("revolute", "O1", FRAME, "crank", "O1"), Pair("higher", "pin", "wheel", "crank", "P"),
             Pair("revolute", "O", FRAME, "wheel", "O")),
            (("wheel",),), "wheel", scale=self.R,
            spatial="the spherical Geneva is a spatial mechanism (crank and wheel axes perpendicular, the contact on "
                    "the sphere; its crank torque comes from the power balance, "
                    "mechlab.kinetostatics.geneva.crank_torque)")

    def __post_init__(self):
        super().__post_init__()
        if self.e >= self.R:
            raise OffsetError(f"the offset must satisfy e < R (the crank axis passes inside the sphere), "
                              f"got e = {self.e:g} ≥ R = {self.R:g}")
        if self.pin_diameter >= self.min_slot_length:
            raise DimensionError(f"pin_diameter = {self.pin_diameter:g} must be smaller than the slot's working "
                                 f"arc R·(π/2 - arcsin(r_H/R)) = {self.min_slot_length - self.pin_diameter / 2:.6g}")

    # -- design (Vainer & Shatokhina, formulas (1)-(9)) ------------------------------------------
    @property
    def k(self) -> float:
        """k = e/R (seed, after (5)).

        Returns
        -------
        float
            k (dimensionless).
        """
        return self.e / self.R

    @property
    def beta0(self) -> float:
        """Half the index angle, π/z (seed Table 1: 60°, 45°, 36°, 30°, 22.5°).

        Returns
        -------
        float
            β0 (radians).
        """
        return np.pi / self.z

    @property
    def rho0(self) -> float:
        """ρ0 = sqrt(e² + R² sin²β0): radius of the entry point A0 about the crank axis (1).

        Returns
        -------
        float
            ρ0 (length).
        """
        return float(np.hypot(self.e, self.R * np.sin(self.beta0)))

    @property
    def alpha0(self) -> float:
        """α0 = arccos(e/ρ0) (2): the crank angle at entry; sin β0 = (e/R) tan α0 (5).

        Returns
        -------
        float
            α0 (radians).
        """
        return float(np.arccos(self.e / self.rho0))

    @property
    def cone_angle(self) -> float:
        """The seed's ψ = atan(ρ0/(R cos β0)) (3): half-angle of the pin axis' cone about the crank axis.

        Returns
        -------
        float
            ψ (radians).
        """
        return float(np.arctan2(self.rho0, self.R * np.cos(self.beta0)))

    @property
    def gamma0(self) -> float:
        """γ0 = atan(R/e) (4): angle between O1A0 and the wheel axis at entry (A0 on the equator).

        Returns
        -------
        float
            γ0 (radians).
        """
        return float(np.arctan2(self.R, self.e))

    @property
    def a2(self) -> float:
        """a² = 1/sin²ψ (seed, after (18)).

        Returns
        -------
        float
            a² (dimensionless).
        """
        return 1.0 / np.sin(self.cone_angle) ** 2

    @property
    def u0(self) -> float:
        """|O1A0| = ρ0/sin ψ = sqrt(R² + e²).

        Returns
        -------
        float
            |O1A0| (length).
        """
        return self.rho0 / np.sin(self.cone_angle)

    @property
    def u_H(self) -> float:
        """|O1A_H| at α = 0: e sin ψ + R sqrt(1 - k² cos²ψ) (root of U² - 2eU sin ψ - (R² - e²) = 0).

        Returns
        -------
        float
            |O1A_H| (length).
        """
        p = self.cone_angle
        return float(self.e * np.sin(p) + self.R * np.sqrt(1.0 - self.k**2 * np.cos(p) ** 2))

    @property
    def rho_H(self) -> float:
        """ρ_H = |O1A_H| sin ψ (6): contact radius about the crank axis in the lowest position.

        Returns
        -------
        float
            ρ_H (length).
        """
        return self.u_H * np.sin(self.cone_angle)

    @property
    def r_H(self) -> float:
        """r_H = |O1A_H| cos ψ = ρ_H / tan ψ (7), (8): contact radius about the wheel axis.

        Returns
        -------
        float
            r_H (length).
        """
        return self.u_H * np.cos(self.cone_angle)

    @property
    def pin_travel(self) -> float:
        """(ρ_H - ρ0)/sin ψ = |O1A_H| - |O1A0|: how far the contact runs along the pin.

        Returns
        -------
        float
            The travel (length).
        """
        return (self.rho_H - self.rho0) / np.sin(self.cone_angle)

    @validated
    def pin_length(self, wall: Length, allowance: Allowance = 6.5) -> float:
        """Crank-pin length (9): (ρ_H - ρ0)/sin ψ + δ + (5…8) mm, δ the slot wall
        thickness, ``allowance`` in [5, 8] mm (2…3 mm inside plus 3…5 mm outside).

        Parameters
        ----------
        wall : float
            δ, the slot wall's thickness (mm).
        allowance : float, optional
            The allowance in [5, 8] mm.

        Returns
        -------
        float
            The pin's length (mm).

        Raises
        ------
        DimensionError
            For a wall that is not positive or an allowance outside [5, 8].

        Examples
        --------
        >>> from mechlab import SphericalGeneva
        >>> g = SphericalGeneva(100, 20, 4)
        >>> round(g.pin_length(3.0), 4)
        20.9649
        """
        return self.pin_travel + wall + allowance

    @property
    def min_slot_length(self) -> float:
        """L = R·∠A_H O G + d/2 with ∠A_H O G = π/2 - arcsin(r_H/R): the meridian arc from
        the equator (entry) to the highest contact point A_H, plus half the pin.

        Returns
        -------
        float
            L (length).
        """
        return self.R * (np.pi / 2 - np.arcsin(self.r_H / self.R)) + self.pin_diameter / 2

    @property
    def dwell_fraction(self) -> float:
        """1 - α0/π: the pin is in a slot for |α| ≤ α0.

        Returns
        -------
        float
            The fraction of the crank's turn during which the wheel stands.
        """
        return 1.0 - self.alpha0 / np.pi

    @property
    def index_angle(self) -> float:
        """The wheel's turn per index, 2π/z.

        Returns
        -------
        float
            The angle (radians).
        """
        return TWO_PI / self.z

    @property
    def engagement_half_angle(self) -> float:
        """α0: the pin is in a slot for |α| ≤ α0 (same name as the planar drives).

        Returns
        -------
        float
            α0 (radians).
        """
        return self.alpha0

    # -- closed forms (seed (16)-(22)) ------------------------------------------------
    def position(self, alpha) -> AnglePath:
        """β(α) = arcsin(sin α / sqrt(a² - cos²α)) (18), β' (19) and β'' (20) (per ω1, ω1²).

        Parameters
        ----------
        alpha : float or array_like
            Crank angles α from the middle of the motion (radians).

        Returns
        -------
        AnglePath
            β (radians) with β' and β''.

        Examples
        --------
        >>> from mechlab import SphericalGeneva
        >>> g = SphericalGeneva(100, 20, 4)
        >>> round(float(g.position(0.3).theta), 4)
        0.298
        """
        al = np.asarray(alpha, dtype=float)
        a2 = self.a2
        q = a2 - np.cos(al) ** 2
        s = np.sqrt(a2 - 1.0)
        beta = np.arcsin(np.sin(al) / np.sqrt(q))
        return AnglePath(beta, s * np.cos(al) / q, -s * (a2 + np.cos(al) ** 2) * np.sin(al) / q**2)

    def max_velocity(self) -> float:
        """ω_max/ω1 = 1/sqrt(a² - 1) = tan ψ at α = 0 (seed (21), printed as ε).

        Returns
        -------
        float
            ω_max/ω1 (dimensionless).

        Examples
        --------
        >>> from mechlab import SphericalGeneva
        >>> g = SphericalGeneva(100, 20, 4)
        >>> round(g.max_velocity(), 4)
        1.0392
        """
        return float(1.0 / np.sqrt(self.a2 - 1.0))

    def acceleration_extreme_alpha(self) -> float:
        """α1 ∈ [0, π/2] of the largest |ε| of (20): sin²α1 = 3a² - sqrt(8a⁴ + 1) (22),
        the root of sin⁴α - 6a² sin²α + a⁴ - 1 = 0 below 1. It may lie beyond α0, where
        the wheel no longer moves. For a² ≥ 6 (ψ ≤ 24.09°) the root is ≥ 1: there is no
        interior extreme and |ε| grows up to α = π/2, returned then.

        Returns
        -------
        float
            α1 (radians).
        """
        a2 = self.a2
        s2 = 3.0 * a2 - np.sqrt(8.0 * a2 * a2 + 1.0)
        return float(np.arcsin(np.sqrt(s2))) if s2 < 1.0 else np.pi / 2

    def max_acceleration(self) -> tuple[float, float]:
        """(|ε|max/ω1², α where reached) while the wheel moves (|α| ≤ α0): at α1 if
        α1 ≤ α0, else at the entry α0 (|ε| increases all the way to α0).

        Returns
        -------
        tuple of float
            |ε|max/ω1² (dimensionless) and the angle α (radians) where it is reached.

        Examples
        --------
        >>> from mechlab import SphericalGeneva
        >>> g = SphericalGeneva(100, 20, 4)
        >>> [round(v, 4) for v in g.max_acceleration()]
        [0.9314, 0.5113]
        """
        al = min(self.acceleration_extreme_alpha(), self.alpha0)
        return float(abs(self.position(al).dd)), al

    def entry_velocity(self) -> float:
        """β'(α0) = sin ψ cos ψ cos α0 / (1 - sin²ψ cos²α0), which by (1)-(3)
        (sin ψ = ρ0/sqrt(R² + e²), cos α0 = e/ρ0) is k·cos β0 = (e/R)·cos(π/z): zero only for e = 0.

        Returns
        -------
        float
            β'(α0) (dimensionless).

        Examples
        --------
        >>> from mechlab import SphericalGeneva
        >>> g = SphericalGeneva(100, 20, 4)
        >>> round(g.entry_velocity(), 4)  # (e/R)·cos(π/z) = 0.2·cos 45°
        0.1414
        """
        return float(self.position(self.alpha0).d)

    def impacts(self) -> Impact:
        """Jumps at entry (α = -α0) and exit (α0): ψ' jumps from 0 to β'(α0) > 0 for
        e > 0 — a hard impact; for e = 0 (α0 = 90°) only ψ'' jumps — soft.

        Returns
        -------
        Impact
            The jumps of ψ' and ψ'' at entry and at exit.

        Examples
        --------
        >>> from mechlab import SphericalGeneva
        >>> g = SphericalGeneva(100, 20, 4)
        >>> round(g.impacts().entry_velocity_jump, 4)
        0.1414
        """
        a, b = self.position(-self.alpha0), self.position(self.alpha0)
        return Impact(float(a.d), float(a.dd), float(-b.d), float(-b.dd))

    # -- exact 3-D model --------------------------------------------------------------
    def pin_direction(self, alpha) -> np.ndarray:
        """Unit vector of the pin axis on its cone: (cos ψ, sin ψ sin α, sin ψ cos α).

        Parameters
        ----------
        alpha : float or array_like
            Crank angles α from the middle of the motion (radians).

        Returns
        -------
        numpy.ndarray
            Unit vectors, shape (n, 3).
        """
        al = np.asarray(alpha, dtype=float)
        p = self.cone_angle
        return np.stack([np.full_like(al, np.cos(p)), np.sin(p) * np.sin(al), np.sin(p) * np.cos(al)], axis=-1)

    def model(self, alpha) -> SphericalModel:
        """The pin axis line O1 + u·d(α) meets the sphere |A| = R at u > 0:
        u² + 2u (O1·d) + e² - R² = 0; u', u'' from its derivatives; β = azimuth of A
        with analogs from the projection of A, A', A'' on the equator plane.

        Parameters
        ----------
        alpha : float or array_like
            Crank angles α from the middle of the motion (radians).

        Returns
        -------
        SphericalModel
            The contact point A (3-D, with analogs), the pin direction, its distance u, β, γ and the contact
            radii ρ and r.
        """
        al = as_angles(alpha)
        p, e, R = self.cone_angle, self.e, self.R
        sp_ = np.sin(p)
        d = self.pin_direction(al)
        d1 = np.stack([np.zeros_like(al), sp_ * np.cos(al), -sp_ * np.sin(al)], axis=-1)
        d2 = np.stack([np.zeros_like(al), -sp_ * np.sin(al), -sp_ * np.cos(al)], axis=-1)
        o1 = np.array([0.0, 0.0, -e])
        g0, g1, g2 = d @ o1, d1 @ o1, d2 @ o1  # O1·d and its derivatives
        u = -g0 + np.sqrt(g0**2 + R**2 - e**2)
        den = u + g0  # = sqrt(...) > 0 since e < R
        u1 = -u * g1 / den
        u2 = -(u1**2 + 2.0 * u1 * g1 + u * g2) / den
        A = PointPath(o1 + u[:, None] * d, u1[:, None] * d + u[:, None] * d1,
                      u2[:, None] * d + 2.0 * u1[:, None] * d1 + u[:, None] * d2)
        beta = vector_angle(PointPath(A.p[:, :2], A.d[:, :2], A.dd[:, :2]))
        gamma = np.arccos(np.clip(d[:, 2], -1.0, 1.0))
        return SphericalModel(A, d, u, beta, gamma, u * sp_, np.hypot(A.p[:, 0], A.p[:, 1]))

    def force_arms(self, alpha) -> tuple[np.ndarray, np.ndarray]:
        """Moment arms of a unit force normal to the slot (meridian) plane at the contact
        point A, about the wheel axis and about the crank axis, from 3-D cross products.
        By the power balance the crank arm equals r·β' = ρ·cos α·cos β.

        Parameters
        ----------
        alpha : float or array_like
            Crank angles α from the middle of the motion (radians).

        Returns
        -------
        tuple of numpy.ndarray
            The wheel's and the crank's moment arms (length), one per angle.

        Examples
        --------
        >>> import numpy as np
        >>> from mechlab import SphericalGeneva
        >>> g = SphericalGeneva(100, 20, 4)
        >>> [v.round(4) for v in g.force_arms(np.array([0.3]))]
        [array([81.7528]), array([74.1698])]
        """
        m = self.model(alpha)
        A = m.A.p
        n = np.stack([-np.sin(m.beta.theta), np.cos(m.beta.theta), np.zeros_like(m.u)], axis=-1)
        wheel = np.cross(A, n)[:, 2]
        crank = np.cross(A - np.array([0.0, 0.0, -self.e]), n)[:, 0]
        return wheel, -crank

    def seed_c1(self) -> float:
        """C1 = (tg⁻²ψ - R²ρ0⁻² cos²β0)·ρ0/(2e) of seed (10); zero by (3) (0 also for e = 0).

        Returns
        -------
        float
            C1 (≈ 0 up to rounding).
        """
        if self.e == 0:
            return 0.0
        p = self.cone_angle
        return float((1.0 / np.tan(p) ** 2 - self.R**2 * np.cos(self.beta0) ** 2 / self.rho0**2)
                     * self.rho0 / (2.0 * self.e))

    # -- Mechanism protocol --------------------------------------------------------------
    @scalar_law
    def engaged(self, phi) -> np.ndarray:
        """Whether the pin is in a slot at crank angles φ (|α| ≤ α0).

        Parameters
        ----------
        phi : float or array_like
            Crank angles φ (radians).

        Returns
        -------
        numpy.ndarray of bool or bool
            True where the wheel moves.

        Examples
        --------
        >>> import numpy as np
        >>> from mechlab import SphericalGeneva
        >>> g = SphericalGeneva(100, 20, 4)
        >>> bool(g.engaged(0.3)), bool(g.engaged(np.pi))
        (False, True)
        """
        return np.abs(mid_motion_angle(as_angles(phi))) <= self.alpha0

    def motion(self, phi) -> AngularMotion:
        """Wheel angle ψ = β + β0 (0 at φ = 0, +2π/z per turn) with analogs.

        The exact 3-D model while the pin is in a slot, zeros while the wheel stands. ``points`` hold 3-D
        PointPaths: O (sphere centre), O1 (crank axis point on the wheel axis), A (where the pin axis meets the
        sphere; below the equator, i.e. out of the slot, during the dwell), P (pin point at |O1A0| on its axis)
        and B (P's foot on the crank axis).

        Parameters
        ----------
        phi : float or array_like
            Crank angles φ (radians); a scalar gives a motion of scalars.

        Returns
        -------
        AngularMotion
            Joint paths and the output angle ψ with ψ', ψ''.

        Raises
        ------
        DimensionError
            If φ is not a finite real number or array.

        Examples
        --------
        >>> import numpy as np
        >>> from mechlab import SphericalGeneva
        >>> g = SphericalGeneva(100, 20, 4)
        >>> round(float(g.motion(np.pi).psi), 4)  # half-way through the index
        0.7854
        """
        phi = as_angles(phi)
        n = len(phi)
        turns = np.floor(phi / TWO_PI)
        alpha = mid_motion_angle(phi)
        m = self.model(alpha)
        on = np.abs(alpha) <= self.alpha0
        b0 = self.beta0
        local = np.where(on, m.beta.theta + b0, np.where(alpha > 0, 2 * b0, 0.0))
        psi = turns * self.index_angle + local
        dpsi = np.where(on, m.beta.d, 0.0)
        ddpsi = np.where(on, m.beta.dd, 0.0)
        u0 = self.u0
        o1 = np.array([0.0, 0.0, -self.e])
        d = m.d
        sp_ = np.sin(self.cone_angle)
        d1 = np.stack([np.zeros(n), sp_ * np.cos(alpha), -sp_ * np.sin(alpha)], axis=-1)
        d2 = np.stack([np.zeros(n), -sp_ * np.sin(alpha), -sp_ * np.cos(alpha)], axis=-1)
        P = PointPath(o1 + u0 * d, u0 * d1, u0 * d2)
        zero3 = np.zeros((n, 3))
        B = PointPath(np.tile([u0 * np.cos(self.cone_angle), 0.0, -self.e], (n, 1)), zero3, zero3.copy())

        def fixed3(xyz):
            return PointPath(np.tile(xyz, (n, 1)), zero3.copy(), zero3.copy())

        mu = np.full(n, np.pi / 2)
        return AngularMotion(phi, {"O": fixed3([0.0, 0.0, 0.0]), "O1": fixed3(o1), "A": m.A, "P": P, "B": B},
                             mu, psi, dpsi, ddpsi)

    def design(self, unit: str = "mm") -> Table:
        """The design quantities of Vainer & Shatokhina, a :class:`Table` of :class:`Quantity` rows.

        Their names carry their unit (as :meth:`ExternalGeneva.design <mechlab.mechanisms.geneva.PlanarGeneva.design>`).

        Parameters
        ----------
        unit : str, optional
            The unit of R, which every length shares: "mm" (the default), "cm", "m" or "in". Angles are in
            degrees.

        Returns
        -------
        Table
            One Quantity per design quantity (R, e, z, α0, β0, ρ0, ψ, γ0, ρ_H, r_H, pin travel, slot length,
            dwell fraction).

        Examples
        --------
        >>> from mechlab import SphericalGeneva
        >>> g = SphericalGeneva(100, 20, 4)
        >>> round(g.design().by("name")["α0 (deg)"].value, 4)
        74.2068
        """
        unit = check_value("unit", unit, choice(*LENGTH_UNITS))
        mm = f" ({unit})"
        return Table(Quantity(k, v) for k, v in (
            ("R" + mm, self.R), ("e" + mm, self.e), ("z", self.z), ("α0 (deg)", np.degrees(self.alpha0)),
            ("β0 (deg)", np.degrees(self.beta0)), ("ρ0" + mm, self.rho0), ("ψ (deg)", np.degrees(self.cone_angle)),
            ("γ0 (deg)", np.degrees(self.gamma0)), ("ρ_H" + mm, self.rho_H), ("r_H" + mm, self.r_H),
            ("pin travel (ρ_H-ρ0)/sinψ" + mm, self.pin_travel), ("min slot length" + mm, self.min_slot_length),
            ("dwell fraction", self.dwell_fraction)))

