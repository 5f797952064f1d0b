"""The book's build helpers (book/_ext), without a browser."""

from __future__ import annotations

import re
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import nbformat
import pytest
from conftest import ROOT
from matplotlib.animation import FuncAnimation

sys.path.insert(0, str(ROOT / "book" / "_ext"))
import errata_page
import mechbook

from mechlab.course.errata import SOURCES, Erratum


def _jshtml() -> str:
    fig, ax = plt.subplots()
    (line,) = ax.plot([0, 1], [0, 1])
    anim = FuncAnimation(fig, lambda i: line.set_ydata([0, i]) or (line,), frames=3)
    html = anim.to_jshtml()
    plt.close(fig)
    return html


def test_animation_controls_become_local():
    html = _jshtml()
    assert "font-awesome" in html and 'class="fa fa-play"' in html  # what matplotlib emits
    out = mechbook.local_animation_controls(html)
    assert "font-awesome" not in out and "fa fa-" not in out
    assert not mechbook.remote_fetches(out)
    icons = set(re.findall(r'class="mechlab-icon mechlab-([a-z-]+)"', out))
    assert icons == {"minus", "fast-backward", "step-backward", "play-backwards", "pause", "play",
                     "step-forward", "fast-forward", "plus"}
    for name in icons:  # every icon has a glyph in the inline style
        assert re.search(rf"\.mechlab-{name}::before\{{content:\"[^\"]+\"", out), name
    assert mechbook.local_animation_controls(out) == out  # idempotent


@pytest.mark.parametrize("text, urls", [
    ('<script src="https://cdn.example.org/x.js"></script>', ["https://cdn.example.org/x.js"]),
    ('<link rel="stylesheet" href="//fonts.example.com/a.css">', ["//fonts.example.com/a.css"]),
    ("<img alt=x src='http://example.org/i.png'>", ["http://example.org/i.png"]),
    ('<style>@import "https://x.org/y.css"; b { background: url(http://x.org/z.png) }</style>',
     ["https://x.org/y.css", "http://x.org/z.png"]),
    ('<a href="https://example.org/">a link is not a fetch</a>', []),
    ('<link rel="canonical" href="https://example.org/">', []),
    ('<script src="_static/x.js"></script><img src="data:image/png;base64,AAAA">', []),
])
def test_remote_fetches(text, urls):
    assert mechbook.remote_fetches(text) == urls


def test_remote_fetches_in_css():
    assert mechbook.remote_fetches("a { src: url('https://f.org/f.woff2') } b { src: url(f.woff) }",
                                   css=True) == ["https://f.org/f.woff2"]


def _notebook(folder: Path, name: str, with_errata: bool = True) -> Path:
    nb = nbformat.v4.new_notebook()
    nb.cells = [nbformat.v4.new_markdown_cell("# 7 · A chapter\n\ntext"),
                nbformat.v4.new_code_cell("import numpy as np\nfrom mechlab import errata\nx = 1"),
                nbformat.v4.new_markdown_cell("## Errata"),
                nbformat.v4.new_code_cell("show(errata.table(notebook='x'))" if with_errata else "y = 2"),
                nbformat.v4.new_code_cell("for e in errata.collect(): e.check()")]
    path = folder / name
    nbformat.write(nb, path)
    return path


def test_demo_cell_and_title(tmp_path):
    path = _notebook(tmp_path, "07_chapter.ipynb")
    assert errata_page.demo_cell(path) == 3
    assert errata_page.notebook_title(path) == "7 · A chapter"
    # without a table, the first cell that uses errata beyond importing it
    assert errata_page.demo_cell(_notebook(tmp_path, "08_other.ipynb", with_errata=False)) == 4


def test_errata_markdown(tmp_path):
    _notebook(tmp_path, "07_chapter.ipynb")
    calls = []

    def check():
        calls.append(1)
        return "printed gives 1.25, correct gives 1.5"

    e = Erratum(source="000", where="formula (21)", printed="$a | b$", correct="$c$\nsplit", check=check,
                notebook="07_chapter.ipynb", kind="remark")
    f = Erratum(source="004", where="Table 1", printed="2.51", correct="2.536", check=lambda: "z = 3: 2.536",
                notebook="07_chapter.ipynb", kind="remark")
    md = errata_page.errata_markdown([f, e], notebooks_dir=tmp_path)
    assert calls == [1]  # the evidence is recomputed at build time
    assert md.startswith(f"0 printed mistakes, 2 remarks and 0 unreadable passages in 2 of the {len(SOURCES)} "
                         f"source texts.")
    lines = md.splitlines()
    # grouped by source in key order, each headed by its work (no key) linked to the References page
    head0 = lines.index(f'**<a href="references.html#seed-000">{SOURCES["000"]}</a>**')
    head4 = lines.index(f'**<a href="references.html#seed-004">{SOURCES["004"]}</a>**')
    assert head0 < lines.index("  - evidence: printed gives 1.25, correct gives 1.5") < head4
    assert ('- **formula (21)** — shown in <a href="notebooks/07_chapter.html#cell-3">7 · A chapter</a>'
            in lines)
    assert "  - printed: $a | b$" in lines and "  - correct: $c$ split" in lines
    assert lines.index("  - evidence: z = 3: 2.536") > head4


def test_errata_markdown_fails_loudly(tmp_path):
    _notebook(tmp_path, "07_chapter.ipynb")

    def wrong():
        raise AssertionError("the printed value is right after all")

    with pytest.raises(AssertionError, match="printed value is right"):
        errata_page.errata_markdown([Erratum("000", "eq. 1", "a", "b", wrong, "07_chapter.ipynb")],
                                    notebooks_dir=tmp_path)
    with pytest.raises(ValueError, match="not in"):
        errata_page.errata_markdown([Erratum("000", "eq. 1", "a", "b", lambda: "ok", "99_missing.ipynb", "remark")],
                                    notebooks_dir=tmp_path)
    with pytest.raises(ValueError, match="source '123'"):
        errata_page.errata_markdown([Erratum("123", "eq. 1", "a", "b", lambda: "ok", "07_chapter.ipynb", "remark")],
                                    notebooks_dir=tmp_path)
    assert errata_page.errata_markdown([], notebooks_dir=tmp_path).startswith("No errata")


def test_every_collected_erratum_links_to_an_existing_chapter():
    md = errata_page.errata_markdown()
    for href in re.findall(r'href="(notebooks/[^"#]+)', md):
        assert (ROOT / href.replace(".html", ".ipynb")).is_file(), href


def test_kernel_startup_shows_widgets_statically(tmp_path, monkeypatch):
    """In a kernel started with the book's profile, a widget's HTML is its last plot plus a note."""
    from ipc_kernels import IPCKernelManager
    from nbclient import NotebookClient

    startup = tmp_path / "ipython" / "profile_default" / "startup"
    startup.mkdir(parents=True)
    (startup / "00-mechbook.py").write_text((ROOT / "book" / "_ext" / "kernel_startup.py").read_text())
    monkeypatch.setenv("IPYTHONDIR", str(tmp_path / "ipython"))
    nb = nbformat.v4.new_notebook(metadata={"kernelspec": {"name": "python3", "display_name": "Python 3",
                                                           "language": "python"}})
    nb.cells = [nbformat.v4.new_code_cell(
        "%matplotlib widget\n"
        "import ipywidgets as W, matplotlib.pyplot as plt\n"
        "import matplotlib\n"
        "backend = matplotlib.get_backend()\n"
        "out = W.Output()\n"
        "fig, ax = plt.subplots(figsize=(2, 2))\n"
        "with out:\n"
        "    ax.plot([0, 1], [1, 0]); plt.show()\n"
        "W.VBox([W.FloatSlider(value=2.5, description='length'), out])"),
        nbformat.v4.new_code_cell("W.IntSlider(description='alone')"),
        nbformat.v4.new_code_cell("print(backend)"),
        nbformat.v4.new_code_cell("from mechlab.widgets import fourbar_explorer\n"
                                  "fourbar_explorer(question='when does the crank stop turning?')")]
    # over Unix sockets, its replies waited for in slices, like every notebook the project executes
    NotebookClient(nb, timeout=120, kernel_name="python3", kernel_manager_class=IPCKernelManager,
                   resources={"metadata": {"path": str(tmp_path)}}).execute()
    box = next(o for o in nb.cells[0].outputs if o.get("output_type") == "execute_result")["data"]
    assert "application/vnd.jupyter.widget-view+json" in box  # the live view is still there for JupyterLab
    html = box["text/html"]
    assert html.count('<img src="data:image/png;base64,') == 1
    assert "length = 2.5" in html and "make lab" in html
    alone = next(o for o in nb.cells[1].outputs if o.get("output_type") == "execute_result")["data"]["text/html"]
    assert "<img" not in alone and "make lab" in alone
    assert "inline" in nb.cells[2].outputs[0]["text"]  # %matplotlib widget fell back to inline
    # a mechlab explorer: drawn statically, its question and status line kept, no "play = 0"
    explorer = next(o for o in nb.cells[3].outputs if o.get("output_type") == "display_data")["data"]["text/html"]
    assert explorer.count('<img src="data:image/png;base64,') == 1
    assert "<b>Investigate:</b> when does the crank stop turning?" in explorer
    assert "transmission angle μ: 60.0° … 112.9°" in explorer
    assert "crank OA = 1.00" in explorer and "slots" not in explorer and "play" not in explorer


def test_check_cells_are_folded_in_the_book():
    nb = nbformat.v4.new_notebook()
    nb.cells = [nbformat.v4.new_markdown_cell("# 1 · Chapter"), nbformat.v4.new_code_cell("x = 1"),
                nbformat.v4.new_code_cell("assert x == 1", metadata={"tags": ["check"],
                                                                     "jupyter": {"source_hidden": True}}),
                nbformat.v4.new_code_cell("y = 2", metadata={"tags": ["hide-output"]})]
    text = nbformat.writes(nb)
    folded = nbformat.reads(mechbook.fold_check_cells(text), as_version=4)
    assert [c.metadata.get("tags", []) for c in folded.cells] == [[], [], ["check", "hide-input"], ["hide-output"]]
    assert [c.source for c in folded.cells] == [c.source for c in nb.cells]   # nothing else changes
    assert mechbook.fold_check_cells(mechbook.fold_check_cells(text)) == mechbook.fold_check_cells(text)
    plain = nbformat.writes(nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell("z = 3")]))
    assert mechbook.fold_check_cells(plain) == plain


def test_inputs_hash_follows_the_library(tmp_path):
    (tmp_path / "mechlab" / "sub").mkdir(parents=True)
    (tmp_path / "book" / "_ext").mkdir(parents=True)
    (tmp_path / "mechlab" / "sub" / "m.py").write_text("x = 1\n")
    (tmp_path / "environment.txt").write_text("numpy==2\n")
    first = mechbook.inputs_hash(tmp_path)
    assert mechbook.inputs_hash(tmp_path) == first
    (tmp_path / "mechlab" / "sub" / "__pycache__").mkdir()
    (tmp_path / "mechlab" / "sub" / "__pycache__" / "m.py").write_text("compiled")
    assert mechbook.inputs_hash(tmp_path) == first  # byte-code does not count
    (tmp_path / "mechlab" / "sub" / "m.py").write_text("x = 2\n")
    assert mechbook.inputs_hash(tmp_path) != first
    second = mechbook.inputs_hash(tmp_path)
    (tmp_path / "book" / "_ext" / "kernel_startup.py").write_text("# changed\n")
    assert mechbook.inputs_hash(tmp_path) != second
