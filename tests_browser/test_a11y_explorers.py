"""Every chapter in JupyterLab audited by axe-core, and its explorers driven by the keyboard alone (issue 29).

Each chapter is opened and run in the JupyterLab of test_lab.py (its `lab` fixture: `make lab`'s
arguments, a temporary working copy). Then, for every explorer the chapter shows (a widget output with a
status line, mechlab.widgets.access.status_line):

* every control in it (slider, button, drop-down, text box, check box, group) has a non-empty
  accessible name, read from Chromium's accessibility tree (CDP Accessibility.queryAXTree);
* the keyboard alone operates it: the focus starts on the output (where a screen reader's cursor
  lands), Tab moves it to the explorer's first control, which must be a named slider or drop-down
  with a visible focus indicator (an outline or a box shadow), the arrow keys change it, and the status
  line (role="status", aria-live="polite") must then read differently;
* a live plot (an ipympl canvas) is an image named by the figure's alternative text.

axe-core (the pin of .axe-deps, as test_a11y_book.py injects it) then audits the whole page, and a
violation of impact "serious" or "critical" in the chapter's own content (its text, its figures, its
explorers) fails the chapter. JupyterLab's own interface is left out by a list, LAB_OWN: each entry is a
rule, the JupyterLab element it flags and the upstream issue; nothing else is. Every violation, the
chapter's and the lab's, goes to book/_build/screenshots/a11y_lab.json (counts by impact).
"""

from __future__ import annotations

import contextlib
import json
import os

import pytest
from conftest import ROOT, block_remote
from test_lab import _READY_JS, _STATE_JS, NOTEBOOKS, SHOTS, lab  # noqa: F401  (the same lab)

AXE_JS = os.environ.get("AXE_JS") or str(ROOT / ".axe-deps" / "node_modules" / "axe-core" / "axe.min.js")
AXE_TAGS = ["wcag2a", "wcag2aa", "wcag21a", "wcag21aa", "best-practice"]
FAILING = {"serious", "critical"}
CHAPTERS = [p for p in NOTEBOOKS if os.environ.get("MECHLAB_A11Y_CHAPTERS", "") in p.stem]
FOUND: dict[str, dict] = {}
# JupyterLab's own interface: (axe rule, the element it flags (a CSS selector the node or an ancestor
# matches), why it is the lab's, with its upstream issue). Found on every chapter's page (JupyterLab 4).
LAB_OWN = [
    ("aria-allowed-attr", "jp-button.jp-ToolbarButtonComponent, jp-button.jp-DebuggerBugButton",
     "toolbar buttons carry aria-pressed without a toggle role: jupyterlab/jupyterlab#16891"),
    ("aria-input-field-name", ".jp-InputArea-editor .cm-content",
     "a cell's code editor (CodeMirror) has no accessible name: jupyterlab/jupyterlab#4878, #10347"),
    ("aria-required-children", ".jp-WindowedPanel-viewport",
     "the notebook's cell list has no list items' roles: jupyterlab/jupyterlab#14804"),
    ("button-name", ".jp-collapseHeadingButton",
     "a Markdown heading's collapse button has no name (JupyterLab's cells package makes it bare; "
     "no upstream issue found: to be filed)"),
    ("region", ".jp-skiplink-wrapper", "the skip link sits outside a landmark: jupyterlab/jupyterlab#9688"),
]
# the roles a student operates; each must have a name
CONTROL_ROLES = ("slider", "button", "combobox", "textbox", "checkbox", "spinbutton", "listbox", "group")

# marks every explorer output of the open notebook (a widget output holding a status line) and returns
# how many; the live-region script must have run (it gives the status line its role)
_MARK_JS = """() => {
  const root = window.jupyterapp.shell.currentWidget.node;
  const outputs = Array.from(root.querySelectorAll('.jp-OutputArea-output'))
    .filter(o => o.querySelector('.mechlab-status[role=status]') && o.querySelector('.noUi-handle, select'));
  outputs.forEach((o, k) => o.setAttribute('data-a11ytest', String(k)));
  return outputs.length;
}"""

# starts the keyboard's walk on explorer k's output, as a screen reader lands on it
_START_JS = """k => {
  const o = document.querySelector(`[data-a11ytest='${k}']`);
  o.setAttribute('tabindex', '-1');
  o.focus();
  return document.activeElement === o;
}"""

# the focused element, if it is a control inside explorer k: its role, its name's source and the status
_FOCUS_JS = """k => {
  const o = document.querySelector(`[data-a11ytest='${k}']`);
  const a = document.activeElement;
  if (!o.contains(a) || a === o) return null;
  const role = a.getAttribute('role') || a.tagName.toLowerCase();
  const ref = a.getAttribute('aria-labelledby');
  const label = ref ? (document.getElementById(ref) || {}).textContent
                    : (a.labels && a.labels[0] ? a.labels[0].textContent : a.getAttribute('aria-label'));
  // the focus indicator: the outline and box shadow the focus adds (focused, then blurred, then focused again)
  const look = () => { const s = getComputedStyle(a);
                       return [s.outlineStyle === 'none' ? 0 : parseFloat(s.outlineWidth), s.boxShadow]; };
  const [outline, shadow] = look();
  a.blur();
  const [outlineOff, shadowOff] = look();
  a.focus();
  const ring = document.activeElement === a && (outline > outlineOff || (shadow !== 'none' && shadow !== shadowOff));
  return {role, label: (label || '').trim(), value: a.getAttribute('aria-valuenow') || a.value || '',
          ring, outline, shadow};
}"""

# every live plot (ipympl canvas) of explorer k: its role and accessible name (the figure's alt text)
_CANVAS_JS = """k => Array.from(document.querySelectorAll(`[data-a11ytest='${k}'] .jupyter-matplotlib-canvas-div`))
  .map(c => ({role: c.getAttribute('role'), label: (c.getAttribute('aria-label') || '').trim()}))"""

_STATUS_JS = "k => document.querySelector(`[data-a11ytest='${k}'] .mechlab-status[role=status]`).textContent.trim()"

# axe on the whole page; each violation's nodes split into the chapter's and JupyterLab's own (LAB_OWN)
_AXE_PAGE_JS = """async ([tags, own]) => {
  const result = await axe.run(document, {runOnly: {type: 'tag', values: tags}, resultTypes: ['violations']});
  const element = target => {   // axe's target: selectors, one per shadow root on the way
    let node = document;
    for (const sel of target) node = node && (node.shadowRoot || node).querySelector(sel);
    return node;
  };
  const text = n => n.target.join(' ') + ' :: ' + (n.failureSummary || '').split('\\n').slice(1).join(' ');
  return result.violations.map(v => {
    const lab = n => { const e = element(n.target);
                       return !!e && own.some(([rule, sel]) => rule === v.id && e.closest(sel)); };
    return {id: v.id, impact: v.impact, help: v.help,
            nodes: v.nodes.filter(n => !lab(n)).map(text), lab: v.nodes.filter(lab).map(text)};
  }).filter(v => v.nodes.length || v.lab.length);
}"""


def audit_page(page) -> list[dict]:
    """axe-core's violations on the page: id, impact, help, the chapter's nodes and JupyterLab's (LAB_OWN)."""
    if not os.path.isfile(AXE_JS):
        pytest.fail(f"axe-core not found at {AXE_JS}: run `make axe-deps` (make test-browser does)")
    page.add_script_tag(path=AXE_JS)
    return page.evaluate(_AXE_PAGE_JS, [AXE_TAGS, [[rule, sel] for rule, sel, _ in LAB_OWN]])


def serious(violations: list[dict]) -> list[str]:
    """The chapter's own serious or critical violations, one line each."""
    return [f"{v['id']} ({v['impact']}, {len(v['nodes'])}×): {v['help']}; e.g. {v['nodes'][0]}"
            for v in violations if v["impact"] in FAILING and v["nodes"]]


def record(name: str, report: dict) -> None:
    """Keep ``report`` and write every chapter's so far, with counts by impact, to a11y_lab.json."""
    FOUND[name] = report
    counts = {where: {impact: sum(len(v[where]) for r in FOUND.values() for v in r["axe"] if v["impact"] == impact)
                      for impact in ("critical", "serious", "moderate", "minor")}
              for where in ("nodes", "lab")}
    SHOTS.mkdir(parents=True, exist_ok=True)
    (SHOTS / "a11y_lab.json").write_text(json.dumps(
        {"chapters": len(FOUND), "nodes by impact, the chapters' content": counts["nodes"],
         "nodes by impact, JupyterLab's own (LAB_OWN)": counts["lab"], "found": FOUND}, indent=1, ensure_ascii=False))



def unnamed_controls(page, k: int) -> list[str]:
    """The controls of explorer ``k`` without an accessible name, as Chromium computes it (role: HTML)."""
    cdp = page.context.new_cdp_session(page)
    try:
        root = cdp.send("Runtime.evaluate", {"expression": f"document.querySelector(\"[data-a11ytest='{k}']\")"})
        found = []
        for role in CONTROL_ROLES:
            nodes = cdp.send("Accessibility.queryAXTree", {"objectId": root["result"]["objectId"], "role": role})
            for node in nodes["nodes"]:
                if node.get("ignored"):
                    continue
                if not ((node.get("name") or {}).get("value") or "").strip():
                    html = cdp.send("DOM.getOuterHTML", {"backendNodeId": node["backendDOMNodeId"]})["outerHTML"]
                    found.append(f"{role}: {html[:160]}")
        return found
    finally:
        cdp.detach()


def operate_by_keyboard(page, k: int) -> dict:
    """Tab from explorer ``k``'s output to its first control, change it with the arrow keys until the
    status line reads differently; what was focused, and the status before and after."""
    assert page.evaluate(_START_JS, k), f"explorer {k}: its output cannot take the focus"
    focused = None
    for _ in range(12):
        page.keyboard.press("Tab")
        focused = page.evaluate(_FOCUS_JS, k)
        if focused:
            break
    assert focused, f"explorer {k}: Tab does not reach a control"
    before = page.evaluate(_STATUS_JS, k)
    for key in ["ArrowRight"] * 3 + ["ArrowLeft"] * 6:   # back past the start if the first moves change nothing
        page.keyboard.press(key)
        try:
            page.wait_for_function(f"([k, s]) => ({_STATUS_JS})(k) !== s", arg=[k, before], timeout=8_000)
            break
        except Exception:   # playwright's TimeoutError: try the next key
            continue
    page.wait_for_function(_READY_JS, timeout=60_000)
    return {"focused": focused, "before": before, "after": page.evaluate(_STATUS_JS, k)}


def open_and_run(page, base: str, token: str, name: str) -> None:
    """Open notebook ``name`` of the lab in ``page`` (a fresh workspace) and run all its cells: no error."""
    page.goto(f"{base}/lab/tree/{name}?reset&token={token}", wait_until="domcontentloaded")
    page.wait_for_function(_READY_JS, timeout=90_000)
    page.evaluate("() => window.jupyterapp.commands.execute('notebook:run-all-cells')")
    state = page.wait_for_function(_STATE_JS, timeout=240_000, polling=500).json_value()
    assert not state["errors"], f"{name}: error output: {state['errors']}"


@pytest.mark.parametrize("path", CHAPTERS, ids=lambda p: p.stem)
def test_chapter_audited_and_explorers_by_keyboard(browser, lab, path):  # noqa: F811
    base, token, _ = lab
    page = browser.new_page(viewport={"width": 1400, "height": 1000})
    remote = block_remote(page)
    try:
        open_and_run(page, base, token, path.name)
        count = page.wait_for_function(_MARK_JS, timeout=30_000).json_value()
        page.wait_for_timeout(500)   # the live-region script names the last drawn controls and canvases
        report = {"explorers": count, "operated": [], "axe": audit_page(page)}
        record(path.stem, report)
        bad = serious(report["axe"])
        assert not bad, f"{path.name}: serious or critical axe violations in the chapter:\n" + "\n".join(bad)
        for k in range(count):
            unnamed = unnamed_controls(page, k)
            assert not unnamed, f"{path.name}, explorer {k}: controls without an accessible name: {unnamed}"
            canvases = page.evaluate(_CANVAS_JS, k)
            assert all(c["role"] == "img" and c["label"] for c in canvases), f"{path.name}, explorer {k}: {canvases}"
            done = operate_by_keyboard(page, k)
            done["canvases"] = canvases
            report["operated"].append(done)
            record(path.stem, report)
            assert done["focused"]["role"] in ("slider", "select"), f"{path.name}, explorer {k}: {done}"
            assert done["focused"]["label"], f"{path.name}, explorer {k}: the focused control has no label: {done}"
            assert done["focused"]["ring"], f"{path.name}, explorer {k}: no visible focus indicator: {done}"
            assert done["after"] != done["before"], f"{path.name}, explorer {k}: the status did not change: {done}"
        assert not remote, f"{path.name}: requests to another host: {remote}"
    finally:
        with contextlib.suppress(Exception):
            page.evaluate("() => window.jupyterapp.shell.currentWidget.sessionContext.shutdown()")
        page.close()


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
    block_remote(page)
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
