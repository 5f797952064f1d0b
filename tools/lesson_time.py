"""How long a chapter takes a student: one stated model, computed from the notebook itself.

    python tools/lesson_time.py            # a table: every chapter's words, cells, widgets, exercises, minutes
    python tools/lesson_time.py --write    # state the model's minutes in every chapter and in book/intro.md

**The student.** A third-year engineering student who works through the chapter in class: reads
every sentence, runs every teaching cell and reads what it shows, answers each widget's question
with the sliders and does the chapter's own exercises. Check cells (tag ``check``, folded away)
cost nothing: the student may skip them.

**The model** (minutes; every constant below is one of the module's names):

- *prose*: the words of the Markdown cells at :data:`WORDS_PER_MINUTE` = 120. Carver (1992)
  measured college readers at about 300 words per minute when they read to understand ("rauding"),
  200 when they read to learn and 138 when they read to memorise; the chapters are read to learn,
  with a symbol, a number or a figure to check in most sentences, and many of their readers read
  English as a second language, so the model takes the low end of Carver's learning band (the
  "engage with a text of many new concepts" purpose of Barre and Esarey's workload estimator, 2016,
  is slower than that "understand" rate too). An inline formula (``$…$``) counts as one word plus
  :data:`INLINE_MATH` (6 s to read a symbol group); a displayed equation (``$$…$$`` or an
  ``equation``/``align`` block) as :data:`DISPLAY_MATH` (a minute to follow it term by term) and no words.
- *worked code*: each code cell not tagged ``check`` costs :data:`CODE_CELL` (run it, wait, read its
  output or figure) plus :data:`CODE_LINE` for each non-blank line (reading code that calls a library
  one does not know yet: about 5 lines a minute).
- *widgets*: each explorer (a call to one of :func:`widget_functions`, the explorers of
  ``mechlab.widgets``) costs :data:`WIDGET`; one asked with a ``question=`` costs :data:`WIDGET_QUESTION`
  instead (read it, move the sliders until the answer shows, write it down).
- *exercises*: each of the chapter's own exercises costs :data:`EXERCISE` minutes by its kind —
  predict (a choice and its reason), explain (a few sentences), compute (a number with its unit),
  debug (find and fix the slip in given code), design (a mechanism meeting a specification), code
  (a function checked against mechlab). An exercise is a Markdown cell whose heading names the kind
  after "Exercise" or "Your turn" (``## Your turn · predict``, ``### Exercise 2 · compute (2 points)``,
  ``## Design exercise: …``), or a cell tagged ``exercise-<kind>``.

A chapter's time is the sum, rounded to the nearest 5 minutes (:func:`rounded`). The same rates
applied to the chapter's nbgrader assignment (``## Exercise n · kind`` headings) give the time of its
exercises after class, which book/intro.md lists beside the lesson.

**Where the numbers go.** ``--write`` rewrites the "## Time" line of each chapter (``About N
minutes.``), the time and exercises columns of the path's table in book/intro.md and its total ("In
all N minutes …"), and redraws the path's picture (tools/learning_path.py reads the table).
tests/test_lesson_time.py fails when a chapter, the table or the total disagrees with the model.
Notebooks in notebooks/companion/ (the lecturer's companion) are not lessons: the table lists their
estimate apart, and nothing requires them to state it.

References: R. P. Carver (1992), "Reading rate: theory, research, and practical implications",
*Journal of Reading* 36(2), 84–95. E. Barre and J. Esarey (2016), "Course workload estimator",
Rice University Center for Teaching Excellence.
"""

from __future__ import annotations

import argparse
import ast
import functools
import math
import re
import sys
from dataclasses import dataclass, field
from pathlib import Path

import nbformat

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "tools"))
import learning_path  # noqa: E402  (the path's picture, drawn from the intro's table)

WORDS_PER_MINUTE = 120.0
INLINE_MATH = 0.1        # minutes per inline formula, beyond its one word
DISPLAY_MATH = 1.0       # minutes per displayed equation
CODE_CELL = 1.5          # minutes to run a teaching cell and read its output
CODE_LINE = 0.2          # minutes per non-blank line of a teaching cell
WIDGET = 3.0             # an explorer without a question: move the sliders, watch
WIDGET_QUESTION = 5.0    # an explorer with a question: find the answer with the sliders
EXERCISE = {"predict": 3.0, "explain": 5.0, "compute": 8.0, "debug": 10.0, "design": 15.0, "code": 15.0}
ROUND_TO = 5

KINDS = "|".join(EXERCISE)
# "## Your turn · predict", "### Exercise 2 · compute (2 points)", "## Design exercise: ..." (not "## Exercises")
EXERCISE_HEADING = re.compile(
    rf"^#{{1,6}}[^\n]*?(?:(?:\bexercise\b|\byour turn\b)[^\n]*?\b(?P<after>{KINDS})\b"
    rf"|\b(?P<before>{KINDS})\s+exercise\b)", re.I | re.M)
DISPLAY = re.compile(r"\$\$.+?\$\$|\\begin\{(equation|align|gather|multline)\*?\}.+?\\end\{\1\*?\}", re.S)
INLINE = re.compile(r"(?<![\\$])\$(?!\$)[^$\n]+?(?<!\\)\$")
LINK = re.compile(r"!?\[([^\]]*)\]\([^)]*\)")
HTML = re.compile(r"<!--.*?-->|<[^>\n]+>", re.S)
TIME = re.compile(r"(## Time\s+About )(\d+)( minutes)")
# a row of the path's table: chapter, "you learn to", time, exercises (added by --write), needs
INTRO_ROW = re.compile(r"^(\| \[\d+[a-z]? · [^\]]+\]\(notebooks/(\w+)\.ipynb\) \|[^|\n]*\| )(\d+) min \|"
                       r"(?: (?:\d+ min|—) \|)?( [^|\n]* \|)$", re.M)
INTRO_TOTAL = re.compile(r"^In all \d+ minutes[^\n]*$", re.M)
ASSIGNMENT = re.compile(r"assignments/release/(\w+)/\1\.ipynb")


@dataclass
class LessonTime:
    """The model's reading of one notebook: what it counted and the minutes each part costs."""

    words: int = 0
    inline_math: int = 0
    display_math: int = 0
    code_cells: int = 0
    code_lines: int = 0
    widgets: int = 0
    questions: int = 0
    exercises: dict[str, int] = field(default_factory=dict)

    @property
    def prose(self) -> float:
        return self.words / WORDS_PER_MINUTE + self.inline_math * INLINE_MATH + self.display_math * DISPLAY_MATH

    @property
    def code(self) -> float:
        return self.code_cells * CODE_CELL + self.code_lines * CODE_LINE

    @property
    def widget(self) -> float:
        return (self.widgets - self.questions) * WIDGET + self.questions * WIDGET_QUESTION

    @property
    def exercise(self) -> float:
        return sum(EXERCISE[kind] * n for kind, n in self.exercises.items())

    @property
    def exact(self) -> float:
        """Minutes before rounding."""
        return self.prose + self.code + self.widget + self.exercise

    @property
    def minutes(self) -> int:
        return rounded(self.exact)


def rounded(minutes: float) -> int:
    """To the nearest :data:`ROUND_TO` minutes (halves up), at least one step: a lesson is never 0 minutes.

    Examples
    --------
    >>> rounded(42.4), rounded(42.5), rounded(0.3)
    (40, 45, 5)
    """
    return max(ROUND_TO, ROUND_TO * math.floor(minutes / ROUND_TO + 0.5))


def is_check(cell) -> bool:
    return "check" in cell.get("metadata", {}).get("tags", [])


def exercise_kinds(cell) -> list[str]:
    """The kinds of the exercises a cell opens: from its tags ``exercise-<kind>``, else from its headings."""
    tagged = [t.removeprefix("exercise-") for t in cell.get("metadata", {}).get("tags", [])
              if t.startswith("exercise-") and t.removeprefix("exercise-") in EXERCISE]
    if tagged or cell["cell_type"] != "markdown":
        return tagged
    return [(m.group("after") or m.group("before")).lower() for m in EXERCISE_HEADING.finditer(cell["source"])]


def prose_counts(text: str) -> tuple[int, int, int]:
    """(words, inline formulas, displayed equations) of Markdown text; a link counts by its words only."""
    display = len(DISPLAY.findall(text))
    text = HTML.sub(" ", DISPLAY.sub(" ", text))
    inline = len(INLINE.findall(text))
    text = INLINE.sub(" formula ", LINK.sub(r"\1", text))
    words = [w for w in text.split() if re.search(r"\w", w)]   # "|", "---", "-" of tables and lists are no words
    return len(words), inline, display


def estimate(nb) -> LessonTime:
    """The model applied to a notebook (an ``nbformat`` node or its dict).

    Examples
    --------
    >>> nb = {"cells": [{"cell_type": "markdown", "metadata": {}, "source": "word " * 240},
    ...                 {"cell_type": "code", "metadata": {}, "source": "x = 1\\ny = 2"},
    ...                 {"cell_type": "markdown", "metadata": {}, "source": "## Your turn · predict"}]}
    >>> t = estimate(nb)
    >>> (t.words, t.code_cells, t.exercises), round(t.exact, 2), t.minutes
    ((243, 1, {'predict': 1}), 6.92, 5)
    """
    t = LessonTime()
    for cell in nb["cells"]:
        source = "".join(cell["source"])
        cell = {**cell, "source": source}
        for kind in exercise_kinds(cell):
            t.exercises[kind] = t.exercises.get(kind, 0) + 1
        if cell["cell_type"] == "markdown":
            words, inline, display = prose_counts(source)
            t.words += words
            t.inline_math += inline
            t.display_math += display
        elif cell["cell_type"] == "code" and not is_check(cell):
            t.code_cells += 1
            t.code_lines += sum(1 for line in source.splitlines() if line.strip())
            widgets, questions = widget_calls(source)
            t.widgets += widgets
            t.questions += questions
    return t


@functools.cache
def widget_functions(root: Path = ROOT) -> frozenset[str]:
    """The explorers a chapter can call: public functions of mechlab/widgets/ named ``*_explorer`` or
    taking a ``question``, and the editors (public classes named ``*Editor`` whose ``__init__`` takes one: a
    chapter builds an editor itself, while the ``*Explorer`` classes are built by their functions), read from
    the source, without importing the widgets."""
    names = set()
    for module in (root / "mechlab" / "widgets").glob("*.py"):
        for node in ast.parse(module.read_text()).body:
            if isinstance(node, ast.ClassDef) and node.name.endswith("Editor"):
                fn = next((f for f in node.body if isinstance(f, ast.FunctionDef) and f.name == "__init__"), None)
            elif isinstance(node, ast.FunctionDef):
                fn = node
            else:
                continue
            args = [a.arg for a in fn.args.args + fn.args.kwonlyargs] if fn else []
            if not node.name.startswith("_") and (node.name.endswith("_explorer") or "question" in args):
                names.add(node.name)
    return frozenset(names)


def widget_calls(source: str) -> tuple[int, int]:
    """(explorers, explorers asked with a question) that a code cell calls."""
    try:
        tree = ast.parse(source)
    except SyntaxError:   # IPython syntax (%magic, !shell): no explorer call is read from such a cell
        return 0, 0
    calls = [node for node in ast.walk(tree) if isinstance(node, ast.Call)
             and getattr(node.func, "id", getattr(node.func, "attr", None)) in widget_functions()]
    return len(calls), sum(any(k.arg == "question" for k in c.keywords) for c in calls)


def read(path: Path):
    return nbformat.read(path, as_version=4)


def chapters(root: Path = ROOT) -> list[Path]:
    """The course's lessons: notebooks/NN_*.ipynb (the companion's folder is not among them)."""
    # "08a_…": a chapter inserted after 8 without renumbering the later ones; "08_" sorts before "08a_"
    return sorted(p for p in (root / "notebooks").glob("[0-9][0-9]*_*.ipynb") if re.match(r"\d\d[a-z]?_", p.name))


def companions(root: Path = ROOT) -> list[Path]:
    return sorted((root / "notebooks" / "companion").glob("*.ipynb"))


def stated(nb) -> int | None:
    """The minutes a chapter's "## Time" section states, None when it states none."""
    found = TIME.search("".join(nb["cells"][0]["source"]))
    return int(found.group(2)) if found else None


def assignment(nb, root: Path = ROOT) -> Path | None:
    """The source notebook of the nbgrader assignment that the chapter's closing cell names."""
    found = ASSIGNMENT.search("".join(nb["cells"][-1]["source"]))
    path = root / "assignments" / "source" / found.group(1) / f"{found.group(1)}.ipynb" if found else None
    return path if path and path.exists() else None


def exercises_minutes(nb, root: Path = ROOT) -> int | None:
    """The model's minutes for the chapter's assignment: its exercises by kind (None: no assignment)."""
    path = assignment(nb, root)
    if path is None:
        return None
    kinds = [k for cell in read(path).cells if cell.cell_type == "markdown" for k in exercise_kinds(cell)]
    return rounded(sum(EXERCISE[k] for k in kinds)) if kinds else None


# the Time line as the notebook's JSON holds it: '"## Time\n",', '"\n",', '"About 60 minutes.\n",'
TIME_JSON = re.compile(r'(## Time\\n",\s*(?:"\\n",\s*)*"About )(\d+)( minutes)')


def set_time(text: str, minutes: int, name: str = "the chapter") -> str:
    r"""The notebook's JSON text with ``minutes`` stated in its "## Time" line, and not one other byte changed
    (a notebook is not rewritten through nbformat: that could reorder the keys of a cell's metadata).

    Raises
    ------
    ValueError
        When the first cell has no "## Time" section of the form "About N minutes".

    Examples
    --------
    >>> set_time('{"source": ["## Time\\n", "\\n", "About 60 minutes.\\n"]}', 45)
    '{"source": ["## Time\\n", "\\n", "About 45 minutes.\\n"]}'
    """
    found = TIME_JSON.search(text)
    if not found:
        raise ValueError(f"{name}: its first cell has no '## Time' section saying 'About N minutes'")
    return f"{text[:found.start(2)]}{minutes}{text[found.end(2):]}"


def intro_text(intro: str, lesson: dict[str, int], homework: dict[str, int | None]) -> str:
    """book/intro.md with the model's minutes in the path's table (time, exercises) and its total."""
    missing = set(lesson) - set(m.group(2) for m in INTRO_ROW.finditer(intro))
    if missing:
        raise ValueError(f"book/intro.md: no row in the path's table for {sorted(missing)}")

    def row(m):
        stem = m.group(2)
        extra = homework.get(stem)
        return f"{m.group(1)}{lesson[stem]} min | {f'{extra} min' if extra else '—'} |{m.group(4)}"
    intro = INTRO_ROW.sub(row, intro)
    intro = re.sub(r"^\| chapter \| you learn to \| time \|(?: exercises \|)? needs "
                   r"\|\n\|---\|---\|---\|(?:---\|)?---\|",
                   "| chapter | you learn to | time | exercises | needs |\n|---|---|---|---|---|", intro, flags=re.M)
    total, extra = sum(lesson.values()), sum(v or 0 for v in homework.values())
    sentence = (f"In all {total} minutes of lessons, about {total / 60:.0f} hours; the exercises (one nbgrader "
                f"assignment per chapter) add about {extra} minutes. The times come from the model of "
                f"[Teaching with mechlab](teaching.md#how-long-a-chapter-takes).")
    if not INTRO_TOTAL.search(intro):
        raise ValueError("book/intro.md: no line 'In all N minutes' under the path's table")
    return INTRO_TOTAL.sub(lambda _: sentence, intro, count=1)


def write(root: Path = ROOT) -> list[str]:
    """State the model's times in every chapter and in book/intro.md, redraw the path; what changed."""
    changed, lesson, homework = [], {}, {}
    for path in chapters(root):
        nb = read(path)
        lesson[path.stem] = estimate(nb).minutes
        homework[path.stem] = exercises_minutes(nb, root)
        text = path.read_text()
        new = set_time(text, lesson[path.stem], path.name)
        if new != text:
            path.write_text(new)
            changed.append(str(path.relative_to(root)))
    intro_path = root / "book" / "intro.md"
    intro = intro_path.read_text()
    new = intro_text(intro, lesson, homework)
    if new != intro:
        intro_path.write_text(new)
        changed.append(str(intro_path.relative_to(root)))
    figure = root / "book" / "figures" / "learning_path.svg"
    picture = learning_path.svg(learning_path.chapters(root))
    if not figure.exists() or figure.read_bytes() != picture:
        figure.parent.mkdir(parents=True, exist_ok=True)
        figure.write_bytes(picture)
        changed.append(str(figure.relative_to(root)))
    return changed


def table(root: Path = ROOT) -> str:
    """Every chapter's counts and minutes (model, stated, assignment), then the companion's estimates."""
    head = (f"{'notebook':40s} {'words':>5s} {'math':>5s} {'cells':>5s} {'lines':>5s} {'widg':>4s} "
            f"{'exercises':16s} {'model':>5s} {'stated':>6s} {'assign':>6s}")
    lines = [head, "-" * len(head)]

    def line(path, t, said, extra):
        kinds = ", ".join(f"{n} {k}" for k, n in sorted(t.exercises.items())) or "—"
        return (f"{path.stem:40s} {t.words:5d} {t.inline_math:3d}/{t.display_math:<1d} {t.code_cells:5d} "
                f"{t.code_lines:5d} {t.widgets:4d} {kinds:16s} {t.minutes:5d} {said:>6} {extra:>6}")
    total = stated_total = extra_total = 0
    for path in chapters(root):
        nb = read(path)
        t, said, extra = estimate(nb), stated(nb), exercises_minutes(nb, root)
        total, stated_total, extra_total = total + t.minutes, stated_total + (said or 0), extra_total + (extra or 0)
        lines.append(line(path, t, "—" if said is None else said, "—" if extra is None else extra))
    lines.append(f"{'all chapters':40s} {'':>5s} {'':>5s} {'':>5s} {'':>5s} {'':>4s} {'':16s} {total:5d} "
                 f"{stated_total:6d} {extra_total:6d}")
    if companions(root):
        lines += ["", "lecturer's companion (not lessons: no stated time required)"]
        lines += [line(path, estimate(read(path)), "", "") for path in companions(root)]
    over = [p.stem for p in chapters(root) if estimate(read(p)).minutes > 60]
    lines += ["", f"over 60 minutes: {', '.join(over) if over else 'none'}",
              "math: inline/displayed formulas; assign: the chapter's nbgrader exercises, after class"]
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--write", action="store_true",
                        help="state the model's minutes in every chapter and in book/intro.md, redraw the path")
    args = parser.parse_args(argv)
    if args.write:
        changed = write()
        print("\n".join(f"wrote {c}" for c in changed) or "every stated time already agrees with the model")
    print(table())


if __name__ == "__main__":
    main()
