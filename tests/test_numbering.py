"""One numbering of the links: for every family the drawing numbers its links as the instantaneous centres do
(the same numbers, each once, the frame's alike), and the design layer's counts of parts and pairs come from
the structure (with the rollers and locking arcs the kinematic structure leaves out)."""

import matplotlib.pyplot as plt
import numpy as np
import pytest
from examples import designs

import mechlab as ml
from mechlab.design import FAMILIES, Specification
from mechlab.design.criteria import counted
from mechlab.draw import draw
from mechlab.mechanisms.sixbar_iv import example as sixbar_example

DEG = np.pi / 180


def families():
    lift = ml.CamProgramme(10.0, 100 * DEG, 100 * DEG, 40 * DEG)
    swing = ml.CamProgramme(20 * DEG, 100 * DEG, 100 * DEG)
    return [ml.FourBar(1, 3, 3, 4), ml.SliderCrank(1, 3, 0.2), ml.SlottedLink(0.5, 1.0), ml.SineMechanism(1.0),
            ml.CurvedSlotLink(1.0, 4.0, ml.CircleSlot((3.0, 0.0), 3.0), start=1.0),
            ml.TranslatingCurvedSlot(1.0, ml.CircleSlot((0.0, 0.2), 3.0)), sixbar_example(),
            ml.EllipticTrammel(1.0, 1.2), ml.Antiparallelogram(1.0, 2.0), ml.LambdaMechanism(0.4, 0.8, np.pi),
            *designs(), ml.ExternalGeneva(4, 1.0), ml.InternalGeneva(6, 1.0),
            ml.TranslatingRollerCam(lift, 40.0, 8.0, offset=2.0),
            ml.OscillatingRollerCam(swing, 40.0, 8.0, float(np.hypot(100.0, 48.0)), 100.0),
            ml.curved_slot_dwell(0.5, 60 * DEG, 150 * DEG),
            ml.Linkage({"O": (0, 0), "P": (0, -2), "G": (0, 2.2)}, ml.Crank("O", "A", 1.0))
            .rpr("A", "P", 4.0).point("C", "PA", (4.0, 0.0)).rrp("C", "D", 1.5, "G")]


@pytest.mark.parametrize("mech", families(), ids=lambda m: type(m.values[0] if hasattr(m, "values") else m).__name__)
def test_drawing_and_centres_number_the_links_alike(mech):
    phi = float(mech.cycle(7)[2]) + 0.01
    d = draw(mech, phi)
    shown = [t.get_text() for t in d.numbers if t.get_visible()]
    links = ml.instant_centres(mech, [phi]).structure.links
    assert sorted(shown, key=int) == [str(k) for k in range(1, len(links) + 1)], (shown, links)   # each once
    assert (d.sketch.frame_number or shown[-1]) == str(links.index("frame") + 1)
    plt.close("all")


def test_design_counts_come_from_the_structure():
    specs = [Specification("index", 0.75, stations=4, inertia=1.0),
             Specification("swing", 50 / 360, amplitude=40 * DEG, max_pressure_angle=60 * DEG),
             Specification("stroke", 1 / 3, amplitude=120.0, mass=6.0, max_size=2000.0),
             Specification("index", 0.5, stations=2, inertia=1.0)]
    seen = {}
    for name, family in FAMILIES.items():
        for spec in specs:
            try:
                seen[name] = family(spec).structure
                break
            except ml.MechanismError:
                continue
    # the counts the families carried by hand before, now counted from their structures
    expected = {"external Geneva": (2, 2, 2), "internal Geneva": (2, 2, 2), "curved slot": (3, 3, 1),
                "disc cam": (3, 3, 1), "lambda six-bar, type 1 (rocker dwell)": (5, 7, 0),
                "lambda six-bar, type 2 (slider dwell)": (5, 7, 0), "lambda six-bar, type 3 (half-turn index)": (5, 7, 0),
                "lambda six-bar, type 5 (translating-slot dwell)": (5, 7, 0)}
    for name, counts in expected.items():
        if name in seen:
            assert (seen[name].parts, seen[name].lower_pairs, seen[name].higher_pairs) == counts, name
    assert {"lambda six-bar, type 1 (rocker dwell)", "external Geneva", "disc cam"} <= set(seen)
    # a six-bar: W = 3·5 - 2·7 = 1 (Chebyshev-Grübler)
    for six in designs():
        c = counted(six)
        assert 3 * c.parts - 2 * c.lower_pairs - c.higher_pairs == 1
