"""Six-bars on the lambda mechanism: МЧВ1 (rocker) and МЧВ3 (slotted link) (Kinitsky, 1994).
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from functools import cached_property

import numpy as np

from ..errors import InfeasibleDesignError, MechanismError
from ..geometry import AnglePath, as_angles, dot, dyad_rpr, dyad_rrr, fixed_point, relative, vector_angle
from ..motion import AngularMotion
from ..validate import Coordinate, Length, Sign
from .base import FRAME, TWO_PI, Link, Mechanism, Pair, Part, Sketch, Structure, bars, output_axis
from .lambda_mechanism import Delta, Dwell, LambdaMechanism, dwell_path, in_dwell, lambda_links, lambda_pairs

__all__ = ["LambdaRockerSixBar", "LambdaSlottedSixBar"]


# --------------------------------------------------------------------------------------------
# МЧВ1
# --------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class LambdaRockerSixBar(Mechanism):
    """МЧВ1: the lambda mechanism + connecting rod D-E + rocker E-F pivoted at F = (fx, fy).

    Output ψ: the angle of the rocker F→E (radians); its dwell comes from the circular part of D's path.

    Parameters
    ----------
    r, a : float
        The lambda mechanism's crank l_OA / l and frame l_OC / l (units of its coupler l).
    delta : float
        δ = ∠ABD of the coupler point D (radians).
    rod : float
        |DE| (positive length).
    rocker : float
        |EF| (positive length).
    fx, fy : float
        The rocker's pivot F.
    assembly : {1, -1}, optional
        E on the left (+1) or right (−1) of the directed line D→F.
    dwell : float, optional
        The designed dwell 2α (radians; informational: drawings, widgets).

    Raises
    ------
    DimensionError
        For a length or angle out of range.
    RotationError
        If the lambda mechanism's crank cannot turn fully.
    InfeasibleDesignError
        If the dyad D-E-F does not close over the whole crank turn.

    Examples
    --------
    >>> import numpy as np
    >>> from mechlab import LambdaRockerSixBar
    >>> m = LambdaRockerSixBar(0.4, 0.8, np.pi, 1.5, 1.0, 1.0, 3.0)
    >>> round(float(m.motion(1.0).psi), 4)
    4.0234
    """

    title = "lambda six-bar, type 1 (rocker dwell)"

    @classmethod
    def example(cls) -> LambdaRockerSixBar:
        """МЧВ1 on the circle-guiding design for δ = 150°, a = 0.9, a 120° dwell, a 20° swing (``mchv1``).

        Returns
        -------
        LambdaRockerSixBar
            A valid instance of the family, the one the services that find the families use.
        """
        return cls(0.21448157412574897, 0.9, 2.6179938779914944, 0.6059814579952297, 0.9261816628317386,
                   0.5579728992779812, 2.247663312975413, -1, 2.0943951023931953)

    r: Length
    a: Length
    delta: Delta
    rod: Length
    rocker: Length
    fx: Coordinate
    fy: Coordinate
    assembly: Sign = 1
    dwell: Dwell = 0.0  # the designed dwell 2α (informational: drawings, widgets)

    pivots = ("O", "C", "F")
    output = "angle"

    def __post_init__(self):
        super().__post_init__()
        _ = self.base  # validates r, a, δ (full rotation)
        # the dyad D-E-F must close over the whole turn
        D = self.base.coupler_point(np.linspace(0, TWO_PI, 1441))
        dist = np.hypot(*(D - self.F).T)
        lo, hi = abs(self.rod - self.rocker), self.rod + self.rocker
        if dist.max() >= hi or dist.min() <= lo:
            bad = dist.max() if dist.max() >= hi else dist.min()
            raise InfeasibleDesignError(
                f"the dyad D-E-F does not close over the whole crank turn: |DF| reaches {bad:.4g}, "
                f"outside the open interval (|DE − EF|, DE + EF) = ({lo:.4g}, {hi:.4g})")

    @cached_property
    def base(self) -> LambdaMechanism:
        return LambdaMechanism(self.r, self.a, self.delta)

    @property
    def F(self) -> np.ndarray:
        """The rocker's pivot F = (fx, fy).

        Returns
        -------
        numpy.ndarray
            F, shape (2,).
        """
        return np.array([float(self.fx), float(self.fy)])

    @cached_property
    def _reference(self):
        phi = np.linspace(0, TWO_PI, 1441)
        th = np.unwrap(self._raw(phi))
        return 0.5 * (th.min() + th.max())

    def _raw(self, phi):
        mo = self.base.motion(phi)
        D = mo.points["D"]
        E = dyad_rrr(D, fixed_point(self.F, len(phi)), self.rod, self.rocker, self.assembly, phi, "the dyad D-E-F")
        return np.arctan2(E.p[:, 1] - self.F[1], E.p[:, 0] - self.F[0])

    def motion(self, phi) -> AngularMotion:
        """Paths of O, A, B, C, D, E, F and the rocker's ψ, ψ', ψ''; transmission = angle DEF.

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
        >>> import numpy as np
        >>> from mechlab import LambdaRockerSixBar
        >>> LambdaRockerSixBar(0.4, 0.8, np.pi, 1.5, 1.0, 1.0, 3.0).motion(1.0).output
        Law(ψ = 4.0234 rad = 230.524°, ψ′ = 0.0383767, ψ″ = -1.22754)
        """
        phi = as_angles(phi)
        mo = self.base.motion(phi)
        D = mo.points["D"]
        Fp = fixed_point(self.F, len(phi))
        E = dyad_rrr(D, Fp, self.rod, self.rocker, self.assembly, phi, "the dyad D-E-F")
        ang = vector_angle(relative(E, Fp))
        psi = self._reference + ((ang.theta - self._reference + np.pi) % TWO_PI - np.pi)
        ed, ef = D.p - E.p, Fp.p - E.p
        mu = np.arccos(np.clip(dot(ed, ef) / (self.rod * self.rocker), -1, 1))
        pts = dict(mo.points)
        pts.update(E=E, F=Fp)
        return AngularMotion(phi, pts, mu, psi, ang.d, ang.dd)

    def structure(self) -> Structure:
        """МЧВ1: the lambda mechanism, the rod D→E and the output rocker F→E (Kinitsky (1994), ch. 3).

        Groups (rod, output), then (coupler, rocker).

        Returns
        -------
        Structure
            Links, pairs and structural groups, from which the drawing, centres, force model and counts derive.

        Examples
        --------
        >>> import numpy as np
        >>> from mechlab import LambdaRockerSixBar
        >>> LambdaRockerSixBar(0.4, 0.8, np.pi, 1.5, 1.0, 1.0, 3.0).structure().numbers()
        {'crank': 1, 'coupler': 2, 'rocker': 3, 'rod': 4, 'output': 5, 'frame': 6}
        """
        r = self.base
        return Structure(
            (*lambda_links(r), Link("rod", "D", ("D", "E"), self.rod, joints=("D", "E")),
             Link("output", "F", ("F", "E"), self.rocker, joints=("F", "E"))),
            (*lambda_pairs(), Pair("revolute", "D", "coupler", "rod", "D"), Pair("revolute", "E", "rod", "output", "E"),
             Pair("revolute", "F", FRAME, "output", "F")),
            (("rod", "output"), ("coupler", "rocker")), "output", scale=r.a)

    def sketch(self, motion) -> Sketch:
        """МЧВ1: the bars, the dwell part of D's path and the output rocker highlighted during the dwell.

        Parameters
        ----------
        motion : AngularMotion
            The mechanism's motion.

        Returns
        -------
        Sketch
            The parts to draw and the fixed pivots.

        Examples
        --------
        >>> import numpy as np
        >>> from mechlab import LambdaRockerSixBar
        >>> m = LambdaRockerSixBar(0.4, 0.8, np.pi, 1.5, 1.0, 1.0, 3.0)
        >>> len(m.sketch(m.motion(1.0)).parts)
        7
        """
        sk = super().sketch(motion)
        path, F, E = dwell_path(self, self.dwell), motion.points["F"].p, motion.points["E"].p
        still, nan = in_dwell(motion.phi, self.dwell), np.full((2, 2), np.nan)
        return replace(sk, parts=sk.parts + (
            Part("extra", lambda i: path),
            Part("highlight", lambda i: np.array([F[i], E[i]]) if still[i] else nan)))


# --------------------------------------------------------------------------------------------
# МЧВ3
# --------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class LambdaSlottedSixBar(Mechanism):
    """МЧВ3: the lambda mechanism whose coupler point D slides in the straight slot of a link turning about P.

    The slot line runs at signed distance ``offset`` from P, on the left of P looking along the slot
    direction u for offset > 0: u × (D − P) = offset. Output ψ: the slot's direction (continuous, so a link
    that turns fully gains 2π, or π for a slot through a pivot on the path, per turn).

    Parameters
    ----------
    r, a : float
        The lambda mechanism's crank l_OA / l and frame l_OC / l (units of its coupler l).
    delta : float
        δ = ∠ABD of the coupler point D (radians).
    px, py : float
        The slotted link's pivot P.
    offset : float, optional
        The slot line's signed distance from P (length).
    dwell : float, optional
        The straight part's crank angle 2α (radians; informational).

    Raises
    ------
    DimensionError
        For a length or angle out of range.
    RotationError
        If the lambda mechanism's crank cannot turn fully.
    InfeasibleDesignError
        If the pin D comes inside the slot offset |e| of the pivot.

    Examples
    --------
    >>> import numpy as np
    >>> from mechlab import LambdaSlottedSixBar
    >>> m = LambdaSlottedSixBar(0.4, 0.8, np.pi, 0.8, 3.0)
    >>> round(float(m.motion(1.0).psi), 4), m.turns
    (-0.9688, 0.0)
    """

    title = "lambda six-bar, type 3 (slotted link)"

    @classmethod
    def example(cls) -> LambdaSlottedSixBar:
        """МЧВ3 (full turn) on the straight-guiding design for δ = 180°, a = 0.8 (``mchv3_full_turn``).

        Returns
        -------
        LambdaSlottedSixBar
            A valid instance of the family, the one the services that find the families use.
        """
        return cls(0.4000000000000008, 0.8, np.pi, -0.06000000000000105, 1.6519507466172711, -0.05, np.pi)

    r: Length
    a: Length
    delta: Delta
    px: Coordinate
    py: Coordinate
    offset: Coordinate = 0.0
    dwell: Dwell = 0.0  # the straight part's crank angle 2α (informational)

    pivots = ("O", "C", "P")
    output = "angle"

    def __post_init__(self):
        super().__post_init__()
        _ = self.base  # validates r, a, δ
        D = self.base.coupler_point(np.linspace(0, TWO_PI, 2881))
        rho = np.hypot(*(D - self.P).T)
        if abs(self.offset) > 0 and rho.min() <= abs(self.offset):
            raise InfeasibleDesignError(
                f"the pin D comes within {rho.min():.4g} of the pivot, inside the slot offset |e| = "
                f"{abs(self.offset):.4g}: the slot cannot reach it")

    @cached_property
    def base(self) -> LambdaMechanism:
        return LambdaMechanism(self.r, self.a, self.delta)

    def cycle(self, n: int = 361) -> np.ndarray:
        """A turn sampled off φ = π by 1e-6 rad (the pin may pass through the pivot exactly there); also ``turn``.

        Parameters
        ----------
        n : int, optional
            Number of samples.

        Returns
        -------
        numpy.ndarray
            ``n`` crank angles over one turn (radians), shifted by 1e-6.

        Examples
        --------
        >>> import numpy as np
        >>> from mechlab import LambdaSlottedSixBar
        >>> [round(float(x), 6) for x in LambdaSlottedSixBar(0.4, 0.8, np.pi, 0.8, 3.0).cycle(3)]
        [1e-06, 3.141594, 6.283186]
        """
        return np.linspace(0.0, TWO_PI, n) + 1e-6

    turn = cycle

    @property
    def P(self) -> np.ndarray:
        """The slotted link's pivot P = (px, py).

        Returns
        -------
        numpy.ndarray
            P, shape (2,).
        """
        return np.array([float(self.px), float(self.py)])

    @cached_property
    def _turns(self):
        """Branch data: the output's period (π for a slot through a pivot on the path, else 2π),
        the unwrapped angle on a fine grid over one turn (the reference branch) and the gain per turn."""
        grid = np.linspace(0, TWO_PI, 4001)[:-1] + np.pi / 4000
        th = self._angle(grid).theta
        period = np.pi if self.offset == 0 and self._through_pivot else TWO_PI
        lifted = np.unwrap(th, period=period)
        step = lifted[1] - lifted[0]
        gain = period * round((lifted[-1] + step - lifted[0]) / period)
        return period, grid, lifted, gain

    @cached_property
    def _through_pivot(self) -> bool:
        D = self.base.coupler_point(np.linspace(0, TWO_PI, 2881))
        return bool(np.hypot(*(D - self.P).T).min() < 1e-6)

    def _angle(self, phi) -> AnglePath:
        D = self.base.motion(phi).points["D"]
        ang, rho = dyad_rpr(D, fixed_point(self.P, len(phi)))
        if np.any(rho.theta < 1e-9):
            i = int(np.argmin(rho.theta))
            raise MechanismError(f"the pin D passes through the pivot P at φ = {np.degrees(phi[i]):.4f}°, "
                                 f"where the slot direction is a limit; sample other crank angles")
        e = float(self.offset)
        if e == 0.0:
            return ang
        s = e / rho.theta
        if np.any(np.abs(s) > 1):  # between the samples of the constructor's check
            i = int(np.argmax(np.abs(s)))
            raise InfeasibleDesignError(
                f"the pin D comes within {rho.theta[i]:.4g} of the pivot at φ = {np.degrees(phi[i]):.4f}°, inside "
                f"the slot offset |e| = {abs(e):.4g}: the slot cannot reach it")
        ds = -e * rho.d / rho.theta**2
        dds = -e * (rho.dd * rho.theta - 2 * rho.d**2) / rho.theta**3
        q = np.sqrt(1 - s * s)
        # slot direction = direction of P→D turned by −asin(e/ρ)
        return AnglePath(ang.theta - np.arcsin(s), ang.d - ds / q, ang.dd - (dds / q + s * ds**2 / q**3))

    def motion(self, phi) -> AngularMotion:
        phi = as_angles(phi)
        mo = self.base.motion(phi)
        ang = self._angle(phi)
        period, grid, lifted, gain = self._turns
        k = np.floor((phi - grid[0]) / TWO_PI)
        local = phi - TWO_PI * k
        # the reference branch interpolated on the fine grid (periodic: + gain per crank turn)
        ext_phi = np.concatenate([grid, [grid[0] + TWO_PI]])
        ext_th = np.concatenate([lifted, [lifted[0] + gain]])
        ref = np.interp(local, ext_phi, ext_th) + gain * k
        psi = ref + ((ang.theta - ref + period / 2) % period - period / 2)
        pts = dict(mo.points)
        pts["P"] = fixed_point(self.P, len(phi))
        mu = np.full(len(phi), np.pi / 2)  # the pin pushes along the slot's normal
        return AngularMotion(phi, pts, mu, psi, ang.d, ang.dd)

    @property
    def turns(self) -> float:
        """Output rotation per crank turn in revolutions (0 for an oscillating link).

        Returns
        -------
        float
            Revolutions of the slotted link per crank turn.
        """
        return self._turns[3] / TWO_PI

    def structure(self) -> Structure:
        """МЧВ3: the lambda mechanism, a block at D sliding in the slot of the output link turning about P.

        The output's axis runs along the slot; groups (block, output), then (coupler, rocker).

        Returns
        -------
        Structure
            Links, pairs and structural groups, from which the drawing, centres, force model and counts derive.

        Examples
        --------
        >>> import numpy as np
        >>> from mechlab import LambdaSlottedSixBar
        >>> LambdaSlottedSixBar(0.4, 0.8, np.pi, 0.8, 3.0).structure().numbers()["frame"]
        5
        """
        return Structure(
            (*lambda_links(self.base), Link("block", "D", output_axis, block=True),
             Link("output", "P", output_axis, label="slotted link")),
            (*lambda_pairs(), Pair("revolute", "D", "coupler", "block", "D"),
             Pair("prismatic", "slot", "output", "block", "D", 0.0), Pair("revolute", "P", FRAME, "output", "P")),
            (("block", "output"), ("coupler", "rocker")), "output", scale=self.a)

    def sketch(self, motion) -> Sketch:
        """МЧВ3: the slotted link (a bar through the pivot along the slot, numbered), highlighted in the dwell.

        With the dwell part of D's path.

        Parameters
        ----------
        motion : AngularMotion
            The mechanism's motion.

        Returns
        -------
        Sketch
            The parts to draw and the fixed pivots.

        Examples
        --------
        >>> import numpy as np
        >>> from mechlab import LambdaSlottedSixBar
        >>> m = LambdaSlottedSixBar(0.4, 0.8, np.pi, 0.8, 3.0)
        >>> len(m.sketch(m.motion(1.0)).parts)
        6
        """
        sk = Sketch(bars(self.structure()), self.pivots)   # the slotted link drawn here, offset slot and all
        P, psi, still = motion.points["P"].p, motion.psi, in_dwell(motion.phi, self.dwell)
        reach = 1.2 * np.max(np.hypot(*(motion.points["D"].p - P).T))
        path, offset = dwell_path(self, self.dwell), self.offset

        def bar(i):
            u = np.array([np.cos(psi[i]), np.sin(psi[i])])
            base = P[i] + offset * np.array([-u[1], u[0]])  # the slot is on the left of P for offset > 0
            if offset:
                return np.array([P[i], base, base + reach * u])
            return np.array([P[i] - reach * u, P[i] + reach * u])

        return replace(sk, parts=sk.parts + (
            Part("output", bar, "output"), Part("extra", lambda i: path),
            Part("highlight", lambda i: bar(i) if still[i] else np.full((2, 2), np.nan))))
