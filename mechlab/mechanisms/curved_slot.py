"""Slotted links whose slot is a curve: Zinchenko et al. (2013), §1-2 (Figs. 2, 4, 7, 8).

Slot curves in the link's frame, ``curve.evaluate(t)`` → PointPath (c, c_t, c_tt): :class:`CircleSlot`
(closed form), :class:`ParametricSlot` (three vectorised functions), :class:`SampledSlot` (a cubic
spline, chord-length parameter). Mechanisms: :class:`CurvedSlotLink` (pivoted link, ψ = ψ_K - β,
formula (12), in the frame of §2, Fig. 8) and :class:`TranslatingCurvedSlot` (s = x_K - x_α,
formula (1), Figs. 4, 7). :func:`structural_twin` builds either for any mechanism from its ``structure()``
(the default ``Mechanism.curved_slot_twin``). ``start`` picks the curve parameter where the pin sits at φ = 0 when
more than one point qualifies (for a circle, the arc the pin runs on).

The pin lies on the slot where |c(t)| = S(φ) = sqrt(a² + d² + 2ad·cos φ) (after formula (25)),
solved on the one working piece of the curve over which |c| runs from a + d to |a - d|
(:meth:`CurvedSlotLink.beta`). A slot tangent to the pin's circle about the pivot (pressure angle
90°, e.g. the two-branch slot of Fig. 10 at E) raises SingularityError; a slot that ends too soon
narrows ``crank_ranges()`` and ``motion`` raises AssemblyError.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from functools import cached_property
from typing import Annotated

import numpy as np
from scipy.optimize import brentq

from ..errors import AssemblyError, DimensionError, SingularityError
from ..geometry import AnglePath, PointPath, as_angles, crank_point, cross, dot, fixed_point, lift, perp
from ..motion import AngularMotion, LinearMotion, scalar_law
from ..validate import Checked, Flag, Function, Length, Point, Real, Spec, mechanism, number
from .base import (
    FRAME,
    FULL_TURN,
    Link,
    Mechanism,
    Pair,
    Part,
    Sketch,
    Structure,
    arc_set,
    bars,
    fmt_ranges,
    output_axis,
)
from .slotted import PivotedSlot, SineMechanism, SlottedLink

# Samples of the curve used to find the working segment and the Newton brackets.
_TABLE = 4097
# |c·c_t| below this fraction of |c||c_t|: the slot is tangent to the circle about the pivot.
_TANGENT_TOL = 1e-10


# ---------------------------------------------------------------------------------------------
# slot curves
# ---------------------------------------------------------------------------------------------
class SlotCurve(Checked):
    """A smooth curve in the link frame, parameter t in [t0, t1] (periodic if closed)."""

    t0: float
    t1: float
    periodic: bool

    def evaluate(self, t) -> PointPath:  # pragma: no cover - interface
        """The curve's points with their first and second derivatives with respect to t.

        Parameters
        ----------
        t : float or array_like
            Curve parameters in [t0, t1] (reduced to it for a periodic curve).

        Returns
        -------
        PointPath
            c(t), c_t, c_tt, each (n, 2), in the link frame.

        Raises
        ------
        DimensionError
            If the curve's functions return arrays of the wrong shape or not finite (a ParametricSlot).
        """
        raise NotImplementedError

    def points(self, t) -> np.ndarray:
        return self.evaluate(t).p


def _xy(value, n, what):
    arr = np.asarray(value, dtype=float)
    if arr.shape != (n, 2):
        raise DimensionError(f"{what} must return an array of shape ({n}, 2), got {arr.shape}")
    if not np.all(np.isfinite(arr)):
        raise DimensionError(f"{what} returned NaN or inf")
    return arr


@dataclass(frozen=True)
class CircleSlot(SlotCurve):
    """Circle of ``radius`` about ``center`` (link frame); c(t) = center + radius·(cos t, sin t).

    Parameters
    ----------
    center : tuple of float
        The circle's centre in the link frame (length).
    radius : float
        Its radius (positive length).

    Raises
    ------
    DimensionError
        For a radius that is not positive and finite.

    Examples
    --------
    >>> import numpy as np
    >>> from mechlab import CircleSlot
    >>> CircleSlot((3.5, 0.0), 3.0).evaluate(np.array([0.0])).p
    array([[6.5, 0. ]])
    """

    center: Point
    radius: Length
    t0: float = field(default=-np.pi, init=False)
    t1: float = field(default=np.pi, init=False)
    periodic: bool = field(default=True, init=False)

    def evaluate(self, t) -> PointPath:
        t = np.atleast_1d(np.asarray(t, dtype=float))
        u = np.stack([np.cos(t), np.sin(t)], axis=-1)
        r = self.radius
        return PointPath(np.asarray(self.center) + r * u, r * np.stack([-u[:, 1], u[:, 0]], axis=-1), -r * u)


@dataclass(frozen=True)
class ParametricSlot(SlotCurve):
    """A curve given by vectorised functions f, f', f'' : t ↦ (n, 2) on [t0, t1].

    Parameters
    ----------
    f, df, ddf : callable
        c(t), c_t(t), c_tt(t), each taking an array of n parameters and returning (n, 2) (link frame).
    t0, t1 : float
        The parameter interval, t0 < t1.
    periodic : bool, optional
        Whether the curve is closed with period t1 − t0.

    Raises
    ------
    DimensionError
        For t0 ≥ t1 (and, on evaluation, for functions returning the wrong shape or non-finite values).

    Examples
    --------
    >>> import numpy as np
    >>> from mechlab import ParametricSlot
    >>> parabola = ParametricSlot(lambda t: np.stack([t, t**2], -1), lambda t: np.stack([1 + 0 * t, 2 * t], -1),
    ...                           lambda t: np.stack([0 * t, 2 + 0 * t], -1), 0.0, 1.0)
    >>> parabola.evaluate(np.array([0.5])).p
    array([[0.5 , 0.25]])
    """

    f: Function
    df: Function
    ddf: Function
    t0: Real
    t1: Real
    periodic: Flag = False

    def __post_init__(self):
        super().__post_init__()
        if not self.t1 > self.t0:
            raise DimensionError(f"the parameter interval must satisfy t0 < t1, got [{self.t0:g}, {self.t1:g}]")

    def evaluate(self, t) -> PointPath:
        t = np.atleast_1d(np.asarray(t, dtype=float))
        n = len(t)
        return PointPath(_xy(self.f(t), n, "f(t)"), _xy(self.df(t), n, "df(t)"), _xy(self.ddf(t), n, "ddf(t)"))


@dataclass(frozen=True, eq=False)
class SampledSlot(SlotCurve):
    """Cubic spline through sampled points of the slot's centre line, chord-length parameter.

    Parameters
    ----------
    samples : array_like
        (m, 2) points (m ≥ 4) in the link frame (length).
    closed : bool, optional
        True makes a periodic spline (the first point is repeated at the end if needed).

    Raises
    ------
    DimensionError
        For fewer than four points, points that are not finite, or two consecutive points that coincide.

    Examples
    --------
    >>> import numpy as np
    >>> from mechlab import SampledSlot
    >>> slot = SampledSlot(np.array([[0, 0], [1, 0.5], [2, 0.8], [3, 0.9]], dtype=float))
    >>> round(slot.t1, 4)  # the chord length
    3.1671
    """

    samples: Annotated[np.ndarray, Spec("points", lo=4)]
    closed: Flag = False
    t0: float = field(default=0.0, init=False)
    t1: float = field(default=1.0, init=False)
    periodic: bool = field(default=False, init=False)

    def __post_init__(self):
        super().__post_init__()
        pts = self.samples
        if self.closed and np.any(pts[0] != pts[-1]):
            pts = np.vstack([pts, pts[:1]])
        seg = np.hypot(*np.diff(pts, axis=0).T)
        if np.any(seg <= 0):
            i = int(np.argmin(seg))
            raise DimensionError(f"slot samples {i} and {i + 1} coincide: the chord-length parameter needs distinct "
                                 f"points")
        t = np.concatenate([[0.0], np.cumsum(seg)])
        from scipy.interpolate import CubicSpline  # imported here: scipy.interpolate is slow to import

        spline = CubicSpline(t, pts, bc_type="periodic" if self.closed else "not-a-knot")
        object.__setattr__(self, "samples", pts)
        object.__setattr__(self, "t1", float(t[-1]))
        object.__setattr__(self, "periodic", bool(self.closed))
        object.__setattr__(self, "_spline", spline)
        object.__setattr__(self, "_d1", spline.derivative(1))
        object.__setattr__(self, "_d2", spline.derivative(2))

    def evaluate(self, t) -> PointPath:
        t = np.atleast_1d(np.asarray(t, dtype=float))
        if self.periodic:
            t = self.t0 + np.mod(t - self.t0, self.t1 - self.t0)
        return PointPath(self._spline(t), self._d1(t), self._d2(t))


# ---------------------------------------------------------------------------------------------
# the working segment: a piece of the curve on which a scalar g(t) is strictly monotone
# ---------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class _Segment:
    """t = t_s + direction·u, u ∈ [0, u_end]; g decreases strictly from g_start to g_end."""

    t_start: float
    direction: int
    u_end: float
    g_end: float
    u_table: np.ndarray
    g_table: np.ndarray
    reason: str          # why the segment ends: "covered", "end", "tangent"


def _walk(curve: SlotCurve, g_of: Callable, dg_of: Callable, t_s: float, direction: int, g_target: float,
          what_tangent: str) -> _Segment:
    """From t_s, follow the curve in ``direction`` while g decreases, until g reaches g_target,
    the curve ends, or g' vanishes (the slot is tangent to the level set)."""
    length = curve.t1 - curve.t0 if curve.periodic else (curve.t1 - t_s if direction > 0 else t_s - curve.t0)
    if length <= 0:
        return _Segment(t_s, direction, 0.0, g_of(np.array([t_s]))[0], np.array([0.0]),
                        g_of(np.array([t_s])), "end")
    u = np.linspace(0.0, length, _TABLE)
    t = t_s + direction * u
    g = g_of(t)
    dg = direction * dg_of(t)  # dg/du
    # first sample where g has reached the target, or where g stops decreasing
    reached = g <= g_target
    rising = dg[1:] >= 0  # ignore u = 0 itself
    i_reach = int(np.argmax(reached)) if np.any(reached) else None
    i_rise = 1 + int(np.argmax(rising)) if np.any(rising) else None
    if i_reach is not None and (i_rise is None or i_reach <= i_rise):
        k = i_reach
        f = lambda uu: g_of(np.array([t_s + direction * uu]))[0] - g_target  # noqa: E731
        u_end = u[k] if f(u[k]) == 0 else brentq(f, u[k - 1], u[k], xtol=1e-15, rtol=1e-15)
        reason, g_end = "covered", g_target
    elif i_rise is not None:
        k = i_rise
        f = lambda uu: direction * dg_of(np.array([t_s + direction * uu]))[0]  # noqa: E731
        u_end = brentq(f, u[k - 1], u[k], xtol=1e-15, rtol=1e-15)
        reason, g_end = "tangent", float(g_of(np.array([t_s + direction * u_end]))[0])
    else:
        k = len(u) - 1
        u_end, reason, g_end = float(u[-1]), "end", float(g[-1])
    keep = u < u_end
    u_tab = np.concatenate([u[keep], [u_end]])
    g_tab = np.concatenate([g[keep], [g_end]])
    return _Segment(float(t_s), int(direction), float(u_end), float(g_end), u_tab, g_tab, reason)


def _solve_on_segment(seg: _Segment, curve: SlotCurve, g_of: Callable, dg_of: Callable, target: np.ndarray):
    """u with g(t_s + dir·u) = target on the segment (g decreasing in u): bracketed Newton, vectorised."""
    gt, ut = seg.g_table, seg.u_table
    # bracket from the monotone table (g decreasing → flip for searchsorted)
    k = np.clip(len(gt) - 1 - np.searchsorted(gt[::-1], target, side="left"), 0, len(gt) - 2)
    lo, hi = ut[k].copy(), ut[k + 1].copy()
    glo, ghi = gt[k], gt[k + 1]
    with np.errstate(divide="ignore", invalid="ignore"):
        w = np.where(glo != ghi, (glo - target) / (glo - ghi), 0.5)
    u = lo + np.clip(w, 0.0, 1.0) * (hi - lo)
    scale = max(1.0, seg.u_end)
    for _ in range(100):
        t = seg.t_start + seg.direction * u
        f = g_of(t) - target
        fp = seg.direction * dg_of(t)
        lo = np.where(f > 0, u, lo)   # g too large → pin not yet far enough along
        hi = np.where(f < 0, u, hi)
        with np.errstate(divide="ignore", invalid="ignore"):
            un = u - f / fp
        bad = ~np.isfinite(un) | (un < lo) | (un > hi)
        un = np.where(bad, 0.5 * (lo + hi), un)
        done = np.abs(un - u) <= 1e-15 * scale
        u = un
        if np.all(done | (f == 0)):
            break
    return u


def _distinct_roots(roots, curve: SlotCurve) -> list[float]:
    """Roots without repeats (on a closed curve t0 and t1 are the same point)."""
    out: list[float] = []
    span = curve.t1 - curve.t0
    for r in sorted(roots):
        if curve.periodic:
            r = curve.t0 + float(np.mod(r - curve.t0, span))
        if all(min(abs(r - q), span - abs(r - q) if curve.periodic else np.inf) > 1e-12 * max(1.0, span)
               for q in out):
            out.append(r)
    return out


def _fmt_deg(x):
    return f"{np.degrees(x):.2f}°"


# a slot given to a mechanism (a DimensionError otherwise, as for any other dimension)
Slot = Annotated[SlotCurve, mechanism((CircleSlot, ParametricSlot, SampledSlot), error=DimensionError)]


def _unit_normal(tangent: np.ndarray) -> np.ndarray:
    """Unit normals (n, 2) to tangents (n, 2): the common normal of a pin in a curved slot."""
    return np.stack([-tangent[:, 1], tangent[:, 0]], axis=-1) / np.hypot(*tangent.T)[:, None]


def slot_sketch(mech, motion, pivot: str = "B") -> Sketch:
    """The diagram of a curved-slot link: the crank, the slot (its working part, ``mech.slot_samples``,
    carried by the link) and the arm holding it: two bars from the pivot to the slot's ends (numbered),
    or for a translating link a rod along the guide (numbered) and the guide."""
    slot = mech.slot_samples(160)
    st = mech.structure()
    crank = bars(st)
    if motion.output.kind == "angle":
        P, psi = motion.points[pivot].p, motion.psi

        def world(i):
            c, s = np.cos(psi[i]), np.sin(psi[i])
            return P[i] + slot @ np.array([[c, s], [-s, c]])

        parts = (Part("slot", world), Part("extra", lambda i: np.array([P[i], world(i)[0]]), st.output),
                 Part("extra", lambda i: np.array([P[i], world(i)[-1]])))
        return Sketch(crank + parts, mech.pivots)
    x = motion.s
    span = np.ptp(x) + 2 * np.max(np.abs(motion.points["A"].p[:, 1]))
    guide = np.array([[x.min() - 0.5 * span, 0.0], [x.max() + 2.2 * span, 0.0]])
    parts = (Part("slot", lambda i: slot + np.array([x[i], 0.0])),
             Part("extra", lambda i: np.array([[x[i], 0.0], [x[i] + 1.5 * span, 0.0]]), st.output),
             Part("extra", lambda i: guide))
    return Sketch(crank + parts, mech.pivots)


# ---------------------------------------------------------------------------------------------
# the oscillating / rotating curved slotted link
# ---------------------------------------------------------------------------------------------
@dataclass(frozen=True, eq=False)
class CurvedSlotLink(PivotedSlot, Mechanism):
    """Crank O-A driving a link pivoted at B = (-pivot_distance, 0) whose curved slot carries the pin A.

    Zinchenko et al. (2013) §2, Fig. 8, formulas (12)-(17): ψ = ψ_K - β with ψ_K the base mechanism's
    angle (formula (18)) and β the polar angle of the pin in the link frame.

    Parameters
    ----------
    crank : float
        Crank radius (positive length).
    pivot_distance : float
        |OB| (positive length, ≠ crank).
    slot : SlotCurve
        The slot, a curve in the link frame (origin at B): a CircleSlot, ParametricSlot or SampledSlot.
    start : float, optional
        The slot parameter t near which the working piece is taken (needed when the pin may lie on
        several pieces).

    Raises
    ------
    DimensionError
        For bad lengths, crank = pivot distance, or a slot with no usable working piece.
    AssemblyError
        If the pin never lies on the slot.

    Examples
    --------
    >>> from mechlab import CircleSlot, CurvedSlotLink
    >>> m = CurvedSlotLink(1.0, 4.0, CircleSlot((3.5, 0.0), 3.0), start=1.5707963267948966)
    >>> round(float(m.motion(1.0).psi), 4)
    -0.5239
    """

    @classmethod
    def example(cls) -> CurvedSlotLink:
        """Crank 1, pivots 4 apart, a circular slot of radius 3.

        Returns
        -------
        CurvedSlotLink
            A valid instance of the family, the one the services that find the families use.
        """
        return cls(1.0, 4.0, CircleSlot((3.0, 0.0), 3.0), start=1.0)

    crank: Length
    pivot_distance: Length
    slot: Slot
    start: Annotated[float | None, number(optional=True)] = None

    pivots = ("O", "B")
    output = "angle"

    def __post_init__(self):
        super().__post_init__()
        self._check_crank_and_pivot()
        if isinstance(self.slot, CircleSlot):
            self._circle_setup()
        else:
            self._segment  # noqa: B018 - validate now (raises with the numbers)

    # -- basic quantities ---------------------------------------------------------------------
    def base(self) -> SlottedLink:
        """The base mechanism: straight slot through the pivot, same crank and pivot (Zinchenko et al. (2013) Fig. 5).

        Returns
        -------
        SlottedLink
            The base mechanism.

        Examples
        --------
        >>> from mechlab import CircleSlot, CurvedSlotLink
        >>> m = CurvedSlotLink(1.0, 4.0, CircleSlot((3.5, 0.0), 3.0), start=1.5707963267948966)
        >>> m.base()
        SlottedLink(crank=1.0, pivot_distance=4.0)
        """
        return SlottedLink(self.crank, self.pivot_distance)

    @property
    def s_max(self) -> float:
        """The pin's largest distance from B: crank + pivot distance.

        Returns
        -------
        float
            The distance (length).
        """
        return self.crank + self.pivot_distance

    @property
    def s_min(self) -> float:
        """The pin's smallest distance from B: |pivot distance − crank|.

        Returns
        -------
        float
            The distance (length).
        """
        return abs(self.pivot_distance - self.crank)

    def _cos_for_distance(self, s):
        a, d = self.crank, self.pivot_distance
        return (s * s - a * a - d * d) / (2 * a * d)

    # -- circle: closed form ------------------------------------------------------------------
    def _circle_setup(self):
        cx, cy = self.slot.center
        D = float(np.hypot(cx, cy))
        if D == 0.0:
            raise DimensionError("a circular slot centred on the pivot keeps the pin at a constant distance from B: "
                                 "the link cannot be driven (|centre| = 0)")
        side = 1
        if self.start is not None:
            p = self.slot.points(np.array([float(self.start)]))[0]
            side = 1 if cx * p[1] - cy * p[0] >= 0 else -1
        object.__setattr__(self, "_side", side)
        if not self.crank_ranges():
            rho = self.slot.radius
            raise AssemblyError(
                f"the pin never lies on the circular slot: its distance from B ranges over "
                f"[{self.s_min:.4g}, {self.s_max:.4g}], the slot's points over [|D - ρ|, D + ρ] = "
                f"[{abs(D - rho):.4g}, {D + rho:.4g}] (D = |centre| = {D:.4g}, ρ = {rho:.4g})")

    # -- general curve: working segment -------------------------------------------------------
    def _g(self, t):
        c = self.slot.points(t)
        return dot(c, c)

    def _dg(self, t):
        c = self.slot.evaluate(t)
        return 2.0 * dot(c.p, c.d)

    @cached_property
    def _segment(self) -> _Segment:
        curve = self.slot
        target = self.s_max**2
        t = np.linspace(curve.t0, curve.t1, _TABLE)
        g = self._g(t) - target
        roots = [float(t[i]) for i in np.flatnonzero(g == 0)]
        for i in np.flatnonzero(g[:-1] * g[1:] < 0):
            roots.append(brentq(lambda x: self._g(np.array([x]))[0] - target, t[i], t[i + 1], xtol=1e-15, rtol=1e-15))
        roots = _distinct_roots(roots, curve)
        if not roots:
            r = np.sqrt(self._g(t))
            raise DimensionError(
                f"the slot never reaches the pin's position at φ = 0: the pin is crank + pivot_distance = "
                f"{self.s_max:.6g} from B, the slot's points lie {r.min():.6g} … {r.max():.6g} from B")
        if self.start is None:
            if len(roots) > 1:
                raise DimensionError(
                    f"the slot passes {len(roots)} times at distance {self.s_max:.6g} from B (t = "
                    + ", ".join(f"{x:.6g}" for x in roots) + "): give start= to say where the pin is at φ = 0")
            t_s = roots[0]
        else:
            t_s = min(roots, key=lambda x: abs(x - float(self.start)))
        c = self.slot.evaluate(np.array([t_s]))
        gd = float(dot(c.p, c.d)[0])
        if abs(gd) <= _TANGENT_TOL * float(np.hypot(*c.p[0]) * np.hypot(*c.d[0])):
            raise SingularityError(
                f"at φ = 0 the slot (t = {t_s:.6g}) is tangent to the circle of radius {self.s_max:.6g} about B: "
                f"pressure angle 90°, the crank cannot drive the link from there")
        direction = -1 if gd > 0 else 1
        return _walk(curve, self._g, self._dg, t_s, direction, self.s_min**2, "circle about B")

    # -- ranges -------------------------------------------------------------------------------
    def crank_ranges(self):
        if isinstance(self.slot, CircleSlot):
            D = float(np.hypot(*self.slot.center))
            rho = self.slot.radius
            return arc_set(self._cos_for_distance(abs(D - rho)), self._cos_for_distance(D + rho))
        seg = self._segment
        if seg.reason == "covered":
            return FULL_TURN
        c_end = self._cos_for_distance(np.sqrt(seg.g_end))
        phi_e = float(np.arccos(np.clip(c_end, -1.0, 1.0)))
        return ((-phi_e, phi_e),)

    def rotation_failure(self) -> str:
        return f"crank cannot turn fully: {self._range_reason()}; it reaches only φ ∈ {fmt_ranges(self.crank_ranges())}"

    def _range_reason(self) -> str:
        if isinstance(self.slot, CircleSlot):
            D = float(np.hypot(*self.slot.center))
            rho = self.slot.radius
            return (f"the circular slot's points lie [{abs(D - rho):.4g}, {D + rho:.4g}] from B, the pin "
                    f"[{self.s_min:.4g}, {self.s_max:.4g}]; at the ends the slot is tangent to the pin's circle "
                    f"about B (pressure angle 90°)")
        seg = self._segment
        r_end = float(np.sqrt(seg.g_end))
        if seg.reason == "tangent":
            return (f"the slot becomes tangent to the circle of radius {r_end:.6g} about B (pressure angle 90°) "
                    f"before the pin comes within |pivot_distance - crank| = {self.s_min:.6g} of B")
        return (f"the pin would leave the slot: the slot ends {r_end:.6g} from B, but the pin comes within "
                f"|pivot_distance - crank| = {self.s_min:.6g} of B")

    def assembly_failure(self, phi: float) -> str:
        return self._range_reason()

    def check_reachable(self, phi):
        ranges = self.crank_ranges()
        if ranges == FULL_TURN:
            return
        inside = np.zeros(phi.shape, dtype=bool)
        for start, end in ranges:
            t = np.mod(phi - start, 2 * np.pi)
            inside |= (t > 0.0) & (t < end - start)
        if not np.all(inside):
            i = int(np.argmin(inside))
            err = SingularityError if self._ends_tangent() else AssemblyError
            raise err(f"cannot move to φ = {np.degrees(phi[i]):.2f}°: {self._range_reason()}; "
                      f"the crank reaches only φ ∈ {fmt_ranges(ranges)}")

    def _ends_tangent(self) -> bool:
        return isinstance(self.slot, CircleSlot) or self._segment.reason == "tangent"

    # -- kinematics ---------------------------------------------------------------------------
    def _distance(self, A: PointPath):
        """S² = |A - B|² with its φ-analogs."""
        v = A.p - np.array([-self.pivot_distance, 0.0])
        q = dot(v, v)
        dq = 2.0 * dot(v, A.d)
        ddq = 2.0 * (dot(A.d, A.d) + dot(v, A.dd))
        return q, dq, ddq

    @scalar_law
    def beta(self, phi) -> AnglePath:
        """β(φ), β'(φ), β''(φ): the pin's polar angle in the link frame (Zinchenko et al. (2013), formula (12)).

        B + R(ψ)·c(t) = A(φ) gives |c(t)| = S(φ), an equation for t alone, solved on the working segment
        (found once, in ``__post_init__``) by a vectorised bracketed Newton iteration on |c(t)|² - S² = 0
        (derivative 2c·c_t) started from a monotone table; a circle in closed form (triangle B-centre-A).
        Analogs from c·c = S²: t' = (S²)'/(2c·c_t), t'' = ((S²)''/2 - (|c_t|² + c·c_tt)·t'²)/(c·c_t);
        β' = θ_t·t', β'' = θ_tt·t'² + θ_t·t''. A parameter with |c(t)| strictly monotone on the piece (the
        distance from B, as :mod:`mechlab.synthesis.dwell_slot` uses) is always safe; c_t must not vanish there.

        Parameters
        ----------
        phi : float or array_like
            Crank angles φ (radians).

        Returns
        -------
        AnglePath
            β (radians) with β' and β''.

        Raises
        ------
        AssemblyError
            Where the pin is off the slot's working piece.
        SingularityError
            Where the slot is tangent to the circle about B at the pin (the analogs are unbounded).

        Examples
        --------
        >>> from mechlab import CircleSlot, CurvedSlotLink
        >>> m = CurvedSlotLink(1.0, 4.0, CircleSlot((3.5, 0.0), 3.0), start=1.5707963267948966)
        >>> round(float(m.beta(1.0).theta), 4)
        0.7072
        """
        phi = as_angles(phi)
        self.check_reachable(phi)
        A = crank_point(self.crank, phi)
        q, dq, ddq = self._distance(A)
        if isinstance(self.slot, CircleSlot):
            return self._beta_circle(q, dq, ddq)
        return self._beta_curve(q, dq, ddq)

    def _beta_circle(self, q, dq, ddq) -> AnglePath:
        cx, cy = self.slot.center
        D = float(np.hypot(cx, cy))
        K = D * D - self.slot.radius ** 2
        S = np.sqrt(q)
        dS = dq / (2 * S)
        ddS = (ddq / 2 - dS**2) / S
        # cos γ = (S² + D² - ρ²)/(2DS), γ = angle between B→centre and B→pin (triangle B-centre-A)
        w = S / (2 * D) + K / (2 * D * S)
        dw = dS / (2 * D) - K * dS / (2 * D * S**2)
        ddw = ddS / (2 * D) - K * ddS / (2 * D * S**2) + K * dS**2 / (D * S**3)
        sin_g = np.sqrt(np.clip(1.0 - w * w, 0.0, None))
        if np.any(sin_g <= 1e-12):
            i = int(np.argmin(sin_g))
            raise SingularityError(
                f"the circular slot is tangent to the pin's circle about B (pin {S[i]:.6g} from B): "
                f"pressure angle 90°, the analogs are unbounded")
        g = np.arccos(np.clip(w, -1.0, 1.0))
        dg = -dw / sin_g
        ddg = -(ddw + w * dg**2) / sin_g
        sgn = self._side
        return AnglePath(np.arctan2(cy, cx) + sgn * g, sgn * dg, sgn * ddg)

    def _beta_curve(self, q, dq, ddq) -> AnglePath:
        seg = self._segment
        u = _solve_on_segment(seg, self.slot, self._g, self._dg, q)
        t = seg.t_start + seg.direction * u
        c = self.slot.evaluate(t)
        gd = dot(c.p, c.d)
        tiny = np.abs(gd) <= _TANGENT_TOL * np.hypot(*c.p.T) * np.hypot(*c.d.T)
        # at φ = 0 and π the pin reverses on the slot: q' = 0 and t' = 0 exactly
        at_turn = np.abs(dq) <= 1e-14 * q
        if np.any(tiny & ~at_turn):
            i = int(np.argmax(tiny & ~at_turn))
            raise SingularityError(f"the slot is tangent to the circle about B at the pin (t = {t[i]:.6g}): "
                                   f"pressure angle 90°")
        with np.errstate(divide="ignore", invalid="ignore"):
            dt = np.where(at_turn, 0.0, dq / (2 * gd))
            dt2 = dt * dt
            ddt = (ddq / 2 - (dot(c.d, c.d) + dot(c.p, c.dd)) * dt2) / gd
        r2 = dot(c.p, c.p)
        c1 = cross(c.p, c.d)
        th_t = c1 / r2
        th_tt = cross(c.p, c.dd) / r2 - 2.0 * c1 * gd / r2**2
        theta = np.arctan2(c.p[:, 1], c.p[:, 0])
        theta = lift(theta, self._theta_reference(u))
        return AnglePath(theta, th_t * dt, th_tt * dt2 + th_t * ddt)

    def _theta_reference(self, u):
        seg = self._segment
        tt = seg.t_start + seg.direction * seg.u_table
        p = self.slot.points(tt)
        ref = np.unwrap(np.arctan2(p[:, 1], p[:, 0]))
        return np.interp(u, seg.u_table, ref)

    def motion(self, phi) -> AngularMotion:
        """Paths of O, A, B and ψ, ψ', ψ'' at crank angles φ (Zinchenko et al. (2013) frame).

        Parameters
        ----------
        phi : float or array_like
            Crank angles φ (radians); a scalar gives a motion of scalars.

        Returns
        -------
        AngularMotion
            Joint paths and the output angle ψ with ψ', ψ''.

        Raises
        ------
        DimensionError
            If φ is not a finite real number or array.
        AssemblyError
            Where the loop cannot close (the message names the reachable range).
        SingularityError
            Where the slot is tangent to the circle about B at the pin.

        Examples
        --------
        >>> from mechlab import CircleSlot, CurvedSlotLink
        >>> m = CurvedSlotLink(1.0, 4.0, CircleSlot((3.5, 0.0), 3.0), start=1.5707963267948966)
        >>> m.motion(1.0).output
        Law(ψ = -0.523911 rad = -30.0179°, ψ′ = 0.0124067, ψ″ = -0.190415)
        """
        phi = as_angles(phi)
        b = self.beta(phi)
        base = self.base().motion(phi)
        psi = base.psi - b.theta
        dpsi = base.dpsi - b.d
        ddpsi = base.ddpsi - b.dd
        n = len(phi)
        A = base.points["A"]
        # the transmission angle needs the slot's tangent: computed on first use only
        mu = lambda mo: self._transmission(phi, psi, A)  # noqa: E731
        return AngularMotion(phi, {"O": fixed_point((0.0, 0.0), n), "A": A,
                                   "B": fixed_point((-self.pivot_distance, 0.0), n)}, mu, psi, dpsi, ddpsi)

    def _transmission(self, phi, psi, A: PointPath):
        """μ = angle between the slot's tangent at the pin and the radius B→A, in [0, π/2].

        The pin pushes along the slot's normal; the link point under it moves
        perpendicular to B→A; the pressure angle between the two is π/2 - μ.
        """
        rel = A.p - np.array([-self.pivot_distance, 0.0])
        tangent = self._slot_tangent_world(phi, psi)
        cosang = np.abs(dot(tangent, rel)) / (np.hypot(*tangent.T) * np.hypot(*rel.T))
        return np.arcsin(np.clip(cosang, 0.0, 1.0))

    def _slot_tangent_world(self, phi, psi):
        A = crank_point(self.crank, phi)
        q, _, _ = self._distance(A)
        if isinstance(self.slot, CircleSlot):
            b = self._beta_circle(q, np.zeros_like(q), np.zeros_like(q))
            pin = np.sqrt(q)[:, None] * np.stack([np.cos(b.theta), np.sin(b.theta)], axis=-1)
            radial = pin - np.asarray(self.slot.center)
            tan_link = np.stack([-radial[:, 1], radial[:, 0]], axis=-1)
        else:
            u = _solve_on_segment(self._segment, self.slot, self._g, self._dg, q)
            tan_link = self.slot.evaluate(self._segment.t_start + self._segment.direction * u).d
        c, s = np.cos(psi), np.sin(psi)
        return np.stack([c * tan_link[:, 0] - s * tan_link[:, 1], s * tan_link[:, 0] + c * tan_link[:, 1]], axis=-1)

    def structure(self) -> Structure:
        """Crank O→A; the pin A in the link's curved slot, a higher pair whose normal is the slot's at the pin.

        The link turns about B (axis at ψ); one group, the link (Zinchenko et al. (2013) §2).

        Returns
        -------
        Structure
            Links, pairs and structural groups, from which the drawing, centres, force model and counts derive.

        Examples
        --------
        >>> from mechlab import CircleSlot, CurvedSlotLink
        >>> m = CurvedSlotLink(1.0, 4.0, CircleSlot((3.5, 0.0), 3.0), start=1.5707963267948966)
        >>> m.structure().numbers()["frame"]
        3
        """
        def normal(mo):
            return _unit_normal(self._slot_tangent_world(mo.phi, mo.psi))

        return Structure(
            (Link("crank", "O", ("O", "A"), self.crank, joints=("O", "A")),
             Link("link", "B", output_axis, label="slotted link")),
            (Pair("revolute", "O", FRAME, "crank", "O"), Pair("higher", "slot", "link", "crank", "A", normal=normal),
             Pair("revolute", "B", FRAME, "link", "B")),
            (("link",),), "link", scale=self.crank + self.pivot_distance)

    def sketch(self, motion) -> Sketch:
        """The crank, the slot turning with the link about B, and the arm holding it.

        Parameters
        ----------
        motion : AngularMotion
            The mechanism's motion.

        Returns
        -------
        Sketch
            The parts to draw and the pivots O and B.
        """
        return slot_sketch(self, motion, "B")

    def slot_samples(self, n: int = 200) -> np.ndarray:
        """(n, 2) points of the slot's working part in the link frame (for drawings).

        Parameters
        ----------
        n : int, optional
            Number of points.

        Returns
        -------
        numpy.ndarray
            Points of the slot's centre line, shape (n, 2) (length).

        Examples
        --------
        >>> from mechlab import CircleSlot, CurvedSlotLink
        >>> m = CurvedSlotLink(1.0, 4.0, CircleSlot((3.5, 0.0), 3.0), start=1.5707963267948966)
        >>> m.slot_samples(3).round(4)
        array([[4.0357, 2.9518],
               [2.8929, 2.9379],
               [1.75  , 2.4367]])
        """
        if isinstance(self.slot, CircleSlot):
            phi = np.linspace(*self._sample_range(), n)
            return self._pin_in_link(phi)
        seg = self._segment
        u = np.linspace(0.0, seg.u_end, n)
        return self.slot.points(seg.t_start + seg.direction * u)

    def _sample_range(self):
        ranges = self.crank_ranges()
        if ranges == FULL_TURN:
            return 0.0, np.pi
        start, end = ranges[0]
        return start + 1e-6 * (end - start), end - 1e-6 * (end - start)

    def _pin_in_link(self, phi):
        A = crank_point(self.crank, as_angles(phi))
        q, dq, ddq = self._distance(A)
        b = self._beta_circle(q, dq, ddq)
        return np.sqrt(q)[:, None] * np.stack([np.cos(b.theta), np.sin(b.theta)], axis=-1)


# ---------------------------------------------------------------------------------------------
# the translating curved slotted link
# ---------------------------------------------------------------------------------------------
@dataclass(frozen=True, eq=False)
class TranslatingCurvedSlot(Mechanism):
    """Crank O-A driving a slotted link that translates along the x axis (Zinchenko et al. (2013) Fig. 4, 7).

    The slot is a curve in the link frame whose origin C = (s, 0) slides on the x axis; the pin satisfies
    A = (s + x_α, y_α), so s = x_K - x_α with x_K = crank·cos φ the sine mechanism's law (formulas (1), (2)).

    Parameters
    ----------
    crank : float
        Crank radius (positive length).
    slot : SlotCurve
        The slot, a curve in the link frame.
    start : float, optional
        The slot parameter t near which the working piece is taken.

    Raises
    ------
    DimensionError
        For a bad crank or a slot with no usable working piece.
    AssemblyError
        If the pin never lies on the slot.

    Examples
    --------
    >>> from mechlab import CircleSlot, TranslatingCurvedSlot
    >>> m = TranslatingCurvedSlot(1.0, CircleSlot((0.0, 0.0), 3.0), start=3.141592653589793)
    >>> round(float(m.motion(1.0).s), 4)
    3.4199
    """

    @classmethod
    def example(cls) -> TranslatingCurvedSlot:
        """Crank 1, a circular slot of radius 3.

        Returns
        -------
        TranslatingCurvedSlot
            A valid instance of the family, the one the services that find the families use.
        """
        return cls(1.0, CircleSlot((0.0, 0.2), 3.0))

    crank: Length
    slot: Slot
    start: Annotated[float | None, number(optional=True)] = None

    pivots = ("O",)
    output = "position"

    def __post_init__(self):
        super().__post_init__()
        if isinstance(self.slot, CircleSlot):
            x0 = self.slot.center[0]
            side = 1
            if self.start is not None:
                side = 1 if self.slot.points(np.array([float(self.start)]))[0, 0] >= x0 else -1
            object.__setattr__(self, "_side", side)
            if not self.crank_ranges():
                y0, rho = self.slot.center[1], self.slot.radius
                raise AssemblyError(
                    f"the pin never lies on the circular slot: its height a·sin φ ranges over "
                    f"[{-self.crank:.4g}, {self.crank:.4g}], the slot's over [{y0 - rho:.4g}, {y0 + rho:.4g}]")
        else:
            self._segments  # noqa: B018

    def base(self) -> SineMechanism:
        """The base mechanism: the sine mechanism with the same crank (Zinchenko et al. (2013) Fig. 6).

        Returns
        -------
        SineMechanism
            The base mechanism.
        """
        return SineMechanism(self.crank)

    # -- working segment: y decreasing from 0 one way, increasing the other -------------------
    def _y(self, t):
        return self.slot.points(t)[:, 1]

    def _dy(self, t):
        return self.slot.evaluate(t).d[:, 1]

    @cached_property
    def _segments(self):
        curve = self.slot
        t = np.linspace(curve.t0, curve.t1, _TABLE)
        y = self._y(t)
        roots = [float(t[i]) for i in np.flatnonzero(y == 0)]
        for i in np.flatnonzero(y[:-1] * y[1:] < 0):
            roots.append(brentq(lambda x: self._y(np.array([x]))[0], t[i], t[i + 1], xtol=1e-15, rtol=1e-15))
        roots = _distinct_roots(roots, curve)
        if not roots:
            raise DimensionError(f"the slot never crosses the x axis (y_α = 0), where the pin is at φ = 0: "
                                 f"its points have y in [{y.min():.6g}, {y.max():.6g}]")
        if self.start is None:
            if len(roots) > 1:
                raise DimensionError(f"the slot crosses the x axis {len(roots)} times (t = "
                                     + ", ".join(f"{x:.6g}" for x in roots) + "): give start= to say where the pin is "
                                                                              "at φ = 0")
            t_s = roots[0]
        else:
            t_s = min(roots, key=lambda x: abs(x - float(self.start)))
        dy = float(self._dy(np.array([t_s]))[0])
        if dy == 0:
            raise SingularityError(f"at φ = 0 the slot (t = {t_s:.6g}) is parallel to the guide: pressure angle 90°")
        up = 1 if dy > 0 else -1
        a = self.crank
        # walking "down" in -y means g = y decreasing; walking "up" means g = -y decreasing
        down = _walk(curve, self._y, self._dy, t_s, -up, -a, "guide")
        neg_y = lambda tt: -self._y(tt)  # noqa: E731
        neg_dy = lambda tt: -self._dy(tt)  # noqa: E731
        upper = _walk(curve, neg_y, neg_dy, t_s, up, -a, "guide")
        return down, upper, neg_y, neg_dy

    def _y_range(self):
        if isinstance(self.slot, CircleSlot):
            y0, rho = self.slot.center[1], self.slot.radius
            return y0 - rho, y0 + rho
        down, upper, _, _ = self._segments
        return down.g_end, -upper.g_end

    def crank_ranges(self):
        a = self.crank
        if not isinstance(self.slot, CircleSlot) and all(sg.reason == "covered" for sg in self._segments[:2]):
            return FULL_TURN
        lo, hi = self._y_range()
        arcs = arc_set(lo / a, hi / a, phase=np.pi / 2)   # a·sin φ ∈ (lo, hi)
        if isinstance(self.slot, CircleSlot) or arcs in ((), FULL_TURN):
            return arcs
        # the pin starts at φ = 0: keep the arc containing it
        for s, e in arcs:
            if np.mod(0.0 - s, 2 * np.pi) < e - s:
                return ((s, e),)
        return ()

    def _range_reason(self) -> str:
        lo, hi = self._y_range()
        if isinstance(self.slot, CircleSlot):
            return (f"the circular slot spans heights [{lo:.4g}, {hi:.4g}], the pin [{-self.crank:.4g}, "
                    f"{self.crank:.4g}]; "
                    f"at its top and bottom the slot is parallel to the guide (pressure angle 90°)")
        return (f"the pin would leave the slot or jam: the usable slot spans heights [{lo:.6g}, {hi:.6g}], "
                f"the pin needs [{-self.crank:.6g}, {self.crank:.6g}]")

    def rotation_failure(self) -> str:
        return f"crank cannot turn fully: {self._range_reason()}; it reaches only φ ∈ {fmt_ranges(self.crank_ranges())}"

    def assembly_failure(self, phi: float) -> str:
        return self._range_reason()

    # -- kinematics ---------------------------------------------------------------------------
    @scalar_law
    def x_alpha(self, phi) -> AnglePath:
        """x_α(φ) with its analogs: the slot point's abscissa in the link frame (formula (1)).

        Parameters
        ----------
        phi : float or array_like
            Crank angles φ (radians).

        Returns
        -------
        AnglePath
            x_α (length) with its first and second analogs (an AnglePath holds the three arrays).

        Raises
        ------
        AssemblyError
            Where the pin is off the slot's working piece.

        Examples
        --------
        >>> from mechlab import CircleSlot, TranslatingCurvedSlot
        >>> m = TranslatingCurvedSlot(1.0, CircleSlot((0.0, 0.0), 3.0), start=3.141592653589793)
        >>> round(float(m.x_alpha(1.0).theta), 4)
        -2.8796
        """
        phi = as_angles(phi)
        self.check_reachable(phi)
        a = self.crank
        y, dy, ddy = a * np.sin(phi), a * np.cos(phi), -a * np.sin(phi)
        if isinstance(self.slot, CircleSlot):
            x0, y0 = self.slot.center
            rho = self.slot.radius
            h2 = rho**2 - (y - y0) ** 2
            if np.any(h2 <= 1e-12 * rho**2):
                raise SingularityError("the circular slot is parallel to the guide at the pin: pressure angle 90°")
            h = np.sqrt(h2)
            dh = -(y - y0) * dy / h
            ddh = (-(dy**2) - (y - y0) * ddy - dh**2) / h
            sg = self._side
            return AnglePath(x0 + sg * h, sg * dh, sg * ddh)
        down, upper, neg_y, neg_dy = self._segments
        t = np.empty_like(phi)
        lower = y < 0
        if np.any(lower):
            u = _solve_on_segment(down, self.slot, self._y, self._dy, y[lower])
            t[lower] = down.t_start + down.direction * u
        if np.any(~lower):
            u = _solve_on_segment(upper, self.slot, neg_y, neg_dy, -y[~lower])
            t[~lower] = upper.t_start + upper.direction * u
        c = self.slot.evaluate(t)
        yt = c.d[:, 1]
        if np.any(np.abs(yt) <= _TANGENT_TOL * np.hypot(*c.d.T)):
            i = int(np.argmin(np.abs(yt)))
            raise SingularityError(f"the slot is parallel to the guide at the pin (t = {t[i]:.6g}): pressure angle 90°")
        dt = dy / yt
        ddt = (ddy - c.dd[:, 1] * dt**2) / yt
        return AnglePath(c.p[:, 0], c.d[:, 0] * dt, c.dd[:, 0] * dt**2 + c.d[:, 0] * ddt)

    def motion(self, phi) -> LinearMotion:
        """Paths of O, A, C and s, s', s'' at crank angles φ.

        Parameters
        ----------
        phi : float or array_like
            Crank angles φ (radians); a scalar gives a motion of scalars.

        Returns
        -------
        LinearMotion
            Joint paths and the output displacement s with s', s''.

        Raises
        ------
        DimensionError
            If φ is not a finite real number or array.
        AssemblyError
            Where the loop cannot close (the message names the reachable range).

        Examples
        --------
        >>> from mechlab import CircleSlot, TranslatingCurvedSlot
        >>> m = TranslatingCurvedSlot(1.0, CircleSlot((0.0, 0.0), 3.0), start=3.141592653589793)
        >>> m.motion(1.0).output
        Law(s = 3.41987, s′ = -0.999359, s″ = -0.404442)
        """
        phi = as_angles(phi)
        xa = self.x_alpha(phi)
        A = crank_point(self.crank, phi)
        s = A.p[:, 0] - xa.theta
        ds = A.d[:, 0] - xa.d
        dds = A.dd[:, 0] - xa.dd
        n = len(phi)
        z = np.zeros(n)
        C = PointPath(np.stack([s, z], -1), np.stack([ds, z], -1), np.stack([dds, z], -1))
        mu = lambda mo: self._transmission(phi)  # noqa: E731 - on first use
        return LinearMotion(phi, {"O": fixed_point((0.0, 0.0), n), "A": A, "C": C}, mu, s, ds, dds)

    def _transmission(self, phi):
        """μ = angle between the slot's tangent at the pin and the guide's normal direction."""
        tan = self._tangent(phi)
        return np.arcsin(np.clip(np.abs(tan[:, 1]) / np.hypot(*tan.T), 0.0, 1.0))

    def _tangent(self, phi):
        a = self.crank
        y = a * np.sin(phi)
        if isinstance(self.slot, CircleSlot):
            x0, y0 = self.slot.center
            x = x0 + self._side * np.sqrt(np.clip(self.slot.radius**2 - (y - y0) ** 2, 0.0, None))
            return np.stack([-(y - y0), x - x0], axis=-1)
        down, upper, neg_y, neg_dy = self._segments
        t = np.empty_like(phi)
        lower = y < 0
        if np.any(lower):
            t[lower] = down.t_start + down.direction * _solve_on_segment(down, self.slot, self._y, self._dy, y[lower])
        if np.any(~lower):
            t[~lower] = upper.t_start + upper.direction * _solve_on_segment(upper, self.slot, neg_y, neg_dy, -y[~lower])
        return self.slot.evaluate(t).d

    def structure(self) -> Structure:
        """Crank O→A; the pin A in the yoke's curved slot (a higher pair, the slot's normal at the pin).

        The yoke at C slides on the frame along x; one group, the yoke.

        Returns
        -------
        Structure
            Links, pairs and structural groups, from which the drawing, centres, force model and counts derive.

        Examples
        --------
        >>> from mechlab import CircleSlot, TranslatingCurvedSlot
        >>> m = TranslatingCurvedSlot(1.0, CircleSlot((0.0, 0.0), 3.0), start=3.141592653589793)
        >>> m.structure().numbers()
        {'crank': 1, 'yoke': 2, 'frame': 3}
        """
        def normal(mo):
            return _unit_normal(self._tangent(mo.phi))

        return Structure(
            (Link("crank", "O", ("O", "A"), self.crank, joints=("O", "A")), Link("yoke", "C", 0.0)),
            (Pair("revolute", "O", FRAME, "crank", "O"), Pair("higher", "slot", "yoke", "crank", "A", normal=normal),
             Pair("prismatic", "guide", FRAME, "yoke", "C", 0.0)),
            (("yoke",),), "yoke", scale=self.crank)

    def sketch(self, motion) -> Sketch:
        """The crank, the slot moving with the yoke, its rod and the guide.

        Parameters
        ----------
        motion : LinearMotion
            The mechanism's motion over an array of crank angles.

        Returns
        -------
        Sketch
            The parts to draw and the pivot O.
        """
        return slot_sketch(self, motion)

    def slot_samples(self, n: int = 200) -> np.ndarray:
        """(n, 2) points of the slot's working part in the link frame (for drawings).

        Parameters
        ----------
        n : int, optional
            Number of points.

        Returns
        -------
        numpy.ndarray
            Points of the slot's centre line, shape (n, 2) (length).
        """
        lo, hi = self._y_range()
        a = self.crank
        ys = np.linspace(max(lo, -a), min(hi, a), n)
        if isinstance(self.slot, CircleSlot):
            x0, y0 = self.slot.center
            return np.stack([x0 + self._side * np.sqrt(np.clip(self.slot.radius**2 - (ys - y0) ** 2, 0, None)), ys], -1)
        down, upper, _neg_y, _neg_dy = self._segments
        ud = np.linspace(down.u_end, 0.0, n // 2)
        uu = np.linspace(0.0, upper.u_end, n - n // 2)
        t = np.concatenate([down.t_start + down.direction * ud, upper.t_start + upper.direction * uu])
        return self.slot.points(t)


# ---------------------------------------------------------------------------------------------
# the twin of any mechanism, from its structure
# ---------------------------------------------------------------------------------------------
def _turned(angle, v):
    """The vectors v (n, 2) turned by ``angle`` (n,)."""
    c, s = np.cos(angle), np.sin(angle)
    return np.stack([c * v[:, 0] - s * v[:, 1], s * v[:, 0] + c * v[:, 1]], axis=-1)


def _slot_in_parameter(path, p, inverse, lo: float, hi: float) -> ParametricSlot:
    """The relative path as a slot over its own parameter p ∈ [lo, hi] (the pin's distance from the pivot, or its
    height above the guide), whose value p(φ) reaches lo and hi where the pin reverses on the slot.

    ``path(φ)`` → PointPath (w, w', w'') in φ; ``p(φ)`` → (p, p', p''), ``inverse(p)`` → φ on that half turn.
    Chain rule: w_p = w'/p', w_pp = (w'' - w_p·p'')/p'²; at a reversal (p' = 0) w_p = w''/p'' (l'Hôpital), and
    w_pp, which needs the third analog, is set to 0: there the pin's own rate p'(φ) is zero, so it multiplies zero. Past
    the ends the slot runs on along its end tangent (the pin never goes there; the walk along the slot
    needs a crossing of the end circle, not a touch).
    """
    span = hi - lo

    def evaluate(t):
        t = np.asarray(t, dtype=float)
        tc = np.clip(t, lo, hi)
        phi = inverse(tc)
        w = path(phi)
        _, dp, ddp = p(phi)
        turn = np.abs(dp) <= 1e-7 * span
        safe = np.where(turn, 1.0, dp)[:, None]
        at_turn = np.where(turn, ddp, 1.0)[:, None]   # p'' ≠ 0 where the pin reverses
        wp = np.where(turn[:, None], w.dd / at_turn, w.d / safe)
        wpp = np.where(turn[:, None], 0.0, (w.dd - wp * ddp[:, None]) / safe**2)
        out = (t - tc)[:, None]
        past = out[:, 0] != 0
        return w.p + out * wp, wp, np.where(past[:, None], 0.0, wpp)

    # ParametricSlot asks for c, c_t and c_tt one after another at the same t: the path is solved once for the three
    last: list = [None]

    def part(k):
        def at(t):
            t = np.asarray(t, dtype=float)
            key = (t.shape, t.tobytes())
            done = last[0]
            if done is None or done[0] != key:
                done = last[0] = (key, evaluate(t))
            return done[1][k].copy()   # a copy: a caller may change what it gets
        return at

    margin = 0.05 * span
    return ParametricSlot(part(0), part(1), part(2), lo - margin, hi + margin)


def crank_pin(mech: Mechanism) -> tuple[Structure, Pair, Pair]:
    """The structure of ``mech``, its crank's revolute pair with the frame and its pin, read from ``structure()``.

    The crank is the input link, turning about a frame pivot at the crank angle's rate; its pin is the pair
    joining it to a moving link at a joint fixed on it (the end of its axis: a linkage's pin joint, or a pin in
    a slot). DimensionError naming the family where there is none (a cam's contact point moves on the cam).
    """
    name = type(mech).__name__
    st = mech.structure().planar("it has no planar curved-slot twin")
    crank = st.input
    base_pair = next((p for p in st.pairs if FRAME in (p.a, p.b) and crank in (p.a, p.b)), None)
    if base_pair is None or base_pair.kind != "revolute" or st.input_rate != 1.0:
        how = ("is not joined to the frame" if base_pair is None
               else f"is joined to the frame by a {base_pair.kind} pair")
        raise DimensionError(f"{name} has no crank turning about a frame pivot (its input, the {crank}, {how}, "
                             f"dθ/dφ = {st.input_rate:g}): no crank pin to follow")
    if st.output == crank:
        raise DimensionError(f"the output of {name} is its crank: there is no output link to carry a slot")
    link = st.link(crank)
    fixed = {link.origin, *(link.axis if isinstance(link.axis, tuple) else ())}
    pin = next((p for p in st.pairs if crank in (p.a, p.b) and FRAME not in (p.a, p.b) and p.point in fixed), None)
    if pin is None:
        raise DimensionError(f"the crank of {name} carries no pin: none of its joints fixed on it "
                             f"({', '.join(sorted(fixed))}) is paired with a moving link")
    return st, base_pair, pin


def pin_relative_path(mech: Mechanism, phi: np.ndarray) -> PointPath:
    """The crank pin (:func:`crank_pin`) seen from the output link at crank angles φ, with its φ-analogs.

    Output turning about its frame pivot E: w = Rot(-ψ)(A - E), w' = Rot(-ψ)(A' - ψ'·(A - E)⊥),
    w'' = Rot(-ψ)(A'' - 2ψ'·A'⊥ - ψ''·(A - E)⊥ - ψ'²·(A - E)). Output sliding on a guide at γ from the crank
    pivot O: w = Rot(-γ)(A - O) - (s, 0), the analogs likewise (Zinchenko et al. (2013) §1).
    """
    st, base_pair, pin = crank_pin(mech)
    out = st.link(st.output)
    guide = st.frame_pair(out.name)
    mo = mech.motion(phi)
    A = mo.points[pin.point]
    if out.translates:
        if guide.kind != "prismatic":
            raise DimensionError(f"the output {out.name} of {type(mech).__name__} translates but is not guided by "
                                 f"the frame")
        O, z = mo.points[base_pair.point], np.zeros(len(mo.phi))
        turn = np.full(len(mo.phi), -float(guide.angle))
        return PointPath(*(_turned(turn, a - o) - np.stack([x, z], -1)
                           for a, o, x in zip(A, O, (mo.s, mo.ds, mo.dds), strict=False)))
    if guide.kind != "revolute":
        raise DimensionError(f"the output {out.name} of {type(mech).__name__} neither turns about a frame pivot nor "
                             f"slides on a guide")
    E = mo.points[guide.point]
    v, dv, ddv = A.p - E.p, A.d - E.d, A.dd - E.dd
    w1, w2 = mo.dpsi[:, None], mo.ddpsi[:, None]
    return PointPath(_turned(-mo.psi, v), _turned(-mo.psi, dv - w1 * perp(v)),
                     _turned(-mo.psi, ddv - 2 * w1 * perp(dv) - w2 * perp(v) - w1**2 * v))


def structural_twin(mech: Mechanism) -> tuple[Mechanism, float]:
    """The curved-slot twin of any mechanism from its ``structure()`` (Zinchenko et al. (2013) §1).

    The crank (input, revolute to the frame) carries the pin (:func:`crank_pin`), a revolute pair with the next
    link; the output turns about its frame pivot E or slides on a guide at angle γ. The pin fixed in the
    output's frame traces the relative path (:func:`pin_relative_path`). The group leaves one freedom relative
    to the output, so w depends on the pin's distance S = |A - E| (its height Rot(-γ)(A - O)_y) alone, and one
    half turn of the crank covers the slot. The twin is a :class:`CurvedSlotLink` (a
    :class:`TranslatingCurvedSlot`) with that slot in Zinchenko et al.'s frame; returned with the crank-angle
    shift to it.
    """
    name = type(mech).__name__
    st, base_pair, pin = crank_pin(mech)
    if not mech.can_turn:
        raise DimensionError(f"the default curved-slot twin needs a crank that turns fully; {name}: "
                             f"{mech.rotation_failure()}")
    if pin.kind != "revolute":
        raise DimensionError(f"the crank of {name} carries no pin jointed to a moving link: its {pin.point} runs "
                             f"in a {pin.kind} pair already")
    out = st.link(st.output)
    guide = st.frame_pair(out.name)
    probe = mech.motion(np.array([0.3]))
    O = probe.points[base_pair.point].p[0]
    a = float(np.hypot(*(probe.points[pin.point].p[0] - O)))

    rel = probe.points[pin.point].p[0] - O
    if abs(np.angle(np.exp(1j * (np.arctan2(rel[1], rel[0]) - 0.3)))) > 1e-9:
        raise DimensionError(f"the crank angle φ of {name} is not the angle of its pin {pin.point} about "
                             f"{base_pair.point}: the twin's crank could not be matched to it")

    def one_slot(path, mirror, what):
        """The second half turn must retrace the first (one slot for the pin): w(mirror(φ)) = w(φ)."""
        f = np.linspace(0.1, np.pi - 0.1, 17)
        gap = np.max(np.hypot(*(path(f).p - path(mirror(f)).p).T))
        if gap > 1e-9 * st.scale:
            raise DimensionError(f"the pin's path relative to the output of {name} is not a function of {what} "
                                 f"alone (the two half turns differ by {gap:.3g}): no one-slot twin")

    if out.translates:
        gamma = float(guide.angle)

        def path(phi):
            return pin_relative_path(mech, phi + gamma)

        def height(f):
            return a * np.sin(f), a * np.cos(f), -a * np.sin(f)

        one_slot(path, lambda f: np.pi - f, "the pin's height above the guide")
        slot = _slot_in_parameter(path, height, lambda y: np.arcsin(np.clip(y / a, -1.0, 1.0)), -a, a)
        return TranslatingCurvedSlot(a, slot, start=0.0), gamma
    E = probe.points[guide.point].p[0]
    d = float(np.hypot(*(E - O)))
    phase = float(np.mod(np.arctan2(*(E - O)[::-1]) - np.pi, 2 * np.pi))

    def path(phi):
        return pin_relative_path(mech, phi + phase)

    def distance(f):
        S = np.sqrt(a * a + d * d + 2 * a * d * np.cos(f))
        dS = -a * d * np.sin(f) / S
        return S, dS, -(a * d * np.cos(f) + dS**2) / S

    one_slot(path, lambda f: -f, "the pin's distance from the pivot")
    slot = _slot_in_parameter(path, distance, lambda S: np.arccos(np.clip((S * S - a * a - d * d) / (2 * a * d),
                                                                          -1.0, 1.0)), abs(a - d), a + d)
    return CurvedSlotLink(a, d, slot, start=a + d), phase
