import matplotlib.pyplot as plt
import numpy as np
import pytest

from mechlab import FourBar, SineMechanism, SliderCrank, SlottedLink
from mechlab.draw import animate, animate_together, draw, drawing_class, plot_law
from mechlab.widgets import fourbar_explorer

MECHANISMS = [FourBar(1, 3, 3, 4), FourBar(3, 3, 3, 4, -1), SliderCrank(1, 3, 0.4), SlottedLink(0.5, 1.0),
              SlottedLink(2.0, 1.0), SineMechanism(1.0)]


@pytest.mark.parametrize("mech", MECHANISMS, ids=lambda m: type(m).__name__)
def test_frames_move_the_same_artists(mech):
    fig, ax = plt.subplots()
    drawing = drawing_class(mech)(ax, mech, trace="A")
    before = [id(a) for a in drawing.artists]
    n_children = len(ax.get_children())
    for i in range(0, drawing.n, 30):
        drawing.set_frame(i)
        A = drawing.motion.points["A"].p[i]
        xs, ys = drawing.link_lines[0].get_data()
        assert np.allclose([xs[-1], ys[-1]], A)  # the crank line ends at the pin
    assert [id(a) for a in drawing.artists] == before
    assert len(ax.get_children()) == n_children
    plt.close(fig)


def test_animation_plays_as_javascript_and_loads_nothing_remote():
    anim = animate(FourBar(1, 3, 3, 4), n=6, trace="B")
    html = anim.to_jshtml()
    assert html.count("data:image/png;base64") == 6 or "frames[5]" in html
    assert "//" not in html.replace("data:image", "").split("<script")[0]  # no remote stylesheet before the script
    assert "font-awesome" not in html and 'class="fa ' not in html
    assert 'class="mechlab-icon mechlab-play"' in html and ".mechlab-play::before" in html


def test_animate_together_moves_each_panel_to_the_same_crank_angle():
    mechs = [FourBar(1, 3, 3, 4), SliderCrank(1, 3), FourBar(1, 3, 3, 4, assembly=-1)]
    anim = animate_together(mechs, titles=["+1", "slider", "-1"], n=8)
    assert [d.mechanism for d in anim.drawings] == mechs
    assert [d.ax.get_title() for d in anim.drawings] == ["+1", "slider", "-1"]
    anim._func(3)
    for d in anim.drawings:
        xs, ys = d.link_lines[0].get_data()  # the crank of every panel at frame 3
        assert np.allclose([xs[-1], ys[-1]], d.motion.points["A"].p[3])
        assert d.motion.phi[3] == anim.drawings[0].motion.phi[3]
    assert anim.to_jshtml().count("mechlab-play") >= 1


def test_draw_and_plot_law():
    d = draw(SliderCrank(1, 3), phi=0.5)
    assert np.allclose(d.motion.points["A"].p[0], [np.cos(0.5), np.sin(0.5)])
    lines = plot_law(FourBar(1, 3, 3, 4).motion(np.linspace(0, 6, 50)))
    assert len(lines) == 3
    plt.close("all")


def test_explorer_shows_a_bad_geometry_as_a_message_and_recovers():
    ex = fourbar_explorer()
    n_figs = len(plt.get_fignums())
    artists = [id(a) for a in ex.drawing.artists]
    ex.sliders["crank"].value = 2.5  # non-Grashof for the crank: rocks, still drawable
    assert ex.message == "" and not ex.mechanism.can_turn
    ex.sliders["ground"].value = 9.9  # |AE| ≥ 7.4 > coupler + rocker = 6: cannot assemble
    assert "cannot be assembled" in ex.message
    assert ex.error_text.get_visible() and not ex.ax_mech.get_visible()
    ex.sliders["ground"].value = 4.0
    ex.sliders["crank"].value = 1.0
    assert ex.message == "" and ex.mechanism.can_turn
    assert ex.ax_mech.get_visible() and not ex.error_text.get_visible()
    ex.angle.value = 90.0
    A = ex.drawing.link_lines[0].get_data()
    assert np.allclose([A[0][-1], A[1][-1]], [0.0, 1.0], atol=0.02)
    assert [id(a) for a in ex.drawing.artists] == artists
    assert len(plt.get_fignums()) == n_figs  # no new figure per slider move
    ex.sliders["assembly"].value = -1
    assert np.all(ex.motion.psi < 0)


def test_live_explorer_blits_the_crank_and_redraws_on_new_lengths():
    """On its own canvas the crank moves by blitting: the pixels change where the crank is."""
    ex = fourbar_explorer(live=True)
    canvas = ex.fig.canvas
    canvas.draw()
    assert ex._background is not None
    before = np.asarray(canvas.buffer_rgba()).copy()
    ex.angle.value = 180.0
    after = np.asarray(canvas.buffer_rgba()).copy()
    assert (before != after).any(axis=-1).sum() > 100  # the links moved on screen
    assert all(a.get_animated() for a in ex._moving_artists())
    ex.sliders["rocker"].value = 3.3
    canvas.draw()
    assert ex.message == "" and ex.mechanism.rocker == pytest.approx(3.3)


def test_the_canvas_frames_sent_to_the_browser_rebuild_its_image_exactly():
    """The full image, then diffs cropped at their last changed pixel, painted over it at the
    top-left corner as ipympl's browser side does, give the canvas's own pixels, every step."""
    import io

    from PIL import Image
    pytest.importorskip("ipympl")
    ex = fourbar_explorer(live=True)
    canvas = ex.fig.canvas
    canvas.syncing_data_url = False   # as with JupyterLab connected
    sent = []
    canvas.send_binary = sent.append
    canvas.draw()
    screen = np.asarray(Image.open(io.BytesIO(sent[-1]))).copy()
    assert canvas._current_image_mode == "full" and screen.shape[:2] == canvas.get_renderer().buffer_rgba().shape[:2]
    sizes = []
    for value in (10.0, 12.0, 200.0, 202.0, 0.0):
        ex.angle.value = value
        diff = np.asarray(Image.open(io.BytesIO(sent[-1])))
        assert canvas._current_image_mode == "diff"
        h, w = diff.shape[:2]
        drawn = diff[..., 3] > 0
        screen[:h, :w][drawn] = diff[drawn]
        assert np.array_equal(screen, np.asarray(canvas.get_renderer().buffer_rgba()))
        sizes.append((h, w))
    assert min(h * w for h, w in sizes) < screen.shape[0] * screen.shape[1]   # cropped when it can be
    plt.close("all")


def test_a_crank_key_press_costs_the_kernel_one_request_and_no_echo():
    """The play button drives the slider in the browser (no message back per key press) and
    starts where the slider is; the kernel does not echo the crank angle back."""
    from ipywidgets.widgets.widget import _instances
    from ipywidgets.widgets.widget_link import DirectionalLink, Link
    ex = fourbar_explorer(live=True)
    links = [w for w in _instances.values()
             if isinstance(w, Link) and w.source == (ex.play, "value") and w.target == (ex.angle, "value")]
    assert len(links) == 1 and isinstance(links[0], DirectionalLink)
    assert ex.angle.trait_metadata("value", "echo_update") is False
    assert ex.sliders["crank"].trait_metadata("value", "echo_update") is None   # other sliders keep theirs
    ex.angle.value = 100.0
    assert ex.play.value == 100
    ex.angle.value = 360.0
    assert ex.play.value == ex.play.max
    plt.close("all")


def test_choice_controls_reach_the_factory():
    from mechlab.widgets import Choice, Control, MechanismExplorer
    seen = []

    def factory(crank, assembly_kind):
        seen.append(assembly_kind)
        return FourBar(crank, 3, 3, 4, 1 if assembly_kind == "open" else -1)
    ex = MechanismExplorer(factory, {"crank": Control("crank", 0.5, 1.5, 0.1, 1.0, "mm"),
                                     "assembly_kind": Choice("branch", ("open", "crossed"), "open")}, live=True)
    ex.sliders["assembly_kind"].value = "crossed"
    assert seen[-1] == "crossed" and ex.mechanism.assembly == -1


# -- labelled kinematic diagrams -------------------------------------------------------------

def _families():
    from mechlab import ExternalGeneva, curved_slot_dwell
    from mechlab.mechanisms.sixbar_iv import example
    from mechlab.synthesis.lambda_guiding import circle_guiding
    from mechlab.synthesis.lambda_sixbars import mchv1
    return [*MECHANISMS, ExternalGeneva(4, 100.0), curved_slot_dwell(0.5, 1.0, 2.6), example(),
            mchv1(circle_guiding(np.radians(150), 0.9, np.radians(120)), 1.0, np.radians(20))]


@pytest.mark.parametrize("mech", _families(), ids=lambda m: type(m).__name__)
def test_labels_sit_at_their_joints_in_every_frame_and_move_in_place(mech):
    fig, ax = plt.subplots()
    drawing = drawing_class(mech)(ax, mech, n=25, readout=True)
    children = [id(a) for a in ax.get_children()]
    names = set(drawing.motion.points)
    assert set(drawing.letters) == names   # one letter per joint, named as the course names it
    parts = len(drawing.numbered_parts(0))
    assert [t.get_visible() for t in drawing.numbers] == [True] * (parts + 1)   # the moving links and the frame
    for i in range(drawing.n):
        drawing.set_frame(i)
        for name in names:   # the letter is anchored at its joint, offset a few points away from it
            assert np.allclose(drawing.letters[name].xy, drawing.motion.points[name].p[i])
            assert 5 < np.hypot(*drawing.letters[name].get_position()) < 20
        numbers = [t.get_text() for t in drawing.numbers[:parts + 1]]
        labelled = any(isinstance(p.number, str) for p in drawing.sketch.parts)   # a family's own numbering
        assert numbers == [str(k) for k in range(1, parts + 2)] or labelled
        assert drawing.readout.get_text() == f"φ = {np.degrees(drawing.motion.phi[i]):.0f}°"
        # the hatched support: a triangle with its apex at each fixed pivot
        xs, ys = drawing.ground_line.get_data()
        apexes = {(round(x, 9), round(y, 9)) for x, y in zip(xs, ys, strict=False)}
        for pivot in mech.pivots:
            x, y = drawing.motion.points[pivot].p[i]
            assert (round(x, 9), round(y, 9)) in apexes
    assert [id(a) for a in ax.get_children()] == children   # set_frame created no artist
    plt.close(fig)


def test_link_numbers_follow_the_mechanism_and_lengths_are_labelled():
    fb = FourBar(1, 3, 3, 4)
    d = draw(fb, phi=0.5, dimensions=True)
    texts = [t.get_text() for t in d.numbers if t.get_visible()]
    assert texts == ["1", "2", "3", "4"]   # crank, coupler, rocker, and the frame (Kozhevnikov's numbering)
    assert [t.get_text() for t in d.lengths] == ["OA = 1", "AB = 3", "BE = 3"]
    mid = (d.motion.points["A"].p[0] + d.motion.points["B"].p[0]) / 2
    assert np.allclose(d.numbers[1].xy, mid)   # the coupler's number at its middle
    assert not d.ax.axison   # a diagram: no ticks, the letters say what it shows
    sc = draw(SliderCrank(1, 3, 0.4))
    assert [t.get_text() for t in sc.numbers if t.get_visible()] == ["1", "2", "3", "4"]   # the slider is 3
    block = sc.extras(0)[1]
    assert np.allclose(sc.numbers[2].xy, block[:-1].mean(axis=0))
    plt.close("all")


def test_labels_can_be_switched_off():
    d = draw(FourBar(1, 3, 3, 4), labels=False)
    assert d.letters == {} and not any(t.get_visible() for t in d.numbers)
    plt.close("all")


# -- animations: wide enough, small enough, a marker on the law -------------------------------

def _frames(html):
    import base64
    import io
    import re

    from PIL import Image
    return [Image.open(io.BytesIO(base64.b64decode(f.replace("\\\n", ""))))
            for f in re.findall(r'data:image/png;base64,([^"]+)"', html)]


@pytest.mark.parametrize("figsize, dpi", [((4.5, 3.4), 55), ((12, 4), 100), ((6.5, 4.5), 100)])
def test_animation_frames_fit_the_book_column_and_are_quantised(figsize, dpi):
    from mechlab.draw import MAX_WIDTH_PX, MIN_WIDTH_PX, PALETTE
    _fig, ax = plt.subplots(figsize=figsize, dpi=dpi)
    anim = animate(FourBar(1, 3, 3, 4), n=4, ax=ax)
    frames = _frames(anim.to_jshtml())
    assert len(frames) == 4
    for frame in frames:
        assert MIN_WIDTH_PX <= frame.size[0] <= MAX_WIDTH_PX
        assert frame.mode == "P" and len(frame.getcolors()) <= PALETTE
    assert frames[0].tobytes() != frames[1].tobytes()   # the frames differ: the crank moved


def test_animation_with_the_law_moves_a_marker_along_psi_in_step():
    fb = FourBar(1, 3, 3, 4)
    anim = animate(fb, n=12, law=True)
    for i in (0, 5, 11):
        anim._func(i)
        phi = anim.drawing.motion.phi[i]
        x, y = anim.marker.get_data()
        assert x[0] == pytest.approx(np.degrees(phi))
        assert y[0] == pytest.approx(np.degrees(np.unwrap(anim.drawing.motion.psi))[i])
        assert anim.drawing.readout.get_text() == f"φ = {np.degrees(phi):.0f}°"
    law_ax = anim.marker.axes
    assert "degrees" in law_ax.get_xlabel() and "degrees" in law_ax.get_ylabel()


def test_plot_law_names_quantity_and_unit():
    fig, axes = plt.subplots(3, 1)
    plot_law(SliderCrank(1, 3).motion(np.linspace(0, 6, 20)), axes)
    assert [a.get_ylabel().split(" ")[0] for a in axes] == ["s", "s′", "s″"]
    assert all("(" in a.get_ylabel() for a in axes) and "degrees" in axes[-1].get_xlabel()
    plt.close(fig)


# -- explorers ------------------------------------------------------------------------------

def _explorers():
    from mechlab.widgets.centres import antiparallelogram_explorer, fourbar_centrode_explorer, trammel_explorer
    from mechlab.widgets.chebyshev import lambda_explorer, mchv1_explorer
    from mechlab.widgets.chebyshev_sliders import mchv2_explorer, mchv5_explorer
    from mechlab.widgets.dwell import dwell_explorer
    from mechlab.widgets.equivalence import fourbar_equivalence, slider_crank_equivalence
    from mechlab.widgets.forces import press_explorer, rocker_explorer
    from mechlab.widgets.geneva import planar_geneva_explorer, spherical_geneva_explorer
    return [fourbar_explorer, fourbar_centrode_explorer, trammel_explorer, antiparallelogram_explorer,
            lambda_explorer, mchv1_explorer, mchv2_explorer, mchv5_explorer, dwell_explorer, fourbar_equivalence,
            slider_crank_equivalence, press_explorer, rocker_explorer, planar_geneva_explorer,
            spherical_geneva_explorer]


@pytest.mark.parametrize("make", _explorers(), ids=lambda f: f.__name__)
def test_every_explorer_asks_its_question_and_every_key_press_moves_the_crank(make):
    ex = make(question="find the largest dwell <for which> the pressure angle stays under 45°")
    assert ex.question.value.startswith("<b>Investigate:</b> find the largest dwell &lt;for which&gt;")
    assert ex.widget.children[0] is ex.question   # above the controls
    assert make().question.value == ""
    title = ex.fig._suptitle.get_text() if ex.fig._suptitle else ""
    assert "seed" not in title.lower()
    assert ex.message == "", ex.message
    # the slider steps by the sampling step: each step lands on a new sample
    assert ex.angle.step == pytest.approx(360.0 / (ex.n - 1))
    frames = set()
    for k in range(6):
        ex.angle.value = 90.0 + k * ex.angle.step
        frames.add(ex.frame)
    assert len(frames) == 6
    w = ex.fig.get_figwidth() * ex.fig.dpi
    assert w >= 600, w   # at least 600 px wide in the book and in JupyterLab
    plt.close("all")


def test_sliders_show_whole_numbers_as_integers_and_say_no_mm_for_dimensionless_lengths():
    from mechlab.widgets.equivalence import fourbar_equivalence
    from mechlab.widgets.geneva import planar_geneva_explorer
    g = planar_geneva_explorer()
    z, c = g.sliders["z"], g.sliders["centre_distance"]
    assert type(z).__name__ == "IntSlider" and z.value == 4 and z.description == "slots z"
    assert type(c).__name__ == "IntSlider" and c.value == 100 and c.description.endswith("(mm)")
    assert isinstance(g.mechanism.z, int)
    for ex in (fourbar_explorer(), fourbar_equivalence()):
        assert not any("mm" in w.description for w in ex.sliders.values())
    fb = fourbar_explorer()
    assert fb.sliders["crank"].readout_format == ".2f"
    assert fb.ax_law.get_ylabel() == "output ψ (degrees)" and "degrees" in fb.ax_rate.get_xlabel()
    plt.close("all")


def test_equivalence_status_names_both_analogs():
    from mechlab.widgets.equivalence import fourbar_equivalence, slider_crank_equivalence
    assert "peak |ψ′|" in fourbar_equivalence().status.value and "peak |ψ″|" in fourbar_equivalence().status.value
    assert "peak |s″|" in slider_crank_equivalence().status.value
    plt.close("all")


def test_force_explorer_shows_a_zero_speed_in_place_and_recovers():
    from mechlab.widgets.forces import press_explorer
    ex = press_explorer()
    ex.sliders["rpm"].value = 0   # the drive's figures need ω1 ≠ 0: a DriveError, shown, not raised
    assert "ω1" in ex.message and ex.error_text.get_visible() and not ex.ax_mech.get_visible()
    assert "ω1" in ex.status.value
    ex.sliders["rpm"].value = 100
    assert ex.message == "" and ex.ax_mech.get_visible() and ex.system.omega1 == pytest.approx(100 * np.pi / 30)
    plt.close("all")


def test_explorer_mechanism_fills_its_axes():
    ex = fourbar_explorer()
    ex.fig.canvas.draw()
    box = ex.ax_mech.get_position()
    grid = ex.ax_mech.get_subplotspec().get_position(ex.fig)
    assert box.width == pytest.approx(grid.width, rel=0.02) and box.height == pytest.approx(grid.height, rel=0.02)
    x0, x1, y0, y1 = ex.drawing.bounds(margin=0.0)
    (vx0, vx1), (vy0, vy1) = ex.ax_mech.get_xlim(), ex.ax_mech.get_ylim()
    # the mechanism spans most of the view in the direction that limits it
    assert max((x1 - x0) / (vx1 - vx0), (y1 - y0) / (vy1 - vy0)) > 0.6
    plt.close("all")



def test_dwell_explorer_gives_the_mechanism_a_column_of_its_proportions():
    """The curved-slot link swings through its law: the drawing over the turn is about as tall as wide, and
    its column has those proportions, so that the view is filled in both directions (not a wide band)."""
    from mechlab.widgets.dwell import dwell_explorer

    ex = dwell_explorer(lam=0.5, phi1_deg=60, phi2_deg=150, roller_radius=0.05)
    ex.fig.canvas.draw()
    x0, x1, y0, y1 = ex.drawing.bounds(margin=0.0)
    (vx0, vx1), (vy0, vy1) = ex.ax_mech.get_xlim(), ex.ax_mech.get_ylim()
    across, up = (x1 - x0) / (vx1 - vx0), (y1 - y0) / (vy1 - vy0)
    assert min(across, up) > 0.85 * max(across, up) and max(across, up) > 0.6, (across, up)
    box = ex.ax_mech.get_window_extent()
    # pixels per unit length at the explorer's 80 dpi (110 with the common layout)
    assert box.width / (vx1 - vx0) > 135
    plt.close("all")

@pytest.mark.parametrize("law", [False, True])
def test_blitted_frames_match_a_full_drawing_of_the_same_frame(law):
    """The static background is drawn once; each frame must still look as if drawn whole."""
    import io

    from PIL import Image

    from mechlab.draw import frame_dpi
    anim = animate(FourBar(1, 3, 3, 4), n=6, trace="B", law=law)
    frames = _frames(anim.to_jshtml())
    fig = anim._fig
    for k in (1, 4):
        anim._func(k)
        whole = io.BytesIO()
        fig.savefig(whole, format="png", dpi=frame_dpi(fig))
        full = np.asarray(Image.open(whole).convert("L"), dtype=float)
        blitted = np.asarray(frames[k].convert("L"), dtype=float)
        assert full.shape == blitted.shape
        differ = np.abs(full - blitted) > 40   # more than the palette's rounding
        assert differ.mean() < 0.003, differ.mean()
    plt.close("all")


def test_force_explorer_greys_and_names_where_efficiency_is_undefined():
    from mechlab.widgets.forces import press_explorer
    ex = press_explorer(f=0.1)
    undefined = np.ma.getmaskarray(ex.result.efficiency())
    assert 0 < undefined.sum() < len(undefined)   # the press's inertia drives the crank over part of the turn
    # the grey spans cover the masked angles and none of the others
    deg = np.degrees(ex.result.phi)
    grey = np.array([any(p.contains_point((d, 0.5)) for p in ex._undefined.get_paths()) for d in deg])
    assert np.array_equal(grey, undefined)
    assert "undefined" in ex.ax_eta.get_legend().get_texts()[0].get_text()
    ex.sliders["P"].value = 10000.0   # a rebuild replaces the spans, it does not stack them
    assert sum(isinstance(c, type(ex._undefined)) for c in ex.ax_eta.collections) == 1
    plt.close("all")


def test_plot_efficiency_draws_eta_whole_where_defined_and_greys_the_rest():
    from mechlab.draw.forces import UNDEFINED_LABEL, plot_efficiency
    from mechlab.kinetostatics.machines import press
    k = press(f=0.1, radius=0.01)
    res = k.forces(motion=k.motion(k.cycle(121)))
    ax = plot_efficiency(res)
    line = ax.get_lines()[0]
    eta = res.efficiency()
    defined = ~np.ma.getmaskarray(eta)
    assert np.array_equal(np.isfinite(line.get_ydata()), defined)
    assert np.allclose(line.get_ydata()[defined], eta.data[defined])
    assert [c.get_label() for c in ax.collections] == [UNDEFINED_LABEL]
    assert "degrees" in ax.get_xlabel() and "η" in ax.get_ylabel()
    plt.close("all")


def test_plot_cam_laws_draws_each_law_normalised():
    from mechlab.analysis.motion_laws import LAWS
    from mechlab.draw import plot_cam_laws
    from mechlab.errors import MechanismError

    fig = plot_cam_laws(n=51)
    try:
        lift, velocity, acceleration = fig.axes
        assert [line.get_label() for line in lift.lines] == list(LAWS)
        for line in lift.lines:            # every law rises from 0 to the stroke over the interval
            x, y = line.get_data()
            assert len(x) == 51 and y[0] == pytest.approx(0, abs=1e-12) and y[-1] == pytest.approx(1)
        assert "Y″" in acceleration.get_ylabel() and "Φ" in velocity.get_xlabel()
    finally:
        plt.close(fig)
    with pytest.raises(MechanismError, match="law names"):
        plot_cam_laws(["trapezoid?"])
    with pytest.raises(MechanismError, match="n"):
        plot_cam_laws(n=1)


def test_plot_cam_undercut_shows_each_curvature_and_zooms_on_the_fold():
    import mechlab as ml
    from mechlab.draw import plot_cam_undercut
    from mechlab.errors import MechanismError

    deg = np.pi / 180
    fine = ml.TranslatingRollerCam(ml.CamProgramme(stroke=20.0, rise=120 * deg, ret=100 * deg, outer_dwell=40 * deg),
                                   base_radius=40.0, roller_radius=10.0)
    sharp = ml.TranslatingRollerCam(ml.CamProgramme(stroke=30.0, rise=40 * deg, ret=40 * deg), base_radius=15.0,
                                    roller_radius=11.0)
    fig = plot_cam_undercut({"fine": fine, "sharp": sharp}, sharp, n=721)
    left, right = fig.axes[:2]
    assert len(left.lines) == 4 and left.get_ylim()[1] > 3 * 11 and "degrees" in left.get_xlabel()
    zoom = right.child_axes[0]
    cut = sharp.undercut()
    surface = sharp.profile(721, check=False).surface
    inside = ((surface[:, 0] >= zoom.get_xlim()[0]) & (surface[:, 0] <= zoom.get_xlim()[1])
              & (surface[:, 1] >= zoom.get_ylim()[0]) & (surface[:, 1] <= zoom.get_ylim()[1]))
    theta = np.linspace(0, 2 * np.pi, 721)
    assert inside[(theta >= cut.where.min()) & (theta <= cut.where.max())].all()   # the whole fold is framed
    assert inside.mean() < 0.2                                                       # and little else
    plt.close(fig)
    with pytest.raises(MechanismError, match="no fold"):
        plot_cam_undercut({"fine": fine}, fine)
    with pytest.raises(MechanismError, match="cams"):
        plot_cam_undercut({}, sharp)


def test_force_plots_draw_the_results_they_are_given():
    from mechlab.draw.forces import (
        plot_drive,
        plot_efficiency,
        plot_reaction_against_transmission,
        plot_torque_and_reactions,
    )
    from mechlab.kinetostatics.drive import drive
    from mechlab.kinetostatics.machines import press, rocker_drive
    from mechlab.kinetostatics.solve import virtual_work_torque

    k = press(f=0.1, radius=0.01)
    mo = k.motion(k.cycle(121))
    res = k.forces(motion=mo)
    vw = virtual_work_torque(k.model, mo, k.loads, k.omega1)
    fig = plot_torque_and_reactions(res, power_balance=vw)
    torque, reactions = fig.axes
    assert np.allclose(torque.lines[0].get_xydata(), np.column_stack([np.degrees(res.phi), res.torque]))
    assert np.allclose(torque.lines[1].get_ydata(), vw) and "N·m" in torque.get_ylabel()
    assert [line.get_label() for line in reactions.lines] == ["|R| in O", "|R| in A", "|R| in B", "|N| in the guide"]
    assert np.allclose(reactions.lines[1].get_ydata(), res.reactions["A"].magnitude)
    assert np.allclose(reactions.lines[3].get_ydata(), np.abs(res.reactions["guide"].normal))
    assert ", N" in reactions.get_ylabel()

    ax = plot_efficiency(res, levels={"mean η": 0.7, "energy ratio": 0.8})
    levels = [line for line in ax.get_lines() if line.get_label().startswith(("mean", "energy"))]
    assert [(line.get_label(), line.get_ydata()[0]) for line in levels] == [("mean η = 0.700", 0.7),
                                                                           ("energy ratio = 0.800", 0.8)]

    kf = rocker_drive()
    mo4 = kf.motion(kf.turn(91))
    r4 = kf.forces(motion=mo4)
    ax = plot_reaction_against_transmission(mo4, {"with masses": r4}, "B")
    assert np.allclose(ax.lines[0].get_xydata(),
                       np.column_stack([np.degrees(mo4.transmission), r4.reactions["B"].magnitude]))
    assert "μ, degrees" in ax.get_xlabel() and ax.get_ylabel() == "|R_B|, N"

    d = drive(res.torque, res.phi, k.omega1, efficiency=0.9)
    ax = plot_drive(d)
    assert np.allclose(ax.lines[0].get_ydata(), d.torque) and np.allclose(ax.lines[1].get_ydata(), d.motor_torque)
    assert not np.allclose(d.torque, d.motor_torque)        # η shows: the dashed line is the motor's
    assert "N·m" in ax.get_ylabel() and "degrees" in ax.get_xlabel()
    plt.close("all")


def test_plot_existence_map_draws_the_map_and_the_transmission_lines():
    from mechlab.draw import plot_existence_map
    from mechlab.synthesis.lambda_guiding import existence_map

    deg = np.pi / 180
    em = existence_map(150 * deg, dwells=(60 * deg, 180 * deg), n=3)
    fig = plot_existence_map(em, 150 * deg, course=(40 * deg, 140 * deg))
    (ax,) = fig.axes
    labels = [line.get_label() for line in ax.lines]
    assert {"2α = 60°", "2α = 180°", "μ = 40°, 140° (course)"} <= set(labels)
    assert np.allclose(ax.lines[labels.index("2α = 180°")].get_xydata(), np.column_stack(em.iso_dwell[180]))
    r, a = ax.lines[labels.index("μ = 40°, 140° (course)")].get_data()
    assert np.allclose(a - r, 2 * np.sin(20 * deg))              # μ_min = 40°: a − r = 2 sin(μ/2)
    assert np.allclose(ax.patches[0].get_xy(), np.column_stack(em.region))    # the region is closed
    assert "150°" in ax.get_title() and "l_OA" in ax.get_xlabel()
    assert len(plot_existence_map(em, 150 * deg, course=None).axes[0].lines) == len(labels) - 2
    plt.close("all")


def test_plot_pressure_angles_draws_each_transition_over_the_turn_and_shades_the_dwell():
    from mechlab.draw import plot_pressure_angles
    from mechlab.synthesis.dwell_slot import TRANSITIONS, curved_slot_dwell

    deg = np.pi / 180
    fig = plot_pressure_angles(0.4, 50 * deg, 140 * deg, pivot_distance=2.0, n=181)
    (ax,) = fig.axes
    assert [line.get_label() for line in ax.lines] == list(TRANSITIONS)
    phi = np.linspace(0.0, 2 * np.pi, 181)
    for line, tr in zip(ax.lines, TRANSITIONS, strict=False):
        theta = curved_slot_dwell(0.4, 50 * deg, 140 * deg, 2.0, tr).motion(phi).pressure_angle
        assert np.allclose(line.get_xdata(), np.degrees(phi)) and np.allclose(line.get_ydata(), np.degrees(theta))
    spans = sorted(p.get_x() for p in ax.patches), sorted(p.get_x() + p.get_width() for p in ax.patches)
    assert np.allclose(spans, [[50, 220], [140, 310]])   # the dwell and its mirror 360° - φ
    assert "degrees" in ax.get_xlabel() and "degrees" in ax.get_ylabel()
    plt.close(fig)


def test_plot_slot_draws_the_profile_in_units_of_the_pivot_distance():
    from mechlab.draw import plot_slot
    from mechlab.synthesis.dwell_slot import curved_slot_dwell
    from mechlab.synthesis.slot_export import slot_profile

    deg = np.pi / 180
    cut = curved_slot_dwell(0.5, 60 * deg, 150 * deg, pivot_distance=120.0, transition="quintic", roller_radius=8.0)
    fig = plot_slot(cut)
    centre, arc, left, right = (np.stack(line.get_data(), -1) for line in fig.axes[0].lines[:4])
    prof = slot_profile(cut)
    assert np.allclose(centre * 120.0, prof.centre) and np.allclose(left * 120.0, prof.left)
    assert np.allclose(right * 120.0, prof.right)
    # the dwell arc: radius l_OA about O, in units of l_OB that is λ
    assert np.allclose(np.hypot(*(arc - cut.law.centre_in_link() / 120.0).T), 0.5)
    assert "l_{OB}" in fig.axes[0].get_xlabel() and "l_{OB}" in fig.axes[0].get_ylabel()
    plt.close(fig)


def test_comparison_cuts_an_axis_that_one_spike_would_squash_and_says_so():
    import mechlab.draw.geneva as G
    from mechlab import ExternalGeneva, InternalGeneva

    class Scaled:
        """The external Geneva with its analogs ``k`` times larger."""
        def __init__(self, k):
            self.g, self.k = ExternalGeneva(4, 1.0), k

        def motion(self, phi):
            from dataclasses import replace
            mo = self.g.motion(phi)
            return replace(mo, dpsi=self.k * mo.dpsi, ddpsi=self.k * mo.ddpsi)

    rows = G.compare   # the legend's rows: the external Geneva's for every curve (the scaled ones' are moot)
    G.compare = lambda ms, **kw: rows({k: ExternalGeneva(4, 1.0) for k in ms}, **kw)
    peak = ExternalGeneva(4, 1.0).max_acceleration()
    try:
        _, axes = plt.subplots(2, 1)
        G.plot_comparison({"a": Scaled(1.0), "b": Scaled(0.8), "c": InternalGeneva(4, 1.0)}, axes=axes)
        assert axes[1].get_ylim()[1] >= peak and not axes[1].texts     # nothing dwarfs the others: no cut
        _, axes = plt.subplots(2, 1)
        G.plot_comparison({"spike": Scaled(10.0), "a": Scaled(1.0), "c": InternalGeneva(4, 1.0)}, axes=axes)
    finally:
        G.compare = rows
        plt.close("all")
    top = axes[1].get_ylim()[1]
    assert peak <= top < 2 * peak                                   # cut near the others' peak, not the spike's
    texts = [t.get_text() for t in axes[1].texts]
    assert any(t.startswith("spike: +") and t.endswith("(cut)") for t in texts)
    assert f"{10 * peak:+.1f}" in " ".join(texts)
