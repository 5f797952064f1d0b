"""Choosing a dwell mechanism for a machine: one specification, every family synthesised and compared.

:class:`Specification` states the machine's motion programme, load and limits;
:func:`candidates` synthesises every family that can meet it (through the course's own
synthesis), simulates each design and compares them on the same criteria
(:class:`~mechlab.design.criteria.Criteria`); the families that cannot are refused with the reason.
"""

from .candidates import Candidate, Comparison, DesignReport, Refusal, Verdict, candidates, check_design
from .criteria import Criteria, Structure, evaluate
from .families import FAMILIES, Design, Unsuitable
from .spec import Specification, SpecificationError

__all__ = ["Specification", "SpecificationError", "candidates", "Comparison", "Candidate", "Refusal", "check_design",
           "DesignReport", "Verdict", "Criteria",
           "Structure", "evaluate", "FAMILIES", "Design", "Unsuitable"]
