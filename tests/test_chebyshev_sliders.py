"""МЧВ2 and МЧВ5: the lambda six-bars with a translating output (seed 001, Fig. 1 в, д)."""

import matplotlib
import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from scipy.optimize import brentq

from mechlab.analysis.motion_laws import rise_invariants
from mechlab.errors import DimensionError, InfeasibleDesignError, MechanismError
from mechlab.mechanisms.lambda_sliders import LambdaSliderSixBar, LambdaTranslatingSlot
from mechlab.synthesis.lambda_guiding import circle_guiding, straight_guiding
from mechlab.synthesis.lambda_sliders import (
    mchv2,
    mchv2_far_position,
    mchv2_stroke,
    mchv5,
    slider_invariants,
    slider_report,
    slider_rise,
)

DEG = np.pi / 180


@pytest.fixture(scope="module")
def guide():
    return circle_guiding(150 * DEG, 0.9, 120 * DEG)


@pytest.fixture(scope="module")
def line():
    return straight_guiding(np.pi, 0.8, np.pi)  # Chebyshev's lambda, 2α = 180°


def central(f, phi, h=1e-5):
    return (f(phi + h) - f(phi - h)) / (2 * h)


def dwell_angles(g, n=801):
    return np.pi + np.linspace(-g.dwell / 2, g.dwell / 2, n)


def residual_bound(g, six):
    """2 max|s| over the dwell: |s| ≤ |ρ² − R²| / |(D − Q)·u| for the near root of
    s² − 2s(D − Q)·u + ρ² − R² = 0."""
    D = g.mechanism.coupler_point(dwell_angles(g)) - g.centre
    return 2 * np.max(np.abs((D**2).sum(1) - g.R**2)) / np.min(np.abs(D @ six.u))


# --------------------------------------------------------------------------------------------
# МЧВ2
# --------------------------------------------------------------------------------------------
def test_mchv2_closure_and_analogs(guide):
    six = mchv2(guide, 1.25, mu_min=None)
    phi = np.linspace(0, 2 * np.pi, 4001)
    mo = six.motion(phi)
    D, E = mo.points["D"].p, mo.points["E"].p
    assert np.abs(np.hypot(*(D - E).T) - six.rod).max() < 1e-12
    u = six.u
    assert np.abs((E - six.Q) @ np.array([-u[1], u[0]])).max() < 1e-12  # E on the guide
    assert np.abs(six.Q + mo.s[:, None] * u - E).max() < 1e-12
    # the base loop closes too
    P = {k: v.p for k, v in mo.points.items()}
    for a_, b_, length in (("O", "A", six.r), ("A", "B", 1.0), ("C", "B", 1.0), ("B", "D", 1.0)):
        assert np.abs(np.hypot(*(P[a_] - P[b_]).T) - length).max() < 1e-12
    ph = np.linspace(0.1, 6.2, 57)
    s = lambda x: six.motion(x).s  # noqa: E731
    ds = lambda x: six.motion(x).ds  # noqa: E731
    m = six.motion(ph)
    assert np.allclose(m.ds, central(s, ph), atol=1e-8)
    assert np.allclose(m.dds, central(ds, ph), atol=1e-7)
    Ed = lambda x: six.motion(x).points["E"].p  # noqa: E731
    assert np.allclose(m.points["E"].d, central(Ed, ph), atol=1e-8)


def test_mchv2_slider_equals_an_independent_circle_line_solve(guide):
    """E from brentq on |Q + s·u − D(φ)| = R per angle, D from the closed form (*) of the lambda module."""
    six = mchv2(guide, 0.8, mu_min=None)
    phi = np.array([0.3, 1.7, np.pi - 0.4, np.pi, 4.0, 5.9])
    D = guide.mechanism.coupler_point(phi)
    got = six.motion(phi).s
    for k, (d, s_lib) in enumerate(zip(D, got, strict=False)):
        f = lambda s, d=d: np.hypot(*(six.Q + s * six.u - d)) - six.rod  # noqa: E731
        w = (d - six.Q) @ six.u
        # bracket the root on the assembly's side of the foot of D on the guide
        lo, hi = (w, w + 2 * six.rod) if six.assembly > 0 else (w - 2 * six.rod, w)
        s_ref = brentq(f, lo, hi, xtol=1e-15, rtol=4 * np.finfo(float).eps)
        assert abs(s_ref - s_lib) < 1e-12, k


@pytest.mark.parametrize("K", [0.8, 1.0, 1.1, 1.25, 1.4])
def test_mchv2_achieves_K_stroke_and_dwell(guide, K):
    six = mchv2(guide, K, mu_min=None)
    rep = slider_report(six)
    phi_far, _D1, E1 = mchv2_far_position(guide, K)
    h = np.hypot(*(E1 - guide.centre))
    assert abs(rep.K - K) < 1e-9
    assert abs(six.motion(np.array([phi_far])).s[0] - h) < 1e-12
    # the stroke is measured from the dwell centre, where the slider is within the residual of Q
    bound = residual_bound(guide, six)
    assert abs(rep.stroke - h) <= bound
    # residual motion in the dwell: of the order of E, below the bound and above a third of it
    assert 0.3 * bound < rep.residual <= bound
    assert guide.E < rep.residual < 20 * guide.E
    assert 0 < rep.mu2_min < rep.mu2_max <= np.pi / 2


def test_mchv2_residual_vanishes_with_E():
    res, Es = [], []
    for dwell in (120, 90, 60, 40):
        g = circle_guiding(150 * DEG, 0.9, dwell * DEG)
        rep = slider_report(mchv2(g, 1.0, mu_min=None))
        res.append(rep.residual)
        Es.append(g.E)
        # |s| ≈ |ρ − R|·R/|(D − Q)·u| with (D − Q)·u → R as the dwell shrinks: residual → 2E
        assert 2.0 < rep.residual / g.E < 2.3
    assert np.all(np.diff(res) < 0) and res[-1] < 2e-3 * res[0]


def test_mchv2_K1_is_on_the_axis_with_the_smallest_stroke(guide):
    six = mchv2(guide, 1.0, mu_min=None)
    m = guide.mechanism
    assert abs(np.cos(six.theta - m.axis_angle) - 1) < 1e-12
    rho = np.hypot(*(m.coupler_point(np.array([0.0]))[0] - guide.centre))
    h = np.hypot(*(mchv2_far_position(guide, 1.0)[2] - guide.centre))
    assert abs(h - (guide.R - rho)) < 1e-12
    # the seed's S = |D0 D1| at K = 1 holds to E: |D0 D1| = R0 − ρ(0) = h + (R0 − R)
    D0, D1 = m.coupler_point(np.array([np.pi, 0.0]))
    assert abs(abs(np.hypot(*(D0 - D1)) - h) - guide.E) < 1e-12
    # h(K) = h(1/K) (mirror guides) and h grows away from K = 1
    hs = [np.hypot(*(mchv2_far_position(guide, k)[2] - guide.centre)) for k in (1.0, 1.2, 1.4)]
    assert np.all(np.diff(hs) > 0)
    h_inv = np.hypot(*(mchv2_far_position(guide, 1 / 1.2)[2] - guide.centre))
    assert abs(h_inv - hs[1]) < 1e-12


def test_mchv2_transmission_angle_is_rod_to_guide_normal(guide):
    six = mchv2(guide, 1.25, mu_min=None)
    mo = six.motion(np.linspace(0, 2 * np.pi, 721))
    rod = mo.points["D"].p - mo.points["E"].p
    beta = np.arccos(np.clip(np.abs(rod @ six.u) / six.rod, 0, 1))  # acute angle rod–guide
    assert np.allclose(mo.transmission, np.pi / 2 - beta, atol=1e-9)
    assert np.allclose(mo.pressure_angle, beta, atol=1e-9)


def test_mchv2_stroke_synthesis(guide):
    for h, side in ((0.4, 1), (0.4, -1), (0.45, 1)):
        six = mchv2_stroke(guide, h, side, mu_min=None)
        rep = slider_report(six)
        far = mchv2_far_position(guide, rep.K)[2]
        assert abs(np.hypot(*(far - guide.centre)) - h) < 1e-9
        assert (rep.K - 1) * side > 0


def test_mchv2_infeasible_requests_name_the_numbers(guide):
    with pytest.raises(InfeasibleDesignError, match=r"turns across QD during the dwell.*-0\.39"):
        mchv2(guide, 2.0, mu_min=None)
    with pytest.raises(InfeasibleDesignError, match=r"below the smallest stroke.*0\.3216"):
        mchv2_stroke(guide, 0.2, mu_min=None)
    with pytest.raises(InfeasibleDesignError, match=r"exceeds the largest stroke"):
        mchv2_stroke(guide, 5.0, mu_min=None)
    with pytest.raises(InfeasibleDesignError, match=r"μ2′ .* falls to 22\.9\d°, below the allowed 30°"):
        mchv2(guide, 1.25)  # the default limit, as mchv1's
    with pytest.raises(InfeasibleDesignError, match="K must be > 0"):
        mchv2(guide, -1.0, mu_min=None)
    with pytest.raises(TypeError):
        mchv2(straight_guiding(np.pi, 0.8, np.pi), 1.0, mu_min=None)
    g2 = circle_guiding(120 * DEG, 0.8, 60 * DEG)
    with pytest.raises(InfeasibleDesignError, match="E1 lies on the other assembly"):
        mchv2(g2, 2.0, mu_min=None)


def test_slider_six_bar_validates_its_dimensions(guide):
    m = guide.mechanism
    q = guide.centre
    with pytest.raises(InfeasibleDesignError, match=r"not less than the rod DE = 0\.1"):
        LambdaSliderSixBar(m.r, m.a, m.delta, 0.1, q[0], q[1], m.axis_angle)
    with pytest.raises(DimensionError, match="assembly"):
        LambdaSliderSixBar(m.r, m.a, m.delta, guide.R, q[0], q[1], m.axis_angle, 0)
    with pytest.raises(MechanismError, match="theta must be finite"):
        LambdaSliderSixBar(m.r, m.a, m.delta, guide.R, q[0], q[1], np.nan)
    with pytest.raises(DimensionError, match="rod must be > 0"):
        LambdaSliderSixBar(m.r, m.a, m.delta, -1.0, q[0], q[1], 0.0)


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(K=st.floats(0.55, 1.8))
def test_mchv2_random_K_met_or_refused(guide, K):
    try:
        six = mchv2(guide, K, mu_min=None)
    except InfeasibleDesignError as err:
        assert f"K = {K:g}" in str(err)
        return
    rep = slider_report(six)
    assert abs(rep.K - K) < 1e-8
    assert rep.residual <= residual_bound(guide, six)


# --------------------------------------------------------------------------------------------
# МЧВ5
# --------------------------------------------------------------------------------------------
def test_mchv5_closure_and_analogs(line):
    m5 = mchv5(line, guide_angle=20 * DEG)
    phi = np.linspace(0, 2 * np.pi, 2001)
    mo = m5.motion(phi)
    D, E = mo.points["D"].p, mo.points["E"].p
    v, w = np.array([np.cos(m5.slot), np.sin(m5.slot)]), np.array([np.cos(m5.guide), np.sin(m5.guide)])
    assert np.abs((D - E) @ np.array([-v[1], v[0]])).max() < 1e-12  # D on the slot through E
    assert np.abs((E - m5.P) @ np.array([-w[1], w[0]])).max() < 1e-12  # E on the guide through P
    ph = np.linspace(0.1, 6.2, 41)
    m = m5.motion(ph)
    assert np.allclose(m.ds, central(lambda x: m5.motion(x).s, ph), atol=1e-8)
    assert np.allclose(m.dds, central(lambda x: m5.motion(x).ds, ph), atol=1e-7)
    assert np.allclose(m.points["E"].dd, central(lambda x: m5.motion(x).points["E"].d, ph), atol=1e-7)
    # closed form: s = (x − Y)/cos γ with x the axis coordinate of D
    x = line.mechanism.axis_coordinates(phi)[0]
    assert np.allclose(mo.s, (x - line.Y) / np.cos(20 * DEG), atol=1e-12)
    assert np.allclose(mo.transmission, 70 * DEG, atol=1e-12)


@pytest.mark.parametrize("gamma", [0.0, 25.0, -40.0])
def test_mchv5_dwell_is_the_straight_line_deviation(line, gamma):
    m5 = mchv5(line, guide_angle=gamma * DEG)
    rep = slider_report(m5)
    assert abs(rep.residual - 2 * line.E / np.cos(gamma * DEG)) < 1e-4 * line.E
    assert abs(rep.K - 1) < 1e-9 and abs(rep.far) < 1e-9
    h0 = slider_report(mchv5(line)).stroke
    assert abs(rep.stroke - h0 / np.cos(gamma * DEG)) < 1e-12
    assert abs(rep.mu2_min - (90 - abs(gamma)) * DEG) < 1e-12


def test_mchv5_residual_vanishes_with_E():
    res = []
    for dwell in (180, 170, 160, 150):
        g = straight_guiding(np.pi, 0.8, dwell * DEG)
        rep = slider_report(mchv5(g))
        assert abs(rep.residual - 2 * g.E) < 1e-4 * g.E  # sampled: the touches at ±t1 fall between samples
        res.append(rep.residual)
    assert np.all(np.diff(res) < 0)


def test_mchv5_stroke_synthesis_and_refusals(line):
    h0 = slider_report(mchv5(line)).stroke
    m5 = mchv5(line, stroke=1.5 * h0, side=-1)
    assert abs(slider_report(m5).stroke - 1.5 * h0) < 1e-12
    assert abs(m5.transmission_angle - (np.pi / 2 - np.arccos(1 / 1.5))) < 1e-12
    with pytest.raises(InfeasibleDesignError, match=rf"below the stroke h0 = {h0:.6g}"):
        mchv5(line, stroke=0.9 * h0)
    with pytest.raises(InfeasibleDesignError, match=r"γ = 70\.53°.*exceeds the allowed 60°"):
        mchv5(line, stroke=3 * h0)
    with pytest.raises(MechanismError, match="either the stroke or the guide angle"):
        mchv5(line, stroke=h0, guide_angle=0.1)
    m = line.mechanism
    with pytest.raises(MechanismError, match="parallel to its slot"):
        LambdaTranslatingSlot(m.r, m.a, m.delta, 0.8, 1.6, 0.0, np.pi)
    with pytest.raises(TypeError):
        mchv5(circle_guiding(150 * DEG, 0.9, 120 * DEG))


def test_invariants_of_the_rise(line, guide):
    # a guide turned by γ scales s by 1/cos γ: the normalised invariants do not change
    i0, i1 = slider_invariants(mchv5(line)), slider_invariants(mchv5(line, guide_angle=35 * DEG))
    assert np.allclose(i0.values, i1.values, rtol=1e-9)
    six = mchv2(guide, 1.25, mu_min=None)
    phi, s, ds, dds = slider_rise(six)
    assert abs(phi[0] - (np.pi + guide.alpha)) < 1e-12 and abs(ds[-1]) < 1e-9
    inv = slider_invariants(six)
    assert np.allclose(inv.values, rise_invariants(phi, s, ds, dds).values)
    # max|y'| ≥ 1 (mean slope over the rise); the constant-acceleration law has C = 4 as the least C
    assert inv.B >= 1 and inv.C >= 4


# --------------------------------------------------------------------------------------------
# drawing and exercises
# --------------------------------------------------------------------------------------------
def test_drawings_highlight_the_dwell(guide, line):
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from mechlab.draw import drawing_class
    for mech in (mchv2(guide, 1.25, mu_min=None), mchv5(line, guide_angle=0.3)):
        fig, ax = plt.subplots()
        d = drawing_class(mech)(ax, mech, trace="D", n=24)
        d.autoscale()
        before = len(ax.lines)
        for i in range(24):
            d.set_frame(i)
            hl = d.extras(i)[-1]
            assert np.isnan(hl).all() != (abs(d.motion.phi[i] - np.pi) <= mech.dwell / 2)
        assert len(ax.lines) == before
        plt.close(fig)
        # links, extras, trace, ground symbol, pivots, joints, and the labels
        assert len(d.artists) == len(d.bars) + len(d.extras(0)) + 4 + len(d.label_artists)




@settings(max_examples=12, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(h=st.floats(0.25, 0.9), side=st.sampled_from([1, -1]))
def test_mchv2_random_strokes_met_or_refused(guide, h, side):
    try:
        six = mchv2_stroke(guide, h, side, mu_min=None)
    except InfeasibleDesignError as err:
        assert f"{h:.6g}" in str(err) or "K = " in str(err)
        return
    K = slider_report(six).K
    assert (K - 1) * side >= 0
    assert abs(np.hypot(*(mchv2_far_position(guide, K)[2] - guide.centre)) - h) < 1e-8


@settings(max_examples=40, deadline=None)
@given(r=st.floats(0.1, 0.6), a=st.floats(0.7, 1.3), delta=st.floats(60, 270), slot=st.floats(-180, 180),
       turn=st.floats(5, 175), px=st.floats(-1, 1), py=st.floats(-1, 1))
def test_translating_slot_on_random_geometry(r, a, delta, slot, turn, px, py):
    """Any lambda, any slot and guide: D on the slot through E, E on the guide, s′ the projection of D′."""
    try:
        m5 = LambdaTranslatingSlot(r, a, delta * DEG, px, py, slot * DEG, (slot + turn) * DEG)
    except MechanismError:
        return  # a lambda whose crank cannot turn: refused by name
    phi = np.linspace(0, 2 * np.pi, 97)
    mo = m5.motion(phi)
    v, w = np.array([np.cos(m5.slot), np.sin(m5.slot)]), np.array([np.cos(m5.guide), np.sin(m5.guide)])
    D, E = mo.points["D"], mo.points["E"]
    scale = 1 / abs(np.sin(turn * DEG))
    assert np.abs((D.p - E.p) @ np.array([-v[1], v[0]])).max() < 1e-12 * scale * 10
    assert np.abs((E.p - m5.P) @ np.array([-w[1], w[0]])).max() < 1e-12 * scale * 10
    # velocities: the block's velocity relative to the link is along the slot
    assert np.abs((D.d - E.d) @ np.array([-v[1], v[0]])).max() < 1e-11 * scale
    assert np.abs((D.dd - E.dd) @ np.array([-v[1], v[0]])).max() < 1e-11 * scale
    assert abs(m5.motion(1.0).s - m5.motion(np.array([1.0, 2.0])).s[0]) < 1e-15  # scalar or array


@settings(max_examples=12, deadline=None)
@given(delta=st.floats(120, 180), a=st.floats(0.8, 1.0), dwell=st.floats(60, 120), K=st.floats(0.8, 1.25))
def test_mchv2_on_random_circle_guides(delta, a, dwell, K):
    """Designs from random (δ, a, 2α) and K: built with K and the dwell met, or refused by name."""
    try:
        g = circle_guiding(delta * DEG, a, dwell * DEG, minimax=False)
        six = mchv2(g, K, mu_min=None)
    except MechanismError as err:
        assert str(err)
        return
    rep = slider_report(six)
    assert abs(rep.K - K) < 1e-8
    assert rep.residual <= residual_bound(g, six)


def test_explorers_show_designs_and_refusals():
    matplotlib.use("Agg")
    from mechlab.widgets.chebyshev_sliders import mchv2_explorer, mchv5_explorer

    ex = mchv2_explorer()
    assert ex.message == "" and isinstance(ex.mechanism, LambdaSliderSixBar)
    ex.sliders["K"].value = 1.25
    assert "μ2′ of the slider dyad falls to 22.90°, below the allowed 30°" in ex.message
    ex.sliders["mu_min"].value = 0.0
    assert ex.message == "" and "transmission angle μ: 22.9°" in ex.status.value  # μ2′ of K = 1.25
    ex.sliders["K"].value = 2.0
    assert "turns across QD during the dwell" in ex.message
    ex.sliders["K"].value = 1.0
    assert ex.message == ""
    ex5 = mchv5_explorer()
    assert ex5.message == "" and isinstance(ex5.mechanism, LambdaTranslatingSlot)
    ex5.sliders["gamma"].value = 30.0
    assert abs(ex5.mechanism.transmission_angle - 60 * DEG) < 1e-12
    ex5.sliders["delta"].value = 150.0  # no straight-line design for δ = 150°, a = 0.8: the reason is shown
    assert "no straight-line lambda mechanism" in ex5.message


def test_mchv2_outer_normal_when_the_inner_one_is_not_reached():
    """On (120°, 0.8, 60°) with K = 1.7 the rod toward Q (МЧВ1's choice) is on the other assembly; the rod
    on the outer normal is reached, and the design meets K."""
    g = circle_guiding(120 * DEG, 0.8, 60 * DEG)
    with pytest.raises(InfeasibleDesignError, match="E1 lies on the other assembly"):
        mchv2(g, 1.7, normal=1, mu_min=None)
    six = mchv2(g, 1.7, mu_min=None)
    phi_far, D1, E1 = mchv2_far_position(g, 1.7, normal=-1)
    assert abs(six.motion(np.array([phi_far])).s[0] - np.hypot(*(E1 - g.centre))) < 1e-12
    # E1 − D1 is along the outward normal: away from Q
    assert (E1 - D1) @ (g.centre - D1) < 0
    rep = slider_report(six)
    assert abs(rep.K - 1.7) < 1e-9 and rep.residual <= residual_bound(g, six)
