"""What a student sees in the explorers and animations: legends off the data, no ipympl caption, figures that
fit the notebook's output area, titles and legends in words, readouts with units, labels that do not pile up."""

import io

import matplotlib.pyplot as plt
import numpy as np
import pytest
from matplotlib.backends.backend_agg import FigureCanvasAgg
from PIL import Image

from mechlab import FourBar, SliderCrank
from mechlab.draw import LABEL_GAP, MECHANISM_NAMES, animate, animate_together, mechanism_name, plot_cam_laws
from mechlab.draw.curved_slot import animate_equivalence, plot_against_base
from mechlab.widgets import bare_canvas, fourbar_explorer

OUTPUT_AREA_PX = 880   # a notebook's output area in JupyterLab at 1280 px is about 912 px wide


def _boxes_overlap(a, b, slack: float = 1.0) -> bool:
    """True if two display boxes share more than a hairline."""
    return (min(a.x1, b.x1) - max(a.x0, b.x0)) > slack and (min(a.y1, b.y1) - max(a.y0, b.y0)) > slack


def _legends_clear(fig):
    """Every legend of ``fig``: inside the figure and over no axes (so over none of its curves)."""
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    legends = [*fig.legends, *(ax.get_legend() for ax in fig.axes if ax.get_legend() is not None)]
    assert legends, "no legend to check"
    for legend in legends:
        box = legend.get_window_extent(renderer)
        assert fig.bbox.x0 - 1 <= box.x0 and box.x1 <= fig.bbox.x1 + 1 and box.y1 <= fig.bbox.y1 + 1, \
            f"legend {[t.get_text() for t in legend.get_texts()]} leaves the figure"
        for ax in fig.axes:
            if ax.get_visible():
                assert not _boxes_overlap(box, ax.get_window_extent(renderer)), \
                    f"legend {[t.get_text() for t in legend.get_texts()]} lies over an axes"
    return legends


def test_mechanism_explorer_legend_sits_between_the_plots_not_on_a_curve():
    ex = fourbar_explorer(live=False)
    (legend,) = _legends_clear(ex.fig)
    assert [t.get_text() for t in legend.get_texts()] == ["ψ′ = dψ/dφ", "ψ″ = d²ψ/dφ²"]
    plt.close("all")


def test_the_lambda_six_bar_explorer_legend_clears_its_curves():
    from mechlab.widgets.chebyshev import mchv1_explorer
    _legends_clear(mchv1_explorer(live=False).fig)


def test_centrode_explorer_legend_is_below_the_drawing():
    from mechlab.widgets.centres import fourbar_centrode_explorer
    ex = fourbar_centrode_explorer(live=False)
    legends = _legends_clear(ex.fig)
    texts = {t.get_text() for legend in legends for t in legend.get_texts()}
    assert any("fixed centrode" in t for t in texts) and any("moving centrode" in t for t in texts)


@pytest.mark.parametrize("which", ["fourbar", "slider_crank"])
def test_equivalence_explorer_legends_clear_the_laws_and_its_title_is_words(which):
    from mechlab.widgets import equivalence
    ex = getattr(equivalence, f"{which}_equivalence")(live=False)
    assert len(_legends_clear(ex.fig)) == 3
    title = ex.ax_link.get_title()
    assert title == {"fourbar": "Four-bar linkage", "slider_crank": "Slider-crank"}[which]
    assert title != type(ex.mechanism).__name__


def test_press_explorer_torque_legend_clears_the_torque():
    from mechlab.widgets.forces import press_explorer
    ex = press_explorer(live=False)
    ex.fig.canvas.draw()
    box = ex.ax_torque.get_legend().get_window_extent()
    assert not _boxes_overlap(box, ex.ax_torque.get_window_extent())


@pytest.mark.parametrize("which", ["press_explorer", "rocker_explorer"])
def test_force_readout_stays_clear_of_the_plots_beside_it(which):
    """Chapter 11: the readout of the reactions, on the mechanism's side, ran into the torque plot's axis label
    (four reactions on one line)."""
    from mechlab.widgets import forces
    ex = getattr(forces, which)(live=False)
    for frame in (0, len(ex.result.phi) // 3):
        ex.drawing.set_frame(frame)
        ex.fig.canvas.draw()
        renderer = ex.fig.canvas.get_renderer()
        text = ex.drawing.text.get_window_extent(renderer)
        assert ex.fig.bbox.x0 <= text.x0 and text.x1 <= ex.fig.bbox.x1
        for ax in (ex.ax_torque, ex.ax_eta):
            assert not _boxes_overlap(text, ax.get_tightbbox(renderer)), f"{which}: the readout runs into a plot"
    plt.close("all")


def test_cam_law_legend_is_above_the_three_panels():
    fig = plot_cam_laws()
    (legend,) = _legends_clear(fig)
    assert len(legend.get_texts()) == len(fig.axes[0].lines)
    plt.close(fig)


def test_plot_against_base_names_the_mechanism_in_words_and_its_legend_clears_the_laws():
    axes = plot_against_base(FourBar(0.3, 0.8, 1.0, 1.0))
    (legend,) = _legends_clear(axes[0].figure)
    assert [t.get_text() for t in legend.get_texts()] == ["Four-bar linkage", "base mechanism"]
    plt.close("all")


def test_equivalence_animation_titles_say_what_is_drawn():
    from mechlab.mechanisms.sixbar_iv import example
    for mech in (FourBar(0.3, 0.8, 1.0, 1.0), example()):
        anim = animate_equivalence(mech, n=4)
        title = anim._fig.axes[0].get_title(loc="left")
        assert title.replace("\n", " ") == mechanism_name(mech) and type(mech).__name__ not in title
        plt.close(anim._fig)


def test_every_registered_name_is_words_not_a_class_name():
    for cls, name in MECHANISM_NAMES.items():
        assert name != cls and (" " in name or "-" in name), (cls, name)


def test_explorer_canvas_has_no_figure_caption():
    pytest.importorskip("ipympl")
    ex = fourbar_explorer(live=True)
    canvas = ex.fig.canvas
    assert not (canvas.header_visible or canvas.footer_visible or canvas.toolbar_visible or canvas.resizable)
    assert all(float(v).is_integer() for v in ex.fig.bbox.size)   # whole pixels, as the browser sizes the canvas
    plt.close("all")


def test_bare_canvas_hides_an_ipympl_header_however_the_figure_was_made():
    ipympl = pytest.importorskip("ipympl.backend_nbagg")
    fig = plt.figure()
    canvas = ipympl.Canvas(fig)
    assert canvas.header_visible   # ipympl's default: "Figure 1" above the plot
    bare_canvas(canvas)
    assert not (canvas.header_visible or canvas.footer_visible or canvas.toolbar_visible or canvas.resizable)
    plt.close(fig)


@pytest.fixture(scope="module")
def choosing():
    from mechlab import design
    from mechlab.widgets.design import ChoosingExplorer
    table = design.Specification("index", dwell_fraction=1.0 / 1.5, stations=6, rpm=40, inertia=2.4,
                                 max_pressure_angle=np.radians(45), max_size=600.0)
    return ChoosingExplorer(table, live=False)


def test_design_explorer_fits_the_output_area(choosing):
    fig = choosing.figure.fig
    assert round(fig.bbox.width) <= OUTPUT_AREA_PX
    assert Image.open(io.BytesIO(choosing.output.value)).size[0] <= OUTPUT_AREA_PX
    assert min(t.get_fontsize() for t in choosing.figure.radar.get_xticklabels()) >= 9   # still readable


def test_radar_labels_stand_outside_its_circle_in_the_glossary_notation(choosing):
    radar = choosing.figure.radar
    fig = radar.figure
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    box = radar.get_window_extent(renderer)
    centre = np.array([(box.x0 + box.x1) / 2, (box.y0 + box.y1) / 2])
    radius = float(np.hypot(*(radar.transData.transform((np.pi / 2, radar.get_ylim()[1])) - centre)))
    labels = radar.get_xticklabels()
    for text in labels:
        b = text.get_window_extent(renderer)
        nearest = np.clip(centre, [b.x0, b.y0], [b.x1, b.y1])   # the label's point nearest the centre
        assert np.hypot(*(nearest - centre)) >= radius - 1, f"{text.get_text()!r} overlaps the outer circle"
    words = " ".join(t.get_text() for t in labels)
    assert "$C_v$" in words and "$C_a$" in words and " B" not in words and " C\n" not in words


def test_force_plan_readout_carries_units():
    from mechlab.kinetostatics.machines import press
    anim = animate(press(), n=12)
    text = anim.drawing.text.get_text()
    assert "N·m" in text.split("\n")[0]
    parts = [part.strip() for line in text.split("\n")[1:] for part in line.split("  ") if part.strip()]
    assert len(parts) == len(anim.drawing.names) and all(part.endswith(" N") for part in parts)
    working = int(np.argmax(anim.drawing.result.reactions["O"].magnitude))   # the working stroke
    anim._func(working)
    text = anim.drawing.text.get_text()
    assert anim.drawing.result.reactions["O"].magnitude[working] >= 1000 and "e+" not in text, text
    plt.close("all")


def _number_centres(drawing):
    fig = drawing.ax.figure
    renderer = fig.canvas.get_renderer()
    boxes = [t.get_window_extent(renderer) for t in drawing.numbers if t.get_visible() and t.get_text()]
    return np.array([[(b.x0 + b.x1) / 2, (b.y0 + b.y1) / 2] for b in boxes])


def test_link_numbers_stand_apart_at_the_frames_pivot():
    """Chapter 6's lambda: the frame's number and the crank's at O drawn on top of each other without
    the separation."""
    from mechlab.synthesis.lambda_guiding import circle_guiding
    g = circle_guiding(150 * np.pi / 180, 0.9, 120 * np.pi / 180)
    for mech, figsize in ((g.guided, (4.5, 3.4)), (FourBar(1, 3, 3, 4), (6.5, 4.5)), (SliderCrank(1, 3, 0.4), (6, 3))):
        fig, ax = plt.subplots(figsize=figsize)
        anim = animate(mech, n=18, trace="D" if "D" in mech.motion(np.zeros(1)).points else None, ax=ax)
        FigureCanvasAgg(fig)   # off screen, as the animation's frames are drawn
        fig.canvas.draw()
        gap = LABEL_GAP * fig.dpi / 72
        for i in range(0, 18, 3):
            anim._func(i)
            fig.canvas.draw()
            c = _number_centres(anim.drawing)
            d = np.hypot(*(c[:, None, :] - c[None, :, :]).transpose(2, 0, 1))
            d[np.diag_indices(len(c))] = np.inf
            assert d.min() >= gap - 1.5, f"{type(mech).__name__} frame {i}: two link numbers {d.min():.1f} px apart"
        plt.close(fig)


def test_animate_together_draws_every_panel_at_one_scale():
    """The swinging type-3 six-bar sweeps a wide fan: its panel gets the width, not a smaller scale."""
    from mechlab.synthesis.lambda_guiding import straight_guiding
    from mechlab.synthesis.lambda_sixbars import mchv3_half_turn, mchv3_oscillating
    s = straight_guiding(np.pi, 0.8, np.pi)
    anim = animate_together([mchv3_oscillating(s, 0.5), mchv3_half_turn(s)], n=4, figsize=(9.6, 3.6))
    scales = []
    for d in anim.drawings:
        box = d.ax.get_window_extent()
        scales.append(box.width / np.ptp(d.ax.get_xlim()))
    assert scales[0] == pytest.approx(scales[1], rel=0.02)
    widths = [d.ax.get_window_extent().width for d in anim.drawings]
    assert widths[0] > 1.5 * widths[1]
    plt.close("all")


def test_spherical_geneva_drawing_numbers_its_links():
    from mechlab.mechanisms.spherical_geneva import SphericalGeneva
    g = SphericalGeneva(40.0, 15.0, 4)
    _fig, ax = plt.subplots()
    anim = animate(g, n=6, ax=ax)
    numbers = {k: t.get_text() for k, t in anim.drawing.numbers.items()}
    assert numbers == {k: str(v) for k, v in g.structure().numbers().items()}
    assert all(t in anim.drawing.artists for t in anim.drawing.numbers.values())
    plt.close("all")


def test_mechanism_explorer_keeps_its_legend_when_rebuilt():
    ex = fourbar_explorer(live=False)
    ex.sliders["crank"].value = 1.2
    _legends_clear(ex.fig)
    plt.close("all")


def test_comparison_table_and_rank_use_the_glossary_symbols(choosing):
    """Kinitsky's invariants B, C, D reach the student as the glossary's C_v, C_a, C_p."""
    head = choosing.comparison.rows()[0]
    assert {"C_v", "C_a", "C_p"} <= set(head) and not {"B", "C", "D"} & set(head)
    labels = [label for label, _ in choosing.rank.options]
    assert {"C_v", "C_a", "C_p"} <= set(labels) and "B" not in labels
    choosing.rank.value = "B"   # the key stays the library's: the table is ranked by C_v
    shown = [c.criteria.B for c in choosing.comparison.candidates]
    assert shown == sorted(shown)


def test_frames_are_whole_until_a_browser_shows_the_canvas():
    """Before JupyterLab's view of the canvas exists a frame may be lost: a diff over it would leave holes."""
    pytest.importorskip("ipympl")
    ex = fourbar_explorer(live=True)
    canvas = ex.fig.canvas
    sent = []
    canvas.send_binary = sent.append
    canvas.draw()   # the first drawing, no browser there yet
    for value in (10.0, 12.0):
        ex.angle.value = value
        assert canvas._current_image_mode == "full"
    canvas.syncing_data_url = False   # the browser said "initialized"
    ex.angle.value = 14.0
    assert canvas._current_image_mode == "diff" and len(sent) == 4
    plt.close("all")
