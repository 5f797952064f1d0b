"""The two mechanisms of seed 002 §7.2 that are not in :mod:`mechlab.linkages`.

* :class:`EllipticTrammel` — a rod AB whose ends slide on two straight guides crossing
  at O at the angle β (seed 002, Fig. 7.5; β = 90° in Fig. 7.6), driven here by Cardan's
  crank O-C, C being the centre of the rod's moving centrode (the circumcentre of
  triangle OAB), so that the crank angle φ is a full-turn input.
* :class:`Antiparallelogram` — the crossed four-bar whose opposite links are equal
  (seed 002, Fig. 7.7), followed on its crossed branch through both change points.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import DimensionError
from ..geometry import PointPath, as_angles, check_length, dot, fixed_point, unit
from ..linkages.base import Mechanism
from ..linkages.fourbar import FourBar
from ..motion import AngularMotion, LinearMotion

# Guides closer than this to parallel (radians) are rejected: the rod could not move.
_MIN_GUIDE_ANGLE = 1e-6


@dataclass(frozen=True)
class EllipticTrammel(Mechanism):
    """Rod A-B of length ``rod``; A slides on the x axis, B on the line through O at angle ``beta``.

    Derivation (seed 002, Fig. 7.5, derived anew): the normals to the guides at A and B
    meet at the rod's instantaneous centre P, so O, A, P, B lie on the circle with
    diameter OP = rod / sin β (angle AOB = β subtends the chord AB = rod). That circle's
    centre C = P/2 is fixed to the rod, and |OC| = r = rod / (2 sin β): a crank O-C of
    radius r drives the rod (Cardan's drive; the crank adds a redundant but consistent
    constraint). With φ the crank angle, P = 2r·(cos φ, sin φ), and the feet of P on
    the guides are

        A = 2r cos φ · (1, 0),    B = 2r cos(φ - β) · (cos β, sin β),

    the rod's angle is θ = π/2 + β - φ (θ' = -1: the small circle rolls inside the big
    one and turns backwards at the crank's rate). Output: s = x_A = 2r cos φ.
    """

    rod: float
    beta: float = np.pi / 2

    links = (("O", "C"), ("A", "B"), ("B", "C"), ("C", "A"))
    pivots = ("O",)
    output = "position"

    def __post_init__(self):
        object.__setattr__(self, "rod", check_length("rod", self.rod))
        b = float(self.beta)
        if not (np.isfinite(b) and _MIN_GUIDE_ANGLE < b < np.pi - _MIN_GUIDE_ANGLE):
            raise DimensionError(
                f"the angle between the guides must satisfy 0 < β < 180°, got β = {np.degrees(b):.6g}°: "
                f"parallel guides leave no room for the rod to turn")
        object.__setattr__(self, "beta", b)

    @property
    def crank(self) -> float:
        """Radius of the Cardan crank O-C: rod / (2 sin β), the moving centrode's radius."""
        return self.rod / (2.0 * np.sin(self.beta))

    @property
    def fixed_radius(self) -> float:
        """Radius of the fixed centrode (centre O): rod / sin β (seed 002, formula (7.12))."""
        return self.rod / np.sin(self.beta)

    def rod_angle(self, phi) -> np.ndarray:
        """Angle θ of the rod A→B at crank angles φ: θ = π/2 + β - φ."""
        return np.pi / 2 + self.beta - as_angles(phi)

    def motion(self, phi) -> LinearMotion:
        """Paths of O, C, A, B and the slider law s = x_A, s', s'' at crank angles φ (rad)."""
        phi = as_angles(phi)
        n = len(phi)
        d = 2.0 * self.crank
        u = unit(phi)
        C = PointPath(self.crank * u, self.crank * np.stack([-u[:, 1], u[:, 0]], -1), -self.crank * u)
        ex = np.array([1.0, 0.0])
        ub = unit(self.beta)
        c0, s0 = np.cos(phi), np.sin(phi)
        cb, sb = np.cos(phi - self.beta), np.sin(phi - self.beta)
        A = PointPath(d * c0[:, None] * ex, -d * s0[:, None] * ex, -d * c0[:, None] * ex)
        B = PointPath(d * cb[:, None] * ub, -d * sb[:, None] * ub, -d * cb[:, None] * ub)
        # transmission: between the rod and the normal to A's guide (as for a slider-crank)
        rod = B.p - A.p
        mu = np.pi / 2 - np.arcsin(np.clip(np.abs(rod[:, 1]) / self.rod, 0.0, 1.0))
        return LinearMotion(phi, {"O": fixed_point((0.0, 0.0), n), "C": C, "A": A, "B": B}, mu,
                            A.p[:, 0].copy(), A.d[:, 0].copy(), A.dd[:, 0].copy())


@dataclass(frozen=True)
class Antiparallelogram(Mechanism):
    """Crossed four-bar O-A-B-E with crank OA = rocker EB = ``crank`` and coupler AB = frame OE = ``ground``.

    A four-bar with s + l = p + q is a change-point linkage: at φ = 0 and φ = π all four
    joints lie on the frame line and the loop may continue as a parallelogram (ψ = φ) or
    as the crossed antiparallelogram. :class:`~mechlab.FourBar` with a fixed assembly
    sign cannot follow the crossed branch: it is ``assembly = -1`` on 0 < φ < π and
    ``+1`` on π < φ < 2π (tests), and FourBar refuses φ = 0, π. This class follows the
    crossed branch analytically through both change points. Derivation (sympy in the
    tests and notebook 04): with k = (crank + ground)/(crank - ground),

        tan(ψ/2) = k·tan(φ/2),   ψ' = 2k / ((1 + k²) + (1 - k²) cos φ),
        ψ'' = 2k(1 - k²) sin φ / ((1 + k²) + (1 - k²) cos φ)².

    ground < crank (k > 1): both long links turn fully in the same sense (short frame);
    ground > crank (k < -1): both short links turn fully in opposite senses (long frame).
    """

    crank: float
    ground: float

    links = (("O", "A"), ("A", "B"), ("B", "E"))
    pivots = ("O", "E")
    output = "angle"

    def __post_init__(self):
        object.__setattr__(self, "crank", check_length("crank", self.crank))
        object.__setattr__(self, "ground", check_length("ground", self.ground))
        if abs(self.crank - self.ground) <= 1e-9 * max(self.crank, self.ground):
            raise DimensionError(
                f"crank = ground = {self.crank:g}: all four links equal (a rhombus), the crossed branch "
                f"degenerates (the rocker folds onto the frame); take crank ≠ ground")

    @property
    def coupler(self) -> float:
        return self.ground

    @property
    def rocker(self) -> float:
        return self.crank

    @property
    def k(self) -> float:
        """k = (crank + ground)/(crank - ground), the ratio in tan(ψ/2) = k·tan(φ/2)."""
        return (self.crank + self.ground) / (self.crank - self.ground)

    def change_points(self) -> tuple[float, float]:
        """Crank angles (rad) where the linkage folds flat: 0 and π."""
        return (0.0, np.pi)

    def cycle(self, n: int = 361) -> np.ndarray:
        """n crank angles over a full turn, shifted by 0.37 of a step so that no sample falls
        on a change point (0 or π), where Kennedy's construction is indeterminate."""
        phi = self.turn(n)
        return phi + 0.37 * (phi[1] - phi[0]) if n > 1 else phi + 0.1

    def as_fourbar(self, assembly: int) -> FourBar:
        """The same lengths as a FourBar with a fixed assembly sign (valid on half a turn each)."""
        return FourBar(self.crank, self.ground, self.crank, self.ground, assembly)

    def output_angle(self, phi) -> np.ndarray:
        """ψ(φ) on the crossed branch, continuous over any range of φ."""
        phi = as_angles(phi)
        k = self.k
        if k > 0:
            return phi + 2.0 * np.arctan2((k - 1.0) * np.sin(phi), (1.0 + k) + (1.0 - k) * np.cos(phi))
        return -phi + 2.0 * np.arctan2((k + 1.0) * np.sin(phi), (1.0 - k) + (1.0 + k) * np.cos(phi))

    def motion(self, phi) -> AngularMotion:
        """Paths of O, A, B, E and ψ, ψ', ψ'' at crank angles φ (radians), any φ."""
        phi = as_angles(phi)
        n = len(phi)
        a, g, k = self.crank, self.ground, self.k
        psi = self.output_angle(phi)
        den = (1.0 + k * k) + (1.0 - k * k) * np.cos(phi)
        dpsi = 2.0 * k / den
        ddpsi = 2.0 * k * (1.0 - k * k) * np.sin(phi) / den**2
        ua, ub = unit(phi), unit(psi)
        pa, pb = np.stack([-ua[:, 1], ua[:, 0]], -1), np.stack([-ub[:, 1], ub[:, 0]], -1)
        A = PointPath(a * ua, a * pa, -a * ua)
        E = fixed_point((g, 0.0), n)
        B = PointPath(E.p + a * ub, a * dpsi[:, None] * pb,
                      a * (ddpsi[:, None] * pb - (dpsi**2)[:, None] * ub))
        ba, be = A.p - B.p, E.p - B.p
        mu = np.arccos(np.clip(dot(ba, be) / (g * a), -1.0, 1.0))
        return AngularMotion(phi, {"O": fixed_point((0.0, 0.0), n), "A": A, "B": B, "E": E}, mu,
                             psi, dpsi, ddpsi)
