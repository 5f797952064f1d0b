"""Every chapter notebook in JupyterLab, as a student uses it, in a real browser.

JupyterLab is started with `make lab`'s arguments (course.lab_argv: 127.0.0.1, token
authentication on, no news or update checks) on a free port, from this venv or from the one
MECHLAB_LAB_PYTHON names (CI: a student's lab-only venv on Debian's python3), serving a working copy made
by course.sync as `make lab` makes my-notebooks/, but in a temporary folder with its own
settings, workspaces and runtime folders, so that the tracked notebooks stay clean. For each
notebook the test runs all cells, asserts there is no error output (chapter 12: its design explorer shows
the specification line the text's specification cell printed), presses the arrow key
on the first explorer's crank-angle slider a dozen times, timing each press to the redrawn
plot (an image re-shown by the inline backend, or an ipympl canvas receiving a blitted
frame), asserts that the plot changed, then audits the page for accessibility and operates every
explorer by the keyboard alone (lab_a11y.audit_chapter); the medians go to
book/_build/screenshots/latency.json (the 100 ms goal is a benchmark, benchmarks/README.md; the
test asserts only that a redraw answers a key press within MECHLAB_LATENCY_LIMIT_MS). The server is stopped by its
PID. A screenshot of each notebook is saved under book/_build/screenshots/.
"""

from __future__ import annotations

import contextlib
import json
import os
import secrets
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
import urllib.request
from pathlib import Path

import pytest
from conftest import ROOT, free_port, watch_remote
from lab_a11y import _READY_JS, SHOTS, audit_chapter

sys.path.insert(0, str(ROOT))
import course

NOTEBOOKS = sorted((ROOT / "notebooks").glob("*.ipynb"))
# the Python whose JupyterLab serves the chapters: this venv's, or a student's lab-only venv (CI: Debian's python3
# with the lab part of environment.txt, made by `python3 course.py venv lab`)
LAB_PYTHON = Path(os.environ.get("MECHLAB_LAB_PYTHON") or sys.executable)

# windowing off so every cell is in the DOM (the test's own setting; the news prompt and the update check
# are off by the settings `make lab` ships, binder/lab-settings, as students get them)
SETTINGS = {
    "@jupyterlab/notebook-extension/tracker.jupyterlab-settings": {"windowingMode": "none"},
}
NEWS_PROMPT = "official Jupyter news"


@pytest.fixture(scope="module")
def lab():
    tmp = Path(tempfile.mkdtemp(prefix="mechlab-lab-"))
    root = tmp / "my-notebooks"
    course.sync(ROOT / "notebooks", root)
    for rel, values in SETTINGS.items():
        path = tmp / "settings" / rel
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(json.dumps(values))
    token = secrets.token_hex(16)
    port = free_port()
    env = dict(os.environ, JUPYTER_RUNTIME_DIR=str(tmp / "runtime"), JUPYTER_CONFIG_DIR=str(tmp / "config"),
               IPYTHONDIR=str(tmp / "ipython"), MPLBACKEND="module://matplotlib_inline.backend_inline")
    log = open(tmp / "lab.log", "w")  # noqa: SIM115  JupyterLab writes it until the finally below closes it
    proc = subprocess.Popen(
        course.lab_argv(LAB_PYTHON, root, port)
        + ["--ServerApp.port_retries=0", f"--IdentityProvider.token={token}", "--LabApp.expose_app_in_browser=True",
           f"--LabApp.user_settings_dir={tmp / 'settings'}", f"--LabApp.workspaces_dir={tmp / 'workspaces'}"],
        stdout=log, stderr=subprocess.STDOUT, env=env, cwd=tmp)
    base = f"http://127.0.0.1:{port}"
    try:
        deadline = time.monotonic() + 90
        while True:
            if proc.poll() is not None:
                pytest.fail(f"JupyterLab exited with {proc.returncode}:\n{(tmp / 'lab.log').read_text()[-3000:]}")
            try:
                with urllib.request.urlopen(f"{base}/api/status?token={token}", timeout=5) as r:
                    if r.status == 200:
                        break
            except OSError:
                pass
            if time.monotonic() > deadline:
                pytest.fail(f"JupyterLab did not answer on {base}:\n{(tmp / 'lab.log').read_text()[-3000:]}")
            time.sleep(0.5)
        yield base, token, root
    finally:
        proc.terminate()  # by its PID, nothing else
        try:
            proc.wait(timeout=20)
        except subprocess.TimeoutExpired:
            proc.kill()
            proc.wait()
        log.close()
        shutil.rmtree(tmp, ignore_errors=True)




# null while running; {errors, pending} once the kernel is idle with every code cell run,
# or as soon as an error output appears (run-all stops there)
_STATE_JS = """() => {
  const w = window.jupyterapp.shell.currentWidget;
  const cells = w.content.model.cells;
  const errors = [];
  let pending = 0;
  for (let i = 0; i < cells.length; i++) {
    const c = cells.get(i);
    if (c.type !== 'code') continue;
    if (c.executionCount === null) pending++;
    for (let j = 0; j < c.outputs.length; j++) {
      const o = c.outputs.get(j).toJSON();
      if (o.output_type === 'error') errors.push(`cell ${i}: ${o.ename}: ${o.evalue}`);
    }
  }
  const idle = w.sessionContext.session.kernel.status === 'idle';
  if (errors.length && idle) return {errors, pending};
  return (idle && pending === 0) ? {errors, pending} : null;
}"""

# the first widget output that has a slider handle and a plot (an image re-shown in an Output
# widget, or an ipympl canvas); marked for the test, with its crank-angle slider ("crank angle",
# else a slider whose label has a φ; else its first slider). Returns "angle" or "other" (a widget
# without a crank angle, e.g. chapter 12's).
_MARK_WIDGET_JS = """() => {
  document.querySelectorAll('[data-mechtest]').forEach(e => e.removeAttribute('data-mechtest'));
  const root = window.jupyterapp.shell.currentWidget.node;  // this notebook's panel only
  for (const o of Array.from(root.querySelectorAll('.jp-OutputArea-output'))) {
    if (o.querySelector('.noUi-handle') && (o.querySelector('img') || o.querySelector('canvas'))) {
      o.setAttribute('data-mechtest', 'explorer');
      const sliders = Array.from(o.querySelectorAll('.widget-slider'));
      const label = s => (s.querySelector('.widget-label') || {}).textContent || '';
      // the crank angle, not a dimension whose label names an angle φ1 (the dwell's start)
      const angle = sliders.find(s => label(s).includes('crank angle')) || sliders.find(s => label(s).includes('φ'));
      (angle || o.querySelector('.widget-slider')).setAttribute('data-mechtest-slider', 'angle');
      return angle ? 'angle' : 'other';
    }
  }
  return false;
}"""

# Every redraw of the marked widget's plot, timed with performance.now(): an <img> added or
# changed (a figure re-shown in an Output widget, the inline backend) or an image drawn onto a
# <canvas> of it (an ipympl canvas receiving a blitted frame); and every key press.
_INSTRUMENT_JS = """() => {
  window.__mechDraws = [];
  window.__mechKeys = [];
  const widget = document.querySelector("[data-mechtest='explorer']");
  const proto = CanvasRenderingContext2D.prototype;
  if (!proto.__mechDrawImage) {
    proto.__mechDrawImage = proto.drawImage;
    proto.drawImage = function (...args) {
      const w = document.querySelector("[data-mechtest='explorer']");
      if (window.__mechDraws && this.canvas.isConnected && w && w.contains(this.canvas))
        window.__mechDraws.push(performance.now());
      return this.__mechDrawImage(...args);
    };
  }
  new MutationObserver(records => {
    const t = performance.now();
    const isImg = n => n.nodeType === 1 && (n.tagName === 'IMG' || n.querySelector('img'));
    if (records.some(r => (r.type === 'attributes' && r.target.tagName === 'IMG')
                          || Array.from(r.addedNodes).some(isImg)))
      window.__mechDraws.push(t);
  }).observe(widget, {subtree: true, childList: true, attributes: true, attributeFilter: ['src']});
  document.addEventListener('keydown', () => window.__mechKeys.push(performance.now()), true);
}"""

# the plot's pixels: the image's source, or the canvas's content as a data URL
_PLOT_JS = """() => {
  const w = document.querySelector("[data-mechtest='explorer']");
  const img = w.querySelector('img');
  if (img) return img.src;
  return Array.from(w.querySelectorAll('canvas')).map(c => c.toDataURL()).join('|');
}"""

# The slider labels and readouts under `root` (a CSS selector) whose text does not fit its content box
# (the box less its padding and border): the text is measured twice, as laid out (a Range's bounding box:
# it covers glyphs past the box, even under an ellipsis) and as drawn in the element's font (canvas
# measureText). scrollWidth misses a cut inside the padding (it equals clientWidth there). Chromium draws the
# ellipsis for any overflow of the layout (in 1/64 px): a label 0.16 px too long read "pressure angle ≤ (de…".
CLIPPED_JS = """root => {
  const ctx = document.createElement('canvas').getContext('2d');
  const els = document.querySelector(root).querySelectorAll(
    '.widget-slider .widget-readout, .widget-slider .widget-label');
  return Array.from(els).filter(e => {
    const text = e.textContent.trim();
    if (!text || e.offsetParent === null) return false;
    const s = getComputedStyle(e);
    const box = e.getBoundingClientRect();
    const left = box.left + parseFloat(s.borderLeftWidth) + parseFloat(s.paddingLeft);
    const right = box.right - parseFloat(s.borderRightWidth) - parseFloat(s.paddingRight);
    const range = document.createRange();
    range.selectNodeContents(e);
    const laid = range.getBoundingClientRect();
    ctx.font = s.font;
    const drawn = ctx.measureText(text).width;
    return laid.left < left - 0.05 || laid.right > right + 0.05 || drawn > right - left + 1;
  }).map(e => e.textContent.trim());
}"""

# Chapter 12: the specification line its specification cell prints (the text's), and the line the marked explorer
# shows above its table (the explorer's): the explorer must open on the text's 2/3 of the turn, not its slider's 0.67
_SPEC_JS = """() => {
  const w = window.jupyterapp.shell.currentWidget;
  const cells = w.content.model.cells;
  let stated = null;
  for (let i = 0; i < cells.length && stated === null; i++) {
    const c = cells.get(i);
    if (c.type === 'code' && c.sharedModel.getSource().includes('design.Specification(') && c.outputs.length)
      stated = [].concat(c.outputs.get(0).toJSON().text || '').join('').trim();
  }
  const line = document.querySelector("[data-mechtest='explorer'] .widget-html-content p");
  return [stated, line ? line.textContent.trim() : null];
}"""

PRESSES = 12
# the speed goal (100 ms median) is measured here and recorded in benchmarks/README.md; a timed test on a
# shared 2-core machine asserts only that the explorer answers, well within a second
LATENCY_LIMIT_MS = float(os.environ.get("MECHLAB_LATENCY_LIMIT_MS", "1000"))
LATENCY: dict[str, dict] = {}


def test_notebooks_found():
    assert NOTEBOOKS, "no notebooks"


@pytest.fixture(scope="module")
def tab(browser):
    """The one tab every chapter is opened in, with what it saw since it was last cleared: a tab keeps its renderer
    and its caches from chapter to chapter, while a new tab for each chapter loaded JupyterLab anew (11 against
    6 CPU-s to open a notebook). Leaving a notebook that changed asks first (beforeunload): the tab says yes."""
    page = browser.new_context(viewport={"width": 1400, "height": 1000}).new_page()
    seen = {"page": page, "errors": [], "remote": watch_remote(page)}  # the lab must not reach for the internet
    page.on("pageerror", lambda e: seen["errors"].append(str(e)))
    page.on("dialog", lambda dialog: dialog.accept())
    yield seen
    page.context.close()


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.stem)
def test_notebook_in_jupyterlab(tab, lab, path):
    base, token, _root = lab
    page, page_errors, remote = tab["page"], tab["errors"], tab["remote"]
    page_errors.clear()
    remote.clear()
    try:
        # ?reset: a fresh workspace, so the notebooks of earlier tests are not reopened
        page.goto(f"{base}/lab/tree/{path.name}?reset&token={token}", wait_until="domcontentloaded")
        page.wait_for_function(_READY_JS, timeout=90_000)
        assert NEWS_PROMPT not in page.inner_text("body"), f"{path.name}: the news prompt is shown"
        page.evaluate("() => window.jupyterapp.commands.execute('notebook:run-all-cells')")
        state = page.wait_for_function(_STATE_JS, timeout=240_000, polling=500).json_value()
        assert not state["errors"], f"{path.name}: error output: {state['errors']}"
        assert state["pending"] == 0

        kind = page.wait_for_function(_MARK_WIDGET_JS, timeout=30_000).json_value()
        if path.stem.startswith("12_"):
            stated, shown = page.evaluate(_SPEC_JS)
            assert stated and "dwell 0.667 of the turn" in stated, f"{path.name}: the specification printed {stated!r}"
            assert shown == stated, f"{path.name}: the explorer opened on {shown!r}, the text states {stated!r}"
        widget = page.locator("[data-mechtest='explorer']")
        widget.scroll_into_view_if_needed()
        page.wait_for_timeout(1000)   # the first full drawing of a live canvas arrives
        # no slider's label or readout is cut off, in any widget of the notebook
        notebook = page.evaluate("() => '#' + CSS.escape(window.jupyterapp.shell.currentWidget.id)")
        clipped = page.evaluate(CLIPPED_JS, notebook)
        assert not clipped, f"{path.name}: slider labels or readouts clipped: {clipped}"
        before = page.evaluate(_PLOT_JS)
        page.evaluate(_INSTRUMENT_JS)
        handle = widget.locator("[data-mechtest-slider='angle'] .noUi-handle").first
        handle.focus()
        samples = []
        for _ in range(PRESSES if kind == "angle" else 2):  # key press → the first redraw after it
            drawn = page.evaluate("() => window.__mechDraws.length")
            page.keyboard.press("ArrowRight")
            page.wait_for_function("n => window.__mechDraws.length > n", arg=drawn, timeout=20_000)
            samples.append(page.evaluate("() => { const k = window.__mechKeys[window.__mechKeys.length - 1];"
                                         " return window.__mechDraws.find(d => d >= k) - k; }"))
            page.wait_for_timeout(200)   # this press's drawing ends before the next press
        page.wait_for_function(_READY_JS, timeout=60_000)
        after = page.evaluate(_PLOT_JS)
        assert after and after != before, f"{path.name}: the plot did not change when the slider moved"
        mode = "canvas" if widget.locator("canvas").count() and not widget.locator("img").count() else "image"
        LATENCY[path.stem] = {"median_ms": round(statistics.median(samples), 1), "mode": mode,
                              "samples_ms": [round(x, 1) for x in samples]} if kind == "angle" else None
        SHOTS.mkdir(parents=True, exist_ok=True)
        (SHOTS / "latency.json").write_text(json.dumps({"chapters": LATENCY}, indent=1, ensure_ascii=False))
        if "spherical" in path.stem:   # the 3-D wheel turns under the mouse (a live ipympl canvas)
            assert mode == "canvas", f"{path.name}: the 3-D explorer is not a live canvas"
            box = widget.locator("canvas").last.bounding_box()
            x, y = box["x"] + 0.25 * box["width"], box["y"] + 0.5 * box["height"]
            turned = page.evaluate(_PLOT_JS)
            page.mouse.move(x, y)
            page.mouse.down()
            for k in range(1, 6):
                page.mouse.move(x + 12 * k, y + 4 * k)
                page.wait_for_timeout(100)
            page.mouse.up()
            page.wait_for_timeout(1500)
            assert page.evaluate(_PLOT_JS) != turned, f"{path.name}: dragging did not turn the 3-D view"

        page.wait_for_timeout(500)
        page.screenshot(path=str(SHOTS / f"lab__{path.stem}.png"))
        audit_chapter(page, path.stem)   # axe, named controls, each explorer by the keyboard (lab_a11y.py)
        assert not page_errors, f"{path.name}: page errors: {page_errors}"
        assert not remote, f"{path.name}: requests to another host: {remote}"
    finally:
        with contextlib.suppress(Exception):  # free the kernel's memory and CPU for the next notebook
            page.evaluate("() => window.jupyterapp.shell.currentWidget.sessionContext.shutdown()")
    # the copy was used, never the tracked notebook
    assert json.loads(path.read_text())["cells"][0].get("outputs", []) == []


def test_news_prompt_off_by_shipped_settings(lab):
    """The lab `make lab` starts (and the hub's image, binder/postBuild) has the news prompt and the
    update check off by its shipped settings (binder/lab-settings/overrides.json), not by the test's."""
    base, token, _ = lab
    url = f"{base}/lab/api/settings/@jupyterlab/apputils-extension:notification?token={token}"
    with urllib.request.urlopen(url, timeout=30) as r:
        plugin = json.load(r)
    assert plugin["schema"]["properties"]["fetchNews"]["default"] == "false"
    assert plugin["schema"]["properties"]["checkForUpdates"]["default"] is False
    assert plugin["settings"] == {}, "the test set it itself"


CLIPPING_PAGE = """<style>
  .widget-label { width: 150px; padding: 0 8px; box-sizing: border-box; overflow: hidden; display: inline-block;
                  white-space: nowrap; text-overflow: ellipsis; font: 13px sans-serif; }
  .widget-label span { display: inline-block; max-width: 100%; overflow: hidden; text-overflow: ellipsis; }
</style>
<div id="root">
  <div class="widget-slider"><label class="widget-label">pressure angle ≤ (deg) at the dwell's end</label></div>
  <div class="widget-slider"><label class="widget-label" id="inner"><span>pressure angle ≤ (deg) at the end</span></label></div>
  <div class="widget-slider"><label class="widget-label" id="inpad">pressure angle ≤ (deg)</label></div>
  <div class="widget-slider"><label class="widget-label" id="hair">dwell (of the turn)</label></div>
  <div class="widget-slider"><label class="widget-label" id="fits">crank angle φ (deg)</label></div>
</div>"""  # noqa: E501  one element a line, as the widgets draw it: no white space inside a label
# sizes three labels around their text: "inpad" 4 px short of it (the text runs into the 8 px padding and
# the ellipsis cuts it), "hair" 0.3 px short (the ellipsis still cuts it), "fits" 4 px more than it needs;
# returns scrollWidth and clientWidth of each label
_SIZE_AROUND_TEXT_JS = """() => {
  for (const [id, spare] of [['inpad', -4], ['hair', -0.3], ['fits', 4]]) {
    const e = document.getElementById(id);
    const range = document.createRange();
    e.style.width = 'auto';
    range.selectNodeContents(e);
    e.style.width = (range.getBoundingClientRect().width + 16 + spare) + 'px';
  }
  return Object.fromEntries(Array.from(document.querySelectorAll('.widget-label'))
    .map(e => [e.textContent, [e.scrollWidth, e.clientWidth]]));
}"""


def test_clipping_check_sees_labels_cut_inside_their_box(browser):
    """Planted labels: one far too long, one cut by an element inside it (scrollWidth equals clientWidth:
    the check before, scrollWidth > clientWidth, missed it), one whose text runs 4 px into its padding and is
    cut by the ellipsis, one only 0.3 px too long (the ellipsis cuts that too); all four are reported, and a
    label with 4 px to spare is not."""
    page = browser.new_page()
    try:
        page.set_content(CLIPPING_PAGE)
        widths = page.evaluate(_SIZE_AROUND_TEXT_JS)
        clipped = page.evaluate(CLIPPED_JS, "#root")
    finally:
        page.close()
    inner = "pressure angle ≤ (deg) at the end"
    assert widths[inner][0] == widths[inner][1], f"the planted cut must be invisible to scrollWidth: {widths}"
    assert clipped == ["pressure angle ≤ (deg) at the dwell's end", inner, "pressure angle ≤ (deg)",
                       "dwell (of the turn)"], widths


def test_slider_latency():
    """Key press on the crank-angle slider → the redrawn plot, per chapter (the first explorer
    of each notebook; a chapter whose first widget has no crank angle is left out): the
    medians are written to book/_build/screenshots/latency.json (the 100 ms goal is judged in
    benchmarks/README.md), and the median over every press of every chapter stays within
    MECHLAB_LATENCY_LIMIT_MS (1000 ms by default): a slider that answers."""
    assert len(LATENCY) == len(NOTEBOOKS), "run with the notebooks' tests"
    SHOTS.mkdir(parents=True, exist_ok=True)
    every = [x for r in LATENCY.values() if r for x in r["samples_ms"]]
    summary = {"median_ms": round(statistics.median(every), 1), "presses": len(every), "chapters": LATENCY}
    (SHOTS / "latency.json").write_text(json.dumps(summary, indent=1, ensure_ascii=False))
    assert summary["median_ms"] <= LATENCY_LIMIT_MS, summary
