import numpy as np
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st
from strategies import revolving_slider_cranks

from mechlab import DimensionError, RotationError, SineMechanism, SliderCrank, SlottedLink

H = 1e-5


@given(revolving_slider_cranks())
@settings(max_examples=300, deadline=None)
def test_slider_crank_closes_and_its_analogs_match_differences(sc):
    phi = sc.turn(181)
    mo, up, dn = sc.motion(phi), sc.motion(phi + H), sc.motion(phi - H)
    A, B = mo.points["A"].p, mo.points["B"].p
    assert np.max(np.abs(np.hypot(*(B - A).T) - sc.rod)) <= 1e-12 * max(sc.rod, sc.crank, abs(sc.offset))
    assert np.allclose(B[:, 1], sc.offset, atol=1e-15)
    assert np.allclose(B[:, 0], mo.s, atol=0)
    assert np.max(np.abs((up.s - dn.s) / (2 * H) - mo.ds)) < 1e-6 * (1 + np.max(np.abs(mo.ds)))
    assert np.max(np.abs((up.ds - dn.ds) / (2 * H) - mo.dds)) < 1e-6 * (1 + np.max(np.abs(mo.dds)))


@given(revolving_slider_cranks())
@settings(max_examples=100, deadline=None)
def test_slider_crank_assemblies_mirror(sc):
    """s₋(φ) = -s₊(π - φ): the -1 assembly is the mirror image in the y axis."""
    plus = SliderCrank(sc.crank, sc.rod, sc.offset, 1)
    minus = SliderCrank(sc.crank, sc.rod, sc.offset, -1)
    phi = np.linspace(0, 2 * np.pi, 91)
    p, m = plus.motion(np.pi - phi), minus.motion(phi)
    assert np.allclose(m.s, -p.s, atol=1e-12)
    assert np.allclose(m.ds, p.ds, atol=1e-12)
    assert np.allclose(m.dds, -p.dds, atol=1e-11)


def test_centred_slider_crank_closed_form():
    a, l = 1.0, 3.5
    phi = np.linspace(0, 2 * np.pi, 50)
    s = SliderCrank(a, l).motion(phi).s
    assert np.allclose(s, a * np.cos(phi) + np.sqrt(l**2 - (a * np.sin(phi)) ** 2), atol=1e-14)


def test_slider_crank_errors():
    with pytest.raises(RotationError, match=r"crank \+ \|offset\| = 2.50 ≥ rod = 2.00"):
        SliderCrank(2.0, 2.0, 0.5).turn()
    with pytest.raises(DimensionError, match="rod must be > 0"):
        SliderCrank(1.0, -2.0)
    with pytest.raises(DimensionError, match="offset must be finite"):
        SliderCrank(1.0, 2.0, float("inf"))


def _base_mechanism_law():
    """Seed 000 formula (18) derived from the geometry, then differentiated by sympy."""
    lam, phi = sp.symbols("lambda phi", positive=True)
    # A - B with B = (-1, 0) and l_OA = λ (units of l_OB)
    psi = sp.atan2(lam * sp.sin(phi), lam * sp.cos(phi) + 1)
    d1 = sp.simplify(sp.diff(psi, phi))
    d2 = sp.simplify(sp.diff(d1, phi))
    return lam, phi, psi, d1, d2


def test_base_mechanism_formulas_18_to_20_derived_by_sympy():
    lam, phi, psi, d1, d2 = _base_mechanism_law()
    printed19 = lam * (lam + sp.cos(phi)) / (lam**2 + 1 + 2 * lam * sp.cos(phi))
    printed20 = lam * sp.sin(phi) * (lam**2 - 1) / (lam**2 + 1 + 2 * lam * sp.cos(phi)) ** 2
    assert sp.simplify(d1 - printed19) == 0
    assert sp.simplify(d2 - printed20) == 0
    for lv in (0.3, 0.7, 1.6, 3.0):
        mech = SlottedLink(lv, 1.0)
        grid = np.linspace(-np.pi, np.pi, 181)
        mo = mech.motion(grid)
        f0, f1, f2 = (sp.lambdify(phi, e.subs(lam, lv), "numpy") for e in (psi, d1, d2))
        assert np.allclose(np.mod(mo.psi - f0(grid) + np.pi, 2 * np.pi) - np.pi, 0, atol=1e-12)
        assert np.allclose(mo.dpsi, f1(grid), atol=1e-12)
        assert np.allclose(mo.ddpsi, f2(grid), atol=1e-11)


def test_slotted_link_peak_velocity_is_lambda_over_lambda_minus_one():
    """Seed 000 (24)-(25): ψ'(0) = λ/(λ+1), ψ'(π) = λ/(λ-1) for the base mechanism."""
    for lam in (0.3, 0.5, 0.8):
        mo = SlottedLink(2.0 * lam, 2.0).motion([0.0, np.pi])
        assert mo.dpsi[0] == pytest.approx(lam / (lam + 1), abs=1e-14)
        assert mo.dpsi[1] == pytest.approx(lam / (lam - 1), abs=1e-14)


def test_whitworth_link_turns_once_per_crank_turn():
    mo = SlottedLink(2.0, 1.0).motion(np.linspace(0, 2 * np.pi, 721))
    assert mo.psi[-1] - mo.psi[0] == pytest.approx(2 * np.pi, abs=1e-12)
    assert np.all(mo.dpsi > 0)
    # time ratio of the quick return: the link's half turns take unequal crank angles
    assert np.all(np.diff(mo.psi) > 0)


def test_slotted_link_rejects_lambda_one():
    with pytest.raises(DimensionError, match="λ = crank / pivot_distance = 2 / 2 = 1"):
        SlottedLink(2.0, 2.0)


@given(st.floats(0.1, 10))
def test_sine_mechanism(r):
    phi = np.linspace(0, 2 * np.pi, 73)
    mo = SineMechanism(r).motion(phi)
    assert np.allclose(mo.s, r * np.cos(phi), atol=1e-14 * r)
    assert np.allclose(mo.ds, -r * np.sin(phi), atol=1e-14 * r)
    assert np.allclose(mo.dds, -r * np.cos(phi), atol=1e-14 * r)
    assert np.allclose(mo.points["K"].p[:, 0], mo.points["A"].p[:, 0])


@pytest.mark.parametrize("offset", ["x", None, float("nan"), [1.0]])
def test_an_offset_that_is_not_a_finite_number_is_named(offset):
    with pytest.raises(DimensionError, match="offset must be"):
        SliderCrank(1.0, 3.0, offset)


def test_no_crank_angles_give_empty_laws():
    from mechlab import ExternalGeneva
    for mech in (SlottedLink(0.5, 1.0), SlottedLink(2.0, 1.0), SliderCrank(1.0, 3.0), SineMechanism(1.0),
                 ExternalGeneva(4, 1.0)):
        mo = mech.motion(np.array([]))
        out = (mo.output.value, mo.output.d, mo.output.dd)
        assert all(x.shape == (0,) for x in out)
