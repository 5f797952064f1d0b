"""The chapters' accessibility audit in JupyterLab fails when it should (issue 29).

The audit itself (axe-core on the page, every explorer's controls named and operated by the keyboard
alone) runs on every chapter inside test_lab.py's chapter test, one visit per chapter
(lab_a11y.audit_chapter). Here: a planted chapter with a figure that names nothing fails it, live and
as stored outputs of a notebook opened from disk, while a described figure passes.
"""

from __future__ import annotations

import contextlib

from lab_a11y import _READY_JS, audit_page, serious
from test_lab import _STATE_JS, lab  # noqa: F401  (the same lab)


def open_and_run(page, base: str, token: str, name: str) -> None:
    """Open notebook ``name`` of the lab in ``page`` (a fresh workspace) and run all its cells: no error."""
    page.goto(f"{base}/lab/tree/{name}?reset&token={token}", wait_until="domcontentloaded")
    page.wait_for_function(_READY_JS, timeout=90_000)
    page.evaluate("() => window.jupyterapp.commands.execute('notebook:run-all-cells')")
    state = page.wait_for_function(_STATE_JS, timeout=240_000, polling=500).json_value()
    assert not state["errors"], f"{name}: error output: {state['errors']}"


# a planted chapter: a figure that names nothing (no alt text can be made for it) and a described one
PLANTED_CELLS = [
    "import matplotlib.pyplot as plt\nimport mechlab.draw   # a kernel that imports it publishes alt texts\n"
    "fig, ax = plt.subplots(figsize=(3, 2))\nax.plot([0, 1], [0, 1]);",
    "fig, ax = plt.subplots(figsize=(3, 2))\nax.set(title='lift', xlabel='φ (deg)', ylabel='s (mm)')\n"
    "ax.plot([0, 90], [0, 5]);",
]
PLANTED_ALT = "Figure: lift, s (mm) against φ (deg), s (mm) from 0 to 5."

# every figure output's <img>: its alt (null: none), whether its output is trusted, how its source begins
_IMAGES_JS = """() => Array.from(
  window.jupyterapp.shell.currentWidget.node.querySelectorAll('.jp-OutputArea-output img'))
  .map(i => ({alt: i.getAttribute('alt'), trusted: !!i.closest('.jp-mod-trusted'), src: i.src.slice(0, 22)}))"""


def _planted_outputs() -> list[list[dict]]:
    """The outputs a kernel with mechlab's alt-text publisher stores for PLANTED_CELLS, made here."""
    import base64
    from types import SimpleNamespace

    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from IPython.core.formatters import DisplayFormatter
    from IPython.core.pylabtools import print_figure
    from matplotlib.figure import Figure

    from mechlab.draw.access import install_alt_text

    shell = SimpleNamespace(display_formatter=DisplayFormatter())
    shell.display_formatter.formatters["image/png"].for_type(Figure, lambda fig: print_figure(fig, "png"))
    install_alt_text(shell, html_copy=True)
    outputs, namespace = [], {}
    for source in PLANTED_CELLS:   # one namespace, as in a kernel
        exec(source, namespace)
        data, metadata = shell.display_formatter.format(namespace["fig"])
        data = {k: base64.b64encode(v).decode() if isinstance(v, bytes) else v for k, v in data.items()}
        outputs.append([{"output_type": "display_data", "data": data, "metadata": metadata}])
        plt.close(namespace["fig"])
    return outputs


def test_a_planted_figure_without_alt_fails_the_audit(browser, lab):  # noqa: F811
    """A chapter whose figure names nothing is failed by the chapter audit (axe "image-alt", critical),
    and a described figure is not: run live in the lab (trusted outputs), and as stored outputs in a
    notebook opened from disk (untrusted: JupyterLab's sanitizer keeps the <img>'s alt and data: source)."""
    import nbformat

    base, token, root = lab
    live = nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell(c) for c in PLANTED_CELLS])
    stored = nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell(c, outputs=[nbformat.from_dict(o) for o in out])
                                             for c, out in zip(PLANTED_CELLS, _planted_outputs(), strict=True)])
    live.metadata["kernelspec"] = stored.metadata["kernelspec"] = {"name": "python3", "display_name": "Python 3"}
    nbformat.write(live, root / "planted_live.ipynb")
    nbformat.write(stored, root / "planted_stored.ipynb")   # not signed: JupyterLab opens it untrusted
    page = browser.new_page(viewport={"width": 1400, "height": 1000})
    try:
        open_and_run(page, base, token, "planted_live.ipynb")
        live_images = page.evaluate(_IMAGES_JS)
        live_bad = serious(audit_page(page))
        page.evaluate("() => window.jupyterapp.shell.currentWidget.sessionContext.shutdown()")
        page.goto(f"{base}/lab/tree/planted_stored.ipynb?reset&token={token}", wait_until="domcontentloaded")
        page.wait_for_function("() => document.querySelectorAll('.jp-OutputArea-output img').length === 2",
                               timeout=90_000)
        stored_images = page.evaluate(_IMAGES_JS)
        stored_bad = serious(audit_page(page))
    finally:
        with contextlib.suppress(Exception):
            page.evaluate("() => window.jupyterapp.shell.currentWidget.sessionContext.shutdown()")
        page.close()
    for images, bad, trusted in ((live_images, live_bad, True), (stored_images, stored_bad, False)):
        assert [i["alt"] for i in images] == [None, PLANTED_ALT], images
        assert all(i["trusted"] == trusted and i["src"] == "data:image/png;base64," for i in images[1:]), images
        assert len(bad) == 1 and bad[0].startswith("image-alt (critical, 1×)"), bad
