"""Cam motion laws and their invariants (seed 001, chapter 2 table)."""

import dataclasses

import numpy as np
import pytest

from mechlab.analysis.motion_laws import LAWS, law_invariants, rise_invariants, thesis_cam_rows
from mechlab.errors import MechanismError


@pytest.mark.parametrize("name", list(LAWS))
def test_law_is_a_rise_with_consistent_analogs(name):
    law = LAWS[name]
    x = np.linspace(0, 1, 20001)
    y, dy, ddy = law(x)
    assert abs(y[0]) < 1e-12 and abs(y[-1] - 1) < 1e-12
    assert abs(dy[0]) < 1e-12 and abs(dy[-1]) < 1e-12
    h = x[1] - x[0]
    assert np.allclose((y[2:] - y[:-2]) / (2 * h), dy[1:-1], atol=5e-4)  # (the kink of y'' at ½)
    ok = np.abs(np.diff(ddy)) < 1  # skip the jumps of the constant-acceleration law
    fd = (dy[2:] - dy[:-2]) / (2 * h)
    keep = ok[:-1] & ok[1:]
    assert np.allclose(fd[keep], ddy[1:-1][keep], atol=1e-5)


@pytest.mark.parametrize("name", list(LAWS))
def test_invariants_match_closed_forms(name):
    law = LAWS[name]
    got = law_invariants(law)
    for g, c in zip(got.values, law.closed, strict=False):
        if c is not None:
            assert abs(g - c) < 1e-7 * max(1, c)


def test_classic_values():
    assert law_invariants("cycloidal (sine)").D == pytest.approx(3 * np.sqrt(3) * np.pi / 2, rel=1e-9)
    assert law_invariants("3-4-5 polynomial").C == pytest.approx(10 / np.sqrt(3), rel=1e-9)
    assert law_invariants("double harmonic").C == pytest.approx(np.pi**2, rel=1e-9)


MISPRINTS = {("cosine", 4.94), ("cycloidal (sine)", 8.15), ("double harmonic", 9.88), ("double harmonic", 7.00)}


def test_thesis_rows_where_they_agree():
    for row in thesis_cam_rows():
        name = row.law
        got = law_invariants(name)
        for g, p in zip(got.values, row.values, strict=False):
            if p is None:
                continue
            if (name, p) in MISPRINTS:
                assert abs(g - p) > 0.005  # the printed misprints (errata of seed 001)
            else:
                assert abs(g - p) <= 0.005 + 1e-9


def test_rise_invariants_of_a_sampled_law_are_scale_free():
    law = LAWS["cosine"]
    Phi, h = 1.7, 0.4
    phi = np.linspace(0, Phi, 40001)
    y, dy, ddy = law(phi / Phi)
    inv = rise_invariants(phi + 2.0, 3.0 + h * y, h * dy / Phi, h * ddy / Phi**2)
    assert np.allclose(inv.values, law.closed, rtol=1e-6)
    with pytest.raises(MechanismError, match="no rise"):
        rise_invariants(phi, np.zeros_like(phi), phi * 0, phi * 0)


def test_law_table_gives_each_law_its_invariants_and_end_accelerations():
    from mechlab.analysis.motion_laws import law_table

    table = law_table()
    assert list(table.column("law")) == list(LAWS)
    for row in table:
        assert (row.B, row.C, row.D) == law_invariants(row.law).values
        assert (row.start, row.end) == pytest.approx(LAWS[row.law](np.array([0.0, 1.0]))[2], abs=1e-8)
    by = table.by("law")
    # soft impacts where Y'' jumps from the dwell's 0; the cycloid starts and ends at zero acceleration
    assert by["constant acceleration"].start == 4 and by["cycloidal (sine)"].start == 0 == by["cycloidal (sine)"].end
    assert "-0" not in repr(table) and table.headers[1] == "C_v = max|Y′|"
    assert len(law_table(["cosine"], n=2001)) == 1
    with pytest.raises(MechanismError, match="names"):
        law_table(["trapezoid"])


# ----------------------------------------------------------------------------- the textbook laws with jerk
import sympy as sp  # noqa: E402

from mechlab.analysis.motion_laws import ALIASES, law_jerk, law_table, named_law  # noqa: E402
from mechlab.errors import DimensionError  # noqa: E402

X = sp.Symbol("x", real=True)


def _from_acceleration(pieces):
    """y, y', y'', y''' of a rise whose acceleration is ``pieces`` [(end, C·shape(x))] with y(0) = y'(0) = 0,
    integrated piece by piece (continuous y, y'), C fixed by y(1) = 1: an independent derivation."""
    C = sp.Symbol("C", positive=True)
    out, start, v0, y0 = [], 0, 0, 0
    for end, acc in pieces:
        acc = acc.subs("C", C)
        v = v0 + sp.integrate(acc, (X, start, X))
        y = y0 + sp.integrate(v, (X, start, X))
        out.append((end, y, v, acc, sp.diff(acc, X)))
        v0, y0, start = v.subs(X, end), y.subs(X, end), end
    c = sp.solve(sp.Eq(y0, 1), C)[0]
    return [(end, *(f.subs(C, c) for f in fs)) for end, *fs in out], c


PI = sp.pi
S = sp.Symbol("C")
SYMBOLIC = {  # the textbooks' definitions (Norton, Design of Machinery, ch. 8; Kinitsky, 1994)
    "modified trapezoid": [(sp.Rational(1, 8), S * sp.sin(4 * PI * X)), (sp.Rational(3, 8), S + 0 * X),
                           (sp.Rational(5, 8), S * sp.cos(4 * PI * (X - sp.Rational(3, 8)))),
                           (sp.Rational(7, 8), -S + 0 * X), (1, -S * sp.sin(4 * PI * (1 - X)))],
    "modified sine": [(sp.Rational(1, 8), S * sp.sin(4 * PI * X)),
                      (sp.Rational(7, 8), S * sp.cos(sp.Rational(4, 3) * PI * (X - sp.Rational(1, 8)))),
                      (1, -S * sp.sin(4 * PI * (1 - X)))],
    "cycloidal (sine)": [(1, S * sp.sin(2 * PI * X))],
    "cosine": [(1, S * sp.cos(PI * X))],
    "3-4-5 polynomial": [(1, S * (X - 3 * X**2 + 2 * X**3))],
    "4-5-6-7 polynomial": [(1, S * X**2 * (1 - X)**2 * (1 - 2 * X))],
    "double harmonic": [(1, S * (sp.cos(PI * X) - sp.cos(2 * PI * X)))],
    "constant acceleration": [(sp.Rational(1, 2), S + 0 * X), (1, -S + 0 * X)],
    "linearly falling acceleration": [(1, S * (1 - 2 * X))],
}


@pytest.mark.parametrize("name", list(LAWS))
def test_closed_forms_agree_with_a_sympy_derivation(name):
    pieces, _ = _from_acceleration(SYMBOLIC[name])
    law = LAWS[name]
    x = np.linspace(0, 1, 41)[1:-1] + 1e-3   # off the pieces' joints
    ends = [p[0] for p in pieces]
    for k, f in enumerate((law.y, law.dy, law.ddy, law.jerk)):
        want = [float(pieces[next(i for i, e in enumerate(ends) if v < float(e))][k + 1].subs(X, v)) for v in x]
        assert np.allclose(f(x), want, atol=1e-11, rtol=1e-11), (name, k)


# the published factors (Norton, Design of Machinery, table 8-3; MechDesigner's motion-law pages):
# C_v = max|y'|, C_a = max|y''|, C_j = max|y'''| (inf: y'' jumps), C_p = D = max|y'y''| where quoted
PUBLISHED = {
    "modified trapezoid": (2.0, 4.888, 61.43), "modified sine": (1.760, 5.528, 69.47),
    "cycloidal (sine)": (2.0, 6.283, 39.48), "3-4-5 polynomial": (1.875, 5.774, 60.0),
    "cosine": (1.571, 4.935, np.inf), "4-5-6-7 polynomial": (2.1875, 7.513, 52.5),
    "constant acceleration": (2.0, 4.0, np.inf), "double harmonic": (2.041, 9.870, np.inf),
}


@pytest.mark.parametrize("name", sorted(PUBLISHED))
def test_law_table_gives_the_published_factors_to_four_digits(name):
    row = law_table([name]).by("law")[name]
    for got, want in zip((row.B, row.C, row.J), PUBLISHED[name], strict=False):
        if np.isinf(want):
            assert got is None and np.isinf(law_jerk(name))   # the table shows an unbounded jerk as None
        else:
            assert got == pytest.approx(want, abs=0.5 * 10.0 ** (np.floor(np.log10(want)) - 3) + 1e-12)


@pytest.mark.parametrize("name", list(LAWS))
def test_jerk_is_the_central_difference_of_the_acceleration(name):
    law = LAWS[name]
    h = 1e-5
    x = np.linspace(h, 1 - h, 4001)
    cuts = np.array([0.5, *law.knots])
    x = x[np.min(np.abs(x[:, None] - cuts[None, :]), axis=1) > 2 * h]
    fd = (law.ddy(x + h) - law.ddy(x - h)) / (2 * h)
    assert np.allclose(law.jerk(x), fd, atol=1e-4 * max(1.0, np.max(np.abs(fd))))


@pytest.mark.parametrize("name", list(LAWS))
def test_closed_jerk_factor_is_the_measured_one(name):
    law = LAWS[name]
    if len(law.closed) == 4 and law.closed[3] is not None:
        assert law_jerk(law) == pytest.approx(law.closed[3], rel=1e-9)
    impact = abs(law.ddy(np.array([0.0]))[0]) > 1e-12 or abs(law.ddy(np.array([1.0]))[0]) > 1e-12
    assert np.isinf(law_jerk(law)) == impact


def test_jerk_factor_sees_a_jump_inside_the_rise():
    # y'' zero at both ends but with two jumps inside: the jerk is an impulse there
    base = LAWS["cycloidal (sine)"]
    assert np.isinf(law_jerk(dataclasses.replace(base, ddy=lambda x: np.where((x > 0.4) & (x < 0.6), 1.0, 0 * x))))
    assert law_jerk(base) == pytest.approx(4 * np.pi**2, rel=1e-12)


def test_aliases_name_the_same_laws_and_a_law_without_jerk_says_so():
    assert named_law("simple harmonic") is LAWS["cosine"] and named_law("3-4-5") is LAWS["3-4-5 polynomial"]
    assert all(target in LAWS for target in ALIASES.values())
    assert law_table(["simple harmonic"]).by("law")["cosine"].C == pytest.approx(np.pi**2 / 2)
    with pytest.raises(DimensionError, match="law must be one of"):
        named_law("trapezoidal")
    bare = dataclasses.replace(LAWS["cosine"], dddy=None)
    with pytest.raises(MechanismError, match="no jerk"):
        law_jerk(bare)
