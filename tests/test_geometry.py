import os
import subprocess
import sys

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from mechlab import AssemblyError, DimensionError, SingularityError
from mechlab.geometry import (
    PointPath,
    as_angles,
    check_length,
    circle_circle,
    crank_point,
    cross,
    dyad_rpr,
    dyad_rrp,
    dyad_rrr,
    fixed_point,
    line_circle,
    wrap,
)
from mechlab.mechanisms.base import FULL_TURN, arc_set

coords = st.floats(-5, 5)


@given(coords, coords, coords, coords, st.floats(0.5, 4), st.floats(0.5, 4), st.sampled_from([1, -1]))
def test_circle_circle_lies_on_both_circles_on_the_requested_side(x1, y1, x2, y2, r1, r2, sign):
    c1, c2 = np.array([[x1, y1]]), np.array([[x2, y2]])
    d = np.hypot(x2 - x1, y2 - y1)
    if d > r1 + r2 + 1e-9 or d < abs(r1 - r2) - 1e-9:
        with pytest.raises(AssemblyError):
            circle_circle(c1, r1, c2, r2, sign)
        return
    if not (abs(r1 - r2) + 1e-3 < d < r1 + r2 - 1e-3):
        return  # near tangency the intersection is ill-conditioned: covered by the dead-point test
    p = circle_circle(c1, r1, c2, r2, sign)
    assert np.hypot(*(p - c1)[0]) == pytest.approx(r1, abs=1e-12)
    assert np.hypot(*(p - c2)[0]) == pytest.approx(r2, abs=1e-12)
    assert np.sign(cross(c2 - c1, p - c1))[0] == sign


def test_circle_circle_error_names_the_numbers():
    with pytest.raises(AssemblyError, match=r"outside \[\|1 - 1\|, 1 \+ 1\] = \[0, 2\]"):
        circle_circle(np.zeros((1, 2)), 1.0, np.array([[3.0, 0.0]]), 1.0, 1)
    with pytest.raises(SingularityError, match="dead point"):
        circle_circle(np.zeros((1, 2)), 1.0, np.array([[2.0, 0.0]]), 1.0, 1)


def _moving_point(phi):
    """An arbitrary smooth point path with exact analogs, for the dyad tests."""
    p = np.stack([0.3 * np.cos(phi) + 0.1 * np.sin(2 * phi), 0.4 * np.sin(phi)], axis=-1)
    d = np.stack([-0.3 * np.sin(phi) + 0.2 * np.cos(2 * phi), 0.4 * np.cos(phi)], axis=-1)
    dd = np.stack([-0.3 * np.cos(phi) - 0.4 * np.sin(2 * phi), -0.4 * np.sin(phi)], axis=-1)
    from mechlab.geometry import PointPath
    return PointPath(p, d, dd)


@pytest.mark.parametrize("sign", [1, -1])
def test_rrr_dyad_closes_and_its_analogs_match_differences(sign):
    phi = np.linspace(0, 2 * np.pi, 101)
    h = 1e-5
    E = fixed_point((2.0, 0.5), len(phi))
    def solve(f):
        return dyad_rrr(_moving_point(f), fixed_point((2.0, 0.5), len(f)), 1.5, 1.2, sign)
    B = solve(phi)
    A = _moving_point(phi)
    assert np.max(np.abs(np.hypot(*(B.p - A.p).T) - 1.5)) < 1e-12
    assert np.max(np.abs(np.hypot(*(B.p - E.p).T) - 1.2)) < 1e-12
    Bp, Bm = solve(phi + h), solve(phi - h)
    assert np.max(np.abs((Bp.p - Bm.p) / (2 * h) - B.d)) < 1e-7
    assert np.max(np.abs((Bp.d - Bm.d) / (2 * h) - B.dd)) < 1e-7


@pytest.mark.parametrize("sign", [1, -1])
def test_rrp_dyad_analogs_match_differences(sign):
    phi = np.linspace(0, 2 * np.pi, 101)
    h = 1e-5
    def solve(f):
        return dyad_rrp(_moving_point(f), (0.0, 0.2), 0.3, 1.0, sign)
    B, s = solve(phi)
    A = _moving_point(phi)
    assert np.max(np.abs(np.hypot(*(B.p - A.p).T) - 1.0)) < 1e-12
    (_, sp), (_, sm) = solve(phi + h), solve(phi - h)
    assert np.max(np.abs((sp.theta - sm.theta) / (2 * h) - s.d)) < 1e-7
    assert np.max(np.abs((sp.d - sm.d) / (2 * h) - s.dd)) < 1e-7


def test_rpr_dyad_analogs_match_differences():
    phi = np.linspace(0, 2 * np.pi, 101)
    h = 1e-5
    def solve(f):
        return dyad_rpr(_moving_point(f), fixed_point((-1.0, 0.1), len(f)))
    ang, rho = solve(phi)
    (ap, rp), (am, rm) = solve(phi + h), solve(phi - h)
    assert np.max(np.abs(wrap(ap.theta - am.theta) / (2 * h) - ang.d)) < 1e-7
    assert np.max(np.abs((ap.d - am.d) / (2 * h) - ang.dd)) < 1e-7
    assert np.max(np.abs((rp.theta - rm.theta) / (2 * h) - rho.d)) < 1e-7
    assert np.max(np.abs((rp.d - rm.d) / (2 * h) - rho.dd)) < 1e-7


def test_line_circle_reports_a_pin_too_far_from_the_guide():
    with pytest.raises(AssemblyError, match="more than the rod length 1"):
        line_circle(np.zeros(2), np.array([1.0, 0.0]), np.array([[0.0, 2.0]]), 1.0, 1)


@given(st.floats(-3, 3), st.floats(-3, 3), st.floats(-np.pi, np.pi))
@settings(max_examples=200)
def test_arc_set_agrees_with_brute_force(lo, hi, phase):
    ranges = arc_set(lo, hi, phase)
    phi = np.linspace(-np.pi, np.pi, 2000, endpoint=False) + 1e-4
    want = (np.cos(phi - phase) > lo) & (np.cos(phi - phase) < hi)
    got = np.zeros_like(want)
    for s, e in ranges:
        t = np.mod(phi - s, 2 * np.pi)
        got |= (t > 0) & (t < e - s)
    margin = np.abs(np.cos(phi - phase) - lo).clip(max=1) * np.abs(np.cos(phi - phase) - hi).clip(max=1) > 1e-6
    assert np.array_equal(got[margin], want[margin])
    if ranges == FULL_TURN:
        assert want.all()


def test_bad_numbers_are_named():
    with pytest.raises(DimensionError, match="crank must be > 0, got -1"):
        check_length("crank", -1)
    with pytest.raises(DimensionError, match="must be finite"):
        check_length("crank", float("nan"))
    with pytest.raises(DimensionError, match="must be a number"):
        check_length("crank", "abc")
    with pytest.raises(DimensionError, match="finite"):
        as_angles([0.0, np.nan])
    with pytest.raises(DimensionError, match="1-D"):
        as_angles(np.zeros((2, 2)))


def test_crank_point_analogs():
    phi = np.array([0.3])
    A = crank_point(2.0, phi)
    assert np.allclose(A.d, 2.0 * np.array([[-np.sin(0.3), np.cos(0.3)]]))
    assert np.allclose(A.dd, -A.p)


def test_unit_complex_on_uniform_and_irregular_grids():
    from mechlab.geometry import unit_complex
    rng = np.random.default_rng(1)
    for phi in (np.linspace(-1.0, 20.0, 100_003), np.arange(1, 5001) * (2 * np.pi / 5000),
                np.sort(rng.uniform(-7, 7, 9000)), np.linspace(0, 1, 7)):
        z = unit_complex(phi)
        assert np.max(np.abs(z - np.exp(1j * phi))) < 5e-15
        assert np.max(np.abs(np.abs(z) - 1)) < 5e-16


def test_complex_views_share_memory():
    from mechlab.geometry import as_complex, as_xy
    xy = np.arange(8.0).reshape(4, 2)
    z = as_complex(xy)
    assert np.shares_memory(z, xy) and np.allclose(z, xy[:, 0] + 1j * xy[:, 1])
    assert np.shares_memory(as_xy(z), z)
    assert as_complex(np.broadcast_to([3.0, 4.0], (5, 2))) == 3 + 4j
    assert as_xy(3 + 4j, 5).shape == (5, 2)


@pytest.mark.parametrize("sign", [1, -1])
def test_rocker_dyad_agrees_with_the_general_dyad_and_with_differences(sign):
    from mechlab.geometry import relative, rocker_dyad, vector_angle
    phi = np.linspace(0, 2 * np.pi, 201)
    A = _moving_point(phi)
    B1, psi = rocker_dyad(A, (2.0, 0.5), 1.5, 1.2, sign, reference=1.0)
    B2 = dyad_rrr(A, fixed_point((2.0, 0.5), len(phi)), 1.5, 1.2, sign)
    ang = vector_angle(relative(B2, fixed_point((2.0, 0.5), len(phi))))
    for a, b in zip(B1, B2, strict=False):
        assert np.max(np.abs(a - b)) < 1e-12
    assert np.max(np.abs(psi.d - ang.d)) < 1e-12 and np.max(np.abs(psi.dd - ang.dd)) < 1e-11
    assert np.all(np.abs(psi.theta - 1.0) <= np.pi) and np.allclose(wrap(psi.theta - ang.theta), 0, atol=1e-14)


@pytest.mark.parametrize("threads", [1, 2, 3])
def test_long_inputs_split_into_blocks_and_threads_give_the_same_numbers(monkeypatch, threads):
    """rocker_dyad and crank_point over many blocks (several threads) equal the row-by-row
    small-call results, and the lazy analogs B', B'' equal those of the general dyad."""
    import mechlab.geometry as G
    monkeypatch.setattr(G, "BLOCK", 1000)
    monkeypatch.setattr(G, "THREADS", threads)
    phi = np.linspace(-1.0, 9.0, 12_345)  # 13 blocks, the last one short
    A = crank_point(0.7, phi, centre=(0.2, -0.1))
    ref = 0.3 + 0.5 * phi  # a moving reference branch, as for a rotating output
    B, psi = G.rocker_dyad(A, (2.0, 0.5), 1.9, 1.6, -1, phi, reference=ref)
    single = [crank_point(0.7, phi[i:i + 1], centre=(0.2, -0.1)) for i in (0, 4_321, 12_344)]
    for a, i in zip(single, (0, 4_321, 12_344), strict=False):
        assert np.array_equal(a.p[0], A.p[i])
        b, p = G.rocker_dyad(a, (2.0, 0.5), 1.9, 1.6, -1, reference=ref[i])
        assert np.allclose([b.p[0], b.d[0], b.dd[0]], [B.p[i], B.d[i], B.dd[i]], atol=1e-13, rtol=0)
        assert np.allclose([p.theta[0], p.d[0], p.dd[0]], [psi.theta[i], psi.d[i], psi.dd[i]], atol=1e-13, rtol=0)
    general = dyad_rrr(PointPath(A.p, np.array(A.d), np.array(A.dd)), fixed_point((2.0, 0.5), len(phi)), 1.9, 1.6, -1)
    for a, b in zip(B, general, strict=False):
        assert np.max(np.abs(a - b)) < 1e-12
    assert np.all(np.abs(psi.theta - ref) <= np.pi)


def test_the_first_failing_block_names_the_angle(monkeypatch):
    import mechlab.geometry as G
    monkeypatch.setattr(G, "BLOCK", 100)
    monkeypatch.setattr(G, "THREADS", 2)
    phi = np.linspace(0.0, 2 * np.pi, 2_000)
    A = crank_point(1.0, phi)
    # |A - E| runs over [1, 3]: the dyad (1.5, 0.6) reaches only [0.9, 2.1]
    with pytest.raises(AssemblyError, match=r"at φ = (\d+\.\d+)°") as err:
        G.rocker_dyad(A, (2.0, 0.0), 1.5, 0.6, 1, phi)
    first = phi[np.argmax(np.abs(2.0 - np.exp(1j * phi)) > 2.1)]
    assert err.value.args[0].count(f"{np.degrees(first):.2f}°") == 1


def test_point_path_analogs_may_be_lazy_and_unpack_like_a_tuple():
    calls = []
    p = PointPath(np.zeros((3, 2)), lambda: calls.append("d") or np.ones((3, 2)), np.full((3, 2), 2.0))
    assert calls == []
    _, d, dd = p
    assert calls == ["d"] and np.array_equal(d, np.ones((3, 2))) and p.d is d and calls == ["d"]
    assert np.array_equal(dd, np.full((3, 2), 2.0))


@pytest.mark.skipif(not hasattr(os, "fork"), reason="needs fork")
def test_a_forked_child_solves_long_inputs_too(monkeypatch):
    """The thread pool does not survive a fork: the child must build its own, not wait forever."""
    import multiprocessing

    import mechlab.geometry as G
    monkeypatch.setattr(G, "BLOCK", 1000)
    monkeypatch.setattr(G, "THREADS", 2)
    phi = np.linspace(0.0, 6.0, 10_000)
    G.crank_point(1.0, phi)  # the parent's pool exists now
    child = multiprocessing.get_context("fork").Process(target=G.crank_point, args=(1.0, phi))
    child.start()
    child.join(timeout=60)
    assert child.exitcode == 0


@pytest.mark.parametrize("value, expect", [("1", "1"), ("3", "3"),
                                           ("0", "MECHLAB_THREADS must be a whole number ≥ 1, got '0'"),
                                           ("two", "MECHLAB_THREADS must be a whole number ≥ 1, got 'two'")])
def test_threads_from_the_environment(value, expect):
    code = "import mechlab.geometry as g; print(g.THREADS)"
    run = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         env={**os.environ, "MECHLAB_THREADS": value})
    assert expect in (run.stdout if run.returncode == 0 else run.stderr)
