"""Every chapter notebook in JupyterLab, as a student uses it, in a real browser.

JupyterLab is started with `make lab`'s arguments (course.lab_argv: 127.0.0.1, token
authentication on, no news or update checks) on a free port, serving a working copy made
by course.sync as `make lab` makes my-notebooks/, but in a temporary folder with its own
settings, workspaces and runtime folders, so that the tracked notebooks stay clean. For each
notebook the test runs all cells, asserts there is no error output, moves one slider
with the keyboard and asserts that the plot image changed. The server is stopped by its
PID. A screenshot of each notebook is saved under book/_build/screenshots/.
"""

from __future__ import annotations

import json
import os
import secrets
import shutil
import subprocess
import sys
import tempfile
import time
import urllib.request
from pathlib import Path

import pytest
from playwright.sync_api import TimeoutError as PlaywrightTimeout

from conftest import ROOT, block_remote, free_port

sys.path.insert(0, str(ROOT))
import course  # noqa: E402  (the script at the repository's root, which `make lab` runs)

NOTEBOOKS = sorted((ROOT / "notebooks").glob("*.ipynb"))
SHOTS = ROOT / "book" / "_build" / "screenshots"

# settings a student would otherwise be asked about (the news prompt wants the internet);
# windowing off so every cell is in the DOM
SETTINGS = {
    "@jupyterlab/apputils-extension/notification.jupyterlab-settings": {"fetchNews": "false",
                                                                       "checkForUpdates": False},
    "@jupyterlab/notebook-extension/tracker.jupyterlab-settings": {"windowingMode": "none"},
}


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
    log = open(tmp / "lab.log", "w")
    proc = subprocess.Popen(
        course.lab_argv(Path(sys.executable), root, port)
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



_READY_JS = """() => {
  const w = window.jupyterapp && window.jupyterapp.shell.currentWidget;
  const k = w && w.sessionContext && w.sessionContext.session && w.sessionContext.session.kernel;
  return !!(w && w.content && w.content.model && w.context.isReady && k && k.status === 'idle');
}"""

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

# the first widget output that has a slider handle and a plot image; marked for the test
_MARK_WIDGET_JS = """() => {
  document.querySelectorAll('[data-mechtest]').forEach(e => e.removeAttribute('data-mechtest'));
  const root = window.jupyterapp.shell.currentWidget.node;  // this notebook's panel only
  const outs = Array.from(root.querySelectorAll('.jp-OutputArea-output'));
  for (const o of outs) {
    if (o.querySelector('.noUi-handle') && o.querySelector('img')) {
      o.setAttribute('data-mechtest', 'explorer');
      return true;
    }
  }
  return false;
}"""


def test_notebooks_found():
    assert NOTEBOOKS, "no notebooks"


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.stem)
def test_notebook_in_jupyterlab(browser, lab, path):
    base, token, root = lab
    page = browser.new_page(viewport={"width": 1400, "height": 1000})
    page_errors = []
    page.on("pageerror", lambda e: page_errors.append(str(e)))

    remote = block_remote(page)  # the lab must not reach for the internet either (news, extensions, CDNs)
    try:
        # ?reset: a fresh workspace, so the notebooks of earlier tests are not reopened
        page.goto(f"{base}/lab/tree/{path.name}?reset&token={token}", wait_until="domcontentloaded")
        page.wait_for_function(_READY_JS, timeout=90_000)
        page.evaluate("() => window.jupyterapp.commands.execute('notebook:run-all-cells')")
        state = page.wait_for_function(_STATE_JS, timeout=240_000, polling=500).json_value()
        assert not state["errors"], f"{path.name}: error output: {state['errors']}"
        assert state["pending"] == 0

        page.wait_for_function(_MARK_WIDGET_JS, timeout=30_000)
        widget = page.locator("[data-mechtest='explorer']")
        image = widget.locator("img").first
        handle = widget.locator(".noUi-handle").first
        handle.scroll_into_view_if_needed()
        before = image.get_attribute("src")
        changed = "([w, src]) => { const i = w.querySelector('img'); return i && i.src !== src; }"
        handle.focus()
        for key in ("ArrowRight", "ArrowLeft"):  # left if the slider starts at its maximum
            for _ in range(6 if key == "ArrowRight" else 12):
                page.keyboard.press(key)
            try:
                page.wait_for_function(changed, arg=[widget.element_handle(), before], timeout=20_000)
                break
            except PlaywrightTimeout:
                continue
        after = widget.locator("img").first.get_attribute("src")
        assert after and after != before, f"{path.name}: the plot did not change when the slider moved"

        page.wait_for_function(_READY_JS, timeout=60_000)  # the last key press is drawn too
        page.wait_for_timeout(500)
        SHOTS.mkdir(parents=True, exist_ok=True)
        page.screenshot(path=str(SHOTS / f"lab__{path.stem}.png"))
        assert not page_errors, f"{path.name}: page errors: {page_errors}"
        assert not remote, f"{path.name}: requests to another host: {remote}"
    finally:
        try:  # free the kernel's memory and CPU for the next notebook
            page.evaluate("() => window.jupyterapp.shell.currentWidget.sessionContext.shutdown()")
        except Exception:
            pass
        page.close()
    # the copy was used, never the tracked notebook
    assert json.loads(path.read_text())["cells"][0].get("outputs", []) == []
