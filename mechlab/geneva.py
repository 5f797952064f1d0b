"""Geneva drives: the planar external and internal Geneva, and the spherical offset
Geneva with perpendicular axes of seed 004 (Vainer & Shatokhina).

Planar Geneva (what every course teaches and seed 004 assumes, its refs. [2], [3])
-------------------------------------------------------------------------------------
Crank pivot O = (0, 0), wheel centre W = (C, 0), crank radius a, z radial slots,
roller (pin) radius r. *Radial entry*: the pin enters a slot moving along it, so
OA ⟂ WA at entry; the right triangle O-A-W with the angle π/z at W gives
``a = C·sin(π/z)`` and ``|WA| = C·cos(π/z)`` (both drives). With λ = sin(π/z) and σ
the crank angle from the middle of the motion, the wheel's angle from the line W→O
(derived from the vector loop A - W, see :meth:`PlanarGeneva.closed_form`) is

* external (κ = -1, the pin on the near side, wheel turns against the crank),
* internal (κ = +1, the pin on the far side, wheel turns with the crank):

    β = κ·atan(λ sin σ / (1 + κλ cos σ)),
    β' = κλ (cos σ + κλ) / D,   β'' = -κλ (1 - λ²) sin σ / D²,   D = 1 + 2κλ cos σ + λ²,

while |σ| ≤ σ0 = π/2 + κπ/z (the pin in a slot); the wheel is locked otherwise.
The crank angle φ of the library is σ + π: φ = 0 is the middle of the dwell.

Spherical offset Geneva (seed 004)
----------------------------------
Sphere (the hemispherical wheel) of radius R about O, wheel axis z, slots in the
meridian planes. The crank axis is the line {y = 0, z = -e} (perpendicular to the
wheel axis, offset e); its point O1 = (0, 0, -e) nearest O lies on the wheel axis.
The pin axis is a generatrix of the cone with apex O1, axis x and half-angle ψ
(seed's ψ, formula (3)): d(α) = (cos ψ, sin ψ sin α, sin ψ cos α), α = 0 at the
crank's lowest position (seed Fig. 2). Because O1 is on the wheel axis, the whole pin
axis lies in the meridian plane of its contact point A = O1 + u·d with the sphere, so
the wheel angle is the azimuth of d:

    tan β = tan ψ · sin α            (equivalent to seed formula (18)),

exactly, for any e. The seed's cos γ = cos α·sin ψ (11) is exact as well: its
"neglected" term C1 of (10) is identically zero by formula (3).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import NamedTuple

import numpy as np

from .errors import DimensionError
from .forces import Drive, DriveError  # noqa: F401  (DriveError re-exported: mechlab.geneva.DriveError)
from .forces import drive as _drive
from .geometry import (AnglePath, PointPath, as_angles, check_length, crank_point, fixed_point, lift,
                       relative, vector_angle)
from .linkages.base import Mechanism
from .motion import AngularMotion

TWO_PI = 2.0 * np.pi


class SlotCountError(DimensionError):
    """The number of slots z is not an integer ≥ 3."""


class OffsetError(DimensionError):
    """The spherical Geneva's offset e does not satisfy 0 ≤ e < R."""


def check_slots(z) -> int:
    """z as an int, raising SlotCountError unless it is a whole number ≥ 3."""
    try:
        zf = float(z)
    except (TypeError, ValueError):
        raise SlotCountError(f"the number of slots z must be a whole number ≥ 3, got {z!r}") from None
    if not np.isfinite(zf) or zf != round(zf) or zf < 3:
        raise SlotCountError(
            f"the number of slots z must be a whole number ≥ 3, got z = {zf:g} "
            f"(a Geneva wheel needs z ≥ 3: with z = 2 the crank radius C·sin(π/z) equals C)")
    return int(round(zf))


def mid_motion_angle(phi) -> np.ndarray:
    """σ = φ - π reduced to [-π, π) turn by turn (0 in the middle of the motion)."""
    phi = np.asarray(phi, dtype=float)
    return phi - TWO_PI * np.floor(phi / TWO_PI) - np.pi


def impact_kind(velocity_jump: float, acceleration_jump: float, tol: float = 1e-9) -> str:
    """'hard' for a jump in velocity (theoretically unbounded acceleration), 'soft'
    for a finite jump in acceleration only, 'none' for continuous analogs."""
    if abs(velocity_jump) > tol:
        return "hard"
    if abs(acceleration_jump) > tol:
        return "soft"
    return "none"


class Impact(NamedTuple):
    """Jumps of ψ' and ψ'' (output analogs) where the pin enters and leaves a slot."""

    entry_velocity_jump: float
    entry_acceleration_jump: float
    exit_velocity_jump: float
    exit_acceleration_jump: float

    @property
    def kind(self) -> str:
        return max((impact_kind(self.entry_velocity_jump, self.entry_acceleration_jump),
                    impact_kind(self.exit_velocity_jump, self.exit_acceleration_jump)),
                   key=("none", "soft", "hard").index)


# ----------------------------------------------------------------------------------
# planar Geneva
# ----------------------------------------------------------------------------------
@dataclass(frozen=True)
class PlanarGeneva(Mechanism):
    """Common part of :class:`ExternalGeneva` and :class:`InternalGeneva` (κ = ∓1).

    ``z`` slots, centre distance ``centre_distance`` = C (O to W), roller radius
    ``roller_radius`` (default 0.15·a). Raises SlotCountError for z < 3 and
    DimensionError for negative sizes or a roller that does not fit (see
    :meth:`_check_roller`).
    """

    z: int
    centre_distance: float
    roller_radius: float | None = None

    kappa = 0  # -1 external, +1 internal
    links = (("O", "A"),)
    pivots = ("O", "W")
    output = "angle"

    def __post_init__(self):
        if self.kappa not in (-1, 1):
            raise TypeError("PlanarGeneva is the common base: use ExternalGeneva or InternalGeneva")
        object.__setattr__(self, "z", check_slots(self.z))
        object.__setattr__(self, "centre_distance", check_length("centre_distance", self.centre_distance))
        r = 0.15 * self.crank_radius if self.roller_radius is None else self.roller_radius
        object.__setattr__(self, "roller_radius", check_length("roller_radius", r))
        self._check_roller()

    # -- dimensions -----------------------------------------------------------------
    @property
    def lam(self) -> float:
        """λ = a / C = sin(π/z) (radial entry)."""
        return float(np.sin(np.pi / self.z))

    @property
    def crank_radius(self) -> float:
        """a = C·sin(π/z): OA ⟂ WA at entry, angle π/z at W."""
        return self.centre_distance * self.lam

    @property
    def entry_radius(self) -> float:
        """|WA| at entry and exit = C·cos(π/z) (the wheel radius to the pin centre)."""
        return self.centre_distance * float(np.cos(np.pi / self.z))

    @property
    def index_angle(self) -> float:
        """Wheel turn per crank turn, 2π/z, signed: negative for the external drive."""
        return self.kappa * TWO_PI / self.z

    @property
    def engagement_half_angle(self) -> float:
        """σ0 = π/2 + κπ/z: the pin is in a slot for |σ| ≤ σ0."""
        return np.pi / 2 + self.kappa * np.pi / self.z

    @property
    def dwell_fraction(self) -> float:
        """Fraction of the crank turn with the wheel locked: 1/2 - κ/z."""
        return 1.0 - self.engagement_half_angle / np.pi

    @property
    def motion_fraction(self) -> float:
        return 1.0 - self.dwell_fraction

    # -- closed forms -----------------------------------------------------------------
    def closed_form(self, sigma) -> AnglePath:
        """β, β', β'' (wheel angle from the line W→O) at crank angles σ from the middle
        of the motion, from the vector loop A - W (formulas in the module docstring).
        Valid while engaged, |σ| ≤ σ0."""
        s = np.asarray(sigma, dtype=float)
        k, lam = self.kappa, self.lam
        D = 1.0 + 2.0 * k * lam * np.cos(s) + lam**2
        beta = k * np.arctan2(lam * np.sin(s), 1.0 + k * lam * np.cos(s))
        return AnglePath(beta, k * lam * (np.cos(s) + k * lam) / D, -k * lam * (1.0 - lam**2) * np.sin(s) / D**2)

    def max_velocity(self) -> float:
        """max |ψ'| = λ/(1 + κλ), at σ = 0 (the pin on the line of centres)."""
        return self.lam / (1.0 + self.kappa * self.lam)

    def acceleration_peak_sigma(self) -> float:
        """σ ≥ 0 of the largest |ψ''| while engaged.

        External: d/dσ (sin σ / D²) = 0 gives 2λ cos²σ + (1 + λ²) cos σ - 4λ = 0 (inside the
        engagement for every z ≥ 3). Internal: |ψ''| grows up to the entry, so σ0.
        """
        lam = self.lam
        if self.kappa < 0:
            b = 1.0 + lam**2
            c = (-b + np.sqrt(b * b + 32.0 * lam**2)) / (4.0 * lam)
            return float(min(np.arccos(c), self.engagement_half_angle))
        return self.engagement_half_angle

    def max_acceleration(self) -> float:
        """max |ψ''| while engaged (closed form at :meth:`acceleration_peak_sigma`)."""
        return float(abs(self.closed_form(self.acceleration_peak_sigma()).dd))

    def entry_acceleration(self) -> float:
        """|ψ''| just after entry = tan(π/z) (both drives): the jump from the locked 0."""
        return float(np.tan(np.pi / self.z))

    def impacts(self) -> Impact:
        """Exact jumps at entry (σ = -σ0) and exit (σ = +σ0): ψ' = 0 there (radial
        entry), ψ'' jumps by ±tan(π/z) — a soft impact."""
        s0 = self.engagement_half_angle
        a, b = self.closed_form(-s0), self.closed_form(s0)
        return Impact(float(a.d), float(a.dd), float(-b.d), float(-b.dd))

    # -- sizes for drawing and design ---------------------------------------------------
    @property
    def slot_bottom(self) -> float:
        """Distance from W of the slot bottom's centre: the pin centre's extreme C ∓ a."""
        return self.centre_distance + self.kappa * self.crank_radius

    def _check_roller(self):
        a, r, b = self.crank_radius, self.roller_radius, self.entry_radius
        gap = b * np.sin(np.pi / self.z)  # half the chord between neighbouring slot mouths
        if r >= min(0.5 * a, gap):
            raise DimensionError(
                f"roller_radius = {r:g} is too large: it must be < min(a/2, C·cos(π/z)·sin(π/z)) = "
                f"min({0.5 * a:.6g}, {gap:.6g}) so that the slots fit between each other and the crank hub")

    # -- motion -------------------------------------------------------------------------
    def _pin(self, phi) -> PointPath:
        # φ = 0 mid-dwell: the external pin then points away from W (A = -a u(φ)),
        # the internal pin towards it (A = a u(φ)); σ = φ - π in both.
        return crank_point(self.crank_radius, phi if self.kappa > 0 else phi + np.pi)

    def motion(self, phi) -> AngularMotion:
        """Wheel angle ψ (0 at φ = 0, κ·2π/z more after each turn) and its analogs.

        Positions and analogs from the vector A - W (geometry.vector_angle) while the
        pin is in a slot, exact zeros while locked; ψ accumulates over several turns.
        """
        phi = as_angles(phi)
        n = len(phi)
        turns = np.floor(phi / TWO_PI)
        sigma = mid_motion_angle(phi)
        s0 = self.engagement_half_angle
        A = self._pin(phi)
        W = fixed_point((self.centre_distance, 0.0), n)
        ang = vector_angle(relative(A, W))
        beta = lift(ang.theta, np.pi) - np.pi
        on = np.abs(sigma) <= s0
        local = np.where(on, beta + self.kappa * np.pi / self.z, np.where(sigma > 0, self.index_angle, 0.0))
        psi = turns * self.index_angle + local
        dpsi = np.where(on, ang.d, 0.0)
        ddpsi = np.where(on, ang.dd, 0.0)
        # the pin pushes along the slot's normal, which is the wheel point's direction of motion
        mu = np.full(n, np.pi / 2)
        return AngularMotion(phi, {"O": fixed_point((0.0, 0.0), n), "A": A, "W": W}, mu, psi, dpsi, ddpsi)

    def engaged(self, phi) -> np.ndarray:
        """True where the pin is in a slot."""
        return np.abs(mid_motion_angle(as_angles(phi))) <= self.engagement_half_angle

    def design(self) -> dict:
        """The main sizes (lengths in the unit of C, angles in degrees)."""
        return {"z": self.z, "C": self.centre_distance, "crank radius a": self.crank_radius,
                "pin radius at entry |WA|": self.entry_radius, "roller radius": self.roller_radius,
                "slot bottom from W": self.slot_bottom, "slot length": self.slot_length,
                "dwell fraction": self.dwell_fraction, "index angle (deg)": np.degrees(abs(self.index_angle)),
                "max |ψ'|": self.max_velocity(), "max |ψ''|": self.max_acceleration()}


@dataclass(frozen=True)
class ExternalGeneva(PlanarGeneva):
    """External Geneva: the pin on the near side of O, the wheel turns against the crank.

    a = C sin(π/z), wheel (entry) radius C cos(π/z), outer radius sqrt(C²cos²(π/z) + r²)
    (the slot corners touch the roller at entry), locking disc radius a - 1.5·r.
    Dwell fraction 1/2 + 1/z; max |ψ'| = λ/(1 - λ); |ψ''| jumps by tan(π/z) at entry.
    """

    kappa = -1

    @property
    def outer_radius(self) -> float:
        """sqrt(C² cos²(π/z) + r²): the slot corners touch the roller at entry."""
        return float(np.hypot(self.entry_radius, self.roller_radius))

    @property
    def slot_length(self) -> float:
        """From the rim to the slot's bottom: outer radius - (C - a - r)."""
        return self.outer_radius - (self.slot_bottom - self.roller_radius)

    @property
    def locking_radius(self) -> float:
        """Radius of the crank's locking disc, a - 1.5 r (the usual design rule: the
        roller clears it by half its radius). The wheel's concave locking arcs have this
        radius, centred at distance C from W on the bisectors between slots."""
        return self.crank_radius - 1.5 * self.roller_radius


@dataclass(frozen=True)
class InternalGeneva(PlanarGeneva):
    """Internal Geneva: the pin on the far side of O, wheel and crank turn the same way.

    a = C sin(π/z), slot mouths at C cos(π/z) from W, slot bottoms at C + a. Dwell
    fraction 1/2 - 1/z; max |ψ'| = λ/(1 + λ) at mid-motion; |ψ''| is largest at entry
    and exit, tan(π/z).
    """

    kappa = +1

    @property
    def inner_radius(self) -> float:
        """The ring's inner rim, where the slot walls end: sqrt(C²cos²(π/z) - r²)."""
        return float(np.sqrt(self.entry_radius**2 - self.roller_radius**2))

    @property
    def outer_radius(self) -> float:
        """The ring's outer rim, drawn 1.5 r beyond the slot bottoms (a drawing choice, not a design rule)."""
        return self.slot_bottom + 2.5 * self.roller_radius

    @property
    def slot_length(self) -> float:
        """From the inner rim to the slot's bottom: C + a + r - inner radius."""
        return self.slot_bottom + self.roller_radius - self.inner_radius


# ----------------------------------------------------------------------------------
# spherical offset Geneva (seed 004)
# ----------------------------------------------------------------------------------
class SphericalModel(NamedTuple):
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


@dataclass(frozen=True)
class SphericalGeneva(Mechanism):
    """Hemispherical Geneva with perpendicular axes and offset e (seed 004).

    ``R`` sphere radius, ``e`` offset of the crank axis from the sphere's centre
    (0 ≤ e < R), ``z`` slots, ``pin_diameter`` d (seed Table 1: R = 40, e = 15, d = 10 mm).
    Design (seed formulas (1)-(9)): β0 = π/z, ρ0 = sqrt(e² + R² sin²β0) (1),
    α0 = arccos(e/ρ0) (2), ψ = atan(ρ0/(R cos β0)) (3), γ0 = atan(R/e) (4).
    The crank angle of the library is φ = α + π (φ = 0 mid-dwell); ψ (output) = β + β0
    while |α| ≤ α0.
    """

    R: float
    e: float
    z: int
    pin_diameter: float = 10.0

    links = (("B", "P"),)
    pivots = ("O", "O1")
    output = "angle"

    def __post_init__(self):
        object.__setattr__(self, "z", check_slots(self.z))
        object.__setattr__(self, "R", check_length("R", self.R))
        object.__setattr__(self, "e", check_length("e", self.e, allow_zero=True))
        object.__setattr__(self, "pin_diameter", check_length("pin_diameter", self.pin_diameter))
        if self.e >= self.R:
            raise OffsetError(f"the offset must satisfy e < R (the crank axis passes inside the sphere), "
                              f"got e = {self.e:g} ≥ R = {self.R:g}")
        if self.pin_diameter >= self.min_slot_length:
            raise DimensionError(f"pin_diameter = {self.pin_diameter:g} must be smaller than the slot's working "
                                 f"arc R·(π/2 - arcsin(r_H/R)) = {self.min_slot_length - self.pin_diameter / 2:.6g}")

    # -- design (seed 004, formulas (1)-(9)) ------------------------------------------
    @property
    def k(self) -> float:
        """k = e/R (seed, after (5))."""
        return self.e / self.R

    @property
    def beta0(self) -> float:
        """Half the index angle, π/z (seed Table 1: 60°, 45°, 36°, 30°, 22.5°)."""
        return np.pi / self.z

    @property
    def rho0(self) -> float:
        """ρ0 = sqrt(e² + R² sin²β0): radius of the entry point A0 about the crank axis (1)."""
        return float(np.hypot(self.e, self.R * np.sin(self.beta0)))

    @property
    def alpha0(self) -> float:
        """α0 = arccos(e/ρ0) (2): the crank angle at entry; sin β0 = (e/R) tan α0 (5)."""
        return float(np.arccos(self.e / self.rho0))

    @property
    def cone_angle(self) -> float:
        """The seed's ψ = atan(ρ0/(R cos β0)) (3): half-angle of the pin axis' cone about the crank axis."""
        return float(np.arctan2(self.rho0, self.R * np.cos(self.beta0)))

    @property
    def gamma0(self) -> float:
        """γ0 = atan(R/e) (4): angle between O1A0 and the wheel axis at entry (A0 on the equator)."""
        return float(np.arctan2(self.R, self.e))

    @property
    def a2(self) -> float:
        """a² = 1/sin²ψ (seed, after (18))."""
        return 1.0 / np.sin(self.cone_angle) ** 2

    @property
    def u0(self) -> float:
        """|O1A0| = ρ0/sin ψ = sqrt(R² + e²)."""
        return self.rho0 / np.sin(self.cone_angle)

    @property
    def u_H(self) -> float:
        """|O1A_H| at α = 0: e sin ψ + R sqrt(1 - k² cos²ψ) (root of U² - 2eU sin ψ - (R² - e²) = 0)."""
        p = self.cone_angle
        return float(self.e * np.sin(p) + self.R * np.sqrt(1.0 - self.k**2 * np.cos(p) ** 2))

    @property
    def rho_H(self) -> float:
        """ρ_H = |O1A_H| sin ψ (6): contact radius about the crank axis in the lowest position."""
        return self.u_H * np.sin(self.cone_angle)

    @property
    def r_H(self) -> float:
        """r_H = |O1A_H| cos ψ = ρ_H / tan ψ (7), (8): contact radius about the wheel axis."""
        return self.u_H * np.cos(self.cone_angle)

    @property
    def pin_travel(self) -> float:
        """(ρ_H - ρ0)/sin ψ = |O1A_H| - |O1A0|: how far the contact runs along the pin."""
        return (self.rho_H - self.rho0) / np.sin(self.cone_angle)

    def pin_length(self, wall: float, allowance: float = 6.5) -> float:
        """Crank-pin length (9): (ρ_H - ρ0)/sin ψ + δ + (5…8) mm, δ the slot wall
        thickness, ``allowance`` in [5, 8] mm (2…3 mm inside plus 3…5 mm outside)."""
        wall = check_length("wall", wall)
        if not 5.0 <= allowance <= 8.0:
            raise DimensionError(f"the pin-length allowance must be within [5, 8] mm (seed formula (9)), got {allowance:g}")
        return self.pin_travel + wall + allowance

    @property
    def min_slot_length(self) -> float:
        """L = R·∠A_H O G + d/2 with ∠A_H O G = π/2 - arcsin(r_H/R): the meridian arc from
        the equator (entry) to the highest contact point A_H, plus half the pin."""
        return self.R * (np.pi / 2 - np.arcsin(self.r_H / self.R)) + self.pin_diameter / 2

    @property
    def dwell_fraction(self) -> float:
        """1 - α0/π: the pin is in a slot for |α| ≤ α0."""
        return 1.0 - self.alpha0 / np.pi

    @property
    def index_angle(self) -> float:
        return TWO_PI / self.z

    @property
    def engagement_half_angle(self) -> float:
        """α0: the pin is in a slot for |α| ≤ α0 (same name as the planar drives)."""
        return self.alpha0

    # -- closed forms (seed (16)-(22)) ------------------------------------------------
    def position(self, alpha) -> AnglePath:
        """β(α) = arcsin(sin α / sqrt(a² - cos²α)) (18), β' (19) and β'' (20) (per ω1, ω1²)."""
        al = np.asarray(alpha, dtype=float)
        a2 = self.a2
        q = a2 - np.cos(al) ** 2
        s = np.sqrt(a2 - 1.0)
        beta = np.arcsin(np.sin(al) / np.sqrt(q))
        return AnglePath(beta, s * np.cos(al) / q, -s * (a2 + np.cos(al) ** 2) * np.sin(al) / q**2)

    def max_velocity(self) -> float:
        """ω_max/ω1 = 1/sqrt(a² - 1) = tan ψ at α = 0 (seed (21), printed as ε)."""
        return float(1.0 / np.sqrt(self.a2 - 1.0))

    def acceleration_extreme_alpha(self) -> float:
        """α1 ∈ [0, π/2] of the largest |ε| of (20): sin²α1 = 3a² - sqrt(8a⁴ + 1) (22),
        the root of sin⁴α - 6a² sin²α + a⁴ - 1 = 0 below 1. It may lie beyond α0, where
        the wheel no longer moves. For a² ≥ 6 (ψ ≤ 24.09°) the root is ≥ 1: there is no
        interior extreme and |ε| grows up to α = π/2, returned then."""
        a2 = self.a2
        s2 = 3.0 * a2 - np.sqrt(8.0 * a2 * a2 + 1.0)
        return float(np.arcsin(np.sqrt(s2))) if s2 < 1.0 else np.pi / 2

    def max_acceleration(self) -> tuple[float, float]:
        """(|ε|max/ω1², α where reached) while the wheel moves (|α| ≤ α0): at α1 if
        α1 ≤ α0, else at the entry α0 (|ε| increases all the way to α0)."""
        al = min(self.acceleration_extreme_alpha(), self.alpha0)
        return float(abs(self.position(al).dd)), al

    def entry_velocity(self) -> float:
        """β'(α0) = sin ψ cos ψ cos α0 / (1 - sin²ψ cos²α0), which by (1)-(3)
        (sin ψ = ρ0/sqrt(R² + e²), cos α0 = e/ρ0) is k·cos β0 = (e/R)·cos(π/z): zero only for e = 0."""
        return float(self.position(self.alpha0).d)

    def impacts(self) -> Impact:
        """Jumps at entry (α = -α0) and exit (α0): ψ' jumps from 0 to β'(α0) > 0 for
        e > 0 — a hard impact; for e = 0 (α0 = 90°) only ψ'' jumps — soft."""
        a, b = self.position(-self.alpha0), self.position(self.alpha0)
        return Impact(float(a.d), float(a.dd), float(-b.d), float(-b.dd))

    # -- exact 3-D model --------------------------------------------------------------
    def pin_direction(self, alpha) -> np.ndarray:
        """Unit vector of the pin axis on its cone: (cos ψ, sin ψ sin α, sin ψ cos α)."""
        al = np.asarray(alpha, dtype=float)
        p = self.cone_angle
        return np.stack([np.full_like(al, np.cos(p)), np.sin(p) * np.sin(al), np.sin(p) * np.cos(al)], axis=-1)

    def model(self, alpha) -> SphericalModel:
        """The pin axis line O1 + u·d(α) meets the sphere |A| = R at u > 0:
        u² + 2u (O1·d) + e² - R² = 0; u', u'' from its derivatives; β = azimuth of A
        with analogs from the projection of A, A', A'' on the equator plane."""
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
        By the power balance the crank arm equals r·β' = ρ·cos α·cos β."""
        m = self.model(alpha)
        A = m.A.p
        n = np.stack([-np.sin(m.beta.theta), np.cos(m.beta.theta), np.zeros_like(m.u)], axis=-1)
        wheel = np.cross(A, n)[:, 2]
        crank = np.cross(A - np.array([0.0, 0.0, -self.e]), n)[:, 0]
        return wheel, -crank

    def seed_c1(self) -> float:
        """C1 = (tg⁻²ψ - R²ρ0⁻² cos²β0)·ρ0/(2e) of seed (10); zero by (3) (0 also for e = 0)."""
        if self.e == 0:
            return 0.0
        p = self.cone_angle
        return float((1.0 / np.tan(p) ** 2 - self.R**2 * np.cos(self.beta0) ** 2 / self.rho0**2)
                     * self.rho0 / (2.0 * self.e))

    # -- Mechanism protocol --------------------------------------------------------------
    def engaged(self, phi) -> np.ndarray:
        return np.abs(mid_motion_angle(as_angles(phi))) <= self.alpha0

    def motion(self, phi) -> AngularMotion:
        """Wheel angle ψ = β + β0 (0 at φ = 0, +2π/z per turn) with analogs: the exact
        3-D model while the pin is in a slot, zeros while the wheel stands.

        ``points`` hold 3-D PointPaths: O (sphere centre), O1 (crank axis point on the
        wheel axis), A (where the pin axis meets the sphere; below the equator, i.e.
        out of the slot, during the dwell), P (pin point at |O1A0| on its axis) and B
        (P's foot on the crank axis).
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

    def design(self) -> dict:
        """Seed 004's design quantities (mm, degrees)."""
        return {"R": self.R, "e": self.e, "z": self.z, "α0 (deg)": np.degrees(self.alpha0),
                "β0 (deg)": np.degrees(self.beta0), "ρ0": self.rho0, "ψ (deg)": np.degrees(self.cone_angle),
                "γ0 (deg)": np.degrees(self.gamma0), "ρ_H": self.rho_H, "r_H": self.r_H,
                "pin travel (ρ_H-ρ0)/sinψ": self.pin_travel, "min slot length": self.min_slot_length,
                "dwell fraction": self.dwell_fraction}


def spherical_table(R: float, e: float, z_values, pin_diameter: float = 10.0) -> list[dict]:
    """Seed 004 Table 1, recomputed: per z, α0 and β0 (deg), ω_max/ω1, the largest
    |ε|/ω1² while the wheel moves (|α| ≤ α0), and α1, β1 (deg) where it is reached."""
    rows = []
    for z in z_values:
        g = SphericalGeneva(R, e, z, pin_diameter)
        eps, al = g.max_acceleration()
        rows.append({"z": g.z, "alpha0": float(np.degrees(g.alpha0)), "beta0": float(np.degrees(g.beta0)),
                     "omega_max": g.max_velocity(), "eps_max": eps, "alpha1": float(np.degrees(al)),
                     "beta1": float(np.degrees(g.position(al).theta))})
    return rows


# Seed 004, Table 1 as printed (R = 40 mm, e = 15 mm, d = 10 mm).
TABLE1_PRINTED = {
    3: {"alpha0": 66.60, "beta0": 60.0, "omega_max": 1.89, "eps_max": 2.51, "alpha1": 16.40, "beta1": 27.80},
    4: {"alpha0": 62.06, "beta0": 45.0, "omega_max": 1.13, "eps_max": 1.06, "alpha1": 27.26, "beta1": 27.56},
    5: {"alpha0": 57.46, "beta0": 36.0, "omega_max": 0.86, "eps_max": 0.71, "alpha1": 34.96, "beta1": 26.22},
    6: {"alpha0": 53.15, "beta0": 30.0, "omega_max": 0.72, "eps_max": 0.57, "alpha1": 41.60, "beta1": 25.38},
    8: {"alpha0": 45.58, "beta0": 22.5, "omega_max": 0.58, "eps_max": 0.46, "alpha1": 52.93, "beta1": 24.85},
}
TABLE1_COLUMNS = ("alpha0", "beta0", "omega_max", "eps_max", "alpha1", "beta1")


class Cell(NamedTuple):
    """One cell of Table 1: ``status`` is "agrees" (the computed value rounds to the
    printed one), "last digit" (off by at most 1.5 units of the printed last digit,
    0.01) or "differs"."""

    z: int
    column: str
    printed: float
    computed: float
    status: str

    @property
    def agrees(self) -> bool:
        return self.status == "agrees"


def table1_comparison(R: float = 40.0, e: float = 15.0) -> list[Cell]:
    """Every cell of seed 004's Table 1 (:data:`TABLE1_PRINTED`, two decimals printed)
    against :func:`spherical_table`."""
    rows = {r["z"]: r for r in spherical_table(R, e, sorted(TABLE1_PRINTED))}
    out = []
    for z, printed in TABLE1_PRINTED.items():
        for col in TABLE1_COLUMNS:
            p, c = printed[col], float(rows[z][col])
            diff = abs(p - c)
            status = "agrees" if diff <= 0.005 + 1e-12 else "last digit" if diff <= 0.015 else "differs"
            out.append(Cell(z, col, p, c, status))
    return out


# ----------------------------------------------------------------------------------
# drive: crank torque from the power balance (seed 004, last section)
# ----------------------------------------------------------------------------------
def crank_torque(mechanism, phi, *, inertia: float, omega1: float, resisting_torque: float = 0.0) -> np.ndarray:
    """Crank torque M1(φ) of a Geneva drive at constant crank speed ω1, from the power balance.

    Wheel side (seed 004, last section): the moment of inertia J (``inertia``, reduced to
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


def drive(mechanism, *, inertia: float, omega1: float, resisting_torque: float = 0.0,
          efficiency: float = 1.0, overload: float = 2.0, n: int = 7201) -> Drive:
    """The motor of a Geneva drive: :func:`crank_torque` sampled by :func:`drive_angles`
    (n samples while the wheel moves, the engagement ends resolved), then the course's one rule,
    :func:`mechlab.forces.drive` (motor torque M1/η where it drives and M1·η where the
    wheel drives the crank back; mean power; nominal torque max(rms, peak/k))."""
    phi = drive_angles(mechanism, n)
    M1 = crank_torque(mechanism, phi, inertia=inertia, omega1=omega1, resisting_torque=resisting_torque)
    return _drive(M1, phi, omega1, overload=overload, efficiency=efficiency)


# ----------------------------------------------------------------------------------
# comparison of intermittent-motion mechanisms
# ----------------------------------------------------------------------------------
def _max_jump(mechanism, n: int, phase: float = 0.0):
    phi = phase + np.linspace(0.0, TWO_PI, n + 1)
    mo = mechanism.motion(phi)
    return float(np.max(np.abs(np.diff(mo.dpsi)))), float(np.max(np.abs(np.diff(mo.ddpsi))))


def detect_impacts(mechanism, n: int = 4096, phase: float = 0.0) -> str:
    """'hard', 'soft' or 'none', found numerically for any angular-output mechanism:
    the largest change of ψ' (ψ'') between neighbouring samples halves when the grid is
    refined if ψ' (ψ'') is continuous, and stays put where it jumps. The grid starts at
    ``phase`` (to avoid a crank angle where a mechanism cannot be evaluated)."""
    v1, a1 = _max_jump(mechanism, n, phase)
    v2, a2 = _max_jump(mechanism, 2 * n, phase)
    if v2 > 0.75 * v1 and v1 > 1e-12:
        return "hard"
    if a2 > 0.75 * a1 and a1 > 1e-12:
        return "soft"
    return "none"


def intermittency(mechanism, *, n: int = 7201, dwell_tol: float = 1e-9, phase: float = 0.0) -> dict:
    """Invariants of one crank turn: dwell fraction (share of φ with |ψ'| ≤ dwell_tol·max|ψ'|),
    output turn Δψ per crank turn, max |ψ'| and |ψ''|, and the dimensionless invariants
    C_v = max|ψ'|·Φ/|Δψ| and C_a = max|ψ''|·Φ²/|Δψ| with Φ = (1 - dwell)·2π the crank
    angle of the motion: the cam-law coefficients (cycloidal law: C_v = 2, C_a = 2π).
    An approximate dwell (a linkage's) needs a larger ``dwell_tol``; the samples start at
    ``phase``."""
    phi = phase + np.linspace(0.0, TWO_PI, n)
    mo = mechanism.motion(phi)
    vmax = float(np.max(np.abs(mo.dpsi)))
    still = np.abs(mo.dpsi) <= dwell_tol * vmax
    dwell = float(np.mean(still[:-1]))
    dpsi_turn = float(mo.psi[-1] - mo.psi[0])
    amax = float(np.max(np.abs(mo.ddpsi)))
    Phi = (1.0 - dwell) * TWO_PI
    return {"dwell_fraction": dwell, "index_deg": float(np.degrees(abs(dpsi_turn))), "max_dpsi": vmax,
            "max_ddpsi": amax, "Cv": vmax * Phi / abs(dpsi_turn), "Ca": amax * Phi**2 / abs(dpsi_turn),
            "impact": detect_impacts(mechanism, phase=phase)}


def compare(mechanisms: dict, **kw) -> list[dict]:
    """:func:`intermittency` of each named mechanism, one row each."""
    return [{"name": name, **intermittency(m, **kw)} for name, m in mechanisms.items()]
