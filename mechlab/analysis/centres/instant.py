"""Every instantaneous centre of a mechanism over its crank angles, and the velocity
analogs read back from them.

Links are numbered as in Kozhevnikov§7.1): for the single-loop linkages
1 = crank, 2 = coupler/rod/slider block, 3 = rocker/slider/slotted link, 4 = frame;
so for a four-bar P14 = O, P12 = A, P23 = B, P34 = E, and Kennedy gives
P13 = AB ∩ OE (crank relative to rocker) and P24 = OA ∩ BE (the coupler's pole).
The slotted link and the sine mechanism are read as three links with a higher pair
(pin A in the slot, Kozhevnikov Fig. 7.3's method): 1 = crank, 2 = slotted link or yoke,
3 = frame; P12 lies on the common normal at A, i.e. on the slot's normal through A.
All of it is read from the mechanism's ``structure()`` (:func:`centre_model`): a new family
needs nothing here.

From the centres alone (Kennedy's angular-velocity-ratio theorem; no loop-closure
analogs used): ω_k/ω_1 = (P1k - P1f)/(P1k - Pkf) along their common line (f = frame),
and a translating link k (Pkf at infinity) moves with the velocity of P1k as a point of
the crank, ω_1·perp(P1k - P1f).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Annotated

import numpy as np

from ...errors import MechanismError, SingularityError
from ...geometry import AnglePath, PointPath, as_angles, dot, fixed_point, perp, unit
from ...mechanisms.base import FRAME, AnyMechanism, Structure
from ...motion import Motion, scalar_law
from ...validate import OptionalAngles, choice, validated
from .homogeneous import Centre, at_infinity, finite, line_with_direction
from .kennedy import Pair, centres_from_twists, kennedy, pair


@dataclass(frozen=True, eq=False)
class CentreModel:
    """How a mechanism's links meet, for the centres, over one motion.

    ``links``: names in seed-002 order (numbers 1..N); ``frame``/``input``/``output``:
    link names; ``known``: centres fixed by the pairs (0-based index pairs);
    ``normals``: common normals of higher pairs; ``poses``: each link's frame as
    (origin path, x-axis angle path); ``guide``: unit direction of a translating output;
    ``input_rate``: the input link's angular analog dθ/dφ.
    """

    links: tuple[str, ...]
    frame: str
    input: str
    output: str
    known: Mapping[Pair, Centre]
    normals: Mapping[Pair, np.ndarray]
    poses: Mapping[str, tuple[PointPath, AnglePath]]
    scale: float
    guide: np.ndarray | None = None
    input_rate: float = 1.0     # dθ_input/dφ: 1 for a crank; -1 for the trammel's rod


def centre_model(mechanism, motion: Motion) -> CentreModel:
    """The centres' view of ``mechanism.structure()``: a revolute pair fixes its centre at the joint,
    a prismatic pair at infinity normal to the guide, a higher pair puts the centre on the common
    normal; a sliding block and its two pairs count as one higher pair (the pin in the slot, Kozhevnikov
    Fig. 7.3's method), whose normal is the slot's."""
    st: Structure = mechanism.structure().planar()
    label = {link.name: link.label or link.name for link in st.links}
    label[FRAME] = FRAME
    order = st.order()   # the numbering the drawing and the force model share
    index = {name: i for i, name in enumerate(order)}
    n = len(motion.phi)
    angles = {FRAME: AnglePath(np.zeros(n), np.zeros(n), np.zeros(n))}
    poses = {FRAME: (fixed_point((0.0, 0.0), n), angles[FRAME])}
    for link in st.links:
        angles[link.name] = link.angle(motion)
        if not link.block:
            poses[label[link.name]] = (motion.points[link.origin], angles[link.name])

    def guide(p):   # the unit direction of a prismatic pair's guide over the motion
        return unit(angles[p.a].theta + p.angle)

    known, normals, blocks = {}, {}, {k.name: [] for k in st.links if k.block}
    for p in st.pairs:
        if p.a in blocks or p.b in blocks:
            blocks[p.b if p.b in blocks else p.a].append(p)
            continue
        ij = pair(index[label[p.a]], index[label[p.b]])
        at = motion.points[p.point].p
        if p.kind == "revolute":
            known[ij] = finite(at)
        elif p.kind == "prismatic":
            known[ij] = at_infinity(perp(guide(p)), n)
        else:
            normals[ij] = line_with_direction(at, _normal(p, motion, angles))
    for name, held in blocks.items():
        if sorted(p.kind for p in held) != ["prismatic", "revolute"]:
            raise MechanismError(f"block {name} must carry one revolute and one prismatic pair, "
                                 f"not {', '.join(p.kind for p in held) or 'none'}")
        pin, slot = sorted(held, key=lambda p: p.kind != "revolute")

        def other(p, name=name):
            return p.a if p.b == name else p.b

        # the slide's direction is fixed in both of its links: the slot's normal is the contact's
        ij = pair(index[label[other(pin)]], index[label[other(slot)]])
        normals[ij] = line_with_direction(motion.points[pin.point].p, perp(guide(slot)))
    out = st.link(st.output)
    return CentreModel(order, FRAME, label[st.input], label[out.name], known, normals, poses, scale=st.scale,
                       guide=guide(st.frame_pair(out.name))[0] if out.translates else None,
                       input_rate=st.input_rate)


def _normal(p, motion, angles) -> np.ndarray:
    """A higher pair's common normal as (n, 2) directions."""
    if callable(p.normal):
        return p.normal(motion)
    return unit(angles[p.a].theta + p.normal)


def twists(st: CentreModel) -> tuple[list[np.ndarray], list[np.ndarray]]:
    """Each link's twist from its pose's analogs: ω = θ', v₀ = o' - θ'·perp(o)."""
    om, v0 = [], []
    for name in st.links:
        o, th = st.poses[name]
        om.append(th.d)
        v0.append(o.d - th.d[:, None] * perp(o.p))
    return om, v0


@dataclass(frozen=True, eq=False)
class InstantCentres:
    """The centres of every pair of links over the crank angles ``phi``.

    ``centres[(i, j)]`` (0-based, i < j) is a :class:`Centre`; call ``ic(a, b)`` with link
    names or 1-based numbers. ``steps`` records Kennedy's construction order.
    """

    mechanism: object
    motion: Motion
    structure: CentreModel
    centres: Mapping[Pair, Centre]
    method: str
    steps: list = field(default_factory=list)

    @property
    def phi(self) -> np.ndarray:
        return self.motion.phi

    @property
    def links(self) -> tuple[str, ...]:
        return self.structure.links

    def index(self, link) -> int:
        if isinstance(link, (int, np.integer)):
            if not 1 <= link <= len(self.links):
                raise MechanismError(f"link number {link} outside 1..{len(self.links)} ({', '.join(self.links)})")
            return int(link) - 1
        try:
            return self.links.index(link)
        except ValueError:
            raise MechanismError(f"no link {link!r}; links: {', '.join(self.links)}") from None

    def __call__(self, a, b) -> Centre:
        i, j = self.index(a), self.index(b)
        if i == j:
            raise MechanismError(f"a link has no centre relative to itself ({self.links[i]})")
        return self.centres[pair(i, j)]

    def label(self, a, b) -> str:
        i, j = sorted((self.index(a) + 1, self.index(b) + 1))
        return f"P{i}{j}"

    # -- analogs read from the centres ---------------------------------------------
    def _rows(self, i, j) -> Centre:
        # the centre over an array of crank angles (one row at a scalar φ), for the analogs below
        c = self.centres[pair(i, j)]
        return Centre(np.atleast_2d(c.h), c.name)

    def _first(self) -> InstantCentres:
        """The centres at the first crank angle, as at a scalar φ."""
        return InstantCentres(self.mechanism, self.motion._first(), self.structure,
                              {k: c._first() for k, c in self.centres.items()}, self.method, self.steps)

    def _shaped(self, values: np.ndarray) -> np.ndarray:
        return values[0] if np.ndim(self.phi) == 0 else values

    def angular_analog(self, link) -> np.ndarray:
        """ω_link / ω_crank from the centres only (Kennedy's ratio theorem); 0 where the link translates."""
        return self._shaped(self._angular_analog(link))

    def _angular_analog(self, link) -> np.ndarray:
        k, one, f = self.index(link), self.index(self.structure.input), self.index(self.structure.frame)
        rate = self.structure.input_rate
        phi = np.atleast_1d(self.phi)
        if k == one:
            return np.full(len(phi), rate)
        if k == f:
            return np.zeros(len(phi))
        p1k, p1f, pkf = self._rows(one, k), self._rows(one, f), self._rows(k, f)
        X, w = p1k.h[:, :2], p1k.h[:, 2]
        u = X - w[:, None] * p1f.xy
        v = X - w[:, None] * np.where(pkf.finite[:, None], pkf.h[:, :2], 0.0)
        vv = dot(v, v)
        bad = pkf.finite & (vv <= (1e-14 * self.structure.scale) ** 2)
        if np.any(bad):
            i = int(np.argmax(bad))
            raise SingularityError(f"{p1k.name} coincides with {pkf.name} at φ = {np.degrees(phi[i]):.4g}°: "
                                   f"a dead point, ω_{k + 1} is unbounded")
        return rate * np.where(pkf.finite, dot(u, v) / np.where(pkf.finite, vv, 1.0), 0.0)

    def velocity_analog(self, link, point: np.ndarray) -> np.ndarray:
        """Velocity analog (n, 2) of a point (n, 2) carried by ``link``, from the centres only."""
        return self._shaped(self._velocity_analog(link, point))

    def _velocity_analog(self, link, point: np.ndarray) -> np.ndarray:
        k, one, f = self.index(link), self.index(self.structure.input), self.index(self.structure.frame)
        point = np.broadcast_to(np.asarray(point, dtype=float), (np.size(self.phi), 2))
        if k == f:
            return np.zeros_like(point)
        om = self._angular_analog(link)
        pkf = self._rows(k, f)
        out = np.where(pkf.finite[:, None], om[:, None] * perp(point - np.where(pkf.finite[:, None],
                                                                                  pkf.h[:, :2], 0.0)), 0.0)
        if k == one:
            return out
        trans = ~pkf.finite
        if np.any(trans):
            p1k, p1f = self._rows(one, k), self._rows(one, f)
            if np.any(trans & ~p1k.finite):
                raise SingularityError(f"{p1k.name} and {pkf.name} both at infinity: the crank would not turn")
            base = self.structure.input_rate * perp(np.where(p1k.finite[:, None], p1k.h[:, :2], 0.0) - p1f.xy)
            out = np.where(trans[:, None], base, out)
        return out

    def output_analog(self) -> np.ndarray:
        """ψ' (angular output) or s' (translating output along its guide), from the centres only."""
        st = self.structure
        if st.guide is None:
            return self.angular_analog(st.output)
        o, _ = st.poses[st.output]
        return self._shaped(dot(self._velocity_analog(st.output, o.p), np.broadcast_to(st.guide, o.p.shape)))

    def collinearity(self) -> float:
        """Largest violation of Kennedy's theorem over all triples of links and angles:
        |det[P_ij; P_jk; P_ik]| of the unit-normalised homogeneous rows (0 when collinear)."""
        worst = 0.0
        n = len(self.links)
        for i in range(n):
            for j in range(i + 1, n):
                for k in range(j + 1, n):
                    rows = [self._rows(i, j).h, self._rows(j, k).h, self._rows(i, k).h]
                    rows = [r * [1.0 / self.structure.scale, 1.0 / self.structure.scale, 1.0] for r in rows]
                    rows = [r / np.linalg.norm(r, axis=1)[:, None] for r in rows]
                    det = np.abs(np.linalg.det(np.stack(rows, axis=1)))
                    worst = max(worst, float(det.max()))
        return worst


@scalar_law
@validated
def instant_centres(mechanism: AnyMechanism, phi: OptionalAngles = None,
                    method: Annotated[str, choice("kennedy", "velocity")] = "kennedy") -> InstantCentres:
    """All instantaneous centres of ``mechanism`` at crank angles φ (default: its cycle); a scalar φ
    gives a motion of scalars and centres of one row each (``h`` of shape (3,)).

    ``method="kennedy"``: from positions only — the pairs' own centres and the higher
    pairs' common normals, then Kennedy's theorem (Kozhevnikov, §7.1). ``method="velocity"``:
    from each link's twist (loop-closure analogs), the independent check; it is also
    defined where Kennedy's lines coincide (a change point), where "kennedy" raises.

    Parameters
    ----------
    mechanism : Mechanism
        Any planar mechanism that describes its ``structure()``.
    phi : float or array_like, optional
        Crank angles (rad); by default ``mechanism.cycle()``.
    method : {"kennedy", "velocity"}
        Kennedy's theorem from positions, or the links' twists.

    Returns
    -------
    InstantCentres
        ``ic(a, b)`` is the :class:`Centre` of links ``a`` and ``b`` (names or 1-based numbers).

    Raises
    ------
    TypeError
        ``mechanism`` is not a Mechanism.
    DimensionError
        ``method`` is not "kennedy" or "velocity", or ``phi`` is not finite.
    SpatialMechanismError
        A spatial mechanism (the spherical Geneva).
    IndeterminateCentre
        Kennedy's lines coincide at a crank angle (``method="kennedy"``).
    AssemblyError
        The mechanism cannot be assembled at a requested crank angle.

    Examples
    --------
    >>> import numpy as np
    >>> import mechlab as ml
    >>> ic = ml.instant_centres(ml.FourBar(1, 3, 3, 4), np.pi / 2)
    >>> ic.links, ic.label("coupler", "frame")
    (('crank', 'coupler', 'rocker', 'frame'), 'P24')
    >>> np.round(ic("coupler", "frame").xy, 4).tolist()  # OA ∩ BE
    [0.0, 7.1072]
    """
    phi = mechanism.cycle() if phi is None else as_angles(phi)
    motion = mechanism.motion(phi)
    st = centre_model(mechanism, motion)
    nums = [str(k + 1) for k in range(len(st.links))]
    if method == "kennedy":
        centres, steps = kennedy(len(st.links), st.known, st.normals, scale=st.scale, phi=phi, names=nums)
    else:
        om, v0 = twists(st)
        centres = centres_from_twists(om, v0, scale=st.scale, phi=phi, names=nums, known=st.known)
        steps = []
    return InstantCentres(mechanism, motion, st, centres, method, steps)
