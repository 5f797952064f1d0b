"""Sphinx extension of the course book: cell anchors, local animation controls, offline check.

* Every code cell of a notebook page gets the HTML id ``cell-<index>`` (its index in
  the notebook's list of cells), so the Errata page can link to the very cell that
  demonstrates a mistake.
* matplotlib's ``to_jshtml()`` links a Font Awesome stylesheet from a CDN for its
  buttons; the link is removed and the icons become local classes that
  ``_static/mechbook.css`` draws with plain Unicode glyphs.
* After the build, every HTML page and stylesheet of the output is scanned for a
  script, stylesheet, image, font or frame that would be fetched from another host;
  each one is a warning, so ``sphinx-build -W`` fails on it.
"""

from __future__ import annotations

import re
from pathlib import Path

from docutils import nodes
from sphinx.util import logging

logger = logging.getLogger(__name__)

_REMOTE_FONT_AWESOME = re.compile(r'<link[^>]*href="(?:https?:)?//[^"]*font-awesome[^"]*"[^>]*>\s*', re.I)
_FA_CLASS = re.compile(r'class="fa fa-([a-z-]+)(?: fa-flip-horizontal)?"')

# A fetch from another host: <script src>, <link href> (stylesheet, icon, preload, font),
# <img|source|iframe|video|audio|embed src>, CSS url() and @import.
_REMOTE_TAG = re.compile(
    r'<(script|img|iframe|source|video|audio|embed)\b[^>]*\bsrc\s*=\s*["\']?((?:https?:)?//[^"\'\s>]+)'
    r'|<link\b(?=[^>]*\brel\s*=\s*["\']?(?:stylesheet|icon|shortcut icon|preload|prefetch|modulepreload|'
    r'manifest|apple-touch-icon)\b)[^>]*\bhref\s*=\s*["\']?((?:https?:)?//[^"\'\s>]+)', re.I)
_REMOTE_CSS = re.compile(r'(?:url\(\s*["\']?|@import\s+["\'])((?:https?:)?//[^"\')\s]+)', re.I)


def local_animation_controls(html: str) -> str:
    """Drop matplotlib's remote Font Awesome link and rename its icon classes to local ones.

    ``<i class="fa fa-play fa-flip-horizontal">`` (play backwards) becomes
    ``mechbook-icon mechbook-play-backwards``; the others keep their icon name.
    """
    html = _REMOTE_FONT_AWESOME.sub("", html)

    def rename(match: re.Match) -> str:
        name = match.group(1)
        if "fa-flip-horizontal" in match.group(0):
            name = "play-backwards"
        return f'class="mechbook-icon mechbook-{name}"'

    return _FA_CLASS.sub(rename, html)


def remote_fetches(text: str, css: bool = False) -> list[str]:
    """URLs on another host that a browser would fetch to show this HTML (or CSS) text."""
    if css:
        return [m.group(1) for m in _REMOTE_CSS.finditer(text)]
    found = [m.group(2) or m.group(3) for m in _REMOTE_TAG.finditer(text)]
    for style in re.findall(r"<style\b[^>]*>(.*?)</style>", text, re.I | re.S):
        found.extend(m.group(1) for m in _REMOTE_CSS.finditer(style))
    return found


def _on_doctree_read(app, doctree):
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
    if exception is not None or app.builder.format != "html":
        return
    out = Path(app.outdir)
    for path in sorted(out.rglob("*")):
        if path.suffix not in (".html", ".css") or "_sources" in path.parts:
            continue
        text = path.read_text(encoding="utf-8", errors="replace")
        for url in remote_fetches(text, css=path.suffix == ".css"):
            logger.warning("the book would fetch %s from another host (in %s)", url,
                           path.relative_to(out), type="mechbook", subtype="offline")


def setup(app):
    app.connect("doctree-read", _on_doctree_read)
    app.connect("build-finished", _on_build_finished)
    return {"version": "1.0", "parallel_read_safe": True, "parallel_write_safe": True}
