"""The offset slider-crank O-A-B with the slider B on a line parallel to the x axis.

Frame: crank pivot O at the origin; the slider's guide is the line y = ``offset``;
φ is measured counter-clockwise from the +x axis; the output s is the slider's x
coordinate. ``assembly = +1`` (or "open") puts the slider ahead of the pin along +x (the
usual drawing), ``-1`` (or "crossed") behind it (the mirror image in the y axis of the offset-mirrored
mechanism: s₋(φ; e) = -s₊(π - φ; e), with the same offset e).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import AssemblyError, RotationError
from ..geometry import as_angles, crank_point, dyad_rrp, fixed_point
from ..motion import Extremes, LinearMotion, limit_positions
from ..validate import Coordinate, Length
from .base import FRAME, Link, Mechanism, Pair, Structure, arc_set, fmt_ranges
from .curved_slot import CircleSlot, TranslatingCurvedSlot
from .fourbar import Assembly


@dataclass(frozen=True)
class SliderCrank(Mechanism):
    """Crank O-A, rod A-B, slider B on the line y = offset; output s = x of B.

    The crank turns fully when crank + |offset| < rod.

    Parameters
    ----------
    crank, rod : float
        Crank radius and rod length (positive; dimensionless or mm).
    offset : float, optional
        The guide's distance from the crank pivot, y of the guide line (length).
    assembly : {1, -1, "open", "crossed"}, optional
        The assembly branch (+1: the slider on the +x side).

    Raises
    ------
    DimensionError
        For a length that is not positive and finite, an offset that is not finite, or a bad ``assembly``.
    AssemblyError
        If it closes at no crank angle.

    Examples
    --------
    >>> from mechlab import SliderCrank
    >>> round(float(SliderCrank(1, 3).motion(0.3).s), 4)
    3.9407
    """

    @classmethod
    def example(cls) -> SliderCrank:
        """Crank 1, rod 3, offset 0.2.

        Returns
        -------
        SliderCrank
            A valid instance of the family, the one the services that find the families use.
        """
        return cls(1.0, 3.0, 0.2)

    crank: Length
    rod: Length
    offset: Coordinate = 0.0
    assembly: Assembly = 1

    pivots = ("O",)
    output = "position"

    def __post_init__(self):
        super().__post_init__()
        if not self.crank_ranges():
            raise AssemblyError(
                f"the slider-crank cannot be assembled at any crank angle: the pin's distance from "
                f"the guide, |crank·sin φ - offset|, is at least {abs(self.offset) - self.crank:.4g} "
                f"≥ rod = {self.rod:.4g}")

    def extremes(self) -> Extremes:
        """The slider's limit positions, its stroke and the time ratio (a turning crank only).

        B is at a limit when crank and rod lie in line: |OB| = rod ± crank with B on the guide,
        x = ±√((rod ± crank)² - offset²); with no offset at ±(rod ± crank), φ = 0 and π.

        Returns
        -------
        Extremes
            Crank angles (radians) and slider positions (length) of both limits, the stroke and the time ratio.

        Raises
        ------
        RotationError
            If the crank cannot turn fully.

        Examples
        --------
        >>> from mechlab import SliderCrank
        >>> round(SliderCrank(1, 3, offset=0.5).extremes().time_ratio, 6)
        1.084501
        """
        if not self.can_turn:
            raise RotationError(f"limit positions and a time ratio need a turning crank; {self.rotation_failure()}")
        a, e, l = self.crank, self.offset, self.rod

        def on_guide(r):
            x = np.sqrt(r * r - e * e)
            return np.array([x, e]), np.array([-x, e])

        return limit_positions(self, "B", on_guide(l + a), on_guide(l - a))

    def crank_ranges(self):
        # |a sin φ - e| < rod  <=>  (e - rod)/a < cos(φ - π/2) < (e + rod)/a
        a, e, l = self.crank, self.offset, self.rod
        return arc_set((e - l) / a, (e + l) / a, phase=np.pi / 2)

    def rotation_failure(self) -> str:
        a, e, l = self.crank, self.offset, self.rod
        return (f"crank cannot turn fully: crank + |offset| = {a + abs(e):.2f} ≥ rod = {l:.2f}; "
                f"it reaches only φ ∈ {fmt_ranges(self.crank_ranges())}")

    def assembly_failure(self, phi: float) -> str:
        gap = abs(self.crank * np.sin(phi) - self.offset)
        return f"the pin is {gap:.4g} from the guide, ≥ rod = {self.rod:.4g}"

    def structure(self) -> Structure:
        """Crank O→A, rod A→B, slider at B on the guide (the x axis); one RRP group (rod, slider).

        Returns
        -------
        Structure
            Links, pairs and structural groups, from which the drawing, centres, force model and counts derive.

        Examples
        --------
        >>> from mechlab import SliderCrank
        >>> SliderCrank(1, 3).structure().numbers()
        {'crank': 1, 'rod': 2, 'slider': 3, 'frame': 4}
        """
        return Structure(
            (Link("crank", "O", ("O", "A"), self.crank, joints=("O", "A")),
             Link("rod", "A", ("A", "B"), self.rod, joints=("A", "B")),
             Link("slider", "B", 0.0)),
            (Pair("revolute", "O", FRAME, "crank", "O"), Pair("revolute", "A", "crank", "rod", "A"),
             Pair("revolute", "B", "rod", "slider", "B"), Pair("prismatic", "guide", FRAME, "slider", "B", 0.0)),
            (("rod", "slider"),), "slider", scale=self.crank + self.rod + abs(self.offset))

    def curved_slot_twin(self):
        """Zinchenko et al. (2013) Fig. 4: a translating link whose slot is the circle of radius l_AB about (0, e).

        Kept over the default for its closed form and for a crank that only rocks.

        Returns
        -------
        tuple of (Mechanism, float)
            The curved-slot twin and the crank-angle shift ``phase`` (radians) from this mechanism's frame to it.

        Examples
        --------
        >>> from mechlab import SliderCrank
        >>> twin, phase = SliderCrank(1, 3).curved_slot_twin()
        >>> type(twin).__name__, phase
        ('TranslatingCurvedSlot', 0.0)
        """
        slot = CircleSlot((0.0, self.offset), self.rod)
        return TranslatingCurvedSlot(self.crank, slot, start=np.pi if self.assembly == 1 else 0.0), 0.0

    def motion(self, phi) -> LinearMotion:
        """Paths of O, A, B and the law s, s', s'' at crank angles φ.

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
        AssemblyError
            Where the loop cannot close (the message names the reachable range).

        Examples
        --------
        >>> from mechlab import SliderCrank
        >>> SliderCrank(1, 3, offset=0.5).motion(0.3).output
        Law(s = 3.94836, s′ = -0.230253, s″ = -1.28188)
        """
        phi = as_angles(phi)
        self.check_reachable(phi)
        A = crank_point(self.crank, phi)
        B, s = dyad_rrp(A, (0.0, self.offset), 0.0, self.rod, self.assembly, phi, "the rod-slider dyad")
        # Transmission angle: between the rod and the normal to the guide.
        mu = np.pi / 2 - np.arcsin(np.clip(np.abs(A.p[:, 1] - self.offset) / self.rod, 0.0, 1.0))
        return LinearMotion(phi, {"O": fixed_point((0.0, 0.0), len(phi)), "A": A, "B": B},
                            mu, s.theta, s.d, s.dd)
