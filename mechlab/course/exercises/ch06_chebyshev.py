"""Exercises of notebook 06_chebyshev_dwell_synthesis (seed 001, chapter 1)."""

import numpy as np

from ...mechanisms.lambda_mechanism import LambdaMechanism
from ...synthesis.lambda_guiding import circle_guiding, straight_guiding
from . import exercise

DEG = np.pi / 180

exercise(
    "06.1",
    "Angle, in degrees, between the symmetry axis of the coupler curve (ray C→D0) and the ray C→O "
    "of LambdaMechanism(r=0.3, a=0.9, δ=140°).",
    lambda: float(np.degrees(np.arccos(-LambdaMechanism(0.3, 0.9, 140 * DEG).axis[0]))),
    rtol=1e-6, unit="deg",
    hint="B is the centre of the circle through A, C and D, so ∠ACD is an inscribed angle.",
)

exercise(
    "06.2",
    "Crank r (in units of l) of the circle-guiding lambda mechanism with δ = 150°, a = 0.9 and a dwell 2α = 120°.",
    lambda: circle_guiding(150 * DEG, 0.9, 120 * DEG).r,
    rtol=1e-4,
    hint="mechlab.synthesis.circle_guiding(delta, a, dwell) — angles in radians.",
)

exercise(
    "06.3",
    "Half-width E of the straight-line band of Chebyshev's lambda (δ = 180°, a = 0.8) over 2α = 180°, in units of l.",
    lambda: straight_guiding(np.pi, 0.8, np.pi).E,
    rtol=1e-3,
    hint="x(t) = (D − C)·e equals 1.6 at t = 0 and t = ±90°; E is half of its excursion in between.",
)
