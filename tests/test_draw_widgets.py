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
