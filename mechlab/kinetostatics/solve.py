"""Kinetostatics by structural groups: reactions and balancing torque, checked by virtual work.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Annotated

import numpy as np

from ..errors import DimensionError, MechanismError, SingularityError
from ..geometry import PointPath, cross, dot, perp, relative, unit, vector_angle
from ..mechanisms.base import output_axis  # Body(..., axis=output_axis): readers import it from here
from ..motion import Motion, first_of
from ..validate import Point, Spec, count, number, validated
from ..validate import mechanism as instance_of
from .model import (
    FRAME,
    Eps,
    Force,
    ForceModel,
    G,
    HigherPair,
    LoadError,
    Omega,
    Prismatic,
    Revolute,
    SelfLockingError,
    StructureError,
    Torque,
)

__all__ = ["ForceResult", "Reaction", "output_axis", "solve", "virtual_work_torque"]

AnyModel = Annotated[ForceModel, instance_of(ForceModel)]
AnyMotion = Annotated[Motion, instance_of(Motion)]
Loads = Annotated[tuple, Spec("items", expected=(Force, Torque))]


def _evaluate(value, motion: Motion, shape: tuple, what: str) -> np.ndarray:
    v = value(motion) if callable(value) else value
    try:
        arr = np.broadcast_to(np.asarray(v, dtype=float), shape)
    except ValueError:
        raise LoadError(f"{what} must broadcast to shape {shape}, got shape {np.shape(v)}") from None
    if not np.all(np.isfinite(arr)):
        raise LoadError(f"{what} must be finite (got NaN or inf)")
    return arr


# --------------------------------------------------------------------------- kinematics of links
@dataclass(frozen=True, eq=False)
class _Frame:
    o: PointPath          # origin
    th: np.ndarray        # axis angle
    dth: np.ndarray       # θ'
    ddth: np.ndarray      # θ''

    def point(self, local) -> PointPath:
        """A point fixed in the link at link coordinates (ξ, η), with analogs."""
        xi, eta = local
        e = unit(self.th)
        r = xi * e + eta * perp(e)
        rp = perp(r)
        return PointPath(self.o.p + r, self.o.d + self.dth[:, None] * rp,
                         self.o.dd + self.ddth[:, None] * rp - (self.dth**2)[:, None] * r)

    def velocity_at(self, p: np.ndarray) -> np.ndarray:
        """Velocity analog of the link's point that coincides with positions ``p``."""
        return self.o.d + self.dth[:, None] * perp(p - self.o.p)


def _frames(model: ForceModel, motion: Motion) -> dict[str, _Frame]:
    n = len(motion)
    pts = motion.points
    frames = {}
    for b in model.bodies:
        if b.origin not in pts:
            raise StructureError(f"origin {b.origin!r} of {b.name} is not a joint of the motion: {sorted(pts)}")
        if b.translates:
            z = np.zeros(n)
            frames[b.name] = _Frame(pts[b.origin], np.full(n, b.axis), z, z)
        elif callable(b.axis):
            got = tuple(np.asarray(v, dtype=float) for v in b.axis(motion))
            if len(got) != 3 or not all(v.shape == (n,) and np.all(np.isfinite(v)) for v in got):
                raise StructureError(f"axis of {b.name} must give finite (θ, θ', θ'') arrays of shape ({n},)")
            th, d, dd = got
            frames[b.name] = _Frame(pts[b.origin], th, d, dd)
        else:
            P, Q = b.axis
            ang = vector_angle(relative(pts[Q], pts[P]))
            frames[b.name] = _Frame(pts[b.origin], ang.theta, ang.d, ang.dd)
    z = np.zeros(n)
    frames[FRAME] = _Frame(PointPath(np.zeros((n, 2)), np.zeros((n, 2)), np.zeros((n, 2))), z, z, z)
    return frames


def _point(motion: Motion, frame: _Frame, at) -> tuple[np.ndarray, np.ndarray]:
    """Position and velocity analog of a load's application point on a link."""
    if isinstance(at, str):
        if at not in motion.points:
            raise StructureError(f"load point {at!r} is not a joint of the motion: {sorted(motion.points)}")
        p = motion.points[at].p
        return p, frame.velocity_at(p)
    q = frame.point(at)
    return q.p, q.d


@dataclass(frozen=True, eq=False)
class _Loads:
    force: dict           # body → (n, 2) resultant of known loads
    moment: dict          # body → (n,) moment about the body origin
    power: np.ndarray     # Σ F·v' + M·θ' over all bodies (virtual power per unit ω1)


def _known_loads(model, motion, frames, loads, omega1, eps1, gravity) -> _Loads:
    n = len(motion)
    g = np.asarray(gravity, dtype=float)
    if g.shape != (2,) or not np.all(np.isfinite(g)):
        raise LoadError(f"gravity must be a finite 2-vector, got {gravity!r}")
    force = {b.name: np.zeros((n, 2)) for b in model.bodies}
    moment = {b.name: np.zeros(n) for b in model.bodies}
    power = np.zeros(n)
    w2 = omega1 * omega1

    def add(body, F, p, v):
        fr = frames[body]
        force[body] += F
        moment[body] += cross(p - fr.o.p, F)
        nonlocal power
        power = power + dot(F, v)

    for b in model.bodies:
        fr = frames[b.name]
        if b.mass > 0:
            S = fr.point(b.com)
            acc = S.dd * w2 + S.d * eps1
            add(b.name, b.mass * (g - acc), S.p, S.d)      # gravity + d'Alembert force −m·a_S
        if b.inertia > 0:
            M = -b.inertia * (fr.ddth * w2 + fr.dth * eps1)  # d'Alembert couple −J_S·ε
            moment[b.name] += M
            power = power + M * fr.dth
    names = {b.name for b in model.bodies}
    for ld in loads:
        if ld.body not in names:
            raise StructureError(f"load on unknown body {ld.body!r}; bodies: {sorted(names)}")
        fr = frames[ld.body]
        if isinstance(ld, Force):
            F = _evaluate(ld.value, motion, (n, 2), f"force on {ld.body}")
            p, v = _point(motion, fr, ld.at)
            add(ld.body, F, p, v)
        elif isinstance(ld, Torque):
            M = _evaluate(ld.value, motion, (n,), f"torque on {ld.body}")
            moment[ld.body] += M
            power = power + M * fr.dth
        else:
            raise LoadError(f"a load must be a Force or a Torque, got {type(ld).__name__}")
    return _Loads(force, moment, power)


@validated
def virtual_work_torque(model: AnyModel, motion: AnyMotion, loads: Loads = (), omega1: Omega = 1.0, eps1: Eps = 0.0,
                        gravity: Point = (0.0, -G)) -> np.ndarray:
    """Frictionless balancing torque from the power balance alone (no reactions).

    All forces — gravity, d'Alembert inertia forces and couples, external loads — and the balancing torque
    M_b do no net work in a virtual displacement δφ of the ideal mechanism, so M_b = −Σ(F_i·r_i' + M_i·θ_i')
    with r_i', θ_i' the analogs of the load points and link angles: Zhukovsky's lever in analytic form.

    Parameters
    ----------
    model : ForceModel
        Bodies with their masses, pairs and groups.
    motion : Motion
        The mechanism's motion (a scalar φ or an array of crank angles, radians).
    loads : tuple of Force or Torque, optional
        External loads on the model's bodies.
    omega1 : float, optional
        Crank speed ω1 (rad/s).
    eps1 : float, optional
        Crank acceleration ε1 (rad/s²).
    gravity : tuple of float, optional
        Gravity vector (m/s²).

    Returns
    -------
    numpy.ndarray
        M_b on the crank (N·m, counter-clockwise positive), one per crank angle (a scalar at a scalar φ).

    Raises
    ------
    StructureError
        If a body's origin or a load's point is not a joint of the motion.
    LoadError
        For a load or gravity of the wrong shape or not finite.

    Examples
    --------
    >>> import numpy as np
    >>> from mechlab.kinetostatics import press, virtual_work_torque
    >>> k = press()
    >>> np.round(virtual_work_torque(k.model, k.motion(np.array([np.pi / 2])), k.loads, k.omega1), 4)
    array([-2.2425])
    >>> round(float(virtual_work_torque(k.model, k.motion(np.pi / 2), k.loads, k.omega1)), 4)
    -2.2425
    """
    if np.ndim(motion.phi) == 0:
        return first_of(virtual_work_torque(model, motion.as_arrays(), loads, omega1, eps1, gravity))
    frames = _frames(model, motion)
    kl = _known_loads(model, motion, frames, loads, omega1, eps1, gravity)
    crank = frames[model.crank]
    return -kl.power / crank.dth


# --------------------------------------------------------------------------- results
@dataclass(frozen=True, eq=False)
class Reaction:
    """Reaction in one pair over the cycle: force and couple of link ``a`` on link ``b``.

    Parameters
    ----------
    pair : str
        The pair's name.
    a, b : str
        The links: the reaction is the force of ``a`` on ``b``.
    point : numpy.ndarray
        The pair's joint positions (m), (n, 2) or (2,) at one angle.
    force : numpy.ndarray
        The reaction force (N), with the friction force of a sliding pair.
    couple : numpy.ndarray
        The pair's reaction couple (prismatic) plus the friction couple (revolute) (N·m).
    normal : numpy.ndarray or None, optional
        The signed normal force N (prismatic, higher pairs; None for a revolute).

    Examples
    --------
    >>> import numpy as np
    >>> from mechlab.kinetostatics import press
    >>> reaction = press().forces(np.pi / 2).reactions["B"]
    >>> reaction.a, reaction.b, round(float(reaction.magnitude), 4)
    ('rod', 'slider', 20.2976)
    """

    pair: str
    a: str
    b: str
    point: np.ndarray
    force: np.ndarray
    couple: np.ndarray
    normal: np.ndarray | None = None

    @property
    def magnitude(self) -> np.ndarray:
        """The reaction force's magnitude |R|.

        Returns
        -------
        numpy.ndarray or float
            |R| (N), one per crank angle.
        """
        return np.hypot(self.force[..., 0], self.force[..., 1])  # one angle (2,) or many (n, 2)


@dataclass(frozen=True, eq=False)
class ForceResult:
    """Kinetostatics over the crank angles ``phi`` at crank speed ω1 and acceleration ε1 (from :func:`solve`).

    Parameters
    ----------
    phi : numpy.ndarray
        Crank angles (radians).
    omega1 : float
        Crank speed ω1 (rad/s).
    eps1 : float
        Crank acceleration ε1 (rad/s²).
    reactions : Mapping[str, Reaction]
        The reaction in every pair, by pair name.
    torque : numpy.ndarray
        Balancing torque on the crank M_b (N·m), from the groups.
    torque_power : numpy.ndarray
        The same from the power balance (with friction losses) (N·m).
    ideal_torque : numpy.ndarray
        Frictionless M_b from virtual work (N·m).
    losses : numpy.ndarray
        Friction power per unit ω1 (N·m, ≥ 0).
    residual : float
        Largest equilibrium residual of any link, relative.
    iterations : int
        Friction passes used (1 without friction).
    model : ForceModel
        The model solved.

    Examples
    --------
    >>> import numpy as np
    >>> from mechlab.kinetostatics import press
    >>> result = press().forces(np.pi / 2)
    >>> round(float(result.torque), 4), sorted(result.reactions)
    (-2.2425, ['A', 'B', 'O', 'guide'])
    """

    phi: np.ndarray
    omega1: float
    eps1: float
    reactions: Mapping[str, Reaction]
    torque: np.ndarray          # balancing torque on the crank, from the groups
    torque_power: np.ndarray    # the same from the power balance (with friction losses)
    ideal_torque: np.ndarray    # frictionless, from virtual work
    losses: np.ndarray          # friction power per unit ω1 (≥ 0)
    residual: float             # largest equilibrium residual of any link, relative
    iterations: int
    model: ForceModel = field(repr=False)

    @property
    def power(self) -> np.ndarray:
        """Driving power M_b·ω1.

        Returns
        -------
        numpy.ndarray or float
            Power (W), one per crank angle.
        """
        return self.torque * self.omega1

    @property
    def power_gap(self) -> float:
        """Largest |M_b(groups) − M_b(power balance)|, relative to the largest |M_b|.

        Returns
        -------
        float
            The relative gap (≈ 1e-15 for a correct solution).
        """
        return float(np.max(np.abs(self.torque - self.torque_power)) / (np.max(np.abs(self.torque)) + 1e-300))

    def verify(self, tol: float = 1e-9) -> str:
        """The built-in checks: M_b from the groups equals the power balance's and every link is in equilibrium.

        Parameters
        ----------
        tol : float, optional
            Relative tolerance of both checks.

        Returns
        -------
        str
            A one-line summary with the two numbers.

        Raises
        ------
        MechanismError
            If either check fails (the message gives the numbers).

        Examples
        --------
        >>> from mechlab.kinetostatics import press
        >>> k = press()
        >>> k.forces(k.turn(73)).verify()
        'M_b from the groups = power balance to ...; every link in equilibrium to ...'
        """
        if not (self.power_gap <= tol and self.residual <= tol):
            raise MechanismError(f"kinetostatics check failed: groups vs power balance {self.power_gap:.2e}, "
                                 f"equilibrium residual {self.residual:.2e} (tolerance {tol:g})")
        return (f"M_b from the groups = power balance to {self.power_gap:.1e}; every link in equilibrium "
                f"to {self.residual:.1e}")

    def efficiency(self) -> np.ma.MaskedArray:
        """Instantaneous efficiency η = 1 − P_friction/P_drive = M_ideal/M_b (Kinitsky (1994), ch. 3).

        Defined where the drive delivers power and the loads absorb it (P_drive > 0 and M_ideal·ω1 > 0);
        masked elsewhere — where the links' inertia or gravity drive the crank, an instantaneous efficiency has
        no meaning.

        Returns
        -------
        numpy.ma.MaskedArray
            η per crank angle, masked where undefined.

        Examples
        --------
        >>> from mechlab.kinetostatics import press
        >>> k = press(f=0.1)
        >>> int(k.forces(k.turn(73)).efficiency().count())  # angles where η is defined
        47
        """
        s = np.sign(self.omega1) or 1.0
        drive = self.torque * s
        tiny = 1e-12 * (np.max(np.abs(self.torque)) + 1e-300)
        defined = (drive > tiny) & (self.ideal_torque * s > tiny)
        eta = np.ones_like(drive)
        np.divide(self.losses, drive, out=eta, where=defined)
        return np.ma.masked_array(np.where(defined, 1.0 - eta, 0.0), mask=~defined)

    def cycle_efficiency(self, moving: np.ndarray | None = None, how: str = "mean") -> float:
        """Cycle efficiency over the positions where the output moves.

        Parameters
        ----------
        moving : numpy.ndarray of bool, optional
            Mask of the positions to use, shaped like ``phi``; all by default.
        how : {"mean", "work"}, optional
            ``"mean"``: the thesis' definition (Kinitsky (1994), ch. 3), the arithmetic mean of the
            instantaneous efficiencies where η is defined; ``"work"``: 1 − ∫P_friction dφ / ∫P_drive dφ.

        Returns
        -------
        float
            The cycle efficiency.

        Raises
        ------
        DimensionError
            If ``moving`` does not match ``phi``'s shape, or ``how`` is neither ``"mean"`` nor ``"work"``.
        MechanismError
            If the drive delivers no power where the output moves (``"mean"``) or no work over the cycle
            (``"work"``).

        Examples
        --------
        >>> from mechlab.kinetostatics import press
        >>> k = press(f=0.1)
        >>> result = k.forces(k.turn(73))
        >>> round(result.cycle_efficiency(), 4), round(result.cycle_efficiency(how="work"), 4)
        (0.8365, 0.932)
        """
        sel = np.ones(len(self.phi), bool) if moving is None else np.asarray(moving, bool)
        if sel.shape != self.phi.shape:
            raise DimensionError(f"moving must be a mask of shape {self.phi.shape}, got {sel.shape}")
        if how == "mean":
            eta = self.efficiency()
            use = sel & ~np.ma.getmaskarray(eta)
            if not np.any(use):
                raise MechanismError("cycle efficiency undefined: the drive delivers no power where the output moves")
            return float(np.mean(eta.data[use]))
        if how == "work":
            s = np.sign(self.omega1) or 1.0
            w = np.where(sel, 1.0, 0.0)
            a_drive = np.trapezoid(w * self.torque * s, self.phi)
            a_loss = np.trapezoid(w * self.losses, self.phi)
            if not a_drive * np.sign(self.phi[-1] - self.phi[0]) > 0:
                raise MechanismError(f"cycle efficiency undefined: the drive's work over the cycle is {a_drive:.4g} ≤ "
                                     f"0")
            return float(1.0 - a_loss / a_drive)
        raise DimensionError(f"how must be 'mean' or 'work', got {how!r}")


# --------------------------------------------------------------------------- solver
def _normals(model, motion, frames):
    """Unit normal (prismatic: to the guide; higher pair: common normal) for each pair."""
    out = {}
    for p in model.pairs:
        fa = frames[p.a]
        if isinstance(p, Prismatic):
            out[p.name] = perp(unit(fa.th + p.angle))
        elif isinstance(p, HigherPair):
            if callable(p.normal):
                nv = np.asarray(p.normal(motion), dtype=float)
                if nv.shape != (len(motion), 2) or not np.all(np.isfinite(nv)):
                    raise LoadError(f"normal of {p.name} must be finite unit vectors of shape {(len(motion), 2)}")
                out[p.name] = nv / np.hypot(nv[:, 0], nv[:, 1])[:, None]
            else:
                out[p.name] = unit(fa.th + float(p.normal))
    return out


def _sliding(p, frames, P, nrm):
    """Relative motion at a pair per unit ω1: θ_b' − θ_a' (revolute) or tangential slip (sliding pairs)."""
    fa, fb = frames[p.a], frames[p.b]
    if isinstance(p, Revolute):
        return fb.dth - fa.dth, None
    t = -perp(nrm)  # tangent (guide direction for a prismatic pair)
    return dot(fb.velocity_at(P) - fa.velocity_at(P), t), t


@validated
def solve(model: AnyModel, motion: AnyMotion, loads: Loads = (), omega1: Omega = 1.0, eps1: Eps = 0.0,
          gravity: Point = (0.0, -G), *, maxiter: Annotated[int, count(1, 10_000)] = 100,
          tol: Annotated[float, number(0.0, 1.0, open=True)] = 1e-12) -> ForceResult:
    """Reactions in every pair and the balancing torque, group by group (the SibSIU proceedings' method).

    Groups are solved in ``model.groups`` order (output first), then the crank. Each group's 3k equilibrium
    equations (ΣF = 0, ΣM about each link's origin = 0) form a batch of linear systems in its unknown
    reactions, solved at every crank angle at once. A motion at one scalar φ gives the results at that
    angle as scalars.

    Friction (any pair with f > 0) is linearised on its senses: with the direction ê of a journal's
    reaction R and the sign of a normal force N from the previous pass, f·r·|R| = f·r·ê·R and
    f·|N| = f·sgn(N)·N are linear in the unknowns and go into each group's matrix; the passes stop when
    ê·R = |R| to 1e-12 and every sgn N is consistent (3-6 passes; the first is frictionless). Unlike
    friction lagging a full pass behind, this converges also where f·tan(pressure angle) > 1. No
    consistent senses, or a singular group matrix with friction, is self-locking. The sense of sliding
    comes from the analogs and the sign of ω1 (ω1 = 0: the start of a motion with ω1 > 0). Prismatic
    friction is f·|N| with N the resultant normal force (edge pressures not modelled).

    Parameters
    ----------
    model : ForceModel
        Bodies with their masses, pairs (with friction) and groups.
    motion : Motion
        The mechanism's motion (a scalar φ or an array of crank angles, radians).
    loads : tuple of Force or Torque, optional
        External loads on the model's bodies.
    omega1 : float, optional
        Crank speed ω1 (rad/s).
    eps1 : float, optional
        Crank acceleration ε1 (rad/s²).
    gravity : tuple of float, optional
        Gravity vector (m/s²).
    maxiter : int, optional
        Largest number of friction passes.
    tol : float, optional
        Convergence tolerance of the friction senses (0 < tol < 1).

    Returns
    -------
    ForceResult
        Reactions, balancing torque (from the groups and from the power balance), losses and checks.

    Raises
    ------
    StructureError
        If a pair's, body's or load's point is not a joint of the motion.
    LoadError
        For a load of the wrong shape or not finite.
    SingularityError
        Where a group cannot carry its loads (a dead point).
    SelfLockingError
        Where friction locks the mechanism.

    Examples
    --------
    >>> import numpy as np
    >>> from mechlab.kinetostatics import press, solve
    >>> k = press()
    >>> result = solve(k.model, k.motion(np.pi / 2), k.loads, k.omega1)
    >>> round(float(result.torque), 4)
    -2.2425
    """
    if np.ndim(motion.phi) == 0:
        return first_of(solve(model, motion.as_arrays(), loads, omega1, eps1, gravity, maxiter=maxiter, tol=tol))
    n = len(motion)
    pts = motion.points
    for p in model.pairs:
        if p.point not in pts:
            raise StructureError(f"point {p.point!r} of pair {p.name} is not a joint of the motion: {sorted(pts)}")
    frames = _frames(model, motion)
    kl = _known_loads(model, motion, frames, loads, omega1, eps1, gravity)
    nrm = _normals(model, motion, frames)
    sense = np.sign(omega1) or 1.0
    P = {p.name: pts[p.point].p for p in model.pairs}
    slip = {p.name: _sliding(p, frames, P[p.name], nrm.get(p.name)) for p in model.pairs}
    rough = [p for p in model.pairs if p.friction > 0 and (not isinstance(p, Revolute) or p.radius > 0)]
    crank_dth = frames[model.crank].dth
    spread = np.concatenate([P[p.name] for p in model.pairs])
    length = float(np.max(np.ptp(spread, axis=0))) or 1.0   # size of the mechanism

    def pass_(dirs):
        """One group-by-group pass with friction linearised at ``dirs`` (pair → direction
        ê of R for a journal, sign of N for a sliding pair): f·r·|R| ≈ f·r·ê·R and
        f·|N| ≈ f·sgn(N)·N are linear in the unknowns, so each group stays a linear system."""
        force, couple, normal, fric = {}, {}, {}, {}   # pair → force/couple of a on b, N, friction on b
        torque = None
        for group in (*model.groups, (model.crank,)):
            unknown = model._unknown_pairs(group, set(force))
            is_crank = group == (model.crank,)
            m = 3 * len(group)
            A = np.zeros((n, m, m))
            rhs = np.zeros((n, m))
            row = {b: 3 * i for i, b in enumerate(group)}
            for b in group:
                r = row[b]
                rhs[:, r:r + 2] -= kl.force[b]
                rhs[:, r + 2] -= kl.moment[b]
            # known reactions and friction of solved pairs acting on this group's links
            for name in force:
                p = by_name[name]
                parts = [(force[name], couple[name])] + ([fric[name]] if name in fric else [])
                for F, C in parts:
                    for body, s in ((p.b, 1.0), (p.a, -1.0)):
                        if body in row:
                            r, o = row[body], frames[body].o.p
                            rhs[:, r:r + 2] -= s * F
                            rhs[:, r + 2] -= s * (cross(P[name] - o, F) + C)
            col = 0
            layout = []
            couple_cols = []
            for p in unknown:
                layout.append((p, col))
                rough_here = p.name in dirs
                for body, s in ((p.b, 1.0), (p.a, -1.0)):
                    if body not in row:
                        continue
                    r, d = row[body], P[p.name] - frames[body].o.p
                    if isinstance(p, Revolute):
                        A[:, r, col] += s
                        A[:, r + 1, col + 1] += s
                        A[:, r + 2, col] += -s * d[:, 1]
                        A[:, r + 2, col + 1] += s * d[:, 0]
                        if rough_here:   # friction couple on b: k·(ê·R), k = −f·r·sgn(ω_b − ω_a)
                            k = fcoef[p.name]
                            A[:, r + 2, col] += s * k * dirs[p.name][:, 0]
                            A[:, r + 2, col + 1] += s * k * dirs[p.name][:, 1]
                    else:
                        e = nrm[p.name]
                        A[:, r, col] += s * e[:, 0]
                        A[:, r + 1, col] += s * e[:, 1]
                        A[:, r + 2, col] += s * cross(d, e)
                        if isinstance(p, Prismatic):
                            A[:, r + 2, col + 1] += s
                        if rough_here:   # friction force on b: k·sgn(N)·N·t, k = −f·sgn(slip)
                            k = fcoef[p.name] * dirs[p.name]
                            t = slip[p.name][1]
                            A[:, r, col] += s * k * t[:, 0]
                            A[:, r + 1, col] += s * k * t[:, 1]
                            A[:, r + 2, col] += s * k * cross(d, t)
                if isinstance(p, Prismatic):
                    couple_cols.append(col + 1)
                col += p.n_unknowns
            if is_crank:
                A[:, 2, col] = 1.0
                couple_cols.append(col)
            # Moment rows and couple columns carry a length: scale them so the conditioning
            # test does not depend on the unit of length.
            S = A.copy()
            S[:, 2::3, :] /= length
            S[:, :, couple_cols] /= length
            cond = np.linalg.cond(S)
            if np.any(~(cond < 1e12)):
                i = int(np.argmax(~(cond < 1e12)))
                at = f"at φ = {np.degrees(motion.phi[i]):.2f}°"
                if dirs:
                    raise SelfLockingError(
                        f"group {group} locks {at}: with friction (f up to {f_max:g}) its equilibrium equations "
                        f"are singular (condition number {cond[i]:.2e}) — no finite driving force moves it")
                raise SingularityError(
                    f"group {group} cannot carry its loads {at}: its equilibrium equations are singular "
                    f"(condition number {cond[i]:.2e}), a dead point of the group")
            x = np.linalg.solve(A, rhs[..., None])[..., 0]
            for p, c in layout:
                if isinstance(p, Revolute):
                    R = x[:, c:c + 2].copy()
                    force[p.name] = R
                    couple[p.name] = np.zeros(n)
                    if p.name in dirs:
                        fric[p.name] = (np.zeros((n, 2)), fcoef[p.name] * dot(dirs[p.name], R))
                else:
                    N = x[:, c].copy()
                    normal[p.name] = N
                    force[p.name] = N[:, None] * nrm[p.name]
                    couple[p.name] = x[:, c + 1].copy() if isinstance(p, Prismatic) else np.zeros(n)
                    if p.name in dirs:
                        fric[p.name] = ((fcoef[p.name] * dirs[p.name] * N)[:, None] * slip[p.name][1], np.zeros(n))
            if is_crank:
                torque = x[:, col].copy()
        return force, couple, normal, fric, torque

    def directions(force, normal, old):
        """ê = R/|R| (journals) and sgn N (sliding pairs); where R = 0 the old direction stays."""
        new = {}
        for p in rough:
            if isinstance(p, Revolute):
                R = force[p.name]
                mag = np.hypot(R[:, 0], R[:, 1])
                e = old[p.name].copy() if p.name in old else np.zeros((n, 2))
                ok = mag > 0
                e[ok] = R[ok] / mag[ok, None]
                new[p.name] = e
            else:
                new[p.name] = np.sign(normal[p.name])
        return new

    by_name = {p.name: p for p in model.pairs}
    fcoef = {}
    for p in rough:
        rel, _ = slip[p.name]
        sgn = np.sign(rel * sense)
        fcoef[p.name] = -p.friction * (p.radius if isinstance(p, Revolute) else 1.0) * sgn
    f_max = max((p.friction for p in rough), default=0.0)

    force, couple, normal, fric, torque = pass_({})
    iterations = 1
    if rough:
        dirs = directions(force, normal, {})
        flips = {p.name: np.zeros(n, int) for p in rough}
        for iterations in range(2, maxiter + 2):  # noqa: B007  the count is named in the error below
            force, couple, normal, fric, torque = pass_(dirs)
            # consistent when the linearisation is exact: ê·R = |R| and sgn(N)·N = |N|
            bad = np.zeros(n, bool)
            for p in rough:
                if isinstance(p, Revolute):
                    R = force[p.name]
                    mag = np.hypot(R[:, 0], R[:, 1])
                    bad |= mag - dot(dirs[p.name], R) > tol * (mag + np.abs(torque) / length + 1e-300)
                else:
                    bad |= (dirs[p.name] * normal[p.name] < 0) | ((dirs[p.name] == 0) & (normal[p.name] != 0))
            if not np.any(bad):
                break
            new = directions(force, normal, dirs)
            for name, d in new.items():   # a sense that keeps reversing: no consistent solution
                flips[name] += (np.sum(d * dirs[name], axis=-1) if d.ndim == 2 else d * dirs[name]) < 0
            dirs = new
            stuck = np.any([v >= 3 for v in flips.values()], axis=0)
            if np.any(stuck):
                bad = stuck
                break
        if np.any(bad):
            i = int(np.argmax(bad))
            raise SelfLockingError(
                f"friction has no consistent solution at φ = {np.degrees(motion.phi[i]):.2f}° after {iterations} "
                f"passes (the senses of the friction forces keep reversing): the mechanism is self-locking "
                f"there at f = {f_max:g}")

    loss = np.zeros(n)
    for p in rough:   # friction power per unit ω1: f·r·|R|·|ω_rel| + f·|N|·|v_rel|
        rel, _ = slip[p.name]
        if isinstance(p, Revolute):
            mag = p.friction * p.radius * np.hypot(force[p.name][:, 0], force[p.name][:, 1])
        else:
            mag = p.friction * np.abs(normal[p.name])
        loss += mag * np.abs(rel)

    reactions = {}
    for p in model.pairs:
        F, C = force[p.name], couple[p.name]
        if p.name in fric:
            F, C = F + fric[p.name][0], C + fric[p.name][1]
        reactions[p.name] = Reaction(p.name, p.a, p.b, P[p.name], F, C, normal.get(p.name))

    residual = _residual(model, frames, kl, reactions, torque)
    torque_power = (sense * loss - kl.power) / crank_dth
    ideal = -kl.power / crank_dth
    return ForceResult(motion.phi, omega1, eps1, reactions, torque, torque_power, ideal, loss, residual,
                       iterations, model)


def _residual(model, frames, kl, reactions, torque) -> float:
    """Largest |ΣF|, |ΣM| over the links, relative to the largest load or reaction."""
    resF = {b.name: kl.force[b.name].copy() for b in model.bodies}
    resM = {b.name: kl.moment[b.name].copy() for b in model.bodies}
    scale = max([np.max(np.abs(v)) for v in kl.force.values()] + [np.max(np.abs(v)) for v in kl.moment.values()]
                + [np.max(np.abs(r.force)) for r in reactions.values()] + [np.max(np.abs(torque)), 1e-300])
    for r in reactions.values():
        for body, s in ((r.b, 1.0), (r.a, -1.0)):
            if body == FRAME:
                continue
            resF[body] += s * r.force
            resM[body] += s * (cross(r.point - frames[body].o.p, r.force) + r.couple)
    resM[model.crank] += torque
    worst = max(max(np.max(np.abs(resF[b])), np.max(np.abs(resM[b]))) for b in resF)
    return float(worst / scale)

