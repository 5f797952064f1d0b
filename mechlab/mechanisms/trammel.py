"""The two mechanisms of Kozhevnikov §7.2 that are not in :mod:`mechlab.mechanisms`.

* :class:`EllipticTrammel` — a rod AB whose ends slide on two straight guides crossing
  at O at the angle β (Kozhevnikov, Fig. 7.5; β = 90° in Fig. 7.6), driven here by Cardan's
  crank O-C, C being the centre of the rod's moving centrode (the circumcentre of
  triangle OAB), so that the crank angle φ is a full-turn input.
* :class:`Antiparallelogram` — the crossed four-bar whose opposite links are equal
  (Kozhevnikov, Fig. 7.7), followed on its crossed branch through both change points.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Annotated

import numpy as np

from ..geometry import PointPath, as_angles, fixed_point, unit
from ..motion import LinearMotion, scalar_law
from ..validate import Length, angle
from .base import FRAME, Link, Mechanism, Pair, Part, Sketch, Structure, block_outline

# Guides closer than this to parallel (radians) are rejected: the rod could not move.
_MIN_GUIDE_ANGLE = 1e-6


@dataclass(frozen=True)
class EllipticTrammel(Mechanism):
    """Rod A-B of length ``rod``; A slides on the x axis, B on the line through O at angle ``beta``.

    Derivation (Kozhevnikov, Fig. 7.5, derived anew): the normals to the guides at A and B meet at the
    rod's instantaneous centre P, so O, A, P, B lie on the circle with diameter OP = rod / sin β. That
    circle's centre C = P/2 is fixed to the rod, and |OC| = r = rod / (2 sin β): a crank O-C of radius r
    drives the rod (Cardan's drive). With φ the crank angle, P = 2r·(cos φ, sin φ), and the feet of P on
    the guides are

        A = 2r cos φ · (1, 0),    B = 2r cos(φ - β) · (cos β, sin β),

    the rod's angle is θ = π/2 + β - φ (θ' = -1). Output: s = x_A = 2r cos φ.

    Parameters
    ----------
    rod : float
        Rod length |AB| (positive length).
    beta : float, optional
        Angle between the guides (radians, 0 < β < π; π/2 by default).

    Raises
    ------
    DimensionError
        For a rod that is not positive and finite, or guides (nearly) parallel.

    Examples
    --------
    >>> from mechlab import EllipticTrammel
    >>> m = EllipticTrammel(2.0)
    >>> m.crank, m.fixed_radius
    (1.0, 2.0)
    >>> round(float(m.motion(0.3).s), 4)
    1.9107
    """

    @classmethod
    def example(cls) -> EllipticTrammel:
        """Rod 1, guides 1.2 rad apart.

        Returns
        -------
        EllipticTrammel
            A valid instance of the family, the one the services that find the families use.
        """
        return cls(1.0, 1.2)

    rod: Length
    beta: Annotated[float, angle(_MIN_GUIDE_ANGLE, np.pi - _MIN_GUIDE_ANGLE, open=True,
                                 why="0 < β < 180°: parallel guides leave no room for the rod to turn")] = np.pi / 2

    pivots = ("O",)
    output = "position"

    @property
    def crank(self) -> float:
        """Radius of the Cardan crank O-C: rod / (2 sin β), the moving centrode's radius.

        Returns
        -------
        float
            The radius (length).
        """
        return self.rod / (2.0 * np.sin(self.beta))

    @property
    def fixed_radius(self) -> float:
        """Radius of the fixed centrode (centre O): rod / sin β (Kozhevnikov, formula (7.12)).

        Returns
        -------
        float
            The radius (length).
        """
        return self.rod / np.sin(self.beta)

    @scalar_law
    def rod_angle(self, phi) -> np.ndarray:
        """Angle θ of the rod A→B at crank angles φ: θ = π/2 + β - φ.

        Parameters
        ----------
        phi : float or array_like
            Crank angles φ (radians).

        Returns
        -------
        numpy.ndarray or float
            θ (radians); a float for a scalar φ.

        Raises
        ------
        DimensionError
            If φ is not finite.

        Examples
        --------
        >>> from mechlab import EllipticTrammel
        >>> round(float(EllipticTrammel(2.0).rod_angle(0.3)), 4)
        2.8416
        """
        return np.pi / 2 + self.beta - as_angles(phi)

    def structure(self) -> Structure:
        """The rod A→B (the input) and the sliders A, B on their guides; numbered as in Kozhevnikov, Fig. 7.5.

        Cardan's crank only parametrises the rod (θ′ = −1): 1 = frame, 2 = slider A, 3 = slider B, 4 = rod.

        Returns
        -------
        Structure
            Links, pairs and structural groups, from which the drawing, centres, force model and counts derive.

        Examples
        --------
        >>> from mechlab import EllipticTrammel
        >>> EllipticTrammel(2.0).structure().numbers()
        {'frame': 1, 'slider A': 2, 'slider B': 3, 'rod': 4}
        """
        return Structure(
            (Link("rod", "A", ("A", "B"), self.rod, joints=("A", "B")), Link("slider A", "A", 0.0),
             Link("slider B", "B", self.beta)),
            (Pair("prismatic", "guide A", FRAME, "slider A", "A", 0.0),
             Pair("prismatic", "guide B", FRAME, "slider B", "B", self.beta),
             Pair("revolute", "A", "slider A", "rod", "A"), Pair("revolute", "B", "slider B", "rod", "B")),
            (), "slider A", scale=self.fixed_radius, numbering=("frame", "slider A", "slider B", "rod"),
            input_rate=-1.0)

    def sketch(self, motion) -> Sketch:
        """Both guides (through O, 1.15 R either side) and the two blocks, numbered as Kozhevnikov's Fig. 7.5.

        The centres use this numbering: 1 the guides (frame), 2 slider A, 3 slider B, 4 the rod; Cardan's
        crank O-C only parametrises the motion and has no number.

        Parameters
        ----------
        motion : LinearMotion
            The trammel's motion.

        Returns
        -------
        Sketch
            The parts to draw and the fixed pivot O.

        Examples
        --------
        >>> from mechlab import EllipticTrammel
        >>> m = EllipticTrammel(2.0)
        >>> len(m.sketch(m.motion(0.3)).parts)
        8
        """
        R = self.fixed_radius
        h = 0.06 * R
        parts = [Part("link", ("O", "C")), Part("link", ("A", "B"), "rod"), Part("link", ("B", "C")),
                 Part("link", ("C", "A"))]
        for name, guide, number in (("A", 0.0, "slider A"), ("B", self.beta, "slider B")):
            u, P = unit(guide), motion.points[name].p
            parts += [Part("extra", lambda i, u=u: np.array([-1.15 * R * u, 1.15 * R * u])),
                      Part("extra", lambda i, P=P, u=u: block_outline(P[i], u, 2 * h, 1.2 * h), number)]
        return Sketch(tuple(parts), self.pivots)

    def motion(self, phi) -> LinearMotion:
        """Paths of O, C, A, B and the slider law s = x_A, s', s'' at crank angles φ.

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
        >>> from mechlab import EllipticTrammel
        >>> EllipticTrammel(2.0).motion(0.3).output
        Law(s = 1.91067, s′ = -0.59104, s″ = -1.91067)
        """
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

