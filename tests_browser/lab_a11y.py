"""Every chapter in JupyterLab audited by axe-core, and its explorers driven by the keyboard alone (issue 29).

test_lab.py's chapter test calls :func:`audit_chapter` once the chapter has run (one visit per chapter). For
every explorer the chapter shows (a widget output with a status line, mechlab.widgets.access.status_line):

* every control in it (slider, button, drop-down, text box, check box, group) has a non-empty
  accessible name, read from Chromium's accessibility tree (CDP Accessibility.queryAXTree);
* the keyboard alone operates it: the focus starts on the output (where a screen reader's cursor
  lands), Tab moves it to the explorer's first control, which must be a named slider or drop-down
  with a visible focus indicator (an outline or a box shadow), the arrow keys change it, and the status
  line (role="status", aria-live="polite") must then read differently;
* a live plot (an ipympl canvas) is an image named by the figure's alternative text.

axe-core (the pin of .axe-deps, as test_a11y_book.py injects it) audits the whole page first, and a
violation of impact "serious" or "critical" in the chapter's own content (its text, its figures, its
explorers) fails the chapter. JupyterLab's own interface is left out by a list, LAB_OWN: each entry is a
rule, the JupyterLab element it flags and the upstream issue; nothing else is. Every violation, the
chapter's and the lab's, goes to book/_build/screenshots/a11y_lab.json (counts by impact).
"""

from __future__ import annotations

import json
import os

import pytest
from conftest import ROOT

SHOTS = ROOT / "book" / "_build" / "screenshots"
# the open notebook is ready: its model loaded and its kernel idle
_READY_JS = """() => {
  const w = window.jupyterapp && window.jupyterapp.shell.currentWidget;
  const k = w && w.sessionContext && w.sessionContext.session && w.sessionContext.session.kernel;
  return !!(w && w.content && w.content.model && w.context.isReady && k && k.status === 'idle');
}"""

AXE_JS = os.environ.get("AXE_JS") or str(ROOT / ".axe-deps" / "node_modules" / "axe-core" / "axe.min.js")
AXE_TAGS = ["wcag2a", "wcag2aa", "wcag21a", "wcag21aa", "best-practice"]
FAILING = {"serious", "critical"}
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


def audit_chapter(page, name: str) -> None:
    """Audit chapter ``name`` (its stem), already open and run in ``page``, with axe, then name and operate
    each of its explorers by the keyboard; an assertion names the first failure."""
    count = page.wait_for_function(_MARK_JS, timeout=30_000).json_value()
    page.wait_for_timeout(500)   # the live-region script names the last drawn controls and canvases
    report = {"explorers": count, "operated": [], "axe": audit_page(page)}
    record(name, report)
    bad = serious(report["axe"])
    assert not bad, f"{name}: serious or critical axe violations in the chapter:\n" + "\n".join(bad)
    for k in range(count):
        unnamed = unnamed_controls(page, k)
        assert not unnamed, f"{name}, explorer {k}: controls without an accessible name: {unnamed}"
        canvases = page.evaluate(_CANVAS_JS, k)
        assert all(c["role"] == "img" and c["label"] for c in canvases), f"{name}, explorer {k}: {canvases}"
        done = operate_by_keyboard(page, k)
        done["canvases"] = canvases
        report["operated"].append(done)
        record(name, report)
        assert done["focused"]["role"] in ("slider", "select"), f"{name}, explorer {k}: {done}"
        assert done["focused"]["label"], f"{name}, explorer {k}: the focused control has no label: {done}"
        assert done["focused"]["ring"], f"{name}, explorer {k}: no visible focus indicator: {done}"
        assert done["after"] != done["before"], f"{name}, explorer {k}: the status did not change: {done}"
