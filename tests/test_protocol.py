"""One extension protocol: a mechanism describes its links, pairs and groups once (``structure()``);
the instantaneous centres, the kinetostatics and the drawing derive from that description, so a new
family needs no registration. Checked on the cams and on a family written here, in the test."""

from dataclasses import dataclass

import matplotlib.pyplot as plt
import numpy as np
import pytest

import mechlab as ml
from mechlab.analysis.centres import instant_centres
from mechlab.draw import LinkageDrawing, animate, draw, drawing_class
from mechlab.geometry import AnglePath, PointPath, as_angles, crank_point, fixed_point
from mechlab.kinetostatics.model import Force, Torque, model_for
from mechlab.kinetostatics.solve import solve
from mechlab.mechanisms.base import FRAME, Link, Mechanism, Pair, Structure
from mechlab.motion import LinearMotion

DEG = np.pi / 180


@dataclass(frozen=True)
class SkewYoke(Mechanism):
    """A Scotch yoke whose slot leans at γ to the guide (x axis): the pin A = r(cos φ, sin φ) lies on the
    slot through K = (s, 0), so s = r(cos φ − sin φ / tan γ). Nothing in mechlab knows this class."""

    crank: float
    gamma: float = 45 * DEG

    output = "position"

    def motion(self, phi):
        phi = as_angles(phi)
        A = crank_point(self.crank, phi)
        law = AnglePath(*(a[:, 0] - a[:, 1] / np.tan(self.gamma) for a in A))
        K = PointPath(*(np.stack([x, 0 * x], -1) for x in law))
        return LinearMotion(phi, {"O": fixed_point((0, 0), len(phi)), "A": A, "K": K}, np.full(len(phi), 1.0),
                            *law)

    def structure(self):
        return Structure(
            (Link("crank", "O", ("O", "A"), self.crank, joints=("O", "A")), Link("block", "A", self.gamma, block=True),
             Link("yoke", "K", 0.0)),
            (Pair("revolute", "O", FRAME, "crank", "O"), Pair("revolute", "A", "crank", "block", "A"),
             Pair("prismatic", "slot", "yoke", "block", "A", self.gamma),
             Pair("prismatic", "guide", FRAME, "yoke", "K", 0.0)),
            (("block", "yoke"),), "yoke", scale=self.crank)


def cams():
    pr = ml.CamProgramme(20.0, 120 * DEG, 100 * DEG, 40 * DEG, law="3-4-5 polynomial")
    swing = ml.CamProgramme(20 * DEG, 120 * DEG, 100 * DEG, 40 * DEG, law="cycloidal (sine)")
    return [ml.TranslatingRollerCam(pr, 40.0, 10.0, offset=8.0),
            ml.OscillatingRollerCam(swing, 40.0, 8.0, pivot_distance=90.0, arm=70.0)]


@pytest.mark.parametrize("mech", [*cams(), SkewYoke(0.3), SkewYoke(0.3, 120 * DEG)], ids=lambda m: type(m).__name__)
def test_centres_of_a_new_family_come_from_its_structure(mech):
    phi = np.linspace(0.05, 2 * np.pi - 0.05, 181)
    mo = mech.motion(phi)
    law_d = mo.ds if mech.output == "position" else mo.dpsi
    kennedy, twists = instant_centres(mech, phi), instant_centres(mech, phi, method="velocity")
    # the output's velocity analog read from the centres alone equals the motion's
    assert np.allclose(kennedy.output_analog(), law_d, atol=1e-8 * np.max(np.abs(law_d)))
    assert kennedy.collinearity() < 1e-9
    for a, b in ((1, 2), (1, 3), (2, 3)):
        pa, pb = kennedy(a, b), twists(a, b)
        both = pa.finite & pb.finite
        assert np.array_equal(pa.finite, pb.finite) or np.all(np.abs(law_d[pa.finite != pb.finite]) < 1e-9)
        xa, xb = (c.h[both, :2] / c.h[both, 2:] for c in (pa, pb))
        assert np.allclose(xa, xb, atol=1e-7 * mech.structure().scale)


def test_cam_centre_lies_on_the_contact_normal_and_the_line_of_the_pivots():
    cam = cams()[1]
    phi = np.linspace(0.1, 6.2, 90)
    ic = instant_centres(cam, phi)
    P = ic("cam", "follower")
    assert np.all(P.finite) and np.abs(P.xy[:, 1]).max() < 1e-9             # on OB (the x axis)
    C, K = ic.motion.points["C"].p, ic.motion.points["K"].p
    n, w = C - K, P.xy - K
    assert np.abs(n[:, 0] * w[:, 1] - n[:, 1] * w[:, 0]).max() < 1e-7 * cam.roller_radius * cam.pivot_distance


@pytest.mark.parametrize("mech", [*cams(), SkewYoke(0.3)], ids=lambda m: type(m).__name__)
def test_kinetostatics_of_a_new_family_from_its_structure(mech):
    # a load on the follower: the group-by-group torque equals the power balance, and with ω1 = 0
    # (statics) it is the virtual work of the load
    phi = np.linspace(0.05, 2 * np.pi - 0.05, 73)
    mo = mech.motion(phi)
    out = mech.structure().output
    load = [Torque(out, -30.0)] if mech.output == "angle" else [Force(out, _load_point(mech), _load(mech))]
    res = solve(model_for(mech), mo, load, omega1=0.0, gravity=(0.0, 0.0))
    res.verify()
    law_d = mo.ds if mech.output == "position" else mo.dpsi
    expected = 30.0 * law_d if mech.output == "angle" else -np.dot(_load(mech), _direction(mech)) * law_d
    assert np.allclose(res.torque, expected, atol=1e-9 * np.max(np.abs(expected)))
    moving = solve(model_for(mech).with_body(out, mass=2.0, inertia=0.01), mo, load, omega1=12.0)
    moving.verify()


def _load_point(mech):
    return "C" if isinstance(mech, ml.TranslatingRollerCam) else "K"


def _load(mech):
    return (0.0, -150.0) if isinstance(mech, ml.TranslatingRollerCam) else (-80.0, 0.0)


def _direction(mech):
    return (0.0, 1.0) if isinstance(mech, ml.TranslatingRollerCam) else (1.0, 0.0)


def test_a_mechanism_without_structure_is_named():
    class Bare(Mechanism):
        def motion(self, phi):
            return ml.FourBar(1, 3, 3, 4).motion(phi)

    with pytest.raises(ml.MechanismError, match="Bare describes no structure"):
        instant_centres(Bare(), [0.1, 0.2])
    with pytest.raises(TypeError, match="no force model for object"):
        model_for(object())


def test_a_block_needs_a_pin_and_a_slide():
    class BadYoke(SkewYoke):
        def structure(self):
            st = super().structure()
            pairs = tuple(p if p.name != "slot" else Pair("revolute", "slot", "yoke", "block", "A")
                          for p in st.pairs)
            return Structure(st.links, pairs, st.groups, st.output, st.scale)

    with pytest.raises(ml.MechanismError, match="block block must carry one revolute and one prismatic pair, "
                                                "not revolute, revolute"):
        instant_centres(BadYoke(0.3), [0.1, 0.2])


@pytest.mark.parametrize("gamma", [45 * DEG, 120 * DEG])
def test_a_new_family_draws_and_animates_from_its_structure(gamma):
    # the yoke is drawn from the structure's pairs: its slot through the pin at γ to the guide, its rod
    # along the guide from K; numbered after the crank, the frame last
    mech = SkewYoke(0.3, gamma)
    anim = animate(mech, n=8)
    d = anim.drawing
    assert drawing_class(mech) is LinkageDrawing and isinstance(d, LinkageDrawing)
    slot_dir = np.array([np.cos(gamma), np.sin(gamma)])
    for i in range(8):
        anim._func(i)
        yoke = np.column_stack(d.extra_lines[0].get_data())
        A, K = d.motion.points["A"].p[i], d.motion.points["K"].p[i]
        along = yoke[1] - yoke[0]
        assert abs(along[0] * slot_dir[1] - along[1] * slot_dir[0]) < 1e-12   # the slot at γ
        w = A - yoke[0]
        assert abs(along[0] * w[1] - along[1] * w[0]) < 1e-12 * np.hypot(*along)   # through the pin
        assert np.allclose(yoke[2], K) and abs(yoke[3, 1] - K[1]) < 1e-15   # the rod along the guide
        assert np.allclose(d.letters["K"].xy, K)
    assert [t.get_text() for t in d.numbers if t.get_visible()] == ["1", "2", "3"]
    assert "mechlab-play" in anim.to_jshtml()
    plt.close("all")


def test_a_family_without_structure_is_not_drawn_and_says_why():
    # the drawing is read from structure() alone: a family that describes none is told to
    class Bars(Mechanism):
        pivots = ("O", "E")

        def motion(self, phi):
            return ml.FourBar(1, 3, 3, 4).motion(phi)

    with pytest.raises(ml.MechanismError, match="Bars describes no structure: define its structure"):
        draw(Bars(), 0.5)
    plt.close("all")


def test_one_drawing_goes_from_family_to_family_restyling_its_lines():
    fig, ax = plt.subplots()
    d = LinkageDrawing(ax, cams()[0], n=12)   # a profile, its fill, a roller, a stem, a "dwell" note
    d.set_mechanism(SkewYoke(0.3))
    children = len(ax.get_children())   # the yoke's letter K and its numbers added
    assert [line.get_visible() for line in d.extra_lines][1:] == [False] * (len(d.extra_lines) - 1)
    assert d.extra_lines[0].get_color() == "#2a7f62" and d.extra_lines[0].get_linewidth() == 2.5   # the yoke
    assert not d.fills[0].get_visible() and not d.note.get_visible()
    d.set_mechanism(cams()[0])
    assert [line.get_color() for line in d.lines_of("roller")] == ["#1f4e79"] and d.fills[0].get_visible()
    d.set_mechanism(SkewYoke(0.3))
    assert len(ax.get_children()) == children   # nothing made twice
    plt.close(fig)
