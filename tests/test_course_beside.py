"""course.pytest_beside, which `make test` and `make test-browser` run on: each group of tests in a process of its
own, at the same time as the chain of commands, every report printed, the first failure's code returned."""

import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))
import course  # noqa: E402  (the script at the repository's root)

# each side writes its mark, then waits for the other's: run one after the other, the first would wait in vain
WAIT = """
import pathlib, time
here, there = pathlib.Path({here!r}), pathlib.Path({there!r})
here.write_text("started")
deadline = time.monotonic() + 60
while not there.exists() and time.monotonic() < deadline:
    time.sleep(0.05)
assert there.exists(), "the other side never started: not run at the same time"
pathlib.Path(str(here) + ".ok").write_text("met")
"""


def _group(tmp_path: Path, name: str, here: Path, there: Path, passes: bool = True) -> list[str]:
    folder = tmp_path / name
    folder.mkdir()
    (folder / "pytest.ini").write_text("[pytest]\n")
    test = WAIT.format(here=str(here), there=str(there)).replace("\n", "\n    ")
    (folder / f"test_{name}.py").write_text(f"def test_{name}():\n    {test}\n    assert {passes}\n")
    return ["-c", str(folder / "pytest.ini"), "--rootdir", str(folder), str(folder)]


@pytest.mark.skipif(course.os.cpu_count() < 2, reason="on one core pytest_beside runs all in sequence, by design")
def test_groups_run_beside_the_chain_and_the_first_failure_is_the_exit_code(tmp_path, capsys):
    marks = [tmp_path / f"mark{k}" for k in range(3)]
    chain_mark = tmp_path / "chain"
    chain = [["-c", WAIT.format(here=str(chain_mark), there=str(marks[0]))],
             ["-c", WAIT.format(here=str(tmp_path / "chain2"), there=str(marks[1]))]]
    beside = [_group(tmp_path, "one", marks[0], chain_mark),
              _group(tmp_path, "two", marks[1], marks[0], passes=False)]
    with pytest.raises(SystemExit) as stop:
        course.pytest_beside(Path(sys.executable), beside, chain)
    assert stop.value.code == 1
    out = capsys.readouterr().out
    assert "1 passed" in out and "1 failed" in out   # both groups' reports, after the chain
    met = [Path(f"{m}.ok") for m in (chain_mark, tmp_path / "chain2", marks[0], marks[1])]
    assert all(m.exists() for m in met), [m.name for m in met if not m.exists()]   # each side met the other


def test_all_passing_returns(tmp_path):
    mark = tmp_path / "side"
    chain_mark = tmp_path / "chain"
    course.pytest_beside(Path(sys.executable), [_group(tmp_path, "only", mark, chain_mark)],
                         [["-c", WAIT.format(here=str(chain_mark), there=str(mark))]])
