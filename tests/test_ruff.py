"""The repository's Python passes ruff with the rules pyproject.toml selects (issue 26), and those
rules are the ones ruff applies: a planted unused import is reported."""

import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent

def ruff(*args: str, cwd: Path = ROOT) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "ruff", "check", "--no-cache", "--output-format", "concise", *args],
                          cwd=cwd, capture_output=True, text=True, timeout=300)


def test_the_repository_has_no_ruff_findings():
    done = ruff(str(ROOT))
    assert done.returncode == 0, f"ruff check found:\n{done.stdout}{done.stderr}"


def test_an_unused_import_is_reported_with_the_projects_configuration(tmp_path):
    planted = tmp_path / "planted.py"
    planted.write_text("import os\n")
    done = ruff("--config", str(ROOT / "pyproject.toml"), str(planted), cwd=tmp_path)
    assert done.returncode == 1, done.stdout + done.stderr
    assert "planted.py:1:8: F401" in done.stdout, done.stdout
