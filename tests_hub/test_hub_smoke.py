"""Five students at once on a JupyterHub on 127.0.0.1 (tests_hub/hub_load.py): every one logs
in, gets a server, runs a whole chapter and moves a slider. Run by `make test-hub`."""

import json
import subprocess
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent


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
    sys.path.insert(0, str(HERE))
    import hub_load

    runs = [json.loads(hub_load.results_file(n).read_text()) for n in (10, 20)]
    assert hub_load.table(runs) in (HERE.parent / "benchmarks" / "README.md").read_text()
