"""Loads of the МЧВ1 six-bar (Kinitsky (1994), chapter 3, Figs. 10-11), solved with :mod:`mechlab.kinetostatics`.

The thesis loads only the output: a resisting moment M_s = M_st + M_d on the rocker E-F (a
constant static moment opposing its motion plus the inertia moment −J·ε of the driven masses
reduced to it), links massless, friction in the journals as f·r·|R|. Its formulas (16)-(17)
are the statics of this model worked by hand (the rod D-E and the rocker B-C are two-force
members; the three-force theorem on the coupler A-B-D); here the same model is solved by
:func:`mechlab.kinetostatics.solve` group by group, so the crank torque is checked against the power
balance. Invariants (Kinitsky (1994), ch. 3): forces are divided by J·ω1²/l and torques by J·ω1²
(l = 1 here, the length of the Chebyshev dyad's links); the cycle efficiency is the mean of the
instantaneous efficiencies over the crank angles where the output moves.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..mechanisms.lambda_sixbars import LambdaRockerSixBar
from .machines import Kinetostatics
from .model import ForceModel, Torque, model_for

__all__ = ["ForceInvariants", "mchv1_drive", "mchv1_forces", "mchv1_model"]


def mchv1_model(six: LambdaRockerSixBar, inertia: float, friction: float = 0.0, radius: float = 0.0) -> ForceModel:
    """Force model of МЧВ1 from its structure: massless links, the output rocker carrying the reduced
    inertia J (massless, so J acts about F as about any point)."""
    model = model_for(six).with_body("output", inertia=inertia)
    return model.with_friction(friction, radius) if friction else model


def mchv1_drive(six: LambdaRockerSixBar, inertia: float, resisting: float = 0.0, omega1: float = 1.0,
                friction: float = 0.0, radius: float = 0.0) -> Kinetostatics:
    """МЧВ1 with the thesis' loads (Kinitsky (1994), ch. 3): :func:`mchv1_model` and a constant moment
    of size ``resisting`` against the output's motion, M = −resisting·sgn ψ′; crank speed ω1
    constant, no gravity (massless links)."""
    def resist(mo):
        return -resisting * np.sign(mo.dpsi)

    return Kinetostatics(six, mchv1_model(six, inertia, friction, radius), (Torque("output", resist),),
                         omega1=omega1, eps1=0.0, gravity=(0.0, 0.0))


@dataclass(frozen=True)
class ForceInvariants:
    """Peak dimensionless reactions in O, A, B, D, E, F, crank torque and cycle efficiency."""

    reactions: dict
    torque: float
    cycle_efficiency: float
    result: object


def mchv1_forces(six: LambdaRockerSixBar, *, inertia: float = 1.0, resisting: float = 0.0, omega1: float = 1.0,
                 friction: float = 0.0, radius: float = 0.0, n: int = 721, dwell: float | None = None):
    """Solve МЧВ1 over a crank turn with the output loaded by its inertia J and a constant
    resisting moment of size ``resisting`` opposing the rocker's motion.

    Returns :class:`ForceInvariants` (reactions and torque divided by J·ω1²/l and J·ω1²) with
    the :class:`mechlab.kinetostatics.ForceResult`. The cycle efficiency is averaged over the crank
    angles outside the dwell ``dwell`` (centred on φ = π), where the output moves.
    """
    phi = np.linspace(0, 2 * np.pi, n)
    motion = six.motion(phi)
    moving = np.abs(motion.dpsi) > 1e-9

    res = mchv1_drive(six, inertia, resisting, omega1, friction, radius).forces(motion=motion)
    unit_force = inertia * omega1**2  # / l, l = 1
    reactions = {k: float(r.magnitude.max() / unit_force) for k, r in res.reactions.items()}
    if dwell is not None:
        moving = moving & (np.abs(((phi - np.pi) + np.pi) % (2 * np.pi) - np.pi) > dwell / 2)
    try:
        eta = res.cycle_efficiency(moving) if friction else 1.0
    except Exception:
        eta = float("nan")
    return ForceInvariants(reactions, float(np.abs(res.torque).max() / unit_force), eta, res)
