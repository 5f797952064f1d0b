"""The comparison criteria of a dwell design, computed from its simulated motion.

Every figure is read off ``mechanism.motion(phi)`` on a fine grid of the crank turn, never
from a family's own formulas, so that all families are judged alike. The kinematic figures are
those by which Kinitsky (1994) compares six-bars with cam laws, measured over the **rise**
(from the end of the dwell to the output's farthest position, or to the next dwell of an
index) with :func:`~mechlab.analysis.motion_laws.rise_invariants`: B (velocity), C
(acceleration), D (kinetic power, velocity × acceleration); and the jerk J = max|x‴|·Φ³/h.

One definition of dwell, the mechanisms' own: the **dwell fraction** is the share of the turn over
which the output stands exactly still (x′ = 0 up to rounding), as ``ExternalGeneva.dwell_fraction``;
the **near-standstill fraction** is the longer share over which it stays within a band of
``dwell_precision``·h, as ``ExternalGeneva.standstill_fraction(precision)``. A linkage that only
approximates a dwell (Chebyshev's six-bars) has a dwell fraction of 0 and a near-standstill one.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Annotated, Protocol, runtime_checkable

import numpy as np
from scipy.ndimage import maximum_filter1d, minimum_filter1d

from ..analysis.motion_laws import rise_invariants
from ..errors import DimensionError
from ..kinetostatics.drive import drive
from ..mechanisms.base import TWO_PI
from ..motion import STILL
from ..validate import Checked, Length, Spec, angle, check_value, count, length, validated
from ..validate import mechanism as instance_of
from .spec import AnySpecification

Circles = Annotated[tuple, Spec("items", expected=tuple)]  # ((x, y), r) pairs


@runtime_checkable
class Movable(Protocol):
    """What a design is judged by: its motion at crank angles (a mechlab mechanism, or one of the student's)."""

    def motion(self, phi): ...


AnyMovable = Annotated[Movable, instance_of(Movable, why="an object with motion(phi), e.g. a mechlab mechanism")]

SAMPLES = 2880  # crank angles per turn (1/8°): the near-standstill is found to this resolution
REFINE = 513  # crank angles per refinement of a dwell's end (two refinements: ends to ~1e-8 rad)


Parts = Annotated[int, count(0, 1000)]
Phase = Annotated[float, angle(-TWO_PI, TWO_PI)]  # a shift of the sampled crank angles (rad)


@dataclass(frozen=True)
class Counts(Checked):
    """What a design is built of: moving parts, lower pairs and higher pairs (cam, pin in slot).

    :func:`counted` reads them from the mechanism's :class:`~mechlab.mechanisms.base.Structure`.

    Parameters
    ----------
    parts : int
        Moving parts (the frame not counted), 0 to 1000.
    lower_pairs : int
        Revolute and prismatic pairs.
    higher_pairs : int
        Higher pairs (cam and follower, pin in slot, locking arcs).

    Raises
    ------
    DimensionError
        A count that is not an integer in [0, 1000].

    Examples
    --------
    >>> from mechlab.design import Counts
    >>> str(Counts(2, 2, 2))
    '2 parts, 2 lower + 2 higher pairs'
    """

    parts: Parts
    lower_pairs: Parts
    higher_pairs: Parts

    def __str__(self) -> str:
        higher = f" + {self.higher_pairs} higher" if self.higher_pairs else ""
        return f"{self.parts} parts, {self.lower_pairs} lower{higher} pairs"


def counted(mechanism, *, rollers: int | None = None, locks: int | None = None) -> Counts:
    """The parts and pairs of a design, counted from ``mechanism.structure()``.

    The kinematic structure leaves out what does not change the motion: a roller (a part on its own
    pin, replaced by a higher pair at its centre) and a Geneva drive's locking arcs (a second, passive
    higher pair). Each of ``rollers`` adds a part and a lower pair; each of ``locks`` a higher pair; by
    default the family's own (its class's ``rollers`` and ``locks``).

    Parameters
    ----------
    mechanism : Mechanism
        A mechanism with a ``structure()`` (a spatial one's links and pairs count alike).
    rollers, locks : int, optional
        Rollers and locking pairs the structure leaves out (default: the mechanism's class's).

    Returns
    -------
    Counts
        Moving parts, lower pairs (revolute, prismatic) and higher pairs.

    Examples
    --------
    >>> import mechlab as ml
    >>> str(counted(ml.FourBar(1, 3, 3, 4)))
    '3 parts, 4 lower pairs'
    """
    st = mechanism.structure()
    rollers = getattr(mechanism, "rollers", 0) if rollers is None else rollers
    locks = getattr(mechanism, "locks", 0) if locks is None else locks
    higher = sum(p.kind == "higher" for p in st.pairs)
    return Counts(len(st.links) + rollers, len(st.pairs) - higher + rollers, higher + locks)


@dataclass(frozen=True)
class Criteria:
    """One design judged on the criteria every family shares (see the module's docstring).

    Parameters
    ----------
    dwell_fraction : float
        Longest share of the turn over which the output stands exactly still (x′ = 0 up to
        rounding, its ends refined to ~1e-8 rad); 0 for an approximate dwell.
    standstill_fraction : float
        Longest share of the turn over which the output stays within ``dwell_precision``·h (the
        near-standstill, to 1/SAMPLES of the turn): what the specification's dwell asks.
    dwell_residual : float
        Output motion (max − min) over the asked dwell, centred on the achieved one, as a
        fraction of h: the dwell's accuracy (0 for an exact dwell).
    B, C, D : float
        The rise's invariants of velocity, acceleration and kinetic power (Kinitsky, 1994). The rise
        starts where the exact dwell ends, or where the near-standstill ends if there is no exact dwell.
    J : float or None
        The rise's peak jerk, max|x‴|·Φ³/h: from the motion's closed-form ``jerk`` where it has one (a
        cam), else a central difference of x″; None where the acceleration jumps (the jerk is unbounded).
    velocity_jump, acceleration_jump : float
        Jumps of x′ and x″ (as fractions of their peaks); non-zero means a hard or soft impact.
    impact : str
        "none", "soft" or "hard".
    pressure_angle : float
        Worst pressure angle over the turn (rad): 90° − the least transmission angle of a linkage.
    size : float
        Largest side of the footprint's bounding box (mm).
    peak_torque, rms_torque, motor_power : float
        Crank torque (N·m) and the motor's nominal power (W) by the course's motor rule.
    structure : Counts
        The parts and pairs of the design (:func:`counted`).

    Examples
    --------
    >>> import mechlab as ml
    >>> from mechlab.design import Counts, Specification, evaluate
    >>> c = evaluate(ml.ExternalGeneva(4, 1.0), Specification("index", 0.75, stations=4),
    ...              scale=50.0, structure=Counts(2, 2, 2))
    >>> round(c.dwell_fraction, 4), c.impact
    (0.75, 'soft')
    """

    dwell_fraction: float
    standstill_fraction: float
    dwell_residual: float
    B: float
    C: float
    D: float
    J: float | None
    velocity_jump: float
    acceleration_jump: float
    impact: str
    pressure_angle: float
    size: float
    peak_torque: float
    rms_torque: float
    motor_power: float
    structure: Counts


def longest_still(x: np.ndarray, shift: float, band: float) -> tuple[int, int]:
    """Longest run (start, length in samples) of the periodic samples ``x`` whose range stays ≤ band.

    ``x`` holds one turn without its end point; the next turn is ``x + shift`` (the index
    angle of a unidirectional output, 0 for a rocking one). A window that fits the band has every
    shorter window inside it fit too, so the longest length is bisected, each trial one vectorised
    sliding maximum and minimum (scipy.ndimage): O(n log n). Of the longest runs, the first.
    """
    n = len(x)
    ext = np.concatenate([x, x + shift])

    def starts(length: int) -> np.ndarray:
        # window k covers ext[k : k + length] with this origin
        hi = maximum_filter1d(ext, length, origin=-(length // 2))[: 2 * n - length + 1]
        lo = minimum_filter1d(ext, length, origin=-(length // 2))[: 2 * n - length + 1]
        return np.flatnonzero(hi - lo <= band)

    fits, too_long = 1, n + 1
    while too_long - fits > 1:
        mid = (fits + too_long) // 2
        fits, too_long = (mid, too_long) if starts(mid).size else (fits, mid)
    return int(starts(fits)[0]) % n, fits


def longest_true(still: np.ndarray) -> tuple[int, int]:
    """Longest run (start, length) of True in the periodic boolean samples ``still`` (one turn)."""
    n = len(still)
    if still.all():
        return 0, n
    if not still.any():
        return 0, 0
    first = int(np.argmin(still))  # a False: no run wraps past it
    edges = np.diff(np.concatenate([[0], np.roll(still, -first).astype(np.int8), [0]]))
    starts, ends = np.flatnonzero(edges == 1), np.flatnonzero(edges == -1)
    k = int(np.argmax(ends - starts))
    return int((starts[k] + first) % n), int(ends[k] - starts[k])


def _still_end(mechanism, still_at: float, moving_at: float, vmax: float, scale: float) -> float:
    """The crank angle between ``still_at`` (output still) and ``moving_at`` (moving) where the exact
    dwell ends, to ~1e-8 rad: two refinements on grids of REFINE angles."""
    for _ in range(2):
        grid = np.linspace(still_at, moving_at, REFINE)
        d = np.abs(np.asarray(mechanism.motion(grid).output.d, float)) * scale
        k = max(int(np.argmax(d > STILL * vmax)), 1)  # the first moving angle (the last one is)
        still_at, moving_at = grid[k - 1], grid[k]
    return 0.5 * (still_at + moving_at)


def exact_dwell(mechanism, phi: np.ndarray, d1: np.ndarray, scale: float = 1.0) -> tuple[int, int, float, float]:
    """The exact dwell of a motion sampled at ``phi`` (one turn and its end point) with output
    velocity ``d1``: (first still sample, still samples, crank angles where it begins and ends).

    The output stands still where |x′| ≤ STILL·max|x′|; a run of fewer than two samples (a velocity
    crossing zero) is no dwell: (start, 0, nan, nan). The ends are refined between the samples.
    ``scale`` converts the motion's units to those of ``d1``.
    """
    n = len(phi) - 1
    v = np.abs(d1[:-1])
    vmax = float(np.max(v))
    start, run = longest_true(v <= STILL * vmax)
    if run < 2:
        return start, 0, np.nan, np.nan
    step = phi[1] - phi[0]
    lo = phi[0] + start * step
    if run == n:
        return 0, n, lo, lo + 2 * np.pi
    hi = lo + (run - 1) * step
    return (start, run, _still_end(mechanism, lo, lo - step, vmax, scale),
            _still_end(mechanism, hi, hi + step, vmax, scale))


def _jumps(mechanism, phase: float, d1: np.ndarray, d2: np.ndarray) -> tuple[float, float]:
    """Largest neighbour-to-neighbour change of x′ and x″ that does not shrink when the grid is halved.

    ``d1``, ``d2``: x′ and x″ on the judge's grid (SAMPLES steps from ``phase``); the motion is
    evaluated again only on the halved grid.
    """
    law = mechanism.motion(phase + np.linspace(0.0, 2 * np.pi, 2 * SAMPLES + 1)).output
    v1, a1 = np.max(np.abs(np.diff(d1))), np.max(np.abs(np.diff(d2)))
    v2, a2 = np.max(np.abs(np.diff(law.d))), np.max(np.abs(np.diff(law.dd)))
    vmax, amax = np.max(np.abs(law.d)), np.max(np.abs(law.dd))
    # a continuous derivative's largest step halves with the step; a jump stays
    v = v2 / vmax if v2 > 0.75 * v1 and vmax > 0 else 0.0
    a = a2 / amax if a2 > 0.75 * a1 and amax > 0 else 0.0
    return float(v), float(a)


def _circle(i: int, circle: tuple) -> tuple[tuple, float]:
    if len(circle) != 2:
        raise DimensionError(f"circles[{i}] must be a (centre, radius) pair, got {circle!r:.60}")
    return (check_value(f"circles[{i}] centre", circle[0], Spec("point")),
            check_value(f"circles[{i}] radius", circle[1], length()))


@validated
def evaluate(mechanism: AnyMovable, spec: AnySpecification, *, scale: Length,
             structure: Annotated[Counts, instance_of(Counts)], circles: Circles = (),
             pressure_angle: Annotated[float | None, angle(0.0, np.pi / 2, optional=True)] = None,
             phase: Phase = 0.0) -> Criteria:
    """Judge ``mechanism`` (lengths × ``scale`` = mm) against ``spec`` from its simulated motion.

    Parameters
    ----------
    mechanism : Mechanism
        Any object with ``motion(phi)`` whose output carries ``value``, ``d`` and ``dd``.
    spec : Specification
        The machine's requirement (amplitude, dwell precision, load, speed).
    scale : float
        The mechanism's lengths × ``scale`` are mm.
    structure : Counts
        Its parts and pairs, reported as they are (see :func:`counted`).
    circles : tuple of ((x, y), r), optional
        Parts the joints do not trace (a Geneva wheel, a cam disc), in the mechanism's units,
        added to the footprint.
    pressure_angle : float, optional
        Worst pressure angle (rad) in [0, π/2] replacing the motion's own (a family whose
        motion does not carry one).
    phase : float
        Shift of the sampled crank angles (rad), in [−2π, 2π].

    Returns
    -------
    Criteria
        The design's dwell, rise invariants, jerk, impacts, pressure angle, size, torque and
        motor power.

    Raises
    ------
    TypeError
        ``mechanism`` has no ``motion``, ``spec`` is not a Specification or ``structure`` not Counts.
    DimensionError
        ``scale``, ``circles``, ``pressure_angle`` or ``phase`` out of range.
    MechanismError
        The mechanism's own motion refuses a crank angle of the turn.

    Examples
    --------
    >>> import mechlab as ml
    >>> from mechlab.design import Counts, Specification, evaluate
    >>> g = ml.ExternalGeneva(4, 1.0)
    >>> c = evaluate(g, Specification("index", 0.75, stations=4), scale=50.0, structure=Counts(2, 2, 2),
    ...              circles=(((g.centre_distance, 0.0), g.outer_radius),))
    >>> round(c.dwell_fraction, 4), round(c.size, 1)
    (0.75, 121.1)
    """
    circles = tuple(_circle(i, c) for i, c in enumerate(circles))
    phi = phase + np.linspace(0.0, 2 * np.pi, SAMPLES + 1)
    mo = mechanism.motion(phi)
    x, d1, d2 = (np.asarray(a, float) for a in (mo.output.value, mo.output.d, mo.output.dd))
    length = 1.0 if spec.rotary else scale  # a translating output's analogs in mm
    x, d1, d2 = x * length, d1 * length, d2 * length
    h = spec.amplitude
    shift = x[-1] - x[0] if spec.motion == "index" else 0.0
    near, near_run = longest_still(x[:-1], shift, spec.dwell_precision * h)
    start, run, begin, finish = exact_dwell(mechanism, phi, d1, length)
    exact = 0 < run < SAMPLES  # a dwell with ends to refine
    dwell = (finish - begin) / (2 * np.pi) if run else 0.0
    if not run:  # an approximate dwell: the near-standstill is the dwell the rise starts from
        start, run = near, near_run
    # residual over the asked dwell, centred on the achieved one
    want = round(float(spec.dwell_fraction * SAMPLES))
    centre = start + run // 2
    idx = np.arange(centre - want // 2, centre - want // 2 + want)
    # the unwrapped output at any sample k: x[k mod n] + shift·⌊k/n⌋
    window = x[:-1][idx % SAMPLES] + shift * np.floor_divide(idx, SAMPLES)
    residual = float(np.ptp(window)) / h if want else 0.0
    # the rise: from the dwell's end to the farthest position (a swing or stroke) or to the next dwell (an index)
    end = start + run
    k = np.arange(end, start + SAMPLES + 1)
    xs = x[:-1][k % SAMPLES] + shift * np.floor_divide(k, SAMPLES)
    if spec.motion != "index":
        k = k[:int(np.argmax(np.abs(xs - xs[0]))) + 1]
        xs = xs[:len(k)]
    rise_phi = phi[0] + k * (2 * np.pi / SAMPLES)
    v_rise, a_rise = d1[:-1][k % SAMPLES], d2[:-1][k % SAMPLES]
    if exact:  # from the exact dwell's refined end (output still there), not the sample after it
        rise_phi, xs = np.r_[finish, rise_phi], np.r_[x[(end - 1) % SAMPLES] + shift * ((end - 1) // SAMPLES), xs]
        v_rise, a_rise = np.r_[0.0, v_rise], np.r_[0.0, a_rise]
        if spec.motion == "index":  # to the next dwell's refined start
            rise_phi[-1] = begin + 2 * np.pi
    inv = rise_invariants(rise_phi, xs, v_rise, a_rise)
    v_jump, a_jump = _jumps(mechanism, phase, np.asarray(mo.output.d, float), np.asarray(mo.output.dd, float))
    impact = "hard" if v_jump > 1e-6 else "soft" if a_jump > 1e-6 else "none"
    jerk = None
    if impact == "none":
        # the law's closed form where the motion carries one (a cam), else a central difference of x″
        d3 = (np.asarray(mo.jerk, float) * length if hasattr(mo, "jerk") else np.gradient(d2, phi))[:-1][k % SAMPLES]
        jerk = float(np.max(np.abs(d3))) * (rise_phi[-1] - rise_phi[0]) ** 3 / abs(xs[-1] - xs[0])
    if pressure_angle is None:
        pressure_angle = float(np.max(mo.pressure_angle))
    pts = [p.p for p in mo.points.values()] + [np.array([[c[0] - r, c[1] - r], [c[0] + r, c[1] + r]])
                                               for c, r in circles]
    allp = np.concatenate([np.asarray(p, float)[:, :2] for p in pts])
    size = float(np.max(np.ptp(allp, axis=0))) * scale
    # the output's load alone (massless links): M1·ω1 = J x′x″ω1³ + M_r|x′|ω1 (SI: x in m for a stroke)
    si = 1.0 if spec.rotary else 1e-3
    load = spec.inertia if spec.rotary else spec.mass
    w = spec.omega1
    torque = load * (d1 * si) * (d2 * si) * w**2 + spec.resisting * np.abs(d1 * si)
    motor = drive(torque, phi, w, overload=spec.overload)
    return Criteria(dwell_fraction=float(dwell), standstill_fraction=near_run / SAMPLES, dwell_residual=residual,
                    B=inv.B, C=inv.C, D=inv.D,
                    J=jerk, velocity_jump=v_jump, acceleration_jump=a_jump, impact=impact,
                    pressure_angle=float(pressure_angle), size=size, peak_torque=motor.peak_torque,
                    rms_torque=motor.rms_torque, motor_power=motor.nominal_power, structure=structure)
