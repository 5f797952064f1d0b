"""Kennedy's theorem, vectorised over crank angles, and centres from velocity twists.

Kennedy (Aronhold-Kennedy) theorem (seed 002, §7.1): the three relative centres
P_ij, P_jk, P_ik of any three links lie on one line. Given the centres that the pairs
fix directly (a pin: the pin; a prismatic pair: the point at infinity normal to the
guide) and, for each higher pair, the common normal at the contact (P_ij lies on it,
seed 002, the text on Fig. 7.3), :func:`kennedy` finds every other centre as the meet
of two such lines. All n crank angles are handled at once; at each angle the best
conditioned pair of lines is used, so a construction that degenerates at some angle
(two lines that coincide there) falls back to another one. If every construction of a
centre degenerates, :class:`~mechlab.centres.homogeneous.IndeterminateCentre` names it.

:func:`centres_from_twists` is the independent check: every link's velocity state
(twist) gives its relative centres directly, P = perp(v₀)/ω in homogeneous form
(perp(v₀), ω), with v₀ the velocity of the link's point at the origin.
"""

from __future__ import annotations

from itertools import combinations
from typing import Mapping, Sequence

import numpy as np

from ..errors import MechanismError
from ..geometry import perp
from .homogeneous import (COINCIDENT_TOL, Centre, IndeterminateCentre, meet_quality, normalise)

Pair = tuple[int, int]


def pair(i: int, j: int) -> Pair:
    """The unordered pair (i, j) with i < j."""
    return (i, j) if i < j else (j, i)


def centre_count(n_links: int) -> int:
    """Number of instantaneous centres of n links, frame included: n(n - 1)/2."""
    if int(n_links) != n_links or n_links < 2:
        raise MechanismError(f"a mechanism has at least 2 links (frame included), got {n_links!r}")
    return int(n_links) * (int(n_links) - 1) // 2


def _lines(p: Centre, q: Centre, scale: float) -> tuple[np.ndarray, np.ndarray]:
    """Lines through p and q (normalised) and a mask of where they are defined."""
    L = np.cross(p.h, q.h)
    ab = np.hypot(L[:, 0], L[:, 1])
    norm = np.where(ab > COINCIDENT_TOL, ab, np.abs(L[:, 2]))
    ok = norm > COINCIDENT_TOL
    return L / np.where(ok, norm, 1.0)[:, None], ok


def kennedy(n_links: int, known: Mapping[Pair, Centre], normals: Mapping[Pair, np.ndarray] | None = None,
            *, scale: float = 1.0, phi=None, names: Sequence[str] | None = None):
    """All centres of ``n_links`` links from the ``known`` ones by Kennedy's theorem.

    ``known`` maps pairs ``(i, j)`` (0-based, i < j) to :class:`Centre`; ``normals`` maps
    a higher pair to its common normal, lines ``(n, 3)``. Returns ``(centres, steps)``:
    every pair's centre, and the construction order as ``(pair, [lines used])`` where a
    line is named by the two centres it joins, or "normal". Raises MechanismError if
    the known centres do not determine the rest.
    """
    normals = dict(normals or {})
    names = list(names) if names is not None else [str(k + 1) for k in range(n_links)]
    label = lambda a, b: "P" + "".join(sorted((names[a], names[b])))  # noqa: E731
    centres: dict[Pair, Centre] = {pair(*k): v for k, v in known.items()}
    steps = []
    todo = [p for p in combinations(range(n_links), 2) if p not in centres]
    while todo:
        best = None
        for i, j in todo:
            lines = [(f"{label(i, k)}{label(k, j)}", k) for k in range(n_links)
                     if k not in (i, j) and pair(i, k) in centres and pair(k, j) in centres]
            if (i, j) in normals:
                lines.append(("normal", None))
            if len(lines) >= 2 and (best is None or len(lines) > len(best[1])):
                best = ((i, j), lines)
        if best is None:
            missing = ", ".join(label(*p) for p in todo)
            raise MechanismError(f"Kennedy's theorem cannot locate {missing}: too few known centres")
        (i, j), lines = best
        arrays = []
        for text, k in lines:
            if k is None:
                L = normals[(i, j)]
                arrays.append((L, np.ones(len(L), dtype=bool)))
            else:
                arrays.append(_lines(centres[pair(i, k)], centres[pair(k, j)], scale))
        # every pair of candidate lines; at each angle keep the best-conditioned meet
        combos = list(combinations(range(len(arrays)), 2))
        quality = np.stack([np.where(arrays[a][1] & arrays[b][1],
                                     meet_quality(arrays[a][0], arrays[b][0], scale), 0.0) for a, b in combos])
        pick = np.argmax(quality, axis=0)
        q = quality[pick, np.arange(quality.shape[1])]
        if np.any(q <= COINCIDENT_TOL):
            s = int(np.argmax(q <= COINCIDENT_TOL))
            at = "" if phi is None else f" at φ = {np.degrees(phi[s]):.4g}°"
            used = " and ".join(t for t, _ in lines)
            raise IndeterminateCentre(
                f"{label(i, j)} is indeterminate{at}: Kennedy's lines {used} coincide there "
                f"(all their centres lie on one line, e.g. a linkage folded flat)")
        meets = np.stack([np.cross(arrays[a][0], arrays[b][0]) for a, b in combos])
        h = meets[pick, np.arange(meets.shape[1])]
        centres[(i, j)] = normalise(h, scale, label(i, j), phi)
        steps.append(((i, j), [t for t, _ in lines]))
        todo.remove((i, j))
    for p, c in centres.items():
        object.__setattr__(c, "name", label(*p))
    return centres, steps


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
