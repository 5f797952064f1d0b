"""The public surface of the package: what ``import mechlab`` promises."""

import inspect
import re
import subprocess
import sys
from pathlib import Path

import mechlab


def test_every_exported_name_resolves_and_is_documented():
    missing = [n for n in mechlab.__all__ if not hasattr(mechlab, n)]
    assert not missing
    assert len(set(mechlab.__all__)) == len(mechlab.__all__)
    undocumented = [n for n in mechlab.__all__
                    if (inspect.isclass(getattr(mechlab, n)) or inspect.isfunction(getattr(mechlab, n)))
                    and not inspect.getdoc(getattr(mechlab, n))]
    assert not undocumented


def test_computation_never_imports_plotting():
    # a fresh interpreter: the test session itself has matplotlib loaded by other tests
    code = "import sys, mechlab, mechlab.kinetostatics.lambda_sixbars; print(sorted(m for m in sys.modules " \
           "if m.split('.')[0] in ('matplotlib', 'ipywidgets', 'IPython')))"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.strip() == "[]"


def test_readme_examples_run():
    readme = (Path(__file__).resolve().parents[1] / "README.md").read_text(encoding="utf-8")
    blocks = re.findall(r"```python\n(.*?)```", readme, flags=re.S)
    assert len(blocks) >= 2
    namespace = {}  # the blocks continue one another, as a reader runs them
    for block in blocks:
        exec(compile(block, "README.md", "exec"), namespace)
