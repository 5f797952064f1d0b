"""The class report marks a submission whose cell was stopped at the time limit (a loop) as stopped, not as a
wrong or missing answer (assignments/report.py; end to end through assignments/course.py and nbgrader)."""

from __future__ import annotations

import csv
import sys
from pathlib import Path

import nbformat
import pytest

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "assignments"))
import report  # noqa: E402  (assignments/ is a folder of scripts, not a package)
from test_grading import DEPS, SOURCE, _answer_line, _auto_points, _fill, _run  # noqa: E402

AID = "forces"    # quick to grade; its exercise 2 is the answer the looping student never gets to


def _verdict(name, kind="correct"):
    return {"name": name, "kind": kind}


def test_an_answer_without_verdict_reads_stopped_only_where_a_cell_was_stopped(tmp_path):
    subs = [report.Submission("ann", AID, [_verdict("M"), _verdict("N")]),
            report.Submission("ben", AID, [_verdict("N")], stopped=["ex2"], timeout=60),
            report.Submission("cid", AID, [_verdict("N", "wrong")])]
    table = {(r["answer"], r["outcome"]): r["students"] for r in report.rows(subs, {AID: ["M", "N"]})}
    assert table == {("M", "right"): 1, ("M", "stopped: ran over 60 s"): 1,
                     ("M", "no verdict (cell did not finish)"): 1, ("N", "right"): 2, ("N", "wrong"): 1}
    report.write(subs, {AID: ["M", "N"]}, tmp_path)
    with open(tmp_path / "class_report.csv", newline="") as f:
        outcomes = [r["outcome"] for r in csv.DictReader(f)]
    assert "stopped: ben: ran over 60 s in ex2" in outcomes
    assert not [o for o in outcomes if o.startswith("flag:")]          # a loop is not a copy
    page = (tmp_path / "class_report.html").read_text()
    assert "Stopped at the time limit" in page and "ben: stopped: ran over 60 s in ex2" in page


@pytest.mark.skipif(not (DEPS / "nbgrader").is_dir(), reason="nbgrader: run `make nbgrader` first")
def test_a_looping_submission_is_reported_stopped(tmp_path):
    release, subs, out = tmp_path / "release", tmp_path / "subs", tmp_path / "out"
    _run("student", "--assignment", AID, "--out", str(release))
    src = nbformat.read(SOURCE / AID / f"{AID}.ipynb", as_version=4)
    edition = release / AID / f"{AID}.ipynb"
    right = _fill(nbformat.read(edition, as_version=4), src)
    looping = _fill(nbformat.read(edition, as_version=4), src)
    cell = _answer_line(looping, "ex2")
    cell.source = "while True:   # never reaches the answer\n    pass\n" + cell.source
    for who, nb in (("right", right), ("looping", looping)):
        (subs / who).mkdir(parents=True)
        nbformat.write(nb, subs / who / f"{AID}.ipynb")
    _run("grade", str(subs), "--out", str(out), "--timeout", "5")
    with open(out / "class_report.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    share = {(r["answer"], r["outcome"]): float(r["share"]) for r in rows if r["share"]}
    assert share[("balancing torque", "right")] == 0.5
    assert share[("balancing torque", "stopped: ran over 5 s")] == 0.5
    assert share[("guide reaction on the plan", "right")] == 1.0        # the cells after the loop still graded
    assert [r["outcome"] for r in rows if not r["answer"] and r["outcome"].startswith("stopped:")] == [
        "stopped: looping: ran over 5 s in ex2"]
    with open(out / "grades.csv", newline="") as f:
        grades = {r["student_id"]: float(r["raw_score"]) for r in csv.DictReader(f)}
    assert grades == {"right": _auto_points(AID), "looping": _auto_points(AID) - 2}
    assert "ran for more than 5 s and was stopped" in (out / "feedback" / "looping" / f"{AID}.html").read_text()
