"""Planar geometry written once: points with their analogs, circle-circle and
line-circle intersections with a branch sign, the dyads RRR, RRP and RPR.

A moving point is a :class:`PointPath`: its positions ``p`` and its first and second
derivatives with respect to the crank angle φ (the velocity and acceleration
analogs), each an ``(n, 2)`` array over n crank angles. The dyad solvers take the
paths of their outer joints and return the path of the inner joint, differentiating
the constraint equations analytically (no finite differences):

* a distance constraint ``|B - A| = l`` gives ``(B - A)·(B' - A') = 0`` and
  ``(B - A)·(B'' - A'') + |B' - A'|² = 0``;
* two such constraints make a 2×2 linear system for ``B'`` (then ``B''``), whose
  determinant ``(B - A) × (B - E)`` vanishes exactly at a dead point.
"""

from __future__ import annotations

import os
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass

import numpy as np

from .errors import AssemblyError, DimensionError, SingularityError
from .validate import Spec, check_value, length, number

# Relative tolerance under which a dyad counts as stretched or folded (a dead point).
DEAD_POINT_TOL = 1e-12


class PointPath:
    """Positions ``p`` of a point and its analogs ``d`` = dp/dφ, ``dd`` = d²p/dφ².

    An analog may be given as a function of no arguments: it is evaluated on first use and kept, so a
    motion costs only what is read of it (a four-bar's ψ, ψ', ψ'' need neither B' nor B''). Unpacks like
    the tuple ``(p, d, dd)``.

    Parameters
    ----------
    p : numpy.ndarray
        Positions, shape (n, 2) (length; (2,) in a motion at one crank angle).
    d : numpy.ndarray or callable
        First analog dp/dφ (length/rad), or a function of no arguments giving it.
    dd : numpy.ndarray or callable
        Second analog d²p/dφ² (length/rad²), or a function of no arguments giving it.

    Examples
    --------
    >>> import numpy as np
    >>> A = crank_point(1.0, np.array([0.3]))
    >>> A.p.round(4), A.d.round(4)
    (array([[0.9553, 0.2955]]), array([[-0.2955,  0.9553]]))
    """

    __slots__ = ("_d", "_dd", "p")

    def __init__(self, p: np.ndarray, d, dd):
        self.p, self._d, self._dd = p, d, dd

    @property
    def d(self) -> np.ndarray:
        """The first analog dp/dφ (evaluated on first use if given as a function).

        Returns
        -------
        numpy.ndarray
            Shape like ``p`` (length/rad).
        """
        if callable(self._d):
            self._d = self._d()
        return self._d

    @property
    def dd(self) -> np.ndarray:
        """The second analog d²p/dφ² (evaluated on first use if given as a function).

        Returns
        -------
        numpy.ndarray
            Shape like ``p`` (length/rad²).
        """
        if callable(self._dd):
            self._dd = self._dd()
        return self._dd

    def __iter__(self):
        return iter((self.p, self.d, self.dd))

    def rows(self, sl: slice):
        """x, y, x', y', x'', y'' of rows ``sl`` (views where possible)."""
        p, d, dd = self.p[sl], self.d[sl], self.dd[sl]
        return p[:, 0], p[:, 1], d[:, 0], d[:, 1], dd[:, 0], dd[:, 1]

    def __repr__(self) -> str:
        return f"PointPath(n={len(self.p)})"


@dataclass(frozen=True, eq=False)
class AnglePath:
    """An angle θ(φ) and its analogs θ' and θ''; unpacks like the tuple ``(theta, d, dd)``.

    Parameters
    ----------
    theta : numpy.ndarray
        The angle (radians) — or, for a displacement law, the coordinate (length).
    d : numpy.ndarray
        θ' = dθ/dφ.
    dd : numpy.ndarray
        θ'' = d²θ/dφ².

    Examples
    --------
    >>> import numpy as np
    >>> theta, d, dd = AnglePath(np.array([0.1]), np.array([1.0]), np.array([0.0]))
    >>> float(d[0])
    1.0
    """

    theta: np.ndarray
    d: np.ndarray
    dd: np.ndarray

    def __iter__(self):
        return iter((self.theta, self.d, self.dd))


def cross(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """z-component of the cross product of arrays of 2-vectors."""
    return a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0]


def dot(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Row-wise dot product of arrays of 2-vectors."""
    return a[..., 0] * b[..., 0] + a[..., 1] * b[..., 1]


def perp(a: np.ndarray) -> np.ndarray:
    """Each 2-vector turned by +90° (counter-clockwise)."""
    return np.stack([-a[..., 1], a[..., 0]], axis=-1)


def unit(theta) -> np.ndarray:
    """Unit vectors at angles ``theta`` as an ``(n, 2)`` array."""
    theta = np.asarray(theta, dtype=float)
    return np.stack([np.cos(theta), np.sin(theta)], axis=-1)


def wrap(angle):
    """Angle reduced to (-π, π]."""
    return np.pi - np.mod(np.pi - np.asarray(angle, dtype=float), 2 * np.pi)


def as_angles(phi, name: str = "phi") -> np.ndarray:
    """Crank angles (radians) as a 1-D float array; a scalar becomes an array of one.

    Parameters
    ----------
    phi : float or array_like
        Crank angles (radians).
    name : str, optional
        The parameter's name in the error message.

    Returns
    -------
    numpy.ndarray
        The angles, one-dimensional (an empty array gives empty results).

    Raises
    ------
    DimensionError
        Naming ``name``, for complex values, strings, None, NaN, ±inf, magnitudes over 1e100 and
        multi-dimensional arrays.

    Examples
    --------
    >>> as_angles(0.3)
    array([0.3])
    """
    return check_value(name, phi, _ANGLES)


REAL, _LENGTH, _DISTANCE, _SIGN, _ANGLES = number(), length(), length(zero=True), Spec("sign"), Spec("angles", lo=0)


def check_number(name: str, value) -> float:
    """``value`` as a finite float of magnitude ≤ 1e100 (:mod:`mechlab.validate`), else DimensionError."""
    return check_value(name, value, REAL)


def check_length(name: str, value, *, allow_zero: bool = False) -> float:
    """``value`` as a float, raising DimensionError if it is not a positive (or zero) finite number."""
    return check_value(name, value, _DISTANCE if allow_zero else _LENGTH)


def check_sign(name: str, value) -> int:
    """An assembly sign: +1 or -1."""
    return check_value(name, value, _SIGN)


def as_complex(a):
    """Points as complex numbers x + iy: an (n, 2) array becomes a complex (n,) array
    (a view, no copy, when the array is C-contiguous); a fixed point a complex scalar."""
    a = np.asarray(a, dtype=float)
    if a.ndim == 1:
        return complex(a[0], a[1])
    if a.strides[0] == 0 and len(a):
        return complex(a[0, 0], a[0, 1])
    if not a.flags.c_contiguous:
        a = np.ascontiguousarray(a)
    return a.view(np.complex128)[:, 0]


def as_xy(z, n: int | None = None) -> np.ndarray:
    """Complex points as an (n, 2) float array: a view of a complex array, or a read-only
    broadcast of a complex scalar over n rows."""
    if np.ndim(z) == 0:
        return np.broadcast_to(np.array([z.real, z.imag], dtype=float), (n, 2))
    z = np.ascontiguousarray(z, dtype=np.complex128)
    return z.view(np.float64).reshape(-1, 2)


def _re_conj(u, v):
    """Re(conj(u)·v) = u·v for complex arrays (0 when v is the scalar 0)."""
    if np.ndim(v) == 0 and v == 0:
        return 0.0
    return u.real * v.real + u.imag * v.imag


def _im_conj(u, v):
    """Im(conj(u)·v) = u × v for complex arrays."""
    return u.real * v.imag - u.imag * v.real


def _abs2(z):
    return z.real * z.real + z.imag * z.imag


def fixed_point(xy, n: int) -> PointPath:
    """A point fixed to the frame over n crank angles (read-only broadcast arrays).

    Parameters
    ----------
    xy : sequence of float
        The point (length).
    n : int
        Number of crank angles.

    Returns
    -------
    PointPath
        Positions (n, 2) and zero analogs.

    Examples
    --------
    >>> fixed_point((4.0, 0.0), 2).p
    array([[4., 0.],
           [4., 0.]])
    """
    p = np.broadcast_to(np.asarray(xy, dtype=float), (n, 2))
    z = np.broadcast_to(np.zeros(2), (n, 2))
    return PointPath(p, z, z)


def unit_complex(phi: np.ndarray) -> np.ndarray:
    """exp(iφ) for an array of angles.

    On a uniform grid φ_k = φ_0 + k·h (checked to a few ulps) it is built as the outer
    product exp(i(φ_0 + j·m·h))·exp(i·l·h) of two short tables, one complex product per
    angle (error ≤ 2e-15), instead of a sine and a cosine per angle.
    """
    n = len(phi)
    if n >= 4096:
        h = (phi[-1] - phi[0]) / (n - 1)
        gap = np.arange(n, dtype=float)
        gap *= h
        gap += phi[0]
        gap -= phi
        # on a uniform grid the largest |φ| is at an end; elsewhere the test fails anyway
        if np.abs(gap, out=gap).max() <= 8 * np.finfo(float).eps * (1.0 + max(abs(phi[0]), abs(phi[-1]))):
            m = int(np.sqrt(n)) + 1
            fine = np.exp(1j * h * np.arange(m))
            coarse = np.exp(1j * (phi[0] + h * m * np.arange((n + m - 1) // m)))
            return np.multiply.outer(coarse, fine).ravel()[:n]
    return np.exp(1j * phi)


class CrankPath(PointPath):
    """The pin of a crank turning about ``centre``: p' = i·(p - centre), p'' = -(p - centre).

    The analogs are derived from the positions when read; :meth:`rows` derives them
    for a block of rows without building the full arrays.
    """

    __slots__ = ("centre",)

    def __init__(self, p: np.ndarray, centre: complex):
        self.centre = centre
        z = as_complex(p)
        super().__init__(p, built_in_blocks(len(z), lambda sl: 1j * (z[sl] - centre)),
                         built_in_blocks(len(z), lambda sl: (z[sl] - centre) * -1.0))

    def rows(self, sl: slice):
        p = self.p[sl]
        x, y = p[:, 0], p[:, 1]
        rx, ry = (x - self.centre.real, y - self.centre.imag) if self.centre else (x, y)
        minus_rx, minus_ry = rx * -1.0, ry * -1.0
        return x, y, minus_ry, rx, minus_rx, minus_ry


def crank_point(radius: float, phi: np.ndarray, centre=(0.0, 0.0)) -> CrankPath:
    """The pin of a crank of given radius at angles φ about ``centre`` (built in blocks).

    Parameters
    ----------
    radius : float
        Crank radius (length).
    phi : numpy.ndarray
        Crank angles (radians), one-dimensional.
    centre : sequence of float, optional
        The crank's pivot (length).

    Returns
    -------
    CrankPath
        The pin's path (a PointPath whose analogs are i·(p − centre) and −(p − centre)).

    Examples
    --------
    >>> import numpy as np
    >>> crank_point(1.0, np.array([0.3])).p.round(4)
    array([[0.9553, 0.2955]])
    """
    c = complex(centre[0], centre[1])
    z = np.empty(len(phi), dtype=complex)

    def kernel(sl):
        np.multiply(unit_complex(phi[sl]), radius, out=z[sl])
        if c:
            z[sl] += c

    for_blocks(len(phi), kernel)
    return CrankPath(as_xy(z), c)


def relative(q: PointPath, p: PointPath) -> PointPath:
    """The vector q - p with its analogs.

    Parameters
    ----------
    q, p : PointPath
        Two moving points.

    Returns
    -------
    PointPath
        q − p, (q − p)', (q − p)''.

    Examples
    --------
    >>> import numpy as np
    >>> relative(fixed_point((4.0, 0.0), 1), fixed_point((1.0, 1.0), 1)).p
    array([[ 3., -1.]])
    """
    return PointPath(q.p - p.p, q.d - p.d, q.dd - p.dd)


def vector_angle(v: PointPath) -> AnglePath:
    """Principal angle of a moving vector v(φ) with θ' = v×v'/|v|² and its derivative.

    Parameters
    ----------
    v : PointPath
        A moving vector (non-zero).

    Returns
    -------
    AnglePath
        θ in (−π, π] (radians), θ' and θ''.

    Examples
    --------
    >>> import numpy as np
    >>> A = crank_point(1.0, np.array([0.3]))
    >>> vector_angle(A).theta.round(4), vector_angle(A).d
    (array([0.3]), array([1.]))
    """
    z, dz, ddz = as_complex(v.p), as_complex(v.d), as_complex(v.dd)
    r2 = _abs2(z)
    d = _im_conj(z, dz) / r2
    dd = _im_conj(z, ddz) / r2 - 2.0 * d * _re_conj(z, dz) / r2
    return AnglePath(np.angle(z), d, dd)


def lift(theta: np.ndarray, reference) -> np.ndarray:
    """The branch of ``theta`` (mod 2π) lying within π of ``reference``."""
    return reference + wrap(theta - reference)


def _fmt_deg(phi: float) -> str:
    return f"{np.degrees(phi):.2f}°"


def _where(phi, i) -> str:
    return f" at φ = {_fmt_deg(phi[i])}" if phi is not None else ""


def _raise_distance_error(d2, r1: float, r2: float, tol: float, phi, what: str):
    """Name the first row whose joint distance is out of reach or at a dead point."""
    lo, hi = abs(r1 - r2), r1 + r2
    out = (d2 > (hi + tol) ** 2) | (d2 < max(lo - tol, 0.0) ** 2)
    if out.any():
        i = int(np.argmax(out))
        raise AssemblyError(
            f"cannot assemble {what}{_where(phi, i)}: the joint distance is {np.sqrt(d2[i]):.6g}, outside "
            f"[|{r1:g} - {r2:g}|, {r1:g} + {r2:g}] = [{lo:.6g}, {hi:.6g}]")
    i = int(np.argmax((d2 >= (hi - tol) ** 2) | (d2 <= (lo + tol) ** 2)))
    d = np.sqrt(d2[i])
    raise SingularityError(
        f"dead point of {what}{_where(phi, i)}: the joint distance {d:.6g} equals "
        f"{'r1 + r2' if abs(d - hi) <= tol else '|r1 - r2|'}; the analogs are unbounded there")


def _circle_offset(z1, r1: float, z2, r2: float, sign: int, phi, what: str):
    """u = X - z1 for the intersection X of circle (z1, r1) with circle (z2, r2), and v = z2 - z1."""
    v = z2 - z1
    d2 = np.atleast_1d(_abs2(v))
    tol = DEAD_POINT_TOL * (r1 + r2)
    # two reductions decide the usual case: every row assembles away from a dead point
    if not (d2.min() > (abs(r1 - r2) + tol) ** 2 and d2.max() < (r1 + r2 - tol) ** 2):
        _raise_distance_error(d2, r1, r2, tol, phi, what)
    d = np.sqrt(d2)
    a = d2
    a += r1 * r1 - r2 * r2
    a /= 2.0 * d
    h = np.maximum(r1 * r1 - a * a, 0.0)
    np.sqrt(h, out=h)
    # the point a along the unit vector v/d and h to its left (sign +1) or right
    q = np.empty(len(a), dtype=complex)
    q.real, q.imag = a, h if sign > 0 else -h
    q /= d
    q *= v
    return q, v


def _circle_circle_z(z1, r1: float, z2, r2: float, sign: int, phi, what: str):
    """Complex core of :func:`circle_circle`."""
    return z1 + _circle_offset(z1, r1, z2, r2, sign, phi, what)[0]


# Rows per block of the long-array dyad solvers: a block's temporaries stay in the
# processor's cache and are recycled by the allocator, where whole-length temporaries
# would each be freshly mapped (page-faulted) memory; at 360,000 angles that is 3× faster.
BLOCK = 16384


def _threads() -> int:
    """MECHLAB_THREADS if set (e.g. 1 on a shared server), else the cores available, at most 4."""
    value = os.environ.get("MECHLAB_THREADS")
    if value is None:
        return min(len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else os.cpu_count() or 1, 4)
    if not value.strip().isdigit() or int(value) < 1:
        raise DimensionError(f"MECHLAB_THREADS must be a whole number ≥ 1, got {value!r}")
    return int(value)


# Threads sharing the blocks of one long call (numpy releases the GIL inside its loops).
THREADS = _threads()
_pool: ThreadPoolExecutor | None = None


def _forget_pool():
    global _pool
    _pool = None


if hasattr(os, "register_at_fork"):  # a forked child has none of the parent's threads
    os.register_at_fork(after_in_child=_forget_pool)


def blocks(n: int) -> list[slice]:
    """Consecutive slices of at most BLOCK rows covering range(n)."""
    return [slice(lo, min(lo + BLOCK, n)) for lo in range(0, n, BLOCK)]


def for_blocks(n: int, kernel) -> None:
    """Call ``kernel(sl)`` on every block of range(n); long inputs are split into one run
    of consecutive blocks per thread. An exception from the earliest failing block is raised."""
    global _pool
    sls = blocks(n)
    if THREADS < 2 or len(sls) < 2 * THREADS:
        for sl in sls:
            kernel(sl)
        return
    if _pool is None:
        _pool = ThreadPoolExecutor(THREADS, thread_name_prefix="mechlab")
    k = -(-len(sls) // THREADS)
    runs = [_pool.submit(lambda part: [kernel(sl) for sl in part], sls[i:i + k]) for i in range(0, len(sls), k)]
    for run in runs:
        run.result()


def circle_circle(c1: np.ndarray, r1: float, c2: np.ndarray, r2: float, sign: int,
                  phi: np.ndarray | None = None, what: str = "the dyad") -> np.ndarray:
    """Intersection of circle (c1, r1) with circle (c2, r2), vectorised over rows.

    ``sign`` = +1 returns the point on the left of the directed line c1 → c2,
    -1 the one on its right. Raises AssemblyError where the circles do not meet and
    SingularityError where they only touch (stretched or folded dyad).

    Parameters
    ----------
    c1, c2 : array_like
        The centres, (n, 2) or one point (length).
    r1, r2 : float
        The radii (length).
    sign : {1, -1}
        Which intersection.
    phi : numpy.ndarray, optional
        The crank angles of the rows, named in the error message.
    what : str, optional
        The dyad's name in the error message.

    Returns
    -------
    numpy.ndarray
        The intersections, shape (n, 2).

    Raises
    ------
    AssemblyError
        Where the circles do not meet.
    SingularityError
        Where they only touch.

    Examples
    --------
    >>> import numpy as np
    >>> circle_circle(np.array([[0.0, 0.0]]), 3.0, np.array([[4.0, 0.0]]), 3.5, 1).round(4)
    array([[1.5938, 2.5416]])
    """
    n = max(np.shape(c1)[0] if np.ndim(c1) == 2 else 1, np.shape(c2)[0] if np.ndim(c2) == 2 else 1)
    z = _circle_circle_z(as_complex(c1), r1, as_complex(c2), r2, sign, phi, what)
    return as_xy(np.broadcast_to(z, (n,)))


def dyad_rrr(A: PointPath, E: PointPath, la: float, le: float, sign: int,
             phi: np.ndarray | None = None, what: str = "the RRR dyad") -> PointPath:
    """Inner joint B of an RRR dyad: |B - A| = la, |B - E| = le.

    ``sign`` = +1 puts B on the left of the directed line A → E. With u = B - A,
    w = B - E and D = u × w (zero only at a dead point), the differentiated
    constraints u·(B' - A') = 0, w·(B' - E') = 0 solve to B' = i(b2·u - b1·w)/D with
    b1 = u·A', b2 = w·E' (complex numbers for points); B'' likewise with
    b1 = u·A'' - |B' - A'|², b2 = w·E'' - |B' - E'|².

    Parameters
    ----------
    A, E : PointPath
        The outer joints' paths.
    la, le : float
        |B − A| and |B − E| (length).
    sign : {1, -1}
        The assembly: +1 puts B on the left of A → E.
    phi : numpy.ndarray, optional
        The crank angles of the rows, named in the error message.
    what : str, optional
        The dyad's name in the error message.

    Returns
    -------
    PointPath
        B with B' and B''.

    Raises
    ------
    AssemblyError
        Where the dyad does not close.
    SingularityError
        At a dead point (stretched or folded).

    Examples
    --------
    >>> import numpy as np
    >>> A = crank_point(1.0, np.array([0.3]))
    >>> dyad_rrr(A, fixed_point((4.0, 0.0), 1), 3.0, 3.5, 1).p.round(4)
    array([[2.2222, 3.0149]])
    """
    zA, zE = as_complex(A.p), as_complex(E.p)
    B = _circle_circle_z(zA, la, zE, le, sign, phi, what)
    u, w = B - zA, B - zE
    D = _im_conj(u, w)
    dA, dE = as_complex(A.d), as_complex(E.d)
    dB = 1j * (_re_conj(w, dE) * u - _re_conj(u, dA) * w) / D
    ddA, ddE = as_complex(A.dd), as_complex(E.dd)
    c1 = _re_conj(u, ddA) - _abs2(dB - dA)
    c2 = _re_conj(w, ddE) - _abs2(dB - dE)
    ddB = 1j * (c2 * u - c1 * w) / D
    return PointPath(as_xy(B), as_xy(dB), as_xy(ddB))


def built_in_blocks(n: int, rows):
    """A function of no arguments that builds the (n, 2) array of points whose rows ``sl``
    are the complex numbers ``rows(sl)``, block by block (a lazy analog of a PointPath)."""
    def build() -> np.ndarray:
        z = np.empty(n, dtype=complex)

        def kernel(sl):
            z[sl] = rows(sl)

        for_blocks(n, kernel)
        return as_xy(z)

    return build


def rocker_dyad(A: PointPath, E, la: float, le: float, sign: int, phi: np.ndarray | None = None,
                what: str = "the RRR dyad", reference=0.0) -> tuple[PointPath, AnglePath]:
    """An RRR dyad whose outer joint E is fixed (a rocker E-B and a coupler A-B).

    Returns the path of B and the rocker's angle ψ (the branch within π of
    ``reference``, an angle or an array of angles) with its analogs. With v = E - A at
    distance d, B = A + u where u = v·(α + iβ), α = 1/2 + (la² - le²)/(2d²),
    β = ±√(la²/d² - α²); w = B - E = u - v and D = u × w = βd². B' = iwψ' gives
    ψ' = -(u·A')/D, and differentiating once more
    ψ'' = -(u·A'' - |B' - A'|² + ψ'²·(u·w))/D with u·w = la² - αd²;
    B'' = iwψ'' - wψ'². B' and B'' are built when read. Solved in blocks of rows
    (see :func:`for_blocks`) into one output buffer, in real arithmetic.
    """
    ex, ey = (float(c) for c in np.asarray(E, dtype=float))
    n = len(A.p)
    buf = np.empty(5 * n)  # B, ψ, ψ', ψ'': one allocation for all outputs
    Bxy = buf[:2 * n].reshape(n, 2)
    psi, w1, w2 = buf[2 * n:3 * n], buf[3 * n:4 * n], buf[4 * n:]
    ref = np.asarray(reference, dtype=float)
    cos_r, sin_r = np.cos(reference), np.sin(reference)
    la2, half_k, tol = la * la, 0.5 * (la * la - le * le), DEAD_POINT_TOL * (la + le)

    def kernel(sl):
        ax, ay, dax, day, ddax, dday = A.rows(sl)
        vx, vy = ex - ax, ey - ay
        d2 = vx * vx
        d2 += vy * vy
        # two reductions decide the usual case: every row assembles away from a dead point
        if not (d2.min() > (abs(la - le) + tol) ** 2 and d2.max() < (la + le - tol) ** 2):
            _raise_distance_error(d2, la, le, tol, None if phi is None else phi[sl], what)
        alpha = half_k / d2
        alpha += 0.5
        beta = la2 / d2
        beta -= alpha * alpha
        np.sqrt(np.maximum(beta, 0.0, out=beta), out=beta)
        if sign < 0:
            beta *= -1.0
        ux, uy = alpha * vx, alpha * vy
        ux -= beta * vy
        uy += beta * vx
        np.add(ax, ux, out=Bxy[sl, 0])
        np.add(ay, uy, out=Bxy[sl, 1])
        wx, wy = ux - vx, uy - vy
        D = beta * d2
        d1 = ux * dax
        d1 += uy * day
        np.divide(d1, D, out=d1)
        d1 *= -1.0
        w1[sl] = d1
        rel_x, rel_y = wy * d1, wx * d1  # B' - A' = iwψ' - A'
        rel_x += dax
        rel_y -= day
        num = rel_x * rel_x
        num += rel_y * rel_y
        num -= ux * ddax
        num -= uy * dday
        alpha *= d2
        alpha -= la2  # -(u·w)
        alpha *= d1
        alpha *= d1
        num += alpha
        np.divide(num, D, out=w2[sl])
        if ref.ndim:  # ψ on the branch of a moving reference
            np.arctan2(wy, wx, out=psi[sl])
            psi[sl] = lift(psi[sl], ref[sl])
        else:  # w turned by -reference, so that its angle lies within π of it
            rx = wx * cos_r
            rx += wy * sin_r
            wy *= cos_r
            wy -= wx * sin_r
            np.arctan2(wy, rx, out=psi[sl])
            psi[sl] += reference

    for_blocks(n, kernel)
    zB, zE = as_complex(Bxy), complex(ex, ey)
    B = PointPath(Bxy, built_in_blocks(n, lambda sl: 1j * (zB[sl] - zE) * w1[sl]),
                  built_in_blocks(n, lambda sl: (zB[sl] - zE) * (1j * w2[sl] - w1[sl] * w1[sl])))
    return B, AnglePath(psi, w1, w2)


def line_circle(p0: np.ndarray, u: np.ndarray, c: np.ndarray, r: float, sign: int,
                phi: np.ndarray | None = None, what: str = "the slider dyad") -> np.ndarray:
    """Parameter s of the points p0 + s·u (|u| = 1) at distance r from c.

    ``sign`` = +1 takes the larger root (ahead along u), -1 the smaller.

    Parameters
    ----------
    p0 : numpy.ndarray
        A point of the line (length).
    u : numpy.ndarray
        The line's unit direction.
    c : numpy.ndarray
        Circle centres, (n, 2) (length).
    r : float
        The distance (length).
    sign : {1, -1}
        Which root.
    phi : numpy.ndarray, optional
        The crank angles of the rows, named in the error message.
    what : str, optional
        The dyad's name in the error message.

    Returns
    -------
    numpy.ndarray
        s, one per row (length).

    Raises
    ------
    AssemblyError
        Where the circle misses the line.
    SingularityError
        Where it only touches it (the rod perpendicular to the guide).

    Examples
    --------
    >>> import numpy as np
    >>> line_circle(np.array([0.0, 0.0]), np.array([1.0, 0.0]), np.array([[0.0, 1.0]]), 2.0, 1).round(4)
    array([1.7321])
    """
    w = c - p0
    along = dot(w, u)
    off = cross(u, w)
    disc = r**2 - off**2
    tol = DEAD_POINT_TOL * r**2
    if np.any(disc < -tol):
        i = int(np.argmax(disc < -tol))
        at = f" at φ = {_fmt_deg(phi[i])}" if phi is not None else ""
        raise AssemblyError(
            f"cannot assemble {what}{at}: the pin is {abs(off[i]):.6g} from the guide line, "
            f"more than the rod length {r:g}")
    if np.any(np.abs(disc) <= tol):
        i = int(np.argmax(np.abs(disc) <= tol))
        at = f" at φ = {_fmt_deg(phi[i])}" if phi is not None else ""
        raise SingularityError(
            f"dead point of {what}{at}: the rod {r:g} stands perpendicular to the guide")
    return along + sign * np.sqrt(disc)


def dyad_rrp(A: PointPath, p0, direction: float, length: float, sign: int,
             phi: np.ndarray | None = None, what: str = "the RRP dyad") -> tuple[PointPath, AnglePath]:
    """Slider B on the fixed line through ``p0`` at angle ``direction``, |B - A| = length.

    Returns the path of B and its coordinate s along the line with s', s''
    (from (B - A)·(s'u - A') = 0 and its derivative).

    Parameters
    ----------
    A : PointPath
        The rod's outer joint.
    p0 : sequence of float
        A point of the guide (length).
    direction : float
        The guide's angle (radians).
    length : float
        |B − A| (length).
    sign : {1, -1}
        +1 takes the slider ahead along the guide, −1 behind.
    phi : numpy.ndarray, optional
        The crank angles of the rows, named in the error message.
    what : str, optional
        The dyad's name in the error message.

    Returns
    -------
    tuple of (PointPath, AnglePath)
        B, and s with s', s'' (length, in an AnglePath).

    Raises
    ------
    AssemblyError
        Where the rod cannot reach the guide.
    SingularityError
        Where the rod stands perpendicular to the guide.

    Examples
    --------
    >>> import numpy as np
    >>> B, s = dyad_rrp(crank_point(1.0, np.array([0.3])), (0.0, 0.0), 0.0, 3.0, 1)
    >>> s.theta.round(4)
    array([3.9407])
    """
    u1 = unit(direction)
    p0 = np.asarray(p0, dtype=float)
    s = line_circle(p0, u1, A.p, length, sign, phi, what)
    B = p0 + s[:, None] * u1
    rod = B - A.p
    ru = dot(rod, np.broadcast_to(u1, rod.shape))
    ds = dot(rod, A.d) / ru
    rel = ds[:, None] * u1 - A.d
    dds = (dot(rod, A.dd) - dot(rel, rel)) / ru
    return PointPath(B, ds[:, None] * u1, dds[:, None] * u1), AnglePath(s, ds, dds)


def dyad_rpr(A: PointPath, pivot: PointPath) -> tuple[AnglePath, AnglePath]:
    """Slotted link through ``pivot`` whose straight slot carries the pin A.

    Returns the link angle (principal value; lift it to a branch) with its analogs,
    and the pin's distance ρ = |A - pivot| along the slot with ρ' and ρ''.

    Parameters
    ----------
    A : PointPath
        The pin's path.
    pivot : PointPath
        The slotted link's pivot (a fixed point).

    Returns
    -------
    tuple of AnglePath
        The link's angle (radians) and ρ (length), each with its analogs.

    Examples
    --------
    >>> import numpy as np
    >>> angle, rho = dyad_rpr(crank_point(1.0, np.array([0.3])), fixed_point((-0.5, 0.0), 1))
    >>> angle.theta.round(4), rho.theta.round(4)
    (array([0.2003]), array([1.485]))
    """
    v = relative(A, pivot)
    rho = np.hypot(v.p[:, 0], v.p[:, 1])
    drho = dot(v.p, v.d) / rho
    ddrho = (dot(v.d, v.d) + dot(v.p, v.dd) - drho**2) / rho
    return vector_angle(v), AnglePath(rho, drho, ddrho)
