"""A class on one JupyterHub, simulated on this machine.

JupyterHub listens on 127.0.0.1 with configurable-http-proxy (npm), a dummy authenticator
and SimpleLocalProcessSpawner (every student's server a process of this user, its home in a
temporary folder). N students at once: each logs in through the hub's login form, starts
a server, opens a chapter (put into their home as nbgitpuller would), runs all its cells
through the kernel's websocket, and moves a slider (the comm message JupyterLab would send).

    python tests_hub/hub_load.py --students 5 --chapter notebooks/00_getting_started.ipynb

Prints one JSON object: success count, p50/p95 of the times, memory per student (PSS of
the server and its kernel), the CPU the hub and the proxy used, the machine's load average
(``--save``: also into benchmarks/hub_load_N.json, the files benchmarks/README.md's table quotes). Every request goes to
127.0.0.1 with a timeout; the hub and the proxy are stopped by their PIDs.
"""

from __future__ import annotations

import argparse
import contextlib
import json
import os
import secrets
import socket
import statistics
import subprocess
import sys
import tempfile
import time
import uuid
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import psutil
import requests
import websocket

ROOT = Path(__file__).resolve().parent.parent
TIMEOUT = 120  # seconds for any one step of a student
PASSWORD = "class-of-2026"
CHP = ROOT / ".hub-deps" / "node_modules" / ".bin" / "configurable-http-proxy"  # `make hub-deps` puts it there

CONFIG = """
c.JupyterHub.ip = "127.0.0.1"
c.JupyterHub.port = {port}
c.JupyterHub.hub_ip = "127.0.0.1"
c.JupyterHub.hub_port = {hub_port}
c.ConfigurableHTTPProxy.api_url = "http://127.0.0.1:{api_port}"
c.ConfigurableHTTPProxy.command = [{chp!r}]
c.JupyterHub.db_url = "sqlite:///{tmp}/hub.sqlite"
c.JupyterHub.cookie_secret_file = "{tmp}/cookie_secret"
c.JupyterHub.authenticator_class = "dummy"
c.DummyAuthenticator.password = {password!r}
c.Authenticator.allow_all = True
c.JupyterHub.spawner_class = "simple"
c.SimpleLocalProcessSpawner.home_dir_template = "{tmp}/home/{{username}}"
c.Spawner.cmd = [{singleuser!r}]
c.Spawner.args = {args!r}
c.Spawner.environment = {{"MECHLAB_THREADS": "1", "MPLBACKEND": "module://matplotlib_inline.backend_inline"}}
c.Spawner.start_timeout = {timeout}
c.Spawner.http_timeout = {timeout}
c.JupyterHub.services = [{{"name": "load-test", "api_token": {token!r}}}]
c.JupyterHub.load_roles = [{{"name": "load-test", "services": ["load-test"],
                            "scopes": ["admin:users", "admin:servers", "tokens", "access:servers"]}}]
"""


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


class Kernel:
    """A kernel's websocket, as JupyterLab talks to it (the default JSON protocol)."""

    def __init__(self, url: str, token: str):
        self.ws = websocket.create_connection(url, header=[f"Authorization: token {token}"], timeout=TIMEOUT)
        self.session = uuid.uuid4().hex
        self.sliders: list[tuple[str, dict]] = []  # (comm id, state) of every slider the kernel opened

    def send(self, msg_type: str, content: dict) -> str:
        msg_id = uuid.uuid4().hex
        self.ws.send(json.dumps({"header": {"msg_id": msg_id, "username": "student", "session": self.session,
                                            "msg_type": msg_type, "version": "5.3"},
                                 "parent_header": {}, "metadata": {}, "content": content, "channel": "shell",
                                 "buffers": []}))
        return msg_id

    def until_idle(self, msg_id: str, errors_fail: bool = True) -> list[dict]:
        """The iopub messages caused by `msg_id`, up to the kernel's idle status; fails on an error unless
        `errors_fail` is false (the error is then one of the messages)."""
        seen, deadline = [], time.monotonic() + TIMEOUT
        while time.monotonic() < deadline:
            raw = self.ws.recv()
            if not isinstance(raw, str):
                continue  # a binary frame (widget buffers): not needed here
            msg = json.loads(raw)
            if msg["parent_header"].get("msg_id") != msg_id:
                continue
            kind = msg["header"]["msg_type"]
            if kind == "error" and errors_fail:
                raise RuntimeError(f"{msg['content']['ename']}: {msg['content']['evalue']}")
            if kind == "comm_open" and msg["content"]["data"].get("state", {}).get("_model_name", "").endswith(
                    "SliderModel"):
                self.sliders.append((msg["content"]["comm_id"], msg["content"]["data"]["state"]))
            if kind == "status" and msg["content"]["execution_state"] == "idle":
                return seen
            seen.append(msg)
        raise TimeoutError(f"no idle status for {msg_id} within {TIMEOUT} s")

    def run(self, code: str, errors_fail: bool = True) -> list[dict]:
        return self.until_idle(self.send("execute_request", {"code": code, "silent": False, "store_history": True,
                                                             "user_expressions": {}, "allow_stdin": False,
                                                             "stop_on_error": True}), errors_fail)


def log_in(base: str, api: requests.Session, name: str) -> tuple[requests.Session, requests.Session, str]:
    """`name` logs in through the hub's form and gets a running server: their browser's session (the hub's
    cookies), an API session with a token of theirs, and their server's token."""
    t0 = time.monotonic()
    web = requests.Session()
    web.get(f"{base}/hub/login", timeout=TIMEOUT).raise_for_status()
    login = web.post(f"{base}/hub/login", data={"username": name, "password": PASSWORD,
                                                "_xsrf": web.cookies.get("_xsrf", "")},
                     allow_redirects=False, timeout=TIMEOUT)
    if login.status_code != 302 or "jupyterhub-hub-login" not in web.cookies:
        raise RuntimeError(f"login of {name} failed: {login.status_code}")
    api.post(f"{base}/hub/api/users/{name}/server", timeout=TIMEOUT).raise_for_status()
    while not api.get(f"{base}/hub/api/users/{name}", timeout=TIMEOUT).json()["servers"].get("", {}).get("ready"):
        if time.monotonic() - t0 > TIMEOUT:
            raise TimeoutError(f"{name}'s server did not start")
        time.sleep(0.25)
    token = api.post(f"{base}/hub/api/users/{name}/tokens", json={"expires_in": 3600},
                     timeout=TIMEOUT).json()["token"]
    user = requests.Session()
    user.headers["Authorization"] = f"token {token}"
    return web, user, token


def student(base: str, api: requests.Session, name: str, chapter: Path) -> dict:
    t0 = time.monotonic()
    _, user, token = log_in(base, api, name)
    t_server = time.monotonic() - t0
    prefix = f"{base}/user/{name}"
    nb = json.loads(chapter.read_text())
    user.put(f"{prefix}/api/contents/{chapter.name}", json={"type": "notebook", "format": "json", "content": nb},
             timeout=TIMEOUT).raise_for_status()
    user.get(f"{prefix}/api/contents/{chapter.name}", timeout=TIMEOUT).raise_for_status()  # opens it
    t1 = time.monotonic()
    session = user.post(f"{prefix}/api/sessions", json={"path": chapter.name, "type": "notebook",
                                                        "kernel": {"name": "python3"}}, timeout=TIMEOUT).json()
    kernel = Kernel(f"{prefix.replace('http', 'ws', 1)}/api/kernels/{session['kernel']['id']}/channels", token)
    try:
        kernel.until_idle(kernel.send("kernel_info_request", {}))
        t_kernel = time.monotonic() - t1
        t2 = time.monotonic()
        for cell in nb["cells"]:
            if cell["cell_type"] == "code":
                kernel.run("".join(cell["source"]))
        t_cells = time.monotonic() - t2
        if not kernel.sliders:
            raise RuntimeError(f"{chapter.name} opened no slider")
        comm_id, state = kernel.sliders[0]
        value = state["max"] if state["value"] != state["max"] else state["min"]
        t3 = time.monotonic()
        effects = kernel.until_idle(kernel.send("comm_msg", {"comm_id": comm_id, "data": {
            "method": "update", "state": {"value": value}, "buffer_paths": []}}))
        t_slider = time.monotonic() - t3
        if not effects:
            raise RuntimeError("moving the slider changed nothing")
        pid = api.get(f"{base}/hub/api/users/{name}", params={"include_stopped_servers": 0},
                      timeout=TIMEOUT).json()["servers"][""]["state"]["pid"]
        server = psutil.Process(pid)
        memory = sum(p.memory_full_info().pss for p in [server, *server.children(recursive=True)])
    finally:
        kernel.ws.close()
    return {"server": t_server, "kernel": t_kernel, "cells": t_cells, "slider": t_slider, "pss_mb": memory / 2**20}


def open_assignment(base: str, api: requests.Session, name: str, repo: str, path: str) -> dict:
    """`name` follows the assignment link a lecturer hands out (nbgitpuller: the git repository `repo` of
    student editions, opened at `path` in it), as their browser would, then runs the edition's code cells in
    order on their server's kernel. Returns where the link landed, the notebook found in their home at the
    link's path, and for each code cell its error's name (None when it ran cleanly) and what it said (its printed
    text and its error's message)."""
    web, user, token = log_in(base, api, name)
    folder = repo.rstrip("/").split("/")[-1]  # nbgitpuller's default target: the repository's name
    query = {"repo": repo, "branch": "main", "urlpath": f"lab/tree/{folder}/{path}"}
    # through the hub (user-redirect, the hub's OAuth to the student's server) to nbgitpuller's page
    landed = web.get(f"{base}/hub/user-redirect/git-pull", params=query, timeout=TIMEOUT)
    landed.raise_for_status()
    prefix = f"{base}/user/{name}"
    # what that page's script does next: the pull, reported as server-sent events, with the browser's cookies
    phases = []
    with web.get(f"{prefix}/git-pull/api", params={"repo": repo, "branch": "main", "targetpath": folder},
                 stream=True, timeout=TIMEOUT) as events:
        events.raise_for_status()
        for line in events.iter_lines(decode_unicode=True):
            if line and line.startswith("data:"):
                event = json.loads(line[5:])
                phases.append(event.get("phase"))
                if event.get("phase") in ("finished", "error"):
                    if event["phase"] == "error":
                        raise RuntimeError(f"nbgitpuller: {event.get('message')} {event.get('output', '')}")
                    break
    got = user.get(f"{prefix}/api/contents/{folder}/{path}", timeout=TIMEOUT)
    got.raise_for_status()
    nb = got.json()["content"]
    session = user.post(f"{prefix}/api/sessions", json={"path": f"{folder}/{path}", "type": "notebook",
                                                        "kernel": {"name": "python3"}}, timeout=TIMEOUT).json()
    kernel = Kernel(f"{prefix.replace('http', 'ws', 1)}/api/kernels/{session['kernel']['id']}/channels", token)
    cells = []
    try:
        kernel.until_idle(kernel.send("kernel_info_request", {}))
        for cell in nb["cells"]:
            if cell["cell_type"] != "code":
                continue
            msgs = kernel.run(cell["source"], errors_fail=False)
            text = "".join(m["content"].get("text", "") for m in msgs if m["header"]["msg_type"] == "stream")
            error = next((m["content"] for m in msgs if m["header"]["msg_type"] == "error"), {})
            cells.append({"id": cell["metadata"].get("nbgrader", {}).get("grade_id"), "error": error.get("ename"),
                          "said": text + error.get("evalue", "")})
    finally:
        kernel.ws.close()
    return {"landed": landed.url, "phases": phases, "notebook": nb, "cells": cells}


def percentile(values: list[float], q: float) -> float:
    return statistics.quantiles(values, n=100, method="inclusive")[q - 1] if len(values) > 1 else values[0]


# benchmarks/README.md's table of a class on one hub: each column is one run's JSON, kept as measured
def results_file(students: int) -> Path:
    return ROOT / "benchmarks" / f"hub_load_{students}.json"


ROWS = [("succeeded", lambda r: f"{r['succeeded']} / {r['students']}"),
        ("login → server running, p50 / p95", lambda r: f"{r['server']['p50']:.1f} / {r['server']['p95']:.1f} s"),
        ("session → kernel answering, p50 / p95", lambda r: f"{r['kernel']['p50']:.1f} / {r['kernel']['p95']:.1f} s"),
        ("all cells of chapter 00 run, p50 / p95", lambda r: f"{r['cells']['p50']:.1f} / {r['cells']['p95']:.1f} s"),
        ("slider moved → kernel done redrawing, p50 / p95",
         lambda r: f"{r['slider']['p50']:.2f} / {r['slider']['p95']:.2f} s"),
        ("memory per student (server + kernel, PSS), p50", lambda r: f"{r['pss_mb']['p50']:.0f} MB"),
        ("hub + proxy CPU over the run", lambda r: f"{r['hub_and_proxy_cpu_s']:.1f} s in {r['wall_s']:.0f} s"),
        ("load average (1 min) before / after: other work on the machine",
         lambda r: f"{r['load_average_before'][0]:g} / {r['load_average_after'][0]:g}")]


def table(reports: list[dict]) -> str:
    """The Markdown table of the runs ``reports`` (one column each), as benchmarks/README.md quotes it."""
    head = [f"{reports[0]['date']}, {reports[0]['cores']}-core VM"] + [f"{r['students']} students" for r in reports]
    lines = ["| " + " | ".join(head) + " |", "|---" * len(head) + "|"]
    lines += ["| " + " | ".join([name] + [cell(r) for r in reports]) + " |" for name, cell in ROWS]
    return "\n".join(lines)


@contextlib.contextmanager
def running_hub(chp: str):
    """JupyterHub (CONFIG) on 127.0.0.1 in a temporary folder, until the block ends: yields its address, an API
    session with the load test's admin token, and the hub's and the proxy's processes. Both are stopped by PID."""
    bin_dir = Path(sys.executable).parent
    port, token = free_port(), secrets.token_hex(32)
    with tempfile.TemporaryDirectory(prefix="mechlab-hub-") as tmp, open(Path(tmp) / "hub.log", "w") as log:
        config = Path(tmp) / "jupyterhub_config.py"
        root_flag = ["--allow-root"] if os.geteuid() == 0 else []  # the single-user servers run as this user
        config.write_text(CONFIG.format(port=port, hub_port=free_port(), api_port=free_port(), chp=chp, tmp=tmp,
                                        password=PASSWORD, singleuser=str(bin_dir / "jupyterhub-singleuser"),
                                        args=root_flag, timeout=TIMEOUT, token=token))
        hub = subprocess.Popen([str(bin_dir / "jupyterhub"), "-f", str(config)], cwd=tmp, stdout=log,
                               stderr=subprocess.STDOUT, env={**os.environ, "PATH": f"{bin_dir}:{os.environ['PATH']}"})
        base, proxy = f"http://127.0.0.1:{port}", None
        api = requests.Session()
        api.headers["Authorization"] = f"token {token}"
        try:
            deadline = time.monotonic() + TIMEOUT
            while True:
                try:
                    if api.get(f"{base}/hub/api/", timeout=5).ok:
                        break
                except requests.ConnectionError:
                    pass
                if hub.poll() is not None or time.monotonic() > deadline:
                    raise RuntimeError(f"the hub did not start:\n{(Path(tmp) / 'hub.log').read_text()[-3000:]}")
                time.sleep(0.5)
            hub_ps = psutil.Process(hub.pid)
            proxy = next(p for p in hub_ps.children() if "configurable-http-proxy" in " ".join(p.cmdline()))
            yield base, api, hub_ps, proxy
        finally:
            hub.terminate()
            try:
                hub.wait(timeout=60)
            except subprocess.TimeoutExpired:
                hub.kill()
            if proxy is not None and proxy.is_running():
                proxy.terminate()
                proxy.wait(timeout=30)


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--students", type=int, default=5)
    parser.add_argument("--save", action="store_true",
                        help="also write the report to benchmarks/hub_load_<students>.json")
    parser.add_argument("--chapter", type=Path, default=ROOT / "notebooks" / "00_getting_started.ipynb")
    parser.add_argument("--chp", default=str(CHP))
    args = parser.parse_args()
    load_before = [round(x, 1) for x in os.getloadavg()]  # what else the machine ran: the figures depend on it
    with running_hub(args.chp) as (base, api, hub_ps, proxy):
        cpu0 = sum(hub_ps.cpu_times()[:2]) + sum(proxy.cpu_times()[:2])
        start = time.monotonic()
        names = [f"student{i:03d}" for i in range(args.students)]
        with ThreadPoolExecutor(args.students) as pool:
            futures = [pool.submit(student, base, api, n, args.chapter) for n in names]
        results, errors = [], []
        for f in futures:
            try:
                results.append(f.result())
            except Exception as e:  # a student's failure is a figure of the run, not its end
                errors.append(f"{type(e).__name__}: {e}")
        wall = time.monotonic() - start
        hub_cpu = sum(hub_ps.cpu_times()[:2]) + sum(proxy.cpu_times()[:2]) - cpu0
        for n in names:
            api.delete(f"{base}/hub/api/users/{n}/server", timeout=TIMEOUT)
    report = {"students": args.students, "succeeded": len(results), "errors": errors, "wall_s": round(wall, 1),
              "hub_and_proxy_cpu_s": round(hub_cpu, 2), "cores": os.cpu_count(),
              "date": time.strftime("%Y-%m-%d", time.gmtime()), "load_average_before": load_before,
              "load_average_after": [round(x, 1) for x in os.getloadavg()]}
    for key in ("server", "kernel", "cells", "slider", "pss_mb"):
        values = [r[key] for r in results]
        if values:
            report[key] = {"p50": round(percentile(values, 50), 2), "p95": round(percentile(values, 95), 2)}
    print(json.dumps(report))
    if args.save:
        results_file(args.students).write_text(json.dumps(report, indent=1) + "\n")


if __name__ == "__main__":
    main()
