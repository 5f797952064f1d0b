"""The symmetric lambda mechanism of Chebyshev and its circle- and straight-line-guiding synthesis.

Source: seed 001 (Ya.T. Kinitsky, thesis abstract, Khmelnytskyi 1994), chapter 1,
Fig. 1a-b and formulas (1)-(13). The OCR of (2)-(11) is unreadable; everything here
is re-derived from the geometry the text describes and checked numerically.

Geometry (seed 001, Fig. 1a): crank O-A (length r), coupler A-B-D, rocker B-C with
l_AB = l_BC = l_BD = l = 1 (all lengths in units of l), frame O-C of length a, coupler
break angle δ = ∠ABD. Frame of this module: O = (0, 0), C = (a, 0); φ is measured
counter-clockwise from the ray O→C (as in :class:`mechlab.mechanisms.FourBar`), so A is
farthest from C, |CA| = a + r, at φ = π; the thesis' crank angle measured from that
position is t = φ − π.

Derivation (the key to the whole chapter). B is equidistant (= 1) from A, C and D, so A,
C, D lie on the unit circle about B. With μ = ∠ABC (the transmission angle of the
four-bar O-A-B-C): |CA| = 2 sin(μ/2), and in the thesis' assembly C lies on the arc AD
of central angle δ, so the inscribed angle ∠ACD = π − δ/2 is *constant* and
|CD| = 2 sin((δ − μ)/2). Hence D is the image of A under a rotation about C by the fixed
angle −(π − δ/2) and a scaling that depends on |CA| only:

    D − C = [sin((δ − μ)/2) / sin(μ/2)] · Rot(−(π − δ/2)) (A − C).          (*)

Since A(π + t) and A(π − t) are mirror images in the line OC with the same |CA|, D(π + t)
and D(π − t) are mirror images in the line through C whose ray C→D0 makes π − δ/2 with the
ray C→O (D0 = D(π)): the coupler curve is symmetric about that axis, as the thesis states,
and the motion along it is symmetric in time about φ = π too. (For δ > π the coupler is bent
the other way; the same formulas hold, and the thesis' table uses δ up to 270°.)
The distance of D from any point Q = C + c·e on the axis is then a function of μ alone.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.optimize import brentq, minimize, root
from ..errors import MechanismError
from ..geometry import check_length, perp
from ..errors import SynthesisError
from ..mechanisms.lambda_mechanism import GuidedLambda, LambdaMechanism, _angle

__all__ = ["CircleGuide", "StraightGuide", "circle_guiding", "straight_guiding", "thesis_iteration", "fifth_order_line",
           "existence_map", "rotation_boundary", "transmission_lines", "band_touches", "WholeTurnLine", "ExistenceMap",
           "TransmissionLines", "whole_turn_line", "whole_turn_guiding", "existence_region"]


# --------------------------------------------------------------------------------------------
# Circle-guiding synthesis
# --------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class CircleGuide:
    """Equal-ripple circle-guiding design (seed 001, Fig. 1b, formulas (1), (9)-(11)).

    Lengths in units of l. ``c`` is the distance C→Q of the arc centre Q along the axis
    e (towards D0); R0 is the radius touched at the axis point D0 (φ = π) and at ±t2,
    R1 the one touched at ±t3 and reached again at the dwell ends ±α, where D leaves the
    band; R = (R0 + R1)/2, E = |R0 − R1|/2. Touch angles t are thesis angles t = φ − π.
    """

    delta: float
    a: float
    dwell: float
    r: float
    c: float
    R0: float
    R1: float
    t3: float
    t2: float

    @property
    def R(self) -> float:
        return 0.5 * (self.R0 + self.R1)

    @property
    def E(self) -> float:
        return 0.5 * abs(self.R0 - self.R1)

    @property
    def alpha(self) -> float:
        return 0.5 * self.dwell

    @property
    def mechanism(self) -> LambdaMechanism:
        return LambdaMechanism(self.r, self.a, self.delta)

    @property
    def centre(self) -> np.ndarray:
        m = self.mechanism
        return m.C + self.c * m.axis

    @property
    def guided(self) -> "GuidedLambda":
        """The mechanism with its band attached (drawn by :mod:`mechlab.draw.chebyshev`)."""
        q = self.centre
        return GuidedLambda(self.r, self.a, self.delta, 1, float(q[0]), float(q[1]), self.R0, self.R1, self.dwell)

    def deviation(self, phi) -> np.ndarray:
        """ρ(φ) − R: the signed distance of D from the mean circle."""
        return self.mechanism.radius_about(self.centre, phi)[0] - self.R


@dataclass(frozen=True)
class StraightGuide:
    """Equal-ripple straight-line guide (R → ∞): D's coordinate x along the axis stays within
    Y ± E over the dwell, touching Y ± E alternately at t = 0, ±t1 and ±α."""

    delta: float
    a: float
    dwell: float
    r: float
    Y: float
    E: float
    t1: float

    @property
    def mechanism(self) -> LambdaMechanism:
        return LambdaMechanism(self.r, self.a, self.delta)

    def deviation(self, phi) -> np.ndarray:
        return self.mechanism.axis_coordinates(phi)[0] - self.Y


def _make(r, a, delta):
    return LambdaMechanism(r, a, delta)


def _rho(r, c, a, delta, t):
    """ρ = |D − Q| and dρ/dt at thesis angles t (Q = C + c·e), through μ(t) (closed form, fast)."""
    m = _make(r, a, delta)
    t = np.asarray(t, dtype=float)
    d = np.sqrt(a * a + r * r + 2 * a * r * np.cos(t))
    mu = 2 * np.arcsin(np.clip(d / 2, 0, 1))
    dmu = (-a * r * np.sin(t) / d) / np.cos(mu / 2)
    rho, drho = _rho_mu(m, c, mu)
    with np.errstate(invalid="ignore"):
        return rho, drho * dmu


def _curvature_offset(r, a, delta) -> float:
    """Distance from C along the axis to the centre of curvature of the coupler curve at D0."""
    m = _make(r, a, delta)
    D = m.motion(np.array([np.pi])).points["D"]
    d, dd = D.d[0], D.dd[0]
    kappa = (d[0] * dd[1] - d[1] * dd[0]) / np.hypot(*d) ** 3
    n = perp(d / np.hypot(*d))
    centre = D.p[0] + n / kappa
    return float((centre - m.C) @ m.axis)


def _interior_extrema(f, t):
    """Indices of the interior local extrema of samples f over t."""
    df = np.diff(f)
    return np.nonzero(np.sign(df[1:]) * np.sign(df[:-1]) < 0)[0] + 1


def _initial_r(a: float) -> float:
    # seed 001, text after (13): r0 = a/4 (0 < a < 1) or (2 − a)/4 (1 < a < 2)
    return a / 4 if a < 1 else (2 - a) / 4


def _check_inputs(delta, a, dwell, what):
    delta = _angle("δ", delta, 0.0, 2 * np.pi, closed_hi=False)
    a = check_length("a", a)
    if not a < 2.0:
        raise SynthesisError(f"{what}: a = {a:.6g} ≥ 2 leaves no crank with full rotation (r < 2 − a)")
    dwell = _angle("dwell 2α", dwell, 0.0, 2 * np.pi)
    return delta, a, dwell


def _fifth_point(delta: float, a: float):
    """(r, c) of the fifth-order-contact mechanism with frame a (None if the line misses a)."""
    r5, a5, c5 = fifth_order_line(delta, 801)
    if len(a5) < 2:
        return None
    i = np.nonzero(np.sign(a5[1:] - a) * np.sign(a5[:-1] - a) <= 0)[0]
    if len(i) == 0:
        return None
    i = i[0]
    w = (a - a5[i]) / (a5[i + 1] - a5[i])
    return r5[i] + w * (r5[i + 1] - r5[i]), c5[i] + w * (c5[i + 1] - c5[i])


def _continuation_guess(delta, a, alpha, eqs_at):
    """Follow the equal-ripple solution from the fifth-order contact (2α → 0) up to α."""
    start = _fifth_point(delta, a)
    if start is None:
        return None
    for first in (25.0, 15.0, 8.0):  # the first step's size matters; try a few
        x = _follow(eqs_at, start, alpha, min(alpha, np.radians(first)))
        if x is not None:
            return x
    return None


def _merged(t3, t2, alpha) -> bool:
    """Touches closer than 0.1 % of α are one touch: a degenerate solution, not equal ripple."""
    return min(t3, t2 - t3, alpha - t2) < 1e-3 * alpha


def _follow(eqs_at, start, alpha, a0):
    x = np.array([start[0], start[1], 0.5 * a0, np.sqrt(3) / 2 * a0])
    prev = a0
    for al in np.linspace(a0, alpha, max(2, int(np.ceil((alpha - a0) / np.radians(6.0))) + 1)):
        x[2:] *= al / prev  # keep the touch angles in proportion to the dwell
        sol = root(lambda y: eqs_at(y, al), x, method="hybr", options=dict(xtol=1e-13))
        if not np.all(np.isfinite(sol.x)) or not 0 < sol.x[2] < sol.x[3] < al or _merged(sol.x[2], sol.x[3], al):
            return None
        x, prev = sol.x, al
    return tuple(x)


def _minimax_guess(delta, a, alpha):
    """Nelder-Mead on (r, c) minimising the spread of ρ over the dwell (fallback start)."""
    ts = np.linspace(0.0, alpha, 121)

    def spread(x):
        r, c = x
        try:
            rho, _ = _rho(r, c, a, delta, ts)
        except MechanismError:
            return 1e3
        return float(rho.max() - rho.min())

    r0 = _initial_r(a)
    try:
        c0 = _curvature_offset(r0, a, delta)
    except MechanismError:
        c0 = 0.0
    best = minimize(spread, [r0, c0], method="Nelder-Mead", options=dict(xatol=1e-6, fatol=1e-12, maxiter=400))
    r0, c0 = best.x
    try:
        rho, _ = _rho(r0, c0, a, delta, ts)
        ext = _interior_extrema(rho, ts)
    except MechanismError:
        ext = []
    if len(ext) >= 2:
        return r0, c0, ts[ext[0]], ts[ext[-1]]
    return r0, c0, 0.5 * alpha, np.sqrt(3) / 2 * alpha


def _solve_circle(delta, a, dwell, eqs, x0):
    """Solve the equal-ripple equations from x0 and check the result on a dense sample;
    returns (CircleGuide, None) or (None, reason)."""
    alpha = dwell / 2
    sol = root(eqs, x0, method="hybr", options=dict(xtol=1e-13))
    r, c, t3, t2 = (float(v) for v in sol.x)
    if not np.all(np.isfinite(sol.x)) or np.max(np.abs(eqs(sol.x))) > 1e-9:
        return None, f"the equal-ripple equations did not converge ({sol.message.strip()})"
    if not 1e-4 < r:
        return None, f"the crank degenerates (r = {r:.3g})"
    if not 0.0 < t3 < t2 < alpha:
        return None, f"the touch points are out of order (t3 = {np.degrees(t3):.3g}°, t2 = {np.degrees(t2):.3g}°)"
    if _merged(t3, t2, alpha):
        return None, (f"the touch points merge (t3 = {np.degrees(t3):.6g}°, t2 = {np.degrees(t2):.6g}°, "
                      f"α = {np.degrees(alpha):.6g}°)")
    try:
        rho, _ = _rho(r, c, a, delta, [0.0, t3])
        g = CircleGuide(delta, a, dwell, r, c, float(rho[0]), float(rho[1]), t3, t2)
        dense = g.deviation(np.pi + np.linspace(-alpha, alpha, 4001))
    except MechanismError as err:
        return None, str(err)
    if np.max(np.abs(eqs(sol.x)[:2])) > 1e-3 * g.E:  # the radii equal to far less than the ripple
        return None, f"the equations are not solved finely enough to resolve the band E = {g.E:.3g}"
    if np.max(np.abs(dense)) > g.E * (1 + 1e-6) + 1e-12:
        return None, (f"the best circle leaves the band inside the dwell (max |ρ − R| = "
                      f"{np.max(np.abs(dense)):.3g} > E = {g.E:.3g})")
    return g, None


def circle_guiding(delta: float, a: float, dwell: float, *, guess: tuple | None = None,
                   minimax: bool = True) -> CircleGuide:
    """Circle-guiding lambda mechanism for break angle δ, frame a and dwell 2α (radians).

    Finds r, the arc centre Q on the axis and R0, R1 such that ρ(t) = |D − Q| over the dwell
    t ∈ [−α, α] equioscillates: ρ(0) = ρ(±t2) = R0 and ρ(±t3) = ρ(±α) = R1 with ρ'(t3) =
    ρ'(t2) = 0 (four alternating touches on each half, the Chebyshev best approximation with
    the three free parameters r, c, R). Solved with scipy's ``root`` (hybr), started by
    continuation in α from the closed-form fifth-order contact (2α → 0, :func:`fifth_order_line`)
    or, failing that, from a minimax estimate (Nelder-Mead on (r, c)); ``guess`` =
    (r, c, t3, t2) starts from a neighbouring solution instead; ``minimax=False`` skips the
    (slow) Nelder-Mead fallback.
    Raises SynthesisError when no such design exists (outside the existence limits of Fig. 2a).
    """
    delta, a, dwell = _check_inputs(delta, a, dwell, "circle guiding")
    alpha = dwell / 2

    def eqs(x, alpha=alpha):
        r, c, t3, t2 = x
        try:
            rho, drho = _rho(r, c, a, delta, [0.0, t3, t2, alpha])
        except MechanismError:
            return np.full(4, 1e3)
        return [rho[0] - rho[2], rho[1] - rho[3], drho[1], drho[2]]

    starts = [guess] if guess is not None else [lambda: _continuation_guess(delta, a, alpha, eqs)]
    if guess is None and minimax:
        starts.append(lambda: _minimax_guess(delta, a, alpha))
    for start in starts:
        x0 = start() if callable(start) else start
        if x0 is None:
            fail = "no starting point"
            continue
        g, fail = _solve_circle(delta, a, dwell, eqs, x0)
        if fail is None:
            return g
    raise SynthesisError(
        f"no circle-guiding lambda mechanism for δ = {np.degrees(delta):.4g}°, a = {a:.4g}, "
        f"2α = {np.degrees(dwell):.4g}°: {fail}; choose (δ, a, 2α) inside the existence map")


def thesis_iteration(delta: float, a: float, dwell: float, tol: float = 1e-6, maxiter: int = 100):
    """The thesis' own scheme for r (seed 001, (12)-(13)), reconstructed; for comparison only.

    Start from r0 = a/4 (a < 1) or (2 − a)/4 (a > 1). With the current r0, formula (5)
    gives the end angle μ1 of the dwell (sin μ1/2 = ½√(a² + r0² + 2a·r0·cos α)); the
    equal-ripple conditions, written in μ (the curve is a function of μ only), are solved for
    μ0, the centre offset c and μ3, μ2; "formula (6)" sin μ0/2 = (a + r)/2 returns a new
    r1 = 2 sin(μ0/2) − a. Stop when |r1 − r0| ≤ ε = 1e-6 (13), else r0 ← (r0 + r1)/2 (the
    thesis' halving). Returns (r, iterations, history of r0). Agrees with
    :func:`circle_guiding` to about ε where it converges.
    """
    delta, a, dwell = _check_inputs(delta, a, dwell, "thesis iteration")
    alpha = dwell / 2
    r0 = _initial_r(a)
    # the inner equal-ripple solve is warm-started from the shape of the scipy solution
    # (μ0, c, μ3, μ2); the outer loop on r is the thesis' own
    g = circle_guiding(delta, a, dwell)
    inner = np.array([2 * np.arcsin((a + g.r) / 2), g.c, *_mu_at(g.r, a, [g.t3, g.t2])])
    history = [r0]
    for it in range(1, maxiter + 1):
        m = _make(r0, a, delta)
        mu1 = _mu_at(r0, a, [alpha])[0]

        def eqs(x, m=m, mu1=mu1):
            mu0, c, m3, m2 = x
            with np.errstate(invalid="ignore"):
                rho, drho = _rho_mu(m, c, np.array([mu0, m3, m2, mu1]))
            return [rho[0] - rho[2], rho[1] - rho[3], drho[1], drho[2]]

        sol = root(eqs, inner, method="hybr", options=dict(xtol=1e-13))
        if not np.all(np.isfinite(sol.x)):
            break
        inner = sol.x
        r1 = float(2 * np.sin(inner[0] / 2) - a)
        if abs(r1 - r0) <= tol:
            history.append(r1)
            if r1 < 1e-3:
                break  # the degenerate fixed point r → 0 (D at rest), not a design
            return r1, it, history
        r0 = 0.5 * (r0 + r1)
        history.append(r0)
        try:
            _make(r0, a, delta)
        except MechanismError:
            break
    raise SynthesisError(f"the thesis' iteration did not converge for δ = {np.degrees(delta):.4g}°, "
                         f"a = {a:.4g}, 2α = {np.degrees(dwell):.4g}° (last r = {r0:.6g})")


def _mu_at(r, a, t):
    t = np.asarray(t, dtype=float)
    d = np.sqrt(a * a + r * r + 2 * a * r * np.cos(t))
    return 2 * np.arcsin(np.clip(d / 2, 0, 1))


def _rho_mu(m: LambdaMechanism, c: float, mus):
    """ρ = |D − Q| and dρ/dμ as functions of μ (D in the axis frame: x = ρ_C cos β, y = ρ_C sin β)."""
    mus = np.asarray(mus, dtype=float)
    a, r, delta = m.a, m.r, m.delta
    d = 2 * np.sin(mus / 2)
    dd = np.cos(mus / 2)
    rc = 2 * np.sin((delta - mus) / 2)
    drc = -np.cos((delta - mus) / 2)
    k = a * a - r * r
    cb = (k + d * d) / (2 * a * d)
    dcb = (2 * d * dd * 2 * a * d - (k + d * d) * 2 * a * dd) / (2 * a * d) ** 2
    rho2 = rc * rc + c * c - 2 * c * rc * cb
    drho2 = 2 * rc * drc - 2 * c * (drc * cb + rc * dcb)
    with np.errstate(invalid="ignore", divide="ignore"):  # trial points of a solver may be off the curve
        rho = np.sqrt(rho2)
        return rho, drho2 / (2 * rho)


# --------------------------------------------------------------------------------------------
# Straight-line guiding
# --------------------------------------------------------------------------------------------
def straight_guiding(delta: float, a: float, dwell: float) -> StraightGuide:
    """Straight-line lambda mechanism (R → ∞): x(t) = (D − C)·e equioscillates over the dwell.

    Free parameters r and the line's offset Y: three alternation points, x(0) = x(±α) = Y + σE,
    x(±t1) = Y − σE with x'(t1) = 0. Solved by brentq on r for x(0) = x(α) (brackets from a scan
    of r over the full-rotation range), keeping the root whose x has one interior extremum and
    stays within Y ± E over the dwell. Chebyshev's lambda (δ = π, a = 0.8) is the case 2α = 180°:
    x(0) = x(±90°) = 1.6 exactly (and x'(±90°) = 0), so r = 0.4 comes out.
    """
    delta, a, dwell = _check_inputs(delta, a, dwell, "straight-line guiding")
    alpha = dwell / 2
    ts = np.linspace(0.0, alpha, 801)

    def x_of(r, t):
        return _make(r, a, delta).axis_coordinates(np.pi + np.asarray(t))[0]

    def f(r):
        x = x_of(r, [0.0, alpha])
        return x[0] - x[1]

    hi = min(a, 2 - a)
    rs = np.linspace(hi * 1e-3, hi * (1 - 1e-6), 241)
    fs = np.array([f(r) for r in rs])
    for i in np.nonzero(np.sign(fs[1:]) * np.sign(fs[:-1]) <= 0)[0]:
        r = brentq(f, rs[i], rs[i + 1], xtol=1e-15, rtol=4 * np.finfo(float).eps)
        x = x_of(r, ts)
        j = _interior_extrema(x, ts)
        if len(j) != 1:
            continue
        Y, E = 0.5 * (x[0] + x[j[0]]), 0.5 * abs(x[0] - x[j[0]])
        if np.max(np.abs(x - Y)) <= E * (1 + 1e-6) + 1e-12:
            break
    else:
        raise SynthesisError(
            f"no straight-line lambda mechanism for δ = {np.degrees(delta):.4g}°, a = {a:.4g}, "
            f"2α = {np.degrees(dwell):.4g}°: no crank r in (0, {hi:.4g}) makes x(0) = x(α) with one "
            f"alternation inside the dwell")
    m = _make(r, a, delta)
    # polish the interior extremum: x'(t1) = 0
    def dx(t):
        D = m.motion(np.array([np.pi + t])).points["D"]
        return float(D.d[0] @ m.axis)
    t1 = brentq(dx, ts[j[0] - 1], ts[j[0] + 1], xtol=1e-15)
    x0, x1 = x_of(r, [0.0, t1])
    return StraightGuide(delta, a, dwell, float(r), float(0.5 * (x0 + x1)), float(0.5 * abs(x0 - x1)), float(t1))


def band_touches(deviation: np.ndarray, E: float, rtol: float = 1e-6) -> np.ndarray:
    """Indices where a sampled deviation reaches ±E (local extrema of |dev| within rtol·E of E),
    with alternating signs required: used by the tests to find touches rather than assume them."""
    dev = np.asarray(deviation)
    idx = [0] + list(_interior_extrema(dev, np.arange(len(dev)))) + [len(dev) - 1]
    return np.array([i for i in idx if abs(abs(dev[i]) - E) <= rtol * E + 1e-15])


# --------------------------------------------------------------------------------------------
# Existence map (seed 001, Fig. 2a)
# --------------------------------------------------------------------------------------------
def rotation_boundary(n: int = 101) -> tuple[np.ndarray, np.ndarray]:
    """Full-rotation limit in the (r, a) plane: r = a (a ≤ 1) and r = 2 − a (a ≥ 1); (r, a) arrays."""
    a = np.linspace(0.0, 2.0, n)
    return np.minimum(a, 2 - a), a


@dataclass(frozen=True)
class TransmissionLines:
    """The lines μ = μ_min and μ = μ_max in the (r, a) plane, each a pair of arrays (r, a)."""

    mu_min: tuple[np.ndarray, np.ndarray]
    mu_max: tuple[np.ndarray, np.ndarray]


def transmission_lines(mu_min: float = np.radians(30), mu_max: float = np.radians(150),
                       n: int = 101) -> TransmissionLines:
    """Working region of the base four-bar: μ = ∠ABC ranges over [2 asin(|a−r|/2), 2 asin((a+r)/2)],
    so μ ≥ μ_min is the line a − r = 2 sin(μ_min/2) and μ ≤ μ_max is a + r = 2 sin(μ_max/2)."""
    s1, s2 = 2 * np.sin(mu_min / 2), 2 * np.sin(mu_max / 2)
    r = np.linspace(0.0, 1.0, n)
    return TransmissionLines((r, r + s1), (r, s2 - r))


def fifth_order_line(delta: float, n: int = 200) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Fifth-order contact of the coupler curve with a circle at D0 (2α → 0, E = 0; line AN of Fig. 2a).

    ρ² about Q = C + c·e is F(μ) = ρ_C² + c² − (c/a)(ρ_C d + k ρ_C/d) with d = 2 sin(μ/2),
    ρ_C = 2 sin((δ − μ)/2), k = a² − r². As μ − μ0 ∝ t² near t = 0, six-point contact at
    D0 means F'(μ0) = F''(μ0) = 0: linear in p = c/a and q = p·k, then a + r = 2 sin(μ0/2)
    and a − r = k/(a + r). Returns (r, a, c) along the line, parametrised by μ0 ∈ (0, δ).
    """
    delta = _angle("δ", delta, 0.0, 2 * np.pi, closed_hi=False)
    mu = np.linspace(1e-3, delta - 1e-3, n)
    u, v = (delta - mu) / 2, mu / 2
    rc, drc, ddrc = 2 * np.sin(u), -np.cos(u), -0.5 * np.sin(u)
    d, dd, ddd = 2 * np.sin(v), np.cos(v), -0.5 * np.sin(v)
    g1, g2 = 2 * rc * drc, 2 * drc**2 + 2 * rc * ddrc
    h1a, h1b = drc * d + rc * dd, ddrc * d + 2 * drc * dd + rc * ddd
    h2a = (drc * d - rc * dd) / d**2
    h2b = ddrc / d - 2 * drc * dd / d**2 - rc * ddd / d**2 + 2 * rc * dd**2 / d**3
    det = h1a * h2b - h2a * h1b
    p = (g1 * h2b - h2a * g2) / det
    q = (h1a * g2 - g1 * h1b) / det
    k = q / p
    a = 0.5 * (d + k / d)
    r = 0.5 * (d - k / d)
    ok = (r > 0) & (r < a) & (r + a < 2)
    return r[ok], a[ok], (p * a)[ok]


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
            m = _make(r, a, delta)
            D = m.motion(np.pi + np.array([0.0, t3, t2, np.pi])).points["D"]
        except MechanismError:
            return np.full(4, 1e3)
        w, e = D.p - m.C, m.axis
        P, dP, X, dX = (w * w).sum(1), 2 * (w * D.d).sum(1), w @ e, D.d @ e
        return np.array([k * (P[0] - P[2]) - 2 * (X[0] - X[2]), k * (P[1] - P[3]) - 2 * (X[1] - X[3]),
                         k * dP[1] - 2 * dX[1], k * dP[2] - 2 * dX[2]])
    return eqs


def whole_turn_line(delta: float, ds: float = 0.02, r_start: float = 0.005) -> WholeTurnLine:
    """The boundary "the whole coupler curve approximated by a circle", α = π (seed 001, text
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
    """
    delta = _angle("δ", delta, 0.0, 2 * np.pi, closed_hi=False)
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
    for _ in range(2000):
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
    the whole turn (checked on 4001 points). SynthesisError if the line misses a. ``line``: the
    already traced :func:`whole_turn_line` of this δ (saves tracing it again)."""
    delta, a, _ = _check_inputs(delta, a, 2 * np.pi, "whole-turn circle guiding")
    line = whole_turn_line(delta) if line is None else line
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
    c = 1 / k
    rho, _ = _rho(r, c, a, delta, [0.0, t3])
    g = CircleGuide(delta, a, 2 * np.pi, r, c, float(rho[0]), float(rho[1]), t3, t2)
    dense = g.deviation(np.linspace(0, 2 * np.pi, 4001))
    if np.max(np.abs(dense)) > g.E * (1 + 1e-6):
        raise SynthesisError(f"δ = {np.degrees(delta):.4g}°, a = {a:.4g}: the whole-turn fit leaves its band "
                             f"(max |ρ − R| = {np.max(np.abs(dense)):.3g} > E = {g.E:.3g})")
    return g


def existence_region(delta: float, line: WholeTurnLine | None = None) -> tuple[np.ndarray, np.ndarray]:
    """Closed polygon (r, a) of the existence region of Fig. 2a for break angle δ: from O along the
    fifth-order line (2α → 0) to A, along the whole-turn line (2α = 360°) to the rotation limit, then
    along the rotation limit (r + a = 2 to (1, 1) if it ends there, r = a) back to O. Checked for
    δ = 150° (the iso-dwell lines 60°…330° lie inside, 2α → 360° converges onto the whole-turn line);
    for δ = 90° :func:`circle_guiding` does not reach long dwells near that line, so it is unchecked."""
    r5, a5 = fifth_order_line(delta, 200)[:2]
    wt = whole_turn_line(delta) if line is None else line
    r, a = list(r5), list(a5)
    r += list(wt.r)
    a += list(wt.a)
    if wt.a[-1] > 1:  # ends on r + a = 2: along it to the corner (1, 1)
        r.append(1.0)
        a.append(1.0)
    r.append(0.0)
    a.append(0.0)  # along r = a back to O
    return np.array(r), np.array(a)


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
    :func:`existence_region`."""
    delta = _angle("δ", delta, 0.0, 2 * np.pi, closed_hi=False)
    line = whole_turn_line(delta)
    mu = transmission_lines()
    iso = {int(round(np.degrees(w))): _iso_dwell(delta, w, n) for w in dwells}
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
        guess = (g.r, g.c, g.t3, g.t2)
        rs.append(g.r)
        as_.append(a)
    return np.array(rs), np.array(as_)

