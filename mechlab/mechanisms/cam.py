"""Disc cams with a roller follower, translating (with offset) or oscillating.

The cam turns counter-clockwise about O = (0, 0) by φ; profiles are in the cam's frame (the fixed
frame at φ = 0). The law is a :class:`~mechlab.synthesis.cam_design.CamProgramme` (rise, dwell,
return, dwell with the laws of :mod:`mechlab.analysis.motion_laws`).

* :class:`TranslatingRollerCam`: roller centre C = (e, s0 + s) on x = e, s0 = √((r_b + r_r)² − e²).
* :class:`OscillatingRollerCam`: arm B→C of length L about B = (d, 0), ψ = ψ0 + y.

Pitch curve P(θ) = Rot(−θ)·C(θ), pressure angle tan α = (s′ − e)/(s + s0) (translating), profile
the inner offset of the pitch curve by r_r, undercut where its convex radius of curvature ≤ r_r
(derived in the book's cam chapter). :meth:`RollerCam.motion` does not read the law back: it
places the roller tangent to the splined profile by Newton's method, as a cam cut from the
exported profile would move.
"""

from __future__ import annotations

import itertools
import warnings
from dataclasses import dataclass, replace
from functools import cached_property

import numpy as np
from scipy.interpolate import PPoly, make_interp_spline
from scipy.optimize import brentq

from ..errors import CamUndercutError, DimensionError, MechanismError, SingularityError
from ..geometry import AnglePath, PointPath, as_angles, check_length, check_number, cross, dot, fixed_point, perp
from ..motion import AngularMotion, LinearMotion, scalar_law
from ..validate import check_value, count
from .base import FRAME, TWO_PI, Link, Mechanism, Pair, Part, Sketch, Structure, bars

__all__ = [
    "CamAngularMotion",
    "CamLinearMotion",
    "CamPeak",
    "CamProfile",
    "CamUndercutError",
    "OscillatingRollerCam",
    "TranslatingRollerCam",
    "Undercut",
]

# Newton on the contact stops when the step in the profile parameter is below this (radians)
_NEWTON_TOL = 1e-11
# accepted mismatch of the roller's centre where two phases' spline pieces meet, relative to the prime
# radius (the pieces share the tangent there: Newton may only step back and forth by rounding)
_GAP_TOL = 1e-9
# grid per moving phase on which the exact peaks' rates are bracketed before Brent's method
_PEAK_GRID = 257
# bracketing the contact holds at most this many (angle × profile node) residuals at once
_CHUNK = 1 << 20


@dataclass(frozen=True)
class CamProfile:
    """The cam sampled at design angles ``theta`` (radians), in the cam frame (lengths as the cam's).

    ``pitch``: the roller centre's path; ``surface``: the profile (its inner offset by the roller
    radius); ``normal``: outward unit normals; ``curvature``: the pitch curve's, convex > 0;
    ``pressure_angle``: signed α (radians).
    """

    theta: np.ndarray
    pitch: np.ndarray
    surface: np.ndarray
    normal: np.ndarray
    curvature: np.ndarray
    pressure_angle: np.ndarray
    roller_radius: float

    @property
    def surface_radius_of_curvature(self) -> np.ndarray:
        """The profile's radius of curvature: 1/κ − r_r (convex > 0; negative where undercut)."""
        with np.errstate(divide="ignore"):
            return 1.0 / self.curvature - self.roller_radius


@dataclass(frozen=True)
class CamPeak:
    """An extreme of a cam over its turn: ``what`` it is, its ``value`` and the cam angle ``phi`` (radians)."""

    what: str
    value: float
    phi: float

    def __str__(self) -> str:
        value = f"{np.degrees(self.value):.4g}°" if self.what == "pressure angle" else f"{self.value:.6g}"
        return f"{self.what} {value} at φ = {np.degrees(self.phi):.3f}°"


@dataclass(frozen=True, eq=False)
class CamLinearMotion(LinearMotion):
    """A translating follower's motion, with ``jerk``: the third analog s‴ of the design law
    (length/rad³; the jerk is s‴·ω³ at constant cam speed ω)."""

    jerk: np.ndarray


@dataclass(frozen=True, eq=False)
class CamAngularMotion(AngularMotion):
    """An oscillating follower's motion, with ``jerk``: the third analog ψ‴ of the design law
    (1/rad²; the angular jerk is ψ‴·ω³ at constant cam speed ω)."""

    jerk: np.ndarray


@dataclass(frozen=True, eq=False)
class Undercut:
    """Where the pitch curve is too sharp for the roller: the smallest convex radius of curvature
    ``radius`` at cam angle ``phi`` (radians), the (start, end) cam angles ``spans`` of each stretch
    with ρ ≤ r_r, and cam angles ``where`` inside them."""

    radius: float
    phi: float
    where: np.ndarray
    spans: np.ndarray

    def __str__(self) -> str:
        lo, hi = np.degrees(self.where.min()), np.degrees(self.where.max())
        return (f"the pitch curve's radius of curvature falls to {self.radius:.4g} at φ = "
                f"{np.degrees(self.phi):.2f}° (≤ roller radius over φ ∈ [{lo:.1f}°, {hi:.1f}°])")


class RollerCam(Mechanism):
    """A disc cam turning about O with a roller follower; subclasses give the follower's track.

    The follower coordinate q (s or ψ) puts the roller centre at ``_centre(q)``; the design law
    is q = q0 + y(φ). ``samples`` is the number of profile nodes per turn that the motion's
    spline goes through.
    """

    rollers = 1   # the follower's roller

    pivots = ("O",)

    # -- the follower (subclasses) ------------------------------------------------------------
    def _centre(self, q):  # pragma: no cover - abstract
        """Roller centre C(q), C_q, C_qq (each (n, 2)) in the fixed frame."""
        raise NotImplementedError

    def _centre_qqq(self, q, Cq):  # pragma: no cover - abstract
        """C_qqq (n, 2), given C_q."""
        raise NotImplementedError

    def _q_at(self, X):  # pragma: no cover - abstract
        """The follower coordinate that puts the roller centre at points X on its track."""
        raise NotImplementedError

    def _follower(self):  # pragma: no cover - abstract
        """The follower as a link, and its pair with the frame."""
        raise NotImplementedError

    def _track(self, x, y):  # pragma: no cover - abstract
        """At points (x, y): a residual zero on the follower's track, and a preference (the largest
        crossing is the working contact)."""
        raise NotImplementedError

    @property
    def q0(self) -> float:  # pragma: no cover - abstract
        raise NotImplementedError

    @property
    def prime_radius(self) -> float:
        """r_b + r_r: the pitch curve's radius in the inner dwell."""
        return self.base_radius + self.roller_radius

    # -- design from the law ------------------------------------------------------------------
    def follower(self, phi) -> AnglePath:
        """The design law of the follower coordinate: q0 + y(φ), y′, y″."""
        y = self.programme(phi)
        return AnglePath(self.q0 + y.theta, y.d, y.dd)

    def _design(self, phi):
        """C, its φ-derivative C′ and C″ in the fixed frame, and the follower's direction C_q."""
        q = self.follower(phi)
        C, Cq, Cqq = self._centre(q.theta)
        d1 = Cq * q.d[:, None]
        d2 = Cqq * (q.d**2)[:, None] + Cq * q.dd[:, None]
        return C, d1, d2, Cq

    @scalar_law
    def pitch(self, phi) -> PointPath:
        """The pitch curve P(θ) = Rot(−θ)·C(θ) in the cam frame, with P′ and P″."""
        theta = as_angles(phi)
        C, d1, d2, _ = self._design(theta)
        # d/dθ Rot(−θ)v = Rot(−θ)(−perp v): relative velocity and acceleration of C on the cam
        v1 = d1 - perp(C)
        v2 = d2 - 2 * perp(d1) - C
        return PointPath(_rotate(C, -theta), _rotate(v1, -theta), _rotate(v2, -theta))

    @scalar_law
    def curvature(self, phi) -> np.ndarray:
        """Curvature of the pitch curve (1/length), positive where convex (the curve runs clockwise)."""
        P = self.pitch(phi)
        return -cross(P.d, P.dd) / np.hypot(*P.d.T) ** 3

    @scalar_law
    def pressure_angle(self, phi) -> np.ndarray:
        """Signed pressure angle α (radians) between the contact normal and the follower's motion."""
        theta = as_angles(phi)
        C, d1, _, Cq = self._design(theta)
        return _pressure(d1 - perp(C), Cq)

    def profile(self, n: int = 721, check: bool = True) -> CamProfile:
        """The cam at n design angles over one turn; CamUndercutError if undercut (unless check=False)."""
        if check:
            self.check_undercut()
        theta = np.linspace(0.0, TWO_PI, int(n))
        P = self.pitch(theta)
        normal = _outward(P.d)
        return CamProfile(theta, P.p, P.p - self.roller_radius * normal, normal, self.curvature(theta),
                          self.pressure_angle(theta), self.roller_radius)

    def undercut(self, n: int | None = None) -> Undercut | None:
        """The undercut flag: None if the roller fits the pitch curve everywhere, else where it does not.

        Exact: the pitch curve's largest convex curvature κmax (:meth:`min_radius_of_curvature`) against
        1/r_r, and the stretches where κ ≥ 1/r_r with their ends found by bisection between the curvature's
        extremes (where it is monotone); not a test on samples.

        Parameters
        ----------
        n : int, optional
            Deprecated and unused (the number of samples of the former test); it goes in the next release.

        Returns
        -------
        Undercut or None
            ``radius``: ρmin of the pitch curve, ``phi``: its cam angle, ``spans``: the (start, end) cam
            angles of each undercut stretch, ``where``: cam angles inside them.

        Examples
        --------
        >>> from mechlab.synthesis.cam_design import CamProgramme
        >>> pr = CamProgramme(30.0, np.radians(40), np.radians(40), law="cycloidal (sine)")
        >>> TranslatingRollerCam(pr, 25.0, 1.0).undercut() is None
        True
        >>> TranslatingRollerCam(pr, 15.0, 10.0).undercut().spans.shape  # one stretch on the rise, one on the return
        (2, 2)
        """
        if n is not None:
            warnings.warn("undercut(n): the test is exact now and takes no samples; n is ignored and goes in "
                          "the next release", DeprecationWarning, stacklevel=2)
        r = self.roller_radius
        value_and_rate = self._curvature_and_rate if self._has_jerk else self._curvature_and_difference
        points = self._critical(value_and_rate)
        t = np.concatenate(points)
        k = value_and_rate(t)[0]
        i = int(np.argmax(k))
        if k[i] * r < 1.0:
            return None
        spans = []
        for phase in points:
            inside = self.curvature(phase) * r >= 1.0
            for j in range(len(phase) - 1):  # κ is monotone from one critical angle to the next
                lo, hi = phase[j], phase[j + 1]
                if inside[j] and inside[j + 1]:
                    piece = (lo, hi)
                elif inside[j] or inside[j + 1]:
                    edge = self._undercut_edge(hi if inside[j + 1] else lo, lo if inside[j + 1] else hi)
                    piece = (edge, hi) if inside[j + 1] else (lo, edge)
                else:
                    continue
                if spans and piece[0] - spans[-1][1] <= 1e-12:  # the same stretch across a phase's end
                    spans[-1] = (spans[-1][0], piece[1])
                else:
                    spans.append(piece)
        spans = np.array(spans)
        where = np.concatenate([np.linspace(a, e, 33) for a, e in spans])
        return Undercut(float(1.0 / k[i]), float(t[i]), where, spans)

    @property
    def _has_jerk(self) -> bool:
        return self.programme.law.dddy is not None and self.programme.return_law.dddy is not None

    def _curvature_and_difference(self, theta):
        """κ and a central difference of it, for a law without a jerk analog."""
        h = 1e-7
        return self.curvature(theta), (self.curvature(theta + h) - self.curvature(theta - h)) / (2 * h)

    def _undercut_edge(self, inside: float, outside: float) -> float:
        """Where κ·r_r crosses 1 between ``inside`` (≥ 1) and ``outside`` (< 1), κ monotone between: the
        bisection's last angle on the undercut side."""
        r = self.roller_radius
        while abs(outside - inside) > 1e-13:
            mid = 0.5 * (inside + outside)
            if self.curvature(np.array([mid]))[0] * r >= 1.0:
                inside = mid
            else:
                outside = mid
        return inside

    def check_undercut(self) -> None:
        """Raise CamUndercutError naming the cam angle if the profile would be undercut."""
        cut = self.undercut()
        if cut is not None:
            raise CamUndercutError(
                f"roller radius {self.roller_radius:g} is too large: {cut}; the profile would be undercut — "
                f"increase the base radius (now {self.base_radius:g}) or use a smaller roller")

    def in_dwell(self, phi) -> np.ndarray:
        return self.programme.in_dwell(phi)

    def sketch(self, motion) -> Sketch:
        """The cam (its profile and base circle, sampled once in the cam frame and turned by φ), the roller,
        the common normal at the contact (the line of the force without friction), the follower's arm as a
        bar, and "dwell" while the follower stands still."""
        profile, base = self.profile(240, check=False).surface, self.base_radius * _CIRCLE
        phi, r, reach = motion.phi, self.roller_radius, 0.6 * self.prime_radius
        C, K = motion.points["C"].p, motion.points["K"].p
        dwell = self.in_dwell(phi)

        def normal(i):
            n = C[i] - K[i] if r > 0 else np.zeros(2)
            n = n / (np.hypot(*n) or 1.0)
            return np.array([K[i] - reach * n, K[i] + reach * n])

        # the course's link numbers: the driving cam 1 (its number on the disc, turning with it), the follower next,
        # the frame last
        mark = 0.55 * self.base_radius * np.array([[np.cos(-3 * np.pi / 4), np.sin(-3 * np.pi / 4)]])
        number = (Part("anchor", lambda i: _turned(mark, phi[i]), "cam"),)
        parts = (Part("fill", lambda i: _turned(profile, phi[i])), Part("profile", lambda i: _turned(profile, phi[i])),
                 Part("base circle", lambda i: _turned(base, phi[i])), Part("roller", lambda i: C[i] + r * _CIRCLE),
                 Part("normal", normal), Part("note", lambda i: "dwell" if dwell[i] else ""))
        return Sketch(number + bars(self.structure()) + parts, self.pivots)

    def structure(self) -> Structure:
        """The cam turns about O and drives the follower through the roller's contact K, a higher pair
        along the common normal (the roller turns freely on the follower: part of it); one group, the
        follower, joined to the frame by its guide or its pivot B."""
        follower, support = self._follower()
        return Structure((Link("cam", "O", _cam_axis), follower),
                         (Pair("revolute", "O", FRAME, "cam", "O"),
                          Pair("higher", "contact", "cam", "follower", "K", normal=contact_normal), support),
                         (("follower",),), "follower", scale=self._reach)

    # -- exact peaks ----------------------------------------------------------------------------
    def _pressure_and_rate(self, theta):
        """α and dα/dφ at cam angles θ in closed form: α = π/2 − (angle of the follower's direction w −
        angle of the roller centre's path on the cam τ), so α′ = (τ × τ′)/|τ|² − (w × w′)/|w|²."""
        q = self.follower(theta)
        C, Cq, Cqq = self._centre(q.theta)
        d1 = Cq * q.d[:, None]
        d2 = Cqq * (q.d**2)[:, None] + Cq * q.dd[:, None]
        tau, tau1, w1 = d1 - perp(C), d2 - perp(d1), Cqq * q.d[:, None]
        rate = cross(tau, tau1) / dot(tau, tau) - cross(Cq, w1) / dot(Cq, Cq)
        return _pressure(tau, Cq), rate

    def _curvature_and_rate(self, theta):
        """κ of the pitch curve and dκ/dφ in closed form, from P⁽ᵏ⁾ = Rot(−θ)·Vₖ, V₀ = C, Vₖ₊₁ = Vₖ′ − perp(Vₖ):
        κ = −(V₁ × V₂)/|V₁|³ and κ′ = −(V₁ × V₃)/|V₁|³ + 3(V₁ × V₂)(V₁·V₂)/|V₁|⁵ (needs the law's jerk)."""
        q, j = self.follower(theta), self.programme.jerk(theta)
        C, Cq, Cqq = self._centre(q.theta)
        d, dd = q.d[:, None], q.dd[:, None]
        C1, C2 = Cq * d, Cqq * d**2 + Cq * dd
        C3 = self._centre_qqq(q.theta, Cq) * d**3 + 3 * Cqq * d * dd + Cq * j[:, None]
        V1, V2 = C1 - perp(C), C2 - 2 * perp(C1) - C
        V3 = C3 - 3 * perp(C2) - 3 * C1 + perp(C)
        m = np.hypot(*V1.T)
        k = -cross(V1, V2) / m**3
        return k, -cross(V1, V3) / m**3 + 3 * cross(V1, V2) * dot(V1, V2) / m**5

    def _critical(self, value_and_rate) -> list[np.ndarray]:
        """Per phase, the cam angles where a value can be extreme: the phase's ends (where y″ may jump)
        and the roots of its closed-form rate, bracketed on a grid of each moving phase and found by
        Brent's method; a dwell's value is constant. Between neighbours the value is monotone."""
        points = []
        for a, e in _phases(self.programme):
            ends = np.array([a, np.nextafter(e, a)])
            roots = []
            if not self.in_dwell(np.array([(a + e) / 2]))[0]:
                grid = np.linspace(a, ends[1], _PEAK_GRID)
                rate = value_and_rate(grid)[1]
                flips = np.flatnonzero(np.sign(rate[:-1]) * np.sign(rate[1:]) < 0)
                roots = [brentq(lambda t: value_and_rate(np.array([t]))[1][0], grid[i], grid[i + 1], xtol=1e-14)
                         for i in flips]
            points.append(np.sort(np.concatenate([ends, roots])))
        return points

    def _peak(self, value_and_rate, size) -> tuple[float, float]:
        """The largest ``size(value)`` over the turn and its cam angle, among :meth:`_critical`'s angles."""
        t = np.concatenate(self._critical(value_and_rate))
        v = size(value_and_rate(t)[0])
        i = int(np.argmax(v))
        return float(v[i]), float(t[i])

    def max_pressure_angle(self) -> CamPeak:
        """The largest |pressure angle| of the design over the turn and the cam angle where it occurs.

        Exact: at a root of dα/dφ (closed form) bracketed on each rise and return and found by Brent's
        method, or at a phase's end; not a maximum over samples.

        Returns
        -------
        CamPeak
            ``value``: |α|max (radians), ``phi``: the cam angle (radians).

        Examples
        --------
        >>> from mechlab.synthesis.cam_design import CamProgramme
        >>> cam = TranslatingRollerCam(CamProgramme(20.0, np.pi / 2, np.pi / 2), 40.0, 10.0)
        >>> peak = cam.max_pressure_angle()
        >>> round(float(np.degrees(peak.value)), 3) == round(float(np.degrees(abs(cam.pressure_angle(peak.phi)))), 3)
        True
        """
        value, phi = self._peak(self._pressure_and_rate, np.abs)
        return CamPeak("pressure angle", value, phi)

    def min_radius_of_curvature(self) -> CamPeak:
        """The smallest convex radius of curvature of the pitch curve (1/κmax, lengths as the cam's) and the
        cam angle where it occurs; the profile's is this minus the roller radius (undercut if ≤ 0).

        Exact: at a root of dκ/dφ, in closed form from the law's jerk, bracketed on each rise and return
        and found by Brent's method, or at a phase's end (κ jumps where y″ does).

        Returns
        -------
        CamPeak
            ``value``: ρmin of the pitch curve, ``phi``: the cam angle (radians).

        Raises
        ------
        MechanismError
            The law gives no jerk analog (a RiseLaw without ``dddy``).

        Examples
        --------
        >>> from mechlab.synthesis.cam_design import CamProgramme
        >>> cam = TranslatingRollerCam(CamProgramme(20.0, np.pi / 2, np.pi / 2), 40.0, 10.0)
        >>> cam.min_radius_of_curvature().value < cam.prime_radius
        True
        """
        kappa, phi = self._peak(self._curvature_and_rate, lambda k: k)
        return CamPeak("radius of curvature", 1.0 / kappa, phi)

    # -- motion through the profile -----------------------------------------------------------
    def _design_surface(self, u) -> np.ndarray:
        P = self.pitch(u)
        return P.p - self.roller_radius * _outward(P.d)

    def _end_slopes(self, end: float, into: float, length: float):
        """Q_u and Q_uu of the designed profile at a phase's end, from inside the phase (one-sided
        differences of 4th order, as the law's y″ may jump there); Q_u along the pitch curve's tangent,
        which is continuous: the pieces then meet with one tangent, and the roller's centre with them."""
        h = min(2e-3, length / 10)   # rounding grows like 1/h², the truncation like h⁴: 2e-3 rad balances them
        Q = self._design_surface(end + into * h * np.arange(6))
        d1 = into * (-25 * Q[0] + 48 * Q[1] - 36 * Q[2] + 16 * Q[3] - 3 * Q[4]) / (12 * h)
        d2 = (45 * Q[0] - 154 * Q[1] + 214 * Q[2] - 156 * Q[3] + 61 * Q[4] - 10 * Q[5]) / (12 * h * h)
        t = self.pitch([end]).d[0]
        t = t / np.hypot(*t)
        return np.dot(d1, t) * t, d2

    @cached_property
    def _surface(self) -> PPoly:
        """A quintic spline through the profile's nodes, one piece per phase (the law's derivatives jump
        where they meet), periodic in its parameter u ∈ [0, 2π)."""
        self.check_undercut()
        spline = None
        for a, b in _phases(self.programme):
            u = np.linspace(a, b, max(8, int(np.ceil(self.samples * (b - a) / TWO_PI)) + 1))
            x, c = _pieces(u, self._design_surface(u), self._end_slopes(a, 1.0, b - a),
                           self._end_slopes(b, -1.0, b - a))
            if spline is None:
                spline = PPoly(c, x, extrapolate="periodic")
            else:
                spline.extend(c, x[1:])
        return spline

    def _pitch_of_surface(self, u):
        """The roller centre tangent to the profile at parameter u: P = Q + r_r·N (N its outward
        normal), with P_u, P_uu; also Q, Q_u, Q_uu."""
        s = self._surface
        Q, Qu, Quu, Quuu = (s(u, k) for k in range(4))
        m2 = dot(Qu, Qu)
        T = Qu / np.sqrt(m2)[:, None]
        N = perp(T)
        w = cross(Qu, Quu) / m2                      # turning rate of the tangent, dθ_T/du
        w_u = cross(Qu, Quuu) / m2 - 2 * cross(Qu, Quu) * dot(Qu, Quu) / m2**2
        r = self.roller_radius
        P = Q + r * N
        Pu = Qu - r * w[:, None] * T
        Puu = Quu - r * (w_u[:, None] * T + (w**2)[:, None] * N)
        return P, Pu, Puu, Q, Qu, Quu

    def _bracket(self, phi):
        """For each φ, a profile parameter next to the working contact: the track's residual changes
        sign between two neighbouring nodes (every half degree); the preferred crossing wins."""
        u = np.linspace(0.0, TWO_PI, 721)[:-1]
        P = self._pitch_of_surface(u)[0]
        m = len(u)
        out = np.empty(len(phi))
        step = max(1, _CHUNK // m)
        for lo in range(0, len(phi), step):
            c, s = np.cos(phi[lo:lo + step, None]), np.sin(phi[lo:lo + step, None])
            h, pref = self._track(c * P[:, 0] - s * P[:, 1], s * P[:, 0] + c * P[:, 1])
            h1 = np.roll(h, -1, axis=1)
            crossing = (h <= 0) != (h1 <= 0)
            if not np.all(crossing.any(axis=1)):
                i = lo + int(np.argmin(crossing.any(axis=1)))
                raise MechanismError(f"the roller's track misses the pitch curve at φ = {np.degrees(phi[i]):.2f}°")
            k = np.argmax(np.where(crossing, pref, -np.inf), axis=1)
            rows = np.arange(len(k))
            f0, f1 = h[rows, k], h1[rows, k]
            out[lo:lo + step] = u[k] + (TWO_PI / m) * f0 / (f0 - f1)
        return out

    def _contact(self, phi):
        """Solve Rot(φ)·P(u) = C(q) for (u, q) by Newton's method, and the analogs u′, q′, u″, q″."""
        u = self._bracket(phi)
        c, s = np.cos(phi), np.sin(phi)

        def rot(v):
            return np.stack([c * v[:, 0] - s * v[:, 1], s * v[:, 0] + c * v[:, 1]], axis=-1)

        q = self._q_at(rot(self._pitch_of_surface(u)[0]))
        for _ in range(30):
            P, Pu = self._pitch_of_surface(u)[:2]
            C, Cq, _ = self._centre(q)
            G, a, b = rot(P) - C, rot(Pu), -Cq
            det = cross(a, b)
            du, dq = -cross(G, b) / det, -cross(a, G) / det
            u, q = u + du, q + dq
            if np.max(np.abs(du)) < _NEWTON_TOL:
                break
        else:
            # a root on the joint of two phases' pieces: Newton may step back and forth across it
            gap = np.max(np.hypot(*G.T))
            if gap > _GAP_TOL * self.prime_radius:
                raise SingularityError(f"the roller's contact did not converge: gap {gap:.2g} at the profile's "
                                       f"joints; use more samples (now {self.samples})")
        P, Pu, Puu, Q, Qu, Quu = self._pitch_of_surface(u)
        C, Cq, Cqq = self._centre(q)
        a, b = rot(Pu), -Cq
        det = cross(a, b)
        if np.any(np.abs(det) <= 1e-12 * np.hypot(*a.T) * np.hypot(*b.T)):
            i = int(np.argmin(np.abs(det)))
            raise SingularityError(f"pressure angle 90° at φ = {np.degrees(phi[i]):.2f}°: the follower is jammed")

        def solve(rhs):
            return cross(rhs, b) / det, cross(a, rhs) / det

        u1, q1 = solve(-perp(rot(P)))
        u2, q2 = solve(rot(P) - 2 * perp(rot(Pu)) * u1[:, None] - rot(Puu) * (u1**2)[:, None]
                       + Cqq * (q1**2)[:, None])
        K = PointPath(rot(Q), rot(perp(Q) + Qu * u1[:, None]),
                      rot(-Q + 2 * perp(Qu) * u1[:, None] + Quu * (u1**2)[:, None] + Qu * u2[:, None]))
        Cpath = PointPath(C, Cq * q1[:, None], Cqq * (q1**2)[:, None] + Cq * q2[:, None])
        alpha = _pressure(a * u1[:, None], Cq)
        return AnglePath(q, q1, q2), Cpath, K, alpha

    def motion(self, phi):
        """Paths of O, the roller centre C and the contact K, and the follower's law, at cam angles φ
        (radians), solved from the splined profile, with the design law's jerk analog (``jerk``: the
        profile is cut to it; closed form). CamUndercutError if the profile is undercut."""
        phi = as_angles(phi)
        q, C, K, alpha = self._contact(phi)
        points = {"O": fixed_point((0.0, 0.0), len(phi)), "C": C, "K": K, **self._fixed_points(len(phi))}
        kind = CamLinearMotion if self.output == "position" else CamAngularMotion
        return kind(phi, points, np.pi / 2 - np.abs(alpha), q.theta, q.d, q.dd, self.programme.jerk(phi))

    def _fixed_points(self, n: int) -> dict:
        return {}


def _phases(programme):
    """The programme's phases as (start, end), each transition cut at its middle and at its laws' knots
    too (where the law changes its formula); empty phases left out."""
    b = programme.breaks
    inner = [b[0] + k * (b[1] - b[0]) for k in (0.5, *programme.law.knots)] + \
            [b[2] + k * (b[3] - b[2]) for k in (0.5, *programme.return_law.knots)]
    cuts = sorted({*b, *inner})
    return [(a, e) for a, e in itertools.pairwise(cuts) if e - a > 1e-12]


def _pieces(u, Q, start, end):
    """Breakpoints and coefficients (k + 1, m, 2) of the quintic spline through the points Q at u with
    the first and second derivatives ``start`` and ``end`` at its ends, as polynomial pieces without
    the empty end intervals."""
    pps = [PPoly.from_spline(make_interp_spline(u, Q[:, j], k=5, bc_type=([(1, start[0][j]), (2, start[1][j])],
                                                                         [(1, end[0][j]), (2, end[1][j])])))
           for j in (0, 1)]
    keep = np.diff(pps[0].x) > 0
    x = pps[0].x
    return np.append(x[:-1][keep], x[1:][keep][-1]), np.stack([pp.c[:, keep] for pp in pps], axis=-1)


def _cam_axis(motion):
    """The cam's angle is the input φ itself."""
    n = len(motion.phi)
    return motion.phi, np.ones(n), np.zeros(n)


def contact_normal(motion) -> np.ndarray:
    """Unit normals (n, 2) of the pitch curve at the roller's centre C, outward from the cam: the
    normal to C's velocity relative to the cam, C′ − perp(C) (per unit cam speed)."""
    C = motion.points["C"]
    return _outward(C.d - perp(C.p))


def _outward(tangent) -> np.ndarray:
    """Unit normals turned +90° from the pitch curve's tangents: outward, as the curve runs clockwise
    on the cam (the cam turns counter-clockwise)."""
    return perp(tangent) / np.hypot(*tangent.T)[:, None]


def _rotate(v, angle):
    c, s = np.cos(angle), np.sin(angle)
    return np.stack([c * v[:, 0] - s * v[:, 1], s * v[:, 0] + c * v[:, 1]], axis=-1)


def _pressure(tangent, direction) -> np.ndarray:
    """Signed angle between the normal to ``tangent`` (the roller centre's path on the cam) and the
    follower's ``direction`` of motion: α = atan2(w·τ, τ × w)."""
    return np.arctan2(dot(direction, tangent), cross(tangent, direction))


@dataclass(frozen=True)
class TranslatingRollerCam(RollerCam):
    """Disc cam with a translating roller follower on the line x = ``offset`` (e), lifting along +y.

    The roller centre is C = (e, s0 + s), s0 = √((r_b + r_r)² − e²).

    Parameters
    ----------
    programme : CamProgramme
        The follower's programme (:class:`~mechlab.synthesis.cam_design.CamProgramme`);
        ``programme.stroke`` is the lift h (length).
    base_radius : float
        r_b, the base circle's radius (mm, or dimensionless with one unit for all).
    roller_radius : float
        r_r, the roller's radius (length).
    offset : float, optional
        e, the follower line's distance from O (length).
    samples : int, optional
        Profile nodes per turn that the motion's spline goes through.

    Raises
    ------
    DimensionError
        For a bad dimension, e.g. |e| ≥ r_b + r_r (the follower's line misses the prime circle).

    Examples
    --------
    >>> import numpy as np
    >>> from mechlab import CamProgramme, TranslatingRollerCam
    >>> cam = TranslatingRollerCam(CamProgramme(30.0, np.radians(40), np.radians(40)), 40.0, 10.0, offset=5.0)
    >>> round(cam.s0, 4), round(float(cam.motion(1.0).s), 4)
    (49.7494, 18.9959)
    """

    programme: object
    base_radius: float
    roller_radius: float
    offset: float = 0.0
    samples: int = 2880

    output = "position"

    def __post_init__(self):
        _check_common(self)
        object.__setattr__(self, "offset", check_number("offset", self.offset))
        if abs(self.offset) >= self.prime_radius:
            raise DimensionError(f"offset |e| = {abs(self.offset):g} must be < base radius + roller radius = "
                                 f"{self.prime_radius:g}: the follower's line misses the prime circle")

    @property
    def s0(self) -> float:
        """Height of the roller centre above O in the inner dwell: √((r_b + r_r)² − e²).

        Returns
        -------
        float
            s0 (length).
        """
        return float(np.sqrt(self.prime_radius**2 - self.offset**2))

    q0 = 0.0

    def _centre(self, q):
        q = np.asarray(q, dtype=float)
        C = np.stack([np.full_like(q, self.offset), self.s0 + q], axis=-1)
        up = np.broadcast_to([0.0, 1.0], C.shape)
        return C, up, np.zeros_like(C)

    def _centre_qqq(self, q, Cq):
        return np.zeros_like(Cq)

    def _q_at(self, X):
        return X[:, 1] - self.s0

    def sketch(self, motion) -> Sketch:
        """The cam's parts, and the follower's stem up its guide (a bushing above the stroke).

        Parameters
        ----------
        motion : LinearMotion
            The cam's motion.

        Returns
        -------
        Sketch
            The parts to draw and the pivot O.

        Examples
        --------
        >>> import numpy as np
        >>> from mechlab import CamProgramme, TranslatingRollerCam
        >>> cam = TranslatingRollerCam(CamProgramme(30.0, np.radians(40), np.radians(40)), 40.0, 10.0)
        >>> len(cam.sketch(cam.motion(1.0)).parts)
        9
        """
        sk = super().sketch(motion)
        C = motion.points["C"].p
        top = self.s0 + self.programme.stroke + 0.9 * self.prime_radius
        w = 0.35 * max(self.roller_radius, 0.1 * self.base_radius)
        y0, x = self.s0 + self.programme.stroke + 0.3 * self.prime_radius, self.offset
        bushing = np.array([[x - w, y0], [x - w, top], [np.nan, np.nan], [x + w, y0], [x + w, top]])
        stem = (Part("link", lambda i: np.array([C[i], [x, top]]), "follower"), Part("guide", lambda i: bushing))
        return replace(sk, parts=sk.parts + stem)

    def _track(self, x, y):
        return x - self.offset, y

    def _follower(self):
        return (Link("follower", "C", np.pi / 2),
                Pair("prismatic", "guide", FRAME, "follower", "C", np.pi / 2))

    @property
    def _reach(self) -> float:
        return self.s0 + self.programme.stroke + abs(self.offset)


@dataclass(frozen=True)
class OscillatingRollerCam(RollerCam):
    """Disc cam with an oscillating roller follower: arm B→C of length L pivoted at B = (d, 0).

    The roller rides below the line OB; ψ = angle of B→C (radians) and the lift turns the arm
    counter-clockwise by the programme's ``stroke`` (the swing, radians): ψ = ψ0 + y, with
    cos ψ0 = ((r_b + r_r)² − d² − L²)/(2dL), −π < ψ0 < 0.

    Parameters
    ----------
    programme : CamProgramme
        The follower's programme; ``programme.stroke`` is the swing (radians).
    base_radius : float
        r_b, the base circle's radius (length).
    roller_radius : float
        r_r, the roller's radius (length).
    pivot_distance : float
        d, from O to the arm's pivot B (length).
    arm : float
        L, the arm's length B→C (length).
    samples : int, optional
        Profile nodes per turn that the motion's spline goes through.

    Raises
    ------
    DimensionError
        When a dimension is bad, the arm cannot reach the prime circle or the swing would carry the
        roller across the line OB.

    Examples
    --------
    >>> import numpy as np
    >>> from mechlab import CamProgramme, OscillatingRollerCam
    >>> programme = CamProgramme(np.radians(20), np.radians(40), np.radians(40))
    >>> cam = OscillatingRollerCam(programme, 40.0, 10.0, 80.0, 60.0)
    >>> round(cam.q0, 4), round(float(cam.motion(1.0).psi), 4)
    (-2.4675, -2.2464)
    """

    programme: object
    base_radius: float
    roller_radius: float
    pivot_distance: float
    arm: float
    samples: int = 2880

    pivots = ("O", "B")
    output = "angle"

    def __post_init__(self):
        _check_common(self)
        object.__setattr__(self, "pivot_distance", check_length("pivot distance", self.pivot_distance))
        object.__setattr__(self, "arm", check_length("arm", self.arm))
        d, L, R = self.pivot_distance, self.arm, self.prime_radius
        if not abs(d - L) < R < d + L:
            raise DimensionError(f"the arm cannot reach the prime circle: base radius + roller radius = {R:g} "
                                 f"must lie in (|d − L|, d + L) = ({abs(d - L):g}, {d + L:g})")
        top = self.q0 + self.programme.stroke
        if top >= 0.0:
            raise DimensionError(f"swing {np.degrees(self.programme.stroke):.4g}° too large: the arm would turn from "
                                 f"ψ0 = {np.degrees(self.q0):.4g}° past the line OB (ψ = 0°)")

    @property
    def q0(self) -> float:
        """ψ0, the arm's angle in the inner dwell (radians).

        Returns
        -------
        float
            ψ0, in (−π, 0).
        """
        d, L, R = self.pivot_distance, self.arm, self.prime_radius
        return -float(np.arccos((R * R - d * d - L * L) / (2 * d * L)))

    def _centre(self, q):
        q = np.asarray(q, dtype=float)
        u = np.stack([np.cos(q), np.sin(q)], axis=-1)
        return np.array([self.pivot_distance, 0.0]) + self.arm * u, self.arm * perp(u), -self.arm * u

    def _centre_qqq(self, q, Cq):
        return -Cq                      # C = B + L(cos q, sin q): the third derivative turns back to −C_q

    def _q_at(self, X):
        return np.arctan2(X[:, 1], X[:, 0] - self.pivot_distance)

    def _track(self, x, y):
        return (x - self.pivot_distance) ** 2 + y**2 - self.arm**2, -y

    def _follower(self):
        return (Link("follower", "B", ("B", "C"), self.arm, joints=("B", "C")),
                Pair("revolute", "B", FRAME, "follower", "B"))

    @property
    def _reach(self) -> float:
        return self.pivot_distance + self.arm

    def _fixed_points(self, n: int) -> dict:
        return {"B": fixed_point((self.pivot_distance, 0.0), n)}


_CIRCLE = np.stack([np.cos(np.linspace(0, TWO_PI, 60)), np.sin(np.linspace(0, TWO_PI, 60))], axis=-1)


def _turned(xy, angle):
    """Points of the cam frame in the fixed frame, the cam turned by ``angle``."""
    c, s = np.cos(angle), np.sin(angle)
    return xy @ np.array([[c, s], [-s, c]])


def _check_common(cam) -> None:
    if not (callable(cam.programme) and all(hasattr(cam.programme, k) for k in ("stroke", "breaks", "in_dwell"))):
        raise DimensionError(f"programme must be a CamProgramme (a rise–dwell–return–dwell law), "
                             f"got {type(cam.programme).__name__}")
    object.__setattr__(cam, "base_radius", check_length("base radius", cam.base_radius))
    object.__setattr__(cam, "roller_radius", check_length("roller radius", cam.roller_radius, allow_zero=True))
    object.__setattr__(cam, "samples", check_value("samples", cam.samples, count(720, why="profile nodes per turn")))
