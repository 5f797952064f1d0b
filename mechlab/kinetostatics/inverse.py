"""Inverse kinetostatics: the load on a mechanism's output that a given driving torque balances, and the
driving torque that a given output load needs.

Both use the power balance of the ideal (frictionless) mechanism, Zhukovsky's lever in analytic form
(:func:`~mechlab.kinetostatics.solve.virtual_work_torque`): a generalised load Q on the output coordinate
q (a torque on the output link for an angular output ψ, a force along the output's path for a linear
output s) does the work Q·q′ per unit crank angle. So the balancing torque is M = M₀ − Q·q′/θ′, with M₀
the torque for the other loads (gravity, inertia, ``loads``) and θ′ the crank's rate (1 for a crank), and
the load balanced by a torque M is Q = (M₀ − M)·θ′/q′. Q is counted positive along +q: a load that
resists a rising output is negative while q′ > 0.
"""

from __future__ import annotations

from typing import Annotated

import numpy as np

from ..errors import FrictionlessOnlyError
from ..mechanisms.base import Mechanism
from ..motion import STILL, AngularMotion, LinearMotion
from ..validate import Point, Spec, check_value, number, validated
from ..validate import mechanism as instance_of
from .model import Force, ForceModel, G, LoadError, Torque, model_for
from .solve import _frames, virtual_work_torque

__all__ = ["FrictionlessOnlyError", "balanced_load", "torque_for_load"]

AnyMechanism = Annotated[Mechanism, instance_of(Mechanism)]
Loads = Annotated[tuple, Spec("items", expected=(Force, Torque))]
Model = Annotated[ForceModel | None, instance_of(ForceModel, optional=True)]
Omega = Annotated[float, number()]
Values = Annotated[float | np.ndarray, Spec("reals")]


def _setup(mech, phi, model, loads, omega1, eps1, gravity):
    """The motion at φ, the model (frictionless), the torque for the other loads, q′ and θ′."""
    motion = mech.motion(np.atleast_1d(check_value("phi", phi, Spec("angles", lo=1))))
    if not isinstance(motion, AngularMotion | LinearMotion):
        raise LoadError(f"{type(mech).__name__} reports no output law: no load on its output")
    model = model_for(mech) if model is None else model
    rough = [p.name for p in model.pairs if getattr(p, "friction", 0.0) > 0]
    if rough:
        raise FrictionlessOnlyError(f"friction in pairs {rough}: inverse kinetostatics uses the power balance of "
                                    f"the ideal mechanism; solve the forward problem (solve) with friction instead")
    M0 = virtual_work_torque(model, motion, tuple(loads), omega1, eps1, gravity)
    return motion, motion.output.d, _frames(model, motion)[model.crank].dth, M0


def _shaped(value, phi):
    """A scalar result for a scalar φ."""
    return value[0] if np.ndim(phi) == 0 else value


def _per_angle(name: str, values, phi) -> None:
    """LoadError naming ``name`` unless ``values`` is one number or one per crank angle of ``phi``."""
    if np.ndim(values) and np.shape(values) != (np.size(phi),):
        raise LoadError(f"{name} must be one number or one per crank angle ({np.size(phi)}), got {np.size(values)} "
                        f"values")


@validated
def balanced_load(mechanism: AnyMechanism, torque: Values, phi, *, model: Model = None, loads: Loads = (),
                  omega1: Omega = 1.0, eps1: Omega = 0.0, gravity: Point = (0.0, -G)) -> np.ma.MaskedArray:
    """The load Q on the mechanism's output (its :attr:`~mechlab.motion.Motion.output` coordinate) that the
    driving torque ``torque`` balances at crank angles ``phi``: Q = (M₀ − M)·θ′/q′.

    Parameters
    ----------
    mechanism : any mechanism with a ``structure()`` (its output link carries the load).
    torque : the driving torque M on the crank (N·m, counter-clockwise positive), one number or one per angle.
    phi : crank angles (radians).
    model : a :class:`ForceModel` with masses (default: ``model_for(mechanism)``, massless).
    loads : other known loads (Force, Torque) on the model's bodies.
    omega1, eps1, gravity : crank speed (rad/s), crank acceleration (rad/s²), gravity (m/s²) for the
        inertia forces and weights.

    Returns
    -------
    numpy.ma.MaskedArray
        Q: a torque (N·m) on the output link for an angular output, a force (N) along the output's path
        for a linear output, positive along +q; masked where the output stands still (q′ = 0: the load
        does no work and no torque balances it). A scalar φ gives a scalar (``numpy.ma.masked`` there).

    Raises
    ------
    FrictionlessOnlyError
        The model has friction.
    LoadError
        The mechanism reports no output law.

    Examples
    --------
    >>> import mechlab as ml
    >>> sc = ml.SliderCrank(0.1, 0.4)
    >>> Q = balanced_load(sc, 10.0, np.pi / 2)            # 10 N·m on the crank at φ = 90°
    >>> round(float(Q), 6)                                # the force on the slider along +s (s′ = −0.1)
    100.0
    """
    _per_angle("torque", torque, phi)
    _motion, dq, dth, M0 = _setup(mechanism, phi, model, loads, omega1, eps1, gravity)
    M = np.broadcast_to(np.asarray(torque, dtype=float), dq.shape)
    # a still output (mechlab.motion.STILL) balances no load: masked, not infinite
    still = np.abs(dq) <= STILL * max(float(np.max(np.abs(dq))), 1.0) * np.abs(dth)
    with np.errstate(divide="ignore", invalid="ignore"):
        Q = np.ma.masked_array(np.where(still, 0.0, (M0 - M) * dth / np.where(still, 1.0, dq)), mask=still)
    return _shaped(Q, phi)


@validated
def torque_for_load(mechanism: AnyMechanism, load: Values, phi, *, model: Model = None, loads: Loads = (),
                    omega1: Omega = 1.0, eps1: Omega = 0.0, gravity: Point = (0.0, -G)) -> np.ndarray:
    """The driving torque curve M(φ) = M₀ − Q·q′/θ′ that balances the load ``load`` (Q) on the mechanism's
    output, with the other loads, at crank angles ``phi`` (the forward problem of :func:`balanced_load`).

    Parameters
    ----------
    mechanism : Mechanism
        As for :func:`balanced_load`.
    load : float or array_like
        Q on the output (N·m on the output link for an angular output, N along the output's path for
        a linear one; positive along +q), one number or one per angle.
    phi, model, loads, omega1, eps1, gravity
        As for :func:`balanced_load`.

    Returns
    -------
    numpy.ndarray
        The balancing torque on the crank (N·m), one per angle (a float for a scalar φ).

    Raises
    ------
    FrictionlessOnlyError
        The model has friction (use :func:`~mechlab.kinetostatics.solve.solve` with a Force or Torque).

    Examples
    --------
    >>> import mechlab as ml
    >>> sc = ml.SliderCrank(0.1, 0.4)
    >>> round(float(torque_for_load(sc, 100.0, np.pi / 2)), 6)
    10.0
    """
    _per_angle("load", load, phi)
    _motion, dq, dth, M0 = _setup(mechanism, phi, model, loads, omega1, eps1, gravity)
    Q = np.broadcast_to(np.asarray(load, dtype=float), dq.shape)
    return _shaped(M0 - Q * dq / dth, phi)
