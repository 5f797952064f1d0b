"""Example designs shared by the test modules (built once per session: each costs a Chebyshev solve), and every
mechanism family found with its example."""

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


def _cams():
    """A translating and an oscillating roller cam (mm, rad): their law is a CamProgramme of the synthesis layer,
    above the mechanisms, so the classes cannot build an example() of their own; built here instead."""
    lift = ml.CamProgramme(10.0, 100 * DEG, 100 * DEG, 40 * DEG)
    swing = ml.CamProgramme(20 * DEG, 100 * DEG, 100 * DEG)
    return {ml.TranslatingRollerCam: lambda: ml.TranslatingRollerCam(lift, 40.0, 8.0, offset=2.0, samples=720),
            ml.OscillatingRollerCam: lambda: ml.OscillatingRollerCam(swing, 40.0, 8.0, float(np.hypot(100.0, 48.0)),
                                                                     100.0, samples=720)}


# families whose example needs a higher layer than their class's (named, with the reason, in _cams)
EXAMPLES_ABOVE = _cams()


def families() -> tuple:
    """Every mechanism family, found at call time (``Mechanism.families()``: mechlab's and any a test module
    defines), and the families of EXAMPLES_ABOVE."""
    return (*ml.Mechanism.families(), *(c for c in EXAMPLES_ABOVE if c not in ml.Mechanism.families()))


def example_of(cls):
    """A valid instance of the family ``cls``: its ``example()``, or the one built here (EXAMPLES_ABOVE)."""
    return EXAMPLES_ABOVE[cls]() if cls in EXAMPLES_ABOVE else cls.example()
