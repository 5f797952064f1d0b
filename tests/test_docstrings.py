"""Module docstrings say what a module holds, its formulas' names and their source; the theory is in the book."""

import ast
from pathlib import Path

import pytest

MAX_LINES = 20
ROOT = Path(__file__).resolve().parents[1]
MODULES = sorted((ROOT / "mechlab").rglob("*.py"))


@pytest.mark.parametrize("path", MODULES, ids=lambda p: str(p.relative_to(ROOT)))
def test_module_docstring_is_short(path):
    doc = ast.get_docstring(ast.parse(path.read_text(encoding="utf-8")), clean=False) or ""
    assert len(doc.splitlines()) <= MAX_LINES, (
        f"{path.name}: module docstring of {len(doc.splitlines())} lines > {MAX_LINES}; move the theory to the book "
        f"or to the docstring of the function it explains")
