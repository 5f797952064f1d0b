"""The book's Errata page: every :class:`mechlab.course.errata.Erratum`, its evidence recomputed now.

Executed by ``book/errata.md`` at build time. Each row links to the code cell of the
chapter's companion (or, where it has none, of the chapter) that demonstrates the mistake: the first code
cell of that notebook that uses ``errata`` (its ``table``/``check``), addressed by the ``cell-<index>`` anchor
that ``_ext/mechbook.py`` puts on every code cell.
"""

from __future__ import annotations

import html
import json
import re
from pathlib import Path

NOTEBOOKS = Path(__file__).resolve().parent.parent.parent / "notebooks"


def _cells(notebook: Path) -> list[dict]:
    return json.loads(Path(notebook).read_text(encoding="utf-8"))["cells"]


def _source(cell: dict) -> str:
    src = cell.get("source", "")
    return "".join(src) if isinstance(src, list) else src


def demo_cell(notebook: Path) -> int | None:
    """Index (in the notebook's cells) of the code cell that shows the chapter's errata.

    The first code cell that calls ``table(`` and mentions ``errata``, or calls the errata's ``table(notebook=…)``
    imported by name; failing that, the
    first one that uses ``errata`` on a line that is not an import.
    """
    code = [(i, _source(c)) for i, c in enumerate(_cells(notebook)) if c["cell_type"] == "code"]
    for i, src in code:
        if ("errata" in src and "table(" in src) or re.search(r"(?<![\w.])table\(notebook=", src):
            return i
    for i, src in code:
        if any("errata" in line and not line.lstrip().startswith(("import ", "from "))
               for line in src.splitlines()):
            return i
    return None


def notebook_title(notebook: Path) -> str:
    """The text of the notebook's first Markdown heading (its chapter title), else its stem."""
    for cell in _cells(notebook):
        if cell["cell_type"] == "markdown":
            for line in _source(cell).splitlines():
                if line.startswith("#"):
                    return line.lstrip("#").strip()
    return Path(notebook).stem


def chapter_link(notebook_name: str, notebooks_dir: Path = NOTEBOOKS, prefix: str = "notebooks/") -> str:
    """An HTML link to the cell of ``notebook_name`` that demonstrates its errata.

    Raises ValueError when the erratum names a notebook that does not exist, so a
    dangling link fails the build instead of reaching a reader.
    """
    path = Path(notebooks_dir) / notebook_name
    if not notebook_name or not path.is_file():
        raise ValueError(f"erratum names notebook {notebook_name!r}, which is not in {notebooks_dir}")
    # errata are reference, not lesson: they stand in the chapter's companion where it has one
    companion = Path(notebooks_dir) / "companion" / f"{path.stem}_companion.ipynb"
    has_companion = companion.is_file() and demo_cell(companion) is not None
    shown, folder = (companion, "companion/") if has_companion else (path, "")
    cell = demo_cell(shown)
    anchor = f"#cell-{cell}" if cell is not None else ""
    href = f"{prefix}{folder}{shown.stem}.html{anchor}"
    return f'<a href="{html.escape(href)}">{html.escape(notebook_title(shown))}</a>'


def _inline(text: str) -> str:
    return " ".join(str(text).split())


def _plural(n: int, one: str, many: str) -> str:
    return f"{n} {one if n == 1 else many}"


def errata_markdown(errata=None, notebooks_dir: Path = NOTEBOOKS, prefix: str = "notebooks/") -> str:
    """MyST Markdown for the errata (default: :func:`mechlab.course.errata.collect`): one section per
    kind (printed mistakes, remarks, unreadable passages), counted separately, grouped by source within.

    Each erratum: the source key (linked to the References page) and where, the chapter
    cell that shows it, then printed, correct and the evidence returned by
    ``Erratum.evidence()`` (which raises if the claim stopped being true, failing the build).
    """
    from mechlab.course.errata import KINDS, SOURCES, collect, count_by_kind

    rows = collect() if errata is None else list(errata)
    if not rows:
        return "No errata have been collected from the chapters yet."
    for e in rows:
        if e.source not in SOURCES:
            raise ValueError(f"erratum cites source {e.source!r}; known: {', '.join(SOURCES)}")
    n = count_by_kind(rows)
    sources = sorted({e.source for e in rows})
    out = [f"{_plural(n['mistake'], 'printed mistake', 'printed mistakes')}, "
           f"{_plural(n['remark'], 'remark', 'remarks')} and "
           f"{_plural(n['unreadable'], 'unreadable passage', 'unreadable passages')} "
           f"in {len(sources)} of the {len(SOURCES)} source texts.", ""]
    for kind, title in KINDS.items():
        mine = [e for e in rows if e.kind == kind]
        if not mine:
            continue
        out += [f"## {title[0].upper()}{title[1:]} ({len(mine)})", ""]
        for key in sorted({e.source for e in mine}):
            out += [f'**<a href="references.html#seed-{key}">{SOURCES[key]}</a>**', ""]
            for e in (e for e in mine if e.source == key):
                evidence = e.evidence()
                out += [f"- **{_inline(e.where)}** — shown in {chapter_link(e.notebook, notebooks_dir, prefix)}",
                        f"  - printed: {_inline(e.printed)}",
                        f"  - correct: {_inline(e.correct)}",
                        f"  - evidence: {_inline(evidence)}"]
            out.append("")
    return "\n".join(out)
