"""Exceptions raised by mechlab.

Every error is a :class:`MechanismError`, itself a :class:`ValueError`, so callers
(and widgets) can catch one type and show its message: the message names the
violated condition and shows the numbers.
"""


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


class StructureError(MechanismError):
    """A mechanism's links, pairs and groups do not make a well-formed structure (statically solvable groups,
    joints defined once, one degree of freedom)."""


class JointError(StructureError):
    """A joint is defined twice, or a group attaches to a joint (or a link) not defined before it."""


class MobilityError(StructureError):
    """The structure's mobility W = 3n - 2p₅ - p₄ is not 1: it is not driven by exactly one crank."""

