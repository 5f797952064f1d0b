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

from typing import NamedTuple

import numpy as np

from .errors import AssemblyError, DimensionError, SingularityError

# Relative tolerance under which a dyad counts as stretched or folded (a dead point).
DEAD_POINT_TOL = 1e-12


class PointPath(NamedTuple):
    """Positions ``p`` of a point and its analogs ``d`` = dp/dφ, ``dd`` = d²p/dφ²."""

    p: np.ndarray
    d: np.ndarray
    dd: np.ndarray


class AnglePath(NamedTuple):
    """An angle θ(φ) and its analogs θ' and θ''."""

    theta: np.ndarray
    d: np.ndarray
    dd: np.ndarray


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


def as_angles(phi) -> np.ndarray:
    """Crank angles as a 1-D float array; a scalar becomes an array of one."""
    arr = np.atleast_1d(np.asarray(phi, dtype=float))
    if arr.ndim != 1:
        raise DimensionError(f"crank angles must be a scalar or a 1-D array, got shape {arr.shape}")
    if not np.all(np.isfinite(arr)):
        raise DimensionError("crank angles must be finite numbers (got NaN or inf)")
    return arr


def check_length(name: str, value, *, allow_zero: bool = False) -> float:
    """Return ``value`` as a float, raising DimensionError if it is not a positive finite number."""
    try:
        x = float(value)
    except (TypeError, ValueError):
        raise DimensionError(f"{name} must be a number, got {value!r}") from None
    if not np.isfinite(x):
        raise DimensionError(f"{name} must be finite, got {x}")
    if x < 0 or (x == 0 and not allow_zero):
        bound = "≥ 0" if allow_zero else "> 0"
        raise DimensionError(f"{name} must be {bound}, got {x:g}")
    return x


def check_sign(name: str, value) -> int:
    """An assembly sign: +1 or -1."""
    if value not in (1, -1):
        raise DimensionError(f"{name} must be +1 or -1, got {value!r}")
    return int(value)


def fixed_point(xy, n: int) -> PointPath:
    """A point fixed to the frame, as a path over n crank angles."""
    p = np.broadcast_to(np.asarray(xy, dtype=float), (n, 2)).copy()
    z = np.zeros((n, 2))
    return PointPath(p, z, z.copy())


def crank_point(radius: float, phi: np.ndarray, centre=(0.0, 0.0)) -> PointPath:
    """The pin of a crank of given radius at angles φ about ``centre``."""
    u = unit(phi)
    return PointPath(np.asarray(centre, dtype=float) + radius * u, radius * perp(u), -radius * u)


def relative(q: PointPath, p: PointPath) -> PointPath:
    """The vector q - p with its analogs."""
    return PointPath(q.p - p.p, q.d - p.d, q.dd - p.dd)


def vector_angle(v: PointPath) -> AnglePath:
    """Principal angle of a moving vector v(φ) with θ' = v×v'/|v|² and its derivative."""
    r2 = dot(v.p, v.p)
    c1 = cross(v.p, v.d)
    d = c1 / r2
    dd = cross(v.p, v.dd) / r2 - 2.0 * c1 * dot(v.p, v.d) / r2**2
    return AnglePath(np.arctan2(v.p[:, 1], v.p[:, 0]), d, dd)


def lift(theta: np.ndarray, reference) -> np.ndarray:
    """The branch of ``theta`` (mod 2π) lying within π of ``reference``."""
    return reference + wrap(theta - reference)


def _fmt_deg(phi: float) -> str:
    return f"{np.degrees(phi):.2f}°"


def circle_circle(c1: np.ndarray, r1: float, c2: np.ndarray, r2: float, sign: int,
                  phi: np.ndarray | None = None, what: str = "the dyad") -> np.ndarray:
    """Intersection of circle (c1, r1) with circle (c2, r2), vectorised.

    ``sign`` = +1 returns the point on the left of the directed line c1 → c2,
    -1 the one on its right. Raises AssemblyError where the circles do not meet and
    SingularityError where they only touch (stretched or folded dyad).
    """
    v = c2 - c1
    d = np.hypot(v[:, 0], v[:, 1])
    lo, hi = abs(r1 - r2), r1 + r2
    tol = DEAD_POINT_TOL * hi
    bad = (d > hi + tol) | (d < lo - tol)
    if np.any(bad):
        i = int(np.argmax(bad))
        at = f" at φ = {_fmt_deg(phi[i])}" if phi is not None else ""
        raise AssemblyError(
            f"cannot assemble {what}{at}: the joint distance is {d[i]:.6g}, outside "
            f"[|{r1:g} - {r2:g}|, {r1:g} + {r2:g}] = [{lo:.6g}, {hi:.6g}]")
    touch = (np.abs(d - hi) <= tol) | (np.abs(d - lo) <= tol)
    if np.any(touch):
        i = int(np.argmax(touch))
        at = f" at φ = {_fmt_deg(phi[i])}" if phi is not None else ""
        raise SingularityError(
            f"dead point of {what}{at}: the joint distance {d[i]:.6g} equals "
            f"{'r1 + r2' if abs(d[i] - hi) <= tol else '|r1 - r2|'}; the analogs are unbounded there")
    u = v / d[:, None]
    a = (r1**2 - r2**2 + d**2) / (2.0 * d)
    h = np.sqrt(np.maximum(r1**2 - a**2, 0.0))
    return c1 + a[:, None] * u + (sign * h)[:, None] * perp(u)


def _solve2(m11, m12, m21, m22, b1, b2):
    det = m11 * m22 - m12 * m21
    return np.stack([(b1 * m22 - m12 * b2) / det, (m11 * b2 - m21 * b1) / det], axis=-1)


def dyad_rrr(A: PointPath, E: PointPath, la: float, le: float, sign: int,
             phi: np.ndarray | None = None, what: str = "the RRR dyad") -> PointPath:
    """Inner joint B of an RRR dyad: |B - A| = la, |B - E| = le.

    ``sign`` = +1 puts B on the left of the directed line A → E. Positions from
    :func:`circle_circle`; analogs from the differentiated distance constraints.
    """
    B = circle_circle(A.p, la, E.p, le, sign, phi, what)
    u, w = B - A.p, B - E.p
    dB = _solve2(u[:, 0], u[:, 1], w[:, 0], w[:, 1], dot(u, A.d), dot(w, E.d))
    ua, we = dB - A.d, dB - E.d
    ddB = _solve2(u[:, 0], u[:, 1], w[:, 0], w[:, 1],
                  dot(u, A.dd) - dot(ua, ua), dot(w, E.dd) - dot(we, we))
    return PointPath(B, dB, ddB)


def line_circle(p0: np.ndarray, u: np.ndarray, c: np.ndarray, r: float, sign: int,
                phi: np.ndarray | None = None, what: str = "the slider dyad") -> np.ndarray:
    """Parameter s of the points p0 + s·u (|u| = 1) at distance r from c.

    ``sign`` = +1 takes the larger root (ahead along u), -1 the smaller.
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
    """
    v = relative(A, pivot)
    rho = np.hypot(v.p[:, 0], v.p[:, 1])
    drho = dot(v.p, v.d) / rho
    ddrho = (dot(v.d, v.d) + dot(v.p, v.dd) - drho**2) / rho
    return vector_angle(v), AnglePath(rho, drho, ddrho)
