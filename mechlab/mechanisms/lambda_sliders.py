"""Six-bars on the lambda mechanism with a translating output: МЧВ2 (rod and slider), МЧВ5 (translating slotted link).
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from functools import cached_property

import numpy as np

from ..errors import InfeasibleDesignError, MechanismError
from ..geometry import PointPath, as_angles, cross, dyad_rrp, unit
from ..motion import LinearMotion, scalar_law
from ..validate import Angle, Coordinate, Length, Sign
from .base import FRAME, TWO_PI, Link, Mechanism, Pair, Part, Sketch, Structure, bars, block_outline
from .lambda_mechanism import Delta, Dwell, LambdaMechanism, dwell_path, in_dwell, lambda_links, lambda_pairs

__all__ = ["LambdaSliderSixBar", "LambdaTranslatingSlot"]


# samples of a turn on which the closure of the attached dyad is checked at construction
_CHECK = np.linspace(0.0, TWO_PI, 2881)


# --------------------------------------------------------------------------------------------
# МЧВ2: rod D-E and a slider E on a straight guide through the arc centre
# --------------------------------------------------------------------------------------------
class _OnLambda(Mechanism):
    """A six-bar on the lambda mechanism (r, a, δ): its base four-bar with the coupler point D."""

    @cached_property
    def base(self) -> LambdaMechanism:
        return LambdaMechanism(self.r, self.a, self.delta)


@dataclass(frozen=True)
class LambdaSliderSixBar(_OnLambda):
    """МЧВ2 (Kinitsky (1994), Fig. 1 в): the lambda mechanism + rod D-E + slider E on a fixed line.

    The line passes through Q = (qx, qy) at angle ``theta``. Output s: E = Q + s·u, u = (cos θ, sin θ).
    Transmission angle μ2′ = π/2 − β, β = asin(dist(D, guide)/rod), the acute angle between the rod and the
    guide.

    Parameters
    ----------
    r, a : float
        The lambda mechanism's crank l_OA / l and frame l_OC / l (units of its coupler l).
    delta : float
        δ = ∠ABD of the coupler point D (radians).
    rod : float
        |DE| (positive length).
    qx, qy : float
        The guide's reference point Q (s = 0 there).
    theta : float
        The guide's angle from +x (radians).
    assembly : {1, -1}, optional
        +1 takes the root of the RRP dyad ahead along u, −1 the one behind
        (:func:`mechlab.geometry.line_circle`).
    dwell : float, optional
        The designed dwell 2α (radians; informational: drawings, reports).

    Raises
    ------
    DimensionError
        For a length or angle out of range.
    RotationError
        If the lambda mechanism's crank cannot turn fully.
    InfeasibleDesignError
        If D goes as far as ``rod`` from the guide somewhere in the turn (the rod would stand across the
        guide: a dead point, or no assembly at all).

    Examples
    --------
    >>> import numpy as np
    >>> from mechlab import LambdaSliderSixBar
    >>> m = LambdaSliderSixBar(0.4, 0.8, np.pi, 1.0, 1.0, 1.0, 0.0)
    >>> round(float(m.motion(1.0).s), 4)
    1.5159
    """

    title = "lambda six-bar, type 2 (slider dwell)"

    @classmethod
    def example(cls) -> LambdaSliderSixBar:
        """МЧВ2 on the circle-guiding design for δ = 150°, a = 0.9, a 120° dwell (``mchv2``).

        Returns
        -------
        LambdaSliderSixBar
            A valid instance of the family, the one the services that find the families use.
        """
        return cls(0.21448157412574897, 0.9, 2.6179938779914944, 0.6059814579952297, 1.3973785525129392,
                   1.8562420285733539, 1.3089969389957479, 1, 2.0943951023931953)

    r: Length
    a: Length
    delta: Delta
    rod: Length
    qx: Coordinate
    qy: Coordinate
    theta: Angle
    assembly: Sign = 1
    dwell: Dwell = 0.0  # the designed dwell 2α (informational: drawings, reports)

    pivots = ("O", "C")
    output = "position"

    def __post_init__(self):
        super().__post_init__()
        _ = self.base  # validates r, a, δ (the crank turns fully)
        off = np.abs(self.offsets(_CHECK))
        i = int(np.argmax(off))
        if off[i] >= self.rod * (1 - 1e-9):
            raise InfeasibleDesignError(
                f"the slider dyad D-E does not work over the whole turn: at φ = {np.degrees(_CHECK[i]):.2f}° "
                f"D is {off[i]:.6g} from the guide, not less than the rod DE = {self.rod:.6g} (the rod would "
                f"stand across the guide)")

    @property
    def Q(self) -> np.ndarray:
        """The guide's reference point (the arc centre for a designed МЧВ2): s = 0 there.

        Returns
        -------
        numpy.ndarray
            Q, shape (2,).
        """
        return np.array([self.qx, self.qy])

    @property
    def u(self) -> np.ndarray:
        """Unit vector of the guide.

        Returns
        -------
        numpy.ndarray
            u = (cos θ, sin θ).
        """
        return unit(self.theta)

    @scalar_law
    def offsets(self, phi) -> np.ndarray:
        """Signed distance u × (D − Q) of D from the guide line (closed form of D).

        Parameters
        ----------
        phi : float or array_like
            Crank angles φ (radians).

        Returns
        -------
        numpy.ndarray or float
            The distances (units of l); a float for a scalar φ.

        Examples
        --------
        >>> import numpy as np
        >>> from mechlab import LambdaSliderSixBar
        >>> round(float(LambdaSliderSixBar(0.4, 0.8, np.pi, 1.0, 1.0, 1.0, 0.0).offsets(1.0)), 4)
        0.6314
        """
        D = self.base.coupler_point(phi)
        return cross(np.broadcast_to(self.u, D.shape), D - self.Q)

    def motion(self, phi) -> LinearMotion:
        """Paths of O, A, B, C, D, E and the slider's s, s′, s″ (exact); transmission = μ2′.

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
        >>> import numpy as np
        >>> from mechlab import LambdaSliderSixBar
        >>> LambdaSliderSixBar(0.4, 0.8, np.pi, 1.0, 1.0, 1.0, 0.0).motion(1.0).output
        Law(s = 1.51592, s′ = 0.0975097, s″ = -1.53927)
        """
        phi = as_angles(phi)
        mo = self.base.motion(phi)
        E, s = dyad_rrp(mo.points["D"], self.Q, self.theta, self.rod, self.assembly, phi, "the slider dyad D-E")
        pts = dict(mo.points)
        pts["E"] = E

        def mu2(m):
            D = m.points["D"].p
            dist = np.abs(cross(np.broadcast_to(self.u, D.shape), D - self.Q))
            return np.pi / 2 - np.arcsin(np.clip(dist / self.rod, 0.0, 1.0))

        return LinearMotion(phi, pts, mu2, s.theta, s.d, s.dd)

    def structure(self) -> Structure:
        """МЧВ2: the lambda mechanism, the rod D→E and the slider E on the guide (angle θ).

        Groups (rod, slider), then (coupler, rocker).

        Returns
        -------
        Structure
            Links, pairs and structural groups, from which the drawing, centres, force model and counts derive.

        Examples
        --------
        >>> import numpy as np
        >>> from mechlab import LambdaSliderSixBar
        >>> LambdaSliderSixBar(0.4, 0.8, np.pi, 1.0, 1.0, 1.0, 0.0).structure().numbers()
        {'crank': 1, 'coupler': 2, 'rocker': 3, 'rod': 4, 'slider': 5, 'frame': 6}
        """
        return Structure(
            (*lambda_links(self.base), Link("rod", "D", ("D", "E"), self.rod, joints=("D", "E")),
             Link("slider", "E", self.theta)),
            (*lambda_pairs(), Pair("revolute", "D", "coupler", "rod", "D"), Pair("revolute", "E", "rod", "slider", "E"),
             Pair("prismatic", "guide", FRAME, "slider", "E", self.theta)),
            (("rod", "slider"), ("coupler", "rocker")), "slider", scale=self.a)

    def sketch(self, motion) -> Sketch:
        """МЧВ2: the guide through Q, the slider block at E (numbered, highlighted in the dwell), D's dwell path.

        Parameters
        ----------
        motion : LinearMotion
            The mechanism's motion.

        Returns
        -------
        Sketch
            The parts to draw and the fixed pivots.

        Examples
        --------
        >>> import numpy as np
        >>> from mechlab import LambdaSliderSixBar
        >>> m = LambdaSliderSixBar(0.4, 0.8, np.pi, 1.0, 1.0, 1.0, 0.0)
        >>> len(m.sketch(m.motion(1.0)).parts)
        8
        """
        sk = Sketch(bars(self.structure()), self.pivots)   # the guide and the output drawn here
        u, s, E, still = self.u, motion.s, motion.points["E"].p, in_dwell(motion.phi, self.dwell)
        size = 0.2 * self.rod
        guide = np.array([self.Q + (s.min() - 2 * size) * u, self.Q + (s.max() + 2 * size) * u])
        path = dwell_path(self, self.dwell)

        def block(i):
            return block_outline(E[i], u, size, size)

        return replace(sk, parts=sk.parts + (
            Part("guide", lambda i: guide), Part("output", block, "slider"), Part("extra", lambda i: path),
            Part("highlight", lambda i: block(i) if still[i] else np.full((2, 2), np.nan))))


# --------------------------------------------------------------------------------------------
# МЧВ5: block at D in the straight slot of a translating output
# --------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class LambdaTranslatingSlot(_OnLambda):
    """МЧВ5 (Kinitsky (1994), Fig. 1 д): the lambda mechanism + a block at D in the slot of a translating link.

    The slot's direction angle is ``slot``; the output link translates along the fixed direction ``guide``.
    Output s: the link's displacement along w = (cos guide, sin guide), zero when the slot line passes
    through P = (px, py): s = v×(D − P)/(v×w), s′ = v×D′/(v×w), s″ = v×D″/(v×w). The point E = P + s·w of
    the slot line (on the guide through P) is the output's reference point. Transmission angle: the acute
    angle between slot and guide (constant; 90° ideal).

    Parameters
    ----------
    r, a : float
        The lambda mechanism's crank l_OA / l and frame l_OC / l (units of its coupler l).
    delta : float
        δ = ∠ABD of the coupler point D (radians).
    px, py : float
        P, where s = 0.
    slot : float
        The slot's direction (radians, from +x).
    guide : float
        The output's direction of travel (radians, from +x).
    dwell : float, optional
        The straight part's crank angle 2α (radians; informational).

    Raises
    ------
    DimensionError
        For a length or angle out of range.
    RotationError
        If the lambda mechanism's crank cannot turn fully.
    MechanismError
        If the guide is parallel to the slot (to within 0.057°).

    Examples
    --------
    >>> import numpy as np
    >>> from mechlab import LambdaTranslatingSlot
    >>> m = LambdaTranslatingSlot(0.4, 0.8, np.pi, 0.8, 3.0, np.pi / 2, 0.0)
    >>> round(float(m.motion(1.0).s), 4)
    0.9404
    """

    title = "lambda six-bar, type 5 (translating-slot dwell)"

    @classmethod
    def example(cls) -> LambdaTranslatingSlot:
        """МЧВ5 on the straight-guiding design for δ = 180°, a = 0.8 (``mchv5``).

        Returns
        -------
        LambdaTranslatingSlot
            A valid instance of the family, the one the services that find the families use.
        """
        return cls(0.4000000000000008, 0.8, np.pi, 0.8000000000000002, 1.601950746617271, np.pi, np.pi / 2, np.pi)

    r: Length
    a: Length
    delta: Delta
    px: Coordinate
    py: Coordinate
    slot: Angle
    guide: Angle
    dwell: Dwell = 0.0  # the straight part's crank angle 2α (informational)

    pivots = ("O", "C")
    output = "position"

    def __post_init__(self):
        super().__post_init__()
        _ = self.base  # validates r, a, δ
        if abs(self._sin) < 1e-3:
            raise MechanismError(
                f"the output's guide ({np.degrees(self.guide):.4g}°) is parallel to its slot "
                f"({np.degrees(self.slot):.4g}°) to within {np.degrees(np.arcsin(min(abs(self._sin), 1))):.3g}° "
                f"(needs at least 0.057°): the block cannot push the link along the guide")

    @property
    def P(self) -> np.ndarray:
        """The point P = (px, py) where s = 0.

        Returns
        -------
        numpy.ndarray
            P, shape (2,).
        """
        return np.array([self.px, self.py])

    @property
    def _sin(self) -> float:
        """v × w = sin(guide − slot)."""
        return float(np.sin(self.guide - self.slot))

    @property
    def transmission_angle(self) -> float:
        """The acute angle between the slot and the guide (π/2 when the guide is along the slot normal).

        Returns
        -------
        float
            The angle (radians).
        """
        return float(np.arcsin(min(abs(self._sin), 1.0)))

    def motion(self, phi) -> LinearMotion:
        """Paths of O, A, B, C, D, E (output reference point) and s, s′, s″ in closed form.

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
        >>> import numpy as np
        >>> from mechlab import LambdaTranslatingSlot
        >>> LambdaTranslatingSlot(0.4, 0.8, np.pi, 0.8, 3.0, np.pi / 2, 0.0).motion(1.0).output
        Law(s = 0.940436, s′ = -0.0250964, s″ = -1.08113)
        """
        phi = as_angles(phi)
        mo = self.base.motion(phi)
        D = mo.points["D"]
        v, w = unit(self.slot), unit(self.guide)
        vv = np.broadcast_to(v, D.p.shape)
        k = 1.0 / self._sin
        s = cross(vv, D.p - self.P) * k
        ds = cross(vv, D.d) * k
        dds = cross(vv, D.dd) * k
        pts = dict(mo.points)
        pts["E"] = PointPath(self.P + s[:, None] * w, ds[:, None] * w, dds[:, None] * w)
        return LinearMotion(phi, pts, np.full(len(phi), self.transmission_angle), s, ds, dds)

    def structure(self) -> Structure:
        """МЧВ5: the lambda mechanism, a block at D in the output's slot, the output translating along ``guide``.

        The output's reference point E is on the guide; groups (block, output), then (coupler, rocker).

        Returns
        -------
        Structure
            Links, pairs and structural groups, from which the drawing, centres, force model and counts derive.

        Examples
        --------
        >>> import numpy as np
        >>> from mechlab import LambdaTranslatingSlot
        >>> LambdaTranslatingSlot(0.4, 0.8, np.pi, 0.8, 3.0, np.pi / 2, 0.0).structure().numbers()
        {'crank': 1, 'coupler': 2, 'rocker': 3, 'output': 4, 'frame': 5}
        """
        return Structure(
            (*lambda_links(self.base), Link("block", "D", self.slot, block=True), Link("output", "E", self.guide)),
            (*lambda_pairs(), Pair("revolute", "D", "coupler", "block", "D"),
             Pair("prismatic", "slot", "output", "block", "D", self.slot - self.guide),
             Pair("prismatic", "guide", FRAME, "output", "E", self.guide)),
            (("block", "output"), ("coupler", "rocker")), "output", scale=self.a)

    def sketch(self, motion) -> Sketch:
        """МЧВ5: the fixed guide, the output link (a slot through D and a bar along the guide), the block at D.

        The guide has a bushing beyond the bar's travel; the output is numbered and highlighted in the dwell,
        with D's dwell path.

        Parameters
        ----------
        motion : LinearMotion
            The mechanism's motion.

        Returns
        -------
        Sketch
            The parts to draw and the fixed pivots.

        Examples
        --------
        >>> import numpy as np
        >>> from mechlab import LambdaTranslatingSlot
        >>> m = LambdaTranslatingSlot(0.4, 0.8, np.pi, 0.8, 3.0, np.pi / 2, 0.0)
        >>> len(m.sketch(m.motion(1.0)).parts)
        8
        """
        sk = Sketch(bars(self.structure()), self.pivots)   # the guide and the output drawn here
        v, w = np.array([np.cos(self.slot), np.sin(self.slot)]), np.array([np.cos(self.guide), np.sin(self.guide)])
        E, D = motion.points["E"].p, motion.points["D"].p
        still = in_dwell(motion.phi, self.dwell)
        # the slot spans D's whole sweep along it, the bar reaches back along the guide past the curve
        reach = float(np.ptp(D @ w)) + 0.3
        s, n, g = motion.s, np.array([-w[1], w[0]]), 0.04
        lo, hi = self.P + (s.max() + 0.4 * reach) * w, self.P + (s.max() + 0.8 * reach) * w
        guide = np.array([lo + g * n, hi + g * n, [np.nan, np.nan], lo - g * n, hi - g * n])
        path = dwell_path(self, self.dwell)

        def link(i):
            along = (D - E[i]) @ v
            slot = np.array([E[i] + (along.min() - 0.1) * v, E[i] + (along.max() + 0.1) * v])
            return np.array([slot[0], slot[1], E[i], E[i] + reach * w])

        return replace(sk, parts=sk.parts + (
            Part("guide", lambda i: guide), Part("output", link, "output"),
            Part("output", lambda i: block_outline(D[i], v, 0.08, 0.08)), Part("extra", lambda i: path),
            Part("highlight", lambda i: link(i) if still[i] else np.full((4, 2), np.nan))))
