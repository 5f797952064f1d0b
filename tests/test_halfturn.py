"""Half-turn relations (seed 000 Tables 1-2), the base mechanism's peaks and the limit theorem."""

import numpy as np
import pytest
import sympy as sp
from hypothesis import given, settings
from strategies import revolving_fourbars, revolving_slider_cranks

from mechlab import DimensionError, FourBar, SlottedLink
from mechlab.analysis.equivalence import base_law
from mechlab.analysis.half_turn import base_peaks, formula_18, limit_theorem, mirror_angle, other_half
from mechlab.mechanisms.curved_slot import CurvedSlotLink, ParametricSlot, SampledSlot, TranslatingCurvedSlot
from mechlab.mechanisms.sixbar_iv import example


def random_grashof_fourbars(n, seed=0):
    """n revolving four-bars (crank-rockers and double-cranks), away from dead points, both assemblies."""
    rng = np.random.default_rng(seed)
    out = []
    while len(out) < n:
        c, r, g = rng.uniform(0.3, 5.0, 3)
        m = 0.03 * (c + r)
        hi = c + r - g - m
        windows = [(0.05, min(hi, g - abs(c - r) - m)), (g + abs(c - r) + m, hi)]
        windows = [(lo, up) for lo, up in windows if up - lo > 1e-3]
        if not windows:
            continue
        lo, up = windows[rng.integers(len(windows))]
        out.append(FourBar(rng.uniform(lo, up), c, r, g, int(rng.choice([1, -1]))))
    return out


def test_limit_theorem_on_1000_random_grashof_fourbars():
    fbs = random_grashof_fourbars(1000)
    kinds = {fb.grashof().kind for fb in fbs}
    assert kinds == {"crank-rocker", "double-crank"}
    worst_v = worst_a = np.inf
    for fb in fbs:
        chk = limit_theorem(fb, 361)
        assert chk.holds(), (fb, chk)
        v, _a = base_peaks(fb.crank / fb.ground)
        # the grid's base peak never exceeds the exact one, and the linkage's peak is above the exact one
        assert chk.base_peak_velocity <= v * (1 + 1e-12) and chk.peak_velocity >= v * (1 - 1e-12)
        worst_v = min(worst_v, chk.peak_velocity / v)
        worst_a = min(worst_a, chk.peak_acceleration / chk.base_peak_acceleration)
    assert worst_v >= 1 - 1e-12 and worst_a >= 1 - 1e-12


def test_limit_theorem_on_six_bar_slider_crank_and_curved_slots():
    assert limit_theorem(example()).holds()
    ell = ParametricSlot(lambda t: np.stack([1.0 + 0.6 * np.cos(t), 0.5 * np.sin(t)], -1),
                         lambda t: np.stack([-0.6 * np.sin(t), 0.5 * np.cos(t)], -1),
                         lambda t: np.stack([-0.6 * np.cos(t), -0.5 * np.sin(t)], -1), -np.pi, np.pi, periodic=True)
    chk = limit_theorem(CurvedSlotLink(0.4, 1.0, ell, start=1.0))
    assert chk.holds() and chk.peak_velocity > chk.base_peak_velocity
    with pytest.raises(DimensionError, match="n must be odd"):
        limit_theorem(example(), 100)


@given(revolving_slider_cranks())
@settings(max_examples=100, deadline=None)
def test_limit_theorem_slider_cranks(sc):
    chk = limit_theorem(sc, 361)
    assert chk.holds()
    assert np.isclose(chk.base_peak_velocity, sc.crank) and np.isclose(chk.base_peak_acceleration, sc.crank)


def test_the_limit_is_sharp_only_for_the_base_mechanism():
    """Equality holds for the straight slot through the pivot (β ≡ 0)."""
    straight = ParametricSlot(lambda t: np.stack([t, 0 * t], -1), lambda t: np.stack([1 + 0 * t, 0 * t], -1),
                              lambda t: np.stack([0 * t, 0 * t], -1), 0.1, 3.0)
    chk = limit_theorem(CurvedSlotLink(0.4, 1.0, straight))
    assert abs(chk.peak_velocity - chk.base_peak_velocity) < 1e-14
    assert abs(chk.peak_acceleration - chk.base_peak_acceleration) < 1e-14


@given(revolving_fourbars())
@settings(max_examples=150, deadline=None)
def test_half_turn_relations_fourbars(fb):
    phi = np.linspace(0, np.pi, 91)
    ht = other_half(fb, phi)
    scale = 1 + np.max(np.abs(ht.actual.dd))
    assert ht.residual() < 1e-10 * scale
    assert np.allclose(ht.phi_star, 2 * np.pi - phi)


@given(revolving_slider_cranks())
@settings(max_examples=100, deadline=None)
def test_half_turn_relations_slider_cranks(sc):
    phi = np.linspace(-np.pi / 2, np.pi / 2, 91)
    ht = other_half(sc, phi)
    assert ht.residual() < 1e-10 * (1 + sc.rod)
    assert np.allclose(ht.phi_star, np.pi - phi)


def test_half_turn_relations_general_slots_and_six_bar():
    f = lambda t: np.stack([0.3 * t**2 - 0.2 * t + 0.1 * t**3, t], -1)  # noqa: E731
    trans = TranslatingCurvedSlot(1.2, SampledSlot(f(np.linspace(-1.5, 1.5, 61))))
    assert other_half(trans, np.linspace(-1.5, 1.5, 61)).residual() < 1e-12
    wav = ParametricSlot(lambda t: np.stack([t, 0.2 * t + 0.05 * np.sin(3 * t)], -1),
                         lambda t: np.stack([1 + 0 * t, 0.2 + 0.15 * np.cos(3 * t)], -1),
                         lambda t: np.stack([0 * t, -0.45 * np.sin(3 * t)], -1), 0.2, 1.9)
    osc = CurvedSlotLink(0.4, 1.0, wav)
    assert other_half(osc, np.linspace(0, np.pi, 61)).residual() < 1e-12
    assert other_half(example(), np.linspace(0, np.pi, 61)).residual() < 1e-10


def test_half_turn_prediction_is_not_trivial():
    """The predicted other half differs from a naive mirror ψ(φ*) = -ψ(φ) by the base law."""
    fb = FourBar(0.3, 0.8, 1.0, 1.0, 1)
    phi = np.linspace(0.1, 3.0, 30)
    ht = other_half(fb, phi)
    naive = fb.motion(phi).dpsi
    assert np.max(np.abs(ht.actual.d - naive)) > 0.1
    assert np.allclose(mirror_angle(fb, phi), 2 * np.pi - phi)


def test_formulas_18_to_20_by_sympy_and_peaks():
    lam, phi = sp.symbols("lambda phi", positive=True)
    psi = sp.atan(lam * sp.sin(phi) / (lam * sp.cos(phi) + 1))        # (18) as printed
    d1, d2 = sp.diff(psi, phi), sp.diff(psi, phi, 2)
    D = lam**2 + 1 + 2 * lam * sp.cos(phi)
    assert sp.simplify(d1 - lam * (lam + sp.cos(phi)) / D) == 0                         # (19)
    assert sp.simplify(d2 - lam * sp.sin(phi) * (lam**2 - 1) / D**2) == 0               # (20)
    grid = np.linspace(0, 2 * np.pi, 400001)
    for lv in (0.2, 0.5, 0.9, 1.3, 4.0):
        f = formula_18(lv, grid)
        v, a = base_peaks(lv)
        assert np.isclose(np.max(np.abs(f.d)), v, rtol=1e-12)
        assert a * (1 - 1e-7) <= np.max(np.abs(f.dd)) <= a * (1 + 1e-12)  # sampled peak just below the exact one
        mo = SlottedLink(lv, 1.0).motion(grid[::1000])
        assert np.allclose(mo.dpsi, f.d[::1000], atol=1e-12)
        assert np.allclose(mo.ddpsi, f.dd[::1000], atol=1e-12)
    with pytest.raises(DimensionError, match="λ must be positive"):
        base_peaks(1.0)


def test_base_law_of_a_curved_slot_is_its_base_mechanism():
    ell = ParametricSlot(lambda t: np.stack([1.0 + 0.6 * np.cos(t), 0.5 * np.sin(t)], -1),
                         lambda t: np.stack([-0.6 * np.sin(t), 0.5 * np.cos(t)], -1),
                         lambda t: np.stack([-0.6 * np.cos(t), -0.5 * np.sin(t)], -1), -np.pi, np.pi, periodic=True)
    mech = CurvedSlotLink(0.4, 1.0, ell, start=1.0)
    phi = mech.turn(91)
    k = base_law(mech, phi)
    f = formula_18(0.4, phi)
    assert np.allclose(k.theta, f.theta, atol=1e-14) and np.allclose(k.d, f.d, atol=1e-14)
