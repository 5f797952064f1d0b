"""The printed book, book/_build/pdf/mechlab.pdf (made by `make pdf`), checked with poppler-utils:
every chapter starts a page, every font is embedded, every character has a font on this
machine, the math is typeset, every animation printed as a strip, no line past the margin."""

from __future__ import annotations

import json
import re
import subprocess
import xml.etree.ElementTree as ET
from functools import cache

import pytest

from conftest import ROOT

PDF = ROOT / "book" / "_build" / "pdf" / "mechlab.pdf"
SINGLE = ROOT / "book" / "_build" / "singlehtml" / "intro.html"
MARGIN_PT = 15 / 25.4 * 72  # tools/print_pdf.py's MARGIN_MM


def poppler(*args: str) -> str:
    return subprocess.run(list(args), check=True, capture_output=True, text=True).stdout


@cache
def pages() -> list[str]:
    """The text of each page."""
    if not PDF.exists():
        pytest.fail(f"{PDF} is missing: run `make pdf`")
    return poppler("pdftotext", "-layout", str(PDF), "-").split("\f")[:-1]


def chapter_titles() -> list[str]:
    titles = []
    for path in sorted((ROOT / "notebooks").glob("*.ipynb")):
        first = json.loads(path.read_text())["cells"][0]["source"]
        titles.append(next(line[2:].strip() for line in first if line.startswith("# ")))
    return titles


def test_page_count_and_every_chapter_starts_a_page():
    tops = [" ".join(page.split())[:300].replace("’", "'") for page in pages()]  # Sphinx's smart quotes
    titles = chapter_titles() + ["Errata", "Glossary", "References"]
    missing = [t for t in titles if not any(top.startswith(t) for top in tops)]
    assert not missing, f"these do not open a page: {missing}"
    n = int(re.search(r"Pages:\s+(\d+)", poppler("pdfinfo", str(PDF)))[1])
    assert n == len(pages()) and len(titles) < n < 400


def test_every_font_is_embedded():
    rows = poppler("pdffonts", str(PDF)).splitlines()[2:]
    assert rows
    # columns from the right: emb sub uni object-id generation
    not_embedded = [row for row in rows if row.split()[-5] != "yes"]
    assert not not_embedded, not_embedded


def test_every_character_has_a_font_here():
    """Chromium prints a character no installed font covers as an empty box: fontconfig must
    know a font for each one (Cyrillic of the glossary, Greek, symbols)."""
    text = "".join(pages())
    chars = sorted({c for c in text if ord(c) > 127 and not c.isspace()})
    assert any("\u0400" <= c <= "\u04ff" for c in chars), "no Cyrillic in the PDF"
    uncovered = [c for c in chars if not poppler("fc-list", f":charset={ord(c):x}", "family").strip()]
    assert not uncovered, f"no font for {uncovered}"


def test_glossary_terms_in_cyrillic_are_printed():
    glossary = (ROOT / "book" / "glossary.md").read_text()
    words = set(re.findall(r"[\u0400-\u04ff]{5,}", glossary))
    text = " ".join(pages())
    assert words and not [w for w in words if w not in text]


def test_math_is_typeset():
    text = "".join(pages())
    assert not re.search(r"\\\(|\\\[|\$\$|\\frac|\\lambda", text), "TeX source printed instead of math"


def test_every_animation_is_a_strip_of_frames():
    animations = SINGLE.read_text().count('<div class="animation">')
    captions = len(re.findall(r"Animation: \d+ of its \d+ frames", "".join(pages())))
    assert animations and captions == animations


def test_no_line_past_the_margin():
    xhtml = poppler("pdftotext", "-bbox-layout", str(PDF), "-")
    root = ET.fromstring(re.sub(r'\sxmlns="[^"]+"', "", xhtml, count=1))
    outside = []
    for number, page in enumerate(root.iter("page"), 1):
        width = float(page.get("width"))
        for line in page.iter("line"):
            x0, x1 = float(line.get("xMin")), float(line.get("xMax"))
            words = " ".join(w.text or "" for w in line.iter("word"))
            # a stretched MathJax glyph (an overline, a tall bracket) reports its unscaled box
            stretched = len(words.strip()) == 1 and not words.strip().isalnum()
            if not stretched and (x0 < MARGIN_PT - 1 or x1 > width - MARGIN_PT + 1):
                outside.append(f"p. {number}: {x0:.0f}–{x1:.0f} of {width:.0f} pt: {words[:60]}")
    assert not outside, "\n".join(outside[:20])
