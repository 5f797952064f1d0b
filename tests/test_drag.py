"""The drag editor (mechlab.widgets.drag), without a browser: what a handle's move means for the dimensions, the
code it copies, the mouse and key events as ipympl delivers them, undo, snapping, the named error, and the
figure updated in place (tests_browser/test_drag_lab.py drives it in JupyterLab)."""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np
import pytest
from examples import designs
from matplotlib.backend_bases import KeyEvent, MouseEvent

import mechlab as ml
from mechlab.errors import AssemblyError, StructureError
from mechlab.mechanisms.lambda_mechanism import GuidedLambda
from mechlab.widgets import DragEditor, as_linkage, linkage_code
from mechlab.widgets.drag import handles, moved

PHI = np.linspace(0.0, 2 * np.pi, 181)
PIXEL = 0.03   # a mouse event's position is a whole pixel: about 0.015 length units in the editor's view


def coupler_fourbar(point=(1.5, 0.8), **frame):
    return (ml.Linkage({"O": (0, 0), "E": (4, 0), **frame}, ml.Crank("O", "A", 1.0))
            .rrr("A", "E", "B", 3.0, 3.0, links=("coupler", "rocker")).point("P", "coupler", point))


def watt_sixbar():
    """A four-bar with a coupler point driving a second rocker (RRR) and a slider on a tilted guide (RRP)."""
    return (coupler_fourbar(F=(3.0, 3.0), G=(4.0, 5.0)).rrr("P", "F", "D", 2.5, 2.0, 1, links=("rod", "output"))
            .point("C", "output", (2.5, 0.5)).rrp("C", "S", 2.5, ml.Guide("G", 0.3), 1, links=("link", "ram")))


LINKAGES = {
    "fourbar": coupler_fourbar(),
    "sixbar": watt_sixbar(),
    "shaper": ml.Linkage.example(),
    "crossed": (ml.Linkage({"O": (0, 0), "E": (2, 0)}, ml.Crank("O", "A", 0.6, "input"))
                .rrr("A", "E", "B", 2.2, 1.4, -1).with_output("AB")),
}


def test_families_map_onto_linkages_that_move_as_they_do():
    for fam in (ml.FourBar(1, 3, 3, 4), ml.FourBar(1.0, 2.5, 2.0, 3.0, -1)):
        lk = as_linkage(fam)
        assert np.allclose(lk.motion(PHI).psi, fam.motion(PHI).psi, atol=1e-12, rtol=0)
        assert np.allclose(lk.motion(PHI).points["B"].p, fam.motion(PHI).points["B"].p, atol=1e-12, rtol=0)
    for fam in (ml.SliderCrank(1.0, 3.0, 0.4), ml.SliderCrank(0.7, 2.0, -0.3, -1)):
        lk = as_linkage(fam)
        assert np.allclose(lk.motion(PHI).points["B"].p, fam.motion(PHI).points["B"].p, atol=1e-12, rtol=0)
    for fam in (ml.LambdaMechanism(0.4, 0.8, np.pi), ml.LambdaMechanism(0.3, 0.9, np.radians(150), -1)):
        lk, phi = as_linkage(fam), fam.turn(361)
        assert np.allclose(lk.motion(phi).psi, fam.motion(phi).psi, atol=1e-12, rtol=0)
        assert np.allclose(lk.motion(phi).points["D"].p, fam.motion(phi).points["D"].p, atol=1e-12, rtol=0)
    for fam in [d for d in designs() if type(d) in (ml.LambdaRockerSixBar, ml.LambdaSliderSixBar)]:
        lk, phi = as_linkage(fam), fam.turn(361) + 1e-3
        assert np.allclose(lk.motion(phi).points["E"].p, fam.motion(phi).points["E"].p, atol=1e-12, rtol=0)
    slot = ml.SlottedLink(0.5, 1.0)
    assert np.allclose(as_linkage(slot).motion(PHI).psi, slot.motion(PHI).psi, atol=1e-12, rtol=0)
    assert as_linkage(LINKAGES["fourbar"]) is LINKAGES["fourbar"]
    with pytest.raises(StructureError, match="ExternalGeneva"):
        as_linkage(ml.ExternalGeneva.example())
    guided = GuidedLambda.example()   # a lambda with its guiding band drawn: the lambda's motion
    assert np.allclose(as_linkage(guided).motion(PHI).points["D"].p, guided.motion(PHI).points["D"].p, atol=1e-12)


@pytest.mark.parametrize("name", LINKAGES)
def test_copied_code_rebuilds_the_same_motion(name):
    lk = LINKAGES[name]
    ns: dict = {}
    exec(linkage_code(lk, "rebuilt"), ns)   # the cell a student pastes
    rebuilt = ns["rebuilt"]
    assert rebuilt == lk
    phi = np.linspace(*lk.crank_ranges()[0], 97)[1:-1]
    a, b = lk.motion(phi), rebuilt.motion(phi)
    for joint in a.points:
        assert np.max(np.abs(a.points[joint].p - b.points[joint].p)) <= 1e-12
        assert np.max(np.abs(a.points[joint].dd - b.points[joint].dd)) <= 1e-12


def test_a_dragged_joint_lands_where_it_is_dropped():
    """Every handle of the six-bar (frame points, crank pin, RRR joints, coupler points) ends exactly where it
    was put, at the same crank angle; an RRP pin ends at its projection on the guide."""
    lk = watt_sixbar()
    phi = 0.7
    before = {k: v.p for k, v in lk.motion(phi).points.items()}
    offset = np.array([0.13, -0.07])
    for joint in handles(lk):
        target = before[joint] + offset
        new, new_phi = moved(lk, joint, target, phi)
        at = new.motion(new_phi).points[joint].p
        if joint == "S":
            u = np.array([np.cos(0.3), np.sin(0.3)])
            assert np.allclose(at, before[joint] + (offset @ u) * u, atol=1e-12), joint
        else:
            assert np.allclose(at, target, atol=1e-12), joint
        if joint == "A":
            assert new.driver.radius == pytest.approx(np.hypot(*target))
            assert new_phi == pytest.approx(np.arctan2(target[1], target[0]))
        else:
            assert new_phi == phi
        unchanged = [k for k in before if k in dict(lk.frame) and k != joint]
        for k in unchanged:   # the other fixed pivots stay
            assert np.allclose(new.motion(new_phi).points[k].p, before[k])


def test_what_each_handle_changes():
    lk = coupler_fourbar()
    new, _ = moved(lk, "E", (4.5, 0.5), 0.0)
    assert dict(new.frame)["E"] == (4.5, 0.5) and new.groups == lk.groups
    new, _ = moved(lk, "B", (2.0, -2.0), 0.0)   # dropped below the line A → E: the other branch
    rrr = new.groups[0]
    assert rrr.assembly == -1 and rrr.first_length == pytest.approx(np.hypot(1, 2))
    assert rrr.second_length == pytest.approx(np.hypot(2, 2))
    new, _ = moved(lk, "P", (1.0, 0.0), 0.0)   # on the line A → B: η = 0
    B = lk.motion(0.0).points["B"].p
    u = (B - [1, 0]) / np.hypot(*(B - [1, 0]))
    assert new.groups[1].at == pytest.approx((float(np.dot([0.0, 0.0], u)), 0.0), abs=1e-12)
    with pytest.raises(StructureError, match="no dimension places"):
        moved(ml.Linkage({"O": (0, 0), "P": (0, -2), "G": (0, 1)}, ml.Crank("O", "A", 1.0))
              .rpr("A", "P", 4.0).prp(("G", 0.0), ("P", 0.0, "PA"), "B"), "B", (1.0, 1.0), 0.0)


def test_snapping_rounds_coordinates_lengths_and_xi_eta_to_the_step():
    lk = coupler_fourbar()
    new, _ = moved(lk, "E", (4.37, 0.12), 0.0, step=0.25)
    assert dict(new.frame)["E"] == (4.25, 0.0)
    new, _ = moved(lk, "B", (2.03, 2.96), 0.0, step=0.25)
    assert [new.groups[0].first_length / 0.25 % 1, new.groups[0].second_length / 0.25 % 1] == [0.0, 0.0]
    new, _ = moved(lk, "P", (1.31, 0.74), 0.0, step=0.1)
    assert all(abs(v * 10 - round(v * 10)) < 1e-9 for v in new.groups[1].at)
    new, _ = moved(lk, "A", (0.02, 0.01), 0.0, step=0.5)   # a length never snaps to zero
    assert new.driver.radius == 0.5


def test_snapping_shows_the_grid_of_its_step():
    ed = DragEditor(coupler_fourbar(), grid=0.5, live=True)
    ticks = ed.ax.xaxis.get_minorticklocs()
    # the minor lines at the half steps (the whole numbers are the major ticks' lines)
    assert ed.snap.value and len(ticks) > 4 and np.allclose(ticks / 0.5, np.round(ticks / 0.5))
    ed.snap.value = False
    assert len(ed.ax.xaxis.get_minorticklocs()) == 0
    ed.snap.value, ed.step.value = True, 1e-4   # too fine to draw: no lines, snapping still on
    assert len(ed.ax.xaxis.get_minorticklocs()) == 0
    assert ed.move("E", (4.2, 0.0001)) and dict(ed.linkage.frame)["E"] == (4.2, 0.0001)
    plt.close("all")


def test_an_unassemblable_position_raises_the_named_error():
    with pytest.raises(AssemblyError, match="cannot close"):
        moved(coupler_fourbar(), "E", (9.0, 0.0), 0.0)   # |AE| = 8 > 3 + 3


# -- the editor --------------------------------------------------------------------------------------------------
@pytest.fixture
def editor():
    ed = DragEditor(ml.FourBar(1, 3, 3, 4), live=True)
    ed.fig.canvas.draw()
    yield ed
    plt.close("all")


def mouse(ed, name, xy, button=1):
    """A mouse event at data point ``xy`` as ipympl delivers it (figure pixels), processed by the canvas."""
    x, y = ed.ax.transData.transform(xy)
    event = MouseEvent(name, ed.fig.canvas, x, y, button=button)
    ed.fig.canvas.callbacks.process(name, event)


def key(ed, k):
    ed.fig.canvas.callbacks.process("key_press_event", KeyEvent("key_press_event", ed.fig.canvas, k))


def test_a_mouse_drag_changes_the_dimensions_and_redraws_in_place(editor):
    ed = editor
    artists = [id(a) for a in ed._moving_artists()]
    figures = plt.get_fignums()
    pixels = np.asarray(ed.fig.canvas.buffer_rgba()).copy()
    seen, dropped = [], []
    ed.on_change(lambda lk: seen.append(lk), while_dragging=True)   # each step of the drag, and the drop
    ed.on_change(lambda lk: dropped.append(lk))
    B = ed._positions()["B"]
    mouse(ed, "button_press_event", B + [0.05, 0.0])   # within the pick radius
    assert ed.joint.value == "B"
    for k in range(1, 5):
        mouse(ed, "motion_notify_event", B + [0.1 * k, 0.15 * k])
    mouse(ed, "button_release_event", B + [0.4, 0.6])
    assert np.allclose(ed._positions()["B"], B + [0.4, 0.6], atol=PIXEL)
    assert len(seen) == 5 and len(dropped) == 1 and dropped[0] is ed.linkage
    assert [id(a) for a in ed._moving_artists()][:len(artists)] == artists and plt.get_fignums() == figures
    assert (np.asarray(ed.fig.canvas.buffer_rgba()) != pixels).any(axis=-1).sum() > 100
    path = ed.curve_line.get_xydata()
    assert np.allclose(path, ed.linkage.motion(np.linspace(0, 2 * np.pi, ed.n)).points["B"].p)
    assert ed.undo() and ed.linkage == as_linkage(ml.FourBar(1, 3, 3, 4)) and not ed.undo()


def test_a_press_away_from_every_handle_grabs_nothing(editor):
    before = editor.linkage
    mouse(editor, "button_press_event", (2.0, -2.5))
    mouse(editor, "motion_notify_event", (2.5, -2.0))
    mouse(editor, "button_release_event", (2.5, -2.0))
    assert editor.linkage is before and not editor._undo


def test_an_unassemblable_drag_shows_the_named_error_and_recovers(editor):
    ed = editor
    ed.angle.value = 180   # A at (-1, 0): |AE| > 3 + 3 once E passes x = 5 (still in view)
    good = ed.linkage
    E = ed._positions()["E"]
    mouse(ed, "button_press_event", E)
    mouse(ed, "motion_notify_event", (5.1, 0.0))
    assert "cannot close" in ed.message and ed.error_text.get_visible() and not ed.ax.get_visible()
    assert ed.linkage is good                                   # the last good state kept
    mouse(ed, "motion_notify_event", E + [0.3, 0.2])            # back where it assembles: drawn again
    assert ed.message == "" and ed.ax.get_visible() and not ed.error_text.get_visible()
    mouse(ed, "motion_notify_event", (5.1, 0.0))
    mouse(ed, "button_release_event", (5.1, 0.0))               # dropped where it cannot: the last good one
    assert ed.message == "" and ed.ax.get_visible() and "not applied" in ed.status.value
    assert np.allclose(dict(ed.linkage.frame)["E"], E + [0.3, 0.2], atol=PIXEL)
    assert ed.undo() and ed.linkage is good


def test_the_keyboard_reaches_every_action(editor):
    ed = editor
    ed.joint.value = "E"
    key(ed, "left")
    assert dict(ed.linkage.frame)["E"] == pytest.approx((4.0 - ed.step.value, 0.0))
    key(ed, "shift+up")
    assert dict(ed.linkage.frame)["E"] == pytest.approx((4.0 - ed.step.value, 10 * ed.step.value))
    key(ed, "u")
    assert dict(ed.linkage.frame)["E"] == pytest.approx((4.0 - ed.step.value, 0.0))
    key(ed, "j")                                                 # the next joint: A
    assert ed.joint.value == "A"
    ed.arrows["up"].click()
    assert ed.linkage.driver.radius == pytest.approx(np.hypot(1.0, ed.step.value))
    assert ed.angle.value == round(np.degrees(np.arctan2(ed.step.value, 1.0)))
    ed.snap.value, ed.step.value = True, 0.5
    ed.joint.value = "B"
    ed.arrows["right"].click()
    assert ed.linkage.groups[0].first_length % 0.5 == 0 and ed.linkage.groups[0].second_length % 0.5 == 0
    ed.copy_button.click()
    assert ed.code_box.value == ed.code() and ed.code_box.layout.display is None
    ed.undo_button.click()
    ed.undo_button.click()
    ed.undo_button.click()
    assert ed.linkage == as_linkage(ml.FourBar(1, 3, 3, 4)) and ed.undo_button.disabled


def test_every_control_has_a_name(editor):
    ed = editor
    named = [ed.joint, ed.step, ed.snap, ed.angle, *ed.arrows.values(), ed.undo_button, ed.copy_button, ed.code_box]
    assert all(w.description.strip() for w in named)
    assert {w.description for w in ed.arrows.values()} == {"← left", "→ right", "↑ up", "↓ down"}


def test_centres_and_transmission_angle_follow_the_linkage(editor):
    ed = editor
    ed.angle.value = 60
    ic = ml.instant_centres(ed.linkage, np.radians(60))
    finite = np.array([c.h[:2] for c in ic.centres.values() if c.h[2] == 1.0])
    marks = ed.centre_marks.get_xydata()
    assert len(marks) == len(finite) == 6
    assert np.allclose(np.sort(marks, axis=0), np.sort(finite, axis=0))
    mu = np.degrees(ed.linkage.motion(np.radians(60)).transmission)
    assert f"μ = {float(mu):.1f}° at φ = 60°" in ed.status.value
    ed.move("B", ed._positions()["B"] + [0.5, 0.5])
    mu2 = np.degrees(ed.linkage.motion(np.radians(60)).transmission)
    assert f"μ = {float(mu2):.1f}° at φ = 60°" in ed.status.value and abs(mu2 - mu) > 1


def test_a_slider_crank_and_a_sixbar_are_edited_too():
    sc = DragEditor(ml.SliderCrank(1.0, 3.0, 0.4), live=True)
    assert set(handles(sc.linkage)) == {"O", "G", "A", "B"}
    assert sc.move("B", (3.4, 2.0)) and sc.linkage.groups[0].length == pytest.approx(np.hypot(3.4 - 1, 0.4))
    six = DragEditor(watt_sixbar(), point="P", live=True)
    assert six.point == "P" and len(six.centre_marks.get_xdata()) + len(six._far) == 28   # 8 links: 8·7/2
    assert six.move("D", six._positions()["D"] + [0.2, 0.1])
    plt.close("all")


def test_the_static_figure_shows_the_mechanism_and_its_coupler_curve(capsys):
    """As in the book (no live kernel): the figure is re-shown as an image, with the curve of the chosen point."""
    ed = DragEditor(coupler_fourbar(), live=False)
    assert ed.output is not None and ed.point == "P"
    want = coupler_fourbar().motion(np.linspace(0, 2 * np.pi, ed.n)).points["P"].p
    assert np.allclose(ed.curve_line.get_xydata(), want)
    assert ed.ax.get_visible() and any(line.get_visible() and len(line.get_xdata()) for line in ed.drawing.link_lines)
    with pytest.raises(StructureError, match="not a joint"):
        DragEditor(coupler_fourbar(), point="Z", live=False)
    plt.close("all")


def test_a_rocking_crank_draws_the_curve_over_its_range_and_refuses_an_unreachable_angle():
    fb = ml.FourBar(2.5, 3.0, 3.0, 4.0)   # the crank rocks (not Grashof for it)
    (lo, hi), = as_linkage(fb).crank_ranges()
    ed = DragEditor(fb, phi=0.5 * (lo + hi), live=True)
    want = as_linkage(fb).motion(np.linspace(lo + 1e-4 * (hi - lo), hi - 1e-4 * (hi - lo), ed.n)).points["B"].p
    assert np.allclose(ed.curve_line.get_xydata(), want) and "where the crank rocks" in ed.status.value
    with pytest.raises(AssemblyError, match="cannot close"):
        DragEditor(fb, phi=hi + 0.3, live=True)
    plt.close("all")


def test_a_callback_moves_an_overlay_with_the_linkage(editor):
    """As the chapter overlays its arc fit: the overlay follows every change and is drawn with the linkage."""
    ed = editor
    (mark,) = ed.ax.plot([], [], "s", color="#2a7f62", ms=12)
    ed.add_overlay(mark)
    ed.on_change(lambda lk: mark.set_data(*([v] for v in lk.motion(ed.phi).points["B"].p)))
    ed.fig.canvas.draw()
    assert mark in ed._moving_artists() and mark.get_animated()
    before = np.asarray(ed.fig.canvas.buffer_rgba()).copy()
    ed.move("B", ed._positions()["B"] + [0.3, 0.3])
    assert np.allclose(mark.get_xydata()[0], ed._positions()["B"])
    green = (np.abs(np.asarray(ed.fig.canvas.buffer_rgba())[..., :3].astype(int) - [0x2A, 0x7F, 0x62]).sum(-1) < 30)
    assert green.sum() > 50 and (green != (np.abs(before[..., :3].astype(int) - [0x2A, 0x7F, 0x62]).sum(-1) < 30)).any()


def test_the_chapter_route_a_live_arc_fit_over_the_coupler_curve_and_its_six_bar():
    """The coupler four-bar of the dwell chapter (ml.coupler_fourbar): a callback refits the best arc of P's curve
    after each drop and moves a circle over it; the dwell six-bar built from the arc opens in the editor too."""
    from matplotlib.patches import Circle

    ed = DragEditor(ml.coupler_fourbar(1.0, 3.0, 3.0, 4.0, (1.5, 1.0)), live=True)
    ring = Circle((0, 0), 1.0, fill=False, ec="#2a7f62", lw=1.5)
    ed.ax.add_patch(ring)
    ed.add_overlay(ring)
    fits = []

    def refit(lk):
        fits.append(ml.coupler_arcs(lk, "P", count=1)[0])
        ring.center, ring.radius = fits[-1].centre, fits[-1].radius

    ed.on_change(refit)
    assert ed.move("P", ed._positions()["P"] + [0.2, -0.4])
    assert ring.center == fits[-1].centre and ring.radius == fits[-1].radius
    assert fits[-1] == ml.coupler_arcs(ed.linkage, "P", count=1)[0]   # the fit of the dropped linkage
    six = DragEditor(ml.arc_dwell_sixbar(ed.linkage, "P", fits[-1]), point="P", live=True)
    dyad = [j for j in handles(six.linkage) if j not in handles(ed.linkage)]
    assert dyad and all(six.move(j, six._positions()[j] + [0.05, 0.05]) for j in dyad if j not in ("O", "E"))
    plt.close("all")


def test_a_drag_step_sends_the_frame_and_little_else(editor, monkeypatch):
    """The hidden toolbar's pointer readout is off (ipympl syncs it as a widget message per mouse move) and the status
    line is rewritten at most every STATUS_EVERY seconds while a handle is held (here: not within the drag); the
    drop writes it."""
    from mechlab.widgets import drag

    monkeypatch.setattr(drag, "STATUS_EVERY", 60.0)
    ed = editor
    canvas = ed.fig.canvas
    written = []
    ed.status.observe(lambda c: written.append(c.new), names="value")
    B = ed._positions()["B"]
    mouse(ed, "button_press_event", B)
    for k in range(1, 6):
        mouse(ed, "motion_notify_event", B + [0.02 * k, 0.0])
    assert canvas._message == "" and len(written) == 1 and written[0].startswith("coupler = 3, rocker = 3")  # B chosen
    mouse(ed, "button_release_event", B + [0.1, 0.0])
    assert f"coupler = {ed.linkage.groups[0].first_length:.4g}" in written[-1] == ed.status.value
