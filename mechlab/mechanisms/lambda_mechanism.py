"""Chebyshev's symmetric lambda mechanism (Kinitsky, 1994).
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from functools import cached_property
from typing import Annotated

import numpy as np

from ..errors import RotationError
from ..geometry import PointPath, as_angles, dot, perp, unit
from ..motion import AngularMotion, scalar_law
from ..validate import Coordinate, Distance, Length, Sign, Spec, angle, check_value
from .base import FRAME, Link, Mechanism, Pair, Part, Sketch, Structure
from .fourbar import FourBar

__all__ = ["GuidedLambda", "LambdaMechanism", "classic_lambda"]

# δ = ∠ABD and a designed dwell 2α, radians
Delta = Annotated[float, angle(0.0, 2 * np.pi, open=True)]
Dwell = Annotated[float, angle(0.0, 2 * np.pi)]


def _angle(name: str, value, lo: float, hi: float, *, closed_hi: bool = True) -> float:
    """An angle (radians) in (lo, hi] (or (lo, hi)), checked by :mod:`mechlab.validate`."""
    return check_value(name, value, Spec("angle", lo, hi, open_lo=True, open_hi=not closed_hi))


# --------------------------------------------------------------------------------------------
# The mechanism
# --------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class LambdaMechanism(Mechanism):
    """Symmetric lambda mechanism O-A-B-C with coupler point D (Kinitsky (1994), Fig. 1a).

    Lengths are in units of the coupler l = l_AB = l_BC = l_BD. ``assembly`` +1 is the thesis' assembly
    (B on the left of A→C, D turned from A about B by +δ), in which the symmetry axis of the coupler curve
    makes π − δ/2 with the ray C→O; −1 is its mirror image in the line OC. The output ψ is the angle of the
    rocker C→B. (The text before Fig. 1 prints only l_OA < l and l_OC + l_OA < 2l, which also admits the
    double crank r > a: see the errata.)

    Parameters
    ----------
    r : float
        l_OA / l, the crank (positive).
    a : float
        l_OC / l, the frame (positive).
    delta : float
        δ = ∠ABD (radians, in (0, 2π)).
    assembly : {1, -1}, optional
        The assembly sign.

    Raises
    ------
    DimensionError
        For a length or angle out of range.
    RotationError
        Unless the base four-bar is a crank-rocker, r < a and r + a < 2 (the boundary lines r = a and
        r + a = 2 of Kinitsky (1994), Fig. 2a); the message names the violated inequality.

    Examples
    --------
    >>> import numpy as np
    >>> from mechlab import LambdaMechanism
    >>> m = LambdaMechanism(0.4, 0.8, np.pi)
    >>> m.coupler_point(1.0).round(4)
    array([1.7404, 1.6314])
    """

    @classmethod
    def example(cls) -> LambdaMechanism:
        """Chebyshev's straight-line proportions (r 0.4, a 0.8, δ = 180°).

        Returns
        -------
        LambdaMechanism
            A valid instance of the family, the one the services that find the families use.
        """
        return cls(0.4, 0.8, np.pi)

    r: Length
    a: Length
    delta: Delta
    assembly: Sign = 1

    pivots = ("O", "C")
    output = "angle"

    def __post_init__(self):
        super().__post_init__()
        r, a = self.r, self.a
        if not r + a < 2.0:
            raise RotationError(
                f"the crank of the lambda mechanism cannot turn fully: r + a = {r + a:.6g} ≥ 2 (Grashof: with "
                f"links r, 1, 1, a the crank turns only if r + a < 2; line EN of Fig. 2a)")
        if not r < a:
            raise RotationError(
                f"the base four-bar is not a crank-rocker: r = {r:.6g} ≥ a = {a:.6g} (the frame is the shortest "
                f"link, so the rocker BC would turn fully too: a double crank); the thesis' region needs r < a "
                f"(line PX of Fig. 2a)")

    @cached_property
    def fourbar(self) -> FourBar:
        """The four-bar O-A-B-C (crank r, coupler 1, rocker 1, ground a)."""
        return FourBar(self.r, 1.0, 1.0, self.a, self.assembly)

    def crank_ranges(self):
        return self.fourbar.crank_ranges()

    # -- symmetry ---------------------------------------------------------------------------
    @property
    def dwell_centre(self) -> float:
        """Crank angle φ = π where A is farthest from C (|CA| = a + r): the curve's axis point D0.

        Returns
        -------
        float
            π (radians).
        """
        return np.pi

    @property
    def axis_angle(self) -> float:
        """Direction (from +x) of the ray C→D0 along the symmetry axis: assembly·δ/2.

        Returns
        -------
        float
            The angle (radians).
        """
        return self.assembly * self.delta / 2.0

    @property
    def axis(self) -> np.ndarray:
        """Unit vector e of the symmetry axis, pointing from C towards D0.

        Returns
        -------
        numpy.ndarray
            e, shape (2,).
        """
        return unit(self.axis_angle)

    @property
    def C(self) -> np.ndarray:
        """The rocker's pivot C = (a, 0).

        Returns
        -------
        numpy.ndarray
            C, shape (2,).
        """
        return np.array([self.a, 0.0])

    @scalar_law
    def mu(self, phi) -> np.ndarray:
        """Transmission angle μ = ∠ABC at crank angles φ: |CA| = 2 sin(μ/2).

        Parameters
        ----------
        phi : float or array_like
            Crank angles φ (radians).

        Returns
        -------
        numpy.ndarray or float
            μ (radians); a float for a scalar φ.

        Examples
        --------
        >>> from mechlab import classic_lambda
        >>> round(float(classic_lambda().mu(1.0)), 4)
        0.6874
        """
        return 2.0 * np.arcsin(np.clip(np.hypot(*self._from_C(as_angles(phi)).T) / 2.0, -1.0, 1.0))

    def _from_C(self, phi) -> np.ndarray:
        """A − C, with r cos φ − a summed as −(a − r) − 2r sin²(φ/2): no cancellation where A passes C."""
        return np.stack([-(self.a - self.r) - 2 * self.r * np.sin(phi / 2) ** 2, self.r * np.sin(phi)], axis=-1)

    @scalar_law
    def coupler_point(self, phi) -> np.ndarray:
        """Positions of D by the closed form (*) of :mod:`mechlab.synthesis.lambda_guiding` (no dyad solve).

        Parameters
        ----------
        phi : float or array_like
            Crank angles φ (radians).

        Returns
        -------
        numpy.ndarray
            D, shape (n, 2), or (2,) for a scalar φ (units of l).

        Examples
        --------
        >>> from mechlab import classic_lambda
        >>> classic_lambda().coupler_point(1.0).round(4)
        array([1.7404, 1.6314])
        """
        v = self._from_C(as_angles(phi))
        d = np.hypot(*v.T)  # |CA| = 2 sin(μ/2)
        k = np.sin((self.delta - 2 * np.arcsin(np.clip(d / 2, -1.0, 1.0))) / 2) / (d / 2)
        th = -self.assembly * (np.pi - self.delta / 2)
        c, s = np.cos(th), np.sin(th)
        return self.C + k[:, None] * np.stack([c * v[:, 0] - s * v[:, 1], s * v[:, 0] + c * v[:, 1]], axis=-1)

    @scalar_law
    def axis_coordinates(self, phi) -> tuple[np.ndarray, np.ndarray]:
        """D in the axis frame at C: x along e (towards D0), y across (left of e).

        Parameters
        ----------
        phi : float or array_like
            Crank angles φ (radians).

        Returns
        -------
        tuple of numpy.ndarray
            (x, y), each one per angle (floats for a scalar φ).

        Examples
        --------
        >>> from mechlab import classic_lambda
        >>> [round(float(v), 4) for v in classic_lambda().axis_coordinates(1.0)]
        [1.6314, -0.9404]
        """
        w = self.coupler_point(phi) - self.C
        e = self.axis
        return w @ e, w @ perp(e)

    # -- kinematics ----------------------------------------------------------------------------
    def motion(self, phi) -> AngularMotion:
        """Paths of O, A, B, C, D (positions and analogs) and the rocker angle ψ, ψ', ψ''.

        D = B + Rot(assembly·δ)(A − B): its analogs follow from those of A and B (exact).

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
        >>> from mechlab import classic_lambda
        >>> classic_lambda().motion(1.0).output
        Law(ψ = 1.39156 rad = 79.7305°, ψ′ = 0.183787, ψ″ = 0.653068)
        """
        phi = as_angles(phi)
        mo = self.fourbar.motion(phi)
        A, B = mo.points["A"], mo.points["B"]
        th = self.assembly * self.delta
        c, s = np.cos(th), np.sin(th)

        def rot(v):
            return np.stack([c * v[:, 0] - s * v[:, 1], s * v[:, 0] + c * v[:, 1]], axis=-1)

        D = PointPath(B.p + rot(A.p - B.p), B.d + rot(A.d - B.d), B.dd + rot(A.dd - B.dd))
        pts = {"O": mo.points["O"], "A": A, "B": B, "C": mo.points["E"], "D": D}
        return AngularMotion(phi, pts, mo.transmission, mo.psi, mo.dpsi, mo.ddpsi)

    def structure(self) -> Structure:
        """The four-bar O-A-B-C: crank O→A, coupler A→B carrying D, rocker C→B (the output); one RRR group.

        Returns
        -------
        Structure
            Links, pairs and structural groups, from which the drawing, centres, force model and counts derive.

        Examples
        --------
        >>> from mechlab import classic_lambda
        >>> classic_lambda().structure().numbers()
        {'crank': 1, 'coupler': 2, 'rocker': 3, 'frame': 4}
        """
        return Structure(lambda_links(self), lambda_pairs(), (("coupler", "rocker"),), "rocker", scale=self.a)

    def sketch(self, motion) -> Sketch:
        """The bars, and the symmetry axis of the coupler curve through C.

        Parameters
        ----------
        motion : AngularMotion
            The mechanism's motion.

        Returns
        -------
        Sketch
            The parts to draw and the pivots O and C.

        Examples
        --------
        >>> from mechlab import classic_lambda
        >>> m = classic_lambda()
        >>> len(m.sketch(m.motion(1.0)).parts)
        4
        """
        sk = super().sketch(motion)
        axis = np.array([self.C - 0.3 * self.axis, self.C + 2.2 * self.axis])
        return replace(sk, parts=sk.parts + (Part("extra", lambda i: axis),))

    def radius_about(self, centre, phi) -> tuple[np.ndarray, np.ndarray]:
        """ρ = |D − Q| and ρ' = dρ/dφ for a fixed point Q.

        Parameters
        ----------
        centre : sequence of float
            Q (units of l).
        phi : array_like
            Crank angles φ (radians).

        Returns
        -------
        tuple of numpy.ndarray
            ρ and ρ', one per angle.

        Examples
        --------
        >>> import numpy as np
        >>> from mechlab import classic_lambda
        >>> [v.round(4) for v in classic_lambda().radius_about((0.8, 1.0), np.array([3.0]))]
        [array([0.605]), array([-0.0696])]
        """
        D = self.motion(phi).points["D"]
        w = D.p - np.asarray(centre, dtype=float)
        rho = np.hypot(w[:, 0], w[:, 1])
        return rho, dot(w, D.d) / rho


@dataclass(frozen=True)
class GuidedLambda(LambdaMechanism):
    """A lambda mechanism with its guiding band: arc centre Q = (qx, qy), radii R0, R1 and the
    dwell 2α (for drawings and widgets; the kinematics are those of LambdaMechanism)."""

    @classmethod
    def example(cls) -> GuidedLambda:
        """The circle-guiding design for δ = 150°, a = 0.9, a 120° dwell (``circle_guiding``).

        Returns
        -------
        GuidedLambda
            A valid instance of the family, the one the services that find the families use.
        """
        return cls(0.21448157412574897, 0.9, 2.6179938779914944, 1, 1.3973785525129392, 1.8562420285733539,
                   0.6060573531852789, 0.6059055628051808, 2.0943951023931953)

    qx: Coordinate = 0.0
    qy: Coordinate = 0.0
    R0: Distance = 0.0
    R1: Distance = 0.0
    dwell: Dwell = 0.0

    def sketch(self, motion) -> Sketch:
        """Adds the band: arcs of R0 and R1 about Q near the dwell (so the picture stays readable) and the
        dwell part of D's path."""
        sk = super().sketch(motion)
        q, e = np.array([self.qx, self.qy]), self.axis
        th0 = np.arctan2(-e[1], -e[0]) if self.R0 > 0 else 0.0
        span = np.linspace(th0 - 0.9, th0 + 0.9, 121)
        arcs = [q + R * np.stack([np.cos(span), np.sin(span)], axis=-1) for R in (self.R0, self.R1)]
        band = (*arcs, dwell_path(self, self.dwell))
        return replace(sk, parts=sk.parts + tuple(Part("extra", lambda i, xy=xy: xy) for xy in band))


def lambda_links(m) -> tuple[Link, ...]:
    """The lambda mechanism's moving links (the base of its six-bars): crank, coupler (a plate A-B-D),
    rocker."""
    return (Link("crank", "O", ("O", "A"), m.r, joints=("O", "A")),
            Link("coupler", "A", ("A", "B"), 1.0, joints=("A", "B", "D", "A")),
            Link("rocker", "C", ("C", "B"), 1.0, joints=("C", "B")))


def lambda_pairs() -> tuple[Pair, ...]:
    """The lambda mechanism's revolute pairs O, A, B, C."""
    return (Pair("revolute", "O", FRAME, "crank", "O"), Pair("revolute", "A", "crank", "coupler", "A"),
            Pair("revolute", "B", "coupler", "rocker", "B"), Pair("revolute", "C", FRAME, "rocker", "C"))


def in_dwell(phi, dwell: float):
    """True where the crank angle φ lies in the dwell of width ``dwell`` centred on φ = π."""
    return (dwell > 0) & (np.abs((np.asarray(phi) - np.pi + np.pi) % (2 * np.pi) - np.pi) <= dwell / 2)


def dwell_path(mech, dwell: float) -> np.ndarray:
    """The part of D's path traced during the dwell (centred on φ = π) of a lambda or a six-bar on one."""
    if dwell <= 0:
        return np.full((1, 2), np.nan)
    t = np.pi + np.linspace(-dwell / 2, dwell / 2, 121) + 1e-6
    return mech.base.coupler_point(t) if hasattr(mech, "base") else mech.coupler_point(t)


def classic_lambda() -> LambdaMechanism:
    """Chebyshev's lambda: crank 1, ground 2, links 2.5, coupler point at 5 (δ = π).

    Returns
    -------
    LambdaMechanism
        r = 0.4, a = 0.8, δ = π (in units of the 2.5 links).

    Examples
    --------
    >>> from mechlab import classic_lambda
    >>> classic_lambda()
    LambdaMechanism(r=0.4, a=0.8, delta=3.141592653589793, assembly=1)
    """
    return LambdaMechanism(1.0 / 2.5, 2.0 / 2.5, np.pi)

