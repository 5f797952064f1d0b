"""Planar Geneva drives, external and internal (Vainer & Shatokhina, their refs. [2], [3]; the
spherical offset Geneva is :mod:`mechlab.mechanisms.spherical_geneva`).

Crank pivot O = (0, 0), wheel centre W = (C, 0), crank radius a, z radial slots, roller radius r.
Radial entry (OA ⟂ WA as the pin enters) gives a = C·sin(π/z) and |WA| = C·cos(π/z); with
λ = sin(π/z) and σ the crank angle from the middle of the motion, the wheel's angle follows in
closed form (:meth:`PlanarGeneva.closed_form`) while |σ| ≤ σ0 = π/2 + κπ/z, κ = -1 external (the
wheel turns against the crank), +1 internal; the wheel is locked otherwise. The library's crank
angle is φ = σ + π (φ = 0 mid-dwell). The book's Geneva chapter derives it.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Annotated

import numpy as np
from scipy.optimize import brentq

from ..errors import DimensionError, OffsetError, SlotCountError  # noqa: F401  OffsetError: re-exported from here
from ..geometry import AnglePath, PointPath, as_angles, crank_point, fixed_point, lift, relative, vector_angle
from ..motion import AngularMotion, Quantity, Table, scalar_law
from ..validate import MAX_SLOTS, Length, check_value, choice, count, length, number
from .base import FRAME, Link, Mechanism, Pair, Part, Sketch, Structure, output_axis

LENGTH_UNITS = ("mm", "cm", "m", "in")   # the units a design table may name


TWO_PI = 2.0 * np.pi


# z: a whole number of slots
Slots = Annotated[int, count(3, MAX_SLOTS, error=SlotCountError,
                             why="a Geneva wheel needs z ≥ 3: with z = 2 the crank radius C·sin(π/z) equals C")]


def check_slots(z) -> int:
    """z as an int, raising SlotCountError unless it is a whole number ≥ 3."""
    return check_value("z", z, Slots.__metadata__[0])


def mid_motion_angle(phi) -> np.ndarray:
    """σ = φ - π reduced to [-π, π) turn by turn (0 in the middle of the motion)."""
    phi = np.asarray(phi, dtype=float)
    return phi - TWO_PI * np.floor(phi / TWO_PI) - np.pi


def impact_kind(velocity_jump: float, acceleration_jump: float, tol: float = 1e-9) -> str:
    """'hard' for a jump in velocity (theoretically unbounded acceleration), 'soft'
    for a finite jump in acceleration only, 'none' for continuous analogs."""
    if abs(velocity_jump) > tol:
        return "hard"
    if abs(acceleration_jump) > tol:
        return "soft"
    return "none"


@dataclass(frozen=True)
class Impact:
    """Jumps of ψ' and ψ'' (output analogs) where the pin enters and leaves a slot."""

    entry_velocity_jump: float
    entry_acceleration_jump: float
    exit_velocity_jump: float
    exit_acceleration_jump: float

    @property
    def kind(self) -> str:
        return max((impact_kind(self.entry_velocity_jump, self.entry_acceleration_jump),
                    impact_kind(self.exit_velocity_jump, self.exit_acceleration_jump)),
                   key=("none", "soft", "hard").index)


# ----------------------------------------------------------------------------------
# planar Geneva
# ----------------------------------------------------------------------------------
@dataclass(frozen=True)
class PlanarGeneva(Mechanism):
    """Common part of :class:`ExternalGeneva` and :class:`InternalGeneva` (κ = ∓1).

    ``z`` slots, centre distance ``centre_distance`` = C (O to W), roller radius
    ``roller_radius`` (default 0.15·a). Raises SlotCountError for z < 3 and
    DimensionError for negative sizes or a roller that does not fit (see
    :meth:`_check_roller`).
    """

    locks = 1   # the crank's locking disc on the wheel's arcs

    z: Slots
    centre_distance: Length
    roller_radius: Annotated[float | None, length(optional=True)] = None

    kappa = 0  # -1 external, +1 internal
    pivots = ("O", "W")
    output = "angle"

    def __post_init__(self):
        if self.kappa not in (-1, 1):
            raise TypeError("PlanarGeneva is the common base: use ExternalGeneva or InternalGeneva")
        super().__post_init__()
        if self.roller_radius is None:
            object.__setattr__(self, "roller_radius", 0.15 * self.crank_radius)
        self._check_roller()

    # -- dimensions -----------------------------------------------------------------
    @property
    def lam(self) -> float:
        """λ = a / C = sin(π/z) (radial entry)."""
        return float(np.sin(np.pi / self.z))

    @property
    def crank_radius(self) -> float:
        """a = C·sin(π/z): OA ⟂ WA at entry, angle π/z at W."""
        return self.centre_distance * self.lam

    @property
    def entry_radius(self) -> float:
        """|WA| at entry and exit = C·cos(π/z) (the wheel radius to the pin centre)."""
        return self.centre_distance * float(np.cos(np.pi / self.z))

    @property
    def index_angle(self) -> float:
        """Wheel turn per crank turn, 2π/z, signed: negative for the external drive."""
        return self.kappa * TWO_PI / self.z

    @property
    def engagement_half_angle(self) -> float:
        """σ0 = π/2 + κπ/z: the pin is in a slot for |σ| ≤ σ0."""
        return np.pi / 2 + self.kappa * np.pi / self.z

    @property
    def dwell_fraction(self) -> float:
        """Fraction of the crank turn with the wheel locked, exactly still (ψ' = 0): 1/2 - κ/z.
        :meth:`standstill_fraction` is the longer share within a tolerance of standing still."""
        return 1.0 - self.engagement_half_angle / np.pi

    def standstill_fraction(self, precision: float = 0.001) -> float:
        """The near-standstill fraction: the longest share of the turn over which the wheel's angle stays
        within a band of ``precision`` × the index angle 2π/z (the design layer's dwell, :mod:`mechlab.design`,
        with its ``dwell_precision``), longer than the exact :attr:`dwell_fraction`.

        The band takes in the end of one motion and the start of the next: crank angles t before the
        motion ends and after the next begins, moving the wheel by a and b with a + b = the band. The wheel
        leaves rest with zero velocity, so the crank angle per wheel angle falls as the wheel speeds up and
        the split a = b is the longest; t is the root of |β(σ0) − β(σ0 − t)| = band/2 (closed form β,
        bracketed on (0, σ0), Brent's method).

        Parameters
        ----------
        precision : the band as a fraction of the index angle, in (0, 1).

        Returns
        -------
        float
            dwell_fraction + t/π.

        Raises
        ------
        DimensionError
            ``precision`` outside (0, 1).

        Examples
        --------
        >>> g = ExternalGeneva(6, 100.0)
        >>> round(g.dwell_fraction, 4), round(g.standstill_fraction(0.001), 4)
        (0.6667, 0.6801)
        """
        precision = check_value("precision", precision, number(0.0, 1.0, open=True))
        s0 = self.engagement_half_angle
        end = self.closed_form(s0).theta
        half = precision * abs(self.index_angle) / 2
        t = brentq(lambda t: abs(end - self.closed_form(s0 - t).theta) - half, 0.0, s0, xtol=1e-15)
        return self.dwell_fraction + t / np.pi

    @property
    def motion_fraction(self) -> float:
        return 1.0 - self.dwell_fraction

    # -- closed forms -----------------------------------------------------------------
    def closed_form(self, sigma) -> AnglePath:
        """β, β', β'' (wheel angle from the line W→O) at crank angles σ from the middle
        of the motion, from the vector loop A - W: β = κ·atan(λ sin σ/(1 + κλ cos σ)),
        β' = κλ(cos σ + κλ)/D, β'' = -κλ(1 - λ²) sin σ/D², D = 1 + 2κλ cos σ + λ².
        Valid while engaged, |σ| ≤ σ0."""
        s = np.asarray(sigma, dtype=float)
        k, lam = self.kappa, self.lam
        D = 1.0 + 2.0 * k * lam * np.cos(s) + lam**2
        beta = k * np.arctan2(lam * np.sin(s), 1.0 + k * lam * np.cos(s))
        return AnglePath(beta, k * lam * (np.cos(s) + k * lam) / D, -k * lam * (1.0 - lam**2) * np.sin(s) / D**2)

    def max_velocity(self) -> float:
        """max |ψ'| = λ/(1 + κλ), at σ = 0 (the pin on the line of centres)."""
        return self.lam / (1.0 + self.kappa * self.lam)

    def acceleration_peak_sigma(self) -> float:
        """σ ≥ 0 of the largest |ψ''| while engaged.

        External: d/dσ (sin σ / D²) = 0 gives 2λ cos²σ + (1 + λ²) cos σ - 4λ = 0 (inside the
        engagement for every z ≥ 3). Internal: |ψ''| grows up to the entry, so σ0.
        """
        lam = self.lam
        if self.kappa < 0:
            b = 1.0 + lam**2
            c = (-b + np.sqrt(b * b + 32.0 * lam**2)) / (4.0 * lam)
            return float(min(np.arccos(c), self.engagement_half_angle))
        return self.engagement_half_angle

    def max_acceleration(self) -> float:
        """max |ψ''| while engaged (closed form at :meth:`acceleration_peak_sigma`)."""
        return float(abs(self.closed_form(self.acceleration_peak_sigma()).dd))

    def entry_acceleration(self) -> float:
        """|ψ''| just after entry = tan(π/z) (both drives): the jump from the locked 0."""
        return float(np.tan(np.pi / self.z))

    def impacts(self) -> Impact:
        """Exact jumps at entry (σ = -σ0) and exit (σ = +σ0): ψ' = 0 there (radial
        entry), ψ'' jumps by ±tan(π/z) — a soft impact."""
        s0 = self.engagement_half_angle
        a, b = self.closed_form(-s0), self.closed_form(s0)
        return Impact(float(a.d), float(a.dd), float(-b.d), float(-b.dd))

    # -- sizes for drawing and design ---------------------------------------------------
    @property
    def slot_bottom(self) -> float:
        """Distance from W of the slot bottom's centre: the pin centre's extreme C ∓ a."""
        return self.centre_distance + self.kappa * self.crank_radius

    @property
    def slot_centre_length(self) -> float:
        """The pin centre's travel along a slot, entry to deepest point: |C·cos(π/z) − (C ∓ a)| =
        C(sin(π/z) + cos(π/z) − 1) external, C(1 + sin(π/z) − cos(π/z)) internal — the length between the
        centres of the slot's end arcs on a drawing (the slot is this plus the roller's diameter long)."""
        return abs(self.entry_radius - self.slot_bottom)

    @property
    def slot_width(self) -> float:
        """The slot's width, the roller's diameter 2r (add the running clearance on a drawing)."""
        return 2.0 * self.roller_radius

    def _check_roller(self):
        a, r, b = self.crank_radius, self.roller_radius, self.entry_radius
        gap = b * np.sin(np.pi / self.z)  # half the chord between neighbouring slot mouths
        if r >= min(0.5 * a, gap):
            raise DimensionError(
                f"roller_radius = {r:g} is too large: it must be < min(a/2, C·cos(π/z)·sin(π/z)) = "
                f"min({0.5 * a:.6g}, {gap:.6g}) so that the slots fit between each other and the crank hub")

    # -- motion -------------------------------------------------------------------------
    def _pin(self, phi) -> PointPath:
        # φ = 0 mid-dwell: the external pin then points away from W (A = -a u(φ)),
        # the internal pin towards it (A = a u(φ)); σ = φ - π in both.
        return crank_point(self.crank_radius, phi if self.kappa > 0 else phi + np.pi)

    def motion(self, phi) -> AngularMotion:
        """Wheel angle ψ (0 at φ = 0, κ·2π/z more after each turn) and its analogs.

        Positions and analogs from the vector A - W (geometry.vector_angle) while the
        pin is in a slot, exact zeros while locked; ψ accumulates over several turns.
        """
        phi = as_angles(phi)
        n = len(phi)
        turns = np.floor(phi / TWO_PI)
        sigma = mid_motion_angle(phi)
        s0 = self.engagement_half_angle
        A = self._pin(phi)
        W = fixed_point((self.centre_distance, 0.0), n)
        ang = vector_angle(relative(A, W))
        beta = lift(ang.theta, np.pi) - np.pi
        on = np.abs(sigma) <= s0
        local = np.where(on, beta + self.kappa * np.pi / self.z, np.where(sigma > 0, self.index_angle, 0.0))
        psi = turns * self.index_angle + local
        dpsi = np.where(on, ang.d, 0.0)
        ddpsi = np.where(on, ang.dd, 0.0)
        # the pin pushes along the slot's normal, which is the wheel point's direction of motion
        mu = np.full(n, np.pi / 2)
        return AngularMotion(phi, {"O": fixed_point((0.0, 0.0), n), "A": A, "W": W}, mu, psi, dpsi, ddpsi)

    @scalar_law
    def engaged(self, phi) -> np.ndarray:
        """True where the pin is in a slot."""
        return np.abs(mid_motion_angle(as_angles(phi))) <= self.engagement_half_angle

    def design(self, unit: str = "mm") -> Table:
        """The main sizes, a :class:`Table` of :class:`Quantity` rows whose names carry their unit.

        Parameters
        ----------
        unit : the unit of C, which every length shares: "mm" (the default), "cm", "m" or "in".
            Angles are in degrees; ψ' and ψ'' (derivatives in the crank angle φ) have no unit.
        """
        unit = check_value("unit", unit, choice(*LENGTH_UNITS))
        lengths = (("C", self.centre_distance), ("crank radius a", self.crank_radius),
                   ("pin radius at entry |WA|", self.entry_radius), ("roller radius", self.roller_radius),
                   ("slot bottom from W", self.slot_bottom), ("slot centre length", self.slot_centre_length),
                   ("slot width", self.slot_width), ("slot length", self.slot_length),
                   *self._drawing_radii())
        return Table(Quantity(k, v) for k, v in (
            ("z", self.z), *((f"{k} ({unit})", v) for k, v in lengths),
            ("dwell fraction", self.dwell_fraction), ("index angle (deg)", np.degrees(abs(self.index_angle))),
            ("max |ψ'| = |dψ/dφ|", self.max_velocity()), ("max |ψ''| = |d²ψ/dφ²|", self.max_acceleration())))

    def _drawing_radii(self) -> tuple:  # pragma: no cover - each drive names its rims
        raise NotImplementedError

    def structure(self) -> Structure:
        """Crank O→A and the wheel turning about W (axis at ψ), joined by one higher pair at the pin A: while
        the pin is in a slot its normal is the slot's (across the radius W→A); during the dwell the locking
        arcs, concentric with O, hold the wheel, and their reaction passes through O (taken on the line
        O→A), so the crank drives nothing. One group, the wheel."""
        def normal(mo):
            A, W = mo.points["A"].p, mo.points["W"].p
            radial = (A - W) / np.hypot(*(A - W).T)[:, None]
            across = np.stack([-radial[:, 1], radial[:, 0]], axis=-1)
            lock = A / np.hypot(*A.T)[:, None]
            return np.where(self.engaged(mo.phi)[:, None], across, lock)

        return Structure(
            (Link("crank", "O", ("O", "A"), self.crank_radius, joints=("O", "A")), Link("wheel", "W", output_axis)),
            (Pair("revolute", "O", FRAME, "crank", "O"), Pair("higher", "pin", "wheel", "crank", "A", normal=normal),
             Pair("revolute", "W", FRAME, "wheel", "W")),
            (("wheel",),), "wheel", scale=self.centre_distance)

    def sketch(self, motion) -> Sketch:
        """The crank, the slotted wheel (its outlines, :func:`wheel_outline`, turned by ψ about W; a radius
        of it carries its number)."""
        sk = super().sketch(motion)
        W, psi = motion.points["W"].p, motion.psi
        outlines = wheel_outline(self)

        def turned(k):
            def at(i):
                xy = outlines[k]
                c, s = np.cos(psi[i]), np.sin(psi[i])
                return W[i] + xy @ np.array([[c, s], [-s, c]]) if len(xy) else xy
            return at

        radius = 0.7 * self.outer_radius
        return replace(sk, parts=sk.parts + (Part("wheel", turned(0)), Part("wheel", turned(1)), Part(
            "anchor", lambda i: np.array([W[i], W[i] + radius * np.array([np.cos(psi[i]), np.sin(psi[i])])]), "wheel")))


@dataclass(frozen=True)
class ExternalGeneva(PlanarGeneva):
    """External Geneva: the pin on the near side of O, the wheel turns against the crank.

    a = C sin(π/z), wheel (entry) radius C cos(π/z), outer radius sqrt(C²cos²(π/z) + r²) (the slot corners
    touch the roller at entry), locking disc radius a - 1.5·r. Dwell fraction 1/2 + 1/z;
    max |ψ'| = λ/(1 - λ); |ψ''| jumps by tan(π/z) at entry.

    Parameters
    ----------
    z : int
        Number of slots (≥ 3).
    centre_distance : float
        C, from the crank pivot O to the wheel's centre W (positive length).
    roller_radius : float, optional
        Roller radius r (length); 0.15·a if None.

    Raises
    ------
    SlotCountError
        For z that is not a whole number ≥ 3.
    DimensionError
        For negative sizes or a roller that does not fit.

    Examples
    --------
    >>> import numpy as np
    >>> from mechlab import ExternalGeneva
    >>> g = ExternalGeneva(4, 100)
    >>> round(g.crank_radius, 4), round(g.outer_radius, 4)
    (70.7107, 71.5017)
    >>> round(float(np.degrees(g.motion(np.pi).psi)), 4)  # the wheel half-way through its index
    -45.0
    """

    title = "external Geneva"

    @classmethod
    def example(cls) -> ExternalGeneva:
        """Four slots, centres 1 apart.

        Returns
        -------
        ExternalGeneva
            A valid instance of the family, the one the services that find the families use.
        """
        return cls(4, 1.0, roller_radius=0.1)

    kappa = -1

    @property
    def outer_radius(self) -> float:
        """sqrt(C² cos²(π/z) + r²): the slot corners touch the roller at entry.

        Returns
        -------
        float
            The wheel's outer radius (length).
        """
        return float(np.hypot(self.entry_radius, self.roller_radius))

    @property
    def slot_length(self) -> float:
        """From the rim to the slot's bottom: outer radius - (C - a - r).

        Returns
        -------
        float
            The slot's length (length).
        """
        return self.outer_radius - (self.slot_bottom - self.roller_radius)

    @property
    def locking_radius(self) -> float:
        """Radius of the crank's locking disc, a - 1.5 r (the usual design rule).

        The wheel's concave locking arcs have the same radius, centred at distance C from W on the bisectors
        between slots.

        Returns
        -------
        float
            The radius (length).
        """
        return self.crank_radius - 1.5 * self.roller_radius

    def _drawing_radii(self) -> tuple:
        return ("wheel outer radius", self.outer_radius), ("locking disc radius", self.locking_radius)

    def sketch(self, motion) -> Sketch:
        """The wheel, and the crank's locking disc whose relief lets the wheel turn.

        Parameters
        ----------
        motion : AngularMotion
            The mechanism's motion.

        Returns
        -------
        Sketch
            The parts to draw and the pivots O and W.

        Examples
        --------
        >>> from mechlab import ExternalGeneva
        >>> g = ExternalGeneva(4, 100)
        >>> len(g.sketch(g.motion(0.3)).parts)
        5
        """
        sk = super().sketch(motion)
        A, s0 = motion.points["A"].p, self.engagement_half_angle

        def lock(i):
            pin = np.arctan2(A[i, 1], A[i, 0])
            return _arc((0.0, 0.0), self.locking_radius, pin + s0, pin + 2 * np.pi - s0, 60)

        return replace(sk, parts=sk.parts[:-1] + (Part("lock", lock),) + sk.parts[-1:])


@dataclass(frozen=True)
class InternalGeneva(PlanarGeneva):
    """Internal Geneva: the pin on the far side of O, wheel and crank turn the same way.

    a = C sin(π/z), slot mouths at C cos(π/z) from W, slot bottoms at C + a. Dwell fraction 1/2 - 1/z;
    max |ψ'| = λ/(1 + λ) at mid-motion; |ψ''| is largest at entry and exit, tan(π/z).

    Parameters
    ----------
    z : int
        Number of slots (≥ 3).
    centre_distance : float
        C, from the crank pivot O to the wheel's centre W (positive length).
    roller_radius : float, optional
        Roller radius r (length); 0.15·a if None.

    Raises
    ------
    SlotCountError
        For z that is not a whole number ≥ 3.
    DimensionError
        For negative sizes or a roller that does not fit.

    Examples
    --------
    >>> from mechlab import InternalGeneva
    >>> g = InternalGeneva(4, 100)
    >>> round(g.inner_radius, 4), round(g.slot_length, 4)
    (69.9107, 111.4066)
    """

    title = "internal Geneva"

    @classmethod
    def example(cls) -> InternalGeneva:
        """Six slots, centres 1 apart.

        Returns
        -------
        InternalGeneva
            A valid instance of the family, the one the services that find the families use.
        """
        return cls(6, 1.0)

    kappa = +1

    @property
    def inner_radius(self) -> float:
        """The ring's inner rim, where the slot walls end: sqrt(C²cos²(π/z) - r²).

        Returns
        -------
        float
            The radius (length).
        """
        return float(np.sqrt(self.entry_radius**2 - self.roller_radius**2))

    @property
    def outer_radius(self) -> float:
        """The ring's outer rim, drawn 1.5 r beyond the slot bottoms (a drawing choice, not a design rule).

        Returns
        -------
        float
            The radius (length).
        """
        return self.slot_bottom + 2.5 * self.roller_radius

    @property
    def slot_length(self) -> float:
        """From the inner rim to the slot's bottom: C + a + r - inner radius.

        Returns
        -------
        float
            The slot's length (length).
        """
        return self.slot_bottom + self.roller_radius - self.inner_radius

    def _drawing_radii(self) -> tuple:
        return ("ring inner radius", self.inner_radius), ("ring outer radius", self.outer_radius)


def _arc(centre, radius, a0, a1, n=40):
    t = np.linspace(a0, a1, n)
    return np.asarray(centre) + radius * np.stack([np.cos(t), np.sin(t)], axis=-1)


def wheel_outline(g: PlanarGeneva, n_arc: int = 24) -> tuple[np.ndarray, np.ndarray]:
    """The wheel's outlines in its own frame (W at the origin, ψ = 0), as two polylines.

    External: the slotted rim with the concave locking arcs (radius a - 1.5 r, centred
    at distance C on the bisectors between slots), and nothing else. Internal: the inner
    rim with the slots running outwards, and the outer rim.
    """
    z, C, r = g.z, g.centre_distance, g.roller_radius
    w = 1.08 * r  # the slot's half-width, with a little clearance
    pts = []
    rim = g.outer_radius if g.kappa < 0 else g.inner_radius
    top = np.sqrt(max(rim**2 - w**2, 0.0))
    gap = np.arcsin(w / rim)
    for k in range(z):
        th = np.pi - g.kappa * np.pi / z + 2 * np.pi * k / z  # slot k's direction at ψ = 0
        u = np.array([np.cos(th), np.sin(th)])
        v = np.array([-u[1], u[0]])
        # the slot from its -v wall round the bottom (towards W outside, away from W inside)
        end = th - 1.5 * np.pi if g.kappa < 0 else th + 0.5 * np.pi
        pts += [top * u - w * v, *_arc(g.slot_bottom * u, w, th - 0.5 * np.pi, end, n_arc), top * u + w * v]
        t = np.linspace(th + gap, th + 2 * np.pi / z - gap, 3 * n_arc)
        radius = np.full_like(t, rim)
        if g.kappa < 0:  # the concave locking arc in the gap after this slot
            dlt = t - (th + np.pi / z)
            disc = g.locking_radius**2 - (C * np.sin(dlt)) ** 2
            near = np.where(disc >= 0, C * np.cos(dlt) - np.sqrt(np.maximum(disc, 0.0)), np.inf)
            radius = np.minimum(radius, near)
        pts += list(radius[:, None] * np.stack([np.cos(t), np.sin(t)], axis=-1))
    outline = np.array(pts + [pts[0]])
    if g.kappa < 0:
        return outline, np.empty((0, 2))
    return outline, _arc((0.0, 0.0), g.outer_radius, 0.0, 2 * np.pi, 120)
