"""A planar linkage built from its structure: frame points, a driving crank and Assur groups attached to
named joints (:class:`Linkage`); its motion, structure, mobility, classification and drawing all follow.

Structural formula (Artobolevsky, 1965): the mechanism of class I (the crank on the frame) with groups
attached one by one; each dyad has class II and order 2, and the mechanism's class is the highest
group class. Mobility by Chebyshev-Grübler, W = 3n - 2p₅ - p₄.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from functools import cached_property
from typing import Annotated, Any

import numpy as np

from ...errors import AssemblyError, DimensionError, JointError, MechanismError, MobilityError, SingularityError
from ...geometry import AnglePath, as_angles
from ...motion import AngularMotion, LinearMotion, Motion
from ...validate import Spec, check_value, mechanism
from ..base import (
    FRAME,
    FULL_TURN,
    TWO_PI,
    Mechanism,
    Part,
    Sketch,
    Structure,
    block_outline,
    branch_references,
    fmt_ranges,
    lift_on_ranges,
)
from .closure import CamFollower, CurvedSlot, Tetrad
from .groups import PRP, RPP, RPR, RRP, RRR, Crank, Group, Guide, Point, State

# Crank angles sampled to find where a linkage assembles; each boundary is then bisected to 1e-13 rad.
SAMPLES = 3600
_POINT = Spec("point")


def _frame(value) -> tuple:
    """The frame points as ((name, (x, y)), …) from a dict or such pairs; DimensionError naming a bad one."""
    pairs = value.items() if isinstance(value, dict) else value
    if not isinstance(pairs, tuple | list | type({}.items())) or \
            not all(isinstance(p, tuple | list) and len(p) == 2 for p in pairs):
        raise DimensionError(f"frame must be a dict of fixed points {{name: (x, y)}}, got {value!r:.60}")
    return tuple((check_value("frame point name", k, Spec("text")), check_value(f"frame point {k}", xy, _POINT))
                 for k, xy in pairs)


def _guide(value, name: str = "guide") -> Guide:
    """A Guide from a Guide, a joint name (angle 0), (joint, angle) or (joint, angle, link)."""
    if isinstance(value, Guide):
        return value
    if isinstance(value, str):
        return Guide(value)
    if isinstance(value, tuple | list) and len(value) in (2, 3):
        return Guide(*value)
    raise TypeError(f"{name} must be a Guide, a joint name, (joint, angle) or (joint, angle, link), got {value!r:.60}")


@dataclass(frozen=True)
class Linkage(Mechanism):
    """A linkage built from its structure: the ``frame`` points {name: (x, y)}, the ``driver``
    (a :class:`Crank` on a frame point) and the ``groups`` (the dyads :class:`RRR`, :class:`RRP`, :class:`RPR`,
    :class:`PRP`, :class:`RPP`; the class-IV :class:`Tetrad`; a pin in a :class:`CurvedSlot`; a
    :class:`CamFollower` on a curve of a moving link; and :class:`Point` s fixed on links), each attached to joints
    defined before it. The dyads are placed in closed form; the tetrad, the curved slot and the cam follower by
    Newton's method continued over φ from the assembly their ``start`` chooses.
    ``output_link`` names the link whose law the motion reports (default: the last group's last link):
    its angle ψ, or its displacement s along a frame guide.

    Build it in steps: every method returns a new linkage with one more group.

    Parameters
    ----------
    frame : dict
        The fixed points (pivots and guides' points), name → (x, y).
    driver : Crank
        The driving crank; φ is its angle from the x axis.
    groups : tuple
        The groups and points in the order they attach.
    output_link : str, optional
        The output link.

    Raises
    ------
    JointError
        A joint defined twice, a group attached to a joint or a link not defined before it.
    MobilityError
        The mobility W = 3n - 2p₅ - p₄ is not 1 (e.g. a second crank).
    AssemblyError
        A group that closes at no crank angle (named, with the crank angle and the numbers).

    Examples
    --------
    >>> import mechlab as ml
    >>> fb = (ml.Linkage({"O": (0, 0), "E": (4, 0)}, ml.Crank("O", "A", 1.0))
    ...       .rrr("A", "E", "B", 3.0, 3.0, links=("coupler", "rocker")))
    >>> round(float(fb.motion(0.5).psi), 6) == round(float(ml.FourBar(1, 3, 3, 4).motion(0.5).psi), 6)
    True
    >>> fb.mobility(), fb.formula()
    (1, 'I(crank) → II₂(coupler, rocker)')
    """

    frame: Any
    driver: Annotated[Any, mechanism(Crank)]
    groups: Annotated[tuple, Spec("items", expected=(Group, Point))] = ()
    output_link: Annotated[str | None, Spec("text", optional=True)] = None

    def __post_init__(self):
        super().__post_init__()
        object.__setattr__(self, "frame", _frame(self.frame))
        self._carriers  # noqa: B018 - every joint defined once, before it is used (JointError)
        st = self.structure()
        w = st.mobility()
        if w != 1:
            cranks = [g.name for g in self._elements if isinstance(g, Crank)]
            raise MobilityError(f"mobility W = 3n - 2p₅ - p₄ = 3·{len(st.links)} - 2·{len(st.pairs)} = {w} ≠ 1: "
                                f"{len(cranks)} cranks ({', '.join(cranks)}) drive it; a linkage has one driver "
                                f"and Assur groups (W = 0 each)")
        if self.output_link is not None and self.output_link not in {k.name for k in st.links}:
            raise JointError(f"output_link = {self.output_link!r} names no link; links: "
                             f"{', '.join(k.name for k in st.links)}")
        if not self.crank_ranges():
            self._place(np.array([0.0]), strict=True)   # raises, naming the group that fails at φ = 0
            raise AssemblyError("the linkage closes at no crank angle")   # pragma: no cover - closed at 0 only

    title = "linkage built from its groups"

    @classmethod
    def example(cls) -> Linkage:
        """A crank-shaper: the crank drives a slotted lever (RPR), whose end C pushes the ram D (RRP).

        Returns
        -------
        Linkage

        Examples
        --------
        >>> import mechlab as ml
        >>> ml.Linkage.example().formula()
        'I(crank) → II₂(block A, PA) → II₂(CD, slider D)'
        """
        return cls({"O": (0.0, 0.0), "P": (0.0, -2.0), "G": (0.0, 2.2)}, Crank("O", "A", 1.0),
                   (RPR("A", "P", 4.0), Point("C", "PA", (4.0, 0.0)), RRP("C", "D", 1.5, Guide("G"))))

    # -- building -----------------------------------------------------------------------------------------
    def then(self, group) -> Linkage:
        """This linkage with ``group`` (an RRR, RRP, RPR, PRP, RPP, Tetrad, CurvedSlot, CamFollower or Point)
        attached.

        Parameters
        ----------
        group : RRR, RRP, RPR, PRP, RPP, Tetrad, CurvedSlot, CamFollower or Point
            The next group, attached to joints already defined.

        Returns
        -------
        Linkage
            A new linkage; its output link becomes the group's last link unless one was named.

        Examples
        --------
        >>> import mechlab as ml
        >>> lk = ml.Linkage({"O": (0, 0), "E": (4, 0)}, ml.Crank("O", "A", 1.0)).then(ml.RRR("A", "E", "B", 3, 3))
        >>> [link.name for link in lk.structure().links]
        ['crank', 'AB', 'EB']
        """
        return replace(self, groups=(*self.groups, group))

    def rrr(self, first: str, second: str, joint: str, first_length: float, second_length: float,
            assembly=1, links=None) -> Linkage:
        """Attach an :class:`RRR` dyad: two links pinned at the new ``joint`` and at ``first``, ``second``.

        Parameters
        ----------
        first, second : str
            The outer joints.
        joint : str
            The new inner joint.
        first_length, second_length : float
            |joint - first| and |joint - second|.
        assembly : +1 or -1
            The joint on the left (+1) or right of the line first → second.
        links : (str, str), optional
            The two links' names.

        Returns
        -------
        Linkage

        Examples
        --------
        >>> import mechlab as ml
        >>> lk = ml.Linkage({"O": (0, 0), "E": (4, 0)}, ml.Crank("O", "A", 1.0)).rrr("A", "E", "B", 3, 3)
        >>> lk.output
        'angle'
        """
        return self.then(RRR(first, second, joint, first_length, second_length, assembly, links))

    def rrp(self, pin: str, joint: str, length: float, guide, assembly=1, links=None) -> Linkage:
        """Attach an :class:`RRP` dyad: a rod ``pin``-``joint`` and a slider at ``joint`` on ``guide``.

        Parameters
        ----------
        pin : str
            The rod's outer joint.
        joint : str
            The new joint, the slider's pin.
        length : float
            The rod's length.
        guide : Guide, str, (str, float) or (str, float, str)
            The guide: a :class:`Guide`, a joint on the guide's link (angle 0 to its axis), (joint, angle) or
            (joint, angle, link) for a guide on another link through that joint.
        assembly : +1 or -1
            The slider ahead of (+1) or behind the pin's foot along the guide.
        links : (str, str), optional
            The rod's and the slider's names.

        Returns
        -------
        Linkage

        Examples
        --------
        >>> import mechlab as ml
        >>> sc = ml.Linkage({"O": (0, 0)}, ml.Crank("O", "A", 1.0)).rrp("A", "B", 3.0, "O")
        >>> round(float(sc.motion(0.0).s), 12)
        4.0
        """
        return self.then(RRP(pin, joint, length, _guide(guide), assembly, links))

    def rpr(self, pin: str, pivot: str, length: float = 0.0, links=None) -> Linkage:
        """Attach an :class:`RPR` dyad: a block at ``pin`` sliding in the slot of a link pivoted at ``pivot``.

        Parameters
        ----------
        pin : str
            The joint carrying the block.
        pivot : str
            The slotted link's pivot (the slot passes through it).
        length : float
            The slotted link's length (for its drawing and its default mass properties).
        links : (str, str), optional
            The block's and the slotted link's names.

        Returns
        -------
        Linkage

        Examples
        --------
        >>> import mechlab as ml
        >>> sl = ml.Linkage({"O": (0, 0), "B": (-2, 0)}, ml.Crank("O", "A", 1.0)).rpr("A", "B", 3.5)
        >>> round(float(sl.motion(np.pi / 2).psi), 12) == round(float(np.arctan2(1, 2)), 12)
        True
        """
        return self.then(RPR(pin, pivot, length, links))

    def prp(self, first, second, joint: str, links=None) -> Linkage:
        """Attach a :class:`PRP` dyad: two blocks pinned at ``joint``, sliding on the guides ``first`` and
        ``second``.

        Parameters
        ----------
        first, second : Guide, str or (str, float)
            The two guides (see :meth:`rrp`).
        joint : str
            The new joint where the guides cross.
        links : (str, str), optional
            The two blocks' names.

        Returns
        -------
        Linkage

        Examples
        --------
        >>> import mechlab as ml
        >>> tangent = (ml.Linkage({"O": (0, 0), "P": (0, -2), "G": (0, 1)}, ml.Crank("O", "A", 1.0))
        ...            .rpr("A", "P", 4.0).prp(("G", 0.0), ("P", 0.0, "PA"), "B"))
        >>> round(float(tangent.motion(0.0).points["B"].p[0]), 12)
        1.5
        """
        return self.then(PRP(_guide(first, "first"), _guide(second, "second"), joint, links))

    def rpp(self, pin: str, joint: str, guide, slot: float = np.pi / 2, links=None) -> Linkage:
        """Attach an :class:`RPP` dyad: a block at ``pin`` sliding in the straight slot of a yoke that slides on
        ``guide``; ``joint`` is where the slot's centre line crosses the guide.

        Parameters
        ----------
        pin : str
            The joint carrying the block.
        joint : str
            The new joint, the yoke's reference point on the guide.
        guide : Guide, str, (str, float) or (str, float, str)
            The yoke's guide (see :meth:`rrp`).
        slot : float
            The slot's angle to the guide (radians); π/2 for a Scotch yoke.
        links : (str, str), optional
            The block's and the yoke's names.

        Returns
        -------
        Linkage

        Examples
        --------
        >>> import mechlab as ml
        >>> yoke = ml.Linkage({"O": (0, 0)}, ml.Crank("O", "A", 1.0)).rpp("A", "K", "O")
        >>> round(float(yoke.motion(np.pi / 3).s), 12)
        0.5
        """
        return self.then(RPP(pin, joint, _guide(guide), slot, links))

    def tetrad(self, first: str, second: str, joints, on_first, on_second, lengths, start, at: float = 0.0,
               links=None) -> Linkage:
        """Attach a :class:`Tetrad`, the class-IV group: a ternary link about ``first`` carrying Q and P, one about
        ``second`` carrying R and T, joined by the binary links Q-R and P-T.

        Parameters
        ----------
        first, second : str
            The known joints the ternary links turn about.
        joints : (str, str, str, str)
            The new joints Q, P, R, T.
        on_first, on_second : ((float, float), (float, float))
            Q and P in the first link's frame, R and T in the second's (origin at its outer joint).
        lengths : (float, float)
            |QR| and |PT|.
        start : (float, float)
            The ternary links' angles near which the group is assembled at the crank angle ``at``.
        at : float
            The crank angle of ``start`` (radians).
        links : (str, str, str, str), optional
            The first ternary, Q-R, P-T and second ternary links' names.

        Returns
        -------
        Linkage

        Examples
        --------
        >>> import mechlab as ml
        >>> six = (ml.Linkage({"O": (0, 0), "E": (1.04, 0)}, ml.Crank("O", "A", 0.25))
        ...        .tetrad("A", "E", ("Q", "P", "R", "T"), ((-0.2, 0.55), (0.7, 0.55)), ((0.55, 0.45), (1.35, 0.15)),
        ...                (0.25, 0.85), (3.67, 3.04), at=np.pi))
        >>> six.formula()
        'I(crank) → IV₂(AQP, QR, PT, ERT)'
        >>> round(float(six.motion(1.0).psi), 4) == round(float(ml.SixBarIV.example().motion(1.0).psi), 4)
        True
        """
        return self.then(Tetrad(first, second, tuple(joints), on_first, on_second, lengths, start, at, links))

    def slot(self, pin: str, curve, joint: str, pivot: str | None = None, guide=None, start: float = 0.0,
             at: float = 0.0, link: str | None = None) -> Linkage:
        """Attach a :class:`CurvedSlot`: the pin ``pin`` runs in the curved slot ``curve`` of a link that turns about
        ``pivot`` or slides on ``guide``.

        Parameters
        ----------
        pin : str
            The known joint in the slot.
        curve : CircleSlot, ParametricSlot or SampledSlot
            The slot in the link's frame (origin at the pivot, or at ``joint`` on the guide).
        joint : str
            The new joint: a point on the turning link's axis (at the distance of the slot's start point), or the
            sliding link's origin on the guide.
        pivot : str, optional
            The known joint the link turns about.
        guide : Guide, str, (str, float) or (str, float, str), optional
            The guide the link slides on (see :meth:`rrp`).
        start : float
            The slot parameter near which the pin lies at the crank angle ``at``.
        at : float
            The crank angle of ``start`` (radians).
        link : str, optional
            The slotted link's name.

        Returns
        -------
        Linkage

        Examples
        --------
        >>> import mechlab as ml
        >>> lk = (ml.Linkage({"O": (0, 0), "B": (-4, 0)}, ml.Crank("O", "A", 1.0))
        ...       .slot("A", ml.CircleSlot((3.0, 0.0), 3.0), "K", pivot="B", start=1.0))
        >>> m = ml.CurvedSlotLink(1.0, 4.0, ml.CircleSlot((3.0, 0.0), 3.0), start=1.0)
        >>> round(float(lk.motion(0.5).psi), 12) == round(float(m.motion(0.5).psi), 12)
        True
        """
        guide = None if guide is None else _guide(guide)
        return self.then(CurvedSlot(pin, curve, joint, pivot, guide, start, at, link))

    def follow(self, curve, on: str, joint: str, pivot: str | None = None, arm: float = 0.0, guide=None,
               start: float = 0.0, at: float = 0.0, link: str | None = None) -> Linkage:
        """Attach a :class:`CamFollower`: the follower's point ``joint`` rides on ``curve``, fixed on the link ``on``
        (a cam's roller-centre curve); the follower turns about ``pivot`` on an arm or slides on ``guide``.

        Parameters
        ----------
        curve : CircleSlot, ParametricSlot or SampledSlot
            The curve in the frame of the link ``on``.
        on : str
            The link carrying the curve.
        joint : str
            The new joint on the curve (the roller's centre).
        pivot : str, optional
            The known joint the follower's arm turns about.
        arm : float
            The arm's length |pivot joint|, with ``pivot``.
        guide : Guide, str, (str, float) or (str, float, str), optional
            The guide the follower slides on, ``joint`` on its line (see :meth:`rrp`).
        start : float
            The curve parameter near which the contact lies at the crank angle ``at``.
        at : float
            The crank angle of ``start`` (radians).
        link : str, optional
            The follower's name.

        Returns
        -------
        Linkage

        Examples
        --------
        >>> import mechlab as ml
        >>> eccentric = (ml.Linkage({"O": (0, 0), "F": (0, 0)}, ml.Crank("O", "A", 1.0, name="cam"))
        ...              .follow(ml.CircleSlot((0.5, 0.0), 2.0), "cam", "C", guide=("F", np.pi / 2), start=1.3))
        >>> round(float(eccentric.motion(np.pi / 2).s), 12)   # the circle's centre at (0, 0.5), C on x = 0
        2.5
        """
        guide = None if guide is None else _guide(guide)
        return self.then(CamFollower(curve, on, joint, pivot, arm, guide, start, at, link))

    def point(self, name: str, on: str, at=(0.0, 0.0)) -> Linkage:
        """Fix the point ``name`` on the link ``on`` at (ξ, η) in the link's coordinates (a coupler point).

        Parameters
        ----------
        name : str
            The new point.
        on : str
            The link it is fixed on.
        at : (float, float)
            ξ along the link's axis from its origin joint, η to the axis' left.

        Returns
        -------
        Linkage

        Examples
        --------
        >>> import mechlab as ml
        >>> lk = ml.Linkage({"O": (0, 0)}, ml.Crank("O", "A", 1.0)).point("M", "crank", (0.5, 0.0))
        >>> lk.motion(0.0).points["M"].p.tolist()
        [0.5, 0.0]
        """
        return self.then(Point(name, on, at))

    def with_output(self, link: str) -> Linkage:
        """The same linkage reporting ``link``'s law.

        Parameters
        ----------
        link : str
            A link's name.

        Returns
        -------
        Linkage

        Examples
        --------
        >>> import mechlab as ml
        >>> lk = ml.Linkage({"O": (0, 0), "E": (4, 0)}, ml.Crank("O", "A", 1.0)).rrr("A", "E", "B", 3, 3)
        >>> lk.with_output("AB").structure().output
        'AB'
        """
        return replace(self, output_link=link)

    # -- the structure ------------------------------------------------------------------------------------
    @property
    def _elements(self) -> tuple:
        return (self.driver, *self.groups)

    @property
    def _fixed(self) -> dict:
        return dict(self.frame)

    @cached_property
    def _carriers(self) -> dict[str, str]:
        """Each joint's carrier: the link it was made on (the frame for a frame point); JointError for a
        joint defined twice or used before it is defined, a link named twice or unknown."""
        carrier = {name: FRAME for name in self._fixed}
        made_by = {name: "the frame" for name in self._fixed}
        links = {FRAME}
        for g in self._elements:
            for j in g.needs():
                if j not in carrier:
                    raise JointError(f"{_what(g)} attaches to the joint {j!r}, which is not defined before it; "
                                     f"joints so far: {', '.join(carrier)}")
            if isinstance(g, Point) and g.on not in links:
                raise JointError(f"the point {g.name} is fixed on the link {g.on!r}, which is not defined before it; "
                                 f"links so far: {', '.join(sorted(links - {FRAME}))}")
            for used in () if isinstance(g, Point) else g.uses():
                if used not in links:
                    raise JointError(f"{_what(g)} uses the link {used!r}, which is not defined before it; links so "
                                     f"far: {', '.join(sorted(links - {FRAME}))}")
            for guide in () if isinstance(g, Point) else g.guides():
                if guide.on is not None and guide.on not in links:
                    raise JointError(f"{_what(g)} slides on a guide fixed on the link {guide.on!r}, which is not "
                                     f"defined before it; links so far: {', '.join(sorted(links))}")
            if isinstance(g, Crank) and carrier[g.pivot] != FRAME:
                raise JointError(f"the crank {g.name} must turn about a frame point; {g.pivot} is on "
                                 f"{carrier[g.pivot]}")
            names = () if isinstance(g, Point) else g.link_names()
            for name in names:
                if name in links:
                    raise JointError(f"{_what(g)} names a link {name!r} that already exists; name its links "
                                     f"with links=(…, …)")
            links.update(names)
            for j in g.makes():
                if j in carrier:
                    raise JointError(f"the joint {j!r} is attached twice: {made_by[j]} defines it, and {_what(g)} "
                                     f"again; give the new joint another name")
                carrier[j] = g.on if isinstance(g, Point) else g.carriers(names)[j]
                made_by[j] = _what(g)
        return carrier

    def structure(self) -> Structure:
        """The links (in the order the groups made them), pairs and Assur groups (output first) of the linkage.

        Returns
        -------
        Structure
            Read by the instantaneous centres, the kinetostatics and the drawing.

        Examples
        --------
        >>> import mechlab as ml
        >>> lk = ml.Linkage({"O": (0, 0), "E": (4, 0)}, ml.Crank("O", "A", 1.0)).rrr("A", "E", "B", 3, 3)
        >>> [p.name for p in lk.structure().pairs]
        ['O', 'A', 'B', 'E']
        """
        return self._structure

    @cached_property
    def _structure(self) -> Structure:
        carrier = self._carriers.__getitem__
        links, pairs, groups = {}, [], []
        for g in self._elements:
            if isinstance(g, Point):
                continue
            new_links, new_pairs = g.structure(carrier, links)
            links.update((k.name, k) for k in new_links)
            pairs += new_pairs
            if not isinstance(g, Crank) or g is not self.driver:
                groups.append(tuple(k.name for k in new_links))
        pairs = _unique_names(pairs)
        last = next(g for g in reversed(self._elements) if not isinstance(g, Point))
        output = self.output_link or last.link_names()[-1]
        extent = [abs(c) for _, xy in self.frame for c in xy]
        extent += [getattr(g, a) for g in self._elements for a in ("radius", "first_length", "second_length",
                                                                    "length") if hasattr(g, a)]
        return Structure(tuple(links.values()), tuple(pairs), tuple(reversed(groups)), output,
                         scale=max(extent) or 1.0)

    def mobility(self) -> int:
        """W = 3n - 2p₅ - p₄ (Chebyshev-Grübler) of the whole linkage: 1 for a crank and Assur groups.

        Returns
        -------
        int

        Examples
        --------
        >>> import mechlab as ml
        >>> ml.Linkage({"O": (0, 0)}, ml.Crank("O", "A", 1.0)).mobility()
        1
        """
        return self.structure().mobility()

    def classification(self) -> tuple[tuple[str, int, int, tuple[str, ...]], ...]:
        """Artobolevsky's classification: (kind, class, order, links) of the driver and of each group in turn.

        Returns
        -------
        tuple
            One (kind, class, order, links) per element; the mechanism's class is the highest class.

        Examples
        --------
        >>> import mechlab as ml
        >>> lk = ml.Linkage({"O": (0, 0), "E": (4, 0)}, ml.Crank("O", "A", 1.0)).rrr("A", "E", "B", 3, 3)
        >>> lk.classification()
        (('crank', 1, 1, ('crank',)), ('RRR', 2, 2, ('AB', 'EB')))
        """
        return tuple((g.kind, g.assur_class, g.order, g.link_names()) for g in self._elements
                     if not isinstance(g, Point))

    @property
    def assur_class(self) -> int:
        """The mechanism's class: the highest class of its groups (I for a crank alone, II with dyads).

        Returns
        -------
        int
            The class (1, 2, 3 or 4).
        """
        return max(c for _, c, _, _ in self.classification())

    def formula(self) -> str:
        """The structural formula, e.g. ``I(crank) → II₂(AB, EB)``: each group's class (Roman) and order.

        Returns
        -------
        str

        Examples
        --------
        >>> import mechlab as ml
        >>> ml.Linkage({"O": (0, 0)}, ml.Crank("O", "A", 1.0)).rrp("A", "B", 3.0, "O").formula()
        'I(crank) → II₂(AB, slider B)'
        """
        roman, sub = {1: "I", 2: "II", 3: "III", 4: "IV"}, str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")
        return " → ".join(f"{roman[c]}{'' if c == 1 else str(o).translate(sub)}({', '.join(names)})"
                          for _, c, o, names in self.classification())

    # -- what the drawing and the forces read ----------------------------------------------------------------
    @property
    def pivots(self) -> tuple[str, ...]:
        """The frame points where a link turns on the frame.

        Returns
        -------
        tuple of str
            Joint names, in the order of the structure's pairs.
        """
        return tuple(dict.fromkeys(p.point for p in self.structure().pairs
                                   if p.kind == "revolute" and FRAME in (p.a, p.b)))

    @property
    def output(self) -> str:
        """``"position"`` when the output link slides on a frame guide, else ``"angle"``.

        Returns
        -------
        str
            The output's kind.
        """
        return "position" if self.structure().link(self.structure().output).translates else "angle"

    def _joints_of(self, link: str) -> tuple[str, ...]:
        st = self.structure()
        on = [p.point for p in st.pairs if link in (p.a, p.b) and p.kind == "revolute"]
        on += [j for j, c in self._carriers.items() if c == link]
        return tuple(dict.fromkeys([st.link(link).origin, *on]))

    # -- motion -----------------------------------------------------------------------------------------------
    def _place(self, phi: np.ndarray, strict: bool, upto=None) -> State:
        """The elements placed at ``phi`` (all, or those before ``upto``)."""
        carrier = self._carriers.__getitem__
        state = State(phi, self._fixed, strict, lambda group, at: self._place(at, False, group), self._grids,
                      carrier)
        with np.errstate(invalid="ignore", divide="ignore"):   # rows that do not close hold NaN until refused
            for k, g in enumerate(self._elements):
                if g is upto:
                    break
                state.element = k
                g.place(state, carrier)
        return state

    @cached_property
    def _grids(self) -> dict:
        """The solutions that groups solved by continuation (:class:`Tetrad`, :class:`CurvedSlot`) follow."""
        return {}

    @cached_property
    def _ranges(self):
        phi = np.arange(SAMPLES) * (TWO_PI / SAMPLES)
        ok = self._place(phi, strict=False).ok
        if ok.all():
            return FULL_TURN
        if not ok.any():
            return ()
        # bracket every change between neighbouring samples and bisect them together
        k = np.flatnonzero(ok != np.roll(ok, -1))
        lo, hi = phi[k], phi[k] + TWO_PI / SAMPLES
        inside_lo = ok[k]
        for _ in range(45):
            mid = 0.5 * (lo + hi)
            good = self._place(mid, strict=False).ok
            same = good == inside_lo
            lo, hi = np.where(same, mid, lo), np.where(same, hi, mid)
        edges = 0.5 * (lo + hi)
        # a range starts where the samples enter it (inside_lo False) and ends where they leave it
        starts, ends = edges[~inside_lo], edges[inside_lo]
        ranges = []
        for s in starts:
            later = ends[ends > s]
            e = later.min() if len(later) else ends.min() + TWO_PI
            if e > TWO_PI:   # a range across φ = 0 is shown from a negative angle, as FourBar's
                s, e = s - TWO_PI, e - TWO_PI
            ranges.append((float(s), float(e)))
        return tuple(sorted(ranges))

    def crank_ranges(self):
        """The open intervals of crank angles where every group closes.

        Found on 3600 samples, each end bisected to 1e-13 rad.

        Returns
        -------
        tuple of (float, float)
            ``((0, 2π),)`` for a crank that turns fully, else the intervals (radians).
        """
        return self._ranges

    def assembly_failure(self, phi: float) -> str:
        try:
            self._place(np.array([phi]), strict=True)
        except (AssemblyError, SingularityError) as err:
            return str(err)
        return "the loop does not close"   # pragma: no cover - only asked where it fails

    @cached_property
    def _output_reference(self):
        name = self.structure().output
        return branch_references(self.crank_ranges(), lambda phi: self._place(phi, strict=False).angles[name].theta)

    def motion(self, phi) -> Motion:
        """Every joint's path (positions and first and second analogs) and the output law at crank angles φ.

        Parameters
        ----------
        phi : float or array
            Crank angles (radians).

        Returns
        -------
        AngularMotion or LinearMotion
            ψ of the output link (continuous over the crank angles), or s along its frame guide.

        Raises
        ------
        AssemblyError
            Where a group cannot close: the group, the crank angle and the reachable range.
        SingularityError
            At a dead point of a group (its analogs unbounded).

        Examples
        --------
        >>> import mechlab as ml
        >>> lk = ml.Linkage({"O": (0, 0), "E": (4, 0)}, ml.Crank("O", "A", 1.0)).rrr("A", "E", "B", 3, 3)
        >>> mo = lk.motion(lk.turn(5))
        >>> mo.points["B"].d.shape
        (5, 2)
        """
        phi = as_angles(phi)
        try:
            state = self._place(phi, strict=True)
        except AssemblyError as err:
            ranges = self.crank_ranges()
            raise AssemblyError(f"{err}; the crank reaches only φ ∈ {fmt_ranges(ranges)}"
                                if ranges != FULL_TURN else str(err)) from None
        st = self.structure()
        out = st.link(st.output)
        group = next(g for g in self._elements if not isinstance(g, Point) and out.name in g.link_names())
        mu = group.transmission(state) if not isinstance(group, Crank) else np.full(len(phi), np.pi / 2)
        if out.translates:
            pair = st.frame_pair(out.name)
            u = np.array([np.cos(pair.angle), np.sin(pair.angle)])
            B = state.points[out.origin]
            s = AnglePath((B.p - state.points[_guide_point(self, out.name)].p) @ u, B.d @ u, B.dd @ u)
            return LinearMotion(phi, state.points, mu, *s)
        th = state.angles[out.name]
        psi = lift_on_ranges(th.theta, phi, self._output_reference) if len(phi) else th.theta
        return AngularMotion(phi, state.points, mu, psi, th.d, th.dd)

    # -- drawing ----------------------------------------------------------------------------------------------
    def sketch(self, motion: Motion) -> Sketch:
        """The kinematic diagram: a bar (or a plate) through each link's joints, a slider with its rail, a
        slotted link with its slot, blocks outlined; each numbered link's part names it, and the drawing numbers
        it by :meth:`Structure.numbers` (the structure's links without blocks, then the frame), as the
        instantaneous centres and the force model do.

        Parameters
        ----------
        motion : Motion
            The motion to draw.

        Returns
        -------
        Sketch

        Examples
        --------
        >>> import mechlab as ml
        >>> lk = ml.Linkage({"O": (0, 0), "E": (4, 0)}, ml.Crank("O", "A", 1.0)).rrr("A", "E", "B", 3, 3)
        >>> [p.number for p in lk.sketch(lk.motion(lk.turn(3))).parts]
        ['crank', 'AB', 'EB']
        """
        st, pts = self.structure(), motion.points
        size = 0.08 * st.scale
        numbered = [k for k in st.links if not k.block]
        parts = []
        for link in numbered:
            joints = self._joints_of(link.name)
            axis = link.angle(motion).theta
            slots = [p for p in st.pairs if p.kind == "prismatic" and p.a == link.name]
            if link.translates or (not isinstance(link.axis, tuple) and len(joints) < 2):
                at = pts[link.origin].p
                parts.append(Part("extra", lambda i, p=at, a=axis: block_outline(p[i], _dir(a[i]), 2 * size, size),
                                  link.name))
            elif len(joints) >= 2:
                parts.append(Part("link", joints + joints[:1] if len(joints) > 2 else joints, link.name))
            for k, p in enumerate(slots):   # the slot (or guide) on this link along the block's track
                track = pts[p.point].p
                o = pts[link.origin].p
                # a link drawn by its slot alone (not as a block, nor as a bar) carries its number there
                shown = isinstance(link.axis, tuple) and len(joints) < 2 and k == 0
                parts.append(Part("slot", lambda i, o=o, t=track, a=axis + p.angle: _along(o[i], t[i], a[i], size),
                                  link.name if shown else None))
        for link in st.links:
            slide = next((p for p in st.pairs if p.kind == "prismatic" and p.b == link.name), None)
            if slide is not None and slide.a == FRAME and link.translates:   # the rail under a slider
                track = pts[slide.point].p
                u = _dir(slide.angle)
                along = track @ u
                foot = track[0] - along[0] * u
                rail = np.array([foot + (along.min() - 2 * size) * u, foot + (along.max() + 2 * size) * u])
                parts.append(Part("guide", lambda i, r=rail: r))
            if link.block:
                at, axis = pts[link.origin].p, link.angle(motion).theta
                parts.append(Part("extra", lambda i, p=at, a=axis: block_outline(p[i], _dir(a[i]), 2 * size, size)))
        for g in self.groups:
            if not isinstance(g, Point):
                parts += g.drawing(motion, st)
        return Sketch(tuple(parts), self.pivots)


class LinkageFamily(Mechanism):
    """A family of linkages: a frozen dataclass of its dimensions whose :meth:`linkage` builds it from a crank and
    Assur groups; everything else is the built linkage's.

    Its motion, reachable crank angles, structure and drawing are those of the :class:`Linkage` built, so the
    instantaneous centres, the force model and the design layer's counts (all read from the structure) follow;
    an instance is refused where it is made, by its fields' declarations (DimensionError naming the field) and
    by the groups' own checks (AssemblyError naming the group that closes at no crank angle, JointError,
    MobilityError). A family defines its fields, :meth:`linkage` and :meth:`~Mechanism.example`, nothing else.

    Examples
    --------
    >>> from dataclasses import dataclass
    >>> import mechlab as ml
    >>> from mechlab.validate import Length
    >>> @dataclass(frozen=True)
    ... class Press(LinkageFamily):
    ...     crank: Length
    ...     rod: Length
    ...     def linkage(self):
    ...         return ml.Linkage({"O": (0, 0)}, ml.Crank("O", "A", self.crank)).rrp("A", "B", self.rod, "O")
    ...     @classmethod
    ...     def example(cls):
    ...         return cls(1.0, 3.0)
    >>> round(float(Press.example().motion(0.0).s), 12), Press.title
    (4.0, 'press')
    """

    def __post_init__(self):
        super().__post_init__()
        self._built   # noqa: B018 - built now, so a bad instance is refused where it is made

    def linkage(self) -> Linkage:
        """The linkage these dimensions build (a family defines it).

        Returns
        -------
        Linkage

        Raises
        ------
        MechanismError
            The family defines no linkage().
        """
        raise MechanismError(f"{type(self).__name__} defines no linkage(): build its crank and groups there")

    @cached_property
    def _built(self) -> Linkage:
        built = self.linkage()
        if not isinstance(built, Linkage):
            raise TypeError(f"{type(self).__name__}.linkage() must return a Linkage, got {type(built).__name__}")
        return built

    @property
    def pivots(self) -> tuple[str, ...]:
        """The built linkage's frame pivots."""
        return self._built.pivots

    @property
    def output(self) -> str:
        """``"position"`` or ``"angle"``: the built linkage's output."""
        return self._built.output

    def structure(self) -> Structure:
        """The built linkage's structure (:meth:`Linkage.structure`)."""
        return self._built.structure()

    def crank_ranges(self):
        """The built linkage's reachable crank angles (:meth:`Linkage.crank_ranges`)."""
        return self._built.crank_ranges()

    def assembly_failure(self, phi: float) -> str:
        return self._built.assembly_failure(phi)

    def motion(self, phi) -> Motion:
        """The built linkage's motion (:meth:`Linkage.motion`)."""
        return self._built.motion(phi)

    def sketch(self, motion: Motion) -> Sketch:
        """The built linkage's kinematic diagram (:meth:`Linkage.sketch`)."""
        return self._built.sketch(motion)


def _dir(angle):
    return np.array([np.cos(angle), np.sin(angle)])


def _along(origin, point, angle, size):
    """A slot through ``origin`` at ``angle`` reaching past ``point`` by 2·size."""
    u = _dir(angle)
    reach = float((point - origin) @ u)
    ends = sorted((0.0, reach + np.copysign(2 * size, reach)))
    return np.array([origin + ends[0] * u, origin + ends[1] * u])


def _guide_point(linkage: Linkage, link: str) -> str:
    """The frame point a frame guide of ``link`` passes through (the zero of its displacement s)."""
    for g in linkage.groups:
        guide = None if isinstance(g, Point) else g.sliding().get(link)
        if guide is not None:
            return guide.through
    raise JointError(f"the link {link} slides on no frame guide")   # pragma: no cover - only asked of sliders


def _what(g) -> str:
    return f"the point {g.name}" if isinstance(g, Point) else g.describe()


def _unique_names(pairs):
    """Pairs named by their joint, a second pair at one joint (a compound hinge) with a suffix: B, B2, …"""
    seen: dict[str, int] = {}
    out = []
    for p in pairs:
        seen[p.name] = seen.get(p.name, 0) + 1
        out.append(p if seen[p.name] == 1 else replace(p, name=f"{p.name}{seen[p.name]}"))
    return out
