"""Cam motion laws and their invariants (seed 001, chapter 2 table)."""

import numpy as np
import pytest

from mechlab.errors import MechanismError
from mechlab.analysis.motion_laws import LAWS, law_invariants, rise_invariants, thesis_cam_rows


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
    for g, c in zip(got.values, law.closed):
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
        for g, p in zip(got.values, row.values):
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
