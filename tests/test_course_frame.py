"""The course's frame: every chapter opens with objectives, prerequisites, time and its machine,
keeps its asserts in hidden check cells, ends with the pointer to its assignment, and no
student-facing text names a source by its seed key or points to a figure the page does not show.
"""

import ast
import json
import re
import sys
from pathlib import Path

import matplotlib
import numpy as np
import pytest

matplotlib.use("Agg")
import matplotlib.pyplot as plt

from mechlab.draw.machines import MACHINES, schematic
from mechlab.errors import MechanismError

ROOT = Path(__file__).parent.parent
sys.path.insert(0, str(ROOT / "tools"))
import learning_path  # noqa: E402  (tools/learning_path.py draws the path's picture)

# "08a_…" is a chapter inserted after 8 without renumbering the later ones (their files, links and assignments)
CHAPTERS = sorted(p for p in (ROOT / "notebooks").glob("[0-9][0-9]*_*.ipynb") if re.match(r"\d\d[a-z]?_", p.name))
ASSIGNMENTS = ("getting_started", "equivalence", "base_mechanism", "symmetry", "instant_centres", "dwell_curved_slot",
               "chebyshev_synthesis", "chebyshev_sixbars", "geneva", "geneva_spherical", "forces", "cams",
               "choosing", "coupler_dwells")
FRAME_HEADINGS = ("## Learning objectives", "## Prerequisites", "## Time", "## The machine")
SEED = re.compile(r"\bseeds?\b", re.I)
FIGURE = re.compile(r"\bFigs?\.\s*(\d+(?:\.\d+)?)")


def cells(path):
    return json.loads(path.read_text())["cells"]


def source(cell):
    return "".join(cell["source"])


def is_check(cell):
    return "check" in cell.get("metadata", {}).get("tags", [])


def asserts_in(code: str) -> int:
    """Asserts, and `raise AssertionError` (an assert in disguise: a teaching cell shows the error, a check
    cell checks it)."""
    return sum(isinstance(node, ast.Assert) or (isinstance(node, ast.Raise) and "AssertionError" in ast.unparse(node))
               for node in ast.walk(ast.parse(code)))


def test_there_are_chapters():
    assert len(CHAPTERS) >= 11


# -- the lecturer's companions: notebooks/companion/NN_*.ipynb, one per chapter with material moved out ----------
COMPANIONS = sorted((ROOT / "notebooks" / "companion").glob("[0-9][0-9]_*.ipynb"))
GOING_FURTHER = re.compile(r"Going further:\*{0,2}\s(?:(?!\n\n).)*?\]\((companion/[0-9][0-9]_\w+\.ipynb)\)", re.S)


@pytest.mark.parametrize("path", COMPANIONS, ids=lambda p: p.name)
def test_companion_names_its_chapter_and_keeps_its_checks(path):
    """A companion's smaller frame: a header naming its chapter (a link to it) and its sources as works; every
    assert in a hidden check cell, and at least one; the chapter links back to it in one "Going further" line."""
    cs = cells(path)
    chapter = next(ROOT.glob(f"notebooks/{path.name[:2]}_*.ipynb"), None)
    header = source(cs[0])
    assert chapter and cs[0]["cell_type"] == "markdown", f"{path.name}: no chapter {path.name[:2]} or no header"
    assert header.startswith(f"# Companion to chapter {int(path.name[:2])} · ") and f"](../{chapter.name})" in header
    # "Kinitsky (1994)", "(Zinchenko et al., 2013)", or "Source: Kozhevnikov, *Theory …*" (the excerpt gives no year)
    cites = re.search(r"[A-Z][a-z]+(?: et al\.)?(?: \(\d{4}\)|, \d{4}\))|Sources?:\s+[A-Z]\w+", header)
    assert cites and not SEED.search(header), f"{path.name}: sources as works"
    code = [c for c in cs if c["cell_type"] == "code"]
    assert not [c["id"] for c in code if not is_check(c) and asserts_in(source(c))], f"{path.name}: untagged assert"
    assert all(c["metadata"].get("jupyter", {}).get("source_hidden") is True for c in code if is_check(c))
    assert any(is_check(c) and asserts_in(source(c)) for c in code), f"{path.name}: no check cell asserts anything"
    links = [m.group(1) for c in cells(chapter) if c["cell_type"] == "markdown"
             for m in GOING_FURTHER.finditer(source(c))]
    assert links == [f"companion/{path.name}"], f"{chapter.name}: one 'Going further' line to {path.name}, got {links}"
    assert not [c["id"] for c in cs if SEED.search(source(c))], f"{path.name}: 'seed' in a cell"


def test_a_chapter_links_only_to_companions_that_exist():
    for path in CHAPTERS:
        for link in GOING_FURTHER.findall("\n".join(source(c) for c in cells(path) if c["cell_type"] == "markdown")):
            assert (ROOT / "notebooks" / link).is_file(), f"{path.name}: {link} does not exist"


@pytest.mark.parametrize("path", CHAPTERS, ids=lambda p: p.name)
def test_chapter_opens_with_its_frame(path):
    first, second = cells(path)[:2]
    text = source(first)
    heading = re.match(r"# \d+[a-z]? · \S", text)
    assert first["cell_type"] == "markdown" and heading, f"{path.name}: no '# n · title' first"
    places = [text.find(h + "\n") for h in FRAME_HEADINGS]
    assert all(p > 0 for p in places) and places == sorted(places), f"{path.name}: headings {FRAME_HEADINGS} in order"
    objectives = text[places[0]:places[1]]
    bullets = re.findall(r"^- \S", objectives, re.M)
    assert 3 <= len(bullets) <= 5, f"{path.name}: {len(bullets)} learning objectives, not 3-5"
    assert re.search(r"\d+ minutes", text[places[2]:places[3]]), f"{path.name}: the time is not given in minutes"
    assert len(text[places[3]:].split()) > 30, f"{path.name}: the machine is not described in words"
    call = re.search(r'schematic\("(\w+)"\)', source(second))
    assert second["cell_type"] == "code" and call, f"{path.name}: no schematic right after the frame"
    assert call.group(1) in MACHINES


@pytest.mark.parametrize("path", CHAPTERS, ids=lambda p: p.name)
def test_teaching_cells_carry_no_assert(path):
    code = [c for c in cells(path) if c["cell_type"] == "code"]
    untagged = {c["id"]: asserts_in(source(c)) for c in code if not is_check(c)}
    offending = [k for k, v in untagged.items() if v]
    assert not offending, f"{path.name}: asserts in teaching cells {offending}"
    for c in code:
        if is_check(c):
            assert c["metadata"].get("jupyter", {}).get("source_hidden") is True, f"{path.name}: {c['id']} not hidden"
    assert any(is_check(c) and asserts_in(source(c)) for c in code), f"{path.name}: no check cell asserts anything"


# -- thin teaching cells ------------------------------------------------------------------------------------------
TEACHING_LINES = 12   # non-blank lines: a few calls into mechlab a student reads; longer logic goes into mechlab
# the teaching cells that stay longer, (chapter, cell index) → why
LONG_TEACHING_CELLS = {
}


def long_teaching_cells(cs) -> dict[int, int]:
    """Index → non-blank lines of each code cell not tagged ``check`` with more than TEACHING_LINES of them."""
    counts = {i: sum(1 for line in source(c).splitlines() if line.strip()) for i, c in enumerate(cs)
              if c["cell_type"] == "code" and not is_check(c)}
    return {i: n for i, n in counts.items() if n > TEACHING_LINES}


@pytest.mark.parametrize("path", CHAPTERS, ids=lambda p: p.name)
def test_teaching_cells_are_short(path):
    long = long_teaching_cells(cells(path))
    allowed = {i for chapter, i in LONG_TEACHING_CELLS if chapter == path.stem}
    assert set(long) <= allowed, (
        f"{path.name}: teaching cells {({i: n for i, n in long.items() if i not in allowed})} (index: non-blank lines) "
        f"exceed {TEACHING_LINES} lines: move figure-composing or computation into mechlab with a test, or "
        f"allow-list the cell in LONG_TEACHING_CELLS with its reason")
    assert allowed <= set(long), f"{path.name}: cells {sorted(allowed - set(long))} are short now: drop their entries"


def test_the_scan_would_see_a_long_teaching_cell():
    def code(n_lines, tags=()):
        return {"cell_type": "code", "metadata": {"tags": list(tags)}, "source": "x = 1\n\n" * n_lines}

    cs = [code(TEACHING_LINES), code(TEACHING_LINES + 1), code(40, tags=["check"]),
          {"cell_type": "markdown", "metadata": {}, "source": "text\n" * 40}]
    assert long_teaching_cells(cs) == {1: TEACHING_LINES + 1}   # blank lines, check cells and prose do not count


@pytest.mark.parametrize("path", CHAPTERS, ids=lambda p: p.name)
def test_chapter_ends_with_its_assignment(path):
    last = cells(path)[-1]
    text = source(last)
    assert last["cell_type"] == "markdown" and text.startswith("## Exercises"), f"{path.name}: no closing Exercises"
    ids = re.findall(r"assignments/release/(\w+)/(\w+)\.ipynb", text)
    assert len(ids) == 1 and ids[0][0] == ids[0][1] and ids[0][0] in ASSIGNMENTS, f"{path.name}: {ids}"
    # the source holds the worked solutions; JupyterLab shows the student's my-notebooks/
    assert "assignments/source" not in text and "my-notebooks/" in text, f"{path.name}: where to work"
    for c in cells(path):
        assert "mechlab.course.exercises" not in source(c), f"{path.name}: an old exercise cell is left"


def test_the_intro_gives_the_path_with_each_chapters_time():
    intro = (ROOT / "book" / "intro.md").read_text()
    rows = dict(re.findall(r"^\|[^|\n]*\(notebooks/(\w+)\.ipynb\)[^\n]*?\| (\d+) min \|", intro, re.M))
    times = {}
    for path in CHAPTERS:
        frame = source(cells(path)[0])
        minutes = re.search(r"## Time\s+\D*?(\d+) minutes", frame, re.I)
        assert minutes, f"{path.name}: its Time section gives no minutes"
        times[path.stem] = int(minutes.group(1))
    assert {k: int(v) for k, v in rows.items()} == {k: v for k, v in times.items() if k in rows}
    assert set(times) == set(rows), "a chapter is missing from the learning path"
    assert f"In all {sum(int(v) for v in rows.values())} minutes" in intro


def chapter_numbers(listed: str) -> set[str]:
    """The intro's "needs" column as chapter labels: "—", "0, 2", "5, 6, 8–11" or "6, 8a" (a range spans the
    plain numbers)."""
    numbers = set()
    for part in re.findall(r"\d+[a-z]?(?:–\d+)?", listed):
        first, _, last = part.partition("–")
        numbers |= {first} if not last else {str(n) for n in range(int(first), int(last) + 1)}
    return numbers


def label(path: Path) -> str:
    """The chapter's number as its heading writes it: 08a_x.ipynb → "8a"."""
    return learning_path.label(path.stem.split("_", 1)[0])


def test_every_prerequisite_comes_earlier_in_the_path():
    path = learning_path.chapters(ROOT)
    assert [c.stem for c in path] == [p.stem for p in CHAPTERS], "the path's order is not the files' order"
    plain = [c.number for c in path if c.number.isdigit()]
    assert plain == [str(n) for n in range(len(plain))], "one number per chapter, from 0"
    # a lettered chapter (8a) follows its number's chapter (8) or the previous letter (8b after 8a)
    assert all(c.number[:-1] == path[i - 1].number.rstrip("abcdefghijklmnopqrstuvwxyz") for i, c in enumerate(path)
               if not c.number.isdigit()), [c.number for c in path]
    place = {c.number: i for i, c in enumerate(path)}
    listed = {stem: chapter_numbers(needs) for *_, stem, _, needs in learning_path.ROW.findall(
        (ROOT / "book" / "intro.md").read_text())}
    for c in path:
        assert learning_path.label(c.stem.split("_", 1)[0]) == c.number, f"{c.stem}: its heading and file name differ"
        assert all(place[n] < place[c.number] for n in c.needs), f"{c.stem} needs {sorted(c.needs)}: not all earlier"
        assert listed[c.stem] == c.needs, f"{c.stem}: the intro lists {listed[c.stem]}, the chapter {set(c.needs)}"
    for path_file in CHAPTERS:  # the heading's number is the file's
        assert source(cells(path_file)[0]).startswith(f"# {label(path_file)} · "), path_file.name


def test_prerequisites_are_read_from_links_before_looking_ahead(tmp_path):
    frame = ("# 3 · X\n\n## Learning objectives\n\n- a\n\n## Prerequisites\n\n[0 · A](00_a.ipynb) and "
             "[2 · B](02_b.ipynb#a-section). Looking ahead: [5 · C](05_c.ipynb).\n\n## Time\n\n[1 · D](01_d.ipynb)")
    (tmp_path / "03_x.ipynb").write_text(json.dumps({"cells": [{"cell_type": "markdown", "source": [frame]}]}))
    assert learning_path.prerequisites(tmp_path / "03_x.ipynb") == {"0", "2"}
    assert chapter_numbers("5, 6, 8–11") == {"5", "6", "8", "9", "10", "11"} and chapter_numbers("—") == set()
    assert chapter_numbers("6, 8a") == {"6", "8a"} and learning_path.label("08a") == "8a"


def test_the_intro_shows_the_path_drawn_from_the_chapters():
    """book/figures/learning_path.svg is what `python tools/learning_path.py` draws from the chapters now."""
    assert "figures/learning_path.svg" in (ROOT / "book" / "intro.md").read_text()
    path = learning_path.chapters(ROOT)
    assert learning_path.svg(path) == learning_path.FIGURE.read_bytes(), "run python tools/learning_path.py"
    where = learning_path.layout(path, learning_path.arrows(path))
    assert learning_path.through_boxes(where, learning_path.arrows(path)) == 0, "an arrow runs through a box"


def test_the_path_labels_are_readable_in_the_book_column():
    """The book shows the picture 752 px wide (its column, the figure at 100 %): every label, the box titles
    and times included, is at least 11 px high there (the SVG's unit is the point, 72 per inch)."""
    fig = learning_path.draw(learning_path.chapters(ROOT))
    px_per_pt = 752 / (fig.get_figwidth() * 72)
    sizes = sorted((t.get_fontsize() * px_per_pt, t.get_text()) for ax in fig.axes for t in [*ax.texts, ax.title])
    learning_path.plt.close(fig)
    assert len(sizes) == 2 * len(learning_path.chapters(ROOT)) + 1 and sizes[0][0] >= 11, sizes[:3]


def figure_problems(text: str, shown: str) -> list[str]:
    """'Fig. N' in ``text`` whose number is not in ``shown`` (the page's own drawings)."""
    return [m.group(0) for m in FIGURE.finditer(text)
            if not re.search(rf"\bFigs?\.\s*{re.escape(m.group(1))}(?!\d)", shown)]


@pytest.mark.parametrize("path", CHAPTERS, ids=lambda p: p.name)
def test_notebook_cites_works_and_shows_its_figures(path):
    cs = cells(path)
    for c in cs:
        assert not SEED.search(source(c)), f"{path.name}: 'seed' in cell {c['id']}"
    drawings = "\n".join(source(c) for c in cs if c["cell_type"] == "code")
    prose = "\n".join(source(c) for c in cs if c["cell_type"] == "markdown")
    assert figure_problems(prose, drawings) == [], f"{path.name}: a source's figure is named but not redrawn"


def visible_markdown(text: str) -> str:
    """A book page without MyST targets '(label)=' and link addresses: what the reader sees."""
    text = re.sub(r"^\(.*\)=\s*$", "", text, flags=re.M)
    return re.sub(r"\]\([^)]*\)", "]", text)


BOOK_PAGES = [ROOT / "book" / f"{name}.md" for name in ("intro", "glossary", "references", "errata")]


@pytest.mark.parametrize("page", [p for p in BOOK_PAGES if p.exists()], ids=lambda p: p.name)
def test_book_page_cites_works(page):
    text = visible_markdown(page.read_text())
    assert not SEED.search(text), f"{page.name}: {SEED.search(text).group(0)!r}"
    assert figure_problems(text, "") == [], f"{page.name}: a source's figure named on a page without figures"


def student_strings(path: Path) -> list[str]:
    """The string constants of a module that a student reads: everything but docstrings."""
    tree = ast.parse(path.read_text())
    docstrings = {id(node.body[0].value) for node in ast.walk(tree)
                  if isinstance(node, (ast.Module, ast.FunctionDef, ast.ClassDef)) and node.body
                  and isinstance(node.body[0], ast.Expr) and isinstance(node.body[0].value, ast.Constant)}
    return [n.value for n in ast.walk(tree)
            if isinstance(n, ast.Constant) and isinstance(n.value, str) and id(n) not in docstrings]


EXERCISE_TEXTS = sorted((ROOT / "mechlab" / "course" / "exercises").glob("*.py"))
ASSIGNMENT_NOTEBOOKS = sorted((ROOT / "assignments").glob("**/*.ipynb"))


@pytest.mark.parametrize("path", EXERCISE_TEXTS + ASSIGNMENT_NOTEBOOKS, ids=lambda p: p.name)
def test_exercise_texts_cite_works(path):
    if path.suffix == ".py":
        texts = student_strings(path)
    else:
        texts = [source(c) for c in cells(path) if c["cell_type"] == "markdown"]
    for text in texts:
        assert not SEED.search(text), f"{path.name}: {text[:80]!r}"
        assert figure_problems(text, "") == [], f"{path.name}: {text[:80]!r}"


def widget_titles() -> list[tuple[str, str]]:
    titles = []
    for path in sorted((ROOT / "mechlab" / "widgets").glob("*.py")):
        for node in ast.walk(ast.parse(path.read_text())):
            if (isinstance(node, ast.keyword) and node.arg in ("title", "question")
                    and isinstance(node.value, ast.Constant)):
                titles.append((path.name, node.value.value))
    return titles


@pytest.mark.parametrize("where, title", widget_titles())
def test_widget_title_cites_works(where, title):
    assert not SEED.search(title) and not FIGURE.search(title), f"{where}: {title!r}"


def test_the_scans_would_see_a_seed_and_a_bare_figure():
    assert SEED.search("as seed 000 shows") and not SEED.search("seeding")
    assert figure_problems("see Fig. 7.3 and Figs. 2-4", "# after Kozhevnikov, Fig. 7.3") == ["Figs. 2"]
    assert asserts_in("x = 1\nfor i in range(2):\n    assert i < 2\n") == 1
    assert asserts_in("try:\n    f()\nexcept E:\n    pass\nelse:\n    raise AssertionError('accepted')\n") == 1
    assert asserts_in("raise ValueError('no')\n") == 0


@pytest.mark.parametrize("name", sorted(MACHINES))
def test_schematic_is_labelled_and_draws_its_mechanism_where_it_is(name):
    fig = schematic(name)
    try:
        (ax,) = fig.axes
        assert ax.get_title() and not ax.axison
        arrows = [t for t in ax.texts if getattr(t, "arrow_patch", None) is not None]
        assert len(arrows) >= 3, "fewer than three labelled parts"
        letters = {t.get_text(): np.array(t.get_position()) for t in ax.texts if re.fullmatch(r"[A-Z]", t.get_text())}
        assert "O" in letters and len(letters) >= 2, f"joint letters {sorted(letters)}"
        # each joint letter sits next to a joint drawn as a marker of the mechanism
        markers = np.concatenate([np.asarray(line.get_xydata(), float) for line in ax.lines if line.get_marker()
                                  not in (None, "None", "")] or [np.empty((0, 2))])
        x0, x1 = ax.get_xlim()
        for letter, where in letters.items():
            assert np.min(np.hypot(*(markers - where).T)) < 0.08 * (x1 - x0), f"{letter} is far from every joint"
    finally:
        plt.close(fig)


@pytest.mark.parametrize("name", sorted(MACHINES))
def test_schematic_is_as_wide_as_an_animation_and_its_letters_clear_of_leader_lines(name):
    """As the notebook shows it (inline backend: the figure's dpi, bbox_inches="tight"), a schematic
    is at least 640 px wide, and no label's arrow crosses a joint letter."""
    import io

    from matplotlib.path import Path as MplPath
    from PIL import Image

    fig = schematic(name)
    try:
        assert fig.dpi == matplotlib.rcParams["figure.dpi"]
        png = io.BytesIO()
        fig.savefig(png, format="png", bbox_inches="tight")
        width = Image.open(png).size[0]
        assert width >= 640, f"{name}: {width} px wide"
        fig.canvas.draw()
        (ax,) = fig.axes
        letters = [t for t in ax.texts if re.fullmatch(r"[A-Z]", t.get_text())]
        arrows = [t.arrow_patch for t in ax.texts if getattr(t, "arrow_patch", None) is not None]
        for letter in letters:
            box = letter.get_window_extent()
            for arrow in arrows:
                # shaft and head as open polylines (the head's CLOSEPOLY vertex is a dummy (0, 0))
                lines = arrow.get_path().transformed(arrow.get_transform()).to_polygons(closed_only=False)
                assert not any(MplPath(line).intersects_bbox(box, filled=False) for line in lines), \
                    f"{name}: a leader line crosses {letter.get_text()}"
    finally:
        plt.close(fig)


def test_unknown_machine_is_named():
    with pytest.raises(MechanismError, match=r"name = 'lathe' is not one of .*film_projector"):
        schematic("lathe")


def test_a_cam_chapter_shows_a_cam():
    """The cam primer's machine is drawn with its disc cam (profile, roller C), not a curved slot."""
    fig = schematic("cartoning_cam")
    try:
        (ax,) = fig.axes
        letters = {t.get_text() for t in ax.texts if re.fullmatch(r"[A-Z]", t.get_text())}
        assert letters == {"O", "C"}
        assert "cam" in ax.get_title()
        closed = [line for line in ax.lines if len(line.get_xydata()) > 100]     # the sampled profile
        assert closed and np.allclose(closed[0].get_xydata()[0], closed[0].get_xydata()[-1], atol=1e-6)
    finally:
        plt.close(fig)


# -- errata: the registry's strings and the rendered page name places in words ------------------------------
def visible_html(text: str) -> str:
    """Rendered Markdown/HTML as read: no tags (link addresses live in their attributes)."""
    return re.sub(r"<[^>]*>", "", visible_markdown(text))


def test_errata_name_their_places_in_words():
    import sys
    sys.path.insert(0, str(ROOT / "book" / "_ext"))
    from errata_page import errata_markdown

    from mechlab.course.errata import collect

    for e in collect():
        for text in (e.where, e.printed, e.correct):
            assert not SEED.search(text) and figure_problems(text, "") == [], f"{e.source} {e.where!r}: {text!r}"
    page = visible_html(errata_markdown())
    assert not SEED.search(page), SEED.search(page)
    assert figure_problems(page, "") == [], "the errata page names a source's figure it does not show"
    assert figure_problems(visible_html('<a href="x.html#fig-2">§3, Fig. 2a</a>'), "") == ["Fig. 2"]


def test_every_erratum_links_to_the_cell_that_shows_it():
    """Errata moved out of the lessons into the companions: each row's link reaches a cell that shows errata."""
    import sys
    sys.path.insert(0, str(ROOT / "book" / "_ext"))
    from errata_page import chapter_link, demo_cell

    from mechlab.course.errata import collect

    for notebook in sorted({e.notebook for e in collect()}):
        href = re.search(r'href="notebooks/([^"#]+)\.html#cell-(\d+)"', chapter_link(notebook))
        assert href, f"{notebook}: no cell anchor in {chapter_link(notebook)}"
        shown = ROOT / "notebooks" / f"{href.group(1)}.ipynb"
        assert demo_cell(shown) == int(href.group(2)), notebook
        shows = source(cells(shown)[int(href.group(2))])
        assert "errata" in shows or "table(notebook=" in shows, notebook


# -- numbers in the prose come from the computation -----------------------------------------------------------
PROSE_NUMBER = re.compile(r"(?<![\w.§^_{\-–])(\d+\.\d+|\d+(?=\s*°))(?![\d–])")
DEFINITIONS = {0.0, 90.0, 180.0, 360.0}     # a right angle, half and whole turns: definitions, not results
QUOTED = re.compile(r"\bprinted\b(?:[^.]|\.\d){0,45}$")     # a source's printed value, in the same sentence
# inputs that the prose states and no code literal sets, per chapter (the file name after its number)
STATED = {
    "getting_started": {"50": "the limit 40° stated as a pressure angle, 90° − 40°",
                        "30": "Kinitsky's (1994) limit, quoted"},
    "dwell_curved_slot": {"45": "the pressure-angle limit the explorer's question sets"},
    "chebyshev_dwell_synthesis": {"2.5": "Chebyshev's proportions 1 : 2 : 2.5 : 5, quoted",
                                  "40": "the course's transmission-angle limit"},
    "chebyshev_dwell_sixbars": {"0.4": "the crank of Chebyshev's lambda, a given design",
                                "250": "the dwell of two rows of Kinitsky's (1994) table, quoted"},
    "geneva_spherical": {"60": "the six-slot indexing table of the drawing turns 360°/6 per index"},
}


def code_literals(code: str) -> set[float]:
    """The numbers the code sets: the inputs a sentence may repeat."""
    values = set()
    for node in ast.walk(ast.parse(code)):
        if isinstance(node, ast.Constant) and type(node.value) in (int, float):
            values.add(float(node.value))
    return values


def typed_results(prose: str, code: str) -> list[str]:
    """Decimals and angles in ``prose`` that the code does not set: results typed into the text.

    Inline code, link addresses, formula and section numbers ((7.8), §7.1) and values quoted from a
    source ("the printed 53.15°") are not results; a right angle, a half and a whole turn are definitions.
    """
    inputs = code_literals(code) | DEFINITIONS
    prose = re.sub(r"`[^`]*`", "", visible_markdown(prose))
    prose = re.sub(r"\((?:\d+(?:\.\d+)?[a-z]?(?:,\s*|\s*[–-]\s*)?)+\)", "", prose)   # formulas (7.8, 7.9)
    prose = re.sub(r"\(\d+\.\d+(?=,)", "(", prose)                                  # (7.6, the pole ...)
    return [m.group(0) for m in PROSE_NUMBER.finditer(prose)
            if float(m.group(1)) not in inputs and not QUOTED.search(prose[:m.start()])]


@pytest.mark.parametrize("path", CHAPTERS, ids=lambda p: p.name)
def test_numbers_in_the_prose_come_from_the_computation(path):
    cs = cells(path)
    code = "\n".join(source(c) for c in cs if c["cell_type"] == "code" and not source(c).startswith("%"))
    stated = STATED.get(path.stem.split("_", 1)[1], {})
    typed = {c["id"]: [v for v in typed_results(source(c), code) if v not in stated]
             for c in cs if c["cell_type"] == "markdown"}
    assert not {k: v for k, v in typed.items() if v}, f"{path.name}: results typed into the text"


def test_the_scan_would_see_a_typed_result():
    code = "lam = 0.5\nphi = np.radians(60)\n"
    assert typed_results("the reactions peak near φ = 270°, with C = 5.77.", code) == ["270", "5.77"]
    assert typed_results("λ = 0.5 and φ1 = 60°; a half turn is 180° (7.8, 7.9), §7.1", code) == []
    assert typed_results("the printed 53.15°, $\\beta = 24.85°$ and\n 41.60 are off; `127.0.0.1`", code) == []
    assert typed_results("(7.6, the pole) rounds to 0.45. The printed 0.46 is off. It misses by 0.01.",
                         code) == ["0.45", "0.01"]


# -- widgets that ask -------------------------------------------------------------------------------------------
def explorer_names() -> set[str]:
    """The widget functions a notebook calls to show an explorer: every public one taking ``question``; and the
    editors, public classes named ``*Editor`` whose ``__init__`` takes it (a chapter builds an editor itself, an
    ``*Explorer`` class through its function)."""
    names = set()
    for path in sorted((ROOT / "mechlab" / "widgets").glob("*.py")):
        for node in ast.parse(path.read_text()).body:
            if isinstance(node, ast.ClassDef) and node.name.endswith("Editor"):
                fn = next((f for f in node.body if isinstance(f, ast.FunctionDef) and f.name == "__init__"), None)
            else:
                fn = node if isinstance(node, ast.FunctionDef) else None
            if (fn is not None and not node.name.startswith("_")
                    and any(a.arg in ("question", "kwargs") for a in fn.args.kwonlyargs + [fn.args.kwarg]
                            if a is not None)):
                names.add(node.name)
    return names


def unasked_explorers(code: str, names: set[str]) -> list[str]:
    """Calls of an explorer in ``code`` that pass no ``question=``."""
    calls = [n for n in ast.walk(ast.parse(code)) if isinstance(n, ast.Call)]
    called = [(getattr(n.func, "id", None) or getattr(n.func, "attr", None), n) for n in calls]
    return [name for name, n in called if name in names and not any(k.arg == "question" for k in n.keywords)]


def test_every_explorer_is_known():
    names = explorer_names()
    assert {"fourbar_explorer", "cam_explorer", "dwell_explorer", "press_explorer", "choosing_explorer",
            "fourbar_equivalence", "spherical_geneva_explorer", "DragEditor"} <= names, names
    assert "ChoosingExplorer" not in names   # built by choosing_explorer; chapter 12 draws its static picture
    assert unasked_explorers("w = fourbar_explorer(crank=1)\nml.widgets.cam_explorer(question='q?')", names) == [
        "fourbar_explorer"]


@pytest.mark.parametrize("path", CHAPTERS, ids=lambda p: p.name)
def test_every_explorer_asks_a_question(path):
    names = explorer_names()
    shown = [source(c) for c in cells(path) if c["cell_type"] == "code" and not source(c).startswith("%")]
    unasked = [name for code in shown for name in unasked_explorers(code, names)]
    assert not unasked, f"{path.name}: explorers without question=: {unasked}"


GREEK = {r"\varphi": "φ", r"\psi": "ψ", r"\omega": "ω", r"\mu": "μ", r"\theta": "θ", r"\lambda": "λ",
         r"\alpha": "α", r"\Delta": "Δ", r"\beta": "β", r"\delta": "δ", r"\varepsilon": "ε"}


def symbol_pattern(symbol: str) -> re.Pattern:
    """A glossary symbol ("k_{ov}", "\\mu", "P_{ij}") as a chapter may write it: LaTeX or Unicode, with or
    without braces and underscore; "ij" stands for two link numbers."""
    parts = []
    for token in re.split(r"(\\[A-Za-z]+|_\{?[a-z0-9]+\}?)", symbol):
        if token in GREEK:
            parts.append(f"(?:{re.escape(token)}(?![A-Za-z])|{GREEK[token]})")
        elif token.startswith("_"):
            sub = token.strip("_{}")
            parts.append(r"_?\{?" + (r"\d\d" if sub == "ij" else re.escape(sub)) + r"\}?")
        else:
            parts.append(re.escape(token))
    return re.compile("".join(parts))


def test_the_glossary_symbols_are_used_in_the_chapters_it_lists():
    """The symbol table's chapters column follows the chapter numbers (it lagged a renumbering once)."""
    rows = re.findall(r"^\| \$(.+?)\$.*\| ([^|]+) \|$", (ROOT / "book" / "glossary.md").read_text(), re.M)
    assert len(rows) >= 15
    texts = {label(p): "\n".join(source(c) for c in cells(p)) for p in CHAPTERS}
    wrong = []
    for symbol, listed in rows:
        symbol = re.split(r",| =", symbol)[0].strip()
        if listed.strip() == "all":
            continue
        pattern = symbol_pattern(symbol)
        wrong += [f"{symbol} not in chapter {n}" for n in sorted(chapter_numbers(listed))
                  if not pattern.search(texts[n])]
    assert not wrong, wrong


def test_a_glossary_symbol_pattern_tells_symbols_apart():
    assert symbol_pattern("k_{ov}").search("overload $k_{ov}$") and symbol_pattern("k_{ov}").search("k_ov = 2")
    assert symbol_pattern(r"\mu").search("μ_min") and not symbol_pattern(r"\mu").search(r"\mult")
    assert symbol_pattern("P_{ij}").search("$P_{13}$") and not symbol_pattern("P_{ij}").search("P_b")
    assert not symbol_pattern("k_a").search("k_c")


def test_chapters_promise_on_the_hub_only_what_its_image_installs():
    """The hub image (binder/postBuild installs the `hub` extra) has no nbgrader, so no Assignments tab: a chapter
    that told students to use one would send them looking for a panel that is not there."""
    import tomllib

    hub = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]["optional-dependencies"]["hub"]
    assert '".[hub]"' in (ROOT / "binder" / "postBuild").read_text()   # the image installs exactly the hub extra
    if not any(dep.startswith("nbgrader") for dep in hub):
        promised = [p.name for p in CHAPTERS
                    if re.search(r"Assignments\s+tab", "\n".join(source(c) for c in cells(p)))]
        assert not promised, f"chapters promise the hub's Assignments tab, which its image lacks: {promised}"
    for path in CHAPTERS:
        exercises = next(source(c) for c in cells(path) if source(c).startswith("## Exercises"))
        assert "JupyterHub" in exercises and "assignment link" in exercises, f"{path.name}: how to get it on the hub"
