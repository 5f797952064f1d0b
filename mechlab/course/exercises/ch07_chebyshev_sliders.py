"""Exercises of notebook 07_chebyshev_dwell_sixbars, section on МЧВ2 and МЧВ5 (seed 001, Fig. 1 в, д)."""

import numpy as np

from ...synthesis.lambda_guiding import circle_guiding, straight_guiding
from ...synthesis.lambda_sliders import mchv2, mchv5, slider_report
from . import exercise

DEG = np.pi / 180


def _mchv2_stroke_k1() -> float:
    # the slider's far position at φ = 0 (K = 1: the far extreme is opposite the dwell centre)
    g = circle_guiding(150 * DEG, 0.9, 120 * DEG)
    return float(mchv2(g, 1.0).motion(np.array([0.0])).s[0])


exercise(
    "07.4",
    "Stroke h = |QE1| (units of l) of МЧВ2 on circle_guiding(150°, 0.9, 120°) with K = 1.",
    _mchv2_stroke_k1,
    rtol=1e-6,
    hint="K = 1 puts the guide on the symmetry axis; at φ = 0 D is on the axis at |QD| = ρ, and h = R − ρ.",
)

exercise(
    "07.5",
    "МЧВ5 on Chebyshev's lambda (straight_guiding(180°, 0.8, 180°)): the angle γ, in degrees, between the "
    "output's guide and the slot normal that gives the stroke h = 0.5.",
    lambda: float(np.degrees(np.arccos(slider_report(mchv5(straight_guiding(np.pi, 0.8, np.pi))).stroke / 0.5))),
    rtol=1e-6, unit="deg",
    hint="s = (x − Y)/cos γ: the stroke is h0/cos γ, h0 the range of D's axis coordinate x over a turn.",
)
