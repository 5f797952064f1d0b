"""Kinetostatics: bodies and loads, the group-by-group solve, the motor rule, the chapters' machines.

:mod:`~mechlab.kinetostatics.model`, :mod:`~mechlab.kinetostatics.solve`, :mod:`~mechlab.kinetostatics.drive`,
:mod:`~mechlab.kinetostatics.machines`, :mod:`~mechlab.kinetostatics.geneva`,
:mod:`~mechlab.kinetostatics.lambda_sixbars` and :mod:`~mechlab.kinetostatics.inverse` (the load a torque
balances, the torque a load needs).

``mechlab.forces`` (``ml.forces``) is this package under the name the course used first.
"""

from .drive import Drive, DriveError, cycle_mean, drive, motor_torque
from .inverse import FrictionlessOnlyError, balanced_load, torque_for_load
from .machines import Kinetostatics, class_iv_drive, press, press_load, rocker_drive, rpm_to_rad
from .model import (
    FRAME,
    Body,
    Force,
    ForceModel,
    FrictionError,
    G,
    HigherPair,
    LoadError,
    MassError,
    Prismatic,
    Revolute,
    SelfLockingError,
    StructureError,
    Torque,
    model_for,
    slender_bar,
)
from .solve import ForceResult, Reaction, output_axis, solve, virtual_work_torque

__all__ = [
    "FRAME",
    "Body",
    "Drive",
    "DriveError",
    "Force",
    "ForceModel",
    "ForceResult",
    "FrictionError",
    "FrictionlessOnlyError",
    "G",
    "HigherPair",
    "Kinetostatics",
    "LoadError",
    "MassError",
    "Prismatic",
    "Reaction",
    "Revolute",
    "SelfLockingError",
    "StructureError",
    "Torque",
    "balanced_load",
    "class_iv_drive",
    "cycle_mean",
    "drive",
    "model_for",
    "motor_torque",
    "output_axis",
    "press",
    "press_load",
    "rocker_drive",
    "rpm_to_rad",
    "slender_bar",
    "solve",
    "torque_for_load",
    "virtual_work_torque",
]
