"""Kinetostatics' force model: links (:class:`Body`), pairs (:class:`Revolute`, :class:`Prismatic`,
:class:`HigherPair`), structural groups (:class:`ForceModel`) and loads (:class:`Force`, :class:`Torque`).

The method is the SibSIU proceedings' ("Kinetostatic analysis of the slider-crank mechanism with an
additional link", formulas (1)-(5), Figs. 2-5): cut the mechanism into structural groups of zero
mobility (Assur groups), load every link with gravity, d'Alembert inertia and the external loads,
and solve the groups from the output back to the crank, which gives the balancing torque last
(:func:`mechlab.kinetostatics.solve.solve`, all crank angles at once). The book's chapter on forces
derives it.

Units: one consistent system (m, kg, rad/s give N and N·m). A load's value is a constant, an
array over the crank angles or a callable ``value(motion)``. :func:`model_for` builds the
massless, frictionless model of any mechanism from its ``structure()``;
``model.with_body(...)`` and ``model.with_friction(f, radius)`` return modified copies.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Annotated, Any, Sequence

import numpy as np
from ..errors import (DimensionError, FrictionError, LoadError, MassError, MechanismError, SelfLockingError,
                      StructureError)
from ..mechanisms.base import FRAME
from ..validate import (Angle, Checked, Distance, Name, Point, Spec, angle, check_value, number, or_function)

__all__ = ["FRAME", "G", "Body", "Revolute", "Prismatic", "HigherPair", "ForceModel", "Force", "Torque", "model_for",
           "slender_bar", "MassError", "FrictionError", "LoadError", "StructureError", "SelfLockingError"]



G = 9.81


def _nonneg(name: str, value, exc) -> float:
    return check_value(name, value, number(0.0, error=exc))


# Crank speeds beyond this (rad/s, ≈ 10⁷ rpm) overflow the inertia forces' squares.
MAX_OMEGA = 1e6
Omega = Annotated[float, number(-MAX_OMEGA, MAX_OMEGA, why="rad/s")]
Eps = Annotated[float, number(-MAX_OMEGA**2, MAX_OMEGA**2, why="rad/s²")]
Mass = Annotated[float, number(0.0, error=MassError)]
Friction = Annotated[float, Spec("number", 0.0, 1.0, open_hi=True, error=FrictionError, why="0 ≤ f < 1")]
JournalRadius = Annotated[float, number(0.0, error=FrictionError)]


class _Labelled(Checked):
    """Messages name a parameter with its owner: "mass of coupler", "friction coefficient of O"."""

    _WORDS = {"inertia": "moment of inertia", "com": "centre of mass (com)", "friction": "friction coefficient",
              "radius": "journal radius", "angle": "guide angle", "normal": "normal angle"}

    def _label(self, field: str) -> str:
        return field if field == "name" else f"{self._WORDS.get(field, field)} of {self.name}"


# --------------------------------------------------------------------------- structure
@dataclass(frozen=True)
class Body(_Labelled):
    """A link: a joint fixed on it (``origin``), its axis, and its mass properties.

    ``axis`` = (P, Q): the link's x axis points from joint P to joint Q; a float: the
    link translates with its axis at that constant angle (radians); a callable
    ``axis(motion) → (θ, θ', θ'')`` (e.g. :func:`output_axis`): any other link angle,
    such as a curved-slot link's ψ. ``com`` is the
    centre of mass in link coordinates (ξ along the axis from the origin, η to its left).
    ``length`` is informational (a bar's length, for the default slender-bar inertia).
    """

    name: Name
    origin: Name
    axis: Any = 0.0
    mass: Mass = 0.0
    inertia: Mass = 0.0
    com: Point = (0.0, 0.0)
    length: Distance = 0.0

    def __post_init__(self):
        super().__post_init__()
        if self.name == FRAME:
            raise StructureError(f"a body may not be called {FRAME!r} (reserved for the frame)")
        if not isinstance(self.axis, tuple):
            object.__setattr__(self, "axis", check_value(f"axis of {self.name}", self.axis, or_function(angle())))
        elif len(self.axis) != 2 or not all(isinstance(j, str) for j in self.axis):
            raise StructureError(f"axis of {self.name} must be (P, Q) joint names or an angle, got {self.axis!r}")

    @property
    def translates(self) -> bool:
        return not isinstance(self.axis, tuple) and not callable(self.axis)


@dataclass(frozen=True)
class Revolute(_Labelled):
    """Turning pair at joint ``point``; reaction R = force of link a on link b."""

    name: Name
    a: Name
    b: Name
    point: Name
    friction: Friction = 0.0
    radius: JournalRadius = 0.0
    n_unknowns = 2


@dataclass(frozen=True)
class Prismatic(_Labelled):
    """Link b slides on link a along a guide at ``angle`` to a's axis, through ``point`` (fixed on b)."""

    name: Name
    a: Name
    b: Name
    point: Name
    angle: Angle = 0.0
    friction: Friction = 0.0
    n_unknowns = 2


@dataclass(frozen=True)
class HigherPair(_Labelled):
    """Contact of links a and b at the moving point ``point``; reaction along the common normal.

    ``normal``: angle of the normal to a's axis, or ``normal(motion) → (n, 2)`` unit vectors.
    """

    name: Name
    a: Name
    b: Name
    point: Name
    normal: Annotated[Any, or_function(angle())] = np.pi / 2
    friction: Friction = 0.0
    n_unknowns = 1


Pair = Revolute | Prismatic | HigherPair


@dataclass(frozen=True)
class ForceModel(Checked):
    """Links, pairs and the structural groups (output first) of a mechanism driven by ``crank``.

    ``numbering``: the bodies' names in the order of their numbers 1, 2, …, the frame included (from
    :meth:`Structure.numbers` in :func:`model_for`, so forces number links as the drawing and the centres
    do); empty for a model built by hand.
    """

    bodies: Annotated[tuple, Spec("items", expected=Body)]
    pairs: Annotated[tuple, Spec("items", expected=(Revolute, Prismatic, HigherPair))]
    groups: tuple
    crank: Name
    pivot: Name
    numbering: Annotated[tuple, Spec("items", expected=str)] = ()

    def __post_init__(self):
        super().__post_init__()
        if isinstance(self.groups, str) or not isinstance(self.groups, tuple | list) or \
                not all(isinstance(g, tuple | list) and all(isinstance(b, str) for b in g) for g in self.groups):
            raise TypeError(f"groups must be a tuple of tuples of body names, got {self.groups!r:.60}")
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
        if any(b not in known for b in self.numbering) or len(set(self.numbering)) != len(self.numbering):
            raise StructureError(f"numbering {self.numbering} must name bodies or the frame, each once; bodies: {names}")
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

    def number(self, name: str) -> int:
        """The number of body ``name`` (or of the frame) in ``numbering``; KeyError for an unnumbered one."""
        if name not in self.numbering:
            raise KeyError(f"body {name!r} has no number; numbered: {list(self.numbering)}")
        return self.numbering.index(name) + 1

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
class Force(Checked):
    """External force on ``body`` applied at ``at`` (joint name or link coordinates (ξ, η)); ``value``
    a vector (Fx, Fy) or a function of the motion giving (n, 2) vectors."""

    body: Name
    at: Any
    value: Any

    def __post_init__(self):
        super().__post_init__()
        if not isinstance(self.at, str):
            object.__setattr__(self, "at", check_value("at", self.at, Spec("point")))
        if not callable(self.value):  # one vector, or one per crank angle
            one = np.ndim(self.value) <= 1
            spec = Spec("point" if one else "points", lo=1, error=LoadError)
            object.__setattr__(self, "value", check_value("value", self.value, spec))


@dataclass(frozen=True)
class Torque(Checked):
    """External couple on ``body`` (counter-clockwise positive): a number or a function of the motion."""

    body: Name
    value: Annotated[Any, or_function(number(error=LoadError))]


# --------------------------------------------------------------------------- models of the core mechanisms
def model_for(mechanism) -> ForceModel:
    """Force model of a mechanism from its ``structure()``: massless frictionless links, a bar's centre
    of mass half-way along its axis, the structure's pairs and groups, the input link as the crank.

    E.g. FourBar: crank (O→A), coupler (A→B), rocker (E→B), pairs O, A, B, E, group (coupler, rocker);
    SliderCrank: crank, rod, slider with the prismatic ``guide``; SlottedLink: crank, block, link with
    the prismatic ``slot``; the cams: cam, follower with the higher pair ``contact``.
    TypeError for an object that is no mechanism; MechanismError for a family with no ``structure()``.
    """
    describe = getattr(mechanism, "structure", None)
    if not callable(describe):
        raise TypeError(f"mechanism must be a mechanism that describes its structure(): no force model for "
                        f"{type(mechanism).__name__}; build a ForceModel for it")
    st = describe().planar()
    bodies = tuple(Body(k.name, k.origin, k.axis, com=(k.length / 2, 0.0), length=k.length) for k in st.links)
    pairs = tuple(_pair(p) for p in st.pairs)
    pivot = next((p for p in st.pairs if p.kind == "revolute" and {p.a, p.b} == {FRAME, st.input}), None)
    if pivot is None:
        raise StructureError(f"the input link {st.input} turns about no pivot on the frame: it is not a crank")
    numbers = st.numbers()
    numbering = tuple(sorted([*(k.name for k in st.links if k.name in numbers), FRAME], key=numbers.get))
    return ForceModel(bodies, pairs, st.groups, st.input, pivot.point, numbering)


def _pair(p):
    if p.kind == "revolute":
        return Revolute(p.name, p.a, p.b, p.point)
    if p.kind == "prismatic":
        return Prismatic(p.name, p.a, p.b, p.point, p.angle)
    return HigherPair(p.name, p.a, p.b, p.point, p.normal)


def slender_bar(mass: float, length: float) -> float:
    """Moment of inertia m·l²/12 of a uniform slender bar about its centre."""
    return _nonneg("mass", mass, MassError) * _nonneg("length", length, DimensionError) ** 2 / 12.0

