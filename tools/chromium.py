"""Debian's Chromium as the book's tools drive it (tests_browser/ and print_pdf.py): the binary,
its offline arguments, and a route that keeps every page on this machine."""

from __future__ import annotations

import os
import shutil
from urllib.parse import urlparse

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
