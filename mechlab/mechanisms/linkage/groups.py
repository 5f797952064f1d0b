"""The pieces a linkage is built from: the driving crank, the Assur dyads RRR, RRP, RPR, PRP, RPP, and points
fixed on a link; each places its new joints and links over all crank angles at once.

A dyad whose inner pair is a revolute joint B (RRR, RRP, PRP) meets two constraints on B, a circle
|B - P| = l about an outer joint or a line fixed on an outer link. Differentiating each constraint
gives one linear equation a·B' = b' and one a·B'' = b'' (Artobolevsky, 1965: the groups' velocity
and acceleration plans, written as equations); the 2×2 system is solved by Cramer's rule, whose
determinant vanishes only at a dead point. The RPR dyad's slotted link turns with the line from its
pivot to the pin. No finite differences anywhere.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Annotated, Any, ClassVar

import numpy as np

from ...errors import AssemblyError, SingularityError, StructureError
from ...geometry import (
    DEAD_POINT_TOL,
    AnglePath,
    PointPath,
    _abs2,
    _im_conj,
    _re_conj,
    as_complex,
    as_xy,
    crank_point,
    fixed_point,
    relative,
    vector_angle,
)
from ...validate import Angle, Checked, Distance, Length, Name, Sign, Spec, mechanism
from ..base import FRAME, Link, Pair

LinkNames = Annotated[Any, Spec("items", expected=str, optional=True)]


class State:
    """What is known of a linkage while it is placed: every joint's path, every link's angle (θ, θ', θ''),
    its origin and the link each joint was made on (its carrier), over the crank angles ``phi``.

    ``strict``: raise the named error where a group cannot close; otherwise mark those rows in ``ok``
    (and leave NaN there), as the search for the reachable crank angles needs. ``before(group, phi)``: the
    linkage placed up to ``group`` at other crank angles (not strict), and ``grids``: what a group solved by
    continuation keeps for its linkage (its solution over a turn); ``carrier(joint)``: the link each joint was
    made on.
    """

    def __init__(self, phi: np.ndarray, fixed: dict, strict: bool, before=None, grids=None, carrier=None):
        self.phi, self.n, self.strict, self.fixed, self.carrier = phi, len(phi), strict, fixed, carrier
        self.before, self.grids = before, {} if grids is None else grids
        self.solved: dict[int, np.ndarray] = {}   # a group's unknowns where it solved them (its transmission)
        self.element = 0   # the index of the element being placed
        self.points: dict[str, PointPath] = {k: fixed_point(xy, len(phi)) for k, xy in fixed.items()}
        zero = np.zeros(len(phi))
        self.angles: dict[str, AnglePath] = {FRAME: AnglePath(zero, zero, zero)}
        self.origins: dict[str, str] = {}
        self.ok = np.ones(len(phi), dtype=bool)

    def z(self, joint: str):
        """A joint's positions and analogs as complex numbers (a scalar for a fixed joint)."""
        p = self.points[joint]
        return as_complex(p.p), as_complex(p.d), as_complex(p.dd)

    def closes(self, good: np.ndarray, group, why, flat=None) -> None:
        """Record where ``group`` closes; strict: raise at the first crank angle where it does not, ``why(i)``
        naming the violated condition there: SingularityError where ``flat`` (the group just reaches, at a dead
        point), AssemblyError otherwise."""
        good = np.broadcast_to(good, (self.n,)) & self.ok
        if self.strict and not good.all():
            i = int(np.argmin(good))
            at = f"{group.describe()} at φ = {np.degrees(self.phi[i]):.2f}°: {why(i)}"
            if flat is not None and np.broadcast_to(flat, (self.n,))[i]:
                raise SingularityError(f"dead point of {at}; the analogs are unbounded there")
            raise AssemblyError(f"{group.describe()} cannot close at φ = {np.degrees(self.phi[i]):.2f}°: {why(i)}")
        self.ok = good

    def dead(self, D, group) -> None:
        """SingularityError (strict) at the first row where a group's determinant D vanishes."""
        bad = ~(np.abs(D) > 0.0) & self.ok
        if self.strict and bad.any():
            i = int(np.argmax(bad))
            raise SingularityError(f"dead point of {group.describe()} at φ = {np.degrees(self.phi[i]):.2f}°: "
                                   f"its two constraints are parallel, the analogs are unbounded there")

    def path(self, z, dz, ddz) -> PointPath:
        return PointPath(*(as_xy(np.broadcast_to(v, (self.n,)).copy()) for v in (z, dz, ddz)))

    def link(self, name: str, origin: str, angle: AnglePath) -> None:
        self.origins[name], self.angles[name] = origin, angle


def _broadcast(z, n):
    return np.broadcast_to(z, (n,))


@dataclass(frozen=True)
class Guide(Checked):
    """A straight guide (or slot) fixed on the link ``on``: the line through joint ``through`` at ``angle``.

    Parameters
    ----------
    through : str
        A joint on the line.
    angle : float, optional
        The line's angle to the axis of the link ``on`` (radians).
    on : str, optional
        The link the guide is fixed on; by default the link ``through`` was made on (the frame for a frame
        point). Name it for a guide on another link through that joint (a slotted lever through its pivot).

    Examples
    --------
    >>> Guide("G", 0.0)
    Guide(through='G', angle=0.0, on=None)
    """

    through: Name
    angle: Angle = 0.0
    on: Annotated[str | None, Spec("text", optional=True)] = None

    def link(self, carrier) -> str:
        """The link the guide is fixed on.

        Parameters
        ----------
        carrier : callable
            ``carrier(joint) → link``: the link each known joint was made on.

        Returns
        -------
        str
            The link's name.
        """
        return self.on if self.on is not None else carrier(self.through)

    def line(self, state: State, carrier):
        """The line's point Q (complex: position, analogs) and its angle θ + angle with analogs.

        Parameters
        ----------
        state : State
            The linkage being placed.
        carrier : callable
            ``carrier(joint) → link``: the link each known joint was made on.

        Returns
        -------
        tuple
            Q's position and analogs as complex numbers, and the line's AnglePath.
        """
        th = state.angles[self.link(carrier)]
        return state.z(self.through), AnglePath(th.theta + self.angle, th.d, th.dd)


# a parameter that takes a Guide (TypeError naming it otherwise)
GuideSpec = Annotated[Any, mechanism(Guide)]


def _circle_rows(state, P, B, dB=None):
    """The circle constraint |B - P| = l differentiated: row a = B - P and b' = a·P' (or b'' = a·P'' - |B' - P'|²
    given B')."""
    zP, dP, ddP = P
    a = B - zP
    if dB is None:
        return a, _re_conj(a, _broadcast(dP, state.n))
    return a, _re_conj(a, _broadcast(ddP, state.n)) - _abs2(dB - dP)


def _line_rows(state, Q, th: AnglePath, B, dB=None):
    """The line constraint (B - Q)·n = 0, n = i·u, u = exp(iθ), differentiated (u' = θ'n, n' = -θ'u):
    n·B' = n·Q' + θ'(B - Q)·u and n·B'' = n·Q'' + 2θ'(B' - Q')·u + θ''(B - Q)·u + θ'²(B - Q)·n."""
    zQ, dQ, ddQ = Q
    u = np.exp(1j * th.theta)
    nrm = 1j * u
    r = B - zQ
    if dB is None:
        return nrm, _re_conj(nrm, _broadcast(dQ, state.n)) + th.d * _re_conj(r, u)
    return nrm, (_re_conj(nrm, _broadcast(ddQ, state.n)) + 2 * th.d * _re_conj(dB - dQ, u)
                 + th.dd * _re_conj(r, u) + th.d**2 * _re_conj(r, nrm))


def _cramer(a1, b1, a2, b2, D):
    """X with a1·X = b1, a2·X = b2 (complex rows): X = -i(b1·a2 - b2·a1)/D, D = a1 × a2."""
    return -1j * (b1 * a2 - b2 * a1) / D


class Group:
    """An element of a linkage: the joints it needs, the joints and links it makes, its pairs."""

    kind: ClassVar[str] = ""
    assur_class: ClassVar[int] = 2   # Artobolevsky's class and order of a dyad
    order: ClassVar[int] = 2

    def needs(self) -> tuple[str, ...]:
        """The joints this element needs placed before it.

        Returns
        -------
        tuple of str
            Joint names.
        """
        raise NotImplementedError

    def makes(self) -> tuple[str, ...]:
        """The joints this element defines.

        Returns
        -------
        tuple of str
            Joint names (empty for a group that makes none).
        """
        return ()

    def carriers(self, names: tuple[str, ...]) -> dict[str, str]:
        """The link each joint this element makes is fixed on (by default its first link).

        Parameters
        ----------
        names : tuple of str
            This element's link names.

        Returns
        -------
        dict
            Joint → link.
        """
        return dict.fromkeys(self.makes(), names[0])

    def guides(self) -> tuple[Guide, ...]:
        """The guides this element slides on.

        Returns
        -------
        tuple of Guide
            The guides (empty for none).
        """
        return ()

    def uses(self) -> tuple[str, ...]:
        """The links this element needs defined before it, beyond those its joints are on.

        Returns
        -------
        tuple of str
            Link names (none by default).
        """
        return ()

    def drawing(self, motion, structure) -> tuple:
        """What this element adds to the kinematic diagram beyond its links' bars and blocks.

        Parameters
        ----------
        motion : Motion
            The motion drawn.
        structure : Structure
            The linkage's structure.

        Returns
        -------
        tuple of Part
            Empty by default.
        """
        return ()

    def sliding(self) -> dict[str, Guide]:
        """The guide each of this element's sliding links slides on.

        Returns
        -------
        dict
            Link name → Guide (empty for an element without a slider).
        """
        return {}

    def link_names(self) -> tuple[str, ...]:
        """The names of the links this element adds.

        Returns
        -------
        tuple of str
            Link names, as given by ``links`` or by default from the joints' letters.
        """
        raise NotImplementedError

    def describe(self) -> str:
        """The element in words, for error messages.

        Returns
        -------
        str
            E.g. ``"the RRR group (AB, EB)"``.
        """
        return f"the {self.kind} group ({', '.join(self.link_names())})"

    def structure(self, carrier, links) -> tuple[tuple[Link, ...], tuple[Pair, ...]]:
        """The links and pairs this element adds to the linkage's structure.

        Parameters
        ----------
        carrier : callable
            ``carrier(joint) → link``: the link each known joint was made on.
        links : dict
            The links defined so far, by name.

        Returns
        -------
        tuple of (tuple of Link, tuple of Pair)
            The new links and their pairs.
        """
        raise NotImplementedError

    def place(self, state: State, carrier) -> None:
        """Place this element's joints and links over all crank angles of ``state`` (positions and analogs).

        Parameters
        ----------
        state : State
            The linkage's joints and link angles placed so far; the new ones are written into it.
        carrier : callable
            ``carrier(joint) → link``: the link each known joint was made on.

        Raises
        ------
        AssemblyError
            Where the group cannot close (a strict state; otherwise those rows are marked in ``state.ok``).
        SingularityError
            At a dead point of the group (a strict state).
        """
        raise NotImplementedError

    def transmission(self, state: State) -> np.ndarray:
        """The transmission angle μ of this group over the placed motion (π/2 is ideal).

        Parameters
        ----------
        state : State
            The placed linkage.

        Returns
        -------
        numpy.ndarray
            μ (radians) at every crank angle.
        """
        raise NotImplementedError

    def _names(self, default: tuple[str, str]) -> tuple[str, str]:
        return tuple(self.links) if self.links is not None else default


class _Dyad(Group):
    """A group of two links (class II): its optional link names are checked to be two."""

    def __post_init__(self):
        super().__post_init__()
        if self.links is not None and len(self.links) != 2:
            raise StructureError(f"links of a {self.kind} dyad: two names, got {self.links!r}")


@dataclass(frozen=True)
class Crank(Group, Checked):
    """The driver: a link turning about the frame pivot ``pivot``, its joint ``joint`` at crank angle φ.

    Parameters
    ----------
    pivot : str
        The frame point it turns about.
    joint : str
        The joint it carries, at angle φ from the x axis.
    radius : float
        |pivot joint| (positive length).
    name : str, optional
        The link's name.

    Raises
    ------
    DimensionError
        For a radius that is not positive and finite.

    Examples
    --------
    >>> Crank("O", "A", 1.0).describe()
    'the crank O-A'
    """

    pivot: Name
    joint: Name
    radius: Length
    name: Name = "crank"

    kind: ClassVar[str] = "crank"
    assur_class: ClassVar[int] = 1
    order: ClassVar[int] = 1

    def needs(self):
        return (self.pivot,)

    def makes(self):
        return (self.joint,)

    def link_names(self):
        return (self.name,)

    def describe(self):
        return f"the {self.name} {self.pivot}-{self.joint}"

    def structure(self, carrier, links):
        return ((Link(self.name, self.pivot, (self.pivot, self.joint), self.radius),),
                (Pair("revolute", self.pivot, carrier(self.pivot), self.name, self.pivot),))

    def place(self, state, carrier):
        state.points[self.joint] = crank_point(self.radius, state.phi, centre=state.fixed[self.pivot])
        state.link(self.name, self.pivot, AnglePath(state.phi, np.ones(state.n), np.zeros(state.n)))


class _OnGuide(_Dyad):
    """A dyad that places its new ``joint`` from a known ``pin`` and one straight ``guide``."""

    def needs(self):
        return (self.pin, self.guide.through)

    def guides(self):
        """The guides this element slides on: its one guide.

        Returns
        -------
        tuple of Guide
            The guides.
        """
        return (self.guide,)

    def makes(self):
        return (self.joint,)


def _place_inner(group, state, carrier, B, circles, lines):
    """The inner joint's analogs from its two differentiated constraints (``circles``: (P, l) about outer joints,
    ``lines``: (Q, θ) fixed on outer links), then the group's links."""
    rows = [(lambda dB=None, P=P: _circle_rows(state, P, B, dB)) for P in circles]
    rows += [(lambda dB=None, Q=Q, th=th: _line_rows(state, Q, th, B, dB)) for Q, th in lines]
    (a1, b1), (a2, b2) = (r() for r in rows)
    with np.errstate(invalid="ignore", divide="ignore"):
        D = _im_conj(a1, a2)
        state.dead(D, group)
        dB = _cramer(a1, b1, a2, b2, D)
        (_, c1), (_, c2) = (r(dB) for r in rows)
        state.points[group.joint] = state.path(B, dB, _cramer(a1, c1, a2, c2, D))
    group.links_placed(state, carrier)


def _place_crossing(group, state, carrier, first, second, why: str):
    """The inner joint where two lines (Q, θ) cross, Q1 + t·u1 with (Q1 + t·u1 - Q2) × u2 = 0; ``why`` names
    the lines when they are parallel."""
    (Q1, th1), (Q2, th2) = first, second
    u1, u2 = np.exp(1j * th1.theta), np.exp(1j * th2.theta)
    sin = _im_conj(u1, u2)
    state.closes(np.abs(sin) > DEAD_POINT_TOL, group, lambda i: why)
    with np.errstate(invalid="ignore", divide="ignore"):
        t = _im_conj(_broadcast(Q2[0] - Q1[0], state.n), u2) / sin
    _place_inner(group, state, carrier, Q1[0] + t * u1, (), (first, second))


def _bar_angle(state, start: str, end: str) -> AnglePath:
    return vector_angle(relative(state.points[end], state.points[start]))


@dataclass(frozen=True)
class RRR(_Dyad, Checked):
    """Two links pinned at the new joint ``joint`` and to the joints ``first`` and ``second``.

    |joint - first| = first_length, |joint - second| = second_length.

    Parameters
    ----------
    first, second : str
        The known joints the two links are pinned to.
    joint : str
        The new joint where the two links meet.
    first_length, second_length : float
        The two links' lengths (positive).
    assembly : {1, -1}, optional
        +1 puts the joint on the left of the directed line first → second, -1 on its right.
    links : sequence of str, optional
        The two links' names (default: the joints' letters, e.g. "AB", "EB").

    Raises
    ------
    DimensionError
        For a length that is not positive and finite.
    StructureError
        For ``links`` that are not two names.

    Examples
    --------
    >>> RRR("A", "E", "B", 3.0, 3.0).link_names()
    ('AB', 'EB')
    """

    first: Name
    second: Name
    joint: Name
    first_length: Length
    second_length: Length
    assembly: Sign = 1
    links: LinkNames = None

    kind: ClassVar[str] = "RRR"

    def needs(self):
        return (self.first, self.second)

    def makes(self):
        return (self.joint,)

    def link_names(self):
        return self._names((self.first + self.joint, self.second + self.joint))

    def structure(self, carrier, links):
        one, two = self.link_names()
        return ((Link(one, self.first, (self.first, self.joint), self.first_length),
                 Link(two, self.second, (self.second, self.joint), self.second_length)),
                (Pair("revolute", self.first, carrier(self.first), one, self.first),
                 Pair("revolute", self.joint, one, two, self.joint),
                 Pair("revolute", self.second, carrier(self.second), two, self.second)))

    def place(self, state, carrier):
        l1, l2 = self.first_length, self.second_length
        P1, P2 = state.z(self.first), state.z(self.second)
        v = _broadcast(P2[0] - P1[0], state.n)
        d2 = _abs2(v)
        tol = DEAD_POINT_TOL * (l1 + l2)
        lo, hi = abs(l1 - l2), l1 + l2
        flat = ((d2 <= (hi + tol) ** 2) & (d2 >= (hi - tol) ** 2)) | (d2 <= (lo + tol) ** 2) & (d2 >= (lo - tol) ** 2)
        state.closes((d2 > (lo + tol) ** 2) & (d2 < (hi - tol) ** 2), self, lambda i: (
            f"|{self.first}{self.second}| = {np.sqrt(d2[i]):.6g} must lie strictly between the difference and the "
            f"sum of the lengths {l1:g} and {l2:g}, ({lo:.6g}, {hi:.6g})"), flat)
        with np.errstate(invalid="ignore", divide="ignore"):
            d = np.sqrt(d2)
            a = (d2 + l1 * l1 - l2 * l2) / (2 * d)
            h = self.assembly * np.sqrt(np.maximum(l1 * l1 - a * a, 0.0))
            B = P1[0] + (a + 1j * h) * v / d
        _place_inner(self, state, carrier, B, (P1, P2), ())

    def links_placed(self, state, carrier):
        """Record the angles of this group's links (θ, θ', θ'') in ``state`` once its joint is placed.

        Parameters
        ----------
        state : State
            The linkage being placed.
        carrier : callable
            ``carrier(joint) → link``: the link each known joint was made on.
        """
        one, two = self.link_names()
        state.link(one, self.first, _bar_angle(state, self.first, self.joint))
        state.link(two, self.second, _bar_angle(state, self.second, self.joint))

    def transmission(self, state):
        """μ at the inner joint between its two links (cos μ = (B→first)·(B→second)/(l1·l2)).

        Parameters
        ----------
        state : State
            The placed linkage.

        Returns
        -------
        numpy.ndarray
            μ (radians) at every crank angle.
        """
        B, P1, P2 = (as_complex(state.points[k].p) for k in (self.joint, self.first, self.second))
        cos = _re_conj(P1 - B, P2 - B) / (self.first_length * self.second_length)
        return np.arccos(np.clip(cos, -1.0, 1.0))


def _turning_with(link: Link, angle: float):
    """The axis of a link that turns with ``link`` at a fixed ``angle`` to its axis: (θ + angle, θ', θ'')."""
    def axis(motion):
        th = link.angle(motion)
        return th.theta + angle, th.d, th.dd
    return axis


def _guide_axis(guide: Guide, on: str, links):
    """The axis of a link sliding on ``guide``: its constant angle on the frame, else turning with the guide's link."""
    return guide.angle if on == FRAME else _turning_with(links[on], guide.angle)


@dataclass(frozen=True)
class RRP(_OnGuide, Checked):
    """A rod ``pin``-``joint`` of ``length`` and a slider at ``joint`` on the straight ``guide``.

    Parameters
    ----------
    pin : str
        The known joint the rod is pinned to.
    joint : str
        The new joint: the slider's pin.
    length : float
        The rod's length (positive).
    guide : Guide
        The straight guide (on any link) the slider runs on.
    assembly : {1, -1}, optional
        +1 takes the slider ahead of the pin's foot along the guide, -1 behind.
    links : sequence of str, optional
        The rod's and the slider's names (default "AB" and "slider B").

    Raises
    ------
    DimensionError
        For a length that is not positive and finite.
    StructureError
        For ``links`` that are not two names.

    Examples
    --------
    >>> RRP("A", "B", 3.0, Guide("G")).link_names()
    ('AB', 'slider B')
    """

    pin: Name
    joint: Name
    length: Length
    guide: GuideSpec
    assembly: Sign = 1
    links: LinkNames = None

    kind: ClassVar[str] = "RRP"

    def sliding(self):
        return {self.link_names()[1]: self.guide}

    def link_names(self):
        return self._names((self.pin + self.joint, f"slider {self.joint}"))

    def structure(self, carrier, links):
        rod, slider = self.link_names()
        on = self.guide.link(carrier)
        return ((Link(rod, self.pin, (self.pin, self.joint), self.length),
                 Link(slider, self.joint, _guide_axis(self.guide, on, links), block=on != FRAME)),
                (Pair("revolute", self.pin, carrier(self.pin), rod, self.pin),
                 Pair("revolute", self.joint, rod, slider, self.joint),
                 Pair("prismatic", f"{slider} on {on}", on, slider, self.joint, self.guide.angle)))

    def place(self, state, carrier):
        r = self.length
        P = state.z(self.pin)
        Q, th = self.guide.line(state, carrier)
        u = np.exp(1j * th.theta)
        w = _broadcast(P[0] - Q[0], state.n)
        off = _im_conj(u, w)
        disc = r * r - off * off
        state.closes(disc > DEAD_POINT_TOL * r * r, self, lambda i: (
            f"the pin {self.pin} is {abs(off[i]):.6g} from the guide, not less than the rod's length {r:g}"),
            np.abs(disc) <= DEAD_POINT_TOL * r * r)
        with np.errstate(invalid="ignore"):
            t = _re_conj(w, u) + self.assembly * np.sqrt(disc)
        _place_inner(self, state, carrier, Q[0] + t * u, (P,), ((Q, th),))

    def links_placed(self, state, carrier):
        """Record the angles of this group's links (θ, θ', θ'') in ``state`` once its joint is placed.

        Parameters
        ----------
        state : State
            The linkage being placed.
        carrier : callable
            ``carrier(joint) → link``: the link each known joint was made on.
        """
        rod, slider = self.link_names()
        state.link(rod, self.pin, _bar_angle(state, self.pin, self.joint))
        state.link(slider, self.joint, self.guide.line(state, carrier)[1])

    def transmission(self, state):
        """μ between the rod and the guide's normal (as :class:`~mechlab.SliderCrank`): π/2 with the rod on the guide.

        Parameters
        ----------
        state : State
            The placed linkage.

        Returns
        -------
        numpy.ndarray
            μ (radians) at every crank angle.
        """
        rod = as_complex(state.points[self.joint].p) - as_complex(state.points[self.pin].p)
        u = np.exp(1j * state.angles[self.link_names()[1]].theta)
        return np.pi / 2 - np.arcsin(np.clip(np.abs(_im_conj(u, rod)) / self.length, 0.0, 1.0))


@dataclass(frozen=True)
class RPR(_Dyad, Checked):
    """A block pinned at the joint ``pin`` slides in the straight slot of a link pivoted at the joint ``pivot``.

    The slot passes through the pivot, so the link turns with the line pivot → pin.

    Parameters
    ----------
    pin : str
        The known joint the block is pinned to.
    pivot : str
        The known joint the slotted link turns about.
    length : float, optional
        The slotted link's length (to draw it; points on it are placed with :class:`Point`).
    links : sequence of str, optional
        The block's and the slotted link's names (default "block A" and "EA" for pin A, pivot E).

    Raises
    ------
    StructureError
        For ``links`` that are not two names.

    Examples
    --------
    >>> RPR("A", "P", length=2.0).link_names()
    ('block A', 'PA')
    """

    pin: Name
    pivot: Name
    length: Distance = 0.0
    links: LinkNames = None

    kind: ClassVar[str] = "RPR"

    def needs(self):
        return (self.pin, self.pivot)

    def link_names(self):
        return self._names((f"block {self.pin}", self.pivot + self.pin))

    def structure(self, carrier, links):
        block, lever = self.link_names()
        return ((Link(block, self.pin, (self.pivot, self.pin), block=True),
                 Link(lever, self.pivot, (self.pivot, self.pin), self.length)),
                (Pair("revolute", self.pin, carrier(self.pin), block, self.pin),
                 Pair("prismatic", f"{block} in {lever}", lever, block, self.pin, 0.0),
                 Pair("revolute", self.pivot, carrier(self.pivot), lever, self.pivot)))

    def place(self, state, carrier):
        v = relative(state.points[self.pin], state.points[self.pivot])
        rho2 = _abs2(_broadcast(as_complex(v.p), state.n))
        scale = max(self.length, float(np.sqrt(np.nanmax(rho2))) if state.n else 0.0, 1e-300)
        state.closes(rho2 > (DEAD_POINT_TOL * scale) ** 2, self, lambda i: (
            f"the pin {self.pin} passes through the pivot {self.pivot}, where the slot's direction is undefined"))
        with np.errstate(invalid="ignore", divide="ignore"):
            angle = vector_angle(PointPath(*(np.broadcast_to(a, (state.n, 2)).copy() for a in v)))
        block, lever = self.link_names()
        state.link(block, self.pin, angle)
        state.link(lever, self.pivot, angle)

    def transmission(self, state):
        """π/2: the pin pushes the slot along its normal (as :class:`~mechlab.SlottedLink`).

        Parameters
        ----------
        state : State
            The placed linkage.

        Returns
        -------
        numpy.ndarray
            μ (radians) at every crank angle.
        """
        return np.full(state.n, np.pi / 2)


@dataclass(frozen=True)
class PRP(_Dyad, Checked):
    """Two blocks pinned together at the new joint ``joint``, each on a guide: the joint is where the lines cross.

    Parameters
    ----------
    first, second : Guide
        The guides (on any links) of the first and the second block.
    joint : str
        The new joint: the blocks' common pin.
    links : sequence of str, optional
        The two blocks' names (default "slider B" and "block B").

    Raises
    ------
    StructureError
        For ``links`` that are not two names.

    Examples
    --------
    >>> PRP(Guide("O", 0.0), Guide("A", 1.0), "B").link_names()
    ('slider B', 'block B')
    """

    first: GuideSpec
    second: GuideSpec
    joint: Name
    links: LinkNames = None

    kind: ClassVar[str] = "PRP"

    def sliding(self):
        return dict(zip(self.link_names(), (self.first, self.second), strict=True))

    def needs(self):
        return (self.first.through, self.second.through)

    def guides(self):
        """The guides this element slides on: the first and the second.

        Returns
        -------
        tuple of Guide
            The guides.
        """
        return (self.first, self.second)

    def makes(self):
        return (self.joint,)

    def link_names(self):
        return self._names((f"slider {self.joint}", f"block {self.joint}"))

    def structure(self, carrier, links):
        one, two = self.link_names()
        on1, on2 = self.first.link(carrier), self.second.link(carrier)
        return ((Link(one, self.joint, _guide_axis(self.first, on1, links)),
                 Link(two, self.joint, _guide_axis(self.second, on2, links), block=True)),
                (Pair("prismatic", f"{one} on {on1}", on1, one, self.joint, self.first.angle),
                 Pair("revolute", self.joint, one, two, self.joint),
                 Pair("prismatic", f"{two} on {on2}", on2, two, self.joint, self.second.angle)))

    def place(self, state, carrier):
        _place_crossing(self, state, carrier, *(g.line(state, carrier) for g in (self.first, self.second)),
                        "its two guides are parallel")

    def links_placed(self, state, carrier):
        """Record the angles of this group's links (θ, θ', θ'') in ``state`` once its joint is placed.

        Parameters
        ----------
        state : State
            The linkage being placed.
        carrier : callable
            ``carrier(joint) → link``: the link each known joint was made on.
        """
        one, two = self.link_names()
        state.link(one, self.joint, self.first.line(state, carrier)[1])
        state.link(two, self.joint, self.second.line(state, carrier)[1])

    def transmission(self, state):
        """μ = the angle between the two guides: π/2 when the first block pushes along the second guide.

        Parameters
        ----------
        state : State
            The placed linkage.

        Returns
        -------
        numpy.ndarray
            μ (radians) at every crank angle.
        """
        one, two = self.link_names()
        return np.abs(np.mod(state.angles[two].theta - state.angles[one].theta + np.pi, 2 * np.pi) - np.pi)


@dataclass(frozen=True)
class RPP(_OnGuide, Checked):
    """A block pinned at the joint ``pin`` slides in the straight slot of a link that slides on ``guide``.

    The slotted link (a yoke) slides along the guide and carries its slot at ``slot`` to the guide; the new
    joint ``joint`` is where the slot's centre line crosses the guide, the yoke's reference point. A yoke on a
    frame guide translates; on a guide fixed on a moving link it turns with that link.

    Parameters
    ----------
    pin : str
        The known joint the block is pinned to.
    joint : str
        The new joint: the slot's centre line on the guide.
    guide : Guide
        The straight guide (on any link) the yoke slides on.
    slot : float, optional
        The slot's angle to the guide (radians; π/2, the default, is the Scotch yoke's).
    links : sequence of str, optional
        The block's and the yoke's names (default "block A" and "yoke K" for pin A, joint K).

    Raises
    ------
    DimensionError
        For an angle that is not finite.
    StructureError
        For ``links`` that are not two names.

    Examples
    --------
    >>> RPP("A", "K", Guide("O")).link_names()
    ('block A', 'yoke K')
    """

    pin: Name
    joint: Name
    guide: GuideSpec
    slot: Angle = np.pi / 2
    links: LinkNames = None

    kind: ClassVar[str] = "RPP"

    def sliding(self):
        return {self.link_names()[1]: self.guide}

    def carriers(self, names):
        """The link each new joint is fixed on: the yoke carries ``joint``.

        Parameters
        ----------
        names : tuple of str
            This group's link names.

        Returns
        -------
        dict
            Joint → link.
        """
        return {self.joint: names[1]}

    def link_names(self):
        return self._names((f"block {self.pin}", f"yoke {self.joint}"))

    def structure(self, carrier, links):
        block, yoke = self.link_names()
        on = self.guide.link(carrier)
        turned = self.guide.angle + self.slot
        return ((Link(block, self.pin, turned if on == FRAME else _turning_with(links[on], turned), block=True),
                 Link(yoke, self.joint, _guide_axis(self.guide, on, links))),
                (Pair("revolute", self.pin, carrier(self.pin), block, self.pin),
                 Pair("prismatic", f"{block} in {yoke}", yoke, block, self.pin, self.slot),
                 Pair("prismatic", f"{yoke} on {on}", on, yoke, self.joint, self.guide.angle)))

    def _slot_line(self, state, carrier):
        Q, th = self.guide.line(state, carrier)
        return Q, th, state.z(self.pin), AnglePath(th.theta + self.slot, th.d, th.dd)

    def place(self, state, carrier):
        Q, th, P, ths = self._slot_line(state, carrier)
        _place_crossing(self, state, carrier, (Q, th), (P, ths), "its slot is parallel to its guide")

    def links_placed(self, state, carrier):
        """Record the angles of this group's links (θ, θ', θ'') in ``state`` once its joint is placed.

        Parameters
        ----------
        state : State
            The linkage being placed.
        carrier : callable
            ``carrier(joint) → link``: the link each known joint was made on.
        """
        block, yoke = self.link_names()
        _, th, _, ths = self._slot_line(state, carrier)
        state.link(block, self.pin, ths)
        state.link(yoke, self.joint, th)

    def transmission(self, state):
        """μ = the acute angle between the slot and the guide (π/2 when the block pushes along the guide).

        Parameters
        ----------
        state : State
            The placed linkage.

        Returns
        -------
        numpy.ndarray
            μ (radians) at every crank angle.
        """
        return np.full(state.n, np.arcsin(min(abs(np.sin(self.slot)), 1.0)))


@dataclass(frozen=True)
class Point(Checked):
    """A point ``name`` fixed on the link ``on`` (a coupler point, the far end of a lever).

    Parameters
    ----------
    name : str
        The new joint's name.
    on : str
        The link it is fixed on.
    at : tuple of float, optional
        (ξ, η) in the link's coordinates: ξ along its axis from its origin joint, η to the axis' left (length).

    Examples
    --------
    >>> Point("C", "AB", (1.5, 0.8)).makes()
    ('C',)
    """

    name: Name
    on: Name
    at: Annotated[tuple, Spec("point")] = (0.0, 0.0)

    def needs(self):
        """The joints a point needs placed before it: none (its link's origin and angle are known once the link is).

        Returns
        -------
        tuple of str
            ``()``.
        """
        return ()

    def makes(self):
        """The joint this point defines.

        Returns
        -------
        tuple of str
            ``(name,)``.
        """
        return (self.name,)

    def place(self, state, carrier):
        """Place the point over all crank angles of ``state`` (positions and analogs).

        Parameters
        ----------
        state : State
            The linkage's joints and link angles placed so far; the new ones are written into it.
        carrier : callable
            ``carrier(joint) → link``: the link each known joint was made on.
        """
        O = state.z(state.origins[self.on])
        th = state.angles[self.on]
        r = complex(*self.at) * np.exp(1j * th.theta)
        z = O[0] + r
        state.points[self.name] = state.path(z, O[1] + 1j * th.d * r, O[2] + (1j * th.dd - th.d**2) * r)
