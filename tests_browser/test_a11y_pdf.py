"""The printed book is a tagged PDF whose figures carry alternative text (issue 29).

tools/print_pdf.py prints with Chromium's tagged output: a structure tree (headings, paragraphs,
figures) that a screen reader follows, each figure with the ``alt`` of its image, and an animation
printed as a strip of frames keeps its description. Checked with poppler's pdfinfo (the tagged flag and
the structure tree) and the PDF's own objects (each figure's /Alt), on a small page printed here and on
the whole book (book/_build/pdf/mechlab.pdf, made by `make pdf`).
"""

from __future__ import annotations

import base64
import re
import subprocess
import zlib
from pathlib import Path

import pytest
from conftest import ROOT

PDF = ROOT / "book" / "_build" / "pdf" / "mechlab.pdf"


def _objects_text(pdf: Path) -> bytes:
    """The PDF's bytes with every Flate stream (object streams hold the structure tree) decompressed."""
    raw = pdf.read_bytes()
    parts = [raw]
    for match in re.finditer(rb"stream\r?\n", raw):
        try:
            parts.append(zlib.decompressobj().decompress(raw[match.end():match.end() + 4_000_000]))
        except zlib.error:
            continue
    return b"\n".join(parts)


def structure(pdf: Path) -> dict:
    """Tagged flag, the structure tree's element counts (pdfinfo -struct), and the figures' /Alt texts."""
    info = subprocess.run(["pdfinfo", str(pdf)], capture_output=True, text=True, check=True).stdout
    tree = subprocess.run(["pdfinfo", "-struct", str(pdf)], capture_output=True, text=True, check=True).stdout
    kinds = [line.split()[0] for line in tree.splitlines() if line.strip()]
    alts = re.findall(rb"/Alt\s*(\((?:\\.|[^\\)])*\)|<[0-9A-Fa-f\s]*>)", _objects_text(pdf))
    return {"tagged": re.search(r"^Tagged:\s+yes", info, re.M) is not None,
            "figures": kinds.count("Figure"), "headings": sum(k in ("H1", "H2", "H3") for k in kinds),
            "alts": [a for a in alts if a not in (b"()", b"<>", b"<FEFF>", b"<feff>")]}


def test_a_small_page_prints_tagged_with_its_figures_described(browser, tmp_path):
    """print_pdf in the session's Chromium (a second sync Playwright cannot start inside the first one's loop,
    whichever browser test ran before)."""
    import matplotlib

    matplotlib.use("Agg")
    import print_pdf  # tools/ (conftest puts it on the path)

    from mechlab import ExternalGeneva, FourBar
    from mechlab.draw import alt_text, animate, draw

    drawing = draw(FourBar(1, 3, 3, 4, 1), 0.3)
    png = tmp_path / "figure.png"
    drawing.ax.figure.savefig(png, dpi=50)
    alt = alt_text(drawing.ax.figure)
    page = tmp_path / "page.html"
    page.write_text(
        "<!doctype html><html lang='en'><head><meta charset='utf-8'><title>A page</title>"
        "<script>window.MathJax = {startup: {promise: Promise.resolve()}};</script></head><body>"
        f"<h1>A chapter</h1><h2>A section</h2><p>A four-bar.</p>"
        f"<img alt='{alt}' src='data:image/png;base64,{base64.b64encode(png.read_bytes()).decode()}'>"
        f"{animate(ExternalGeneva(4, 1.0), n=4).to_jshtml()}</body></html>", encoding="utf-8")
    pdf = tmp_path / "page.pdf"
    assert print_pdf.print_pdf(page, pdf, browser) == 1   # the animation became a strip
    found = structure(pdf)
    assert found["tagged"] and found["headings"] >= 2
    # the figure and the strip's frames: each a Figure with a non-empty /Alt
    assert found["figures"] >= 2 and len(found["alts"]) >= found["figures"], found


def test_the_book_pdf_is_tagged_and_its_figures_described():
    if not PDF.is_file():
        pytest.fail(f"no {PDF}: run `make pdf` first (make test-browser does)")
    found = structure(PDF)
    assert found["tagged"] and found["headings"] > 20
    assert found["figures"] > 10 and len(found["alts"]) >= found["figures"], \
        {k: (v if k != "alts" else len(v)) for k, v in found.items()}
