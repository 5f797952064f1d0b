"""Every page of the built book audited by axe-core in Chromium (issue 29: WCAG 2.1 AA).

axe-core comes from npm at a pin (`make axe-deps` puts it in .axe-deps/, `make test-browser` does it first;
AXE_JS overrides the path of axe.min.js). Each page of book/_build/html is served on 127.0.0.1, axe runs on it
with the WCAG 2.0/2.1 A and AA rules and the best practices, and a violation of impact "serious" or "critical"
fails the page's test. Each page is loaded once for this audit and test_book.py's checks (test_book.visit):
axe runs as soon as the page and its math are loaded, before those checks scroll it and play its animations.
The theme's colour-mode switch is left out: the theme (pydata-sphinx-theme) names it "Color mode" while its
icons carry titles, and its scripts set them again after book/_static/a11y.js removes them on some loads (axe
"label-content-name-mismatch"), which is the theme's to fix, not this book's content. Every violation found,
whatever its impact, goes to book/_build/screenshots/a11y.json: per page, the rule, its impact and how many
elements break it.
"""

from __future__ import annotations

import json

import pytest
from conftest import axe_violations
from test_book import PAGES, SHOTS, server, visit  # noqa: F401  (the same pages on the same server, visited once)

FAILING = {"serious", "critical"}
FOUND: dict[str, list[dict]] = {}


@pytest.fixture(scope="module", autouse=True)
def _report():
    yield
    SHOTS.mkdir(parents=True, exist_ok=True)
    counts = {impact: sum(len(v["nodes"]) for vs in FOUND.values() for v in vs if v["impact"] == impact)
              for impact in ("critical", "serious", "moderate", "minor")}
    (SHOTS / "a11y.json").write_text(json.dumps({"pages": len(FOUND), "nodes by impact": counts,
                                                 "violations": FOUND}, indent=1, ensure_ascii=False))


@pytest.mark.parametrize("page_path", PAGES)
def test_page_has_no_serious_accessibility_violation(browser, server, page_path):  # noqa: F811
    seen = visit(browser, server, page_path)
    if seen["axe"] is None:            # axe did not run: its own error, or the page's that stopped the visit first
        raise seen["axe_error"] or seen["error"]
    found = FOUND[page_path] = seen["axe"]
    bad = [f"{v['id']} ({v['impact']}, {len(v['nodes'])}×): {v['help']}; e.g. {v['nodes'][0]}"
           for v in found if v["impact"] in FAILING]
    assert not bad, "\n".join(bad)


def test_a_planted_violation_is_found(browser, server):  # noqa: F811
    """The audit sees what it must: an image without alt text and grey-on-white text are reported."""
    page = browser.new_page()
    try:
        page.goto(f"{server}/{PAGES[0]}", wait_until="networkidle")
        page.evaluate("""() => { const main = document.querySelector('main') || document.body;
          main.insertAdjacentHTML('afterbegin', '<img src="_static/favicon.svg"><p style="color:#bbb">faint</p>'); }""")
        ids = {v["id"] for v in axe_violations(page)}
    finally:
        page.close()
    assert {"image-alt", "color-contrast"} <= ids


def test_math_carries_assistive_mathml(browser, server):  # noqa: F811
    """MathJax's assistive MathML is on: every typeset formula has a hidden MathML copy a screen reader reads."""
    page = browser.new_page()
    try:
        page.goto(f"{server}/glossary.html", wait_until="networkidle")
        page.wait_for_function("() => window.MathJax && MathJax.startup && MathJax.startup.promise")
        page.evaluate("() => MathJax.startup.promise")
        typeset, assistive = page.evaluate("() => [document.querySelectorAll('mjx-container').length, "
                                           "document.querySelectorAll('mjx-container mjx-assistive-mml math').length]")
    finally:
        page.close()
    assert typeset > 20 and assistive == typeset
