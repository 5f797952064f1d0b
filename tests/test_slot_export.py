"""Export of the designed slot: flanks, CSV and DXF read back with ezdxf."""

import os
import tempfile

import ezdxf
import numpy as np
import pytest

from mechlab.errors import DimensionError
from mechlab.mechanisms.curved_slot import CurvedSlotLink, SampledSlot
from mechlab.synthesis.dwell_slot import curved_slot_dwell
from mechlab.synthesis.slot_export import (
    SlotUndercutError,
    check_roller,
    min_radius_of_curvature,
    read_csv,
    read_dxf,
    slot_profile,
    write_csv,
    write_dxf,
)

DEG = np.pi / 180


@pytest.fixture(scope="module")
def mech():
    return curved_slot_dwell(0.5, 60 * DEG, 150 * DEG, transition="quintic", roller_radius=0.1)


def test_flanks_are_offsets_at_roller_distance(mech):
    prof = slot_profile(mech)
    for flank in (prof.left, prof.right):
        assert np.allclose(np.hypot(*(flank - prof.centre).T), 0.1, atol=1e-12)
    # normals are perpendicular to the curve (chords of the sampled centre line)
    chord = np.diff(prof.centre, axis=0)
    mid_normal = prof.normal[:-1] + prof.normal[1:]
    cosang = np.abs(np.sum(chord * mid_normal, axis=1)) / (np.hypot(*chord.T) * np.hypot(*mid_normal.T))
    assert cosang.max() < 1e-2
    # the centre line is where the pin is: at S(φ) from B with the solver's β
    S = mech.law.S(prof.phi)[0]
    assert np.allclose(np.hypot(*prof.centre.T), S, atol=1e-12)


def test_dwell_part_of_the_flanks_are_arcs_about_O(mech):
    prof = slot_profile(mech)
    O = mech.law.centre_in_link()
    on = (prof.phi > mech.phi1) & (prof.phi < mech.phi2)
    r = mech.crank
    radii = sorted(np.hypot(*(f[on] - O).T).mean() for f in (prof.left, prof.right))
    assert radii[0] == pytest.approx(r - 0.1, abs=1e-12) and radii[1] == pytest.approx(r + 0.1, abs=1e-12)


def test_dxf_round_trip(mech):
    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, "slot.dxf")
        write_dxf(mech, path)
        doc = ezdxf.readfile(path)
        msp = doc.modelspace()
        prof = slot_profile(mech)
        centre = msp.query('LWPOLYLINE[layer=="CENTRE"]')
        assert len(centre) == 1
        pts = np.array([p[:2] for p in centre[0].get_points()])
        assert np.abs(pts - prof.centre).max() < 1e-12
        flanks = [np.array([p[:2] for p in e.get_points()]) for e in msp.query('LWPOLYLINE[layer=="FLANKS"]')]
        assert len(flanks) == 2
        assert min(np.abs(flanks[0] - prof.left).max(), np.abs(flanks[1] - prof.left).max()) < 1e-12
        (arc,) = msp.query('ARC[layer=="DWELL"]')
        assert np.allclose([arc.dxf.center.x, arc.dxf.center.y], mech.law.centre_in_link(), atol=1e-12)
        assert arc.dxf.radius == pytest.approx(mech.crank, abs=1e-12)
        # the arc's end points are the dwell's ends on the centre line
        ends = np.array([[p.x, p.y] for p in (arc.start_point, arc.end_point)])
        dwell = mech.dwell_points(2)
        assert min(np.abs(ends - dwell).max(), np.abs(ends[::-1] - dwell).max()) < 1e-9
        caps = msp.query('ARC[layer=="FLANKS"]')
        assert len(caps) == 2 and all(c.dxf.radius == pytest.approx(0.1) for c in caps)
        # each cap joins the two flanks at a slot end and bulges outwards
        for cap, i in zip(caps, (0, -1), strict=False):
            pts_cap = np.array([[p.x, p.y] for p in (cap.start_point, cap.end_point)])
            assert {tuple(np.round(p, 9)) for p in pts_cap} == {tuple(np.round(prof.left[i], 9)),
                                                               tuple(np.round(prof.right[i], 9))}
        assert doc.header["$INSUNITS"] == 4


def test_read_dxf_gives_back_what_write_dxf_wrote(mech, tmp_path):
    write_dxf(mech, tmp_path / "slot.dxf")
    got = read_dxf(tmp_path / "slot.dxf")
    prof = slot_profile(mech)
    assert np.abs(got.centre - prof.centre).max() < 1e-12
    assert np.allclose(got.dwell_centre, mech.law.centre_in_link(), atol=1e-12)
    assert got.dwell_radius == pytest.approx(mech.crank, abs=1e-12)
    flanks = sorted(got.flanks, key=lambda f: np.abs(f - prof.left).max())
    assert np.abs(flanks[0] - prof.left).max() < 1e-12 and np.abs(flanks[1] - prof.right).max() < 1e-12
    # a slot written without a roller has a centre line and a dwell arc but no flanks
    bare = curved_slot_dwell(0.4, 50 * DEG, 140 * DEG, pivot_distance=80.0, transition="quintic")
    write_dxf(bare, tmp_path / "bare.dxf")
    plain = read_dxf(tmp_path / "bare.dxf")
    assert plain.flanks == () and plain.dwell_radius == pytest.approx(32.0, abs=1e-12)


def test_read_dxf_names_a_file_that_is_no_slot(tmp_path):
    from mechlab import CamProgramme, TranslatingRollerCam, write_cam_dxf

    with pytest.raises(DimensionError, match=r"path = .*missing.dxf.* not a file"):
        read_dxf(tmp_path / "missing.dxf")
    (tmp_path / "text.dxf").write_text("not a drawing")
    with pytest.raises(DimensionError, match="not a readable DXF"):
        read_dxf(tmp_path / "text.dxf")
    cam = TranslatingRollerCam(CamProgramme(10.0, 100 * DEG, 100 * DEG, 40 * DEG), 40.0, 8.0, samples=720)
    write_cam_dxf(cam, tmp_path / "cam.dxf")
    with pytest.raises(DimensionError, match="0 polylines on layer CENTRE and 0 arcs"):
        read_dxf(tmp_path / "cam.dxf")


def test_csv_round_trip_and_spline_through_it_reproduces_motion(mech):
    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, "slot.csv")
        write_csv(mech, path, n=1441)
        cols = read_csv(path)
    prof = slot_profile(mech, n=1441)
    assert np.array_equal(np.stack([cols["x"], cols["y"]], -1), prof.centre)
    assert np.array_equal(np.stack([cols["x_left"], cols["y_left"]], -1), prof.left)
    # a spline through the exported points drives the link like the designed slot
    pts = np.stack([cols["x"], cols["y"]], -1)
    t0, t1 = pts[1] - pts[0], pts[-1] - pts[-2]
    pts = np.vstack([pts[0] - 2 * t0, pts[0] - t0, pts, pts[-1] + t1, pts[-1] + 2 * t1])
    link = CurvedSlotLink(mech.crank, 1.0, SampledSlot(pts))
    phi = np.linspace(0.05, 2 * np.pi - 0.05, 181)
    assert np.abs(link.motion(phi).psi - mech.motion(phi).psi).max() < 1e-6


def test_roller_checks():
    quintic = curved_slot_dwell(0.5, 60 * DEG, 150 * DEG, transition="quintic")
    rmin, _ = min_radius_of_curvature(quintic)
    assert rmin == pytest.approx(quintic.crank, rel=1e-9)   # the dwell arc is the sharpest part
    with pytest.raises(SlotUndercutError, match="radius of curvature"):
        check_roller(quintic, 0.6)
    cubic = curved_slot_dwell(0.5, 60 * DEG, 150 * DEG, transition="cubic")
    assert min_radius_of_curvature(cubic)[0] < 1e-5      # κ ∝ 1/φ at the slot's ends
    with pytest.raises(SlotUndercutError, match="quintic"):
        curved_slot_dwell(0.5, 60 * DEG, 150 * DEG, transition="cubic", roller_radius=0.01)
    with pytest.raises(SlotUndercutError, match="≥ 0"):
        slot_profile(quintic, roller_radius=-1.0)
