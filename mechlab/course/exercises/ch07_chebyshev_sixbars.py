"""Exercises of notebook 07_chebyshev_dwell_sixbars (seed 001, chapters 1-3)."""

import numpy as np

from ...synthesis.lambda_guiding import circle_guiding
from ...synthesis.lambda_sixbars import mchv1, time_ratio_far_angle
from ...analysis.motion_laws import law_invariants
from . import exercise

DEG = np.pi / 180

exercise(
    "07.1",
    "Crank angle φ_n, in degrees, from the end of a 120° dwell to the far extreme of the rocker for K = 1.25.",
    lambda: float(np.degrees(time_ratio_far_angle(1.25, 120 * DEG))),
    rtol=1e-9, unit="deg",
    hint="K = φ_n / (360° − 2α − φ_n).",
)

exercise(
    "07.2",
    "Rocker length b (units of l) of МЧВ1 on circle_guiding(150°, 0.9, 120°) for K = 1 and β_m = 20°.",
    lambda: mchv1(circle_guiding(150 * DEG, 0.9, 120 * DEG), 1.0, 20 * DEG).rocker,
    rtol=1e-6,
    hint="b = S / (2 sin(β_m/2)) with S the chord from the arc centre Q to the far position E1.",
)

exercise(
    "07.3",
    "Invariant D = max(y'·y'') of the cycloidal (sine-acceleration) cam law.",
    lambda: law_invariants("cycloidal (sine)").D,
    rtol=1e-6,
    hint="y' = 1 − cos 2πx, y'' = 2π sin 2πx; set the derivative of the product to zero.",
)
