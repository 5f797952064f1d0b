"""The whole book as one PDF: the single-page HTML book (sphinx-build -b singlehtml) printed
by Debian's Chromium through Playwright, offline.

    python tools/print_pdf.py book/_build/singlehtml/intro.html book/_build/pdf/mechlab.pdf

Before printing: MathJax has typeset every formula, each animation is replaced by a strip
of a few of its frames, a display formula too wide for the column is scaled down to fit,
and a print style sheet drops the web page's navigation, wraps
code, fits tables to the page and starts each chapter on a new page.
"""

from __future__ import annotations

import sys
from pathlib import Path

from playwright.sync_api import sync_playwright

from chromium import CHROMIUM, CHROMIUM_ARGS, block_remote

FRAMES = 4  # frames of an animation in its printed strip
MARGIN_MM = 15

PRINT_CSS = """
@page { size: A4; }
.bd-header, .bd-sidebar-primary, .bd-sidebar-secondary, .header-article, .prev-next-area, .bd-footer,
.bd-footer-article, .bd-footer-content, footer, .headerlink, .copybtn, .toggle-details, .skip-link,
#pst-back-to-top, .search-button-field, .mechbook-live-note { display: none !important; }
.bd-main, .bd-content, .bd-article-container, .bd-article, .bd-page-width, .bd-container, .bd-container__inner
  { max-width: none !important; width: 100% !important; margin: 0 !important; padding: 0 !important; }
body { font-size: 10pt; }
/* code and text outputs wrap instead of running past the margin */
pre, .highlight pre, .output pre { white-space: pre-wrap !important; overflow-wrap: anywhere;
  overflow: visible !important; max-height: none !important; font-size: 8pt; }
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
.mechbook-print-strip { display: flex; gap: 2mm; break-inside: avoid; }
.mechbook-print-strip img { width: calc((100% - 6mm) / 4); }
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

FOOTER = ('<div style="font-size:8px;width:100%;text-align:center;color:#555">'
          '<span class="pageNumber"></span> / <span class="totalPages"></span></div>')


def print_pdf(html: Path, pdf: Path) -> int:
    """Print `html` to `pdf`; returns the number of animations turned into strips."""
    pdf.parent.mkdir(parents=True, exist_ok=True)
    with sync_playwright() as pw:
        browser = pw.chromium.launch(executable_path=CHROMIUM, headless=True, args=CHROMIUM_ARGS)
        try:
            page = browser.new_page()
            remote = block_remote(page)
            page.goto(html.resolve().as_uri(), wait_until="load", timeout=120_000)
            page.wait_for_function("() => window.MathJax && MathJax.startup && MathJax.startup.promise",
                                   timeout=60_000)
            page.evaluate("() => MathJax.startup.promise")
            page.wait_for_function("() => typeof Animation === 'undefined' || "
                                   "[...document.querySelectorAll('div.animation img[id^=_anim_img]')]"
                                   ".every(i => window['anim' + i.id.slice(9)])", timeout=60_000)
            strips = page.evaluate(STRIPS_JS, FRAMES)
            page.add_style_tag(content=PRINT_CSS)
            page.emulate_media(media="print")
            # lay the page out at the printed column's width (A4 less the margins, 96 px per inch)
            page.set_viewport_size({"width": round((210 - 2 * MARGIN_MM) / 25.4 * 96), "height": 1100})
            page.evaluate(FIT_MATH_JS)
            margin = f"{MARGIN_MM}mm"
            page.pdf(path=str(pdf), format="A4", print_background=True, display_header_footer=True,
                     header_template="<span></span>", footer_template=FOOTER,
                     margin={"top": margin, "bottom": margin, "left": margin, "right": margin})
            if remote:
                sys.exit(f"the book asked for other hosts while printing: {remote}")
            return strips
        finally:
            browser.close()


if __name__ == "__main__":
    source, target = Path(sys.argv[1]), Path(sys.argv[2])
    n = print_pdf(source, target)
    print(f"the PDF: {target} ({n} animations printed as strips of {FRAMES} frames)")
