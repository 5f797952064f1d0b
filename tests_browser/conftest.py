"""Real-browser tests: Debian's Chromium driven by Playwright (never `playwright install`).

Run with `make test-browser` (it builds the book and installs Chromium with apt-get if it
is missing). This folder is separate from tests/, so the plain `pytest tests` run never
collects it. CHROMIUM overrides the browser binary (default: chromium on PATH).
"""

from __future__ import annotations

import os
import socket
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "tools"))
from chromium import CHROMIUM, CHROMIUM_ARGS, LOCAL_HOSTS, watch_remote  # noqa: E402,F401  (shared with tools/print_pdf.py)


def free_port() -> int:
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


@pytest.fixture(scope="session")
def browser():
    if not Path(CHROMIUM).exists():
        pytest.fail(f"Chromium not found at {CHROMIUM}: `make test-browser` installs Debian's chromium "
                    "with apt-get (or set CHROMIUM=/path/to/chromium)")
    from playwright.sync_api import sync_playwright

    with sync_playwright() as pw:
        b = pw.chromium.launch(executable_path=CHROMIUM, headless=True, args=CHROMIUM_ARGS)
        try:
            yield b
        finally:
            b.close()


# axe-core from npm at a pin (`make axe-deps` puts it in .axe-deps/; AXE_JS overrides the path of axe.min.js):
# test_book.py runs it during its one visit of each book page, test_a11y_book.py asserts on what it found
AXE_JS = os.environ.get("AXE_JS") or str(ROOT / ".axe-deps" / "node_modules" / "axe-core" / "axe.min.js")
AXE_TAGS = ["wcag2a", "wcag2aa", "wcag21a", "wcag21aa", "best-practice"]
_AXE_RUN_JS = """async (tags) => {
  const result = await axe.run({exclude: [['.theme-switch-button']]},
                               {runOnly: {type: 'tag', values: tags}, resultTypes: ['violations']});
  return result.violations.map(v => ({id: v.id, impact: v.impact, help: v.help,
    nodes: v.nodes.map(n => n.target.join(' ') + ' :: ' + (n.failureSummary || '').split('\\n').slice(1).join(' '))}));
}"""


def axe_violations(page) -> list[dict]:
    """axe-core's violations on the page open in ``page`` (Playwright): id, impact, help, offending nodes."""
    if not os.path.isfile(AXE_JS):
        pytest.fail(f"axe-core not found at {AXE_JS}: run `make axe-deps` (make test-browser does)")
    page.add_script_tag(path=AXE_JS)
    return page.evaluate(_AXE_RUN_JS, AXE_TAGS)
