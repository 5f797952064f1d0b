"""Dwell synthesis with a curved slot (seed 000 §3): law, slot, solver, pressure angle."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from mechlab.errors import DimensionError, MechanismError, SingularityError
from mechlab.mechanisms.curved_slot import CurvedSlotLink, SampledSlot
from mechlab.mechanisms.slotted import SlottedLink
from mechlab.synthesis.dwell_slot import (
    TRANSITIONS,
    DwellError,
    DwellIntervalError,
    DwellLaw,
    DwellRatioError,
    compare_transitions,
    cubic_dwell_window,
    curved_slot_dwell,
    dwell_limit,
    slotted_link_law,
    two_branch_slot,
)

DEG = np.pi / 180


def designs():
    """Random admissible designs: λ away from 1, a dwell strictly inside (0°, 180°)."""
    lam = st.one_of(st.floats(0.15, 0.85), st.floats(1.2, 4.0))
    return st.tuples(lam, st.floats(15.0, 110.0), st.floats(10.0, 60.0), st.floats(15.0, 60.0),
                     st.sampled_from(TRANSITIONS), st.floats(0.3, 5.0)).map(
        lambda t: (t[0], t[1] * DEG, min(t[1] + t[2], 180.0 - t[3]) * DEG, t[5], t[4]))


# -- the base mechanism ----------------------------------------------------------------------
def test_base_law_matches_slotted_link_and_differences():
    for lam in (0.3, 0.7, 1.6, 3.0):
        phi = np.linspace(-2 * np.pi, 2 * np.pi, 1001)
        K = slotted_link_law(lam, phi)
        mo = SlottedLink(lam, 1.0).motion(phi)
        assert np.allclose(K.psi, mo.psi, atol=1e-12) and np.allclose(K.d, mo.dpsi, atol=1e-12)
        assert np.allclose(K.dd, mo.ddpsi, atol=1e-12)
        h = 1e-5
        up, dn = slotted_link_law(lam, phi + h), slotted_link_law(lam, phi - h)
        assert np.abs((up.dd - dn.dd) / (2 * h) - K.ddd).max() < 1e-6 * max(1, np.abs(K.ddd).max())


# -- the law ---------------------------------------------------------------------------------
def test_cubic_coefficients_and_dwell_angle_closed_form():
    lam, p1, p2 = 0.5, 60 * DEG, 150 * DEG
    law = DwellLaw(lam, p1, p2, "cubic")
    a1 = law.left.coef[3]
    a2 = law.right.coef[3]
    assert a1 == pytest.approx(-lam / (3 * (lam + 1) * p1**2), rel=1e-12)
    assert a2 == pytest.approx(lam / (3 * (lam - 1) * (np.pi - p2) ** 2), rel=1e-12)
    assert law.psi_dwell == pytest.approx(lam * p1 / (3 * (lam + 1)), rel=1e-12)   # printed with the wrong sign
    h = law.half(np.array([0.0, np.pi]))
    assert h.psi[0] == 0.0
    assert h.d[0] == pytest.approx(lam / (lam + 1), rel=1e-12) and h.d[1] == pytest.approx(lam / (lam - 1), rel=1e-12)


@settings(max_examples=60, deadline=None)
@given(designs())
def test_law_analogs_are_derivatives_and_continuous(design):
    lam, p1, p2, d, tr = design
    law = DwellLaw(lam, p1, p2, tr, d)
    phi = np.linspace(-np.pi + 0.01, np.pi - 0.01, 401)
    phi = phi[np.min(np.abs(np.abs(phi)[:, None] - np.array([0.0, p1, p2])[None]), axis=1) > 1e-4]
    h = 1e-6
    up, dn, mid = law(phi + h), law(phi - h), law(phi)
    scale = 1 + np.abs(mid.dd).max()
    assert np.abs((up.psi - dn.psi) / (2 * h) - mid.d).max() < 1e-7 * scale
    assert np.abs((up.d - dn.d) / (2 * h) - mid.dd).max() < 1e-6 * scale
    # ψ, ψ', ψ'' continuous at the joins 0, φ1, φ2, π (and the jerk too for quintic/sextic)
    e = 1e-9
    for x in (0.0, p1, p2, np.pi):
        a, b = law(np.array([x - e])), law(np.array([x + e]))
        for m, tol in (("psi", 1e-7), ("d", 1e-6), ("dd", 1e-5 * scale)):
            assert abs(getattr(a, m)[0] - getattr(b, m)[0]) < tol, (x, m)
        if tr != "cubic":
            assert abs(a.ddd[0] - b.ddd[0]) < 1e-4 * (1 + abs(a.ddd[0])), x


def test_cubic_jerk_jumps_where_the_quintic_is_smooth():
    lam, p1, p2 = 0.5, 60 * DEG, 150 * DEG
    e = 1e-9
    for tr, jumps in (("cubic", True), ("quintic", False), ("sextic", False)):
        law = DwellLaw(lam, p1, p2, tr)
        for x in (0.0, p1, p2, np.pi):
            j = abs(law(np.array([x - e])).ddd[0] - law(np.array([x + e])).ddd[0])
            assert (j > 0.1) == jumps, (tr, x, j)


# -- through the solver ----------------------------------------------------------------------
@pytest.mark.parametrize("tr", TRANSITIONS)
@pytest.mark.parametrize("lam", [0.5, 2.0])
def test_dwell_is_exact_through_the_slot(tr, lam):
    m = curved_slot_dwell(lam, 60 * DEG, 150 * DEG, transition=tr)
    assert isinstance(m.link, CurvedSlotLink)
    dwell = np.linspace(m.phi1, m.phi2, 2001)
    mo = m.motion(dwell)
    assert np.abs(mo.psi - m.law.psi_dwell).max() <= 1e-12
    assert np.abs(mo.dpsi).max() <= 1e-12 and np.abs(mo.ddpsi).max() <= 1e-12
    # the whole turn reproduces the design (ψ'' of the cubic loses digits at the slot's ends,
    # where its curvature is unbounded)
    phi = m.turn(1441)
    mo, law = m.motion(phi), m.law(phi)
    assert np.abs(mo.psi - law.psi).max() < 1e-12 and np.abs(mo.dpsi - law.d).max() < 1e-12
    assert np.abs(mo.ddpsi - law.dd).max() < (1e-5 if tr == "cubic" else 1e-12)


@settings(max_examples=10, deadline=None)
@given(designs())
def test_random_designs_dwell_and_half_turn_relation_through_the_slot(design):
    lam, p1, p2, d, tr = design
    m = curved_slot_dwell(lam, p1, p2, d, tr)
    dw = np.linspace(p1, p2, 101)
    assert np.abs(m.motion(dw).psi - m.law.psi_dwell).max() <= 1e-12 * max(1.0, abs(m.law.psi_dwell))
    full = np.linspace(0.0, 2 * np.pi, 181)
    assert np.abs(m.motion(full).psi - m.law(full).psi).max() < 1e-11
    # half-turn relation (Table 2) on the solved motion: same slot point at φ and -φ
    phi = np.linspace(0.02, np.pi - 0.02, 97)
    plus, minus, K = m.motion(phi), m.motion(-phi), slotted_link_law(lam, phi)
    turn = 2 * np.pi if lam > 1 else 0.0
    assert np.allclose(minus.psi, plus.psi - 2 * K.psi, atol=1e-10) or \
        np.allclose(minus.psi + turn, plus.psi - 2 * K.psi + turn, atol=1e-10)
    assert np.allclose(minus.dpsi, 2 * K.d - plus.dpsi, atol=1e-9)
    assert np.allclose(minus.ddpsi, plus.ddpsi - 2 * K.dd, atol=1e-7 * (1 + np.abs(plus.ddpsi).max()))


@pytest.mark.parametrize("tr", TRANSITIONS)
def test_velocity_analog_continuous_at_joins_through_the_slot(tr):
    m = curved_slot_dwell(0.4, 50 * DEG, 140 * DEG, transition=tr)
    h = 1e-7
    for x in (0.0, m.phi1, m.phi2, np.pi):
        mo = m.motion(np.array([x - h, x, x + h]))
        assert abs(mo.dpsi[0] - mo.dpsi[2]) < 1e-5, x
        assert abs(mo.dpsi[1] - m.law(np.array([x])).d[0]) < 1e-12


def test_independent_spline_slot_reproduces_the_dwell():
    """A CubicSpline through sampled slot points (no access to the law) gives the same motion."""
    m = curved_slot_dwell(0.5, 60 * DEG, 150 * DEG, transition="quintic")
    S = np.linspace(m.crank + 1.0, 0.5, 4001)
    pts = m.law.slot_points(m.law.phi_of_distance(S))
    # extend a little beyond both ends so the pin's extreme positions lie inside the spline
    t0, t1 = pts[1] - pts[0], pts[-1] - pts[-2]
    pts = np.vstack([pts[0] - 3 * t0, pts[0] - 2 * t0, pts[0] - t0, pts, pts[-1] + t1, pts[-1] + 2 * t1])
    link = CurvedSlotLink(m.crank, 1.0, SampledSlot(pts))
    phi = np.linspace(0, 2 * np.pi, 361)
    a, b = link.motion(phi), m.motion(phi)
    assert np.abs(a.psi - b.psi).max() < 1e-7
    assert np.abs(a.dpsi - b.dpsi).max() < 1e-4


# -- pressure angle --------------------------------------------------------------------------
@pytest.mark.parametrize("tr", TRANSITIONS)
def test_pressure_angle_closed_form_agrees_with_solver(tr):
    m = curved_slot_dwell(0.5, 60 * DEG, 150 * DEG, transition=tr)
    phi = np.linspace(-np.pi, np.pi, 721)
    assert np.abs(m.motion(phi).pressure_angle - m.law.pressure_angle(phi)).max() < 1e-7
    # on the dwell: θ = |π/2 - (φ - ψ_K)|, zero where cos φ = -λ
    dw = np.linspace(m.phi1, m.phi2, 50)
    K = slotted_link_law(0.5, dw)
    assert np.allclose(m.motion(dw).pressure_angle, np.abs(np.pi / 2 - (dw - K.psi)), atol=1e-12)


def test_max_pressure_angle_against_independent_formula():
    """Cubic: the worst pressure angle is at a slot end. From tan θ = S²|β''|/(r d) there,
    with β''(0) = -ψ''(0) = 2λ/((λ+1)φ1) and β''(π) = -ψ''(π): tan θ(0) = 2(1 + λ)/φ1 and
    tan θ(π) = 2(1 - λ)/(π - φ2) (λ < 1)."""
    for lam, p1, p2 in ((0.5, 60, 150), (0.3, 80, 140), (0.7, 100, 160)):
        m = curved_slot_dwell(lam, p1 * DEG, p2 * DEG)
        th, where = m.max_pressure_angle()
        far = np.arctan(2 * (1 + lam) / (p1 * DEG))
        near = np.arctan(2 * (1 - lam) / (np.pi - p2 * DEG))
        # (1e-7: the cubic slot is not smooth at its ends, β(S) has a (S - S_end)^{3/2} term)
        assert m.motion(0.0).pressure_angle == pytest.approx(far, abs=1e-7)
        assert m.motion(np.pi).pressure_angle == pytest.approx(near, abs=1e-7)
        assert th == pytest.approx(max(far, near), abs=1e-7)
        assert min(abs(where), abs(where - np.pi)) < 1e-5


def test_sextic_zero_pressure_angle_at_ends_and_curvature_on_dwell():
    m = curved_slot_dwell(0.5, 60 * DEG, 150 * DEG, transition="sextic")
    assert np.abs(m.motion(np.array([0.0, np.pi])).pressure_angle).max() < 1e-6
    dw = np.linspace(m.phi1, m.phi2, 20)
    assert np.allclose(np.abs(m.law.curvature(dw)), 1 / m.crank, rtol=1e-9)


def test_comparison_table_orders_the_laws():
    rows = compare_transitions(0.5, 60 * DEG, 150 * DEG).by("transition")
    assert set(rows) == set(TRANSITIONS)
    # the quintic lowers the peak acceleration and keeps the slot's curvature bounded
    assert rows["quintic"].peak_ddpsi < rows["cubic"].peak_ddpsi
    assert rows["cubic"].curvature_end > 100 * rows["quintic"].curvature_end
    assert rows["cubic"].jerk_jump > 0.1 and rows["quintic"].jerk_jump < 1e-3
    # the sextic moves the worst pressure angle away from the slot's ends and lowers it
    assert rows["sextic"].max_pressure_deg < rows["cubic"].max_pressure_deg - 5
    assert rows["cubic"].where_deg == pytest.approx(0.0, abs=1e-3)
    # peak |ψ'| is never below the base mechanism's λ/(1 - λ) (limit theorem)
    for r in rows.values():
        assert r.peak_dpsi >= 0.5 / 0.5 - 1e-12


def test_dwell_limit_is_set_by_the_slot_end_not_by_120_degrees():
    lam, limit = 0.5, np.radians(60.0)
    res = dwell_limit(lam, limit, transition="cubic")
    # cubic: θ(0) ≤ θ_max needs φ1 ≥ 2(1 + λ)/tan θ_max, θ(π) ≤ θ_max needs π - φ2 ≥ 2(1 - λ)/tan θ_max
    p1, p2 = 2 * (1 + lam) / np.tan(limit), np.pi - 2 * (1 - lam) / np.tan(limit)
    assert res.max_dwell_deg == pytest.approx(np.degrees(p2 - p1), abs=0.02)
    assert res.max_dwell_deg < 120.0 and "slot end" in res.where
    m = curved_slot_dwell(lam, res.phi1, res.phi2)
    assert m.max_pressure_angle()[0] <= limit + 1e-5


@pytest.mark.parametrize("lam, limit_deg", [(0.5, 60.0), (0.3, 70.0), (1.5, 70.0)])
def test_cubic_dwell_window_puts_the_limit_at_both_slot_ends(lam, limit_deg):
    limit = np.radians(limit_deg)
    p1, p2 = cubic_dwell_window(lam, limit)
    m = curved_slot_dwell(lam, p1, p2)
    # θ reaches the bound at both ends (1e-7: the cubic slot's end term) and nowhere exceeds it
    assert m.motion(np.array([0.0, np.pi])).pressure_angle == pytest.approx([limit, limit], abs=1e-7)
    assert m.max_pressure_angle()[0] == pytest.approx(limit, abs=1e-7)
    # the bisection of dwell_limit finds the same longest dwell (to its 2e-4 rad tolerance)
    assert dwell_limit(lam, limit, "cubic").max_dwell_deg == pytest.approx(np.degrees(p2 - p1), abs=0.02)


def test_cubic_dwell_window_refuses_when_no_dwell_is_left():
    with pytest.raises(DwellIntervalError, match=r"no dwell is left for λ = 2.5"):
        cubic_dwell_window(2.5, np.radians(70.0))
    with pytest.raises(DwellRatioError):
        cubic_dwell_window(1.0, np.radians(60.0))


# -- the two-branch slot and λ > 1 ---------------------------------------------------------
def test_two_branch_slot_jams_and_jumps():
    tb = two_branch_slot(0.5, 100 * DEG)
    assert tb.velocity_jump == pytest.approx(2 * 0.5 / 1.5, rel=1e-12)
    assert tb.pressure_angle_at_E == pytest.approx(np.pi / 2, abs=1e-12)
    assert tb.dpsi_after == pytest.approx(0.0, abs=1e-12)
    link = tb.link()
    with pytest.raises(SingularityError, match="pressure angle 90°"):
        link.motion(0.0)
    near = link.motion(np.array([1e-3, 0.5, 1.0]))
    assert np.abs(near.psi).max() < 1e-12          # it dwells on the arc through E
    assert near.pressure_angle[0] > np.radians(89.0)


def test_lambda_above_one_gives_intermittent_rotation():
    m = curved_slot_dwell(2.0, 60 * DEG, 150 * DEG, transition="quintic")
    phi = np.linspace(0, 4 * np.pi, 1441)
    mo = m.motion(phi)
    assert mo.psi[-1] - mo.psi[0] == pytest.approx(4 * np.pi, abs=1e-12)
    assert mo.dpsi.min() >= -1e-12    # it never turns back
    assert np.abs(mo.dpsi[m.law.in_dwell(phi)]).max() < 1e-12


# -- bad input -------------------------------------------------------------------------------
@pytest.mark.parametrize("args, err, text", [
    ((0.5, 100 * DEG, 60 * DEG), DwellIntervalError, "φ1 < φ2"),
    ((0.5, 60 * DEG, 60 * DEG), DwellIntervalError, "φ1 < φ2"),
    ((0.5, -10 * DEG, 60 * DEG), DwellIntervalError, "within \\[0°, 180°\\]"),
    ((0.5, 60 * DEG, 200 * DEG), DwellIntervalError, "within \\[0°, 180°\\]"),
    ((0.5, 0.0, 60 * DEG), DwellIntervalError, "two-branch"),
    ((1.0, 60 * DEG, 150 * DEG), DwellRatioError, "λ ≠ 1"),
    ((-0.5, 60 * DEG, 150 * DEG), DwellRatioError, "positive"),
    ((0.5, float("nan"), 150 * DEG), DwellIntervalError, "finite"),
])
def test_bad_inputs_raise_named_errors(args, err, text):
    with pytest.raises(err, match=text):
        curved_slot_dwell(*args)
    assert issubclass(err, MechanismError) and issubclass(err, DimensionError)


def test_bad_transition_and_pivot():
    with pytest.raises(DwellError, match="transition must be one of"):
        curved_slot_dwell(0.5, 1.0, 2.0, transition="linear")
    with pytest.raises(DimensionError, match="pivot_distance"):
        curved_slot_dwell(0.5, 1.0, 2.0, pivot_distance=0.0)


# -- errata, exercises, drawing, widget ----------------------------------------------------
def test_errata_of_section_3_hold():
    from mechlab.course.errata import collect, seed000_dwell, table

    assert len(seed000_dwell.ERRATA) >= 6
    for e in seed000_dwell.ERRATA:
        assert e.source == "000" and e.notebook == "05_dwell_curved_slot.ipynb"
        assert "λ" in e.evidence() or "l_OA" in e.evidence()
    chapter = [e for e in collect() if e.notebook == "05_dwell_curved_slot.ipynb"]  # seed000_remarks adds some
    assert table(notebook="05_dwell_curved_slot.ipynb").count("\n") == len(chapter) + 1


def test_drawing_moves_slot_with_link():
    import matplotlib.pyplot as plt

    from mechlab.draw import animate, drawing_class

    m = curved_slot_dwell(0.5, 60 * DEG, 150 * DEG, transition="quintic", roller_radius=0.05)
    fig, ax = plt.subplots()
    d = drawing_class(m)(ax, m, n=24)
    n_artists = len(ax.get_children())
    for i in range(24):
        d.set_frame(i)
        # the pin lies on the drawn slot centre line (to the drawing's sampling)
        A = d.motion.points["A"].p[i]
        line = np.array(d.lines_of("slot centre")[0].get_data()).T
        assert np.hypot(*(line - A).T).min() < 0.02
        assert (d.note.get_text() == "dwell") == bool(m.law.in_dwell(d.motion.phi[i:i + 1])[0])
    assert len(ax.get_children()) == n_artists
    plt.close(fig)
    fig, ax = plt.subplots(figsize=(2, 2), dpi=40)
    anim = animate(m, n=4, ax=ax)
    assert anim.drawing.lines_of("dwell") and "<script" in anim.to_jshtml()


def test_widget_shows_errors_and_recovers():
    from mechlab.widgets.dwell import dwell_explorer

    e = dwell_explorer(n=61)
    assert e.message == "" and "pressure angle" in e.status.value
    e.sliders["phi1"].value = 160.0
    assert "φ1 < φ2" in e.message
    e.sliders["phi1"].value = 60.0
    assert e.message == ""
    e.sliders["transition"].value = "cubic"
    e.sliders["roller_radius"].value = 0.05
    assert "quintic" in e.message
    e.sliders["transition"].value = "quintic"
    assert e.message == "" and e.mechanism.transition == "quintic"


def test_rotating_link_dwells_at_a_pressure_angle_of_at_least_90_minus_arcsin():
    from scipy.optimize import minimize_scalar

    from mechlab.synthesis.dwell_slot import arc_pressure_angle

    for lam in (1.3, 2.0, 3.5):
        res = minimize_scalar(lambda x, lam=lam: arc_pressure_angle(lam, x)[0], bounds=(0.0, np.pi), method="bounded",
                              options={"xatol": 1e-12})
        assert res.fun == pytest.approx(np.pi / 2 - np.arcsin(1 / lam), abs=1e-9)
        m = curved_slot_dwell(lam, 60 * DEG, 150 * DEG, transition="quintic")
        dw = np.linspace(m.phi1, m.phi2, 60)
        th = m.motion(dw).pressure_angle
        assert np.allclose(th, arc_pressure_angle(lam, dw), atol=1e-12)
        assert th.min() >= np.pi / 2 - np.arcsin(1 / lam) - 1e-12
    # λ < 1: the dwell arc has a point of zero pressure angle, at cos φ = -λ
    assert arc_pressure_angle(0.4, np.arccos(-0.4))[0] < 1e-12


@pytest.mark.parametrize("tr", TRANSITIONS)
def test_slot_curvature_is_continuous_at_the_joins_and_dwell_is_extreme(tr):
    m = curved_slot_dwell(0.5, 60 * DEG, 150 * DEG, transition=tr)
    e = 1e-7
    k = m.law.curvature(np.array([m.phi1 - e, m.phi1 + e, m.phi2 - e, m.phi2 + e]))
    assert np.allclose(np.abs(k), 1 / m.crank, rtol=1e-5)
    assert abs(m.motion(m.turn(721)).psi.max() - m.law.psi_dwell) < 1e-12
