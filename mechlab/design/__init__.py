"""Choosing a dwell mechanism for a machine: one specification, every family synthesised and compared.

:class:`Specification` states the machine's motion programme, load and limits;
:func:`candidates` synthesises every family that can meet it (through the course's own
synthesis), simulates each design and compares them on the same criteria
(:class:`~mechlab.design.criteria.Criteria`); the families that cannot are refused with the reason.
"""

from ..errors import renamed
from .candidates import Candidate, Comparison, LimitVerdict, Refusal, SpecificationReport, candidates, check_design
from .criteria import Counts, Criteria, evaluate
from .families import FAMILIES, Design, Unsuitable
from .spec import Specification, SpecificationError

__all__ = [
    "FAMILIES",
    "Candidate",
    "Comparison",
    "Counts",
    "Criteria",
    "Design",
    "LimitVerdict",
    "Refusal",
    "Specification",
    "SpecificationError",
    "SpecificationReport",
    "Unsuitable",
    "candidates",
    "check_design",
    "evaluate",
]


# old names kept for a release: one Structure (mechlab.mechanisms.base) describes a mechanism, and the exercises'
# Verdict and DesignReport are the course's
__getattr__ = renamed(__name__, Structure=(Counts, "mechlab.design.Counts (the parts and pairs counted from a "
                                                     "mechanism's structure())"),
                      Verdict=(LimitVerdict, "mechlab.design.LimitVerdict"),
                      DesignReport=(SpecificationReport, "mechlab.design.SpecificationReport"))
