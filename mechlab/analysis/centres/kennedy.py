"""Kennedy's theorem, vectorised over crank angles, and centres from velocity twists.

Kennedy (Aronhold-Kennedy) theorem (Kozhevnikov, §7.1): the three relative centres
P_ij, P_jk, P_ik of any three links lie on one line. Given the centres that the pairs
fix directly (a pin: the pin; a prismatic pair: the point at infinity normal to the
guide) and, for each higher pair, the common normal at the contact (P_ij lies on it,
Kozhevnikov, the text on Fig. 7.3), :func:`kennedy` finds every other centre as the meet
of two such lines. All n crank angles are handled at once; at each angle the best
conditioned pair of lines is used, so a construction that degenerates at some angle
(two lines that coincide there) falls back to another one. If every construction of a
centre degenerates, :class:`~mechlab.analysis.centres.homogeneous.IndeterminateCentre` names it.

:func:`centres_from_twists` is the independent check: every link's velocity state
(twist) gives its relative centres directly, P = perp(v₀)/ω in homogeneous form
(perp(v₀), ω), with v₀ the velocity of the link's point at the origin.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from itertools import combinations
from typing import Annotated

import numpy as np

from ...errors import DimensionError, MechanismError, SingularityError
from ...geometry import perp
from ...validate import Length, Spec, count, validated
from .homogeneous import COINCIDENT_TOL, Centre, IndeterminateCentre, meet_quality, normalise

Pair = tuple[int, int]


Snapshots = Annotated[np.ndarray, Spec("points", lo=1)]  # (n, 2): one point per snapshot


def pair(i: int, j: int) -> Pair:
    """The unordered pair (i, j) with i < j."""
    return (i, j) if i < j else (j, i)


@validated
def centre_count(n_links: Annotated[int, count(2, why="a mechanism has at least 2 links, frame included")]) -> int:
    """Number of instantaneous centres of n links, frame included: n(n - 1)/2.

    Parameters
    ----------
    n_links : int
        Links, the frame included (≥ 2).

    Returns
    -------
    int
        n(n − 1)/2.

    Raises
    ------
    DimensionError
        ``n_links`` is not an integer ≥ 2.

    Examples
    --------
    >>> import mechlab as ml
    >>> ml.centre_count(4)
    6
    """
    return n_links * (n_links - 1) // 2


def _lines(p: np.ndarray, q: np.ndarray, scale: float) -> tuple[np.ndarray, np.ndarray]:
    """Lines through the homogeneous points p and q (normalised) and a mask of where they are defined."""
    L = np.cross(p, q)
    ab = np.hypot(L[:, 0], L[:, 1])
    norm = np.where(ab > COINCIDENT_TOL, ab, np.abs(L[:, 2]))
    ok = norm > COINCIDENT_TOL
    return L / np.where(ok, norm, 1.0)[:, None], ok


def _candidate_lines(centres, valid, normals, i, j, n_links, label):
    """The Kennedy lines for P_ij available now: (name, lines (n, 3), usable rows)."""
    out = []
    for k in range(n_links):
        if k in (i, j) or pair(i, k) not in centres or pair(k, j) not in centres:
            continue
        a, b = pair(i, k), pair(k, j)
        L, ok = _lines(centres[a], centres[b], 1.0)  # rows not yet found are masked
        out.append((f"{label(i, k)}{label(k, j)}", L, ok & valid[a] & valid[b]))
    if (i, j) in normals:
        L = normals[(i, j)]
        out.append(("normal", L, np.ones(len(L), dtype=bool)))
    return out


def kennedy(n_links: int, known: Mapping[Pair, Centre], normals: Mapping[Pair, np.ndarray] | None = None,
            *, scale: float = 1.0, phi=None, names: Sequence[str] | None = None):
    """All centres of ``n_links`` links from the ``known`` ones by Kennedy's theorem.

    ``known`` maps pairs ``(i, j)`` (0-based, i < j) to :class:`Centre`; ``normals`` maps
    a higher pair to its common normal, lines ``(n, 3)``. Returns ``(centres, steps)``:
    every pair's centre, and the construction order as ``(pair, [lines used])`` where a
    line is named by the two centres it joins, or "normal". Works angle by angle: a
    centre whose lines coincide at some angles is completed there once another centre
    offers a further line. Raises MechanismError if the known centres do not determine
    the rest, IndeterminateCentre if at some angle every construction degenerates.
    """
    normals = {pair(*k): v for k, v in (normals or {}).items()}
    names = list(names) if names is not None else [str(k + 1) for k in range(n_links)]
    label = lambda a, b: "P" + "".join(sorted((names[a], names[b])))  # noqa: E731
    centres = {pair(*k): v.h.copy() for k, v in known.items()}
    if not centres:
        raise MechanismError("Kennedy's theorem needs the centres of the pairs to start from; none given")
    n = len(next(iter(centres.values())))
    valid = {k: np.ones(n, dtype=bool) for k in centres}
    steps = []
    while True:
        todo = [p for p in combinations(range(n_links), 2) if p not in centres or not valid[p].all()]
        if not todo:
            break
        progress = False
        cands = [(p, _candidate_lines(centres, valid, normals, *p, n_links, label)) for p in todo]
        cands.sort(key=lambda c: -len(c[1]))
        for (i, j), lines in cands:
            if len(lines) < 2:
                continue
            combos = list(combinations(range(len(lines)), 2))
            quality = np.stack([np.where(lines[a][2] & lines[b][2], meet_quality(lines[a][1], lines[b][1], scale), 0.0)
                                for a, b in combos])
            pick = np.argmax(quality, axis=0)
            q = quality[pick, np.arange(n)]
            meets = np.stack([np.cross(lines[a][1], lines[b][1]) for a, b in combos])
            h = meets[pick, np.arange(n)]
            old = valid.get((i, j), np.zeros(n, dtype=bool))
            new = (q > COINCIDENT_TOL) & ~old
            if not new.any():
                continue
            if (i, j) not in centres:
                centres[(i, j)] = np.zeros((n, 3))
                steps.append(((i, j), [t for t, _, _ in lines]))
            centres[(i, j)][new] = h[new]
            valid[(i, j)] = old | new
            progress = True
            break
        if not progress:
            unknown = [p for p in todo if p not in centres]
            if unknown:
                missing = ", ".join(label(*p) for p in unknown)
                if all(len(c[1]) < 2 for c in cands if c[0] in unknown):
                    raise MechanismError(f"Kennedy's theorem cannot locate {missing}: too few known centres")
            p = next(p for p in todo if p in centres) if not unknown else unknown[0]
            rows = ~valid.get(p, np.zeros(n, dtype=bool))
            r = int(np.argmax(rows))
            at = "" if phi is None else f" at φ = {np.degrees(phi[r]):.4g}°"
            used = " and ".join(t for t, _, _ in dict(cands)[p]) or "no lines"
            raise IndeterminateCentre(
                f"{label(*p)} is indeterminate{at}: Kennedy's lines {used} coincide there "
                f"(all their centres lie on one line, e.g. a linkage folded flat)")
    out = {p: normalise(h, scale, label(*p), phi) for p, h in centres.items()}
    return out, steps


def twist_centre(omega: np.ndarray, v0: np.ndarray, scale: float = 1.0, name: str = "P", phi=None) -> Centre:
    """Centre of a relative twist (ω, v₀): the point with v₀ + ω·perp(P) = 0, i.e.
    (perp(v₀), ω) homogeneously; at infinity when ω = 0 (a relative translation)."""
    return normalise(np.column_stack([perp(v0), omega]), scale, name, phi)


def centres_from_twists(omega: Sequence[np.ndarray], v0: Sequence[np.ndarray], *, scale: float = 1.0,
                        phi=None, names: Sequence[str] | None = None,
                        known: Mapping[Pair, Centre] | None = None) -> dict[Pair, Centre]:
    """Every relative centre from the links' twists: ``omega[k]`` (n,) and ``v0[k]`` (n, 2).

    Pairs in ``known`` (pins, guides) keep their geometric centre: where two jointed
    links happen to be at relative rest, their twist alone could not place it.
    """
    n = len(omega)
    names = list(names) if names is not None else [str(k + 1) for k in range(n)]
    known = {pair(*k): v for k, v in (known or {}).items()}
    out = {}
    for i, j in combinations(range(n), 2):
        label = "P" + "".join(sorted((names[i], names[j])))
        out[(i, j)] = (Centre(known[(i, j)].h, label) if (i, j) in known
                       else twist_centre(omega[j] - omega[i], v0[j] - v0[i], scale, label, phi))
    return out


@validated
def five_link_higher_pair(P15: Snapshots, P12: Snapshots, P23: Snapshots, P34: Snapshots, P45: Snapshots,
                          contact: Snapshots, normal: Snapshots, scale: Length = 1.0):
    """Kozhevnikov, Fig. 7.3: a five-link mechanism (5 = frame) with pins P15, P12, P23, P34, P45
    and a higher pair between links 2 and 4 touching at ``contact`` with common normal
    ``normal``; every argument is (n, 2) for n snapshots.

    The same centres are found twice: by Kennedy's theorem from the five pins and the normal
    (the seed's construction), and from the links' twists, obtained by solving the velocity
    constraints with ω₁ = 1 (each pin: equal velocities of both links there; the contact: no
    relative velocity along the normal). The twists are the independent check.

    Parameters
    ----------
    P15, P12, P23, P34, P45 : array_like
        The pins, each ``(n, 2)`` for n snapshots.
    contact : array_like
        The higher pair's contact point, ``(n, 2)``.
    normal : array_like
        The common normal at the contact, ``(n, 2)``, non-zero.
    scale : float
        A length of the mechanism's size (default 1), for the tolerances.

    Returns
    -------
    by_kennedy, by_twists : dict
        The ten centres, keyed by 0-based pairs (i, j), i < j, each a :class:`Centre`.
    steps : list
        Kennedy's construction order.

    Raises
    ------
    DimensionError
        An argument is not ``(n, 2)`` with one row per snapshot, or the normal is zero.
    IndeterminateCentre
        Kennedy's construction degenerates (two lines or two points coincide).
    SingularityError
        The velocity constraints are singular (a dead-centre position).

    Examples
    --------
    >>> import numpy as np
    >>> import mechlab as ml
    >>> row = lambda x, y: np.array([[x, y]])
    >>> by_kennedy, by_twists, steps = ml.five_link_higher_pair(
    ...     row(0, 0), row(1, 1), row(3, 2), row(4, 0.5), row(5, -1), row(2.5, 0.3), row(0.3, 1))
    >>> np.round(by_kennedy[(1, 3)].xy, 4).tolist(), np.round(by_twists[(1, 3)].xy, 4).tolist()  # P24
    ([[3.0069, 1.9897]], [[3.0069, 1.9897]])
    """
    pins = {(0, 4): P15, (0, 1): P12, (1, 2): P23, (2, 3): P34, (3, 4): P45}
    n = len(contact)
    given = {"P15": P15, "P12": P12, "P23": P23, "P34": P34, "P45": P45, "normal": normal}
    for name, rows in given.items():
        if len(rows) != n:
            raise DimensionError(f"{name} must hold one row per snapshot, as contact does ({n}), got {len(rows)}")
    if np.any(np.hypot(normal[:, 0], normal[:, 1]) == 0.0):
        raise DimensionError("normal must be a non-zero direction in every snapshot")
    from .homogeneous import finite, line_with_direction
    known = {k: finite(v) for k, v in pins.items()}
    lines = {(1, 3): line_with_direction(contact, normal)}
    names = [str(k + 1) for k in range(5)]
    by_kennedy, steps = kennedy(5, known, lines, scale=scale, names=names)
    # unknowns: ω2, ω3, ω4, v0 of links 1..4 (ω1 = 1, frame at rest) -> 11 columns
    col_w = {1: 0, 2: 1, 3: 2}
    col_v = {k: 3 + 2 * k for k in range(4)}
    M = np.zeros((n, 11, 11))
    rhs = np.zeros((n, 11))
    row = 0

    def add_motion(r, link, Q, weight, comp):
        # weight·(v0_link + ω_link·perp(Q))[comp] added to row r (ω1 = 1 goes to the right side)
        if link == 4:
            return
        M[:, r, col_v[link] + comp] += weight
        pq = perp(Q)[:, comp]
        if link == 0:
            rhs[:, r] -= weight * pq
        else:
            M[:, r, col_w[link]] += weight * pq

    for (i, j), Q in pins.items():
        for comp in (0, 1):
            add_motion(row, i, Q, 1.0, comp)
            add_motion(row, j, Q, -1.0, comp)
            row += 1
    for comp in (0, 1):  # the contact: (v2(A) - v4(A))·n = 0
        add_motion(row, 1, contact, normal[:, comp], comp)
        add_motion(row, 3, contact, -normal[:, comp], comp)
    try:
        sol = np.linalg.solve(M, rhs[..., None])[..., 0]
    except np.linalg.LinAlgError:
        bad = int(np.argmin(np.abs(np.linalg.det(M))))
        raise SingularityError(f"the velocity constraints are singular in snapshot {bad}: the links' twists are "
                               f"not fixed by ω1 (the pins and the contact are in a dead-centre position)") from None
    omega = [np.ones(n), sol[:, 0], sol[:, 1], sol[:, 2], np.zeros(n)]
    v0 = [sol[:, 3:5], sol[:, 5:7], sol[:, 7:9], sol[:, 9:11], np.zeros((n, 2))]
    by_twists = centres_from_twists(omega, v0, scale=scale, names=names, known=known)
    return by_kennedy, by_twists, steps
