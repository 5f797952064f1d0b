"""Arcs and straight runs of coupler curves (mechlab.synthesis.coupler_dwell), checked against independent
computations: a brute-force grid search of centres, planted exact circles and lines, Chebyshev's lambda through
the course's own lambda synthesis, and every six-bar simulated through the structure builder."""

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

import mechlab as ml
from mechlab.errors import CouplerFitError, DimensionError, InfeasibleDesignError
from mechlab.synthesis import coupler_dwell as cd


def lambda_linkage(r, a, delta):
    """Chebyshev's lambda as a coupler four-bar: AB = BC = BD = 1, D = B + Rot(δ)(A − B), i.e. (1 − cos δ, −sin δ)
    in the coupler's frame."""
    return ml.coupler_fourbar(r, 1.0, 1.0, a, (1 - np.cos(delta), -np.sin(delta)))


def half_range(z, centres):
    """The minimax ripple about each centre: half the range of the distances (brute force)."""
    rho = np.hypot(z[None, :, 0] - centres[:, None, 0], z[None, :, 1] - centres[:, None, 1])
    return 0.5 * (rho.max(1) - rho.min(1))


def brute_circle(z, lo, hi, levels=6, k=121):
    """The best centre on a grid over the box [lo, hi], zoomed in around the best point level by level."""
    best = None
    for _ in range(levels):
        xs, ys = np.linspace(lo[0], hi[0], k), np.linspace(lo[1], hi[1], k)
        C = np.stack(np.meshgrid(xs, ys), -1).reshape(-1, 2)
        f = half_range(z, C)
        i = int(np.argmin(f))
        best = (C[i], float(f[i]))
        span = 4 * (np.asarray(hi) - np.asarray(lo)) / (k - 1)
        lo, hi = best[0] - span, best[0] + span
    return best


# ----------------------------------------------------------------------------------------------------------------
# The four-bar
# ----------------------------------------------------------------------------------------------------------------
def test_coupler_fourbar_is_the_builders_fourbar_and_its_point():
    lk = ml.coupler_fourbar(1.0, 3.0, 3.5, 4.0, (1.5, 0.8))
    fb = ml.FourBar(1.0, 3.0, 3.5, 4.0)
    phi = lk.turn(37)
    mo, ref = lk.motion(phi), fb.motion(phi)
    assert np.allclose(mo.psi, ref.psi, atol=1e-12)
    A, B = mo.points["A"].p, mo.points["B"].p
    u = (B - A) / 3.0
    v = np.stack([-u[:, 1], u[:, 0]], 1)
    assert np.allclose(mo.points["P"].p, A + 1.5 * u + 0.8 * v, atol=1e-12)


def test_lambda_as_a_coupler_fourbar_traces_the_lambda_curve():
    delta = np.radians(150)
    lk, lam = lambda_linkage(0.3, 0.9, delta), ml.LambdaMechanism(0.3, 0.9, delta)
    phi = lk.turn(101)
    assert np.allclose(lk.motion(phi).points["P"].p, lam.coupler_point(phi), atol=1e-13)


# ----------------------------------------------------------------------------------------------------------------
# Exact fits against independent computations
# ----------------------------------------------------------------------------------------------------------------
@pytest.mark.parametrize("interval", [(0.3, 1.9), (2.0, 3.6), (4.0, 6.5)])
def test_minimax_circle_beats_and_matches_a_brute_force_grid_of_centres(interval):
    lk = ml.coupler_fourbar(1.0, 3.0, 3.0, 3.5, (2.0, 1.2))
    fit = ml.fit_arc(lk, "P", interval, n=360)
    z = lk.motion(np.linspace(*interval, int(np.ceil((interval[1] - interval[0]) / (2 * np.pi / 360))) + 1)) \
        .points["P"].p
    # the brute force knows nothing of the fit: a box of ±4 curve sizes about the samples' mean
    size = float(np.hypot(*np.ptp(z, 0)))
    lo, hi = z.mean(0) - 4 * size, z.mean(0) + 4 * size
    centre, ripple = brute_circle(z, lo, hi)
    assert ripple >= fit.ripple * (1 - 1e-9)                    # no grid centre beats the minimax fit
    assert ripple <= fit.ripple * (1 + 1e-3)                    # and the grid finds it
    assert np.hypot(*(centre - fit.centre)) <= 1e-2 * fit.radius
    rho = np.hypot(*(z - fit.centre).T)
    assert abs(0.5 * (rho.max() + rho.min()) - fit.radius) <= 1e-12 * fit.radius
    assert abs(0.5 * np.ptp(rho) - fit.ripple) <= 1e-12 * fit.radius


def test_a_planted_equiripple_circle_is_recovered():
    # ρ = R + ε cos 4θ on θ ∈ [0, π] alternates 5 times about R: the best circle is the planted one (to ε²/R)
    theta = np.linspace(0.0, np.pi, 401)
    R, eps, c = 2.0, 1e-6, np.array([0.3, -0.7])
    rho = R + eps * np.cos(4 * theta)
    z = c + rho[:, None] * np.stack([np.cos(theta), np.sin(theta)], 1)
    centre, radius, ripple = cd._minimax_circle(z)
    assert np.hypot(*(centre - c)) < 1e-10
    assert abs(radius - R) < 1e-10 and abs(ripple - eps) < 1e-10


@pytest.mark.parametrize("interval", [(0.3, 1.9), (2.0, 3.6), (5.3, 6.9), (np.pi - 1.0, np.pi + 1.0)])
def test_the_exchange_and_the_linear_programmes_reach_the_same_circle(monkeypatch, interval):
    """Remez's exchange (the fast route) and the sequential linear programmes (the robust one) are two ways to
    one optimum: forcing the second gives the first's circle."""
    lk = ml.coupler_fourbar(1.0, 3.0, 3.0, 3.5, (2.0, 1.2))
    z = lk.motion(np.linspace(*interval, 181)).points["P"].p
    fast = cd._minimax_circle(z)
    monkeypatch.setattr(cd, "_exchange", lambda *args, **kwargs: None)
    robust = cd._minimax_circle(z)
    assert abs(fast[2] - robust[2]) <= 1e-6 * fast[2]
    assert np.hypot(*(fast[0] - robust[0])) <= 1e-4 * fast[1]
    assert brute_circle(z, fast[0] - 0.05, fast[0] + 0.05)[1] >= fast[2] * (1 - 1e-9)


def test_exact_circles_of_a_fourbar_are_recovered():
    lk = ml.coupler_fourbar(1.0, 3.0, 3.5, 4.0, (1.0, 0.5))
    pin = ml.fit_arc(lk, "A", (0.2, 3.0))                    # the crank pin: a circle about O
    assert np.allclose(pin.centre, (0, 0), atol=1e-12) and abs(pin.radius - 1) < 1e-12 and pin.ripple < 1e-12
    assert abs(pin.extent - 2.8) < 1e-12
    tip = ml.fit_arc(lk, "B", (1.0, 2.5))                    # the rocker's tip: an arc about E
    assert np.allclose(tip.centre, (4, 0), atol=1e-11) and abs(tip.radius - 3.5) < 1e-11 and tip.ripple < 1e-11
    longest = ml.coupler_arcs(lk, "B", count=1)[0]           # the whole cycle lies on the rocker's circle
    assert longest.crank_interval[1] - longest.crank_interval[0] > 2 * np.pi - 2 * (2 * np.pi / 720)
    assert np.allclose(longest.centre, (4, 0), atol=1e-9)


def test_exact_lines_are_recovered():
    sc = ml.Linkage({"O": (0, 0)}, ml.Crank("O", "A", 1.0)).rrp("A", "B", 3.0, ("O", 0.4))
    run = ml.fit_run(sc, "B", (0.5, 2.5))                    # the slider on its guide at 0.4 rad
    assert run.ripple < 1e-12
    assert abs(np.sin(run.direction - 0.4)) < 1e-12
    s = sc.motion(np.linspace(0.5, 2.5, 200)).s
    assert abs(run.length - np.ptp(s)) < 1e-6                # the stroke over the interval (sampled ends exact)
    best = ml.coupler_runs(sc, "B", dwell=np.radians(100), count=2)
    assert all(r.ripple < 1e-12 for r in best)


def test_the_minimax_line_beats_every_direction_of_a_brute_force_scan():
    lk = ml.coupler_fourbar(1.0, 3.0, 3.0, 3.5, (2.0, 1.2))
    interval = (5.3, 6.9)
    run = ml.fit_run(lk, "P", interval, n=360)
    z = lk.motion(np.linspace(*interval, int(np.ceil(1.6 / (2 * np.pi / 360))) + 1)).points["P"].p
    th = np.linspace(0, np.pi, 200001)
    normal = np.stack([-np.sin(th), np.cos(th)], 1)
    widths = 0.5 * np.ptp(z @ normal.T, axis=0)
    assert widths.min() >= run.ripple * (1 - 1e-12)
    # the scan's step dθ leaves the best direction by dθ/2 at most, widening by ≤ length·dθ/2 (a kink, not a minimum
    # of zero slope)
    assert widths.min() <= run.ripple + run.length * (th[1] - th[0]) / 2
    u = np.array([np.cos(run.direction), np.sin(run.direction)])
    across = (z - run.point) @ np.array([-u[1], u[0]])
    assert abs(across.max() + across.min()) < 1e-12 and abs(across.max() - run.ripple) < 1e-12


# ----------------------------------------------------------------------------------------------------------------
# Chebyshev's lambda against the course's lambda synthesis
# ----------------------------------------------------------------------------------------------------------------
def test_lambda_arc_equals_circle_guiding():
    """circle_guiding solves the equal-ripple equations on the continuous curve; the fit here is exact on the
    samples, so its ripple can only fall short of E, by the sampled extremes' miss ½|ρ''|(h/2)² = O(h²): measured
    -1.1e-4·E at n = 720, -9.4e-7·E at n = 7200; the centre and R move with it (7e-7, 4e-9)."""
    delta, a, dwell = np.radians(150), 0.9, np.radians(120)
    guide = ml.circle_guiding(delta, a, dwell)
    lk = lambda_linkage(guide.r, a, delta)
    fit = ml.fit_arc(lk, "P", (np.pi - dwell / 2, np.pi + dwell / 2), n=7200)
    assert guide.E * (1 - 1e-5) <= fit.ripple <= guide.E * (1 + 1e-9)
    assert np.hypot(*(np.array(fit.centre) - guide.centre)) < 1e-7
    assert abs(fit.radius - guide.R) < 1e-7
    # the search finds the lambda's designed dwell as the best 120° arc of its curve, centred on φ = π
    best = ml.coupler_arcs(lk, dwell=dwell, count=1)[0]
    assert abs(0.5 * sum(best.crank_interval) - np.pi) < 1e-9
    assert abs(best.ripple / guide.E - 1) < 2e-4 and np.hypot(*(np.array(best.centre) - guide.centre)) < 1e-5


def test_lambda_run_equals_straight_guiding():
    """Chebyshev's lambda (δ = π, a = 0.8, r = 0.4): the straight band over 2α = 180° has E = 1.9507e-3 and lies
    across the symmetry axis (horizontal here) at height Y; sampled at n = 7200 the minimax line's ripple falls
    short of E by 3.5e-7·E (the O(h²) miss of the sampled extremes)."""
    guide = ml.straight_guiding(np.pi, 0.8, np.pi)
    lam = lambda_linkage(guide.r, 0.8, np.pi)
    run = ml.fit_run(lam, "P", (np.pi / 2, 3 * np.pi / 2), n=7200)
    assert guide.E * (1 - 1e-5) <= run.ripple <= guide.E * (1 + 1e-9)
    assert abs(np.sin(run.direction)) < 1e-9                  # across the vertical axis
    assert abs(run.point[1] - guide.Y) < 1e-5 * guide.E + 1e-12
    best = ml.coupler_runs(lam, dwell=np.pi, count=1)[0]
    assert abs(0.5 * sum(best.crank_interval) - np.pi) < 1e-9 and abs(best.ripple / guide.E - 1) < 1e-4


def test_lambda_rocker_sixbar_equals_mchv1():
    """The course's МЧВ1 attaches a rod of length R to D and a rocker pivoted at F; given the same pivot,
    arc_dwell_sixbar builds the same six-bar from the fitted arc: the rocker's angle agrees over the whole turn
    to the fitted centre's distance from the designed one (1e-8 at n = 7200)."""
    delta, a, dwell = np.radians(150), 0.9, np.radians(120)
    guide = ml.circle_guiding(delta, a, dwell)
    course = ml.mchv1(guide, 1.0, np.radians(20))
    lk = lambda_linkage(guide.r, a, delta)
    fit = ml.fit_arc(lk, "P", (np.pi - dwell / 2, np.pi + dwell / 2), n=7200)
    six = ml.arc_dwell_sixbar(lk, "P", fit, output_pivot=(course.fx, course.fy))
    phi = lk.turn(361)
    ours, theirs = six.motion(phi).psi, course.motion(phi).psi
    diff = np.angle(np.exp(1j * (ours - theirs)))
    assert np.max(np.abs(diff)) < 1e-6
    check = ml.check_dwell(six, fit.crank_interval)
    assert abs(check.swing - np.radians(20)) < 0.25 * np.radians(20)   # mchv1's designed swing (its own tolerance)


def test_lambda_slotted_sixbar_dwells_like_the_course_mchv3():
    guide = ml.straight_guiding(np.pi, 0.8, np.pi)
    lam = lambda_linkage(guide.r, 0.8, np.pi)
    run = ml.fit_run(lam, "P", (np.pi / 2, 3 * np.pi / 2))
    course = ml.mchv3_oscillating(guide, 0.5)                 # the course's pivot: on the line, beyond the run
    six = ml.run_dwell_sixbar(lam, "P", run, pivot=course.P)
    phi = lam.turn(361)
    diff = np.angle(np.exp(1j * (six.motion(phi).psi - course.motion(phi).psi)))
    assert np.max(np.abs(diff - diff[0])) < 1e-9              # the same slotted link's law (up to its zero)


# ----------------------------------------------------------------------------------------------------------------
# The six-bars dwell as fitted
# ----------------------------------------------------------------------------------------------------------------
def dwell_bound(six, fit, check):
    """First order in ripple / R: P at R + e from Q moves D by e / sin μ along the rocker's tangent, so the rocker
    turns by at most 2·ripple / (b sin μ) over the dwell (μ the rod-rocker angle over the dwell; check's
    transmission, the least over the cycle of both dyads, is no larger)."""
    dyad = six.groups[-1]
    pts = six.motion(np.linspace(*fit.crank_interval, 200)).points
    D, P, F = (pts[k].p for k in (dyad.joint, dyad.first, dyad.second))
    u, v = P - D, F - D
    mu = np.arccos(np.clip(np.sum(u * v, 1) / (np.hypot(*u.T) * np.hypot(*v.T)), -1, 1))
    assert np.min(np.minimum(mu, np.pi - mu)) >= check.transmission - 1e-9
    return 2 * fit.ripple / (dyad.second_length * np.sin(np.min(np.minimum(mu, np.pi - mu))))


def test_arc_sixbar_dwells_as_fitted():
    lk = ml.coupler_fourbar(1.0, 3.0, 3.0, 3.5, (2.0, 1.2))
    for arc in ml.coupler_arcs(lk, dwell=np.radians(90)):
        six = ml.arc_dwell_sixbar(lk, "P", arc)
        check = ml.check_dwell(six, arc.crank_interval)
        assert check.dwell_error <= 1.1 * dwell_bound(six, arc, check)
        assert check.transmission > np.radians(20)
        D = six.motion(np.linspace(*arc.crank_interval, 50)).points["D"].p
        assert np.max(np.hypot(*(D - arc.centre).T)) <= 1.1 * arc.ripple / np.sin(check.transmission)
    best = ml.coupler_arcs(lk, dwell=np.radians(90), count=1)[0]
    check = ml.check_dwell(ml.arc_dwell_sixbar(lk, "P", best), best.crank_interval)
    assert check.dwell_error < 0.01 * check.swing


def test_run_sixbar_dwells_as_fitted():
    lk = ml.coupler_fourbar(1.0, 3.0, 3.0, 3.5, (2.0, 1.2))
    run = ml.coupler_runs(lk, dwell=np.radians(60), count=1)[0]
    six = ml.run_dwell_sixbar(lk, "P", run)
    check = ml.check_dwell(six, run.crank_interval)
    G = np.array(dict(six.frame)["G"])
    # P stays within ripple of the line through G: the slot turns by at most 2·ripple / (nearest distance)
    P = lk.motion(np.linspace(*run.crank_interval, 200)).points["P"].p
    assert check.dwell_error <= 2 * run.ripple / np.hypot(*(P - G).T).min() * 1.01
    assert check.output == "angle" and check.swing > 10 * check.dwell_error


def test_check_dwell_reads_a_slider_and_every_rrr_dyad():
    sc = ml.Linkage({"O": (0, 0)}, ml.Crank("O", "A", 1.0)).rrp("A", "B", 3.0, "O")
    check = ml.check_dwell(sc, (0.0, 0.5))
    s = 1.0 * np.cos([0.0, 0.5]) + np.sqrt(9 - np.sin([0.0, 0.5]) ** 2)
    assert check.output == "position" and abs(check.swing - 2.0) < 1e-9        # the in-line stroke, 2 × crank
    assert abs(check.dwell_error - (s[0] - s[1])) < 1e-12                      # s falls monotonically there
    fb = ml.coupler_fourbar(1.0, 3.0, 3.0, 3.5)
    mu = ml.FourBar(1.0, 3.0, 3.0, 3.5).motion(np.arange(720) * np.pi / 360).transmission
    assert abs(ml.check_dwell(fb, (0.0, 1.0)).transmission - np.min(np.minimum(mu, np.pi - mu))) < 1e-12


@st.composite
def crank_rockers(draw):
    """Crank-rockers: the crank shortest and s + l < p + q by a margin (Grashof), coupler point anywhere near."""
    crank = 1.0
    coupler, rocker, frame = (draw(st.floats(1.5, 5.0)) for _ in range(3))
    longest, others = max(coupler, rocker, frame), sorted((coupler, rocker, frame))[:2]
    assume(crank + longest < sum(others) - 0.2)
    u, v = draw(st.floats(-1.0, 2.0)), draw(st.floats(-1.5, 1.5))
    return ml.coupler_fourbar(crank, coupler, rocker, frame, (u * coupler, v * coupler), draw(st.sampled_from([1, -1])))


@settings(max_examples=20, deadline=None, suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much])
@given(crank_rockers(), st.floats(np.radians(40), np.radians(150)))
def test_random_crank_rockers_every_sixbar_dwells_as_fitted(lk, dwell):
    arcs = ml.coupler_arcs(lk, dwell=dwell, count=2)
    for arc in arcs:
        assert abs(arc.crank_interval[1] - arc.crank_interval[0] - dwell) < 1e-12
        # the exact fit is optimal: no nearby centre does better (a ring of trial centres)
        z = lk.motion(np.linspace(*arc.crank_interval, int(np.ceil(dwell / (2 * np.pi / 720))) + 1)).points["P"].p
        ring = np.array(arc.centre) + 1e-3 * arc.radius * np.stack(
            [np.cos(np.arange(16) * np.pi / 8), np.sin(np.arange(16) * np.pi / 8)], 1)
        assert half_range(z, ring).min() >= arc.ripple * (1 - 1e-9)
        try:
            six = ml.arc_dwell_sixbar(lk, "P", arc)
        except InfeasibleDesignError:
            continue   # no pivot of the default set closes the dyad over the cycle: refused by name
        check = ml.check_dwell(six, arc.crank_interval)
        if arc.ripple < 0.01 * arc.radius:   # the bound is first order in ripple / R
            assert check.dwell_error <= 1.1 * dwell_bound(six, arc, check) + 1e-12
    for run in ml.coupler_runs(lk, dwell=dwell, count=1):
        assert run.ripple <= 0.5 * run.length + 1e-12


def test_longest_arc_meets_its_ripple_bound_and_is_maximal():
    lk = ml.coupler_fourbar(1.0, 3.0, 3.0, 3.5, (2.0, 1.2))
    arcs = ml.coupler_arcs(lk, max_ripple=1e-3)
    assert arcs
    h = 2 * np.pi / 720
    for arc in arcs:
        assert arc.ripple <= 1e-3 * arc.radius
        # one sample longer at the end breaks the bound (the longest on the grid)
        longer = ml.fit_arc(lk, "P", (arc.crank_interval[0], arc.crank_interval[1] + h))
        assert longer.ripple > 1e-3 * longer.radius
    widths = [a.crank_interval[1] - a.crank_interval[0] for a in arcs]
    assert widths == sorted(widths, reverse=True)


def test_longest_run_meets_its_ripple_bound():
    lam = lambda_linkage(0.4, 0.8, np.pi)
    run = ml.coupler_runs(lam, max_ripple=2e-3, count=1)[0]
    assert run.ripple <= 2e-3 * run.length
    assert run.crank_interval[1] - run.crank_interval[0] > np.radians(180)   # the lambda's long straight part


# ----------------------------------------------------------------------------------------------------------------
# Bad input
# ----------------------------------------------------------------------------------------------------------------
def test_bad_input_raises_named_errors():
    lk = ml.coupler_fourbar(1.0, 3.0, 3.0, 3.5, (2.0, 1.2))
    with pytest.raises(CouplerFitError, match="no joint 'Q'"):
        ml.coupler_arcs(lk, "Q")
    with pytest.raises(CouplerFitError, match="does not move"):   # a frame point: nothing to fit
        ml.coupler_runs(lk, "E", dwell=1.0)
    with pytest.raises(CouplerFitError, match="does not move"):
        ml.fit_arc(lk, "O", (0.0, 1.0))
    with pytest.raises(DimensionError):
        ml.coupler_arcs(lk, dwell=-1.0)
    with pytest.raises(DimensionError):
        ml.coupler_arcs(lk, dwell=7.0)
    with pytest.raises(CouplerFitError, match="fewer than 5"):
        ml.coupler_arcs(lk, dwell=np.radians(1))
    with pytest.raises(DimensionError):
        ml.coupler_runs(lk, n=3)
    with pytest.raises(CouplerFitError, match="start < stop"):
        ml.fit_arc(lk, "P", (2.0, 1.0))
    with pytest.raises(CouplerFitError):
        ml.fit_run(lk, "P", (1.0,))
    with pytest.raises(TypeError):
        ml.arc_dwell_sixbar(lk, "P", (0.0, 0.0))
    with pytest.raises(DimensionError):
        ml.coupler_fourbar(1.0, -3.0, 3.0, 3.5)
    arc = ml.coupler_arcs(lk, dwell=np.radians(90), count=1)[0]
    with pytest.raises(InfeasibleDesignError, match="centre"):
        ml.arc_dwell_sixbar(lk, "P", arc, output_pivot=arc.centre)
    far = np.array(arc.centre) + (0.01, 0.0)                  # a rocker far shorter than P's excursions: cannot close
    with pytest.raises(InfeasibleDesignError, match="close"):
        ml.arc_dwell_sixbar(lk, "P", arc, output_pivot=far)
    run = ml.coupler_runs(lk, dwell=np.radians(60), count=1)[0]
    on_curve = lk.motion(np.array([1.0])).points["P"].p[0]
    with pytest.raises(InfeasibleDesignError, match="passes through"):
        ml.run_dwell_sixbar(lk, "P", run, pivot=on_curve)


def test_a_crank_that_only_rocks_is_searched_within_its_reach():
    lk = ml.coupler_fourbar(3.0, 2.0, 4.0, 4.0, (1.0, 0.5))  # non-Grashof: the crank rocks
    ranges = lk.crank_ranges()
    assert len(ranges) == 2                                   # the two assemblies' halves of the curve
    arcs = ml.coupler_arcs(lk, dwell=np.radians(30))
    assert arcs
    for arc in arcs:
        assert any(lo <= arc.crank_interval[0] and arc.crank_interval[1] <= hi for lo, hi in ranges)
    with pytest.raises(CouplerFitError, match="reaches no interval"):
        ml.coupler_arcs(lk, dwell=max(hi - lo for lo, hi in ranges) + 0.1)
