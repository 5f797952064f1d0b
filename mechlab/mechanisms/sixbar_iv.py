"""A six-bar linkage with a class-IV, second-order Assur group (Zinchenko et al. (2013) §1).

Frame 1, crank 2' = O-A, and one group of four links and six revolute pairs (Artobolevsky's
classification, the seed's ref. [1]): link 2 ternary (A, Q, P; the coupler), links 3 = Q-R and
5 = P-T binary, link 4 ternary (R, T, E; the output, turning about E). Its contour Q-R-T-P has four
sides (class IV) and W = 3·4 - 2·6 = 0, so both loop equations are solved together. Seen from the
output, links 3, 2, 5 form a four-bar whose coupler carries A: the relative path is a coupler curve
(:mod:`mechlab.analysis.equivalence`).

Frame as :class:`~mechlab.mechanisms.FourBar` (O at the origin, E at (ground, 0)); ``r_joint``,
``t_joint`` are R, T in the output's frame (origin E, x along ψ), ``coupler_point`` is A in link 2's
frame (origin Q, x along Q→P). Solution (:meth:`SixBarIV.motion`): unknowns (θ2, ψ), loop equations
F1 = |Q - R|² - l3², F2 = |P - T|² - l5²; continuation over a 720-step grid from the assembly at
φ = π chosen by ``inner_assembly`` and ``start``, then a vectorised Newton polish; analogs from
J·x' = -F_φ and its derivative (J singular at a dead position of the group).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property

import numpy as np
from scipy.optimize import brentq

from ..errors import AssemblyError, DimensionError, RotationError, SingularityError
from ..geometry import (
    AnglePath,
    PointPath,
    as_angles,
    crank_point,
    dot,
    dyad_rrr,
    fixed_point,
    perp,
    relative,
    unit,
    vector_angle,
)
from ..motion import AngularMotion
from ..validate import Length, OptionalAngle, Point, Sign
from .base import FRAME, Link, Mechanism, Pair, Structure, output_axis

_GRID = 720


def _rot(theta, v):
    """Rotate the fixed 2-vector v by angles theta: (n, 2)."""
    c, s = np.cos(theta), np.sin(theta)
    return np.stack([c * v[0] - s * v[1], s * v[0] + c * v[1]], axis=-1)


@dataclass(frozen=True)
class SixBarIV(Mechanism):
    """Crank O-A driving the class-IV group (links 2-5); output ψ = angle of link 4 about E.

    The crank turns about O = (0, 0), the output link 4 about E = (ground, 0); link 4 carries the joints R
    and T, link 3 = R-Q, link 5 = T-P, the coupler 2 carries Q, P and the crank pin A.

    Parameters
    ----------
    crank : float
        Crank radius |OA| (positive length).
    ground : float
        Distance |OE| (positive length).
    r_joint, t_joint : tuple of float
        R and T in the output link's frame (origin E, x axis at ψ) (length).
    link3 : float
        |RQ| (positive length).
    link5 : float
        |TP| (positive length).
    qp : float
        |QP| on the coupler (positive length).
    coupler_point : tuple of float
        A − Q in the coupler's frame (x axis along Q→P) (length).
    inner_assembly : {1, -1}, optional
        P on the left (+1) or right of the directed line Q→T in the starting position.
    start : float, optional
        The angle of R→Q in the output link's frame at φ = π near which the starting assembly is taken
        (radians; needed when several fit).

    Raises
    ------
    DimensionError
        For bad lengths, or R and T coinciding.
    AssemblyError
        If the group cannot be assembled at φ = π.
    RotationError
        If the crank cannot turn fully (the group reaches a dead position), with the numbers.

    Examples
    --------
    >>> from mechlab.mechanisms.sixbar_iv import example
    >>> m = example()
    >>> m.crank, m.ground
    (0.25, 1.04)
    >>> round(float(m.motion(1.0).psi), 4)
    2.6439
    """

    title = "class-IV six-bar"

    @classmethod
    def example(cls) -> SixBarIV:
        """The course's class-IV six-bar (lengths in units of about the ground O-E).

        Output link 4 pivoted at E carries R and T; the inner four-bar R-Q-P-T (ground
        |RT| ≈ 0.85, crank R-Q 0.25, coupler Q-P 0.9, rocker P-T 0.85) is a crank-rocker,
        so its coupler curve (the slot of the equivalent slotted link) is a closed oval.
        Of the two assemblies at φ = 180° the one with R→Q at ≈ 1° is taken.

        Returns
        -------
        SixBarIV
            The course's six-bar, the one the services that find the families use.
        """
        return cls(crank=0.25, ground=1.04, r_joint=(0.55, 0.45), t_joint=(1.35, 0.15), link3=0.25,
                   link5=0.85, qp=0.9, coupler_point=(0.2, -0.55), inner_assembly=1, start=0.0)

    crank: Length
    ground: Length
    r_joint: Point
    t_joint: Point
    link3: Length
    link5: Length
    qp: Length
    coupler_point: Point
    inner_assembly: Sign = 1
    start: OptionalAngle = None

    pivots = ("O", "E")
    output = "angle"

    def __post_init__(self):
        super().__post_init__()
        if np.hypot(self.t_joint[0] - self.r_joint[0], self.t_joint[1] - self.r_joint[1]) == 0:
            raise DimensionError("r_joint and t_joint coincide: link 4 must carry two distinct joints")
        self._grid  # noqa: B018 - assemble and follow one turn now (raises with the numbers)

    # -- the inner four-bar R-Q-P-T seen from the output link -----------------------------------
    def _inner(self, theta):
        theta = np.atleast_1d(np.asarray(theta, dtype=float))
        n = len(theta)
        Q = crank_point(self.link3, theta, centre=self.r_joint)
        T = fixed_point(self.t_joint, n)
        P = dyad_rrr(Q, T, self.qp, self.link5, self.inner_assembly, what="the inner four-bar R-Q-P-T")
        return Q, P

    def relative_pin(self, theta) -> PointPath:
        """A in the output link's frame as a function of θ = angle of R→Q in that frame, with its θ-derivatives.

        This is the coupler curve of the inner four-bar R-Q-P-T.

        Parameters
        ----------
        theta : float or array_like
            Angles θ of R→Q in the output link's frame (radians).

        Returns
        -------
        PointPath
            Positions (n, 2) of A with their first and second θ-derivatives.

        Raises
        ------
        AssemblyError
            Where the inner four-bar does not close.

        Examples
        --------
        >>> import numpy as np
        >>> from mechlab.mechanisms.sixbar_iv import example
        >>> example().relative_pin(np.array([0.5])).p.round(4)
        array([[1.1928, 0.1658]])
        """
        Q, P = self._inner(theta)
        ang = vector_angle(relative(P, Q))
        e = unit(ang.theta)
        u, v = self.coupler_point
        off = u * e + v * perp(e)             # A - Q
        doff = perp(off)                       # d(off)/dθ2
        A = Q.p + off
        dA = Q.d + ang.d[:, None] * doff
        ddA = Q.dd + ang.dd[:, None] * doff - (ang.d**2)[:, None] * off
        return PointPath(A, dA, ddA)

    def _start_state(self):
        """(θ2, ψ) at φ = π from the inner four-bar: the coupler point at distance crank + ground from E."""
        target = self.crank + self.ground
        th = np.linspace(-np.pi, np.pi, 4097)
        try:
            r = np.hypot(*self.relative_pin(th).p.T) - target
        except AssemblyError:
            r = None
        if r is None:
            # the inner four-bar does not let R-Q turn fully: sample where it assembles
            ok = []
            for t in th:
                try:
                    self.relative_pin([t])
                    ok.append(t)
                except (AssemblyError, SingularityError):
                    pass
            if not ok:
                raise AssemblyError("the inner four-bar R-Q-P-T cannot be assembled at any angle of R→Q")
            th = np.array(ok)
            r = np.hypot(*self.relative_pin(th).p.T) - target
        roots = []
        for i in np.flatnonzero((r[:-1] * r[1:] <= 0) & (np.diff(th) < 0.01)):
            f = lambda x: float(np.hypot(*self.relative_pin([x]).p[0]) - target)  # noqa: E731
            roots.append(th[i] if r[i] == 0 else brentq(f, th[i], th[i + 1], xtol=1e-15))
        if not roots:
            rr = r + target
            raise AssemblyError(
                f"cannot assemble the class-IV group at φ = 180°: A is crank + ground = {target:.6g} from E, "
                f"but the coupler point's distance from E ranges over [{rr.min():.6g}, {rr.max():.6g}]")
        if self.start is None and len(roots) > 1:
            raise DimensionError(
                f"{len(roots)} assemblies at φ = 180° (angle of R→Q = "
                + ", ".join(f"{np.degrees(x):.2f}°" for x in roots) + "): give start= (radians) to choose one")
        t0 = roots[0] if self.start is None else min(roots, key=lambda x: abs(np.angle(np.exp(1j * (x - self.start)))))
        rel = self.relative_pin([t0]).p[0]
        Q, P = self._inner([t0])
        theta2_rel = float(np.arctan2(P.p[0, 1] - Q.p[0, 1], P.p[0, 0] - Q.p[0, 0]))
        psi = np.pi - float(np.arctan2(rel[1], rel[0]))
        return np.array([theta2_rel + psi, psi]), float(t0)

    # -- loop equations ---------------------------------------------------------------------------
    def _joints(self, A, x):
        th2, psi = x[..., 0], x[..., 1]
        E = np.array([self.ground, 0.0])
        AQ = _rot(th2, self.coupler_point)          # A - Q
        Q = A - AQ
        P = Q + self.qp * unit(th2)
        R = E + _rot(psi, self.r_joint)
        T = E + _rot(psi, self.t_joint)
        return Q, P, R, T, E

    def _residual(self, A, x):
        Q, P, R, T, E = self._joints(A, x)
        F = np.stack([dot(Q - R, Q - R) - self.link3**2, dot(P - T, P - T) - self.link5**2], axis=-1)
        J = np.empty(F.shape + (2,))
        J[..., 0, 0] = dot(Q - R, perp(Q - A))
        J[..., 0, 1] = -dot(Q - R, perp(R - E))
        J[..., 1, 0] = dot(P - T, perp(P - A))
        J[..., 1, 1] = -dot(P - T, perp(T - E))
        return F, 2.0 * J

    def _velocity(self, A: PointPath, x):
        """x' from J x' = -F_φ; also returns J/2 for the second derivative."""
        Q, P, R, T, _E = self._joints(A.p, x)
        _F, J2 = self._residual(A.p, x)
        J = 0.5 * J2
        rhs = -np.stack([dot(Q - R, A.d), dot(P - T, A.d)], axis=-1)
        return np.linalg.solve(J, rhs[..., None])[..., 0], J

    def _newton(self, A, x, iters=30):
        for _ in range(iters):
            F, J = self._residual(A, x)
            step = np.linalg.solve(J, -F[..., None])[..., 0]
            x = x + step
            if np.all(np.abs(step) <= 1e-15 * (1 + np.abs(x))):
                break
        return x

    def _scalar_step(self, phi, x2, x4):
        """Residual, Jacobian/2 and the velocity x' at one crank angle (plain floats: the
        continuation below runs hundreds of tiny 2×2 solves, where numpy's overhead dominates)."""
        a = self.crank
        Ax, Ay = a * math.cos(phi), a * math.sin(phi)
        dAx, dAy = -Ay, Ax
        u, v = self.coupler_point
        c2, s2 = math.cos(x2), math.sin(x2)
        Qx, Qy = Ax - (c2 * u - s2 * v), Ay - (s2 * u + c2 * v)
        Px, Py = Qx + self.qp * c2, Qy + self.qp * s2
        c4, s4 = math.cos(x4), math.sin(x4)
        (rx, ry), (tx, ty) = self.r_joint, self.t_joint
        Rx, Ry = self.ground + c4 * rx - s4 * ry, s4 * rx + c4 * ry
        Tx, Ty = self.ground + c4 * tx - s4 * ty, s4 * tx + c4 * ty
        qrx, qry, ptx, pty = Qx - Rx, Qy - Ry, Px - Tx, Py - Ty
        F1 = qrx * qrx + qry * qry - self.link3**2
        F2 = ptx * ptx + pty * pty - self.link5**2
        # perp(w) = (-w_y, w_x)
        j11 = qrx * (-(Qy - Ay)) + qry * (Qx - Ax)
        j12 = -(qrx * (-Ry) + qry * (Rx - self.ground))
        j21 = ptx * (-(Py - Ay)) + pty * (Px - Ax)
        j22 = -(ptx * (-Ty) + pty * (Tx - self.ground))
        det = j11 * j22 - j12 * j21
        b1, b2 = -(qrx * dAx + qry * dAy), -(ptx * dAx + pty * dAy)
        if det == 0.0:
            return F1, F2, (j11, j12, j21, j22), det, (math.nan, math.nan)
        return F1, F2, (j11, j12, j21, j22), det, ((b1 * j22 - j12 * b2) / det, (j11 * b2 - j21 * b1) / det)

    @cached_property
    def _grid(self):
        x0, t0 = self._start_state()
        phis = np.pi + np.linspace(0.0, 2 * np.pi, _GRID + 1)
        xs = np.empty((_GRID + 1, 2))
        xs[0] = x0
        h = float(phis[1] - phis[0])
        scale = (self.crank + self.ground + self.qp + self.link3 + self.link5) ** 2
        x2, x4 = float(x0[0]), float(x0[1])
        for k in range(_GRID):
            _, _, _, det, (d2, d4) = self._scalar_step(float(phis[k]), x2, x4)
            if abs(det) < 1e-9 * scale:
                raise RotationError(
                    f"crank cannot turn fully: the class-IV group reaches a dead position near "
                    f"φ = {np.degrees(phis[k]) % 360:.2f}° (det J = {det:.3g})")
            y2, y4 = x2 + h * d2, x4 + h * d4
            for _ in range(30):   # Newton corrector at φ_{k+1}
                F1, F2, (j11, j12, j21, j22), det, _ = self._scalar_step(float(phis[k + 1]), y2, y4)
                if det == 0.0:
                    break
                # J here is the half-Jacobian of F/2, so solve (J)(δ) = -F/2
                e2 = (-0.5 * F1 * j22 + j12 * 0.5 * F2) / det
                e4 = (-0.5 * F2 * j11 + j21 * 0.5 * F1) / det
                y2, y4 = y2 + e2, y4 + e4
                if abs(e2) + abs(e4) <= 1e-15 * (1 + abs(y2) + abs(y4)):
                    break
            F1, F2, _, _, _ = self._scalar_step(float(phis[k + 1]), y2, y4)
            if not (abs(F1) < 1e-10 * scale and abs(F2) < 1e-10 * scale) or abs(y4 - x4) > 0.5:
                raise RotationError(
                    f"crank cannot turn fully: the class-IV group cannot follow the crank past "
                    f"φ = {np.degrees(phis[k + 1]) % 360:.2f}°")
            x2, x4 = y2, y4
            xs[k + 1] = (x2, x4)
        closing = np.angle(np.exp(1j * (xs[-1] - xs[0])))
        if np.max(np.abs(closing)) > 1e-8:
            raise RotationError(
                f"crank cannot turn fully: after one turn the group does not return to its starting "
                f"assembly (θ2 and ψ differ by {np.degrees(closing[0]):.3g}°, {np.degrees(closing[1]):.3g}°)")
        turns = np.round((xs[-1] - xs[0]) / (2 * np.pi))
        return phis, xs, turns, t0

    # -- structure and motion (the curved-slot twin comes from them: Mechanism.curved_slot_twin) ---------
    def structure(self) -> Structure:
        """Crank O→A and the class-IV group: coupler A-Q-P (axis Q→P), link 3 Q→R, link 5 P→T, output R-T-E.

        The output turns about E (axis at ψ); seven revolute pairs. The coupler 2 and the output 4 are
        triangles (ternary links), link 3 = QR, link 5 = PT, the frame 6.

        Returns
        -------
        Structure
            Links, pairs and structural groups, from which the drawing, centres, force model and counts derive.

        Examples
        --------
        >>> from mechlab.mechanisms.sixbar_iv import example
        >>> example().structure().numbers()
        {'crank': 1, 'coupler': 2, 'link 3': 3, 'output': 4, 'link 5': 5, 'frame': 6}
        """
        return Structure(
            (Link("crank", "O", ("O", "A"), self.crank, joints=("O", "A")),
             Link("coupler", "A", ("Q", "P"), self.qp, joints=("A", "Q", "P", "A")),
             Link("link 3", "Q", ("Q", "R"), self.link3, joints=("Q", "R")),
             Link("link 5", "P", ("P", "T"), self.link5, joints=("P", "T")),
             Link("output", "E", output_axis, joints=("R", "T", "E", "R"))),
            (Pair("revolute", "O", FRAME, "crank", "O"), Pair("revolute", "A", "crank", "coupler", "A"),
             Pair("revolute", "Q", "coupler", "link 3", "Q"), Pair("revolute", "P", "coupler", "link 5", "P"),
             Pair("revolute", "R", "link 3", "output", "R"), Pair("revolute", "T", "link 5", "output", "T"),
             Pair("revolute", "E", FRAME, "output", "E")),
            (("coupler", "link 3", "link 5", "output"),), "output", scale=self.ground,
            numbering=("crank", "coupler", "link 3", "output", "link 5", FRAME))

    def motion(self, phi) -> AngularMotion:
        """Joint paths (O, A, Q, P, R, T, E) and ψ, ψ', ψ'' of link 4 at crank angles φ.

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
        >>> from mechlab.mechanisms.sixbar_iv import example
        >>> example().motion(1.0).output
        Law(ψ = 2.64387 rad = 151.483°, ψ′ = -0.0346817, ψ″ = 0.50691)
        """
        phi = as_angles(phi)
        n = len(phi)
        phis, xs, turns, _ = self._grid
        # interpolated starting guess on the followed turn (θ2 and ψ may make whole turns per turn)
        k = np.floor((phi - np.pi) / (2 * np.pi))
        local = phi - 2 * np.pi * k
        guess = np.stack([np.interp(local, phis, xs[:, j]) for j in (0, 1)], axis=-1) + k[:, None] * 2 * np.pi * turns
        A = crank_point(self.crank, phi)
        x = self._newton(A.p, guess)
        dx, J = self._velocity(A, x)
        if np.any(np.abs(np.linalg.det(J)) < 1e-12):
            i = int(np.argmin(np.abs(np.linalg.det(J))))
            raise SingularityError(f"dead position of the class-IV group at φ = {np.degrees(phi[i]):.2f}°")
        Q, P, R, T, E = self._joints(A.p, x)
        w2, w4 = dx[:, 0], dx[:, 1]
        dQ = A.d + w2[:, None] * perp(Q - A.p)
        dP = A.d + w2[:, None] * perp(P - A.p)
        dR = w4[:, None] * perp(R - E)
        dT = w4[:, None] * perp(T - E)
        rq, rp = dQ - dR, dP - dT
        rhs = -np.stack([
            dot(rq, rq) + dot(Q - R, A.dd - (w2**2)[:, None] * (Q - A.p) + (w4**2)[:, None] * (R - E)),
            dot(rp, rp) + dot(P - T, A.dd - (w2**2)[:, None] * (P - A.p) + (w4**2)[:, None] * (T - E)),
        ], axis=-1)
        ddx = np.linalg.solve(J, rhs[..., None])[..., 0]
        a2, a4 = ddx[:, 0], ddx[:, 1]
        ddQ = A.dd + a2[:, None] * perp(Q - A.p) - (w2**2)[:, None] * (Q - A.p)
        ddP = A.dd + a2[:, None] * perp(P - A.p) - (w2**2)[:, None] * (P - A.p)
        ddR = a4[:, None] * perp(R - E) - (w4**2)[:, None] * (R - E)
        ddT = a4[:, None] * perp(T - E) - (w4**2)[:, None] * (T - E)
        pts = {"O": fixed_point((0.0, 0.0), n), "A": A, "Q": PointPath(Q, dQ, ddQ), "P": PointPath(P, dP, ddP),
               "R": PointPath(R, dR, ddR), "T": PointPath(T, dT, ddT), "E": fixed_point((self.ground, 0.0), n)}
        # transmission angle of the inner four-bar at P (between P→Q and P→T)
        a, b = Q - P, T - P
        mu = np.arccos(np.clip(dot(a, b) / (np.hypot(*a.T) * np.hypot(*b.T)), -1.0, 1.0))
        return AngularMotion(phi, pts, mu, x[:, 1], w4, a4)

    def inner_angle(self, phi) -> AnglePath:
        """θ (angle of R→Q in the output link's frame) with its analogs: the pin's place on the slot.

        Parameters
        ----------
        phi : float or array_like
            Crank angles φ (radians).

        Returns
        -------
        AnglePath
            θ (radians) with θ' and θ''.

        Examples
        --------
        >>> from mechlab.mechanisms.sixbar_iv import example
        >>> round(float(example().inner_angle(1.0).theta), 4)
        -4.6043
        """
        mo = self.motion(phi)
        v = relative(mo.points["Q"], mo.points["R"])
        ang = vector_angle(v)
        return AnglePath(ang.theta - mo.psi, ang.d - mo.dpsi, ang.dd - mo.ddpsi)


def example() -> SixBarIV:
    """The course's class-IV six-bar: :meth:`SixBarIV.example`."""
    return SixBarIV.example()
