"""Lambda mechanism of Chebyshev and its circle/straight-line synthesis (seed 001, chapter 1)."""

import numpy as np
import pytest
from hypothesis import assume, example, given, settings
from hypothesis import strategies as st

from mechlab.mechanisms.lambda_mechanism import LambdaMechanism, classic_lambda
from mechlab.errors import SynthesisError
from mechlab.synthesis.lambda_guiding import band_touches, circle_guiding, existence_map, fifth_order_line, rotation_boundary, straight_guiding, thesis_iteration, transmission_lines
from mechlab.errors import DimensionError, MechanismError, RotationError

DEG = np.pi / 180


@st.composite
def lambdas(draw):
    a = draw(st.floats(0.3, 1.7))
    r = draw(st.floats(0.05, 0.95)) * min(a, 2 - a)
    assume(min(a, 2 - a) - r > 0.15)  # stay clear of the dead points (finite differences)
    delta = draw(st.floats(60.0, 300.0)) * DEG
    return LambdaMechanism(r, a, delta, draw(st.sampled_from([1, -1])))


@settings(max_examples=60, deadline=None)
@given(lambdas())
def test_lengths_closed_form_and_analogs(m):
    phi = np.linspace(0, 2 * np.pi, 4001)
    mo = m.motion(phi)
    P = {k: v.p for k, v in mo.points.items()}
    for u, v in [("A", "B"), ("B", "C"), ("B", "D")]:
        assert np.allclose(np.hypot(*(P[u] - P[v]).T), 1.0, atol=1e-12)
    # ∠ABD = δ and the closed form (*) of the module docstring
    ba, bd = P["A"] - P["B"], P["D"] - P["B"]
    turn = np.arctan2(ba[:, 0] * bd[:, 1] - ba[:, 1] * bd[:, 0], (ba * bd).sum(1))
    assert np.allclose(np.mod(turn * m.assembly, 2 * np.pi), m.delta, atol=1e-9)
    assert np.allclose(P["D"], m.coupler_point(phi), atol=1e-12)
    h = phi[1] - phi[0]
    D = mo.points["D"]
    s1, s2 = np.abs(D.d).max(), np.abs(D.dd).max()
    assert np.allclose((D.p[2:] - D.p[:-2]) / (2 * h), D.d[1:-1], atol=1e-4 * s1)
    assert np.allclose((D.d[2:] - D.d[:-2]) / (2 * h), D.dd[1:-1], atol=1e-4 * s2 + 1e-3 * s1)


@settings(max_examples=60, deadline=None)
@given(lambdas())
def test_symmetry_axis_makes_pi_minus_half_delta_with_CO(m):
    t = np.linspace(0, np.pi, 301)
    Dp, Dm = m.coupler_point(np.pi + t), m.coupler_point(np.pi - t)
    e = m.axis
    w = Dp - m.C
    mirror = m.C + 2 * (w @ e)[:, None] * e - w
    assert np.allclose(mirror, Dm, atol=1e-12)
    co = -m.C / np.linalg.norm(m.C)
    assert np.isclose(np.arccos(co @ e), np.pi - m.delta / 2, atol=1e-12)


def test_rotation_conditions_and_bad_input():
    with pytest.raises(RotationError, match="r = 0.9 ≥ a = 0.8 .*double crank"):
        LambdaMechanism(0.9, 0.8, np.pi)
    with pytest.raises(RotationError, match="r \\+ a = 2.1 ≥ 2"):
        LambdaMechanism(0.6, 1.5, np.pi)
    with pytest.raises(DimensionError):
        LambdaMechanism(-0.1, 0.8, np.pi)
    with pytest.raises(MechanismError, match="δ"):
        LambdaMechanism(0.3, 0.8, 7.0)
    r, a = rotation_boundary()
    assert np.allclose(np.minimum(a, 2 - a), r)


def test_transmission_angle_lines():
    lines = transmission_lines()
    for key, mu in (("mu_min", 30 * DEG), ("mu_max", 150 * DEG)):
        r, a = getattr(lines, key)
        i = len(r) // 3
        m = LambdaMechanism(r[i], a[i], np.pi) if r[i] < a[i] and r[i] + a[i] < 2 else None
        if m is not None:
            got = m.motion(np.linspace(0, 2 * np.pi, 20001)).transmission
            ext = got.min() if key == "mu_min" else got.max()
            assert abs(ext - mu) < 1e-6


def test_classic_lambda_is_the_straight_line_synthesis_for_180_degrees():
    s = straight_guiding(np.pi, 0.8, np.pi)
    assert abs(s.r - 0.4) < 1e-12
    m = classic_lambda()
    assert (m.r, m.a) == (0.4, 0.8)
    # equal ripple found on a dense sample: x(0) = x(±90°) = Y − E, x(±t1) = Y + E
    t = np.linspace(-np.pi / 2, np.pi / 2, 20001)
    dev = s.deviation(np.pi + t)
    assert np.max(np.abs(dev)) <= s.E * (1 + 1e-9)
    touches = band_touches(dev, s.E, rtol=1e-4)
    assert len(touches) == 5 and np.all(np.diff(np.sign(dev[touches])) != 0)
    assert 0.0019 < s.E < 0.0020  # half the band: 0.2 % of l over half a turn


@pytest.mark.parametrize("delta,a,dwell", [(150, 0.9, 120), (120, 0.9, 180), (180, 0.5, 240), (150, 0.5, 60)])
def test_circle_guiding_equal_ripple(delta, a, dwell):
    g = circle_guiding(delta * DEG, a, dwell * DEG)
    assert 0 < g.r < min(a, 2 - a)
    alpha = g.alpha
    t = np.linspace(-alpha, alpha, 40001)
    dev = g.deviation(np.pi + t)
    assert np.max(np.abs(dev)) <= g.E * (1 + 1e-6)
    touches = band_touches(dev, g.E, rtol=1e-5)
    # t = 0, ±t3, ±t2, ±α: seven alternating touches over the whole dwell, four on each half
    assert len(touches) == 7
    assert np.all(np.diff(np.sign(dev[touches])) != 0)
    assert np.allclose(np.sort(np.abs(t[touches]))[::2], [0, g.t3, g.t2, alpha], atol=2 * (t[1] - t[0]))
    # outside the dwell D leaves the band
    out = g.deviation(np.pi + np.array([alpha * 1.05, -alpha * 1.05]))
    assert np.all(np.abs(out) > g.E)
    assert np.isclose(g.R, 0.5 * (g.R0 + g.R1)) and np.isclose(g.E, 0.5 * abs(g.R0 - g.R1))


def test_error_grows_with_dwell_and_thesis_iteration_agrees():
    es = [circle_guiding(150 * DEG, 0.9, d * DEG).E for d in (60, 120, 180, 240)]
    assert np.all(np.diff(es) > 0)
    g = circle_guiding(150 * DEG, 0.9, 120 * DEG)
    r, iterations, history = thesis_iteration(150 * DEG, 0.9, 120 * DEG)
    assert abs(r - g.r) < 1e-6 and iterations < 20 and history[0] == 0.9 / 4


def test_fifth_order_contact():
    r5, a5, c5 = fifth_order_line(150 * DEG, 50)
    i = len(r5) // 2
    m = LambdaMechanism(r5[i], a5[i], 150 * DEG)
    Q = m.C + c5[i] * m.axis
    t = np.array([0.0, 0.05, 0.1])
    rho = m.radius_about(Q, np.pi + t)[0]
    # six-point contact: ρ(t) − ρ(0) = O(t⁶)
    ratio = (rho[2] - rho[0]) / (rho[1] - rho[0])
    assert 40 < ratio < 90  # 2⁶ = 64


def test_infeasible_requests_raise_named_errors():
    with pytest.raises(SynthesisError, match="no circle-guiding"):
        circle_guiding(150 * DEG, 1.5, 120 * DEG)
    with pytest.raises(SynthesisError, match="no straight-line"):
        straight_guiding(np.pi, 1.0, np.pi)
    with pytest.raises(SynthesisError, match="a = 2.5 ≥ 2"):
        circle_guiding(np.pi, 2.5, 1.0)
    with pytest.raises(MechanismError, match="dwell"):
        circle_guiding(np.pi, 0.8, 7.0)


def test_existence_map_curves():
    em = existence_map(150 * DEG, dwells=(120 * DEG,), n=9)
    r, a = em.iso_dwell[120]
    assert len(r) >= 4 and np.all(r < np.minimum(a, 2 - a))
    r5, a5 = em.fifth
    assert np.all((r5 > 0) & (r5 < a5) & (r5 + a5 < 2))


@settings(max_examples=25, deadline=None)
@given(st.floats(100.0, 260.0), st.floats(0.2, 1.4), st.floats(30.0, 300.0))
@example(121.0, 1.0, 30.0)  # the solver once returned merged touches there, with r = 0.005 and E = 1.7e-10
def test_circle_guiding_is_valid_or_a_named_error(delta, a, dwell):
    try:
        g = circle_guiding(delta * DEG, a, dwell * DEG)
    except SynthesisError as err:
        assert "no circle-guiding lambda mechanism" in str(err)
        return
    assert 0 < g.r < min(a, 2 - a) and 0 < g.t3 < g.t2 < g.alpha
    assert min(g.t3, g.t2 - g.t3, g.alpha - g.t2) > 1e-3 * g.alpha  # four distinct touches per half
    t = np.linspace(-g.alpha, g.alpha, 6001)
    dev = g.deviation(np.pi + t)
    assert np.max(np.abs(dev)) <= g.E * (1 + 1e-5) + 1e-14
    assert len(band_touches(dev, g.E, rtol=1e-4)) >= 5


def test_widgets_exercises_and_errata():
    import matplotlib

    matplotlib.use("Agg")
    from mechlab.course.errata import table
    from mechlab.course.errata.seed001_chebyshev import ERRATA
    from mechlab.course.exercises import check, solution
    from mechlab.widgets.chebyshev import lambda_explorer, mchv1_explorer

    ex = lambda_explorer()
    assert ex.message == "" and ex.mechanism is not None
    ex.sliders["a"].value = 1.58  # outside the existence map: the reason is shown, the widget survives
    assert "no circle-guiding" in ex.message
    ex.sliders["a"].value = 0.9
    assert ex.message == ""
    six = mchv1_explorer()
    assert six.message == "" and "transmission" in six.status.value
    six.sliders["K"].value = 0.8  # the dyad's transmission angle reaches 28.8° < 30°: refused, reason shown
    assert "transmission angle D-E-F reaches 28.8°, outside 30°…150°" in six.message
    six.sliders["mu_min"].value = 0.0  # no limit: the design is shown
    assert six.message == ""
    for key in ("06.1", "06.2", "06.3", "07.1", "07.2", "07.3"):
        assert check(key, solution(key), quiet=True)
        assert not check(key, 1.1 * solution(key) + 0.01, quiet=True)
    for e in ERRATA:
        assert e.source == "001" and e.evidence()
    assert table(notebook="06_chebyshev_dwell_synthesis.ipynb").count("\n| 001") == 5


@pytest.mark.parametrize("delta,a", [(150, 1.15), (180, 1.3), (240, 1.6)])
def test_whole_turn_line_band_spans_the_turn_and_iso_dwells_converge_to_it(delta, a):
    from mechlab.synthesis.lambda_guiding import whole_turn_guiding

    g = whole_turn_guiding(delta * DEG, a)
    assert g.dwell == 2 * np.pi and 0 < g.r < min(a, 2 - a)
    phi = np.linspace(0, 2 * np.pi, 40000, endpoint=False)
    dev = g.deviation(phi)
    assert np.max(np.abs(dev)) <= g.E * (1 + 1e-6)
    k = band_touches(np.r_[dev, dev[0]], g.E, rtol=1e-5)[:-1]  # close the loop: φ = 0 is t = ±π
    # six alternating touches round the closed curve: t = π, ±t3, ±t2, 0
    assert len(k) == 6 and np.all(np.diff(np.sign(dev[k])) != 0)
    assert np.allclose(np.sort(np.abs(phi[k] - np.pi)), np.sort([0, g.t3, g.t3, g.t2, g.t2, np.pi]), atol=1e-3)
    # just inside: the ordinary synthesis at 2α → 360° tends to this r (quadratically in 360° − 2α)
    # (started from the line's solution: the default start from the fifth-order contact does not
    # reach 350° for every δ, e.g. δ = 90°)
    gaps, x = [], (g.r, g.c, g.t3, g.t2)
    for dw in (359, 355, 350):
        h = circle_guiding(delta * DEG, a, dw * DEG, guess=x)
        x = (h.r, h.c, h.t3, h.t2)
        gaps.insert(0, abs(h.r - g.r))
    assert gaps[0] > gaps[1] > gaps[2] and gaps[2] < 1e-3 * max(g.r, 0.1)
    assert 15 < gaps[1] / gaps[2] < 35  # (5/1)² = 25


def test_whole_turn_line_meets_the_fifth_order_line_at_A_and_ends_on_the_rotation_limit():
    from mechlab.synthesis.lambda_guiding import existence_region, whole_turn_line

    for delta in (90, 150, 180, 240):
        d = delta * DEG
        wt = whole_turn_line(d)
        r5, a5, _ = fifth_order_line(d, 4000)
        A = 2 * np.sin(d / 4)
        # both lines start at A = (r → 0, a = 2 sin(δ/4))
        assert abs(wt.a[0] - A) < 0.01 and wt.r[0] < 0.01
        i = np.argmax(a5)
        assert abs(a5[i] - A) < 1e-3 and r5[i] < 1e-3
        # the other end: r = a for δ < 120°, r + a = 2 for δ > 120°
        end = (wt.a[-1] - wt.r[-1]) if delta < 120 else (2 - wt.a[-1] - wt.r[-1])
        assert 0 < end < 0.03
        assert np.all(wt.c > 0) and np.all(np.diff(wt.r) > 0)
    # δ = 120°: the whole-turn line is a = 1 exactly, with the band's centre at c = 1
    wt = whole_turn_line(120 * DEG)
    assert np.allclose(wt.a, 1, atol=1e-9) and np.allclose(wt.c, 1, atol=1e-9) and wt.r[-1] > 0.99
    r, a = existence_region(150 * DEG)
    assert (r[0], a[0]) == pytest.approx((0, 0), abs=1e-3) and (r[-1], a[-1]) == (0.0, 0.0)
    assert np.all(r <= np.minimum(a, 2 - a) + 1e-12)
    # an iso-dwell point lies inside the region, a point beyond the whole-turn line outside
    from matplotlib.path import Path

    poly = Path(np.c_[r, a])
    g = circle_guiding(150 * DEG, 1.1, 300 * DEG)
    assert poly.contains_point((g.r, 1.1)) and not poly.contains_point((0.5, 1.3))
    with pytest.raises(SynthesisError, match="no circle-guiding"):
        circle_guiding(150 * DEG, 1.3, 120 * DEG)
