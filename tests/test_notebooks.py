"""The course's notebooks are committed without outputs and name their kernel.

(nbval executes them: see the README's test command.)
"""

import json
from pathlib import Path

import pytest

NOTEBOOKS = sorted((Path(__file__).parent.parent / "notebooks").glob("*.ipynb")) + sorted(
    (Path(__file__).parent.parent / "notebooks" / "companion").glob("*.ipynb"))   # the chapters' companions too


def test_there_are_notebooks():
    assert NOTEBOOKS, "no notebooks found"


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.name)
def test_notebook_is_committed_clean(path):
    nb = json.loads(path.read_text())
    for cell in nb["cells"]:
        if cell["cell_type"] == "code":
            assert cell.get("outputs") == [], f"{path.name}: a code cell carries outputs"
            assert cell.get("execution_count") is None, f"{path.name}: a code cell has an execution count"
    assert nb["metadata"].get("kernelspec", {}).get("name") == "python3"
