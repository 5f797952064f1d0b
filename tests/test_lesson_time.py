"""Honest times: every chapter states the minutes of the time model (tools/lesson_time.py), and so do
the intro's table and total; the model itself grows with what a chapter asks of the student.

When a chapter changes, `python tools/lesson_time.py --write` states the new times.
"""

import copy
import re
import sys
from pathlib import Path

import nbformat
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

ROOT = Path(__file__).parent.parent
sys.path.insert(0, str(ROOT / "tools"))
import lesson_time  # noqa: E402

CHAPTERS = lesson_time.chapters(ROOT)
FIX = "run `python tools/lesson_time.py --write`"


def notebook(*cells):
    """A notebook of (kind, source[, tags]) cells."""
    nb = nbformat.v4.new_notebook()
    for kind, source, *tags in cells:
        cell = nbformat.v4.new_markdown_cell(source) if kind == "md" else nbformat.v4.new_code_cell(source)
        cell.metadata["tags"] = list(tags)
        nb.cells.append(cell)
    return nb


BASE = notebook(("md", "# 1 · A lesson\n\n## Time\n\nAbout 5 minutes.\n\nThe crank $\\varphi$ turns."),
                ("code", "import mechlab as ml\nfb = ml.FourBar(1, 3, 3, 4)\nfb.grashof()"),
                ("code", "assert True", "check"))


def test_there_are_chapters():
    assert len(CHAPTERS) >= 11 and not any("companion" in p.parts for p in CHAPTERS)


@pytest.mark.parametrize("path", CHAPTERS, ids=lambda p: p.name)
def test_each_chapter_states_the_models_time(path):
    nb = lesson_time.read(path)
    model, said = lesson_time.estimate(nb).minutes, lesson_time.stated(nb)
    assert said is not None, f"{path.name}: no 'About N minutes' under '## Time'"
    assert said == model, f"{path.name} states {said} minutes, the model gives {model}: {FIX}"


def test_the_intro_gives_the_models_times_and_total():
    intro = (ROOT / "book" / "intro.md").read_text()
    rows = {m.group(2): (int(m.group(3)), m.group(0)) for m in lesson_time.INTRO_ROW.finditer(intro)}
    assert set(rows) == {p.stem for p in CHAPTERS}, "the path's table lists every chapter once"
    model = {p.stem: lesson_time.estimate(lesson_time.read(p)).minutes for p in CHAPTERS}
    wrong = {stem: (rows[stem][0], m) for stem, m in model.items() if rows[stem][0] != m}
    assert not wrong, f"the intro's time ≠ the model's (intro, model): {wrong}; {FIX}"
    for p in CHAPTERS:
        extra = lesson_time.exercises_minutes(lesson_time.read(p), ROOT)
        cell = f" {extra} min |" if extra else " — |"
        assert rows[p.stem][1].partition(" min |")[2].startswith(cell), (
            f"{p.stem}: the exercises' minutes in the intro are not the model's {extra}; {FIX}")
    total = re.search(r"^In all (\d+) minutes", intro, re.M)
    assert total and int(total.group(1)) == sum(model.values()), f"the intro's total; {FIX}"


def test_the_times_are_in_five_minute_steps_and_positive():
    for minutes in (0.0, 2.4, 2.5, 7.49, 7.5, 61.0):
        r = lesson_time.rounded(minutes)
        assert r % 5 == 0 and r >= 5 and (abs(r - minutes) <= 2.5 or minutes < 2.5)


@settings(max_examples=30, deadline=None)
@given(st.integers(0, 3000), st.integers(1, 500))
def test_more_words_more_minutes(words, more):
    """A property: adding prose never shortens a lesson, and costs its words at the stated reading speed."""
    def with_words(n):
        nb = copy.deepcopy(BASE)
        nb.cells.append(nbformat.v4.new_markdown_cell("torque " * n))
        return lesson_time.estimate(nb)
    short, long = with_words(words), with_words(words + more)
    assert long.words - short.words == more
    assert long.exact - short.exact == pytest.approx(more / lesson_time.WORDS_PER_MINUTE)
    assert long.minutes >= short.minutes


@pytest.mark.parametrize("kind", sorted(lesson_time.EXERCISE))
@pytest.mark.parametrize("heading", ["## Your turn · {kind}", "### Exercise 2 · {kind} (2 points)"])
def test_an_added_exercise_adds_its_kinds_minutes(kind, heading):
    before = lesson_time.estimate(BASE)
    nb = copy.deepcopy(BASE)
    text = heading.format(kind=kind)
    nb.cells.append(nbformat.v4.new_markdown_cell(text))
    after = lesson_time.estimate(nb)
    words = lesson_time.prose_counts(text)[0]
    assert after.exercises == {kind: 1}
    expected = lesson_time.EXERCISE[kind] + words / lesson_time.WORDS_PER_MINUTE
    assert after.exact - before.exact == pytest.approx(expected)


def test_what_is_no_exercise_and_what_costs_nothing():
    before = lesson_time.estimate(BASE).exact
    nb = copy.deepcopy(BASE)
    # the closing pointer to the assignment, a slider section and a check cell are no work for the model
    nb.cells.append(nbformat.v4.new_markdown_cell("## Exercises"))
    nb.cells.append(nbformat.v4.new_code_cell("assert 1 + 1 == 2\n" * 30, metadata={"tags": ["check"]}))
    t = lesson_time.estimate(nb)
    assert t.exercises == {} and t.exact == pytest.approx(before + 1 / lesson_time.WORDS_PER_MINUTE)
    tagged = copy.deepcopy(BASE)
    tagged.cells.append(nbformat.v4.new_code_cell("answer = ...", metadata={"tags": ["exercise-debug"]}))
    assert lesson_time.estimate(tagged).exercises == {"debug": 1}


def test_widgets_equations_and_code_lines_cost_their_stated_minutes():
    base = lesson_time.estimate(BASE)
    nb = copy.deepcopy(BASE)
    nb.cells.append(nbformat.v4.new_code_cell('cam_explorer(question="How high does α climb?")'))
    nb.cells.append(nbformat.v4.new_code_cell("fourbar_explorer()"))
    nb.cells.append(nbformat.v4.new_markdown_cell("$$\\tan\\alpha = \\frac{s' - e}{s + s_0}$$"))
    t = lesson_time.estimate(nb)
    assert (t.widgets, t.questions, t.display_math, t.words) == (2, 1, 1, base.words)
    expected = (2 * lesson_time.CODE_CELL + 2 * lesson_time.CODE_LINE + lesson_time.WIDGET_QUESTION
                + lesson_time.WIDGET + lesson_time.DISPLAY_MATH)
    assert t.exact - base.exact == pytest.approx(expected)


def test_write_states_the_model_in_a_copy_of_the_course(tmp_path):
    """`--write` on a small course of two chapters: their Time lines, the intro's table, total and picture."""
    (tmp_path / "notebooks").mkdir()
    (tmp_path / "book").mkdir()
    for n, stem in enumerate(["00_first", "01_second"]):
        nb = copy.deepcopy(BASE)
        nb.cells[0].source = f"# {n} · Chapter\n\n## Prerequisites\n\n" + (
            "[0 · First](00_first.ipynb).\n\n" if n else "None.\n\n") + "## Time\n\nAbout 90 minutes.\n"
        nb.cells.append(nbformat.v4.new_markdown_cell("word " * (1200 * n)))
        nbformat.write(nb, tmp_path / "notebooks" / f"{stem}.ipynb")
    (tmp_path / "notebooks" / "companion").mkdir()
    nbformat.write(copy.deepcopy(BASE), tmp_path / "notebooks" / "companion" / "01_second_companion.ipynb")
    (tmp_path / "book" / "intro.md").write_text(
        "| chapter | you learn to | time | needs |\n|---|---|---|---|\n"
        "| [0 · First](notebooks/00_first.ipynb) | start | 90 min | — |\n"
        "| [1 · Second](notebooks/01_second.ipynb) | go on | 90 min | 0 |\n\nIn all 180 minutes, three hours.\n")
    changed = lesson_time.write(tmp_path)
    assert sorted(changed) == ["book/figures/learning_path.svg", "book/intro.md",
                               "notebooks/00_first.ipynb", "notebooks/01_second.ipynb"]
    times = [lesson_time.estimate(lesson_time.read(tmp_path / "notebooks" / f"{s}.ipynb")).minutes
             for s in ("00_first", "01_second")]
    assert times[1] > times[0]
    for stem, minutes in zip(("00_first", "01_second"), times, strict=False):
        assert lesson_time.stated(lesson_time.read(tmp_path / "notebooks" / f"{stem}.ipynb")) == minutes
    intro = (tmp_path / "book" / "intro.md").read_text()
    assert f"| start | {times[0]} min | — | — |" in intro and f"| go on | {times[1]} min | — | 0 |" in intro
    assert f"In all {sum(times)} minutes" in intro and "| time | exercises | needs |" in intro
    assert lesson_time.learning_path.chapters(tmp_path)[1].minutes == times[1]   # the picture reads the table
    assert lesson_time.write(tmp_path) == [], "a second --write changes nothing"
    assert "lecturer's companion" in lesson_time.table(tmp_path)


def test_write_refuses_a_chapter_without_a_time_line():
    nb = copy.deepcopy(BASE)
    nb.cells[0].source = "# 0 · No time\n\n## Time\n\nAn hour or so.\n"
    with pytest.raises(ValueError, match="no '## Time' section"):
        lesson_time.set_time(nbformat.writes(nb), 30, "00_x.ipynb")


@pytest.mark.parametrize("path", CHAPTERS, ids=lambda p: p.name)
def test_writing_a_time_changes_only_that_line(path):
    """Only the number moves, whatever order the notebook's keys are stored in."""
    old = path.read_text()
    said = lesson_time.stated(lesson_time.read(path))
    new = lesson_time.set_time(old, said + 5)
    diff = [(a, b) for a, b in zip(old.splitlines(), new.splitlines(), strict=False) if a != b]
    assert len(old.splitlines()) == len(new.splitlines()) and len(diff) == 1, diff
    assert lesson_time.stated(nbformat.reads(new, as_version=4)) == said + 5


def test_the_book_shows_the_companion_as_its_own_part_after_the_chapters():
    """The companion is no chapter for the model, nor for the book: its glob is a part of its own, and the
    chapters' glob does not reach into notebooks/companion/ (Sphinx's `*` stops at a `/`)."""
    parsing = pytest.importorskip("sphinx_external_toc.parsing")
    from sphinx.util.matching import patfilter

    site = parsing.parse_toc_yaml(ROOT / "book" / "_toc.yml")
    parts = {subtree.caption: [str(item) for item in subtree.items] for subtree in site.root.subtrees}
    captions = list(parts)
    assert captions.index("Chapters") + 1 == captions.index("Lecturer's companion")
    assert parts["Chapters"] == ["notebooks/*"] and parts["Lecturer's companion"] == ["notebooks/companion/*"]
    docs = [f"notebooks/{p.stem}" for p in CHAPTERS] + ["notebooks/companion/06_x_companion"]
    assert patfilter(docs, "notebooks/*") == [f"notebooks/{p.stem}" for p in CHAPTERS]
    assert patfilter(docs, "notebooks/companion/*") == ["notebooks/companion/06_x_companion"]
    assert {"notation", "install", "glossary", "errata"} <= set(parts["Back matter"])
    assert all((ROOT / "book" / f"{name}.md").exists() for name in parts["Back matter"])
