"""Sphinx configuration of the course book (Jupyter Book 1.x stack, driven by sphinx-build).

The Jupyter Book 1 components are used directly — myst-nb (executes the notebooks),
sphinx-book-theme, sphinx-external-toc (``_toc.yml`` in jb-book format) — so that the
build loads nothing from another host: math comes from ``sphinx-mathjax-offline``,
and the extensions that fetch from a CDN at reading time (thebe, comments, the
ipywidgets html-manager) are left out. Build with ``make book`` (or
``sphinx-build -W --keep-going -b html book book/_build/html``).

The chapters are the notebooks of ``notebooks/`` itself: ``book/notebooks`` is a
symbolic link, and ``_toc.yml`` globs ``notebooks/*`` so a new chapter appears in the
book without any edit here.
"""

from __future__ import annotations

import os
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
BUILD = HERE / "_build"
sys.path.insert(0, str(HERE / "_ext"))
sys.path.insert(0, str(HERE.parent / "tools"))
import ipc_kernels  # noqa: E402

# myst-nb's kernels over unique Unix sockets with sliced waits: no TCP port race, no missed reply
ipc_kernels.install()

# Every kernel that executes a page starts with _ext/kernel_startup.py (static widgets,
# inline figures): point IPython at a profile inside the git-ignored build folder.
_ipython_dir = BUILD / "ipython"
(_ipython_dir / "profile_default" / "startup").mkdir(parents=True, exist_ok=True)
(_ipython_dir / "profile_default" / "startup" / "00-mechbook.py").write_text(
    (HERE / "_ext" / "kernel_startup.py").read_text())
os.environ["IPYTHONDIR"] = str(_ipython_dir)
os.environ["MPLBACKEND"] = "module://matplotlib_inline.backend_inline"

project = "mechlab: planar mechanisms with dwells and intermittent motion"
author = "the mechlab course team"
copyright = "2026, the mechlab course team"
language = "en"

extensions = [
    "myst_nb",
    "sphinx_external_toc",
    "sphinx_design",
    "sphinx_copybutton",
    "sphinx-mathjax-offline",  # MathJax 3 served from _static/mathjax, not from a CDN
    "mechbook",  # _ext/mechbook.py: cell anchors, offline checks, animation controls
    "alttext",  # _ext/alttext.py: a figure's alt text from its output metadata; a page's image without one fails
    "sphinx.ext.autodoc",
    "sphinx.ext.autosummary",
    "sphinx.ext.napoleon",  # numpydoc sections in docstrings
    "apiref",  # _ext/apiref.py: docstrings read as reStructuredText
    "hublink",  # _ext/hublink.py: an "open on the hub" link per chapter, only when hub_url is set
]

# Teaching on a JupyterHub (book/teaching.md): the hub's address gives every chapter page a link
# that opens it there through nbgitpuller. Empty: no link, the book stays fully offline.
hub_url = ""
hub_repo = ""  # the course's git URL as students clone it
hub_branch = "main"

external_toc_path = "_toc.yml"
external_toc_exclude_missing = False

exclude_patterns = ["_build", "**.ipynb_checkpoints", "README.md", "Thumbs.db", ".DS_Store"]
# autosummary's generated module pages carry their own toctree of submodules
suppress_warnings: list[str] = ["etoc.toctree"]

# --- MyST and notebook execution ------------------------------------------------------
myst_enable_extensions = ["dollarmath", "amsmath", "colon_fence", "deflist", "html_image",
                          "substitution"]
myst_heading_anchors = 3
myst_dmath_double_inline = True

nb_execution_mode = "cache"  # executed at build time; the cache lives in the git-ignored _build
nb_execution_cache_path = str(BUILD / ".jupyter_cache")
# a cell running longer (an endless loop, a stall) is stopped: the build's warning names the notebook,
# shows the cell's source and says "A cell timed out ... after 60 seconds" (course.py reads the same variable)
nb_execution_timeout = int(os.environ.get("MECHLAB_CELL_TIMEOUT", "60"))
# a failing cell (an assertion of a chapter) is a warning, so `-W --keep-going` reports every
# failing notebook of the build and then fails it
nb_execution_raise_on_error = False
nb_execution_show_tb = True
nb_execution_excludepatterns: list[str] = []
nb_merge_streams = True
nb_render_markdown_format = "myst"  # math and inline HTML in Markdown outputs (the Errata table)
# A static page has no kernel: widgets are rendered by _ext/kernel_startup.py as the figure
# for their default values plus a note; the widget view itself (it would need the
# html-manager from a CDN) is never chosen, and no widget JavaScript is loaded.
nb_ipywidgets_js: dict = {}
nb_mime_priority_overrides = [("html", "application/vnd.jupyter.widget-view+json", None),
                              ("html", "application/vnd.jupyter.widget-state+json", None)]

# --- HTML -----------------------------------------------------------------------------
html_theme = "sphinx_book_theme"
html_title = "mechlab"
html_static_path = ["_static"]
html_css_files = ["mechbook.css"]
html_js_files = ["a11y.js"]  # fixes of the theme's markup that axe-core found (tests_browser/test_a11y_book.py)
html_last_updated_fmt = ""
html_theme_options = {
    "home_page_in_toc": True,
    "show_navbar_depth": 1,
    "use_download_button": True,
    "use_fullscreen_button": False,
    "use_repository_button": False,
    "use_issues_button": False,
    "use_edit_page_button": False,
    "navigation_with_keys": False,
    "show_toc_level": 2,
}
html_sourcelink_suffix = ""
html_copy_source = True
# pydata-sphinx-theme logs a console error when the colour mode is left empty
html_context = {"default_mode": "light"}
html_favicon = "_static/favicon.svg"  # a local icon: the browser would ask for /favicon.ico (a 404)

# --- API reference ----------------------------------------------------------------------
# autosummary writes one stub page per module into _api (git-ignored) at every build
autosummary_generate = True
autosummary_imported_members = False
# a package page documents what its modules define, not its re-exports (no duplicates)
autodoc_default_options = {"members": True, "show-inheritance": True, "ignore-module-all": True}
autodoc_typehints = "none"
autodoc_member_order = "bysource"
napoleon_google_docstring = False
napoleon_numpy_docstring = True
