"""Exercises of notebook 00_getting_started."""

import numpy as np

from ...mechanisms.fourbar import FourBar
from . import exercise

exercise(
    "00.1",
    "Minimum transmission angle, in degrees, of FourBar(crank=1.5, coupler=3.5, rocker=3, ground=4).",
    lambda: float(np.degrees(FourBar(1.5, 3.5, 3.0, 4.0).motion(np.linspace(0, 2 * np.pi, 100001)).transmission.min())),
    rtol=1e-3, unit="deg",
    hint="μ is smallest when |AE| is smallest (φ = 0): use the law of cosines in triangle A-B-E.",
)

exercise(
    "00.2",
    "Grashof kind (crank-rocker, double-crank, rocker-crank, double-rocker, change-point or triple-rocker) "
    "of FourBar(crank=2, coupler=4, rocker=3, ground=1).",
    lambda: FourBar(2.0, 4.0, 3.0, 1.0).grashof().kind,
    hint="Find the shortest link, then compare s + l with p + q.",
)

exercise(
    "00.3",
    "Angular velocity of the rocker, in rad/s, of FourBar(1, 3, 3, 4) at φ = 90° when the crank turns at 10 rad/s.",
    lambda: float(FourBar(1.0, 3.0, 3.0, 4.0).motion(np.pi / 2).velocity(10.0)),
    rtol=1e-4, unit="rad/s",
    hint="ω2 = ψ'·ω1: read ψ' from motion(phi).dpsi.",
)
