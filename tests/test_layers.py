"""The folder list is the architecture: every module imports only from its own role or a lower one.

The layers, lowest first, are those of the README's Design section. A computation module
(up to ``kinetostatics``) never imports drawing, widgets or course material, and a lower layer
never imports a higher one; the test reads the imports of every module's source, including
imports inside functions, so a late import cannot hide a wrong direction.
"""

import ast
from pathlib import Path

import pytest

PACKAGE = Path(__file__).resolve().parents[1] / "mechlab"
LAYERS = ["errors", "validate", "geometry", "motion", "mechanisms", "analysis", "synthesis", "kinetostatics",
          "design", "draw", "widgets", "course"]
COMPUTATION = LAYERS[:LAYERS.index("design") + 1]


def _module_name(path: Path) -> tuple[str, bool]:
    parts = list(path.relative_to(PACKAGE.parent).with_suffix("").parts)
    is_package = parts[-1] == "__init__"
    return ".".join(parts[:-1] if is_package else parts), is_package


def _imported_modules(path: Path) -> set[str]:
    """Absolute names of the mechlab modules (or names from ``mechlab``) that ``path`` imports."""
    name, is_package = _module_name(path)
    here = name.split(".") if is_package else name.split(".")[:-1]
    found = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.ImportFrom):
            base = here[:len(here) - node.level + 1] if node.level else []
            target = ".".join(base + ([node.module] if node.module else []))
            if target == "mechlab":  # `from mechlab import x` or `from .. import x`: x is the module
                found.update(f"mechlab.{a.name}" for a in node.names)
            elif target.startswith("mechlab."):
                found.add(target)
        elif isinstance(node, ast.Import):
            found.update(a.name for a in node.names if a.name.startswith("mechlab."))
    return found


def _layer(module: str) -> str:
    return module.split(".")[1]


MODULES = sorted(p for p in PACKAGE.rglob("*.py") if p != PACKAGE / "__init__.py")


def test_every_module_belongs_to_a_layer():
    unknown = sorted({_layer(_module_name(p)[0]) for p in MODULES} - set(LAYERS))
    assert not unknown, f"modules outside the declared layers: {unknown} (add them to the README's Design and here)"


@pytest.mark.parametrize("path", MODULES, ids=lambda p: str(p.relative_to(PACKAGE)))
def test_imports_go_down_only(path):
    module, _ = _module_name(path)
    rank = LAYERS.index(_layer(module))
    upward = sorted(m for m in _imported_modules(path) if m.count(".") and LAYERS.index(_layer(m)) > rank)
    assert not upward, f"{module} (layer {_layer(module)}) imports higher layers: {upward}"


def test_computation_never_imports_presentation():
    offenders = {}
    for path in MODULES:
        module, _ = _module_name(path)
        if _layer(module) in COMPUTATION:
            bad = [m for m in _imported_modules(path) if _layer(m) in ("draw", "widgets", "course")]
            if bad:
                offenders[module] = bad
    assert not offenders


def test_the_checker_sees_a_wrong_direction(tmp_path, monkeypatch):
    # the checker itself: a mechanism module importing a drawing is caught
    fake = tmp_path / "mechlab" / "mechanisms"
    fake.mkdir(parents=True)
    (fake / "bad.py").write_text("from ..draw import animate\n\ndef f():\n    from ..widgets import x\n")
    monkeypatch.setattr(f"{__name__}.PACKAGE", tmp_path / "mechlab")
    assert _imported_modules(fake / "bad.py") == {"mechlab.draw", "mechlab.widgets"}
