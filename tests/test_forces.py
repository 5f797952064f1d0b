"""Kinetostatics (mechlab.kinetostatics): power balance, equilibrium, hand-derived cases, friction, drive."""

import itertools

import numpy as np
import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st
from strategies import revolving_fourbars, revolving_slider_cranks

from mechlab import FourBar, MechanismError, SineMechanism, SliderCrank, SlottedLink
from mechlab.kinetostatics.drive import DriveError, cycle_mean, drive
from mechlab.kinetostatics.machines import Kinetostatics
from mechlab.kinetostatics.model import (
    FRAME,
    Body,
    Force,
    ForceModel,
    FrictionError,
    HigherPair,
    LoadError,
    MassError,
    Prismatic,
    Revolute,
    SelfLockingError,
    StructureError,
    Torque,
    model_for,
    slender_bar,
)
from mechlab.kinetostatics.solve import solve, virtual_work_torque

unit_floats = st.floats(min_value=-1.0, max_value=1.0, allow_nan=False)
pos_floats = st.floats(min_value=0.05, max_value=3.0, allow_nan=False)


@st.composite
def slotted_links(draw):
    pd = draw(st.floats(min_value=0.3, max_value=5.0))
    lam = draw(st.one_of(st.floats(0.1, 0.9), st.floats(1.1, 3.0)))
    return SlottedLink(lam * pd, pd)


@st.composite
def sine_mechanisms(draw):
    return SineMechanism(draw(st.floats(min_value=0.1, max_value=5.0)))


def loaded(draw, mech):
    """The mechanism's model with random masses, inertias, centres of mass and loads on every link."""
    model = model_for(mech)
    size = max(mech.crank, 0.1)
    loads = []
    for b in model.bodies:
        model = model.with_body(b.name, mass=draw(pos_floats), inertia=draw(pos_floats) * size**2,
                                com=(draw(unit_floats) * size, draw(unit_floats) * size))
        loads.append(Force(b.name, (draw(unit_floats) * size, draw(unit_floats) * size),
                           (draw(unit_floats) * 10, draw(unit_floats) * 10)))
        loads.append(Torque(b.name, draw(unit_floats) * 10 * size))
    return model, loads, draw(st.floats(0.5, 30.0)), draw(st.floats(-50.0, 50.0))


@given(st.data(), st.one_of(revolving_fourbars(), revolving_slider_cranks(), slotted_links(), sine_mechanisms()))
@settings(max_examples=120, deadline=None)
def test_group_torque_equals_power_balance_and_links_are_in_equilibrium(data, mech):
    model, loads, w, e = loaded(data.draw, mech)
    mo = mech.motion(mech.turn(73))
    res = solve(model, mo, loads, omega1=w, eps1=e)
    vw = virtual_work_torque(model, mo, loads, omega1=w, eps1=e)
    scale = np.max(np.abs(vw)) + 1e-300
    assert np.max(np.abs(res.torque - vw)) <= 1e-9 * scale
    assert np.max(np.abs(res.torque - res.ideal_torque)) <= 1e-9 * scale
    assert res.residual <= 1e-11
    assert np.all(res.efficiency().filled(1.0) == 1.0)   # no friction: η = 1 wherever it is defined


@given(st.data(), st.one_of(revolving_fourbars(), revolving_slider_cranks(), slotted_links(), sine_mechanisms()),
       st.floats(0.0, 0.15), st.floats(0.0, 0.2))
@settings(max_examples=80, deadline=None)
def test_friction_power_balance(data, mech, f, r):
    model, loads, w, e = loaded(data.draw, mech)
    model = model.with_friction(f, r * mech.crank)
    mo = mech.motion(mech.turn(73))
    try:
        res = solve(model, mo, loads, omega1=w, eps1=e)
    except SelfLockingError:
        return
    scale = np.max(np.abs(res.torque)) + 1e-300
    # driving power = useful power + friction losses, with the losses from the iterated reactions
    assert np.max(np.abs(res.torque - res.torque_power)) <= 1e-9 * scale
    assert res.residual <= 1e-10
    assert np.all(res.losses >= 0)
    eta = res.efficiency()
    assert np.all(eta.filled(0.0) <= 1.0 + 1e-12)


def test_slider_crank_static_against_hand_solution():
    """Massless links, a force P resisting the slider, ω1 = 0: statics by hand.

    Slider: rod thrust S along u = (B − A)/l, guide normal N, load (−P, 0):
    S·u_x = P, N = −S·u_y. Crank: the rod pushes A with −S·u, so M_b = S·(A × u).
    """
    sc = SliderCrank(0.1, 0.4, 0.03)
    phi = np.radians(np.arange(5.0, 360.0, 10.0))
    mo = sc.motion(phi)
    P = 250.0
    res = solve(model_for(sc), mo, [Force("slider", "B", (-P, 0.0))], omega1=0.0, gravity=(0.0, 0.0))
    A, B = mo.points["A"].p, mo.points["B"].p
    u = (B - A) / sc.rod
    S = P / u[:, 0]
    assert np.allclose(res.torque, S * (A[:, 0] * u[:, 1] - A[:, 1] * u[:, 0]), rtol=1e-12, atol=1e-12)
    assert np.allclose(res.torque, P * mo.ds, rtol=1e-12, atol=1e-12)   # virtual work: M_b = P·s'
    assert np.allclose(res.reactions["guide"].normal, -S * u[:, 1], rtol=1e-12, atol=1e-12)
    assert np.allclose(res.reactions["B"].force, S[:, None] * u, rtol=1e-12, atol=1e-12)   # rod on slider
    assert np.allclose(res.reactions["O"].force, S[:, None] * u, rtol=1e-12, atol=1e-12)   # frame on crank
    assert np.allclose(res.reactions["guide"].couple, 0.0, atol=1e-12)  # N passes through B


def test_fourbar_reaction_grows_as_transmission_angle_falls():
    """Massless four-bar, torque T on the rocker: the coupler is a two-force member and
    |R_B| = T / (l_BE · sin μ) — the transmission angle drives the reaction."""
    fb = FourBar(0.1, 0.3, 0.3, 0.35)
    mo = fb.motion(fb.turn(181))
    T = 40.0
    res = solve(model_for(fb), mo, [Torque("rocker", -T)], omega1=10.0, gravity=(0.0, 0.0))
    assert np.allclose(res.reactions["B"].magnitude, T / (fb.rocker * np.sin(mo.transmission)), rtol=1e-10)
    assert np.allclose(res.torque, T * mo.dpsi, rtol=1e-10, atol=1e-12)   # M_b·ω1 = T·ω3


def test_crank_gravity_and_inertia_by_hand():
    """Only the crank has mass, its centre at distance c on the crank line, ω1 constant:
    the inertia force passes through O, so M_b = m·g·c·cos φ; R_O = m(a_S − g)."""
    fb = FourBar(0.1, 0.3, 0.3, 0.35)
    m, c, w = 2.0, 0.04, 15.0
    model = model_for(fb).with_body("crank", mass=m, inertia=0.003, com=(c, 0.0))
    phi = fb.turn(37)
    res = solve(model, fb.motion(phi), omega1=w)
    assert np.allclose(res.torque, m * 9.81 * c * np.cos(phi), rtol=1e-12, atol=1e-12)
    aS = -w**2 * c * np.stack([np.cos(phi), np.sin(phi)], axis=1)
    assert np.allclose(res.reactions["O"].force, m * (aS - np.array([0.0, -9.81])), rtol=1e-12, atol=1e-12)


def test_crank_angular_acceleration_needs_J_O_eps():
    """Massive crank only, at rest (ω1 = 0) but accelerating: M_b = J_O·ε1 + gravity moment, J_O = J_S + m c²."""
    fb = FourBar(0.1, 0.3, 0.3, 0.35)
    m, c, J, e = 1.5, 0.05, 0.002, 7.0
    res = solve(model_for(fb).with_body("crank", mass=m, inertia=J, com=(c, 0.0)), fb.motion(fb.turn(19)),
                omega1=0.0, eps1=e, gravity=(0.0, 0.0))
    assert np.allclose(res.torque, (J + m * c * c) * e, rtol=1e-12)


def test_higher_pair_equals_massless_block():
    """A pin in a straight slot as a higher pair (reaction along the slot's normal) gives the
    same balancing torque and pivot reaction as the RPR dyad with a massless block."""
    sl = SlottedLink(0.1, 0.25)
    mo = sl.motion(sl.turn(91))
    base = model_for(sl).with_body("link", mass=3.0)
    loads = [Torque("link", -12.0)]
    rpr = solve(base, mo, loads, omega1=12.0, eps1=2.0)
    link = base.body("link")
    crank = base.body("crank")
    hp = ForceModel((crank, link),
                    (Revolute("O", FRAME, "crank", "O"), HigherPair("A", "link", "crank", "A", np.pi / 2),
                     Revolute("B", FRAME, "link", "B")),
                    (("link",),), "crank", "O")
    res = solve(hp, mo, loads, omega1=12.0, eps1=2.0)
    assert np.allclose(res.torque, rpr.torque, rtol=1e-12, atol=1e-12)
    assert np.allclose(res.reactions["B"].force, rpr.reactions["B"].force, rtol=1e-12, atol=1e-11)
    assert np.allclose(np.abs(res.reactions["A"].normal), np.abs(rpr.reactions["slot"].normal), rtol=1e-12)
    assert np.allclose(rpr.reactions["slot"].couple, 0.0, atol=1e-10)   # a massless block carries no couple


def test_curved_normal_callable_and_friction_in_higher_pair():
    sl = SlottedLink(0.1, 0.25)
    mo = sl.motion(sl.turn(91))
    link, crank = model_for(sl).body("link"), model_for(sl).body("crank")
    from mechlab.geometry import perp, unit
    def normal(m):
        return perp(unit(m.psi))  # the slot normal, given as a function of the motion
    hp = ForceModel((crank, link), (Revolute("O", FRAME, "crank", "O"),
                                    HigherPair("A", "link", "crank", "A", normal, friction=0.1),
                                    Revolute("B", FRAME, "link", "B")), (("link",),), "crank", "O")
    res = solve(hp, mo, [Torque("link", -12.0)], omega1=12.0)
    assert np.max(np.abs(res.torque - res.torque_power)) < 1e-9 * np.max(np.abs(res.torque))
    assert np.all(res.losses >= 0) and np.max(res.losses) > 0
    assert res.residual < 1e-12


def test_friction_lowers_efficiency_and_cycle_definitions():
    sc = SliderCrank(0.1, 0.4)
    mo = sc.motion(sc.turn(361))
    def working(m):
        return np.where(m.ds < 0, 2000.0, 0.0)   # resists the slider's return stroke only
    loads = [Force("slider", "B", lambda m: np.stack([working(m), 0 * m.s], axis=1))]
    model = model_for(sc).with_body("rod", mass=1.0).with_body("slider", mass=2.0)
    ideal = solve(model, mo, loads, omega1=10.0)
    rough = solve(model.with_friction(0.1, 0.01), mo, loads, omega1=10.0)
    eta = rough.efficiency()
    assert np.all(eta[~eta.mask] < 1.0) and np.all(eta[~eta.mask] > 0.0)
    assert np.all(rough.torque[~eta.mask] > ideal.torque[~eta.mask])
    # η = M_ideal / M_b (power balance) where the drive delivers power
    sel = ~eta.mask
    assert np.allclose(eta[sel], ideal.torque[sel] / rough.torque[sel], rtol=1e-12)
    moving = mo.ds < 0
    mean = rough.cycle_efficiency(moving)
    assert np.isclose(mean, np.mean(eta.data[moving & sel]), rtol=1e-14)
    work = rough.cycle_efficiency(how="work")
    a_drive = np.trapezoid(rough.torque, mo.phi)
    assert np.isclose(work, 1 - np.trapezoid(rough.losses, mo.phi) / a_drive)
    assert 0 < work < 1 and 0 < mean < 1
    assert ideal.cycle_efficiency(how="work") == pytest.approx(1.0, abs=1e-12)


def test_self_locking_is_reported():
    sc = SliderCrank(0.1, 0.105)  # rod barely longer than the crank: pressure angle near 72°
    mo = sc.motion(sc.turn(73))
    with pytest.raises(SelfLockingError, match="self-locking"):
        solve(model_for(sc).with_friction(0.9, 0.02), mo, [Force("slider", "B", (-100.0, 0.0))], omega1=5.0)


def test_bad_inputs_raise_named_errors():
    fb = FourBar(0.1, 0.3, 0.3, 0.35)
    model = model_for(fb)
    with pytest.raises(MassError, match=r"mass of coupler must be ≥ 0, got -1"):
        model.with_body("coupler", mass=-1.0)
    with pytest.raises(MassError, match="moment of inertia of rocker"):
        model.with_body("rocker", mass=1.0, inertia=float("nan"))
    with pytest.raises(FrictionError, match=r"friction coefficient of O must be < 1, got 1.5 \(0 ≤ f < 1\)"):
        model.with_friction(1.5, 0.01)
    with pytest.raises(FrictionError, match=r"friction coefficient of O must be ≥ 0, got -0.1"):
        model.with_friction(-0.1, 0.01)
    with pytest.raises(FrictionError, match="journal radius"):
        model.with_friction(0.1, -0.01)
    mo = fb.motion(fb.turn(11))
    with pytest.raises(LoadError, match=r"force on rocker must broadcast to shape \(11, 2\)"):
        solve(model, mo, [Force("rocker", "B", np.zeros((5, 2)))])
    with pytest.raises(LoadError, match="must be finite"):
        solve(model, mo, [Torque("rocker", np.nan)])
    with pytest.raises(StructureError, match="unknown body 'piston'"):
        solve(model, mo, [Torque("piston", 1.0)])
    with pytest.raises(StructureError, match=r"not statically determinate: 4 unknown .* 6 equilibrium"):
        ForceModel(model.bodies, model.pairs[:3], model.groups, "crank", "O")
    with pytest.raises(MechanismError):
        solve(model, mo, omega1=float("inf"))
    assert issubclass(MassError, MechanismError) and issubclass(FrictionError, MechanismError)


def test_group_that_cannot_carry_its_load_is_a_singularity():
    """A contact normal through the link's own pivot gives no moment about it: the
    one-link group's equations are singular, reported as a SingularityError (not a NaN)."""
    from mechlab.errors import SingularityError
    sl = SlottedLink(0.1, 0.25)
    base = model_for(sl)
    bad = ForceModel((base.body("crank"), base.body("link")),
                     (Revolute("O", FRAME, "crank", "O"), HigherPair("A", "link", "crank", "A", 0.0),
                      Revolute("B", FRAME, "link", "B")), (("link",),), "crank", "O")
    with pytest.raises(SingularityError, match=r"group \('link',\) cannot carry its loads at φ = 0.00°"):
        solve(bad, sl.motion(sl.turn(5)), [Torque("link", 1.0)])


def _quad_drive(f, a, b, eta, sense=1.0):
    """Mean, rms of the motor torque m(f) = f/η where f·sense > 0, f·η elsewhere, by quad on
    [a, b] split at the roots of f (found by brentq on a fine grid); peak by bounded search."""
    from scipy.integrate import quad
    from scipy.optimize import brentq, minimize_scalar
    x = np.linspace(a, b, 2001)
    y = f(x)
    edges = [a, *[brentq(f, u, v, xtol=1e-15)
                  for u, v, fu, fv in zip(x, x[1:], y, y[1:], strict=False) if fu * fv < 0], b]

    def m(t):
        v = f(t)
        return v / eta if v * sense > 0 else v * eta

    mean = sum(quad(m, u, v, epsabs=1e-13, epsrel=1e-12, limit=200)[0] for u, v in itertools.pairwise(edges)) / (b - a)
    sq = sum(quad(lambda t: m(t) ** 2, u, v, epsabs=1e-13, epsrel=1e-12, limit=200)[0]
             for u, v in itertools.pairwise(edges)) / (b - a)
    # every local maximum of |m| on the grid is refined: near-equal peaks may swap order
    am = np.abs([m(t) for t in x])
    peak = float(am.max())
    for i in np.flatnonzero((am >= np.roll(am, 1)) & (am >= np.roll(am, -1))):
        lo, hi = x[max(i - 1, 0)], x[min(i + 1, len(x) - 1)]
        peak = max(peak, -minimize_scalar(lambda t: -abs(m(t)), bounds=(lo, hi), method="bounded",
                                          options={"xatol": 1e-12}).fun)
    return mean, float(np.sqrt(sq)), peak


def test_drive_one_rule_by_hand():
    """M = 10 + 30 sin φ N·m at ω1 = 10 rad/s through η = 0.8: the motor supplies M/η where
    M > 0 and gets M·η back where M < 0. With φ1 = π + asin(1/3), φ2 = 2π - asin(1/3) the
    roots, ∫(10 + 30 sin φ) over [φ1, φ2] = 10(φ2 - φ1) - 60 cos(asin(1/3)) = -A < 0, so
    2π·⟨M_m⟩ = (20π + A)/η - A·η (closed form); peak = 40/η = 50; rms and the rule by quad."""
    phi = np.linspace(0, 2 * np.pi, 3601)
    M = 10.0 + 30.0 * np.sin(phi)
    d = drive(M, phi, omega1=10.0, overload=2.0, efficiency=0.8)
    s = np.arcsin(1 / 3)
    A = -(10 * (np.pi - 2 * s) - 60 * np.cos(s))
    mean = ((20 * np.pi + A) / 0.8 - A * 0.8) / (2 * np.pi)
    assert d.mean_torque == pytest.approx(mean, rel=1e-6)
    q_mean, q_rms, q_peak = _quad_drive(lambda t: 10.0 + 30.0 * np.sin(t), 0.0, 2 * np.pi, 0.8)
    assert q_mean == pytest.approx(mean, rel=1e-10)
    assert d.rms_torque == pytest.approx(q_rms, rel=1e-6)
    assert d.peak_torque == pytest.approx(50.0, rel=1e-6) and q_peak == pytest.approx(50.0, rel=1e-9)
    assert d.mean_power == pytest.approx(mean * 10.0, rel=1e-6)
    assert d.peak_power == pytest.approx(500.0, rel=1e-6)
    assert d.nominal_torque == pytest.approx(q_rms, rel=1e-6) and d.governing == "rms"   # rms 29.9 > 50/2
    assert d.nominal_power == pytest.approx(10.0 * q_rms, rel=1e-6)
    tight = drive(M, phi, 10.0, overload=1.2, efficiency=0.8)
    assert tight.governing == "peak" and tight.nominal_torque == pytest.approx(50.0 / 1.2, rel=1e-6)
    assert np.array_equal(d.torque, M) and np.allclose(d.motor_torque, np.where(M > 0, M / 0.8, M * 0.8))
    # the crank turning the other way with the opposite torque is the same drive
    r = drive(-M, phi, omega1=-10.0, overload=2.0, efficiency=0.8)
    assert r.mean_power == pytest.approx(d.mean_power, rel=1e-12) and r.mean_torque == pytest.approx(-d.mean_torque)
    assert r.nominal_power == pytest.approx(d.nominal_power, rel=1e-12) and r.governing == d.governing
    assert d.choose([100, 250, 300, 400]) == 300
    with pytest.raises(MechanismError, match="no motor"):
        d.choose([10, 20])
    for kw, msg in (({"overload": 0.5}, "overload factor"), ({"efficiency": 1.5}, "efficiency"),
                    ({"efficiency": 0.0}, "efficiency")):
        with pytest.raises(DriveError, match=msg):
            drive(M, phi, 10.0, **kw)
    with pytest.raises(DriveError, match="ω1 must be finite and non-zero"):
        drive(M, phi, 0.0)
    with pytest.raises(DriveError, match="same length"):
        drive(M[:-1], phi, 10.0)
    with pytest.raises(DriveError, match="finite"):
        drive(np.where(phi > 1, np.nan, M), phi, 10.0)
    with pytest.raises(DriveError, match="phi must increase"):
        drive(M, phi[::-1], 10.0)
    assert issubclass(DriveError, MechanismError)
    assert cycle_mean(np.cos(phi) ** 2, phi) == pytest.approx(0.5, rel=1e-9)


def test_drive_integrates_a_jump_exactly_with_both_one_sided_samples():
    """A press-like step: P on [a, b], 0 elsewhere. Sampled with both one-sided values at a and
    b the trapezoidal rule is exact: ⟨M⟩ = P(b - a)/2π, ⟨M²⟩ = P²(b - a)/2π."""
    a, b, P = 1.0, 2.5, 7.0
    phi = np.concatenate([np.linspace(0, a, 5), np.linspace(a, b, 9), np.linspace(b, 2 * np.pi, 7)])
    M = np.concatenate([np.zeros(5), np.full(9, P), np.zeros(7)])
    d = drive(M, phi, 3.0, overload=3.0)
    assert d.mean_torque == pytest.approx(P * (b - a) / (2 * np.pi), rel=1e-14)
    assert d.rms_torque == pytest.approx(P * np.sqrt((b - a) / (2 * np.pi)), rel=1e-14)
    assert d.peak_torque == P and d.governing == "rms"


coefficients = st.lists(st.floats(-10.0, 10.0), min_size=3, max_size=7)


@given(coefficients, st.floats(0.3, 1.0), st.floats(1.0, 4.0), st.floats(0.5, 50.0), st.sampled_from([1.0, -1.0]))
@settings(max_examples=60, deadline=None)
@example(c=[0.0, 0.0, 0.0, 0.0, 1e-05, 0.0, 2.0], eta=1.0, k=1.0, w=1.0, sense=1.0)  # three peaks within 1e-5
def test_drive_rule_on_random_torques_against_quad(c, eta, k, w, sense):
    """Random trigonometric torques M(φ) = c0 + Σ (c_2j-1 cos jφ + c_2j sin jφ): the sampled
    rule against quad; rms ≥ |mean| (Cauchy–Schwarz: the thermal figure never below the
    energy figure); with η < 1 the mean power is never below the lossless one."""
    def f(t):
        out = c[0] + 0.0 * t
        for j in range(1, (len(c) - 1) // 2 + 1):
            out = out + c[2 * j - 1] * np.cos(j * t) + c[2 * j] * np.sin(j * t)
        return out

    phi = np.linspace(0.0, 2 * np.pi, 20001)
    M = f(phi)
    d = drive(M, phi, sense * w, overload=k, efficiency=eta)
    mean, rms, peak = _quad_drive(f, 0.0, 2 * np.pi, eta, sense)
    size = max(np.max(np.abs(M)), 1e-3)
    assert d.mean_torque == pytest.approx(mean, abs=1e-6 * size)
    assert d.rms_torque == pytest.approx(rms, abs=1e-6 * size)
    assert d.peak_torque == pytest.approx(peak, abs=1e-6 * size) and d.peak_torque <= peak + 1e-12 * size
    assert d.nominal_torque == max(d.rms_torque, d.peak_torque / k)
    assert d.nominal_power == pytest.approx(d.nominal_torque * w, rel=1e-14)
    assert d.mean_power == pytest.approx(d.mean_torque * sense * w, rel=1e-14)
    assert d.rms_torque >= abs(d.mean_torque) * (1 - 1e-12) - 1e-12 * size
    lossless = drive(M, phi, sense * w, overload=k)
    assert d.mean_power >= lossless.mean_power - 1e-12 * size * w
    assert lossless.mean_power == pytest.approx(cycle_mean(M, phi) * sense * w, rel=1e-12, abs=1e-12 * size * w)


def test_kinetostatics_wrapper_and_slender_bar():
    sc = SliderCrank(0.1, 0.4)
    k = Kinetostatics(sc, loads=[Force("slider", "B", (-100.0, 0.0))], omega1=5.0)
    res = k.forces(sc.turn(37))
    assert np.allclose(res.torque, 100.0 * sc.motion(sc.turn(37)).ds, rtol=1e-9, atol=1e-12)
    assert k.can_turn and k.structure() == sc.structure()
    assert slender_bar(3.0, 0.4) == pytest.approx(0.04)
    m = model_for(sc).with_body("rod", mass=3.0)
    assert m.body("rod").inertia == pytest.approx(0.04)


def test_model_for_unknown_mechanism():
    with pytest.raises(TypeError, match="no force model"):
        model_for(object())


def test_press_and_rocker_examples():
    from mechlab.kinetostatics.machines import press, rocker_drive
    k = press(P=2000.0, work_fraction=0.3)
    res = k.forces(k.turn(1441))
    # the press does P × (working part of the stroke) of work per turn: mean torque = that / 2π
    stroke = 2 * 0.10
    # (the load switches on inside a sampling step: the trapezoidal rule is good to ~0.5 %)
    assert cycle_mean(res.torque, res.phi) == pytest.approx(2000.0 * 0.3 * stroke / (2 * np.pi), rel=1e-2)
    from mechlab.errors import RotationError
    with pytest.raises(RotationError, match="crank cannot turn fully"):
        press(rod=0.08)
    with pytest.raises(RotationError, match="Grashof"):
        rocker_drive(ground=0.55)
    r = rocker_drive(T=40.0, m_coupler=0.0, m_rocker=0.0).forces()
    assert cycle_mean(np.abs(r.torque), r.phi) > 0
    # no masses: the rocker torque's work over a turn = 2·T·swing, the crank's = 2π·mean
    mo = r.model and rocker_drive().motion(r.phi)
    swing = np.ptp(mo.psi)
    assert cycle_mean(r.torque, r.phi) * 2 * np.pi == pytest.approx(2 * 40.0 * swing, rel=1e-3)


def test_force_drawing_and_explorer_move_in_place():
    import matplotlib.pyplot as plt

    from mechlab.draw import animate, drawing_class
    from mechlab.kinetostatics.machines import press
    from mechlab.widgets.forces import press_explorer
    k = press()
    fig, ax = plt.subplots()
    d = drawing_class(k)(ax, k, n=24)
    d.autoscale()
    before = len(ax.get_children())
    arts = d.set_frame(7)
    assert len(ax.get_children()) == before and d.quiver in arts
    i = 7
    R = d.result.reactions["B"]
    assert np.allclose(d.quiver.U[2], R.force[i, 0] * d.scale) and np.allclose(d.quiver.V[2], R.force[i, 1] * d.scale)
    plt.close(fig)
    anim = animate(k, n=3)
    assert "<script" in anim.to_jshtml() and anim.drawing.result.residual < 1e-12
    e = press_explorer()
    assert e.message == "" and "by the power balance: the same M_b ✓" in e.status.value
    e.sliders["rod"].value = 0.08
    assert "crank cannot turn fully" in e.message
    e.sliders["rod"].value = 0.40
    e.sliders["f"].value = 0.1
    assert e.message == "" and e.result.iterations > 1
    e.angle.value = 123.0
    assert abs(np.degrees(e.result.phi[e.frame]) - 123.0) <= 3.0


def test_errata_checks_hold():
    from mechlab.course.errata.seed003_forces import ERRATA
    assert len(ERRATA) == 3
    for e in ERRATA:
        text = e.evidence()
        assert e.notebook == "11_forces.ipynb" and any(ch.isdigit() for ch in text)


def test_class_iv_group_solved_as_one():
    """The class-IV six-bar's four-link group (12 equations, 12 unknowns) in one batch."""
    from mechlab.mechanisms.sixbar_iv import example
    sb = example()
    mo = sb.motion(sb.turn(91))
    bodies = (Body("crank", "O", ("O", "A")), Body("l2", "Q", ("Q", "P"), mass=2.0, inertia=0.05, com=(0.3, -0.2)),
              Body("l3", "R", ("R", "Q"), mass=0.5, inertia=0.003), Body("l5", "T", ("T", "P"), mass=1.0, inertia=0.06),
              Body("l4", "E", ("E", "R"), mass=3.0, inertia=0.2, com=(0.4, 0.1)))
    pairs = (Revolute("O", FRAME, "crank", "O"), Revolute("A", "crank", "l2", "A"), Revolute("Q", "l2", "l3", "Q"),
             Revolute("P", "l2", "l5", "P"), Revolute("R", "l3", "l4", "R"), Revolute("T", "l5", "l4", "T"),
             Revolute("E", FRAME, "l4", "E"))
    model = ForceModel(bodies, pairs, (("l2", "l3", "l5", "l4"),), "crank", "O")
    loads = [Torque("l4", lambda m: -20.0 * np.sign(m.dpsi))]
    res = solve(model, mo, loads, omega1=10.0, eps1=-4.0)
    vw = virtual_work_torque(model, mo, loads, omega1=10.0, eps1=-4.0)
    assert np.max(np.abs(res.torque - vw)) <= 1e-9 * np.max(np.abs(vw)) and res.residual < 1e-12
    rf = solve(model.with_friction(0.1, 0.02), mo, loads, omega1=10.0)
    assert np.max(np.abs(rf.torque - rf.torque_power)) <= 1e-9 * np.max(np.abs(rf.torque))


def test_geneva_wheel_as_a_one_link_group():
    """Pin in a radial slot: M_b = (J ψ'' ω² + T sgn ψ') ψ' (the wheel's power balance)."""
    from mechlab.mechanisms.geneva import ExternalGeneva
    g = ExternalGeneva(5, 0.1)
    s0 = g.engagement_half_angle
    phi = np.pi + s0 * (1 - 1e-9) * np.linspace(-1, 1, 121)
    mo = g.motion(phi)
    J, T, w = 0.05, 5.0, 10.0
    model = ForceModel((Body("crank", "O", ("O", "A")), Body("wheel", "W", ("W", "A"), inertia=J)),
                       (Revolute("O", FRAME, "crank", "O"), HigherPair("pin", "wheel", "crank", "A"),
                        Revolute("W", FRAME, "wheel", "W")), (("wheel",),), "crank", "O")
    res = solve(model, mo, [Torque("wheel", lambda m: -T * np.sign(m.dpsi))], omega1=w, gravity=(0, 0))
    ref = (J * mo.ddpsi * w**2 + T * np.sign(mo.dpsi)) * mo.dpsi
    assert np.max(np.abs(res.torque - ref)) <= 1e-9 * np.max(np.abs(ref))
    WA = np.hypot(*(mo.points["A"].p - mo.points["W"].p).T)
    assert np.allclose(np.abs(res.reactions["pin"].normal) * WA, np.abs(ref / mo.dpsi), rtol=1e-9)


def test_pair_angles_must_be_finite():
    with pytest.raises(MechanismError, match="guide angle of g must be finite"):
        Prismatic("g", FRAME, "s", "B", float("nan"))
    with pytest.raises(MechanismError, match="normal angle of h must be finite"):
        HigherPair("h", FRAME, "s", "B", float("inf"))


@pytest.mark.parametrize("f", [0.0, 0.1, 0.2])
def test_guide_friction_against_hand_solution(f):
    """Massless slider-crank, friction only in the guide. On the slider: rod thrust S·u, normal
    N = −S·u_y, load (−P, 0), friction −f|N|·sgn(v) along x, so S = P/(u_x − f|u_y|·sgn v)
    and M_b = S·(A × u). Self-locking where the denominator is ≤ 0, i.e. f·tan β ≥ 1."""
    sc = SliderCrank(0.1, 0.105)
    phi = np.radians(np.arange(3.0, 360.0, 6.0))
    mo = sc.motion(phi)
    P = 500.0
    model = model_for(sc).with_friction(f, 0.0, pairs=["guide"])
    u = (mo.points["B"].p - mo.points["A"].p) / sc.rod
    den = u[:, 0] - f * np.abs(u[:, 1]) * np.sign(mo.ds)
    res = solve(model, mo, [Force("slider", "B", (-P, 0.0))], omega1=7.0, gravity=(0.0, 0.0))
    S = P / den
    A = mo.points["A"].p
    assert np.allclose(res.torque, S * (A[:, 0] * u[:, 1] - A[:, 1] * u[:, 0]), rtol=1e-10, atol=1e-10)
    assert np.allclose(np.abs(res.reactions["guide"].normal), np.abs(S * u[:, 1]), rtol=1e-10, atol=1e-10)
    assert np.allclose(res.losses, f * np.abs(S * u[:, 1]) * np.abs(mo.ds), rtol=1e-10, atol=1e-10)


def test_guide_friction_self_locks_where_f_tan_beta_exceeds_one():
    """tan β = 0.1/√(0.105² − 0.1²) = 3.12 at φ = ±90°; with f = 0.5, f·tan β = 1.56 > 1. At
    φ = 270° the slider moves away from the crank (against the load): the denominator
    u_x − f|u_y| < 0, no finite thrust moves it — locked. At φ = 90° it moves towards the crank,
    friction then points away from it and S = P/(u_x + f|u_y|): a plain solution, which a naive
    fixed-point iteration on the friction forces (factor f·tan β > 1) would miss."""
    sc = SliderCrank(0.1, 0.105)
    f, P = 0.5, 500.0
    model = model_for(sc).with_friction(f, 0.0, pairs=["guide"])
    load = [Force("slider", "B", (-P, 0.0))]
    with pytest.raises(SelfLockingError, match=r"φ = 270.00°"):
        solve(model, sc.motion(np.radians([270.0])), load, omega1=7.0, gravity=(0.0, 0.0))
    mo = sc.motion(np.radians([90.0]))
    res = solve(model, mo, load, omega1=7.0, gravity=(0.0, 0.0))
    u = (mo.points["B"].p - mo.points["A"].p)[0] / sc.rod
    assert mo.ds[0] < 0 and f * abs(u[1] / u[0]) > 1
    S = P / (u[0] + f * abs(u[1]))
    assert res.torque[0] == pytest.approx(S * (0.0 * u[1] - 0.1 * u[0]), rel=1e-12)


def test_curved_slot_higher_pair_equals_the_equivalent_fourbar():
    """Seed 000: the four-bar is a slotted link whose circular slot (radius l_AB about the
    rocker's B) carries the pin. As a higher pair, the pin's push acts along the common normal
    through the arc centre — the massless coupler's line — so with a torque on the link the
    pin force, the pivot reaction and M_b equal the four-bar's (frame turned by π)."""
    from mechlab.geometry import unit
    from mechlab.kinetostatics.solve import output_axis
    from mechlab.mechanisms.curved_slot import CircleSlot, CurvedSlotLink
    fb = FourBar(0.1, 0.3, 0.3, 0.35)
    cs = CurvedSlotLink(fb.crank, fb.ground, CircleSlot((fb.rocker, 0.0), fb.coupler), start=1.0)
    phi = cs.turn(91)
    mo = cs.motion(phi)

    def slot_normal(m):   # from the arc centre (carried by the link at l_BE along ψ) to the pin
        return m.points["A"].p - (m.points["B"].p + fb.rocker * unit(m.psi))

    model = ForceModel((Body("crank", "O", ("O", "A")), Body("link", "B", output_axis, mass=1.5, inertia=0.02,
                                                                com=(0.1, 0.02))),
                       (Revolute("O", FRAME, "crank", "O"), HigherPair("slot", "link", "crank", "A", slot_normal),
                        Revolute("B", FRAME, "link", "B")), (("link",),), "crank", "O")
    loads = [Torque("link", -40.0)]
    res = solve(model, mo, loads, omega1=8.0, gravity=(0.0, 0.0))
    vw = virtual_work_torque(model, mo, loads, omega1=8.0, gravity=(0.0, 0.0))
    assert np.max(np.abs(res.torque - vw)) <= 1e-9 * np.max(np.abs(vw)) and res.residual < 1e-12
    massless = model.with_body("link", mass=0.0, inertia=0.0)
    r = solve(massless, mo, loads, gravity=(0.0, 0.0))
    r4 = solve(model_for(fb), fb.motion(phi + np.pi), [Torque("rocker", -40.0)], gravity=(0.0, 0.0))
    assert np.allclose(r.torque, r4.torque, rtol=1e-10, atol=1e-10)
    assert np.allclose(np.abs(r.reactions["slot"].normal), r4.reactions["A"].magnitude, rtol=1e-10)
    assert np.allclose(r.reactions["B"].magnitude, r4.reactions["E"].magnitude, rtol=1e-10)
    with pytest.raises(StructureError, match="axis of link"):
        solve(ForceModel((model.bodies[0], Body("link", "B", lambda m: (m.psi, m.dpsi))), model.pairs,
                         model.groups, "crank", "O"), mo, loads)


def test_verify_and_explorer_messages():
    from mechlab.kinetostatics.machines import press
    from mechlab.kinetostatics.solve import ForceResult
    from mechlab.widgets.forces import press_explorer, rocker_explorer
    res = press(f=0.1).forces()
    assert "power balance" in res.verify() and res.power_gap < 1e-12
    bad = ForceResult(res.phi, res.omega1, res.eps1, res.reactions, res.torque * 1.01, res.torque_power,
                      res.ideal_torque, res.losses, res.residual, res.iterations, res.model)
    with pytest.raises(MechanismError, match="kinetostatics check failed"):
        bad.verify()
    e = press_explorer()
    e.sliders["f"].value = 0.45
    e.sliders["rod"].value = 0.11    # f·tan β ≈ 0.98 in the guide alone near φ = 270°, plus the journals
    assert "self-locking" in e.message and "φ = 273.00°" in e.message
    e.sliders["rod"].value = 0.40
    assert e.message == ""
    r = rocker_explorer()
    assert r.message == "" and "cycle efficiency" in r.status.value
    # the status reads in units and a verdict, never a residual
    assert "the same M_b ✓" in r.status.value and "N·m" in r.status.value and "e-" not in r.status.value
    r.sliders["ground"].value = 0.55
    assert "Grashof" in r.message


def test_journal_friction_at_the_crank_pivot_by_hand():
    """Friction only in the crank's journal O (radius r): the rod force S·u and hence
    R_O = S·u are unchanged (a couple does not enter the force balance), and the crank needs
    the extra f·r·|S| in the sense of its rotation: M_b = P·s' + f·r·|S|·sgn ω1."""
    sc = SliderCrank(0.1, 0.4, 0.02)
    phi = np.radians(np.arange(4.0, 360.0, 8.0))
    mo = sc.motion(phi)
    P, f, r = 800.0, 0.15, 0.012
    load = [Force("slider", "B", (-P, 0.0))]
    u = (mo.points["B"].p - mo.points["A"].p) / sc.rod
    S = P / u[:, 0]
    for w in (6.0, -6.0):
        res = solve(model_for(sc).with_friction(f, r, pairs=["O"]), mo, load, omega1=w, gravity=(0.0, 0.0))
        assert np.allclose(res.torque, P * mo.ds + f * r * np.abs(S) * np.sign(w), rtol=1e-12, atol=1e-12)
        assert np.allclose(res.reactions["O"].force, S[:, None] * u, rtol=1e-12, atol=1e-12)
        assert np.allclose(res.reactions["O"].couple, -f * r * np.abs(S) * np.sign(w), rtol=1e-12, atol=1e-12)


# -- audit: the solver against mechanics written out independently in this file ----------------
# Links as model_for documents them (origin joint, x axis), the kinematics by 5-point central
# differences of the joint positions (no analogs from mechlab), loads in link coordinates.
LINKS = {FourBar: {"crank": ("O", ("O", "A")), "coupler": ("A", ("A", "B")), "rocker": ("E", ("E", "B"))},
         SliderCrank: {"crank": ("O", ("O", "A")), "rod": ("A", ("A", "B")), "slider": ("B", None)}}
FD_H = 1e-3


def _fd(mech, phi):
    """Joint positions p and their first and second derivatives in φ by 5-point stencils."""
    k = np.arange(-2, 3)
    mos = [mech.motion(phi + j * FD_H) for j in k]
    return {name: _stencil(np.stack([m.points[name].p for m in mos])) for name in mos[0].points}


def _bodies(mech, phi, model):
    """Per link: origin, angle θ, θ', θ'' and a function giving a point in link coordinates
    with its φ-derivatives — all by finite differences of positions."""
    k = np.arange(-2, 3)
    mos = [mech.motion(phi + j * FD_H) for j in k]
    out = {}
    for name, (origin, axis) in LINKS[type(mech)].items():
        O = np.stack([m.points[origin].p for m in mos])
        if axis is None:
            th = np.zeros((5, len(phi)))
        else:
            v = np.stack([m.points[axis[1]].p - m.points[axis[0]].p for m in mos])
            th = np.unwrap(np.arctan2(v[..., 1], v[..., 0]), axis=0)
        body = model.body(name)

        def at(local, O=O, th=th):
            c, s = np.cos(th), np.sin(th)
            P = O + np.stack([local[0] * c - local[1] * s, local[0] * s + local[1] * c], axis=-1)
            return _stencil(P)

        out[name] = {"O": _stencil(O), "th": _stencil(th), "at": at, "body": body}
    return out


def _stencil(X):
    """Centre value and 5-point first and second differences of samples at φ + (-2…2)·h."""
    return (X[2], (X[0] - 8 * X[1] + 8 * X[3] - X[4]) / (12 * FD_H),
            (-X[0] + 16 * X[1] - 30 * X[2] + 16 * X[3] - X[4]) / (12 * FD_H**2))


def _applied(links, loads, w, e, g):
    """Per link: resultant applied force (gravity, −m·a_S, external forces), its moment about
    the link's origin (with −J_S·ε and external couples) and its power per unit ω1."""
    out = {}
    for name, L in links.items():
        b = L["body"]
        o = L["O"][0]
        _th, dth, ddth = L["th"]
        S, dS, ddS = L["at"](b.com)
        F = b.mass * (np.asarray(g) - (ddS * w * w + dS * e))
        M = _cross(S - o, F) - b.inertia * (ddth * w * w + dth * e)
        P = np.sum(F * dS, axis=1) - b.inertia * (ddth * w * w + dth * e) * dth
        for ld in loads:
            if ld.body != name:
                continue
            if isinstance(ld, Force):
                Q, dQ, _ = L["at"](ld.at)
                Fx = np.broadcast_to(np.asarray(ld.value, float), F.shape)
                F = F + Fx
                M = M + _cross(Q - o, Fx)
                P = P + np.sum(Fx * dQ, axis=1)
            else:
                M = M + ld.value
                P = P + ld.value * dth
        out[name] = (F, M, P)
    return out


def _cross(a, b):
    return a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0]


@given(st.data(), st.one_of(revolving_fourbars(), revolving_slider_cranks()))
@settings(max_examples=80, deadline=None)
def test_audit_torque_by_power_balance_and_reactions_by_newton_euler(data, mech):
    """Independent of mechlab.kinetostatics: (1) the crank torque from the power balance
    M_b = −Σ(F·v_S + M·ω)/ω1 with velocities from finite differences; (2) every reaction and
    M_b from the 9 Newton–Euler equations of the three links, assembled here and solved per
    angle. Both against solve()."""
    model, loads, w, e = loaded(data.draw, mech)
    g = (0.0, -9.81)
    phi = mech.turn(37)[:-1] + 0.01
    res = solve(model, mech.motion(phi), loads, omega1=w, eps1=e, gravity=g)
    links = _bodies(mech, phi, model)
    app = _applied(links, loads, w, e, g)
    power = sum(P for _, _, P in app.values())
    crank_dth = links["crank"]["th"][1]
    Mb = -power / crank_dth
    scale = max(np.max(np.abs(Mb)), max(np.max(np.abs(F)) for F, _, _ in app.values()) * mech.crank, 1e-9)
    assert np.max(np.abs(res.torque - Mb)) <= 1e-6 * scale
    # Newton–Euler, unknowns x = [R_O, R_A, R_B, R_E or (N, C), M_b]; R_X = force of pair X's a on b
    n = len(phi)
    pos = {k: v[0] for k, v in _fd(mech, phi).items()}
    A = np.zeros((n, 9, 9))
    rhs = np.zeros((n, 9))
    names = list(LINKS[type(mech)])
    for i, name in enumerate(names):
        F, M, _ = app[name]
        rhs[:, 3 * i:3 * i + 2] = -F
        rhs[:, 3 * i + 2] = -M
    o = {name: links[name]["O"][0] for name in names}

    def put(link, col, point, s):   # an unknown force (cols col, col+1) acting with sign s on link at point
        i = names.index(link)
        d = pos[point] - o[link]
        A[:, 3 * i, col] += s
        A[:, 3 * i + 1, col + 1] += s
        A[:, 3 * i + 2, col] += -s * d[:, 1]
        A[:, 3 * i + 2, col + 1] += s * d[:, 0]

    put("crank", 0, "O", 1.0)                       # frame on crank
    put("crank", 2, "A", -1.0)
    put(names[1], 2, "A", 1.0)                      # crank on coupler / rod
    put(names[1], 4, "B", -1.0)
    put(names[2], 4, "B", 1.0)                      # coupler on rocker / rod on slider
    if isinstance(mech, FourBar):
        put("rocker", 6, "E", 1.0)                  # frame on rocker
    else:
        A[:, 7, 6] = 1.0                            # guide normal N along +y on the slider (guide ∥ x)
        A[:, 8, 7] = 1.0                            # guide couple on the slider (N acts through B, its origin)
    A[:, 2, 8] = 1.0                                # M_b on the crank
    x = np.linalg.solve(A, rhs[..., None])[..., 0]
    assert np.max(np.abs(x[:, 8] - res.torque)) <= 1e-6 * scale
    force_scale = max(np.max(np.abs(x[:, :6])), 1e-9)
    for col, pair in ((0, "O"), (2, "A"), (4, "B")):
        assert np.max(np.abs(res.reactions[pair].force - x[:, col:col + 2])) <= 1e-6 * force_scale
    if isinstance(mech, FourBar):
        assert np.max(np.abs(res.reactions["E"].force - x[:, 6:8])) <= 1e-6 * force_scale
    else:
        assert np.max(np.abs(res.reactions["guide"].normal - x[:, 6])) <= 1e-6 * force_scale
        assert np.max(np.abs(res.reactions["guide"].couple - x[:, 7])) <= 1e-6 * force_scale * mech.rod


@given(st.data(), st.one_of(revolving_fourbars(), revolving_slider_cranks()))
@settings(max_examples=40, deadline=None)
def test_audit_friction_vanishes_linearly_and_efficiency_tends_to_one(data, mech):
    """With friction f in every pair (journal radius r): η ≤ 1, and as f → 0 the losses per
    unit f tend to Σ r·|R0|·|ω_rel| + |N0|·|v_rel| computed here from the frictionless
    reactions and finite-difference relative velocities; the torque tends to the ideal one
    and the cycle efficiency to 1, both linearly in f."""
    model, loads, w, e = loaded(data.draw, mech)
    phi = mech.turn(37)[:-1] + 0.01
    mo = mech.motion(phi)
    r = 0.1 * mech.crank
    ideal = solve(model, mo, loads, omega1=w, eps1=e)
    links = _bodies(mech, phi, model)
    names = list(LINKS[type(mech)])
    dth = {k: links[k]["th"][1] for k in names}
    rel = {"O": dth["crank"], "A": dth[names[1]] - dth["crank"], "B": dth[names[2]] - dth[names[1]]}
    if isinstance(mech, FourBar):
        rel["E"] = dth["rocker"]
    lead = sum(r * ideal.reactions[p].magnitude * np.abs(v) for p, v in rel.items())
    if isinstance(mech, SliderCrank):
        lead = lead + np.abs(ideal.reactions["guide"].normal) * np.abs(_fd(mech, phi)["B"][1][:, 0])
    results = {}
    for f in (1e-3, 1e-4):
        try:
            results[f] = solve(model.with_friction(f, r), mo, loads, omega1=w, eps1=e)
        except SelfLockingError as err:   # cannot happen at these f unless a dead point is within reach
            raise AssertionError(f"self-locking at f = {f} on {mech}") from err
    for f, res in results.items():
        eta = res.efficiency()
        assert np.all(eta.filled(0.0) <= 1.0 + 1e-12)
        assert np.all(res.losses >= 0)
        tol = 20 * f * np.max(lead) + 1e-9 * np.max(np.abs(ideal.torque))
        assert np.max(np.abs(res.losses / f - lead)) <= tol
    d3 = np.max(np.abs(results[1e-3].torque - ideal.torque))
    d4 = np.max(np.abs(results[1e-4].torque - ideal.torque))
    assert d4 <= 0.11 * d3 + 1e-12 * np.max(np.abs(ideal.torque))
    # cycle: drive work = useful work W + friction work A(f), A(f) = f·∫lead·(1 + O(f)), so the
    # loss ratio (1 - η)/η = A/W falls tenfold from f = 1e-3 to 1e-4 (η = 1 - A/(W + A) → 1)
    work = np.trapezoid(ideal.torque * np.sign(w), phi)
    if work > 1e-3 * np.trapezoid(np.abs(ideal.torque), phi):
        c3, c4 = (1 - results[f].cycle_efficiency(how="work") for f in (1e-3, 1e-4))
        assert 0 <= c4 <= c3 <= 1
        q3, q4 = c3 / (1 - c3), c4 / (1 - c4)
        assert q3 == pytest.approx(1e-3 * np.trapezoid(lead, phi) / work, rel=0.05)
        assert q4 == pytest.approx(0.1 * q3, rel=0.05)


@pytest.mark.parametrize("offset, assembly", [(0.0, 1), (0.03, 1), (0.03, -1)])
def test_press_load_does_not_depend_on_the_sampling(offset, assembly):
    """The working window comes from the dimensions, not from the largest sampled |s|: the load
    at one crank angle equals the load there within a full turn (it did not before: at φ = 240°
    alone the press felt P although the slider was 0.16 m from the outer dead point). Its work
    per turn is −P·fraction·stroke, the stroke sqrt((l+a)² − e²) − sqrt((l−a)² − e²)."""
    from mechlab.kinetostatics.machines import press_load
    sc = SliderCrank(0.1, 0.4, offset, assembly)
    load = press_load(2000.0, 0.3)
    phi = sc.turn(7201)
    mo = sc.motion(phi)
    F = load(mo)
    for i in range(0, len(phi), 97):
        assert np.array_equal(load(sc.motion(phi[i:i + 1]))[0], F[i])
    stroke = np.sqrt(0.5**2 - offset**2) - np.sqrt(0.3**2 - offset**2)
    assert np.trapezoid(F[:, 0] * mo.ds, phi) == pytest.approx(-2000.0 * 0.3 * stroke, rel=2e-3)
    assert np.all(F[:, 0] * assembly <= 0) and np.all(F[:, 1] == 0)


@pytest.mark.parametrize("scale", [1e-250, 1e-160, 1.0, 1e160, 1e250])
def test_drive_rule_is_scale_free(scale):
    """M² of a torque of 1e-160 underflows and of 1e160 overflows: the figures scale with M all the same."""
    phi = np.linspace(0.0, 2 * np.pi, 2001)
    M = 2.0 + 3.0 * np.sin(phi)
    ref = drive(M, phi, 4.0, overload=2.5, efficiency=0.8)
    d = drive(scale * M, phi, 4.0, overload=2.5, efficiency=0.8)
    for name in ("mean_torque", "rms_torque", "peak_torque", "nominal_torque"):
        assert getattr(d, name) == pytest.approx(scale * getattr(ref, name), rel=1e-12, abs=0)
    assert d.governing == ref.governing


def test_class_iv_drive_puts_the_masses_where_the_chapter_says_in_model_for_frames():
    """The chapter's hand-built model (coupler from Q, output along E→R) and class_iv_drive's (model_for's
    frames: coupler from A, output along ψ) carry the same masses at the same points: same torque and
    reactions, to rounding; a centre of mass copied without the change of frame would not."""
    from mechlab.kinetostatics.machines import class_iv_drive
    from mechlab.mechanisms.sixbar_iv import example
    sb = example()
    hand = ForceModel(
        (Body("crank", "O", ("O", "A")),
         Body("link2", "Q", ("Q", "P"), mass=2.0, inertia=0.05, com=(0.3, -0.2)),
         Body("link3", "R", ("R", "Q"), mass=0.5, inertia=0.003, com=(sb.link3 / 2, 0)),
         Body("link5", "T", ("T", "P"), mass=1.0, inertia=0.06, com=(sb.link5 / 2, 0)),
         Body("link4", "E", ("E", "R"), mass=3.0, inertia=0.2, com=(0.4, 0.1))),
        (Revolute("O", FRAME, "crank", "O"), Revolute("A", "crank", "link2", "A"),
         Revolute("Q", "link2", "link3", "Q"), Revolute("P", "link2", "link5", "P"),
         Revolute("R", "link3", "link4", "R"), Revolute("T", "link5", "link4", "T"),
         Revolute("E", FRAME, "link4", "E")),
        groups=(("link2", "link3", "link5", "link4"),), crank="crank", pivot="O")
    k = class_iv_drive(omega1=7.0, T=15.0)
    mo = k.motion(k.turn(73))
    ref = solve(hand, mo, [Torque("link4", lambda m: -15.0 * np.sign(m.dpsi))], omega1=7.0)
    res = k.forces(motion=mo)
    scale = np.max(np.abs(ref.torque))
    assert np.allclose(res.torque, ref.torque, rtol=0, atol=1e-10 * scale)
    for name, r in ref.reactions.items():
        assert np.allclose(res.reactions[name].force, r.force, rtol=0, atol=1e-10 * scale)
    assert k.model.body("link 3").com == (sb.link3 / 2, 0.0)        # the bars' centres half-way
    pasted = k.model.with_body("output", com=(0.4, 0.1))
    assert np.max(np.abs(solve(pasted, mo, k.loads, omega1=7.0).torque - ref.torque)) > 1e-2 * scale
    rough = class_iv_drive(omega1=7.0, T=15.0, f=0.1, radius=0.02).forces(motion=mo)
    assert rough.power_gap <= 1e-9 and np.all(rough.losses >= 0) and np.any(rough.losses > 0)
    with pytest.raises(MechanismError):
        class_iv_drive(T=-1.0)


# ------------------------------------------------------------------------------ inverse kinetostatics
def test_balanced_load_is_what_the_forward_solve_balances():
    """The load that a given crank torque balances, put on the output by its public names, makes the
    group-by-group solve return that torque (with masses, gravity, ω1 and ε1); and back again."""
    from mechlab.kinetostatics import Force, Torque, balanced_load, model_for, solve, torque_for_load

    phi = np.linspace(0.2, 6.0, 25)
    fb = FourBar(0.1, 0.3, 0.3, 0.35)
    model = model_for(fb).with_body("coupler", mass=2.0, inertia=0.02).with_body("rocker", mass=1.5, inertia=0.01)
    M = 5.0 + np.sin(phi)
    Q = balanced_load(fb, M, phi, model=model, omega1=12.0, eps1=3.0)
    assert not np.ma.is_masked(Q)
    load = Torque(fb.structure().output, lambda motion: np.asarray(Q))  # one value per angle: a function
    res = solve(model, fb.motion(phi), [load], omega1=12.0, eps1=3.0)
    assert np.allclose(res.torque, M, rtol=1e-9, atol=1e-9)
    assert np.allclose(torque_for_load(fb, np.asarray(Q), phi, model=model, omega1=12.0, eps1=3.0), M, rtol=1e-12)
    # a slider: the force along the slider's path (+s), masked at the dead centres where s' = 0
    sc = SliderCrank(0.1, 0.4)
    phi = np.array([0.0, 0.7, 2.0, np.pi, 4.0])
    Q = balanced_load(sc, 10.0, phi)
    assert list(np.ma.getmaskarray(Q)) == [True, False, False, True, False]
    mo = sc.motion(phi[~Q.mask])
    along = mo.points["B"].d / mo.ds[:, None]                       # the unit vector of +s
    res = solve(model_for(sc), mo, [Force(sc.structure().output, "B", Q.compressed()[:, None] * along)])
    assert np.allclose(res.torque, 10.0, rtol=1e-9)
    assert isinstance(balanced_load(sc, 10.0, 1.0), float) and balanced_load(sc, 10.0, 0.0) is np.ma.masked


def test_inverse_kinetostatics_refuses_friction_and_bad_input_by_name():
    from mechlab.errors import DimensionError
    from mechlab.kinetostatics import FrictionlessOnlyError, balanced_load, model_for

    sc = SliderCrank(0.1, 0.4)
    with pytest.raises(FrictionlessOnlyError, match="friction in pairs"):
        balanced_load(sc, 10.0, [1.0], model=model_for(sc).with_friction(0.1, 0.01))
    with pytest.raises(TypeError, match="mechanism must be"):
        balanced_load("slider", 10.0, [1.0])
    with pytest.raises(DimensionError, match="phi"):
        balanced_load(sc, 10.0, [np.nan])


def test_an_unknown_efficiency_kind_is_a_named_error():
    """cycle_efficiency(how=...) outside "mean" and "work": the library's DimensionError, not a bare ValueError."""
    from mechlab.errors import DimensionError
    from mechlab.kinetostatics.machines import press

    result = press(P=2000.0, work_fraction=0.3).forces(np.linspace(0.0, 2 * np.pi, 73))
    with pytest.raises(DimensionError, match="how must be 'mean' or 'work'"):
        result.cycle_efficiency(how="average")


def test_virtual_work_torque_at_a_scalar_angle():
    """At a scalar φ the torque is a scalar, the array's value at that angle (as ``solve`` gives its results)."""
    fb = FourBar(1.0, 3.0, 3.0, 4.0)
    model, loads = model_for(fb), [Torque("rocker", -5.0)]
    phi = np.array([0.3, 1.7, 4.0])
    many = virtual_work_torque(model, fb.motion(phi), loads, omega1=3.0)
    one = [virtual_work_torque(model, fb.motion(float(x)), loads, omega1=3.0) for x in phi]
    assert all(np.ndim(t) == 0 for t in one)
    assert np.allclose(one, many, rtol=1e-14, atol=0)
    assert np.isclose(one[1], float(solve(model, fb.motion(1.7), loads, omega1=3.0).torque), rtol=1e-9)
