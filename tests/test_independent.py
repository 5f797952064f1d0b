"""An auditor's re-check of mechlab's numbers by independent implementations.

Nothing here calls mechlab's geometry helpers. Each mechanism family is written again
as a vector-loop closure F(x, φ) = 0 in sympy; positions are solved angle by angle
with scipy.optimize.fsolve (continuation along φ: predictor x + x'h + x''h²/2), the
analogs by implicit differentiation of the same closure (J·x' = -F_φ and
J·x'' = -(d/dφ of J·x' + F_φ at fixed x'), sympy-generated). Geometries are drawn at
random by hypothesis with strategies of this file (not tests/strategies.py), and the
library is compared with the re-implementation; a self-check compares the
re-implementation's analogs with central differences of its own positions. The lambda
six-bars (МЧВ1, МЧВ2, МЧВ3, МЧВ5) take D from the independent four-bar and their outputs from
formulas written here from the classes' docstrings (dyad, slot line, RRP, projection), with
the analogs by five-point differences.

Slow part (about 45 s in all on 2 cores): the per-angle fsolve loops, a few thousand solves per test; kept to
≤ 60 hypothesis examples per test and ~60-120 angles per example.
"""

from __future__ import annotations

import functools

import numpy as np
import pytest
import sympy as sp
from hypothesis import HealthCheck, assume, example, given, settings
from hypothesis import strategies as st
from scipy.optimize import brentq, fsolve, minimize_scalar

import mechlab as ml
from mechlab.errors import MechanismError

SETTINGS = settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow,
                                                                            HealthCheck.filter_too_much])
FEW = settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow,
                                                                      HealthCheck.filter_too_much])


def cross2(u, v):
    u, v = np.asarray(u, float), np.asarray(v, float)
    return u[..., 0] * v[..., 1] - u[..., 1] * v[..., 0]


def wrap(a):
    return (np.asarray(a) + np.pi) % (2 * np.pi) - np.pi


# ------------------------------------------------------------------------------------------
# the independent engine: a loop closure solved per angle, analogs by implicit differentiation
# ------------------------------------------------------------------------------------------
class Loop:
    """F(x, φ; p) = 0 with n unknowns x and n equations, from sympy expressions."""

    def __init__(self, F, x, phi, params):
        F, x = sp.Matrix(F), sp.Matrix(x)
        J = F.jacobian(x)
        Fp = F.diff(phi)
        dx = sp.Matrix(sp.symbols(f"dx0:{len(x)}"))
        G = J * dx + Fp                       # dF/dφ along the path, x' held as symbols
        H = G.jacobian(x) * dx + G.diff(phi)  # d²F/dφ² minus J·x''
        a = (list(x), phi, list(params))
        self.n = len(x)
        self._F = sp.lambdify(a, F, "numpy")
        self._J = sp.lambdify(a, J, "numpy")
        self._Fp = sp.lambdify(a, Fp, "numpy")
        self._H = sp.lambdify((list(x), list(dx), phi, list(params)), H, "numpy")

    def F(self, x, phi, p):
        return np.asarray(self._F(list(x), phi, list(p)), dtype=float).ravel()

    def J(self, x, phi, p):
        return np.asarray(self._J(list(x), phi, list(p)), dtype=float).reshape(self.n, self.n)

    def analogs(self, x, phi, p):
        J = self.J(x, phi, p)
        dx = np.linalg.solve(J, -np.asarray(self._Fp(list(x), phi, list(p)), dtype=float).ravel())
        ddx = np.linalg.solve(J, -np.asarray(self._H(list(x), list(dx), phi, list(p)), dtype=float).ravel())
        return dx, ddx

    def solve_at(self, x0, phi, p):
        x, _info, _ier, _msg = fsolve(self.F, np.asarray(x0, float), args=(phi, p), fprime=self.J,
                                   full_output=True, xtol=1e-14)
        for _ in range(2):  # two Newton polish steps
            J = self.J(x, phi, p)
            if not abs(np.linalg.det(J)) > 1e-14:
                break
            x = x - np.linalg.solve(J, self.F(x, phi, p))
        res = float(np.max(np.abs(self.F(x, phi, p))))
        return x, (res if np.isfinite(res) else np.inf)

    def follow(self, x0, phis, p, substeps=3):
        """Continuation from x0 (a root at phis[0]) through the angles phis; returns x, x', x''."""
        xs, ds, dds = [], [], []
        x, _ = self.solve_at(x0, phis[0], p)
        prev = phis[0]
        for ph in phis:
            for q in np.linspace(prev, ph, substeps + 1)[1:] if ph != prev else [ph]:
                h = q - prev
                d, dd = self.analogs(x, prev, p)
                x, res = self.solve_at(x + d * h + 0.5 * dd * h * h, q, p)
                assert res < 1e-9, f"independent solve failed at φ = {q}: residual {res}"
                prev = q
            d, dd = self.analogs(x, ph, p)
            xs.append(x)
            ds.append(d)
            dds.append(dd)
        return np.array(xs), np.array(ds), np.array(dds)


phi_s = sp.Symbol("phi")


def _sym(names):
    return sp.symbols(names)


@functools.cache
def fourbar_loop():
    th, ps = _sym("th ps")
    a, c, r, g = _sym("a c r g")
    F = [a * sp.cos(phi_s) + c * sp.cos(th) - g - r * sp.cos(ps),
         a * sp.sin(phi_s) + c * sp.sin(th) - r * sp.sin(ps)]
    return Loop(F, [th, ps], phi_s, [a, c, r, g])


@functools.cache
def slider_loop():
    th, s = _sym("th s")
    a, l, e = _sym("a l e")
    F = [a * sp.cos(phi_s) + l * sp.cos(th) - s, a * sp.sin(phi_s) + l * sp.sin(th) - e]
    return Loop(F, [th, s], phi_s, [a, l, e])


@functools.cache
def slotted_loop():
    ps, rho = _sym("ps rho")
    a, d = _sym("a d")
    # A - B = ρ·e(ψ) with B = (-d, 0)
    F = [a * sp.cos(phi_s) + d - rho * sp.cos(ps), a * sp.sin(phi_s) - rho * sp.sin(ps)]
    return Loop(F, [ps, rho], phi_s, [a, d])


@functools.cache
def yoke_loop():
    s, y = _sym("s y")
    a, = _sym("a,")
    return Loop([s - a * sp.cos(phi_s), y - a * sp.sin(phi_s)], [s, y], phi_s, [a])


def _curve_loop(cx, cy, t, extra):
    """Pin on a slot c(t) of a link pivoted at B = (-d, 0) turned by ψ: B + R(ψ)c(t) = A."""
    ps = sp.Symbol("ps")
    a, d = _sym("a d")
    F = [-d + sp.cos(ps) * cx - sp.sin(ps) * cy - a * sp.cos(phi_s),
         sp.sin(ps) * cx + sp.cos(ps) * cy - a * sp.sin(phi_s)]
    return Loop(F, [ps, t], phi_s, [a, d, *extra])


@functools.cache
def circle_slot_loop():
    t, x0, y0, rho = _sym("t x0 y0 rho")
    return _curve_loop(x0 + rho * sp.cos(t), y0 + rho * sp.sin(t), t, [x0, y0, rho])


@functools.cache
def spiral_slot_loop():
    # polar slot: distance t from B, polar angle k·(t - m)² + w·t
    t, k, m, w = _sym("t k m w")
    b = k * (t - m) ** 2 + w * t
    return _curve_loop(t * sp.cos(b), t * sp.sin(b), t, [k, m, w])


def spiral_funcs(k, m, w):
    def f(t):
        b = k * (t - m) ** 2 + w * t
        return np.stack([t * np.cos(b), t * np.sin(b)], -1)

    def df(t):
        b = k * (t - m) ** 2 + w * t
        db = 2 * k * (t - m) + w
        return np.stack([np.cos(b) - t * db * np.sin(b), np.sin(b) + t * db * np.cos(b)], -1)

    def ddf(t):
        b = k * (t - m) ** 2 + w * t
        db, ddb = 2 * k * (t - m) + w, 2 * k
        return np.stack([-2 * db * np.sin(b) - t * ddb * np.sin(b) - t * db * db * np.cos(b),
                         2 * db * np.cos(b) + t * ddb * np.cos(b) - t * db * db * np.sin(b)], -1)

    return f, df, ddf


@functools.cache
def translating_circle_loop():
    s, t, a, x0, y0, rho = _sym("s t a x0 y0 rho")
    F = [s + x0 + rho * sp.cos(t) - a * sp.cos(phi_s), y0 + rho * sp.sin(t) - a * sp.sin(phi_s)]
    return Loop(F, [s, t], phi_s, [a, x0, y0, rho])


@functools.cache
def sixbar_loop():
    th, ps = _sym("th ps")
    a, g, rx, ry, tx, ty, l3, l5, qp, ux, uy = _sym("a g rx ry tx ty l3 l5 qp ux uy")
    Ax, Ay = a * sp.cos(phi_s), a * sp.sin(phi_s)
    # A = Q + Rot(θ2)·u, P = Q + qp·e(θ2); R, T fixed to link 4 (origin E, angle ψ)
    Qx = Ax - (sp.cos(th) * ux - sp.sin(th) * uy)
    Qy = Ay - (sp.sin(th) * ux + sp.cos(th) * uy)
    Px, Py = Qx + qp * sp.cos(th), Qy + qp * sp.sin(th)
    Rx, Ry = g + sp.cos(ps) * rx - sp.sin(ps) * ry, sp.sin(ps) * rx + sp.cos(ps) * ry
    Tx, Ty = g + sp.cos(ps) * tx - sp.sin(ps) * ty, sp.sin(ps) * tx + sp.cos(ps) * ty
    F = [(Qx - Rx) ** 2 + (Qy - Ry) ** 2 - l3 ** 2, (Px - Tx) ** 2 + (Py - Ty) ** 2 - l5 ** 2]
    return Loop(F, [th, ps], phi_s, [a, g, rx, ry, tx, ty, l3, l5, qp, ux, uy])


# ------------------------------------------------------------------------------------------
# independent solutions per family
# ------------------------------------------------------------------------------------------
def my_fourbar(a, c, r, g, assembly, phis):
    """θ (coupler A→B), ψ (rocker E→B) with analogs; assembly by the sign of (E - A) × (B - A)."""
    loop, p = fourbar_loop(), (a, c, r, g)
    roots = []
    for t0 in np.linspace(-np.pi, np.pi, 7, endpoint=False):
        for s0 in np.linspace(-np.pi, np.pi, 7, endpoint=False):
            x, res = loop.solve_at((t0, s0), phis[0], p)
            if res < 1e-10:
                roots.append(x)
    A = a * np.array([np.cos(phis[0]), np.sin(phis[0])])
    good = [x for x in roots
            if np.sign(cross2(np.array([g, 0.0]) - A, c * np.array([np.cos(x[0]), np.sin(x[0])]))) == assembly]
    assert good, "independent four-bar: no root of the requested assembly"
    return loop.follow(good[0], phis, p)


def assembly_sign_holds(a, c, g, th, assembly, phis):
    A = a * np.stack([np.cos(phis), np.sin(phis)], -1)
    AB = c * np.stack([np.cos(th), np.sin(th)], -1)
    return np.all(np.sign(cross2(np.array([g, 0.0]) - A, AB)) == assembly)


def my_grashof_turns(a, c, r, g, n=720, m=4000):
    """Brute force: at each of n crank angles, is there a rocker angle ψ (of m tried) that puts B
    at distance c from A? Reached iff c lies between min and max over ψ of |B(ψ) - A|."""
    ph = np.linspace(0, 2 * np.pi, n, endpoint=False)[:, None]
    ps = np.linspace(-np.pi, np.pi, m)[None, :]
    dist = np.hypot(g + r * np.cos(ps) - a * np.cos(ph), r * np.sin(ps) - a * np.sin(ph))
    return (dist.min(axis=1) <= c) & (c <= dist.max(axis=1))


# ------------------------------------------------------------------------------------------
# strategies (this file's own)
# ------------------------------------------------------------------------------------------
L = st.floats(0.2, 5.0, allow_nan=False, allow_infinity=False)
SIGN = st.sampled_from([1, -1])


def _cmp_angle(lib, mine, tol, what):
    lib, mine = np.asarray(lib), np.asarray(mine)
    err = np.max(np.abs(wrap(lib - mine)))
    assert err < tol, f"{what}: max |Δ| = {err:.3g}"
    # the library's branch must be continuous exactly where the independent one is
    derr = np.max(np.abs(np.diff(lib) - np.diff(mine)))
    assert derr < tol, f"{what}: branch jump {derr:.3g}"


def _cmp(lib, mine, tol, what, scale=1.0):
    lib, mine = np.asarray(lib), np.asarray(mine)
    err = np.max(np.abs(lib - mine)) / max(scale, 1.0)
    assert err < tol, f"{what}: max |Δ| = {err:.3g} (scale {scale:.3g})"


# ------------------------------------------------------------------------------------------
# 0. the engine itself: analogs = central differences of its own positions
# ------------------------------------------------------------------------------------------
def test_engine_analogs_match_its_own_central_differences():
    h = 1e-4
    phis = np.array([0.3, 1.7, 4.0])
    for ph in phis:
        grid = ph + h * np.arange(-2, 3)
        x, d, dd = my_fourbar(1.0, 3.2, 2.7, 3.9, 1, grid)
        fd = (x[3] - x[1]) / (2 * h)
        fdd = (x[3] - 2 * x[2] + x[1]) / h**2
        assert np.allclose(d[2], fd, atol=1e-7) and np.allclose(dd[2], fdd, atol=1e-5)


# ------------------------------------------------------------------------------------------
# 1. four-bar: every kind, both assemblies, over every crank range
# ------------------------------------------------------------------------------------------
@st.composite
def any_fourbar(draw):
    a, c, r, g = (draw(L) for _ in range(4))
    s = draw(SIGN)
    try:
        fb = ml.FourBar(a, c, r, g, s)
    except MechanismError:
        assume(False)
    ranges = fb.crank_ranges()
    assume(all(e - b > 0.2 for b, e in ranges))
    # keep clear of the Grashof equality (change points), where a branch is not defined
    lens = sorted((a, c, r, g))
    assume(abs(lens[0] + lens[3] - lens[1] - lens[2]) > 0.02 * (lens[1] + lens[2]))
    return fb


@SETTINGS
@given(any_fourbar())
@example(ml.FourBar(1, 3, 3, 4, 1))          # crank-rocker
@example(ml.FourBar(3, 4, 3.5, 1, -1))       # double-crank
@example(ml.FourBar(3, 4, 1, 3.5, 1))        # rocker-crank (the crank rocks)
@example(ml.FourBar(2.5, 1.0, 3.0, 3.2, -1))  # double-rocker: two crank ranges
@example(ml.FourBar(3, 3, 3, 5, 1))          # triple-rocker
def test_fourbar_positions_analogs_transmission(fb):
    a, c, r, g, k = fb.crank, fb.coupler, fb.rocker, fb.ground, fb.assembly
    for start, end in fb.crank_ranges():
        w = end - start
        phis = np.linspace(start + 0.03 * w, end - 0.03 * w, 61) if w < 2 * np.pi else np.linspace(0, 2 * np.pi, 61)
        x, d, dd = my_fourbar(a, c, r, g, k, phis)
        assert assembly_sign_holds(a, c, g, x[:, 0], k, phis)
        mo = fb.motion(phis)
        scale = max(1.0, np.max(np.abs(d[:, 1])) ** 2, np.max(np.abs(dd[:, 1])))
        _cmp_angle(mo.psi, x[:, 1], 1e-9, f"ψ of {fb}")
        _cmp(mo.dpsi, d[:, 1], 1e-8 * scale, f"ψ' of {fb}")
        _cmp(mo.ddpsi, dd[:, 1], 1e-7 * scale, f"ψ'' of {fb}")
        B = np.stack([g + r * np.cos(x[:, 1]), r * np.sin(x[:, 1])], -1)
        _cmp(mo.points["B"].p, B, 1e-9, "B")
        dB = d[:, 1, None] * np.stack([-r * np.sin(x[:, 1]), r * np.cos(x[:, 1])], -1)
        _cmp(mo.points["B"].d, dB, 1e-8 * scale, "B'")
        mu = np.arccos(np.clip(np.cos(x[:, 0] - x[:, 1]), -1, 1))
        _cmp(mo.transmission, mu, 1e-7, "transmission angle")


def _grashof_kind(a, c, r, g):
    """Textbook Grashof classification written again (Norton's table)."""
    named = [("crank", a), ("coupler", c), ("rocker", r), ("ground", g)]
    s_name, s = min(named, key=lambda t: t[1])
    l_ = max(v for _, v in named)
    pq = a + c + r + g - s - l_
    if s + l_ > pq:
        return "triple-rocker"
    return {"crank": "crank-rocker", "ground": "double-crank", "rocker": "rocker-crank",
            "coupler": "double-rocker"}[s_name]


@SETTINGS
@given(L, L, L, L)
def test_grashof_class_against_brute_force_reach(a, c, r, g):
    lens = sorted((a, c, r, g))
    assume(abs(lens[0] + lens[3] - lens[1] - lens[2]) > 0.03 * (lens[1] + lens[2]))
    try:
        fb = ml.FourBar(a, c, r, g)
    except MechanismError:
        # refused: the brute force must find no crank angle at all where the loop closes
        assert not my_grashof_turns(a, c, r, g).any()
        return
    kind = fb.grashof().kind
    assert kind == _grashof_kind(a, c, r, g)
    reach = my_grashof_turns(a, c, r, g, n=180)
    turns = bool(reach.all())
    assert turns == (kind in ("crank-rocker", "double-crank")) == fb.can_turn, (kind, reach.mean())
    # the brute-force reachable set agrees with crank_ranges() on the grid (away from its ends)
    grid = np.linspace(0, 2 * np.pi, 180, endpoint=False)
    inside = np.zeros(len(grid), bool)
    near = np.zeros(len(grid), bool)
    for s0, e0 in fb.crank_ranges():
        t = np.mod(grid - s0, 2 * np.pi)
        inside |= (t > 0) & (t < e0 - s0)
        near |= (np.abs(wrap(grid - s0)) < 0.05) | (np.abs(wrap(grid - e0)) < 0.05)
    assert np.all((inside == reach) | near)
    # the output link turns fully iff the inverted four-bar (rocker as crank) can turn
    inv = my_grashof_turns(r, c, a, g, n=180).all()
    assert inv == (kind in ("rocker-crank", "double-crank"))


# ------------------------------------------------------------------------------------------
# 2. slider-crank (offset, both assemblies)
# ------------------------------------------------------------------------------------------
@st.composite
def any_slider(draw):
    a, l = draw(L), draw(L)
    e = draw(st.floats(-3.0, 3.0))
    s = draw(SIGN)
    try:
        m = ml.SliderCrank(a, l, e, s)
    except MechanismError:
        assume(False)
    assume(all(e1 - b1 > 0.2 for b1, e1 in m.crank_ranges()))
    return m


@SETTINGS
@given(any_slider())
def test_slider_crank_positions_analogs_transmission(m):
    a, l, e, k = m.crank, m.rod, m.offset, m.assembly
    for start, end in m.crank_ranges():
        w = end - start
        phis = np.linspace(start + 0.03 * w, end - 0.03 * w, 61) if w < 2 * np.pi else np.linspace(0, 2 * np.pi, 61)
        # start: the rod's angle from its offset, on the side the assembly asks for
        sn = (e - a * np.sin(phis[0])) / l
        th0 = np.arcsin(sn) if k > 0 else np.pi - np.arcsin(sn)
        x, d, dd = slider_loop().follow((th0, a * np.cos(phis[0]) + l * np.cos(th0)), phis, (a, l, e))
        assert np.all(np.sign(np.cos(x[:, 0])) == k)  # ahead of the pin for +1
        mo = m.motion(phis)
        scale = max(1.0, np.max(np.abs(d)) ** 2, np.max(np.abs(dd)))
        _cmp(mo.s, x[:, 1], 1e-9, "s", scale=a + l)
        _cmp(mo.ds, d[:, 1], 1e-8 * scale, "s'")
        _cmp(mo.dds, dd[:, 1], 1e-7 * scale, "s''")
        _cmp(mo.transmission, np.arccos(np.clip(np.abs(np.sin(x[:, 0])), 0, 1)), 1e-7, "μ")


# ------------------------------------------------------------------------------------------
# 3. slotted link (λ < 1 and λ > 1) and the sine mechanism
# ------------------------------------------------------------------------------------------
@SETTINGS
@given(L, L)
def test_slotted_link_both_regimes(a, dist):
    assume(abs(a / dist - 1) > 0.05)
    m = ml.SlottedLink(a, dist)
    phis = np.linspace(0, 2 * np.pi, 91)
    x, d, dd = slotted_loop().follow((0.0, a + dist), phis, (a, dist))
    mo = m.motion(phis)
    scale = max(1.0, np.max(np.abs(dd[:, 0])))
    _cmp(mo.psi, x[:, 0], 1e-9, "ψ (absolute, continuous)")
    _cmp(mo.dpsi, d[:, 0], 1e-9 * scale, "ψ'")
    _cmp(mo.ddpsi, dd[:, 0], 1e-8 * scale, "ψ''")
    # λ > 1: one full turn of the link per crank turn; λ < 1: it oscillates, within ±asin λ
    if a > dist:
        assert abs(x[-1, 0] - 2 * np.pi) < 1e-9 and m.rotates
    else:
        assert np.max(np.abs(x[:, 0])) <= np.arcsin(a / dist) + 1e-12 and not m.rotates


@FEW
@given(L)
def test_sine_mechanism(a):
    phis = np.linspace(-1.0, 7.0, 41)
    x, d, dd = yoke_loop().follow((a * np.cos(-1.0), 0.0), phis, (a,))
    mo = ml.SineMechanism(a).motion(phis)
    _cmp(mo.s, x[:, 0], 1e-12, "s")
    _cmp(mo.ds, d[:, 0], 1e-12, "s'")
    _cmp(mo.dds, dd[:, 0], 1e-12, "s''")


# ------------------------------------------------------------------------------------------
# 4. instantaneous centres: point velocities from the centres vs the loop's velocities
# ------------------------------------------------------------------------------------------
@st.composite
def revolving(draw):
    fb = draw(any_fourbar())
    assume(fb.can_turn)
    return fb


@FEW
@given(revolving(), st.floats(-2, 2), st.floats(-2, 2))
def test_instant_centres_fourbar_velocities(fb, u, v):
    phis = np.linspace(0.05, 2 * np.pi - 0.05, 37)
    x, d, _ = my_fourbar(fb.crank, fb.coupler, fb.rocker, fb.ground, fb.assembly, phis)
    ic = ml.instant_centres(fb, phis)
    try:
        om_c, om_r = ic.angular_analog("coupler"), ic.angular_analog("rocker")
    except MechanismError:  # a centre at infinity or coincident: Kennedy is not defined there
        assume(False)
    scale = max(1.0, np.max(np.abs(d)))
    _cmp(om_c, d[:, 0], 1e-7 * scale, "ω_coupler/ω_crank from the centres")
    _cmp(om_r, d[:, 1], 1e-7 * scale, "ω_rocker/ω_crank from the centres")
    # a point fixed to the coupler at (u, v) in the coupler's frame (origin A, x along A→B)
    A = fb.crank * np.stack([np.cos(phis), np.sin(phis)], -1)
    e = np.stack([np.cos(x[:, 0]), np.sin(x[:, 0])], -1)
    n = np.stack([-e[:, 1], e[:, 0]], -1)
    P = A + u * e + v * n
    vP = fb.crank * np.stack([-np.sin(phis), np.cos(phis)], -1) + d[:, 0, None] * np.stack(
        [-(P - A)[:, 1], (P - A)[:, 0]], -1)
    _cmp(ic.velocity_analog("coupler", P), vP, 1e-7 * scale, "coupler point velocity from the centres")


@FEW
@given(any_slider())
def test_instant_centres_slider_crank(m):
    assume(m.can_turn)
    phis = np.linspace(0.05, 2 * np.pi - 0.05, 37)
    a, l, e, k = m.crank, m.rod, m.offset, m.assembly
    sn = (e - a * np.sin(phis[0])) / l
    th0 = np.arcsin(sn) if k > 0 else np.pi - np.arcsin(sn)
    _x, d, _ = slider_loop().follow((th0, a * np.cos(phis[0]) + l * np.cos(th0)), phis, (a, l, e))
    ic = ml.instant_centres(m, phis)
    try:
        out, om = ic.output_analog(), ic.angular_analog("rod")
    except MechanismError:
        assume(False)
    scale = max(1.0, np.max(np.abs(d)))
    _cmp(out, d[:, 1], 1e-7 * scale, "s' from the centres")
    _cmp(om, d[:, 0], 1e-7 * scale, "ω_rod from the centres")


@FEW
@given(L, L)
def test_instant_centres_slotted_and_sine(a, dist):
    assume(abs(a / dist - 1) > 0.05)
    phis = np.linspace(0.05, 2 * np.pi - 0.05, 37)
    _x, d, _ = slotted_loop().follow((0.0, a + dist), np.concatenate([[0.0], phis]), (a, dist))
    ic = ml.instant_centres(ml.SlottedLink(a, dist), phis)
    _cmp(ic.output_analog(), d[1:, 0], 1e-7 * max(1, np.max(np.abs(d))), "ψ' of the slotted link from the centres")
    icy = ml.instant_centres(ml.SineMechanism(a), phis)
    _cmp(icy.output_analog(), -a * np.sin(phis), 1e-9, "s' of the sine mechanism from the centres")


# ------------------------------------------------------------------------------------------
# 5. curved slots and the class-IV six-bar
# ------------------------------------------------------------------------------------------
@st.composite
def circle_slot_links(draw):
    a, dist = draw(L), draw(L)
    assume(abs(a / dist - 1) > 0.05)
    D = draw(st.floats(0.1, 6.0))
    ang = draw(st.floats(-np.pi, np.pi))
    rho = draw(st.floats(0.2, 8.0))
    # the circle's distances from B, [|D - ρ|, D + ρ], must overlap the pin's, [|a - d|, a + d]
    lo, hi = max(abs(D - rho), abs(a - dist)), min(D + rho, a + dist)
    assume(hi - lo > 0.1 * (a + dist))
    # no coincident extremes (the slot tangent to the pin's circle exactly at φ = 0 or π)
    ends = np.array([abs(D - rho), D + rho])
    assume(np.min(np.abs(ends[:, None] - np.array([abs(a - dist), a + dist])[None, :])) > 0.05 * (a + dist))
    side = draw(SIGN)
    return a, dist, (D * np.cos(ang), D * np.sin(ang)), rho, side


def _circle_point(S, cx, cy, rho, side):
    """The point of the circle at distance S from B on the side `side` of the line B→centre."""
    D = np.hypot(cx, cy)
    gam = np.arccos(np.clip((S * S + D * D - rho * rho) / (2 * S * D), -1, 1))
    th = np.arctan2(cy, cx) + side * gam
    return S * np.array([np.cos(th), np.sin(th)])


@FEW
@given(circle_slot_links())
def test_curved_slot_link_circle(case):
    """Full-turn and rocking circular slots: the pin's side of B→centre fixed by `start`."""
    a, dist, (cx, cy), rho, side = case
    D = np.hypot(cx, cy)
    pick = _circle_point(np.clip(a + dist, abs(D - rho) + 1e-9, D + rho - 1e-9), cx, cy, rho, side)
    m = ml.CurvedSlotLink(a, dist, ml.CircleSlot((cx, cy), rho), start=np.arctan2(pick[1] - cy, pick[0] - cx))
    for start, end in m.crank_ranges():
        w = end - start
        phis = np.linspace(0, 2 * np.pi, 61) if w >= 2 * np.pi else np.linspace(start + 0.03 * w, end - 0.03 * w, 61)
        S = np.hypot(a * np.cos(phis[0]) + dist, a * np.sin(phis[0]))
        p = _circle_point(S, cx, cy, rho, side)
        A0 = np.array([a * np.cos(phis[0]) + dist, a * np.sin(phis[0])])  # A - B
        x0 = (np.arctan2(A0[1], A0[0]) - np.arctan2(p[1], p[0]), np.arctan2(p[1] - cy, p[0] - cx))
        x, d, dd = circle_slot_loop().follow(x0, phis, (a, dist, cx, cy, rho))
        mo = m.motion(phis)
        scale = max(1.0, np.max(np.abs(d[:, 0])) ** 2, np.max(np.abs(dd[:, 0])))
        _cmp_angle(mo.psi, x[:, 0], 1e-8, "ψ (circular slot)")
        _cmp(mo.dpsi, d[:, 0], 1e-8 * scale, "ψ' (circular slot)")
        _cmp(mo.ddpsi, dd[:, 0], 1e-7 * scale, "ψ'' (circular slot)")


@SETTINGS
@given(L, L, st.floats(-1.5, 1.5), st.floats(-1.0, 1.0))
def test_curved_slot_link_parametric_spiral(a, dist, k, w):
    assume(abs(a / dist - 1) > 0.05)
    lo, hi = abs(a - dist) * 0.9, (a + dist) * 1.1
    mid = 0.5 * (lo + hi)
    f, df, ddf = spiral_funcs(k, mid, w)
    m = ml.CurvedSlotLink(a, dist, ml.ParametricSlot(f, df, ddf, lo, hi))
    phis = np.linspace(0, 2 * np.pi, 61)
    t0 = a + dist
    b0 = k * (t0 - mid) ** 2 + w * t0
    x, d, dd = spiral_slot_loop().follow((-b0, t0), phis, (a, dist, k, mid, w))
    mo = m.motion(phis)
    scale = max(1.0, np.max(np.abs(d[:, 0])) ** 2, np.max(np.abs(dd[:, 0])))
    _cmp_angle(mo.psi, x[:, 0], 1e-8, "ψ (spiral slot)")
    _cmp(mo.dpsi, d[:, 0], 1e-7 * scale, "ψ' (spiral slot)")
    _cmp(mo.ddpsi, dd[:, 0], 1e-6 * scale, "ψ'' (spiral slot)")


@SETTINGS
@given(L, st.floats(-3, 3), st.floats(-0.8, 0.8), st.floats(1.05, 3.0), SIGN)
def test_translating_circular_slot(a, x0, yfrac, over, side):
    y0 = yfrac * a
    rho = over * (a + abs(y0))  # every pin height a·sin φ is on the circle: full turn
    t_start = 0.0 if side > 0 else np.pi  # a point on the side the pin runs on
    m = ml.TranslatingCurvedSlot(a, ml.CircleSlot((x0, y0), rho), start=t_start)
    phis = np.linspace(0, 2 * np.pi, 61)
    t0 = np.arcsin(-y0 / rho)
    if side < 0:
        t0 = np.pi - t0
    x, d, dd = translating_circle_loop().follow((a - x0 - rho * np.cos(t0), t0), phis, (a, x0, y0, rho))
    mo = m.motion(phis)
    scale = max(1.0, np.max(np.abs(dd[:, 0])))
    _cmp(mo.s, x[:, 0], 1e-9, "s (translating circular slot)", scale=a + rho)
    _cmp(mo.ds, d[:, 0], 1e-8 * scale, "s'")
    _cmp(mo.dds, dd[:, 0], 1e-7 * scale, "s''")


@FEW
@given(st.floats(0.2, 1.5), st.floats(-0.8, 0.8), st.floats(-1.0, 1.0), st.floats(-3, 3))
def test_translating_parametric_slot(a, k, w, x0):
    """Slot x = x0 + k·y² + w·sin y (a graph over y): s = a cos φ - x(a sin φ) by hand; the
    library solves y_α(t) = a sin φ on the curve."""
    f = lambda t: np.stack([x0 + k * t**2 + w * np.sin(t), t], -1)  # noqa: E731
    df = lambda t: np.stack([2 * k * t + w * np.cos(t), np.ones_like(t)], -1)  # noqa: E731
    ddf = lambda t: np.stack([2 * k - w * np.sin(t), np.zeros_like(t)], -1)  # noqa: E731
    m = ml.TranslatingCurvedSlot(a, ml.ParametricSlot(f, df, ddf, -2 * a - 1, 2 * a + 1))
    phis = np.linspace(0, 2 * np.pi, 61)
    y, dy, ddy = a * np.sin(phis), a * np.cos(phis), -a * np.sin(phis)
    x, xy, xyy = x0 + k * y**2 + w * np.sin(y), 2 * k * y + w * np.cos(y), 2 * k - w * np.sin(y)
    mo = m.motion(phis)
    _cmp(mo.s, a * np.cos(phis) - x, 1e-9, "s", scale=a + abs(x0) + 4)
    _cmp(mo.ds, -a * np.sin(phis) - xy * dy, 1e-8, "s'")
    _cmp(mo.dds, -a * np.cos(phis) - (xyy * dy**2 + xy * ddy), 1e-7, "s''")


@FEW
@given(st.one_of(st.floats(0.2, 0.9), st.floats(1.15, 3.0)), st.floats(0.2, 1.2), st.floats(0.2, 1.0),
       st.sampled_from(["cubic", "quintic", "sextic"]))
def test_curved_slot_dwell_is_a_dwell(lam, p1, span, transition):
    """Through the designed slot: ψ constant on [φ1, φ2]; ψ(0) = 0 and ψ'(0) = ψ_K'(0) = λ/(1 + λ)
    (base law tan ψ_K = λ sin φ / (1 + λ cos φ)); C² at the joins; ψ(-φ) = ψ(φ) - 2ψ_K(φ) (slot passed
    twice at the same point); cubic: the dwell value is ψ_B = λφ1/(3(λ + 1)) (from ψ = ψ_B + a1(φ1 - φ)³,
    ψ(0) = 0, ψ'(0) = λ/(1 + λ))."""
    p2 = min(p1 + span, np.pi - 0.3)
    assume(p2 - p1 > 0.15)
    m = ml.curved_slot_dwell(lam, p1, p2, transition=transition)
    dw = m.motion(np.linspace(p1, p2, 31))
    assert np.ptp(dw.psi) < 1e-10 and np.max(np.abs(dw.dpsi)) < 1e-9 and np.max(np.abs(dw.ddpsi)) < 1e-8
    m0 = m.motion([0.0])
    assert abs(m0.psi[0]) < 1e-12 and abs(m0.dpsi[0] - lam / (1 + lam)) < 1e-9
    h = 1e-7
    for f in (p1, p2):
        lo, hi = m.motion([f - h]), m.motion([f + h])
        assert abs(lo.psi[0] - hi.psi[0]) < 1e-9 and abs(lo.dpsi[0] - hi.dpsi[0]) < 1e-7
        assert abs(lo.ddpsi[0] - hi.ddpsi[0]) < 1e-5
    q = np.linspace(0.05, np.pi - 0.05, 23)
    psiK = np.arctan2(lam * np.sin(q), 1 + lam * np.cos(q))
    _cmp(m.motion(-q).psi, m.motion(q).psi - 2 * psiK, 1e-9, "half-turn relation")
    if transition == "cubic":
        assert abs(dw.psi[0] - lam * p1 / (3 * (lam + 1))) < 1e-10


@FEW
@given(st.lists(st.floats(-0.04, 0.04), min_size=8, max_size=8))
def test_sixbar_iv_against_own_newton(eps):
    from mechlab.mechanisms.sixbar_iv import SixBarIV, example

    ex = example()
    f = [1 + e for e in eps]
    try:
        m = SixBarIV(crank=ex.crank * f[0], ground=ex.ground * f[1],
                     r_joint=(ex.r_joint[0] * f[2], ex.r_joint[1]), t_joint=(ex.t_joint[0] * f[3], ex.t_joint[1]),
                     link3=ex.link3 * f[4], link5=ex.link5 * f[5], qp=ex.qp * f[6],
                     coupler_point=(ex.coupler_point[0] * f[7], ex.coupler_point[1]),
                     inner_assembly=ex.inner_assembly, start=ex.start)
    except MechanismError:
        assume(False)
    p = (m.crank, m.ground, *m.r_joint, *m.t_joint, m.link3, m.link5, m.qp, *m.coupler_point)
    phis = np.pi + np.linspace(0, 2 * np.pi, 73)
    mo0 = m.motion(phis[:1])
    Q, P = mo0.points["Q"].p[0], mo0.points["P"].p[0]
    x_start = np.array([np.arctan2(*(P - Q)[::-1]), mo0.psi[0]])
    # the library's start is a root of the independent loop equations
    assert np.max(np.abs(sixbar_loop().F(x_start, phis[0], p))) < 1e-10
    x, d, dd = sixbar_loop().follow(x_start, phis, p)
    mo = m.motion(phis)
    scale = max(1.0, np.max(np.abs(dd[:, 1])))
    _cmp_angle(mo.psi, x[:, 1], 1e-8, "ψ of SixBarIV")
    _cmp(mo.dpsi, d[:, 1], 1e-8 * scale, "ψ' of SixBarIV")
    _cmp(mo.ddpsi, dd[:, 1], 1e-7 * scale, "ψ'' of SixBarIV")
    _cmp(mo.psi[-1] - mo.psi[0], x[-1, 1] - x[0, 1], 1e-8, "ψ gained over one turn")


@FEW
@given(st.floats(0.2, 5.0), st.floats(0.2, 5.0))
def test_antiparallelogram_crossed_branch(a, g):
    """The crossed branch: on each half turn, the four-bar root with ψ ≠ φ (not the parallelogram)."""
    assume(abs(a - g) > 0.05 * max(a, g))
    m = ml.Antiparallelogram(a, g)
    for lo, hi in ((0.05, np.pi - 0.05), (np.pi + 0.05, 2 * np.pi - 0.05)):
        phis = np.linspace(lo, hi, 31)
        sols = [my_fourbar(a, g, a, g, k, phis) for k in (1, -1)]
        crossed = [s_ for s_ in sols if np.all(np.abs(wrap(s_[0][:, 1] - phis)) > 1e-6)]
        assert len(crossed) == 1
        x, d, dd = crossed[0]
        mo = m.motion(phis)
        scale = max(1.0, np.max(np.abs(dd[:, 1])))
        _cmp(wrap(mo.psi - x[:, 1]), 0 * phis, 1e-9, "antiparallelogram ψ")
        _cmp(mo.dpsi, d[:, 1], 1e-8 * scale, "antiparallelogram ψ'")
        _cmp(mo.ddpsi, dd[:, 1], 1e-7 * scale, "antiparallelogram ψ''")


# ------------------------------------------------------------------------------------------
# 5b. long inputs, many turns, unsorted angles, documented mirror relations
# ------------------------------------------------------------------------------------------
@FEW
@given(revolving())
def test_fourbar_long_grid_many_turns_unsorted(fb):
    a, c, r, g, k = fb.crank, fb.coupler, fb.rocker, fb.ground, fb.assembly
    # long uniform grid over three turns, backwards from 2π: blocks, threads and the fast exp(iφ) table
    phis = np.linspace(2 * np.pi, -4 * np.pi, 60001)
    mo = fb.motion(phis)
    idx = np.arange(0, 60001, 1000)
    x, d, dd = my_fourbar(a, c, r, g, k, phis[idx])
    scale = max(1.0, np.max(np.abs(dd[:, 1])))
    _cmp_angle(mo.psi[idx], x[:, 1], 1e-9, "ψ on a long grid")
    _cmp(mo.dpsi[idx], d[:, 1], 1e-8 * scale, "ψ' on a long grid")
    _cmp(mo.ddpsi[idx], dd[:, 1], 1e-7 * scale, "ψ'' on a long grid")
    step = np.max(np.abs(np.diff(mo.psi)))
    assert step <= 1.01 * np.max(np.abs(mo.dpsi)) * abs(phis[1] - phis[0])  # no branch jump anywhere
    # unsorted input gives the same numbers per angle
    perm = np.random.default_rng(1).permutation(idx)
    _cmp(fb.motion(phis[perm]).psi, mo.psi[perm], 1e-12, "unsorted ψ")
    # documented mirror relation: ψ₋(φ) = -ψ₊(-φ), ψ'₋(φ) = ψ'₊(-φ), ψ''₋(φ) = -ψ''₊(-φ)
    q = np.linspace(0, 2 * np.pi, 37)
    p_, m_ = ml.FourBar(a, c, r, g, 1).motion(q), ml.FourBar(a, c, r, g, -1).motion(-q)
    _cmp(wrap(p_.psi + m_.psi), 0 * q, 1e-12, "mirror ψ")
    _cmp(p_.dpsi, m_.dpsi, 1e-12 * scale, "mirror ψ'")
    _cmp(p_.ddpsi, -m_.ddpsi, 1e-11 * scale, "mirror ψ''")


@FEW
@given(any_slider())
def test_slider_crank_documented_mirror(m):
    """s₋(φ; e) = -s₊(π - φ; e) (slider_crank module docstring)."""
    other = ml.SliderCrank(m.crank, m.rod, m.offset, -m.assembly)
    start, end = m.crank_ranges()[0]
    w = end - start
    q = np.linspace(start + 0.03 * w, end - 0.03 * w, 37) if w < 2 * np.pi else np.linspace(0, 2 * np.pi, 37)
    _cmp(m.motion(q).s, -other.motion(np.pi - q).s, 1e-12, "mirror s", scale=m.crank + m.rod)


@FEW
@given(revolving(), st.floats(-2, 2), st.floats(-2, 2))
def test_instant_centres_kennedy_equals_velocity_method(fb, u, v):
    phis = np.linspace(0.05, 2 * np.pi - 0.05, 37)
    try:
        k1 = ml.instant_centres(fb, phis)
        k2 = ml.instant_centres(fb, phis, method="velocity")
    except MechanismError:
        assume(False)
    for key, c1 in k1.centres.items():
        c2 = k2.centres[key]
        both = c1.finite & c2.finite
        assert np.array_equal(c1.finite, c2.finite) or not np.any(~both & (c1.finite | c2.finite))
        if both.any():
            sc = max(1.0, np.max(np.abs(c1.xy[both])))
            _cmp(c1.xy[both], c2.xy[both], 1e-7 * sc, f"centre {key}")


# ------------------------------------------------------------------------------------------
# 6. Geneva
# ------------------------------------------------------------------------------------------
@functools.cache
def geneva_angle(kappa):
    """Angle of W→A as a sympy function of σ (crank angle from mid-motion), λ = a/C, C = 1:
    external pin A = λ(cos σ, sin σ), internal A = -λ(cos σ, sin σ) (φ = σ + π, φ = 0 mid-dwell)."""
    s, lam = sp.symbols("sigma lam")
    sgn = 1 if kappa < 0 else -1
    b = sp.atan2(sgn * lam * sp.sin(s), sgn * lam * sp.cos(s) - 1)
    return [sp.lambdify((s, lam), e, "numpy") for e in (b, sp.diff(b, s), sp.diff(b, s, 2))]


@pytest.mark.parametrize("cls, kappa", [(ml.ExternalGeneva, -1), (ml.InternalGeneva, 1)])
@settings(max_examples=40, deadline=None)
@given(z=st.integers(3, 16), C=st.floats(0.3, 5.0))
def test_planar_geneva_from_the_pin_geometry(cls, kappa, z, C):
    m = cls(z, C)
    lam = np.sin(np.pi / z)
    a = C * lam
    # engagement: radial entry, OA ⟂ WA, found by brentq on the dot product (not from π/2 ± π/z)
    sgn = 1 if kappa < 0 else -1

    def radial(s):
        A = sgn * a * np.array([np.cos(s), np.sin(s)])
        return float(np.dot(A, A - np.array([C, 0.0])))

    s0 = brentq(radial, 1e-9, np.pi - 1e-9)
    assert abs(s0 - m.engagement_half_angle) < 1e-10
    b, db, ddb = geneva_angle(kappa)
    # interior angles: at σ = ±σ0 exactly ψ'' jumps (entry/exit), its value there is a convention
    sig = np.linspace(-s0, s0, 201)[1:-1]
    # wheel angle = polar angle of the pin about W, measured from its value at entry
    psi = wrap(b(sig, lam) - b(-s0, lam))
    mo = m.motion(sig + np.pi)
    _cmp(mo.psi, psi, 1e-11, "Geneva ψ from atan2 of the pin")
    _cmp(mo.dpsi, db(sig, lam), 1e-10, "Geneva ψ'")
    _cmp(mo.ddpsi, ddb(sig, lam), 1e-9 * max(1, np.max(np.abs(ddb(sig, lam)))), "Geneva ψ''")
    # index 2π/z per turn, signed; locked (analogs 0) outside the engagement
    assert abs(wrap(b(s0, lam) - b(-s0, lam)) - kappa * 2 * np.pi / z) < 1e-10
    assert abs(m.motion([2 * np.pi]).psi[0] - kappa * 2 * np.pi / z) < 1e-12
    lock = m.motion(np.linspace(-(np.pi - s0) + 1e-6, np.pi - s0 - 1e-6, 9))
    assert np.all(lock.psi == 0) and np.all(lock.dpsi == 0) and np.all(lock.ddpsi == 0)
    assert abs(m.dwell_fraction - (1 - s0 / np.pi)) < 1e-12
    assert abs(m.dwell_fraction - (0.5 - kappa / z)) < 1e-12
    # peak velocity ratio at mid-motion λ/(1 + κλ) (derived: β'(0) = κλ(1 + κλ)/(1 + κλ)²)
    assert abs(m.max_velocity() - lam / (1 + kappa * lam)) < 1e-12
    fine = np.linspace(-s0, s0, 20001)
    assert abs(np.max(np.abs(db(fine, lam))) - m.max_velocity()) < 1e-9
    # peak acceleration: brute maximum of |β''| refined by a bounded search
    i = int(np.argmax(np.abs(ddb(fine, lam))))
    lo, hi = fine[max(i - 1, 0)], fine[min(i + 1, len(fine) - 1)]
    best = -minimize_scalar(lambda s: -abs(ddb(s, lam)), bounds=(lo, hi), method="bounded",
                            options={"xatol": 1e-12}).fun if hi > lo else abs(ddb(fine[i], lam))
    best = max(best, abs(ddb(fine[i], lam)))
    assert abs(m.max_acceleration() - best) < 1e-8 * max(1, best)
    # the jump at entry: |ψ''| = tan(π/z)
    assert abs(abs(ddb(-s0, lam)) - np.tan(np.pi / z)) < 1e-10
    assert abs(m.entry_acceleration() - np.tan(np.pi / z)) < 1e-12
    cf = m.closed_form(sig)
    _cmp(cf.theta, wrap(b(sig, lam) - np.pi), 1e-11, "closed_form β")
    _cmp(cf.d, db(sig, lam), 1e-11, "closed_form β'")
    _cmp(cf.dd, ddb(sig, lam), 1e-10 * max(1, np.max(np.abs(cf.dd))), "closed_form β''")
    imp = m.impacts()
    _cmp([imp.entry_velocity_jump, imp.exit_velocity_jump], [db(-s0, lam), -db(s0, lam)], 1e-12, "velocity jumps")
    _cmp([imp.entry_acceleration_jump, imp.exit_acceleration_jump], [ddb(-s0, lam), -ddb(s0, lam)], 1e-10,
         "acceleration jumps")
    assert imp.kind == "soft"
    # over several turns, forwards and backwards: ψ accumulates κ·2π/z per turn, continuously
    many = np.linspace(-3 * 2 * np.pi, 3 * 2 * np.pi, 6 * 400 + 1)
    mo = m.motion(many)
    assert np.max(np.abs(np.diff(mo.psi))) < 2 * np.max(np.abs(db(fine, lam))) * (many[1] - many[0])
    assert abs(mo.psi[-1] - mo.psi[0] - 6 * kappa * 2 * np.pi / z) < 1e-10


@FEW
@given(st.floats(20.0, 80.0), st.floats(0.0, 0.95), st.integers(3, 12))
def test_spherical_geneva_from_3d_geometry(R, kfrac, z):
    """Pin axis through O1 = (0, 0, -e) on the cone about x whose generatrix passes through the entry
    point A0 = R(cos β0, -sin β0, 0) on the equator (β0 = π/z); contact point A on the sphere |A| = R
    by the quadratic; wheel angle = azimuth of A, measured from entry (ψ = β + β0)."""
    e = kfrac * R
    try:
        m = ml.SphericalGeneva(R, e, z, pin_diameter=0.05 * R)
    except MechanismError:  # the pin does not fit the slot's working arc (a design limit)
        assume(False)
    b0 = np.pi / z
    v0 = np.array([R * np.cos(b0), R * np.sin(b0), e])       # A0 - O1 (at α = α0, β = +β0)
    cone = np.arccos(v0[0] / np.linalg.norm(v0))
    a0 = np.arctan2(v0[1], v0[2])
    assert abs(a0 - m.alpha0) < 1e-12 and abs(cone - m.cone_angle) < 1e-12
    al = np.linspace(-a0, a0, 41)[1:-1]
    d = np.stack([np.full_like(al, np.cos(cone)), np.sin(cone) * np.sin(al), np.sin(cone) * np.cos(al)], -1)
    O1 = np.array([0.0, 0.0, -e])
    od = d @ O1
    u = -od + np.sqrt(od**2 - e * e + R * R)
    A = O1 + u[:, None] * d
    assert np.allclose(np.linalg.norm(A, axis=1), R, atol=1e-12)
    beta = np.arctan2(A[:, 1], A[:, 0])
    mo = m.motion(al + np.pi)
    _cmp(mo.psi, beta + b0, 1e-11, "spherical Geneva ψ")
    # analog by sympy from the same construction (β = atan2(sin c sin α, cos c), u cancels)
    a_s = sp.Symbol("a")
    bexpr = sp.atan2(sp.sin(cone) * sp.sin(a_s), sp.cos(cone))
    db = sp.lambdify(a_s, sp.diff(bexpr, a_s))(al)
    _cmp(mo.dpsi, db, 1e-11, "spherical Geneva ψ'")


def test_external_geneva_classical_table():
    """Classical table of the external Geneva (e.g. Artobolevsky / Kozhevnikov): z, ω2max/ω1,
    ε2max/ω1², and the closed form cos σm = √(((1+λ²)/4λ)² + 2) - (1+λ²)/4λ re-derived."""
    table = {3: (6.464, 31.44), 4: (2.414, 5.409), 5: (1.43, 2.299), 6: (1.000, 1.350), 8: (0.620, 0.700)}
    for z, (w, e) in table.items():
        m = ml.ExternalGeneva(z, 1.0)
        lam = np.sin(np.pi / z)
        q = (1 + lam**2) / (4 * lam)
        sm = np.arccos(np.sqrt(q * q + 2) - q)
        assert abs(m.acceleration_peak_sigma() - sm) < 1e-12
        assert abs(m.max_velocity() - w) < 5e-3 * w
        assert abs(m.max_acceleration() - e) < 2e-3 * e, (z, m.max_acceleration())


# ------------------------------------------------------------------------------------------
# 7. Chebyshev's lambda mechanism
# ------------------------------------------------------------------------------------------
@st.composite
def lambdas(draw):
    a = draw(st.floats(0.2, 1.7))
    r = draw(st.floats(0.05, 1.0)) * min(a, 2 - a) * 0.95
    delta = draw(st.floats(0.2, 2 * np.pi - 0.2))
    return ml.LambdaMechanism(r, a, delta, draw(SIGN))


def _rot(th, v):
    c, s = np.cos(th), np.sin(th)
    return np.stack([c * v[:, 0] - s * v[:, 1], s * v[:, 0] + c * v[:, 1]], -1)


@FEW
@given(lambdas())
def test_lambda_coupler_point_from_own_fourbar(m):
    phis = np.linspace(0, 2 * np.pi, 61)
    x, d, _ = my_fourbar(m.r, 1.0, 1.0, m.a, m.assembly, phis)
    A = m.r * np.stack([np.cos(phis), np.sin(phis)], -1)
    B = A + np.stack([np.cos(x[:, 0]), np.sin(x[:, 0])], -1)
    D = B + _rot(m.assembly * m.delta, A - B)  # A turned about B by δ (the docstring's definition)
    mo = m.motion(phis)
    _cmp(mo.points["D"].p, D, 1e-9, "D")
    _cmp(m.coupler_point(phis), D, 1e-9, "D by the closed form (*)")
    # D' = B' + Rot(δ)(A' - B') from the independent analogs (B' = θ'·perp(B - A) + A')
    dA = m.r * np.stack([-np.sin(phis), np.cos(phis)], -1)
    dB = dA + d[:, 0, None] * np.stack([-(B - A)[:, 1], (B - A)[:, 0]], -1)
    _cmp(mo.points["D"].d, dB + _rot(m.assembly * m.delta, dA - dB), 1e-8 * max(1, np.max(np.abs(d))), "D'")
    # D is equidistant (1) from B; the curve is symmetric about the axis through C at assembly·δ/2
    e = np.array([np.cos(m.axis_angle), np.sin(m.axis_angle)])
    Dm = my_fourbar(m.r, 1.0, 1.0, m.a, m.assembly, 2 * np.pi - phis)
    Bm = (m.r * np.stack([np.cos(2 * np.pi - phis), np.sin(2 * np.pi - phis)], -1)
          + np.stack([np.cos(Dm[0][:, 0]), np.sin(Dm[0][:, 0])], -1))
    Am = m.r * np.stack([np.cos(2 * np.pi - phis), np.sin(2 * np.pi - phis)], -1)
    Dmir = Bm + _rot(m.assembly * m.delta, Am - Bm)
    w = D - m.C
    refl = 2 * (w @ e)[:, None] * e - w + m.C  # D mirrored in the axis
    _cmp(refl, Dmir, 1e-9, "symmetry of the coupler curve about the axis")


def _my_D(r, a, delta, phis):
    x, _, _ = my_fourbar(r, 1.0, 1.0, a, 1, phis)
    A = r * np.stack([np.cos(phis), np.sin(phis)], -1)
    B = A + np.stack([np.cos(x[:, 0]), np.sin(x[:, 0])], -1)
    return B + _rot(delta, A - B)


@settings(max_examples=6, deadline=None)
@given(st.floats(110, 180), st.floats(0.7, 1.0), st.floats(60, 180))
def test_circle_guiding_is_equal_ripple_on_own_solve(delta_deg, a, dwell_deg):
    """circle_guiding's design checked on D from the independent four-bar: over the dwell
    |D − Q| stays in [min(R0, R1), max(R0, R1)], equals R0 at t = 0 and ±t2, R1 at ±t3 and ±α."""
    try:
        g = ml.circle_guiding(np.radians(delta_deg), a, np.radians(dwell_deg))
    except MechanismError:
        assume(False)
    al = g.dwell / 2
    t = np.concatenate([np.linspace(-al, al, 401), [0.0, g.t2, -g.t2, g.t3, -g.t3]])
    D = _my_D(g.r, g.a, g.delta, np.pi + t)
    rho = np.hypot(*(D - g.centre).T)
    lo, hi = min(g.R0, g.R1), max(g.R0, g.R1)
    tol = 1e-9 + 1e-6 * g.E
    assert rho[:401].min() > lo - tol and rho[:401].max() < hi + tol
    _cmp(rho[[0, 400, 404, 405]], g.R1, tol, "ρ = R1 at ±α, ±t3")
    _cmp(rho[[401, 402, 403]], g.R0, tol, "ρ = R0 at 0, ±t2")


def test_classic_chebyshev_lambda_straight_line():
    """1 : 2 : 2.5 : 5 (crank : ground : links : coupler point), in units of the 2.5 links.

    Hand derivation (δ = π, D = 2B - A): at φ = π, A = (-0.4, 0), B = (0.2, 0.8), D = (0.8, 1.6);
    at φ = π/2, A = (0, 0.4), B = (0.8, 1.0), D = (1.6, 1.6); by symmetry D(3π/2) = (0, 1.6).
    So D touches y = 1.6 three times with zero slope of y at all three (a double contact),
    along a stroke of 1.6 = 4 crank lengths. The deviation over the stroke is found here by
    a bounded search of y(φ) from the independent four-bar solve: 0.0039015 (0.0097537 crank
    lengths, 0.24 % of the stroke; the literature's "within 1 %" for the lambda linkage).
    """
    from mechlab.mechanisms.lambda_mechanism import classic_lambda

    m = classic_lambda()
    assert m.r == 0.4 and m.a == 0.8 and m.delta == np.pi
    phis = np.array([np.pi / 2, np.pi, 3 * np.pi / 2])
    D = m.motion(phis).points["D"]
    _cmp(D.p, [[1.6, 1.6], [0.8, 1.6], [0.0, 1.6]], 1e-12, "D at π/2, π, 3π/2")
    _cmp(D.d[:, 1], [0, 0, 0], 1e-12, "y'(D) at π/2, π, 3π/2")

    def y_mine(ph):
        x, _, _ = my_fourbar(0.4, 1.0, 1.0, 0.8, 1, np.array([ph]))
        B = 0.4 * np.array([np.cos(ph), np.sin(ph)]) + np.array([np.cos(x[0, 0]), np.sin(x[0, 0])])
        return 2 * B[1] - 0.4 * np.sin(ph)

    dev = []
    for lo, hi in ((np.pi / 2, np.pi), (np.pi, 3 * np.pi / 2)):
        r = minimize_scalar(lambda p: -(y_mine(p) - 1.6), bounds=(lo + 1e-3, hi - 1e-3), method="bounded",
                            options={"xatol": 1e-10})
        dev.append(-r.fun)
    assert abs(dev[0] - dev[1]) < 1e-9
    assert abs(dev[0] - 0.0039015) < 1e-6
    dense = m.motion(np.linspace(np.pi / 2, 3 * np.pi / 2, 4001)).points["D"].p[:, 1] - 1.6
    assert dense.min() > -1e-12 and abs(dense.max() - dev[0]) < 1e-7
    assert dev[0] / 1.6 < 0.01
    # straight_guiding(δ = π, a = 0.8, 2α = π) finds the classic r = 0.4 with ripple E = dev/2
    sg = ml.straight_guiding(np.pi, 0.8, np.pi)
    assert abs(sg.r - 0.4) < 1e-9 and abs(sg.E - dev[0] / 2) < 1e-7 and abs(sg.Y - (1.6 + dev[0] / 2)) < 1e-7


# ------------------------------------------------------------------------------------------
# 7b. the six-bars on the lambda mechanism: outputs from D of the independent four-bar
# ------------------------------------------------------------------------------------------
H = 1e-3  # longest step of the five-point differences for the outputs' analogs


def _outputs_at_steps(six, phis, output, h):
    """The output from the independent D at φ + k·h, k = −2…2 (continuation over that list);
    returns the value and the five-point differences for the first and second analogs (error O(h⁴))."""
    grid = (phis[:, None] + h[:, None] * np.arange(-2, 3)).ravel()
    D = _my_D(six.r, six.a, six.delta, grid)
    y = output(D).reshape(len(phis), 5)
    if np.ptp(y, axis=1).max() > np.pi:  # an angle wrapped inside a stencil
        y = np.unwrap(y, axis=1)
    d1 = (-y[:, 4] + 8 * y[:, 3] - 8 * y[:, 1] + y[:, 0]) / (12 * h)
    d2 = (-y[:, 4] + 16 * y[:, 3] - 30 * y[:, 2] + 16 * y[:, 1] - y[:, 0]) / (12 * h ** 2)
    return y[:, 2], d1, d2


def _check_sixbar(six, output, angular, phis=None):
    phis = np.linspace(0, 2 * np.pi, 25)[:-1] + 0.0123 if phis is None else phis
    mo = six.motion(phis)
    lib = (mo.psi, mo.dpsi, mo.ddpsi) if angular else (mo.s, mo.ds, mo.dds)
    # a fast output (a pin grazing the slotted link's pivot) needs a shorter step: ≤ 0.004 of output per step
    h = np.minimum(H, 0.004 / np.maximum(1.0, np.abs(lib[1])))
    y, dy, ddy = _outputs_at_steps(six, phis, lambda D: output(D, np.repeat(lib[0], 5)), h)
    if angular:
        _cmp(wrap(lib[0] - y), 0.0, 1e-9, "output angle")
    else:
        _cmp(lib[0], y, 1e-9, "output position")
    _cmp(lib[1], dy, 1e-5, "first analog", scale=np.max(np.abs(dy)))
    _cmp(lib[2], ddy, 1e-4, "second analog", scale=np.max(np.abs(ddy)))


def _circle_meet(P1, r1, P2, r2, side):
    """The point at r1 from P1 and r2 from P2, on the left (+1) or right (−1) of P1→P2."""
    d = P2 - P1
    L = np.hypot(*d.T)[:, None]
    along = (r1 ** 2 - r2 ** 2 + L ** 2) / (2 * L)
    h = np.sqrt(r1 ** 2 - along ** 2)
    u = d / L
    return P1 + along * u + side * h * np.stack([-u[:, 1], u[:, 0]], -1)


@settings(max_examples=8, deadline=None, suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much])
@given(st.floats(130, 180), st.floats(0.7, 1.0), st.floats(80, 160), st.floats(0.7, 1.4), st.floats(10, 40),
       st.sampled_from([1, -1]))
def test_mchv1_output_from_own_dyad(delta_deg, a, dwell_deg, K, swing_deg, side):
    try:
        six = ml.mchv1(ml.circle_guiding(np.radians(delta_deg), a, np.radians(dwell_deg), minimax=False), K,
                       np.radians(swing_deg), side=side, mu_min=None)
    except MechanismError:
        assume(False)
    F = np.array([six.fx, six.fy])

    def rocker_angle(D, _):
        # E on the left of D→F for assembly +1 (the class docstring)
        E = _circle_meet(D, six.rod, np.broadcast_to(F, D.shape), six.rocker, six.assembly)
        return np.arctan2(E[:, 1] - F[1], E[:, 0] - F[0])

    _check_sixbar(six, rocker_angle, angular=True)


def _slot_angle(six):
    """The slot's direction ψ from the class docstring's u × (D − P) = e: |D − P|·sin(θ_w − ψ) = e,
    ψ = θ_w − asin(e/ρ) or θ_w − π + asin(e/ρ) (the two lines through D tangent to the circle of
    radius |e| about P); the one nearer the library's ψ — the other has the slot the other way round."""
    P, e = np.array([six.px, six.py]), six.offset

    def angle(D, psi_lib):
        w = D - P
        th, rho = np.arctan2(w[:, 1], w[:, 0]), np.hypot(*w.T)
        c1, c2 = th - np.arcsin(e / rho), th - np.pi + np.arcsin(e / rho)
        pick = np.abs(wrap(c1 - psi_lib)) <= np.abs(wrap(c2 - psi_lib))
        return np.where(pick, c1, c2)

    return angle


@settings(max_examples=6, deadline=None, suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much])
@given(st.floats(150, 180), st.floats(0.75, 0.9), st.sampled_from(["oscillating", "half", "full"]),
       st.floats(0.02, 0.3))
def test_mchv3_slot_angle_from_own_slot_line(delta_deg, a, kind, x):
    try:
        g = ml.straight_guiding(np.radians(delta_deg), a, np.pi)
        six = {"oscillating": lambda: ml.synthesis.lambda_sixbars.mchv3_oscillating(g, x),
               "half": lambda: ml.synthesis.lambda_sixbars.mchv3_half_turn(g),
               "full": lambda: ml.mchv3_full_turn(g, x / 5, 0.05)}[kind]()
    except MechanismError:
        assume(False)
    _check_sixbar(six, _slot_angle(six), angular=True)


@settings(max_examples=6, deadline=None, suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much])
@given(st.floats(130, 180), st.floats(0.7, 1.0), st.floats(80, 160), st.floats(0.6, 1.6))
def test_mchv2_slider_from_own_rrp(delta_deg, a, dwell_deg, K):
    try:
        six = ml.mchv2(ml.circle_guiding(np.radians(delta_deg), a, np.radians(dwell_deg), minimax=False), K,
                       mu_min=None)
    except MechanismError:
        assume(False)
    Q, u = np.array([six.qx, six.qy]), np.array([np.cos(six.theta), np.sin(six.theta)])

    def slider(D, s_lib):
        w = D - Q
        along, off = w @ u, cross2(u, w)
        root = np.sqrt(six.rod ** 2 - off ** 2)
        # E = Q + s·u at distance R from D: two roots; the library keeps one branch over the turn
        s1, s2 = along + root, along - root
        return np.where(np.abs(s1 - s_lib) <= np.abs(s2 - s_lib), s1, s2)

    _check_sixbar(six, slider, angular=False)
    mo = six.motion(np.linspace(0, 2 * np.pi, 2001))
    assert np.all(np.abs(np.hypot(*(mo.points["E"].p - mo.points["D"].p).T) - six.rod) < 1e-12)


@settings(max_examples=6, deadline=None)
@given(st.floats(150, 180), st.floats(0.75, 0.9), st.floats(-50, 50))
def test_mchv5_output_from_own_projection(delta_deg, a, gamma_deg):
    try:
        six = ml.mchv5(ml.straight_guiding(np.radians(delta_deg), a, np.pi), guide_angle=np.radians(gamma_deg))
    except MechanismError:
        assume(False)
    P = np.array([six.px, six.py])
    v, w = np.array([np.cos(six.slot), np.sin(six.slot)]), np.array([np.cos(six.guide), np.sin(six.guide)])

    def position(D, _):  # the slot line through P + s·w, direction v, contains D
        return cross2(v, D - P) / cross2(v, w)

    _check_sixbar(six, position, angular=False)


# ------------------------------------------------------------------------------------------
# 8. error paths: invalid input raises a MechanismError subclass with a message, never NaN
# ------------------------------------------------------------------------------------------
BAD = [0.0, -1.0, -1e-300, float("nan"), float("inf"), -float("inf"), "x", None]
FACTORIES = {
    "FourBar": (lambda v, i: ml.FourBar(*[v if k == i else x for k, x in enumerate((1.0, 3.0, 3.0, 4.0))]), 4),
    "SliderCrank": (lambda v, i: ml.SliderCrank(*[v if k == i else x for k, x in enumerate((1.0, 3.0))]), 2),
    "SlottedLink": (lambda v, i: ml.SlottedLink(*[v if k == i else x for k, x in enumerate((0.5, 1.0))]), 2),
    "SineMechanism": (lambda v, i: ml.SineMechanism(v), 1),
    "ExternalGeneva.C": (lambda v, i: ml.ExternalGeneva(4, v), 1),
    "InternalGeneva.C": (lambda v, i: ml.InternalGeneva(6, v), 1),
    "LambdaMechanism": (lambda v, i: ml.LambdaMechanism(*[v if k == i else x for k, x in
                                                           enumerate((0.4, 0.8, np.pi))]), 3),
    "CircleSlot.radius": (lambda v, i: ml.CircleSlot((0.3, 0.5), v), 1),
}


@pytest.mark.parametrize("name", sorted(FACTORIES))
@pytest.mark.parametrize("bad", BAD, ids=repr)
def test_bad_dimension_raises_named_mechanism_error(name, bad):
    make, nargs = FACTORIES[name]
    for i in range(nargs):
        if name == "LambdaMechanism" and i == 2 and bad in (-1.0, -1e-300):
            continue  # δ < 0 is a different check; covered below
        with pytest.raises(MechanismError) as exc:
            make(bad, i)
        assert str(exc.value)


BAD_VALUES = st.one_of(st.floats(max_value=0.0, allow_nan=False), st.just(float("nan")), st.just(float("inf")),
                       st.just(-float("inf")), st.text(max_size=3), st.none())


@settings(max_examples=60, deadline=None)
@given(st.sampled_from(sorted(FACTORIES)), st.integers(0, 3), BAD_VALUES)
def test_random_bad_dimension(name, i, bad):
    make, nargs = FACTORIES[name]
    i = i % nargs
    assume(not (name == "LambdaMechanism" and i == 2 and isinstance(bad, float) and bad < 0))
    with pytest.raises(MechanismError):
        make(bad, i)


@pytest.mark.parametrize("z", [2, 1, 0, -3, 3.5, float("nan"), float("inf"), "four", None])
def test_geneva_slot_count_errors(z):
    for cls in (ml.ExternalGeneva, ml.InternalGeneva):
        with pytest.raises(ml.SlotCountError):
            cls(z, 1.0)


@SETTINGS
@given(L, L, L, L)
def test_non_assemblable_fourbar_is_refused_or_every_reachable_angle_is_finite(a, c, r, g):
    # change-point linkages (s + l = p + q) included: they rock between dead points (audit F1-F2)
    # the closure exists somewhere iff some |AE| ∈ [|g - a|, g + a] meets [|c - r|, c + r]
    possible = max(abs(g - a), abs(c - r)) < min(g + a, c + r)
    try:
        fb = ml.FourBar(a, c, r, g)
    except MechanismError:
        assert not possible or min(g + a, c + r) - max(abs(g - a), abs(c - r)) < 1e-9
        return
    assert possible
    mo = fb.motion(fb.cycle(41))
    for arr in (mo.psi, mo.dpsi, mo.ddpsi, mo.transmission):
        assert np.all(np.isfinite(arr))
    # an angle outside the ranges is refused by name, with numbers
    if not fb.can_turn:
        _s0, _e0 = fb.crank_ranges()[0]
        out = [p for p in np.linspace(0, 2 * np.pi, 73)
               if not any(0 < np.mod(p - b, 2 * np.pi) < e - b for b, e in fb.crank_ranges())]
        if out:
            with pytest.raises(ml.AssemblyError, match="cannot assemble"):
                fb.motion(out[:1])
        with pytest.raises(ml.RotationError, match="cannot turn fully"):
            fb.turn()


@SETTINGS
@given(L, L, st.floats(-8, 8))
def test_non_assemblable_slider_crank(a, l, e):
    try:
        m = ml.SliderCrank(a, l, e)
    except MechanismError:
        assert abs(e) - a >= l - 1e-12
        return
    assert abs(e) - a < l
    mo = m.motion(m.cycle(41))
    assert np.all(np.isfinite(mo.s)) and np.all(np.isfinite(mo.ds)) and np.all(np.isfinite(mo.dds))


ERROR_CASES = {
    "circle slot centred on the pivot": lambda: ml.CurvedSlotLink(0.5, 1, ml.CircleSlot((0, 0), 1.0)),
    "circle centre nan": lambda: ml.CircleSlot((np.nan, 0), 1.0),
    "slot is a string": lambda: ml.CurvedSlotLink(0.5, 1, "circle"),
    "parametric slot returns NaN": lambda: ml.CurvedSlotLink(0.5, 1, ml.ParametricSlot(
        lambda t: np.full((len(t), 2), np.nan), lambda t: np.ones((len(t), 2)), lambda t: np.ones((len(t), 2)), 0, 1)),
    "parametric slot wrong shape": lambda: ml.CurvedSlotLink(0.5, 1, ml.ParametricSlot(
        lambda t: t, lambda t: t, lambda t: t, 0, 1)),
    "parametric t1 < t0": lambda: ml.ParametricSlot(lambda t: t, lambda t: t, lambda t: t, 1, 0),
    "sampled slot, 3 points": lambda: ml.SampledSlot(np.ones((3, 2))),
    "sampled slot, repeated point": lambda: ml.SampledSlot(np.array([[0, 0], [0, 0], [1, 1], [2, 2.0]])),
    "translating circle out of reach": lambda: ml.TranslatingCurvedSlot(1, ml.CircleSlot((0.0, 5.0), 1.0)),
    "curved slot, unreachable angle": lambda: ml.CurvedSlotLink(0.5, 1, ml.CircleSlot((0.3, 0.5), 0.6)).motion([0.0]),
    "slider-crank, unreachable angle": lambda: ml.SliderCrank(1, 1.2, 0.5).motion([-np.pi / 2]),
    "slider-crank, turn() of a rocking crank": lambda: ml.SliderCrank(1, 1.2, 0.5).turn(),
    "slider-crank out of reach": lambda: ml.SliderCrank(1, 1, 2.5),
    "slotted link, λ = 1": lambda: ml.SlottedLink(1, 1),
    "Geneva roller too large": lambda: ml.ExternalGeneva(4, 1.0, roller_radius=0.5),
    "Geneva roller negative": lambda: ml.InternalGeneva(4, 1.0, roller_radius=-0.1),
    "Geneva roller nan": lambda: ml.InternalGeneva(4, 1.0, roller_radius=np.nan),
    "spherical Geneva e ≥ R": lambda: ml.SphericalGeneva(1.0, 1.5, 4),
    "SixBarIV joint nan": lambda: ml.SixBarIV(0.25, 1.04, (np.nan, 0.45), (1.35, 0.15), 0.25, 0.85, 0.9, (0.2, -0.55)),
    "SixBarIV R = T": lambda: ml.SixBarIV(0.25, 1.04, (0.5, 0.5), (0.5, 0.5), 0.25, 0.85, 0.9, (0.2, -0.55)),
    "SixBarIV crank too long": lambda: ml.SixBarIV(5, 1.04, (0.55, 0.45), (1.35, 0.15), 0.25, 0.85, 0.9, (0.2, -0.55)),
    "SixBarIV link too short": lambda: ml.SixBarIV(0.25, 1.04, (0.55, 0.45), (1.35, 0.15), 0.25, 0.1, 0.9,
                                                   (0.2, -0.55)),
    "SixBarIV length is a string": lambda: ml.SixBarIV("a", 1.04, (0.55, 0.45), (1.35, 0.15), 0.25, 0.85, 0.9,
                                                       (0.2, -0.55)),
    "lambda δ = 0": lambda: ml.LambdaMechanism(0.4, 0.8, 0.0),
    "lambda δ = 2π": lambda: ml.LambdaMechanism(0.4, 0.8, 2 * np.pi),
    "lambda r > a": lambda: ml.LambdaMechanism(0.9, 0.8, 1.0),
    "lambda r + a ≥ 2": lambda: ml.LambdaMechanism(0.7, 1.4, 1.0),
    "four-bar assembly 0": lambda: ml.FourBar(1, 3, 3, 4, 0),
    "four-bar assembly nan": lambda: ml.FourBar(1, 3, 3, 4, np.nan),
    "four-bar length is an array": lambda: ml.FourBar(np.array([1.0, 2.0]), 3, 3, 4),
    "four-bar length complex": lambda: ml.FourBar(1 + 1j, 3, 3, 4),
    "antiparallelogram rhombus": lambda: ml.Antiparallelogram(1.0, 1.0),
}


@pytest.mark.parametrize("case", sorted(ERROR_CASES))
def test_invalid_input_raises_mechanism_error(case):
    with pytest.raises(MechanismError) as exc:
        ERROR_CASES[case]()
    assert len(str(exc.value)) > 20


MECHS = {
    "FourBar": lambda: ml.FourBar(1, 3, 3, 4), "SliderCrank": lambda: ml.SliderCrank(1, 3, 0.5),
    "SlottedLink": lambda: ml.SlottedLink(0.5, 1), "SineMechanism": lambda: ml.SineMechanism(1),
    "CurvedSlotLink": lambda: ml.CurvedSlotLink(0.5, 1, ml.CircleSlot((0.3, 0.5), 1.0)),
    "TranslatingCurvedSlot": lambda: ml.TranslatingCurvedSlot(1, ml.CircleSlot((0.0, 0.0), 2.0)),
    "SixBarIV": lambda: __import__("mechlab.mechanisms.sixbar_iv", fromlist=["example"]).example(),
    "ExternalGeneva": lambda: ml.ExternalGeneva(4, 1.0), "InternalGeneva": lambda: ml.InternalGeneva(6, 1.0),
    "LambdaMechanism": lambda: ml.LambdaMechanism(0.4, 0.8, np.pi),
}


def _law(mo):
    return mo.output.value, mo.output.d, mo.output.dd


@pytest.mark.parametrize("name", sorted(MECHS))
def test_crank_angle_shapes_documented_by_as_angles(name):
    """A scalar crank angle gives a motion of scalars (positions of shape (2,)); 1-D arrays and lists are
    taken; a 2-D array or a non-finite angle is a DimensionError. (Empty arrays: see the audit findings.)"""
    m = MECHS[name]()
    ref = _law(m.motion(np.array([1.0, 2.0])))
    for v in (1.0, np.float64(1.0), np.array(1.0), 1):
        mo = m.motion(v)
        out = _law(mo)
        assert all(np.shape(o) == () for o in (*out, mo.phi, mo.transmission))
        assert all(p.p.shape == p.d.shape == p.dd.shape == (2,) for p in mo.points.values())
        assert all(abs(o - r[0]) < 1e-12 for o, r in zip(out, ref, strict=False))
    out = _law(m.motion([1.0, 2.0]))
    assert all(np.allclose(o, r, atol=1e-12) for o, r in zip(out, ref, strict=False))
    for bad in (np.ones((2, 2)), np.ones((1, 1)), [float("nan")], [1.0, float("inf")]):
        with pytest.raises(ml.DimensionError):
            m.motion(bad)
