"""Five students at once on a JupyterHub on 127.0.0.1 (tests_hub/hub_load.py): every one logs
in, gets a server, runs a whole chapter and moves a slider; and one student opens an assignment
through the link a lecturer hands out. Run by `make test-hub`."""

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
sys.path.insert(0, str(HERE))
import hub_load  # noqa: E402


def test_five_students_run_a_chapter_and_move_a_slider():
    done = subprocess.run([sys.executable, str(HERE / "hub_load.py"), "--students", "5"], capture_output=True,
                          text=True, timeout=1200)
    assert done.returncode == 0, done.stderr[-3000:]
    report = json.loads(done.stdout.splitlines()[-1])
    assert report["succeeded"] == 5, report["errors"]
    assert 0 < report["slider"]["p95"] < report["cells"]["p50"]  # a slider move is far cheaper than a chapter
    assert 50 < report["pss_mb"]["p50"] < 2000  # a server and its kernel, not nothing and not a leak


def test_the_capacity_table_quotes_the_saved_runs():
    """benchmarks/README.md's table of a class on one hub is the JSON of the runs `make bench-hub STUDENTS=N`
    saved (benchmarks/hub_load_N.json), not figures copied by hand that go stale."""
    runs = [json.loads(hub_load.results_file(n).read_text()) for n in (10, 20)]
    assert hub_load.table(runs) in (HERE.parent / "benchmarks" / "README.md").read_text()


ASSIGNMENT = "getting_started"
NBGRADER_DEPS = ROOT / "assignments" / ".nbgrader-deps"


def student_editions(tmp_path: Path) -> str:
    """The lecturer's side (book/teaching.md, "A class on a JupyterHub"): the student edition of ASSIGNMENT
    made by `make student` (assignments/course.py with nbgrader), committed to a git repository of its own;
    returns the repository's URL."""
    if not (NBGRADER_DEPS / "nbgrader").is_dir():
        pytest.fail(f"nbgrader not in {NBGRADER_DEPS}: run `make nbgrader` (make test-hub does)")
    repo = tmp_path / "course-assignments"
    env = {**os.environ, "PATH": f"{NBGRADER_DEPS / 'bin'}{os.pathsep}{os.environ['PATH']}",
           "PYTHONPATH": os.pathsep.join([str(NBGRADER_DEPS), str(ROOT), str(ROOT / "tools")])}
    subprocess.run([sys.executable, str(ROOT / "assignments" / "course.py"), "student", "--assignment", ASSIGNMENT,
                    "--out", str(repo)], env=env, check=True, capture_output=True, timeout=600)
    git = ["git", "-C", str(repo), "-c", "user.name=lecturer", "-c", "user.email=lecturer@127.0.0.1"]
    for args in (["init", "-q", "-b", "main"], ["add", "."], ["commit", "-q", "-m", "student editions"]):
        subprocess.run(git + args, check=True, capture_output=True, timeout=60)
    return repo.as_uri()


def test_a_student_opens_an_assignment_from_the_lecturers_link(tmp_path):
    """A student clicks the assignment link (nbgitpuller through the hub's user-redirect, the route the chapters'
    Exercises sections name): it lands on their server, puts the student edition into their home at the link's
    path, unchanged, and the edition runs on the hub's image. Unanswered, every check says so in plain words:
    "no answer yet" / "no choice yet" for a value, the first failing case for the colleague's code to debug, and
    the design check's NotYet (nbgrader's failed-check signal); no other error, no solution in the edition."""
    repo = student_editions(tmp_path)
    path = f"{ASSIGNMENT}/{ASSIGNMENT}.ipynb"
    released = json.loads((tmp_path / "course-assignments" / path).read_text())
    with hub_load.running_hub(str(hub_load.CHP)) as (base, api, _, _):
        seen = hub_load.open_assignment(base, api, "student-a", repo, path)
    assert seen["landed"].startswith(f"{base}/user/student-a/git-pull?"), seen["landed"]
    assert seen["phases"][-1] == "finished", seen["phases"]
    assert [c["source"] for c in seen["notebook"]["cells"]] == ["".join(c["source"]) for c in released["cells"]]
    assert "BEGIN SOLUTION" not in json.dumps(released) and "BEGIN HIDDEN TESTS" not in json.dumps(released)
    cells = seen["cells"]
    checks = [c for c in cells if (c["id"] or "").endswith("_check")]
    assert len(checks) >= 5, cells
    assert [c["error"] for c in cells if c not in checks] == [None] * (len(cells) - len(checks)), cells
    for check in checks:
        assert check["error"] in (None, "NotYet"), check
        assert any(words in check["said"] for words in ("no answer yet", "no choice yet", "no design yet",
                                                       "✗ case 1 of")), check
