"""Build your own linkage (ml.Linkage): mechanisms no family covers, built from a crank and Assur dyads, against
closed forms written here and differentiated by mpmath at 40 digits (positions and both analogs to 1e-10); the
built four-bar against FourBar's closed form to 1e-12; the named errors of an ill-formed structure; what the
course derives from a structure (centres, forces, drawing, cycle) on a built linkage."""

import doctest

import matplotlib.pyplot as plt
import mpmath as mp
import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st
from strategies import fourbars, revolving_fourbars

import mechlab as ml
from mechlab.design import criteria
from mechlab.draw import draw
from mechlab.errors import AssemblyError, JointError, MobilityError, RotationError, SingularityError, StructureError
from mechlab.kinetostatics.model import Force, Torque, model_for
from mechlab.kinetostatics.solve import solve
from mechlab.mechanisms.linkage import built, groups

DEG = np.pi / 180


# -- independent closed forms (mpmath, 40 digits) ----------------------------------------------------------------
def rrr_closed(P1, P2, l1, l2, side):
    """B with |B - P1| = l1, |B - P2| = l2 from the angle ψ of P2→B: K cos ψ + M sin ψ = N (Freudenstein's
    form), ψ = atan2(M, K) + side·acos(N/√(K² + M²)); side +1 is B left of P1→P2."""
    K, M = 2 * l2 * (P2[0] - P1[0]), 2 * l2 * (P2[1] - P1[1])
    N = l1**2 - l2**2 - (P2[0] - P1[0]) ** 2 - (P2[1] - P1[1]) ** 2
    psi = mp.atan2(M, K) + side * mp.acos(N / mp.sqrt(K**2 + M**2))
    return (P2[0] + l2 * mp.cos(psi), P2[1] + l2 * mp.sin(psi))


def on_link(origin, end, at):
    """A point at (ξ, η) in the frame of the link origin → end."""
    th = mp.atan2(end[1] - origin[1], end[0] - origin[0])
    return (origin[0] + at[0] * mp.cos(th) - at[1] * mp.sin(th), origin[1] + at[0] * mp.sin(th) + at[1] * mp.cos(th))


def paths(closed, phi):
    """Positions, first and second analogs of the values ``closed(φ)`` (a tuple of numbers) at the angles
    ``phi``, each an array (len(phi), len(closed(φ))): evaluated by mpmath at 40 digits, the analogs by
    central differences there with h = 1e-12 (truncation ~h² = 1e-24, rounding ~1e-40/h² = 1e-16), far below
    the 1e-10 compared; independent of mechlab's solvers."""
    h = mp.mpf("1e-12")
    out = [], [], []
    with mp.workdps(40):
        for x in phi:
            x = mp.mpf(float(x))
            lo, mid, hi = (np.array(closed(t), dtype=object) for t in (x - h, x, x + h))
            for k, v in enumerate((mid, (hi - lo) / (2 * h), (hi - 2 * mid + lo) / h**2)):
                out[k].append([float(c) for c in v])
    return [np.array(v) for v in out]


def assert_paths(mo, joints, closed, phi, tol=1e-10):
    """Each joint's positions and analogs equal the closed form's (``closed(φ)``: the joints' x, y in turn) to
    ``tol`` (relative to the largest value)."""
    want = paths(closed, phi)
    for j, name in enumerate(joints):
        for got, w in zip(mo.points[name], want, strict=True):
            w = w[:, 2 * j:2 * j + 2]
            assert np.abs(got - w).max() <= tol * max(1.0, np.abs(w).max()), name


def crank(r, phi):
    return (r * mp.cos(phi), r * mp.sin(phi))


def assert_law(got, want, angle=False):
    for k, (g, w) in enumerate(zip(got, want, strict=True)):
        w = w[:, 0]
        diff = np.mod(g - w + np.pi, 2 * np.pi) - np.pi if angle and k == 0 else g - w
        assert np.abs(diff).max() <= 1e-10 * max(1.0, np.abs(w).max()), k


# -- a crank shaper: a slotted lever (RPR), a point on it, a rod and a ram (RRP) -------------------------------
R, D_, L, H, ROD = 1.0, 2.0, 4.0, 2.2, 1.5


def shaper():
    return (ml.Linkage({"O": (0, 0), "P": (0, -D_), "G": (0, H)}, ml.Crank("O", "A", R))
            .rpr("A", "P", L, links=("block", "lever")).point("C", "lever", (L, 0.0))
            .rrp("C", "D", ROD, "G", links=("rod", "ram")))


def shaper_closed(phi):
    A = crank(R, phi)
    th = mp.atan2(A[1] + D_, A[0])
    C = (L * mp.cos(th), -D_ + L * mp.sin(th))
    Dx = C[0] + mp.sqrt(ROD**2 - (H - C[1]) ** 2)
    return (*A, *C, Dx, mp.mpf(H), th)


def test_shaper_against_its_closed_form():
    sh = shaper()
    phi = np.linspace(0.0, 2 * np.pi, 73)[:-1] + 0.01
    mo = sh.motion(phi)
    assert sh.output == "position" and isinstance(mo, ml.LinearMotion)
    assert_paths(mo, ["A", "C", "D"], shaper_closed, phi)
    want = paths(shaper_closed, phi)
    assert_law((mo.s, mo.ds, mo.dds), [w[:, 4:5] for w in want])
    lever = mo.link_angle("P", "C")   # the lever's angle and its analogs
    assert_law((lever.value, lever.d, lever.dd), [w[:, 6:7] for w in want], angle=True)
    assert sh.can_turn and sh.formula() == "I(crank) → II₂(block, lever) → II₂(rod, ram)"


# -- six-bars: a crank-rocker O-A-B-E and a dyad C-D-F on a point C of its rocker (Watt) or coupler (Stephenson)
FOUR = dict(a=1.0, c=3.2, r=2.6, g=3.5)
F_PIVOT = (5.5, 2.8)


def six_bar(kind, at, F, lengths, side):
    a, c, r, g = FOUR.values()
    on = "EB" if kind == "watt" else "AB"
    lk = (ml.Linkage({"O": (0, 0), "E": (g, 0), "F": F}, ml.Crank("O", "A", a))
          .rrr("A", "E", "B", c, r).point("C", on, at).rrr("C", "F", "D", *lengths, assembly=side))

    def closed(phi):
        A = crank(a, phi)
        B = rrr_closed(A, (g, 0), c, r, 1)
        C = on_link((g, 0), B, at) if kind == "watt" else on_link(A, B, at)
        D = rrr_closed(C, F, *lengths, side)
        return (*B, *C, *D, mp.atan2(D[1] - F[1], D[0] - F[0]))

    return lk, closed


@pytest.mark.parametrize("kind", ["watt", "stephenson"])
def test_six_bars_against_their_closed_forms(kind):
    six, closed = six_bar(kind, (3.6, 0.9) if kind == "watt" else (1.8, 1.4), F_PIVOT, (2.4, 2.1), -1)
    phi = six.cycle(61)
    mo = six.motion(phi)
    assert_paths(mo, ["B", "C", "D"], closed, phi)
    assert_law((mo.psi, mo.dpsi, mo.ddpsi), [w[:, 6:7] for w in paths(closed, phi)], angle=True)
    assert six.mobility() == 1 and six.assur_class == 2
    assert list(six.structure().groups) == [("CD", "FD"), ("AB", "EB")]   # output first


def test_a_six_bar_whose_second_stage_is_a_double_rocker():
    # the second four-bar E-C-D-F alone is a double-rocker (its coupler C-D the shortest, Grashof); driven by the
    # first stage's rocker it stays within its range: the six-bar turns with its crank, its output rocks
    g = FOUR["g"]
    F = (g + 1.0, 2.9)
    six, closed = six_bar("watt", (2.0, 0.0), F, (1.0, 2.2), 1)
    second = ml.FourBar(2.0, 1.0, 2.2, float(np.hypot(F[0] - g, F[1])))
    assert second.grashof().kind == "double-rocker"
    assert six.can_turn
    mo = six.motion(six.turn(61) + 0.01)
    assert_paths(mo, ["D"], lambda t: closed(t)[4:6], mo.phi)
    assert np.ptp(mo.psi) < np.pi


# -- PRP: a tangent mechanism (the slotted lever's line cut by a frame guide); RRP on a moving guide ----------
def test_prp_and_a_guide_on_a_moving_link():
    lk = (ml.Linkage({"O": (0, 0), "P": (0, -2), "G": (0, 1)}, ml.Crank("O", "A", 1.0))
          .rpr("A", "P", 4.0).point("M", "crank", (0.5, 0.3))
          .prp(("G", 0.0), ("P", 0.0, "PA"), "B")
          .rrp("M", "K", 1.2, ("P", 0.0, "PA"), links=("MK", "slider K")))

    def closed(phi):
        A = crank(1.0, phi)
        th = mp.atan2(A[1] + 2, A[0])
        M = on_link((0, 0), A, (0.5, 0.3))
        u, w = (mp.cos(th), mp.sin(th)), (M[0], M[1] + 2)
        t = w[0] * u[0] + w[1] * u[1] + mp.sqrt(1.2**2 - (u[0] * w[1] - u[1] * w[0]) ** 2)
        return (3 / mp.tan(th), mp.mpf(1), *M, t * u[0], -2 + t * u[1])

    phi = np.linspace(0.0, 2 * np.pi, 50)[:-1] + 0.02
    assert_paths(lk.motion(phi), ["B", "M", "K"], closed, phi)
    assert lk.formula() == "I(crank) → II₂(block A, PA) → II₂(slider B, block B) → II₂(MK, slider K)"


# -- the built four-bar is FourBar ---------------------------------------------------------------------------
def built_fourbar(fb):
    return ml.Linkage({"O": (0, 0), "E": (fb.ground, 0)}, ml.Crank("O", "A", fb.crank)).rrr(
        "A", "E", "B", fb.coupler, fb.rocker, fb.assembly)


def close(got, want, tol=1e-12):
    return np.abs(got - want).max() <= tol * max(1.0, np.abs(want).max())


@settings(max_examples=40, deadline=None)
@given(st.one_of(revolving_fourbars(), fourbars()), st.floats(0.0, 1.0))
def test_built_fourbar_equals_the_closed_form(fb, shift):
    lk = built_fourbar(fb)
    assert lk.can_turn == fb.can_turn
    for (s1, e1), (s2, e2) in zip(lk.crank_ranges(), fb.crank_ranges(), strict=True):
        assert abs(np.mod(s1 - s2 + np.pi, 2 * np.pi) - np.pi) < 1e-9 and abs(e1 - s1 - (e2 - s2)) < 1e-9
    start, end = fb.crank_ranges()[0]
    phi = start + (shift if fb.can_turn else 0.0) + (end - start) * np.linspace(0.0, 1.0, 257)[1:-1]
    # away from the dead points (transmission angle within [15°, 165°]): there the analogs are well conditioned,
    # and two exact formulas agree to rounding
    phi = phi[np.sin(fb.motion(phi).transmission) > np.sin(15 * DEG)]
    assume(len(phi) >= 8)
    a, b = lk.motion(phi), fb.motion(phi)
    # rounding in a dyad's solve grows with the ratio of its lengths (hypothesis found 3.2e-12 at 1 : 5 : 0.27 : 5),
    # and ψ'' with its square: at FourBar(4, 7.209, 0.2, 5) (ratio 36) the closed form's ψ'' is 9.1e-12 and the
    # built one's 6.1e-12 from a 50-digit value (test_overrides' extreme-ratio case), so they differ by 1.5e-11
    lengths = (fb.crank, fb.coupler, fb.rocker, fb.ground)
    ratio = max(lengths) / min(lengths)
    tol = 1e-12 * max(1.0, ratio / 5, (ratio / 8) ** 2)
    assert close(a.psi, b.psi, tol) and close(a.dpsi, b.dpsi, tol) and close(a.transmission, b.transmission, tol)
    # ψ'' at twice that: FourBar(3, 4, 0.25, 1)'s own ψ'' lies 9.5e-13 from a 40-digit closed form,
    # the built one's 3.5e-13
    assert close(a.ddpsi, b.ddpsi, 2 * tol)
    # the joints' positions and first analogs at tol, their second analogs at 2·tol as ψ'' (FourBar(5, 7, 0.2012, 2):
    # B's second analog 7.9e-10 apart on 97.8, ψ'' 8.6e-12 relative)
    for k in "AB":
        assert all(close(x, y, t) for x, y, t in zip(a.points[k], b.points[k], (tol, tol, 2 * tol), strict=True))


def test_built_slider_crank_equals_the_closed_form():
    for sc in (ml.SliderCrank(1.0, 3.0, 0.4, 1), ml.SliderCrank(0.7, 2.0, -0.3, -1)):
        lk = ml.Linkage({"O": (0, 0), "G": (0, sc.offset)}, ml.Crank("O", "A", sc.crank)).rrp(
            "A", "B", sc.rod, "G", sc.assembly)
        phi = sc.turn(97)
        a, b = lk.motion(phi), sc.motion(phi)
        assert close(a.s, b.s) and close(a.ds, b.ds) and close(a.dds, b.dds) and close(a.transmission, b.transmission)


# -- named errors of an ill-formed structure -------------------------------------------------------------------
def base():
    return ml.Linkage({"O": (0, 0), "E": (4, 0)}, ml.Crank("O", "A", 1.0))


def test_a_joint_attached_twice_is_named():
    with pytest.raises(JointError, match="the joint 'A' is attached twice: the crank O-A defines it"):
        base().rrr("A", "E", "A", 3, 3)
    with pytest.raises(JointError, match="the joint 'E' is attached twice: the frame defines it"):
        base().rrr("A", "O", "E", 3, 3)


def test_unknown_joints_and_links_are_named():
    with pytest.raises(JointError, match="attaches to the joint 'Z', which is not defined before it; joints so far: "
                                         "O, E, A"):
        base().rrr("A", "Z", "B", 3, 3)
    with pytest.raises(JointError, match="the point C is fixed on the link 'rocker', which is not defined"):
        base().point("C", "rocker", (1, 0))
    with pytest.raises(JointError, match="names a link 'crank' that already exists"):
        base().rrr("A", "E", "B", 3, 3, links=("crank", "rocker"))
    with pytest.raises(JointError, match="must turn about a frame point; A is on crank"):
        base().rrr("A", "E", "B", 3, 3).then(ml.Crank("A", "K", 0.3, name="second"))
    assert issubclass(JointError, StructureError) and issubclass(StructureError, ml.MechanismError)


def test_mobility_other_than_one_is_named():
    with pytest.raises(MobilityError, match=r"mobility W = 3n - 2p₅ - p₄ = 3·4 - 2·5 = 2 ≠ 1: 2 cranks "
                                            r"\(crank, second\)"):
        base().rrr("A", "E", "B", 3, 3).then(ml.Crank("E", "K", 0.3, name="second"))


def test_a_group_that_cannot_close_is_named_with_the_crank_angle():
    with pytest.raises(AssemblyError, match=r"the RRR group \(AB, EB\) cannot close at φ = 0.00°: \|AE\| = 3 must lie "
                                            r"strictly between the difference and the sum of the lengths 1 and 1, "
                                            r"\(0, 2\)"):
        base().rrr("A", "E", "B", 1.0, 1.0)
    rocking = base().rrr("A", "E", "B", 2.0, 1.5)   # |AE|² = 17 - 8 cos φ < 3.5²: cos φ > 0.59375, a rocking crank
    assert not rocking.can_turn
    with pytest.raises(RotationError, match="crank cannot turn fully"):
        rocking.turn()
    with pytest.raises(AssemblyError, match=r"the RRR group \(AB, EB\) cannot close at φ = 180.00°: .*; the crank "
                                            r"reaches only φ ∈ \[-53.58°, 53.58°\]"):
        rocking.motion(np.pi)
    with pytest.raises(AssemblyError, match=r"the RRP group \(CD, slider D\) cannot close at φ = 90.00°: the pin C "
                                            r"is 1 from the guide, not less than the rod's length 0.5"):
        base().point("C", "crank", (1, 0)).rrp("C", "D", 0.5, ("E", 0.0)).motion(np.pi / 2)


def test_a_dead_point_is_named():
    # |AE| = 5 = 3 + 2 at φ = 180°: the dyad lies flat there, its analogs unbounded; the crank reaches up to it
    flat = base().rrr("A", "E", "B", 3.0, 2.0)
    (start, end), = flat.crank_ranges()
    assert abs(end - start - 2 * np.pi) < 1e-4 and not flat.can_turn   # all but a sliver about 180°
    with pytest.raises(SingularityError, match=r"dead point of the RRR group \(AB, EB\) at φ = 180.00°: \|AE\| = 5 "
                                               r"must lie strictly .*; the analogs are unbounded there"):
        flat.motion(np.pi)
    assert np.all(np.isfinite(flat.motion(flat.cycle(9)).ddpsi))


def test_bad_pieces_are_refused_by_name():
    with pytest.raises(ml.DimensionError, match="first_length must be > 0"):
        ml.RRR("A", "E", "B", -1.0, 3.0)
    with pytest.raises(TypeError, match="guide must be a Guide, got float 3"):
        ml.RRP("A", "B", 1.0, 3.0)
    with pytest.raises(TypeError, match="driver must be a Crank"):
        ml.Linkage({"O": (0, 0)}, ml.RRR("A", "E", "B", 1.0, 3.0))
    with pytest.raises(StructureError, match="links of a RRR dyad: two names"):
        ml.RRR("A", "E", "B", 1.0, 3.0, links=("x",))
    with pytest.raises(ml.DimensionError, match="frame point E"):
        ml.Linkage({"O": (0, 0), "E": (np.nan, 0)}, ml.Crank("O", "A", 1.0))


# -- what the course derives from a structure, on built linkages ----------------------------------------------
def test_centres_forces_and_drawing_follow_from_the_structure():
    sh = shaper()
    phi = np.linspace(0.0, 2 * np.pi, 61)[:-1] + 0.013
    mo = sh.motion(phi)
    ic = ml.instant_centres(sh, phi)
    assert np.abs(ic.output_analog() - mo.ds).max() < 1e-9
    # a load on the ram: the group-by-group torque equals its virtual work, and the power balance holds
    res = solve(model_for(sh), mo, [Force("ram", "D", (-100.0, 0.0))], omega1=0.0, gravity=(0.0, 0.0))
    res.verify()
    assert np.abs(res.torque - 100.0 * mo.ds).max() < 1e-9 * 100 * np.abs(mo.ds).max()
    moving = solve(model_for(sh).with_body("lever", mass=3.0), mo, [Force("ram", "D", (-100.0, 0.0))], omega1=8.0)
    moving.verify()
    # the drawing numbers the links as the centres do: crank 1, lever 2, rod 3, ram 4, frame 5
    d = draw(sh, 0.4)
    assert [t.get_text() for t in d.numbers if t.get_visible()] == ["1", "2", "3", "4", "5"]
    assert ic.structure.links == ("crank", "lever", "rod", "ram", "frame")
    plt.close("all")


@pytest.mark.parametrize("lk", [shaper(), base().rrr("A", "E", "B", 3, 3).point("C", "AB", (1, 1)),
                                ml.Linkage({"O": (0, 0), "P": (0.4, -2), "G": (0, 1)}, ml.Crank("O", "A", 1.0))
                                .rpr("A", "P", 4.0).prp(("G", 0.0), ("P", 0.0, "PA"), "B")],
                         ids=["shaper", "four-bar", "tangent"])
def test_drawing_and_centres_number_the_links_alike(lk):
    d = draw(lk, 0.3)
    shown = [t.get_text() for t in d.numbers if t.get_visible()]
    names = ml.instant_centres(lk, [0.3]).structure.links
    assert shown == [str(k) for k in range(1, len(names) + 1)]   # each number once, the frame last
    plt.close("all")


def test_a_whitworth_quick_return_indexes_and_moves_over_its_cycle():
    # λ = 2 > 1: the slotted link turns fully, once per crank turn; its angle is continuous over the turn
    lk = ml.Linkage({"O": (0, 0), "B": (-0.5, 0)}, ml.Crank("O", "A", 1.0)).rpr("A", "B", 2.0)
    mo = lk.motion(lk.turn(721))
    assert abs(mo.psi[-1] - mo.psi[0] - 2 * np.pi) < 1e-12 and np.all(np.abs(np.diff(mo.psi)) < 0.05)
    slotted = ml.SlottedLink(1.0, 0.5).motion(lk.turn(721))
    assert np.abs(np.mod(mo.psi - slotted.psi + np.pi, 2 * np.pi) - np.pi).max() < 1e-12
    assert close(mo.dpsi, slotted.dpsi) and close(mo.ddpsi, slotted.ddpsi)
    row = ml.intermittency(lk, n=721)
    assert row.dwell_fraction == 0.0 and abs(row.index_deg - 360.0) < 1e-9


def test_torque_on_a_built_six_bar_is_its_virtual_work():
    a, c, r, g = FOUR.values()
    six = (ml.Linkage({"O": (0, 0), "E": (g, 0), "F": F_PIVOT}, ml.Crank("O", "A", a))
           .rrr("A", "E", "B", c, r).point("C", "AB", (1.8, 1.4)).rrr("C", "F", "D", 2.4, 2.1, assembly=-1))
    phi = six.cycle(37)
    mo = six.motion(phi)
    res = solve(model_for(six), mo, [Torque("FD", -20.0)], omega1=0.0, gravity=(0.0, 0.0))
    res.verify()
    assert np.abs(res.torque - 20.0 * mo.dpsi).max() < 1e-9 * 20 * np.abs(mo.dpsi).max()


def test_examples_in_the_docstrings_run():
    for module in (built, groups, criteria):
        result = doctest.testmod(module, optionflags=doctest.ELLIPSIS)
        assert result.attempted > 0 and result.failed == 0, module.__name__


def test_the_shaper_returns_quickly_as_its_closed_form_says():
    # the ram's dead points are where the lever is tangent to the crank circle (O→A ⟂ P→A): sin φ = −R/D, so the
    # working stroke (the crank over the top) takes π + 2 asin(R/D) of the turn and the return π − 2 asin(R/D):
    # time ratio 2 at R/D = 1/2; the stroke from the closed form at those two angles
    from scipy.optimize import brentq

    sh = shaper()
    ends = sorted(brentq(lambda p: float(sh.motion(p).ds), lo, hi, xtol=1e-14)
                  for lo, hi in ((-0.9, -0.1), (np.pi + 0.1, np.pi + 0.9)))
    beta = float(np.arcsin(R / D_))
    assert abs(ends[0] + beta) < 1e-10 and abs(ends[1] - np.pi - beta) < 1e-10
    work, back = ends[1] - ends[0], 2 * np.pi - (ends[1] - ends[0])
    assert abs(work / back - 2.0) < 1e-9
    with mp.workdps(40):
        stroke = float(shaper_closed(mp.pi + mp.asin(mp.mpf(R) / D_))[4] - shaper_closed(-mp.asin(mp.mpf(R) / D_))[4])
    s = [float(sh.motion(p).s) for p in ends]
    assert abs(abs(s[1] - s[0]) - abs(stroke)) < 1e-10 * abs(stroke)
