"""Six-bars on the lambda mechanism with a translating output: МЧВ2 (rod and slider), МЧВ5 (translating slotted link).
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from functools import cached_property
import numpy as np
from ..errors import MechanismError
from ..geometry import PointPath, as_angles, cross, dyad_rrp, unit
from .base import FRAME, TWO_PI, Link, Mechanism, Pair, Part, Sketch, Structure, bars, block_outline
from ..motion import LinearMotion, scalar_law
from .lambda_mechanism import Delta, Dwell, LambdaMechanism, dwell_path, in_dwell, lambda_links, lambda_pairs
from ..validate import Angle, Coordinate, Length, Sign
from ..errors import InfeasibleDesignError

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
    """МЧВ2 (Kinitsky (1994), Fig. 1 в): lambda mechanism (r, a, δ) + rod D-E (``rod``) + slider E on the
    fixed line through Q = (``qx``, ``qy``) at angle ``theta`` (radians, from +x).

    Output s: E = Q + s·u, u = (cos θ, sin θ). ``assembly`` = +1 takes the root of the RRP dyad
    ahead along u, −1 the one behind (:func:`mechlab.geometry.line_circle`). Transmission angle
    μ2′ = π/2 − β, β = asin(dist(D, guide)/rod), the acute angle between the rod and the guide.
    Raises InfeasibleDesignError if D goes as far as ``rod`` from the guide somewhere in the turn
    (the rod would stand across the guide: a dead point, or no assembly at all).
    """

    title = "lambda six-bar, type 2 (slider dwell)"

    @classmethod
    def example(cls) -> LambdaSliderSixBar:
        """МЧВ2 on the circle-guiding design for δ = 150°, a = 0.9, a 120° dwell (``mchv2``)."""
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
        self.base  # validates r, a, δ (the crank turns fully)
        off = np.abs(self.offsets(_CHECK))
        i = int(np.argmax(off))
        if off[i] >= self.rod * (1 - 1e-9):
            raise InfeasibleDesignError(
                f"the slider dyad D-E does not work over the whole turn: at φ = {np.degrees(_CHECK[i]):.2f}° "
                f"D is {off[i]:.6g} from the guide, not less than the rod DE = {self.rod:.6g} (the rod would "
                f"stand across the guide)")

    @property
    def Q(self) -> np.ndarray:
        """The guide's reference point (the arc centre for a designed МЧВ2): s = 0 there."""
        return np.array([self.qx, self.qy])

    @property
    def u(self) -> np.ndarray:
        """Unit vector of the guide."""
        return unit(self.theta)

    @scalar_law
    def offsets(self, phi) -> np.ndarray:
        """Signed distance u × (D − Q) of D from the guide line (closed form of D)."""
        D = self.base.coupler_point(phi)
        return cross(np.broadcast_to(self.u, D.shape), D - self.Q)

    def motion(self, phi) -> LinearMotion:
        """Paths of O, A, B, C, D, E and the slider's s, s′, s″ (exact); transmission = μ2′."""
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
        """МЧВ2: the lambda mechanism, the rod D→E and the slider E on the guide (angle θ); groups
        (rod, slider), then (coupler, rocker)."""
        return Structure(
            (*lambda_links(self.base), Link("rod", "D", ("D", "E"), self.rod, joints=("D", "E")),
             Link("slider", "E", self.theta)),
            (*lambda_pairs(), Pair("revolute", "D", "coupler", "rod", "D"), Pair("revolute", "E", "rod", "slider", "E"),
             Pair("prismatic", "guide", FRAME, "slider", "E", self.theta)),
            (("rod", "slider"), ("coupler", "rocker")), "slider", scale=self.a)

    def sketch(self, motion) -> Sketch:
        """МЧВ2: the guide through Q, the slider block at E (numbered, highlighted in the dwell), D's dwell
        path."""
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
    """МЧВ5 (Kinitsky (1994), Fig. 1 д): lambda mechanism (r, a, δ) + block at D sliding in a straight slot
    (direction angle ``slot``) of an output link translating along the fixed direction ``guide``.

    Output s: the link's displacement along w = (cos guide, sin guide), zero when the slot line
    passes through P = (``px``, ``py``): s = v×(D − P)/(v×w), s′ = v×D′/(v×w), s″ = v×D″/(v×w).
    The point E = P + s·w of the slot line (on the guide through P) is the output's reference
    point. Transmission angle: the acute angle between slot and guide (constant; 90° ideal: the
    pressure angle is the angle between the slot's normal, along which the block pushes, and w).
    """

    title = "lambda six-bar, type 5 (translating-slot dwell)"

    @classmethod
    def example(cls) -> LambdaTranslatingSlot:
        """МЧВ5 on the straight-guiding design for δ = 180°, a = 0.8 (``mchv5``)."""
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
        self.base
        if abs(self._sin) < 1e-3:
            raise MechanismError(
                f"the output's guide ({np.degrees(self.guide):.4g}°) is parallel to its slot "
                f"({np.degrees(self.slot):.4g}°) to within {np.degrees(np.arcsin(min(abs(self._sin), 1))):.3g}° "
                f"(needs at least 0.057°): the block cannot push the link along the guide")

    @property
    def P(self) -> np.ndarray:
        return np.array([self.px, self.py])

    @property
    def _sin(self) -> float:
        """v × w = sin(guide − slot)."""
        return float(np.sin(self.guide - self.slot))

    @property
    def transmission_angle(self) -> float:
        """The acute angle between the slot and the guide (π/2 when the guide is along the slot normal)."""
        return float(np.arcsin(min(abs(self._sin), 1.0)))

    def motion(self, phi) -> LinearMotion:
        """Paths of O, A, B, C, D, E (output reference point) and s, s′, s″ in closed form."""
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
        """МЧВ5: the lambda mechanism, a block at D in the output's slot (angle ``slot``), the output
        translating along ``guide`` through E; groups (block, output), then (coupler, rocker)."""
        return Structure(
            (*lambda_links(self.base), Link("block", "D", self.slot, block=True), Link("output", "E", self.guide)),
            (*lambda_pairs(), Pair("revolute", "D", "coupler", "block", "D"),
             Pair("prismatic", "slot", "output", "block", "D", self.slot - self.guide),
             Pair("prismatic", "guide", FRAME, "output", "E", self.guide)),
            (("block", "output"), ("coupler", "rocker")), "output", scale=self.a)

    def sketch(self, motion) -> Sketch:
        """МЧВ5: the fixed guide (a bushing beyond the bar's travel), the output link (a slot through D
        and a bar along the guide; numbered, highlighted in the dwell), the block at D, D's dwell path."""
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
