"""The lecturer's two commands around nbgrader (see README, "For lecturers"); run by `make student` and `make grade`.

    python assignments/course.py student [--out assignments/release] [--class ids.csv] [--assignment ID ...]
    python assignments/course.py grade SUBMISSIONS [--out assignments/graded] [--timeout 60] [--fresh [--yes]]
                                                   [--class ids.csv]

Both work in fresh temporary nbgrader courses (this folder's ``source/`` and ``nbgrader_config.py``), so
nothing tracked is written. ``student`` writes the student edition (solutions and hidden tests removed).
``grade`` takes a folder with one sub-folder per student holding that student's notebooks, named
``<assignment id>.ipynb`` (or a re-download's ``<id> (1).ipynb``: the last saved counts) anywhere below
it. Each submission is graded in a sandbox of its own (a fresh course holding only it, its own temp folder,
both removed afterwards), so no submission sees a file another one wrote. A cell left running is
interrupted after ``--timeout`` seconds, deleted graded cells are restored, an error in any cell does not
stop the run. Results accumulate in ``grades.csv`` (nbgrader's gradebook export, one row per student and
assignment) and ``feedback/<student>/<assignment>.html``: grading a late submission adds its row; grading a
student again replaces only that student's row and page, and the replaced ones are kept in ``history.csv``
and ``history/<time>/``. ``--fresh`` starts a new ``grades.csv`` (after a confirmation, or ``--yes``),
keeping the old one in ``history/`` too: nothing graded is ever deleted.

A variant per student (``variants.py``): with ``--class`` (a CSV of student ids) ``student`` writes
``<out>/<student>/<id>/`` per student, each with the student's own numbers and sealed self-checks, and
``grade`` gives nbgrader, as the master of each submission, the variant of the student id the submission is
filed under; numbers edited by hand or another student's, and answers right for another student's numbers,
are flagged. Without ``--class``, one shared variant. Each grading also rewrites ``class_report.csv`` and
``class_report.html`` (``report.py``) from every graded submission: share right, named slips, design
outcomes, flags.
"""

from __future__ import annotations

import argparse
import csv
import functools
import json
import os
import re
import shutil
import sys
import tempfile
import time
import uuid
import warnings
from contextlib import contextmanager
from pathlib import Path

import nbformat

sys.path.insert(0, str(Path(__file__).resolve().parent))
import report
import variants

HERE = Path(__file__).resolve().parent
GRADES = "grades.csv"
IDS = sorted(p.name for p in (HERE / "source").iterdir() if (p / f"{p.name}.ipynb").is_file())


def _course(work: Path) -> Path:
    # files a run of the sources left (a DXF an exercise writes, checkpoints) are not part of the course
    shutil.copytree(HERE / "source", work / "source", ignore=shutil.ignore_patterns("*.dxf", ".ipynb_checkpoints"))
    shutil.copy(HERE / "nbgrader_config.py", work)
    return work


def read_class(path: Path | None) -> list[str]:
    """The student ids of a class list: a CSV whose first column (or column ``student_id``/``id``) holds them."""
    if path is None:
        return []
    with open(path, newline="", encoding="utf-8") as f:
        table = [row for row in csv.reader(f) if row and row[0].strip()]
    if not table:
        sys.exit(f"CLASS={path}: no student id in it")
    head = [h.strip().lower() for h in table[0]]
    col = next((head.index(h) for h in ("student_id", "id", "student") if h in head), None)
    ids = [row[col or 0].strip() for row in (table[1:] if col is not None else table)]
    bad = [i for i in ids if not re.fullmatch(r"[\w.@-]+", i)]
    if bad or len(set(ids)) != len(ids):
        sys.exit(f"CLASS={path}: ids must be unique words (letters, digits, . @ - _): {bad or 'duplicates'}")
    return ids


# the source's link to its chapter, relative to assignments/source/<id>/
CHAPTER_LINK = re.compile(r"\]\((?:\.\./)+notebooks/([^)/]+\.ipynb)\)")


def for_my_notebooks(nb):
    """``nb`` with its links to a chapter made to open from ``my-notebooks/``: the chapters tell the student to
    save the edition there, beside their working copy of every chapter (``course.py sync``)."""
    for cell in nb.cells:
        if cell.cell_type == "markdown":
            cell.source = CHAPTER_LINK.sub(r"](\1)", cell.source)
    return nb


class Masters:
    """Each student's master of each assignment (:func:`variants.render`), made once: the shared one for an
    id outside the class list (or when there is none)."""

    def __init__(self, class_ids: list[str]):
        self.class_ids = class_ids
        self._cache: dict[tuple[str, str], nbformat.NotebookNode] = {}

    def of(self, aid: str, student: str):
        who = student if student in self.class_ids else variants.SHARED
        if (aid, who) not in self._cache:
            src = nbformat.read(HERE / "source" / aid / f"{aid}.ipynb", as_version=4)
            self._cache[aid, who] = for_my_notebooks(variants.render(src, aid, who))
        return self._cache[aid, who]

    def install(self, work: Path, aid: str, student: str) -> None:
        """Put ``student``'s master of ``aid`` in the course ``work`` as nbgrader's source."""
        nbformat.write(self.of(aid, student), work / "source" / aid / f"{aid}.ipynb")

    def expected(self, aid: str) -> dict[str, dict[str, dict]]:
        """student → answer name → the hidden test's recorded call, for every student of the class."""
        return {who: {c["name"]: c for _, calls in variants._checks(self.of(aid, who)) for c in calls
                      if c["kind"] == "number"} for who in self.class_ids}


@functools.cache
def alembic_head() -> str:
    """The revision nbgrader's gradebook schema is at (what ``alembic heads`` prints for nbgrader's migrations)."""
    from alembic.script import ScriptDirectory
    from nbgrader.dbutil import ALEMBIC_DIR

    return ScriptDirectory(ALEMBIC_DIR).get_current_head()


@functools.cache
def _throwaway_gradebooks() -> None:
    """Every gradebook this script opens is a sandbox's or an edition's, removed when done (grades leave as CSV):
    sqlite need not wait for the disk at each of the few hundred commits nbgrader makes per submission."""
    import sqlite3

    from sqlalchemy import event
    from sqlalchemy.engine import Engine

    @event.listens_for(Engine, "connect")
    def _no_sync(connection, _record):
        if isinstance(connection, sqlite3.Connection):
            connection.execute("PRAGMA synchronous = OFF")
            connection.execute("PRAGMA journal_mode = MEMORY")


def _api(work: Path, **settings):
    """nbgrader's Python API on the course in ``work`` (one process for every step: nbgrader's start-up is slow),
    configured by nbgrader_config.py and then ``settings`` ({"Execute.timeout": 10, ...})."""
    from nbgrader import api as nbgrader_api
    from nbgrader.apps import NbGraderAPI
    from nbgrader.coursedir import CourseDirectory
    from nbgrader.preprocessors import execute as nbgrader_execute
    from traitlets.config.loader import PyFileConfigLoader

    if str(HERE.parent / "tools") not in sys.path:
        sys.path.insert(0, str(HERE.parent / "tools"))
    import ipc_kernels

    warnings.filterwarnings("ignore", module="nbgrader")  # SQLAlchemy's notes on nbgrader's own session use
    config = PyFileConfigLoader("nbgrader_config.py", path=str(work)).load_config()
    config.CourseDirectory.root = str(work)
    # the kernel's start-up notes (e.g. on TCP without encryption where IPC is missing) are not for a grading run
    # graded kernels over unique Unix sockets, as on every other route (tools/ipc_kernels.py): no port race.
    # nbgrader's Execute passes its own AsyncKernelManager over any configured class, so its name is rebound.
    nbgrader_execute.AsyncKernelManager = ipc_kernels.IPCKernelManager
    # a new gradebook asks for the schema's version by running `alembic heads` in a subprocess (~4 s of CPU,
    # nbgrader imported again); every sandbox makes a new gradebook, so it is read here, in this process, once
    nbgrader_api.get_alembic_version = alembic_head
    _throwaway_gradebooks()
    config.Execute.extra_arguments = [*config.Execute.get("extra_arguments", []), "--IPKernelApp.log_level=ERROR"]
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


def student(out: Path, class_ids: list[str] | None = None, ids: list[str] | None = None) -> None:
    """The student edition in ``out`` (of the assignments ``ids``, all by default): one shared, or with a
    class list ``out/<student>/<id>/`` per student, each with the student's own numbers and self-check tokens."""
    masters = Masters(class_ids or [])
    ids = ids or IDS
    with tempfile.TemporaryDirectory() as tmp:
        work = _course(Path(tmp))
        api = _api(work)
        shutil.rmtree(out, ignore_errors=True)
        for who in class_ids or [variants.SHARED]:
            for aid in ids:
                masters.install(work, aid, who)
            _release(api, ids)
            shutil.copytree(work / "release", out / who, dirs_exist_ok=True)
    print(f"student edition of {len(ids)} assignments" + (f" for {len(class_ids)} students" if class_ids else "")
          + f": {out}")


def _assignment_id(nb: Path) -> str:
    """The assignment a notebook belongs to: its name without a browser's download counter ("geneva (1)")."""
    return re.sub(r"\s*\(\d+\)$", "", nb.stem)


def _collect(submissions: Path) -> dict[tuple[str, str], Path]:
    """Every student's notebook of each assignment, {(student, id): path}; of two notebooks of one assignment
    (a re-download), the one saved last is graded."""
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
    return dict(sorted(latest.items()))


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


@contextmanager
def _environ(**values):
    """Set environment variables for what starts inside the block (the graded kernel inherits them)."""
    saved = {k: os.environ.get(k) for k in values}
    os.environ.update(values)
    try:
        yield
    finally:
        for k, v in saved.items():
            if v is None:
                os.environ.pop(k, None)
            else:
                os.environ[k] = v


def _temp_folder(path: Path):
    """Point TMPDIR (and Windows' TMP, TEMP) at ``path`` for what starts inside: the graded kernel's
    ``tempfile.gettempdir()`` is then the submission's own."""
    return _environ(**dict.fromkeys(("TMPDIR", "TMP", "TEMP"), str(path)))


def _grade_one(student: str, aid: str, nb: Path, timeout: int, masters: Masters):
    """Grade one submission in a sandbox of its own: a fresh nbgrader course holding only this notebook (and,
    as nbgrader's source, the master of this student's own variant), and a temp folder of its own, both
    removed afterwards. Files the submission writes are visible to its own checks and to no other
    submission's. Returns nbgrader's CSV rows for it, its feedback page (None if none), the verdicts its
    checks logged, the flag on its variant numbers ("" if they are the student's own) and the cells stopped
    at the time limit."""
    with tempfile.TemporaryDirectory(prefix="mechlab-grade-") as tmp:
        sandbox = Path(tmp)
        work = _course(sandbox / "course")
        masters.install(work, aid, student)
        submitted = nbformat.read(nb, as_version=4)
        flag = variants.whose(submitted, aid, student, {who: masters.of(aid, who) for who in
                                                         {*masters.class_ids, student}})
        dest = work / "submitted" / student / aid / f"{aid}.ipynb"
        dest.parent.mkdir(parents=True)
        nbformat.write(_without_copies(submitted), dest)
        (sandbox / "tmp").mkdir()
        log = sandbox / "verdicts.jsonl"
        stopped: list[str] = []
        with _temp_folder(sandbox / "tmp"), _environ(MECHLAB_GRADE_LOG=str(log)):
            api = _api(work, **{"Execute.timeout": timeout})
            _release(api, [aid])
            if _done(api.autograde(aid, student, force=True, create=True), f"autograde {student}/{aid}"):
                stopped = _plain_timeouts(work / "autograded" / student / aid / f"{aid}.ipynb", timeout)
                _done(api.generate_feedback(aid, student, force=True), f"feedback {student}/{aid}")
        rows = _export(work)
        page = work / "feedback" / student / aid / f"{aid}.html"
        verdicts = [json.loads(line) for line in log.read_text(encoding="utf-8").splitlines()] if log.is_file() else []
        return rows, page.read_text(encoding="utf-8") if page.is_file() else None, verdicts, flag, stopped


STOPPED = {"KeyboardInterrupt", "CellTimeoutError"}  # what nbclient leaves in a cell it interrupted


def _plain_timeouts(nb_path: Path, timeout: int) -> list[str]:
    """Say in plain words, in the feedback, that a cell was stopped, in place of the interrupt's traceback.
    Returns the stopped cells (grade id, else "cell N") for the class report."""
    nb = nbformat.read(nb_path, as_version=4)
    changed = []
    for n, cell in enumerate(nb.cells, 1):
        outputs = cell.get("outputs", [])
        if any(o.get("output_type") == "error" and o.get("ename") in STOPPED for o in outputs):
            cell.outputs = [o for o in outputs if o.get("ename") not in STOPPED] + [nbformat.v4.new_output(
                "stream", name="stderr",
                text=f"This cell ran for more than {timeout} s and was stopped (an endless loop?). "
                     "Cells below that use what it defines fail too.\n")]
            changed.append(cell.metadata.get("nbgrader", {}).get("grade_id") or f"cell {n}")
    if changed:
        nbformat.write(nb, nb_path)
    return changed


def grade(submissions: Path, out: Path, timeout: int, fresh: bool = False, yes: bool = False,
          class_ids: list[str] | None = None) -> None:
    """Grade every submission below ``submissions`` into ``out``, adding to what was graded there before: a
    re-graded student's rows and feedback replace only their own, and the replaced ones are kept in
    ``out/history/``. ``fresh`` starts a new grades.csv, after a confirmation, keeping the old one in history."""
    if not submissions.is_dir():
        sys.exit(f"SUBMISSIONS={submissions} is not a folder (one sub-folder per student, holding <id>.ipynb)")
    found = _collect(submissions)
    if not found:
        sys.exit(f"no submitted notebook in {submissions} (expected <student>/<id>.ipynb, id one of "
                 f"{', '.join(IDS)})")
    stamp = time.strftime("%Y%m%d-%H%M%S")
    history = out / "history" / stamp
    if fresh and (out / GRADES).is_file():
        _confirm_fresh(out, yes)
        _keep(out / GRADES, history / GRADES)
        for page in (out / "feedback").glob("*/*.html"):
            _keep(page, history / "feedback" / page.parent.name / page.name)
    table = _read_grades(out / GRADES)
    masters = Masters(class_ids or [])
    for (student, aid), nb in found.items():
        rows, page, verdicts, flag, stopped = _grade_one(student, aid, nb, timeout, masters)
        _write_verdicts(out / "verdicts" / student / f"{aid}.json", verdicts, flag, stopped, timeout)
        old = [r for r in table if (r["student_id"], r["assignment"]) == (student, aid)]
        if old:
            _append_history(out / "history.csv", old, stamp)
            feedback = out / "feedback" / student / f"{aid}.html"
            if feedback.is_file():
                _keep(feedback, history / "feedback" / student / feedback.name)
        table = [r for r in table if r not in old] + rows
        if page is not None:
            dest = out / "feedback" / student / f"{aid}.html"
            dest.parent.mkdir(parents=True, exist_ok=True)
            dest.write_text(page, encoding="utf-8")
        _write_grades(out / GRADES, table)  # after each submission: an interrupted run keeps what it graded
    _class_report(out, table, masters)
    for row in table:
        if (row["student_id"], row["assignment"]) in found:
            score, top = float(row["score"]), float(row["max_score"])
            print(f"{row['student_id']:>16} {row['assignment']:<22} {score:5.1f} / {top:g}")
    print(f"graded {len(found)} notebooks into {out / GRADES} ({len(table)} rows in all), feedback in "
          f"{out / 'feedback'}" + (f"; replaced results kept in {out / 'history'}" if history.exists() else "")
          + f"; what the class got wrong: {out / 'class_report.html'}")


def _write_verdicts(path: Path, verdicts: list[dict], flag: str, stopped: list[str], timeout: int) -> None:
    """One submission's logged verdicts, variant flag and cells stopped at the ``timeout`` (replaced when the
    student is graded again)."""
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(json.dumps({"verdicts": verdicts, "flags": [flag] if flag else [], "stopped": stopped,
                                "timeout": timeout}, ensure_ascii=False), encoding="utf-8")


def _class_report(out: Path, table: list[dict], masters: Masters) -> None:
    """class_report.csv/.html from every graded submission in ``out`` (this run's and earlier ones)."""
    subs = []
    for row in table:
        who, aid = row["student_id"], row["assignment"]
        path = out / "verdicts" / who / f"{aid}.json"
        saved = json.loads(path.read_text(encoding="utf-8")) if path.is_file() else {"verdicts": [], "flags": []}
        subs.append(report.Submission(who, aid, saved["verdicts"], float(row["score"] or 0),
                                      float(row["max_score"] or 0), list(saved["flags"]),
                                      list(saved.get("stopped", [])), saved.get("timeout")))
    names: dict[str, list[str]] = {}
    for aid in sorted({s.assignment for s in subs}):
        recorded = [c["name"] for _, calls in variants._checks(masters.of(aid, variants.SHARED)) for c in calls]
        logged = [v["name"] for s in subs if s.assignment == aid for v in s.verdicts]
        names[aid] = list(dict.fromkeys(recorded + logged))
        if masters.class_ids:
            expected = masters.expected(aid)
            for s in subs:
                if s.assignment == aid:
                    s.flags += report.copied_answers(s, expected)
    report.write(subs, names, out)



def _confirm_fresh(out: Path, yes: bool) -> None:
    if yes:
        return
    if not sys.stdin.isatty():
        sys.exit("--fresh starts a new grades.csv; confirm with --yes (the old one is kept in history/)")
    answer = input(f"Start a new {out / GRADES}? The old one and its feedback go to {out / 'history'}/. [y/N] ")
    if answer.strip().lower() not in ("y", "yes"):
        sys.exit("nothing changed")


def _keep(path: Path, dest: Path) -> None:
    """Move ``path`` into the history, never over an earlier copy."""
    dest.parent.mkdir(parents=True, exist_ok=True)
    n = 1
    while dest.exists():
        dest = dest.with_name(f"{dest.stem}.{n}{dest.suffix}")
        n += 1
    shutil.move(path, dest)


def _read_grades(path: Path) -> list[dict]:
    if not path.is_file():
        return []
    with open(path, newline="", encoding="utf-8") as f:
        return list(csv.DictReader(f))


def _write_grades(path: Path, rows: list[dict]) -> None:
    """Write through a temporary file beside it, so that grades.csv is never left truncated."""
    path.parent.mkdir(parents=True, exist_ok=True)
    rows = sorted(rows, key=lambda r: (r["assignment"], r["student_id"]))
    fields = list(rows[0]) if rows else []
    part = path.with_name(path.name + ".part")
    with open(part, "w", newline="", encoding="utf-8") as f:
        writer = csv.DictWriter(f, fieldnames=fields)
        writer.writeheader()
        writer.writerows(rows)
    os.replace(part, path)


def _append_history(path: Path, rows: list[dict], stamp: str) -> None:
    new = not path.is_file()
    with open(path, "a", newline="", encoding="utf-8") as f:
        writer = csv.DictWriter(f, fieldnames=["replaced_at", *rows[0]])
        if new:
            writer.writeheader()
        writer.writerows({"replaced_at": stamp, **r} for r in rows)


def _export(work: Path) -> list[dict]:
    """nbgrader's gradebook of one sandbox as CSV rows."""
    from nbgrader.api import Gradebook
    from nbgrader.plugins import CsvExportPlugin

    dest = work / "grades.csv"
    with Gradebook(f"sqlite:///{work / 'gradebook.db'}") as gb:
        CsvExportPlugin(to=str(dest)).export(gb)
    return _read_grades(dest)


def main(argv=None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    sub = parser.add_subparsers(dest="command", required=True)
    s = sub.add_parser("student", help="write the student edition")
    s.add_argument("--out", type=Path, default=HERE / "release")
    s.add_argument("--class", dest="class_list", type=Path,
                   help="CSV of student ids: one edition per student, with the student's own numbers")
    s.add_argument("--assignment", action="append", choices=IDS, help="only this assignment (repeatable)")
    g = sub.add_parser("grade", help="autograde a folder of submissions")
    g.add_argument("submissions", type=Path)
    g.add_argument("--out", type=Path, default=HERE / "graded")
    g.add_argument("--timeout", type=int, default=60, help="seconds a cell may run before it is interrupted")
    g.add_argument("--fresh", action="store_true",
                   help="start a new grades.csv (asks first; the old one is kept in <out>/history/)")
    g.add_argument("--yes", action="store_true", help="with --fresh: do not ask")
    g.add_argument("--class", dest="class_list", type=Path,
                   help="the class list the editions were made for: each submission graded against its own numbers")
    args = parser.parse_args(argv)
    class_ids = read_class(args.class_list)
    if args.command == "student":
        student(args.out.resolve(), class_ids, args.assignment)
    else:
        grade(args.submissions.resolve(), args.out.resolve(), args.timeout, args.fresh, args.yes, class_ids)


if __name__ == "__main__":
    main()
