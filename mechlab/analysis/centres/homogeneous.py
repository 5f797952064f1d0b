"""Points and lines in homogeneous coordinates, so that centres at infinity are explicit.

An instantaneous centre of two links that translate relative to each other lies at
infinity, in the direction perpendicular to their relative velocity (Kozhevnikov, §7.1:
the centre of a slider and its guide "lies at infinity on the normal to the guide").
A :class:`Centre` therefore stores each point as ``(x, y, w)``: a finite point has
``w = 1`` and position ``(x, y)``; a point at infinity has ``w = 0`` and the unit
direction ``(x, y)`` (defined up to sign). Joining two points gives a line
``(a, b, c)`` (``a x + b y + c w = 0``, normalised so that ``a² + b² = 1``), and the
meet of two lines is their cross product: parallel lines meet at infinity, with no
division anywhere. Only two coincident lines (or two coincident points) leave the
meet (or join) undefined; those raise :class:`IndeterminateCentre` naming the lines
and the crank angle, never a silent NaN.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...errors import CentreAtInfinity, DimensionError, IndeterminateCentre
from ...validate import Checked, Name, Spec, check_value

ROWS = Spec("points", lo=0, width=3)  # homogeneous rows (x, y, w)

# A meet farther than 1/INFINITY_TOL mechanism sizes away counts as a point at infinity.
INFINITY_TOL = 1e-12
# Two lines whose meet is smaller than this (relative) in every component coincide.
COINCIDENT_TOL = 1e-10


def _fmt_phi(phi, i) -> str:
    return "" if phi is None else f" at φ = {np.degrees(phi[i]):.4g}°"


@dataclass(frozen=True, eq=False)
class Centre(Checked):
    """An instantaneous centre over n crank angles, in normalised homogeneous coordinates.

    ``h`` is ``(n, 3)``: rows ``(x, y, 1)`` for finite points and ``(dx, dy, 0)`` with a
    unit direction for points at infinity; ``(3,)`` (one row) at a scalar crank angle. Build one with :func:`finite`,
    :func:`at_infinity` or :func:`normalise`.

    Parameters
    ----------
    h : numpy.ndarray
        Homogeneous rows ``(x, y, w)``, shape ``(n, 3)`` or ``(3,)``.
    name : str
        The centre's label, e.g. "P24".

    Raises
    ------
    DimensionError
        A row that is not normalised so (``xy`` would otherwise read a wrong position).

    Examples
    --------
    >>> import numpy as np
    >>> import mechlab as ml
    >>> c = ml.Centre(np.array([[1.0, 2.0, 1.0], [0.0, 1.0, 0.0]]), "P13")
    >>> c.finite.tolist(), len(c)
    ([True, False], 2)
    """

    h: np.ndarray
    name: Name = "P"

    def __post_init__(self):
        super().__post_init__()
        one = np.ndim(self.h) == 1  # one row, at a scalar crank angle
        rows = check_value("h", np.atleast_2d(self.h) if one else self.h, ROWS)
        w, r = rows[:, 2], np.hypot(rows[:, 0], rows[:, 1])
        bad = ~((w == 1.0) | ((w == 0.0) & (np.abs(r - 1.0) <= 1e-9)))
        if np.any(bad):
            i = int(np.argmax(bad))
            raise DimensionError(f"h[{i}] = {rows[i].tolist()} of centre {self.name} must be normalised: "
                                 f"(x, y, 1) for a finite point or (dx, dy, 0) with a unit direction")
        object.__setattr__(self, "h", rows[0] if one else rows)

    def __len__(self) -> int:
        return len(np.atleast_2d(self.h))

    @property
    def finite(self) -> np.ndarray:
        """Boolean mask: True where the centre is a finite point.

        Returns
        -------
        numpy.ndarray of bool
            Shape ``(n,)`` (a scalar for one row): w ≠ 0.

        Examples
        --------
        >>> import numpy as np
        >>> import mechlab as ml
        >>> ml.Centre(np.array([[1.0, 2.0, 1.0], [0.0, 1.0, 0.0]])).finite.tolist()
        [True, False]
        """
        return self.h[..., 2] != 0.0

    @property
    def xy(self) -> np.ndarray:
        """Positions ``(n, 2)`` of finite centres.

        Returns
        -------
        numpy.ndarray
            The positions (x, y), in the mechanism's length units.

        Raises
        ------
        CentreAtInfinity
            A centre lies at infinity (use :attr:`finite`, :attr:`direction` or :meth:`masked`).

        Examples
        --------
        >>> import numpy as np
        >>> import mechlab as ml
        >>> ml.Centre(np.array([[1.0, 2.0, 1.0]])).xy.tolist()
        [[1.0, 2.0]]
        """
        if not np.all(self.finite):
            i = int(np.argmin(np.atleast_1d(self.finite)))
            d = np.atleast_2d(self.h)[i, :2]
            raise CentreAtInfinity(
                f"{self.name} lies at infinity at sample {i} (direction ({d[0]:.4g}, {d[1]:.4g})): "
                f"the two links translate relative to each other there; use .finite / .direction")
        return self.h[..., :2].copy()

    @property
    def direction(self) -> np.ndarray:
        """Unit directions of the centres at infinity.

        Returns
        -------
        numpy.ndarray
            Shape ``(n, 2)``: the unit direction where a centre is at infinity, zero rows where it is finite.

        Examples
        --------
        >>> import numpy as np
        >>> import mechlab as ml
        >>> ml.Centre(np.array([[1.0, 2.0, 1.0], [0.0, 1.0, 0.0]])).direction.tolist()
        [[0.0, 0.0], [0.0, 1.0]]
        """
        return np.where(self.finite[..., None], 0.0, self.h[..., :2])

    def masked(self) -> np.ma.MaskedArray:
        """Positions as a masked array, masked where the centre is at infinity (for plotting).

        Returns
        -------
        numpy.ma.MaskedArray
            Shape ``(n, 2)``; rows at infinity masked.

        Examples
        --------
        >>> import numpy as np
        >>> import mechlab as ml
        >>> ml.Centre(np.array([[1.0, 2.0, 1.0], [0.0, 1.0, 0.0]])).masked().mask.tolist()
        [[False, False], [True, True]]
        """
        mask = np.repeat(~self.finite[..., None], 2, axis=-1)
        return np.ma.array(np.where(mask, 0.0, self.h[..., :2]), mask=mask)

    def _first(self) -> Centre:
        """The centre at the first crank angle, as at a scalar φ (``h`` of shape (3,))."""
        return Centre(self.h[0], self.name)

    def __getitem__(self, idx) -> Centre:
        return Centre(np.atleast_2d(self.h[idx]), self.name)


def normalise(h: np.ndarray, scale: float = 1.0, name: str = "P", phi=None) -> Centre:
    """Homogeneous rows → :class:`Centre`: divide by w, or mark as infinite when |w| is tiny.

    A row counts as at infinity when the point would lie more than ``scale/INFINITY_TOL``
    away; a row that is zero (to ``COINCIDENT_TOL``) is undefined and raises
    :class:`IndeterminateCentre`.
    """
    h = np.asarray(h, dtype=float)
    xy, w = h[:, :2], h[:, 2]
    r = np.hypot(xy[:, 0], xy[:, 1])
    zero = (r <= COINCIDENT_TOL * scale) & (np.abs(w) <= COINCIDENT_TOL)
    if np.any(zero):
        i = int(np.argmax(zero))
        raise IndeterminateCentre(f"{name} is undefined{_fmt_phi(phi, i)}: its construction degenerates")
    inf = np.abs(w) * scale <= INFINITY_TOL * r
    out = np.empty_like(h)
    safe_w = np.where(inf, 1.0, w)
    out[:, :2] = np.where(inf[:, None], xy / np.where(r == 0, 1.0, r)[:, None], xy / safe_w[:, None])
    out[:, 2] = np.where(inf, 0.0, 1.0)
    return Centre(_canonical(out), name)


def _canonical(h: np.ndarray) -> np.ndarray:
    """Directions at infinity with a fixed sign (x > 0, or x = 0 and y > 0): ±d is one point."""
    flip = (h[:, 2] == 0.0) & ((h[:, 0] < 0.0) | ((h[:, 0] == 0.0) & (h[:, 1] < 0.0)))
    h[flip, :2] *= -1.0
    return h


def separation(c1: Centre, c2: Centre, scale: float = 1.0) -> np.ndarray:
    """Projective distance of two centres, row by row: the sine of the angle between
    their homogeneous vectors (x/scale, y/scale, w). About |P1 - P2|/scale for nearby
    finite points, |d1 × d2| for two points at infinity, small for a far finite point
    and a point at infinity in its direction; 0 only for the same point."""
    a = c1.h * [1.0 / scale, 1.0 / scale, 1.0]
    b = c2.h * [1.0 / scale, 1.0 / scale, 1.0]
    a = a / np.linalg.norm(a, axis=1)[:, None]
    b = b / np.linalg.norm(b, axis=1)[:, None]
    return np.linalg.norm(np.cross(a, b), axis=1)


def finite(xy, name: str = "P") -> Centre:
    """Finite centres at positions ``xy`` (n, 2) (a pin joint)."""
    xy = np.asarray(xy, dtype=float)
    return Centre(np.column_stack([xy, np.ones(len(xy))]), name)


def at_infinity(direction, n: int | None = None, name: str = "P") -> Centre:
    """Centres at infinity in ``direction`` (a 2-vector or (n, 2)) — a prismatic pair."""
    d = np.asarray(direction, dtype=float)
    if d.ndim == 1:
        d = np.broadcast_to(d, (n, 2))
    d = d / np.hypot(d[:, 0], d[:, 1])[:, None]
    return Centre(_canonical(np.column_stack([d, np.zeros(len(d))])), name)


def line_through(p: Centre, q: Centre, scale: float = 1.0, what: str = "the line", phi=None) -> np.ndarray:
    """Lines ``(n, 3)`` through two centres (either may be at infinity), normalised a² + b² = 1.

    The line through two points at infinity is the line at infinity ``(0, 0, 1)``.
    """
    L = np.cross(p.h, q.h)
    ab = np.hypot(L[:, 0], L[:, 1])
    at_inf_line = (ab <= COINCIDENT_TOL) & (np.abs(L[:, 2]) > COINCIDENT_TOL)
    bad = (ab <= COINCIDENT_TOL) & ~at_inf_line
    if np.any(bad):
        i = int(np.argmax(bad))
        raise IndeterminateCentre(f"{what} is undefined{_fmt_phi(phi, i)}: {p.name} and {q.name} coincide")
    norm = np.where(at_inf_line, np.abs(L[:, 2]), ab)
    return L / norm[:, None]


def line_with_direction(point: np.ndarray, direction: np.ndarray) -> np.ndarray:
    """Lines through finite ``point`` (n, 2) along ``direction`` (n, 2) (e.g. a common normal)."""
    n = len(point)
    return line_through(finite(point), at_infinity(direction, n))


def meet(l1: np.ndarray, l2: np.ndarray, scale: float = 1.0, name: str = "P", phi=None) -> Centre:
    """The intersection of two lines (n, 3) as a :class:`Centre` (parallel lines meet at infinity)."""
    return normalise(np.cross(l1, l2), scale, name, phi)


def meet_quality(l1: np.ndarray, l2: np.ndarray, scale: float = 1.0) -> np.ndarray:
    """How well two normalised lines fix their meet: the size of ``l1 × l2`` with its
    position part divided by ``scale``. It is |sin| of the angle between crossing lines
    (times a factor ≥ 1), the separation/scale of parallel ones, and 0 only when they coincide."""
    m = np.cross(l1, l2)
    return np.sqrt((m[:, 0] ** 2 + m[:, 1] ** 2) / scale**2 + m[:, 2] ** 2)


def in_frame(c: Centre, origin: np.ndarray, angle: np.ndarray) -> Centre:
    """Centres expressed in a moving frame with ``origin`` (n, 2) and x-axis at ``angle`` (n,).

    Finite points are shifted and rotated by -angle; directions at infinity are only rotated.
    """
    cs, sn = np.cos(angle), np.sin(angle)
    fin = c.finite
    rel = c.h[:, :2] - np.where(fin[:, None], origin, 0.0)
    x = cs * rel[:, 0] + sn * rel[:, 1]
    y = -sn * rel[:, 0] + cs * rel[:, 1]
    return Centre(np.column_stack([x, y, c.h[:, 2]]), c.name)


def segments(c: Centre, clip: float) -> list[np.ndarray]:
    """Pieces of a centrode that stay within ``clip`` of the origin, as (m, 2) polylines.

    The curve is cut where the centre goes to infinity or beyond ``clip`` (a hyperbola's
    branches, say), so that plotting never joins the two ends through the picture.
    """
    ok = c.finite.copy()
    ok[ok] = np.hypot(*c.h[ok, :2].T) <= clip
    pieces, start = [], None
    for i, good in enumerate(np.append(ok, False)):
        if good and start is None:
            start = i
        elif not good and start is not None:
            if i - start >= 2:
                pieces.append(c.h[start:i, :2].copy())
            start = None
    return pieces
