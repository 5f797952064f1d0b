"""Sphinx extension of the course book: folded check cells, cell anchors, local animation
controls, offline check.

* A code cell tagged ``check`` (the chapters' verification: asserts a student may skip)
  is folded in the book: its source gets myst-nb's ``hide-input`` tag when the notebook
  is read, so the page shows a "Show code cell source" toggle in its place (and the
  cell's output, if any). The cell still runs at build time; a failing check fails the
  build as before.
* A chapter's errata table (the columns of :func:`mechlab.course.errata.table`) gets the
  class ``mechbook-errata``: the book's stylesheet shows it as one card per erratum, its
  cells stacked under their names, so that it fits the column however long its evidence.
* Every code cell of a notebook page gets the HTML id ``cell-<index>`` (its index in
  the notebook's list of cells), so the Errata page can link to the very cell that
  demonstrates a mistake.
* matplotlib's ``to_jshtml()`` links a Font Awesome stylesheet from a CDN for its
  buttons; mechlab's animations already come without it, and any other animation on a
  page goes through the same :func:`mechlab.draw.local_animation_controls`.
* The execution cache (``nb_execution_cache_path``) is keyed by the notebooks' text
  only; a page's outputs also depend on the library. A hash of ``mechlab/``,
  ``book/_ext/`` and ``environment.txt`` is kept next to the cache: when it changes the
  cache is dropped and every page is read (executed) again, so no stale output is
  ever published. A build that ended with warnings leaves a marker, and the next build
  reads every page again, so its warnings (a failing notebook) are reported again
  instead of an unchanged page passing silently.
* After the build, every HTML page and stylesheet of the output is scanned for a
  script, stylesheet, image, font or frame that would be fetched from another host;
  each one is a warning, so ``sphinx-build -W`` fails on it.
"""

from __future__ import annotations

import hashlib
import json
import re
import shutil
from pathlib import Path

from docutils import nodes
from sphinx.util import logging

# the same clean-up mechlab's own animations get, applied to any to_jshtml() output of a page
from mechlab.draw import local_animation_controls

logger = logging.getLogger(__name__)


# A fetch from another host: <script src>, <link href> (stylesheet, icon, preload, font),
# <img|source|iframe|video|audio|embed src>, CSS url() and @import.
_REMOTE_TAG = re.compile(
    r'<(script|img|iframe|source|video|audio|embed)\b[^>]*\bsrc\s*=\s*["\']?((?:https?:)?//[^"\'\s>]+)'
    r'|<link\b(?=[^>]*\brel\s*=\s*["\']?(?:stylesheet|icon|shortcut icon|preload|prefetch|modulepreload|'
    r'manifest|apple-touch-icon)\b)[^>]*\bhref\s*=\s*["\']?((?:https?:)?//[^"\'\s>]+)', re.I)
_REMOTE_CSS = re.compile(r'(?:url\(\s*["\']?|@import\s+["\'])((?:https?:)?//[^"\')\s]+)', re.I)


def remote_fetches(text: str, css: bool = False) -> list[str]:
    """URLs on another host that a browser would fetch to show this HTML (or CSS) text."""
    if css:
        return [m.group(1) for m in _REMOTE_CSS.finditer(text)]
    found = [m.group(2) or m.group(3) for m in _REMOTE_TAG.finditer(text)]
    for style in re.findall(r"<style\b[^>]*>(.*?)</style>", text, re.I | re.S):
        found.extend(m.group(1) for m in _REMOTE_CSS.finditer(style))
    return found


def inputs_hash(root: Path) -> str:
    """SHA-256 of what executed pages depend on besides their own text."""
    root = Path(root)
    files = sorted((root / "mechlab").rglob("*.py")) + sorted((root / "book" / "_ext").glob("*.py")) \
        + [root / "environment.txt"]
    digest = hashlib.sha256()
    for path in files:
        if path.is_file() and "__pycache__" not in path.parts:
            digest.update(path.relative_to(root).as_posix().encode() + b"\0" + path.read_bytes() + b"\0")
    return digest.hexdigest()


CHECK_TAG = "check"
ERRATA_COLUMNS = ["source", "where", "printed", "correct", "evidence"]
FOLD_TAG = "hide-input"


def fold_check_cells(text: str) -> str:
    """A notebook's JSON text with ``hide-input`` added to the tags of every cell tagged
    ``check`` (unchanged text when there is none)."""
    nb = json.loads(text)
    changed = False
    for cell in nb.get("cells", []):
        tags = cell.get("metadata", {}).get("tags", [])
        if CHECK_TAG in tags and FOLD_TAG not in tags:
            cell["metadata"]["tags"] = [*tags, FOLD_TAG]
            changed = True
    return json.dumps(nb, ensure_ascii=False) if changed else text


def _on_source_read(app, docname, source):
    if str(app.env.doc2path(docname)).endswith(".ipynb"):
        source[0] = fold_check_cells(source[0])


def _on_config_inited(app, config):
    cache = Path(config.nb_execution_cache_path)
    stamp = cache.parent / (cache.name + ".inputs")
    current = inputs_hash(Path(app.confdir).parent)
    app.mechbook_stale = not stamp.is_file() or stamp.read_text() != current
    marker = _warned_marker(config)
    app.mechbook_reread = marker.is_file()
    marker.unlink(missing_ok=True)
    if app.mechbook_stale:
        shutil.rmtree(cache, ignore_errors=True)
        stamp.parent.mkdir(parents=True, exist_ok=True)
        stamp.write_text(current)


def _warned_marker(config) -> Path:
    cache = Path(config.nb_execution_cache_path)
    return cache.parent / ".mechbook-warned"


def _on_env_get_outdated(app, env, added, changed, removed):
    if not (getattr(app, "mechbook_stale", False) or getattr(app, "mechbook_reread", False)):
        return []
    return sorted(d for d in env.found_docs if d not in added and d not in changed and d not in removed)


def table_header(table: nodes.table) -> list[str]:
    """The texts of a table's first header row ([] without a header)."""
    for thead in table.findall(nodes.thead):
        for row in thead.findall(nodes.row):
            return [entry.astext().strip() for entry in row.findall(nodes.entry)]
    return []


def _on_doctree_read(app, doctree):
    for table in doctree.findall(nodes.table):
        if table_header(table) == ERRATA_COLUMNS:
            table["classes"].append("mechbook-errata")
    for node in doctree.findall(nodes.container):
        if node.get("nb_element") == "cell_code" and node.get("cell_index") is not None:
            anchor = f"cell-{node['cell_index']}"
            if anchor not in node["ids"]:
                node["ids"].append(anchor)
    for node in doctree.findall(nodes.raw):
        if "html" in node.get("format", "") and "font-awesome" in node.astext():
            text = local_animation_controls(node.astext())
            node.children = [nodes.Text(text)]
            node.rawsource = text


def _on_build_finished(app, exception):
    try:
        if exception is None and app.builder.format == "html":
            _check_offline(app)
    finally:
        if exception is not None or getattr(app, "_warncount", 0):
            marker = _warned_marker(app.config)
            marker.parent.mkdir(parents=True, exist_ok=True)
            marker.write_text("the last build had warnings: read every page again\n")


def _check_offline(app):
    out = Path(app.outdir)
    for path in sorted(out.rglob("*")):
        if path.suffix not in (".html", ".css") or "_sources" in path.parts:
            continue
        text = path.read_text(encoding="utf-8", errors="replace")
        for url in remote_fetches(text, css=path.suffix == ".css"):
            logger.warning("the book would fetch %s from another host (in %s)", url,
                           path.relative_to(out), type="mechbook", subtype="offline")


def setup(app):
    app.connect("config-inited", _on_config_inited)
    app.connect("source-read", _on_source_read)
    app.connect("env-get-outdated", _on_env_get_outdated)
    app.connect("doctree-read", _on_doctree_read)
    app.connect("build-finished", _on_build_finished)
    return {"version": "1.0", "parallel_read_safe": True, "parallel_write_safe": True}
