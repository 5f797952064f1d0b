"""Exceptions raised by mechlab.

Every error is a :class:`MechanismError`, itself a :class:`ValueError`, so callers
(and widgets) can catch one type and show its message: the message names the
violated condition and shows the numbers.
"""

import warnings


class MechanismError(ValueError):
    """A mechanism's dimensions or requested motion are not admissible.

    The root of every mechlab error, itself a :class:`ValueError`: a caller (a widget) catches this
    one type and shows its message, which names the violated condition and the numbers.

    Examples
    --------
    >>> from mechlab import FourBar, MechanismError
    >>> try:
    ...     FourBar(1, 3, 3.5, -4)
    ... except MechanismError as err:
    ...     print(type(err).__name__, "-", err)
    DimensionError - ground must be > 0, got -4
    """


class DimensionError(MechanismError):
    """A length or parameter is negative, zero, or not finite.

    Raised by a constructor (or function) given a dimension outside its range; the message names the
    parameter, the bound and the value.

    Examples
    --------
    >>> from mechlab import FourBar
    >>> FourBar(1, 3, 3.5, -4)
    Traceback (most recent call last):
    ...
    mechlab.errors.DimensionError: ground must be > 0, got -4
    """


class AssemblyError(MechanismError):
    """The linkage cannot be assembled at a requested crank angle.

    Raised by ``motion(phi)`` when a dyad does not close at some φ; the message names the first such
    angle (degrees) and the range the crank reaches.

    Examples
    --------
    >>> import numpy as np
    >>> from mechlab import SliderCrank
    >>> SliderCrank(1, 1).motion(np.pi / 2)
    Traceback (most recent call last):
    ...
    mechlab.errors.AssemblyError: cannot assemble at φ = 90.00°: the pin is 1 from the guide, ≥ rod = 1; ...
    """


class RotationError(MechanismError):
    """The crank was asked to turn fully, but the linkage does not allow it.

    Raised by :meth:`Mechanism.turn <mechlab.mechanisms.base.Mechanism.turn>` (and by constructors
    that require a full-turn crank); the message gives the Grashof condition and the reachable arcs.

    Examples
    --------
    >>> from mechlab import FourBar
    >>> FourBar(3, 2, 4, 4).turn()
    Traceback (most recent call last):
    ...
    mechlab.errors.RotationError: crank cannot turn fully: s + l = 6.00 < p + q = 7.00 (Grashof), but ...
    """


class SingularityError(MechanismError):
    """A dead point: the analogs are unbounded (transmission angle 0 or 180°).

    Raised where a dyad is stretched or folded (its two circles only touch), a guide is met at 90°,
    or a group's equilibrium equations are singular.

    Examples
    --------
    >>> from mechlab.geometry import circle_circle
    >>> circle_circle((0.0, 0.0), 1.0, (2.0, 0.0), 1.0, 1)
    Traceback (most recent call last):
    ...
    mechlab.errors.SingularityError: dead point of the dyad: the joint distance 2 equals r1 + r2; ...
    """


class SynthesisError(MechanismError):
    """A requested lambda-mechanism design does not exist (outside the existence limits).

    Examples
    --------
    >>> from mechlab import circle_guiding
    >>> circle_guiding(0.1, 3.0, 0.5)
    Traceback (most recent call last):
    ...
    mechlab.errors.SynthesisError: circle guiding: a = 3 ≥ 2 leaves no crank with full rotation (r < 2 − a)
    """


class NoDesignError(SynthesisError):
    """A circle-guiding request refused with its evidence.

    ``kind`` names the reason (``"frame"``, ``"resolution"``, ``"rotation"``, ``"fold"``,
    ``"whole turn"``) and ``evidence`` holds the numbers that justify it, so that a caller (or a test)
    can check them.

    Parameters
    ----------
    message : str
        The explanation shown to the user.
    kind : str, optional
        The reason's name (empty when none applies).
    **evidence
        The numbers behind the refusal, kept as the ``evidence`` dict.

    Examples
    --------
    >>> from mechlab import NoDesignError, circle_guiding
    >>> try:
    ...     circle_guiding(0.1, 1.5, 0.5)
    ... except NoDesignError as err:
    ...     print(err.kind, sorted(err.evidence))
    frame ['span']
    """

    def __init__(self, message: str, kind: str = "", **evidence):
        super().__init__(message)
        self.kind, self.evidence = kind, evidence


class InfeasibleDesignError(SynthesisError):
    """A six-bar requested by K, β_m (or a pivot position) cannot be built.

    Examples
    --------
    >>> from mechlab import InfeasibleDesignError, SynthesisError
    >>> issubclass(InfeasibleDesignError, SynthesisError)
    True
    >>> raise InfeasibleDesignError("the rod cannot reach the rocker")
    Traceback (most recent call last):
    ...
    mechlab.errors.InfeasibleDesignError: the rod cannot reach the rocker
    """


class TransmissionAngleError(InfeasibleDesignError):
    """A six-bar's design leaves the working range of a transmission angle (its base four-bar's or its dyad's)."""


class StructureError(MechanismError):
    """A mechanism's links, pairs and groups do not make a well-formed structure.

    Well-formed: statically solvable groups, joints defined once, one degree of freedom. Raised by the
    builder and by the force model's bodies and pairs.

    Examples
    --------
    >>> from mechlab import Body
    >>> Body("frame", "O")
    Traceback (most recent call last):
    ...
    mechlab.errors.StructureError: a body may not be called 'frame' (reserved for the frame)
    """


class JointError(StructureError):
    """A joint is defined twice, or a group attaches to a joint (or a link) not defined before it."""


class MobilityError(StructureError):
    """The structure's mobility W = 3n - 2p₅ - p₄ is not 1: it is not driven by exactly one crank."""


# -- raised by design.spec
class SpecificationError(DimensionError):
    """A specification that no mechanism can be asked for (its message names the field).

    Examples
    --------
    >>> from mechlab.design import Specification
    >>> Specification("index", 0.5)
    Traceback (most recent call last):
    ...
    mechlab.errors.SpecificationError: an index motion needs the number of stations
    """


# -- raised by kinetostatics.model
class MassError(DimensionError):
    """A mass or moment of inertia is negative or not finite.

    Examples
    --------
    >>> from mechlab import Body
    >>> Body("link", "A", mass=-1)
    Traceback (most recent call last):
    ...
    mechlab.errors.MassError: mass of link must be ≥ 0, got -1
    """


class FrictionError(DimensionError):
    """A friction coefficient or journal radius is out of range.

    Examples
    --------
    >>> from mechlab import Revolute
    >>> Revolute("A", "frame", "crank", "A", friction=-0.1)
    Traceback (most recent call last):
    ...
    mechlab.errors.FrictionError: friction coefficient of A must be ≥ 0, got -0.1 (0 ≤ f < 1)
    """


class LoadError(DimensionError):
    """A load's value has the wrong shape or is not finite.

    Examples
    --------
    >>> from mechlab import Force
    >>> Force("slider", "B", value=float("nan"))
    Traceback (most recent call last):
    ...
    mechlab.errors.LoadError: value must be a point (x, y), got nan
    """


class FrictionlessOnlyError(LoadError):
    """Inverse kinetostatics needs the ideal mechanism: with friction the torque is not linear in the load.

    Examples
    --------
    >>> from mechlab.kinetostatics import press, torque_for_load
    >>> rough = press(f=0.1)
    >>> torque_for_load(rough.mechanism, 100.0, 0.5, model=rough.model)
    Traceback (most recent call last):
    ...
    mechlab.errors.FrictionlessOnlyError: friction in pairs ['O', 'A', 'B', 'guide']: ...
    """


class SelfLockingError(MechanismError):
    """Friction admits no consistent solution (or makes a group singular): the mechanism locks.

    Raised by :func:`mechlab.kinetostatics.solve` when a group's equations with friction are singular
    or its friction iteration does not settle; the message names the group and the crank angle.

    Examples
    --------
    >>> from mechlab import SelfLockingError, MechanismError
    >>> issubclass(SelfLockingError, MechanismError)
    True
    >>> raise SelfLockingError("group ('rod', 'slider') locks at φ = 90.00°")
    Traceback (most recent call last):
    ...
    mechlab.errors.SelfLockingError: group ('rod', 'slider') locks at φ = 90.00°
    """


# -- raised by kinetostatics.drive
class DriveError(DimensionError):
    """Inadmissible drive data.

    Efficiency outside (0, 1], overload factor < 1, torque samples that are not finite or do not match
    the crank angles, ω1 = 0.

    Examples
    --------
    >>> import numpy as np
    >>> from mechlab.kinetostatics import drive
    >>> drive(np.ones(3), np.linspace(0, 1, 3), 0.0)
    Traceback (most recent call last):
    ...
    mechlab.errors.DriveError: crank speed ω1 must be finite and non-zero: omega1 = 0.0
    """


# -- raised by mechanisms.spherical_geneva
class SpatialMechanismError(MechanismError):
    """A planar method (instantaneous centres, planar kinetostatics) asked of a spatial mechanism."""


# -- raised by mechanisms.geneva
class SlotCountError(DimensionError):
    """The number of slots z is not an integer ≥ 3.

    Examples
    --------
    >>> from mechlab import ExternalGeneva
    >>> ExternalGeneva(2, 100)
    Traceback (most recent call last):
    ...
    mechlab.errors.SlotCountError: z must be a whole number ≥ 3, got 2 (...)
    """


class OffsetError(DimensionError):
    """The spherical Geneva's offset e does not satisfy 0 ≤ e < R.

    Examples
    --------
    >>> from mechlab import SphericalGeneva
    >>> SphericalGeneva(100, 120, 4)
    Traceback (most recent call last):
    ...
    mechlab.errors.OffsetError: the offset must satisfy e < R (...), got e = 120 ≥ R = 100
    """


# -- raised by synthesis.slot_export
class SlotUndercutError(MechanismError):
    """The roller is too large for the slot's curvature (a flank would fold over)."""


# -- raised by mechanisms.cam
class CamUndercutError(MechanismError):
    """The roller is too large for the pitch curve's curvature: the profile would be undercut.

    Examples
    --------
    >>> import numpy as np
    >>> from mechlab import CamProgramme, TranslatingRollerCam
    >>> programme = CamProgramme(30.0, np.radians(40), np.radians(40))
    >>> TranslatingRollerCam(programme, 10.0, 15.0).profile()
    Traceback (most recent call last):
    ...
    mechlab.errors.CamUndercutError: roller radius 15 is too large: ...
    """


# -- raised by synthesis.dwell_slot
class DwellError(MechanismError):
    """A dwell design that cannot be built.

    Examples
    --------
    >>> from mechlab import dwell_limit
    >>> dwell_limit(0.5, 0.01)
    Traceback (most recent call last):
    ...
    mechlab.errors.DwellError: no dwell keeps the pressure angle ≤ 0.6° for λ = 0.5 with the cubic transition
    """


class DwellIntervalError(DwellError, DimensionError):
    """The dwell interval [φ1, φ2] is empty, reversed, or not strictly inside (0, π).

    Examples
    --------
    >>> from mechlab import DwellLaw
    >>> DwellLaw(2.0, 1.0, 0.5)
    Traceback (most recent call last):
    ...
    mechlab.errors.DwellIntervalError: the dwell needs φ1 < φ2, got [φ1, φ2] = [57.30°, 28.65°]
    """


class DwellRatioError(DwellError, DimensionError):
    """λ = l_OA / l_OB is not a positive number different from 1.

    Examples
    --------
    >>> from mechlab import DwellLaw
    >>> DwellLaw(1.0, 0.5, 1.0)
    Traceback (most recent call last):
    ...
    mechlab.errors.DwellRatioError: λ = l_OA / l_OB = 1, but λ ≠ 1 is needed ...
    """


# -- raised by analysis.centres.homogeneous
class CentreAtInfinity(SingularityError):
    """A finite position was asked of an instantaneous centre that lies at infinity.

    Examples
    --------
    >>> from mechlab.analysis.centres.homogeneous import at_infinity
    >>> at_infinity((1.0, 0.0), n=1).xy
    Traceback (most recent call last):
    ...
    mechlab.errors.CentreAtInfinity: ...
    """


class IndeterminateCentre(SingularityError):
    """Kennedy's construction is undefined: its two lines (or two points) coincide.

    Examples
    --------
    >>> import numpy as np
    >>> from mechlab.analysis.centres.homogeneous import normalise
    >>> normalise(np.zeros((1, 3)))
    Traceback (most recent call last):
    ...
    mechlab.errors.IndeterminateCentre: P is undefined...: its construction degenerates
    """


# -- raised by design.families
class Unsuitable(MechanismError):
    """The family cannot meet the specification; the message says why, with the numbers.

    Examples
    --------
    >>> from mechlab.design import Specification
    >>> from mechlab.design.families import external_geneva
    >>> external_geneva(Specification("stroke", 0.5, amplitude=30))
    Traceback (most recent call last):
    ...
    mechlab.errors.Unsuitable: indexes a rotating table one way; a stroke was asked
    """


def renamed(module: str, **old):
    """A module ``__getattr__`` that still serves renamed names for one release, with a DeprecationWarning.

    Parameters
    ----------
    module : str
        The module's name (``__name__``).
    **old
        Each old name → (the object, its new dotted name).

    Returns
    -------
    callable
        ``__getattr__(name)``: the object under its old name (warning which name replaces it), else
        AttributeError.

    Examples
    --------
    >>> __getattr__ = renamed("mymodule", twice=(print, "builtins.print"))
    >>> import warnings
    >>> with warnings.catch_warnings(record=True) as seen:
    ...     warnings.simplefilter("always")
    ...     __getattr__("twice") is print, "builtins.print" in str(seen[0].message)
    (True, True)
    """
    def __getattr__(name):
        if name in old:
            obj, new = old[name]
            warnings.warn(f"{module}.{name} is now {new}; the old name goes in the next release",
                          DeprecationWarning, stacklevel=2)
            return obj
        raise AttributeError(f"module {module!r} has no attribute {name!r}")
    return __getattr__



# -- raised by synthesis.coupler_dwell
class CouplerFitError(SynthesisError):
    """No arc or straight run of a coupler curve can be fitted as asked: an unknown joint, a crank interval that
    is reversed or too short for the samples, longer than the crank reaches, or a straight path asked for a circle.

    Examples
    --------
    >>> import mechlab as ml
    >>> ml.coupler_arcs(ml.coupler_fourbar(1, 3, 3, 4), "Q")
    Traceback (most recent call last):
    ...
    mechlab.errors.CouplerFitError: the linkage has no joint 'Q'; its joints: O, E, A, B, P
    """
