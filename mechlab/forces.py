"""Kinetostatics: loads, reactions group by group, balancing torque, friction, efficiency, drive.

The method is the one seed 003 (SibSIU proceedings, "Kinetostatic analysis of the
slider-crank mechanism with an additional link", formulas (1)-(5) and the force plans
of its Figs. 2-5) applies by hand: split the mechanism into structural groups of zero
mobility (Assur groups), load every link with its gravity, its d'Alembert inertia
force and couple and the external loads, and solve the groups **from the output back
to the crank**, each group's reactions becoming known loads on the links it is
attached to; the crank (the leading link) is solved last and gives the balancing
(driving) torque. Here every group is solved at once for all crank angles: the
3·k equilibrium equations of its k links are a batch of small linear systems.

Stable API (used by the chapters on Chebyshev six-bars and Geneva drives)
-------------------------------------------------------------------------
Structure (frozen dataclasses; lengths and masses in one consistent unit system —
with metres, kilograms and rad/s, forces come out in N and torques in N·m):

* ``Body(name, origin, axis=0.0, mass=0, inertia=0, com=(0, 0), length=0)`` — a link.
  ``origin`` is a joint (a key of ``motion.points``) fixed on the link; ``axis`` is
  its x axis: a pair of joint names ``(P, Q)`` (direction P→Q, the two points need not
  both lie on the link, the direction must be fixed in it), a constant angle
  (a translating link), or ``axis(motion) → (θ, θ', θ'')`` such as ``output_axis``.
  ``com`` = centre of mass in link coordinates (along the axis, to its left);
  ``inertia`` = moment of inertia J_S about the centre of mass.
* ``Revolute(name, a, b, point, friction=0, radius=0)`` — turning pair at a joint;
  ``friction`` is Coulomb's f, ``radius`` the journal radius r (friction couple f·r·|R|).
* ``Prismatic(name, a, b, point, angle=0, friction=0)`` — link b slides on link a
  along a guide at ``angle`` to a's axis (absolute when a is the frame); reaction =
  normal force N plus a couple (the offset of N along the guide); friction f·|N|.
* ``HigherPair(name, a, b, point, normal, friction=0)`` — contact at the moving point
  ``point`` with the common normal at angle ``normal`` to a's axis, or
  ``normal(motion) → (n, 2)`` unit vectors (a curved slot, a cam); reaction N along it.
* ``ForceModel(bodies, pairs, groups, crank, pivot)`` — ``groups`` lists the structural
  groups (tuples of body names) in solving order, output first; ``crank`` is the
  leading link turning about the joint ``pivot``. Pair ``a`` or ``b`` may be ``FRAME``.
  ``model.with_body(name, mass=…, inertia=…, com=…)``, ``model.with_friction(f, radius)``
  return modified copies. ``model_for(mechanism)`` builds the model of a FourBar,
  SliderCrank, SlottedLink or SineMechanism (massless, frictionless, com mid-link).

Loads: ``Force(body, at, value)`` (``at`` a joint name or link coordinates) and
``Torque(body, value)``; a value is a constant, an array over the crank angles, or a
callable ``value(motion)`` returning one (so the load follows any sampling).

Analysis:

* ``solve(model, motion, loads=(), omega1=1.0, eps1=0.0, gravity=(0, -9.81))`` →
  :class:`ForceResult` with ``reactions[name]`` (:class:`Reaction`: point, force of a
  on b, couple, normal force), ``torque`` (balancing torque on the crank, from the
  groups), ``torque_power`` (the same from the power balance, computed independently),
  ``ideal_torque`` (without friction, by virtual work), ``losses`` (friction power per
  unit ω1), ``residual`` (largest equilibrium residual of any link), ``verify(tol=1e-9)``
  (both built-in checks, raises if either fails), ``efficiency()``, ``cycle_efficiency(...)``.
* ``virtual_work_torque(model, motion, loads, omega1, eps1, gravity)`` — the frictionless
  balancing torque from the power balance alone: M_b = −Σ(F_i·v_i + M_i·ω_i)/ω1
  (Zhukovsky's lever in analytic form).
* ``drive(torque, phi, omega1, overload=2.0, efficiency=1.0)`` → :class:`Drive` — the
  course's one rule for the motor of a crank without a flywheel (the Geneva's
  :func:`mechlab.geneva.drive` calls it): motor torque M/η where the motor drives, M·η
  where it is driven back; mean power ⟨M_m⟩·ω1 (seed 004, last section) for the energy;
  nominal torque max(M_rms, M_peak/k) — the rms (equivalent) torque for the heating, the
  peak within the overload factor k; ``choose(catalogue)`` picks a motor.
* ``Kinetostatics(mechanism, model, loads, omega1, eps1, gravity)`` — a mechanism with
  its loads: ``.motion(phi)``/``.cycle(n)`` delegate to the mechanism, ``.forces(phi)``
  solves; :mod:`mechlab.draw.forces` draws it with reaction arrows (``animate`` works).
* The chapter's examples: ``press(...)`` (a crank press, the resistance ``press_load(P,
  work_fraction)`` on its slider) and ``rocker_drive(...)`` (a four-bar with a resisting
  torque on the rocker), both returning a Kinetostatics; ``rpm_to_rad(rpm)``.

Friction is solved by **linearisation and iteration on its senses**: with the direction
ê of a journal's reaction R and the sign of a sliding pair's normal force N taken from
the previous pass, the friction couple f·r·|R| = f·r·ê·R and the friction force
f·|N| = f·sgn(N)·N are *linear* in the unknowns, so they go into each group's matrix
and every pass is still a linear group-by-group solve (the first pass is frictionless).
The passes stop when the linearisation is exact (ê·R = |R| to 1e-12, every sgn N
consistent) — usually after 3-6 passes. A friction force that is less than a full
pass behind would not converge where f·tan(pressure angle) > 1 even though a solution
exists; this scheme does. Where no consistent senses exist (a sense keeps reversing)
or the group's matrix with friction is singular, the mechanism is self-locking there:
:class:`SelfLockingError` names the crank angle. The sense of sliding comes from the
analogs and the sign of ω1 (ω1 = 0 is treated as the start of a motion with ω1 > 0).
Prismatic friction is f·|N| with N the resultant normal force (edge pressures from
the reaction couple are not modelled).

Efficiency (seed 001, chapter 3): the instantaneous efficiency from the power balance,
η = 1 − P_friction / P_drive = M_ideal / M_b, defined where the drive delivers power
and the loads absorb it (P_drive > 0 and M_ideal·ω1 > 0; elsewhere masked); the thesis' cycle efficiency is the arithmetic mean
of the instantaneous values over the period in which the output moves
(``how="mean"``); ``how="work"`` gives the energy ratio 1 − A_friction / A_drive.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from typing import Any, Callable, Mapping, Sequence

import numpy as np

from .errors import DimensionError, MechanismError, SingularityError
from .geometry import PointPath, cross, dot, perp, relative, unit, vector_angle
from .motion import Motion

FRAME = "frame"
G = 9.81


# --------------------------------------------------------------------------- errors
class MassError(DimensionError):
    """A mass or moment of inertia is negative or not finite."""


class FrictionError(DimensionError):
    """A friction coefficient or journal radius is out of range."""


class LoadError(DimensionError):
    """A load's value has the wrong shape or is not finite."""


class StructureError(MechanismError):
    """The force model's links, pairs and groups do not make statically solvable groups."""


class SelfLockingError(MechanismError):
    """Friction admits no consistent solution (or makes a group singular): the mechanism locks."""


def _nonneg(name: str, value, exc) -> float:
    try:
        x = float(value)
    except (TypeError, ValueError):
        raise exc(f"{name} must be a number, got {value!r}") from None
    if not np.isfinite(x) or x < 0:
        raise exc(f"{name} must be a finite number ≥ 0, got {x:g}")
    return x


def _friction(name: str, f) -> float:
    f = _nonneg(f"friction coefficient of {name}", f, FrictionError)
    if f >= 1.0:
        raise FrictionError(f"friction coefficient of {name} must satisfy 0 ≤ f < 1, got f = {f:g}")
    return f


# --------------------------------------------------------------------------- structure
@dataclass(frozen=True)
class Body:
    """A link: a joint fixed on it (``origin``), its axis, and its mass properties.

    ``axis`` = (P, Q): the link's x axis points from joint P to joint Q; a float: the
    link translates with its axis at that constant angle (radians); a callable
    ``axis(motion) → (θ, θ', θ'')`` (e.g. :func:`output_axis`): any other link angle,
    such as a curved-slot link's ψ. ``com`` is the
    centre of mass in link coordinates (ξ along the axis from the origin, η to its left).
    ``length`` is informational (a bar's length, for the default slender-bar inertia).
    """

    name: str
    origin: str
    axis: Any = 0.0
    mass: float = 0.0
    inertia: float = 0.0
    com: tuple = (0.0, 0.0)
    length: float = 0.0

    def __post_init__(self):
        if self.name == FRAME:
            raise StructureError(f"a body may not be called {FRAME!r} (reserved for the frame)")
        object.__setattr__(self, "mass", _nonneg(f"mass of {self.name}", self.mass, MassError))
        object.__setattr__(self, "inertia", _nonneg(f"moment of inertia of {self.name}", self.inertia, MassError))
        object.__setattr__(self, "length", _nonneg(f"length of {self.name}", self.length, DimensionError))
        com = tuple(float(c) for c in self.com)
        if len(com) != 2 or not all(np.isfinite(com)):
            raise DimensionError(f"centre of mass of {self.name} must be two finite numbers, got {self.com!r}")
        object.__setattr__(self, "com", com)
        if callable(self.axis):
            pass
        elif not isinstance(self.axis, tuple):
            a = float(self.axis)
            if not np.isfinite(a):
                raise DimensionError(f"axis angle of {self.name} must be finite, got {a}")
            object.__setattr__(self, "axis", a)
        elif len(self.axis) != 2:
            raise StructureError(f"axis of {self.name} must be (P, Q) joint names or an angle, got {self.axis!r}")

    @property
    def translates(self) -> bool:
        return not isinstance(self.axis, tuple) and not callable(self.axis)


@dataclass(frozen=True)
class Revolute:
    """Turning pair at joint ``point``; reaction R = force of link a on link b."""

    name: str
    a: str
    b: str
    point: str
    friction: float = 0.0
    radius: float = 0.0
    n_unknowns = 2

    def __post_init__(self):
        object.__setattr__(self, "friction", _friction(self.name, self.friction))
        object.__setattr__(self, "radius", _nonneg(f"journal radius of {self.name}", self.radius, FrictionError))


@dataclass(frozen=True)
class Prismatic:
    """Link b slides on link a along a guide at ``angle`` to a's axis, through ``point`` (fixed on b)."""

    name: str
    a: str
    b: str
    point: str
    angle: float = 0.0
    friction: float = 0.0
    n_unknowns = 2

    def __post_init__(self):
        object.__setattr__(self, "friction", _friction(self.name, self.friction))
        object.__setattr__(self, "angle", float(self.angle))
        if not np.isfinite(self.angle):
            raise DimensionError(f"guide angle of {self.name} must be finite, got {self.angle}")


@dataclass(frozen=True)
class HigherPair:
    """Contact of links a and b at the moving point ``point``; reaction along the common normal.

    ``normal``: angle of the normal to a's axis, or ``normal(motion) → (n, 2)`` unit vectors.
    """

    name: str
    a: str
    b: str
    point: str
    normal: Any = np.pi / 2
    friction: float = 0.0
    n_unknowns = 1

    def __post_init__(self):
        object.__setattr__(self, "friction", _friction(self.name, self.friction))
        if not callable(self.normal):
            object.__setattr__(self, "normal", float(self.normal))
            if not np.isfinite(self.normal):
                raise DimensionError(f"normal angle of {self.name} must be finite, got {self.normal}")


Pair = Revolute | Prismatic | HigherPair


@dataclass(frozen=True)
class ForceModel:
    """Links, pairs and the structural groups (output first) of a mechanism driven by ``crank``."""

    bodies: tuple
    pairs: tuple
    groups: tuple
    crank: str
    pivot: str

    def __post_init__(self):
        object.__setattr__(self, "bodies", tuple(self.bodies))
        object.__setattr__(self, "pairs", tuple(self.pairs))
        object.__setattr__(self, "groups", tuple(tuple(g) for g in self.groups))
        names = [b.name for b in self.bodies]
        if len(set(names)) != len(names):
            raise StructureError(f"body names must be unique, got {names}")
        pnames = [p.name for p in self.pairs]
        if len(set(pnames)) != len(pnames):
            raise StructureError(f"pair names must be unique, got {pnames}")
        known = set(names) | {FRAME}
        for p in self.pairs:
            for end in (p.a, p.b):
                if end not in known:
                    raise StructureError(f"pair {p.name} joins unknown body {end!r}; bodies: {names}")
            if p.a == p.b:
                raise StructureError(f"pair {p.name} joins {p.a} to itself")
        if self.crank not in names:
            raise StructureError(f"crank {self.crank!r} is not a body; bodies: {names}")
        listed = [b for g in self.groups for b in g] + [self.crank]
        if sorted(listed) != sorted(names):
            raise StructureError(f"every body except the crank must be in exactly one group: groups "
                                 f"{self.groups} + crank {self.crank!r} vs bodies {names}")
        solved: set[str] = set()
        for g in (*self.groups, (self.crank,)):
            unknown = self._unknown_pairs(g, solved)
            count = sum(p.n_unknowns for p in unknown) + (g == (self.crank,))
            if count != 3 * len(g):
                raise StructureError(
                    f"group {g} is not statically determinate: {count} unknown reaction components "
                    f"(pairs {[p.name for p in unknown]}) for 3·{len(g)} = {3 * len(g)} equilibrium equations")
            solved |= {p.name for p in unknown}
        if solved != set(pnames):
            raise StructureError(f"pairs {sorted(set(pnames) - solved)} belong to no group")

    def _unknown_pairs(self, group, solved):
        return [p for p in self.pairs if (p.a in group or p.b in group) and p.name not in solved]

    def body(self, name: str) -> Body:
        for b in self.bodies:
            if b.name == name:
                return b
        raise KeyError(f"no body {name!r}; bodies: {[b.name for b in self.bodies]}")

    def pair(self, name: str):
        for p in self.pairs:
            if p.name == name:
                return p
        raise KeyError(f"no pair {name!r}; pairs: {[p.name for p in self.pairs]}")

    def with_body(self, name: str, *, mass=None, inertia=None, com=None) -> "ForceModel":
        """A copy with link ``name``'s mass properties changed.

        ``inertia=None`` with a new mass gives a slender uniform bar, J_S = m·length²/12.
        """
        old = self.body(name)
        m = old.mass if mass is None else mass
        if inertia is None:
            inertia = old.inertia if mass is None else _nonneg(f"mass of {name}", m, MassError) * old.length**2 / 12
        new = replace(old, mass=m, inertia=inertia, com=old.com if com is None else com)
        return replace(self, bodies=tuple(new if b.name == name else b for b in self.bodies))

    def with_friction(self, f: float, radius: float = 0.0, *, pairs: Sequence[str] | None = None) -> "ForceModel":
        """A copy with friction coefficient f in the named pairs (all by default) and journal radius r."""
        chosen = set(pairs) if pairs is not None else {p.name for p in self.pairs}
        unknown = chosen - {p.name for p in self.pairs}
        if unknown:
            raise KeyError(f"no pairs {sorted(unknown)}; pairs: {[p.name for p in self.pairs]}")
        out = []
        for p in self.pairs:
            if p.name in chosen:
                p = replace(p, friction=f, radius=radius) if isinstance(p, Revolute) else replace(p, friction=f)
            out.append(p)
        return replace(self, pairs=tuple(out))


# --------------------------------------------------------------------------- loads
@dataclass(frozen=True)
class Force:
    """External force on ``body`` applied at ``at`` (joint name or link coordinates (ξ, η))."""

    body: str
    at: Any
    value: Any


@dataclass(frozen=True)
class Torque:
    """External couple on ``body`` (counter-clockwise positive)."""

    body: str
    value: Any


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


def output_axis(motion) -> tuple:
    """The output angle ψ with ψ', ψ'' as a link axis (``Body(..., axis=output_axis)``)."""
    return motion.psi, motion.dpsi, motion.ddpsi


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


def virtual_work_torque(model: ForceModel, motion: Motion, loads=(), omega1: float = 1.0, eps1: float = 0.0,
                        gravity=(0.0, -G)) -> np.ndarray:
    """Frictionless balancing torque from the power balance alone (no reactions).

    All forces — gravity, d'Alembert inertia forces and couples, external loads — and
    the balancing torque M_b do no net work in a virtual displacement δφ of the
    ideal mechanism, so M_b = −Σ(F_i·r_i' + M_i·θ_i') with r_i', θ_i' the analogs of
    the load points and link angles: Zhukovsky's lever in analytic form.
    """
    frames = _frames(model, motion)
    kl = _known_loads(model, motion, frames, loads, float(omega1), float(eps1), gravity)
    crank = frames[model.crank]
    return -kl.power / crank.dth


# --------------------------------------------------------------------------- results
@dataclass(frozen=True, eq=False)
class Reaction:
    """Reaction in one pair over the cycle: force and couple of link a on link b.

    ``force`` includes the friction force of a sliding pair; ``couple`` is the pair's
    reaction couple (prismatic) plus the friction couple (revolute); ``normal`` is the
    signed normal force N (prismatic, higher pairs; None for a revolute).
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
        return np.hypot(self.force[:, 0], self.force[:, 1])


@dataclass(frozen=True, eq=False)
class ForceResult:
    """Kinetostatics over the crank angles ``phi`` at crank speed ω1 and acceleration ε1."""

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
        """Driving power M_b·ω1."""
        return self.torque * self.omega1

    @property
    def power_gap(self) -> float:
        """Largest |M_b(groups) − M_b(power balance)|, relative to the largest |M_b|."""
        return float(np.max(np.abs(self.torque - self.torque_power)) / (np.max(np.abs(self.torque)) + 1e-300))

    def verify(self, tol: float = 1e-9) -> str:
        """The built-in checks: the balancing torque from the groups equals the power balance's
        and every link is in equilibrium, both to ``tol``; returns a one-line summary and
        raises MechanismError (with the numbers) otherwise."""
        if not (self.power_gap <= tol and self.residual <= tol):
            raise MechanismError(f"kinetostatics check failed: groups vs power balance {self.power_gap:.2e}, "
                                 f"equilibrium residual {self.residual:.2e} (tolerance {tol:g})")
        return (f"M_b from the groups = power balance to {self.power_gap:.1e}; every link in equilibrium "
                f"to {self.residual:.1e}")

    def efficiency(self) -> np.ma.MaskedArray:
        """Instantaneous efficiency η = 1 − P_friction/P_drive = M_ideal/M_b (seed 001, ch. 3).

        Defined where the drive delivers power and the loads absorb it (P_drive > 0 and
        M_ideal·ω1 > 0); masked elsewhere — where the links' inertia or gravity drive the crank,
        an instantaneous efficiency has no meaning.
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

        ``how="mean"``: the thesis' definition (seed 001, ch. 3), the arithmetic mean of the
        instantaneous efficiencies (over the positions of ``moving`` where η is defined);
        ``how="work"``: 1 − ∫P_friction dφ / ∫P_drive dφ over those positions.
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
                raise MechanismError(f"cycle efficiency undefined: the drive's work over the cycle is {a_drive:.4g} ≤ 0")
            return float(1.0 - a_loss / a_drive)
        raise ValueError(f"how must be 'mean' or 'work', got {how!r}")


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


def solve(model: ForceModel, motion: Motion, loads=(), omega1: float = 1.0, eps1: float = 0.0,
          gravity=(0.0, -G), *, maxiter: int = 100, tol: float = 1e-12) -> ForceResult:
    """Reactions in every pair and the balancing torque, group by group (seed 003's method).

    Groups are solved in ``model.groups`` order (output first), then the crank. Each
    group's 3k equilibrium equations (ΣF = 0, ΣM about each link's origin = 0) form a
    batch of linear systems in its unknown reactions, solved at every crank angle at
    once. Friction (if any pair has f > 0) is linearised and iterated on its senses, see
    the module docstring. Raises SingularityError where a group cannot carry its loads (a dead
    point) and SelfLockingError where friction locks the mechanism.
    """
    omega1, eps1 = float(omega1), float(eps1)
    if not (np.isfinite(omega1) and np.isfinite(eps1)):
        raise DimensionError(f"crank speed and acceleration must be finite, got ω1 = {omega1}, ε1 = {eps1}")
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
        for iterations in range(2, maxiter + 2):
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


# --------------------------------------------------------------------------- models of the core mechanisms
def model_for(mechanism) -> ForceModel:
    """Force model of a core mechanism: massless frictionless links, centres of mass mid-link.

    * FourBar: links crank (O→A), coupler (A→B), rocker (E→B); pairs O, A, B, E; group RRR
      (coupler, rocker).
    * SliderCrank: crank, rod (A→B), slider (at B, translating); pairs O, A, B and the
      prismatic ``guide``; group RRP (rod, slider).
    * SlottedLink: crank, block (at A, turning with the link), link (B→A); pairs O, A,
      the prismatic ``slot`` (block in the link) and B; group RPR (block, link).
    * SineMechanism: crank, block (at A), yoke (at K); pairs O, A, ``slot`` (block in
      the yoke, vertical) and ``guide`` (yoke on the frame); group (block, yoke).
    """
    from .linkages import FourBar, SineMechanism, SliderCrank, SlottedLink

    if not isinstance(mechanism, (FourBar, SliderCrank, SlottedLink, SineMechanism)):
        raise TypeError(f"no force model for {type(mechanism).__name__}; build a ForceModel for it")
    crank = Body("crank", "O", ("O", "A"), com=(mechanism.crank / 2, 0.0), length=mechanism.crank)
    crank_pair = Revolute("O", FRAME, "crank", "O")
    if isinstance(mechanism, FourBar):
        return ForceModel(
            (crank, Body("coupler", "A", ("A", "B"), com=(mechanism.coupler / 2, 0.0), length=mechanism.coupler),
             Body("rocker", "E", ("E", "B"), com=(mechanism.rocker / 2, 0.0), length=mechanism.rocker)),
            (crank_pair, Revolute("A", "crank", "coupler", "A"), Revolute("B", "coupler", "rocker", "B"),
             Revolute("E", FRAME, "rocker", "E")),
            (("coupler", "rocker"),), "crank", "O")
    if isinstance(mechanism, SliderCrank):
        return ForceModel(
            (crank, Body("rod", "A", ("A", "B"), com=(mechanism.rod / 2, 0.0), length=mechanism.rod),
             Body("slider", "B", 0.0)),
            (crank_pair, Revolute("A", "crank", "rod", "A"), Revolute("B", "rod", "slider", "B"),
             Prismatic("guide", FRAME, "slider", "B", 0.0)),
            (("rod", "slider"),), "crank", "O")
    if isinstance(mechanism, SlottedLink):
        reach = mechanism.pivot_distance + mechanism.crank
        return ForceModel(
            (crank, Body("block", "A", ("B", "A")),
             Body("link", "B", ("B", "A"), com=(reach / 2, 0.0), length=reach)),
            (crank_pair, Revolute("A", "crank", "block", "A"), Prismatic("slot", "link", "block", "A", 0.0),
             Revolute("B", FRAME, "link", "B")),
            (("block", "link"),), "crank", "O")
    if isinstance(mechanism, SineMechanism):
        return ForceModel(
            (crank, Body("block", "A", np.pi / 2), Body("yoke", "K", 0.0)),
            (crank_pair, Revolute("A", "crank", "block", "A"), Prismatic("slot", "yoke", "block", "A", np.pi / 2),
             Prismatic("guide", FRAME, "yoke", "K", 0.0)),
            (("block", "yoke"),), "crank", "O")
    raise TypeError(f"no force model for {type(mechanism).__name__}; build a ForceModel for it")


def slender_bar(mass: float, length: float) -> float:
    """Moment of inertia m·l²/12 of a uniform slender bar about its centre."""
    return _nonneg("mass", mass, MassError) * _nonneg("length", length, DimensionError) ** 2 / 12.0


# --------------------------------------------------------------------------- drive
class DriveError(DimensionError):
    """Inadmissible drive data: efficiency outside (0, 1], overload factor < 1, torque samples
    that are not finite or do not match the crank angles, ω1 = 0."""


@dataclass(frozen=True, eq=False)
class Drive:
    """A crank's torque over one cycle at constant ω1 and the motor it needs without a flywheel.

    ``phi``, ``torque``: the crank angles and the crank torque M(φ) as given;
    ``motor_torque``: M_m(φ), the motor's torque referred to the crank (M/η where the
    motor drives, M·η where the mechanism drives it back, see :func:`drive`). Every
    statistic below is of M_m: ``mean_torque`` ⟨M_m⟩, ``rms_torque`` √⟨M_m²⟩ (thermal),
    ``peak_torque`` max|M_m|; ``mean_power`` = ⟨M_m⟩·ω1 (seed 004's N_cp),
    ``peak_power`` = peak·|ω1|; ``nominal_torque`` = max(rms, peak/overload),
    ``nominal_power`` = nominal_torque·|ω1|; ``governing`` = "rms" or "peak", the
    term that decided.
    """

    phi: np.ndarray
    torque: np.ndarray
    motor_torque: np.ndarray
    mean_torque: float
    peak_torque: float
    rms_torque: float
    mean_power: float
    peak_power: float
    nominal_torque: float
    nominal_power: float
    overload: float
    efficiency: float
    governing: str

    def choose(self, catalogue: Sequence[float]) -> float:
        """The smallest motor power in ``catalogue`` (same unit as the powers here) ≥ nominal_power."""
        ok = sorted(p for p in catalogue if p >= self.nominal_power)
        if not ok:
            raise MechanismError(f"no motor in the catalogue reaches the nominal power {self.nominal_power:.4g} "
                                 f"(largest: {max(catalogue):.4g})")
        return ok[0]


def cycle_mean(y: np.ndarray, phi: np.ndarray) -> float:
    """Mean of y(φ) over the sampled interval (trapezoidal rule, any spacing)."""
    return float(np.trapezoid(y, phi) / (phi[-1] - phi[0]))


def motor_torque(torque, omega1: float, efficiency: float = 1.0) -> np.ndarray:
    """The motor's torque referred to the crank: M/η where the motor drives (M·ω1 > 0), M·η
    where the mechanism drives the motor back (M·ω1 < 0) through the same transmission."""
    M = np.asarray(torque, dtype=float)
    driving = M * np.sign(omega1) > 0
    return np.where(driving, M / efficiency, M * efficiency)


def drive(torque, phi, omega1: float, *, overload: float = 2.0, efficiency: float = 1.0) -> Drive:
    """The one rule of the course for sizing a motor that drives a crank without a flywheel.

    ``torque`` is the crank torque M(φ) at the crank angles ``phi`` over one cycle (e.g.
    ``ForceResult.torque``; :func:`mechlab.geneva.drive` builds the Geneva's); ``omega1``
    the constant crank speed (either sign); ``efficiency`` η of the transmission between
    motor and crank (0 < η ≤ 1); ``overload`` the motor's admissible ratio k of peak to
    nominal torque (k ≥ 1). Returns a :class:`Drive`.

    Derivation. *Motor side.* Where the motor drives (M·ω1 > 0) it must supply M/η; where
    the mechanism drives the motor back (M·ω1 < 0: kinetic energy of the links returned,
    gravity) only M·η reaches it (a transmission that does not lock backwards, with the
    same η both ways). So M_m = M/η or M·η, and every figure below is of M_m. At constant
    ω1 time is proportional to φ, so a mean over the cycle is ⟨x⟩ = ∫x dφ / Φ.

    1. *Energy: the mean power* N̄ = ⟨M_m⟩·ω1 — seed 004's N_cp = M_cp·ω_KP with M_cp the
       mean of the torques in n positions (its formula printed with n multiplying instead
       of dividing; see the errata). It is what the motor draws on average, and the size of
       the motor when a flywheel makes its torque nearly constant.
    2. *Heating: the equivalent (rms) torque* M_eq = √⟨M_m²⟩. A motor's losses are a
       constant part (iron, bearings, fan) plus the copper losses I²R; at constant flux
       (a DC shunt motor, an induction motor in its working range) the current is
       proportional to the torque, so the heat of one cycle — short against the motor's
       thermal time constant of minutes — grows as ⟨M_m²⟩, and the constant torque that
       heats the motor as much is M_eq: the *method of equivalent torque* of the
       electric-drive texts (M. G. Chilikin, A. S. Sandler, Общий курс электропривода,
       the chapter on choosing the motor's power; A. Hughes, B. Drury, Electric Motors
       and Drives, on rating for intermittent loads). The mean power is **not** a thermal
       measure: by Cauchy–Schwarz M_eq ≥ |⟨M_m⟩|, with equality only for a constant
       torque, so sizing by the mean power understates the heating whenever the torque
       fluctuates — a Geneva wheel with inertia alone and η = 1 has ⟨M⟩ = 0 and still
       heats the motor. The nominal torque must be ≥ M_eq.
    3. *Overload*: the motor must also deliver the peak |M_m| within its overload factor
       k = M_max/M_nom (seed 004: "the overload factor must be taken into account"), so
       M_nom ≥ M_peak/k.

    Hence M_nom = max(M_eq, M_peak/k), N_nom = M_nom·|ω1| (the motor's torque and power
    referred to the crank shaft: a gear of ratio u multiplies the speed and divides the
    torque by u and leaves the power), and ``governing`` names the larger term.

    Integration: the trapezoidal rule over the samples (any spacing). Where the torque
    jumps (a hard impact, a load switching on), give both one-sided values at the same
    or nearly the same φ: each smooth piece is then integrated on its own to the
    accuracy of its sampling, as :func:`mechlab.geneva.drive` does at the engagement
    ends. The peak is the largest sample.
    """
    M = np.asarray(torque, dtype=float)
    phi = np.asarray(phi, dtype=float)
    if M.shape != phi.shape or M.ndim != 1 or len(M) < 2:
        raise DriveError(f"torque and phi must be 1-D arrays of the same length ≥ 2, got {M.shape}, {phi.shape}")
    if not (np.all(np.isfinite(M)) and np.all(np.isfinite(phi))):
        raise DriveError("torque and phi must be finite (got NaN or inf)")
    if not np.all(np.diff(phi) >= 0) or phi[-1] <= phi[0]:
        raise DriveError(f"phi must increase over the cycle, got φ from {phi[0]:g} to {phi[-1]:g}")
    omega1 = float(omega1)
    if not np.isfinite(omega1) or omega1 == 0:
        raise DriveError(f"crank speed ω1 must be finite and non-zero, got {omega1}")
    if not (np.isfinite(overload) and overload >= 1):
        raise DriveError(f"the overload factor must satisfy k ≥ 1, got k = {overload}")
    if not (np.isfinite(efficiency) and 0 < efficiency <= 1):
        raise DriveError(f"the efficiency must satisfy 0 < η ≤ 1, got η = {efficiency}")
    Mm = motor_torque(M, omega1, efficiency)
    mean = cycle_mean(Mm, phi)
    peak = float(np.max(np.abs(Mm)))
    # scaled by the peak, so that M² neither underflows nor overflows
    rms = peak * float(np.sqrt(cycle_mean((Mm / peak) ** 2, phi))) if peak > 0 else 0.0
    w = abs(omega1)
    by_peak = peak / overload
    nominal = max(rms, by_peak)
    return Drive(phi, M, Mm, mean, peak, rms, mean * omega1, peak * w, nominal, nominal * w,
                 float(overload), float(efficiency), "peak" if by_peak > rms else "rms")

# --------------------------------------------------------------------------- a mechanism with its loads
from .linkages.base import Mechanism  # noqa: E402  (after the solver: the module is usable without it)


@dataclass(frozen=True, eq=False)
class Kinetostatics(Mechanism):
    """A mechanism with its force model and loads: moves like the mechanism, ``forces(phi)`` solves.

    Used by :mod:`mechlab.draw.forces` to animate force plans with ``mechlab.draw.animate``.
    """

    mechanism: Any
    model: ForceModel | None = None
    loads: tuple = ()
    omega1: float = 1.0
    eps1: float = 0.0
    gravity: tuple = (0.0, -G)

    def __post_init__(self):
        if self.model is None:
            object.__setattr__(self, "model", model_for(self.mechanism))
        object.__setattr__(self, "loads", tuple(self.loads))

    @property
    def links(self):
        return self.mechanism.links

    @property
    def pivots(self):
        return self.mechanism.pivots

    @property
    def output(self):
        return self.mechanism.output

    def crank_ranges(self):
        return self.mechanism.crank_ranges()

    def rotation_failure(self) -> str:
        return self.mechanism.rotation_failure()

    def turn(self, n: int = 361):
        return self.mechanism.turn(n)

    def cycle(self, n: int = 361):
        return self.mechanism.cycle(n)

    def motion(self, phi):
        return self.mechanism.motion(phi)

    def forces(self, phi=None, motion: Motion | None = None, **kw) -> ForceResult:
        """Solve at crank angles φ (default: the mechanism's cycle) or on a given motion."""
        if motion is None:
            motion = self.motion(self.cycle() if phi is None else phi)
        return solve(self.model, motion, self.loads, self.omega1, self.eps1, self.gravity, **kw)


# --------------------------------------------------------------------------- the chapter's two examples
def rpm_to_rad(rpm: float) -> float:
    """Crank speed in rad/s from revolutions per minute."""
    return float(rpm) * 2.0 * np.pi / 60.0


def press_load(P: float, work_fraction: float = 0.3) -> Callable:
    """Technological resistance of a press: a force P against the slider while it moves
    towards its outer dead point in the last ``work_fraction`` of its stroke.

    Returns ``load(motion) → (n, 2)`` for :class:`Force` on the slider of a slider-crank
    motion (points O, A, B; guide parallel to x). The outer dead point and the stroke come
    from the dimensions (crank a = |OA|, rod l = |AB|, offset e = y of B): the slider is
    sqrt((l + a)² − e²) from O along the guide there, on the side where B is ahead of A,
    so the load at a crank angle does not depend on which other angles are sampled.
    """
    P = _nonneg("press force P", P, LoadError)
    if not 0 < work_fraction <= 1:
        raise LoadError(f"work_fraction must satisfy 0 < fraction ≤ 1, got {work_fraction}")

    def load(motion):
        crank, rod, offset, side = _slider_crank_dimensions(motion)
        outer = float(np.sqrt((rod + crank) ** 2 - offset**2))
        stroke = outer - float(np.sqrt((rod - crank) ** 2 - offset**2))
        working = (motion.ds * side > 0) & (motion.s * side >= outer - work_fraction * stroke)
        return np.stack([np.where(working, -side * P, 0.0), np.zeros(len(motion))], axis=1)
    return load


def _slider_crank_dimensions(motion) -> tuple[float, float, float, float]:
    """Crank, rod, offset and the side (+1: B ahead of A along x) of a slider-crank motion."""
    pts = motion.points
    A, B = pts["A"].p, pts["B"].p
    crank = float(np.hypot(*A[0]))
    rod = float(np.hypot(*(B[0] - A[0])))
    return crank, rod, float(B[0, 1]), float(np.sign(B[0, 0] - A[0, 0]) or 1.0)


def press(crank: float = 0.10, rod: float = 0.40, *, rpm: float = 120.0, P: float = 2000.0,
          work_fraction: float = 0.3, m_crank: float = 2.0, m_rod: float = 3.0, m_slider: float = 4.0,
          f: float = 0.0, radius: float = 0.01, eps1: float = 0.0) -> Kinetostatics:
    """The chapter's crank press (metres, kilograms, N): a centred slider-crank whose slider
    meets the resistance of :func:`press_load`; the crank is balanced (centre of mass at O),
    the rod is a uniform bar, friction f in every pair (journal radius ``radius``)."""
    sc = _slider_crank(crank, rod)
    sc.turn(2)  # a press's crank turns fully: RotationError (with the numbers) otherwise
    model = (model_for(sc).with_body("crank", mass=m_crank, inertia=slender_bar(m_crank, crank), com=(0.0, 0.0))
             .with_body("rod", mass=m_rod).with_body("slider", mass=m_slider).with_friction(f, radius))
    return Kinetostatics(sc, model, (Force("slider", "B", press_load(P, work_fraction)),), rpm_to_rad(rpm), eps1)


def rocker_drive(crank: float = 0.10, coupler: float = 0.30, rocker: float = 0.30, ground: float = 0.35, *,
                 rpm: float = 120.0, T: float = 40.0, m_coupler: float = 2.0, m_rocker: float = 2.0,
                 f: float = 0.0, radius: float = 0.01) -> Kinetostatics:
    """The chapter's four-bar: a crank-rocker whose rocker meets a resisting torque of size T
    against its motion, uniform bars for coupler and rocker, friction f in every pair."""
    fb = _four_bar(crank, coupler, rocker, ground)
    fb.turn(2)  # RotationError (Grashof, with the numbers) unless the crank turns fully
    model = (model_for(fb).with_body("coupler", mass=m_coupler).with_body("rocker", mass=m_rocker)
             .with_friction(f, radius))
    T = _nonneg("resisting torque T", T, LoadError)
    return Kinetostatics(fb, model, (Torque("rocker", lambda m: -T * np.sign(m.dpsi)),), rpm_to_rad(rpm))


def _slider_crank(crank, rod):
    from .linkages import SliderCrank
    return SliderCrank(crank, rod)


def _four_bar(crank, coupler, rocker, ground):
    from .linkages import FourBar
    return FourBar(crank, coupler, rocker, ground)


__all__ = [
    "FRAME", "G", "Body", "Revolute", "Prismatic", "HigherPair", "ForceModel", "Force", "Torque",
    "Reaction", "ForceResult", "Drive", "DriveError", "Kinetostatics",
    "solve", "virtual_work_torque", "model_for", "slender_bar", "drive", "motor_torque", "cycle_mean",
    "output_axis",
    "rpm_to_rad", "press_load", "press", "rocker_drive",
    "MassError", "FrictionError", "LoadError", "StructureError", "SelfLockingError",
]
