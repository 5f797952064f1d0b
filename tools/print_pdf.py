"""The whole book as one PDF: the single-page HTML book (sphinx-build -b singlehtml) printed
by Debian's Chromium through Playwright, offline.

    python tools/print_pdf.py book/_build/singlehtml/intro.html book/_build/pdf/mechlab.pdf [--quote-pages]

Before printing: MathJax has typeset every formula, each animation is replaced by four of
its frames in two rows of two (each half the column wide), a display formula too wide for the
column is scaled down to fit, each line of code is wrapped under its own indent, and a print
style sheet drops the web page's navigation and the folded check cells' "Show code cell
source" toggles (a printed page cannot unfold them; the checks' outputs stay), fits tables
to the page and starts each chapter on a new page. The book is printed twice: the first
print tells on which page each chapter starts, the second carries those page numbers in the
contents. With --quote-pages (`make pdf`), the page count is then quoted in book/teaching.md
("(N A4 pages)"); tests_browser/test_pdf.py compares the two.
"""

from __future__ import annotations

import re
import subprocess
import sys
import tempfile
from pathlib import Path

from chromium import CHROMIUM, CHROMIUM_ARGS, watch_remote
from playwright.sync_api import sync_playwright

FRAMES = 4  # frames of an animation in its printed strip
MARGIN_MM = 15
CODE_HANG_CH = 4  # a wrapped code line goes on this many characters right of its line's indent
TEACHING = Path(__file__).resolve().parents[1] / "book" / "teaching.md"
PAGE_COUNT = re.compile(r"\((?:about )?\d+ A4(\s+)pages\)")  # how teaching.md quotes the count

PRINT_CSS = """
@page { size: A4; }
.bd-header, .bd-sidebar-primary, .bd-sidebar-secondary, .header-article, .prev-next-area, .bd-footer,
.bd-footer-article, .bd-footer-content, footer, .headerlink, .copybtn, .toggle-details, .skip-link,
#pst-back-to-top, .search-button-field, .mechbook-live-note, details.hide.above-input { display: none !important; }
.bd-main, .bd-content, .bd-article-container, .bd-article, .bd-page-width, .bd-container, .bd-container__inner
  { max-width: none !important; width: 100% !important; margin: 0 !important; padding: 0 !important; }
body { font-size: 10pt; }
/* code and text outputs wrap instead of running past the margin; each code line (CODE_LINES_JS) is a
   block whose wrapped part hangs under its indent plus --hang */
pre, .highlight pre, .output pre { white-space: pre-wrap !important; overflow-wrap: anywhere;
  overflow: visible !important; max-height: none !important; font-size: 8pt; }
.mechbook-code-line { display: block; padding-left: calc(var(--indent) + var(--hang));
  text-indent: calc(-1 * (var(--indent) + var(--hang))); }
.mechbook-code-line:empty::before { content: " "; }
/* the contents: a chapter's page number at the right of its line */
#jb-print-toc a[data-page]::after { content: attr(data-page); float: right; }
/* a long cell may break across pages rather than leave its frame empty at the foot of one */
.cell, .cell_input, .cell_output, div.highlight { display: block !important; }
.cell, .cell_input, .highlight, pre { break-inside: auto !important; }
/* tables fit the page: fixed layout over the full width, small type, long words broken */
/* 2 mm short of the margin: cell padding and borders must not carry a full line past it */
table { width: calc(100% - 2mm) !important; table-layout: fixed; font-size: 7.5pt; }
th, td { overflow-wrap: anywhere; word-break: break-word; padding: 2px 3px !important; }
.table-wrapper, .pst-scrollable-table-container, .cell_output, .output { overflow: visible !important; }
img { max-width: 100% !important; height: auto !important; break-inside: avoid; }
mjx-container[display="true"] { max-width: 100%; overflow: visible !important; }
h1, h2, h3, h4 { break-after: avoid; }
/* every chapter and back-matter page on a new page (chapters carry their numbers in their titles) */
span[id^="document-"] + section { break-before: page; }
#the-chapters > h2 { display: none; }
.mechbook-print-strip { display: grid; grid-template-columns: 1fr 1fr; gap: 2mm; break-inside: avoid; }
.mechbook-print-strip img { width: 100%; }
.mechbook-print-strip-caption { font-size: 8pt; color: #555; margin-top: 1mm; }
"""

# matplotlib's to_jshtml() keeps its frames in the global `anim<id>` (`frames`: Image objects)
STRIPS_JS = """(count) => {
  let done = 0;
  for (const div of document.querySelectorAll("div.animation")) {
    const img = div.querySelector("img[id^='_anim_img']");
    const anim = img && window["anim" + img.id.slice("_anim_img".length)];
    if (!anim || !anim.frames || !anim.frames.length) continue;
    const n = anim.frames.length, k = Math.min(count, n);
    const strip = document.createElement("div");
    strip.className = "mechbook-print-strip";
    for (let i = 0; i < k; i++) {
      const frame = document.createElement("img");
      frame.src = anim.frames[Math.round(i * (n - 1) / Math.max(k - 1, 1))].src;
      frame.alt = i ? `Frame ${i + 1} of ${k} of the same animation.` : `${img.alt} (frame 1 of ${k} shown)`;
      strip.appendChild(frame);
    }
    const caption = document.createElement("p");
    caption.className = "mechbook-print-strip-caption";
    caption.textContent = `Animation: ${k} of its ${n} frames, evenly spaced (run the chapter to see it move).`;
    div.replaceWith(strip, caption);
    done++;
  }
  return done;
}"""

# a display formula wider than the column is scaled down to fit (MathJax 3 does not break lines)
FIT_MATH_JS = """() => {
  let scaled = 0;
  for (const m of document.querySelectorAll("mjx-container[display='true']")) {
    const room = m.parentElement.getBoundingClientRect().width;
    const need = m.firstElementChild.getBoundingClientRect().width;
    if (need > room) { m.style.fontSize = `${Math.floor(98 * room / need)}%`; scaled++; }
  }
  return scaled;
}"""

# Each line of a code cell as a block of its own (`mechbook-code-line`, its leading spaces as --indent), so
# that a line too long for the page wraps under its own indent, not at the left edge. Pygments' spans are
# flat; one that spans lines (a docstring) is cut into one copy per line.
CODE_LINES_JS = """(hang) => {
  let count = 0;
  for (const pre of document.querySelectorAll('div.highlight pre')) {
    const lines = [[]];
    for (const node of Array.from(pre.childNodes)) {
      node.textContent.split('\\n').forEach((part, i) => {
        if (i > 0) lines.push([]);
        if (!part) return;
        const piece = node.nodeType === Node.TEXT_NODE ? document.createTextNode(part) : node.cloneNode(false);
        if (node.nodeType !== Node.TEXT_NODE) piece.textContent = part;
        lines[lines.length - 1].push(piece);
      });
    }
    if (lines.length > 1 && !lines[lines.length - 1].length) lines.pop();  // the final newline
    pre.replaceChildren(...lines.map(nodes => {
      const line = document.createElement('span');
      line.className = 'mechbook-code-line';
      const text = nodes.map(n => n.textContent).join('');
      line.style.setProperty('--indent', `${text.length - text.trimStart().length}ch`);
      line.style.setProperty('--hang', `${hang}ch`);
      line.append(...nodes);
      return line;
    }));
    count++;
  }
  return count;
}"""

# the printed contents' entries (sphinx-book-theme's #jb-print-toc) as [index, text]; then their pages, as data-page
TOC_JS = """() => Array.from(document.querySelectorAll('#jb-print-toc a.reference.internal'))
  .map((a, i) => [i, a.textContent.trim()])"""
SET_PAGES_JS = """(pages) => {
  const links = document.querySelectorAll('#jb-print-toc a.reference.internal');
  for (const [i, page] of pages) links[i].setAttribute('data-page', String(page));
}"""

FOOTER = ('<div style="font-size:8px;width:100%;text-align:center;color:#555">'
          '<span class="pageNumber"></span> / <span class="totalPages"></span></div>')


def page_texts(pdf: Path) -> list[str]:
    """The text of each page of `pdf` (poppler's pdftotext)."""
    out = subprocess.run(["pdftotext", "-layout", str(pdf), "-"], check=True, capture_output=True, text=True).stdout
    return out.split("\f")[:-1]


def first_pages(titles: list[str], pages: list[str]) -> dict[str, int]:
    """The page (from 1) that each title opens (its first 300 characters start with it), for the titles found.

    The titles are in the book's order: each is looked for from the page of the one before, so that a
    back-matter title ("Errata") is not taken for a chapter's section of the same name.
    """
    tops = [" ".join(page.split())[:300].replace("\u2019", "'") for page in pages]
    found, start = {}, 0
    for title in titles:
        wanted = " ".join(title.split()).replace("\u2019", "'")
        number = next((n for n in range(start + 1, len(tops) + 1) if tops[n - 1].startswith(wanted)), None)
        if number:
            found[title], start = number, number - 1
    return found


def quote_page_count(count: int, teaching: Path = TEACHING) -> bool:
    """Write `count` into teaching.md's "(N A4 pages)"; True when the text changed."""
    text = teaching.read_text()
    if not PAGE_COUNT.search(text):
        sys.exit(f"{teaching} no longer quotes the page count as '(N A4 pages)'")
    new = PAGE_COUNT.sub(lambda m: f"({count} A4{m[1]}pages)", text, count=1)
    if new != text:
        teaching.write_text(new)
    return new != text


def print_pdf(html: Path, pdf: Path, browser=None) -> int:
    """Print `html` to `pdf`, twice (the contents get the pages the first print found); returns the number
    of animations turned into strips.

    `browser`: a Playwright Chromium already running (the browser tests' session browser: a second sync
    Playwright cannot start inside the first one's event loop); without it, Chromium is launched here.
    """
    pdf.parent.mkdir(parents=True, exist_ok=True)
    if browser is not None:
        return _print(browser, html, pdf)
    with sync_playwright() as pw:
        browser = pw.chromium.launch(executable_path=CHROMIUM, headless=True, args=CHROMIUM_ARGS)
        try:
            return _print(browser, html, pdf)
        finally:
            browser.close()


def _print(browser, html: Path, pdf: Path) -> int:
    """print_pdf's work, in a new page of `browser` (closed after)."""
    page = browser.new_page()
    try:
        remote = watch_remote(page)
        page.goto(html.resolve().as_uri(), wait_until="load", timeout=120_000)
        page.wait_for_function("() => window.MathJax && MathJax.startup && MathJax.startup.promise",
                               timeout=60_000)
        page.evaluate("() => MathJax.startup.promise")
        page.wait_for_function("() => typeof Animation === 'undefined' || "
                               "[...document.querySelectorAll('div.animation img[id^=_anim_img]')]"
                               ".every(i => window['anim' + i.id.slice(9)])", timeout=60_000)
        strips = page.evaluate(STRIPS_JS, FRAMES)
        page.evaluate(CODE_LINES_JS, CODE_HANG_CH)
        page.add_style_tag(content=PRINT_CSS)
        page.emulate_media(media="print")
        # lay the page out at the printed column's width (A4 less the margins, 96 px per inch)
        page.set_viewport_size({"width": round((210 - 2 * MARGIN_MM) / 25.4 * 96), "height": 1100})
        page.evaluate(FIT_MATH_JS)
        margin = f"{MARGIN_MM}mm"
        # tagged: a structure tree (headings, paragraphs, figures with their alt text) for screen readers
        options = dict(format="A4", print_background=True, display_header_footer=True, tagged=True, outline=True,
                       header_template="<span></span>", footer_template=FOOTER,
                       margin={"top": margin, "bottom": margin, "left": margin, "right": margin})
        entries = page.evaluate(TOC_JS)
        with tempfile.TemporaryDirectory(prefix="mechlab-pdf-") as tmp:
            draft = Path(tmp) / "draft.pdf"
            page.pdf(path=str(draft), **options)
            found = first_pages([text for _, text in entries], page_texts(draft))
        page.evaluate(SET_PAGES_JS, [[i, found[text]] for i, text in entries if text in found])
        page.pdf(path=str(pdf), **options)
        if remote:
            sys.exit(f"the book asked for other hosts while printing: {remote}")
        return strips
    finally:
        page.close()


if __name__ == "__main__":
    source, target = Path(sys.argv[1]), Path(sys.argv[2])
    n = print_pdf(source, target)
    count = len(page_texts(target))
    changed = quote_page_count(count) if "--quote-pages" in sys.argv[3:] else False
    print(f"the PDF: {target} ({count} pages, {n} animations printed as {FRAMES} frames each)"
          + (f"; the page count quoted in {TEACHING.name} is now {count}" if changed else ""))
