"""Choosing a dwell mechanism for a machine: one specification, every family synthesised and compared.

:class:`Specification` states the machine's motion programme, load and limits;
:func:`candidates` synthesises every family that can meet it (through the course's own
synthesis), simulates each design and compares them on the same criteria
(:class:`~mechlab.design.criteria.Criteria`); the families that cannot are refused with the reason.
"""

import warnings

from .candidates import Candidate, Comparison, DesignReport, Refusal, Verdict, candidates, check_design
from .criteria import Counts, Criteria, evaluate
from .families import FAMILIES, Design, Unsuitable
from .spec import Specification, SpecificationError

__all__ = ["Specification", "SpecificationError", "candidates", "Comparison", "Candidate", "Refusal", "check_design",
           "DesignReport", "Verdict", "Criteria",
           "Counts", "evaluate", "FAMILIES", "Design", "Unsuitable"]


def __getattr__(name):
    # the counts' old name, kept for a release: one Structure (mechlab.mechanisms.base) describes a mechanism
    if name == "Structure":
        warnings.warn("mechlab.design.Structure is now mechlab.design.Counts (the parts and pairs counted from a "
                      "mechanism's structure()); the old name goes in the next release", DeprecationWarning, stacklevel=2)
        return Counts
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
