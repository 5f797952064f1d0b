"""The API reference: docstrings are plain text with formulas, read as reStructuredText.

The library's docstrings write absolute values as ``|ψ'|``; reStructuredText would read
``|…|`` as a substitution, so every bar is escaped before autodoc parses a docstring.
"""

from __future__ import annotations


def _escape_bars(app, what, name, obj, options, lines):
    lines[:] = [line.replace("|", r"\|") for line in lines]


def setup(app):
    app.connect("autodoc-process-docstring", _escape_bars)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
