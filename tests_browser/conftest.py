"""Real-browser tests: Debian's Chromium driven by Playwright (never `playwright install`).

Run with `make test-browser` (it builds the book and installs Chromium with apt-get if it
is missing). This folder is separate from tests/, so the plain `pytest tests` run never
collects it. CHROMIUM overrides the browser binary (default: chromium on PATH).
"""

from __future__ import annotations

import socket
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "tools"))
from chromium import CHROMIUM, CHROMIUM_ARGS, LOCAL_HOSTS, block_remote  # noqa: E402,F401  (shared with tools/print_pdf.py)


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
