"""Dwell six-bars from any four-bar's coupler curve: its best circular arcs and straight runs, fitted minimax on
the vectorised curve, and the dyad (or slotted link) that turns each into a dwell.

The classic route (Hrones and Nelson, 1951; Hartenberg and Denavit, 1964, ch. 8): while a coupler point P runs
along a nearly circular arc of radius R about Q, a rod of length R from P to a joint D leaves D resting at Q,
so a rocker pivoted elsewhere on D dwells; while P runs along a nearly straight line, a slotted link pivoted on
that line dwells. Here the arcs and runs are found on the coupler curve sampled over the crank angle by the
structure builder (:class:`~mechlab.Linkage`), each with its ripple: the half-width of the thinnest annulus
(strip) that holds the curve over the crank interval — the minimax (Chebyshev) fit, not least squares.

Searching: every window of the sampled curve is screened at once, vectorised (an algebraic circle fit (Kasa,
1976) or the principal axis, whose ripple is an upper bound of the minimax one since it is the same
half-range for a suboptimal centre or direction); the best few windows are then fitted exactly (see
:func:`fit_arc`, :func:`fit_run`). Lengths are dimensionless (or mm), angles in radians.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from functools import cached_property
from typing import Annotated

import numpy as np
from scipy.optimize import linprog

from ..errors import CouplerFitError, InfeasibleDesignError, MechanismError
from ..mechanisms.base import FULL_TURN, TWO_PI
from ..mechanisms.linkage import RPR, RRR, Crank, Linkage
from ..validate import Sign, Spec, check_value, count, length, mechanism, number, validated

__all__ = [
    "ArcFit",
    "DwellCheck",
    "RunFit",
    "arc_dwell_sixbar",
    "check_dwell",
    "coupler_arcs",
    "coupler_fourbar",
    "coupler_runs",
    "fit_arc",
    "fit_run",
    "run_dwell_sixbar",
]

N_DEFAULT = 720          # crank-angle samples per turn: 0.5° apart
MAX_RIPPLE = 1e-3        # the longest arc (run) search keeps ripple ≤ 0.1 % of its radius (length) by default
MAX_RADIUS = 10.0        # arcs of radius above 10 × the curve's size are straight runs, not arcs
MIN_POINTS = 5           # a window needs 5 samples: a circle has 3 parameters, a minimax fit 4 alternating touches
MIN_TRANSMISSION = np.radians(15)  # a dyad nearer a dead point is refused: the dwell error outgrows ripple / (b sin μ)
MAX_LP_STEPS = 30        # sequential linear programmes per exact circle fit (2-5 are typical)

LinkageArg = Annotated[Linkage, mechanism(Linkage)]
Samples = Annotated[int, count(8, 100_000)]
Dwell = Annotated[float | None, Spec("angle", 0.0, TWO_PI, open_lo=True, open_hi=True, optional=True)]
Bound = Annotated[float, number(0.0, 1.0, open=True)]
Radius = Annotated[float | None, length(optional=True)]
Count = Annotated[int, count(1, 100)]


# --------------------------------------------------------------------------------------------------------------
# Results
# --------------------------------------------------------------------------------------------------------------
class _OverInterval:
    """A fit over a crank interval: its width, the dwell."""

    crank_interval: tuple

    @property
    def dwell(self) -> float:
        """The crank interval's width (radians).

        Returns
        -------
        float
            stop − start.
        """
        return self.crank_interval[1] - self.crank_interval[0]


@dataclass(frozen=True)
class ArcFit(_OverInterval):
    """A nearly circular arc of a coupler curve: the minimax circle over a crank interval.

    Parameters
    ----------
    centre : tuple of float
        The circle's centre Q (x, y).
    radius : float
        Its radius R.
    extent : float
        The angle the arc subtends at Q (radians): the range of the direction of P − Q over the interval.
    crank_interval : tuple of float
        (start, stop), the crank angles (radians) over which P runs along the arc; start < stop, stop may
        exceed 2π.
    ripple : float
        max |ρ − R| over the interval, ρ = |P − Q| (length): the half-width of the thinnest annulus holding
        the arc.

    Examples
    --------
    >>> import numpy as np
    >>> import mechlab as ml
    >>> lk = ml.coupler_fourbar(1.0, 3.0, 3.0, 4.0, (0.0, 0.0))   # P at the crank pin: a circle about O
    >>> fit = ml.fit_arc(lk, "P", (0.0, np.pi))
    >>> bool(np.allclose(fit.centre, (0, 0))), round(fit.radius, 9), round(fit.extent, 9) == round(np.pi, 9)
    (True, 1.0, True)
    """

    centre: tuple
    radius: float
    extent: float
    crank_interval: tuple
    ripple: float


@dataclass(frozen=True)
class RunFit(_OverInterval):
    """A nearly straight run of a coupler curve: the minimax line (the centre of the thinnest strip) over a crank
    interval.

    Parameters
    ----------
    point : tuple of float
        The middle of the run on the line (x, y).
    direction : float
        The line's direction (radians), the way P travels along it over the interval.
    length : float
        How far P travels along the line (the range of its projection).
    crank_interval : tuple of float
        (start, stop), crank angles (radians), start < stop; stop may exceed 2π.
    ripple : float
        The largest distance of P from the line over the interval (length): half the strip's width.

    Examples
    --------
    >>> import numpy as np
    >>> import mechlab as ml
    >>> lam = ml.coupler_fourbar(0.4, 1.0, 1.0, 0.8, (2.0, 0.0))   # Chebyshev's lambda
    >>> run = ml.fit_run(lam, "P", (np.pi / 2, 3 * np.pi / 2))
    >>> round(run.ripple, 7), round(np.degrees(run.direction) % 180, 6)   # across the lambda's vertical axis
    (0.0019507, 0.0)
    """

    point: tuple
    direction: float
    length: float
    crank_interval: tuple
    ripple: float


@dataclass(frozen=True)
class DwellCheck:
    """What a simulated dwell six-bar does (:func:`check_dwell`).

    Parameters
    ----------
    crank_interval : tuple of float
        The crank interval checked (radians).
    dwell_error : float
        The output's range over the interval: radians for a rocker, length for a slider.
    swing : float
        The output's range over the whole cycle (radians or length).
    transmission : float
        The least transmission angle over the cycle (radians, in [0, π/2]) of all the linkage's RRR dyads
        (μ folded: min(μ, π − μ)); an RPR slot transmits at π/2.
    output : str
        ``"angle"`` or ``"position"``.

    Examples
    --------
    >>> import mechlab as ml
    >>> ml.DwellCheck((1.0, 2.0), 1e-4, 0.5, 0.7, "angle").dwell_error
    0.0001
    """

    crank_interval: tuple
    dwell_error: float
    swing: float
    transmission: float
    output: str


# --------------------------------------------------------------------------------------------------------------
# The four-bar and its sampled curve
# --------------------------------------------------------------------------------------------------------------
@validated
def coupler_fourbar(crank: Annotated[float, length()], coupler: Annotated[float, length()],
                    rocker: Annotated[float, length()], frame: Annotated[float, length()],
                    point: Annotated[tuple, Spec("point")] = (0.0, 0.0), assembly: Sign = 1) -> Linkage:
    """The four-bar O(0, 0)-A-B-E(frame, 0) with the coupler point P, built with the structure builder.

    Parameters
    ----------
    crank, coupler, rocker, frame : float
        |OA|, |AB|, |EB|, |OE| (positive lengths).
    point : (float, float)
        P = (u, v) in the coupler's frame: u along A→B from A, v to its left.
    assembly : {1, -1}
        B on the left (+1) or right of the line A → E.

    Returns
    -------
    Linkage
        ``Linkage({"O": (0, 0), "E": (frame, 0)}, Crank("O", "A", crank)).rrr("A", "E", "B", coupler, rocker,
        assembly, links=("coupler", "rocker")).point("P", "coupler", point)``; its output is the rocker.

    Raises
    ------
    DimensionError
        A length that is not positive and finite, a bad point or assembly.
    AssemblyError
        Lengths that close at no crank angle.

    Examples
    --------
    >>> import mechlab as ml
    >>> lk = ml.coupler_fourbar(1.0, 3.0, 3.0, 4.0, (1.5, 1.0))
    >>> lk.formula(), lk.motion(0.0).points["P"].p.round(6).tolist()
    ('I(crank) → II₂(coupler, rocker)', [0.883975, 1.799038])
    """
    return (Linkage({"O": (0.0, 0.0), "E": (frame, 0.0)}, Crank("O", "A", crank))
            .rrr("A", "E", "B", coupler, rocker, assembly, links=("coupler", "rocker"))
            .point("P", "coupler", point))


@dataclass(frozen=True)
class _Curve:
    """The coupler curve on a uniform crank grid: samples of each reachable range (one periodic range for a full
    turn); ``last[i]`` is the last sample of the range holding sample i."""

    phi: np.ndarray
    z: np.ndarray
    h: float
    periodic: bool
    last: np.ndarray

    @cached_property
    def ext(self) -> np.ndarray:
        """The samples, a periodic curve's twice over: a window is a run of consecutive indices."""
        return np.concatenate([self.z, self.z]) if self.periodic else self.z

    @cached_property
    def origin(self) -> np.ndarray:
        return self.z.mean(0)

    @cached_property
    def sums(self) -> np.ndarray:
        """Prefix sums of 1, x, y, x², xy, y², x³, x²y, xy², y³ (about the curve's mean), a leading row of zeros."""
        x, y = (self.ext - self.origin).T
        powers = np.stack([np.ones_like(x), x, y, x * x, x * y, y * y, x**3, x * x * y, x * y * y, y**3], 1)
        return np.vstack([np.zeros(10), np.cumsum(powers, 0)])

    def window(self, start: int, samples: int) -> np.ndarray:
        return self.ext[start:start + samples]

    def longest(self, starts):
        """The longest window (samples) that fits at each start."""
        if self.periodic:
            return np.full(len(starts), len(self.phi))
        return self.last[starts] - starts + 1

    def interval(self, start, samples) -> tuple[float, float]:
        return float(self.phi[start]), float(self.phi[start] + (samples - 1) * self.h)


def _joint(linkage: Linkage, point: str) -> str:
    point = check_value("point", point, Spec("text"))
    joints = _joints(linkage)
    if point not in joints:
        raise CouplerFitError(f"the linkage has no joint {point!r}; its joints: {', '.join(joints)}")
    return point


def _joints(linkage: Linkage) -> list[str]:
    """The joints of a linkage: its frame points, then those its crank and groups make, in order."""
    return [k for k, _ in linkage.frame] + [j for g in (linkage.driver, *linkage.groups) for j in g.makes()]


def _path(linkage: Linkage, point: str, phi) -> np.ndarray:
    return linkage.motion(np.asarray(phi, dtype=float)).points[point].p


def _sample(linkage: Linkage, point: str, n: int) -> _Curve:
    h = TWO_PI / n
    ranges = linkage.crank_ranges()
    if ranges == FULL_TURN:
        phi = np.arange(n) * h
        return _Curve(phi, _moving(_path(linkage, point, phi), point, "as the crank turns"), h, True,
                      np.full(n, n - 1))
    # a crank that does not turn fully: each reachable range on its own, half a step inside its ends
    parts, last = [], []
    for s, e in ranges:
        k = int(np.floor((e - s) / h))
        if k > 0:
            parts.append(s + h * (np.arange(k) + 0.5))
            last.append(np.full(k, sum(len(p) for p in parts) - 1))
    phi = np.concatenate(parts) if parts else np.zeros(0)
    if len(phi) < MIN_POINTS:
        raise CouplerFitError(f"the crank reaches only {len(phi)} of the {n} sample angles: no curve to fit")
    return _Curve(phi, _moving(_path(linkage, point, phi), point, "as the crank moves"), h, False,
                  np.concatenate(last))


def _moving(z, point: str, where: str) -> np.ndarray:
    """The samples z, or CouplerFitError when the point stands still (a frame point: nothing to fit)."""
    if float(np.hypot(*np.ptp(z, axis=0))) <= 1e-12 * max(1.0, float(np.max(np.abs(z)))):
        raise CouplerFitError(f"the joint {point} does not move {where}: its path has no arc or run to fit")
    return z


def _size(z) -> float:
    return float(np.hypot(*np.ptp(z, axis=0))) or 1.0


# --------------------------------------------------------------------------------------------------------------
# Screening: every window at once (upper bounds of the minimax ripple)
# --------------------------------------------------------------------------------------------------------------
def _window_moments(curve, starts, lengths):
    """Each window's mean and its central moments Σx², Σxy, Σy², Σx(x² + y²), Σy(x² + y²) (x, y about the
    window's mean), from prefix sums of the power sums: O(1) a window."""
    W = curve.sums[starts + lengths] - curve.sums[starts]
    m, sx, sy, sxx, sxy, syy, sxxx, sxxy, sxyy, syyy = W.T
    mx, my = sx / m, sy / m
    cxx, cxy, cyy = sxx - m * mx * mx, sxy - m * mx * my, syy - m * my * my
    cxxx = sxxx - 3 * mx * sxx + 2 * m * mx**3
    cyyy = syyy - 3 * my * syy + 2 * m * my**3
    cxyy = sxyy - 2 * my * sxy - mx * syy + 2 * m * mx * my * my
    cxxy = sxxy - 2 * mx * sxy - my * sxx + 2 * m * my * mx * mx
    mean = curve.origin + np.stack([mx, my], 1)
    return mean, cxx, cxy, cyy, cxxx + cxyy, cxxy + cyyy


def _gather(curve, starts, lengths):
    """The windows' samples, padded to the longest (by the last sample), and the mask of the real ones (None when
    all have one length)."""
    k = np.arange(int(np.max(lengths)))
    idx = np.minimum(starts[:, None] + k[None, :], len(curve.ext) - 1)
    mask = None if np.all(lengths == lengths[0]) else k[None, :] < lengths[:, None]
    return curve.ext[idx], mask


def _half_ranges(v, mask):
    """(max + min)/2 and (max − min)/2 of each row of v over its mask."""
    hi = v.max(1) if mask is None else np.where(mask, v, -np.inf).max(1)
    lo = v.min(1) if mask is None else np.where(mask, v, np.inf).min(1)
    return 0.5 * (hi + lo), 0.5 * (hi - lo)


def _screen_arcs(curve, starts, lengths):
    """Kasa's algebraic circle of each window (about the window's mean Σx = Σy = 0, so its normal equations
    reduce to a 2×2 system), then the exact half-range of ρ about that centre: (radius, ripple) per window."""
    mean, cxx, cxy, cyy, cxq, cyq = _window_moments(curve, starts, lengths)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        det = cxx * cyy - cxy * cxy
        centre = mean + 0.5 * np.stack([cyy * cxq - cxy * cyq, cxx * cyq - cxy * cxq], 1) / det[:, None]
        P, mask = _gather(curve, starts, lengths)
        rho = np.hypot(P[..., 0] - centre[:, 0, None], P[..., 1] - centre[:, 1, None])
        radius, ripple = _half_ranges(rho, mask)
    bad = ~np.isfinite(radius) | ~np.isfinite(ripple)
    return np.where(bad, np.inf, radius), np.where(bad, np.inf, ripple)


def _screen_runs(curve, starts, lengths):
    """The principal axis of each window, the half-range across it and the range along it: (length, ripple)."""
    _, cxx, cxy, cyy, _, _ = _window_moments(curve, starts, lengths)
    th = 0.5 * np.arctan2(2 * cxy, cxx - cyy)
    c, s = np.cos(th)[:, None], np.sin(th)[:, None]
    P, mask = _gather(curve, starts, lengths)
    _, along = _half_ranges(P[..., 0] * c + P[..., 1] * s, mask)
    _, across = _half_ranges(P[..., 1] * c - P[..., 0] * s, mask)
    return 2 * along, across


# --------------------------------------------------------------------------------------------------------------
# Exact minimax fits
# --------------------------------------------------------------------------------------------------------------
def _kasa(z):
    """Kasa's algebraic circle of the points z (the start of the exact fit)."""
    centre = z.mean(0)
    X = z - centre
    x, y = X[:, 0], X[:, 1]
    q = x * x + y * y
    A = np.array([[x @ x, x @ y], [x @ y, y @ y]])
    rhs = 0.5 * np.array([x @ q, y @ q])
    try:
        ab = np.linalg.solve(A, rhs)
    except np.linalg.LinAlgError:
        return None
    return centre + ab if np.all(np.isfinite(ab)) else None


def _half_range(z, c):
    rho = np.hypot(z[:, 0] - c[0], z[:, 1] - c[1])
    return 0.5 * (rho.max() + rho.min()), 0.5 * (rho.max() - rho.min())


def _extremes(v, around=2):
    """Indices of the local extrema of the samples v, both ends included, with ``around`` neighbours each side."""
    d = np.diff(v)
    inner = np.flatnonzero(d[:-1] * d[1:] <= 0) + 1
    k = np.concatenate([[0, len(v) - 1], inner, [np.argmax(v), np.argmin(v)]])
    return np.unique(np.clip(k[:, None] + np.arange(-around, around + 1)[None, :], 0, len(v) - 1))


def _newton4(z, j, sign, x, scale):
    """Solve ρ_j(c) − R = sign_j·t on four samples j for x = (c, R, t) by Newton's method; None if singular."""
    for _ in range(8):
        d = x[:2] - z[j]
        rho = np.hypot(d[:, 0], d[:, 1])
        J = np.column_stack([d / rho[:, None], -np.ones(4), -sign])
        try:
            dx = np.linalg.solve(J, -(rho - x[2] - sign * x[3]))
        except np.linalg.LinAlgError:
            return None
        x = x + dx
        if np.max(np.abs(dx)) <= 1e-12 * scale:   # quadratic: the next step would be ~1e-24
            break
    return x if np.all(np.isfinite(x)) else None


def _verified(z, j, sign, x, scale):
    """(centre, R, ripple) if no sample leaves the band R ± |t| of x = (c, R, t) and the four samples j, where
    ρ − R = sign·t, alternate in the order of their directions θ from the centre; else None.

    Linearised about c, ρ varies by Δc·(cos θ, sin θ) and R by a constant: a Haar system in θ over any arc
    shorter than a turn, so by Chebyshev's characterisation four samples alternating in θ (not merely along the
    curve, which may turn back) with no sample outside the band make x the minimax circle.
    """
    R_all, f_all = _half_range(z, x[:2])
    if not np.isfinite(f_all) or f_all > abs(x[3]) * (1 + 1e-9) + 1e-15 * scale:
        return None
    theta = np.unwrap(np.arctan2(z[:, 1] - x[1], z[:, 0] - x[0]))[j]
    if np.any(np.diff(sign[np.argsort(theta)]) == 0):
        return None
    return x[:2], R_all, f_all


def _exchange(z, c, scale, rounds=6):
    """Remez's exchange: take four consecutive alternating extremes of ρ − R (the four whose smallest deviation
    is largest), make the circle equioscillate on them (Newton), and repeat with the new extremes until no
    sample leaves the band; None when the pattern has fewer than four alternations or does not settle."""
    for _ in range(rounds):
        rho = np.hypot(z[:, 0] - c[0], z[:, 1] - c[1])
        R = 0.5 * (rho.max() + rho.min())
        r = rho - R
        k = _extremes(rho, 0)
        merged = []   # consecutive extremes on one side of R: keep the farther
        for i in k:
            if merged and np.sign(r[i]) == np.sign(r[merged[-1]]):
                if abs(r[i]) > abs(r[merged[-1]]):
                    merged[-1] = i
            else:
                merged.append(i)
        if len(merged) < 4:
            return None
        merged = np.array(merged)
        size = np.abs(r[merged])
        low = np.min(np.lib.stride_tricks.sliding_window_view(size, 4), axis=1)
        j = merged[int(np.argmax(low)):][:4]
        sign = np.sign(r[j])
        x = _newton4(z, j, sign, np.array([c[0], c[1], R, float(np.mean(np.abs(r[j])))]), scale)
        if x is None:
            return None
        done = _verified(z, j, sign, x, scale)
        if done is not None:
            return done
        c = x[:2]
    return None


def _minimax_circle(z):
    """The minimax circle of the points z: min over the centre c of max |ρ_i − R|, ρ_i = |z_i − c|.

    Method (why): for a fixed c the best R is the mid-range of ρ, so the ripple f(c) = (max ρ − min ρ)/2 is a
    max of smooth functions of c, non-smooth where the extreme sample changes — a gradient method stalls on
    those kinks. The optimum is characterised by four samples where ρ − R = ±f alternately (Chebyshev's
    alternation for the three parameters), so Remez's exchange from Kasa's circle is tried first
    (:func:`_exchange`: a few Newton solves, accepted only when no sample leaves the band, which proves it).
    Where it does not settle, the robust route: linearising ρ_i about c turns min over (Δc, R) of
    max |ρ_i + ∇ρ_i·Δc − R| into a linear programme in (Δc, R, t) (scipy's HiGHS), solved exactly; the step is
    accepted when the true f (over all the samples) decreases, else the trust box is shrunk. Only the local
    extrema of ρ along the window (ends included) and their neighbours enter the programme: a smooth window's
    ρ has a handful, and they decide the optimum. ρ is smooth and nearly linear in c away from the points (the
    error is |Δc|²/ρ), so from Kasa's algebraic circle (Kasa, 1976), already close, the steps converge in a
    few iterations; after each, Newton's method on the four samples the programme binds is tried
    (:func:`_alternation`). It stops when the programme predicts a gain below 10⁻⁹ f, or a gain below 10⁻⁶ f
    that the step does not realise (linearisation error: the optimum to about 10⁻⁶ of the ripple). Returns
    (centre, R, ripple), the ripple being the exact half-range of ρ over all the samples about the final
    centre.
    """
    c = _kasa(z)
    if c is None:
        return None
    R, f = _half_range(z, c)
    if not np.isfinite(f):
        return None
    scale = max(R, _size(z))
    fast = _exchange(z, c, scale)
    if fast is not None:
        return fast
    box = 0.25 * scale
    objective = np.array([0.0, 0.0, 0.0, 1.0])
    for _ in range(MAX_LP_STEPS):
        d = c - z
        rho = np.hypot(d[:, 0], d[:, 1])
        k = _extremes(rho)
        g = d[k] / rho[k, None]
        ones = np.ones((len(k), 1))
        # in units of the current ripple f about the current R: HiGHS's tolerances (1e-7) are then relative to it
        e = (rho[k] - R) / f if f > 0 else rho[k] - R
        unit = f if f > 0 else 1.0
        A = np.vstack([np.hstack([g, -ones, -ones]), np.hstack([-g, ones, -ones])])
        b = np.concatenate([-e, e])
        lim = box / unit
        res = linprog(objective, A_ub=A, b_ub=b, bounds=[(-lim, lim), (-lim, lim), (None, None), (0, None)],
                      method="highs")
        gain = f - unit * res.x[3] if res.status == 0 else 0.0
        if gain <= 1e-9 * f + 1e-15 * scale:
            break   # no further gain predicted: the alternation is reached
        step = unit * res.x[:2]
        done = _alternation(z, k, res, c + step, R + unit * res.x[2], unit * res.x[3], scale)
        if done is not None:
            return done
        R_new, f_new = _half_range(z, c + step)
        if f_new < f:
            c, R, f = c + step, R_new, f_new
            box = max(4 * float(np.hypot(*step)), 1e-12 * scale)
        elif gain <= 1e-6 * f:
            break   # a tiny predicted gain not realised: the linearisation's error, at the optimum
        else:
            box *= 0.25
    return c, R, f


def _alternation(z, k, res, c, R, t, scale):
    """Newton's method on the four samples the programme found binding (its largest duals), ρ_j(c) − R = ±t
    alternately; the fit if no other sample leaves the band, else None."""
    duals = np.abs(res.ineqlin.marginals)
    rows = np.argsort(duals)[::-1][:4]
    if len(rows) < 4 or duals[rows[-1]] <= 0:
        return None
    j, sign = k[rows % len(k)], np.where(rows < len(k), 1.0, -1.0)
    x = _newton4(z, j, sign, np.array([c[0], c[1], R, t]), scale)
    return None if x is None else _verified(z, j, sign, x, scale)


def _hull(z):
    """The convex hull of the points z (Andrew's monotone chain), counter-clockwise, collinear points dropped."""
    pts = sorted(set(map(tuple, np.asarray(z, dtype=float))))
    if len(pts) <= 2:
        return np.array(pts)

    def half(seq):
        out = []
        for p in seq:
            while len(out) >= 2 and ((out[-1][0] - out[-2][0]) * (p[1] - out[-2][1])
                                     - (out[-1][1] - out[-2][1]) * (p[0] - out[-2][0])) <= 0:
                out.pop()
            out.append(p)
        return out

    lower, upper = half(pts), half(reversed(pts))
    return np.array(lower[:-1] + upper[:-1])


def _minimax_line(z):
    """The minimax line of the points z: the centre line of their thinnest strip.

    Method (why): the thinnest strip holding a point set has one side flush with an edge of its convex hull
    (Houle and Toussaint, 1988), so trying every hull edge with the farthest hull vertex from it is exact, with
    no iteration; the hull of a window of a smooth curve has few vertices. Returns (unit direction, a point on
    the line, ripple = half the strip's width).
    """
    H = _hull(z)
    if len(H) < 2:
        return np.array([1.0, 0.0]), z[0].copy(), 0.0
    if len(H) == 2:
        u = (H[1] - H[0]) / np.hypot(*(H[1] - H[0]))
        return u, H[0].copy(), 0.0
    E = np.roll(H, -1, axis=0) - H
    U = E / np.hypot(E[:, 0], E[:, 1])[:, None]
    N = np.stack([-U[:, 1], U[:, 0]], axis=1)   # inward normals of a counter-clockwise hull
    dist = np.einsum("ekd,ed->ek", H[None, :, :] - H[:, None, :], N)   # vertex k's distance from edge e
    width = dist.max(1)
    i = int(np.argmin(width))
    return U[i], H[i] + 0.5 * width[i] * N[i], 0.5 * float(width[i])


def _arc_result(z, phi_interval, fitted):
    c, R, ripple = fitted
    ang = np.unwrap(np.arctan2(z[:, 1] - c[1], z[:, 0] - c[0]))
    return ArcFit((float(c[0]), float(c[1])), float(R), float(np.ptp(ang)), phi_interval, float(ripple))


def _run_result(z, phi_interval, fitted):
    u, p0, ripple = fitted
    if (z[-1] - z[0]) @ u < 0:
        u = -u
    s = (z - p0) @ u
    mid = p0 + 0.5 * (s.max() + s.min()) * u
    return RunFit((float(mid[0]), float(mid[1])), float(np.arctan2(u[1], u[0])), float(np.ptp(s)), phi_interval,
                  float(ripple))


def _interval(crank_interval):
    if isinstance(crank_interval, str) or np.ndim(crank_interval) != 1 or len(crank_interval) != 2:
        raise CouplerFitError(f"crank_interval must be (start, stop) in radians, got {crank_interval!r:.60}")
    start, stop = (check_value(f"crank_interval[{i}]", v, number()) for i, v in enumerate(crank_interval))
    if not 0 < stop - start < TWO_PI:
        raise CouplerFitError(f"crank_interval needs start < stop < start + 2π, got ({start:.6g}, {stop:.6g})")
    return start, stop


def _exact_samples(linkage, point, interval, n):
    start, stop = interval
    m = max(MIN_POINTS, int(np.ceil((stop - start) / (TWO_PI / n))) + 1)
    return _moving(_path(linkage, point, np.linspace(start, stop, m)), point,
                   f"over φ ∈ ({start:.6g}, {stop:.6g})")


@validated
def fit_arc(linkage: LinkageArg, point: str, crank_interval, *, n: Samples = N_DEFAULT) -> ArcFit:
    """The minimax circle of the coupler point's path over a given crank interval.

    The path is sampled at crank steps of at most 2π/n, both ends included; the fit is exact on those
    samples (:func:`_minimax_circle`: sequential linear programmes from Kasa's circle).

    Parameters
    ----------
    linkage : Linkage
        Any linkage of the structure builder (:func:`coupler_fourbar` makes a four-bar).
    point : str
        The joint whose path is fitted.
    crank_interval : (float, float)
        (start, stop), radians, start < stop < start + 2π, inside the crank's reach.
    n : int, optional
        Samples per crank turn.

    Returns
    -------
    ArcFit
        Centre, radius, extent, the interval and the ripple.

    Raises
    ------
    CouplerFitError
        An unknown joint, an interval that is reversed or a full turn long, a joint that does not move, or a
        path that is a straight line.
    AssemblyError
        The crank does not reach the whole interval.

    Examples
    --------
    >>> import numpy as np
    >>> import mechlab as ml
    >>> lk = ml.coupler_fourbar(1.0, 3.0, 3.0, 3.5, (2.0, 1.2))
    >>> fit = ml.fit_arc(lk, "P", (2.0, 3.6))
    >>> round(fit.radius, 3), bool(fit.ripple < 1e-3 * fit.radius)
    (2.163, True)
    """
    point = _joint(linkage, point)
    interval = _interval(crank_interval)
    z = _exact_samples(linkage, point, interval, n)
    fitted = _minimax_circle(z)
    if fitted is None:
        raise CouplerFitError(f"the path of {point} over φ ∈ ({interval[0]:.6g}, {interval[1]:.6g}) is a "
                              f"straight line (or a point): it has no circle; fit a run (fit_run)")
    return _arc_result(z, interval, fitted)


@validated
def fit_run(linkage: LinkageArg, point: str, crank_interval, *, n: Samples = N_DEFAULT) -> RunFit:
    """The minimax line (the thinnest strip's centre line) of the coupler point's path over a crank interval.

    Exact on the samples (crank steps of at most 2π/n, both ends included): every edge of their convex hull is
    tried as one side of the strip.

    Parameters
    ----------
    linkage : Linkage
        Any linkage of the structure builder.
    point : str
        The joint whose path is fitted.
    crank_interval : (float, float)
        (start, stop), radians, start < stop < start + 2π, inside the crank's reach.
    n : int, optional
        Samples per crank turn.

    Returns
    -------
    RunFit
        The run's middle point, direction, length, interval and ripple.

    Raises
    ------
    CouplerFitError
        An unknown joint, an interval that is reversed or a full turn long, or a joint that does not move.
    AssemblyError
        The crank does not reach the whole interval.

    Examples
    --------
    >>> import numpy as np
    >>> import mechlab as ml
    >>> sc = ml.Linkage({"O": (0, 0)}, ml.Crank("O", "A", 1.0)).rrp("A", "B", 3.0, "O")
    >>> run = ml.fit_run(sc, "B", (0.2, 2.0))   # the slider's pin runs on its guide
    >>> round(run.ripple, 12), round(abs(np.cos(run.direction)), 12)
    (0.0, 1.0)
    """
    point = _joint(linkage, point)
    interval = _interval(crank_interval)
    z = _exact_samples(linkage, point, interval, n)
    return _run_result(z, interval, _minimax_line(z))


# --------------------------------------------------------------------------------------------------------------
# The search
# --------------------------------------------------------------------------------------------------------------
class _Arcs:
    """What the search needs to know of arcs: screening, the exact fit, its size (the radius) and the result."""

    screen = staticmethod(_screen_arcs)

    @staticmethod
    def exact(z):
        return _minimax_circle(z)

    @staticmethod
    def size(fitted):
        return fitted[1]

    @staticmethod
    def ripple(fitted):
        return fitted[2]

    result = staticmethod(_arc_result)


class _Runs:
    """The same for straight runs; the size is the run's length."""

    screen = staticmethod(_screen_runs)

    @staticmethod
    def exact(z):
        u, p0, ripple = _minimax_line(z)
        s = (z - p0) @ u
        return u, p0, ripple, float(np.ptp(s))

    @staticmethod
    def size(fitted):
        return fitted[3]

    @staticmethod
    def ripple(fitted):
        return fitted[2]

    @staticmethod
    def result(z, interval, fitted):
        return _run_result(z, interval, fitted[:3])


def _distinct(order, starts, lengths, n, periodic, limit):
    """Greedily keep windows (in ``order``, best first) that overlap none kept by more than a quarter of the
    shorter."""
    order = np.asarray(order, dtype=int)
    free = np.ones(len(order), bool)
    s, L = starts[order].astype(float), lengths[order].astype(float)
    kept = []
    while free.any() and len(kept) < limit:
        first = int(np.argmax(free))
        kept.append(int(order[first]))
        t, M = s[first], L[first]
        shifts = (-n, 0, n) if periodic else (0,)   # cyclic windows: try the shifts by a turn
        over = np.max([np.clip(np.minimum(s + L + k, t + M) - np.maximum(s + k, t), 0, None) for k in shifts], 0)
        free &= ~(over > 0.25 * np.minimum(L, M))
        free[first] = False
    return kept


def _screen_by_length(kind, curve, starts, lengths):
    """``kind.screen`` of windows of many lengths, in groups of similar length (a group is padded to its
    longest, so one long window does not pad every short one)."""
    order = np.argsort(lengths, kind="stable")
    size, ripple = np.empty(len(starts)), np.empty(len(starts))
    first = 0
    while first < len(order):
        stop = int(np.searchsorted(lengths[order], 1.25 * lengths[order[first]] + 1, side="right"))
        group = order[first:stop]
        size[group], ripple[group] = kind.screen(curve, starts[group], lengths[group])
        first = stop
    return size, ripple


def _accept(kind, fitted, bound, cap):
    size = kind.size(fitted)
    return np.isfinite(size) and size > 0 and kind.ripple(fitted) <= bound * size and (cap is None or size <= cap)


def _search(kind, linkage, point, dwell, n, count, bound, cap):
    point = _joint(linkage, point)
    curve = _sample(linkage, point, n)
    if cap == "size":
        cap = MAX_RADIUS * _size(curve.z)
    N = len(curve.phi)
    starts = np.arange(N)
    if dwell is not None:
        m = int(np.floor(dwell / curve.h + 1e-9)) + 1
        if m < MIN_POINTS:
            raise CouplerFitError(f"a dwell of {np.degrees(dwell):.4g}° spans fewer than {MIN_POINTS} of the "
                                  f"{n} samples per turn; ask a longer dwell or more samples n")
        fits = curve.longest(starts) >= m + (0 if curve.periodic else 1)
        if not fits.any():
            raise CouplerFitError(f"the crank reaches no interval of {np.degrees(dwell):.4g}°: it turns only "
                                  f"through φ ∈ {linkage.crank_ranges()}")
        starts = starts[fits]
        lengths = np.full(len(starts), m)
        size, ripple = kind.screen(curve, starts, lengths)
        with np.errstate(divide="ignore", invalid="ignore"):   # a window where the point pauses: no score
            score = ripple / size
        if cap is not None:
            score = np.where(size <= cap, score, np.inf)
        order = np.argsort(score, kind="stable")
        order = order[np.isfinite(score[order])]
        picks = _distinct(order, starts, lengths, N, curve.periodic, count + 2)   # spares: exact ranks differ
        found = []
        # the exact fits over the exact intervals (start on the grid, width = dwell), one motion for all
        m_exact = max(MIN_POINTS, int(np.ceil(dwell / curve.h)) + 1)
        phis = curve.phi[starts[picks]][:, None] + np.linspace(0.0, dwell, m_exact)[None, :]
        paths = _path(linkage, point, phis.ravel()).reshape(len(picks), m_exact, 2)
        for i, z in zip(picks, paths, strict=True):
            interval = (float(curve.phi[starts[i]]), float(curve.phi[starts[i]] + dwell))
            fitted = kind.exact(z)
            if fitted is None or (cap is not None and kind.size(fitted) > cap):
                continue
            found.append((kind.ripple(fitted) / kind.size(fitted), kind.result(z, interval, fitted)))
        found.sort(key=lambda item: item[0])
        return tuple(f for _, f in found[:count])
    # the longest window within the bound at every start: bisection on the length, all starts at once
    top = np.minimum(curve.longest(starts), N)
    good = np.full(N, MIN_POINTS - 1)   # the longest length known to pass (below MIN_POINTS: none yet)
    bad = top + 1                       # the shortest known to fail
    while True:
        live = bad - good > 1
        if not live.any():
            break
        trial = (good[live] + bad[live]) // 2
        size, ripple = _screen_by_length(kind, curve, starts[live], trial)
        ok = (ripple <= bound * size) & np.isfinite(size) & (size > 0)
        if cap is not None:
            ok &= size <= cap
        good[live] = np.where(ok, trial, good[live])
        bad[live] = np.where(ok, bad[live], trial)
    order = np.lexsort((starts, -good))
    order = order[good[order] >= MIN_POINTS]
    picks = _distinct(order, starts, good, N, curve.periodic, count + 2)   # spares: the exact lengths differ
    found = []
    for i in picks:
        s = int(starts[i])

        def exact(L, s=s):
            z = curve.window(s, L)
            fitted = kind.exact(z)
            return (z, fitted) if fitted is not None and _accept(kind, fitted, bound, cap) else None

        lo, hi = int(good[i]), int(top[i]) + 1   # screening is an upper bound: the exact fit may reach further
        first = exact(lo)
        while first is None and lo > MIN_POINTS:   # (the exact radius may be a little off the screened one)
            lo = max(MIN_POINTS, lo - max(1, lo // 8))
            first = exact(lo)
        if first is None:
            continue
        best = (lo, first)
        step = max(1, int(bad[i]) - lo)
        while lo + step < hi:   # gallop, then bisect between the last length kept and the first refused
            got = exact(lo + step)
            if got is None:
                hi = lo + step
                break
            lo, best = lo + step, (lo + step, got)
            step *= 2
        while hi - lo > 1:
            mid = (lo + hi) // 2
            got = exact(mid)
            if got is None:
                hi = mid
            else:
                lo, best = mid, (mid, got)
        L, (z, fitted) = best
        found.append((-L, kind.ripple(fitted) / kind.size(fitted), s, kind.result(z, curve.interval(s, L), fitted)))
    found.sort(key=lambda item: item[:2])
    # grown to their exact lengths, two may now overlap: keep the longer
    keep = _distinct(np.arange(len(found)), np.array([f[2] for f in found], int),
                     np.array([-f[0] for f in found], int), N, curve.periodic, count) if found else []
    return tuple(found[i][3] for i in sorted(keep))


@validated
def coupler_arcs(linkage: LinkageArg, point: str = "P", *, dwell: Dwell = None, n: Samples = N_DEFAULT,
                 count: Count = 3, max_ripple: Bound = MAX_RIPPLE, max_radius: Radius = None) -> tuple[ArcFit, ...]:
    """The best nearly circular arcs of a coupler point's path, best first.

    With ``dwell`` (a crank interval's width): the arcs over that width with the least relative ripple
    ripple / R — the dwell error of a six-bar whose rocker scales with R (:func:`arc_dwell_sixbar`) — at
    distinct starts on the crank grid (windows overlapping by more than a quarter are one arc). With ``dwell=None``:
    the longest arcs (in crank angle) whose ripple stays ≤ ``max_ripple`` · R. Every window of the sampled
    curve is screened at once with Kasa's circle (an upper bound of the minimax ripple); the best few are then
    fitted exactly (:func:`fit_arc`'s minimax circle), so a result's ripple is its exact minimax ripple on the
    samples. Arcs whose radius exceeds ``max_radius`` (default: 10 × the curve's size) are straight runs
    (:func:`coupler_runs`), not arcs.

    Parameters
    ----------
    linkage : Linkage
        Any linkage of the structure builder (:func:`coupler_fourbar`).
    point : str, optional
        The coupler point's joint.
    dwell : float, optional
        The crank interval's width (radians, in (0, 2π)); None: the longest arcs within ``max_ripple``.
    n : int, optional
        Samples per crank turn (the crank grid; a start is found to one step, 2π/n).
    count : int, optional
        How many arcs at most.
    max_ripple : float, optional
        With ``dwell=None``: the largest ripple / R admitted (0.1 % by default).
    max_radius : float, optional
        The largest radius admitted.

    Returns
    -------
    tuple of ArcFit
        Best first; empty when no window meets the bounds.

    Raises
    ------
    CouplerFitError
        An unknown joint, a joint that does not move, a dwell spanning fewer than 5 samples, or longer than the
        crank reaches.
    DimensionError
        ``dwell``, ``n``, ``count``, ``max_ripple`` or ``max_radius`` out of range.

    Examples
    --------
    >>> import numpy as np
    >>> import mechlab as ml
    >>> lk = ml.coupler_fourbar(1.0, 3.0, 3.0, 3.5, (2.0, 1.2))
    >>> arc = ml.coupler_arcs(lk, dwell=np.radians(90), count=1)[0]
    >>> round(np.degrees(arc.crank_interval[1] - arc.crank_interval[0]), 6), arc.ripple < 0.01 * arc.radius
    (90.0, True)
    """
    return _search(_Arcs, linkage, point, dwell, n, count, max_ripple, max_radius or "size")


@validated
def coupler_runs(linkage: LinkageArg, point: str = "P", *, dwell: Dwell = None, n: Samples = N_DEFAULT,
                 count: Count = 3, max_ripple: Bound = MAX_RIPPLE) -> tuple[RunFit, ...]:
    """The best nearly straight runs of a coupler point's path, best first.

    With ``dwell``: the runs over that crank width with the least relative ripple ripple / length, at distinct
    starts; with ``dwell=None``: the longest runs (in crank angle) whose ripple stays ≤ ``max_ripple`` · length.
    Screened with each window's principal axis (an upper bound), then fitted exactly (:func:`fit_run`).

    Parameters
    ----------
    linkage : Linkage
        Any linkage of the structure builder (:func:`coupler_fourbar`).
    point : str, optional
        The coupler point's joint.
    dwell : float, optional
        The crank interval's width (radians, in (0, 2π)); None: the longest runs within ``max_ripple``.
    n : int, optional
        Samples per crank turn.
    count : int, optional
        How many runs at most.
    max_ripple : float, optional
        With ``dwell=None``: the largest ripple / length admitted.

    Returns
    -------
    tuple of RunFit
        Best first; empty when no window meets the bound.

    Raises
    ------
    CouplerFitError
        An unknown joint, a joint that does not move, a dwell spanning fewer than 5 samples, or longer than the
        crank reaches.
    DimensionError
        ``dwell``, ``n``, ``count`` or ``max_ripple`` out of range.

    Examples
    --------
    >>> import numpy as np
    >>> import mechlab as ml
    >>> lam = ml.coupler_fourbar(0.4, 1.0, 1.0, 0.8, (2.0, 0.0))   # Chebyshev's lambda
    >>> run = ml.coupler_runs(lam, dwell=np.pi, count=1)[0]
    >>> round(run.ripple, 5), round(run.length, 3)
    (0.00195, 1.6)
    """
    return _search(_Runs, linkage, point, dwell, n, count, max_ripple, None)


# --------------------------------------------------------------------------------------------------------------
# The six-bars
# --------------------------------------------------------------------------------------------------------------
def _names(linkage: Linkage):
    return set(_joints(linkage)), {k.name for k in linkage.structure().links}


def _fresh(base: str, taken: set) -> str:
    name, k = base, 2
    while name in taken:
        name, k = f"{base}{k}", k + 1
    return name


def _full_cycle(linkage: Linkage, n: int) -> np.ndarray:
    ranges = linkage.crank_ranges()
    if ranges == FULL_TURN:
        return np.arange(n) * (TWO_PI / n)
    return np.concatenate([np.linspace(s, e, max(8, int(n * (e - s) / TWO_PI)))[1:-1] for s, e in ranges])


def _with_frame(linkage: Linkage, name: str, xy) -> Linkage:
    return replace(linkage, frame=(*linkage.frame, (name, (float(xy[0]), float(xy[1])))))


def _closes_like(sixbar: Linkage, base: Linkage, what: str) -> None:
    mine, theirs = np.ravel(sixbar.crank_ranges()), np.ravel(base.crank_ranges())
    if mine.shape != theirs.shape or not np.allclose(mine, theirs, atol=1e-9):
        raise InfeasibleDesignError(f"{what} does not close wherever the four-bar does: the six-bar's crank "
                                    f"reaches only φ ∈ {sixbar.crank_ranges()} (the four-bar's: "
                                    f"{base.crank_ranges()}); choose another pivot")


def _dyad_mu(d, R, b):
    """The folded transmission angle min(μ, π − μ) of a dyad of links R and b whose ends are d apart."""
    with np.errstate(invalid="ignore"):
        mu = np.arccos(np.clip((R * R + b * b - d * d) / (2 * R * b), -1.0, 1.0))
    return np.minimum(mu, np.pi - mu)


@validated
def arc_dwell_sixbar(linkage: LinkageArg, point: str, arc: Annotated[ArcFit, mechanism(ArcFit)], *,
                     output_pivot=None) -> Linkage:
    """The dwell six-bar of an arc: a rod of length R from the coupler point to a joint D and an output rocker
    from ``output_pivot`` to D (an RRR dyad); D rests near the arc's centre while P runs along the arc, so the
    rocker dwells.

    The default pivot: D's rocker should meet the rod near square through the dwell and transmit well over
    the rest of the cycle. Pivots F = Q + b·(cos θ, sin θ) are tried with θ from 30° to 150° in steps of 15° on
    either side of the direction from Q to the arc's middle (90°: square to the rod at mid-dwell, so the rod
    turns ± extent/2 about square during the dwell) and b = 0.5 R … 2 R (so the dwell error is of the order
    of ripple / R); the one whose dyad closes over the cycle with the largest least transmission angle is kept.
    A dyad that passes within 15° of a dead point is refused (there the rocker's dwell error outgrows
    ripple / (b sin μ), and its branch could flip): an arc of extent near 180° or more turns the rod through as
    much during the dwell, so no rocker transmits throughout.

    Parameters
    ----------
    linkage : Linkage
        The four-bar (any linkage of the builder) carrying the coupler point.
    point : str
        The coupler point's joint.
    arc : ArcFit
        An arc of that point's path (:func:`coupler_arcs`, :func:`fit_arc`).
    output_pivot : (float, float), optional
        The output rocker's frame pivot; its length is the pivot's distance from the arc's centre.

    Returns
    -------
    Linkage
        The six-bar: the frame gains the pivot ``F`` and the joint ``D`` joins rod and rocker (fresh names
        when taken: ``F2``, ``D2``, …); links ``rod`` and ``output``; the output is the rocker's angle.

    Raises
    ------
    InfeasibleDesignError
        The dyad does not close over the four-bar's whole cycle, passes within 15° of a dead point, or the pivot
        sits at the arc's centre.
    CouplerFitError
        An unknown joint.
    TypeError
        ``arc`` is not an ArcFit.

    Examples
    --------
    >>> import numpy as np
    >>> import mechlab as ml
    >>> lk = ml.coupler_fourbar(1.0, 3.0, 3.0, 3.5, (2.0, 1.2))
    >>> arc = ml.coupler_arcs(lk, dwell=np.radians(90), count=1)[0]
    >>> six = ml.arc_dwell_sixbar(lk, "P", arc)
    >>> six.formula()
    'I(crank) → II₂(coupler, rocker) → II₂(rod, output)'
    >>> check = ml.check_dwell(six, arc.crank_interval)
    >>> bool(check.dwell_error < 0.05 * check.swing)
    True
    """
    point = _joint(linkage, point)
    joints, links = _names(linkage)
    F_name, D_name = _fresh("F", joints), _fresh("D", joints)
    rod, out = _fresh("rod", links), _fresh("output", links)
    Q, R = np.asarray(arc.centre, dtype=float), arc.radius
    mid = 0.5 * (arc.crank_interval[0] + arc.crank_interval[1])
    phi = _full_cycle(linkage, 720)
    Pc = _path(linkage, point, np.concatenate([[mid], phi]))
    P_mid, Pc = Pc[0], Pc[1:]
    if output_pivot is None:
        to_mid = np.arctan2(*(P_mid - Q)[::-1])
        th = to_mid + np.radians(np.concatenate([np.arange(30, 151, 15), -np.arange(30, 151, 15)]))
        cand = [(Q + k * R * np.array([np.cos(t), np.sin(t)]), k * R) for t in th for k in (0.5, 0.75, 1.0, 1.5, 2.0)]
        F = max(cand, key=lambda fb: _dyad_quality(Pc, fb[0], R, fb[1]))[0]
    else:
        F = np.asarray(check_value("output_pivot", output_pivot, Spec("point")), dtype=float)
    b = float(np.hypot(*(F - Q)))
    if b <= 1e-9 * R:
        raise InfeasibleDesignError("the output pivot sits at the arc's centre: the rocker would have no length")
    mu = _dyad_quality(Pc, F, R, b)
    if mu < 0:
        raise InfeasibleDesignError(f"the dyad rod {R:.6g} - rocker {b:.6g} (pivot ({F[0]:.6g}, {F[1]:.6g})) does "
                                    f"not close over the four-bar's cycle: |P F| leaves ({abs(R - b):.6g}, "
                                    f"{R + b:.6g}); choose another pivot")
    if mu < MIN_TRANSMISSION:
        raise InfeasibleDesignError(f"the dyad rod {R:.6g} - rocker {b:.6g} (pivot ({F[0]:.6g}, {F[1]:.6g})) passes "
                                    f"within {np.degrees(mu):.2g}° of a dead point (least transmission angle; "
                                    f"{np.degrees(MIN_TRANSMISSION):g}° needed); an arc of extent "
                                    f"{np.degrees(arc.extent):.0f}° turns the rod through as much during the dwell")
    # D at Q at mid-dwell: on the left (+1) or right of the directed line P → F
    side = (F - P_mid)[0] * (Q - P_mid)[1] - (F - P_mid)[1] * (Q - P_mid)[0]
    assembly = 1 if side > 0 else -1
    try:
        six = (_with_frame(linkage, F_name, F)
               .rrr(point, F_name, D_name, R, b, assembly, links=(rod, out)))
    except MechanismError as err:
        raise InfeasibleDesignError(f"the dyad {rod}-{out} at pivot ({F[0]:.6g}, {F[1]:.6g}): {err}") from None
    _closes_like(six, linkage, f"the dyad {rod}-{out} (pivot ({F[0]:.6g}, {F[1]:.6g}), rod {R:.6g}, rocker {b:.6g})")
    return six


def _dyad_quality(P, F, R, b) -> float:
    """The least folded transmission angle of the dyad P-D-F over the sampled P, or -1 where it does not close."""
    d = np.hypot(*(P - F).T)
    if not np.all((d > abs(R - b)) & (d < R + b)):
        return -1.0
    return float(np.min(_dyad_mu(d, R, b)))


@validated
def run_dwell_sixbar(linkage: LinkageArg, point: str, run: Annotated[RunFit, mechanism(RunFit)], *,
                     pivot=None) -> Linkage:
    """The dwell six-bar of a straight run: a block at the coupler point slides in the slot of an output link
    pivoted on the run's line (an RPR dyad); the slot lies along the line while P runs on it, so the link
    dwells.

    The default pivot lies on the line beyond one end of the run, half the run's length past it (the dwell
    error is about ripple / the pivot's distance, the swing about the curve's size / that distance); of the
    two ends, the one whose pivot keeps farther from the whole coupler curve.

    Parameters
    ----------
    linkage : Linkage
        The four-bar (any linkage of the builder) carrying the coupler point.
    point : str
        The coupler point's joint.
    run : RunFit
        A straight run of that point's path (:func:`coupler_runs`, :func:`fit_run`).
    pivot : (float, float), optional
        The slotted link's frame pivot (on the run's line for a true dwell).

    Returns
    -------
    Linkage
        The six-bar: the frame gains the pivot ``G`` (fresh name when taken), links ``block`` and ``slotted``;
        the output is the slotted link's angle.

    Raises
    ------
    InfeasibleDesignError
        The coupler point passes through the pivot (within 0.1 % of the curve's size).
    CouplerFitError
        An unknown joint.
    TypeError
        ``run`` is not a RunFit.

    Examples
    --------
    >>> import numpy as np
    >>> import mechlab as ml
    >>> lam = ml.coupler_fourbar(0.4, 1.0, 1.0, 0.8, (2.0, 0.0))
    >>> run = ml.coupler_runs(lam, dwell=np.pi, count=1)[0]
    >>> six = ml.run_dwell_sixbar(lam, "P", run)
    >>> check = ml.check_dwell(six, run.crank_interval)
    >>> bool(check.dwell_error < 0.02 * check.swing)
    True
    """
    point = _joint(linkage, point)
    joints, links = _names(linkage)
    G_name = _fresh("G", joints)
    block, slotted = _fresh("block", links), _fresh("slotted", links)
    phi = _full_cycle(linkage, 720)
    Pc = _path(linkage, point, phi)
    if pivot is None:
        u = np.array([np.cos(run.direction), np.sin(run.direction)])
        mid = np.asarray(run.point, dtype=float)
        cand = [mid + k * run.length * u for k in (1.0, -1.0)]
        G = max(cand, key=lambda g: float(np.min(np.hypot(*(Pc - g).T))))
    else:
        G = np.asarray(check_value("pivot", pivot, Spec("point")), dtype=float)
    near = int(np.argmin(np.hypot(*(Pc - G).T)))   # the closest approach, resolved between the samples
    lo, hi = phi[max(near - 1, 0)], phi[min(near + 1, len(phi) - 1)]
    gap = float(np.min(np.hypot(*(_path(linkage, point, np.linspace(lo, hi, 201)) - G).T)))
    if gap <= 1e-3 * _size(Pc):
        raise InfeasibleDesignError(f"the coupler point {point} passes through the pivot ({G[0]:.6g}, {G[1]:.6g}) "
                                    f"(closest {gap:.3g}, under 0.1 % of the curve's size): the slot's direction is "
                                    f"undefined there, or it whips round")
    reach = float(np.max(np.hypot(*(Pc - G).T)))
    try:
        six = _with_frame(linkage, G_name, G).then(RPR(point, G_name, reach, links=(block, slotted)))
    except MechanismError as err:
        raise InfeasibleDesignError(f"the slotted link at ({G[0]:.6g}, {G[1]:.6g}): {err}") from None
    _closes_like(six, linkage, f"the slotted link at ({G[0]:.6g}, {G[1]:.6g})")
    return six


@validated
def check_dwell(sixbar: LinkageArg, crank_interval, *, n: Samples = N_DEFAULT) -> DwellCheck:
    """Simulate a dwell six-bar through the builder's motion: the output's range over the dwell's crank
    interval, its range over the cycle and the least transmission angle.

    Parameters
    ----------
    sixbar : Linkage
        A six-bar (:func:`arc_dwell_sixbar`, :func:`run_dwell_sixbar`, or any linkage).
    crank_interval : (float, float)
        The dwell's crank interval (radians).
    n : int, optional
        Samples per crank turn.

    Returns
    -------
    DwellCheck
        Dwell error, swing (or stroke), least transmission angle, output kind.

    Raises
    ------
    CouplerFitError
        A reversed interval, or one a full turn long.
    AssemblyError
        The linkage does not close over the interval.

    Examples
    --------
    >>> import numpy as np
    >>> import mechlab as ml
    >>> fb = ml.coupler_fourbar(1.0, 3.0, 3.0, 3.5)
    >>> check = ml.check_dwell(fb, (0.0, 0.5))   # a plain four-bar's rocker does not dwell
    >>> bool(check.dwell_error > 0.1 * check.swing), round(np.degrees(check.transmission), 1)
    (True, 49.2)
    """
    interval = _interval(crank_interval)
    m = max(MIN_POINTS, int(np.ceil((interval[1] - interval[0]) / (TWO_PI / n))) + 1)
    inside = sixbar.motion(np.linspace(*interval, m))
    cycle = sixbar.motion(_full_cycle(sixbar, n))
    kind = sixbar.output
    law = (lambda mo: mo.s) if kind == "position" else (lambda mo: mo.psi)
    mus = [np.pi / 2]
    for g in sixbar.groups:
        if isinstance(g, RRR):
            pts = cycle.points
            d = np.hypot(*(pts[g.first].p - pts[g.second].p).T)
            mus.append(float(np.min(_dyad_mu(d, g.first_length, g.second_length))))
    return DwellCheck(interval, float(np.ptp(law(inside))), float(np.ptp(law(cycle))), float(min(mus)), kind)

