"""Disc cams with roller followers: the motion solved from the profile reproduces the law; pressure
angle, curvature and undercut against independent formulas; export read back; drawing."""

import os
import tempfile

import ezdxf
import matplotlib.pyplot as plt
import numpy as np
import pytest
from hypothesis import HealthCheck, Phase, assume, given, settings
from hypothesis import strategies as st

import mechlab as ml
from mechlab.analysis.motion_laws import LAWS
from mechlab.draw import animate, draw
from mechlab.mechanisms.cam import CamUndercutError, _phases
from mechlab.synthesis.slot_export import read_csv, write_cam_csv, write_cam_dxf

DEG = np.pi / 180
PHI = np.linspace(0.0, 2 * np.pi, 1441)


def programme(law="cycloidal (sine)", stroke=20.0):
    return ml.CamProgramme(stroke, 120 * DEG, 100 * DEG, 40 * DEG, law=law)


def translating(law="cycloidal (sine)", offset=8.0, roller=10.0, base=40.0):
    return ml.TranslatingRollerCam(programme(law), base, roller, offset=offset)


def oscillating(law="cycloidal (sine)", roller=8.0):
    return ml.OscillatingRollerCam(programme(law, stroke=20 * DEG), 40.0, roller, pivot_distance=90.0, arm=70.0)


def away_from_cuts(cam, phi, gap=1e-9):
    """Angles not on a phase boundary, where the law's second analog may jump (one-sided there)."""
    cuts = np.array([a for a, _ in _phases(cam.programme)] + [2 * np.pi])
    return np.min(np.abs(phi[:, None] - cuts[None, :]), axis=1) > gap


# ------------------------------------------------------------------------------------------- the law
def test_programme_phases_and_analogs_by_differences():
    pr = programme("3-4-5 polynomial")
    y = pr(np.array([0.0, 120 * DEG, 140 * DEG, 160 * DEG, 260 * DEG, 300 * DEG]))
    assert np.allclose(y.theta, [0, 20, 20, 20, 0, 0], atol=1e-12)
    # analogs against central differences of y itself
    phi, h = np.linspace(0.01, 2 * np.pi - 0.01, 997), 1e-5
    y, yp, ym = pr(phi), pr(phi + h), pr(phi - h)
    ok = np.min(np.abs(phi[:, None] - np.array(pr.breaks)[None, :]), axis=1) > 2 * h
    assert np.allclose(y.d[ok], ((yp.theta - ym.theta) / (2 * h))[ok], atol=1e-6)
    assert np.allclose(y.dd[ok], ((yp.d - ym.d) / (2 * h))[ok], atol=1e-5)
    assert pr.in_dwell(np.array([130 * DEG, 250 * DEG, 300 * DEG])).tolist() == [True, False, True]


# -------------------------------------------------------------------- the motion, through the profile
@pytest.mark.parametrize("law", list(LAWS))
@pytest.mark.parametrize("make", [translating, oscillating])
def test_motion_solved_from_the_profile_reproduces_the_law(make, law):
    cam = make(law)
    mo = cam.motion(PHI)
    q = cam.follower(PHI)
    got = (mo.s, mo.ds, mo.dds) if cam.output == "position" else (mo.psi, mo.dpsi, mo.ddpsi)
    ok = away_from_cuts(cam, PHI)
    h = cam.programme.stroke
    assert np.max(np.abs(got[0] - q.theta)) < 1e-10 * h
    assert np.max(np.abs(got[1] - q.d)) < 1e-8 * np.max(np.abs(q.d))
    assert np.max(np.abs(got[2] - q.dd)[ok]) < 1e-6 * np.max(np.abs(q.dd))


@settings(max_examples=15, deadline=None)
@given(offset=st.floats(-20, 20), roller=st.just(0.0) | st.floats(1, 12), base=st.floats(35, 80),
       phi=st.floats(0, 2 * np.pi))
def test_roller_touches_the_profile(offset, roller, base, phi):
    cam = translating("3-4-5 polynomial", offset, roller, base)
    mo = cam.motion([phi])
    C, K = mo.points["C"].p[0], mo.points["K"].p[0]
    assert np.hypot(*(C - K)) == pytest.approx(roller, abs=1e-9)
    assert C[0] == pytest.approx(offset, abs=1e-9)
    # K, turned back into the cam frame, lies on the densely sampled profile, whose normal there points at C
    prof = cam.profile(20001)
    c, s = np.cos(phi), np.sin(phi)
    k = np.array([c * K[0] + s * K[1], -s * K[0] + c * K[1]])
    i = int(np.argmin(np.hypot(*(prof.surface - k).T)))
    assert np.hypot(*(prof.surface[i] - k)) < 2e-3 * base
    if roller > 0:
        n = np.array([c * prof.normal[i, 0] - s * prof.normal[i, 1], s * prof.normal[i, 0] + c * prof.normal[i, 1]])
        assert np.dot(n, (C - K) / roller) > 1 - 1e-5


def test_contact_analogs_by_differences():
    cam = oscillating("cycloidal (sine)")
    phi, h = np.linspace(0.1, 6.1, 61), 1e-5
    mo, up, dn = cam.motion(phi), cam.motion(phi + h), cam.motion(phi - h)
    for name in ("C", "K"):
        P, Pp, Pm = mo.points[name], up.points[name], dn.points[name]
        assert np.allclose(P.d, (Pp.p - Pm.p) / (2 * h), atol=1e-5)
        assert np.allclose(P.dd, (Pp.d - Pm.d) / (2 * h), atol=1e-4)


def test_a_coarser_profile_moves_the_follower_less_exactly():
    # the motion comes from the sampled profile: fewer samples, a larger (still small) error
    fine, coarse = translating(), ml.TranslatingRollerCam(programme(), 40.0, 10.0, offset=8.0, samples=720)
    q = fine.follower(PHI)
    err = [np.max(np.abs(c.motion(PHI).dds - q.dd)[away_from_cuts(c, PHI)]) for c in (fine, coarse)]
    assert 3 * err[0] < err[1] < 1e-5


# ------------------------------------------------------------------------------- pressure angle
@pytest.mark.parametrize("offset", [-10.0, 0.0, 12.0])
def test_translating_pressure_angle_is_the_textbook_formula(offset):
    cam = translating("cosine", offset)
    y = cam.programme(PHI)
    alpha = np.arctan((y.d - offset) / (y.theta + cam.s0))   # tan α = (s′ − e)/(s + s0)
    assert np.allclose(cam.pressure_angle(PHI), alpha, atol=1e-13)
    assert np.allclose(cam.motion(PHI).pressure_angle, np.abs(alpha), atol=1e-9)


def test_oscillating_pressure_angle_from_the_instant_centre():
    # Kennedy: the cam–follower centre P lies on OB where ω_cam·P = ω_f·(P − B): P = ψ′B/(ψ′ − 1);
    # the contact normal runs through C and P, the roller centre moves along perp(C − B)
    cam = oscillating()
    psi = cam.follower(PHI)
    B = np.array([cam.pivot_distance, 0.0])
    C = B + cam.arm * np.stack([np.cos(psi.theta), np.sin(psi.theta)], -1)
    P = (psi.d / (psi.d - 1))[:, None] * B
    n, w = C - P, np.stack([-(C - B)[:, 1], (C - B)[:, 0]], -1)
    cos_a = np.abs(np.sum(n * w, 1)) / (np.hypot(*n.T) * np.hypot(*w.T))
    assert np.allclose(np.abs(cam.pressure_angle(PHI)), np.arccos(np.clip(cos_a, -1, 1)), atol=1e-7)
    assert np.allclose(cam.motion(PHI).pressure_angle, np.abs(cam.pressure_angle(PHI)), atol=1e-8)


# ------------------------------------------------------------------------ curvature and undercut
def polar_curvature(cam, phi):
    """e = 0: the pitch curve is r(θ) = r_b + r_r + s(θ) in polar form,
    κ = (r² + 2r′² − r r″)/(r² + r′²)^1.5."""
    y = cam.programme(phi)
    r, r1, r2 = cam.prime_radius + y.theta, y.d, y.dd
    return (r**2 + 2 * r1**2 - r * r2) / (r**2 + r1**2) ** 1.5


def test_curvature_radial_follower_is_the_polar_formula():
    cam = translating("3-4-5 polynomial", offset=0.0)
    assert np.allclose(cam.curvature(PHI), polar_curvature(cam, PHI), rtol=1e-12, atol=1e-15)


@pytest.mark.parametrize("make", [lambda: translating("cycloidal (sine)", 12.0), oscillating])
def test_curvature_by_finite_differences_of_the_pitch_curve(make):
    cam = make()
    theta = np.linspace(0.0, 2 * np.pi, 20001)
    P, h = cam.pitch(theta).p, theta[1] - theta[0]
    d1 = (P[2:] - P[:-2]) / (2 * h)
    d2 = (P[2:] - 2 * P[1:-1] + P[:-2]) / h**2
    k = -(d1[:, 0] * d2[:, 1] - d1[:, 1] * d2[:, 0]) / np.hypot(*d1.T) ** 3
    assert np.allclose(cam.curvature(theta[1:-1]), k, atol=1e-4 * np.max(np.abs(k)))  # O(h) where y‴ jumps
    # the inner dwell is an arc of the prime circle
    inner = theta > 260 * DEG
    assert np.allclose(np.hypot(*P[inner].T), cam.prime_radius, atol=1e-12 * cam.prime_radius)


def test_undercut_at_the_known_radius():
    # a short steep rise: its nose, just after the top, is sharper than the prime circle. With e = 0
    # the pitch curve depends on r_b + r_r only (here 26): its smallest radius from the polar formula
    pr = ml.CamProgramme(30.0, 40 * DEG, 40 * DEG, 0.0, law="cycloidal (sine)")
    phi = np.linspace(0, 2 * np.pi, 200001)
    k = polar_curvature(ml.TranslatingRollerCam(pr, 25.0, 1.0), phi)
    rho_min, where = 1 / k.max(), phi[np.argmax(k)]
    assert ml.TranslatingRollerCam(pr, 26.0 - 0.99 * rho_min, 0.99 * rho_min).undercut() is None
    cam = ml.TranslatingRollerCam(pr, 26.0 - 1.01 * rho_min, 1.01 * rho_min)
    flag = cam.undercut()
    assert flag.radius == pytest.approx(rho_min, rel=1e-5) and flag.phi == pytest.approx(where, abs=1e-3)
    assert flag.where.min() <= where <= flag.where.max()
    with pytest.raises(CamUndercutError, match=rf"falls to {rho_min:.4g} at φ = ") as err:
        cam.motion(PHI)
    said = float(str(err.value).split("at φ = ")[1].split("°")[0])
    assert said == pytest.approx(np.degrees(where), abs=0.006)   # exact, printed to 0.01°
    # drawn anyway, the profile's offset turns back on itself where ρ < r_r (a swallowtail)
    prof = cam.profile(72001, check=False)
    dq, dp = np.diff(prof.surface, axis=0), np.diff(prof.pitch, axis=0)
    back = np.sum(dq * dp, axis=1) < 0
    assert back.any() and np.all(prof.surface_radius_of_curvature[1:][back] < 0)


# ------------------------------------------------------------------------------------- bad input
@pytest.mark.parametrize("build, match", [
    (lambda: ml.CamProgramme(20, 200 * DEG, 150 * DEG, 20 * DEG), r"= 370°? exceeds one turn"),
    (lambda: ml.CamProgramme(-1, 90 * DEG, 90 * DEG), "stroke must be > 0"),
    (lambda: ml.CamProgramme(10, 90 * DEG, 0.0), "ret angle must be > 0"),
    (lambda: ml.CamProgramme(10, 90 * DEG, 90 * DEG, law="spline"), "law must be one of .*, got 'spline'"),
    (lambda: translating(offset=50.0), r"offset \|e\| = 50 must be < base radius \+ roller radius = 50"),
    (lambda: translating(roller=-1.0), "roller radius must be ≥ 0"),
    (lambda: translating(base=float("nan")), "base radius must be finite"),
    (lambda: ml.OscillatingRollerCam(programme(stroke=0.3), 40, 8, 200, 70), "the arm cannot reach"),
    (lambda: ml.OscillatingRollerCam(programme(stroke=2.8), 40, 8, 90, 70), "swing 160.4° too large"),
    (lambda: ml.TranslatingRollerCam("cycloidal", 40, 8), "programme must be a CamProgramme"),
    (lambda: ml.TranslatingRollerCam(programme(), 40, 8, samples=100), "samples must be a whole number ≥ 720"),
])
def test_bad_input_is_named(build, match):
    with pytest.raises(ml.DimensionError, match=match):
        build()


# ------------------------------------------------------------------------------------------ export
def test_csv_and_dxf_round_trip():
    cam = translating()
    prof = cam.profile(361)
    with tempfile.TemporaryDirectory() as d:
        cols = read_csv(write_cam_csv(cam, os.path.join(d, "cam.csv"), n=361))
        assert np.array_equal(np.column_stack([cols["x"], cols["y"]]), prof.surface)
        assert np.allclose(np.radians(cols["pressure_angle_deg"]), cam.pressure_angle(prof.theta), atol=1e-15)
        write_cam_dxf(cam, os.path.join(d, "cam.dxf"), n=361)
        doc = ezdxf.readfile(os.path.join(d, "cam.dxf"))
    msp = doc.modelspace()
    (surface,) = msp.query('LWPOLYLINE[layer=="PROFILE"]')
    assert surface.closed and np.abs(np.array([p[:2] for p in surface.get_points()]) - prof.surface[:-1]).max() < 1e-12
    (pitch,) = msp.query('LWPOLYLINE[layer=="PITCH"]')
    assert np.abs(np.array([p[:2] for p in pitch.get_points()]) - prof.pitch[:-1]).max() < 1e-12
    (base,) = msp.query('CIRCLE[layer=="BASE"]')
    assert base.dxf.radius == 40.0 and doc.header["$INSUNITS"] == 4
    # every profile point is one roller radius inside the pitch curve, along the normal
    assert np.allclose(np.hypot(*(prof.pitch - prof.surface).T), 10.0, atol=1e-12)


def test_export_refuses_an_undercut_profile():
    cam = ml.TranslatingRollerCam(ml.CamProgramme(30.0, 40 * DEG, 40 * DEG), 15.0, 11.0)
    with pytest.raises(CamUndercutError), tempfile.TemporaryDirectory() as d:
        write_cam_dxf(cam, os.path.join(d, "cam.dxf"))


# ----------------------------------------------------------------------------------------- drawing
@pytest.mark.parametrize("make", [translating, oscillating])
def test_drawing_moves_artists_in_place(make):
    cam = make()
    anim = animate(cam, n=4)
    d = anim.drawing
    children = len(d.ax.get_children())
    for i in range(4):
        anim._func(i)
        # the roller is drawn about C, touching the profile at K; the profile turns with the cam
        C, K = d.motion.points["C"].p[i], d.motion.points["K"].p[i]
        roller, profile = d.lines_of("roller")[0], d.lines_of("profile")[0]
        assert np.allclose(np.hypot(*(np.column_stack(roller.get_data()) - C).T), cam.roller_radius)
        assert np.min(np.hypot(*(np.column_stack(profile.get_data()) - K).T)) < 0.02 * cam.base_radius
    assert len(d.ax.get_children()) == children
    assert "mechlab-play" in anim.to_jshtml()
    x0, x1, y0, y1 = draw(cam, 0.3).bounds()
    assert x1 - x0 > 2 * cam.base_radius and y1 - y0 > 2 * cam.base_radius
    plt.close("all")


# ------------------------------------------------------------------------------------------ explorer
def test_cam_explorer_shows_an_undercut_in_place_and_recovers():
    from mechlab.widgets.cam import cam_explorer

    ex = cam_explorer(question="Where does the roller stop fitting?")
    assert "Investigate:" in ex.widget.children[0].value
    assert ex.message == "" and "largest" in ex.status.value
    artists = [id(a) for a in ex.drawing.artists]
    ex.sliders["rise"].value = 40.0
    ex.sliders["base_radius"].value = 12.0
    assert "undercut" in ex.message and "φ =" in ex.message and not ex.ax_mech.get_visible()
    ex.sliders["rise"].value = 240.0        # with the return and the dwell, more than a turn
    assert "exceeds one turn" in ex.message
    ex.sliders["rise"].value = 120.0
    ex.sliders["base_radius"].value = 40.0
    assert ex.message == "" and ex.ax_mech.get_visible()
    ex.angle.value = 60.0
    assert [id(a) for a in ex.drawing.artists] == artists
    plt.close("all")


def _random_cam(law, rise, ret, dwell, stroke, base, offset, swinging, pivot, arm, roller=1.0):
    if swinging:
        pr = ml.CamProgramme(np.radians(stroke / 2), rise * DEG, ret * DEG, dwell * DEG, law=law)
        return ml.OscillatingRollerCam(pr, base, roller, pivot * (base + roller), arm * (base + roller))
    pr = ml.CamProgramme(stroke, rise * DEG, ret * DEG, dwell * DEG, law=law)
    return ml.TranslatingRollerCam(pr, base, roller, offset=offset * (base + roller))


@settings(max_examples=20, deadline=None, suppress_health_check=list(HealthCheck),
          phases=[Phase.explicit, Phase.reuse, Phase.generate])   # a failing cam is reported unshrunk: each costs 0.5 s
@given(law=st.sampled_from(list(LAWS)), rise=st.floats(20, 200), ret=st.floats(20, 200), dwell=st.floats(0, 100),
       stroke=st.floats(2, 60), base=st.floats(10, 80), offset=st.floats(-0.8, 0.8), swinging=st.booleans(),
       pivot=st.floats(1.2, 3), arm=st.floats(0.5, 2.5), share=st.floats(0.2, 1.5))
def test_the_undercut_flag_is_exact_against_dense_sampling(law, rise, ret, dwell, stroke, base, offset, swinging,
                                                          pivot, arm, share):
    # random cams, the roller a share of the pitch curve's smallest radius (from 200,001 samples): the exact flag
    # agrees with the samples, its radius is never above theirs, and its stretches hold every undercut sample
    assume(rise + ret + dwell <= 360)
    try:
        probe = _random_cam(law, rise, ret, dwell, stroke, base, offset, swinging, pivot, arm)
    except ml.DimensionError:
        assume(False)
    phi = np.linspace(0.0, 2 * np.pi, 200001)
    k = probe.curvature(phi)
    roller = share / k.max()
    cam = _random_cam(law, rise, ret, dwell, stroke, max(base - roller + 1.0, 1e-3), offset, swinging, pivot, arm,
                      roller)   # the same pitch curve (r_b + r_r kept) for a translating follower
    k = cam.curvature(phi)
    flag = cam.undercut()
    sampled = k * roller >= 1.0
    if flag is None:
        assert not sampled.any() or k.max() * roller - 1.0 < 1e-9
        return
    assert flag.radius <= 1 / k.max() * (1 + 1e-12) and flag.radius == pytest.approx(1 / k.max(), rel=1e-4)
    assert cam.curvature(flag.phi) == pytest.approx(1 / flag.radius, rel=1e-12)
    inside = np.zeros_like(sampled)
    for a, e in flag.spans:
        inside |= (phi >= a) & (phi <= e)
        assert np.all(cam.curvature(np.array([a, e])) * roller >= 1.0)   # the ends are on the undercut side
    # (a sample may sit on an end, where κ·r_r = 1 up to rounding)
    assert np.all((inside == sampled) | (np.abs(k * roller - 1.0) < 1e-9))
    assert np.all(cam.curvature(flag.where) * roller >= 1.0)


def test_an_undercut_narrower_than_any_grid_is_found():
    # the roller a hair larger than the smallest radius: the stretch is ~1e-4° wide, below the former
    # test's 0.05° grid; a hair smaller and the flag is None
    pr = ml.CamProgramme(30.0, 40 * DEG, 40 * DEG, 0.0, law="cycloidal (sine)")
    rho = ml.TranslatingRollerCam(pr, 25.0, 1.0).min_radius_of_curvature()
    wide = ml.TranslatingRollerCam(pr, 26.0 - rho.value * (1 + 1e-9), rho.value * (1 + 1e-9)).undercut()
    assert wide is not None and wide.radius == pytest.approx(rho.value, rel=1e-12)
    assert np.all(np.diff(wide.spans, axis=1) < 1e-3 * DEG)
    assert any(a <= rho.phi <= e for a, e in wide.spans)
    assert ml.TranslatingRollerCam(pr, 26.0 - rho.value * (1 - 1e-9), rho.value * (1 - 1e-9)).undercut() is None
    with pytest.warns(DeprecationWarning, match="n is ignored"):
        assert ml.TranslatingRollerCam(pr, 25.0, 1.0).undercut(7201) is None


@settings(max_examples=25, deadline=None, suppress_health_check=list(HealthCheck))
@given(law=st.sampled_from(list(LAWS)), rise=st.floats(30, 200), ret=st.floats(30, 200), dwell=st.floats(0, 100),
       stroke=st.floats(2, 60), base=st.floats(10, 80), roller=st.floats(0, 20), offset=st.floats(-0.8, 0.8),
       swinging=st.booleans(), pivot=st.floats(1.2, 3), arm=st.floats(0.5, 2.5))
def test_any_practical_cam_follows_its_law(law, rise, ret, dwell, stroke, base, roller, offset, swinging, pivot, arm):
    # any programme, law and size that cuts (no undercut) and works (|α| ≤ 60°): the solved motion is the law
    assume(rise + ret + dwell <= 360)
    try:
        if swinging:
            pr = ml.CamProgramme(np.radians(stroke / 2), rise * DEG, ret * DEG, dwell * DEG, law=law)
            cam = ml.OscillatingRollerCam(pr, base, roller, pivot * (base + roller), arm * (base + roller))
        else:
            pr = ml.CamProgramme(stroke, rise * DEG, ret * DEG, dwell * DEG, law=law)
            cam = ml.TranslatingRollerCam(pr, base, roller, offset=offset * (base + roller))
    except ml.DimensionError:
        assume(False)
    assume(cam.undercut() is None and np.max(np.abs(cam.pressure_angle(PHI))) <= 60 * DEG)
    mo = cam.motion(PHI)
    q = cam.follower(PHI)
    got = (mo.s, mo.ds, mo.dds) if cam.output == "position" else (mo.psi, mo.dpsi, mo.ddpsi)
    assert np.max(np.abs(got[0] - q.theta)) < 1e-8 * pr.stroke
    assert np.max(np.abs(got[1] - q.d)) < 1e-6 * np.max(np.abs(q.d))
    assert np.max(np.abs(got[2] - q.dd)[away_from_cuts(cam, PHI)]) < 1e-4 * np.max(np.abs(q.dd))


# ------------------------------------------------------------------------- jerk and the exact peaks
@pytest.mark.parametrize("make", [translating, oscillating])
def test_every_cam_reports_the_jerk_of_its_law(make):
    cam = make("modified sine")
    mo = cam.motion(PHI)
    h = 1e-5
    ok = away_from_cuts(cam, PHI, gap=3 * h)
    fd = (cam.follower(PHI + h).dd - cam.follower(PHI - h).dd) / (2 * h)
    assert np.allclose(mo.jerk[ok], fd[ok], atol=1e-5 * np.max(np.abs(fd)))
    assert np.max(np.abs(mo.jerk)) > 0 and np.all(mo.jerk[cam.in_dwell(PHI)] == 0)
    assert isinstance(cam.motion(1.0).jerk, float)   # a scalar angle gives a scalar jerk


@pytest.mark.parametrize("law", ["cycloidal (sine)", "modified trapezoid", "constant acceleration", "cosine"])
@pytest.mark.parametrize("make", [translating, oscillating])
def test_peaks_are_exact_and_beat_every_sample(make, law):
    cam = make(law)
    phi = np.linspace(0.0, 2 * np.pi, 200001)
    peak = cam.max_pressure_angle()
    alpha = np.abs(cam.pressure_angle(phi))
    # (where y'' jumps a peak may sit on a phase's end, a kink or a jump that the samples miss by up to a step)
    assert peak.value >= alpha.max() - 1e-12 and peak.value - alpha.max() < 1e-5
    assert abs(cam.pressure_angle(peak.phi)) == pytest.approx(peak.value, abs=1e-14)
    rho = cam.min_radius_of_curvature()
    k = cam.curvature(phi)
    assert 1 / rho.value >= k.max() - 1e-14 and rho.value == pytest.approx(1 / k.max(), rel=1e-4)
    assert cam.curvature(rho.phi) == pytest.approx(1 / rho.value, rel=1e-14)
    # the closed-form rates are the derivatives of the values they locate
    t, h = np.linspace(0.05, 5.0, 9), 1e-6
    t = t[~cam.in_dwell(t)]
    for value_and_rate in (cam._pressure_and_rate, cam._curvature_and_rate):
        fd = (value_and_rate(t + h)[0] - value_and_rate(t - h)[0]) / (2 * h)
        assert np.allclose(value_and_rate(t)[1], fd, atol=1e-7)
    assert "pressure angle" in str(peak) and "°" in str(peak)
