"""The student's working copy (course.py sync, run as `python course.py`, no make):
a course update never overwrites a student's edit, and the course's checkout stays clean.
Also: JupyterLab as course.py starts it serves the working copy on 127.0.0.1 with a token."""

import datetime
import json
import os
import shutil
import socket
import subprocess
import sys
import time
import urllib.error
import urllib.request
from pathlib import Path

import psutil
import pytest

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))
import course  # noqa: E402  (the script at the repository's root)


def notebook(text: str) -> str:
    return json.dumps({"cells": [{"cell_type": "code", "execution_count": None, "metadata": {}, "outputs": [],
                                  "source": [text]}],
                       "metadata": {"kernelspec": {"name": "python3", "display_name": "Python 3",
                                                   "language": "python"}},
                       "nbformat": 4, "nbformat_minor": 5}, indent=1) + "\n"


def git(repo: Path, *args: str) -> str:
    return subprocess.run(["git", "-C", str(repo), *args], check=True, capture_output=True, text=True).stdout


def commit(repo: Path, message: str) -> None:
    git(repo, "add", "-A")
    git(repo, "-c", "user.name=lecturer", "-c", "user.email=l@example.org", "commit", "-qm", message)


def sync(repo: Path) -> str:
    """The route a student without make takes: `python course.py sync`."""
    done = subprocess.run([sys.executable, "course.py", "sync"], cwd=repo, capture_output=True, text=True,
                          check=True)
    return done.stdout


@pytest.fixture
def repo(tmp_path):
    """A course repository: course.py, the real .gitignore and three chapters."""
    repo = tmp_path / "course"
    (repo / "notebooks").mkdir(parents=True)
    for name in ("course.py", ".gitignore"):
        shutil.copy(ROOT / name, repo / name)
    for name in ("01_a", "02_b", "03_c"):
        (repo / "notebooks" / f"{name}.ipynb").write_text(notebook(f"print('{name} v1')"))
    git(repo, "init", "-q")
    commit(repo, "the course")
    return repo


def test_an_edit_survives_a_course_update(repo):
    work, today = repo / "my-notebooks", datetime.date.today().isoformat()
    out = sync(repo)
    assert "created your working copy" in out and "3 files" in out
    assert (work / "02_b.ipynb").read_text() == notebook("print('02_b v1')")

    # the student edits chapter 01 and deletes chapter 03
    mine = notebook("print('my answer')")
    (work / "01_a.ipynb").write_text(mine)
    (work / "03_c.ipynb").unlink()
    # the lecturer changes chapters 01 and 02 and adds 04 (as a `git pull` would bring)
    for name in ("01_a", "02_b", "04_d"):
        (repo / "notebooks" / f"{name}.ipynb").write_text(notebook(f"print('{name} v2')"))
    commit(repo, "course update")

    out = sync(repo)
    beside = work / f"01_a (course update {today}).ipynb"
    assert (work / "01_a.ipynb").read_text() == mine
    assert beside.read_text() == notebook("print('01_a v2')")
    assert f"kept 01_a.ipynb: it has your changes; the course's new version is beside it: {beside.name}" in out
    assert (work / "02_b.ipynb").read_text() == notebook("print('02_b v2')")
    assert "refreshed 02_b.ipynb" in out
    assert (work / "04_d.ipynb").read_text() == notebook("print('04_d v2')")
    assert "added 04_d.ipynb" in out
    assert (work / "03_c.ipynb").read_text() == notebook("print('03_c v1')")
    assert "restored 03_c.ipynb" in out
    assert git(repo, "status", "--porcelain") == ""

    # a second sync with no course change does nothing and says so
    before = {p.name: p.read_bytes() for p in work.iterdir()}
    out = sync(repo)
    assert "is up to date with the course" in out
    assert {p.name: p.read_bytes() for p in work.iterdir()} == before

    # a second update of the edited chapter on the same day goes beside too, not over the first one
    (repo / "notebooks" / "01_a.ipynb").write_text(notebook("print('01_a v3')"))
    commit(repo, "another update")
    out = sync(repo)
    assert beside.read_text() == notebook("print('01_a v2')")
    assert (work / f"01_a (course update {today}, 2).ipynb").read_text() == notebook("print('01_a v3')")
    assert (work / "01_a.ipynb").read_text() == mine

    # chapters leaving the course: an untouched copy goes, an edited one stays
    (repo / "notebooks" / "01_a.ipynb").unlink()
    (repo / "notebooks" / "02_b.ipynb").unlink()
    commit(repo, "chapters removed")
    out = sync(repo)
    assert not (work / "02_b.ipynb").exists() and "removed 02_b.ipynb" in out
    assert (work / "01_a.ipynb").read_text() == mine and "kept 01_a.ipynb: no longer in the course" in out
    assert git(repo, "status", "--porcelain") == ""


def test_a_students_own_file_with_a_new_chapters_name_is_kept(repo):
    work = repo / "my-notebooks"
    sync(repo)
    own = notebook("print('my own notebook')")
    (work / "04_d.ipynb").write_text(own)
    (repo / "notebooks" / "04_d.ipynb").write_text(notebook("print('04_d')"))
    commit(repo, "new chapter")
    out = sync(repo)
    assert (work / "04_d.ipynb").read_text() == own
    assert "kept 04_d.ipynb: it is a file of yours" in out
    assert len(list(work.glob("04_d (course update *).ipynb"))) == 1


def test_renumbered_chapters_leave_one_copy_each_and_lose_no_edit(repo):
    """A course update that renumbers the chapters (their topic words stay): an untouched copy moves to
    the new name, an edited one stays under the old name and the student is told the new one."""
    work = repo / "my-notebooks"
    sync(repo)
    mine = notebook("print('my answer')")
    (work / "02_b.ipynb").write_text(mine)
    (work / "03_c.ipynb").unlink()
    for old, new in (("01_a", "02_a"), ("02_b", "03_b"), ("03_c", "01_c")):
        git(repo, "mv", f"notebooks/{old}.ipynb", f"notebooks/{new}.ipynb")
        (repo / "notebooks" / f"{new}.ipynb").write_text(notebook(f"print('{new} v2')"))
    commit(repo, "chapters renumbered")

    out = sync(repo)
    assert sorted(p.name for p in work.iterdir()) == [course.MANIFEST, "01_c.ipynb", "02_a.ipynb", "02_b.ipynb",
                                                      "03_b.ipynb"]
    assert "renamed 01_a.ipynb to 02_a.ipynb (the chapter's new number; you had not changed it)" in out
    assert (work / "02_a.ipynb").read_text() == notebook("print('02_a v2')")
    assert (work / "02_b.ipynb").read_text() == mine
    assert "kept 02_b.ipynb: it has your changes; the course now calls this chapter 03_b.ipynb" in out
    assert (work / "03_b.ipynb").read_text() == notebook("print('03_b v2')")
    assert "added 01_c.ipynb (the chapter 03_c.ipynb under its new number)" in out
    assert "removed" not in out and git(repo, "status", "--porcelain") == ""

    # the kept copy is the student's own file from now on: later syncs leave it alone and say nothing
    before = {p.name: p.read_bytes() for p in work.iterdir()}
    assert "is up to date with the course" in sync(repo)
    assert {p.name: p.read_bytes() for p in work.iterdir()} == before


def test_only_a_one_to_one_match_of_topic_words_is_a_rename():
    assert course.topic("02_equivalence.ipynb") == "equivalence.ipynb"
    assert course.topic("data/03_table.csv") == "data/table.csv" and course.topic("README.md") == "README.md"
    assert course.renames({"01_x.ipynb", "02_y.ipynb"}, {"03_x.ipynb", "04_z.ipynb"}) == {"03_x.ipynb": "01_x.ipynb"}
    # another folder and a name without a number are other files
    assert course.renames({"01_x.ipynb"}, {"02_x.ipynb", "sub/03_x.ipynb", "x.ipynb"}) == {"02_x.ipynb": "01_x.ipynb"}
    # two new chapters with the same topic words: which one the old copy is cannot be told
    assert course.renames({"01_x.ipynb"}, {"02_x.ipynb", "03_x.ipynb"}) == {}


def test_an_interrupted_sync_loses_nothing(repo, monkeypatch):
    """If the copy dies half-way, the file keeps its old content and the next sync completes."""
    work = repo / "my-notebooks"
    sync(repo)
    (repo / "notebooks" / "02_b.ipynb").write_text(notebook("print('02_b v2')"))

    def broken(src, dst):
        raise OSError("disk full")
    monkeypatch.setattr(course.shutil, "copyfile", broken)
    with pytest.raises(OSError):
        course.sync(repo / "notebooks", work)
    monkeypatch.undo()
    assert (work / "02_b.ipynb").read_text() == notebook("print('02_b v1')")
    assert not list(work.glob(".sync-*"))  # no temporary left for the student to see
    assert course.sync(repo / "notebooks", work) == ["refreshed 02_b.ipynb (you had not changed it)"]


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def test_lab_serves_the_working_copy_on_loopback_with_a_token(repo, tmp_path):
    """JupyterLab started with course.py's arguments: token required, 127.0.0.1 only, and a save
    through Jupyter's contents API lands in the working copy, never in notebooks/."""
    work = repo / "my-notebooks"
    course.sync(repo / "notebooks", work)
    port, token = free_port(), "test-token-0123456789"
    env = {**os.environ, "JUPYTER_TOKEN": token, "JUPYTER_CONFIG_DIR": str(tmp_path / "cfg"),
           "JUPYTER_RUNTIME_DIR": str(tmp_path / "rt")}
    server = subprocess.Popen(course.lab_argv(Path(sys.executable), work, port), env=env,
                              stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    base = f"http://127.0.0.1:{port}"

    def call(path, method="GET", body=None, auth=True):
        req = urllib.request.Request(base + path, method=method, data=body and json.dumps(body).encode(),
                                     headers={"Authorization": f"token {token}"} if auth else {})
        with urllib.request.urlopen(req, timeout=10) as r:
            return json.load(r)
    try:
        for _ in range(120):
            try:
                call("/api/status")
                break
            except (urllib.error.URLError, ConnectionError):
                time.sleep(0.5)
        else:
            pytest.fail("JupyterLab did not start")
        with pytest.raises(urllib.error.HTTPError) as no_token:
            call("/api/contents", auth=False)
        assert no_token.value.code == 403
        listed = {item["name"] for item in call("/api/contents")["content"]}
        assert listed == {"01_a.ipynb", "02_b.ipynb", "03_c.ipynb"}
        with pytest.raises(urllib.error.HTTPError):  # the server's root is the working copy
            call("/api/contents/../notebooks/01_a.ipynb")
        model = call("/api/contents/01_a.ipynb")
        model["content"]["cells"][0]["source"] = "print('saved in the lab')"
        call("/api/contents/01_a.ipynb", "PUT", {"type": "notebook", "format": "json", "content": model["content"]})
        assert "saved in the lab" in (work / "01_a.ipynb").read_text()
        assert git(repo, "status", "--porcelain") == ""
        listening = [c for c in psutil.Process(server.pid).net_connections()
                     if c.status == "LISTEN"]
        assert listening and all(c.laddr.ip == "127.0.0.1" for c in listening)
    finally:
        server.terminate()
        server.wait(timeout=30)
