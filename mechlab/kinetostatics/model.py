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

from collections.abc import Sequence
from dataclasses import dataclass, replace
from typing import Annotated, Any, ClassVar

import numpy as np

from ..errors import (
    DimensionError,
    FrictionError,
    LoadError,
    MassError,
    SelfLockingError,
    StructureError,
)
from ..mechanisms.base import FRAME
from ..validate import Angle, Checked, Distance, Name, Point, Spec, angle, check_value, number, or_function

__all__ = [
    "FRAME",
    "Body",
    "Force",
    "ForceModel",
    "FrictionError",
    "G",
    "HigherPair",
    "LoadError",
    "MassError",
    "Prismatic",
    "Revolute",
    "SelfLockingError",
    "StructureError",
    "Torque",
    "model_for",
    "slender_bar",
]



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

    _WORDS: ClassVar[dict[str, str]] = {
        "inertia": "moment of inertia", "com": "centre of mass (com)", "friction": "friction coefficient",
        "radius": "journal radius", "angle": "guide angle", "normal": "normal angle"}

    def _label(self, field: str) -> str:
        return field if field == "name" else f"{self._WORDS.get(field, field)} of {self.name}"


# --------------------------------------------------------------------------- structure
@dataclass(frozen=True)
class Body(_Labelled):
    """A link of a force model: a joint fixed on it (``origin``), its axis, and its mass properties.

    Parameters
    ----------
    name : str
        The link's name (not ``"frame"``, which is reserved).
    origin : str
        A joint fixed on the link, the origin of its link coordinates.
    axis : tuple of str, float or callable, optional
        (P, Q): the link's x axis points from joint P to joint Q; a float: the link translates with its
        axis at that constant angle (radians); a callable ``axis(motion) → (θ, θ', θ'')`` (e.g.
        :func:`output_axis`): any other link angle, such as a curved-slot link's ψ.
    mass : float, optional
        Mass (kg, ≥ 0).
    inertia : float, optional
        Moment of inertia about the centre of mass (kg·m², ≥ 0).
    com : tuple of float, optional
        Centre of mass in link coordinates (ξ along the axis from the origin, η to its left; m).
    length : float, optional
        Informational: a bar's length (m), for the default slender-bar inertia.

    Raises
    ------
    StructureError
        For the name ``"frame"`` or an axis that is neither two joint names, an angle nor a callable.
    MassError
        For a negative or non-finite mass or inertia.

    Examples
    --------
    >>> from mechlab import Body
    >>> Body("coupler", "A", ("A", "B"), mass=2.0, com=(1.5, 0.0)).translates
    False
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
        """True when the axis is a constant angle: the link only translates.

        Returns
        -------
        bool
            Whether the link keeps its orientation.
        """
        return not isinstance(self.axis, tuple) and not callable(self.axis)


@dataclass(frozen=True)
class Revolute(_Labelled):
    """Turning pair at joint ``point``; its reaction R is the force of link ``a`` on link ``b``.

    Parameters
    ----------
    name : str
        The pair's name.
    a, b : str
        The two links (``"frame"`` for the frame).
    point : str
        The joint where the pair sits.
    friction : float, optional
        Friction coefficient f (0 ≤ f < 1).
    radius : float, optional
        Journal radius r (m, ≥ 0): the friction couple is f·r·|R|.

    Raises
    ------
    FrictionError
        For a friction coefficient or radius out of range.

    Examples
    --------
    >>> from mechlab import Revolute
    >>> Revolute("A", "crank", "coupler", "A", friction=0.1, radius=0.01).friction
    0.1
    """

    name: Name
    a: Name
    b: Name
    point: Name
    friction: Friction = 0.0
    radius: JournalRadius = 0.0
    n_unknowns = 2


@dataclass(frozen=True)
class Prismatic(_Labelled):
    """Link ``b`` slides on link ``a`` along a guide at ``angle`` to a's axis, through ``point`` (fixed on b).

    Parameters
    ----------
    name : str
        The pair's name.
    a, b : str
        The guiding link and the sliding link (``"frame"`` for the frame).
    point : str
        A joint fixed on ``b`` on the guide line.
    angle : float, optional
        The guide's angle to a's axis (radians).
    friction : float, optional
        Friction coefficient f (0 ≤ f < 1).

    Raises
    ------
    FrictionError
        For a friction coefficient out of range.

    Examples
    --------
    >>> from mechlab import Prismatic
    >>> Prismatic("guide", "frame", "slider", "B").angle
    0.0
    """

    name: Name
    a: Name
    b: Name
    point: Name
    angle: Angle = 0.0
    friction: Friction = 0.0
    n_unknowns = 2


@dataclass(frozen=True)
class HigherPair(_Labelled):
    """Contact of links ``a`` and ``b`` at the moving point ``point``; its reaction acts along the common normal.

    Parameters
    ----------
    name : str
        The pair's name.
    a, b : str
        The two links in contact.
    point : str
        The contact point (a joint of the motion).
    normal : float or callable, optional
        The normal's angle to a's axis (radians), or ``normal(motion) → (n, 2)`` unit vectors.
    friction : float, optional
        Friction coefficient f (0 ≤ f < 1).

    Raises
    ------
    FrictionError
        For a friction coefficient out of range.

    Examples
    --------
    >>> from mechlab import HigherPair
    >>> round(HigherPair("contact", "cam", "follower", "K").normal, 4)
    1.5708
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

    Usually built by :func:`model_for` from a mechanism's ``structure()``, then given masses
    (:meth:`with_body`) and friction (:meth:`with_friction`).

    Parameters
    ----------
    bodies : tuple of Body
        The moving links.
    pairs : tuple of Revolute, Prismatic or HigherPair
        The kinematic pairs.
    groups : tuple of tuple of str
        The structural groups, each a tuple of body names, in the order they are solved (output first).
    crank : str
        The driving body.
    pivot : str
        The joint where the crank turns on the frame.
    numbering : tuple of str, optional
        The bodies' names in the order of their numbers 1, 2, …, the frame included (from
        :meth:`Structure.numbers` in :func:`model_for`, so forces number links as the drawing and the
        centres do); empty for a model built by hand.

    Raises
    ------
    StructureError
        For repeated names, a pair or group naming an unknown body, or groups that leave a pair unsolved.

    Examples
    --------
    >>> from mechlab import FourBar, model_for
    >>> model = model_for(FourBar(1, 3, 3.5, 4))
    >>> model.numbering, model.groups
    (('crank', 'coupler', 'rocker', 'frame'), (('coupler', 'rocker'),))
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
            raise StructureError(f"numbering {self.numbering} must name bodies or the frame, each once; bodies: "
                                 f"{names}")
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
        """The number of body ``name`` (or of the frame) in ``numbering``.

        Parameters
        ----------
        name : str
            A body's name, or ``"frame"``.

        Returns
        -------
        int
            Its number, from 1.

        Raises
        ------
        KeyError
            For a body that has no number.

        Examples
        --------
        >>> from mechlab import FourBar, model_for
        >>> model_for(FourBar(1, 3, 3.5, 4)).number("rocker")
        3
        """
        if name not in self.numbering:
            raise KeyError(f"body {name!r} has no number; numbered: {list(self.numbering)}")
        return self.numbering.index(name) + 1

    def body(self, name: str) -> Body:
        """The body called ``name``.

        Parameters
        ----------
        name : str
            A body's name.

        Returns
        -------
        Body
            That body.

        Raises
        ------
        KeyError
            If there is no such body.

        Examples
        --------
        >>> from mechlab import FourBar, model_for
        >>> model_for(FourBar(1, 3, 3.5, 4)).body("coupler").com
        (1.5, 0.0)
        """
        for b in self.bodies:
            if b.name == name:
                return b
        raise KeyError(f"no body {name!r}; bodies: {[b.name for b in self.bodies]}")

    def pair(self, name: str):
        """The pair called ``name``.

        Parameters
        ----------
        name : str
            A pair's name.

        Returns
        -------
        Revolute or Prismatic or HigherPair
            That pair.

        Raises
        ------
        KeyError
            If there is no such pair.

        Examples
        --------
        >>> from mechlab import FourBar, model_for
        >>> model_for(FourBar(1, 3, 3.5, 4)).pair("B")
        Revolute(name='B', a='coupler', b='rocker', point='B', friction=0.0, radius=0.0)
        """
        for p in self.pairs:
            if p.name == name:
                return p
        raise KeyError(f"no pair {name!r}; pairs: {[p.name for p in self.pairs]}")

    def with_body(self, name: str, *, mass=None, inertia=None, com=None) -> ForceModel:
        """A copy with link ``name``'s mass properties changed.

        Parameters
        ----------
        name : str
            The body to change.
        mass : float, optional
            New mass (kg); unchanged if None.
        inertia : float, optional
            New moment of inertia about the centre of mass (kg·m²). None with a new mass gives a slender
            uniform bar, J_S = m·length²/12; None without one keeps the old inertia.
        com : tuple of float, optional
            New centre of mass in link coordinates (m); unchanged if None.

        Returns
        -------
        ForceModel
            The changed copy.

        Raises
        ------
        KeyError
            If there is no such body.
        MassError
            For a negative or non-finite mass or inertia.

        Examples
        --------
        >>> from mechlab import FourBar, model_for
        >>> model_for(FourBar(1, 3, 3.5, 4)).with_body("coupler", mass=2.0).body("coupler").inertia
        1.5
        """
        old = self.body(name)
        m = old.mass if mass is None else mass
        if inertia is None:
            inertia = old.inertia if mass is None else _nonneg(f"mass of {name}", m, MassError) * old.length**2 / 12
        new = replace(old, mass=m, inertia=inertia, com=old.com if com is None else com)
        return replace(self, bodies=tuple(new if b.name == name else b for b in self.bodies))

    def with_friction(self, f: float, radius: float = 0.0, *, pairs: Sequence[str] | None = None) -> ForceModel:
        """A copy with friction coefficient f in the named pairs (all by default) and journal radius r.

        Parameters
        ----------
        f : float
            Friction coefficient (0 ≤ f < 1).
        radius : float, optional
            Journal radius of the revolute pairs (m).
        pairs : sequence of str, optional
            The pairs to change; all if None.

        Returns
        -------
        ForceModel
            The changed copy.

        Raises
        ------
        KeyError
            For a pair name the model does not have.
        FrictionError
            For ``f`` or ``radius`` out of range.

        Examples
        --------
        >>> from mechlab import FourBar, model_for
        >>> model_for(FourBar(1, 3, 3.5, 4)).with_friction(0.1, 0.01).pair("A").radius
        0.01
        """
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
    """External force on ``body``, applied at a joint or at a point of the link.

    Parameters
    ----------
    body : str
        The loaded body.
    at : str or tuple of float
        A joint name, or link coordinates (ξ, η) (m).
    value : array_like or callable
        A vector (Fx, Fy) (N), one per crank angle ((n, 2)), or a function of the motion giving (n, 2) vectors.

    Raises
    ------
    LoadError
        For a value of the wrong shape or not finite.

    Examples
    --------
    >>> from mechlab import Force
    >>> Force("slider", "B", (-100.0, 0.0)).at
    'B'
    """

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
    """External couple on ``body`` (counter-clockwise positive).

    Parameters
    ----------
    body : str
        The loaded body.
    value : float or callable
        The couple (N·m), or a function of the motion giving one per crank angle.

    Raises
    ------
    LoadError
        For a value that is not a finite number or a function.

    Examples
    --------
    >>> from mechlab import Torque
    >>> Torque("rocker", -5.0).value
    -5.0
    """

    body: Name
    value: Annotated[Any, or_function(number(error=LoadError))]


# --------------------------------------------------------------------------- models of the core mechanisms
def model_for(mechanism) -> ForceModel:
    """Force model of a mechanism from its ``structure()``.

    Massless frictionless links, a bar's centre of mass half-way along its axis, the structure's pairs and
    groups, the input link as the crank. E.g. FourBar: crank (O→A), coupler (A→B), rocker (E→B), pairs
    O, A, B, E, group (coupler, rocker); SliderCrank: crank, rod, slider with the prismatic ``guide``;
    SlottedLink: crank, block, link with the prismatic ``slot``; the cams: cam, follower with the higher
    pair ``contact``.

    Parameters
    ----------
    mechanism : Mechanism
        A mechanism that describes its ``structure()``.

    Returns
    -------
    ForceModel
        The model, numbered as the drawing and the centres number the links.

    Raises
    ------
    TypeError
        For an object that is no mechanism.
    MechanismError
        For a family with no ``structure()``, or a spatial one.
    StructureError
        If the input link turns about no pivot on the frame.

    Examples
    --------
    >>> from mechlab import SliderCrank, model_for
    >>> [p.name for p in model_for(SliderCrank(1, 3)).pairs]
    ['O', 'A', 'B', 'guide']
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
    """Moment of inertia m·l²/12 of a uniform slender bar about its centre.

    Parameters
    ----------
    mass : float
        Mass (kg, ≥ 0).
    length : float
        Length (m, ≥ 0).

    Returns
    -------
    float
        J_S (kg·m²).

    Raises
    ------
    MassError
        For a negative or non-finite mass.
    DimensionError
        For a negative or non-finite length.

    Examples
    --------
    >>> from mechlab.kinetostatics import slender_bar
    >>> slender_bar(2.0, 3.0)
    1.5
    """
    return _nonneg("mass", mass, MassError) * _nonneg("length", length, DimensionError) ** 2 / 12.0

