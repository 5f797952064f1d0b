"""Debian's Chromium as the book's tools drive it (tests_browser/ and print_pdf.py): the binary,
its offline arguments, and a watch that reports every request a page makes to another host."""

from __future__ import annotations

import os
import shutil
from urllib.parse import urlparse

CHROMIUM = os.environ.get("CHROMIUM") or shutil.which("chromium") or "/usr/bin/chromium"
# The closed proxy on this machine receives every request to another host, so none leaves it, whatever a page
# asks for (Chromium goes straight to loopback addresses, which a proxy never serves). Blocking them in the
# browser, not in a Playwright route, keeps Chromium's caches: a route pauses every request for the Python side
# and turns the cache off, and visiting the book's pages that way took twice the CPU.
OFFLINE_PROXY = "http://127.0.0.1:9"
# headless on a machine without internet: nothing in the background may phone home
CHROMIUM_ARGS = ["--no-sandbox", "--disable-gpu", "--disable-background-networking",
                 "--disable-component-update", "--disable-sync", "--no-first-run",
                 "--disable-dev-shm-usage", "--disable-default-apps", "--disable-extensions",
                 "--no-default-browser-check", "--metrics-recording-only", "--mute-audio",
                 f"--proxy-server={OFFLINE_PROXY}"]
LOCAL_HOSTS = {"127.0.0.1", "localhost", "[::1]", "::1"}


def is_remote(url: str) -> bool:
    """Whether ``url`` is a request to a host other than this machine."""
    parts = urlparse(url)
    return parts.scheme in ("http", "https", "ws", "wss") and parts.hostname not in LOCAL_HOSTS


def watch_remote(page) -> list[str]:
    """The list, kept up to date, of the URLs of other hosts that ``page`` (Playwright) asks for. The browser,
    started with `CHROMIUM_ARGS`, sends them to a closed proxy: none reaches its host."""
    remote: list[str] = []
    page.on("request", lambda request: remote.append(request.url) if is_remote(request.url) else None)
    return remote
