"""Real-browser tests: Debian's Chromium driven by Playwright (never `playwright install`).

Run with `make test-browser` (it builds the book and installs Chromium with apt-get if it
is missing). This folder is separate from tests/, so the plain `pytest tests` run never
collects it. CHROMIUM overrides the browser binary (default: chromium on PATH).
"""

from __future__ import annotations

import os
import shutil
import socket
from pathlib import Path
from urllib.parse import urlparse

import pytest

ROOT = Path(__file__).resolve().parent.parent
CHROMIUM = os.environ.get("CHROMIUM") or shutil.which("chromium") or "/usr/bin/chromium"
# headless on a machine without internet: nothing in the background may phone home
CHROMIUM_ARGS = ["--no-sandbox", "--disable-gpu", "--disable-background-networking",
                 "--disable-component-update", "--disable-sync", "--no-first-run",
                 "--disable-dev-shm-usage", "--disable-default-apps", "--disable-extensions",
                 "--no-default-browser-check", "--metrics-recording-only", "--mute-audio"]
LOCAL_HOSTS = {"127.0.0.1", "localhost", "[::1]", "::1"}


def block_remote(page) -> list[str]:
    """Abort every request of ``page`` to a host other than this machine; returns the list
    the aborted URLs are collected in (the course loads nothing from the internet)."""
    remote: list[str] = []

    def route(r):
        url = urlparse(r.request.url)
        if url.scheme in ("http", "https", "ws", "wss") and url.hostname not in LOCAL_HOSTS:
            remote.append(r.request.url)
            r.abort()
        else:
            r.continue_()

    page.route("**/*", route)
    return remote


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
