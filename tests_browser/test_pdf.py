"""The printed book, book/_build/pdf/mechlab.pdf (made by `make pdf`), checked with poppler-utils:
every chapter starts a page, every font is embedded, every character has a font on this
machine, the math is typeset, every animation printed as a strip, no line past the margin."""

from __future__ import annotations

import json
import re
import subprocess
import sys
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


def test_no_interactive_toggles():
    """A printed page cannot unfold anything: no "Show code cell source" (or "Hide …") toggle is printed."""
    toggles = [n for n, page in enumerate(pages(), 1) if re.search(r"(Show|Hide) code cell", page)]
    assert not toggles, f"toggles printed on pages {toggles}"


def test_page_count_quoted_in_teaching():
    """book/teaching.md quotes the page count of the PDF as printed (tools/print_pdf.py --quote-pages)."""
    quoted = re.search(r"\((\d+) A4\s+pages\)", (ROOT / "book" / "teaching.md").read_text())
    assert quoted and int(quoted[1]) == len(pages())


def test_contents_give_each_chapter_its_page():
    """The contents (at the front) end each chapter's and back-matter page's line with the page it opens."""
    sys.path.insert(0, str(ROOT / "tools"))
    from print_pdf import first_pages

    titles = chapter_titles() + ["Errata", "Glossary", "References"]
    starts = first_pages(titles, pages())
    assert len(starts) == len(titles), f"chapters not found: {set(titles) - set(starts)}"
    def plain(text):
        return " ".join(text.split()).replace("\u2019", "'")

    front = plain(" ".join(pages()[: min(starts.values()) - 1]))
    wrong = [t for t in titles if not re.search(re.escape(plain(t)) + rf" {starts[t]}\b", front)]
    assert not wrong, f"no page number (or the wrong one) in the contents for {wrong}"


CODE_PAGE = """<div class="highlight"><pre><span class="k">def</span> <span class="nf">f</span>(x):
    <span class="k">return</span> <span class="n">some_function_with_a_long_name</span>(x, <span class="s2">"a string that is long enough
to run past the edge"</span>, another_argument, and_one_more_argument, and_the_last_one)
</pre></div>"""  # noqa: E501  a code line too long for the column is what the test is about


def test_code_wraps_under_its_indent(browser):
    """A code line too long for the column wraps under its own indent plus CODE_HANG_CH, not at the left edge;
    the text and the highlighting are unchanged."""
    sys.path.insert(0, str(ROOT / "tools"))
    import print_pdf

    page = browser.new_page(viewport={"width": 420, "height": 600})
    try:
        page.set_content(CODE_PAGE)
        before = page.inner_text("pre")
        page.evaluate(print_pdf.CODE_LINES_JS, print_pdf.CODE_HANG_CH)
        page.add_style_tag(content=print_pdf.PRINT_CSS)
        rows = page.evaluate("""() => Array.from(document.querySelectorAll('.mechbook-code-line')).map(line => {
            const r = document.createRange(); r.selectNodeContents(line);
            const left = line.parentElement.getBoundingClientRect().left;
            const ch = (() => { const s = document.createElement('span'); s.textContent = '0'.repeat(10);
                                line.parentElement.appendChild(s); const w = s.getBoundingClientRect().width / 10;
                                s.remove(); return w; })();
            const tops = new Map();
            for (const rect of r.getClientRects()) if (rect.width > 0 && !tops.has(Math.round(rect.top)))
                tops.set(Math.round(rect.top), (rect.left - left) / ch);
            return Array.from(tops.values());
        })""")
        after = page.inner_text("pre")
        keywords = page.locator("pre .k").count()
    finally:
        page.close()
    assert after.replace("\n", "") == before.replace("\n", "") and keywords == 2
    assert len(rows) == 3 and len(rows[0]) == 1, rows  # def f(x): fits
    first, *wrapped = rows[1]
    assert wrapped, "the long line did not wrap: widen CODE_PAGE's line"
    # its text starts at its indent (4 spaces), its continuations at 4 + CODE_HANG_CH characters
    assert round(first) == 0 and [round(x) for x in wrapped] == [4 + print_pdf.CODE_HANG_CH] * len(wrapped), rows
    assert len(rows[2]) > 1 and [round(x) for x in rows[2][1:]] == [print_pdf.CODE_HANG_CH] * (len(rows[2]) - 1)
