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
