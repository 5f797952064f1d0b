"""An "open on the hub" link under the title of each chapter page, through nbgitpuller.

Set in ONE place, book/conf.py: ``hub_url`` (the lecturer's JupyterHub), ``hub_repo`` (the
course's git URL) and ``hub_branch``. With either empty (the default) no link is made and
the book stays fully offline.
"""

from __future__ import annotations

from pathlib import PurePosixPath
from urllib.parse import urlencode

from docutils import nodes


def nbgitpuller_link(hub: str, repo: str, branch: str, path: str) -> str:
    """The link that clones (or updates, by nbgitpuller's merge rules) `repo` into the student's
    home on `hub` and opens `path` (relative to the repository) in JupyterLab."""
    folder = PurePosixPath(repo.rstrip("/")).name.removesuffix(".git")
    query = urlencode({"repo": repo, "branch": branch, "urlpath": f"lab/tree/{folder}/{path}"})
    return f"{hub.rstrip('/')}/hub/user-redirect/git-pull?{query}"


def _on_doctree_resolved(app, doctree, docname):
    cfg = app.config
    if not (cfg.hub_url and cfg.hub_repo) or not docname.startswith("notebooks/"):
        return
    source = PurePosixPath(app.env.doc2path(docname, False))
    link = nbgitpuller_link(cfg.hub_url, cfg.hub_repo, cfg.hub_branch, source.as_posix())
    section = next(iter(doctree.findall(nodes.section)), None)
    if section is None:
        return
    para = nodes.paragraph(classes=["mechbook-hub-link"])
    para += nodes.reference("", "Open this chapter on the course's JupyterHub", refuri=link)
    section.insert(1, para)


def setup(app):
    app.add_config_value("hub_url", "", "html", str)
    app.add_config_value("hub_repo", "", "html", str)
    app.add_config_value("hub_branch", "main", "html", str)
    app.connect("doctree-resolved", _on_doctree_resolved)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
