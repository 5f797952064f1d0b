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

    Zinchenko et al.'s (2013) base mechanism; output ψ is the slotted link's angle (radians).

    Parameters
    ----------
    crank : float
        Crank radius l_OA (positive length).
    pivot_distance : float
        Distance l_OB of the link's pivot B from O (positive length).

    Raises
    ------
    DimensionError
        For bad lengths and for λ = crank / pivot_distance = 1, where the pin passes through the pivot
        and the slot's direction is undefined.

    Examples
    --------
    >>> from mechlab import SlottedLink
    >>> m = SlottedLink(2, 1)
    >>> m.lam, m.rotates
    (2.0, True)
    >>> round(float(m.motion(0.3).psi), 4)
    0.2003
    """

    @classmethod
    def example(cls) -> SlottedLink:
        """Crank 0.5, pivots 1 apart (λ = 0.5).

        Returns
        -------
        SlottedLink
            A valid instance of the family, the one the services that find the families use.
        """
        return cls(0.5, 1.0)

    crank: Length
    pivot_distance: Length

    pivots = ("O", "B")
    output = "angle"

    def __post_init__(self):
        super().__post_init__()
        self._check_crank_and_pivot()

    def motion(self, phi) -> AngularMotion:
        """Paths of O, A, B and ψ, ψ', ψ'' at crank angles φ (Zinchenko et al. (2013) frame).

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
        >>> from mechlab import SlottedLink
        >>> SlottedLink(2, 1).motion(0.3).output
        Law(ψ = 0.200336 rad = 11.4784°, ψ′ = 0.670042, ψ″ = 0.022786)
        """
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
        """Crank O→A; a block at A slides in the link's slot B→A; the link turns about B; one RPR group.

        Returns
        -------
        Structure
            Links, pairs and structural groups, from which the drawing, centres, force model and counts derive.

        Examples
        --------
        >>> from mechlab import SlottedLink
        >>> SlottedLink(2, 1).structure().numbers()["frame"]
        3
        """
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

    The output s is the yoke's x coordinate, s = crank·cos φ; joint K = (s, 0) is where the slot's centre
    line crosses the guide.

    Parameters
    ----------
    crank : float
        Crank radius (positive length).

    Raises
    ------
    DimensionError
        If ``crank`` is not positive and finite.

    Examples
    --------
    >>> from mechlab import SineMechanism
    >>> round(float(SineMechanism(1).motion(0.3).s), 4)
    0.9553
    """

    @classmethod
    def example(cls) -> SineMechanism:
        """Crank 1.

        Returns
        -------
        SineMechanism
            A valid instance of the family, the one the services that find the families use.
        """
        return cls(1.0)

    crank: Length

    pivots = ("O",)
    output = "position"

    def motion(self, phi) -> LinearMotion:
        """Paths of O, A, K and s, s', s'' at crank angles φ.

        Parameters
        ----------
        phi : float or array_like
            Crank angles φ (radians); a scalar gives a motion of scalars.

        Returns
        -------
        LinearMotion
            Joint paths and the output displacement s with s', s''.

        Raises
        ------
        DimensionError
            If φ is not a finite real number or array.

        Examples
        --------
        >>> from mechlab import SineMechanism
        >>> SineMechanism(1).motion(0.3).output
        Law(s = 0.955336, s′ = -0.29552, s″ = -0.955336)
        """
        phi = as_angles(phi)
        n = len(phi)
        A = crank_point(self.crank, phi)
        law = AnglePath(A.p[:, 0].copy(), A.d[:, 0].copy(), A.dd[:, 0].copy())
        K = PointPath(*(np.stack([x, np.zeros(n)], axis=-1) for x in law))
        mu = np.full(n, np.pi / 2)
        return LinearMotion(phi, {"O": fixed_point((0.0, 0.0), n), "A": A, "K": K}, mu, *law)

    def structure(self) -> Structure:
        """Crank O→A; a block at A slides in the yoke's slot; the yoke at K slides on the frame along x.

        The slot is perpendicular to the guide; one group (block, yoke).

        Returns
        -------
        Structure
            Links, pairs and structural groups, from which the drawing, centres, force model and counts derive.

        Examples
        --------
        >>> from mechlab import SineMechanism
        >>> SineMechanism(1).structure().numbers()
        {'crank': 1, 'yoke': 2, 'frame': 3}
        """
        return Structure(
            (Link("crank", "O", ("O", "A"), self.crank, joints=("O", "A")), Link("block", "A", np.pi / 2, block=True),
             Link("yoke", "K", 0.0)),
            (Pair("revolute", "O", FRAME, "crank", "O"), Pair("revolute", "A", "crank", "block", "A"),
             Pair("prismatic", "slot", "yoke", "block", "A", np.pi / 2),
             Pair("prismatic", "guide", FRAME, "yoke", "K", 0.0)),
            (("block", "yoke"),), "yoke", scale=self.crank)
