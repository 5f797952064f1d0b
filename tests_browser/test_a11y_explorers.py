"""Every chapter's explorers driven by the keyboard alone in JupyterLab, and audited (issue 29).

Each chapter is opened and run in the JupyterLab of test_lab.py (its `lab` fixture: `make lab`'s
arguments, a temporary working copy). Then, for every explorer the chapter shows (a widget output with a
status line, mechlab.widgets.access.status_line):

* every control in it (slider, button, drop-down, text box, check box, group) has a non-empty
  accessible name, read from Chromium's accessibility tree (CDP Accessibility.queryAXTree);
* the keyboard alone operates it: the focus starts on the output (where a screen reader's cursor
  lands), Tab moves it to the explorer's first control, which must be a named slider or drop-down,
  the arrow keys change it, and the status line (role="status", aria-live="polite") must then read
  differently;

and axe-core (the pin of .axe-deps, as test_a11y_book.py injects it) audits the explorers: a
violation of impact "serious" or "critical" there fails the chapter. It audits every output area of
the notebook too, for the record (book/_build/screenshots/a11y_lab.json, counts by impact): there
JupyterLab shows a static figure as an <img> without alt whatever the output's metadata says (its
renderImage reads no alt; jupyter/enhancement-proposals#120), a gap of the lab, not of the course.
JupyterLab's own interface is left out (it is not the course's content).
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
  return {role, label: (label || '').trim(), value: a.getAttribute('aria-valuenow') || a.value || ''};
}"""

_STATUS_JS = "k => document.querySelector(`[data-a11ytest='${k}'] .mechlab-status[role=status]`).textContent.trim()"

_AXE_RUN_JS = """async ([selector, tags]) => {
  const result = await axe.run({include: [[selector]]},
                               {runOnly: {type: 'tag', values: tags}, resultTypes: ['violations']});
  return result.violations.map(v => ({id: v.id, impact: v.impact, help: v.help,
    nodes: v.nodes.map(n => n.target.join(' ') + ' :: ' + (n.failureSummary || '').split('\\n').slice(1).join(' '))}));
}"""


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


@pytest.mark.parametrize("path", CHAPTERS, ids=lambda p: p.stem)
def test_explorers_by_keyboard_with_named_controls(browser, lab, path):  # noqa: F811
    base, token, _ = lab
    if not os.path.isfile(AXE_JS):
        pytest.fail(f"axe-core not found at {AXE_JS}: run `make axe-deps` (make test-browser does)")
    page = browser.new_page(viewport={"width": 1400, "height": 1000})
    remote = block_remote(page)
    try:
        page.goto(f"{base}/lab/tree/{path.name}?reset&token={token}", wait_until="domcontentloaded")
        page.wait_for_function(_READY_JS, timeout=90_000)
        page.evaluate("() => window.jupyterapp.commands.execute('notebook:run-all-cells')")
        state = page.wait_for_function(_STATE_JS, timeout=240_000, polling=500).json_value()
        assert not state["errors"], f"{path.name}: error output: {state['errors']}"
        count = page.wait_for_function(_MARK_JS, timeout=30_000).json_value()
        report = {"explorers": count, "operated": []}
        for k in range(count):
            unnamed = unnamed_controls(page, k)
            assert not unnamed, f"{path.name}, explorer {k}: controls without an accessible name: {unnamed}"
            done = operate_by_keyboard(page, k)
            report["operated"].append(done)
            assert done["focused"]["role"] in ("slider", "select"), f"{path.name}, explorer {k}: {done}"
            assert done["focused"]["label"], f"{path.name}, explorer {k}: the focused control has no label: {done}"
            assert done["after"] != done["before"], f"{path.name}, explorer {k}: the status did not change: {done}"
        page.add_script_tag(path=AXE_JS)
        violations = page.evaluate(_AXE_RUN_JS, ["[data-a11ytest]", AXE_TAGS])
        # every output, for the record: JupyterLab draws a figure's image without an alt (it does not read
        # the output's "alt" metadata: jupyter/enhancement-proposals#120), which is the lab's, not ours
        report["axe"] = page.evaluate(_AXE_RUN_JS, [".jp-OutputArea-output", AXE_TAGS])
        report["axe_explorers"] = violations
        FOUND[path.stem] = report
        SHOTS.mkdir(parents=True, exist_ok=True)
        counts = {where: {impact: sum(len(v["nodes"]) for r in FOUND.values() for v in r[where]
                                      if v["impact"] == impact)
                          for impact in ("critical", "serious", "moderate", "minor")}
                  for where in ("axe", "axe_explorers")}
        (SHOTS / "a11y_lab.json").write_text(json.dumps({"chapters": len(FOUND), "nodes by impact, every output":
                                                         counts["axe"], "nodes by impact, explorers":
                                                         counts["axe_explorers"], "found": FOUND},
                                                        indent=1, ensure_ascii=False))
        failing = [v for v in violations if v["impact"] in FAILING]
        assert not failing, f"{path.name}: serious or critical axe violations in its explorers: {failing}"
        assert not remote, f"{path.name}: requests to another host: {remote}"
    finally:
        with contextlib.suppress(Exception):
            page.evaluate("() => window.jupyterapp.shell.currentWidget.sessionContext.shutdown()")
        page.close()
