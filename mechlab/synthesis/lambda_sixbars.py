"""Six-bar dwell mechanisms made by attaching a dyad to the coupler point D (Kinitsky (1994), Figs. 1, 3).

* МЧВ1 (:class:`LambdaRockerSixBar`, :func:`mchv1`): a circle-guiding lambda mechanism, a rod D-E of
  length R (E near the arc centre Q while D runs on the arc) and a rocker E-F that dwells. By time
  ratio K and swing β_m (formulas (14), (15), Fig. 3): farthest out where DE lies on the normal to
  the curve at D, t = α + φ_n, φ_n = 2K(π − α)/(1 + K); E1 = D1 + R·n; F on the perpendicular
  bisector of Q-E1, rocker b = S/(2 sin(β_m/2)), S = |QE1|.
* МЧВ3 (:class:`LambdaSlottedSixBar`): a straight-line lambda mechanism driving a slotted link about
  P. Slot through P, P on the line beyond the curve: oscillation with a dwell (МЧВ3-1М); P on the
  straight part: 180° per turn with a dwell (МЧВ3-2М). МЧВ3-3М (360°) is reconstructed (the abstract:
  pivot inside the curve, dwell adjusted by moving it): slot offset to lie along the line, residual
  ≈ E/(distance of the pivot's foot from the dwell part), ≈ √(4E/e) with the foot inside it.

Frames as in :mod:`mechlab.synthesis.lambda_guiding`: the dwell centred on φ = π, the crank turning
counter-clockwise.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Annotated

import numpy as np
from scipy.optimize import brentq

from ..errors import InfeasibleDesignError, MechanismError, TransmissionAngleError
from ..geometry import cross
from ..mechanisms.base import TWO_PI
from ..mechanisms.lambda_sixbars import LambdaRockerSixBar, LambdaSlottedSixBar
from ..motion import Table, scalar_law
from ..validate import (
    MAX_GRID,
    Angles,
    Distance,
    Length,
    Sign,
    Spec,
    angle,
    check_value,
    count,
    mechanism,
    number,
    validated,
)
from .lambda_guiding import CircleGuide, StraightGuide, straight_guiding

# A time ratio K (> 0), the working limit μ_min of a transmission angle (None: no limit), the guides
MIN_SWING = 1e-6  # radians: a smaller swing β_m overflows the rocker's design
# the grids mchv3_full_turn_best searches by default: the pivot's step beyond the guide and its depth (units of l)
BEYONDS = np.arange(0.0, 0.5001, 0.005)
DEPTHS = np.arange(0.005, 0.2001, 0.005)
TimeRatio = Annotated[float, number(0.0, 1e6, open=True, error=InfeasibleDesignError)]
MuMin = Annotated[float | None, angle(0.0, np.pi / 2, optional=True)]
Circle = Annotated[CircleGuide, mechanism(CircleGuide)]
Straight = Annotated[StraightGuide, mechanism(StraightGuide)]
Grid = Annotated[np.ndarray, Spec("samples", lo=1, hi=MAX_GRID)]  # one axis of a scan
DwellAngle = Annotated[float, angle(0.0, TWO_PI, open=True)]  # the crank angle 2α of a dwell
SixBar = Annotated[LambdaSlottedSixBar, mechanism((LambdaRockerSixBar, LambdaSlottedSixBar))]

__all__ = [
    "BestPivotRow",
    "PivotRow",
    "SixBarReport",
    "dwell_extent",
    "mchv1",
    "mchv3_best_table",
    "mchv3_full_turn",
    "mchv3_full_turn_best",
    "mchv3_half_turn",
    "mchv3_oscillating",
    "mchv3_pivot_table",
    "report",
    "rise_law",
    "slot_residual_first_order",
    "time_ratio_far_angle",
]


@validated
def time_ratio_far_angle(K: TimeRatio, dwell: DwellAngle) -> float:
    """Crank angle φ_n from the end of the dwell to the far extreme: K = φ_n / (2π − 2α − φ_n),
    so φ_n = 2K(π − α)/(1 + K) (Kinitsky (1994), (14)-(15)).

    Parameters
    ----------
    K : float
        Time ratio, > 0.
    dwell : float
        Crank angle of the dwell 2α (rad), in (0, 2π).

    Returns
    -------
    float
        φ_n (rad).

    Raises
    ------
    InfeasibleDesignError
        ``K`` is not a positive number.
    DimensionError
        ``dwell`` outside (0, 2π).

    Examples
    --------
    >>> import numpy as np
    >>> import mechlab as ml
    >>> round(ml.time_ratio_far_angle(1.0, 2 * np.pi / 3), 4)  # 120°: half of what the dwell leaves
    2.0944
    """
    alpha = dwell / 2
    return 2 * K * (np.pi - alpha) / (1 + K)


@dataclass(frozen=True)
class SixBarReport:
    """What a simulation of a dwell six-bar shows (angles in radians)."""

    dwell: float          # crank angle of the designed dwell 2α
    residual: float       # range of ψ over the dwell (residual motion)
    swing: float          # |ψ(far extreme) − ψ(dwell centre)|
    far: float            # crank angle φ of the far extreme (ψ' = 0)
    K: float              # measured time ratio (far − dwell end) / (next dwell start − far)
    mu_min: float         # smallest transmission angle of the base four-bar over the turn
    mu_max: float
    mu2_min: float        # of the attached dyad
    mu2_max: float


@validated
def mchv1(guide: Circle, K: TimeRatio, swing: float, *, side: Sign = 1,
          mu_min: MuMin = np.radians(30)) -> LambdaRockerSixBar:
    """МЧВ1 from a circle-guiding design, a time ratio K and a swing β_m (radians) — Fig. 3.

    The rod's direction at the far extreme, E1 = D1 + R·n, is the normal n to the coupler curve at D1
    oriented by O1 − D0 (O1 = Q, the arc centre; D0 = D at the dwell's centre): in the dwell E sits at O1,
    so the rod points along O1 − D0, and from there to the far extreme it turns with the normal of the
    convex branch without changing assembly, staying on that side of the curve. Orienting it by O1 − D1
    instead fails where O1 lies near the tangent at D1: at (δ, a, 2α) = (180°, 1.2, 240°), K = 1,
    n·(O1 − D1) = −0.014 picks the wrong side (S = 0.5052 instead of 0.53381, b = 1.53705).

    ``side`` picks the rocker's pivot F on the perpendicular bisector of the chord O1-E1 (the thesis' locus
    of F for a given K): +1 (the default) to the left of O1→E1, −1 to the right. The thesis fixes F by
    its figure only; +1 is kept as the default for continuity with earlier results, and the other side
    gives a different mechanism (at (δ, a, 2α) = (180°, 0.5, 240°), K = 1, β_m = 20°, side −1 has B, C, D
    9 %, 0.6 % and 28 % larger): pass ``side`` to choose, and compare both with :func:`report`. Raises
    InfeasibleDesignError (naming the condition) when K, β_m or the geometry admit no mechanism, and — unless
    ``mu_min`` is None — TransmissionAngleError (an InfeasibleDesignError) when the transmission angle
    of the base four-bar or the angle D-E-F of the attached dyad leaves the working range
    [μ_min, 180° − μ_min] over the turn (Kinitsky (1994), §1.8: 30° ≤ μ ≤ 150°, the figure "cnm" of
    Fig. 2a); pass ``mu_min=None`` to get such a design anyway.

    Parameters
    ----------
    guide : CircleGuide
        A circle-guiding lambda mechanism (:func:`circle_guiding`).
    K : float
        Time ratio, > 0.
    swing : float
        The rocker's swing β_m (rad), in (0, π).
    side : {1, -1}
        Side of the chord O1-E1 on which the rocker's pivot F lies.
    mu_min : float, optional
        Least admitted transmission angle (rad); None accepts any (default 30°).

    Returns
    -------
    LambdaRockerSixBar
        The six-bar, lengths in units of the crank's l.

    Raises
    ------
    InfeasibleDesignError
        K, β_m or the geometry admit no mechanism (the message names the condition).
    TransmissionAngleError
        A transmission angle leaves [μ_min, 180° − μ_min] over the turn.
    DimensionError
        ``swing`` outside (0, π), or ``side`` not ±1.
    TypeError
        ``guide`` is not a CircleGuide.

    Examples
    --------
    >>> import numpy as np
    >>> import mechlab as ml
    >>> guide = ml.circle_guiding(np.radians(150), 0.9, np.radians(120))
    >>> six = ml.mchv1(guide, 1.0, np.radians(20))
    >>> psi = six.motion(np.array([0.0, np.pi])).psi  # the far extreme and the dwell's centre
    >>> round(float(np.degrees(abs(psi[0] - psi[1]))), 2)
    20.0
    """
    swing = check_value("swing", swing, Spec("angle", MIN_SWING, np.pi, open_hi=True))
    m, alpha, R, Q = guide.mechanism, guide.alpha, guide.R, guide.centre
    phi_far = np.pi + alpha + time_ratio_far_angle(K, guide.dwell)
    D1 = m.motion(np.array([phi_far])).points["D"]
    D0 = m.coupler_point(np.array([np.pi]))[0]
    v = D1.d[0] / np.hypot(*D1.d[0])
    # the rod lies along the normal at D1, on the side the rod D0→E = Q points to in the dwell (docstring)
    n = np.array([-v[1], v[0]])
    if n @ (Q - D0) < 0:
        n = -n
    E1 = D1.p[0] + R * n
    S = float(np.hypot(*(E1 - Q)))
    if S < 1e-9:
        raise InfeasibleDesignError("E does not move: the far position of E coincides with the arc centre")
    b = S / (2 * np.sin(swing / 2))
    U = 0.5 * (Q + E1)
    w = (E1 - Q) / S
    h = np.sqrt(max(b * b - S * S / 4, 0.0))
    F = U + side * h * np.array([-w[1], w[0]])
    # the assembly in which E sits at E1 at the far extreme (and near Q in the dwell)
    asm = 1 if cross(F - D1.p[0], E1 - D1.p[0]) > 0 else -1
    if (cross(F - D0, Q - D0) > 0) != (asm > 0):
        raise InfeasibleDesignError(
            f"K = {K:g}, β_m = {np.degrees(swing):.4g}° (side {side:+d}): the rod D-E would have to change "
            f"assembly between the dwell and the far extreme; try the other side or a smaller swing")
    try:
        six = LambdaRockerSixBar(m.r, m.a, m.delta, R, b, float(F[0]), float(F[1]), asm, guide.dwell)
    except MechanismError as err:
        raise InfeasibleDesignError(f"K = {K:g}, β_m = {np.degrees(swing):.4g}°: {err}") from None
    # the designed extreme must be the real far extreme of the simulated rocker
    rep = report(six, guide.dwell)
    if abs((rep.far - phi_far + np.pi) % TWO_PI - np.pi) > 1e-6 or abs(rep.swing - swing) > 0.25 * swing:
        raise InfeasibleDesignError(
            f"K = {K:g}, β_m = {np.degrees(swing):.4g}° (side {side:+d}): the simulated rocker's far extreme is at "
            f"φ = {np.degrees(rep.far):.2f}°, not at the designed {np.degrees(phi_far % TWO_PI):.2f}°")
    if mu_min is not None:
        # both four-bars transmit: the base (crank, coupler, rocker) and the attached dyad D-E-F
        angles = (("of the base four-bar", rep.mu_min, rep.mu_max), ("D-E-F", rep.mu2_min, rep.mu2_max))
        for what, low, high in angles:
            if low < mu_min or high > np.pi - mu_min:
                bad = low if low < mu_min else high
                raise TransmissionAngleError(
                    f"K = {K:g}, β_m = {np.degrees(swing):.4g}° (side {side:+d}): the transmission angle {what} "
                    f"reaches {np.degrees(bad):.1f}°, outside {np.degrees(mu_min):g}°…{180 - np.degrees(mu_min):g}° "
                    f"(mu_min); pass mu_min=None to accept it")
    return six


def _far_extreme(mech, dwell: float) -> float:
    """Crank angle (in (π + α, 3π − α)) of the rocker's far extreme: ψ' = 0 farthest from ψ(π)."""
    alpha = dwell / 2
    phi = np.linspace(np.pi + alpha, 3 * np.pi - alpha, 2001)
    mo = mech.motion(phi)
    ref = mech.motion(np.array([np.pi])).psi[0]
    i = int(np.argmax(np.abs(mo.psi - ref)))
    lo, hi = phi[max(i - 1, 0)], phi[min(i + 1, len(phi) - 1)]
    def f(x):
        return mech.motion(np.array([x])).dpsi[0]
    if f(lo) * f(hi) > 0:
        return float(phi[i] % TWO_PI)
    return float(brentq(f, lo, hi, xtol=1e-14) % TWO_PI)


def report(mech, dwell: float) -> SixBarReport:
    """Simulate a dwell six-bar over a turn: residual motion in the dwell (centred on φ = π),
    swing, far extreme, measured K and transmission angles."""
    alpha = dwell / 2
    mo = mech.motion(np.linspace(0, TWO_PI, 2881))
    inside = mech.motion(np.pi + np.linspace(-alpha, alpha, 801)).psi
    far = _far_extreme(mech, dwell)
    psi_far = mech.motion(np.array([far])).psi[0]
    psi0 = mech.motion(np.array([np.pi])).psi[0]
    t = (far - np.pi) % TWO_PI  # thesis angle of the far extreme
    K = (t - alpha) / (TWO_PI - alpha - t)
    mu_base = mech.base.motion(mo.phi).transmission
    return SixBarReport(dwell, float(np.ptp(inside)), float(abs(psi_far - psi0)), far, float(K),
                        float(mu_base.min()), float(mu_base.max()), float(mo.transmission.min()),
                        float(mo.transmission.max()))


def _line_frame(guide: StraightGuide):
    m = guide.mechanism
    e = m.axis
    foot = m.C + guide.Y * e  # the point of the straight line on the axis
    return m, e, foot


@validated
def mchv3_oscillating(guide: Straight, distance: Length) -> LambdaSlottedSixBar:
    """МЧВ3-1М: pivot on the straight line, ``distance`` (units of l) beyond the end D1 of the
    straight part: the slot stays along the line during the dwell, the link oscillates.

    Parameters
    ----------
    guide : StraightGuide
        A straight-line guiding lambda mechanism (:func:`straight_guiding`).
    distance : float
        How far past the end of the straight part the pivot lies (units of l), > 0.

    Returns
    -------
    LambdaSlottedSixBar
        The six-bar with an oscillating slotted link.

    Raises
    ------
    TypeError
        ``guide`` is not a StraightGuide.
    DimensionError
        ``distance`` is not a positive length.

    Examples
    --------
    >>> import numpy as np
    >>> import mechlab as ml
    >>> guide = ml.straight_guiding(np.pi, 0.8, np.pi)
    >>> six = ml.mchv3_oscillating(guide, 0.1)
    >>> psi = six.motion(np.pi + np.linspace(-np.pi / 2, np.pi / 2, 101)).psi
    >>> round(float(np.degrees(np.ptp(psi))), 2)  # residual motion over the 180° dwell, degrees
    1.4
    """
    m, e, foot = _line_frame(guide)
    half = abs(m.axis_coordinates(np.array([np.pi + guide.dwell / 2]))[1][0])
    along = np.array([-e[1], e[0]])
    P = foot - (half + distance) * along
    return LambdaSlottedSixBar(m.r, m.a, m.delta, float(P[0]), float(P[1]), 0.0, guide.dwell)


@validated
def mchv3_half_turn(guide: Straight) -> LambdaSlottedSixBar:
    """МЧВ3-2М: pivot on the straight part of the path (at D0): 180° per crank turn with a dwell.

    Parameters
    ----------
    guide : StraightGuide
        A straight-line guiding lambda mechanism (:func:`straight_guiding`).

    Returns
    -------
    LambdaSlottedSixBar
        The six-bar whose slotted link turns half a turn per crank turn.

    Raises
    ------
    TypeError
        ``guide`` is not a StraightGuide.

    Examples
    --------
    >>> import numpy as np
    >>> import mechlab as ml
    >>> guide = ml.straight_guiding(np.pi, 0.8, np.pi)
    >>> float(ml.mchv3_half_turn(guide).turns)
    -0.5
    """
    m = guide.mechanism
    P = m.coupler_point(np.array([np.pi]))[0]
    return LambdaSlottedSixBar(m.r, m.a, m.delta, float(P[0]), float(P[1]), 0.0, guide.dwell)


@validated
def rise_law(mech: SixBar, dwell: DwellAngle, n: Annotated[int, count(2)] = 4001):
    """Output law over the rise: from the end of the dwell (φ = π + α) to the far extreme.

    Sampled for :func:`mechlab.analysis.motion_laws.rise_invariants` (Kinitsky (1994), chapter 2).

    Parameters
    ----------
    mech : LambdaRockerSixBar or LambdaSlottedSixBar
        A rotary-output dwell six-bar.
    dwell : float
        The dwell's crank angle 2α (rad), in (0, 2π).
    n : int
        Samples, ≥ 2 (default 4001).

    Returns
    -------
    phi, psi, dpsi, ddpsi : numpy.ndarray
        Crank angles (rad), ψ (rad), ψ′ and ψ″ over the rise.

    Raises
    ------
    TypeError
        ``mech`` is not a lambda six-bar with a rotating output.
    DimensionError
        ``dwell`` outside (0, 2π), or ``n`` < 2.

    Examples
    --------
    >>> import numpy as np
    >>> import mechlab as ml
    >>> guide = ml.circle_guiding(np.radians(150), 0.9, np.radians(120))
    >>> phi, psi, dpsi, ddpsi = ml.rise_law(ml.mchv1(guide, 1.0, np.radians(20)), guide.dwell, n=11)
    >>> round(float(np.degrees(phi[0])), 1), round(float(np.degrees(phi[-1])), 1)
    (240.0, 360.0)
    """
    far = _far_extreme(mech, dwell)
    start = np.pi + dwell / 2
    end = far if far > start else far + TWO_PI
    phi = np.linspace(start, end, n)
    mo = mech.motion(phi)
    return phi, mo.psi, mo.dpsi, mo.ddpsi


@validated
def mchv3_full_turn(guide: Straight, beyond: Distance = 0.06, depth: Length = 0.05,
                    side: Sign = 1) -> LambdaSlottedSixBar:
    """МЧВ3-3М (as reconstructed): 360° per crank turn with an approximate dwell.

    The pivot P sits inside the coupler curve, ``beyond`` past one end of the dwell part of the
    straight line (``side`` ±1 picks the end) and ``depth`` into the curve; the slot is offset
    from P by ``depth``, so on the straight part it lies along the line itself. As D runs along
    the line the slot stays put up to ≈ E/s (s = D's distance from the foot of P on the line,
    ≥ ``beyond``): the residual motion is of order E/beyond, and moving P along the line trades
    the dwell's length for its accuracy (the thesis' adjustable dwell). The defaults suit
    Chebyshev's lambda (2α = 180°). Raises InfeasibleDesignError if P is not inside the curve.

    The residual is not caused by the pivot being inside the curve: for D exactly on the line the
    slot *is* the line (it is tangent to the offset circle), so an exact straight segment would dwell
    exactly; to first order the slot turns by h/s (:func:`slot_residual_first_order`; h = D's distance
    from the line, ≤ E). With 2α = 180° the curve leaves ≤ 0.065 l for the pivot past the dwell end, so
    over the full 180° the defaults give 2.15° and the best pivot 2.01° (:func:`mchv3_full_turn_best`):
    ~2° is inherent there; a guide designed for a shorter dwell does better (160°: 0.94°, 140°: 0.55°).

    Parameters
    ----------
    guide : StraightGuide
        A straight-line guiding lambda mechanism (:func:`straight_guiding`).
    beyond : float
        Pivot past the end of the dwell part (units of l), ≥ 0 (default 0.06).
    depth : float
        Pivot into the curve and the slot's offset (units of l), > 0 (default 0.05).
    side : {1, -1}
        Which end of the dwell part.

    Returns
    -------
    LambdaSlottedSixBar
        The six-bar whose slotted link turns once per crank turn.

    Raises
    ------
    InfeasibleDesignError
        The pivot is not inside the coupler curve (or the slot cannot reach the pin).
    TypeError
        ``guide`` is not a StraightGuide.
    DimensionError
        ``beyond``, ``depth`` or ``side`` out of range.

    Examples
    --------
    >>> import numpy as np
    >>> import mechlab as ml
    >>> guide = ml.straight_guiding(np.pi, 0.8, np.pi)
    >>> float(ml.mchv3_full_turn(guide).turns)
    -1.0
    """
    m, e, foot = _line_frame(guide)
    along = np.array([-e[1], e[0]])
    half = abs(m.axis_coordinates(np.array([np.pi + guide.dwell / 2]))[1][0])
    P = foot + side * (half + beyond) * along + depth * e
    best = None
    for off in (depth, -depth):
        try:
            cand = LambdaSlottedSixBar(m.r, m.a, m.delta, float(P[0]), float(P[1]), off, guide.dwell)
        except MechanismError:
            continue
        if abs(cand.turns) != 1:
            continue
        res = np.ptp(cand.motion(np.pi + np.linspace(-0.3, 0.3, 7) * guide.dwell / 2).psi)
        if best is None or res < best[0]:
            best = (res, cand)
    if best is None:
        raise InfeasibleDesignError(
            f"beyond = {beyond:g}, depth = {depth:g}: the pivot is not inside the coupler curve (or the slot "
            f"cannot reach the pin), so the link does not turn once per crank turn")
    return best[1]


@validated
def dwell_extent(mech: SixBar, tol: Annotated[float, number(0.0, 1.0, open=True)] = 0.02,
                 n: Annotated[int, count(3)] = 2881) -> float:
    """Crank angle around φ = π over which |ψ'| stays below tol·max|ψ'| (the usable dwell).

    Parameters
    ----------
    mech : LambdaRockerSixBar or LambdaSlottedSixBar
        A rotary-output dwell six-bar.
    tol : float
        Share of the peak |ψ′|, in (0, 1) (default 0.02).
    n : int
        Samples of the cycle, ≥ 3 (default 2881).

    Returns
    -------
    float
        The usable dwell (rad); 0 when the output moves at φ = π.

    Raises
    ------
    TypeError
        ``mech`` is not a lambda six-bar with a rotating output.
    DimensionError
        ``tol`` or ``n`` out of range.

    Examples
    --------
    >>> import numpy as np
    >>> import mechlab as ml
    >>> guide = ml.straight_guiding(np.pi, 0.8, np.pi)
    >>> round(float(np.degrees(ml.dwell_extent(ml.mchv3_full_turn(guide)))), 1)
    237.9
    """
    phi = mech.cycle(n)
    d = np.abs(mech.motion(phi).dpsi)
    still = d <= tol * d.max()
    i0 = int(np.argmin(np.abs(phi - np.pi)))
    if not still[i0]:
        return 0.0
    lo = i0
    while lo > 0 and still[lo - 1]:
        lo -= 1
    hi = i0
    while hi < len(phi) - 1 and still[hi + 1]:
        hi += 1
    return float(phi[hi] - phi[lo])


@scalar_law
@validated
def slot_residual_first_order(mech: Annotated[LambdaSlottedSixBar, mechanism(LambdaSlottedSixBar)], guide: Straight,
                              phi: Angles) -> np.ndarray:
    """First-order turn of the МЧВ3-3М slot away from the guide's line L at crank angles φ (radians).

    Derivation: the slot is the tangent from the pin D to the circle of radius |e| about P; P sits
    at distance |e| from L, so for D exactly on L that tangent *is* L, whatever D's position on it —
    an exact straight segment would give an exact dwell, the pivot inside the curve costs nothing.
    With D off L by h = x − Y (x: D's coordinate along the axis) and at s = y − y_P along L from
    the foot of P (the tangent point), the tangent turns about that point by atan(h/s) ≈ h/s. So the
    residual motion over the dwell is ≈ ptp(h/s): the straightness E of the guide divided by D's
    distance from the pivot's foot, worst at the dwell end nearest the pivot (E/beyond).

    Parameters
    ----------
    mech : LambdaSlottedSixBar
        An МЧВ3-3М (:func:`mchv3_full_turn`).
    guide : StraightGuide
        The straight-line guide it was built on.
    phi : float or array_like
        Crank angles (rad).

    Returns
    -------
    numpy.ndarray
        h/s (rad): compare differences, the simulated ψ − ψ(φ0) ≈ ±(h/s − (h/s)(φ0)).

    Raises
    ------
    TypeError
        ``mech`` or ``guide`` of the wrong kind.
    DimensionError
        ``phi`` is not finite.

    Examples
    --------
    >>> import numpy as np
    >>> import mechlab as ml
    >>> guide = ml.straight_guiding(np.pi, 0.8, np.pi)
    >>> turn = ml.slot_residual_first_order(ml.mchv3_full_turn(guide), guide, np.array([np.pi - 0.5, np.pi + 0.5]))
    >>> np.round(turn, 5).tolist()
    [-0.00023, -0.00044]
    """
    m = mech.base
    x, y = m.axis_coordinates(phi)
    e = m.axis
    yP = (mech.P - m.C) @ np.array([-e[1], e[0]])
    return (x - guide.Y) / (y - yP)


@validated
def mchv3_full_turn_best(guide: Straight, side: Sign = 1,
                         max_speed: Annotated[float | None, number(0.0, open=True, optional=True)] = 15.0,
                         beyonds: Grid = BEYONDS, depths: Grid = DEPTHS):
    """МЧВ3-3М with the pivot placed for the smallest residual over the guide's dwell.

    Scans the pivot's position (``beyonds`` past the dwell end × ``depths`` into the curve) with the
    first-order residual ptp(h/s) of :func:`slot_residual_first_order` (no dyad solve), keeping pivots
    inside the coupler curve (winding number ±1: the link turns once per crank turn) whose offset
    circle the pin's path clears; candidates are tried best first, built by :func:`mchv3_full_turn`
    and simulated, until one whose peak |ψ'| over the turn (fine grid) is ≤ ``max_speed`` (None: no
    limit). The bound matters: the smallest residuals come with the pin grazing the offset circle,
    where the link whips round (ψ' ≈ 96, ψ'' ≈ 13 000 for the 180° optimum without it).
    Returns (mechanism, simulated residual = range of ψ over the guide's dwell).

    Findings (δ = 180°, a = 0.8, :func:`straight_guiding`; residual over the guide's dwell): for
    Chebyshev's 2α = 180° no pivot inside the curve lies farther than ≈ 0.065 l past the dwell end, so
    the residual cannot drop much below E/0.065 ≈ 1.7°: the best found is 2.01° (pivot 0.065 l past,
    0.04 l deep; peak ψ' 13.9, ψ'' 758) against the reconstruction's default (0.06, 0.05) with 2.15°
    (ψ' 13.4, ψ'' 276); without the speed bound 2.03° with ψ' ≈ 96. A free Nelder-Mead over P and e
    at the default's clearance gives 2.12°. So the ~2° is inherent to a 180° straight part, not a poor
    choice of pivot. Shorter dwells leave the pivot room: a guide for 2α = 160° gives 0.94°, 140° 0.55°.

    Parameters
    ----------
    guide : StraightGuide
        A straight-line guiding lambda mechanism (:func:`straight_guiding`).
    side : {1, -1}
        Which end of the dwell part.
    max_speed : float, optional
        Largest admitted peak |ψ′| over the turn (default 15); None: no limit.
    beyonds, depths : array_like
        The scan's grids of pivot positions (units of l).

    Returns
    -------
    mechanism : LambdaSlottedSixBar
        The best МЧВ3-3М found.
    residual : float
        Its simulated residual, the range of ψ over the guide's dwell (rad).

    Raises
    ------
    InfeasibleDesignError
        No pivot on the grids gives a full-turn link within ``max_speed``.
    TypeError
        ``guide`` is not a StraightGuide.
    DimensionError
        ``side``, ``max_speed`` or a grid out of range.

    Examples
    --------
    >>> import numpy as np
    >>> import mechlab as ml
    >>> guide = ml.straight_guiding(np.pi, 0.8, np.pi)
    >>> six, residual = ml.mchv3_full_turn_best(guide)
    >>> round(float(np.degrees(residual)), 2)
    2.01
    """
    m, _e, _foot = _line_frame(guide)
    half = abs(m.axis_coordinates(np.array([np.pi + guide.dwell / 2]))[1][0])
    xc, yc = m.axis_coordinates(np.linspace(0, TWO_PI, 1441))
    t = np.pi + np.linspace(-guide.dwell / 2, guide.dwell / 2, 121) + 1e-6
    xd, yd = m.axis_coordinates(t)
    h = xd - guide.Y
    beyonds = np.asarray(beyonds, dtype=float)
    yP = side * (half + beyonds)
    cands = []
    for depth in np.asarray(depths, dtype=float):
        dx, dy = xc[None, :] - (guide.Y + depth), yc[None, :] - yP[:, None]
        ang = np.unwrap(np.arctan2(dy, dx), axis=1)
        winding = np.round((ang[:, -1] - ang[:, 0]) / TWO_PI)
        gap = np.hypot(dx, dy).min(axis=1) - depth
        with np.errstate(divide="ignore", invalid="ignore"):
            res = np.ptp(h[None, :] / (yd[None, :] - yP[:, None]), axis=1)
        ok = (winding != 0) & (gap > 1e-4)
        cands += [(res[i], beyonds[i], depth) for i in np.nonzero(ok)[0]]
    cands.sort()
    phi = np.linspace(0, TWO_PI, 20001) + 1e-6
    dwell = np.pi + np.linspace(-guide.dwell / 2, guide.dwell / 2, 2001) + 1e-6
    for _, beyond, depth in cands[:400]:
        try:
            mech = mchv3_full_turn(guide, float(beyond), float(depth), side)
            if max_speed is not None and np.abs(mech.motion(phi).dpsi).max() > max_speed:
                continue
        except MechanismError:
            continue
        return mech, float(np.ptp(mech.motion(dwell).psi))
    raise InfeasibleDesignError(
        f"no pivot inside the coupler curve gives a full-turn link with peak |ψ'| ≤ {max_speed} for the dwell "
        f"2α = {np.degrees(guide.dwell):.4g}°")



@dataclass(frozen=True)
class PivotRow:
    """One pivot of :func:`mchv3_pivot_table`: lengths in units of the crank l, angles in degrees."""

    beyond: float = field(metadata={"label": "pivot beyond the dwell part (l)"})
    turns: float = field(metadata={"label": "turns per crank turn"})
    residual: float = field(metadata={"label": "residual over the dwell, °"})
    dwell: float = field(metadata={"label": "crank angle with |ψ′| < 2 % of its peak, °"})


@validated
def mchv3_pivot_table(guide: Straight, beyonds: Grid = (0.0, 0.03, 0.06), depth: Length = 0.05,
                      n: Annotated[int, count(3)] = 1201) -> Table:
    """МЧВ3-3М (:func:`mchv3_full_turn`) with its pivot moved along the line past the guide's dwell part:
    per pivot the turns, the residual (range of ψ over the guide's dwell 2α, ``n`` samples) and the
    usable dwell of :func:`dwell_extent`. The residual falls as the pivot moves away (to first order
    h/s, :func:`slot_residual_first_order`; Kinitsky, 1994, МЧВ3-3М as reconstructed in chapter 8).

    Parameters
    ----------
    guide : StraightGuide
        A straight-line guiding lambda mechanism (:func:`straight_guiding`).
    beyonds : array_like
        Pivot positions past the dwell part (units of l).
    depth : float
        Pivot depth into the curve (units of l).
    n : int
        Samples over the dwell, ≥ 3 (default 1201).

    Returns
    -------
    Table
        One ``PivotRow`` per pivot (angles in degrees).

    Raises
    ------
    InfeasibleDesignError
        A pivot is not inside the coupler curve.
    TypeError
        ``guide`` is not a StraightGuide.
    DimensionError
        ``beyonds``, ``depth`` or ``n`` out of range.

    Examples
    --------
    >>> import numpy as np
    >>> import mechlab as ml
    >>> guide = ml.straight_guiding(np.pi, 0.8, np.pi)
    >>> [round(row.residual, 2) for row in ml.mchv3_pivot_table(guide)]
    [16.14, 3.88, 2.15]
    """
    dw = np.pi + np.linspace(-guide.dwell / 2, guide.dwell / 2, n) + 1e-5  # off φ = π, where the slot turns over
    rows = []
    for beyond in beyonds:
        full = mchv3_full_turn(guide, float(beyond), depth)
        rows.append(PivotRow(float(beyond), float(full.turns), float(np.degrees(np.ptp(full.motion(dw).psi))),
                             float(np.degrees(dwell_extent(full)))))
    return Table(rows)


@dataclass(frozen=True)
class BestPivotRow:
    """One guide of :func:`mchv3_best_table`: lengths in units of the crank l, angles in degrees; ``mechanism``
    is the best МЧВ3-3М (not a column)."""

    dwell: float = field(metadata={"label": "guide's dwell 2α, °"})
    past: float = field(metadata={"label": "best pivot past the end (l)"})
    depth: float = field(metadata={"label": "depth (l)"})
    residual: float = field(metadata={"label": "residual over 2α, °"})
    peak_dpsi: float = field(metadata={"label": "peak |ψ′|"})
    mechanism: LambdaSlottedSixBar = field(repr=False, compare=False)


@validated
def mchv3_best_table(dwells: Angles, delta: DwellAngle = np.pi, a: Length = 0.8, beyonds: Grid | None = None,
                     depths: Grid | None = None) -> Table:
    """The best МЧВ3-3М (:func:`mchv3_full_turn_best`) on the straight guide (:func:`straight_guiding`, δ, a)
    of each dwell 2α in ``dwells`` (radians): where its pivot lies past the end of the dwell part and how
    deep inside the curve, its residual over 2α and its peak |ψ'| over the turn.

    Parameters
    ----------
    dwells : array_like
        The guides' dwells 2α (rad).
    delta : float
        Break angle δ of the lambda mechanism (rad, default π).
    a : float
        Frame length (units of l, default 0.8).
    beyonds, depths : array_like, optional
        The scan's grids; None: those of :func:`mchv3_full_turn_best`.

    Returns
    -------
    Table
        One ``BestPivotRow`` per dwell (lengths in l, angles in degrees).

    Raises
    ------
    SynthesisError
        No straight-line guide exists for a dwell.
    InfeasibleDesignError
        No pivot on the grids gives a full-turn link.
    DimensionError
        An argument out of range.

    Examples
    --------
    >>> import numpy as np
    >>> import mechlab as ml
    >>> row = list(ml.mchv3_best_table(np.radians([160.0])))[0]
    >>> round(row.residual, 2), round(row.past, 3)
    (0.94, 0.165)
    """
    grids = {k: v for k, v in (("beyonds", beyonds), ("depths", depths)) if v is not None}
    rows = []
    for dwell in dwells:
        guide = straight_guiding(delta, a, float(dwell))
        best, residual = mchv3_full_turn_best(guide, **grids)
        m = guide.mechanism
        half = abs(m.axis_coordinates(np.array([np.pi + guide.dwell / 2]))[1][0])
        past = abs((best.P - m.C) @ np.array([-m.axis[1], m.axis[0]])) - half
        rows.append(BestPivotRow(float(np.degrees(dwell)), float(past), float(abs(best.offset)),
                                 float(np.degrees(residual)), float(np.abs(best.motion(best.turn(4001)).dpsi).max()),
                                 best))
    return Table(rows)
