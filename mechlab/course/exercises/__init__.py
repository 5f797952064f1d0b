"""Feedback for the course's exercises (the exercises themselves are nbgrader assignments in ``assignments/``).

:func:`check` compares a number with an expected value the grader passes in (textbook tolerance,
"give more digits", unit and sign slips named); :func:`check_choice` checks a prediction;
the checkers of :mod:`.design` (and :mod:`.coupler`, the dwell six-bar from a coupler curve) run a student's design
or function through mechlab and report every specification with its numbers. This package stores no answer.
"""

from ...errors import renamed
from .coupler import dwell_sixbar_design
from .design import (
                     DesignReport,
                     Requirement,
                     cam_design,
                     dwell_slot_design,
                     fourbar_design,
                     function_check,
                     geneva_design,
                     guide_design,
                     output_design,
                     press_design,
                     sixbar_design,
)
from .feedback import NotYet, Verdict, check, check_choice, check_form, recording, self_check, tolerance

__all__ = [
                     "DesignReport",
                     "NotYet",
                     "Requirement",
                     "Verdict",
                     "cam_design",
                     "check",
                     "check_choice",
                     "check_form",
                     "dwell_sixbar_design",
                     "dwell_slot_design",
                     "fourbar_design",
                     "function_check",
                     "geneva_design",
                     "guide_design",
                     "output_design",
                     "press_design",
                     "recording",
                     "self_check",
                     "sixbar_design",
                     "tolerance",
]

# the old name (validate.Spec is what a parameter may be)
__getattr__ = renamed(__name__, Spec=(Requirement, "mechlab.course.exercises.Requirement"))
