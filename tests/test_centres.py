"""Instantaneous centres and centrodes (seed 002): Kennedy's construction against the
links' velocity twists, analogs read back from the centres against loop closure,
centrodes of the elliptic trammel (Cardan circles) and of the antiparallelogram
(ellipses and hyperbolas), the seed's complex-number formulas (7.6)-(7.9)."""

import numpy as np
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st
from strategies import central_difference, fourbars, revolving_fourbars, revolving_slider_cranks

from mechlab import (
    AssemblyError,
    DimensionError,
    FourBar,
    MechanismError,
    SineMechanism,
    SingularityError,
    SliderCrank,
    SlottedLink,
)
from mechlab.analysis.centres import centrodes, kennedy
from mechlab.analysis.centres.centrodes import rolling_speeds
from mechlab.analysis.centres.homogeneous import (
    Centre,
    CentreAtInfinity,
    IndeterminateCentre,
    at_infinity,
    finite,
    in_frame,
    line_through,
    meet,
    segments,
    separation,
)
from mechlab.analysis.centres.instant import instant_centres
from mechlab.analysis.centres.kennedy import centre_count, five_link_higher_pair
from mechlab.geometry import relative, vector_angle
from mechlab.mechanisms.antiparallelogram import Antiparallelogram
from mechlab.mechanisms.trammel import EllipticTrammel

SETTINGS = settings(max_examples=40, deadline=None)


def agree(ic_a, ic_b):
    """Largest projective separation of the same centres found two ways."""
    return max(float(separation(ic_a.centres[p], ic_b.centres[p], ic_a.structure.scale).max())
               for p in ic_a.centres)


# -- homogeneous points and lines ---------------------------------------------------------------------
def test_meet_of_crossing_parallel_and_coincident_lines():
    n = 3
    p, q = finite(np.array([[0.0, 0.0]] * n)), finite(np.array([[1.0, 1.0]] * n))
    r, s = finite(np.array([[0.0, 2.0]] * n)), finite(np.array([[2.0, 0.0]] * n))
    x = meet(line_through(p, q), line_through(r, s))
    assert np.allclose(x.xy, [[1.0, 1.0]] * n, atol=1e-15)
    # parallel lines y = x and y = x + 1 meet at infinity in direction (1, 1)/√2
    t, u = finite(np.array([[0.0, 1.0]] * n)), finite(np.array([[1.0, 2.0]] * n))
    x = meet(line_through(p, q), line_through(t, u))
    assert not x.finite.any() and np.allclose(x.direction, [[2**-0.5, 2**-0.5]] * n)
    with pytest.raises(CentreAtInfinity, match="lies at infinity"):
        _ = x.xy
    assert x.masked().mask.all()
    # a point at infinity joins a finite one into the line through it in that direction
    vertical = line_through(p, at_infinity((0.0, -1.0), n))
    assert np.allclose(np.abs(vertical[:, :2]), [[1.0, 0.0]] * n) and np.allclose(vertical[:, 2], 0)
    with pytest.raises(IndeterminateCentre, match="undefined"):
        meet(line_through(p, q), line_through(p, q))
    with pytest.raises(IndeterminateCentre, match="coincide"):
        line_through(p, p)


def test_in_frame_and_segments():
    c = Centre(np.array([[2.0, 0.0, 1.0], [1.0, 0.0, 0.0], [0.0, 3.0, 1.0], [0.0, 4.0, 1.0], [0.0, 50.0, 1.0]]))
    q = in_frame(c, np.array([[1.0, 0.0]] * 5), np.full(5, np.pi / 2))
    assert np.allclose(q.h[0], [0.0, -1.0, 1.0]) and np.allclose(q.h[1], [0.0, -1.0, 0.0])
    pieces = segments(c, clip=10.0)
    assert len(pieces) == 1 and np.allclose(pieces[0], [[0, 3], [0, 4]])


def test_centre_count_and_too_few_centres():
    assert [centre_count(n) for n in (3, 4, 5, 6)] == [3, 6, 10, 15]
    with pytest.raises(MechanismError):
        centre_count(1)
    with pytest.raises(MechanismError, match="cannot locate"):
        kennedy(4, {(0, 1): finite(np.zeros((2, 2)))})


# -- four-bar, slider-crank, slotted link, sine mechanism ------------------------------------------------
def check_mechanism(m, phi, tol=1e-9):
    ic = instant_centres(m, phi)
    iv = instant_centres(m, phi, method="velocity")
    assert agree(ic, iv) < tol                                    # Kennedy = twists
    assert ic.collinearity() < 1e-9                               # Kennedy's theorem itself
    law = ic.motion.output.d
    scale = max(1.0, float(np.abs(law).max()))
    assert np.abs(ic.output_analog() - law).max() < tol * scale   # analogs from the centres
    return ic


@SETTINGS
@given(revolving_fourbars())
def test_fourbar_centres(fb):
    phi = fb.turn(181)
    ic = check_mechanism(fb, phi)
    O, A, B, E = (ic.motion.points[k].p for k in "OABE")
    assert [ic.label(*p) for p in [("crank", "rocker"), ("coupler", "frame")]] == ["P13", "P24"]
    p13, p24 = ic("crank", "rocker"), ic("coupler", "frame")
    fin = p13.finite
    assert np.abs(p13.h[fin, 1]).max() < 1e-9 * fb.ground           # P13 on the frame line OE
    fin = p24.finite                                                 # P24 on OA and on EB
    cross = lambda u, v: u[:, 0] * v[:, 1] - u[:, 1] * v[:, 0]       # noqa: E731
    P = p24.h[fin, :2]
    assert np.abs(cross(P - O[fin], A[fin] - O[fin]) / np.hypot(*P.T).clip(1)).max() < 1e-9 * fb.ground
    assert np.abs(cross(P - E[fin], B[fin] - E[fin]) / np.hypot(*(P - E[fin]).T).clip(1)).max() < 1e-9 * fb.ground
    # the coupler's angular analog from the centres equals the loop-closure one
    loop = vector_angle(relative(ic.motion.points["B"], ic.motion.points["A"])).d
    assert np.abs(ic.angular_analog("coupler") - loop).max() < 1e-9 * (1 + np.abs(loop).max())


@SETTINGS
@given(fourbars())
def test_rocking_fourbar_centres(fb):
    check_mechanism(fb, fb.cycle(101))


@SETTINGS
@given(revolving_slider_cranks())
def test_slider_crank_centres(sc):
    ic = check_mechanism(sc, sc.turn(181))
    assert not ic("slider", "frame").finite.any()                  # P34 at infinity, normal to the guide
    assert np.allclose(ic("slider", "frame").direction, [0.0, 1.0])
    # classic: s' is the crank-pivot-to-P13 distance on the normal to the guide through O
    p13 = ic("crank", "slider").xy
    assert np.abs(p13[:, 0]).max() < 1e-9 * sc.rod
    assert np.allclose(-p13[:, 1], ic.motion.ds, atol=1e-9 * sc.rod)


@SETTINGS
@given(st.floats(0.1, 3.0).filter(lambda lam: abs(lam - 1) > 0.05), st.floats(0.3, 5.0))
def test_slotted_link_centres_via_the_common_normal(lam, d):
    m = SlottedLink(lam * d, d)
    ic = check_mechanism(m, m.turn(181))
    assert ic.steps == [((0, 1), ["P13P23", "normal"])]
    # P12 lies on the frame line O-B and on the normal to the slot through A
    p12, A, B = ic("crank", "slotted link"), ic.motion.points["A"].p, ic.motion.points["B"].p
    fin = p12.finite                # at infinity where the slot stands perpendicular to OB (λ > 1)
    assert fin.all() or (lam > 1 and np.allclose(np.abs(A[~fin, 0] - B[~fin, 0]), 0, atol=1e-9))
    P = p12.h[fin, :2]
    assert np.abs(P[:, 1]).max() < 1e-9 * d
    assert np.abs(np.sum((P - A[fin]) * (A[fin] - B[fin]), axis=1)).max() < 1e-9 * d * d


def test_sine_mechanism_centres():
    m = SineMechanism(2.0)
    phi = m.turn(73)
    ic = check_mechanism(m, phi)
    assert np.allclose(ic("crank", "yoke").xy, np.column_stack([0 * phi, 2.0 * np.sin(phi)]), atol=1e-14)
    assert np.allclose(ic.output_analog(), -2.0 * np.sin(phi), atol=1e-14)


def test_parallelogram_has_a_centre_at_infinity():
    fb = FourBar(1.0, 4.0, 1.0, 4.0, 1)  # a parallelogram on 0 < φ < π (change-point linkage)
    phi = np.linspace(0.2, 2.9, 7)
    ic = instant_centres(fb, phi)
    assert np.allclose(ic.motion.psi, phi)
    p13 = ic("crank", "rocker")
    assert not p13.finite.any() and np.allclose(p13.direction, [1.0, 0.0])   # ω3 = ω1: P13 at infinity
    assert np.allclose(ic.output_analog(), 1.0, atol=1e-12)
    assert not ic("coupler", "frame").finite.any()                          # the coupler translates
    assert np.allclose(ic.angular_analog("coupler"), 0.0, atol=1e-12)


# -- seed 002, Fig. 7.3: five links, one higher pair ------------------------------------------------------
points = st.lists(st.floats(-3, 3), min_size=14, max_size=14)


@settings(max_examples=100, deadline=None)
@given(points)
def test_five_link_mechanism_with_a_higher_pair(xs):
    arr = np.array(xs).reshape(7, 1, 2)
    P15, P12, P23, P34, P45, A, nrm = arr
    pts = np.concatenate([P15, P12, P23, P34, P45])
    gaps = np.hypot(*(pts[:, None] - pts[None]).reshape(-1, 2).T)
    if np.sort(gaps)[5] < 0.2 or np.hypot(*nrm[0]) < 0.2:
        return  # keep away from coincident pins and a vanishing normal
    try:
        by_k, by_t, steps = five_link_higher_pair(P15, P12, P23, P34, P45, A, nrm, scale=3.0)
    except SingularityError:  # IndeterminateCentre, or singular velocity constraints
        return  # a degenerate snapshot (e.g. the normal through P23 and P34): nothing to compare
    for p in by_k:
        s = separation(by_k[p], by_t[p], 3.0)
        if by_k[p].finite.all() and np.hypot(*by_k[p].h[0, :2]) > 1e6:
            continue  # nearly parallel lines: the point is far and ill-conditioned
        assert s.max() < 1e-6, (by_k[p].name, by_k[p].h, by_t[p].h)
    assert next(s[0] for s in steps) == (1, 3)  # P24 first, from the normal, as in the seed


def test_five_link_check_line_of_the_seed():
    """The seed's check: P25 lies on P35P23 (and the seed's whole construction order works)."""
    rng = np.random.default_rng(7)
    args = [rng.normal(size=(50, 2)) for _ in range(7)]
    by_k, _, _ = five_link_higher_pair(*args)
    from mechlab.analysis.centres.homogeneous import line_through as lt
    L = lt(by_k[(1, 2)], by_k[(2, 4)])
    h = by_k[(1, 4)].h
    assert np.abs(np.sum(L * h / np.linalg.norm(h, axis=1)[:, None], axis=1)).max() < 1e-9


# -- elliptic trammel: Cardan circles -----------------------------------------------------------------
@SETTINGS
@given(st.floats(0.2, 5.0), st.floats(15.0, 165.0))
def test_elliptic_trammel(l, beta_deg):
    m = EllipticTrammel(l, np.radians(beta_deg))
    phi = m.turn(721)
    mo = m.motion(phi)
    A, B, C = (mo.points[k] for k in "ABC")
    ub = np.array([np.cos(m.beta), np.sin(m.beta)])
    assert np.abs(A.p[:, 1]).max() == 0.0                                      # A on its guide
    assert np.abs(B.p[:, 0] * ub[1] - B.p[:, 1] * ub[0]).max() < 1e-12 * l     # B on its guide
    assert np.abs(np.hypot(*(B.p - A.p).T) - l).max() < 1e-12 * l              # the rod
    theta = np.arctan2(*(B.p - A.p).T[::-1])
    assert np.abs(np.angle(np.exp(1j * (theta - m.rod_angle(phi))))).max() < 1e-12
    assert np.abs(np.hypot(*(C.p - A.p).T) - np.hypot(*(C.p - B.p).T)).max() < 1e-12 * l  # C circumcentre
    h = phi[1] - phi[0]
    for pth in (A, B, C):
        assert np.abs(central_difference(pth.p, h) - pth.d[1:-1]).max() < 3e-5 * m.fixed_radius
        assert np.abs(central_difference(pth.d, h) - pth.dd[1:-1]).max() < 3e-5 * m.fixed_radius
    ic = check_mechanism(m, phi[:-1])
    cd = centrodes(m, "rod", phi=phi[:-1])
    R = l / np.sin(m.beta)
    assert np.abs(np.hypot(*cd.fixed.xy.T) - R).max() < 1e-12 * R            # (7.12): circle, centre O
    centre = np.array([l / 2, l / (2 * np.tan(m.beta))])                     # (7.16): a = l/2, b = (l/2)ctg β
    mv = cd.moving.xy
    if np.abs(mv - centre).max() > 2 * R:  # the y₁ axis may point the other way
        centre[1] = -centre[1]
    assert np.abs(np.hypot(*(mv - centre).T) - R / 2).max() < 1e-12 * R        # half the radius
    assert np.abs(mv[:, 0] ** 2 + mv[:, 1] ** 2 - l * mv[:, 0] - 2 * centre[1] * mv[:, 1]).max() < 1e-11 * R * R
    assert ic.label("rod", "frame") == "P14" and len(ic.centres) == 6
    # P14 lies on Cardan's crank line O-C, at twice the crank's length (the circles touch there)
    assert np.allclose(cd.centre.xy, 2 * C.p[:-1], atol=1e-12 * R)


def test_cardan_point_moves_on_a_diameter():
    m = EllipticTrammel(2.0, np.radians(70))
    phi = m.turn(97)
    cd = centrodes(m, "rod", phi=phi)
    # a point of the moving circle (fixed to the rod), e.g. the diametral opposite of A
    C0 = cd.moving_at(0).xy[0]
    mo = cd.centres.motion
    A, C = mo.points["A"].p, mo.points["C"].p
    rel = in_frame(finite(2 * C - A), A, m.rod_angle(phi)).xy   # the point opposite A on the circle
    assert np.allclose(rel, rel[0], atol=1e-12)
    world = 2 * C - A
    d = world[np.argmax(np.hypot(*world.T))]
    assert np.abs(world[:, 0] * d[1] - world[:, 1] * d[0]).max() < 1e-12 * 4   # all on one line through O
    assert C0.shape == (2,)


def test_trammel_bad_input():
    with pytest.raises(DimensionError, match="0 < β < 180°"):
        EllipticTrammel(1.0, 0.0)
    with pytest.raises(DimensionError):
        EllipticTrammel(-1.0)


# -- antiparallelogram ------------------------------------------------------------------------------------
def test_antiparallelogram_relation_by_sympy():
    a, g, t = sp.symbols("a g t", positive=True)
    k = (a + g) / (a - g)
    # tan(φ/2) = t, tan(ψ/2) = k t: rational parametrisation of both cranks
    c1, s1 = (1 - t**2) / (1 + t**2), 2 * t / (1 + t**2)
    T = k * t
    c2, s2 = (1 - T**2) / (1 + T**2), 2 * T / (1 + T**2)
    loop = (g + a * c2 - a * c1) ** 2 + (a * s2 - a * s1) ** 2 - g**2
    assert sp.simplify(sp.together(loop)) == 0


@pytest.mark.parametrize("a, g", [(1.0, 2.0), (2.0, 1.0), (0.3, 4.0), (5.0, 4.5)])
def test_antiparallelogram_motion(a, g):
    m = Antiparallelogram(a, g)
    phi = np.linspace(-2 * np.pi, 2 * np.pi, 20001)
    mo = m.motion(phi)
    _O, A, B, E = (mo.points[k].p for k in "OABE")
    assert np.abs(np.hypot(*(B - A).T) - g).max() < 1e-12 * g
    assert np.abs(np.hypot(*(B - E).T) - a).max() < 1e-12 * a
    h = phi[1] - phi[0]
    for f, d in ((mo.psi, mo.dpsi), (mo.dpsi, mo.ddpsi)):
        assert np.abs(central_difference(f, h) - d[1:-1]).max() < 1e-4 * (1 + np.abs(d).max())
    assert np.all(np.sign(mo.dpsi) == np.sign(m.k))   # both cranks turn fully, never stop
    # the crossed branch is FourBar's assembly -1 on (0, π) and +1 on (π, 2π)
    up, down = np.linspace(0.1, 3.0, 30), np.linspace(3.3, 6.1, 30)
    for part, s in ((up, -1), (down, 1)):
        fb = m.as_fourbar(s).motion(part)
        mine = m.motion(part)
        assert np.allclose(np.exp(1j * fb.psi), np.exp(1j * mine.psi), atol=1e-12)
        assert np.allclose(fb.dpsi, mine.dpsi, atol=1e-10) and np.allclose(fb.ddpsi, mine.ddpsi, atol=1e-9)
    with pytest.raises(AssemblyError):
        m.as_fourbar(1).motion([0.0])       # FourBar refuses the change point


def test_antiparallelogram_centrodes_are_ellipses_and_hyperbolas():
    for a, g in [(1.0, 2.0), (2.0, 1.0)]:
        m = Antiparallelogram(a, g)
        phi = np.linspace(0.0, 2 * np.pi, 720, endpoint=False) + 0.004
        long_, short = max(a, g), min(a, g)
        shapes = {}
        for link, ref, fa, fb in (("coupler", "frame", g, g), ("rocker", "crank", a, a)):
            cd = centrodes(m, link, ref, phi)
            for curve, focus in ((cd.fixed, fa), (cd.moving, fb)):
                fin = curve.finite
                P = curve.h[fin, :2]
                d1, d2 = np.hypot(*P.T), np.hypot(P[:, 0] - focus, P[:, 1])
                if np.ptp(d1 + d2) < 1e-9 * long_:
                    assert np.allclose(d1 + d2, long_, atol=1e-9)     # ellipse, major axis = long link
                    shapes[(link, ref)] = "ellipse"
                else:
                    assert np.allclose(np.abs(d1 - d2), short, atol=1e-9)  # hyperbola, |d1 - d2| = short link
                    shapes[(link, ref)] = "hyperbola"
        if a < g:   # long frame: the coupler's centrodes are hyperbolas, the cranks roll as elliptic gears
            assert shapes == {("coupler", "frame"): "hyperbola", ("rocker", "crank"): "ellipse"}
        else:
            assert shapes == {("coupler", "frame"): "ellipse", ("rocker", "crank"): "hyperbola"}


def test_antiparallelogram_change_points_and_centres_at_infinity():
    m = Antiparallelogram(1.0, 2.0)
    with pytest.raises(IndeterminateCentre, match="P13 is indeterminate at φ = 0°"):
        instant_centres(m, [0.0, 1.0])
    with pytest.raises(IndeterminateCentre, match="φ = 180°"):
        instant_centres(m, [1.0, np.pi])
    iv = instant_centres(m, [0.0, np.pi], method="velocity")   # the twists still place them
    assert np.allclose(iv("crank", "rocker").xy, [[1.5, 0.0], [0.5, 0.0]])
    assert np.allclose(iv("coupler", "frame").xy, [[1.5, 0.0], [0.5, 0.0]])
    # P24 (OA ∩ EB) is at infinity where the short links are parallel: tan²(φ/2) = -1/k
    ph = 2 * np.arctan(np.sqrt(-1.0 / m.k))
    ic = instant_centres(m, [ph, -ph, 1.0])
    p24 = ic("coupler", "frame")
    assert list(p24.finite) == [False, False, True]
    A = ic.motion.points["A"].p
    assert np.allclose(np.abs(np.sum(p24.direction[:2] * A[:2], axis=1)), 1.0)   # along OA
    assert np.allclose(ic.output_analog(), ic.motion.dpsi)
    with pytest.raises(DimensionError, match="rhombus"):
        Antiparallelogram(1.0, 1.0)


# -- centrodes roll without slipping: seed formulas (7.6)-(7.9) ---------------------------------------------
@pytest.mark.parametrize("m, link, ref", [
    (FourBar(1.0, 3.0, 3.0, 4.0), "coupler", "frame"),
    (FourBar(1.0, 3.0, 3.0, 4.0, -1), "rocker", "crank"),
    (SliderCrank(1.0, 3.0, 0.5), "rod", "frame"),
    (EllipticTrammel(1.0, np.radians(60)), "rod", "frame"),
    (Antiparallelogram(1.0, 2.0), "rocker", "crank"),
])
def test_rolling_without_slipping(m, link, ref):
    phi = np.linspace(0.05, 3.0, 2001)
    fs, ms, xi, z = rolling_speeds(m, link, ref, phi)
    assert np.allclose(fs, ms, rtol=1e-10, atol=1e-12)
    cd = centrodes(m, link, ref, phi)
    assert np.allclose(z, cd.fixed.xy @ [1, 1j], atol=1e-9)            # (7.7) = Kennedy's centre
    assert np.allclose(xi, cd.moving.xy @ [1, 1j], atol=1e-9)          # (7.6) = the moving centrode
    h = phi[1] - phi[0]
    speed_fixed = np.hypot(*central_difference(cd.fixed.xy, h).T)
    speed_moving = np.hypot(*central_difference(cd.moving.xy, h).T)
    near = np.hypot(*cd.centre.xy[1:-1].T) < 10 * cd.centres.structure.scale  # differences fail near infinity
    assert near.sum() > 1000
    assert np.allclose(speed_fixed[near], fs[1:-1][near], rtol=2e-3, atol=1e-6)   # (7.8), O(h²) differences
    assert np.allclose(speed_moving[near], ms[1:-1][near], rtol=2e-3, atol=1e-6)  # (7.9)
    i = 700
    assert np.allclose(cd.fixed_at(i).xy[i], cd.centre.xy[i]) and np.allclose(cd.moving_at(i).xy[i], cd.centre.xy[i])


def test_lookup_errors():
    ic = instant_centres(FourBar(1, 3, 3, 4), [0.3])
    assert ic(1, 3) is ic("crank", "rocker")
    for bad in (lambda: ic("nothing", "frame"), lambda: ic(0, 2), lambda: ic(2, 2),
                lambda: instant_centres(FourBar(1, 3, 3, 4), [0.3], method="guess"),
                lambda: instant_centres(object(), [0.3])):
        with pytest.raises((MechanismError, AttributeError, TypeError)):
            bad()


# -- drawings, widgets, exercises, errata ----------------------------------------------------------------
def test_centrode_animation_moves_the_same_artists():
    import matplotlib.pyplot as plt

    from mechlab.draw.centres import animate_centrodes, draw_centres

    anim = animate_centrodes(Antiparallelogram(1.0, 2.0), "coupler", n=8)
    ov, dr = anim.overlay, anim.drawing
    before = [id(a) for a in ov.artists + dr.artists]
    texts = set()
    assert len(ov.cd.phi) == 8 * anim.step and anim.step == 45
    for i in range(0, 8 * anim.step, anim.step):
        ov.set_frame(i)
        dr.set_frame(i)
        texts.add(ov.arrow_text.get_text())
        P = ov.cd.centre[i]
        if P.finite[0]:
            assert np.allclose(ov.pole.get_data(), P.h[0, :2, None])
        xs, ys = ov.moving_line.get_data()            # the moving centrode passes through the pole
        if P.finite[0] and np.hypot(*P.h[0, :2]) < ov.clip:
            pts = np.ma.column_stack([xs, ys])
            assert np.ma.min(np.hypot(pts[:, 0] - P.h[0, 0], pts[:, 1] - P.h[0, 1])) < 1e-9
    assert [id(a) for a in ov.artists + dr.artists] == before
    html = anim.to_jshtml(fps=5)
    assert html.count("data:image/png;base64") == 8 and "<script" in html
    ax = draw_centres(instant_centres(EllipticTrammel(1.0, 1.0), [0.7]), 0)
    labels = {t.get_text() for t in ax.texts}
    assert {"P14", "P24", "P34"} <= labels                   # the 3 finite centres of Fig. 7.5
    assert any("P12 → ∞" in t and "P13 → ∞" in t and "P23 → ∞" in t for t in labels)
    plt.close("all")


def test_draw_centrodes_shows_one_frame_with_the_pole_on_both_curves():
    import matplotlib.pyplot as plt

    from mechlab.draw.centres import draw_centrodes

    ap = Antiparallelogram(1.0, 2.0)
    cd = centrodes(ap, "rocker", "crank", ap.cycle(181))
    ax = draw_centrodes(cd, i=20, title="ellipses")
    fixed, moving, pole = (next(l for l in ax.lines if l.get_label() == name) for name in
                           ("fixed centrode (crank)", "moving centrode (rocker)", cd.centres.label("rocker", "crank")))
    P = cd.centre[20].h[0, :2]
    assert np.allclose(np.ravel(pole.get_data()), P) and ax.get_title() == "ellipses"
    for line in (fixed, moving):   # the two curves touch at the pole
        xy = np.ma.column_stack(line.get_data())
        assert np.ma.min(np.hypot(xy[:, 0] - P[0], xy[:, 1] - P[1])) < 1e-9
    assert {"O", "A", "B", "E"} <= {t.get_text() for t in ax.texts}   # the joint letters the text uses
    with pytest.raises(MechanismError):
        draw_centrodes(cd, i=181)
    with pytest.raises(TypeError, match="Centrodes"):
        draw_centrodes(ap)
    plt.close("all")


def test_explorers_follow_sliders_and_show_errors():
    from mechlab.widgets.centres import antiparallelogram_explorer, fourbar_centrode_explorer, trammel_explorer

    ex = fourbar_centrode_explorer()
    ex.angle.value = 90.0
    P = ex.centrodes.centre[ex.frame].xy[0]
    assert np.allclose(ex.overlay.pole.get_data(), P[:, None]) and "P24" in ex.status.value
    ex.sliders["ground"].value = 9.9
    assert "cannot be assembled" in ex.message
    ex.sliders["ground"].value = 4.0
    assert ex.message == "" and ex.centrodes is not None
    tr = trammel_explorer(rod=2.0, beta_deg=60.0)
    R = np.hypot(*tr.centrodes.fixed.xy.T)
    assert np.allclose(R, 2.0 / np.sin(np.radians(60.0)))
    ap = antiparallelogram_explorer()
    ap.sliders["crank"].value = 2.0
    assert "rhombus" in ap.message
    ap.sliders["crank"].value = 1.0
    assert ap.message == "" and ap.centrodes.fixed.finite.all()


def test_errata():
    from mechlab.course.errata import seed002_centres

    for e in seed002_centres.ERRATA:
        assert e.source == "002" and e.notebook == "01_instant_centres.ipynb"
        text = e.evidence()
        assert any(ch.isdigit() for ch in text)


def test_point_velocities_from_the_centres():
    """A point carried by the coupler (or the rod): its velocity analog read from the centres
    equals the loop-closure one, here the midpoint of the joints, (A' + B')/2."""
    for m, link in ((FourBar(1.0, 3.0, 2.5, 3.5, -1), "coupler"), (SliderCrank(1.0, 3.0, 0.4), "rod")):
        phi = m.turn(181)
        ic = instant_centres(m, phi)
        A, B = ic.motion.points["A"], ic.motion.points["B"]
        v = ic.velocity_analog(link, (A.p + B.p) / 2)
        assert np.abs(v - (A.d + B.d) / 2).max() < 1e-12 * 4
        assert np.allclose(ic.velocity_analog("frame", A.p), 0.0)
        assert np.allclose(ic.velocity_analog("crank", A.p), A.d, atol=1e-12)


def test_pole_at_infinity_in_the_seed_formulas_and_the_change_point_free_cycle():
    from mechlab.analysis.centres.centrodes import pole_from_two_points

    z = np.array([0.0 + 0j, 1.0 + 0j])
    with pytest.raises(CentreAtInfinity, match="translates"):   # equal velocities: a translation
        pole_from_two_points(z, z + 1, np.array([1j, 1j]), np.array([1j, 1j]), phi=np.zeros(2))
    m = Antiparallelogram(1.0, 2.0)
    phi = m.cycle(181)
    assert np.isclose(phi[-1] - phi[0], 2 * np.pi)
    for cp in m.change_points():
        assert np.abs(np.angle(np.exp(1j * (phi - cp)))).min() > 0.3 * (phi[1] - phi[0])
    instant_centres(m, phi)   # no change point sampled, so Kennedy's construction succeeds
    with pytest.raises(MechanismError, match="none given"):
        kennedy(3, {})
