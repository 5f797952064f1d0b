"""The builder's groups beyond the dyads RRR/RRP/RPR/PRP: the RPP dyad (a yoke), the class-IV Tetrad and a pin in a
CurvedSlot (both solved by Newton's method continued over φ), against closures written here and solved by mpmath at
40 digits (positions and both analogs to 1e-10, as tests/test_builder.py); their named errors; and what the course
derives from a structure (forces by virtual work, instantaneous centres, drawing) on linkages built with them."""

import matplotlib.pyplot as plt
import mpmath as mp
import numpy as np
import pytest
from test_builder import assert_paths, crank, on_link
from test_overrides import cubic, ellipse, sixbar_iv, wavy

import mechlab as ml
from mechlab.draw import draw
from mechlab.errors import AssemblyError, DimensionError, JointError, RotationError, StructureError
from mechlab.kinetostatics.model import Force, Torque, model_for
from mechlab.kinetostatics.solve import solve

SIX = ml.SixBarIV.example()


# -- RPP: a yoke on a guide that turns with a slotted lever --------------------------------------------------
def test_rpp_on_a_turning_guide():
    """A yoke slides along the lever P-A (a guide through P turning with it); its slot, at 1 rad to the lever,
    holds a block pinned at M on the crank: K = P + t·u, (K - M) × v = 0."""
    lk = (ml.Linkage({"O": (0, 0), "P": (0, -2)}, ml.Crank("O", "A", 1.0))
          .rpr("A", "P", 4.0).point("M", "crank", (0.5, 0.3)).rpp("M", "K", ("P", 0.0, "PA"), 1.0))

    def closed(phi):
        A = crank(1.0, phi)
        th = mp.atan2(A[1] + 2, A[0])
        M = on_link((0, 0), A, (0.5, 0.3))
        u, v = (mp.cos(th), mp.sin(th)), (mp.cos(th + 1), mp.sin(th + 1))
        t = (M[0] * v[1] - (M[1] + 2) * v[0]) / (u[0] * v[1] - u[1] * v[0])
        return (t * u[0], -2 + t * u[1])

    phi = np.linspace(0.0, 2 * np.pi, 40)[:-1] + 0.02
    mo = lk.motion(phi)
    assert_paths(mo, ["K"], closed, phi)
    assert lk.formula() == "I(crank) → II₂(block A, PA) → II₂(block M, yoke K)" and lk.mobility() == 1
    assert np.allclose(mo.transmission, 1.0)   # the acute angle between slot and guide


def test_rpp_slot_along_its_guide_is_refused():
    with pytest.raises(AssemblyError, match=r"RPP group \(block A, yoke K\) cannot close .* slot is parallel"):
        ml.Linkage({"O": (0, 0)}, ml.Crank("O", "A", 1.0)).rpp("A", "K", "O", 0.0)


# -- the class-IV tetrad ---------------------------------------------------------------------------------------
def tetrad_closed(lk, m):
    """The group's loop |Q - R| = l₃, |P - T| = l₅ solved here by mpmath (findroot from the linkage's angles, at 40
    digits), the joints Q, P, R, T written from the family's frames."""
    cp = complex(*m.coupler_point)
    q, p = -cp, m.qp - cp

    def closed(phi):
        guess = lk.motion(float(phi))
        A = crank(m.crank, phi)
        E = (mp.mpf(m.ground), mp.mpf(0))

        def joints(t1, t2):
            def at(o, w, t):
                return (o[0] + w.real * mp.cos(t) - w.imag * mp.sin(t), o[1] + w.real * mp.sin(t) + w.imag * mp.cos(t))
            return (at(A, q, t1), at(A, p, t1), at(E, complex(*m.r_joint), t2), at(E, complex(*m.t_joint), t2))

        def loop(t1, t2):
            Q, P, R, T = joints(t1, t2)
            return [(Q[0] - R[0]) ** 2 + (Q[1] - R[1]) ** 2 - m.link3**2,
                    (P[0] - T[0]) ** 2 + (P[1] - T[1]) ** 2 - m.link5**2]

        Q, P = guess.points["Q"].p, guess.points["P"].p
        t1, t2 = mp.findroot(loop, (float(np.arctan2(*(P - Q)[::-1])), float(guess.psi)))
        return tuple(c for j in joints(t1, t2) for c in j)
    return closed


@pytest.mark.parametrize("m", [SIX, ml.SixBarIV(0.2, 1.1, (0.55, 0.45), (1.35, 0.15), 0.25, 0.85, 0.9, (0.2, -0.55),
                                                 start=0.0)], ids=["course", "shorter crank"])
def test_tetrad_against_its_loop_solved_here(m):
    lk = sixbar_iv(m)
    phi = np.linspace(0.0, 2 * np.pi, 13)[:-1] + 0.05
    assert_paths(lk.motion(phi), ["Q", "P", "R", "T"], tetrad_closed(lk, m), phi)
    assert lk.classification()[-1][:3] == ("tetrad", 4, 2) and lk.assur_class == 4


def test_tetrad_that_reaches_a_dead_position_has_a_partial_range():
    """|PT| = 0.9: the family refuses (its crank must turn fully); the built group, followed both ways from its
    assembly at φ = π, reaches the dead positions at either end, where its Jacobian vanishes (ψ′ unbounded), and
    names the range beyond."""
    with pytest.raises(RotationError, match="cannot follow the crank"):
        ml.SixBarIV(0.25, 1.04, (0.55, 0.45), (1.35, 0.15), 0.25, 0.9, 0.9, (0.2, -0.55), start=0.0)
    at = SIX.motion(np.pi)   # the course's assembly there starts the continuation
    Q, P = at.points["Q"].p, at.points["P"].p
    lk = ml.Linkage({"O": (0, 0), "E": (1.04, 0)}, ml.Crank("O", "A", 0.25)).tetrad(
        "A", "E", ("Q", "P", "R", "T"), ((-0.2, 0.55), (0.7, 0.55)), ((0.55, 0.45), (1.35, 0.15)), (0.25, 0.9),
        (float(np.arctan2(*(P - Q)[::-1])), float(at.psi)), at=np.pi)
    (lo, hi), = lk.crank_ranges()
    assert lo < np.pi < hi and hi - lo < 2 * np.pi
    near = lk.motion(np.array([lo + 1e-7, hi - 1e-7]))
    assert np.all(np.abs(near.dpsi) > 20 * np.median(np.abs(lk.motion(lk.cycle(101)).dpsi)))
    with pytest.raises(AssemblyError, match=r"tetrad group \(AQP, QR, PT, ERT\) cannot close .* reaches only φ ∈"):
        lk.motion(hi + 0.1)


def test_tetrad_errors_are_named():
    args = ("A", "E", ("Q", "P", "R", "T"), ((-0.2, 0.55), (0.7, 0.55)), ((0.55, 0.45), (1.35, 0.15)), (0.25, 0.85),
            (3.67, 3.04))
    with pytest.raises(StructureError, match="four names"):
        ml.Tetrad("A", "E", ("Q", "P", "R"), *args[3:])
    with pytest.raises(DimensionError, match="on_first: the link's two joints coincide"):
        ml.Tetrad(*args[:3], ((0.1, 0.2), (0.1, 0.2)), *args[4:])
    with pytest.raises(DimensionError, match="lengths"):
        ml.Tetrad(*args[:5], (0.25, -1.0), args[6])
    base = ml.Linkage({"O": (0, 0), "E": (1.04, 0)}, ml.Crank("O", "A", 0.25))
    with pytest.raises(AssemblyError, match=r"tetrad group .* cannot be assembled near start"):
        base.tetrad(*args[:5], (5.0, 0.85), args[6], at=np.pi)   # |QR| = 5 closes nowhere


# -- a pin in a curved slot --------------------------------------------------------------------------------------
def test_curved_slot_against_its_loop_solved_here():
    """The pin A in an elliptic slot of the link turning about B: B + Rot(ψ)·c(t) = A, solved by mpmath; the
    link's axis point K = B + |c(start)|·(cos ψ, sin ψ)."""
    curve = ellipse()
    lk = ml.Linkage({"O": (0, 0), "B": (-1.0, 0)}, ml.Crank("O", "A", 0.4)).slot("A", curve, "K", pivot="B",
                                                                                  start=1.3)
    reach = float(np.hypot(*curve.points(np.array([1.3]))[0]))

    def closed(phi):
        A = crank(0.4, phi)
        guess = lk.motion(float(phi))

        def loop(psi, t):
            c = (1 + 0.6 * mp.cos(t), 0.5 * mp.sin(t))
            return [-1 + c[0] * mp.cos(psi) - c[1] * mp.sin(psi) - A[0], c[0] * mp.sin(psi) + c[1] * mp.cos(psi) - A[1]]

        local = complex(*(guess.points["A"].p - (-1.0, 0.0))) * np.exp(-1j * float(guess.psi))
        t0 = float(ml.CurvedSlot("A", curve, "K", pivot="B", start=1.3).parameter(np.array([local]))[0])
        psi, _ = mp.findroot(loop, (float(guess.psi), t0))
        return (-1 + reach * mp.cos(psi), reach * mp.sin(psi))

    phi = np.linspace(0.0, 2 * np.pi, 13)[:-1] + 0.05
    assert_paths(lk.motion(phi), ["K"], closed, phi)
    assert lk.mobility() == 1 and lk.structure().pairs[1].kind == "higher"


def test_curved_slot_errors_are_named():
    with pytest.raises(StructureError, match="give one of pivot= and guide="):
        ml.CurvedSlot("A", ellipse(), "K")
    with pytest.raises(StructureError, match="give one of pivot= and guide="):
        ml.CurvedSlot("A", ellipse(), "K", pivot="B", guide=ml.Guide("O"))
    with pytest.raises(DimensionError, match="curve"):
        ml.CurvedSlot("A", "a circle", "K", pivot="B")
    short = ml.Linkage({"O": (0, 0), "B": (-1.0, 0)}, ml.Crank("O", "A", 0.4)).slot(
        "A", wavy(amp=0.0, t0=0.8, t1=1.9), "K", pivot="B", start=1.37)
    with pytest.raises(AssemblyError, match=r"slot group \(slotted K\) cannot close at φ = 180.00°: .* reaches only"):
        short.motion(np.pi)


def eccentric():
    """A circular roller-centre curve of radius 2 about (0.5, 0) on the cam."""
    return ml.CircleSlot((0.5, 0.0), 2.0)


# -- what the course derives from the structure ------------------------------------------------------------------
def built_with_new_groups():
    return {"tetrad": (sixbar_iv(SIX), Torque("output", -20.0)),
            "turning slot": (ml.Linkage({"O": (0, 0), "B": (-1.0, 0)}, ml.Crank("O", "A", 0.4))
                             .slot("A", ellipse(), "K", pivot="B", start=1.3), Torque("slotted K", -20.0)),
            "sliding slot": (ml.Linkage({"O": (0, 0)}, ml.Crank("O", "A", 1.2)).slot(
                "A", cubic(), "C", guide="O", start=-0.3, link="yoke"), Force("yoke", "C", (-20.0, 0.0))),
            "yoke": (ml.Linkage({"O": (0, 0)}, ml.Crank("O", "A", 1.0)).rpp("A", "K", ("O", 0.3), 1.2,
                                                                         links=("block", "yoke")),
                     Force("yoke", "K", (-20.0 * np.cos(0.3), -20.0 * np.sin(0.3)))),
            "cam and arm": (ml.Linkage({"O": (0, 0), "B": (3.0, 0.0)}, ml.Crank("O", "A", 1.0, name="cam"))
                            .follow(eccentric(), "cam", "C", pivot="B", arm=2.2, start=1.3), Torque("follower", -20.0))}


@pytest.mark.parametrize("name", sorted(built_with_new_groups()))
def test_forces_centres_and_drawing_follow_from_the_structure(name):
    """The group-by-group torque equals the load's virtual work (20·ψ′ or 20·s′), the instantaneous centres give
    the output's analog, and the drawing numbers the links 1…n with the frame last."""
    lk, load = built_with_new_groups()[name]
    phi = lk.cycle(37)
    mo = lk.motion(phi)
    law = mo.dpsi if lk.output == "angle" else mo.ds
    res = solve(model_for(lk), mo, [load], omega1=0.0, gravity=(0.0, 0.0))
    res.verify()
    assert np.abs(res.torque - 20.0 * law).max() < 1e-9 * 20 * np.abs(law).max()
    assert np.abs(ml.instant_centres(lk, phi).output_analog() - law).max() < 1e-9 * np.abs(law).max()
    shown = [t.get_text() for t in draw(lk, 0.3).numbers if t.get_visible()]
    assert shown == [str(k) for k in range(1, len(lk.structure().numbers()) + 1)]
    plt.close("all")


def test_the_grid_is_solved_once_per_linkage():
    """The continuation runs once when the linkage is made; later motions only polish the grid's guess."""
    lk = sixbar_iv(SIX)
    grids = dict(lk._grids)
    assert len(grids) == 1
    lk.motion(lk.turn(7))
    assert lk._grids == grids


# -- a cam follower --------------------------------------------------------------------------------------------
def test_translating_follower_on_an_eccentric():
    """The roller centre C = (0, y) on the circle of radius 2 about M = 0.5·(cos φ, sin φ):
    y = 0.5 sin φ + √(4 - 0.25 cos² φ), solved here by mpmath."""
    lk = ml.Linkage({"O": (0, 0)}, ml.Crank("O", "A", 1.0, name="cam")).follow(
        eccentric(), "cam", "C", guide=("O", np.pi / 2), start=1.3)

    def closed(phi):
        return (mp.mpf(0), 0.5 * mp.sin(phi) + mp.sqrt(4 - 0.25 * mp.cos(phi) ** 2))

    phi = np.linspace(0.0, 2 * np.pi, 13)[:-1] + 0.05
    assert_paths(lk.motion(phi), ["C"], closed, phi)
    assert lk.output == "position" and lk.mobility() == 1


def test_arm_follower_on_an_eccentric_is_an_rrr_dyad():
    """On a circular curve the arm follower is the rocker of an RRR dyad from the curve's centre M (a point on the
    cam) to the pivot B: the same ψ, analogs and roller centre to 1e-12."""
    base = ml.Linkage({"O": (0, 0), "B": (3.0, 0.0)}, ml.Crank("O", "A", 1.0, name="cam"))
    lk = base.follow(eccentric(), "cam", "C", pivot="B", arm=2.2, start=1.3)
    side = 1 if lk.motion(0.0).points["C"].p[1] < 0 else -1   # C on the right of M→B: the dyad's assembly −1
    rrr = base.point("M", "cam", (0.5, 0.0)).rrr("M", "B", "C", 2.0, 2.2, -side)
    phi = lk.turn(361)
    a, b = lk.motion(phi), rrr.motion(phi)
    assert np.abs(np.mod(a.psi - b.psi + np.pi, 2 * np.pi) - np.pi).max() < 1e-12
    for x, y in ((a.dpsi, b.dpsi), (a.ddpsi, b.ddpsi), *zip(a.points["C"], b.points["C"], strict=True)):
        assert np.abs(x - y).max() < 1e-12 * max(1.0, np.abs(y).max())


def test_cam_follower_errors_are_named():
    with pytest.raises(StructureError, match="give one of pivot= and guide="):
        ml.CamFollower(eccentric(), "cam", "C")
    with pytest.raises(DimensionError, match="arm must be a positive length"):
        ml.CamFollower(eccentric(), "cam", "C", pivot="B")
    with pytest.raises(JointError, match="uses the link 'cam', which is not defined before it"):
        ml.Linkage({"O": (0, 0)}, ml.Crank("O", "A", 1.0)).follow(eccentric(), "cam", "C", guide="O")
