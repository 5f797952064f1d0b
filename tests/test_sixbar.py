"""The class-IV six-bar: closure of both loops, analogs, equivalence with its curved-slot twin."""

import dataclasses

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from mechlab import AssemblyError, DimensionError, RotationError
from mechlab.analysis.equivalence import equivalent_slot, law_difference, relative_path
from mechlab.mechanisms.sixbar_iv import example

H = 1e-5


def rigid_residual(six, mo):
    """Largest violation of every link length / shape constraint of the six-bar."""
    p = {k: v.p for k, v in mo.points.items()}
    d = lambda a, b: np.hypot(*(p[a] - p[b]).T)  # noqa: E731
    u, v = six.coupler_point
    E = np.array([six.ground, 0.0])
    checks = [d("O", "A") - six.crank, d("Q", "R") - six.link3, d("P", "T") - six.link5, d("Q", "P") - six.qp,
              d("A", "Q") - np.hypot(u, v),
              d("R", "E") - np.hypot(*six.r_joint), d("T", "E") - np.hypot(*six.t_joint),
              d("R", "T") - np.hypot(six.t_joint[0] - six.r_joint[0], six.t_joint[1] - six.r_joint[1])]
    # R and T sit at their places in link 4's frame rotated by ψ
    c, s = np.cos(mo.psi), np.sin(mo.psi)
    rx, ry = six.r_joint
    checks.append(np.hypot(p["R"][:, 0] - E[0] - (c * rx - s * ry), p["R"][:, 1] - (s * rx + c * ry)))
    return max(float(np.max(np.abs(x))) for x in checks)


def test_example_closes_and_analogs_match_differences():
    six = example()
    phi = six.turn(361)
    mo = six.motion(phi)
    assert rigid_residual(six, mo) < 1e-12
    up, dn = six.motion(phi + H), six.motion(phi - H)
    assert np.max(np.abs((up.psi - dn.psi) / (2 * H) - mo.dpsi)) < 1e-8
    assert np.max(np.abs((up.dpsi - dn.dpsi) / (2 * H) - mo.ddpsi)) < 1e-8
    for name in "QPRT":
        a, b = up.points[name], dn.points[name]
        assert np.max(np.abs((a.p - b.p) / (2 * H) - mo.points[name].d)) < 1e-8
        assert np.max(np.abs((a.d - b.d) / (2 * H) - mo.points[name].dd)) < 1e-8
    # periodic: one crank turn brings the output back
    assert abs(mo.psi[-1] - mo.psi[0]) < 1e-12


def test_relative_path_is_the_inner_coupler_curve():
    six = example()
    phi = six.turn(181)
    rel = relative_path(six, phi)
    th = six.inner_angle(phi)
    curve = six.relative_pin(th.theta)
    assert np.max(np.abs(rel.p - curve.p)) < 1e-12
    # chain rule: d(curve)/dφ = curve'(θ)·θ'
    assert np.max(np.abs(rel.d - curve.d * th.d[:, None])) < 1e-11


def test_example_equivalent_slot_reproduces_the_law():
    six = example()
    phi = six.turn(721)
    errs = law_difference(six.motion(phi), equivalent_slot(six).motion(phi))
    assert max(errs) < 1e-9


def _perturbed(draw_vals):
    base = example()
    dx, dy, dl, da, dg = draw_vals
    return dataclasses.replace(base, coupler_point=(0.2 + dx, -0.55 + dy), link5=0.85 + dl, crank=0.25 + da,
                               ground=1.04 + dg)


@given(st.tuples(*(st.floats(-0.04, 0.04) for _ in range(5))))
@settings(max_examples=25, deadline=None)
def test_random_nearby_six_bars_are_equivalent_to_their_curved_slots(vals):
    try:
        six = _perturbed(vals)
    except (RotationError, AssemblyError, DimensionError):
        return
    phi = six.turn(241)
    mo = six.motion(phi)
    assert rigid_residual(six, mo) < 1e-12
    assert max(law_difference(mo, equivalent_slot(six).motion(phi))) < 1e-9


def test_errors_name_the_conditions():
    with pytest.raises(DimensionError, match="2 assemblies at φ = 180°"):
        dataclasses.replace(example(), start=None)
    with pytest.raises(AssemblyError, match=r"A is crank \+ ground = 2.04 from E"):
        dataclasses.replace(example(), ground=1.79)
    with pytest.raises(RotationError, match="crank cannot turn fully"):
        dataclasses.replace(example(), crank=0.3, ground=1.0)
    with pytest.raises(DimensionError, match="link3 must be > 0"):
        dataclasses.replace(example(), link3=0.0)
    with pytest.raises(DimensionError, match="coincide"):
        dataclasses.replace(example(), t_joint=(0.55, 0.45))
