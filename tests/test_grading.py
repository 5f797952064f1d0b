"""End to end through nbgrader (assignments/course.py, as `make student` and `make grade` run it), in tmp dirs.

One student edition; submissions of every assignment with the worked solutions (full marks); and, for
the Geneva assignment, the cases instructors report: wrong answers, no answers, a deleted graded cell, a
duplicated cell, a cell that never finishes, an error in an ungraded cell, a notebook downloaded twice.
nbgrader lives in assignments/.nbgrader-deps (`make nbgrader`).
"""

from __future__ import annotations

import copy
import csv
import html
import json
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import nbformat
import pytest

ROOT = Path(__file__).resolve().parents[1]
SOURCE = ROOT / "assignments" / "source"
DEPS = ROOT / "assignments" / ".nbgrader-deps"
IDS = sorted(p.name for p in SOURCE.iterdir() if (p / f"{p.name}.ipynb").is_file())
CASES = "geneva"  # the assignment every misbehaving submission is made of
TIMEOUT = 10      # seconds before the never-ending cell is interrupted

pytestmark = pytest.mark.skipif(not (DEPS / "nbgrader").is_dir(), reason="nbgrader: run `make nbgrader` first")


def _run(*args: str) -> str:
    env = dict(os.environ, PYTHONPATH=f"{DEPS}{os.pathsep}{ROOT}",
               PATH=f"{DEPS / 'bin'}{os.pathsep}{os.environ['PATH']}")
    res = subprocess.run([sys.executable, str(ROOT / "assignments" / "course.py"), *args], env=env,
                         capture_output=True, text=True, timeout=1800)
    assert res.returncode == 0, res.stdout + res.stderr
    return res.stdout


STUB = "# YOUR ANSWER HERE (replace the ... above)"   # nbgrader_config.py's ClearSolutions.code_stub


def _solution(cell) -> str:
    """A source cell's worked solution (the lines of its solution region)."""
    lines = cell.source.splitlines()
    i, j = lines.index("### BEGIN SOLUTION"), lines.index("### END SOLUTION")
    return "\n".join(lines[i + 1:j])


def _regions(source: str, begin: str, end: str) -> list[str]:
    return [block for block in re.findall(f"{begin}\n(.*?)\n{end}", source, flags=re.S)]


def _cells(nb, kind: str):
    return [c for c in nb.cells if c.metadata.get("nbgrader", {}).get(kind)]


def _answered(aid: str, release: Path, good: int | None = None):
    """The student edition of ``aid`` with the first ``good`` exercises answered right (all by default)
    and the others answered by a wrong number."""
    src = nbformat.read(SOURCE / aid / f"{aid}.ipynb", as_version=4)
    nb = nbformat.read(release / aid / f"{aid}.ipynb", as_version=4)
    solved = {c.metadata.nbgrader.grade_id: _solution(c) for c in _cells(src, "solution")}
    for k, cell in enumerate(_cells(nb, "solution")):
        right = good is None or k < good
        if cell.cell_type == "markdown":                      # an explanation, graded by hand
            cell.source = solved[cell.metadata.nbgrader.grade_id] if right else "I do not know."
            continue
        assert STUB in cell.source
        cell.source = (cell.source.replace(STUB, solved[cell.metadata.nbgrader.grade_id]) if right
                       else cell.source.replace(STUB, "").replace("...", "0.123"))
    return nb


@pytest.fixture(scope="module")
def release(tmp_path_factory):
    """The student edition of every assignment (`make student`), made once: the tests below only read it."""
    out = tmp_path_factory.mktemp("edition") / "release"
    _run("student", "--out", str(out))
    return out


@pytest.fixture(scope="module")
def graded(tmp_path_factory, release):
    tmp = tmp_path_factory.mktemp("course")
    subs, out = tmp / "submissions", tmp / "graded"
    books = {"alice": {aid: _answered(aid, release) for aid in IDS}}
    n = len(_cells(books["alice"][CASES], "solution"))
    books["bob"] = {CASES: nbformat.read(release / CASES / f"{CASES}.ipynb", as_version=4)}   # nothing answered
    books["carol"] = {CASES: _answered(CASES, release, good=2)}                                 # two right
    deleted = _answered(CASES, release)
    gone = (_cells(deleted, "grade")[2], _cells(deleted, "solution")[2])     # the check of ex. 2, the answer to ex. 3
    deleted.cells = [c for c in deleted.cells if all(c is not g for g in gone)]
    books["dave"] = {CASES: deleted}
    copied = _answered(CASES, release)
    k = copied.cells.index(_cells(copied, "solution")[0])
    copied.cells.insert(k + 1, copy.deepcopy(copied.cells[k]))
    copied.cells[k + 1]["id"] = "pasted"                                   # JupyterLab gives a pasted cell a new id
    books["erin"] = {CASES: copied}
    endless = _answered(CASES, release)
    endless.cells.insert(2, nbformat.v4.new_code_cell("import time\nwhile True:\n    time.sleep(0.1)"))
    endless.cells.insert(3, nbformat.v4.new_code_cell("1 / 0  # an error in an ungraded cell"))
    books["frank"] = {CASES: endless}
    for student, nbs in books.items():
        for aid, nb in nbs.items():
            (subs / student).mkdir(parents=True, exist_ok=True)
            nbformat.write(nb, subs / student / f"{aid}.ipynb")
    # gina downloaded twice: the empty edition first, then her answers as "geneva (1).ipynb"
    (subs / "gina" / "work").mkdir(parents=True)
    nbformat.write(books["bob"][CASES], subs / "gina" / f"{CASES}.ipynb")
    os.utime(subs / "gina" / f"{CASES}.ipynb", (1e9, 1e9))
    nbformat.write(_answered(CASES, release), subs / "gina" / "work" / f"{CASES} (1).ipynb")
    _run("grade", str(subs), "--out", str(out), "--timeout", str(TIMEOUT))
    with open(out / "grades.csv", newline="") as f:
        rows = {(r["student_id"], r["assignment"]): r for r in csv.DictReader(f)}
    return dict(release=release, out=out, rows=rows, n=n)


def _score(graded, student, aid=CASES) -> tuple[float, float]:
    row = graded["rows"][(student, aid)]
    return float(row["raw_score"]), float(row["max_score"])


def _feedback(graded, student, aid=CASES) -> str:
    """The feedback page's text (its style sheets left out)."""
    page = (graded["out"] / "feedback" / student / f"{aid}.html").read_text()
    return html.unescape(re.sub(r"<style.*?</style>", "", page, flags=re.S))


def _points(aid: str) -> list[float]:
    src = nbformat.read(SOURCE / aid / f"{aid}.ipynb", as_version=4)
    return [c.metadata.nbgrader.points for c in _cells(src, "grade")]


def _auto_points(aid: str) -> float:
    """The points the autograder gives (an explanation's points wait for the lecturer)."""
    src = nbformat.read(SOURCE / aid / f"{aid}.ipynb", as_version=4)
    return sum(c.metadata.nbgrader.points for c in _cells(src, "grade") if c.cell_type == "code")


def test_worked_solutions_get_full_marks(graded):
    for aid in IDS:
        score, top = _score(graded, "alice", aid)
        assert top == sum(_points(aid)) > 0 and score == _auto_points(aid), (aid, score, top)
        assert "✓" in _feedback(graded, "alice", aid)


def test_wrong_and_empty_answers_get_partial_and_zero_marks_with_feedback(graded):
    pts = _points(CASES)
    assert _score(graded, "carol") == (sum(pts[1:3]), sum(pts))     # the setup cell counts 0 points
    assert _score(graded, "bob") == (0.0, sum(pts))
    assert "✗" in _feedback(graded, "carol") and "no answer yet" in _feedback(graded, "bob")


def test_what_students_do_does_not_stop_grading(graded):
    pts, auto = _points(CASES), _auto_points(CASES)                 # an explanation's points wait for the lecturer
    # the deleted check cell comes back and is graded; the deleted answer loses its exercise only
    assert _score(graded, "dave") == (auto - pts[3], sum(pts))
    assert "was missing from the submission" in _feedback(graded, "dave")
    assert _score(graded, "erin")[0] == auto
    assert _score(graded, "frank")[0] == auto                       # a cell left running, an ungraded error
    assert _score(graded, "gina")[0] == auto                        # the notebook saved last counts
    assert "ZeroDivisionError" in _feedback(graded, "frank")
    assert f"ran for more than {TIMEOUT} s and was stopped (an endless loop?)" in _feedback(graded, "frank")
    assert "CellTimeoutError" not in _feedback(graded, "frank")                 # plain words, not a traceback


def _right_values(graded) -> set[str]:
    """The numbers the worked solutions are praised for ("✓ crank radius = 57.4 mm: right to …")."""
    text = "".join(_feedback(graded, "alice", aid) for aid in IDS)
    return set(re.findall(r"✓ [^=\n]* = (-?[0-9.]+(?:e[-+]?\d+)?)[^:\n]*: right to", text))


def test_hidden_tests_and_answers_stay_hidden(graded):
    values = _right_values(graded)
    assert len(values) >= len(IDS), values
    own = set(re.findall(r"✓ [^=\n]* = (-?[0-9.]+)[^:\n]*: right to", _feedback(graded, "carol")))  # her own
    for student in ("bob", "carol"):
        page = _feedback(graded, student)
        assert "BEGIN HIDDEN" not in page and "check(crank_radius, ml." not in page
        assert not [v for v in values - own if re.search(rf"(?<![\d.]){re.escape(v)}(?!\d)", page)]


def test_student_edition_has_no_solution_and_no_answer(graded):
    values = _right_values(graded)
    for aid in IDS:
        src = (SOURCE / aid / f"{aid}.ipynb").read_text()
        text = (graded["release"] / aid / f"{aid}.ipynb").read_text()
        nb = nbformat.reads(src, as_version=4)
        hidden = [block for c in nb.cells for block in _regions(c.source, "### BEGIN SOLUTION", "### END SOLUTION")
                  + _regions(c.source, "### BEGIN HIDDEN TESTS", "### END HIDDEN TESTS")]
        shown = "\n".join(c.source for c in nb.cells)
        for block in hidden:
            shown = shown.replace(block, "")
        secret = [line.strip() for block in hidden for line in block.splitlines()
                  if len(line.strip()) > 12 and line.strip() not in shown]      # lines only the lecturer sees
        student = "\n".join(c.source for c in nbformat.reads(text, as_version=4).cells)
        assert secret and not [s for s in secret if s in student], aid
        assert "BEGIN SOLUTION" not in student and "HIDDEN TESTS" not in student
        assert not [v for v in values if len(v) > 3 and v in student], aid


def test_the_editions_links_open_from_my_notebooks(release, tmp_path):
    """The chapters tell the student to save the edition in my-notebooks/, the working copy `course.py sync`
    makes: there, the header's link opens the chapter, and every other relative link opens a file too."""
    work = tmp_path / "my-notebooks"
    subprocess.run([sys.executable, str(ROOT / "course.py"), "sync", "--workdir", str(work)], check=True,
                   capture_output=True, timeout=300)
    for aid in IDS:
        nb = nbformat.read(release / aid / f"{aid}.ipynb", as_version=4)
        links = [link for c in nb.cells if c.cell_type == "markdown"
                 for link in re.findall(r"\]\(([^)#\s]+)", c.source) if "://" not in link]
        assert [link for link in links if re.fullmatch(r"\d\d[a-z]?_\w+\.ipynb", link)], (aid, links)   # its chapter
        assert not [link for link in links if not (work / link).is_file()], (aid, links)


SLOT = "dwell_curved_slot"   # the assignment whose design exercise writes a file (a DXF) and checks it


def _with_answer(nb, grade_id: str, code: str):
    for cell in _cells(nb, "solution"):
        if cell.metadata.nbgrader.grade_id == grade_id:
            cell.source = code
    return nb


def test_a_submission_never_gets_credit_for_another_submissions_file(release, tmp_path, monkeypatch):
    """alice writes the DXF (beside her notebook and into the temp folder); mallory submits the right design,
    writes no DXF and copies whatever lies in the temp folder. Graded in sequence, she must get no credit for
    alice's file, and grading leaves nothing in the temp folder."""
    subs, out, temp = (tmp_path / name for name in ("subs", "out", "temp"))
    temp.mkdir()
    src = nbformat.read(SOURCE / SLOT / f"{SLOT}.ipynb", as_version=4)
    design = next(c for c in _cells(src, "solution") if c.metadata.nbgrader.grade_id == "ex5")
    right = _solution(design)
    assert 'write_dxf(design, "packaging_slot.dxf")' in right
    shared = 'import os, tempfile\nfrom mechlab.synthesis.slot_export import write_dxf\n' \
             'write_dxf(design, os.path.join(tempfile.gettempdir(), "packaging_slot.dxf"))'
    alice = _with_answer(_answered(SLOT, release), "ex5", right + "\n" + shared)
    copying = ('import os, shutil, tempfile\n' + right.replace('write_dxf(design, "packaging_slot.dxf")', "") +
               '\nleft = os.path.join(tempfile.gettempdir(), "packaging_slot.dxf")\n'
               'if os.path.exists(left):\n    shutil.copy(left, "packaging_slot.dxf")')
    mallory = _with_answer(_answered(SLOT, release), "ex5", copying)
    for student, nb in (("alice", alice), ("mallory", mallory)):
        (subs / student).mkdir(parents=True)
        nbformat.write(nb, subs / student / f"{SLOT}.ipynb")
    for name in ("TMPDIR", "TMP", "TEMP"):
        monkeypatch.setenv(name, str(temp))
    _run("grade", str(subs), "--out", str(out), "--timeout", str(TIMEOUT))
    with open(out / "grades.csv", newline="") as fh:
        rows = {r["student_id"]: r for r in csv.DictReader(fh)}
    pts = _auto_points(SLOT)                                        # the explanation waits for the lecturer
    assert float(rows["alice"]["raw_score"]) == pts
    assert float(rows["mallory"]["raw_score"]) == pts - 4           # the design exercise's 4 points
    assert "no DXF file" in (out / "feedback" / "mallory" / f"{SLOT}.html").read_text()
    assert list(temp.iterdir()) == []


def test_a_dxf_outside_the_notebooks_folder_is_not_read(tmp_path, monkeypatch):
    """The check reads only files in the working folder: a path into a shared folder is refused by name."""
    import mechlab as ml
    from mechlab.course.exercises import dwell_slot_design
    from mechlab.synthesis.slot_export import write_dxf

    design = ml.curved_slot_dwell(0.3, 1.03, 2.61, transition="quintic")
    elsewhere = tmp_path / "shared" / "slot.dxf"
    elsewhere.parent.mkdir()
    write_dxf(design, elsewhere)
    (tmp_path / "mine").mkdir()
    monkeypatch.chdir(tmp_path / "mine")
    report = dwell_slot_design(design, min_dwell=80, max_pressure=80, dxf=elsewhere)
    assert not report and "beside this notebook" in report.problem
    write_dxf(design, "slot.dxf")
    assert dwell_slot_design(design, min_dwell=80, max_pressure=80, dxf="slot.dxf")


def _grades(out: Path) -> dict[tuple[str, str], dict]:
    with open(out / "grades.csv", newline="") as f:
        return {(r["student_id"], r["assignment"]): r for r in csv.DictReader(f)}


def test_grading_accumulates_and_keeps_what_it_replaces(graded, release, tmp_path):
    """A second `make grade` (a late submission, a re-graded student) adds to the first (the class graded above);
    the replaced row and feedback are kept in history; --fresh refuses without a confirmation and keeps the old
    batch too."""
    out = tmp_path / "out"
    shutil.copytree(graded["out"], out)
    first = _grades(out)
    assert float(first[("bob", CASES)]["raw_score"]) == 0.0 and not (out / "history").exists()
    empty = nbformat.read(release / CASES / f"{CASES}.ipynb", as_version=4)
    second, third = tmp_path / "batch2", tmp_path / "batch3"
    for folder, student, nb in ((second, "bob", _answered(CASES, release)), (second, "late", empty),
                                (third, "later", empty)):
        (folder / student).mkdir(parents=True)
        nbformat.write(nb, folder / student / f"{CASES}.ipynb")
    top = _auto_points(CASES)                          # the explanation waits for the lecturer
    _run("grade", str(second), "--out", str(out), "--timeout", str(TIMEOUT))
    rows = _grades(out)
    assert set(rows) == set(first) | {("late", CASES)}
    assert [k for k in first if rows[k] != first[k]] == [("bob", CASES)]   # the others untouched by the second batch
    assert float(rows[("bob", CASES)]["raw_score"]) == top                   # replaced by his re-submission
    with open(out / "history.csv", newline="") as f:
        old = list(csv.DictReader(f))
    assert [(r["student_id"], float(r["raw_score"])) for r in old] == [("bob", 0.0)] and old[0]["replaced_at"]
    assert (out / "feedback" / "alice" / f"{CASES}.html").is_file()
    kept = list((out / "history").glob(f"*/feedback/bob/{CASES}.html"))
    assert len(kept) == 1 and "no answer yet" in kept[0].read_text()
    env = dict(os.environ, PYTHONPATH=f"{DEPS}{os.pathsep}{ROOT}")
    refused = subprocess.run([sys.executable, str(ROOT / "assignments" / "course.py"), "grade", str(third),
                              "--out", str(out), "--fresh"], env=env, capture_output=True, text=True,
                             stdin=subprocess.DEVNULL, timeout=300)
    assert refused.returncode != 0 and "--yes" in refused.stderr + refused.stdout
    assert _grades(out) == rows                                             # nothing changed
    _run("grade", str(third), "--out", str(out), "--timeout", str(TIMEOUT), "--fresh", "--yes")
    assert set(_grades(out)) == {("later", CASES)}
    assert len(list((out / "history").glob("*/grades.csv"))) == 1


# -- a variant per student, and what the class got wrong ---------------------------------------------------
VARIANT = "geneva_spherical"                      # the assignment the class below submits
# ten: the swapped pair and eight others, each graded by nbgrader in a kernel of its own (≈5 CPU-s each);
# MECHLAB_CLASS_SIZE=30 runs a whole class
CLASS = int(os.environ.get("MECHLAB_CLASS_SIZE", "10"))


def _fill(nb, src, which=None, wrong="0.123"):
    """``nb`` (a student's edition) with its answers from the worked solutions (``which``: the grade ids to
    answer right, all by default; the others get ``wrong``)."""
    solved = {c.metadata.nbgrader.grade_id: _solution(c) for c in _cells(src, "solution")}
    for cell in _cells(nb, "solution"):
        gid = cell.metadata.nbgrader.grade_id
        right = which is None or gid in which
        if cell.cell_type == "markdown":
            cell.source = solved[gid] if right else "I do not know."
        else:
            cell.source = cell.source.replace(STUB, solved[gid] if right else "").replace("...", wrong) \
                if right or wrong is not None else cell.source
    return nb


def _answer_line(nb, gid):
    return next(c for c in _cells(nb, "solution") if c.metadata.nbgrader.grade_id == gid)


@pytest.fixture(scope="module")
def klass(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("class")
    ids = [f"s{k:02d}" for k in range(CLASS)]
    (tmp / "class.csv").write_text("student_id\n" + "\n".join(ids) + "\n")
    release, subs, out = tmp / "release", tmp / "submissions", tmp / "graded"
    _run("student", "--class", str(tmp / "class.csv"), "--assignment", VARIANT, "--out", str(release))
    # made again for a few of them, listed in another order in a smaller class: the same bytes, whatever the list
    again, regenerated = tmp / "again", ids[::-6]
    (tmp / "again.csv").write_text("student_id\n" + "\n".join(regenerated) + "\n")
    _run("student", "--class", str(tmp / "again.csv"), "--assignment", VARIANT, "--out", str(again))
    src = nbformat.read(SOURCE / VARIANT / f"{VARIANT}.ipynb", as_version=4)
    books = {who: _fill(nbformat.read(release / who / VARIANT / f"{VARIANT}.ipynb", as_version=4), src)
             for who in ids}
    # s00 and s01 swap their compute answers (each computed from the other's numbers)
    for a, b in (("s00", "s01"), ("s01", "s00")):
        theirs = nbformat.read(release / b / VARIANT / f"{VARIANT}.ipynb", as_version=4)
        v = variants_numbers(theirs)
        for gid in ("ex2", "ex3", "ex4"):
            cell = _answer_line(books[a], gid)
            cell.source = cell.source.replace('V["', '_THEIRS["')
            cell.source = f"_THEIRS = {v!r}\n" + cell.source
    for who, nb in books.items():
        (subs / who).mkdir(parents=True)
        nbformat.write(nb, subs / who / f"{VARIANT}.ipynb")
    _run("grade", str(subs), "--out", str(out), "--timeout", str(TIMEOUT), "--class", str(tmp / "class.csv"))
    with open(out / "grades.csv", newline="") as f:
        rows = {r["student_id"]: r for r in csv.DictReader(f)}
    return dict(ids=ids, release=release, again=again, regenerated=regenerated, out=out, rows=rows)


def variants_numbers(nb) -> dict:
    sys.path.insert(0, str(ROOT / "assignments"))
    import variants
    return variants.numbers(nb)[0]


def test_each_student_gets_numbers_of_their_own_and_the_same_again(klass):
    seen = set()
    for who in klass["ids"]:
        nb = klass["release"] / who / VARIANT / f"{VARIANT}.ipynb"
        numbers = variants_numbers(nbformat.read(nb, as_version=4))
        seen.add(json.dumps(numbers, sort_keys=True))
        if who in klass["regenerated"]:
            assert nb.read_bytes() == (klass["again"] / who / VARIANT / f"{VARIANT}.ipynb").read_bytes()
        text = nb.read_text()
        assert "BEGIN SOLUTION" not in text and "HIDDEN TESTS" not in text and "self_check(" in text
    assert len(seen) == len(klass["ids"])
    assert sorted(p.name for p in klass["again"].iterdir()) == sorted(klass["regenerated"])


def test_every_variant_solved_scores_full_marks_and_swapped_answers_are_flagged(klass):
    pts = _auto_points(VARIANT)
    swapped = sum(_points(VARIANT)[k] for k in (2, 3, 4))     # the check cells of ex2-4 (after setup and ex1)
    for who in klass["ids"]:
        score = float(klass["rows"][who]["raw_score"])
        assert score == (pts - swapped if who in ("s00", "s01") else pts), (who, score)
    with open(klass["out"] / "class_report.csv", newline="") as f:
        flags = [r["outcome"] for r in csv.DictReader(f) if r["outcome"].startswith("flag:")]
    assert any(f.startswith("flag: s00:") and "s01's answer" in f for f in flags), flags
    assert any(f.startswith("flag: s01:") and "s00's answer" in f for f in flags), flags
    assert not [f for f in flags if not f.startswith(("flag: s00:", "flag: s01:"))], flags


@pytest.fixture(scope="module")
def planted(tmp_path_factory):
    """A class of six on the variant assignment: right, slipped, wrong, copied, empty, looping."""
    tmp = tmp_path_factory.mktemp("planted")
    ids = ["right", "slipped", "wrong", "copied", "empty", "looping"]
    (tmp / "class.csv").write_text("\n".join(ids) + "\n")
    release, subs, out = tmp / "release", tmp / "submissions", tmp / "graded"
    _run("student", "--class", str(tmp / "class.csv"), "--assignment", VARIANT, "--out", str(release))
    src = nbformat.read(SOURCE / VARIANT / f"{VARIANT}.ipynb", as_version=4)
    edition = {who: nbformat.read(release / who / VARIANT / f"{VARIANT}.ipynb", as_version=4) for who in ids}
    books = {"right": _fill(edition["right"], src), "wrong": _fill(edition["wrong"], src, which=set()),
             "empty": edition["empty"], "copied": _fill(copy.deepcopy(edition["right"]), src),
             "slipped": _fill(edition["slipped"], src), "looping": _fill(edition["looping"], src)}
    slip = _answer_line(books["slipped"], "ex2")
    slip.source += "\nindex_time = index_time * 1000  # in ms"                    # a unit slip
    # a loop that waits, not one that spins (tests/test_report_stopped.py has that one): its 10 s take no CPU
    books["looping"].cells.insert(3, nbformat.v4.new_code_cell("import time\nwhile True:\n    time.sleep(0.1)"))
    for who, nb in books.items():
        (subs / who).mkdir(parents=True)
        nbformat.write(nb, subs / who / f"{VARIANT}.ipynb")
    _run("grade", str(subs), "--out", str(out), "--timeout", str(TIMEOUT), "--class", str(tmp / "class.csv"))
    with open(out / "class_report.csv", newline="") as f:
        report = list(csv.DictReader(f))
    return dict(out=out, report=report)


def test_the_class_report_shows_shares_slips_and_flags(planted):
    rows = planted["report"]
    share = {(r["answer"], r["outcome"]): float(r["share"]) for r in rows if r["share"]}
    # index time: right for right, copied (the right student's answers, graded against copied's own numbers:
    # the copied notebook's locked numbers are restored, the answers recomputed from them) and looping
    assert share[("index time", "right")] == pytest.approx(3 / 6, abs=1e-3)
    assert share[("index time", "ms for s")] == pytest.approx(1 / 6, abs=1e-3)
    assert share[("index time", "wrong")] == pytest.approx(1 / 6, abs=1e-3)
    assert share[("index time", "no answer")] == pytest.approx(1 / 6, abs=1e-3)
    flags = [r["outcome"] for r in rows if r["outcome"].startswith("flag:")]
    assert flags == ["flag: copied: carries the numbers of right"], flags
    assert share[("Geneva drive design", "every specification met")] == pytest.approx(4 / 6, abs=1e-3)
    assert share[("Geneva drive design", "missed: could not be examined")] == pytest.approx(2 / 6, abs=1e-3)
    page = (planted["out"] / "class_report.html").read_text()
    assert "What the class got wrong" in page and "carries the numbers of right" in page
