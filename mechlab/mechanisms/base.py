"""What every mechanism shares: the crank's reachable angles, the cycle, the description of its
structure (links, pairs, structural groups) from which the instantaneous centres, the kinetostatics
and the curved-slot equivalence are derived, and its sketch, from which it is drawn."""

from __future__ import annotations

import re
import sys
from collections.abc import Callable
from dataclasses import dataclass
from typing import Annotated, Any, ClassVar

import numpy as np

from ..errors import AssemblyError, MechanismError, RotationError, SpatialMechanismError
from ..geometry import AnglePath, lift, relative, unit, vector_angle
from ..motion import AngularMotion, Motion, scalar_in_scalar_out
from ..validate import Checked, Samples, mechanism, validated

TWO_PI = 2.0 * np.pi
FULL_TURN = ((0.0, TWO_PI),)
# cos(φ - phase) this close to a bound counts as reaching it (the dyads' dead-point tolerance)
TOUCH = 1e-12


def arc_set(lo: float, hi: float, phase: float = 0.0) -> tuple[tuple[float, float], ...]:
    """The crank angles φ with lo < cos(φ - phase) < hi, as open intervals (radians).

    Returns ``FULL_TURN`` when every angle qualifies, ``()`` when none does, else one
    or two intervals ``(start, end)`` with ``start < end``. A bound reached to within
    TOUCH (a linkage folding flat at one angle, e.g. a change-point four-bar) excludes
    that angle and its rounding neighbourhood: such a crank does not turn fully.
    """
    lo, hi = lo + TOUCH, hi - TOUCH
    if lo >= 1.0 or hi <= -1.0 or lo >= hi:
        return ()
    if lo < -1.0 and hi > 1.0:
        return FULL_TURN
    a = float(np.arccos(min(hi, 1.0)))
    b = float(np.arccos(max(lo, -1.0)))
    if hi > 1.0:
        arcs = ((-b, b),)
    elif lo < -1.0:
        arcs = ((a, TWO_PI - a),)
    else:
        arcs = ((a, b), (-b, -a))
    return tuple((s + phase, e + phase) for s, e in arcs)


# the frame's name in a structure's pairs
FRAME = "frame"
PAIR_KINDS = ("revolute", "prismatic", "higher")


@dataclass(frozen=True)
class Link:
    """A moving link: a joint ``origin`` fixed on it and its x axis.

    ``axis``: a pair of joint names (P, Q), the direction P→Q fixed in the link; an angle (radians) for a
    link that translates; or ``axis(motion) → (θ, θ′, θ″)``. ``length`` is a bar's length (a uniform
    bar's centre of mass lies half-way along the axis). ``block``: a sliding block, which the
    instantaneous centres merge with its two pairs into one higher pair (Kozhevnikov, §7.1).
    ``label``: the link's name in the centres' numbering, where it differs from ``name``. ``joints``: the
    joints the drawing's bar (or plate, the first joint repeated last) passes through; none for a link
    drawn otherwise (a block, a slotted link, a wheel, a cam).
    """

    name: str
    origin: str
    axis: Any = 0.0
    length: float = 0.0
    block: bool = False
    label: str = ""
    joints: tuple[str, ...] = ()

    @property
    def translates(self) -> bool:
        """True when the axis is a constant angle: the link only translates."""
        return not (callable(self.axis) or isinstance(self.axis, tuple))

    def angle(self, motion: Motion) -> AnglePath:
        """The axis' angle θ with θ′, θ″ over the motion."""
        if callable(self.axis):
            return AnglePath(*(np.asarray(v, dtype=float) for v in self.axis(motion)))
        if isinstance(self.axis, tuple):
            P, Q = self.axis
            return vector_angle(relative(motion.points[Q], motion.points[P]))
        n = len(motion.phi)
        return AnglePath(np.full(n, float(self.axis)), np.zeros(n), np.zeros(n))


@dataclass(frozen=True)
class Pair:
    """A kinematic pair of links ``a`` and ``b`` (or :data:`FRAME`) at the joint ``point``.

    ``kind``: ``"revolute"``; ``"prismatic"`` (b slides on a along a guide at ``angle`` to a's axis);
    ``"higher"`` (contact along a common normal: ``normal`` is its angle to a's axis, or
    ``normal(motion) → (n, 2)`` unit vectors in the fixed frame).
    """

    kind: str
    name: str
    a: str
    b: str
    point: str
    angle: float = 0.0
    normal: Any = np.pi / 2

    def __post_init__(self):
        if self.kind not in PAIR_KINDS:
            raise MechanismError(f"pair {self.name}: kind must be one of {PAIR_KINDS}, got {self.kind!r}")


@dataclass(frozen=True)
class Structure:
    """How a mechanism is built, described once.

    ``links``: the moving links, the input (driving) link first; ``pairs``: every kinematic pair;
    ``groups``: the structural (Assur) groups of links, from the output back to the input, which
    is attached to the frame by its own revolute pair; ``output``: the link whose law the motion
    reports; ``scale``: a typical length. ``numbering``: the links' labels, the frame included,
    in the order the drawing, the instantaneous centres and the force model number them (default: the
    links but the blocks, then the frame: :meth:`numbers`); ``input_rate``: dθ/dφ of the input link (1 for a
    crank). ``spatial``: why the mechanism is not planar (its links move on a sphere), empty for a planar
    one; the planar methods (centres, kinetostatics, the curved-slot twin) refuse a spatial structure.
    """

    links: tuple[Link, ...]
    pairs: tuple[Pair, ...]
    groups: tuple[tuple[str, ...], ...]
    output: str
    scale: float
    numbering: tuple[str, ...] = ()
    input_rate: float = 1.0
    spatial: str = ""

    @property
    def input(self) -> str:
        return self.links[0].name

    def order(self) -> tuple[str, ...]:
        """The numbered links' labels (a link's ``label``, else its name) in the order of their numbers.

        ``numbering`` when given (Kozhevnikov's for the trammel), else the moving links but the blocks (a
        block merges with its two pairs into one higher pair and carries no number), then :data:`FRAME`.
        MechanismError when ``numbering`` names a link the structure lacks, one twice, or not the frame.
        """
        labels = {k.name: k.label or k.name for k in self.links}
        if self.numbering:
            order = tuple(labels.get(name, name) for name in self.numbering)
        else:
            order = (*(labels[k.name] for k in self.links if not k.block), FRAME)
        unknown = sorted(set(order) - set(labels.values()) - {FRAME})
        if unknown or len(set(order)) != len(order) or FRAME not in order:
            raise MechanismError(f"numbering {order} must name links at most once each and the frame once; "
                                 f"links: {', '.join(labels.values())}")
        return order

    def numbers(self) -> dict[str, int]:
        """Each numbered link's number, the frame's included: the one numbering of drawing, centres and forces.

        Returns
        -------
        dict
            Number (from 1) of each link in :meth:`order`, keyed by its name, by its label where it has
            one, and by :data:`FRAME`.

        Raises
        ------
        MechanismError
            ``numbering`` names a link the structure does not have, or one twice.

        Examples
        --------
        >>> import mechlab as ml
        >>> st = ml.SlottedLink(0.5, 1.0).structure()
        >>> st.numbers()["link"], st.numbers()["frame"]
        (2, 3)
        """
        name = {k.label or k.name: k.name for k in self.links}
        numbers = {}
        for i, label in enumerate(self.order(), start=1):
            numbers[label] = numbers[name.get(label, label)] = i
        return numbers

    def planar(self, what: str = "planar instantaneous centres and the planar kinetostatics do not apply"
               ) -> Structure:
        """This structure, or SpatialMechanismError for a spatial one (``what``: why the caller needs it planar)."""
        if self.spatial:
            raise SpatialMechanismError(f"{self.spatial}: it has no planar structure, so {what}")
        return self

    def link(self, name: str) -> Link:
        for link in self.links:
            if name in (link.name, link.label):
                return link
        raise MechanismError(f"no link {name!r}; links: {', '.join(k.name for k in self.links)}")

    def mobility(self, group: tuple[str, ...] | None = None) -> int:
        """Mobility W = 3n - 2p₅ - p₄ (Chebyshev-Grübler; Artobolevsky, 1965).

        n moving links (those of ``group`` when given, else all), p₅ the lower pairs (revolute,
        prismatic) and p₄ the higher pairs that join them to the rest; a group of ``groups`` leaves
        out the pairs to the groups listed before it, which are detached first (from the output
        back). A structural (Assur) group has W = 0, a mechanism driven by one crank W = 1.
        """
        names = {k.name for k in self.links} if group is None else set(group)
        unknown = sorted(names - {k.name for k in self.links})
        if unknown:
            raise MechanismError(f"group names no link {unknown}; links: {', '.join(k.name for k in self.links)}")
        group = tuple(group or ())
        detached = {k for g in self.groups[:self.groups.index(group)] for k in g} if group in self.groups else set()
        joining = [p for p in self.pairs if (p.a in names or p.b in names) and not {p.a, p.b} & detached]
        higher = sum(p.kind == "higher" for p in joining)
        return 3 * len(names) - 2 * (len(joining) - higher) - higher

    def frame_pair(self, link: str) -> Pair:
        """The pair joining ``link`` to the frame."""
        for p in self.pairs:
            if FRAME in (p.a, p.b) and link in (p.a, p.b):
                return p
        raise MechanismError(f"the {link} is not joined to the frame")


@dataclass(frozen=True)
class Part:
    """One piece of a mechanism's kinematic diagram.

    ``role`` names its style in the drawing ("link", "output", "guide", "highlight", "extra", "slot",
    "profile", "fill", "anchor" (not drawn: only carries a number), "note" (a text), …); ``at`` is a
    tuple of joint names (a bar through them) or ``at(i)`` → the polyline (k, 2) at frame i (NaN rows
    break it; a ``note``'s text); ``number``: the name of the structure's link whose number the part
    carries (:meth:`Structure.numbers`), or None.
    """

    role: str
    at: tuple[str, ...] | Callable[[int], Any]
    number: str | None = None

    def points(self, points: dict, i: int):
        """The polyline at frame i (``points``: the motion's paths)."""
        if isinstance(self.at, tuple):
            return np.array([points[k].p[i] for k in self.at])
        return self.at(i)


@dataclass(frozen=True)
class Sketch:
    """What a drawing shows of a mechanism: its ``parts`` in drawing order and the joints fixed to the frame
    (hatched supports); the links' numbers are the structure's (:meth:`Structure.numbers`)."""

    parts: tuple[Part, ...]
    pivots: tuple[str, ...]


def bars(st: Structure) -> tuple[Part, ...]:
    """A bar through the ``joints`` of each link of the structure that has some, carrying its number."""
    return tuple(Part("link", k.joints, k.name) for k in st.links if k.joints)


@validated
def output_axis(motion: Annotated[AngularMotion, mechanism(AngularMotion)]) -> tuple:
    """The output angle ψ with ψ′, ψ″: the axis of a link that turns with the output.

    Parameters
    ----------
    motion : AngularMotion
        A motion whose output is an angle.

    Returns
    -------
    tuple of numpy.ndarray
        ψ (radians), ψ′ and ψ″.

    Raises
    ------
    TypeError
        If ``motion`` is not an :class:`~mechlab.motion.AngularMotion`.

    Examples
    --------
    >>> from mechlab import FourBar
    >>> psi, dpsi, ddpsi = output_axis(FourBar(1, 3, 3.5, 4).motion(0.3))
    >>> round(float(psi), 4), round(float(dpsi), 4)
    (2.1036, -0.2569)
    """
    return motion.psi, motion.dpsi, motion.ddpsi


def block_outline(centre, u, length: float, width: float) -> np.ndarray:
    """A slider block ``length`` × ``width`` centred on ``centre``, its length along the unit vector u
    (a closed polyline)."""
    u = np.asarray(u, dtype=float)
    n = np.array([-u[1], u[0]])
    return np.array([centre + a * length / 2 * u + b * width / 2 * n
                     for a, b in ((-1, -1), (1, -1), (1, 1), (-1, 1), (-1, -1))])


def fmt_ranges(ranges) -> str:
    return " or ".join(f"[{np.degrees(s):.2f}°, {np.degrees(e):.2f}°]" for s, e in ranges)


class Mechanism(Checked):
    """Base of the single-loop mechanisms: a crank O-A driving one output.

    Subclasses are frozen dataclasses of their dimensions and define :meth:`crank_ranges`, :meth:`motion`
    and :meth:`structure` (its links, pairs and groups, from which the drawing, the centres, the force
    model and the design layer's counts are read). ``pivots`` (a class attribute) names the joints fixed to
    the frame, ``output`` is ``"angle"`` or ``"position"``. The constructor takes the family's dimensions
    (lengths dimensionless or mm) and raises DimensionError for one that is out of range.

    Examples
    --------
    >>> from mechlab import FourBar, Mechanism
    >>> m = FourBar(1, 3, 3.5, 4)
    >>> isinstance(m, Mechanism), m.pivots, m.output
    (True, ('O', 'E'), 'angle')
    """

    pivots: ClassVar[tuple[str, ...]] = ("O",)
    output: ClassVar[str] = "angle"
    # the family's name in words (default: its class name, "SliderCrank" → "slider crank")
    title: ClassVar[str] = "mechanism"
    # what the kinematic structure leaves out and the design layer counts: rollers (each a part on its own pin)
    # and passive higher pairs (a Geneva drive's locking arcs)
    rollers: ClassVar[int] = 0
    locks: ClassVar[int] = 0

    def __init_subclass__(cls, **kwargs):
        # every family's motion(phi): a scalar φ in, a motion of scalars out
        super().__init_subclass__(**kwargs)
        if "motion" in cls.__dict__:
            cls.motion = scalar_in_scalar_out(cls.__dict__["motion"])
        if "title" not in cls.__dict__:
            cls.title = re.sub(r"(?<=[a-z])(?=[A-Z])", " ", cls.__name__.lstrip("_")).lower()

    @classmethod
    def example(cls) -> Mechanism:
        """A valid instance of the family, built from its own dimensions: what the services that find the
        families themselves (:meth:`families`) draw, move, count and fuzz.

        A family defines it on its class (a subclass that only changes a method inherits none of its own and
        is no family of its own).

        Raises
        ------
        MechanismError
            The class defines no example.

        Examples
        --------
        >>> import mechlab as ml
        >>> ml.FourBar.example().can_turn
        True
        """
        raise MechanismError(f"{cls.__name__} defines no example(): give the family a classmethod example() "
                             f"that builds one valid instance")

    @classmethod
    def families(cls) -> tuple[type[Mechanism], ...]:
        """Every family at or below this class: the subclasses that define their own :meth:`example`.

        Found at call time by walking ``__subclasses__()``, so a family defined anywhere (a notebook cell, a
        test module) is found as soon as its class exists; nothing is registered. Ordered by module and name.

        Returns
        -------
        tuple of type
            The family classes.

        Examples
        --------
        >>> import mechlab as ml
        >>> ml.FourBar in ml.Mechanism.families()
        True
        """
        found, todo = {}, [cls]
        while todo:
            c = todo.pop()
            if "example" in c.__dict__ and c is not Mechanism and _still_defined(c):
                found[c] = None
            todo += c.__subclasses__()
        return tuple(sorted(found, key=lambda c: (c.__module__, c.__qualname__)))

    def crank_ranges(self) -> tuple[tuple[float, float], ...]:
        """Open intervals of crank angles where the mechanism assembles.

        Returns
        -------
        tuple of (float, float)
            ``((0, 2π),)`` for a crank that turns fully, else one or two intervals ``(start, end)``
            (radians, ``start < end``); ``()`` if none.

        Examples
        --------
        >>> from mechlab import FourBar
        >>> [tuple(round(x, 4) for x in r) for r in FourBar(3, 2, 4, 4).crank_ranges()]
        [(0.5054, 2.0469), (-2.0469, -0.5054)]
        """
        return FULL_TURN

    @property
    def can_turn(self) -> bool:
        """True when the crank turns fully (a revolving input).

        Returns
        -------
        bool
            Whether :meth:`crank_ranges` is the full turn.
        """
        return self.crank_ranges() == FULL_TURN

    def rotation_failure(self) -> str:
        """Why the crank cannot turn fully (subclasses name the inequality).

        Returns
        -------
        str
            The violated condition with its numbers and the reachable range (degrees).

        Examples
        --------
        >>> from mechlab import FourBar
        >>> FourBar(3, 2, 4, 4).rotation_failure()
        'crank cannot turn fully: s + l = 6.00 < p + q = 7.00 (Grashof), but the shortest link is ...'
        """
        return f"crank cannot turn fully: it reaches only φ ∈ {fmt_ranges(self.crank_ranges())}"

    @validated
    def turn(self, n: Samples = 361) -> np.ndarray:
        """n crank angles over one full turn [0, 2π].

        Parameters
        ----------
        n : int, optional
            Number of samples (≥ 2).

        Returns
        -------
        numpy.ndarray
            ``n`` equally spaced crank angles (radians), both ends included.

        Raises
        ------
        RotationError
            If the crank cannot turn fully.
        DimensionError
            If ``n`` is not an admissible number of samples.

        Examples
        --------
        >>> from mechlab import FourBar
        >>> FourBar(1, 3, 3.5, 4).turn(5)
        array([0.        , 1.57079633, 3.14159265, 4.71238898, 6.28318531])
        """
        if not self.can_turn:
            raise RotationError(self.rotation_failure())
        return np.linspace(0.0, TWO_PI, n)

    @validated
    def cycle(self, n: Samples = 361) -> np.ndarray:
        """n crank angles over a full turn, or strictly inside the first reachable range.

        A crank that cannot turn rocks between two dead points, where the analogs are unbounded; the samples
        stop short of them by 1e-4 of the range (where a joint distance is stationary at a dead point, as at
        φ = 0 or π, it moves away from the dead point only with the square of the margin).

        Parameters
        ----------
        n : int, optional
            Number of samples (≥ 2).

        Returns
        -------
        numpy.ndarray
            ``n`` crank angles (radians).

        Raises
        ------
        DimensionError
            If ``n`` is not an admissible number of samples.

        Examples
        --------
        >>> from mechlab import FourBar
        >>> FourBar(3, 2, 4, 4).cycle(3)
        array([0.50551467, 1.27613795, 2.04676123])
        """
        if self.can_turn:
            return self.turn(n)
        start, end = self.crank_ranges()[0]
        margin = 1e-4 * (end - start)
        return np.linspace(start + margin, end - margin, n)

    def check_reachable(self, phi: np.ndarray) -> None:
        """Check that every crank angle lies in a reachable range.

        Parameters
        ----------
        phi : numpy.ndarray
            Crank angles (radians), one-dimensional.

        Raises
        ------
        AssemblyError
            Naming the first unreachable angle, why (:meth:`assembly_failure`) and the reachable range.

        Examples
        --------
        >>> import numpy as np
        >>> from mechlab import FourBar
        >>> FourBar(3, 2, 4, 4).check_reachable(np.array([0.0]))
        Traceback (most recent call last):
        ...
        mechlab.errors.AssemblyError: cannot assemble at φ = 0.00°: |AE| = 1 ≤ |coupler - rocker| = 2; ...
        """
        ranges = self.crank_ranges()
        if ranges == FULL_TURN:
            return
        inside = np.zeros(phi.shape, dtype=bool)
        for start, end in ranges:
            t = np.mod(phi - start, TWO_PI)
            inside |= (t > 0.0) & (t < end - start)
        if not np.all(inside):
            i = int(np.argmin(inside))
            raise AssemblyError(
                f"cannot assemble at φ = {np.degrees(phi[i]):.2f}°: {self.assembly_failure(phi[i])}; "
                f"the crank reaches only φ ∈ {fmt_ranges(ranges)}")

    def assembly_failure(self, phi: float) -> str:
        """The violated condition at one crank angle (subclasses give the numbers).

        Parameters
        ----------
        phi : float
            A crank angle (radians) where the mechanism does not assemble.

        Returns
        -------
        str
            The condition with its numbers.

        Examples
        --------
        >>> from mechlab import FourBar
        >>> FourBar(3, 2, 4, 4).assembly_failure(0.0)
        '|AE| = 1 ≤ |coupler - rocker| = 2'
        """
        return "the loop does not close"

    def motion(self, phi) -> Motion:  # pragma: no cover - abstract
        """Joint paths and the output law at crank angles φ (every family defines it).

        Parameters
        ----------
        phi : float or array_like
            Crank angles φ (radians); a scalar gives a motion of scalars.

        Returns
        -------
        Motion
            Joint paths with their first and second analogs and the output law (an AngularMotion or a LinearMotion).

        Raises
        ------
        DimensionError
            If φ is not a finite real number or array.
        AssemblyError
            Where the loop cannot close (the message names the reachable range).

        Examples
        --------
        >>> from mechlab import FourBar
        >>> FourBar(1, 3, 3.5, 4).motion(0.3).output
        Law(ψ = 2.10358 rad = 120.526°, ψ′ = -0.256937, ψ″ = 0.348417)
        """
        raise NotImplementedError

    def structure(self) -> Structure:
        """The mechanism's links, pairs and structural groups (a family describes itself here once).

        Returns
        -------
        Structure
            Links, pairs and structural groups, from which the drawing, centres, force model and counts derive.

        Raises
        ------
        MechanismError
            If the family defines no structure.

        Examples
        --------
        >>> from mechlab import FourBar
        >>> FourBar(1, 3, 3.5, 4).structure().numbers()
        {'crank': 1, 'coupler': 2, 'rocker': 3, 'frame': 4}
        """
        raise MechanismError(f"{type(self).__name__} describes no structure: define its structure() method")

    def sketch(self, motion: Motion) -> Sketch:
        """The kinematic diagram over ``motion``, read from ``structure()``.

        A bar through the ``joints`` of each link that has some, the fixed ``pivots``, a link carrying a slot
        drawn as a slotted bar (turning) or a yoke (translating), a link sliding on the frame as a guide and a
        block; each part carries its link's number (:meth:`Structure.numbers`). The one method a family
        overrides to show more.

        Parameters
        ----------
        motion : Motion
            This mechanism's motion (from :meth:`motion`).

        Returns
        -------
        Sketch
            The parts to draw and the fixed pivots.

        Examples
        --------
        >>> from mechlab import FourBar
        >>> m = FourBar(1, 3, 3.5, 4)
        >>> sketch = m.sketch(m.motion(0.3))
        >>> len(sketch.parts), sketch.pivots
        (3, ('O', 'E'))
        """
        st = self.structure()
        return Sketch(bars(st) + _pair_parts(st, motion), self.pivots)

    def curved_slot_twin(self) -> tuple[Mechanism, float]:
        """The curved-slot mechanism that moves like this one (Zinchenko et al. (2013) §1), in their frame.

        By default the slot is the crank pin's path relative to the output link, read from ``structure()`` and
        the motion (:func:`mechlab.mechanisms.curved_slot.structural_twin`); DimensionError where no twin
        exists.

        Returns
        -------
        tuple of (Mechanism, float)
            The curved-slot twin and the crank-angle shift ``phase`` (radians) from this mechanism's frame to it.

        Raises
        ------
        DimensionError
            If the mechanism has no curved-slot twin.

        Examples
        --------
        >>> from mechlab import SliderCrank
        >>> twin, phase = SliderCrank(1, 3).curved_slot_twin()
        >>> type(twin).__name__, phase
        ('TranslatingCurvedSlot', 0.0)
        """
        from .curved_slot import structural_twin  # curved_slot builds on this module

        return structural_twin(self)


def branch_references(ranges, raw_angle, samples: int = 2049):
    """Per crank range, the reference that makes an output angle continuous.

    ``raw_angle(phi)`` gives principal angles. On each range the unwrapped angle θ
    minus ``turns``·φ (turns = whole output turns per crank turn, 0 unless the crank
    turns fully) spans less than 2π, so θ is the branch within π of ``mid + turns·φ``.
    Returns tuples ``(start, end, mid, turns)``.
    """
    refs = []
    for start, end in ranges:
        phi = np.linspace(start, end, samples)[1:-1]
        theta = np.unwrap(raw_angle(phi))
        turns = round((theta[-1] - theta[0]) / TWO_PI) if ranges == FULL_TURN else 0
        rel = theta - turns * phi
        refs.append((start, end, 0.5 * (rel.min() + rel.max()), turns))
    return tuple(refs)


def lift_on_ranges(theta: np.ndarray, phi: np.ndarray, refs) -> np.ndarray:
    """Principal angles ``theta`` moved onto the continuous branch given by ``refs``."""
    if len(refs) == 1:
        _, _, mid, turns = refs[0]
        return lift(theta, mid + turns * phi)
    out = theta.copy()
    for start, end, mid, turns in refs:
        on = np.mod(phi - start, TWO_PI) <= end - start
        out[on] = lift(theta[on], mid + turns * phi[on])
    return out


def _pair_parts(st: Structure, motion: Motion) -> tuple[Part, ...]:
    """The parts the pairs of a structure show: slotted links, yokes, guides and blocks."""
    pts = motion.points
    parts = []
    for link in st.links:
        slot = next((p for p in st.pairs if p.kind == "prismatic" and p.a == link.name and st.link(p.b).block), None)
        guide = next((p for p in st.pairs if p.kind == "prismatic" and p.a == FRAME and p.b == link.name), None)
        origin = pts[link.origin].p
        if slot is not None and not link.translates:   # a slotted bar from its pivot along the slot
            th = link.angle(motion).theta + slot.angle
            reach = 1.15 * link.length
            parts.append(Part("extra", lambda i, o=origin, th=th, r=reach: np.array(
                [o[i], o[i] + r * np.array([np.cos(th[i]), np.sin(th[i])])]), link.name))
        elif slot is not None:   # a yoke: the slot across the pin's track (1.3 × its reach), a rod along the guide
            v = unit(link.axis + slot.angle)
            u = unit(guide.angle if guide is not None else link.axis)
            reach = float(np.max(np.abs((pts[slot.point].p - origin) @ v)))
            parts.append(Part("extra", lambda i, o=origin, v=v, u=u, r=reach: np.array(
                [o[i] + 1.3 * r * v, o[i] - 1.3 * r * v, o[i], o[i] + 1.6 * r * u]), link.name))
        elif guide is not None and link.translates and not link.block:   # a block on its guide
            u = unit(guide.angle)   # the frame's axis is x
            path = pts[guide.point].p
            size = 0.08 * st.scale
            along = path @ u
            foot = path[0] - along[0] * u
            rail = np.array([foot + (along.min() - 2 * size) * u, foot + (along.max() + 2 * size) * u])
            parts += [Part("extra", lambda i, g=rail: g),
                      Part("extra", lambda i, p=path, u=u, h=size: block_outline(p[i], u, 2 * h, h), link.name)]
    return tuple(parts)


# a parameter that takes any mechanism (TypeError naming the class otherwise)
AnyMechanism = Annotated[Mechanism, mechanism(Mechanism)]


def _still_defined(cls: type) -> bool:
    """Whether ``cls`` is still where it was defined: a module's attribute (a notebook cell's class is
    one of ``__main__``), or a class made in a function. A class a doctest or an ``exec`` made in borrowed
    globals (its module names a mechlab module that holds no such name) is gone with them, not a family."""
    if "<locals>" in cls.__qualname__:
        return True
    owner = sys.modules.get(cls.__module__)
    for part in cls.__qualname__.split("."):
        owner = getattr(owner, part, None)
    return owner is cls

