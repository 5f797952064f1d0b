"""The chapter's machines with loads: a slider-crank press, a four-bar rocker drive and the class-IV six-bar.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Annotated, Any

import numpy as np

from ..mechanisms.base import Mechanism
from ..motion import Motion, scalar_law
from ..validate import Distance, Length, OptionalAngles, Point, Real, Spec, number, validated
from ..validate import mechanism as mechanism_of
from .model import MAX_OMEGA, Eps, Force, ForceModel, G, LoadError, Omega, Torque, _nonneg, model_for, slender_bar
from .solve import ForceResult, solve

__all__ = ["Kinetostatics", "class_iv_drive", "press", "press_load", "rocker_drive", "rpm_to_rad"]

Rpm = Annotated[float, number(0.0, MAX_OMEGA * 60 / (2 * np.pi), why="rev/min")]
Size = Annotated[float, number(0.0)]  # a mass, a load, a friction coefficient: ≥ 0


@dataclass(frozen=True, eq=False)
class Kinetostatics(Mechanism):
    """A mechanism with its force model and loads: moves like the mechanism, ``forces(phi)`` solves.

    Used by :mod:`mechlab.draw.forces` to animate force plans with ``mechlab.draw.animate``; its motion,
    structure, sketch and crank ranges are the mechanism's.

    Parameters
    ----------
    mechanism : Mechanism
        The mechanism that moves.
    model : ForceModel, optional
        Its force model; ``model_for(mechanism)`` (massless, frictionless) if None.
    loads : tuple of Force or Torque, optional
        External loads on the model's bodies.
    omega1 : float, optional
        Crank speed ω1 (rad/s).
    eps1 : float, optional
        Crank acceleration ε1 (rad/s²).
    gravity : tuple of float, optional
        Gravity vector (m/s²).

    Raises
    ------
    TypeError
        If ``mechanism`` is not a Mechanism, or a load is not a Force or Torque.
    DimensionError
        For a crank speed, acceleration or gravity that is not finite.

    Examples
    --------
    >>> from mechlab import FourBar, Kinetostatics, Torque
    >>> k = Kinetostatics(FourBar(0.1, 0.3, 0.3, 0.35), loads=(Torque("rocker", -10.0),), omega1=10.0)
    >>> round(float(k.forces(1.0).torque), 4)
    0.9171
    """

    mechanism: Annotated[Any, mechanism_of(Mechanism)]
    model: ForceModel | None = None
    loads: Annotated[tuple, Spec("items", expected=(Force, Torque))] = ()
    omega1: Omega = 1.0
    eps1: Eps = 0.0
    gravity: Point = (0.0, -G)

    def __post_init__(self):
        super().__post_init__()
        if self.model is None:
            object.__setattr__(self, "model", model_for(self.mechanism))

    def structure(self):
        return self.mechanism.structure()

    def sketch(self, motion):
        return self.mechanism.sketch(motion)

    @property
    def pivots(self):
        """The mechanism's joints fixed to the frame.

        Returns
        -------
        tuple of str
            Joint names, e.g. ``("O", "E")``.
        """
        return self.mechanism.pivots

    @property
    def output(self):
        """The mechanism's output kind.

        Returns
        -------
        str
            ``"angle"`` or ``"position"``.
        """
        return self.mechanism.output

    def crank_ranges(self):
        return self.mechanism.crank_ranges()

    def rotation_failure(self) -> str:
        return self.mechanism.rotation_failure()

    def turn(self, n: int = 361):
        return self.mechanism.turn(n)

    def cycle(self, n: int = 361):
        return self.mechanism.cycle(n)

    def motion(self, phi):
        return self.mechanism.motion(phi)

    @scalar_law
    @validated
    def forces(self, phi: OptionalAngles = None, motion: Motion | None = None, **kw) -> ForceResult:
        """Solve the kinetostatics at crank angles φ (default: the mechanism's cycle) or on a given motion.

        Parameters
        ----------
        phi : float or array_like, optional
            Crank angles (radians); a scalar gives results at that angle as scalars.
        motion : Motion, optional
            A motion of the mechanism to solve on instead of ``phi``.
        **kw
            Passed to :func:`~mechlab.kinetostatics.solve` (``maxiter``, ``tol``).

        Returns
        -------
        ForceResult
            Reactions, balancing torque, losses and checks.

        Raises
        ------
        AssemblyError
            Where the mechanism does not assemble.
        SingularityError
            Where a group cannot carry its loads.
        SelfLockingError
            Where friction locks the mechanism.

        Examples
        --------
        >>> import numpy as np
        >>> from mechlab.kinetostatics import press
        >>> round(float(press().forces(np.pi / 2).torque), 4)
        -2.2425
        """
        if motion is None:
            motion = self.motion(self.cycle() if phi is None else phi)
        return solve(self.model, motion, self.loads, self.omega1, self.eps1, self.gravity, **kw)


# --------------------------------------------------------------------------- the chapter's two examples
@validated
def rpm_to_rad(rpm: Real) -> float:
    """Crank speed in rad/s from revolutions per minute.

    Parameters
    ----------
    rpm : float
        Speed (rev/min).

    Returns
    -------
    float
        Speed (rad/s).

    Raises
    ------
    DimensionError
        If ``rpm`` is not a finite number.

    Examples
    --------
    >>> from mechlab.kinetostatics import rpm_to_rad
    >>> round(rpm_to_rad(120), 4)
    12.5664
    """
    return rpm * 2.0 * np.pi / 60.0


@validated
def press_load(P: Annotated[float, number(0.0, error=LoadError, why="the press force, N")],
               work_fraction: Annotated[float, Spec("number", 0.0, 1.0, open_lo=True, error=LoadError)] = 0.3
               ) -> Callable:
    """Technological resistance of a press: a force P against the slider on its working stroke.

    The force acts while the slider moves towards its outer dead point in the last ``work_fraction`` of its
    stroke. The outer dead point and the stroke come from the dimensions (crank a = |OA|, rod l = |AB|,
    offset e = y of B): the slider is sqrt((l + a)² − e²) from O along the guide there, on the side where B
    is ahead of A, so the load at a crank angle does not depend on which other angles are sampled.

    Parameters
    ----------
    P : float
        The press force (N, ≥ 0).
    work_fraction : float, optional
        The working part of the stroke (0 < fraction ≤ 1).

    Returns
    -------
    callable
        ``load(motion) → (n, 2)`` force vectors (N) for a :class:`Force` on the slider of a slider-crank
        motion (points O, A, B; guide parallel to x).

    Raises
    ------
    LoadError
        For a negative or non-finite P, or a fraction outside (0, 1].

    Examples
    --------
    >>> import numpy as np
    >>> from mechlab.kinetostatics import press, press_load
    >>> press_load(2000.0)(press().motion(np.array([3.0, 5.8])))
    array([[    0.,     0.],
           [-2000.,     0.]])
    """

    def load(motion):
        crank, rod, offset, side = _slider_crank_dimensions(motion)
        outer = float(np.sqrt((rod + crank) ** 2 - offset**2))
        stroke = outer - float(np.sqrt((rod - crank) ** 2 - offset**2))
        working = (motion.ds * side > 0) & (motion.s * side >= outer - work_fraction * stroke)
        return np.stack([np.where(working, -side * P, 0.0), np.zeros(len(motion))], axis=1)
    return load


def _slider_crank_dimensions(motion) -> tuple[float, float, float, float]:
    """Crank, rod, offset and the side (+1: B ahead of A along x) of a slider-crank motion."""
    pts = motion.points
    A, B = pts["A"].p, pts["B"].p
    crank = float(np.hypot(*A[0]))
    rod = float(np.hypot(*(B[0] - A[0])))
    return crank, rod, float(B[0, 1]), float(np.sign(B[0, 0] - A[0, 0]) or 1.0)


@validated
def press(crank: Length = 0.10, rod: Length = 0.40, *, rpm: Rpm = 120.0, P: Size = 2000.0,
          work_fraction: Annotated[float, Spec("number", 0.0, 1.0, open_lo=True)] = 0.3, m_crank: Size = 2.0,
          m_rod: Size = 3.0, m_slider: Size = 4.0, f: Size = 0.0, radius: Distance = 0.01,
          eps1: Real = 0.0) -> Kinetostatics:
    """The chapter's crank press (metres, kilograms, N).

    A centred slider-crank whose slider meets the resistance of :func:`press_load`; the crank is balanced
    (centre of mass at O), the rod is a uniform bar, friction f in every pair (journal radius ``radius``).

    Parameters
    ----------
    crank, rod : float, optional
        Crank radius and rod length (m).
    rpm : float, optional
        Crank speed (rev/min).
    P : float, optional
        Press force (N).
    work_fraction : float, optional
        Working part of the stroke (0 < fraction ≤ 1).
    m_crank, m_rod, m_slider : float, optional
        Masses (kg).
    f : float, optional
        Friction coefficient in every pair.
    radius : float, optional
        Journal radius (m).
    eps1 : float, optional
        Crank acceleration (rad/s²).

    Returns
    -------
    Kinetostatics
        The press with its model and load.

    Raises
    ------
    RotationError
        If the crank cannot turn fully.
    DimensionError
        For a dimension, mass or speed out of range.

    Examples
    --------
    >>> import numpy as np
    >>> from mechlab.kinetostatics import press
    >>> k = press()
    >>> round(k.omega1, 4), round(float(k.forces(np.pi / 2).power), 4)
    (12.5664, -28.1804)
    """
    sc = _slider_crank(crank, rod)
    sc.turn(2)  # a press's crank turns fully: RotationError (with the numbers) otherwise
    model = (model_for(sc).with_body("crank", mass=m_crank, inertia=slender_bar(m_crank, crank), com=(0.0, 0.0))
             .with_body("rod", mass=m_rod).with_body("slider", mass=m_slider).with_friction(f, radius))
    return Kinetostatics(sc, model, (Force("slider", "B", press_load(P, work_fraction)),), rpm_to_rad(rpm), eps1)


@validated
def rocker_drive(crank: Length = 0.10, coupler: Length = 0.30, rocker: Length = 0.30, ground: Length = 0.35, *,
                 rpm: Rpm = 120.0, T: Size = 40.0, m_coupler: Size = 2.0, m_rocker: Size = 2.0,
                 f: Size = 0.0, radius: Distance = 0.01) -> Kinetostatics:
    """The chapter's four-bar: a crank-rocker whose rocker meets a resisting torque of size T against its motion.

    Coupler and rocker are uniform bars, friction f in every pair.

    Parameters
    ----------
    crank, coupler, rocker, ground : float, optional
        Link lengths (m).
    rpm : float, optional
        Crank speed (rev/min).
    T : float, optional
        Resisting torque on the rocker (N·m, ≥ 0).
    m_coupler, m_rocker : float, optional
        Masses (kg).
    f : float, optional
        Friction coefficient in every pair.
    radius : float, optional
        Journal radius (m).

    Returns
    -------
    Kinetostatics
        The four-bar with its model and load.

    Raises
    ------
    RotationError
        Unless the crank turns fully (Grashof, with the numbers).
    LoadError
        For a negative T.

    Examples
    --------
    >>> from mechlab.kinetostatics import rocker_drive
    >>> round(float(rocker_drive().forces(1.0).torque), 4)
    5.4214
    """
    fb = _four_bar(crank, coupler, rocker, ground)
    fb.turn(2)  # RotationError (Grashof, with the numbers) unless the crank turns fully
    model = (model_for(fb).with_body("coupler", mass=m_coupler).with_body("rocker", mass=m_rocker)
             .with_friction(f, radius))
    T = _nonneg("resisting torque T", T, LoadError)
    return Kinetostatics(fb, model, (Torque("rocker", lambda m: -T * np.sign(m.dpsi)),), rpm_to_rad(rpm))


@validated
def class_iv_drive(*, omega1: Omega = 10.0, T: Size = 20.0, f: Size = 0.0, radius: Distance = 0.0) -> Kinetostatics:
    """The chapter's class-IV six-bar (:func:`mechlab.mechanisms.sixbar_iv.example`) with masses.

    Its output link 4 meets a torque of size T against its motion, crank speed ω1 (rad/s), friction f in
    every journal of radius ``radius`` (lengths in the example's unit, about 1 m).

    The model is :func:`model_for`'s (links, pairs and the one group of four links, Zinchenko et al. (2013)
    §1) with the masses of the course's example: coupler 2 kg, J_S = 0.05, S at (0.3, −0.2) from Q along
    Q→P; links 3 and 5 uniform bars of 0.5 and 1 kg (J_S = 0.003, 0.06); output 3 kg, J_S = 0.2, S at
    (0.4, 0.1) from E along E→R. ``model_for`` puts the coupler's origin at A and the output's axis at ψ, so
    those two points are given here in its frames.

    Parameters
    ----------
    omega1 : float, optional
        Crank speed (rad/s).
    T : float, optional
        Resisting torque on the output (N·m, ≥ 0).
    f : float, optional
        Friction coefficient in every journal.
    radius : float, optional
        Journal radius.

    Returns
    -------
    Kinetostatics
        The six-bar with its model and load.

    Raises
    ------
    LoadError
        For a negative T.

    Examples
    --------
    >>> from mechlab.kinetostatics import class_iv_drive
    >>> round(float(class_iv_drive().forces(1.0).torque), 4)
    -21.5334
    """
    from ..mechanisms.sixbar_iv import example
    sb = example()
    u, v = sb.coupler_point                       # A − Q in the frame Q→P
    beta = np.arctan2(sb.r_joint[1], sb.r_joint[0])   # E→R from the output's axis ψ
    c, s = np.cos(beta), np.sin(beta)
    model = (model_for(sb).with_body("coupler", mass=2.0, inertia=0.05, com=(0.3 - u, -0.2 - v))
             .with_body("link 3", mass=0.5, inertia=0.003).with_body("link 5", mass=1.0, inertia=0.06)
             .with_body("output", mass=3.0, inertia=0.2, com=(0.4 * c - 0.1 * s, 0.4 * s + 0.1 * c))
             .with_friction(f, radius))
    T = _nonneg("resisting torque T", T, LoadError)
    return Kinetostatics(sb, model, (Torque("output", lambda m: -T * np.sign(m.dpsi)),), omega1)


def _slider_crank(crank, rod):
    from ..mechanisms.slider_crank import SliderCrank
    return SliderCrank(crank, rod)


def _four_bar(crank, coupler, rocker, ground):
    from ..mechanisms.fourbar import FourBar
    return FourBar(crank, coupler, rocker, ground)

