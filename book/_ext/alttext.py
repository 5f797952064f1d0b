"""Sphinx extension of the course book: every image carries alternative text.

* A figure displayed by a page's code (a notebook cell) gets its description from where it
  was made: the book's kernels publish :func:`mechlab.draw.access.alt_text` of every figure
  as the ``alt`` of the output's image metadata (``_ext/kernel_startup.py`` calls
  :func:`mechlab.draw.access.install_alt_text`). myst-nb reads only ``width`` and ``height``
  from an output's metadata; this extension makes its image renderer read ``alt`` too, so the
  page's ``<img>`` carries it (and the PDF printed from the page, its alternative text).
* After an HTML build, every page is scanned for an ``<img>`` whose ``alt`` is missing, empty
  or only the image's address (what docutils writes for an image without one: a figure that
  names nothing, an animation without a description): each one is a
  warning naming the page, so ``sphinx-build -W`` fails on it.
* In the single-page book that ``tools/print_pdf.py`` prints, a figure directive's ``<figure>`` is a
  ``role="group"`` around its image and caption: Chromium's tagged PDF makes every ``<figure>`` a
  /Figure structure element, which gets no /Alt (its name is its caption), so the described image
  would sit inside an undescribed Figure (PDF/UA wants every Figure described). The image inside
  stays the Figure, with its alt; the web pages keep their ``<figure>``.
"""

from __future__ import annotations

from html.parser import HTMLParser
from pathlib import Path

from sphinx.util import logging

logger = logging.getLogger(__name__)


class _Images(HTMLParser):
    def __init__(self):
        super().__init__(convert_charrefs=True)
        self.missing: list[str] = []
        self.count = 0

    def handle_starttag(self, tag, attrs):
        if tag != "img":
            return
        self.count += 1
        attrs = dict(attrs)
        alt, src = (attrs.get("alt") or "").strip(), attrs.get("src") or ""
        # docutils writes the image's own address as its alt when a node has none
        if not alt or alt == src or (src and alt.rsplit("/", 1)[-1] == src.rsplit("/", 1)[-1]):
            src = src or attrs.get("id") or "?"
            self.missing.append(src if not src.startswith("data:") else src[:40] + "…")


def images_without_alt(html: str) -> tuple[int, list[str]]:
    """The number of ``<img>`` elements in ``html`` and the sources of those without a non-empty ``alt``."""
    parser = _Images()
    parser.feed(html)
    parser.close()
    return parser.count, parser.missing


def _render_image_with_alt(render_image):
    def render(self, data):
        result = render_image(self, data)
        alt = data.output_metadata.get(data.mime_type, {}).get("alt")
        for node in result:
            if alt and not node.get("alt"):
                node["alt"] = str(alt)
        return result

    render.mechbook_alt = True
    return render


def _figure_as_group(visit_figure):
    def visit(self, node):
        visit_figure(self, node)
        if self.builder.name == "singlehtml" and self.body[-1].startswith("<figure"):
            self.body[-1] = self.body[-1].replace("<figure", '<figure role="group"', 1)

    visit.mechbook_group = True
    return visit


def _check_alt(app, exception):
    if exception is not None or app.builder.format != "html":
        return
    out = Path(app.outdir)
    for path in sorted(out.rglob("*.html")):
        if "_sources" in path.parts:
            continue
        _, missing = images_without_alt(path.read_text(encoding="utf-8", errors="replace"))
        for src in missing:
            logger.warning("an image without alternative text in %s (%s): describe the figure where it is made "
                           "(mechlab.draw.access.set_alt, or a title and axis labels)", path.relative_to(out), src,
                           type="mechbook", subtype="alt")


def setup(app):
    from myst_nb.core.render import NbElementRenderer

    if not getattr(NbElementRenderer.render_image, "mechbook_alt", False):
        NbElementRenderer.render_image = _render_image_with_alt(NbElementRenderer.render_image)
    from sphinx.writers.html5 import HTML5Translator

    if not getattr(HTML5Translator.visit_figure, "mechbook_group", False):
        HTML5Translator.visit_figure = _figure_as_group(HTML5Translator.visit_figure)
    app.connect("build-finished", _check_alt, priority=400)   # before mechbook's, which records the warnings
    return {"version": "1.0", "parallel_read_safe": True, "parallel_write_safe": True}
