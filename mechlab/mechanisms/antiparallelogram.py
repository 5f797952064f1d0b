"""The antiparallelogram: the crossed four-bar with equal opposite links (Kozhevnikov, §7.2).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import DimensionError
from ..geometry import PointPath, as_angles, dot, fixed_point, unit
from ..motion import AngularMotion, scalar_law
from ..validate import Length, Samples, validated
from .base import Mechanism
from .fourbar import FourBar


@dataclass(frozen=True)
class Antiparallelogram(Mechanism):
    """Crossed four-bar O-A-B-E with crank OA = rocker EB = ``crank`` and coupler AB = frame OE = ``ground``.

    A four-bar with s + l = p + q is a change-point linkage: at φ = 0 and φ = π all four joints lie on the
    frame line and the loop may continue as a parallelogram (ψ = φ) or as the crossed antiparallelogram.
    :class:`~mechlab.FourBar` with a fixed assembly sign cannot follow the crossed branch: it is
    ``assembly = -1`` on 0 < φ < π and ``+1`` on π < φ < 2π (tests), and FourBar refuses φ = 0, π. This
    class follows the crossed branch analytically through both change points. Derivation (sympy in the
    tests and notebook 01): with k = (crank + ground)/(crank - ground),

        tan(ψ/2) = k·tan(φ/2),   ψ' = 2k / ((1 + k²) + (1 - k²) cos φ),
        ψ'' = 2k(1 - k²) sin φ / ((1 + k²) + (1 - k²) cos φ)².

    ground < crank (k > 1): both long links turn fully in the same sense (short frame);
    ground > crank (k < -1): both short links turn fully in opposite senses (long frame).

    Parameters
    ----------
    crank : float
        Crank and rocker length (positive).
    ground : float
        Frame and coupler length (positive, ≠ crank).

    Raises
    ------
    DimensionError
        For a length that is not positive and finite, or crank = ground (a rhombus).

    Examples
    --------
    >>> from mechlab import Antiparallelogram
    >>> m = Antiparallelogram(2, 1)
    >>> m.k, round(float(m.output_angle(1.0)), 4)
    (3.0, 2.0459)
    """

    @classmethod
    def example(cls) -> Antiparallelogram:
        """Crank 1, ground 2.

        Returns
        -------
        Antiparallelogram
            A valid instance of the family, the one the services that find the families use.
        """
        return cls(1.0, 2.0)

    crank: Length
    ground: Length

    pivots = ("O", "E")
    output = "angle"

    def __post_init__(self):
        super().__post_init__()
        if abs(self.crank - self.ground) <= 1e-9 * max(self.crank, self.ground):
            raise DimensionError(
                f"crank = ground = {self.crank:g}: all four links equal (a rhombus), the crossed branch "
                f"degenerates (the rocker folds onto the frame); take crank ≠ ground")

    structure = FourBar.structure   # the four-bar's links and pairs, crossed

    @property
    def coupler(self) -> float:
        """The coupler's length, equal to the frame's.

        Returns
        -------
        float
            |AB| = ``ground``.
        """
        return self.ground

    @property
    def rocker(self) -> float:
        """The rocker's length, equal to the crank's.

        Returns
        -------
        float
            |EB| = ``crank``.
        """
        return self.crank

    @property
    def k(self) -> float:
        """k = (crank + ground)/(crank - ground), the ratio in tan(ψ/2) = k·tan(φ/2).

        Returns
        -------
        float
            k (> 1 for a short frame, < -1 for a long one).
        """
        return (self.crank + self.ground) / (self.crank - self.ground)

    def change_points(self) -> tuple[float, float]:
        """Crank angles where the linkage folds flat: 0 and π.

        Returns
        -------
        tuple of float
            ``(0.0, π)`` (radians).
        """
        return (0.0, np.pi)

    @validated
    def cycle(self, n: Samples = 361) -> np.ndarray:
        """n crank angles over a full turn, shifted so that no sample falls on a change point.

        The shift is 0.37 of a step: at 0 and π Kennedy's construction is indeterminate.

        Parameters
        ----------
        n : int, optional
            Number of samples.

        Returns
        -------
        numpy.ndarray
            ``n`` crank angles (radians).

        Examples
        --------
        >>> from mechlab import Antiparallelogram
        >>> Antiparallelogram(2, 1).cycle(3)
        array([1.16238928, 4.30398194, 7.44557459])
        """
        phi = self.turn(n)
        return phi + 0.37 * (phi[1] - phi[0]) if n > 1 else phi + 0.1

    def as_fourbar(self, assembly: int) -> FourBar:
        """The same lengths as a FourBar with a fixed assembly sign (valid on half a turn each).

        Parameters
        ----------
        assembly : {1, -1}
            The FourBar's assembly sign: -1 follows the crossed branch on 0 < φ < π, +1 on π < φ < 2π.

        Returns
        -------
        FourBar
            The four-bar with crank, coupler, rocker, ground = crank, ground, crank, ground.

        Examples
        --------
        >>> from mechlab import Antiparallelogram
        >>> Antiparallelogram(2, 1).as_fourbar(-1)
        FourBar(crank=2.0, coupler=1.0, rocker=2.0, ground=1.0, assembly=-1)
        """
        return FourBar(self.crank, self.ground, self.crank, self.ground, assembly)

    @scalar_law
    def output_angle(self, phi) -> np.ndarray:
        """ψ(φ) on the crossed branch, continuous over any range of φ.

        Parameters
        ----------
        phi : float or array_like
            Crank angles φ (radians).

        Returns
        -------
        numpy.ndarray or float
            ψ (radians); a float for a scalar φ.

        Examples
        --------
        >>> from mechlab import Antiparallelogram
        >>> round(float(Antiparallelogram(2, 1).output_angle(1.0)), 4)
        2.0459
        """
        phi = as_angles(phi)
        k = self.k
        if k > 0:
            return phi + 2.0 * np.arctan2((k - 1.0) * np.sin(phi), (1.0 + k) + (1.0 - k) * np.cos(phi))
        return -phi + 2.0 * np.arctan2((k + 1.0) * np.sin(phi), (1.0 - k) + (1.0 + k) * np.cos(phi))

    def motion(self, phi) -> AngularMotion:
        """Paths of O, A, B, E and ψ, ψ', ψ'' at crank angles φ, any φ (through both change points).

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
        >>> from mechlab import Antiparallelogram
        >>> Antiparallelogram(2, 1).motion(1.0).output
        Law(ψ = 2.04588 rad = 117.22°, ψ′ = 1.05679, ψ″ = -1.25301)
        """
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

