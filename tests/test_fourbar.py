import numpy as np
import pytest
from hypothesis import given, settings
from strategies import fourbars, revolving_fourbars

from mechlab import AssemblyError, DimensionError, FourBar, RotationError

H = 1e-5


def _closure(fb, mo):
    A, B, E = (mo.points[k].p for k in "ABE")
    return max(np.max(np.abs(np.hypot(*(A - mo.points["O"].p).T) - fb.crank)),
               np.max(np.abs(np.hypot(*(B - A).T) - fb.coupler)),
               np.max(np.abs(np.hypot(*(B - E).T) - fb.rocker)))


@given(revolving_fourbars())
@settings(max_examples=300, deadline=None)
def test_loop_closes_to_1e12_over_the_whole_turn(fb):
    mo = fb.motion(fb.turn(721))
    scale = max(fb.crank, fb.coupler, fb.rocker, fb.ground)
    assert _closure(fb, mo) <= 1e-12 * scale
    # ψ is the rocker's angle: B = E + rocker·(cos ψ, sin ψ)
    B = mo.points["E"].p + fb.rocker * np.stack([np.cos(mo.psi), np.sin(mo.psi)], axis=-1)
    assert np.max(np.abs(B - mo.points["B"].p)) <= 1e-12 * scale


@given(fourbars())
@settings(max_examples=300, deadline=None)
def test_analogs_match_central_differences(fb):
    phi = fb.cycle(101)[10:-10]  # away from the dead points that bound a rocking crank
    mo, up, dn = fb.motion(phi), fb.motion(phi + H), fb.motion(phi - H)
    scale1 = 1 + np.max(np.abs(mo.dpsi))
    scale2 = 1 + np.max(np.abs(mo.ddpsi))
    assert np.max(np.abs((up.psi - dn.psi) / (2 * H) - mo.dpsi)) < 1e-5 * scale1
    assert np.max(np.abs((up.dpsi - dn.dpsi) / (2 * H) - mo.ddpsi)) < 1e-5 * scale2
    for k in "AB":
        assert np.max(np.abs((up.points[k].p - dn.points[k].p) / (2 * H) - mo.points[k].d)) < 1e-5 * scale1 * fb.rocker


@given(revolving_fourbars())
@settings(max_examples=200, deadline=None)
def test_the_two_assemblies_are_mirror_images(fb):
    """ψ₋(φ) = -ψ₊(-φ), ψ'₋(φ) = ψ'₊(-φ), ψ''₋(φ) = -ψ''₊(-φ): reflection in the frame line O-E."""
    plus = FourBar(fb.crank, fb.coupler, fb.rocker, fb.ground, 1)
    minus = FourBar(fb.crank, fb.coupler, fb.rocker, fb.ground, -1)
    phi = np.linspace(0, 2 * np.pi, 181)
    p, m = plus.motion(-phi), minus.motion(phi)
    assert np.allclose(m.psi, -p.psi, atol=1e-12)
    assert np.allclose(m.dpsi, p.dpsi, atol=1e-10)
    assert np.allclose(m.ddpsi, -p.ddpsi, atol=1e-9)
    assert np.allclose(m.points["B"].p * [1, -1], p.points["B"].p, atol=1e-12)


@given(revolving_fourbars())
@settings(max_examples=200, deadline=None)
def test_psi_is_continuous_and_turns_with_a_double_crank(fb):
    mo = fb.motion(fb.turn(2001))
    step = np.max(np.abs(mo.dpsi)) * (mo.phi[1] - mo.phi[0])
    assert np.max(np.abs(np.diff(mo.psi))) <= 1.01 * step + 1e-12
    turns = (mo.psi[-1] - mo.psi[0]) / (2 * np.pi)
    assert turns == pytest.approx(1.0 if fb.grashof().kind == "double-crank" else 0.0, abs=1e-9)


def test_assembly_plus_one_is_kc_plus_one_clockwise_abe():
    mo = FourBar(1, 3, 3, 4, 1).motion(np.linspace(0, 2 * np.pi, 50))
    A, B, E = (mo.points[k].p for k in "ABE")
    turn = (B[:, 0] - A[:, 0]) * (E[:, 1] - B[:, 1]) - (B[:, 1] - A[:, 1]) * (E[:, 0] - B[:, 0])
    assert np.all(turn < 0)  # A → B → E turns clockwise


@given(fourbars())
@settings(max_examples=300, deadline=None)
def test_grashof_and_crank_ranges_agree_with_brute_force(fb):
    a, c, r, g = fb.crank, fb.coupler, fb.rocker, fb.ground
    phi = np.linspace(0, 2 * np.pi, 3600, endpoint=False)
    d = np.sqrt(a * a + g * g - 2 * a * g * np.cos(phi))
    reach = (d < c + r) & (d > abs(c - r))
    assert fb.can_turn == bool(reach.all())
    kind = fb.grashof().kind
    if fb.can_turn:
        assert kind in ("crank-rocker", "double-crank")
    elif kind in ("crank-rocker", "double-crank"):
        pytest.fail(f"{kind} whose crank cannot turn: {fb}")
    # every sample of cycle() assembles; the dead points bound the range
    fb.motion(fb.cycle(101))
    if not fb.can_turn:
        _start, end = fb.crank_ranges()[0]
        with pytest.raises(AssemblyError, match="the crank reaches only"):
            fb.motion([end + 1e-3])


def test_classic_crank_rocker_values():
    fb = FourBar(1, 3, 3, 4)
    assert fb.grashof().kind == "crank-rocker"
    mo = fb.motion([0.0, np.pi])
    # φ = 0: |AE| = 3, isosceles triangle with sides 3, 3, 3 → ψ = 120°
    assert np.degrees(mo.psi[0]) == pytest.approx(120.0, abs=1e-12)
    # φ = π: |AE| = 5, cos ψ' with sides 3, 3, 5
    assert np.cos(np.pi - mo.psi[1]) == pytest.approx(5 / 6, abs=1e-12)
    assert np.degrees(mo.transmission[0]) == pytest.approx(60.0, abs=1e-12)


@pytest.mark.parametrize("dims, kind", [((1, 3, 3, 4), "crank-rocker"), ((3, 4, 3.5, 1), "double-crank"),
                                        ((3, 3, 1, 4), "rocker-crank"), ((3, 1, 3, 4), "double-rocker"),
                                        ((2, 3, 3, 4), "change-point"), ((3, 3, 3, 4), "triple-rocker")])
def test_grashof_kinds(dims, kind):
    assert FourBar(*dims).grashof().kind == kind


def test_errors_name_the_condition_and_the_numbers():
    with pytest.raises(RotationError, match=r"crank cannot turn fully: s \+ l = 7.00 > p \+ q = 6.00"):
        FourBar(3, 3, 3, 4).turn()
    with pytest.raises(RotationError, match=r"shortest link is the coupler"):
        FourBar(3, 1, 3, 4).turn()
    with pytest.raises(AssemblyError, match=r"cannot be assembled at any crank angle"):
        FourBar(5, 1, 1, 1)
    with pytest.raises(DimensionError, match="rocker must be > 0, got 0"):
        FourBar(1, 3, 0, 4)
    with pytest.raises(DimensionError, match="assembly must be"):
        FourBar(1, 3, 3, 4, assembly=0)
    with pytest.raises(AssemblyError, match=r"φ = 180.00°: \|AE\| = 6 ≥ coupler \+ rocker = 5"):
        FourBar(2, 2, 3, 4).motion(np.pi)
    # the crank rocks until |AE| = coupler + rocker: cos φ = (2² + 4² - 5²) / (2·2·4)
    limit = np.arccos(-5 / 16)
    # (the bounds on cos φ are pulled in by TOUCH = 1e-12: the range shrinks by 1e-12 / sin(limit))
    assert np.allclose(FourBar(2, 2, 3, 4).crank_ranges(), [(-limit, limit)], atol=2e-12, rtol=0)
    assert FourBar(2, 2, 3, 4).crank_ranges()[0][1] < limit


def test_rocking_crank_cycle_stays_inside_its_range():
    fb = FourBar(3, 3, 3, 4)
    phi = fb.cycle(50)
    (start, end), *_ = fb.crank_ranges()
    assert start < phi[0] < phi[-1] < end
    mo = fb.motion(phi)
    assert np.all(np.isfinite(mo.ddpsi))


def test_physical_values_follow_the_chain_rule():
    """ω2 = ψ'ω1 and ε2 = ψ''ω1² + ψ'ε1, checked against a time history."""
    fb = FourBar(1, 3, 3, 4)
    w1, e1, t = 3.0, 2.0, np.linspace(0, 0.5, 5)
    phi = 0.2 + w1 * t + 0.5 * e1 * t**2
    dt = 1e-5
    def psi(tt):
        return fb.motion(0.2 + w1 * tt + 0.5 * e1 * tt**2).psi
    mo = fb.motion(phi)
    omega1 = w1 + e1 * t
    num_w = (psi(t + dt) - psi(t - dt)) / (2 * dt)
    num_e = (psi(t + dt) - 2 * psi(t) + psi(t - dt)) / dt**2
    assert np.allclose(mo.velocity(omega1), num_w, atol=1e-8)
    assert np.allclose(mo.acceleration(omega1, e1), num_e, atol=1e-4)


@pytest.mark.parametrize("dims", [(1, 2, 2, 1), (1, 3, 3, 1), (1, 1, 3, 3), (3, 1, 3, 1), (2, 3, 4, 5)])
def test_change_point_four_bars_rock_between_dead_points_and_their_cycle_is_finite(dims):
    """A linkage folding flat at one crank angle (s + l = p + q) does not turn fully, and
    cycle() stops far enough short of its dead points, also where |AE| is stationary there."""
    fb = FourBar(*dims)
    assert fb.grashof().kind == "change-point" and not fb.can_turn
    with pytest.raises(RotationError, match="change-point"):
        fb.turn()
    mo = fb.motion(fb.cycle(41))
    assert all(np.all(np.isfinite(x)) for x in (mo.psi, mo.dpsi, mo.ddpsi))


def test_lengths_of_unusable_magnitude_and_angles_that_are_not_numbers_are_named():
    with pytest.raises(DimensionError, match=r"crank = 1e-200 lies outside the supported magnitudes"):
        FourBar(1e-200, 3e-200, 3e-200, 4e-200)
    with pytest.raises(DimensionError, match=r"outside the supported magnitudes"):
        FourBar(1e160, 3e160, 3e160, 4e160)
    fb = FourBar(1, 3, 3, 4)
    for bad in ("a", 1j, None, [1.0, "x"]):
        with pytest.raises(DimensionError, match="crank angles must be real numbers"):
            fb.motion(bad)
    assert FourBar(1e-90, 3e-90, 3e-90, 4e-90).motion([0.3]).psi == pytest.approx(fb.motion([0.3]).psi, abs=1e-12)
