"""Exceptions raised by mechlab.

Every error is a :class:`MechanismError`, itself a :class:`ValueError`, so callers
(and widgets) can catch one type and show its message: the message names the
violated condition and shows the numbers.
"""

import warnings


class MechanismError(ValueError):
    """A mechanism's dimensions or requested motion are not admissible."""


class DimensionError(MechanismError):
    """A length or parameter is negative, zero, or not finite."""


class AssemblyError(MechanismError):
    """The linkage cannot be assembled at a requested crank angle."""


class RotationError(MechanismError):
    """The crank was asked to turn fully, but the linkage does not allow it."""


class SingularityError(MechanismError):
    """A dead point: the analogs are unbounded (transmission angle 0 or 180°)."""


class SynthesisError(MechanismError):
    """A requested lambda-mechanism design does not exist (outside the existence limits)."""


class NoDesignError(SynthesisError):
    """A circle-guiding request refused with its evidence: ``kind`` names the reason (``"frame"``,
    ``"resolution"``, ``"rotation"``, ``"fold"``, ``"whole turn"``) and ``evidence`` holds the numbers
    that justify it, so that a caller (or a test) can check them."""

    def __init__(self, message: str, kind: str = "", **evidence):
        super().__init__(message)
        self.kind, self.evidence = kind, evidence


class InfeasibleDesignError(SynthesisError):
    """A six-bar requested by K, β_m (or a pivot position) cannot be built."""


class TransmissionAngleError(InfeasibleDesignError):
    """A six-bar's design leaves the working range of a transmission angle (its base four-bar's or its dyad's)."""


class StructureError(MechanismError):
    """A mechanism's links, pairs and groups do not make a well-formed structure (statically solvable groups,
    joints defined once, one degree of freedom)."""


class JointError(StructureError):
    """A joint is defined twice, or a group attaches to a joint (or a link) not defined before it."""


class MobilityError(StructureError):
    """The structure's mobility W = 3n - 2p₅ - p₄ is not 1: it is not driven by exactly one crank."""


# -- raised by design.spec
class SpecificationError(DimensionError):
    """A specification that no mechanism can be asked for (its message names the field)."""


# -- raised by kinetostatics.model
class MassError(DimensionError):
    """A mass or moment of inertia is negative or not finite."""


class FrictionError(DimensionError):
    """A friction coefficient or journal radius is out of range."""


class LoadError(DimensionError):
    """A load's value has the wrong shape or is not finite."""


class FrictionlessOnlyError(LoadError):
    """Inverse kinetostatics needs the ideal mechanism: with friction the torque is not linear in the load."""


class SelfLockingError(MechanismError):
    """Friction admits no consistent solution (or makes a group singular): the mechanism locks."""


# -- raised by kinetostatics.drive
class DriveError(DimensionError):
    """Inadmissible drive data: efficiency outside (0, 1], overload factor < 1, torque samples
    that are not finite or do not match the crank angles, ω1 = 0."""


# -- raised by mechanisms.spherical_geneva
class SpatialMechanismError(MechanismError):
    """A planar method (instantaneous centres, planar kinetostatics) asked of a spatial mechanism."""


# -- raised by mechanisms.geneva
class SlotCountError(DimensionError):
    """The number of slots z is not an integer ≥ 3."""


class OffsetError(DimensionError):
    """The spherical Geneva's offset e does not satisfy 0 ≤ e < R."""


# -- raised by synthesis.slot_export
class SlotUndercutError(MechanismError):
    """The roller is too large for the slot's curvature (a flank would fold over)."""


# -- raised by mechanisms.cam
class CamUndercutError(MechanismError):
    """The roller is too large for the pitch curve's curvature: the profile would be undercut."""


# -- raised by synthesis.dwell_slot
class DwellError(MechanismError):
    """A dwell design that cannot be built."""


class DwellIntervalError(DwellError, DimensionError):
    """The dwell interval [φ1, φ2] is empty, reversed, or not strictly inside (0, π)."""


class DwellRatioError(DwellError, DimensionError):
    """λ = l_OA / l_OB is not a positive number different from 1."""


# -- raised by analysis.centres.homogeneous
class CentreAtInfinity(SingularityError):
    """A finite position was asked of an instantaneous centre that lies at infinity."""


class IndeterminateCentre(SingularityError):
    """Kennedy's construction is undefined: its two lines (or two points) coincide."""


# -- raised by design.families
class Unsuitable(MechanismError):
    """The family cannot meet the specification; the message says why, with the numbers."""


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

