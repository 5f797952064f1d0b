"""Figures every student can read (issue 29): alternative text made where the figure is made and
true to its numbers; categorical colours that stay apart for protanopes and deuteranopes, with a
second channel (marker, dash) wherever colour separates categories."""

import itertools
import re

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt
import numpy as np
import pytest

import mechlab.design as D
from mechlab import ExternalGeneva, FourBar
from mechlab.draw import OUTCOME_STYLE, alt_text, animate, draw, plot_design_outcomes, plot_law
from mechlab.draw.access import CATEGORY_COLOURS, CVD_MATRICES, delta_e, install_alt_text, set_alt, simulate_cvd
from mechlab.draw.design import STYLES, comparison_figure
from mechlab.errors import MechanismError
from mechlab.synthesis.lambda_guiding import design_outcomes

DEG = np.pi / 180
# CIE76 ΔE between two categories' colours as a protanope or deuteranope sees them; matplotlib's old
# tab10 falls to 4.6 (orange and green, protan), Okabe-Ito keeps above 17
MIN_DELTA_E = 15.0


def test_a_diagram_says_what_it_shows_and_follows_the_numbers():
    fb = FourBar(1, 3, 3, 4, 1)
    first, second = draw(fb, 0.3, trace="B"), draw(fb, 1.2)
    text = alt_text(first.ax.figure)
    assert text.startswith("Kinematic diagram of a four bar with joints O, A, B")
    assert f"φ = {np.degrees(0.3):.0f}°" in text and "path of joint B" in text
    assert f"φ = {np.degrees(1.2):.0f}°" in alt_text(second.ax.figure)
    plt.close("all")


def test_an_animation_carries_its_alt_text_in_the_page():
    geneva = ExternalGeneva(4, 1.0)
    html = animate(geneva, n=8, law=True).to_jshtml()
    alt = re.search(r'<img alt="([^"]+)" id="_anim_img', html).group(1)
    stroke = np.ptp(np.degrees(np.unwrap(geneva.motion(geneva.cycle(361)).output.value)))
    assert "external geneva" in alt and "Animation of 8 frames" in alt
    assert f"a stroke of {stroke:.3g}" in alt   # a Geneva of 4 slots turns its wheel by 90°
    assert round(stroke) == 90
    # its frame slider has an accessible name (axe-core's "label" rule), given once
    assert html.count('aria-label="Frame of the animation"') == 1 == html.count('class="anim-slider"')
    from mechlab.draw import local_animation_controls
    assert local_animation_controls(html).count('aria-label="Frame of the animation"') == 1
    # its repetition-mode form (a landmark) is named after its subject: two animations on a page differ
    other = animate(FourBar(1, 3, 3, 4, 1), n=8).to_jshtml()
    modes = [re.findall(r'<form[^>]*aria-label="([^"]+)"', page) for page in (html, other)]
    assert [len(m) for m in modes] == [1, 1] and modes[0] != modes[1], modes
    assert modes[0][0].startswith("Repetition mode of: ") and "geneva" in modes[0][0].lower(), modes
    plt.close("all")


def test_a_law_plot_states_its_ranges():
    fb = FourBar(1, 3, 3, 4, 1)
    mo = fb.motion(np.linspace(0, 2 * np.pi, 200))
    lines = plot_law(mo)
    psi = np.degrees(np.unwrap(mo.output.value))
    assert f"from {psi.min():.3g} to {psi.max():.3g}" in alt_text(lines[0].figure)
    plt.close("all")


def test_the_outcome_map_counts_its_kinds():
    m = design_outcomes(150 * DEG, fractions=(0.0, 0.5, 1.0), dwells=(60 * DEG, 180 * DEG, 2 * np.pi))
    fig = plot_design_outcomes(m)
    text = alt_text(fig)
    # 3 × 3 requests: six frames off the span, two designs, one whole turn (test_design_outcomes)
    assert "δ = 150°: 6 outside the span of a, 2 equal-ripple design, 1 2α = 360° off the whole-turn line" in text
    plt.close(fig)


def test_the_comparison_names_its_candidates_and_who_is_best():
    comp = D.candidates(D.Specification("swing", 40 / 360, amplitude=np.radians(40),
                                        max_pressure_angle=np.radians(60)))
    fig = comparison_figure(comp)
    text = alt_text(fig)
    assert comp.candidates and f"Comparison of {len(comp.candidates)} candidate mechanisms" in text
    for c in comp.candidates:
        assert c.family in text
    smallest = min(comp.candidates, key=lambda c: c.criteria.size).family
    assert f"size: {smallest}" in text
    plt.close(fig)


def test_a_figure_that_names_nothing_has_no_alt_text_and_one_that_does_is_composed():
    fig, ax = plt.subplots()
    ax.plot([0, 1], [0, 1])
    assert alt_text(fig) == ""   # what the book's check refuses (tests/test_a11y_book.py)
    ax.set(title="lift", xlabel="φ (deg)", ylabel="s (mm)")
    ax.plot([0, 1], [1, 0], label="cycloidal")
    ax.legend()
    # its subject, then its key reading: each curve's range (unlabelled: named by the y axis)
    assert alt_text(fig) == ("Figure: lift, s (mm) against φ (deg), legend: cycloidal, "
                             "s (mm) from 0 to 1; cycloidal from 0 to 1.")
    ax.set_xlabel(r"x (units of $l_{OB}$)")   # mathtext is read as plain words
    assert "s (mm) against x (units of l_OB)" in alt_text(fig)
    assert alt_text(set_alt(fig, "  Lift  of a cam. ")) == "Lift of a cam."
    with pytest.raises(MechanismError, match="non-empty"):
        set_alt(fig, " ")
    with pytest.raises(MechanismError, match="needs a matplotlib Figure"):
        set_alt(ax, "an axes")
    plt.close(fig)


def _png_shell(**env):
    """A bare shell (a display formatter that renders a Figure as PNG, as the inline backend registers)."""
    from types import SimpleNamespace

    from IPython.core.formatters import DisplayFormatter
    from IPython.core.pylabtools import print_figure

    formatter = DisplayFormatter()
    formatter.formatters["image/png"].for_type(matplotlib.figure.Figure, lambda fig: print_figure(fig, "png"))
    return SimpleNamespace(display_formatter=formatter)


def test_a_kernel_publishes_the_alt_text_with_the_image(monkeypatch):
    import base64

    from IPython.core.interactiveshell import InteractiveShell
    from IPython.core.pylabtools import select_figure_formats

    ip = InteractiveShell.instance()
    select_figure_formats(ip, {"png"})   # what the inline backend registers
    install_alt_text(ip)
    install_alt_text(ip)   # twice: still one wrapper
    fig, _ = plt.subplots(figsize=(2, 2))
    data, metadata = ip.display_formatter.format(set_alt(fig, 'A "square" <box>.'))
    assert "image/png" in data and metadata["image/png"]["alt"] == 'A "square" <box>.'
    # JupyterLab reads no alt metadata: the same picture in an <img> that carries it, ranked above image/png
    png = data["image/png"] if isinstance(data["image/png"], str) else base64.b64encode(data["image/png"]).decode()
    assert data["text/html"] == f'<img src="data:image/png;base64,{png}" alt="A &quot;square&quot; &lt;box&gt;.">'
    data, _ = ip.display_formatter.format(fig, include={"image/png", "text/plain"})   # asked for: no html
    assert "text/html" not in data
    data, metadata = ip.display_formatter.format(plt.subplots(figsize=(2, 2))[0])   # nothing to say: no alt
    assert "image/png" in data and "alt" not in metadata.get("image/png", {}) and "text/html" not in data
    # the book's kernels (static pages) keep the picture once: the page's renderer reads the metadata
    monkeypatch.setenv("MECHLAB_WIDGETS", "static")
    book = _png_shell()
    install_alt_text(book)
    data, metadata = book.display_formatter.format(fig)
    assert metadata["image/png"]["alt"] == 'A "square" <box>.' and "text/html" not in data
    with pytest.raises(MechanismError, match="IPython shell"):
        install_alt_text(object())
    plt.close("all")


def test_a_live_canvas_carries_the_figure_description():
    from mechlab.widgets import _ipympl_canvas
    from mechlab.widgets.access import describe_live_figure

    fig = matplotlib.figure.Figure()
    canvas = _ipympl_canvas(fig)   # what an explorer makes in a live kernel
    describe_live_figure(fig)
    assert canvas.tooltip is None   # a figure that names nothing: no name
    ax = fig.add_subplot()
    ax.set(title="lift", xlabel="φ (deg)", ylabel="s (mm)")
    ax.plot([0, 90], [0, 5])
    fig.canvas.draw()   # a full draw renews it
    assert canvas.tooltip == alt_text(fig) == "Figure: lift, s (mm) against φ (deg), s (mm) from 0 to 5."
    assert canvas.description == "" and "description" in canvas.keys   # synced: the front end shows the tooltip


def test_the_simulation_matches_machado_et_al():
    # the matrices preserve white (each row sums to 1) and a deuteranope sees pure red and green alike
    for matrix in CVD_MATRICES.values():
        assert np.allclose(matrix.sum(axis=1), 1.0, atol=2e-6)
    assert delta_e(simulate_cvd("#ff0000", "deuteranopia"), simulate_cvd("#00ff00", "deuteranopia")) < \
        0.35 * delta_e("#ff0000", "#00ff00")
    assert np.allclose(simulate_cvd("#777777", "protanopia"), matplotlib.colors.to_rgb("#777777"), atol=1e-3)


def _contrast(a, b):
    """WCAG 2.1's contrast ratio of two colours."""
    lum = [float(np.array([0.2126, 0.7152, 0.0722]) @ np.where(
        (c := np.asarray(matplotlib.colors.to_rgb(x))) <= 0.04045, c / 12.92, ((c + 0.055) / 1.055) ** 2.4))
        for x in (a, b)]
    return (max(lum) + 0.05) / (min(lum) + 0.05)


def _worst_pair(colours):
    return min((delta_e(simulate_cvd(a, kind), simulate_cvd(b, kind)), a, b, kind)
               for a, b in itertools.combinations(colours, 2) for kind in ("protanopia", "deuteranopia"))


def test_the_category_colours_stay_apart_for_protanopes_and_deuteranopes():
    assert len(set(CATEGORY_COLOURS)) == len(CATEGORY_COLOURS) >= 9
    assert _worst_pair(CATEGORY_COLOURS)[0] >= MIN_DELTA_E, _worst_pair(CATEGORY_COLOURS)
    tab10 = [plt.get_cmap("tab10")(i) for i in range(10)]   # the old palette: the check would refuse it
    assert _worst_pair(tab10)[0] < MIN_DELTA_E
    # every default line colour ("C0", "C1", …) is one of them
    assert [c.upper() for c in matplotlib.rcParams["axes.prop_cycle"].by_key()["color"]] == \
        [c.upper() for c in CATEGORY_COLOURS]


def test_chapter_6_outcome_kinds_differ_by_marker_and_colour():
    markers = [marker for marker, _, _ in OUTCOME_STYLE.values()]
    assert len(set(markers)) == len(markers)
    colours = [colour for _, colour, _ in OUTCOME_STYLE.values()]
    assert _worst_pair(colours)[0] >= MIN_DELTA_E, _worst_pair(colours)


def test_chapter_12_families_differ_by_dash_and_marker_and_colour():
    assert len({s["color"] for s in STYLES.values()}) == len({str(s["ls"]) for s in STYLES.values()}) \
        == len({s["marker"] for s in STYLES.values()}) == len(STYLES) == len(D.FAMILIES)
    assert _worst_pair([s["color"] for s in STYLES.values()])[0] >= MIN_DELTA_E
    # none is yellow (1.2:1 on white); Okabe-Ito's orange and sky blue stay below WCAG 1.4.11's 3:1 for
    # graphics (about 2:1), which is why each family's marker and dash carry it too
    assert all(_contrast(s["color"], "white") >= 1.9 for s in STYLES.values()), \
        {f: round(_contrast(s["color"], "white"), 2) for f, s in STYLES.items()}
    comp = D.candidates(D.Specification("swing", 40 / 360, amplitude=np.radians(40),
                                        max_pressure_angle=np.radians(60)))
    fig = comparison_figure(comp)
    laws = [line for line in fig.axes[1].get_lines() if line.get_visible()]
    assert len(laws) == len(comp.candidates) >= 2
    assert len({(line.get_linestyle(), line.get_marker()) for line in laws}) == len(laws)
    plt.close(fig)


def _controls(widget):
    """The controls (sliders, toggle buttons, drop-downs) in an ipywidgets tree: its value widgets but text
    and pictures."""
    import ipywidgets as W
    found = [widget] if isinstance(widget, W.ValueWidget) and not isinstance(widget, (W.HTML, W.Play, W.Image)) else []
    for child in getattr(widget, "children", ()) or ():
        found += _controls(child)
    return found


def test_every_explorer_control_is_named_and_its_status_is_a_live_region():
    from mechlab.widgets import fourbar_explorer
    from mechlab.widgets.access import LABEL_CONTROLS_JS, STATUS_CLASS
    from mechlab.widgets.forces import press_explorer
    from mechlab.widgets.geneva import planar_geneva_explorer

    for explorer in (fourbar_explorer(live=False), press_explorer(live=False), planar_geneva_explorer(live=False)):
        controls = _controls(explorer.widget)
        assert len(controls) >= 3 and all(c.description.strip() for c in controls), \
            [type(c).__name__ for c in controls if not c.description.strip()]
        assert STATUS_CLASS in explorer.status._dom_classes and explorer.status.value.strip()
        before = explorer.status.value
        slider = next(c for c in controls if c is not explorer.angle and hasattr(c, "step") and c.step)
        slider.value = slider.value + slider.step   # a change of the first dimension is told in the status
        assert explorer.status.value != before
        plt.close("all")
    # the page script names each slider handle by its visible label and makes the status line polite
    assert "aria-labelledby" in LABEL_CONTROLS_JS and f".{STATUS_CLASS}" in LABEL_CONTROLS_JS
    assert "'aria-live', 'polite'" in LABEL_CONTROLS_JS


def test_the_choosing_explorers_picture_and_status_follow_the_specification():
    from mechlab.widgets.design import ChoosingExplorer

    ex = ChoosingExplorer(D.Specification("index", 0.75, stations=4, inertia=1.0), live=False)
    assert ex.output.alt == alt_text(ex.figure.fig) and ex.output.tooltip == ex.output.alt
    assert f"Comparison of {len(ex.comparison.candidates)} candidate mechanisms" in ex.output.alt
    first = ex.comparison.candidates[0]
    assert ex.status.value.startswith(f"{len(ex.comparison.candidates)} of ") and first.family in ex.status.value
    ex.sliders["dwell_fraction"].value = 0.40   # no family meets it
    assert ex.status.value.startswith("0 of ") and "no family meets" in ex.output.alt
    assert all(c.description.strip() for c in _controls(ex.widget))
    plt.close("all")


def test_the_printed_books_figures_are_groups_around_their_described_image(tmp_path):
    """A figure directive's <figure> is role="group" in the single-page book tools/print_pdf.py prints (else
    Chromium tags it a second, undescribed /Figure around the image's), and stays a <figure> on the web."""
    import subprocess
    import sys
    from pathlib import Path

    ext = Path(__file__).resolve().parent.parent / "book" / "_ext"
    src = tmp_path / "src"
    src.mkdir()
    (src / "conf.py").write_text(f"import sys\nsys.path.insert(0, {str(ext)!r})\nextensions = ['alttext']\n")
    fig, _ = plt.subplots(figsize=(1, 1))
    fig.savefig(src / "f.png")
    plt.close(fig)
    (src / "index.rst").write_text("Title\n=====\n\n.. figure:: f.png\n   :alt: A square.\n\n   Its caption.\n")
    tags = {}
    for builder in ("html", "singlehtml"):
        subprocess.run([sys.executable, "-m", "sphinx", "-q", "-b", builder, str(src), str(tmp_path / builder)],
                       check=True, capture_output=True)
        tags[builder] = re.findall(r"<figure[^>]*>", (tmp_path / builder / "index.html").read_text())
    assert len(tags["html"]) == len(tags["singlehtml"]) == 1
    assert 'role="group"' in tags["singlehtml"][0] and "role" not in tags["html"][0]


KEY_READING = re.compile(r"\d|\b(more|less|larger|smaller|than|best|worst|largest|smallest)\b")


def test_every_library_figure_states_a_key_reading_not_only_its_subject():
    fb = FourBar(1, 3, 3, 4, 1)
    mo = fb.motion(np.linspace(0, 2 * np.pi, 90))
    comp = D.candidates(D.Specification("swing", 40 / 360, amplitude=np.radians(40),
                                        max_pressure_angle=np.radians(60)))
    figures = [draw(fb, 0.3).ax.figure, plot_law(mo)[0].figure, comparison_figure(comp),
               plot_design_outcomes(design_outcomes(150 * DEG, fractions=(0.5,), dwells=(180 * DEG,)))]
    for fig in figures:
        text = alt_text(fig)
        titles = [t.get_text() for t in [getattr(fig, "_suptitle", None), *(ax.title for ax in fig.axes)] if t]
        assert KEY_READING.search(text) and text.rstrip(".") not in titles, text
    plt.close("all")


def test_a_composed_description_gives_each_curves_range_but_a_diagrams_lines_none():
    fig, (plot, diagram) = plt.subplots(1, 2)
    phi = np.linspace(0, 360, 73)
    plot.plot(phi, 40 + 20 * np.sin(np.radians(phi)), label="μ")
    plot.axhline(40, color="0.5")   # a reference line, no reading
    plot.set(xlabel="φ (deg)", ylabel="μ (deg)", title="transmission angle")
    diagram.plot([0, 1], [0, 2])
    diagram.set(title="the four-bar")
    diagram.set_axis_off()
    text = alt_text(fig)
    assert "panel 1: transmission angle, μ (deg) against φ (deg), μ from 20 to 60;" in text
    assert text.endswith("panel 2: the four-bar.")
    for k in range(6):   # a seventh curve: four ranges and how many more
        plot.plot(phi, np.full_like(phi, k) + phi / 360, label=f"c{k}")
    assert "; and 3 more curves" in alt_text(fig)
    plt.close(fig)


@pytest.mark.parametrize("name", sorted(__import__("mechlab.draw.machines", fromlist=["MACHINES"]).MACHINES))
def test_a_schematics_alt_names_the_machine_and_what_its_parts_do(name):
    """A chapter's opening schematic is read by its title and its labelled parts (their words, not a generic
    "schematic"): each arrowed label of the drawing appears in the alt text."""
    from mechlab.draw.access import alt_text
    from mechlab.draw.machines import schematic

    fig = schematic(name)
    alt = alt_text(fig)
    labels = [" ".join(t.get_text().split()) for t in fig.axes[0].texts if hasattr(t, "xy") and len(t.get_text()) > 2]
    assert len(labels) >= 3 and fig.axes[0].get_title() in alt
    assert all(label in alt for label in labels), alt
