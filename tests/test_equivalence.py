"""Kinematic equivalence (seed 000 §1): relative paths, curved-slot twins, base law, assembly symmetry."""

import numpy as np
import pytest
from hypothesis import given, settings
from strategies import revolving_fourbars, revolving_slider_cranks
from test_protocol import SkewYoke

import mechlab as ml
from mechlab import DimensionError, FourBar, SineMechanism, SliderCrank, SlottedLink
from mechlab.analysis.equivalence import (
    EquivalentSlot,
    assembly_symmetry,
    base_law,
    base_mechanism,
    equivalence_error,
    equivalent_slot,
    law_difference,
    other_assembly,
    relative_path,
)
from mechlab.analysis.half_turn import formula_18
from mechlab.geometry import PointPath, as_angles, crank_point, fixed_point, relative, vector_angle
from mechlab.mechanisms.base import FRAME, Link, Mechanism, Pair, Structure
from mechlab.mechanisms.sixbar_iv import example
from mechlab.motion import AngularMotion

H = 1e-5


@given(revolving_fourbars())
@settings(max_examples=150, deadline=None)
def test_fourbar_twin_reproduces_the_law(fb):
    phi = fb.turn(241)
    twin = equivalent_slot(fb)
    errs = law_difference(fb.motion(phi), twin.motion(phi))
    scale = 1 + np.max(np.abs(fb.motion(phi).ddpsi))
    assert errs[0] < 1e-9 and errs[1] < 1e-9 * scale and errs[2] < 1e-9 * scale
    # the twin's pivot is the four-bar's E and its pin is the same point
    tm = twin.motion(phi)
    assert np.allclose(tm.points["E"].p, [fb.ground, 0.0], atol=1e-15)
    assert np.allclose(tm.points["A"].p, fb.motion(phi).points["A"].p, rtol=0, atol=1e-14 * (1 + fb.crank))


@given(revolving_slider_cranks())
@settings(max_examples=150, deadline=None)
def test_slider_crank_twin_reproduces_the_law(sc):
    assert equivalence_error(sc, sc.turn(241)) < 1e-9 * (1 + sc.rod)


@given(revolving_fourbars())
@settings(max_examples=100, deadline=None)
def test_fourbar_relative_path_is_the_circle_about_B(fb):
    phi = fb.turn(181)
    rel = relative_path(fb, phi)
    assert np.max(np.abs(np.hypot(rel.p[:, 0] - fb.rocker, rel.p[:, 1]) - fb.coupler)) < 1e-12 * (1 + fb.coupler)
    # each assembly keeps to one arc of the circle (α1–α1 or α2–α2): y never changes sign
    assert np.all(np.sign(rel.p[:, 1]) == fb.assembly)
    up, dn = relative_path(fb, phi + H), relative_path(fb, phi - H)
    s = 1 + np.max(np.abs(rel.dd))
    assert np.max(np.abs((up.p - dn.p) / (2 * H) - rel.d)) < 1e-6 * s
    assert np.max(np.abs((up.d - dn.d) / (2 * H) - rel.dd)) < 1e-6 * s


def test_branch_sign_of_each_assembly():
    """Which arc each assembly uses, on the seed's example l_OA = 0.3, l_AB = 0.8, l_BE = l_OE = 1."""
    phi = np.linspace(0, 2 * np.pi, 73)
    up = relative_path(FourBar(0.3, 0.8, 1.0, 1.0, 1), phi).p[:, 1]
    dn = relative_path(FourBar(0.3, 0.8, 1.0, 1.0, -1), phi).p[:, 1]
    assert np.all(up > 0) and np.all(dn < 0)


@given(revolving_slider_cranks())
@settings(max_examples=100, deadline=None)
def test_slider_crank_relative_path_is_the_circle_about_the_slider_pin(sc):
    phi = sc.turn(181)
    rel = relative_path(sc, phi)
    assert np.max(np.abs(np.hypot(rel.p[:, 0], rel.p[:, 1] - sc.offset) - sc.rod)) < 1e-12 * (1 + sc.rod)
    assert np.all(np.sign(rel.p[:, 0]) == -sc.assembly)   # the pin is behind the slider for +1


@given(revolving_fourbars())
@settings(max_examples=150, deadline=None)
def test_fourbar_assembly_symmetry(fb):
    sym = assembly_symmetry(fb, fb.turn(181))
    scale = 1 + np.max(np.abs(fb.motion(fb.turn(181)).ddpsi))
    assert sym.mirror < 1e-11 * scale and sym.mean_is_base < 1e-11 * scale and sym.branches < 1e-11 * (1 + fb.coupler)


@given(revolving_slider_cranks())
@settings(max_examples=150, deadline=None)
def test_slider_crank_assembly_symmetry(sc):
    assert assembly_symmetry(sc, sc.turn(181)).holds(1e-10 * (1 + sc.rod + abs(sc.offset)))


def test_symmetry_residuals_detect_a_wrong_relation():
    """The residuals are not vacuous: comparing an assembly with itself breaks them."""
    fb = FourBar(0.3, 0.8, 1.0, 1.0, 1)
    phi = fb.turn(91)
    p = fb.motion(phi)
    base = base_law(fb, phi)
    assert np.max(np.abs(p.dpsi + p.dpsi - 2 * base.d)) > 1e-2
    assert other_assembly(fb).assembly == -1


@given(revolving_fourbars())
@settings(max_examples=100, deadline=None)
def test_base_law_is_formula_18_in_the_fourbar_frame(fb):
    phi = fb.turn(181)
    k = base_law(fb, phi)
    f = formula_18(fb.crank / fb.ground, phi - np.pi)
    assert np.max(np.abs(np.angle(np.exp(1j * (k.theta - np.pi - f.theta))))) < 1e-12
    assert np.allclose(k.d, f.d, atol=1e-12) and np.allclose(k.dd, f.dd, atol=1e-11)
    # and it is the angle of A - E
    A = fb.motion(phi).points["A"].p
    assert np.allclose(np.angle(np.exp(1j * (np.arctan2(A[:, 1], A[:, 0] - fb.ground) - k.theta))), 0, atol=1e-12)


def test_base_mechanisms():
    assert base_mechanism(FourBar(1, 3, 3, 4)) == SlottedLink(1.0, 4.0)
    assert base_mechanism(SliderCrank(1, 3)) == SineMechanism(1.0)
    law = base_law(SliderCrank(1.5, 4.0, 0.5), np.array([0.3]))
    assert np.allclose([law.theta[0], law.d[0], law.dd[0]], [1.5 * np.cos(0.3), -1.5 * np.sin(0.3), -1.5 * np.cos(0.3)])


def test_unsupported_mechanisms_raise_clear_errors():
    with pytest.raises(DimensionError, match="assembly symmetry is stated for FourBar and SliderCrank"):
        other_assembly(SlottedLink(1.0, 2.0))


# -- the default twin, derived from structure() and the motion ----------------------------------------
class TiltedFourBar(Mechanism):
    """A four-bar whose frame pivot E lies at angle ``tilt`` from O (not on +x): the FourBar turned by
    ``tilt``; it defines no curved_slot_twin(). Nothing in mechlab knows this class."""

    def __init__(self, fourbar, tilt):
        self.fb, self.tilt = fourbar, tilt

    def motion(self, phi):
        phi = as_angles(phi)
        mo = self.fb.motion(phi - self.tilt)
        c, s = np.cos(self.tilt), np.sin(self.tilt)
        turn = np.array([[c, s], [-s, c]])   # row vectors turned by +tilt
        pts = {k: PointPath(*(x @ turn for x in v)) for k, v in mo.points.items()}
        return AngularMotion(phi, pts, mo.transmission, mo.psi + self.tilt, mo.dpsi, mo.ddpsi)

    def structure(self):
        return self.fb.structure()


def default_twin(mech):
    """The twin from Mechanism.curved_slot_twin (the default), even where the family overrides it."""
    return EquivalentSlot(mech, *Mechanism.curved_slot_twin(mech))


def assert_twin_moves_like(mech, n=361):
    phi = mech.cycle(n)
    mo = mech.motion(phi)
    errs = law_difference(mo, default_twin(mech).motion(phi))
    scale = 1 + np.max(np.abs(mo.output.dd))
    assert errs[0] < 1e-8 and errs[1] < 1e-8 * scale and errs[2] < 1e-8 * scale, errs


@given(revolving_fourbars())
@settings(max_examples=60, deadline=None)
def test_default_twin_of_any_revolving_fourbar(fb):
    assert_twin_moves_like(fb, 241)
    # its slot is the relative path: the circle of radius l_AB about B (the override's closed form)
    slot = default_twin(fb).slot_samples(50)
    assert np.max(np.abs(np.hypot(slot[:, 0] - fb.rocker, slot[:, 1]) - fb.coupler)) < 1e-9 * (1 + fb.coupler)


@given(revolving_slider_cranks())
@settings(max_examples=60, deadline=None)
def test_default_twin_of_any_revolving_slider_crank(sc):
    assert_twin_moves_like(sc, 241)


@pytest.mark.parametrize("mech", [FourBar(0.3, 0.8, 1.0, 1.0, 1), FourBar(0.3, 0.8, 1.0, 1.0, -1),
                                  FourBar(2.0, 1.5, 2.5, 0.6, 1), FourBar(2.0, 1.5, 2.5, 0.6, -1),
                                  SliderCrank(1.0, 3.0, 0.5, 1), SliderCrank(1.0, 3.0, -0.8, -1),
                                  example(), SlottedLink(0.5, 1.0), SlottedLink(1.5, 1.0),
                                  TiltedFourBar(FourBar(0.3, 0.8, 1.0, 1.0, -1), 2.0), SkewYoke(0.3, 1.0)],
                         ids=["crank-rocker+", "crank-rocker-", "double-crank+", "double-crank-", "offset-slider+",
                              "offset-slider-", "sixbar-IV", "slotted-rocking", "slotted-turning", "tilted-fourbar",
                              "skew-yoke"])
def test_default_twin_reproduces_the_law(mech):
    """ψ, ψ′, ψ″ (s, s′, s″) of the default twin equal the mechanism's over the crank's turn; the last
    two families are defined in the tests and override nothing."""
    assert_twin_moves_like(mech)


class CrankOnly(Mechanism):
    """A crank whose output is the crank itself."""

    def motion(self, phi):
        phi = as_angles(phi)
        A = crank_point(1.0, phi)
        return AngularMotion(phi, {"O": fixed_point((0, 0), len(phi)), "A": A}, np.ones(len(phi)), phi,
                             np.ones(len(phi)), np.zeros(len(phi)))

    def structure(self):
        return Structure((Link("crank", "O", ("O", "A"), 1.0),), (Pair("revolute", "O", FRAME, "crank", "O"),),
                         (), "crank", 1.0)


@pytest.mark.parametrize("mech, error, words", [
    (CrankOnly(), DimensionError, "output of CrankOnly is its crank"),
    (ml.TranslatingRollerCam(ml.CamProgramme(20.0, 2.0, 1.8, 0.7), 40.0, 10.0), DimensionError, "no pin"),
    (ml.ExternalGeneva(4, 1.0), DimensionError, "no pin"),
    (ml.EllipticTrammel(1.0, 2.0), DimensionError, "no crank turning about a frame pivot"),
    (ml.SphericalGeneva(40, 15, 4), ml.MechanismError, "spatial"),
    # two groups in series: the pin's path relative to the output is not one slot
    (ml.mchv1(ml.circle_guiding(150 * np.pi / 180, 0.9, 120 * np.pi / 180), 1.0, 20 * np.pi / 180),
     DimensionError, "not a function of the pin's distance"),
])
def test_no_twin_says_why(mech, error, words):
    with pytest.raises(error, match=words):
        equivalent_slot(mech)


def test_default_twin_needs_a_turning_crank():
    """A rocking crank keeps the four-bar's closed-form twin; the default says why it has none."""
    with pytest.raises(DimensionError, match="needs a crank that turns fully"):
        default_twin(FourBar(3, 3, 3, 4, 1))



class RockingSlot(Mechanism):
    """A crank O-P (radius a) whose pin P slides in the straight slot of a link pivoted at Q = (-d, 0): the
    slotted link with its joints named otherwise. Nothing in mechlab knows this class."""

    pivots = ("O", "Q")

    def __init__(self, a, d):
        self.a, self.d = a, d

    def motion(self, phi):
        phi = as_angles(phi)
        P, Q = crank_point(self.a, phi), fixed_point((-self.d, 0.0), len(phi))
        psi = vector_angle(relative(P, Q))
        return AngularMotion(phi, {"O": fixed_point((0, 0), len(phi)), "P": P, "Q": Q}, np.full(len(phi), np.pi / 2),
                             psi.theta, psi.d, psi.dd)

    def structure(self):
        return Structure(
            (Link("crank", "O", ("O", "P"), self.a, joints=("O", "P")), Link("block", "P", ("Q", "P"), block=True),
             Link("link", "Q", ("Q", "P"), self.a + self.d)),
            (Pair("revolute", "O", FRAME, "crank", "O"), Pair("revolute", "P", "crank", "block", "P"),
             Pair("prismatic", "slot", "link", "block", "P", 0.0), Pair("revolute", "Q", FRAME, "link", "Q")),
            (("block", "link"),), "link", scale=self.a + self.d)


@pytest.mark.parametrize("a, d", [(0.4, 1.0), (1.6, 1.0)], ids=["rocking", "turning"])
def test_relative_path_reads_the_pin_from_the_structure(a, d):
    """The pin P runs along the slot through Q, the link's x axis: seen from the link it is (S, 0) with
    S = |P - Q| = sqrt(a² + d² + 2ad cos φ), S' = -ad sin φ / S, S'' = -(ad cos φ + S'²) / S."""
    phi = np.linspace(0.05, 2 * np.pi - 0.05, 121)
    rel = relative_path(RockingSlot(a, d), phi)
    S = np.sqrt(a * a + d * d + 2 * a * d * np.cos(phi))
    dS = -a * d * np.sin(phi) / S
    ddS = -(a * d * np.cos(phi) + dS**2) / S
    for w, x in zip(rel, (S, dS, ddS), strict=False):
        assert np.allclose(w, np.stack([x, 0 * x], -1), rtol=0, atol=1e-12 * (a + d))


def test_relative_path_on_a_slanted_guide_is_seen_along_the_guide():
    """A slider on a guide at γ: the pin's displacement seen from the slider is its displacement relative to
    the slider's joint E turned by -γ (the slider's x axis runs along the guide)."""
    mech = ml.mchv5(ml.straight_guiding(np.pi, 0.8, np.pi), guide_angle=0.3)
    guide = mech.structure().frame_pair(mech.structure().output)
    assert guide.kind == "prismatic" and abs(guide.angle) > 0.3
    phi = mech.cycle(61)
    mo, w = mech.motion(phi), relative_path(mech, phi).p
    v = mo.points["A"].p - mo.points[guide.point].p
    c, s = np.cos(guide.angle), np.sin(guide.angle)
    turned = np.stack([c * v[:, 0] + s * v[:, 1], -s * v[:, 0] + c * v[:, 1]], -1)
    assert np.ptp(w - turned, axis=0).max() < 1e-12


@pytest.mark.parametrize("mech, words", [
    (ml.TranslatingRollerCam(ml.CamProgramme(20.0, 2.0, 1.8, 0.7), 40.0, 10.0), "carries no pin"),
    (ml.EllipticTrammel(1.0, 2.0), "no crank turning about a frame pivot"),
])
def test_relative_path_without_a_crank_pin_says_why(mech, words):
    with pytest.raises(DimensionError, match=words):
        relative_path(mech, [0.3, 0.4])

# -- drawings, animation, explorer, exercises and errata of chapters 02-04 -------------------------
import matplotlib.pyplot as plt  # noqa: E402

from mechlab.draw import drawing_class  # noqa: E402  this section's imports open it
from mechlab.draw.curved_slot import animate_equivalence, plot_against_base  # noqa: E402
from mechlab.mechanisms.curved_slot import CircleSlot, CurvedSlotLink, TranslatingCurvedSlot  # noqa: E402


def _slot_distance_to_pin(drawing, i):
    slot = np.stack(drawing.lines_of("slot")[0].get_data(), -1)
    pin = drawing.motion.points["A"].p[i]
    return np.min(np.hypot(*(slot - pin).T))


@pytest.mark.parametrize("mech", [CurvedSlotLink(0.4, 1.0, CircleSlot((1.0, 0.0), 0.9), start=1.0),
                                  TranslatingCurvedSlot(1.0, CircleSlot((0.0, 0.3), 2.0), start=np.pi),
                                  equivalent_slot(FourBar(0.3, 0.8, 1.0, 1.0, -1)),
                                  equivalent_slot(SliderCrank(1.0, 3.0, 0.5)), example()],
                         ids=["curved", "translating", "twin-fourbar", "twin-slider", "sixbar"])
def test_drawings_move_the_slot_with_the_link(mech):
    fig, ax = plt.subplots()
    d = drawing_class(mech)(ax, mech, trace="A", n=61)
    d.autoscale()
    ids = [id(a) for a in d.artists]
    for i in range(0, 61, 10):
        d.set_frame(i)
        if d.lines_of("slot"):
            # the slot drawn at frame i passes through the pin (to the polyline's resolution)
            assert _slot_distance_to_pin(d, i) < 0.02
    assert [id(a) for a in d.artists] == ids
    plt.close(fig)


def test_animate_equivalence_and_plot_against_base():
    anim = animate_equivalence(FourBar(0.3, 0.8, 1.0, 1.0), n=5)
    html = anim.to_jshtml()
    assert "data:image/png;base64" in html
    left, right = anim.drawings
    assert np.allclose(left.motion.points["A"].p, right.motion.points["A"].p, atol=1e-14)
    axes = plot_against_base(SliderCrank(1.0, 3.0, 0.5))
    base_line = axes[1].get_lines()[1].get_ydata()
    phi = SliderCrank(1.0, 3.0, 0.5).cycle(361)
    assert np.allclose(base_line, -np.sin(phi))     # x_K' = -l_OA sin φ
    plt.close("all")


def test_plot_assembly_arcs_draws_two_mirror_arcs_of_the_circle_about_B():
    from mechlab.draw.curved_slot import ARC_NAMES, plot_assembly_arcs

    fb = FourBar(0.6, 1.6, 2.0, 2.0, -1)    # in units of the frame OE = 2: the chapter's four-bar
    fig = plot_assembly_arcs(fb, n=181)
    ax = fig.axes[0]
    circle, plus, minus = (np.stack(line.get_data(), -1) for line in ax.lines[:3])
    assert [line.get_label() for line in ax.lines[1:3]] == list(ARC_NAMES.values())
    phi = fb.cycle(181)
    assert np.allclose(plus * 2.0, relative_path(FourBar(0.6, 1.6, 2.0, 2.0, 1), phi).p)
    assert np.allclose(minus[:, 0], plus[:, 0]) and np.allclose(minus[:, 1], -plus[:, 1])   # mirror images
    assert (plus[:, 1] > 0).all()
    B = np.array([1.0, 0.0])   # l_BE / l_OE
    for curve in (circle, plus, minus):
        assert np.allclose(np.hypot(*(curve - B).T), 0.8)   # l_AB / l_OE
    assert "units of the frame OE" in ax.get_xlabel() and "OE" in ax.get_ylabel()
    plt.close(fig)


def test_equivalence_explorer_reports_errors_and_recovers():
    from mechlab.widgets.equivalence import fourbar_equivalence, slider_crank_equivalence
    ex = fourbar_equivalence()
    assert ex.error < 1e-9 and ex.limit.holds() and "twin error" in ex.status.value
    ex.sliders["crank"].value = 1.5            # no longer Grashof for the crank
    assert ex.mechanism is None and "crank cannot turn fully" in ex.message
    ex.sliders["crank"].value = 0.3
    ex.sliders["assembly"].value = -1
    assert ex.message == "" and ex.mechanism.assembly == -1 and ex.error < 1e-9
    ex.angle.value = 200.0
    i = int(np.argmin(np.abs(np.degrees(ex.motion.phi) - 200.0)))
    assert np.allclose(ex.rel_pin.get_data(), [[ex.rel[i, 0]], [ex.rel[i, 1]]])
    sc = slider_crank_equivalence()
    assert sc.error < 1e-9 and "s′" in sc.status.value


def test_seed000_errata_recompute_their_evidence():
    from mechlab.course.errata import seed000_equivalence
    assert len(seed000_equivalence.ERRATA) == 3
    for e in seed000_equivalence.ERRATA:
        text = e.evidence()
        assert e.source == "000" and e.notebook == "03_base_mechanism.ipynb"
        assert ("φ = 60°" in text or "λ = 0.3" in text) and len(text.splitlines()) == 1


@pytest.mark.parametrize("fb", [FourBar(3, 3, 3, 4, 1), FourBar(3, 3, 3, 4, -1), FourBar(1.0, 3.0, 1.5, 2.0, 1)],
                         ids=["triple-rocker+", "triple-rocker-", "rocking-crank"])
def test_twin_of_a_rocking_crank_has_the_same_range_and_law(fb):
    """A crank that only rocks: the twin's pin meets the slot's extreme points (pressure angle
    90°) exactly at the four-bar's dead points, so both have the same range."""
    twin = equivalent_slot(fb)
    (s, e), = fb.crank_ranges()
    (ts, te), = twin.crank_ranges()
    assert np.isclose(np.mod(ts - s, 2 * np.pi), 0, atol=1e-12) or np.isclose(np.mod(ts - s, 2 * np.pi), 2 * np.pi)
    assert np.isclose(te - ts, e - s, atol=1e-12)
    phi = np.linspace(s + 0.01 * (e - s), e - 0.01 * (e - s), 201)
    assert max(law_difference(fb.motion(phi), twin.motion(phi))) < 1e-9


@pytest.mark.parametrize("call", ["base_mechanism", "other_half", "assembly_symmetry"])
def test_a_mechanism_without_a_crank_length_or_assemblies_is_refused_by_name(call):
    """A Geneva drive has neither a crank length l_OA nor two assemblies: a named DimensionError, not an
    AttributeError from deep inside."""
    from mechlab.analysis.equivalence import assembly_symmetry, base_mechanism

    geneva = ml.ExternalGeneva(4, 1.0)
    fn = {"base_mechanism": lambda: base_mechanism(geneva), "other_half": lambda: ml.other_half(geneva, 0.3),
          "assembly_symmetry": lambda: assembly_symmetry(geneva, np.linspace(0.0, 1.0, 3))}[call]
    with pytest.raises(ml.DimensionError, match="ExternalGeneva"):
        fn()
