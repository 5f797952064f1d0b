"""book/_ext/hublink.py: the "open on the hub" link of each chapter page, built by Sphinx on a
tiny project (no browser): present and correct when the hub is configured, absent otherwise."""

from __future__ import annotations

import re
from urllib.parse import parse_qs, urlparse

import pytest
from conftest import ROOT
from sphinx.cmd.build import build_main

CONF = f"""
import sys
sys.path.insert(0, {str(ROOT / 'book' / '_ext')!r})
extensions = ["hublink"]
"""


@pytest.fixture
def project(tmp_path):
    src = tmp_path / "src"
    (src / "notebooks").mkdir(parents=True)
    (src / "conf.py").write_text(CONF)
    (src / "index.rst").write_text("Course\n======\n\n.. toctree::\n\n   notebooks/01_x\n")
    (src / "notebooks" / "01_x.rst").write_text("1 · A chapter\n=============\n\nText.\n")
    return src


def build(src, *settings: str) -> dict[str, str]:
    out = src.parent / "html"
    args = ["-q", "-E", "-b", "html", *[f"-D{s}" for s in settings], str(src), str(out)]
    assert build_main(args) == 0
    return {name: (out / f"{name}.html").read_text() for name in ("index", "notebooks/01_x")}


def hub_links(html: str) -> list[str]:
    return re.findall(r'<p class="mechbook-hub-link"><a class="reference external" href="([^"]+)"', html)


def test_no_hub_no_link(project):
    pages = build(project)
    assert not any("git-pull" in html for html in pages.values())


def test_a_chapter_links_to_its_notebook_through_nbgitpuller(project):
    pages = build(project, "hub_url=https://hub.example.org/", "hub_repo=https://git.example.org/t/mechlab.git",
                  "hub_branch=spring")
    assert hub_links(pages["index"]) == []
    (link,) = hub_links(pages["notebooks/01_x"])
    url = urlparse(link.replace("&amp;", "&"))
    assert (url.scheme, url.netloc, url.path) == ("https", "hub.example.org", "/hub/user-redirect/git-pull")
    assert parse_qs(url.query) == {"repo": ["https://git.example.org/t/mechlab.git"], "branch": ["spring"],
                                   "urlpath": ["lab/tree/mechlab/notebooks/01_x.rst"]}
