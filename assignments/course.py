"""The lecturer's two commands around nbgrader (see README, "For lecturers"); run by `make student` and `make grade`.

    python assignments/course.py student [--out assignments/release]
    python assignments/course.py grade SUBMISSIONS [--out assignments/graded] [--timeout 60]

Both work in a fresh temporary nbgrader course (this folder's ``source/`` and ``nbgrader_config.py``), so
nothing tracked is written. ``student`` writes the student edition (solutions and hidden tests removed).
``grade`` takes a folder with one sub-folder per student holding that student's notebooks, named
``<assignment id>.ipynb`` (or a re-download's ``<id> (1).ipynb``: the last saved counts) anywhere below
it; it autogrades them (a cell left running is interrupted after ``--timeout`` seconds, deleted graded
cells are restored, an error in any cell does not stop the run) and writes ``grades.csv`` (nbgrader's
gradebook export) and ``feedback/<student>/<assignment>.html``.
"""

from __future__ import annotations

import argparse
import csv
import re
import shutil
import sys
import tempfile
import uuid
from pathlib import Path

import nbformat

HERE = Path(__file__).resolve().parent
IDS = sorted(p.name for p in (HERE / "source").iterdir() if (p / f"{p.name}.ipynb").is_file())


def _course(work: Path) -> Path:
    shutil.copytree(HERE / "source", work / "source")
    shutil.copy(HERE / "nbgrader_config.py", work)
    return work


def _api(work: Path, **settings):
    """nbgrader's Python API on the course in ``work`` (one process for every step: nbgrader's start-up is slow),
    configured by nbgrader_config.py and then ``settings`` ({"Execute.timeout": 10, ...})."""
    from nbgrader.apps import NbGraderAPI
    from nbgrader.coursedir import CourseDirectory
    from traitlets.config.loader import PyFileConfigLoader

    config = PyFileConfigLoader("nbgrader_config.py", path=str(work)).load_config()
    config.CourseDirectory.root = str(work)
    for key, value in settings.items():
        section, name = key.split(".")
        setattr(config[section], name, value)
    return NbGraderAPI(coursedir=CourseDirectory(config=config), config=config)


def _done(result: dict, what: str) -> bool:
    if not result["success"]:
        print(f"{what} failed:\n{result.get('error') or result.get('log', '')}")
    return result["success"]


def _release(api, ids) -> None:
    for aid in ids:
        if not _done(api.generate_assignment(aid, force=True, create=True), f"generate_assignment {aid}"):
            sys.exit(1)


def student(out: Path) -> None:
    with tempfile.TemporaryDirectory() as tmp:
        work = _course(Path(tmp))
        _release(_api(work), IDS)
        shutil.rmtree(out, ignore_errors=True)
        shutil.copytree(work / "release", out)
    print(f"student edition of {len(IDS)} assignments: {out}")


def _assignment_id(nb: Path) -> str:
    """The assignment a notebook belongs to: its name without a browser's download counter ("geneva (1)")."""
    return re.sub(r"\s*\(\d+\)$", "", nb.stem)


def _collect(submissions: Path, work: Path) -> dict[str, list[str]]:
    """Copy every student's notebooks into nbgrader's submitted/<student>/<id>/<id>.ipynb; of two notebooks
    of one assignment (a re-download), the one saved last is graded."""
    latest: dict[tuple[str, str], Path] = {}
    for folder in sorted(p for p in submissions.iterdir() if p.is_dir()):
        for nb in sorted(folder.rglob("*.ipynb")):
            aid = _assignment_id(nb)
            if aid not in IDS or ".ipynb_checkpoints" in nb.parts:
                print(f"skipped {nb}: not an assignment of this course ({', '.join(IDS)})")
                continue
            key = (folder.name, aid)
            if key not in latest or nb.stat().st_mtime > latest[key].stat().st_mtime:
                latest[key] = nb
    found: dict[str, list[str]] = {}
    for (student, aid), nb in sorted(latest.items()):
        dest = work / "submitted" / student / aid / f"{aid}.ipynb"
        dest.parent.mkdir(parents=True, exist_ok=True)
        nbformat.write(_without_copies(nbformat.read(nb, as_version=4)), dest)
        found.setdefault(aid, []).append(student)
    return found


def _without_copies(nb):
    """A copied graded cell keeps its code but loses its nbgrader role (the first copy is graded), and
    every cell gets an id of its own: nbgrader 0.9.6 stops on a repeated grade_id."""
    seen, ids = set(), set()
    for cell in nb.cells:
        role = cell.metadata.get("nbgrader")
        if role is not None and (role.get("grade_id") in seen or "grade_id" not in role):
            del cell.metadata["nbgrader"]
        elif role is not None:
            seen.add(role["grade_id"])
        if cell.get("id") in ids or "id" not in cell:
            cell["id"] = uuid.uuid4().hex[:8]
        ids.add(cell["id"])
    return nb


def grade(submissions: Path, out: Path, timeout: int) -> None:
    if not submissions.is_dir():
        sys.exit(f"SUBMISSIONS={submissions} is not a folder (one sub-folder per student, holding <id>.ipynb)")
    with tempfile.TemporaryDirectory() as tmp:
        work = _course(Path(tmp))
        found = _collect(submissions, work)
        if not found:
            sys.exit(f"no submitted notebook in {submissions} (expected <student>/<id>.ipynb, id one of "
                     f"{', '.join(IDS)})")
        api = _api(work, **{"Execute.timeout": timeout})
        _release(api, found)
        for aid, students in found.items():
            for who in students:
                if _done(api.autograde(aid, who, force=True, create=True), f"autograde {who}/{aid}"):
                    _done(api.generate_feedback(aid, who, force=True), f"feedback {who}/{aid}")
        shutil.rmtree(out, ignore_errors=True)
        (out / "feedback").mkdir(parents=True)
        _export(work, out / "grades.csv")
        for html in (work / "feedback").glob("*/*/*.html"):
            dest = out / "feedback" / html.parts[-3] / html.name
            dest.parent.mkdir(parents=True, exist_ok=True)
            shutil.copy(html, dest)
    with open(out / "grades.csv", newline="") as f:
        for row in csv.DictReader(f):
            score, top = float(row["score"]), float(row["max_score"])
            print(f"{row['student_id']:>16} {row['assignment']:<22} {score:5.1f} / {top:g}")
    print(f"graded {sum(map(len, found.values()))} notebooks: {out / 'grades.csv'}, feedback in {out / 'feedback'}")


def _export(work: Path, dest: Path) -> None:
    from nbgrader.api import Gradebook
    from nbgrader.plugins import CsvExportPlugin

    with Gradebook(f"sqlite:///{work / 'gradebook.db'}") as gb:
        CsvExportPlugin(to=str(dest)).export(gb)


def main(argv=None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    sub = parser.add_subparsers(dest="command", required=True)
    s = sub.add_parser("student", help="write the student edition")
    s.add_argument("--out", type=Path, default=HERE / "release")
    g = sub.add_parser("grade", help="autograde a folder of submissions")
    g.add_argument("submissions", type=Path)
    g.add_argument("--out", type=Path, default=HERE / "graded")
    g.add_argument("--timeout", type=int, default=60, help="seconds a cell may run before it is interrupted")
    args = parser.parse_args(argv)
    if args.command == "student":
        student(args.out.resolve())
    else:
        grade(args.submissions.resolve(), args.out.resolve(), args.timeout)


if __name__ == "__main__":
    main()
