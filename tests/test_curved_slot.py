"""Curved-slot slotted links (seed 000 §1-2): closure, analogs, closed form vs general solver, errors."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from strategies import revolving_fourbars, revolving_slider_cranks

from mechlab import AssemblyError, DimensionError, FourBar, SingularityError
from mechlab.mechanisms.curved_slot import (
    CircleSlot,
    CurvedSlotLink,
    ParametricSlot,
    SampledSlot,
    TranslatingCurvedSlot,
)

H = 1e-5


def circle_as_parametric(center, radius):
    x0, y0 = center
    return ParametricSlot(lambda t: np.stack([x0 + radius * np.cos(t), y0 + radius * np.sin(t)], -1),
                          lambda t: np.stack([-radius * np.sin(t), radius * np.cos(t)], -1),
                          lambda t: np.stack([-radius * np.cos(t), -radius * np.sin(t)], -1),
                          -np.pi, np.pi, periodic=True)


def wavy(k=0.2, amp=0.1, w=3.0, t0=0.3, t1=1.8):
    """y = k·x + amp·sin(w·x), parametrised by x: an implicit equation to check closure against."""
    return ParametricSlot(lambda t: np.stack([t, k * t + amp * np.sin(w * t)], -1),
                          lambda t: np.stack([np.ones_like(t), k + amp * w * np.cos(w * t)], -1),
                          lambda t: np.stack([np.zeros_like(t), -amp * w * w * np.sin(w * t)], -1), t0, t1)


def ellipse(x0=1.0, p=0.6, q=0.5):
    return ParametricSlot(lambda t: np.stack([x0 + p * np.cos(t), q * np.sin(t)], -1),
                          lambda t: np.stack([-p * np.sin(t), q * np.cos(t)], -1),
                          lambda t: np.stack([-p * np.cos(t), -q * np.sin(t)], -1), -np.pi, np.pi, periodic=True)


def pin_in_link(mech, mo):
    """R(-ψ)(A - B): the pin seen from the slotted link."""
    v = mo.points["A"].p - mo.points["B"].p
    c, s = np.cos(mo.psi), np.sin(mo.psi)
    return np.stack([c * v[:, 0] + s * v[:, 1], -s * v[:, 0] + c * v[:, 1]], -1)


def assert_analogs(mo, up, dn, law=("psi", "dpsi", "ddpsi"), tol=1e-6):
    _f0, f1, f2 = (getattr(mo, k) for k in law)
    u0, u1 = getattr(up, law[0]), getattr(up, law[1])
    d0, d1 = getattr(dn, law[0]), getattr(dn, law[1])
    assert np.max(np.abs((u0 - d0) / (2 * H) - f1)) < tol * (1 + np.max(np.abs(f1)))
    assert np.max(np.abs((u1 - d1) / (2 * H) - f2)) < tol * (1 + np.max(np.abs(f2)))


# -- circular slots: closed form = general solver = four-bar -----------------------------------
@given(revolving_fourbars())
@settings(max_examples=120, deadline=None)
def test_circular_slot_closed_form_equals_general_solver_and_fourbar(fb):
    """Seed 000 §1, Fig. 1-2: the four-bar is a slotted link whose slot is the circle of radius
    l_AB about B (at l_BE from the pivot). Frame: the seed's is the four-bar's turned by π."""
    side = fb.assembly
    closed = CurvedSlotLink(fb.crank, fb.ground, CircleSlot((fb.rocker, 0.0), fb.coupler), start=side * 1.0)
    general = CurvedSlotLink(fb.crank, fb.ground, circle_as_parametric((fb.rocker, 0.0), fb.coupler),
                             start=side * 1.0)
    phi = np.linspace(0, 2 * np.pi, 181)
    ref = fb.motion(phi + np.pi)
    scale = 1 + np.max(np.abs(ref.ddpsi))
    for mech in (closed, general):
        mo = mech.motion(phi)
        assert np.max(np.abs(np.angle(np.exp(1j * (mo.psi + np.pi - ref.psi))))) < 1e-11
        assert np.max(np.abs(mo.dpsi - ref.dpsi)) < 1e-10 * scale
        assert np.max(np.abs(mo.ddpsi - ref.ddpsi)) < 1e-9 * scale
        assert np.all(np.abs(np.diff(mo.psi)) < 1.0)  # continuous branch


@given(revolving_slider_cranks())
@settings(max_examples=120, deadline=None)
def test_translating_circle_equals_slider_crank(sc):
    """Seed 000 Fig. 3-4: the slider-crank is a translating slot along a circle of radius l_AB."""
    phi = np.linspace(0, 2 * np.pi, 181)
    ref = sc.motion(phi)
    circle = TranslatingCurvedSlot(sc.crank, CircleSlot((0.0, sc.offset), sc.rod),
                                   start=np.pi if sc.assembly == 1 else 0.0)
    mo = circle.motion(phi)
    s = 1 + sc.rod + sc.crank
    assert np.max(np.abs(mo.s - ref.s)) < 1e-12 * s
    assert np.max(np.abs(mo.ds - ref.ds)) < 1e-11 * s
    assert np.max(np.abs(mo.dds - ref.dds)) < 1e-10 * s


# -- general curves: closure and analogs --------------------------------------------------------
@given(st.floats(0.1, 0.6), st.floats(-0.15, 0.15), st.floats(0.0, 0.35))
@settings(max_examples=60, deadline=None)
def test_general_slot_closes_and_analogs_match_differences(a, amp, k):
    d = 1.0
    slot = wavy(k=k, amp=amp * 0.5, t0=0.2, t1=1.9)
    try:
        mech = CurvedSlotLink(a, d, slot)
    except (SingularityError, DimensionError):
        return  # this slot jams or misses the pin: covered by the error tests
    phi = mech.cycle(241)
    mo = mech.motion(phi)
    pin = pin_in_link(mech, mo)
    # closure: the pin lies on y = k x + amp sin(3x)
    assert np.max(np.abs(pin[:, 1] - (k * pin[:, 0] + amp * 0.5 * np.sin(3 * pin[:, 0])))) < 1e-12
    inner = phi[1:-1]
    assert_analogs(mech.motion(inner), mech.motion(inner + H), mech.motion(inner - H))


def test_ellipse_slot_closure_analogs_and_beta_decomposition():
    mech = CurvedSlotLink(0.4, 1.0, ellipse(), start=1.0)
    phi = mech.turn(721)
    mo = mech.motion(phi)
    pin = pin_in_link(mech, mo)
    assert np.max(np.abs(((pin[:, 0] - 1.0) / 0.6) ** 2 + (pin[:, 1] / 0.5) ** 2 - 1)) < 1e-12
    assert np.all(pin[:, 1] > 0)  # the upper arc (start = 1.0 rad)
    assert_analogs(mo, mech.motion(phi + H), mech.motion(phi - H))
    # ψ = ψ_K - β (seed 000, formula (12))
    base, beta = mech.base().motion(phi), mech.beta(phi)
    assert np.allclose(mo.psi, base.psi - beta.theta, atol=1e-14)
    assert np.allclose(mo.dpsi, base.dpsi - beta.d, atol=1e-14)
    assert np.allclose(np.arctan2(pin[:, 1], pin[:, 0]), beta.theta, atol=1e-12)
    # the transmission angle is in [0, π/2] and below π/2 (the slot is not radial)
    assert np.all((mo.transmission > 0) & (mo.transmission <= np.pi / 2))


def test_rotating_link_lambda_above_one():
    """λ > 1: the link turns fully; ψ(2π) - ψ(0) = 2π and the analogs are continuous."""
    mech = CurvedSlotLink(2.0, 1.0, CircleSlot((2.0, 0.0), 2.5), start=1.0)
    assert mech.rotates and mech.can_turn
    phi = mech.turn(721)
    mo = mech.motion(phi)
    assert np.isclose(mo.psi[-1] - mo.psi[0], 2 * np.pi, atol=1e-12)
    assert_analogs(mo, mech.motion(phi + H), mech.motion(phi - H))
    fb = FourBar(2.0, 2.5, 2.0, 1.0, 1)  # the same linkage (double-crank)
    assert np.allclose(fb.motion(phi + np.pi).dpsi, mo.dpsi, atol=1e-12)


def test_translating_general_curve_and_spline():
    """x = 0.3 y² - 0.2 y + 0.1 y³: closure, analogs; a spline through it agrees to 1e-6."""
    f = lambda t: np.stack([0.3 * t**2 - 0.2 * t + 0.1 * t**3, t], -1)  # noqa: E731
    slot = ParametricSlot(f, lambda t: np.stack([0.6 * t - 0.2 + 0.3 * t**2, np.ones_like(t)], -1),
                          lambda t: np.stack([0.6 + 0.6 * t, np.zeros_like(t)], -1), -1.5, 1.5)
    mech = TranslatingCurvedSlot(1.2, slot)
    phi = mech.turn(361)
    mo = mech.motion(phi)
    A = mo.points["A"].p
    y = A[:, 1]
    assert np.max(np.abs(A[:, 0] - mo.s - (0.3 * y**2 - 0.2 * y + 0.1 * y**3))) < 1e-13
    assert_analogs(mo, mech.motion(phi + H), mech.motion(phi - H), law=("s", "ds", "dds"))
    xa = mech.x_alpha(phi)
    base = mech.base().motion(phi)
    assert np.allclose(mo.s, base.s - xa.theta, atol=1e-15)  # formula (1)
    spline = TranslatingCurvedSlot(1.2, SampledSlot(f(np.linspace(-1.5, 1.5, 301))))
    sm = spline.motion(phi)
    assert np.max(np.abs(sm.s - mo.s)) < 1e-6
    assert np.max(np.abs(sm.ds - mo.ds)) < 1e-4


def test_sampled_closed_spline_reproduces_fourbar():
    fb = FourBar(0.3, 0.8, 1.0, 1.0, -1)
    th = np.linspace(0, 2 * np.pi, 721)[:-1]
    slot = SampledSlot(np.stack([1.0 + 0.8 * np.cos(th), 0.8 * np.sin(th)], -1), closed=True)
    mech = CurvedSlotLink(0.3, 1.0, slot, start=0.75 * slot.t1)  # lower half ↔ kc = -1
    phi = mech.turn(181)
    assert np.max(np.abs(mech.motion(phi).dpsi - fb.motion(phi + np.pi).dpsi)) < 1e-8


def test_solver_is_vectorised_and_handles_unsorted_angles():
    mech = CurvedSlotLink(0.4, 1.0, ellipse(), start=1.0)
    rng = np.random.default_rng(1)
    phi = rng.uniform(-10, 10, 500)
    mo = mech.motion(phi)
    order = np.argsort(np.mod(phi, 2 * np.pi))
    again = mech.motion(np.mod(phi, 2 * np.pi)[order])
    assert np.allclose(np.angle(np.exp(1j * (mo.psi[order] - again.psi))), 0, atol=1e-12)
    assert np.allclose(mo.dpsi[order], again.dpsi, atol=1e-12)


# -- errors -----------------------------------------------------------------------------------------
def test_pin_would_leave_a_short_slot():
    short = wavy(k=0.2, amp=0.0, t0=0.8, t1=1.9)  # a straight slot missing the pivot, ending at x = 0.8
    mech = CurvedSlotLink(0.4, 1.0, short)
    assert not mech.can_turn
    (lo, hi), = mech.crank_ranges()
    assert np.isclose(lo, -hi)
    # at the range end the pin is exactly at the slot's end (x = 0.8 → distance √(0.8² + 0.16²))
    r_end = np.hypot(0.8, 0.16)
    a, d = 0.4, 1.0
    assert np.isclose(np.sqrt(a * a + d * d + 2 * a * d * np.cos(hi)), r_end, rtol=1e-12)
    with pytest.raises(AssemblyError, match=r"the pin would leave the slot: the slot ends 0.815843 from B"):
        mech.motion(np.pi)
    mo = mech.motion(mech.cycle(50))  # inside the range it works
    assert np.all(np.isfinite(mo.dpsi))


def test_slot_tangent_to_pivot_circle_is_a_singularity():
    # ellipse about the pivot's far side whose nearest point is farther than |d - a|: the slot turns tangent
    mech = CurvedSlotLink(0.4, 1.0, ellipse(x0=1.2, p=0.45, q=0.5), start=1.0)
    assert not mech.can_turn
    with pytest.raises(SingularityError, match="tangent to the circle of radius"):
        mech.motion(np.pi)


def test_bad_input_messages():
    with pytest.raises(DimensionError, match=r"λ = crank / pivot_distance = 1 / 1 = 1"):
        CurvedSlotLink(1.0, 1.0, CircleSlot((1.0, 0.0), 1.0))
    with pytest.raises(DimensionError, match=r"the slot never reaches the pin's position at φ = 0: the pin is "
                                             r"crank \+ pivot_distance = 1.4 from B"):
        CurvedSlotLink(0.4, 1.0, wavy(t0=0.2, t1=1.0))
    with pytest.raises(DimensionError, match="give start="):
        CurvedSlotLink(0.4, 1.0, ellipse())
    with pytest.raises(AssemblyError, match=r"never lies on the circular slot"):
        CurvedSlotLink(0.4, 1.0, CircleSlot((5.0, 0.0), 1.0))
    with pytest.raises(DimensionError, match="radius must be > 0"):
        CircleSlot((1.0, 0.0), -1.0)
    with pytest.raises(DimensionError, match=r"must return an array of shape"):
        CurvedSlotLink(0.4, 1.0, ParametricSlot(lambda t: t, lambda t: t, lambda t: t, 0.0, 1.0))
    with pytest.raises(DimensionError, match="samples 1 and 2 coincide"):
        SampledSlot(np.array([[0, 0], [1, 0], [1, 0], [2, 0.0]]))
    above = ParametricSlot(lambda t: np.stack([t, 1 + t], -1), lambda t: np.stack([1 + 0 * t, 1 + 0 * t], -1),
                           lambda t: np.stack([0 * t, 0 * t], -1), 0.0, 1.0)
    with pytest.raises(DimensionError, match="never crosses the x axis"):
        TranslatingCurvedSlot(1.0, above)
    half = ParametricSlot(lambda t: np.stack([0 * t, t], -1), lambda t: np.stack([0 * t, 1 + 0 * t], -1),
                          lambda t: np.stack([0 * t, 0 * t], -1), -0.5, 0.5)
    mech = TranslatingCurvedSlot(1.0, half)  # a straight slot of half-height 0.5 < crank 1
    assert not mech.can_turn
    with pytest.raises(AssemblyError, match=r"cannot assemble at φ = 90.00°.*spans heights \[-0.5, 0.5\]"):
        mech.motion(np.pi / 2)


def test_pin_starting_where_the_slot_is_tangent_is_refused_and_the_seam_counts_once():
    """A closed slot whose seam (t = ±π) is its farthest point from B, reached by the pin at φ = 0:
    one root, not two, and the seed's Fig. 10 verdict (pressure angle 90°)."""
    shifted = ParametricSlot(lambda t: np.stack([1 - 0.4 * np.cos(t), -0.4 * np.sin(t)], -1),
                             lambda t: np.stack([0.4 * np.sin(t), -0.4 * np.cos(t)], -1),
                             lambda t: np.stack([0.4 * np.cos(t), 0.4 * np.sin(t)], -1), -np.pi, np.pi, periodic=True)
    with pytest.raises(SingularityError, match=r"at φ = 0 the slot \(t = -3.14159\) is tangent"):
        CurvedSlotLink(0.4, 1.0, shifted)
