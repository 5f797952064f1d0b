"""mechlab: exact, vectorised kinematics of planar mechanisms with dwells.

Angles are in radians inside the library (degrees only at the widgets' controls);
lengths are dimensionless or in mm, as long as one mechanism uses one unit.
Computation never imports plotting: drawings live in :mod:`mechlab.draw`, controls
in :mod:`mechlab.widgets`.
"""

from . import design
from . import kinetostatics as forces
from .analysis import motion_laws
from .analysis.centres import (
    Centre,
    CentreAtInfinity,
    IndeterminateCentre,
    centre_count,
    centrodes,
    instant_centres,
    rolling_speeds,
)
from .analysis.centres.kennedy import five_link_higher_pair
from .analysis.equivalence import (
    assembly_symmetry,
    base_law,
    base_mechanism,
    equivalent_slot,
    law_difference,
    relative_path,
)
from .analysis.half_turn import base_peaks, formula_18, limit_theorem, other_half
from .analysis.intermittency import compare, detect_impacts, intermittency
from .analysis.textbook import (
    TransmissionExtremes,
    crank_ranges_degrees,
    nearest_assembly,
    transmission_extremes,
    zero_acceleration,
)
from .errors import (
    AssemblyError,
    CouplerFitError,
    DimensionError,
    InfeasibleDesignError,
    MechanismError,
    NoDesignError,
    RotationError,
    SingularityError,
    SynthesisError,
)
from .kinetostatics import (
    Body,
    DriveError,
    Force,
    ForceModel,
    HigherPair,
    Kinetostatics,
    Prismatic,
    Revolute,
    SelfLockingError,
    Torque,
    model_for,
)
from .mechanisms import (
    Antiparallelogram,
    CamUndercutError,
    CircleSlot,
    CurvedSlotLink,
    EllipticTrammel,
    ExternalGeneva,
    FourBar,
    Grashof,
    InternalGeneva,
    LambdaMechanism,
    LambdaRockerSixBar,
    LambdaSliderSixBar,
    LambdaSlottedSixBar,
    LambdaTranslatingSlot,
    Mechanism,
    OscillatingRollerCam,
    ParametricSlot,
    SampledSlot,
    SineMechanism,
    SixBarIV,
    SliderCrank,
    SlottedLink,
    SphericalGeneva,
    TranslatingCurvedSlot,
    TranslatingRollerCam,
)
from .mechanisms.geneva import OffsetError, SlotCountError
from .mechanisms.lambda_mechanism import classic_lambda
from .mechanisms.linkage import (
    PRP,
    RPP,
    RPR,
    RRP,
    RRR,
    CamFollower,
    Crank,
    CurvedSlot,
    Guide,
    Linkage,
    Point,
    Tetrad,
)
from .motion import AngularMotion, Extremes, Law, LinearMotion, Motion, Quantity, Table
from .synthesis.atlas import Atlas, AtlasDesign, build_atlas, load_atlas
from .synthesis.cam_design import CamProgramme
from .synthesis.coupler_dwell import (
    ArcFit,
    DwellCheck,
    RunFit,
    arc_dwell_sixbar,
    check_dwell,
    coupler_arcs,
    coupler_fourbar,
    coupler_runs,
    fit_arc,
    fit_run,
    run_dwell_sixbar,
)
from .synthesis.dwell_slot import (
    TRANSITIONS,
    DwellError,
    DwellIntervalError,
    DwellLaw,
    DwellRatioError,
    DwellSlotMechanism,
    best_placement,
    compare_transitions,
    cubic_dwell_window,
    curved_slot_dwell,
    dwell_limit,
    slotted_link_law,
    two_branch_slot,
)
from .synthesis.geneva import TABLE1_PRINTED, spherical_table, table1_comparison, table1_review
from .synthesis.lambda_guiding import (
    DesignOutcomes,
    band_touches,
    circle_guiding,
    design_outcomes,
    existence_map,
    existence_region,
    fifth_order_line,
    load_design_outcomes,
    save_design_outcomes,
    straight_guiding,
    thesis_iteration,
    transmission_lines,
    whole_turn_guiding,
    whole_turn_line,
)
from .synthesis.lambda_sixbars import (
    dwell_extent,
    mchv1,
    mchv3_best_table,
    mchv3_full_turn,
    mchv3_full_turn_best,
    mchv3_half_turn,
    mchv3_oscillating,
    mchv3_pivot_table,
    rise_law,
    slot_residual_first_order,
    time_ratio_far_angle,
)
from .synthesis.lambda_sliders import mchv2, mchv2_far_position, mchv2_stroke, mchv5, slider_invariants, slider_report
from .synthesis.slot_export import read_csv, read_dxf, slot_profile, write_cam_csv, write_cam_dxf, write_csv, write_dxf

__version__ = "0.1.0"

__all__ = [  # noqa: RUF022  grouped by topic, each group under its comment, not alphabetical
    # errors
    "MechanismError", "DimensionError", "AssemblyError", "RotationError", "SingularityError",
    # mechanisms and results
    "Mechanism", "FourBar", "Grashof", "SliderCrank", "SlottedLink", "SineMechanism",
    "CurvedSlotLink", "TranslatingCurvedSlot", "CircleSlot", "ParametricSlot", "SampledSlot", "SixBarIV",
    "EllipticTrammel", "Antiparallelogram", "LambdaMechanism",
    "ExternalGeneva", "InternalGeneva", "SphericalGeneva",
    "Linkage", "Crank", "RRR", "RRP", "RPR", "PRP", "RPP", "Tetrad", "CurvedSlot", "CamFollower", "Guide",
    "Point",
    "Motion", "AngularMotion", "LinearMotion", "Law", "Extremes", "Table", "Quantity",
    # textbook helpers
    "nearest_assembly", "transmission_extremes", "TransmissionExtremes", "zero_acceleration", "crank_ranges_degrees",
    # equivalence, base mechanism, half-turn relations
    "relative_path", "equivalent_slot", "base_law", "base_mechanism", "assembly_symmetry", "law_difference",
    "other_half", "limit_theorem", "base_peaks", "formula_18",
    # instantaneous centres
    "instant_centres", "centrodes", "Centre", "CentreAtInfinity", "IndeterminateCentre", "centre_count",
    "rolling_speeds", "five_link_higher_pair",
    # dwell synthesis
    "curved_slot_dwell", "DwellSlotMechanism", "DwellLaw", "TRANSITIONS", "compare_transitions", "dwell_limit",
    "slotted_link_law",
    "cubic_dwell_window",
    "two_branch_slot", "best_placement", "DwellError", "DwellIntervalError", "DwellRatioError",
    "slot_profile", "write_csv", "write_dxf", "read_csv", "read_dxf",
    # cams
    "CamProgramme", "TranslatingRollerCam", "OscillatingRollerCam", "CamUndercutError", "write_cam_csv",
    "write_cam_dxf",
    # Chebyshev
    "circle_guiding", "straight_guiding", "whole_turn_line", "whole_turn_guiding", "existence_map",
    "existence_region", "design_outcomes", "DesignOutcomes", "save_design_outcomes", "load_design_outcomes",
    "band_touches", "fifth_order_line", "thesis_iteration",
    "transmission_lines",
    "classic_lambda", "LambdaRockerSixBar", "LambdaSlottedSixBar", "LambdaSliderSixBar", "LambdaTranslatingSlot",
    "mchv1", "mchv2", "mchv2_far_position", "mchv2_stroke", "mchv3_full_turn", "mchv3_full_turn_best",
    "mchv3_half_turn", "mchv3_oscillating", "mchv3_pivot_table", "mchv3_best_table",
    "slot_residual_first_order", "mchv5", "dwell_extent", "rise_law",
    "time_ratio_far_angle",
    "slider_report", "slider_invariants", "SynthesisError", "InfeasibleDesignError", "NoDesignError",
    # dwell from coupler curves
    "coupler_fourbar", "ArcFit", "RunFit", "coupler_arcs", "coupler_runs", "fit_arc", "fit_run", "arc_dwell_sixbar",
    "run_dwell_sixbar", "check_dwell", "DwellCheck", "CouplerFitError",
    # the coupler-curve atlas
    "Atlas", "AtlasDesign", "build_atlas", "load_atlas",
    # Geneva
    "spherical_table", "table1_comparison", "table1_review", "TABLE1_PRINTED", "compare", "intermittency",
    "detect_impacts",
    "SlotCountError", "OffsetError",
    # forces
    "forces", "motion_laws", "design", "Kinetostatics", "ForceModel", "Body", "Revolute", "Prismatic", "HigherPair",
    "Force", "Torque", "model_for", "SelfLockingError", "DriveError",
]
