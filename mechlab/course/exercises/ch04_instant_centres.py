"""Exercises of notebook 04_instant_centres (seed 002, §7.1-7.2)."""

import numpy as np

from ...mechanisms.antiparallelogram import Antiparallelogram
from ...mechanisms.trammel import EllipticTrammel
from ...analysis.centres.instant import instant_centres
from ...analysis.centres import centrodes
from ...mechanisms.fourbar import FourBar
from . import exercise


def _p13_x():
    ic = instant_centres(FourBar(1.0, 3.0, 3.0, 4.0), np.radians([60.0]))
    return float(ic("crank", "rocker").xy[0, 0])


def _moving_radius():
    m = EllipticTrammel(100.0, np.radians(60.0))
    pts = centrodes(m, "rod", phi=m.turn(721)[:-1]).moving.xy
    return float(np.hypot(*(pts[:, None] - pts[None]).reshape(-1, 2).T).max() / 2)   # half the diameter


def _antiparallelogram_ratio():
    ic = instant_centres(Antiparallelogram(1.0, 2.0), np.radians([90.0]))
    return float(ic.output_analog()[0])


exercise(
    "04.1",
    "FourBar(crank=1, coupler=3, rocker=3, ground=4) at φ = 60°: the x coordinate of P13, the centre of the "
    "crank relative to the rocker (it lies on the frame line OE).",
    _p13_x, rtol=1e-4,
    hint="P13 lies on line P12P23 (the coupler AB) and on line P14P34 (the frame OE): intersect AB with y = 0.",
)

exercise(
    "04.2",
    "EllipticTrammel(rod=100 mm, β = 60°): the radius of the rod's moving centrode, in mm.",
    _moving_radius, rtol=1e-4, unit="mm",
    hint="O, A, B and the pole lie on one circle whose chord AB subtends β at O; the moving centrode is that circle.",
)

exercise(
    "04.3",
    "Antiparallelogram(crank=1, ground=2) (crossed, frame = the long link): the velocity analog ψ' of the "
    "rocker at φ = 90°, read from the centres P13, P14, P34.",
    _antiparallelogram_ratio, rtol=1e-6,
    hint="ψ' = ω3/ω1 = (P13 - P14)/(P13 - P34) along the frame line, with its sign: the cranks turn in opposite senses.",
)
