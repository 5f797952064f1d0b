"""Geneva drives: planar external/internal and the spherical offset Geneva of seed 004."""

import dataclasses
import itertools

import numpy as np
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from mechlab.analysis.intermittency import compare, detect_impacts, intermittency
from mechlab.analysis.motion_laws import invariants, rise_invariants
from mechlab.errors import DimensionError, MechanismError
from mechlab.kinetostatics.drive import DriveError
from mechlab.kinetostatics.drive import drive as fdrive
from mechlab.kinetostatics.geneva import crank_torque, drive_angles, geneva_drive
from mechlab.mechanisms.fourbar import FourBar
from mechlab.mechanisms.geneva import ExternalGeneva, InternalGeneva, OffsetError, SlotCountError, impact_kind
from mechlab.mechanisms.slotted import SlottedLink
from mechlab.mechanisms.spherical_geneva import SphericalGeneva
from mechlab.synthesis.geneva import (
    TABLE1_COLUMNS,
    TABLE1_PRINTED,
    ReviewRow,
    SphericalRow,
    spherical_table,
    table1_comparison,
    table1_review,
)

H = 1e-5
slots = st.integers(min_value=3, max_value=16)
sizes = st.floats(min_value=1.0, max_value=500.0, allow_nan=False, allow_infinity=False)


def _spherical(z, R, frac):
    return SphericalGeneva(R, frac * R, z, pin_diameter=0.05 * R)


# -- planar Geneva --------------------------------------------------------------------------
@pytest.mark.parametrize("cls", [ExternalGeneva, InternalGeneva])
@given(z=slots, C=sizes)
@settings(max_examples=60, deadline=None)
def test_planar_geneva_geometry_analogs_and_closed_form(cls, z, C):
    g = cls(z, C)
    phi = np.linspace(0.0, 2 * np.pi, 721)
    mo, up, dn = g.motion(phi), g.motion(phi + H), g.motion(phi - H)
    A, W = mo.points["A"].p, mo.points["W"].p
    assert np.allclose(np.hypot(*A.T), g.crank_radius, rtol=1e-13)
    on = g.engaged(phi)
    # the pin lies on the slot: the slot line W + t·u(ψ + ψ_entry-direction) passes through A
    slot_dir = mo.psi - g.kappa * np.pi / g.z + np.pi
    rel = A - W
    off = rel[:, 0] * np.sin(slot_dir) - rel[:, 1] * np.cos(slot_dir)
    assert np.max(np.abs(off[on])) <= 1e-12 * C
    # analogs vs central differences, away from the jumps at entry/exit
    far = np.abs(np.abs(np.mod(phi, 2 * np.pi) - np.pi) - g.engagement_half_angle) > 10 * H
    assert np.max(np.abs((up.psi - dn.psi) / (2 * H) - mo.dpsi)[far]) < 1e-7
    assert np.max(np.abs((up.dpsi - dn.dpsi) / (2 * H) - mo.ddpsi)[far]) < 1e-6 * (1 + g.max_acceleration())
    # closed forms (module docstring) agree with the vector model
    sigma = phi[on] - np.pi
    cf = g.closed_form(sigma)
    assert np.allclose(cf.theta + g.kappa * np.pi / z, mo.psi[on], atol=1e-12)
    assert np.allclose(cf.d, mo.dpsi[on], atol=1e-12)
    assert np.allclose(cf.dd, mo.ddpsi[on], atol=1e-10 * (1 + g.max_acceleration()))
    # locked outside the engagement: zero analogs, ψ at 0 or one index
    assert np.all(mo.dpsi[~on] == 0) and np.all(mo.ddpsi[~on] == 0)
    assert mo.psi[0] == 0 and abs(mo.psi[-1] - g.index_angle) < 1e-14


@pytest.mark.parametrize("cls", [ExternalGeneva, InternalGeneva])
@given(z=slots)
@settings(max_examples=30, deadline=None)
def test_planar_extremes_closed_form_vs_sampled(cls, z):
    g = cls(z, 1.0)
    s0 = g.engagement_half_angle
    sigma = np.linspace(-s0, s0, 200001)
    cf = g.closed_form(sigma)
    lam = np.sin(np.pi / z)
    assert abs(np.max(np.abs(cf.d)) - g.max_velocity()) < 1e-12
    assert abs(g.max_velocity() - lam / (1 + g.kappa * lam)) < 1e-15
    assert abs(np.max(np.abs(cf.dd)) - g.max_acceleration()) < 1e-8 * g.max_acceleration()
    i = np.argmax(np.abs(cf.dd))
    assert abs(abs(sigma[i]) - g.acceleration_peak_sigma()) < 1e-4
    # radial entry: ψ' = 0 and |ψ''| = tan(π/z) at entry and exit → soft impact
    imp = g.impacts()
    assert abs(imp.entry_velocity_jump) < 1e-14 and abs(imp.exit_velocity_jump) < 1e-14
    assert np.isclose(abs(imp.entry_acceleration_jump), np.tan(np.pi / z), rtol=1e-13)
    assert np.isclose(g.entry_acceleration(), abs(imp.exit_acceleration_jump), rtol=1e-13)
    assert imp.kind == "soft"
    assert np.isclose(g.dwell_fraction, 0.5 - g.kappa / z, rtol=1e-14)


def test_planar_closed_forms_by_sympy():
    lam, s = sp.symbols("lambda sigma", real=True)
    for k in (-1, 1):
        # vector loop: external pin a·u(σ), internal -a·u(σ); W = (1, 0); angle from W→O
        pin = (lam * sp.cos(s), lam * sp.sin(s)) if k < 0 else (-lam * sp.cos(s), -lam * sp.sin(s))
        vx, vy = pin[0] - 1, pin[1]
        beta = sp.atan2(-vy, -vx)  # angle of (vx, vy) measured from (-1, 0)
        d1 = sp.diff(beta, s)
        d2 = sp.diff(d1, s)
        D = 1 + 2 * k * lam * sp.cos(s) + lam**2
        f1 = sp.lambdify((lam, s), d1 - k * lam * (sp.cos(s) + k * lam) / D)
        f2 = sp.lambdify((lam, s), d2 + k * lam * (1 - lam**2) * sp.sin(s) / D**2)
        for z in (3, 4, 7, 12):
            x = np.linspace(-1.5, 1.5, 31)
            assert np.max(np.abs(f1(np.sin(np.pi / z), x))) < 1e-13
            assert np.max(np.abs(f2(np.sin(np.pi / z), x))) < 1e-12


def test_planar_dimensions():
    g = ExternalGeneva(4, 100.0, roller_radius=5.0)
    assert np.isclose(g.crank_radius, 100 / np.sqrt(2)) and np.isclose(g.entry_radius, 100 / np.sqrt(2))
    assert np.isclose(g.outer_radius, np.hypot(100 / np.sqrt(2), 5.0))
    assert np.isclose(g.slot_length, g.outer_radius - (100 - 100 / np.sqrt(2) - 5.0))
    assert np.isclose(g.locking_radius, 100 / np.sqrt(2) - 7.5)
    assert g.dwell_fraction == pytest.approx(0.75) and g.index_angle == pytest.approx(-np.pi / 2)
    assert g.max_velocity() == pytest.approx(np.sqrt(2) + 1)  # λ/(1-λ) with λ = 1/√2
    i = InternalGeneva(6, 50.0)
    assert i.dwell_fraction == pytest.approx(1 / 3) and i.max_velocity() == pytest.approx(1 / 3)
    assert i.slot_length == pytest.approx(50 + 25 + i.roller_radius - i.inner_radius)
    assert i.inner_radius < i.entry_radius < i.slot_bottom < i.outer_radius
    rows = g.design().by("name")
    assert set(rows) >= {"crank radius a (mm)", "slot length (mm)", "dwell fraction"}
    assert rows["C (mm)"].value == 100 and rows["crank radius a (mm)"].value == pytest.approx(100 / np.sqrt(2))
    assert "slot length (in)" in g.design(unit="in").by("name")


@pytest.mark.parametrize("cls", [ExternalGeneva, InternalGeneva])
@pytest.mark.parametrize("z", [3, 4, 6, 8])
def test_slot_centre_length_is_the_pins_travel_in_the_slot(cls, z):
    """The drawing's slot-centre length is how far the pin centre runs along the slot (measured on the
    motion: the range of |WA| while engaged), in closed form; the design table lists it with the rims."""
    g = cls(z, 100.0)
    s0 = g.engagement_half_angle
    phi = np.pi + np.linspace(-s0, s0, 20001)          # the engagement, entry to exit (σ = φ − π)
    mo = g.motion(phi)
    assert g.engaged(phi[1:-1]).all() and not g.engaged(np.pi + s0 + 1e-9)
    dist = np.hypot(*(mo.points["A"].p - mo.points["W"].p).T)
    assert g.slot_centre_length == pytest.approx(dist.max() - dist.min(), rel=1e-12)
    s, c = np.sin(np.pi / z), np.cos(np.pi / z)
    assert g.slot_centre_length == pytest.approx(100 * (s + c - 1 if cls is ExternalGeneva else 1 + s - c), rel=1e-14)
    rows = g.design().by("name")
    assert rows["slot centre length (mm)"].value == g.slot_centre_length
    assert rows["slot width (mm)"].value == 2 * g.roller_radius
    rims = ("wheel outer radius", "locking disc radius") if cls is ExternalGeneva else \
        ("ring inner radius", "ring outer radius")
    assert all(f"{name} (mm)" in rows for name in rims)


def test_geneva_design_names_its_unit():
    """Every length of the design table names its unit; an unknown unit is refused by name."""
    names = [q.name for q in ExternalGeneva(6, 100.0).design()]
    lengths = [n for n in names if n != "z" and not any(w in n for w in ("fraction", "deg", "ψ"))]
    assert len(lengths) == 10 and all(n.endswith(" (mm)") for n in lengths), names
    with pytest.raises(DimensionError, match="unit"):
        ExternalGeneva(6, 100.0).design(unit="furlong")
    # the spherical drive's table too: every row but z, the angles and the fraction is a length
    sph = SphericalGeneva(40.0, 15.0, 4)
    names = [q.name for q in sph.design()]
    lengths = [n for n in names if n != "z" and not any(w in n for w in ("fraction", "deg"))]
    assert len(lengths) == 7 and all(n.endswith(" (mm)") for n in lengths), names
    assert sph.design(unit="cm").by("name")["R (cm)"].value == 40.0
    with pytest.raises(DimensionError, match="unit"):
        sph.design(unit="furlong")


def test_geneva_turns_accumulate():
    g = ExternalGeneva(5, 1.0)
    mo = g.motion(np.array([0.0, 2 * np.pi, 4 * np.pi, 5 * np.pi]))
    assert np.allclose(mo.psi[:3], [0.0, -2 * np.pi / 5, -4 * np.pi / 5])
    assert np.isclose(mo.psi[3], -4 * np.pi / 5 + g.closed_form(0.0).theta - np.pi / 5)


@pytest.mark.parametrize("bad, err, msg", [
    (lambda: ExternalGeneva(2, 1.0), SlotCountError, r"whole number ≥ 3, got 2"),
    (lambda: InternalGeneva(3.5, 1.0), SlotCountError, r"got 3.5"),
    (lambda: ExternalGeneva("four", 1.0), SlotCountError, r"got 'four'"),
    (lambda: ExternalGeneva(4, -1.0), DimensionError, r"centre_distance must be > 0, got -1"),
    (lambda: ExternalGeneva(4, 1.0, roller_radius=-0.1), DimensionError, r"roller_radius must be > 0"),
    (lambda: ExternalGeneva(4, 1.0, roller_radius=0.4), DimensionError, r"roller_radius = 0.4 is too large"),
    (lambda: SphericalGeneva(40, 40, 4), OffsetError, r"e < R .* got e = 40 ≥ R = 40"),
    (lambda: SphericalGeneva(40, 50, 4), OffsetError, r"e = 50 ≥ R = 40"),
    (lambda: SphericalGeneva(40, -1, 4), DimensionError, r"e must be ≥ 0, got -1"),
    (lambda: SphericalGeneva(-40, 1, 4), DimensionError, r"R must be > 0"),
    (lambda: SphericalGeneva(40, 15, 2), SlotCountError, r"z = 2"),
    (lambda: SphericalGeneva(40, 15, 4, pin_diameter=80), DimensionError, r"pin_diameter = 80 must be smaller"),
    (lambda: SphericalGeneva(40, 15, 4).pin_length(3.0, allowance=9), DimensionError, r"\[5, 8\] mm"),
    (lambda: ExternalGeneva(4, 1.0).motion([np.nan]), DimensionError, "finite"),
])
def test_bad_inputs_raise_named_errors(bad, err, msg):
    with pytest.raises(err, match=msg):
        bad()
    assert issubclass(err, MechanismError)


# -- spherical Geneva ---------------------------------------------------------------------------
@given(z=slots, R=sizes, frac=st.floats(0.0, 0.9))
@settings(max_examples=80, deadline=None)
def test_spherical_closed_form_equals_exact_3d_model(z, R, frac):
    g = _spherical(z, R, frac)
    al = np.linspace(-g.alpha0, g.alpha0, 241)
    m, cf = g.model(al), g.position(al)
    # the contact point is on the sphere and on the pin axis through O1, in its meridian plane
    assert np.max(np.abs(np.linalg.norm(m.A.p, axis=1) - R)) <= 1e-12 * R
    assert np.allclose(m.A.p, np.array([0, 0, -g.e]) + m.u[:, None] * m.d, atol=1e-12 * R)
    # exact model = seed (18)-(20); cos γ = cos α sin ψ (11) exactly; ρ, r from (12)-(14)
    assert np.max(np.abs(m.beta.theta - cf.theta)) < 1e-13
    assert np.max(np.abs(m.beta.d - cf.d)) < 1e-12
    assert np.max(np.abs(m.beta.dd - cf.dd)) < 1e-11
    assert np.allclose(np.cos(m.gamma), np.cos(al) * np.sin(g.cone_angle), atol=1e-14)
    k, gam, psi = g.k, m.gamma, g.cone_angle
    O1A = g.e * np.cos(gam) + R * np.sqrt(1 - k**2 * np.sin(gam) ** 2)
    assert np.allclose(m.u, O1A, rtol=1e-12)
    assert np.allclose(m.rho, O1A * np.sin(psi), rtol=1e-12) and np.allclose(m.r, O1A * np.sin(gam), rtol=1e-12)
    # C1 of (10) vanishes: its bracket is rounding error relative to cot²ψ
    cot2 = 1 / np.tan(g.cone_angle) ** 2
    assert abs(cot2 - R**2 * np.cos(g.beta0) ** 2 / g.rho0**2) <= 1e-13 * cot2
    if frac > 0.01:
        assert abs(g.seed_c1()) < 1e-12
    # in the slot the contact is on the upper hemisphere, reaching the equator at ±α0
    assert np.all(m.A.p[:, 2] >= -1e-12 * R) and abs(m.A.p[0, 2]) < 1e-12 * R
    assert np.isclose(m.beta.theta[-1], g.beta0, atol=1e-13)
    # analogs of the 3-D contact point vs central differences
    up, dn = g.model(al + H), g.model(al - H)
    assert np.max(np.abs((up.A.p - dn.A.p) / (2 * H) - m.A.d)) < 1e-7 * R
    assert np.max(np.abs((up.A.d - dn.A.d) / (2 * H) - m.A.dd)) < 1e-6 * R


def test_spherical_law_by_sympy():
    """(18) → (19), (20) and the bracket of dε/dα behind (22), differentiated by sympy."""
    al, a = sp.symbols("alpha a", positive=True)
    beta = sp.asin(sp.sin(al) / sp.sqrt(a**2 - sp.cos(al) ** 2))
    w = sp.sqrt(a**2 - 1) * sp.cos(al) / (a**2 - sp.cos(al) ** 2)
    eps = -sp.sqrt(a**2 - 1) * (a**2 + sp.cos(al) ** 2) * sp.sin(al) / (a**2 - sp.cos(al) ** 2) ** 2
    for x in (0.1, 0.4, 0.7):  # a > 1, α small enough for the asin branch
        vals = {a: 1.37, al: x}
        assert abs(float(sp.diff(beta, al).subs(vals)) - float(w.subs(vals))) < 1e-13
    assert sp.simplify(sp.diff(w, al) - eps) == 0
    s = sp.sin(al)
    deps = -sp.sqrt(a**2 - 1) * sp.cos(al) * (s**4 - 6 * a**2 * s**2 + a**4 - 1) / (a**2 - 1 + s**2) ** 3
    for x in (0.2, 0.9, 1.3):
        vals = {a: 1.61, al: x}
        assert abs(float(sp.diff(eps, al).subs(vals)) - float(deps.subs(vals))) < 1e-12
    # tan β = tan ψ sin α is the same function (a² = 1/sin²ψ)
    g = SphericalGeneva(40, 15, 5)
    x = np.linspace(-1.2, 1.2, 50)
    assert np.allclose(g.position(x).theta, np.arctan(np.tan(g.cone_angle) * np.sin(x)), atol=1e-14)


@given(z=slots, R=sizes, frac=st.floats(0.0, 0.9))
@settings(max_examples=60, deadline=None)
def test_spherical_design_and_extremes(z, R, frac):
    g = _spherical(z, R, frac)
    e, b0 = g.e, g.beta0
    assert np.isclose(R * np.sin(b0) * np.cos(g.alpha0), e * np.sin(g.alpha0), atol=1e-12 * R)  # (5)
    m0 = g.model([0.0, g.alpha0])
    assert np.isclose(m0.u[0], g.u_H, rtol=1e-13) and np.isclose(m0.u[1], g.u0, rtol=1e-13)
    assert np.isclose(m0.rho[0], g.rho_H, rtol=1e-13) and np.isclose(m0.r[0], g.r_H, rtol=1e-13)
    assert np.isclose(m0.rho[1], g.rho0, rtol=1e-13)
    assert np.isclose(g.r_H, g.rho_H / np.tan(g.cone_angle), rtol=1e-13)  # (8)
    assert np.isclose(np.cos(m0.gamma[1]), np.cos(g.gamma0), atol=1e-13)  # (4)
    # the highest contact point is A_H; the slot arc from the equator to it, (9) and L
    al = np.linspace(-g.alpha0, g.alpha0, 2001)
    Az = g.model(al).A.p[:, 2]
    assert np.argmax(Az) == 1000
    assert np.isclose(g.min_slot_length - g.pin_diameter / 2, R * np.arcsin(Az.max() / R), rtol=1e-12)
    assert np.isclose(g.pin_length(2.0, 5.0), m0.u[0] - m0.u[1] + 7.0, rtol=1e-12)
    # extremes: ω_max = tan ψ at α = 0; |ε| max while moving: at α1 of (22) or at α0
    cf = g.position(al)
    assert np.isclose(np.abs(cf.d).max(), g.max_velocity(), rtol=1e-12)
    assert np.isclose(g.max_velocity(), np.tan(g.cone_angle), rtol=1e-12)
    eps, a_at = g.max_acceleration()
    assert np.abs(cf.dd).max() <= eps * (1 + 1e-12) and np.abs(cf.dd).max() >= eps * (1 - 1e-5)
    assert np.isclose(abs(g.position(a_at).dd), eps, rtol=1e-14)
    a1 = g.acceleration_extreme_alpha()
    fine = np.linspace(0, np.pi / 2, 100001)
    assert abs(fine[np.argmax(np.abs(g.position(fine).dd))] - a1) < 1e-4
    assert np.isclose(g.dwell_fraction, 1 - g.alpha0 / np.pi)


@given(z=slots, R=sizes, frac=st.floats(0.05, 0.9))
@settings(max_examples=40, deadline=None)
def test_spherical_motion_and_impacts(z, R, frac):
    g = _spherical(z, R, frac)
    phi = np.linspace(0, 2 * np.pi, 721)
    mo = g.motion(phi)
    on = g.engaged(phi)
    assert np.allclose(mo.psi[on], g.position(phi[on] - np.pi).theta + g.beta0, atol=1e-13)
    assert np.all(mo.dpsi[~on] == 0) and mo.psi[0] == 0 and np.isclose(mo.psi[-1], 2 * np.pi / z)
    P = mo.points["P"]
    assert np.allclose(np.linalg.norm(P.p - mo.points["B"].p, axis=1), g.rho0, rtol=1e-12)
    # offset e > 0: the wheel starts with ψ' = β'(α0) ≠ 0 → hard impact (not soft, as printed)
    imp = g.impacts()
    assert imp.entry_velocity_jump > 0 and imp.kind == "hard"
    s, c = np.sin(g.cone_angle), np.cos(g.cone_angle)
    assert np.isclose(imp.entry_velocity_jump, s * c * np.cos(g.alpha0) / (1 - s * s * np.cos(g.alpha0) ** 2))
    assert np.isclose(g.entry_velocity(), g.k * np.cos(np.pi / z), rtol=1e-12)
    # power balance: the crank arm of the slot-normal force is r·β'
    al = np.linspace(-g.alpha0, g.alpha0, 31)
    wheel, crank = g.force_arms(al)
    m = g.model(al)
    assert np.allclose(wheel, m.r, rtol=1e-12)
    assert np.allclose(crank, m.r * m.beta.d, atol=1e-12 * R)


def test_spherical_without_offset_has_soft_impact():
    g = SphericalGeneva(40, 0, 4)
    assert np.isclose(g.alpha0, np.pi / 2) and np.isclose(g.cone_angle, np.pi / 4)
    imp = g.impacts()
    assert abs(imp.entry_velocity_jump) < 1e-15 and imp.kind == "soft"


# -- Table 1 ------------------------------------------------------------------------------------
def test_table1_reproduces_and_documents_differences():
    rows = spherical_table(40, 15, [3, 4, 5, 6, 8])
    assert [r.z for r in rows] == [3, 4, 5, 6, 8]
    cells = {(c.z, c.column): c for c in table1_comparison()}
    assert len(cells) == 30
    # these columns reproduce in every row (to the printed two decimals)
    for z in TABLE1_PRINTED.column("z"):
        assert cells[z, "beta0"].agrees and cells[z, "omega_max"].agrees
    assert all(cells[z, "eps_max"].agrees for z in (4, 6))
    assert cells[4, "alpha0"].agrees and cells[5, "alpha0"].agrees and cells[8, "alpha0"].agrees
    # the documented differences (see notebook 10 and mechlab.course.errata.seed004_geneva)
    differs = {k for k, c in cells.items() if c.status == "differs"}
    assert differs == {(3, "eps_max"), (3, "alpha1"), (3, "beta1"), (4, "alpha1"), (4, "beta1"),
                       (5, "alpha1"), (5, "beta1"), (6, "alpha0"), (6, "beta1"), (8, "alpha1"), (8, "beta1")}
    last = {k for k, c in cells.items() if c.status == "last digit"}
    assert last == {(3, "alpha0"), (5, "eps_max"), (6, "alpha1"), (8, "eps_max")}
    # z = 6: ρ0 = 25 mm exactly, α0 = arccos(0.6) = 53.13°
    assert np.isclose(SphericalGeneva(40, 15, 6).rho0, 25.0) and round(cells[6, "alpha0"].computed, 2) == 53.13
    # z = 8: the stationary point of (22) lies beyond α0 (pin out of the slot): printed α1, β1, ε
    g8 = SphericalGeneva(40, 15, 8)
    a1 = g8.acceleration_extreme_alpha()
    assert a1 > g8.alpha0
    assert round(np.degrees(a1), 1) == 53.0 and round(abs(g8.position(a1).dd), 2) == 0.46
    assert round(np.degrees(g8.position(a1).theta), 1) == 24.8 > 22.5
    assert rows[-1].alpha1 == pytest.approx(rows[-1].alpha0) and rows[-1].beta1 == pytest.approx(22.5)
    # more slots, smaller accelerations (seed conclusion 4)
    eps = [r.eps_max for r in rows]
    assert all(a > b for a, b in itertools.pairwise(eps))


def test_table1_review_shows_printed_and_computed_with_units_and_marks():
    review = table1_review()
    assert list(review.column("z")) == [3, 4, 5, 6, 8] and review.headers[1] == "α0, °"
    assert all(h.endswith(", °") for h in (review.headers[i] for i in (1, 2, 5, 6)))
    row6 = review.by("z")[6]
    assert row6.alpha0 == "53.15 / 53.13 ✗" and row6.alpha1 == "41.60 / 41.59 ·" and row6.beta0 == "30.00 / 30.00"
    # every mark is the comparison's status, cell by cell
    marks = {(r.z, col): getattr(r, col) for r in review for col in review.columns[1:]}
    assert {k for k, m in marks.items() if m.endswith(" ✗")} == {(c.z, c.column) for c in table1_comparison()
                                                          if c.status == "differs"}
    assert "<th>|ε|max/ω1²</th>" in review._repr_html_()


def test_the_review_columns_are_table1s_with_its_labels():
    review = {f.name: f.metadata.get("label") for f in dataclasses.fields(ReviewRow)}
    table1 = {f.name: f.metadata.get("label") for f in dataclasses.fields(SphericalRow)}
    assert tuple(review) == tuple(table1) == ("z", *TABLE1_COLUMNS) and len(TABLE1_COLUMNS) == 6
    assert all(review[c] == table1[c] is not None for c in TABLE1_COLUMNS)


# -- drive --------------------------------------------------------------------------------------
def _wheel_law(g):
    """β(σ) of the wheel (magnitude) as a sympy expression and the engagement half-angle,
    written here from the geometry, independently of mechlab.mechanisms.geneva:
    planar — the pin at a = C·λ from O (λ = sin(π/z)), the wheel centre at C: tan β =
    λ sin σ/(1 + κλ cos σ) (κ = -1 external: the pin between O and W at σ = 0), σ0 = π/2 + κπ/z;
    spherical — tan β = tan ψ sin α, ψ = atan(ρ0/(R cos(π/z))), ρ0 = √(e² + R² sin²(π/z)),
    α0 = arccos(e/ρ0) (seed 004 (1)-(3), (18))."""
    s = sp.Symbol("s")
    if isinstance(g, SphericalGeneva):
        rho0 = np.hypot(g.e, g.R * np.sin(np.pi / g.z))
        t = rho0 / (g.R * np.cos(np.pi / g.z))
        return sp.atan(t * sp.sin(s)), float(np.arccos(g.e / rho0)), s
    k = -1 if isinstance(g, ExternalGeneva) else 1
    lam = sp.sin(sp.pi / g.z)
    return sp.atan2(lam * sp.sin(s), 1 + k * lam * sp.cos(s)), float(np.pi / 2 + k * np.pi / g.z), s


def _reference_drive(g, J, w, Mr, eta, k):
    """Mean, rms and peak motor torque of the one rule, by scipy.integrate.quad and a bounded
    maximisation on the closed-form wheel law (no sampling grid)."""
    from scipy.integrate import quad
    from scipy.optimize import brentq, minimize_scalar
    beta, s0, s = _wheel_law(g)
    d1 = sp.lambdify(s, sp.diff(beta, s), "numpy")
    d2 = sp.lambdify(s, sp.diff(beta, s, 2), "numpy")

    def M1(x):   # crank torque from the wheel's power balance; β' > 0 inside the engagement
        return (J * d2(x) * w**2 + Mr) * d1(x)

    def Mm(x):
        m = M1(x)
        return m / eta if m > 0 else m * eta

    grid = np.linspace(-s0, s0, 4001)[1:-1]
    vals = np.array([M1(x) for x in grid])
    roots = [brentq(M1, a, b, xtol=1e-15)
             for a, b, fa, fb in zip(grid, grid[1:], vals, vals[1:], strict=False) if fa * fb < 0]
    edges = [-s0, *roots, s0]
    mean = sum(quad(Mm, a, b, epsabs=0, epsrel=1e-12, limit=200)[0] for a, b in itertools.pairwise(edges)) / (2 * np.pi)
    sq = sum(quad(lambda x: Mm(x) ** 2, a, b, epsabs=0, epsrel=1e-12, limit=200)[0]
             for a, b in itertools.pairwise(edges)) / (2 * np.pi)
    i = int(np.argmax(np.abs(vals)))
    lo, hi = grid[max(i - 1, 0)], grid[min(i + 1, len(grid) - 1)]
    peak = max(-minimize_scalar(lambda x: -abs(Mm(x)), bounds=(lo, hi), method="bounded",
                                options={"xatol": 1e-12}).fun, abs(Mm(grid[i])), abs(Mm(-s0)), abs(Mm(s0)))
    return mean, np.sqrt(sq), peak, M1, s0


GENEVAS = [ExternalGeneva(4, 100.0), ExternalGeneva(6, 0.1), InternalGeneva(6, 100.0), SphericalGeneva(40, 15, 4),
           SphericalGeneva(40, 15, 8)]


@pytest.mark.parametrize("g", GENEVAS, ids=["external4", "external6", "internal6", "spherical4", "spherical8"])
@pytest.mark.parametrize("J, Mr, eta, k", [(0.0, 2.0, 1.0, 2.0), (0.5, 0.0, 0.8, 2.0), (0.02, 1.5, 0.85, 2.0),
                                           (0.02, 1.5, 0.85, 8.0)])
def test_drive_is_the_one_rule_against_quad(g, J, Mr, eta, k):
    w = 2 * np.pi
    d = geneva_drive(g, inertia=J, omega1=w, resisting_torque=Mr, efficiency=eta, overload=k)
    mean, rms, peak, M1, s0 = _reference_drive(g, J, w, Mr, eta, k)
    scale = max(abs(mean), rms)
    assert d.mean_torque == pytest.approx(mean, rel=1e-6, abs=1e-9 * scale)
    assert d.rms_torque == pytest.approx(rms, rel=1e-6)
    assert d.peak_torque == pytest.approx(peak, rel=1e-5)   # the largest sample: O(h²) below the true peak
    assert d.peak_torque <= peak * (1 + 1e-12)
    # the rule: mean power for the energy, nominal torque max(rms, peak/k) for heating and overload
    assert d.mean_power == pytest.approx(mean * w, rel=1e-6, abs=1e-9 * scale * w)
    assert d.nominal_torque == max(d.rms_torque, d.peak_torque / k)
    assert d.nominal_power == pytest.approx(max(rms, peak / k) * w, rel=1e-5)
    assert d.governing == ("peak" if peak / k > rms else "rms")
    assert d.rms_torque >= abs(d.mean_torque)
    # the sampled crank torque is the power balance's, and zero while the wheel is locked
    sigma = d.phi - np.pi
    on = np.abs(sigma) < s0
    ref = np.array([M1(x) for x in sigma[on]])
    assert np.max(np.abs(d.torque[on] - ref)) <= 1e-9 * np.max(np.abs(ref))
    assert np.all(d.torque[~on] == 0.0)
    assert np.all(np.diff(d.phi) > 0) and d.phi[0] == 0.0 and d.phi[-1] == 2 * np.pi


@pytest.mark.parametrize("g", GENEVAS, ids=["external4", "external6", "internal6", "spherical4", "spherical8"])
def test_drive_closed_form_integrals(g):
    """Closed forms of the Geneva's torque integrals. Resisting torque alone: the work per
    turn is M_r·2π/z, so ⟨M_m⟩ = M_r/(zη), and the peak is M_r·max β'/η. Inertia alone: the
    wheel gains J ω²(β'max² - β'end²)/2 of kinetic energy (the motor supplies it / η) and
    gives it back (× η): ⟨M_m⟩ = J ω² (β'max² - β'end²)(1/η - η)/(4π), zero for η = 1."""
    beta, s0, s = _wheel_law(g)
    d1 = sp.lambdify(s, sp.diff(beta, s), "numpy")
    vmax, vend = d1(0.0), d1(s0)
    w, eta = 3.0, 0.8
    d = geneva_drive(g, inertia=0.0, omega1=w, resisting_torque=2.0, efficiency=eta)
    assert d.mean_torque == pytest.approx(2.0 / (g.z * eta), rel=1e-6)
    assert d.peak_torque == pytest.approx(2.0 * vmax / eta, rel=1e-6)
    J = 0.5
    d = geneva_drive(g, inertia=J, omega1=w, efficiency=eta)
    assert d.mean_torque == pytest.approx(J * w**2 * (vmax**2 - vend**2) * (1 / eta - eta) / (4 * np.pi), rel=1e-5)
    d = geneva_drive(g, inertia=J, omega1=w)
    assert abs(d.mean_torque) <= 1e-9 * d.peak_torque and d.rms_torque > 0.1 * d.peak_torque
    # efficiency costs where the motor drives; η = 1 is the power balance itself
    d1_, d0_ = (geneva_drive(g, inertia=J, omega1=w, resisting_torque=1.0, efficiency=e) for e in (0.8, 1.0))
    assert d1_.mean_torque > d0_.mean_torque and d1_.peak_torque > d0_.peak_torque
    with pytest.raises(DriveError, match="efficiency"):
        geneva_drive(g, inertia=1.0, omega1=1.0, efficiency=1.5)
    with pytest.raises(DriveError, match="overload"):
        geneva_drive(g, inertia=1.0, omega1=1.0, overload=0.5)
    with pytest.raises(DimensionError, match="inertia"):
        geneva_drive(g, inertia=-1.0, omega1=1.0)
    with pytest.raises(DimensionError, match="n must be"):
        geneva_drive(g, inertia=1.0, omega1=1.0, n=5)


def test_drive_resolves_the_hard_impact_jump():
    """The spherical Geneva's torque jumps at entry (β' ≠ 0 there): on a plain uniform grid the
    trapezoidal rule smears the jump over one step (error O(h)); drive_angles puts samples a
    few 1e-13 apart on both sides, so the mean is right to O(h²)."""
    g = SphericalGeneva(40, 15, 4)
    mean = _reference_drive(g, 0.0, 1.0, 2.0, 0.8, 2.0)[0]
    phi = drive_angles(g, 721)
    fine = fdrive(crank_torque(g, phi, inertia=0.0, omega1=1.0, resisting_torque=2.0), phi, 1.0, efficiency=0.8)
    uniform = np.linspace(0, 2 * np.pi, 721)
    plain = fdrive(crank_torque(g, uniform, inertia=0.0, omega1=1.0, resisting_torque=2.0), uniform, 1.0,
                   efficiency=0.8)
    assert abs(fine.mean_torque / mean - 1) < 1e-5 < abs(plain.mean_torque / mean - 1)
    coarse = geneva_drive(g, inertia=0.0, omega1=1.0, resisting_torque=2.0, efficiency=0.8, n=721)
    assert coarse.mean_torque == fine.mean_torque


# -- comparison ---------------------------------------------------------------------------------
def test_impact_detection_and_comparison():
    assert impact_kind(0.1, 0.0) == "hard" and impact_kind(0.0, 0.2) == "soft" and impact_kind(0, 0) == "none"
    assert detect_impacts(ExternalGeneva(4, 1.0)) == "soft"
    assert detect_impacts(InternalGeneva(4, 1.0)) == "soft"
    assert detect_impacts(SphericalGeneva(40, 15, 4)) == "hard"
    assert detect_impacts(SlottedLink(2.0, 1.0)) == "none"
    assert detect_impacts(FourBar(1.0, 3.0, 3.0, 4.0)) == "none"
    ext = intermittency(ExternalGeneva(4, 1.0), n=14401)
    assert ext.dwell_fraction == pytest.approx(0.75, abs=2e-4) and ext.index_deg == pytest.approx(90.0)
    assert ext.max_dpsi == pytest.approx(np.sqrt(2) + 1, rel=1e-9)
    assert ext.B == pytest.approx((np.sqrt(2) + 1) * (np.pi / 2) / (np.pi / 2), rel=1e-3)
    shifted = intermittency(ExternalGeneva(4, 1.0), n=14401, phase=0.3)
    assert shifted.dwell_fraction == pytest.approx(0.75, abs=2e-4) and shifted.impact == "soft"
    loose = intermittency(ExternalGeneva(4, 1.0), n=14401, dwell_tol=0.5)
    # a loose tolerance counts the slow ends of the motion as near-standstill, never as dwell
    assert loose.standstill_fraction > 0.8 and loose.dwell_fraction == ext.dwell_fraction
    rows = compare({"external": ExternalGeneva(4, 1.0), "spherical": SphericalGeneva(40, 15, 4),
                    "whitworth": SlottedLink(2.0, 1.0)})
    assert [r.name for r in rows] == ["external", "spherical", "whitworth"]
    assert rows[2].dwell_fraction == 0.0 and rows[2].index_deg == pytest.approx(360.0)
    # seed 004's motivation: the spherical drive accelerates less than the external planar one
    assert rows[1].max_ddpsi < rows[0].max_ddpsi


def test_compare_takes_a_dwell_tolerance_per_mechanism():
    """A per-name tolerance is the one intermittency uses for that row; a name it leaves out keeps 1e-9; one
    number applies to every row; the table shows the chapter's columns at its precision."""
    mechs = {"external": ExternalGeneva(4, 1.0), "whitworth": SlottedLink(2.0, 1.0), "internal": InternalGeneva(6, 1.0)}
    loose = {"whitworth": 0.4, "internal": 0.02}   # Whitworth λ = 2: min ψ′ / max ψ′ = (λ - 1)/(λ + 1) = 1/3
    rows = compare(mechs, n=1441, phase=1e-3, dwell_tol=loose)
    for r, (name, m) in zip(rows, mechs.items(), strict=False):
        assert r == intermittency(m, n=1441, phase=1e-3, dwell_tol=loose.get(name, 1e-9), name=name)
    assert rows.by("name")["whitworth"].standstill_fraction > 0 == rows.by("name")["whitworth"].dwell_fraction
    assert compare(mechs, n=1441).by("name")["whitworth"].standstill_fraction == 0
    assert [r.standstill_fraction for r in compare(mechs, n=1441, dwell_tol=0.4)] == \
        [intermittency(m, n=1441, dwell_tol=0.4).standstill_fraction for m in mechs.values()]
    assert rows.headers[:4] == ("name", "dwell", "near-standstill", "Δψ per turn, °")
    assert "<td>0.750</td><td>0.750</td><td>90</td>" in rows._repr_html_()
    with pytest.raises(DimensionError, match=r"dwell_tol names no mechanism compared: 'whitworh' \(the mechanisms: "
                                             r"'external', 'whitworth', 'internal'\)"):
        compare(mechs, dwell_tol={"whitworh": 0.1})
    with pytest.raises(DimensionError, match=r"dwell_tol\['internal'\] must be < 1, got 1.5"):
        compare(mechs, dwell_tol={"internal": 1.5})
    with pytest.raises(DimensionError, match="dwell_tol must be finite, got nan"):
        compare(mechs, dwell_tol=float("nan"))



@pytest.mark.parametrize("cls", [ExternalGeneva, InternalGeneva])
@pytest.mark.parametrize("z", [4, 6, 8])
def test_intermittency_is_the_motion_law_invariants(cls, z):
    """intermittency's B, C, D are rise_invariants of the engaged part of the turn, and B, C equal the
    Geneva's closed forms max|ψ'|·Φ/h and max|ψ''|·Φ²/h with Φ = 2σ0, h = 2π/z."""
    g = cls(z, 1.0)
    r = intermittency(g, n=14401)
    s0, h = g.engagement_half_angle, abs(g.index_angle)
    phi = np.pi + np.linspace(-s0, s0, 20001)
    mo = g.motion(phi)
    rise = rise_invariants(phi, mo.psi, mo.dpsi, mo.ddpsi)
    assert r.B == pytest.approx(g.max_velocity() * 2 * s0 / h, rel=1e-3)
    assert r.C == pytest.approx(g.max_acceleration() * (2 * s0) ** 2 / h, rel=2e-3)
    assert (r.B, r.C, r.D) == pytest.approx(rise.values, rel=2e-3)
    # the one definition: the same samples through invariants give intermittency's numbers exactly
    turn = g.motion(np.linspace(0.0, 2 * np.pi, 14401))
    same = invariants((1 - r.dwell_fraction) * 2 * np.pi, turn.psi[-1] - turn.psi[0], turn.dpsi, turn.ddpsi)
    assert (r.B, r.C, r.D) == same.values

# -- exercises and errata -------------------------------------------------------------------------


def test_errata_seed004_geneva():
    from mechlab.course.errata import seed004_geneva, table
    assert len(seed004_geneva.ERRATA) == 8
    for e in seed004_geneva.ERRATA:
        assert e.source == "004" and e.notebook == "10_geneva_spherical.ipynb"
        assert e.evidence()
    md = table(notebook="10_geneva_spherical.ipynb")
    assert md.count("\n| 004 |") == 8


# -- drawings and widgets -------------------------------------------------------------------------
def test_planar_drawing_matches_the_motion():
    import matplotlib.pyplot as plt

    from mechlab.draw import drawing_class
    from mechlab.geometry import wrap
    from mechlab.mechanisms.geneva import wheel_outline

    for g in (ExternalGeneva(5, 100.0), InternalGeneva(6, 100.0)):
        inner, outer = wheel_outline(g)
        assert np.allclose(inner[0], inner[-1])
        dist = np.hypot(*inner.T)
        w = 1.08 * g.roller_radius
        if g.kappa < 0:
            assert dist.max() <= g.outer_radius + 1e-9 and np.isclose(dist.min(), g.slot_bottom - w, rtol=1e-3)
            assert len(outer) == 0
        else:
            assert np.isclose(dist.max(), g.slot_bottom + w, rtol=1e-3)
            assert np.isclose(dist.min(), g.inner_radius, rtol=1e-9)
            assert np.allclose(np.hypot(*outer.T), g.outer_radius)
        fig, ax = plt.subplots()
        d = drawing_class(g)(ax, g, n=24)
        d.autoscale()
        assert len(d.lines_of("wheel")) == 2
        n_art = len(d.artists)
        for i in range(24):
            assert len(d.set_frame(i)) == n_art
            if not g.engaged(d.motion.phi[i]):
                continue
            # the pin lies on a slot's centre line of the drawn (rotated) wheel
            A, W = d.motion.points["A"].p[i], d.motion.points["W"].p[i]
            rel = np.arctan2(*(A - W)[::-1]) - d.motion.psi[i]
            slots = np.pi - g.kappa * np.pi / g.z + 2 * np.pi * np.arange(g.z) / g.z
            assert np.min(np.abs(wrap(rel - slots))) < 1e-9
        plt.close("all")
    # the locking disc faces the wheel during the dwell, its relief during the motion
    g = ExternalGeneva(4, 100.0)
    fig, ax = plt.subplots()
    d = drawing_class(g)(ax, g, n=37)
    lock_line = d.lines_of("lock")[0]
    for i, phi in enumerate(d.motion.phi):
        d.set_frame(i)
        lock = np.column_stack(lock_line.get_data())
        toward_w = np.any(np.abs(np.arctan2(lock[:, 1], lock[:, 0])) < np.radians(6))
        assert toward_w == (not g.engaged(phi)) or abs(abs(phi - np.pi) - g.engagement_half_angle) < 0.2
    plt.close(fig)


def test_spherical_drawing_and_comparison_plot():
    import matplotlib.pyplot as plt

    from mechlab.draw import drawing_class
    from mechlab.draw.geneva import SphericalGenevaDrawing, plot_comparison

    g = SphericalGeneva(40.0, 15.0, 5)
    fig, ax = plt.subplots()  # a 2-D axes, as animate() makes: the drawing puts a 3-D one in its place
    d = drawing_class(g)(ax, g, n=20, trace="P")
    d.autoscale()
    assert isinstance(d, SphericalGenevaDrawing) and d.ax.name == "3d" and ax not in fig.axes
    for i in range(20):
        d.set_frame(i)
        x, y, _z = (np.asarray(a) for a in d.contact.get_data_3d())
        assert (len(x) == 1) == bool(g.engaged(d.motion.phi[i]))
        if len(x):  # the contact point lies on one of the drawn slot arcs' meridians
            az = [np.arctan2(*np.asarray(s.get_data_3d())[1::-1, -1]) for s in d.slot_lines[:g.z]]
            from mechlab.geometry import wrap
            assert np.min(np.abs(wrap(np.arctan2(y[0], x[0]) - np.array(az)))) < 1e-9
    assert d.bounds() == (-40.0, 40.0, -40.0, 40.0)
    axes = plot_comparison({"ext": ExternalGeneva(4, 1.0), "sph": g}, n=181)
    assert len(axes[0].lines) == 2 and len(axes[1].lines) == 2
    assert "impact: hard" in axes[0].lines[1].get_label()
    axes = plot_comparison({"sph": g}, n=181, phase=0.1, dwell_tol={"sph": 0.5})
    assert np.isclose(axes[0].lines[0].get_xdata()[0], np.degrees(0.1))
    assert "dwell 0." in axes[0].lines[0].get_label()
    plt.close("all")


def test_geneva_explorers():
    from mechlab.widgets.geneva import planar_geneva_explorer, spherical_geneva_explorer

    ex = planar_geneva_explorer(z=4, centre_distance=100.0)
    assert isinstance(ex.mechanism, ExternalGeneva) and "dwell fraction 0.750" in ex.status.value
    ex.kind.value = "internal"
    assert isinstance(ex.mechanism, InternalGeneva) and "dwell fraction 0.250" in ex.status.value
    ex.sliders["z"].value = 6
    assert ex.mechanism.z == 6
    sp_ = spherical_geneva_explorer(R=40.0, e=15.0, z=4)
    assert sp_.ax_mech.name == "3d" and "hard impact" in sp_.status.value
    sp_.sliders["e"].value = 45.0
    assert sp_.mechanism is None and "e = 45 ≥ R = 40" in sp_.message
    sp_.sliders["e"].value = 0.0
    assert sp_.message == "" and "soft impact" in sp_.status.value
    sp_.angle.value = 180.0
    assert sp_.frame == np.argmin(np.abs(np.degrees(sp_.motion.phi) - 180.0))


def test_small_helpers():
    from mechlab.mechanisms.geneva import check_slots, mid_motion_angle

    assert check_slots(4.0) == 4 and isinstance(check_slots(np.int64(5)), int)
    s = mid_motion_angle(np.array([0.0, np.pi, 2 * np.pi, 3 * np.pi, -np.pi]))
    assert np.allclose(s, [-np.pi, 0.0, -np.pi, 0.0, 0.0])
    g = SphericalGeneva(40.0, 15.0, 4)
    d = g.pin_direction(np.linspace(-3, 3, 7))
    assert np.allclose(np.linalg.norm(d, axis=1), 1.0) and np.allclose(d[:, 0], np.cos(g.cone_angle))
    assert set(g.design().by("name")) >= {"α0 (deg)", "ρ0 (mm)", "r_H (mm)", "min slot length (mm)"}
    from mechlab.mechanisms.geneva import PlanarGeneva
    with pytest.raises(TypeError, match="ExternalGeneva or InternalGeneva"):
        PlanarGeneva(4, 1.0)
    assert np.array_equal(g.engaged([np.pi, 0.0]), [True, False])


@pytest.mark.parametrize("cls", [ExternalGeneva, InternalGeneva])
@pytest.mark.parametrize("z", [3, 6, 8])
def test_two_dwell_fractions_exact_and_near_standstill(cls, z):
    """dwell_fraction is exact (the wheel locked); standstill_fraction is the design layer's dwell within
    a band of precision × the index angle, here in closed form against the design layer's own sampled
    measure (mechlab.design.criteria.longest_still) — 0.680 against 2/3 for the external z = 6."""
    from mechlab.design.criteria import longest_still

    g = cls(z, 100.0)
    n = 200000
    phi = np.linspace(0, 2 * np.pi, n + 1)
    x = g.motion(phi).psi
    for precision in (0.001, 0.01):
        _, run = longest_still(x[:-1], x[-1] - x[0], precision * abs(g.index_angle))
        assert g.standstill_fraction(precision) == pytest.approx(run / n, abs=2.0 / n)
        assert g.standstill_fraction(precision) > g.dwell_fraction
    locked = ~g.engaged(phi)
    assert g.dwell_fraction == pytest.approx(locked.mean(), abs=2.0 / n)
    if cls is ExternalGeneva and z == 6:
        assert round(g.standstill_fraction(), 3) == 0.680 and g.dwell_fraction == pytest.approx(2 / 3)
    with pytest.raises(DimensionError, match="precision"):
        g.standstill_fraction(0.0)
