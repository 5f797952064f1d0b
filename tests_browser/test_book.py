"""The built book in a real browser: every page, offline, math rendered, images, animations.

Serves book/_build/html (built by `make book`) on 127.0.0.1 and visits every page with Chromium, once for
these checks and test_a11y_book.py's audit (``visit``), all in one tab. A request to any other host goes to a
closed proxy (tools/chromium.py) and is reported. A screenshot of each page is saved under
book/_build/screenshots/ (the whole page; its first screen only with MECHLAB_SCREENSHOTS=screen, as CI sets it:
a whole chapter is some 10,000 px tall and its picture took three times as long as loading the page, for a file
nobody sees there), and what is measured on the way (every animation's width on screen, every page's size, the
widest table against the column) goes to book/_build/screenshots/book.json.
"""

from __future__ import annotations

import functools
import http.server
import json
import os
import re
import threading
from urllib.parse import urlparse

import pytest
from conftest import LOCAL_HOSTS, ROOT, axe_violations, watch_remote

HTML = ROOT / "book" / "_build" / "html"
SHOTS = ROOT / "book" / "_build" / "screenshots"
PAGES = sorted(p.relative_to(HTML).as_posix() for p in HTML.rglob("*.html")
               if not {"_sources", "_static", "_images"} & set(p.relative_to(HTML).parts))
MIN_ANIMATION_PX = 600            # an animation frame on screen, in the 784 px column
MAX_PAGE_BYTES = 5 * 1024 * 1024  # a page: its HTML (frames embedded) and the images it loads from the book
MEASURED: dict[str, dict] = {}
FULL_PAGE_SHOTS = os.environ.get("MECHLAB_SCREENSHOTS", "full") != "screen"


def page_bytes(page_path: str) -> int:
    """The page's HTML and the book's own images it shows (not the theme's shared scripts and styles)."""
    html = (HTML / page_path).read_text(encoding="utf-8")
    images = {(HTML / page_path).parent.joinpath(src).resolve()
              for src in re.findall(r'<img[^>]+src="(?!data:)([^"#?]+)"', html)}
    return len(html.encode()) + sum(p.stat().st_size for p in images if p.is_file())


class _Quiet(http.server.SimpleHTTPRequestHandler):
    def log_message(self, *args):
        pass


@pytest.fixture(scope="module")
def server():
    if not (HTML / "intro.html").is_file():
        pytest.fail(f"no built book in {HTML}: run `make book` first (make test-browser does)")
    httpd = http.server.ThreadingHTTPServer(("127.0.0.1", 0), functools.partial(_Quiet, directory=str(HTML)))
    thread = threading.Thread(target=httpd.serve_forever, daemon=True)
    thread.start()
    try:
        yield f"http://127.0.0.1:{httpd.server_address[1]}"
    finally:
        httpd.shutdown()
        httpd.server_close()


# The text of the page outside code, with rendered math removed: a TeX delimiter left in
# it is math that MathJax did not typeset.
_PROSE_JS = """() => {
  const main = document.querySelector('main') || document.body;
  const copy = main.cloneNode(true);
  copy.querySelectorAll('pre, code, .highlight, mjx-container, script, style, textarea').forEach(e => e.remove());
  return copy.textContent;
}"""

_MATH_JS = """() => Array.from(document.querySelectorAll('.math')).map(e => ({
  typeset: !!e.querySelector('mjx-container') || e.tagName.toLowerCase() === 'mjx-container',
  text: e.textContent.slice(0, 80)}))"""

_IMAGES_JS = """async () => {
  const imgs = Array.from(document.images);
  imgs.forEach(i => { i.loading = 'eager'; });
  await Promise.all(imgs.map(i => i.complete ? null : new Promise(r => { i.onload = i.onerror = r; })));
  return imgs.map(i => ({src: (i.currentSrc || i.src || '').slice(0, 100), ok: i.complete && i.naturalWidth > 0}));
}"""


def test_pages_found():
    assert "intro.html" in PAGES and "errata.html" in PAGES and "glossary.html" in PAGES \
        and "references.html" in PAGES
    assert any(p.startswith("notebooks/") for p in PAGES), PAGES


VISITS: dict[str, dict] = {}   # each page's one visit: what test_page and test_a11y_book assert on


def visit(browser, server, page_path) -> dict:
    """Load ``page_path`` once for this module's checks and test_a11y_book's audit (two passes loading every page
    took twice the time): {"error": test_page's first failed check or None, "axe": axe's violations (None if it
    did not run), "axe_error": why it did not}."""
    if page_path not in VISITS:
        VISITS[page_path] = _visit(browser, server, page_path)
    return VISITS[page_path]


_TABS: dict[int, dict] = {}


def _browser_own(message) -> bool:
    """A console message about the browser's own request for /favicon.ico, which Chromium makes for a page that
    names no icon (index.html, Sphinx's redirect to intro.html): the book's server has none to give."""
    return (message.location.get("url") or "").endswith("/favicon.ico")


def _tab(browser) -> dict:
    """The one tab every page is visited in, with what it saw since it was last cleared: a tab keeps its renderer
    and its caches from page to page, while a new tab for each page loaded the theme, MathJax and axe anew and
    took twice the CPU."""
    if id(browser) not in _TABS:
        page = browser.new_context(viewport={"width": 1280, "height": 900}).new_page()
        tab = _TABS[id(browser)] = {"page": page, "errors": [], "failed": [], "remote": watch_remote(page)}
        page.on("console", lambda m: tab["errors"].append(f"console {m.type}: {m.text} ({m.location.get('url')})")
                if m.type == "error" and not _browser_own(m) else None)
        page.on("pageerror", lambda e: tab["errors"].append(f"page error: {e}"))
        page.on("requestfailed", lambda r: tab["failed"].append(f"{r.url[:120]}: {r.failure}")
                if urlparse(r.url).hostname in LOCAL_HOSTS else None)
        page.on("response", lambda r: tab["failed"].append(f"{r.url[:120]}: HTTP {r.status}") if r.status >= 400
                else None)
    tab = _TABS[id(browser)]
    for seen in ("errors", "failed", "remote"):
        tab[seen].clear()
    return tab


def _visit(browser, server, page_path) -> dict:
    seen = {"error": None, "axe": None, "axe_error": None}
    tab = _tab(browser)
    page, errors, failed, remote = tab["page"], tab["errors"], tab["failed"], tab["remote"]
    try:
        response = page.goto(f"{server}/{page_path}", wait_until="networkidle")
        assert response is not None and response.ok, f"{page_path}: HTTP {response and response.status}"
        page.evaluate("async () => { if (window.MathJax && MathJax.startup && MathJax.startup.promise)"
                      " await MathJax.startup.promise; }")
        # test_a11y_book's audit, on the page as loaded (before the checks below scroll it and play its animations)
        try:
            seen["axe"] = axe_violations(page)
        except (Exception, pytest.fail.Exception) as error:
            seen["axe_error"] = error

        math = page.evaluate(_MATH_JS)
        raw = [m["text"] for m in math if not m["typeset"]]
        assert not raw, f"{page_path}: math not typeset: {raw[:5]}"
        prose = page.evaluate(_PROSE_JS)
        for delim in ("\\(", "\\)", "\\[", "\\]", "$$", "\\begin{", "\\frac", "\\varphi"):
            assert delim not in prose, f"{page_path}: raw TeX {delim!r} left in the text"

        # a widget view left in the page would be an empty box (no kernel, no widget manager)
        assert page.locator("script[type='application/vnd.jupyter.widget-view+json']").count() == 0, \
            f"{page_path}: a widget was not rendered statically"

        if re.match(r"notebooks/\d\d[a-z]?_", page_path):  # each chapter has a widget: shown as its figure + note
            assert page.locator(".mechbook-widget img").count() >= 1, f"{page_path}: no static widget figure"
            assert "make lab" in page.locator(".mechbook-live-note").first.inner_text()

        images = page.evaluate(_IMAGES_JS)
        broken = [i["src"] for i in images if not i["ok"]]
        assert not broken, f"{page_path}: images not loaded: {broken}"

        # check cells (tag "check") are folded: their source is behind a closed toggle, not shown
        folded = page.evaluate("() => Array.from(document.querySelectorAll('.cell.tag_check')).map(c => {"
                               " const src = c.querySelector('.cell_input');"
                               " return !!src && !src.checkVisibility(); })")
        assert all(folded), f"{page_path}: a check cell's source is shown: {folded}"
        column = page.evaluate("() => (document.querySelector('article.bd-article') || document.querySelector('main'))"
                               ".getBoundingClientRect().width")
        tables = page.evaluate("() => Array.from(document.querySelectorAll('article table, main table'))"
                               ".map(t => t.getBoundingClientRect().width)")
        assert all(w <= column + 1 for w in tables), f"{page_path}: a table is wider than the column {column}: {tables}"

        animations = page.locator("div.animation")
        widths = []
        for k in range(animations.count()):
            anim = animations.nth(k)
            anim.scroll_into_view_if_needed()
            img = anim.locator("img").first
            page.wait_for_function("e => e.complete && e.naturalWidth > 0", arg=img.element_handle())
            widths.append(img.evaluate("e => e.getBoundingClientRect().width"))
            slider = anim.locator("input.anim-slider")
            frames = int(slider.get_attribute("max") or page.evaluate("e => e.max", slider.element_handle()))
            assert frames >= 1, f"{page_path}: animation {k} has one frame"
            before = (img.get_attribute("src"), slider.input_value())
            anim.locator("button[title='Play']").click()
            page.wait_for_function("([el, v]) => el.value !== v", arg=[slider.element_handle(), before[1]],
                                   timeout=5000)
            anim.locator("button[title='Pause']").click()
            after = (img.get_attribute("src"), slider.input_value())
            assert after[1] != before[1] and after[0] != before[0], \
                f"{page_path}: animation {k} did not move on Play"
            # the icons of its buttons are drawn locally (no Font Awesome from a CDN)
            icon = anim.locator("button[title='Play'] i")
            glyph = page.evaluate("e => getComputedStyle(e, '::before').content", icon.element_handle())
            assert glyph not in ("none", "normal", ""), f"{page_path}: Play button has no icon"

        size = page_bytes(page_path)
        MEASURED[page_path] = {"bytes": size, "animation_widths_px": widths, "column_px": column,
                               "widest_table_px": max(tables, default=0)}
        SHOTS.mkdir(parents=True, exist_ok=True)
        (SHOTS / "book.json").write_text(json.dumps(MEASURED, indent=1))
        assert all(w >= MIN_ANIMATION_PX for w in widths), f"{page_path}: animations narrower than " \
            f"{MIN_ANIMATION_PX} px: {widths}"
        assert size < MAX_PAGE_BYTES, f"{page_path}: {size / 2**20:.2f} MB"
        page.evaluate("() => { if (document.activeElement) document.activeElement.blur(); window.scrollTo(0, 0); }")
        page.screenshot(path=str(SHOTS / (page_path.replace("/", "__").removesuffix(".html") + ".png")),
                        full_page=FULL_PAGE_SHOTS)
        assert not remote, f"{page_path}: requests to another host: {remote}"
        assert not failed, f"{page_path}: failed requests: {failed}"
        assert not errors, f"{page_path}: {errors}"
    except (Exception, pytest.fail.Exception) as error:   # a failed check: test_page reports it
        seen["error"] = error
    return seen


@pytest.mark.parametrize("page_path", PAGES)
def test_page(browser, server, page_path):
    error = visit(browser, server, page_path)["error"]
    if error is not None:
        raise error


def test_errata_links_resolve(browser, server):
    """Every link of the Errata page to a chapter reaches that page and the cell it names."""
    page = browser.new_page()
    try:
        page.goto(f"{server}/errata.html")
        hrefs = page.evaluate("() => Array.from(document.querySelectorAll('main a'))"
                              ".map(a => a.getAttribute('href')).filter(h => h && h.startsWith('notebooks/'))")
        assert hrefs or "No errata" in page.inner_text("main"), "the Errata page links to no chapter"
        for href in sorted(set(hrefs)):
            path, _, anchor = href.partition("#")
            assert (HTML / path).is_file(), f"errata links to missing page {path}"
            if anchor:
                page.goto(f"{server}/{href}")
                assert page.locator(f"[id='{anchor}']").count() == 1, f"{href}: no element with id {anchor}"
    finally:
        page.close()


def test_a_request_to_another_host_is_reported_and_never_answered(browser, server):
    """The browser's offline proxy (tools/chromium.py): a page's request to another host, by name or by address,
    over HTTP or HTTPS, fails at once on this machine (at the proxy, not for want of a network), and the watch
    reports it."""
    page = browser.new_page()
    failures = {}
    try:
        remote = watch_remote(page)
        page.on("requestfailed", lambda r: failures.setdefault(r.url, r.failure))
        page.goto(f"{server}/intro.html")
        outcomes = page.evaluate("""async (urls) => Promise.all(urls.map(u => fetch(u, {mode: 'no-cors'})
            .then(() => 'answered', () => 'refused')))""", OTHER_HOSTS)
    finally:
        page.close()
    assert outcomes == ["refused"] * len(OTHER_HOSTS)
    assert failures == dict.fromkeys(OTHER_HOSTS, "net::ERR_PROXY_CONNECTION_FAILED"), failures
    assert sorted(remote) == sorted(OTHER_HOSTS)


OTHER_HOSTS = ["http://203.0.113.7/a.png", "https://example.org/b.js", "http://cdn.jsdelivr.net/c.css"]
