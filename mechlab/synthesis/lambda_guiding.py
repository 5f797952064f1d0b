"""The symmetric lambda mechanism of Chebyshev and its circle- and straight-line-guiding synthesis.

Source: Kinitsky (1994), chapter 1, Fig. 1a-b and formulas (1)-(13); the OCR of (2)-(11) is
unreadable, so everything here is re-derived from the geometry the text describes and checked
numerically. Crank O-A (r), coupler A-B-D, rocker B-C with l_AB = l_BC = l_BD = l = 1, frame O-C of
length a, break angle δ = ∠ABD. Frame: O = (0, 0), C = (a, 0), φ counter-clockwise from O→C
(as :class:`mechlab.mechanisms.FourBar`), so A is farthest from C at φ = π; the thesis' t = φ − π.

A, C, D lie on the unit circle about B, so with μ = ∠ABC, |CA| = 2 sin(μ/2), the inscribed angle
∠ACD = π − δ/2 is constant and |CD| = 2 sin((δ − μ)/2):

    D − C = [sin((δ − μ)/2) / sin(μ/2)] · Rot(−(π − δ/2)) (A − C).          (*)

Hence the coupler curve and the motion along it are symmetric about the axis through C at π − δ/2
from C→O (also for δ > π), and the distance of D from a point on that axis depends on μ alone.
The book's chapter on Chebyshev dwell synthesis derives it.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path
from typing import Annotated

import numpy as np
from scipy.optimize import brentq, least_squares, minimize, minimize_scalar, root

from ..errors import DimensionError, MechanismError, NoDesignError, SynthesisError
from ..geometry import check_length, check_number
from ..mechanisms.lambda_mechanism import GuidedLambda, LambdaMechanism, _angle
from ..validate import Flag, Spec, angle, check_value, count, mechanism, number, validated

__all__ = [
    "CircleGuide",
    "DesignOutcomes",
    "ExistenceMap",
    "StraightGuide",
    "ThesisIteration",
    "TransmissionLines",
    "WholeTurnLine",
    "band_touches",
    "circle_guiding",
    "design_outcomes",
    "existence_map",
    "existence_region",
    "fifth_order_line",
    "load_design_outcomes",
    "rotation_boundary",
    "save_design_outcomes",
    "straight_guiding",
    "thesis_iteration",
    "transmission_lines",
    "whole_turn_guiding",
    "whole_turn_line",
]

MAX_SAMPLES = 100_000  # samples of a curve
RIPPLE_FLOOR = 1e-12   # (in l) the equal-ripple equations are solved to about this; a finer band is not resolved
RESOLUTION = 1e-9      # (in l) a band narrower than this may be refused as unresolved (with the band found)
EQ_NOISE = 1e-15       # rounding level of the equal-ripple equations (of order 1): a residual below it is a solution
MAX_STEPS = 400        # continuation steps in α per request (a whole turn takes about 40)
MAX_ISO_POINTS = 400   # frames a per iso-dwell line: each is a synthesis (≈ 10 ms)
MAX_ARC = 40.0         # arclength of a traced line in (r, a, k, t3, t2): the region is far smaller


# --------------------------------------------------------------------------------------------
# Circle-guiding synthesis
# --------------------------------------------------------------------------------------------
def _mu_at(r, a, t):
    """Transmission angle μ at thesis angles t: |CA| = 2 sin(μ/2) = √(a² + r² + 2ar cos t) (formula (5)),
    summed as (a − r)² + 4ar cos²(t/2), which does not cancel where A passes C (r → a, t → π)."""
    t = np.asarray(t, dtype=float)
    return 2 * np.arcsin(np.clip(0.5 * np.sqrt((a - r) ** 2 + 4 * a * r * np.cos(t / 2) ** 2), 0, 1))


def _band_terms(r, a, delta, mu):
    """P = |D − C|², X = (D − C)·e and dP/dμ, dX/dμ in closed form: |CD| = 2 sin((δ − μ)/2) and the
    angle β of D − C from e has cos β = (a² − r² + d²)/(2ad), d = |CA| = 2 sin(μ/2) (module docstring)."""
    d, dd = 2 * np.sin(mu / 2), np.cos(mu / 2)
    rc, drc = 2 * np.sin((delta - mu) / 2), -np.cos((delta - mu) / 2)
    g = (a - r) * (a + r)
    with np.errstate(invalid="ignore", divide="ignore"):  # a solver's trial point may leave the curve
        cb, dcb = (g + d * d) / (2 * a * d), (d * d - g) * dd / (2 * a * d * d)
    return rc * rc, rc * cb, 2 * rc * drc, drc * cb + rc * dcb


def _offset(k, P, X, Y2):
    """u = (kP − 2X)/(1 + s), s = √((1 − kX)² + k²Y²) = |k|·|D − Q| (Y: D's coordinate across e): for
    Q = C + e/k, |D − Q| − |1/k| = sign(k)·u. Smooth through k = 0, where the band is straight and u = −X.
    Y² is passed, not P − X²: where Q lies next to D that difference keeps only a few digits of ρ."""
    s = np.sqrt(np.maximum((1 - k * X) ** 2 + k * k * Y2, 0.0))
    return (k * P - 2 * X) / (1 + s)


def _across2(r, t, mu, P):
    """Y² of D across the axis: Y = |CD| sin β with sin β = r sin t / |CA|, |CA| = 2 sin(μ/2), |CD|² = P."""
    return P * (r * np.sin(t) / (2 * np.sin(mu / 2))) ** 2


def _u_at(r, a, delta, k, t):
    """The offset u of D at thesis angles t (:func:`_offset`)."""
    mu = _mu_at(r, a, t)
    P, X, _, _ = _band_terms(r, a, delta, mu)
    return _offset(k, P, X, _across2(r, t, mu, P))


@dataclass(frozen=True)
class CircleGuide:
    """Equal-ripple circle-guiding design (Kinitsky, 1994, Fig. 1b, formulas (1), (9)-(11)).

    Lengths in units of l. The band's centre is Q = C + e/k on the axis e (towards D0): ``k`` is
    the reciprocal of the offset c = |CQ| (signed), 0 for a straight band, so a design passes
    smoothly through the straight crossing. R0 is the radius touched at the axis point D0 (t = 0)
    and at ±t2, R1 the one touched at ±t3 and again at the dwell ends ±α, where D leaves the band;
    R = (R0 + R1)/2 (1), E = |R0 − R1|/2 (11). Thesis angles t = φ − π.
    """

    delta: float
    a: float
    dwell: float
    r: float
    k: float
    t3: float
    t2: float

    @property
    def alpha(self) -> float:
        return 0.5 * self.dwell

    @property
    def mechanism(self) -> LambdaMechanism:
        return LambdaMechanism(self.r, self.a, self.delta)

    @property
    def straight(self) -> bool:
        return self.k == 0.0

    def _u(self, t):
        x, y = self.mechanism.axis_coordinates(np.pi + np.asarray(t, dtype=float))
        return _offset(self.k, x * x + y * y, x, y * y)

    @property
    def E(self) -> float:
        u = self._u([0.0, self.t3])
        return 0.5 * float(abs(u[0] - u[1]))

    @property
    def kappa(self) -> float:
        """Signed curvature 1/R of the mean circle (> 0: its centre lies on the side of e); 0: straight."""
        return float(self.k / (1 + self.k * self._u([0.0, self.t3]).mean()))

    @property
    def c(self) -> float:
        """Offset |CQ| of the band's centre along e (±inf for a straight band)."""
        return np.copysign(np.inf, self.k) if self.straight else 1 / self.k

    def _radius(self, t) -> float:
        return np.inf if self.straight else float((1 + self.k * self._u([t])[0]) / abs(self.k))

    @property
    def R0(self) -> float:
        return self._radius(0.0)

    @property
    def R1(self) -> float:
        return self._radius(self.t3)

    @property
    def R(self) -> float:
        return np.inf if self.straight else 1 / abs(self.kappa)

    @property
    def centre(self) -> np.ndarray:
        if self.straight:
            raise SynthesisError("the band is straight (κ = 0): it has no centre; use it as a straight guide")
        m = self.mechanism
        return m.C + m.axis / self.k

    @property
    def guided(self) -> GuidedLambda:
        """The mechanism with its band attached (its sketch shows the band)."""
        q = self.centre
        return GuidedLambda(self.r, self.a, self.delta, 1, float(q[0]), float(q[1]), self.R0, self.R1, self.dwell)

    def deviation(self, phi) -> np.ndarray:
        """Signed distance of D from the mean circle, ρ(φ) − R (for a straight band: x − Y along e)."""
        x, y = self.mechanism.axis_coordinates(phi)
        sign = np.sign(self.k) if self.k else -1.0
        return sign * (_offset(self.k, x * x + y * y, x, y * y) - self._u([0.0, self.t3]).mean())


@dataclass(frozen=True)
class StraightGuide:
    """Equal-ripple straight-line guide (R → ∞): D's coordinate x along the axis stays within
    Y ± E over the dwell, touching Y ± E alternately at three or more thesis angles ``touches``."""

    delta: float
    a: float
    dwell: float
    r: float
    Y: float
    E: float
    touches: tuple

    @property
    def mechanism(self) -> LambdaMechanism:
        return LambdaMechanism(self.r, self.a, self.delta)

    def deviation(self, phi) -> np.ndarray:
        return self.mechanism.axis_coordinates(phi)[0] - self.Y


def _interior_extrema(f, t):
    """Indices of the interior local extrema of samples f over t (a flat top of equal samples counts once,
    at its first sample)."""
    df = np.diff(f)
    return np.nonzero(((df[:-1] > 0) & (df[1:] <= 0)) | ((df[:-1] < 0) & (df[1:] >= 0)))[0] + 1


def _initial_r(a: float) -> float:
    # Kinitsky (1994), text after (13): r0 = a/4 (0 < a < 1) or (2 − a)/4 (1 < a < 2)
    return a / 4 if a < 1 else (2 - a) / 4


def _check_inputs(delta, a, dwell, what):
    delta = _angle("δ", delta, 0.0, 2 * np.pi, closed_hi=False)
    a = check_length("a", a)
    if not a < 2.0:
        raise SynthesisError(f"{what}: a = {a:.6g} ≥ 2 leaves no crank with full rotation (r < 2 − a)")
    dwell = _angle("dwell 2α", dwell, 0.0, 2 * np.pi)
    return delta, a, dwell


def _ripple(delta, a, r, k, t3, t2, al):
    """The equal-ripple equations of :func:`_circle_eqs` at m points: arrays (m,) of r, k, t3, t2, α → (m, 4)."""
    t = np.empty((len(r), 4))
    t[:, 0], t[:, 1], t[:, 2], t[:, 3] = 0.0, t3, t2, al
    mu = _mu_at(r[:, None], a, t)
    P, X, dP, dX = _band_terms(r[:, None], a, delta, mu)
    with np.errstate(invalid="ignore", divide="ignore"):
        u = _offset(k[:, None], P, X, _across2(r[:, None], t, mu, P))
    out = np.empty((len(r), 4))
    out[:, 0] = u[:, 0] - u[:, 2]  # = ±(ρ(0) − ρ(t2))
    out[:, 1] = u[:, 1] - u[:, 3]
    out[:, 2] = (k * dP[:, 1] - 2 * dX[:, 1]) / (1 + np.abs(k))
    out[:, 3] = (k * dP[:, 2] - 2 * dX[:, 2]) / (1 + np.abs(k))
    return np.where(np.isfinite(out), out, 1e3)


def _circle_eqs(delta, a, alpha):
    """Equal ripple in (r, k, t3, t2): ρ(0) = ρ(t2), ρ(t3) = ρ(α), ρ'(t3) = ρ'(t2) = 0 about Q = C + e/k.
    With ρ² = (P − 2X/k + 1/k²): ρ(u) = ρ(v) ⇔ k(P(u) − P(v)) − 2(X(u) − X(v)) = 0 and ρ' = 0 ⇔
    kP' − 2X' = 0 (derivatives in μ; dμ/dt ≠ 0 inside the dwell): smooth through k = 0. Divided by 1 + |k|,
    each equation is of the order of the differences of ρ it sets to 0, for a far centre (k → 0) as for one
    next to C (|k| ≫ 1): residuals compare with the band E on one scale. ``eqs.rows`` takes a stack of points."""
    def eqs(y):
        return _ripple(delta, a, *np.array([*y, alpha], dtype=float)[:, None])[0]

    eqs.rows = lambda ys: _ripple(delta, a, *np.asarray(ys, dtype=float).T, np.full(len(ys), alpha))
    return eqs


def _fifth_point(delta: float, a: float):
    """(r, k) of the fifth-order-contact mechanism with frame a, solved for μ0 by brentq on the closed
    form of :func:`fifth_order_line` (a grows monotonically along it); None if the line misses a."""
    mu = np.linspace(1e-9, delta - 1e-9, 801)
    r5 = _fifth_terms(delta, mu)[0]
    # the line's end on r = 0 exactly: a frame just inside it lies between that end and the next sample
    ends = [brentq(lambda m: _fifth_terms(delta, m)[0], mu[j], mu[j + 1], xtol=1e-15)
            for j in np.nonzero(np.isfinite(r5[1:] * r5[:-1]) & (r5[1:] * r5[:-1] < 0))[0]]
    mu = np.sort(np.r_[mu, ends])
    r5, a5, _, _ = _fifth_terms(delta, mu)
    ok = (r5 > -1e-12) & (r5 <= a5) & (r5 + a5 <= 2)  # the line's ends (r = 0) included, a sample may sit on one
    i = np.nonzero(ok[1:] & ok[:-1] & ((a5[1:] - a) * (a5[:-1] - a) <= 0))[0]
    if len(i) == 0:
        return None
    m0 = brentq(lambda m: _fifth_terms(delta, m)[1] - a, mu[i[0]], mu[i[0] + 1], xtol=1e-15)
    r5, _, k5, _ = _fifth_terms(delta, m0)
    return (float(r5), float(k5)) if r5 > 0 else None


def _merged(t3, t2, alpha) -> bool:
    """Touches closer than 0.1 % of α are one touch: a degenerate solution, not equal ripple."""
    return min(t3, t2 - t3, alpha - t2) < 1e-3 * alpha


def _band_spread(delta, a, alpha, r, k, n=401) -> float:
    """Half the spread of |D − Q| (Q = C + e/k; of x for k = 0) over t ∈ [0, α] sampled n times: the
    half-width of a band that holds D over the dwell, so an upper bound on the best band's E."""
    return 0.5 * float(np.ptp(_u_at(r, a, delta, k, np.linspace(0.0, alpha, n))))


def _narrowest_band(delta, a, alpha, r, k):
    """(r, k, half-width) of the narrowest band found near (r, k) by Nelder-Mead on the sampled spread
    (relative steps in r and k); the half-width is measured on 4001 samples, an upper bound on the best E."""
    def spread(v):
        return _band_spread(delta, a, alpha, r * (1 + v[0]), k * (1 + v[1]), 401) if abs(v[0]) < 0.5 else 1.0

    v = minimize(spread, [0.0, 0.0], method="Nelder-Mead",
                 options=dict(initial_simplex=[[0, 0], [1e-7, 0], [0, 1e-7]], xatol=1e-13, fatol=1e-19,
                              maxiter=1000)).x
    rr, kk = (r * (1 + v[0]), k * (1 + v[1])) if spread(v) < spread([0, 0]) else (r, k)
    return float(rr), float(kk), _band_spread(delta, a, alpha, rr, kk, 4001)


@dataclass(frozen=True)
class _Reach:
    """How far a continuation got: the last solution x = (r, k, t3, t2) at 2α = ``dwell``; ``resolved``
    False where the band is too narrow for the equations (x then interpolates at fixed nodes)."""

    x: np.ndarray
    dwell: float
    resolved: bool


def _jacobian(eqs):
    """Central-difference Jacobian of eqs with steps of 1e-5 of each unknown (all 2n points in one call of
    ``eqs.rows``): near the span's ends the equations balance terms of order r³ against terms of order r,
    and the forward differences of ``root`` (steps of 1.5e-8 of the unknown) drown in rounding there."""
    def jac(x):
        x = np.asarray(x, dtype=float)
        h = 1e-5 * np.maximum(np.abs(x), 1e-3)
        f = eqs.rows(np.r_[x + np.diag(h), x - np.diag(h)])
        return ((f[:len(x)] - f[len(x):]) / (2 * h[:, None])).T
    return jac


def _equal_ripple(eqs, x0, maxfev=400):
    """Solve the equal-ripple equations: scipy's hybr, then least_squares scaled by the Jacobian where hybr
    stalls (a band centre close to C, |k| ≫ 1, makes the system badly scaled)."""
    jac = _jacobian(eqs)
    sol = root(eqs, x0, jac=jac, method="hybr", options=dict(xtol=1e-13, maxfev=maxfev))
    res = np.max(np.abs(eqs(sol.x)))
    if res <= EQ_NOISE or res > 1e-6 or not np.all(np.isfinite(sol.x)):  # solved, or not close
        return sol.x
    ls = least_squares(eqs, sol.x, jac=jac, x_scale="jac", xtol=1e-15, ftol=1e-15, gtol=1e-15, max_nfev=60)
    return ls.x if np.max(np.abs(eqs(ls.x))) < np.max(np.abs(eqs(sol.x))) else sol.x




def _step(delta, a, al, x0):
    """One solve at half-dwell al from x0: ("resolved", x) for a converged equal-ripple solution whose
    band the equations resolve; ("unresolved", x) where the band is below RESOLUTION (x: r, k
    interpolating at the nodes α sin 30°, α sin 60° of the small-dwell limit); ("failed", None)."""
    hi = min(a, 2 - a)
    eqs = _circle_eqs(delta, a, al)
    nodes = [0.5 * al, 0.5 * np.sqrt(3) * al]

    def sub_eqs(y):
        return eqs([*y, *nodes])[:2]

    sub_eqs.rows = lambda ys: eqs.rows(np.c_[ys, np.tile(nodes, (len(ys), 1))])[:, :2]
    sub = root(sub_eqs, x0[:2], jac=_jacobian(sub_eqs), method="hybr", options=dict(xtol=1e-13, maxfev=200))
    # r must stay near the last one: r → 0 is a trivial narrow band (D stops moving), not the design followed
    near = np.all(np.isfinite(sub.x)) and 0 < sub.x[0] < hi and abs(sub.x[0] - x0[0]) < 0.1 * x0[0]
    # where a band far below resolution leaves the node equations to rounding, the last crank and centre serve
    rk = sub.x if near else x0[:2]
    spread = _band_spread(delta, a, al, *rk)
    if spread < 0.1 * RESOLUTION:  # too narrow for any design to be returned: no full solve
        return "unresolved", np.r_[rk, nodes]
    x = _equal_ripple(eqs, x0, maxfev=100)  # a continuation step converges in a few iterations or not at all
    r, k, t3, t2 = x
    if np.all(np.isfinite(x)) and 0.5 * x0[0] < r < hi and 0 < t3 < t2 < al and not _merged(t3, t2, al):
        u = _u_at(r, a, delta, k, np.array([0.0, t3]))
        E = 0.5 * abs(u[0] - u[1])
        if E >= 0.1 * RESOLUTION and np.max(np.abs(eqs(x))) <= 1e-4 * E + EQ_NOISE:
            return "resolved", x
    # a band up to 100 × RESOLUTION is passed through (the full solve may only succeed further on)
    if spread < 100 * RESOLUTION:
        return "unresolved", np.r_[rk, nodes]
    return "failed", None


def _follow(delta, a, x, al, alpha) -> _Reach | None:
    """Continue the solution x at half-dwell al (up or down) towards α: predicted along the secant of the last
    two solutions (the first step scales the touches with α), the step halved where a solve fails (down to
    0.005°), grown again after a success. Returns the last point reached."""
    sign = 1.0 if alpha >= al else -1.0
    reached, step, last = None, np.radians(4.0), None
    for _ in range(MAX_STEPS):
        nxt = alpha if abs(alpha - al) <= step else al + sign * step
        x0 = np.r_[x[:2], x[2:] * nxt / al] if last is None else x + (x - last[0]) * (nxt - al) / (al - last[1])
        kind, y = _step(delta, a, nxt, x0)
        if kind == "failed" and last is not None:  # the secant can overshoot where the solution turns
            kind, y = _step(delta, a, nxt, np.r_[x[:2], x[2:] * nxt / al])
        if kind == "unresolved" and reached is not None and reached.resolved and step > np.radians(0.01):
            kind = "failed"  # leave resolved designs in short steps: a long one can miss the solution
        if kind == "failed":
            if step < np.radians(0.005):
                break
            step /= 2
            continue
        last = (x, al) if kind == "resolved" and reached is not None and reached.resolved else None
        x, al, reached = y, nxt, _Reach(y, 2 * nxt, kind == "resolved")
        if al == alpha:
            break
        step = min(1.5 * step, np.radians(12.0))
    return reached


def _rotation_limit_dwell(delta, a, reach: _Reach) -> float | None:
    """The dwell 2α at which the design's crank reaches the rotation limit r = min(a, 2 − a) (the
    equal-ripple equations at that r, unknowns k, t3, t2, α), from the last design reached; None if
    that solve fails."""
    rl = min(a, 2 - a) * (1 - 1e-9)

    def eqs(y):
        return _ripple(delta, a, *np.array([rl, *y], dtype=float)[:, None])[0]

    eqs.rows = lambda ys: _ripple(delta, a, np.full(len(ys), rl), *np.asarray(ys, dtype=float).T)

    sol = root(eqs, [*reach.x[1:], reach.dwell / 2], jac=_jacobian(eqs), method="hybr",
               options=dict(xtol=1e-13, maxfev=400))
    _, t3, t2, al = sol.x
    if np.max(np.abs(eqs(sol.x))) > 1e-10 or not 0 < t3 < t2 < al <= np.pi or al < reach.dwell / 2 * (1 - 1e-9):
        return None
    return float(2 * al)


@lru_cache(maxsize=32)
def _whole_turn_cached(delta: float) -> WholeTurnLine:
    return whole_turn_line(delta)


def _whole_turn_start(delta, a):
    """(r, k, t3, t2) of the whole-turn design with frame a, interpolated on :func:`whole_turn_line`
    (None if the line misses a)."""
    line = _whole_turn_cached(delta)
    i = np.nonzero(np.sign(line.a[1:] - a) * np.sign(line.a[:-1] - a) <= 0)[0]
    if len(i) == 0:
        return None
    i = i[0]
    w = (a - line.a[i]) / (line.a[i + 1] - line.a[i])
    return np.array([(1 - w) * v[i] + w * v[i + 1] for v in (line.r, 1 / line.c, line.t3, line.t2)])


def _minimax_guess(delta, a, alpha):
    """Nelder-Mead on (r, k) minimising the spread of ρ over the dwell (fallback start)."""
    ts = np.linspace(0.0, alpha, 121)

    def offsets(r, k):
        return _u_at(r, a, delta, k, ts)

    def spread(x):
        if not 0 < x[0] < min(a, 2 - a):
            return 1e3
        u = offsets(*x)
        return float(u.max() - u.min()) if np.all(np.isfinite(u)) else 1e3

    start = _fifth_point(delta, a) or (_initial_r(a), 0.0)
    best = minimize(spread, start, method="Nelder-Mead", options=dict(xatol=1e-7, fatol=1e-13, maxiter=600))
    ext = _interior_extrema(offsets(*best.x), ts)
    if len(ext) < 2:
        return None
    return best.x[0], best.x[1], ts[ext[0]], ts[ext[-1]]


def _solve_circle(delta, a, dwell, x0):
    """Solve the equal-ripple equations from x0 and check the result on a dense sample;
    returns (CircleGuide, None) or (None, reason)."""
    alpha = dwell / 2
    eqs = _circle_eqs(delta, a, alpha)
    x = _equal_ripple(eqs, x0)
    r, k, t3, t2 = (float(v) for v in x)
    if not np.max(np.abs(eqs(x))) <= 1e-10:
        return None, f"the equal-ripple equations did not converge (residual {np.max(np.abs(eqs(x))):.3g})"
    if not 1e-4 * min(a, 2 - a) < r < min(a, 2 - a):  # r → 0 is the trivial band (D stands still)
        return None, f"the crank leaves (0, min(a, 2 − a)) = (0, {min(a, 2 - a):.4g}): r = {r:.4g}"
    if not 0.0 < t3 < t2 < alpha or _merged(t3, t2, alpha):
        return None, (f"the touch points are not four distinct ones (t3 = {np.degrees(t3):.6g}°, "
                      f"t2 = {np.degrees(t2):.6g}°, α = {np.degrees(alpha):.6g}°)")
    g = CircleGuide(delta, a, dwell, r, 0.0 if k == 0 else k, t3, t2)
    if g.E < 0.1 * RESOLUTION:
        return None, f"the band E = {g.E:.3g} is too narrow for its touches to be told from rounding"
    if np.max(np.abs(eqs(x))) > 1e-4 * g.E + EQ_NOISE:
        return None, f"the equations are not solved finely enough to resolve the band E = {g.E:.3g}"
    dense = g.deviation(np.pi + np.linspace(-alpha, alpha, 4001))
    if np.max(np.abs(dense)) > g.E * (1 + 1e-6) + RIPPLE_FLOOR:
        return None, (f"the best circle leaves the band inside the dwell (max |ρ − R| = "
                      f"{np.max(np.abs(dense)):.3g} > E = {g.E:.3g}; a ripple near {RIPPLE_FLOOR:g} l is not resolved)")
    return g, None


def _from_inside(delta, a, dwell, depth):
    """Continuation in the frame for a near an end of the fifth-order line's span (r → 0 there, and the
    design's r changes too fast with α for the continuation in α): the design at a frame ten times
    further from that end, followed to a in steps uniform in s = log|a − end| (24, halved where a solve
    fails or falls to the trivial r → 0), each predicted along the secant of the last two (the first with
    r ∝ |a − end|, as on the fifth-order line). x = (r, k, t3, t2) or None."""
    lo5, hi5 = 2 * np.sin(max(delta - np.pi, 0.0) / 2), 2 * np.sin(delta / 4)
    end = lo5 if a - lo5 < hi5 - a else hi5
    if abs(a - end) > 0.1 * (hi5 - lo5):
        return None
    a_in = end + 10 * (a - end)
    try:
        g = _circle(delta, a_in, dwell, None, False, depth + 1)
    except SynthesisError:
        return None
    s, goal = np.log(abs(a_in - end)), np.log(abs(a - end))
    x, last, step = np.array([g.r, g.k, g.t3, g.t2]), None, (goal - s) / 24
    first = step
    while s != goal:
        nxt = goal if abs(goal - s) <= abs(step) * 1.001 else s + step
        ai = end + np.sign(a - end) * np.exp(nxt)
        guess = np.r_[x[0] * np.exp(nxt - s), x[1:]] if last is None else x + (x - last[0]) * (nxt - s) / (s - last[1])
        y = _equal_ripple(_circle_eqs(delta, ai, dwell / 2), guess, maxfev=100)
        if np.all(np.isfinite(y)) and 0.5 * guess[0] < y[0] < min(ai, 2 - ai) and 0 < y[2] < y[3] < dwell / 2:
            last, x, s, step = (x, s), y, nxt, first if abs(2 * step) > abs(first) else 2 * step
        elif abs(step) > abs(first) / 64:
            step /= 2
        else:
            return None
    return x


def _frame_span(delta: float) -> tuple[float, float]:
    """The frames a the existence region spans: from the lower end of the fifth-order line on r = 0,
    a = 2 sin((δ − π)/2) (0 for δ ≤ π), to point A, a = 2 sin(δ/4), or for δ < 120° on to the far end
    of the whole-turn line, which rises above A there (those frames have long dwells only)."""
    lo, hi = 2 * np.sin(max(delta - np.pi, 0.0) / 2), 2 * np.sin(delta / 4)
    if delta < np.radians(120):
        hi = max(hi, float(_whole_turn_cached(delta).a.max()))
    return lo, hi


def circle_guiding(delta: float, a: float, dwell: float, *, guess: tuple | None = None,
                   minimax: bool = True) -> CircleGuide:
    """Circle-guiding lambda mechanism for break angle δ, frame a and dwell 2α (radians).

    Finds r and the band's centre Q = C + e/k such that ρ(t) = |D − Q| over the dwell
    t ∈ [−α, α] equioscillates: ρ(0) = ρ(±t2) = R0 and ρ(±t3) = ρ(±α) = R1 with ρ'(t3) =
    ρ'(t2) = 0 (four alternating touches on each half, the Chebyshev best approximation with
    the three free parameters r, Q, R). The unknowns are (r, k, t3, t2): k = 1/|CQ| passes
    through 0 where the best band is straight, so no design near the straight crossing is lost.
    Solved with scipy's ``root`` (hybr) by continuation in α from the closed-form fifth-order contact
    (2α → 0, :func:`fifth_order_line`), or for frames above point A (δ < 120°) down from the
    whole-turn line (2α = 360°, :func:`whole_turn_line`); 2α = 360° itself is :func:`whole_turn_guiding`.
    Near the span's ends, where r → 0, a design at a frame ten times further inside is followed in a
    (:func:`_from_inside`); where hybr stalls, scipy's ``least_squares`` polishes.

    Parameters
    ----------
    delta : float
        Break angle δ of the lambda mechanism (rad), in (0, 2π).
    a : float
        Frame length l_OC (units of l), in (0, 2).
    dwell : float
        The dwell's crank angle 2α (rad), in (0, 2π].
    guess : tuple of float, optional
        (r, k, t3, t2) of a neighbouring solution, tried first.
    minimax : bool
        False skips the (slower) Nelder-Mead fallback.

    Returns
    -------
    CircleGuide
        The design: crank r, band centre Q, radius R and half-width E (units of l).

    Raises
    ------
    NoDesignError
        No design, with ``kind`` and the evidence: ``"frame"`` (a outside the region's span),
        ``"rotation"`` (the crank reaches the rotation limit at 2α = ``dwell_max`` < 2α), ``"fold"``
        (above A the designs start at 2α = ``dwell_min``), ``"resolution"`` (a band of half-width
        ``bound`` < RESOLUTION about Q = C + e/``k`` with crank ``r`` holds D: the ripple is below
        what double precision resolves), ``"whole turn"``.
    SynthesisError
        a ≥ 2, or the equal-ripple solve fails.
    DimensionError
        δ, a, 2α or ``guess`` out of range.

    Examples
    --------
    >>> import numpy as np
    >>> import mechlab as ml
    >>> guide = ml.circle_guiding(np.radians(150), 0.9, np.radians(120))
    >>> round(guide.r, 6), round(guide.R, 4), f"{guide.E:.3g}"
    (0.214482, 0.606, '7.59e-05')
    """
    delta, a, dwell = _check_inputs(delta, a, dwell, "circle guiding")
    minimax = check_value("minimax", minimax, Flag.__metadata__[0])
    if guess is not None:
        if isinstance(guess, str) or np.ndim(guess) != 1 or len(guess) != 4:
            raise DimensionError(f"guess must be (r, k, t3, t2), got {guess!r:.60}")
        guess = tuple(check_value(f"guess[{i}]", v, number()) for i, v in enumerate(guess))
    return _circle(delta, a, dwell, guess, minimax)


OUTCOMES = ("design", "frame", "resolution", "rotation", "fold", "whole turn", "unresolved")
OUTCOME_FRACTIONS = (0.0, 0.001, 0.05, 0.1625, 0.275, 0.3875, 0.5, 0.6125, 0.725, 0.8375, 0.95, 0.999, 1.0)
OUTCOME_DWELLS = tuple(np.radians((0.5, 5, 15, 30, 60, 90, 120, 150, 180, 210, 240, 270, 300, 330, 359.64, 360)))
MAX_OUTCOMES = 1000  # requests per map: each is a synthesis (up to ~1 s near the span's ends)


@dataclass(frozen=True)
class DesignOutcomes:
    """What :func:`circle_guiding` returns over a grid of frames and dwells (:func:`design_outcomes`).

    Parameters
    ----------
    delta : float
        Break angle δ (rad).
    span : tuple of float
        (lo, hi): the existence region's span of frames a, ends included.
    fraction : numpy.ndarray
        Each frame's place in the span: 0 at its lower end, 1 at its upper end.
    a : numpy.ndarray
        The frames (units of l).
    dwell : numpy.ndarray
        The dwells 2α (rad).
    kind : numpy.ndarray of str
        ``kind[i, j]`` is ``"design"``, the refusal's kind (:class:`NoDesignError`) or
        ``"unresolved"`` for frame i, dwell j.

    Examples
    --------
    >>> import numpy as np
    >>> import mechlab as ml
    >>> outcomes = ml.design_outcomes(np.radians(150), fractions=(0.0, 0.5), dwells=(np.radians(60),))
    >>> outcomes.kind.tolist()  # a = 0 is no frame
    [['frame'], ['design']]
    """

    delta: float
    span: tuple[float, float]
    fraction: np.ndarray  # each frame's place in the span: 0 at its lower end, 1 at its upper end
    a: np.ndarray
    dwell: np.ndarray
    kind: np.ndarray


def design_outcomes(delta: float, fractions=OUTCOME_FRACTIONS, dwells=OUTCOME_DWELLS) -> DesignOutcomes:
    """:func:`circle_guiding` (``minimax=False``) at every frame ``lo + f (hi − lo)`` for ``f`` in ``fractions``
    of the existence region's span and every dwell 2α in ``dwells`` (rad): a map of where designs exist
    and why the rest are refused.

    Parameters
    ----------
    delta : float
        Break angle δ (rad), in (0, 2π).
    fractions : array_like
        Places of the frames in the span, in [0, 1].
    dwells : array_like
        Dwells 2α (rad), in (0, 2π].

    Returns
    -------
    DesignOutcomes
        The frames, the dwells and each request's outcome.

    Raises
    ------
    DimensionError
        An argument out of range, empty, or more than MAX_OUTCOMES requests.

    Examples
    --------
    >>> import numpy as np
    >>> import mechlab as ml
    >>> outcomes = ml.design_outcomes(np.radians(150), fractions=(0.5,), dwells=(np.radians(60), np.radians(120)))
    >>> outcomes.kind.tolist(), round(float(outcomes.a[0]), 4)
    ([['design', 'design']], 0.6088)
    """
    delta = _angle("δ", delta, 0.0, 2 * np.pi, closed_hi=False)
    fractions = np.atleast_1d(check_value("fractions", fractions, Spec("reals", 0.0, 1.0, why="fractions of the span")))
    dwells = np.atleast_1d(check_value("dwells", dwells,
                                       Spec("radians", 0.0, 2 * np.pi, why="dwells 2α, up to a turn")))
    if fractions.size == 0 or dwells.size == 0:
        raise DimensionError("design_outcomes: fractions and dwells must each hold at least one value")
    if fractions.size * dwells.size > MAX_OUTCOMES:
        raise DimensionError(f"fractions × dwells: {fractions.size} frames × {dwells.size} dwells = "
                             f"{fractions.size * dwells.size} requests > MAX_OUTCOMES = {MAX_OUTCOMES}")
    lo, hi = _frame_span(delta)
    a = lo + (hi - lo) * fractions
    kind = np.empty((a.size, dwells.size), dtype=object)
    for i, a_ in enumerate(a):
        for j, dw in enumerate(dwells):
            try:
                circle_guiding(delta, a_, dw, minimax=False)
                kind[i, j] = "design"
            except NoDesignError as err:
                kind[i, j] = err.kind
            except MechanismError:  # a = 0 is no frame at all; anything else is a request left unresolved
                kind[i, j] = "frame" if a_ == 0 else "unresolved"
    return DesignOutcomes(float(delta), (float(lo), float(hi)), fractions, a, dwells, kind)


# The maps of the companion of chapter 6, stored: each is 208 syntheses, 15-30 s of CPU (a test recomputes a sample)
OUTCOME_DATA = Path(__file__).resolve().parent.parent / "data" / "design_outcomes.npz"
STORED_OUTCOME_DELTAS = tuple(np.radians((90.0, 180.0, 240.0)))


@validated
def save_design_outcomes(maps: Annotated[object, Spec("items", expected=DesignOutcomes)],
                         path: Annotated[object, Spec("path")]) -> Path:
    """Write maps of :func:`design_outcomes` to ``path`` (``.npz``), read back by :func:`load_design_outcomes`.

    Parameters
    ----------
    maps : sequence of DesignOutcomes
        The maps, in the order they are to be read back.
    path : str or path-like
        The file to write.

    Returns
    -------
    pathlib.Path
        ``path``.

    Raises
    ------
    DimensionError
        ``maps`` is empty.
    TypeError
        ``maps`` is not a tuple or list of DesignOutcomes, or ``path`` is not a path.

    Examples
    --------
    >>> import pathlib, tempfile
    >>> import numpy as np
    >>> import mechlab as ml
    >>> small = ml.design_outcomes(np.radians(150), fractions=(0.0, 0.5), dwells=(np.radians(60),))
    >>> with tempfile.TemporaryDirectory() as tmp:
    ...     path = ml.save_design_outcomes([small], pathlib.Path(tmp) / "maps.npz")
    ...     [m.kind.tolist() for m in ml.load_design_outcomes(path)]
    [[['frame'], ['design']]]
    """
    if not maps:
        raise DimensionError("maps must hold at least one DesignOutcomes (from design_outcomes)")
    columns = {}
    for i, m in enumerate(maps):
        columns.update({f"{i}.delta": m.delta, f"{i}.span": np.array(m.span), f"{i}.fraction": m.fraction,
                        f"{i}.a": m.a, f"{i}.dwell": m.dwell,
                        f"{i}.kind": np.vectorize(OUTCOMES.index, otypes=[np.uint8])(m.kind)})
    path = Path(path)
    np.savez_compressed(path, count=len(maps), **columns)
    return path


@validated
def load_design_outcomes(path: Annotated[object, Spec("path", optional=True)] = None) -> list[DesignOutcomes]:
    """The maps of :func:`design_outcomes` the course stores (δ = 90°, 180°, 240°, the default frames and dwells),
    or those :func:`save_design_outcomes` wrote to ``path``.

    Parameters
    ----------
    path : str or path-like, optional
        A file written by :func:`save_design_outcomes` (default: the shipped ``mechlab/data/design_outcomes.npz``,
        rebuilt by ``save_design_outcomes([design_outcomes(d) for d in STORED_OUTCOME_DELTAS], OUTCOME_DATA)``).

    Returns
    -------
    list of DesignOutcomes
        The maps, in the order they were saved.

    Raises
    ------
    DimensionError
        ``path`` is no file, or holds no maps written by :func:`save_design_outcomes`.
    TypeError
        ``path`` is not a path.

    Examples
    --------
    >>> import numpy as np
    >>> import mechlab as ml
    >>> maps = ml.load_design_outcomes()
    >>> [round(float(np.degrees(m.delta))) for m in maps], maps[0].kind.shape
    ([90, 180, 240], (13, 16))
    """
    path = Path(OUTCOME_DATA if path is None else path)
    if not path.is_file():
        raise DimensionError(f"path {str(path)!r} is no file (maps are written by save_design_outcomes)")
    try:
        with np.load(path, allow_pickle=False) as f:
            return [DesignOutcomes(float(f[f"{i}.delta"]), tuple(float(v) for v in f[f"{i}.span"]),
                                   f[f"{i}.fraction"], f[f"{i}.a"], f[f"{i}.dwell"],
                                   np.array(OUTCOMES, dtype=object)[f[f"{i}.kind"]])
                    for i in range(int(f["count"]))]
    except (OSError, ValueError, KeyError, IndexError) as err:
        raise DimensionError(f"path {str(path)!r} holds no maps written by save_design_outcomes: {err}") from None


def _below_resolution(where, delta, a, alpha, cranks) -> NoDesignError | None:
    """The "resolution" refusal if one of the (r, k) in ``cranks``, narrowed by :func:`_narrowest_band`, holds D
    within RESOLUTION over the dwell (the evidence: that r, k and the half-width measured); else None."""
    for r0, k0 in cranks:
        r, k, bound = _narrowest_band(delta, a, alpha, r0, k0)
        if bound < RESOLUTION:
            return NoDesignError(
                f"{where}: the ripple is below what double precision resolves: the crank r = {r:.6g} with the "
                f"band about Q = C + e/k, k = {k:.6g}, holds D within ± {bound:.2g} l over the dwell, so the best "
                f"band is no wider", "resolution", r=float(r), k=float(k), bound=bound)
    return None


def _crank_inside(delta, a, dwell, lo, hi, depth):
    """Within rounding of the span's end (|a − end| ≤ 1e-13) no start exists, as the crank r vanishes with the
    distance to the end: the (r, k) of the frame 1e-12 inside, r scaled down by the distances, or None."""
    end = hi if hi - a <= a - lo else lo
    if abs(a - end) > 1e-13 * max(1.0, abs(end)):
        return None
    inner = end - np.sign(end - a) * 1e-12 * max(1.0, abs(end))
    try:
        g = _circle(delta, inner, dwell, None, False, depth + 1)
        r, k = g.r, g.k
    except NoDesignError as err:
        if err.kind != "resolution":
            return None
        r, k = err.evidence["r"], err.evidence["k"]
    except SynthesisError:
        return None
    return r * abs(a - end) / abs(inner - end), k


def _circle(delta, a, dwell, guess, minimax, depth=0):
    """circle_guiding after its input checks; ``depth`` counts the nested solves of :func:`_from_inside`."""
    alpha = dwell / 2
    where = f"no circle-guiding lambda mechanism for δ = {np.degrees(delta):.4g}°, a = {a:.4g}, " \
            f"2α = {np.degrees(dwell):.4g}°"
    lo, hi = _frame_span(delta)
    if not lo < a < hi:
        raise NoDesignError(f"{where}: the existence region of Fig. 2a spans a ∈ ({lo:.4g}, {hi:.4g}) only "
                            f"(the ends of the fifth-order and whole-turn lines)", "frame", span=(lo, hi))
    if alpha >= np.pi:
        try:
            return whole_turn_guiding(delta, a, _whole_turn_cached(delta))
        except SynthesisError as err:
            line = _whole_turn_cached(delta)
            raise NoDesignError(f"{where}: {err}", "whole turn",
                                span=(float(line.a.min()), float(line.a.max()))) from err
    if guess is not None:
        g, _ = _solve_circle(delta, a, dwell, np.asarray(guess, dtype=float))
        if g is not None:
            return g
    start = _fifth_point(delta, a)
    if start is not None:
        al0 = min(alpha, np.radians(1.0))
        reach = _follow(delta, a, np.array([*start, 0.5 * al0, 0.5 * np.sqrt(3) * al0]), al0, alpha)
    else:  # above A: down from the whole-turn line (its design at 2α = 360° is the first one reached)
        x = _whole_turn_start(delta, a)
        kind, x = ("failed", None) if x is None else _step(delta, a, np.pi, x)
        reach = None if kind != "resolved" else (_follow(delta, a, x, np.pi, alpha) or _Reach(x, 2 * np.pi, True))
    if reach is not None and reach.dwell == dwell:
        g, _ = _solve_circle(delta, a, dwell, reach.x)
        if g is not None:
            return g
        # a band near resolution can fail the dense check by rounding: then it must be held below RESOLUTION
        if (err := _below_resolution(where, delta, a, alpha, [reach.x[:2]])) is not None:
            raise err
    if reach is not None and start is not None:
        top = _rotation_limit_dwell(delta, a, reach)
        if top is not None and top < dwell:
            raise NoDesignError(
                f"{where}: the longest dwell this frame allows is 2α = {np.degrees(top):.6g}°, where the crank "
                f"reaches the rotation limit r = min(a, 2 − a) = {min(a, 2 - a):.6g} (a dead point)",
                "rotation", dwell_max=top, r_limit=min(a, 2 - a))
        if reach.resolved and reach.dwell < dwell and reach.x[0] > 0.97 * min(a, 2 - a):
            raise NoDesignError(
                f"{where}: the designs of this frame end at 2α = {np.degrees(reach.dwell):.6g}° (the continuation "
                f"stops "
                f"there, to 0.005°), with the crank r = {reach.x[0]:.6g} next to the rotation limit r = min(a, 2 − a) "
                f"= {min(a, 2 - a):.6g} (a dead point)", "rotation", dwell_max=reach.dwell, r_limit=min(a, 2 - a))
    if reach is not None and start is None and reach.dwell > dwell:
        why = ("its crank reaches the rotation limit r = a" if reach.x[0] > 0.98 * min(a, 2 - a) else
               "the family of designs from the whole-turn line folds back")
        raise NoDesignError(f"{where}: above point A designs start at 2α = {np.degrees(reach.dwell):.6g}° (to 0.01°; "
                            f"{why})",
                            "fold", dwell_min=reach.dwell, r=float(reach.x[0]))
    if start is not None and depth < 3 and (x := _from_inside(delta, a, dwell, depth)) is not None:
        g, _ = _solve_circle(delta, a, dwell, x)
        if g is not None:
            return g
    if minimax:
        x0 = _minimax_guess(delta, a, alpha)
        if x0 is not None:
            g, _ = _solve_circle(delta, a, dwell, x0)
            if g is not None:
                return g
    # the solve is lost, but near the span's ends (r → 0, or a → 0) the band may be below resolution (the crank
    # of a continuation that reached the dwell was tried above)
    last = None if reach is None or reach.dwell == dwell else reach.x
    cranks = [x[:2] for x in (start, last) if x is not None]
    if not cranks and depth < 3 and (inside := _crank_inside(delta, a, dwell, lo, hi, depth)) is not None:
        cranks = [inside]
    if (err := _below_resolution(where, delta, a, alpha, cranks)) is not None:
        raise err
    got = "no start" if reach is None else f"the continuation stops at 2α = {np.degrees(reach.dwell):.6g}°"
    raise SynthesisError(f"{where}: the equal-ripple solve fails ({got}); choose (δ, a, 2α) inside the existence map")


@dataclass(frozen=True)
class ThesisIteration:
    """The thesis' iteration for r: the result, the number of steps and every step's (r0, r1, μ0, μ1, μ3, μ2)."""

    r: float
    steps: int
    history: np.ndarray


def _touch_angles(delta, mu0, mu1, start):
    """Formulas (2)-(4) as we read them: given δ and the end angles μ0 > μ1 of the dwell, the inner
    touches μ3 > μ2 and (p, q) = (c/a, c(a² − r²)/a) of the band ρ² = ρ_C² + c² − pρ_C d − qρ_C/d.
    The equalities ρ(μ0) = ρ(μ2), ρ(μ3) = ρ(μ1) and ρ'(μ3) = ρ'(μ2) = 0 are linear in (p, q):
    the two derivative conditions give (p, q), the two equalities then fix μ3, μ2."""
    def terms(mu):
        d, dd = 2 * np.sin(mu / 2), np.cos(mu / 2)
        rc, drc = 2 * np.sin((delta - mu) / 2), -np.cos((delta - mu) / 2)
        return rc * rc, rc * d, rc / d, 2 * rc * drc, drc * d + rc * dd, (drc * d - rc * dd) / d**2

    def pq(m3, m2):
        _, _, _, dF, dG, dH = terms(np.array([m3, m2]))
        return np.linalg.solve(np.array([dG, dH]).T, dF)

    def eqs(x):
        p, q = pq(*x)
        F, G, H, *_ = terms(np.array([mu0, x[0], x[1], mu1]))
        rho2 = F - p * G - q * H
        return [rho2[0] - rho2[2], rho2[1] - rho2[3]]

    sol = root(eqs, start, method="hybr", options=dict(xtol=1e-14))
    return sol.x, pq(*sol.x), float(np.max(np.abs(eqs(sol.x))))


def thesis_iteration(delta: float, a: float, dwell: float, tol: float = 1e-6, maxiter: int = 200) -> ThesisIteration:
    """The thesis' own scheme for r (Kinitsky, 1994, (12)-(13)), step by step; for comparison.

    From r0 = a/4 (a < 1) or (2 − a)/4 (a > 1): μ0 from a + r0 = 2 sin(μ0/2) and μ1 from (5),
    sin(μ1/2) = ½√(a² + r0² + 2a·r0·cos α); then (2)-(4) give the inner touches μ3, μ2 and
    k = a² − r² of the band (:func:`_touch_angles`); (6) returns r1 = ½(d0 − k/d0), d0 = 2 sin(μ0/2)
    (from a + r = d0, a − r = k/d0). Stop when |r1 − r0| ≤ ε = 10⁻⁶ (13), else r0 ← (r0 + r1)/2
    (the thesis' "halving"). Converges in 8 steps at (150°, 0.9, 60°) and 26-27 at (180°, 0.5, 120°),
    (180°, 0.8, 180°), to within a few ε of :func:`circle_guiding`.

    An iterate may leave the crank's range (0, min(a, 2 − a)): from r0 = a/4 the first r1 is negative at
    short dwells, e.g. (δ, a, 2α) = (90°, 0.7, 60°), (120°, 0.9, 60°), (150°, 1.1, 60°). The scheme's
    formulas still hold there ((5) and a + r = 2 sin(μ0/2) while 0 < a + r < 2) and the halving brings the
    next iterate back, as the thesis' scheme does; only the converged r must be a design: in the crank's
    range with its touches in order μ0 > μ3 > μ2 > μ1. Raises SynthesisError where the touch equations
    have no solution, a + r leaves (0, 2), the fixed point is not a design or ``maxiter`` steps do not
    settle; the scheme is a fixed-point iteration without a convergence proof, so it may fail where
    :func:`circle_guiding` finds a design.

    Parameters
    ----------
    delta : float
        Break angle δ of the lambda mechanism (rad), in (0, 2π).
    a : float
        Frame length l_OC (units of l), in (0, 2).
    dwell : float
        The dwell's crank angle 2α (rad), in (0, 2π].
    tol : float
        ε of the stopping rule, in [1e-14, 1] (default 1e-6).
    maxiter : int
        Most steps, in [1, 10000] (default 200).

    Returns
    -------
    ThesisIteration
        r, the number of steps and every step's (r0, r1, μ0, μ1, μ3, μ2).

    Raises
    ------
    SynthesisError
        The iteration does not converge to a design, or a ≥ 2.
    DimensionError
        An argument out of range.

    Examples
    --------
    >>> import numpy as np
    >>> import mechlab as ml
    >>> it = ml.thesis_iteration(np.radians(150), 0.9, np.radians(60))
    >>> round(it.r, 7), it.steps
    (0.1831762, 8)
    """
    delta, a, dwell = _check_inputs(delta, a, dwell, "thesis iteration")
    maxiter = int(_bounded("maxiter", maxiter, 1, 10_000))
    tol = _bounded("tol", tol, 1e-14, 1.0)
    alpha = dwell / 2
    r0, rows = _initial_r(a), []
    for step in range(1, maxiter + 1):
        mu0, mu1 = _mu_at(r0, a, [0.0, alpha])
        try:
            (m3, m2), (p, q), res = _touch_angles(delta, mu0, mu1, _mu_at(r0, a, [alpha / 2, alpha * np.sqrt(3) / 2]))
        except np.linalg.LinAlgError:  # the scheme's touch equations are singular here (e.g. δ → 0)
            break
        d0 = 2 * np.sin(mu0 / 2)
        r1 = 0.5 * (d0 - (q / p) / d0)
        rows.append((r0, r1, mu0, mu1, m3, m2))
        design = 0 < r0 < min(a, 2 - a) and mu1 < m2 < m3 < mu0
        if res > 1e-9 or not np.isfinite(r1) or (abs(r1 - r0) <= tol and not design):
            break
        if abs(r1 - r0) <= tol:
            return ThesisIteration(float(r1), step, np.array(rows))
        r0 = 0.5 * (r0 + r1)
        if not 0 < a + r0 < 2:   # μ0 from a + r = 2 sin(μ0/2) no longer exists
            break
    raise SynthesisError(f"the thesis' iteration did not converge for δ = {np.degrees(delta):.4g}°, "
                         f"a = {a:.4g}, 2α = {np.degrees(dwell):.4g}° after {len(rows)} steps (last r = {r0:.6g})")


def _bounded(name, value, lo, hi):
    """``value`` as a float in [lo, hi], else a DimensionError naming it and the bounds."""
    x = check_number(name, value)
    if not lo <= x <= hi:
        raise DimensionError(f"{name} = {x:g} must lie in [{lo:g}, {hi:g}]")
    return x


# --------------------------------------------------------------------------------------------
# Straight-line guiding
# --------------------------------------------------------------------------------------------
def _axis_x(r, a, delta, t):
    """x = (D − C)·e at thesis angles t (closed form), and dx/dμ."""
    _, X, _, dX = _band_terms(r, a, delta, _mu_at(r, a, t))
    return X, dX


def _extremes(r, a, delta, alpha, n=201):
    """(t, x) of every local extreme of x over [0, α], ends included, the interior ones polished
    by a bounded scalar search between the neighbouring samples."""
    ts = np.linspace(0.0, alpha, n)
    xs = _axis_x(r, a, delta, ts)[0]
    out = [(0.0, xs[0]), (alpha, xs[-1])]
    for j in _interior_extrema(xs, ts):
        sign = 1.0 if xs[j] > xs[j - 1] else -1.0  # a maximum: minimise −x
        res = minimize_scalar(lambda t, sign=sign: -sign * _axis_x(r, a, delta, t)[0], bounds=(ts[j - 1], ts[j + 1]),
                              method="bounded", options=dict(xatol=1e-13))
        out.append((float(res.x), -sign * float(res.fun)))
    return sorted(out)


def _alternation(ext, E, Y, rtol=1e-6):
    """The touches of Y ± E among the extremes, with consecutive same-side touches merged: (t, side)."""
    touches = []
    for t, x in ext:
        side = np.sign(x - Y)
        if abs(abs(x - Y) - E) <= rtol * E + 1e-15 and (not touches or touches[-1][1] != side):
            touches.append((t, side))
    return touches


def straight_guiding(delta: float, a: float, dwell: float) -> StraightGuide:
    """Straight-line lambda mechanism (R → ∞): the minimax (equal-ripple) straight band of x(t) = (D − C)·e
    over the half dwell t ∈ [0, α] (the other half is its mirror image).

    The free parameters are r and the line's offset Y. E(r) = (max x − min x)/2 over t = 0, α and the
    interior extremes of x is minimised by scipy's bounded scalar search from a scan of r over the
    full-rotation range. Where E(r) has a kink at its minimum the band touches Y ± E alternately at three
    (or more) points (Chebyshev's alternation) and r is polished on the equations of that pattern (x equal
    at the same-side touches, x' = 0 at the interior ones); where E(r) is smooth there (dE/dr = 0, the
    family is not Haar) two alternate touches suffice. ``touches`` lists them (thesis angles t ≥ 0).
    Chebyshev's lambda (δ = π, a = 0.8) comes out r = 0.4 for every 2α from 180° to 208.955°
    (x(0) = x(±90°) = 1.6, x'(±90°) = 0, E = 1.9507·10⁻³).

    Parameters
    ----------
    delta : float
        Break angle δ of the lambda mechanism (rad), in (0, 2π).
    a : float
        Frame length l_OC (units of l), in (0, 2).
    dwell : float
        The dwell's crank angle 2α (rad), in (0, 2π].

    Returns
    -------
    StraightGuide
        The design: crank r, the line's offset Y and half-width E (units of l), and the touches.

    Raises
    ------
    SynthesisError
        No minimum of E(r) inside the crank's range, 2α = 360°, or a ≥ 2.
    DimensionError
        δ, a or 2α out of range.

    Examples
    --------
    >>> import numpy as np
    >>> import mechlab as ml
    >>> guide = ml.straight_guiding(np.pi, 0.8, np.pi)  # Chebyshev's lambda
    >>> round(guide.r, 6), round(guide.E, 7)
    (0.4, 0.0019507)
    """
    delta, a, dwell = _check_inputs(delta, a, dwell, "straight-line guiding")
    alpha = dwell / 2
    hi = min(a, 2 - a)
    if alpha >= np.pi:
        raise SynthesisError(f"straight-line guiding needs a dwell 2α < 360°, got {np.degrees(dwell):.4g}°")
    ts = np.linspace(0.0, alpha, 401)
    rs = np.linspace(hi * 1e-3, hi * (1 - 1e-3), 300)
    xs = _axis_x(rs[:, None], a, delta, ts[None, :])[0]
    spread = 0.5 * (xs.max(1) - xs.min(1))

    def half_spread(r):
        x = np.array([v for _, v in _extremes(r, a, delta, alpha)])
        return 0.5 * float(x.max() - x.min())

    best = None
    for i in _interior_extrema(spread, rs):
        if spread[i] > spread[i - 1]:
            continue  # a local maximum of the sampled spread
        res = minimize_scalar(half_spread, bounds=(rs[i - 1], rs[i + 1]), method="bounded",
                              options=dict(xatol=1e-14))
        if best is None or res.fun < best[1]:
            best = (float(res.x), float(res.fun))
    if best is None:
        raise SynthesisError(
            f"no straight-line lambda mechanism for δ = {np.degrees(delta):.4g}°, a = {a:.4g}, "
            f"2α = {np.degrees(dwell):.4g}°: the band's half-width E(r) has no minimum inside the crank's range "
            f"(0, {hi:.4g}) (it falls towards the rotation limit or towards r = 0)")
    r = _polish_straight(delta, a, alpha, best[0])
    ext = _extremes(r, a, delta, alpha)
    x = np.array([v for _, v in ext])
    Y, E = 0.5 * float(x.max() + x.min()), 0.5 * float(x.max() - x.min())
    touches = _alternation(ext, E, Y, rtol=1e-5)
    return StraightGuide(delta, a, dwell, r, Y, E, tuple(t for t, _ in touches))


def _polish_straight(delta, a, alpha, r):
    """Solve the equal-ripple equations of the alternation pattern found at r; keeps r if that fails
    or makes the band wider."""
    ext = _extremes(r, a, delta, alpha)
    x = np.array([v for _, v in ext])
    Y, E = 0.5 * (x.max() + x.min()), 0.5 * (x.max() - x.min())
    pattern = _alternation(ext, E, Y, rtol=1e-4)[:3]
    if len(pattern) < 3:
        return r
    inner = [i for i, (t, _) in enumerate(pattern) if 0 < t < alpha]

    def eqs(y):
        tt = [t for t, _ in pattern]
        for i, v in zip(inner, y[1:], strict=False):
            tt[i] = v
        X, dX = _axis_x(y[0], a, delta, np.array(tt))
        return [X[0] - X[2], *dX[inner]]

    sol = root(eqs, [r, *(pattern[i][0] for i in inner)], method="hybr", options=dict(xtol=1e-15))
    if not np.all(np.isfinite(sol.x)) or np.max(np.abs(eqs(sol.x))) > 1e-12 or not 0 < sol.x[0] < min(a, 2 - a):
        return r
    if inner == [1]:  # touches at 0 and α on one side: x(0) = x(α) involves r alone, bracket it to the last bit
        def ends(rr):
            X = LambdaMechanism(rr, a, delta).axis_coordinates(np.pi + np.array([0.0, alpha]))[0]
            return X[0] - X[1]
        lo, hi = sol.x[0] * (1 - 1e-9), sol.x[0] * (1 + 1e-9)
        if ends(lo) * ends(hi) < 0:
            sol.x[0] = brentq(ends, lo, hi, xtol=1e-16, rtol=4 * np.finfo(float).eps)
    def width(rr):
        return np.ptp([v for _, v in _extremes(rr, a, delta, alpha)])

    return float(sol.x[0]) if width(sol.x[0]) <= width(r) * (1 + 1e-9) else r
@validated
def band_touches(deviation: Annotated[np.ndarray, Spec("samples", lo=1, hi=MAX_SAMPLES)],
                 E: Annotated[float, number(0.0)], rtol: Annotated[float, number(0.0, 1.0)] = 1e-6) -> np.ndarray:
    """Indices where a sampled deviation reaches ±E (local extrema of |dev| within rtol·E of E).

    Used by the tests to find a band's touches rather than assume them.

    Parameters
    ----------
    deviation : array_like
        Sampled deviation from the band's middle (units of l).
    E : float
        The band's half-width, ≥ 0.
    rtol : float
        Relative tolerance on E, in [0, 1] (default 1e-6).

    Returns
    -------
    numpy.ndarray of int
        The indices of the touches (the ends included where they touch).

    Raises
    ------
    DimensionError
        ``deviation`` not finite samples, or ``E`` or ``rtol`` out of range.

    Examples
    --------
    >>> import numpy as np
    >>> import mechlab as ml
    >>> guide = ml.circle_guiding(np.radians(150), 0.9, np.radians(120))
    >>> t = np.linspace(-guide.alpha, guide.alpha, 2001)
    >>> touches = ml.band_touches(guide.deviation(np.pi + t), guide.E, 1e-4)
    >>> np.round(np.degrees(t[touches]), 1).tolist()  # seven alternating touches (Chebyshev)
    [-60.0, -51.7, -29.5, 0.0, 29.5, 51.7, 60.0]
    """
    dev = np.asarray(deviation)
    idx = [0] + list(_interior_extrema(dev, np.arange(len(dev)))) + [len(dev) - 1]
    return np.array([i for i in idx if abs(abs(dev[i]) - E) <= rtol * E + 1e-15])


# --------------------------------------------------------------------------------------------
# Existence map (Kinitsky, 1994, Fig. 2a)
# --------------------------------------------------------------------------------------------
def rotation_boundary(n: int = 101) -> tuple[np.ndarray, np.ndarray]:
    """Full-rotation limit in the (r, a) plane: r = a (a ≤ 1) and r = 2 − a (a ≥ 1); (r, a) arrays."""
    a = np.linspace(0.0, 2.0, n)
    return np.minimum(a, 2 - a), a


TransmissionAngle = Annotated[float, angle(0.0, np.pi, open=True)]


@dataclass(frozen=True)
class TransmissionLines:
    """The lines μ = μ_min and μ = μ_max in the (r, a) plane, each a pair of arrays (r, a)."""

    mu_min: tuple[np.ndarray, np.ndarray]
    mu_max: tuple[np.ndarray, np.ndarray]


@validated
def transmission_lines(mu_min: TransmissionAngle = np.pi / 6, mu_max: TransmissionAngle = 5 * np.pi / 6,
                       n: Annotated[int, count(2, MAX_SAMPLES)] = 101) -> TransmissionLines:
    """Working region of the base four-bar: μ = ∠ABC ranges over [2 asin(|a−r|/2), 2 asin((a+r)/2)],
    so μ ≥ μ_min is the line a − r = 2 sin(μ_min/2) and μ ≤ μ_max is a + r = 2 sin(μ_max/2).

    Parameters
    ----------
    mu_min, mu_max : float
        Transmission angle limits (rad), in (0, π), μ_min < μ_max (default 30° and 150°).
    n : int
        Points per line, ≥ 2 (default 101).

    Returns
    -------
    TransmissionLines
        ``mu_min`` and ``mu_max``, each a pair of arrays (r, a).

    Raises
    ------
    DimensionError
        A limit out of range, μ_min ≥ μ_max, or ``n`` < 2.

    Examples
    --------
    >>> import mechlab as ml
    >>> lines = ml.transmission_lines(n=3)
    >>> [round(float(a), 4) for a in lines.mu_min[1]]  # a = r + 2 sin(15°)
    [0.5176, 1.0176, 1.5176]
    """
    if mu_min >= mu_max:
        raise DimensionError(f"mu_min must be < mu_max, got {np.degrees(mu_min):.4g}° ≥ {np.degrees(mu_max):.4g}°")
    s1, s2 = 2 * np.sin(mu_min / 2), 2 * np.sin(mu_max / 2)
    r = np.linspace(0.0, 1.0, n)
    return TransmissionLines((r, r + s1), (r, s2 - r))


def fifth_order_line(delta: float, n: int = 200) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Fifth-order contact of the coupler curve with a circle at D0 (2α → 0, E = 0; line AN of Fig. 2a).

    ρ² about Q = C + c·e is F(μ) = ρ_C² + c² − (c/a)(ρ_C d + g ρ_C/d) with d = 2 sin(μ/2),
    ρ_C = 2 sin((δ − μ)/2), g = a² − r². As μ − μ0 ∝ t² near t = 0, six-point contact at
    D0 means F'(μ0) = F''(μ0) = 0: linear in w = a/c and g, then a + r = 2 sin(μ0/2)
    and a − r = g/(a + r).

    Parameters
    ----------
    delta : float
        Break angle δ (rad), in (0, 2π).
    n : int
        Samples of μ0 ∈ (0, δ), ≥ 2 (default 200).

    Returns
    -------
    r, a, k : numpy.ndarray
        The line's points where the crank turns fully, and k = 1/c (0 where the contact circle is
        a straight line).

    Raises
    ------
    DimensionError
        ``delta`` or ``n`` out of range.

    Examples
    --------
    >>> import numpy as np
    >>> import mechlab as ml
    >>> r, a, k = ml.fifth_order_line(np.radians(150), 5)
    >>> np.round(r, 4).tolist(), np.round(a, 4).tolist()
    ([0.0005, 0.218], [0.0005, 0.4254])
    """
    delta = _angle("δ", delta, 0.0, 2 * np.pi, closed_hi=False)
    n = int(_bounded("n", n, 2, MAX_SAMPLES))
    r, a, k, ok = _fifth_terms(delta, np.linspace(1e-3, delta - 1e-3, n))
    return r[ok], a[ok], k[ok]


def _fifth_terms(delta, mu):
    """(r, a, k, ok) of the fifth-order contact at μ0 = mu (closed form, :func:`fifth_order_line`);
    ok where the crank turns fully."""
    with np.errstate(divide="ignore", invalid="ignore"):  # k → ±∞ where the line meets r = 0 at μ0 → 0
        return _fifth_closed(delta, mu)


def _fifth_closed(delta, mu):
    u, v = (delta - mu) / 2, mu / 2
    rc, drc, ddrc = 2 * np.sin(u), -np.cos(u), -0.5 * np.sin(u)
    d, dd, ddd = 2 * np.sin(v), np.cos(v), -0.5 * np.sin(v)
    f1, f2 = 2 * rc * drc, 2 * drc**2 + 2 * rc * ddrc
    h1a, h1b = drc * d + rc * dd, ddrc * d + 2 * drc * dd + rc * ddd
    h2a = (drc * d - rc * dd) / d**2
    h2b = ddrc / d - 2 * drc * dd / d**2 - rc * ddd / d**2 + 2 * rc * dd**2 / d**3
    # w·F' = h1 + g·h2 at first and second order (F' = f − (c/a)(h1 + g h2) = 0, w = a/c)
    det = -f1 * h2b + h2a * f2
    w = (-h1a * h2b + h2a * h1b) / det
    g = (f1 * h1b - f2 * h1a) / det
    a = 0.5 * (d + g / d)
    r = 0.5 * (d - g / d)
    return r, a, w / a, (r > 0) & (r < a) & (r + a < 2)


@dataclass(frozen=True)
class WholeTurnLine:
    """Points of the whole-turn boundary (2α = 360°) in the (r, a) plane, with the band's centre
    offset c (Q = C + c·e) and the touch angles t3 < t2 of each point (arrays)."""

    r: np.ndarray
    a: np.ndarray
    c: np.ndarray
    t3: np.ndarray
    t2: np.ndarray


def _whole_turn_eqs(delta):
    """Equal ripple over the whole turn, unknowns y = (r, a, κ, t3, t2) with κ = 1/c.

    ρ² about Q = C + e/κ is |w|² − 2x/κ + 1/κ² (w = D − C, x = w·e), so ρ(u) = ρ(v) ⇔
    κ(|w(u)|² − |w(v)|²) − 2(x(u) − x(v)) = 0 and ρ'(t) = 0 ⇔ κ·(|w|²)' − 2x' = 0: smooth through
    κ = 0 (a straight band), unlike the (r, c) form used for shorter dwells. The touches are
    ρ(0) = ρ(t2) = R0, ρ(t3) = ρ(π) = R1 with ρ'(t3) = ρ'(t2) = 0; ρ'(π) = 0 by symmetry."""
    def eqs(y):
        r, a, k, t3, t2 = y
        try:
            m = LambdaMechanism(r, a, delta)
            D = m.motion(np.pi + np.array([0.0, t3, t2, np.pi])).points["D"]
        except MechanismError:
            return np.full(4, 1e3)
        w, e = D.p - m.C, m.axis
        P, dP, X, dX = (w * w).sum(1), 2 * (w * D.d).sum(1), w @ e, D.d @ e
        return np.array([k * (P[0] - P[2]) - 2 * (X[0] - X[2]), k * (P[1] - P[3]) - 2 * (X[1] - X[3]),
                         k * dP[1] - 2 * dX[1], k * dP[2] - 2 * dX[2]])
    return eqs


def whole_turn_line(delta: float, ds: float = 0.02, r_start: float = 0.005) -> WholeTurnLine:
    """The boundary "the whole coupler curve approximated by a circle", α = π (Kinitsky, 1994, text
    before (12), boundary 2, lines KU and AP of Fig. 2a).

    On it the equal-ripple circle fit of :func:`circle_guiding` spans the whole crank turn: ρ
    touches R0 at t = 0 and ±t2, R1 at ±t3 and at t = π (6 alternating touches round the closed
    curve). The generic solver cannot get there (continuation in α from the fifth-order contact
    collapses to r → 0 as 2α → 360°), so this is a dedicated solve (:func:`_whole_turn_eqs`),
    traced by pseudo-arclength continuation (step ``ds`` in (r, a, κ, t3, t2)) from r = ``r_start``
    near the point A = (r → 0, a → 2 sin(δ/4)), where it meets the fifth-order line (found
    numerically: there κ → 1/a, t3 → 60°, t2 → 120°), until it leaves the crank-rocker region:
    on r = a for δ < 120°, at (1, 1) for δ = 120° and on r + a = 2 for δ > 120°.
    For a < 1 beyond that end the iso-dwell lines crowd onto r = a instead (2α → 360° as r → a).

    Parameters
    ----------
    delta : float
        Break angle δ (rad), in (0, 2π).
    ds : float
        Continuation step, in [1e-3, 0.2] (default 0.02).
    r_start : float
        Crank r of the first point, in [1e-4, 0.05] (default 0.005).

    Returns
    -------
    WholeTurnLine
        The line's r, a, band offset c and touch angles t3, t2 (arrays).

    Raises
    ------
    SynthesisError
        No whole-turn line starts near r = 0.
    DimensionError
        An argument out of range.

    Examples
    --------
    >>> import numpy as np
    >>> import mechlab as ml
    >>> line = ml.whole_turn_line(np.radians(150), ds=0.1)
    >>> round(float(line.a.max()), 4)  # the point A: a = 2 sin(δ/4)
    1.2175
    """
    delta = _angle("δ", delta, 0.0, 2 * np.pi, closed_hi=False)
    ds = _bounded("ds", ds, 1e-3, 0.2)
    r_start = _bounded("r_start", r_start, 1e-4, 0.05)
    eqs = _whole_turn_eqs(delta)
    a0 = 2 * np.sin(delta / 4)
    pts, guess = [], np.array([a0, 1 / a0, np.pi / 3, 2 * np.pi / 3])
    for r in (r_start, 2 * r_start):
        sol = root(lambda z, r=r: eqs([r, *z]), guess, method="hybr", options=dict(xtol=1e-13))
        if np.max(np.abs(eqs([r, *sol.x]))) > 1e-10:
            raise SynthesisError(f"no whole-turn circle-guiding line found for δ = {np.degrees(delta):.4g}° "
                                 f"near r = 0, a = 2 sin(δ/4) = {a0:.4g}")
        guess = sol.x
        pts.append(np.r_[r, sol.x])
    for _ in range(int(np.ceil(MAX_ARC / ds))):
        tan = pts[-1] - pts[-2]
        tan /= np.linalg.norm(tan)

        def aug(y, tan=tan, y0=pts[-1]):
            return [*eqs(y), (y - y0) @ tan - ds]

        y = root(aug, pts[-1] + ds * tan, method="hybr", options=dict(xtol=1e-13)).x
        r, a, k, t3, t2 = y
        if (np.max(np.abs(aug(y))) > 1e-10 or not 0 < t3 < t2 < np.pi or not 1e-3 < r < min(a, 2 - a)
                or k <= 0):
            break
        pts.append(y)
    y = np.array(pts)
    return WholeTurnLine(y[:, 0], y[:, 1], 1 / y[:, 2], y[:, 3], y[:, 4])


def whole_turn_guiding(delta: float, a: float, line: WholeTurnLine | None = None) -> CircleGuide:
    """The circle-guiding design with 2α = 360° for frame a: the point of :func:`whole_turn_line`
    at that a, polished by a solve at fixed a; a CircleGuide with dwell = 2π whose band holds D over
    the whole turn (checked on 4001 points).

    Parameters
    ----------
    delta : float
        Break angle δ (rad), in (0, 2π).
    a : float
        Frame length (units of l), in (0, 2).
    line : WholeTurnLine, optional
        The already traced :func:`whole_turn_line` of this δ (saves tracing it again).

    Returns
    -------
    CircleGuide
        The design with dwell 2π.

    Raises
    ------
    SynthesisError
        The line misses a, the solve does not converge or the fit leaves its band.
    DimensionError
        δ or a out of range.
    TypeError
        ``line`` is not a WholeTurnLine.

    Examples
    --------
    >>> import numpy as np
    >>> import mechlab as ml
    >>> delta = np.radians(150)
    >>> guide = ml.whole_turn_guiding(delta, 1.2, line=ml.whole_turn_line(delta, ds=0.1))
    >>> round(guide.r, 5), round(guide.E, 5)
    (0.37827, 0.04855)
    """
    delta, a, _ = _check_inputs(delta, a, 2 * np.pi, "whole-turn circle guiding")
    line = whole_turn_line(delta) if line is None else check_value("line", line, mechanism(WholeTurnLine))
    i = np.nonzero(np.sign(line.a[1:] - a) * np.sign(line.a[:-1] - a) <= 0)[0]
    if len(i) == 0:
        raise SynthesisError(
            f"no whole-turn circle-guiding lambda mechanism for δ = {np.degrees(delta):.4g}°, a = {a:.4g}: the "
            f"line 2α = 360° spans a ∈ [{line.a.min():.4g}, {line.a.max():.4g}]")
    i = i[0]
    w = (a - line.a[i]) / (line.a[i + 1] - line.a[i])
    x0 = [(1 - w) * v[i] + w * v[i + 1] for v in (line.r, 1 / line.c, line.t3, line.t2)]
    eqs = _whole_turn_eqs(delta)
    sol = root(lambda z: eqs([z[0], a, *z[1:]]), x0, method="hybr", options=dict(xtol=1e-14))
    r, k, t3, t2 = (float(v) for v in sol.x)
    if np.max(np.abs(eqs([r, a, k, t3, t2]))) > 1e-10 or not 0 < t3 < t2 < np.pi:
        raise SynthesisError(f"the whole-turn solve did not converge for δ = {np.degrees(delta):.4g}°, a = {a:.4g}")
    g = CircleGuide(delta, a, 2 * np.pi, r, k, t3, t2)
    dense = g.deviation(np.linspace(0, 2 * np.pi, 4001))
    if np.max(np.abs(dense)) > g.E * (1 + 1e-6):
        raise SynthesisError(f"δ = {np.degrees(delta):.4g}°, a = {a:.4g}: the whole-turn fit leaves its band "
                             f"(max |ρ − R| = {np.max(np.abs(dense)):.3g} > E = {g.E:.3g})")
    return g


def existence_region(delta: float, line: WholeTurnLine | None = None) -> tuple[np.ndarray, np.ndarray]:
    """Closed polygon (r, a) of the existence region of Fig. 2a for break angle δ: along the fifth-order
    line (2α → 0) from its lower end (0, a_lo) to A = (0, 2 sin(δ/4)), along the whole-turn line
    (2α = 360°) to the rotation limit, down the rotation limit r = min(a, 2 − a) to a = a_lo, and back to
    (0, a_lo); a_lo = 2 sin((δ − π)/2) for δ > π (where the fifth-order line leaves r = 0), else 0.

    Parameters
    ----------
    delta : float
        Break angle δ (rad), in (0, 2π).
    line : WholeTurnLine, optional
        The already traced :func:`whole_turn_line` of this δ.

    Returns
    -------
    r, a : numpy.ndarray
        The closed polygon's vertices (units of l).

    Raises
    ------
    SynthesisError
        The whole-turn line cannot be traced.
    DimensionError
        ``delta`` out of range.
    TypeError
        ``line`` is not a WholeTurnLine.

    Examples
    --------
    >>> import numpy as np
    >>> import mechlab as ml
    >>> delta = np.radians(150)
    >>> r, a = ml.existence_region(delta, line=ml.whole_turn_line(delta, ds=0.1))
    >>> (float(r[0]), float(a[0])) == (float(r[-1]), float(a[-1])), round(float(a.max()), 4)
    (True, 1.2175)
    """
    r5, a5 = fifth_order_line(delta, 200)[:2]
    wt = whole_turn_line(delta) if line is None else check_value("line", line, mechanism(WholeTurnLine))
    a_lo = _frame_span(delta)[0]
    down = np.linspace(wt.a[-1], a_lo, 60)[1:]
    down = np.sort(np.r_[down, [1.0] if a_lo < 1 < wt.a[-1] else []])[::-1]  # keep the corner (1, 1)
    r = np.r_[0.0, r5, wt.r, np.minimum(down, 2 - down), 0.0]
    a = np.r_[a_lo, a5, wt.a, down, a_lo]
    return r, a


@dataclass(frozen=True)
class ExistenceMap:
    """The curves of Fig. 2a (Kinitsky, 1994) in the (r, a) plane, each a pair of arrays (r, a):
    ``rotation`` (r = a, r + a = 2), ``fifth`` (fifth-order contact), ``whole`` (2α = 360°, all of
    it in ``whole_line``), the closed outline ``region`` of the existence region, the transmission
    lines μ = 30° and 150° (``mu_min``, ``mu_max``) and ``iso_dwell``: one curve per dwell, keyed by
    the dwell in whole degrees."""

    rotation: tuple[np.ndarray, np.ndarray]
    fifth: tuple[np.ndarray, np.ndarray]
    whole: tuple[np.ndarray, np.ndarray]
    whole_line: WholeTurnLine
    region: tuple[np.ndarray, np.ndarray]
    mu_min: tuple[np.ndarray, np.ndarray]
    mu_max: tuple[np.ndarray, np.ndarray]
    iso_dwell: dict


def existence_map(delta: float, dwells=(np.radians(60), np.radians(120), np.radians(180), np.radians(240)),
                  n: int = 25) -> ExistenceMap:
    """The curves of Fig. 2a for break angle δ (:class:`ExistenceMap`); the iso-dwell curves by
    continuation in a, the whole-turn line by :func:`whole_turn_line`, the region by
    :func:`existence_region`.

    Parameters
    ----------
    delta : float
        Break angle δ (rad), in (0, 2π).
    dwells : array_like
        Dwells 2α (rad) of the iso-dwell curves (default 60°, 120°, 180°, 240°).
    n : int
        Frames a per iso-dwell curve, in [2, MAX_ISO_POINTS] (default 25).

    Returns
    -------
    ExistenceMap
        The curves, each a pair of arrays (r, a); ``iso_dwell`` keyed by the dwell in degrees.

    Raises
    ------
    SynthesisError
        The whole-turn line cannot be traced.
    DimensionError
        An argument out of range.

    Examples
    --------
    >>> import numpy as np
    >>> import mechlab as ml
    >>> curves = ml.existence_map(np.radians(150), dwells=(np.radians(120),), n=3)
    >>> list(curves.iso_dwell), np.round(curves.iso_dwell[120][0], 4).tolist()
    ([120], [0.0441, 0.1625])
    """
    delta = _angle("δ", delta, 0.0, 2 * np.pi, closed_hi=False)
    n = int(_bounded("n", n, 2, MAX_ISO_POINTS))
    dwells = [_angle("dwell 2α", w, 0.0, 2 * np.pi)
              for w in np.atleast_1d(check_value("dwells", dwells, Spec("reals")))]
    line = whole_turn_line(delta)
    mu = transmission_lines()
    iso = {round(float(np.degrees(w))): _iso_dwell(delta, w, n) for w in dwells}
    return ExistenceMap(rotation_boundary(), fifth_order_line(delta)[:2], (line.r, line.a), line,
                        existence_region(delta, line), mu.mu_min, mu.mu_max, iso)


def _iso_dwell(delta, dwell, n):
    """r(a) along one iso-dwell line by continuation in a (a fresh minimax start only when the
    previous point failed)."""
    rs, as_ = [], []
    guess = None
    for a in np.linspace(0.05, 1.95, n):
        try:
            g = circle_guiding(delta, a, dwell, guess=guess, minimax=False)
        except MechanismError:
            try:
                g = circle_guiding(delta, a, dwell, minimax=False) if guess is not None else None
            except MechanismError:
                g = None
        if g is None:
            guess = None
            continue
        guess = (g.r, g.k, g.t3, g.t2)
        rs.append(g.r)
        as_.append(a)
    return np.array(rs), np.array(as_)

