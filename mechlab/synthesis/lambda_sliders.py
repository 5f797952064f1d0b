"""Six-bar dwell mechanisms with a translating output on the lambda mechanism: МЧВ2 and МЧВ5
(Kinitsky (1994), chapter 1, the list of kinds before Fig. 1 and the caption of Fig. 1 в, д).

Kinitsky sorts the dwell six-bars by the class-II group attached at the coupler point D (kind 1
RRR, МЧВ1; kind 2 RRP, МЧВ2; kind 3 RPR, МЧВ3; kind 5 RPP, МЧВ5). The abstract only names МЧВ2 and
МЧВ5; their geometry is reconstructed from it and from the МЧВ1 construction (Fig. 3, formulas
(14)-(15)), and what was assumed is stated with each function.

* МЧВ2, :class:`LambdaSliderSixBar` (circle guide): rod D-E of length R, slider E on a straight
  guide through the arc centre Q (:func:`mchv2`, :func:`mchv2_stroke`, :func:`mchv2_far_position`).
* МЧВ5, :class:`LambdaTranslatingSlot` (straight-line guide): a block at D in a straight slot of an
  output translating in a fixed guide (:func:`mchv5`). On a circle guide the translating slotted
  link is МЧВ2 again (a curved slot replaces the rod D-E).

Frames as in :mod:`mechlab.synthesis.lambda_guiding`: O = (0, 0), C = (a, 0), the dwell centred on
φ = π, the crank turning counter-clockwise, lengths in units of l.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Annotated

import numpy as np
from scipy.optimize import brentq

from ..analysis.motion_laws import Invariants, rise_invariants
from ..errors import InfeasibleDesignError, MechanismError
from ..mechanisms.base import TWO_PI
from ..mechanisms.lambda_sliders import LambdaSliderSixBar, LambdaTranslatingSlot
from ..motion import AngularMotion
from ..validate import Length, Sign, Spec, angle, mechanism, number, validated
from .lambda_guiding import CircleGuide, StraightGuide
from .lambda_sixbars import Circle, MuMin, Straight, TimeRatio, report, rise_law, time_ratio_far_angle

Slider = Annotated[LambdaSliderSixBar, mechanism((LambdaSliderSixBar, LambdaTranslatingSlot))]
OptionalDwell = Annotated[float | None, angle(0.0, 2 * np.pi, open=True, optional=True)]

__all__ = [
    "SliderReport",
    "mchv2",
    "mchv2_far_position",
    "mchv2_stroke",
    "mchv5",
    "slider_invariants",
    "slider_report",
    "slider_rise",
]


@validated
def mchv2_far_position(guide: Circle, K: TimeRatio, normal: Sign = 1):
    """The far crank angle φ_far = π + α + φ_n and the far position E1 = D1 + R·n of the slider
    for a time ratio K.

    Parameters
    ----------
    guide : CircleGuide
        A circle-guiding lambda mechanism (:func:`circle_guiding`).
    K : float
        Time ratio, > 0.
    normal : {1, -1}
        n is the unit normal to D's path at D1, on the side of Q for +1 (as in МЧВ1's Fig. 3),
        on the other side for −1.

    Returns
    -------
    phi_far : float
        The far crank angle (rad; beyond 2π when the far extreme follows φ = 2π).
    D1, E1 : numpy.ndarray
        The coupler point and the slider there (units of l).

    Raises
    ------
    TypeError
        ``guide`` is not a CircleGuide.
    InfeasibleDesignError
        ``K`` is not a positive number.
    DimensionError
        ``normal`` is not ±1.

    Examples
    --------
    >>> import numpy as np
    >>> import mechlab as ml
    >>> guide = ml.circle_guiding(np.radians(150), 0.9, np.radians(120))
    >>> phi_far, D1, E1 = ml.mchv2_far_position(guide, 1.25)
    >>> round(float(np.degrees(phi_far)), 2), np.round(E1, 4).tolist()
    (373.33, [1.6784, 2.0975])
    """
    m, Q = guide.mechanism, guide.centre
    phi_far = np.pi + guide.alpha + time_ratio_far_angle(K, guide.dwell)
    D1 = m.motion(np.array([phi_far])).points["D"]
    v = D1.d[0] / np.hypot(*D1.d[0])
    n = np.array([-v[1], v[0]])
    if n @ (Q - D1.p[0]) < 0:
        n = -n
    return phi_far, D1.p[0], D1.p[0] + normal * guide.R * n


@validated
def mchv2(guide: Circle, K: TimeRatio = 1.0, *, normal: Annotated[int | None, Spec("sign", optional=True)] = None,
          mu_min: MuMin = np.radians(30)) -> LambdaSliderSixBar:
    """МЧВ2 for a circle-guiding design and a time ratio K: rod DE = R, guide through Q and E1.

    The slider's stroke is then h = |QE1| (:func:`mchv2_far_position`); K = 1 gives the guide along
    the symmetry axis. The assembly is the one that keeps E at Q during the dwell. At the far
    extreme the rod lies on the normal to D's path, on Q's side (``normal`` = +1, as in МЧВ1) or on
    the other (−1; for some designs only this one is reached on the dwell's assembly); None tries
    +1, then −1. Raises InfeasibleDesignError with the numbers when the design does not work: the
    guide turns across QD during the dwell ((D − Q)·u changes sign, so the slider leaves Q), the rod
    would stand across the guide somewhere, the simulated far extreme is not the designed one, or the
    transmission angle μ2′ falls below ``mu_min`` (radians; by default the thesis' working limit 30°,
    as for :func:`mchv1`; ``mu_min=None`` accepts any).

    Assumed: the guide's direction is the design freedom. While D runs on the arc the slider stays
    at Q to the order of E: E = Q + s·u, s = (D−Q)·u ± √(R² − ((D−Q)×u)²) (the RRP dyad of
    :func:`mechlab.geometry.dyad_rrp`), the residual bounded by 2·max|ρ² − R²|/min|(D − Q)·u|
    (≈ 2E/cos β) while (D − Q)·u keeps its sign. The slider is farthest out where the rod lies on
    the normal to D's path, at t = α + φ_n, φ_n = 2K(π − α)/(1 + K) ((14)-(15)): E1 = D1 + R·n,
    h = |QE1|; K = 1 gives the least stroke h = R − |QD(0)| (the seed's |D0D1| to within E);
    h(K) = h(1/K). μ2′ = π/2 − β with sin β = (distance of D from the guide)/R.

    Parameters
    ----------
    guide : CircleGuide
        A circle-guiding lambda mechanism (:func:`circle_guiding`).
    K : float
        Time ratio, > 0 (default 1).
    normal : {1, -1}, optional
        Side of the rod at the far extreme; None tries +1, then −1.
    mu_min : float, optional
        Least admitted transmission angle μ2′ (rad, default 30°); None accepts any.

    Returns
    -------
    LambdaSliderSixBar
        МЧВ2, lengths in units of l.

    Raises
    ------
    InfeasibleDesignError
        The design does not work (the message names the condition and the numbers).
    TypeError
        ``guide`` is not a CircleGuide.
    DimensionError
        ``normal`` or ``mu_min`` out of range.

    Examples
    --------
    >>> import numpy as np
    >>> import mechlab as ml
    >>> guide = ml.circle_guiding(np.radians(150), 0.9, np.radians(120))
    >>> report = ml.slider_report(ml.mchv2(guide, 1.0))
    >>> round(report.stroke, 4), round(report.K, 4)
    (0.3217, 1.0)
    """
    if normal is not None:
        return _mchv2(guide, K, normal, mu_min)
    try:
        return _mchv2(guide, K, 1, mu_min)
    except InfeasibleDesignError as inner:
        try:
            return _mchv2(guide, K, -1, mu_min)
        except InfeasibleDesignError as outer:
            raise InfeasibleDesignError(f"{inner}; with the rod on the outer normal instead: {outer}") from None


def _mchv2(guide: CircleGuide, K: float, normal: int, mu_min: float | None) -> LambdaSliderSixBar:
    phi_far, _D1, E1 = mchv2_far_position(guide, K, normal)
    Q, R = guide.centre, guide.R
    h = float(np.hypot(*(E1 - Q)))
    if h < 1e-9:
        raise InfeasibleDesignError(f"K = {K:g}: the far position E1 coincides with the arc centre Q (no stroke)")
    u = (E1 - Q) / h
    theta = float(np.arctan2(u[1], u[0]))
    m = guide.mechanism
    D0 = m.coupler_point(np.array([np.pi]))[0]
    along = float((D0 - Q) @ u)
    if abs(along) < 1e-9 * R:
        raise InfeasibleDesignError(f"K = {K:g}: the guide is perpendicular to QD0, the rod stands across it "
                                    f"in the middle of the dwell")
    asm = -1 if along > 0 else 1  # the root of the RRP dyad near s = 0 while |DQ| ≈ R
    # dwell: |s| = |ρ² − R²| / (|w| + √(w² − ρ² + R²)), w = (D − Q)·u, small if w keeps its sign
    al = (m.coupler_point(np.pi + np.linspace(-guide.alpha, guide.alpha, 801)) - Q) @ u
    if al.min() * al.max() <= 0:
        raise InfeasibleDesignError(
            f"K = {K:g}: the guide (at {np.degrees(theta):.2f}°) turns across QD during the dwell, (D − Q)·u runs "
            f"from {al.min():.4g} to {al.max():.4g}: the slider leaves Q, the dwell is lost")
    try:
        six = LambdaSliderSixBar(m.r, m.a, m.delta, R, float(Q[0]), float(Q[1]), theta, asm, guide.dwell)
        at_far = six.motion(np.array([phi_far])).s[0]
    except MechanismError as err:
        raise InfeasibleDesignError(f"МЧВ2 with K = {K:g} (stroke {h:.4g}): {err}") from None
    if abs(at_far - h) > 1e-9 * max(1.0, h):
        raise InfeasibleDesignError(
            f"K = {K:g}: on the assembly that holds E at Q in the dwell the slider reaches s = {at_far:.6g} at "
            f"φ_far = {np.degrees(phi_far % TWO_PI):.2f}°, not E1 (s = {h:.6g}): E1 lies on the other assembly")
    rep = slider_report(six, guide.dwell)
    if abs((rep.far - phi_far + np.pi) % TWO_PI - np.pi) > 1e-6:
        raise InfeasibleDesignError(
            f"K = {K:g}: the simulated slider's far extreme is at φ = {np.degrees(rep.far):.2f}°, not at the "
            f"designed {np.degrees(phi_far % TWO_PI):.2f}° (stroke {rep.stroke:.4g} instead of {h:.4g})")
    if mu_min is not None and rep.mu2_min < mu_min:
        raise InfeasibleDesignError(
            f"K = {K:g}: the transmission angle μ2′ of the slider dyad falls to {np.degrees(rep.mu2_min):.2f}°, "
            f"below the allowed {np.degrees(mu_min):.4g}°")
    return six


@validated
def mchv2_stroke(guide: Circle, stroke: Length, side: Sign = 1, K_max: Annotated[float, number(1.0, 1e6)] = 20.0, *,
                 normal: Sign = 1, mu_min: MuMin = np.radians(30)) -> LambdaSliderSixBar:
    """МЧВ2 with a requested stroke h = |QE1| (units of l): the time ratio K is solved for.

    h(K) is smallest at K = 1 (guide on the axis) and, with the mirror symmetry, h(K) = h(1/K);
    ``side`` = +1 returns the solution with K ≥ 1, −1 the one with K ≤ 1. The smallest K on that
    side with h(K) = h is found by a scan of K ∈ [1, ``K_max``] and brentq (``normal`` as in
    :func:`mchv2`, here fixed: h(K) depends on it; ``mu_min`` as there).

    Parameters
    ----------
    guide : CircleGuide
        A circle-guiding lambda mechanism (:func:`circle_guiding`).
    stroke : float
        The slider's stroke h (units of l), > 0.
    side : {1, -1}
        +1 for the solution with K ≥ 1, −1 for K ≤ 1.
    K_max : float
        Upper end of the scan of K, ≥ 1 (default 20).
    normal : {1, -1}
        Side of the rod at the far extreme.
    mu_min : float, optional
        Least admitted transmission angle μ2′ (rad, default 30°); None accepts any.

    Returns
    -------
    LambdaSliderSixBar
        МЧВ2 with that stroke.

    Raises
    ------
    InfeasibleDesignError
        The stroke lies outside the achievable range (named), or :func:`mchv2` refuses the K found.
    TypeError
        ``guide`` is not a CircleGuide.
    DimensionError
        ``stroke``, ``side``, ``K_max`` or ``mu_min`` out of range.

    Examples
    --------
    >>> import numpy as np
    >>> import mechlab as ml
    >>> guide = ml.circle_guiding(np.radians(150), 0.9, np.radians(120))
    >>> report = ml.slider_report(ml.mchv2_stroke(guide, 0.35, mu_min=None))
    >>> round(report.stroke, 4), round(report.K, 3)
    (0.3501, 1.182)
    """
    h = stroke

    def gap(k):  # k ≥ 1; K = k or 1/k
        _, _, E1 = mchv2_far_position(guide, k if side > 0 else 1 / k, normal)
        return float(np.hypot(*(E1 - guide.centre))) - h

    ks = np.geomspace(1.0, K_max, 121)
    g = np.array([gap(k) for k in ks])
    hs = g + h
    if g[0] > 0:
        raise InfeasibleDesignError(
            f"stroke h = {h:.6g} is below the smallest stroke of МЧВ2 on this guide, h(K = 1) = {hs[0]:.6g} "
            f"(guide along the symmetry axis)")
    up = np.nonzero((g[:-1] <= 0) & (g[1:] > 0))[0]
    if len(up) == 0:
        raise InfeasibleDesignError(
            f"stroke h = {h:.6g} exceeds the largest stroke |QE1| = {hs.max():.6g} of МЧВ2 on this guide "
            f"for K in [1/{K_max:g}, {K_max:g}]")
    i = int(up[0])
    k = brentq(gap, ks[i], ks[i + 1], xtol=1e-14, rtol=4 * np.finfo(float).eps)
    return mchv2(guide, k if side > 0 else 1 / k, normal=normal, mu_min=mu_min)


def _axis_stroke(guide: StraightGuide) -> float:
    """Range of the axis coordinate x of D over a turn: the stroke of МЧВ5 with γ = 0."""
    m = guide.mechanism
    phi = np.linspace(0.0, TWO_PI, 2881)
    x = m.axis_coordinates(phi)[0]

    def dx(t):
        return float(m.motion(np.array([t])).points["D"].d[0] @ m.axis)

    ext = []
    for i in (int(np.argmin(x)), int(np.argmax(x))):
        lo, hi = phi[i] - phi[1], phi[i] + phi[1]
        t = brentq(dx, lo, hi, xtol=1e-15) if dx(lo) * dx(hi) < 0 else phi[i]
        ext.append(float(m.axis_coordinates(np.array([t]))[0][0]))
    return ext[1] - ext[0]


@validated
def mchv5(guide: Straight, stroke: Annotated[float | None, Spec("length", 0.0, None, True, optional=True)] = None, *,
          guide_angle: Annotated[float | None, angle(-np.pi / 2, np.pi / 2, open=True, optional=True)] = None,
          side: Sign = 1, max_pressure: Annotated[float, angle(0.0, np.pi / 2, open=True)] = np.radians(60)
          ) -> LambdaTranslatingSlot:
    """МЧВ5 on a straight-line design: slot along the straight part of D's path (perpendicular to
    the axis e), through its foot P = C + Y·e, output guide turned by γ from e.

    Give either ``guide_angle`` γ (radians, default 0: s = x − Y, stroke h0 = range of x) or a
    ``stroke`` h ≥ h0 (γ = arccos(h0/h), turned by ``side``·γ). Raises InfeasibleDesignError
    when h < h0 or the needed pressure angle γ exceeds ``max_pressure``.

    With the slot direction v and the guide direction w, s = v×(D − P)/(v×w) in closed form (its
    analogs the same projection of D′, D″); with γ = 0, s = x − Y and the residual is exactly 2E,
    a turned guide scales the stroke by 1/cos γ at a constant pressure angle γ. K = 1 whatever γ
    (the curve's symmetry), so K cannot be chosen.

    Parameters
    ----------
    guide : StraightGuide
        A straight-line guiding lambda mechanism (:func:`straight_guiding`).
    stroke : float, optional
        The output's stroke h (units of l), ≥ h0.
    guide_angle : float, optional
        γ (rad), in (−π/2, π/2); default 0.
    side : {1, -1}
        Sign of γ when it follows from ``stroke``.
    max_pressure : float
        Largest admitted pressure angle γ (rad, default 60°).

    Returns
    -------
    LambdaTranslatingSlot
        МЧВ5, lengths in units of l.

    Raises
    ------
    MechanismError
        Both ``stroke`` and ``guide_angle`` given.
    InfeasibleDesignError
        h < h0, or γ exceeds ``max_pressure``.
    TypeError
        ``guide`` is not a StraightGuide.
    DimensionError
        An argument out of range.

    Examples
    --------
    >>> import numpy as np
    >>> import mechlab as ml
    >>> guide = ml.straight_guiding(np.pi, 0.8, np.pi)
    >>> round(ml.slider_report(ml.mchv5(guide)).stroke, 4), round(ml.slider_report(ml.mchv5(guide, 0.4)).stroke, 4)
    (0.3596, 0.4)
    """
    if stroke is not None and guide_angle is not None:
        raise MechanismError("give either the stroke or the guide angle γ, not both")
    h0 = _axis_stroke(guide)
    if stroke is not None:
        h = stroke
        if h < h0 * (1 - 1e-12):
            raise InfeasibleDesignError(
                f"stroke h = {h:.6g} is below the stroke h0 = {h0:.6g} of the slot across the axis: a translating "
                f"slot parallel to the straight part moves at least h0 (h = h0/cos γ)")
        gamma = side * float(np.arccos(min(h0 / h, 1.0)))
    else:
        gamma = 0.0 if guide_angle is None else guide_angle
    if abs(gamma) > max_pressure:
        raise InfeasibleDesignError(
            f"the output's guide would be turned by γ = {np.degrees(abs(gamma)):.4g}° from the slot normal "
            f"(stroke {h0 / np.cos(gamma):.6g} = h0/cos γ, h0 = {h0:.6g}): its pressure angle exceeds the allowed "
            f"{np.degrees(max_pressure):.4g}°")
    m = guide.mechanism
    e = m.axis
    P = m.C + guide.Y * e
    ang = float(np.arctan2(e[1], e[0]))
    return LambdaTranslatingSlot(m.r, m.a, m.delta, float(P[0]), float(P[1]), ang + np.pi / 2, ang + gamma,
                                 guide.dwell)


# --------------------------------------------------------------------------------------------
# Simulation: the same measures as the rotating-output six-bars
# --------------------------------------------------------------------------------------------
class _AsAngle:
    """A translating-output six-bar presented to :func:`.sixbars.report` and
    :func:`.sixbars.rise_law`, which read ψ: here ψ := s (so "swing" reads as the stroke)."""

    def __init__(self, mech):
        self.mech, self.base = mech, mech.base

    def motion(self, phi) -> AngularMotion:
        mo = self.mech.motion(phi)
        return AngularMotion(mo.phi, mo.points, lambda _: mo.transmission, mo.s, mo.ds, mo.dds)


@dataclass(frozen=True)
class SliderReport:
    """What a simulation of a translating-output dwell six-bar shows (lengths in units of l)."""

    dwell: float      # crank angle of the designed dwell 2α
    residual: float   # range of s over the dwell (residual motion)
    stroke: float     # |s(far extreme) − s(dwell centre)|
    far: float        # crank angle φ of the far extreme (s′ = 0)
    K: float          # measured time ratio (far − dwell end) / (next dwell start − far)
    mu_min: float     # smallest transmission angle of the base four-bar over the turn
    mu_max: float
    mu2_min: float    # of the attached group (μ2′ for МЧВ2; constant for МЧВ5)
    mu2_max: float


@validated
def slider_report(mech: Slider, dwell: OptionalDwell = None) -> SliderReport:
    """Simulate МЧВ2 or МЧВ5 over a turn (the measures of :func:`.sixbars.report`): residual motion
    in the dwell centred on φ = π, stroke, far extreme, measured K, transmission angles.

    Parameters
    ----------
    mech : LambdaSliderSixBar or LambdaTranslatingSlot
        МЧВ2 or МЧВ5.
    dwell : float, optional
        The dwell's crank angle 2α (rad), in (0, 2π); by default the mechanism's own.

    Returns
    -------
    SliderReport
        dwell, residual, stroke (units of l), far (rad), K, and the transmission angles (rad).

    Raises
    ------
    TypeError
        ``mech`` is not МЧВ2 or МЧВ5.
    DimensionError
        ``dwell`` outside (0, 2π).

    Examples
    --------
    >>> import numpy as np
    >>> import mechlab as ml
    >>> guide = ml.circle_guiding(np.radians(150), 0.9, np.radians(120))
    >>> report = ml.slider_report(ml.mchv2(guide, 1.0))
    >>> round(report.stroke, 4), round(float(np.degrees(report.mu2_min)), 1)
    (0.3217, 53.3)
    """
    dwell = mech.dwell if dwell is None else dwell
    r = report(_AsAngle(mech), dwell)
    return SliderReport(r.dwell, r.residual, r.swing, r.far, r.K, r.mu_min, r.mu_max, r.mu2_min, r.mu2_max)


@validated
def slider_rise(mech: Slider, dwell: OptionalDwell = None, n: Annotated[int, Spec("count", 3, 10**6)] = 4001):
    """(φ, s, s′, s″) over the rise, from the end of the dwell to the far extreme (:func:`.sixbars.rise_law`)."""
    # the arguments are checked above; rise_law's own check admits the rotary six-bars only
    return rise_law.__wrapped__(_AsAngle(mech), mech.dwell if dwell is None else dwell, n)


@validated
def slider_invariants(mech: Slider, dwell: OptionalDwell = None) -> Invariants:
    """B, C, D of the rise (:func:`mechlab.analysis.motion_laws.rise_invariants`; Kinitsky (1994), chapter 2).

    Parameters
    ----------
    mech : LambdaSliderSixBar or LambdaTranslatingSlot
        МЧВ2 or МЧВ5.
    dwell : float, optional
        The dwell's crank angle 2α (rad), in (0, 2π); by default the mechanism's own.

    Returns
    -------
    Invariants
        B (velocity), C (acceleration), D (kinetic power) of the rise from the dwell's end to the far extreme.

    Raises
    ------
    TypeError
        ``mech`` is not МЧВ2 or МЧВ5.
    DimensionError
        ``dwell`` outside (0, 2π).

    Examples
    --------
    >>> import numpy as np
    >>> import mechlab as ml
    >>> guide = ml.circle_guiding(np.radians(150), 0.9, np.radians(120))
    >>> ml.slider_invariants(ml.mchv2(guide, 1.0))
    Invariants(B=2.0049, C=10.4420, D=10.1496)
    """
    return rise_invariants(*slider_rise(mech, dwell))

