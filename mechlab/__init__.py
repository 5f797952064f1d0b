"""mechlab: exact, vectorised kinematics of planar mechanisms with dwells.

Angles are in radians inside the library (degrees only at the widgets' controls);
lengths are dimensionless or in mm, as long as one mechanism uses one unit.
Computation never imports plotting: drawings live in :mod:`mechlab.draw`, controls
in :mod:`mechlab.widgets`.
"""

from . import forces, motion_laws
from .centres import (Antiparallelogram, Centre, CentreAtInfinity, EllipticTrammel, IndeterminateCentre,
                      centrodes, instant_centres)
from .chebyshev import (InfeasibleDesignError, LambdaMechanism, LambdaRockerSixBar, LambdaSlottedSixBar,
                        LambdaSliderSixBar, LambdaTranslatingSlot, SynthesisError, circle_guiding, existence_map,
                        existence_region, mchv1, mchv2, mchv2_stroke, mchv3_full_turn, mchv3_full_turn_best, mchv5,
                        slider_invariants, slider_report, slot_residual_first_order, straight_guiding,
                        whole_turn_guiding, whole_turn_line)
from .dwell import (TRANSITIONS, DwellError, DwellIntervalError, DwellLaw, DwellRatioError, DwellSlotMechanism,
                    compare_transitions, curved_slot_dwell, dwell_limit, two_branch_slot)
from .equivalence import assembly_symmetry, base_law, base_mechanism, equivalent_slot, relative_path
from .errors import AssemblyError, DimensionError, MechanismError, RotationError, SingularityError
from .forces import (Body, DriveError, Force, ForceModel, HigherPair, Kinetostatics, Prismatic, Revolute,
                     SelfLockingError, Torque, model_for)
from .geneva import (ExternalGeneva, InternalGeneva, OffsetError, SlotCountError, SphericalGeneva, compare,
                     intermittency, spherical_table)
from .halfturn import base_peaks, limit_theorem, other_half
from .linkages import FourBar, Grashof, Mechanism, SineMechanism, SliderCrank, SlottedLink
from .linkages.curved_slot import CircleSlot, CurvedSlotLink, ParametricSlot, SampledSlot, TranslatingCurvedSlot
from .motion import AngularMotion, LinearMotion, Motion
from .sixbar import SixBarIV
from .slot_export import slot_profile, write_csv, write_dxf

__version__ = "0.1.0"

__all__ = [
    # errors
    "MechanismError", "DimensionError", "AssemblyError", "RotationError", "SingularityError",
    # mechanisms and results
    "Mechanism", "FourBar", "Grashof", "SliderCrank", "SlottedLink", "SineMechanism",
    "CurvedSlotLink", "TranslatingCurvedSlot", "CircleSlot", "ParametricSlot", "SampledSlot", "SixBarIV",
    "EllipticTrammel", "Antiparallelogram", "LambdaMechanism",
    "ExternalGeneva", "InternalGeneva", "SphericalGeneva",
    "Motion", "AngularMotion", "LinearMotion",
    # equivalence, base mechanism, half-turn relations
    "relative_path", "equivalent_slot", "base_law", "base_mechanism", "assembly_symmetry",
    "other_half", "limit_theorem", "base_peaks",
    # instantaneous centres
    "instant_centres", "centrodes", "Centre", "CentreAtInfinity", "IndeterminateCentre",
    # dwell synthesis
    "curved_slot_dwell", "DwellSlotMechanism", "DwellLaw", "TRANSITIONS", "compare_transitions", "dwell_limit",
    "two_branch_slot", "DwellError", "DwellIntervalError", "DwellRatioError",
    "slot_profile", "write_csv", "write_dxf",
    # Chebyshev
    "circle_guiding", "straight_guiding", "whole_turn_line", "whole_turn_guiding", "existence_map",
    "existence_region", "LambdaRockerSixBar", "LambdaSlottedSixBar", "LambdaSliderSixBar", "LambdaTranslatingSlot",
    "mchv1", "mchv2", "mchv2_stroke", "mchv3_full_turn", "mchv3_full_turn_best", "slot_residual_first_order", "mchv5",
    "slider_report", "slider_invariants", "SynthesisError", "InfeasibleDesignError",
    # Geneva
    "spherical_table", "compare", "intermittency", "SlotCountError", "OffsetError",
    # forces
    "forces", "motion_laws", "Kinetostatics", "ForceModel", "Body", "Revolute", "Prismatic", "HigherPair",
    "Force", "Torque", "model_for", "SelfLockingError", "DriveError",
]
