"""Exercises of notebook 01_equivalence (seed 000 §1)."""

import numpy as np

from ...analysis.equivalence import equivalent_slot, relative_path
from ...mechanisms.fourbar import FourBar
from ...mechanisms.sixbar_iv import example
from . import exercise


def _slot_of_seed_example():
    slot = equivalent_slot(FourBar(0.3, 0.8, 1.0, 1.0, 1)).slot_mechanism.slot
    return [slot.radius, float(np.hypot(*slot.center))]


exercise(
    "01.1",
    "FourBar(crank=0.3, coupler=0.8, rocker=1, ground=1) (the example of Zinchenko et al., 2013) moves like a "
    "slotted link with a circular slot. Give [radius of the slot, distance of its centre from the link's pivot].",
    _slot_of_seed_example,
    hint="Fix the rocker: A can only move on a circle about B. Which link is its radius, which the distance E-B?",
)

exercise(
    "01.2",
    "ψ′ of FourBar(0.3, 0.8, 1, 1, +1) at φ = 0 (A on the segment O-E, nearest to E), without solving the "
    "four-bar: at that instant the pin is at rest on the slot, so the link moves like the base mechanism.",
    lambda: float(FourBar(0.3, 0.8, 1.0, 1.0, 1).motion(0.0).dpsi),
    rtol=1e-6,
    hint="Formula (19) with λ = l_OA/l_OE, at the paper's φ = π: λ/(λ - 1).",
)


def _distance_range():
    six = example()
    r = np.hypot(*relative_path(six, six.turn(3601)).p.T)
    return [float(r.min()), float(r.max())]


exercise(
    "01.3",
    "The class-IV six-bar mechlab.mechanisms.sixbar_iv.example() has crank 0.25 and ground 1.04. Over a turn, between which "
    "distances from the output pivot E does the pin A run along its slot (the inner coupler curve)? "
    "Give [smallest, largest].",
    _distance_range,
    rtol=1e-4,
    hint="|A - E| is the same in every frame fixed to E: the triangle O-A-E.",
)
