"""mechlab: exact, vectorised kinematics of planar mechanisms with dwells.

Angles are in radians inside the library (degrees only at the widgets' controls);
lengths are dimensionless or in mm, as long as one mechanism uses one unit.
"""

from .errors import (AssemblyError, DimensionError, MechanismError, RotationError,
                     SingularityError)
from .linkages import FourBar, Grashof, Mechanism, SineMechanism, SliderCrank, SlottedLink
from .motion import AngularMotion, LinearMotion, Motion

__version__ = "0.1.0"

__all__ = [
    "MechanismError", "DimensionError", "AssemblyError", "RotationError", "SingularityError",
    "Mechanism", "FourBar", "Grashof", "SliderCrank", "SlottedLink", "SineMechanism",
    "Motion", "AngularMotion", "LinearMotion",
]
