"""Example designs shared by the test modules (built once per session: each costs a Chebyshev solve)."""

import functools

import numpy as np

import mechlab as ml

DEG = np.pi / 180


@functools.cache
def guides():
    """A circle-guiding (δ = 150°, a = 0.9, dwell 120°) and a straight-guiding (δ = 180°, a = 0.8) lambda mechanism."""
    return ml.circle_guiding(150 * DEG, 0.9, 120 * DEG), ml.straight_guiding(np.pi, 0.8, np.pi)


@functools.cache
def designs():
    """The four lambda six-bars built on guides(): МЧВ1, МЧВ2, МЧВ3 (full turn) and МЧВ5."""
    circle, straight = guides()
    return (ml.mchv1(circle, 1.0, 20 * DEG), ml.mchv2(circle, 1.0), ml.mchv3_full_turn(straight),
            ml.mchv5(straight))
