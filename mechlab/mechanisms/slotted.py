"""Slotted links with a straight slot: Zinchenko et al.'s (2013) base mechanisms.

* :class:`SlottedLink` — the link turns about a pivot B, its straight slot passes
  through B and carries the crank pin A (Zinchenko et al. (2013), Fig. 5). Frame of Zinchenko et al. (2013) §2:
  crank pivot O at the origin, link pivot B at (-pivot_distance, 0), so that φ = 0
  where A is farthest from B; ψ is the link's angle from the ray B→O. With
  λ = l_OA / l_OB, tan ψ = λ sin φ / (λ cos φ + 1) (Zinchenko et al. (2013), formula (18)).
  λ < 1: the link oscillates; λ > 1: it turns fully (Whitworth quick return).
* :class:`SineMechanism` — the translating slotted link (Scotch yoke) whose straight
  slot is perpendicular to its guide (Zinchenko et al. (2013), Fig. 6): s = l_OA cos φ (formula (2)).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import DimensionError
from ..geometry import AnglePath, PointPath, as_angles, crank_point, dyad_rpr, fixed_point, lift
from ..motion import AngularMotion, LinearMotion
from ..validate import Length
from .base import FRAME, Link, Mechanism, Pair, Structure


class PivotedSlot:
    """What every slotted link pivoted at B = (-pivot_distance, 0) shares (Zinchenko et al. (2013) frame):
    its λ, whether it turns fully, and the check of λ ≠ 1."""

    crank: Length
    pivot_distance: Length

    def _check_crank_and_pivot(self):
        if abs(self.lam - 1.0) <= 1e-12:
            raise DimensionError(
                f"λ = crank / pivot_distance = {self.crank:g} / {self.pivot_distance:g} = 1: the pin "
                f"passes through the pivot B at φ = 180°, where the slot direction is undefined")

    @property
    def lam(self) -> float:
        """λ = l_OA / l_OB (Zinchenko et al. (2013), text before formula (18))."""
        return self.crank / self.pivot_distance

    @property
    def rotates(self) -> bool:
        """λ > 1: the slotted link (of the base mechanism) turns fully."""
        return self.lam > 1.0


@dataclass(frozen=True)
class SlottedLink(PivotedSlot, Mechanism):
    """Crank O-A (radius ``crank``) driving a slotted link pivoted at B = (-pivot_distance, 0).

    Raises DimensionError for bad lengths and for λ = crank / pivot_distance = 1,
    where the pin passes through the pivot and the slot's direction is undefined.
    """

    @classmethod
    def example(cls) -> SlottedLink:
        """Crank 0.5, pivots 1 apart (λ = 0.5)."""
        return cls(0.5, 1.0)

    crank: Length
    pivot_distance: Length

    pivots = ("O", "B")
    output = "angle"

    def __post_init__(self):
        super().__post_init__()
        self._check_crank_and_pivot()

    def motion(self, phi) -> AngularMotion:
        """Paths of O, A, B and ψ, ψ', ψ'' at crank angles φ (radians, Zinchenko et al. (2013) frame)."""
        phi = as_angles(phi)
        n = len(phi)
        A = crank_point(self.crank, phi)
        B = fixed_point((-self.pivot_distance, 0.0), n)
        ang, _ = dyad_rpr(A, B)
        # λ < 1: A - B always has a positive x component, so ψ is principal;
        # λ > 1: ψ - φ = -atan(sin φ / (λ + cos φ)) stays within π/2 of 0.
        psi = lift(ang.theta, phi) if self.rotates else ang.theta
        mu = np.full(n, np.pi / 2)  # the pin pushes along the slot's normal: no pressure angle
        return AngularMotion(phi, {"O": fixed_point((0.0, 0.0), n), "A": A, "B": B}, mu, psi, ang.d, ang.dd)

    def structure(self) -> Structure:
        """Crank O→A; a block at A slides in the link's slot B→A; the link turns about B; one RPR group."""
        reach = self.pivot_distance + self.crank
        return Structure(
            (Link("crank", "O", ("O", "A"), self.crank, joints=("O", "A")), Link("block", "A", ("B", "A"), block=True),
             Link("link", "B", ("B", "A"), reach, label="slotted link")),
            (Pair("revolute", "O", FRAME, "crank", "O"), Pair("revolute", "A", "crank", "block", "A"),
             Pair("prismatic", "slot", "link", "block", "A", 0.0), Pair("revolute", "B", FRAME, "link", "B")),
            (("block", "link"),), "link", scale=self.crank + self.pivot_distance)


@dataclass(frozen=True)
class SineMechanism(Mechanism):
    """Scotch yoke: the pin A drives a yoke whose slot is perpendicular to its guide (x axis).

    The output s is the yoke's x coordinate, s = crank·cos φ; joint K = (s, 0) is where
    the slot's centre line crosses the guide.
    """

    @classmethod
    def example(cls) -> SineMechanism:
        """Crank 1."""
        return cls(1.0)

    crank: Length

    pivots = ("O",)
    output = "position"

    def motion(self, phi) -> LinearMotion:
        """Paths of O, A, K and s, s', s'' at crank angles φ (radians)."""
        phi = as_angles(phi)
        n = len(phi)
        A = crank_point(self.crank, phi)
        law = AnglePath(A.p[:, 0].copy(), A.d[:, 0].copy(), A.dd[:, 0].copy())
        K = PointPath(*(np.stack([x, np.zeros(n)], axis=-1) for x in law))
        mu = np.full(n, np.pi / 2)
        return LinearMotion(phi, {"O": fixed_point((0.0, 0.0), n), "A": A, "K": K}, mu, *law)

    def structure(self) -> Structure:
        """Crank O→A; a block at A slides in the yoke's slot (perpendicular to the guide); the yoke at K
        slides on the frame along x; one group (block, yoke)."""
        return Structure(
            (Link("crank", "O", ("O", "A"), self.crank, joints=("O", "A")), Link("block", "A", np.pi / 2, block=True),
             Link("yoke", "K", 0.0)),
            (Pair("revolute", "O", FRAME, "crank", "O"), Pair("revolute", "A", "crank", "block", "A"),
             Pair("prismatic", "slot", "yoke", "block", "A", np.pi / 2),
             Pair("prismatic", "guide", FRAME, "yoke", "K", 0.0)),
            (("block", "yoke"),), "yoke", scale=self.crank)
