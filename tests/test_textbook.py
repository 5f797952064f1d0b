"""The textbook-friendly API against hand-worked cases: the output accessor, link angles,
assembly names and the branch of a sketch, placed frames, scalar in and scalar out, limit
positions and time ratios, transmission-angle extremes, zero acceleration.

Every expected number is derived here from a closed form (law of cosines, the slider-crank's
s(φ) and its derivatives written by hand), not read back from mechlab.
"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

import mechlab as ml
from mechlab.kinetostatics.machines import press

DEG = np.pi / 180
FEW = settings(max_examples=40, deadline=None)


def norton_coupler(a, b, c, d, phi, sign):
    """Coupler θ3 and rocker θ4 of a four-bar (crank a, coupler b, rocker c, ground d along +x)
    by the law of cosines in triangle A-B-O4: θ3 = ∠(O4 - A) + sign·β, cos β = (b² + |AO4|² - c²)/(2b|AO4|)."""
    A = a * np.array([np.cos(phi), np.sin(phi)])
    AE = np.array([d, 0.0]) - A
    f = np.hypot(*AE)
    beta = np.arccos((b * b + f * f - c * c) / (2 * b * f))
    theta3 = np.arctan2(AE[1], AE[0]) + sign * beta
    B = A + b * np.array([np.cos(theta3), np.sin(theta3)])
    return theta3, np.arctan2(B[1], B[0] - d)


def wrap(x):
    return (np.asarray(x) + np.pi) % (2 * np.pi) - np.pi


# ----------------------------------------------------------------------------------------------
# the output law and link angles
# ----------------------------------------------------------------------------------------------
def _guide():
    return ml.circle_guiding(120 * DEG, 0.8, 60 * DEG)


FAMILIES = {
    "FourBar": lambda: ml.FourBar(1, 3, 3, 4),
    "SliderCrank": lambda: ml.SliderCrank(1, 3, 0.5),
    "SlottedLink": lambda: ml.SlottedLink(0.5, 1),
    "SineMechanism": lambda: ml.SineMechanism(1),
    "CurvedSlotLink": lambda: ml.CurvedSlotLink(0.5, 1, ml.CircleSlot((0.3, 0.5), 1.0)),
    "TranslatingCurvedSlot": lambda: ml.TranslatingCurvedSlot(1, ml.CircleSlot((0.0, 0.0), 2.0)),
    "SixBarIV": lambda: __import__("mechlab.mechanisms.sixbar_iv", fromlist=["example"]).example(),
    "ExternalGeneva": lambda: ml.ExternalGeneva(4, 1.0),
    "InternalGeneva": lambda: ml.InternalGeneva(6, 1.0),
    "SphericalGeneva": lambda: ml.SphericalGeneva(40, 15, 4),
    "EllipticTrammel": lambda: ml.EllipticTrammel(1.0, np.radians(60)),
    "Antiparallelogram": lambda: ml.Antiparallelogram(1.0, 2.0),
    "LambdaMechanism": lambda: ml.LambdaMechanism(0.4, 0.8, np.pi),
    "LambdaRockerSixBar": lambda: ml.mchv1(_guide(), 1.0, 20 * DEG),
    "LambdaSliderSixBar": lambda: ml.mchv2(_guide(), 1.0),
    "LambdaTranslatingSlot": lambda: ml.mchv5(ml.straight_guiding(np.pi, 0.8, np.pi)),
    "LambdaSlottedSixBar": lambda: ml.mchv3_full_turn(ml.straight_guiding(np.pi, 0.8, np.pi), 0.06, 0.05),
    "DwellSlotMechanism": lambda: ml.curved_slot_dwell(0.5, 60 * DEG, 150 * DEG),
    "EquivalentSlot": lambda: ml.equivalent_slot(ml.FourBar(0.3, 0.8, 1.0, 1.0, -1)),
    "Kinetostatics": lambda: press(),
}


@pytest.mark.parametrize("name", sorted(FAMILIES))
def test_scalar_in_scalar_out_and_the_output_law_for_every_family(name):
    m = FAMILIES[name]()
    phi = m.cycle(7)[1:-1]
    many = m.motion(phi)
    law = many.output
    fields = ("psi", "dpsi", "ddpsi") if law.kind == "angle" else ("s", "ds", "dds")
    assert law.kind == m.output and law.name == ("ψ" if law.kind == "angle" else "s")
    for got, field in zip((law.value, law.d, law.dd), fields, strict=False):
        assert got is getattr(many, field)
    assert np.array_equal(many.velocity(3.0), 3.0 * law.d)
    one = m.motion(float(phi[2]))
    assert np.ndim(one.phi) == 0 and np.ndim(one.transmission) == 0
    for v, ref in zip((one.output.value, one.output.d, one.output.dd), (law.value, law.d, law.dd), strict=False):
        assert np.ndim(v) == 0 and v == pytest.approx(ref[2], abs=1e-12)
    for k, p in one.points.items():
        assert p.p.shape == many.points[k].p.shape[1:] and np.allclose(p.p, many.points[k].p[2], atol=1e-12)
    bars = [k.joints for k in m.structure().links if k.joints]   # the joints each drawn bar passes through
    if name == "SphericalGeneva":    # joints in space: no planar link angle
        with pytest.raises(ml.DimensionError, match="planar"):
            one.link_angle(*bars[0])
        return
    start, end = bars[-1][:2]
    angle = one.link_angle(start, end)
    assert np.ndim(angle.value) == 0
    assert wrap(angle.value - many.link_angle(start, end).value[2]) == pytest.approx(0.0, abs=1e-12)


def test_norton_example_4_1_coupler_and_rocker_angles():
    """Norton, Design of Machinery, Example 4-1: a = 2, b = 7, c = 9, d = 6, θ2 = 30°, open:
    θ3 = 88.84°, θ4 = 117.29°; the crossed circuit is the other sign of β."""
    for name, sign in (("open", 1), ("crossed", -1)):
        mo = ml.FourBar(2, 7, 9, 6, name).motion(30 * DEG)
        t3, t4 = norton_coupler(2, 7, 9, 6, 30 * DEG, sign)
        assert wrap(mo.link_angle("A", "B").value - t3) == pytest.approx(0, abs=1e-12)
        assert wrap(mo.link_angle("E", "B").value - t4) == pytest.approx(0, abs=1e-12)
        assert wrap(mo.psi - t4) == pytest.approx(0, abs=1e-12)
    mo = ml.FourBar(2, 7, 9, 6, "open").motion(30 * DEG)
    assert mo.link_angle("A", "B").degrees == pytest.approx(88.84, abs=0.005)
    assert np.degrees(mo.psi) == pytest.approx(117.29, abs=0.005)


@FEW
@given(st.floats(0.2, 1.0), st.floats(2.0, 4.0), st.floats(2.0, 4.0), st.floats(2.5, 4.0), st.sampled_from([1, -1]))
def test_coupler_angle_and_analogs_against_the_law_of_cosines(a, b, c, d, sign):
    s, l_ = min(a, b, c, d), max(a, b, c, d)
    assume(s == a and s + l_ < a + b + c + d - s - l_ - 0.05)   # a crank-rocker, clear of change points
    phi = np.linspace(0.0, 2 * np.pi, 73)
    got = ml.FourBar(a, b, c, d, sign).motion(phi).link_angle("A", "B")
    h = 1e-4
    for i in range(0, 73, 6):
        t = [norton_coupler(a, b, c, d, phi[i] + k * h, sign)[0] for k in (-2, -1, 0, 1, 2)]
        t = np.unwrap(t)
        d1 = (t[0] - 8 * t[1] + 8 * t[3] - t[4]) / (12 * h)
        d2 = (-t[0] + 16 * t[1] - 30 * t[2] + 16 * t[3] - t[4]) / (12 * h * h)
        assert wrap(got.value[i] - t[2]) == pytest.approx(0, abs=1e-12)
        assert got.d[i] == pytest.approx(d1, abs=1e-7)
        assert got.dd[i] == pytest.approx(d2, abs=1e-4)
    assert np.all(np.abs(np.diff(got.value)) < np.pi)   # continuous along the samples


def test_link_angle_refuses_unknown_and_coincident_joints():
    mo = ml.FourBar(1, 3, 3, 4).motion([0.0, 1.0])
    with pytest.raises(ml.DimensionError, match=r"end = 'C' is not a joint.*\['A', 'B', 'E', 'O'\]"):
        mo.link_angle("A", "C")
    with pytest.raises(ml.SingularityError, match="O and O coincide"):
        mo.link_angle("O", "O")
    with pytest.raises(ml.DimensionError, match="not an angle"):
        _ = ml.SliderCrank(1, 3).motion(0.0).output.degrees


def test_law_repr_reads_in_degrees():
    text = repr(ml.FourBar(2, 7, 9, 6, "open").motion(30 * DEG).link_angle("A", "B"))
    assert "θ(A→B) = 1.5505" in text and "88.8372°" in text


# ----------------------------------------------------------------------------------------------
# assembly names, the branch of a sketch, placed frames
# ----------------------------------------------------------------------------------------------
def test_assembly_names_map_to_the_signs():
    assert ml.FourBar(1, 3, 3, 4, "open").assembly == 1 and ml.FourBar(1, 3, 3, 4, "crossed").assembly == -1
    assert ml.SliderCrank(1, 3, 0.2, "open") == ml.SliderCrank(1, 3, 0.2, 1)
    assert ml.SliderCrank(1, 3, 0.2, "crossed") == ml.SliderCrank(1, 3, 0.2, -1)
    for bad in ("opened", 0, 2, None):
        with pytest.raises(ml.DimensionError, match="'open' \\(= \\+1\\) or 'crossed'"):
            ml.FourBar(1, 3, 3, 4, bad)


@FEW
@given(st.floats(0.2, 1.0), st.floats(2.0, 4.0), st.floats(2.0, 4.0), st.floats(2.5, 4.0), st.floats(0.05, 3.09))
def test_open_is_the_uncrossed_quadrilateral_above_the_frame_line(a, b, c, d, phi):
    """Open: B and O on opposite sides of the diagonal AE while 0 < φ < π; crossed: the same side."""
    s, l_ = min(a, b, c, d), max(a, b, c, d)
    assume(s == a and s + l_ < a + b + c + d - s - l_ - 0.05)
    for name, opposite in (("open", True), ("crossed", False)):
        p = ml.FourBar(a, b, c, d, name).motion(phi).points
        A, B = p["A"].p, p["B"].p
        E = np.array([d, 0.0])
        u, v, w = E - A, B - A, -A
        side_b, side_o = u[0] * v[1] - u[1] * v[0], u[0] * w[1] - u[1] * w[0]
        assert (side_b * side_o < 0) == opposite


def test_nearest_assembly_picks_the_branch_of_the_sketch():
    fb = ml.FourBar(1, 3, 3, 4)
    phi = 60 * DEG
    for sign in (1, -1):
        B = ml.FourBar(1, 3, 3, 4, sign).motion(phi).points["B"].p
        sketch = B + np.array([0.3, -0.2])      # a rough sketch near the true B
        assert ml.nearest_assembly(fb, phi, B=sketch).assembly == sign
    sc = ml.SliderCrank(1, 3, 0.5)
    assert ml.nearest_assembly(sc, 0.3, B=(-3.0, 0.5)).assembly == -1
    with pytest.raises(ml.DimensionError, match=r"'Q'.*not joints"):
        ml.nearest_assembly(fb, phi, Q=(0, 0))
    with pytest.raises(ml.DimensionError, match="has no assembly"):
        ml.nearest_assembly(ml.SineMechanism(1), phi, B=(0, 0))


def test_placed_watt_linkage_with_pivots_anywhere():
    """Pivots O = (1, 2), E = (4, 6): the crank angle θ2 and every angle from the world x axis."""
    O, E = np.array([1.0, 2.0]), np.array([4.0, 6.0])
    a, b, c = 1.0, 4.0, 3.5
    alpha = np.arctan2(*(E - O)[::-1])
    mech = ml.FourBar(a, b, c, np.hypot(*(E - O)))
    theta2 = np.linspace(0, 2 * np.pi, 37)
    mo = mech.motion(theta2 - alpha).placed(O, alpha)
    A, B = mo.points["A"].p, mo.points["B"].p
    assert np.allclose(mo.phi, theta2) and np.allclose(mo.points["O"].p, O) and np.allclose(mo.points["E"].p, E)
    assert np.allclose(A, O + a * np.stack([np.cos(theta2), np.sin(theta2)], 1), atol=1e-12)
    assert np.allclose(np.hypot(*(B - A).T), b, atol=1e-12) and np.allclose(np.hypot(*(B - E).T), c, atol=1e-12)
    assert np.allclose(wrap(mo.psi - np.arctan2(B[:, 1] - E[1], B[:, 0] - E[0])), 0, atol=1e-12)
    local = mech.motion(theta2 - alpha)
    assert np.allclose(mo.link_angle("A", "B").value, local.link_angle("A", "B").value + alpha, atol=1e-12)
    assert np.array_equal(mo.dpsi, local.dpsi) and np.array_equal(mo.transmission, local.transmission)
    # analogs rotate: central differences of the world positions in θ2
    h = 1e-6
    up = mech.motion(theta2 - alpha + h).placed(O, alpha).points["B"].p
    dn = mech.motion(theta2 - alpha - h).placed(O, alpha).points["B"].p
    assert np.allclose(mo.points["B"].d, (up - dn) / (2 * h), atol=1e-7)
    # a scalar placed motion
    one = mech.motion(0.5).placed(O, alpha)
    assert one.points["B"].p.shape == (2,) and one.phi == pytest.approx(0.5 + alpha)


# ----------------------------------------------------------------------------------------------
# limit positions, time ratio, transmission extremes, zero acceleration
# ----------------------------------------------------------------------------------------------
@pytest.mark.parametrize("dims", [(1, 3, 3, 4), (2, 7, 9, 6), (0.5, 2.5, 2.0, 2.2), (1.0, 4.0, 2.5, 3.5)])
def test_crank_rocker_time_ratio_from_the_law_of_cosines(dims):
    a, b, c, d = dims
    # crank and coupler in line: O-B = b + a (extended) or b - a (folded); triangle O-B-E
    th1 = np.arccos(((b + a) ** 2 + d * d - c * c) / (2 * (b + a) * d))
    th2 = np.arccos(((b - a) ** 2 + d * d - c * c) / (2 * (b - a) * d))
    forward = np.pi + th2 - th1
    Q = max(forward, 2 * np.pi - forward) / min(forward, 2 * np.pi - forward)
    psi1 = np.arccos((d * d + c * c - (b + a) ** 2) / (2 * d * c))   # angle at E in the same triangles
    psi2 = np.arccos((d * d + c * c - (b - a) ** 2) / (2 * d * c))
    ex = ml.FourBar(*dims, "open").extremes()
    assert ex.phi_extended == pytest.approx(th1, abs=1e-12) and ex.phi_folded == pytest.approx(np.pi + th2, abs=1e-12)
    assert ex.extended == pytest.approx(np.pi - psi1, abs=1e-12) and ex.folded == pytest.approx(np.pi - psi2, abs=1e-12)
    assert ex.stroke == pytest.approx(psi1 - psi2, abs=1e-12)
    assert ex.time_ratio == pytest.approx(Q, rel=1e-12)
    crossed = ml.FourBar(*dims, "crossed").extremes()     # the mirror image
    assert crossed.phi_extended == pytest.approx(2 * np.pi - th1, abs=1e-12)
    assert crossed.phi_folded == pytest.approx(np.pi - th2, abs=1e-12)
    assert crossed.time_ratio == pytest.approx(Q, rel=1e-12)
    # ψ is extreme there: the rocker's ψ' vanishes
    mo = ml.FourBar(*dims).motion(np.array([ex.phi_extended, ex.phi_folded]))
    assert np.allclose(mo.dpsi, 0.0, atol=1e-12)


def test_extremes_refused_without_a_rocking_output():
    with pytest.raises(ml.RotationError, match="double-crank"):
        ml.FourBar(3, 3, 3, 1).extremes()
    with pytest.raises(ml.RotationError, match="triple-rocker"):
        ml.FourBar(3, 3, 3, 7).extremes()
    with pytest.raises(ml.RotationError, match="crank cannot turn"):
        ml.SliderCrank(1.0, 1.2, 0.5).extremes()


@pytest.mark.parametrize("a, l_, e", [(1.0, 3.0, 0.0), (1.0, 4.0, 0.5), (0.05, 0.2, -0.03), (2.0, 5.0, 1.0)])
def test_slider_crank_limit_positions_and_time_ratio(a, l_, e):
    ex = ml.SliderCrank(a, l_, e).extremes()
    x_out, x_in = np.sqrt((l_ + a) ** 2 - e * e), np.sqrt((l_ - a) ** 2 - e * e)
    assert ex.extended == pytest.approx(x_out, abs=1e-12) and ex.folded == pytest.approx(x_in, abs=1e-12)
    assert ex.stroke == pytest.approx(x_out - x_in, abs=1e-12)
    assert ex.phi_extended == pytest.approx(np.mod(np.arcsin(e / (l_ + a)), 2 * np.pi), abs=1e-12)
    assert ex.phi_folded == pytest.approx(np.pi + np.arcsin(e / (l_ - a)), abs=1e-12)
    theta = abs(np.arcsin(e / (l_ - a)) - np.arcsin(e / (l_ + a)))
    assert ex.time_ratio == pytest.approx((np.pi + theta) / (np.pi - theta), rel=1e-12)
    if e == 0:
        assert (ex.extended, ex.folded, ex.time_ratio) == pytest.approx((l_ + a, l_ - a, 1.0), abs=1e-12)
    mirrored = ml.SliderCrank(a, l_, e, "crossed").extremes()
    assert mirrored.extended == pytest.approx(-x_out, abs=1e-12) and mirrored.stroke == pytest.approx(ex.stroke)


@pytest.mark.parametrize("dims", [(1, 3, 3, 4), (2, 7, 9, 6), (0.5, 2.5, 2.0, 2.2)])
def test_four_bar_transmission_extremes_where_the_crank_lies_on_the_frame_line(dims):
    a, b, c, d = dims
    mu_min = np.arccos((b * b + c * c - (d - a) ** 2) / (2 * b * c))
    mu_max = np.arccos((b * b + c * c - (d + a) ** 2) / (2 * b * c))
    t = ml.transmission_extremes(ml.FourBar(*dims))
    assert t.mu_min == pytest.approx(mu_min, abs=1e-10) and t.mu_max == pytest.approx(mu_max, abs=1e-10)
    assert wrap(t.phi_min) == pytest.approx(0.0, abs=1e-4) and t.phi_max == pytest.approx(np.pi, abs=1e-4)
    assert t.worst_deviation == pytest.approx(max(np.pi / 2 - mu_min, mu_max - np.pi / 2), abs=1e-10)
    assert "μ_min" in repr(t) and "°" in repr(t)


def test_slider_crank_transmission_extremes():
    a, l_, e = 1.0, 4.0, 0.5
    t = ml.transmission_extremes(ml.SliderCrank(a, l_, e))
    # μ = 90° - asin(|a sin φ - e| / l): least where a sin φ = -a (φ = 270°), 90° where a sin φ = e
    assert t.mu_min == pytest.approx(np.pi / 2 - np.arcsin((a + e) / l_), abs=1e-10)
    assert t.phi_min == pytest.approx(1.5 * np.pi, abs=1e-4)
    assert t.mu_max == pytest.approx(np.pi / 2, abs=1e-10)
    assert np.sin(t.phi_max) == pytest.approx(e / a, abs=1e-6)


def _s_dd(a, l_, phi):
    """s'' of the centred slider-crank s = a cos φ + √(l² - a² sin² φ), differentiated by hand."""
    w = np.sqrt(l_ * l_ - (a * np.sin(phi)) ** 2)
    return -a * np.cos(phi) - a * a * np.cos(2 * phi) / w - (a * a * np.sin(phi) * np.cos(phi)) ** 2 / w**3


@pytest.mark.parametrize("a, l_", [(1.0, 3.0), (1.0, 4.0), (0.1, 0.4), (1.0, 1.5)])
def test_slider_crank_zero_acceleration_angles(a, l_):
    roots = ml.zero_acceleration(ml.SliderCrank(a, l_))
    assert len(roots) == 2
    assert np.abs(_s_dd(a, l_, roots)).max() < 1e-9 * a
    # symmetric about φ = π, on either side of the quarter turns (a finite rod tilts them towards 0)
    assert roots.sum() == pytest.approx(2 * np.pi, abs=1e-9)
    assert 0 < roots[0] < np.pi / 2
    grid = np.linspace(0, 2 * np.pi, 2001)
    sign_changes = np.count_nonzero(np.diff(np.sign(_s_dd(a, l_, grid))))
    assert sign_changes == 2


def test_non_grashof_is_named_and_crank_ranges_read_in_degrees():
    g = ml.FourBar(3, 3, 3, 7).grashof()
    assert g.kind == "triple-rocker" and g.grashof_class == "non-Grashof" and "non-Grashof" in str(g)
    assert ml.FourBar(1, 3, 3, 4).grashof().grashof_class == "Grashof"
    assert ml.crank_ranges_degrees(ml.FourBar(1, 3, 3, 4)) == ((0.0, 360.0),)
    # triple-rocker 3, 3, 3, 7: |AE| ≤ 6 where 9 + 49 - 42 cos φ ≤ 36, i.e. cos φ ≥ 22/42
    limit = np.degrees(np.arccos(22 / 42))
    (lo, hi), = ml.crank_ranges_degrees(ml.FourBar(3, 3, 3, 7))
    assert lo == pytest.approx(-limit, abs=1e-9) and hi == pytest.approx(limit, abs=1e-9)


# ----------------------------------------------------------------------------------------------
# exports
# ----------------------------------------------------------------------------------------------
# Names too generic for the top level, reached through their module (the notebooks import them so).
MODULE_ONLY = {"report", "example", "separation"}


def test_every_computation_helper_the_notebooks_import_is_exported():
    """`from mechlab.<computation module> import name` in a chapter: name is in mechlab.__all__ (drawing, widgets,
    course material stay in their packages; the kinetostatics and motion-law modules are exported whole as
    ``ml.forces`` and ``ml.motion_laws``; geometry is the primitives' layer)."""
    import json
    import pathlib
    import re
    higher = ("mechlab.draw", "mechlab.widgets", "mechlab.course", "mechlab.kinetostatics",
              "mechlab.analysis.motion_laws", "mechlab.geometry")
    wanted = set()
    for nb in sorted(pathlib.Path(__file__).parents[1].glob("notebooks/*.ipynb")):
        cells = json.loads(nb.read_text())["cells"]
        code = "\n".join("".join(c["source"]) for c in cells if c["cell_type"] == "code")
        for module, names in re.findall(r"^from (mechlab\.[\w.]+) import \(?([\w ,\n]+?)\)?$", code, re.M):
            if not module.startswith(higher):
                wanted |= {n for n in re.split(r"[,\s]+", names) if n}
    assert "classic_lambda" in wanted
    assert sorted(wanted - MODULE_ONLY - set(ml.__all__)) == []


# ----------------------------------------------------------------------------------------------
# results: frozen dataclasses, tables that show in a notebook
# ----------------------------------------------------------------------------------------------
def test_public_results_are_frozen_dataclasses_and_tables_show_as_tables():
    import dataclasses
    results = [ml.dwell_limit(0.5, 60 * DEG), ml.two_branch_slot(0.5, 100 * DEG),
               ml.intermittency(ml.ExternalGeneva(4, 1.0), n=1441), ml.FourBar(1, 3, 3, 4).grashof(),
               ml.FourBar(1, 3, 3, 4).extremes(), ml.transmission_extremes(ml.FourBar(1, 3, 3, 4), n=361),
               ml.FourBar(1, 3, 3, 4).motion(0.2).output]
    for r in results:
        assert dataclasses.is_dataclass(r) and not isinstance(r, (dict, tuple))
        with pytest.raises(dataclasses.FrozenInstanceError):
            setattr(r, dataclasses.fields(r)[0].name, 0)
    table = ml.spherical_table(40, 15, [4, 6])
    assert isinstance(table, ml.Table) and len(table) == 2 and table[1].z == 6
    assert table.columns == ("z", "alpha0", "beta0", "omega_max", "eps_max", "alpha1", "beta1")
    assert np.array_equal(table.column("z"), [4, 6]) and table.by("z")[6] is table[1]
    # ρ0 = 25 mm for z = 6 gives α0 = arccos(0.6) (Vainer & Shatokhina's Table 1: 53.13°)
    assert table.by("z")[6].alpha0 == pytest.approx(np.degrees(np.arccos(0.6)), abs=1e-9)
    html = table._repr_html_()
    assert html.count("<tr>") == 3 and "<th>|ε|max/ω1²</th>" in html and "53.1301" in html
    text = repr(table).splitlines()
    assert len(text) == 3 and text[0].split()[:3] == ["z", "α0,", "°"] and text[2].split()[0] == "6"
    # the columns a reader sees carry their units; the field names stay the keys
    assert table.headers == ("z", "α0, °", "β0, °", "ω_max/ω1", "|ε|max/ω1²", "α1, °", "β1, °")
    assert ml.Table([ml.intermittency(ml.ExternalGeneva(4, 1.0), n=361)]).headers[0] == "name"
    rows = ml.compare({"external": ml.ExternalGeneva(4, 1.0), "whitworth": ml.SlottedLink(2.0, 1.0)}, n=1441)
    assert [r.name for r in rows] == ["external", "whitworth"] and rows.by("name")["whitworth"].dwell_fraction == 0
    assert "link" not in ml.Table([ml.two_branch_slot(0.5, 100 * DEG)]).columns   # a factory is no column


def test_a_triple_rocker_refuses_to_turn_naming_non_grashof():
    with pytest.raises(ml.RotationError, match=r"s \+ l = 10\.00 > p \+ q = 6\.00 \(non-Grashof, a triple-rocker"):
        ml.FourBar(3, 3, 3, 7).turn()


def test_base_laws_take_a_scalar_and_give_scalars():
    """ψ_K(φ) = atan2(λ sin φ, 1 + λ cos φ) (the base mechanism, Zinchenko et al., 2013, (18)), λ = 0.5 here."""
    from mechlab.synthesis.dwell_slot import slotted_link_law as dwell_base_law
    lam, x = 0.5, 0.7
    expected = np.arctan2(lam * np.sin(x), 1 + lam * np.cos(x))
    for law in (dwell_base_law(lam, x), ml.formula_18(lam, x)):
        values = [getattr(law, f) for f in ("d", "dd")] + [getattr(law, "psi", getattr(law, "theta", None))]
        assert all(np.ndim(v) == 0 for v in values)
        assert values[-1] == pytest.approx(expected, abs=1e-14)
        assert values[0] == pytest.approx(lam * (lam + np.cos(x)) / (1 + lam * lam + 2 * lam * np.cos(x)), abs=1e-14)
    one, many = ml.base_law(ml.FourBar(1, 3, 3, 4), x), ml.base_law(ml.FourBar(1, 3, 3, 4), [x, 1.0])
    assert np.ndim(one.theta) == 0 and one.theta == pytest.approx(many.theta[0], abs=1e-15)
    assert one.d == pytest.approx(many.d[0], abs=1e-15) and one.dd == pytest.approx(many.dd[0], abs=1e-15)
