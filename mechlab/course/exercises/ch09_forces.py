"""Exercises of notebook 09_forces (kinetostatics, balancing torque, efficiency, drive)."""

import numpy as np

from ...kinetostatics.model import Force, Torque, model_for
from ...kinetostatics.drive import drive
from ...kinetostatics.machines import press
from ...kinetostatics.solve import solve
from ...mechanisms.fourbar import FourBar
from ...mechanisms.slider_crank import SliderCrank
from . import exercise


def _static_press_torque():
    sc = SliderCrank(0.1, 0.4)
    res = solve(model_for(sc), sc.motion(np.radians(240.0)), [Force("slider", "B", (-1000.0, 0.0))],
                omega1=0.0, gravity=(0.0, 0.0))
    return float(res.torque[0])


exercise(
    "09.1",
    "Massless SliderCrank(crank=0.1 m, rod=0.4 m), a force of 1000 N resisting the slider (pointing along −x), "
    "at rest at φ = 240° (the slider moving towards +x): the balancing torque on the crank, in N·m.",
    _static_press_torque, rtol=1e-4, unit="N·m",
    hint="Virtual work: M_b·δφ = P·δs, so M_b = P·s′ — read s′ from motion(phi).ds.",
)


def _rocker_reaction():
    fb = FourBar(0.1, 0.3, 0.3, 0.35)
    res = solve(model_for(fb), fb.motion(np.radians(90.0)), [Torque("rocker", -40.0)], gravity=(0.0, 0.0))
    return float(res.reactions["B"].magnitude[0])


exercise(
    "09.2",
    "Massless FourBar(0.1, 0.3, 0.3, 0.35) m with a torque of 40 N·m on the rocker, at φ = 90°: the magnitude "
    "of the reaction in the joint B, in N.",
    _rocker_reaction, rtol=1e-4, unit="N",
    hint="The coupler is a two-force member: its force F along AB has the arm l_BE·sin μ about E.",
)


def _press_mean_power():
    k = press(P=3000.0, work_fraction=0.25, m_crank=0.0, m_rod=0.0, m_slider=0.0, rpm=90.0)
    res = k.forces(k.turn(7201))
    return drive(res.torque, res.phi, k.omega1).mean_power


exercise(
    "09.3",
    "The chapter's press with massless links, P = 3000 N over the last 25 % of the 0.2 m stroke, at 90 rpm: "
    "the mean driving power, in W.",
    _press_mean_power, rtol=5e-3, unit="W",
    hint="Work per turn = P × working distance; mean power = that × turns per second.",
)


def _press_cycle_efficiency():
    k = press(f=0.1, radius=0.01)
    return k.forces(k.turn(721)).cycle_efficiency(how="work")


exercise(
    "09.4",
    "The chapter's press (defaults) with f = 0.1 in every pair and journal radius 10 mm: the cycle efficiency as "
    "the energy ratio 1 − A_friction/A_drive over one turn (721 samples).",
    _press_cycle_efficiency, rtol=1e-3,
    hint="press(f=0.1, radius=0.01).forces(phi).cycle_efficiency(how='work').",
)
