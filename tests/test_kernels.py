"""Kernels start without a race and replies are never missed (tools/ipc_kernels.py).

Every route that executes notebooks (nbval, the book's myst-nb, nbconvert) starts its kernels
through tools/ipc_kernels.py; these tests start kernels the same way, many at once, from
other folders, and check that each route really does.
"""

from __future__ import annotations

import asyncio
import multiprocessing
import os
import subprocess
import sys
import time
from pathlib import Path

import nbformat
import pytest

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tools"))
import ipc_kernels  # noqa: E402

PARALLEL, ROUNDS = 8, 10
# nbval's start-up timeout: a kernel that lost a port race never answers, a slow one does within it
STARTUP_TIMEOUT = 60
# a cell that prints the transport its own kernel was started with, and fails unless it is IPC
TRANSPORT_CELL = ("import ipykernel, json\ntransport = json.loads(ipykernel.get_connection_info())['transport']\n"
                  "print(transport)\nassert transport == 'ipc', transport")


def _start_run_stop(start_at: float) -> str:
    """Start a kernel at `start_at` (all workers at once), run one line in it, stop it; '' or the error."""
    sys.path.insert(0, str(ROOT / "tools"))
    import ipc_kernels

    while time.time() < start_at:
        time.sleep(0.002)
    km = ipc_kernels.BlockingIPCKernelManager(kernel_name="python3")
    try:
        km.start_kernel(extra_arguments=["--HistoryManager.enabled=False"])
        kc = km.client()
        kc.start_channels()
        kc.wait_for_ready(timeout=STARTUP_TIMEOUT)
        reply = kc.execute_interactive("x = 6 * 7", timeout=STARTUP_TIMEOUT)
        kc.stop_channels()
        return "" if reply["content"]["status"] == "ok" else str(reply["content"])
    except Exception as error:
        return repr(error)
    finally:
        km.shutdown_kernel(now=True)


def test_many_kernels_start_at_once():
    """8 kernels started in the same instant, 10 times over, from 8 processes: every one answers."""
    failures = []
    with multiprocessing.get_context("spawn").Pool(PARALLEL) as pool:
        for round_ in range(ROUNDS):
            start_at = time.time() + 0.5
            errors = pool.map(_start_run_stop, [start_at] * PARALLEL)
            failures += [f"round {round_}: {error}" for error in errors if error]
    assert not failures, "\n".join(failures)


def test_socket_names_are_unique_absolute_and_private():
    """No two kernels can name the same socket, and the names do not depend on the working folder."""
    managers = [ipc_kernels.IPCKernelManager(), ipc_kernels.BlockingIPCKernelManager()]
    paths = [km.ip for km in managers]
    assert [km.transport for km in managers] == ["ipc", "ipc"]
    assert len(set(paths)) == 2 and all(os.path.isabs(p) for p in paths)
    assert all(len(p) + len("-ipc-5") <= ipc_kernels.SOCKET_PATH_MAX for p in paths)
    assert os.stat(os.path.dirname(paths[0])).st_mode & 0o077 == 0  # only the user may connect


def test_kernel_in_the_notebooks_folder_answers_a_client_elsewhere(tmp_path, monkeypatch):
    """nbclient starts the kernel in the notebook's folder; the client stays in the build's folder
    (plain ``--KernelManager.transport=ipc`` binds relative names there and never connects). Nothing is
    left behind in either folder or in the runtime folder."""
    notebook_dir, build_dir = tmp_path / "chapter", tmp_path / "build"
    notebook_dir.mkdir()
    build_dir.mkdir()
    monkeypatch.chdir(build_dir)
    km = ipc_kernels.BlockingIPCKernelManager(kernel_name="python3")
    km.start_kernel(cwd=str(notebook_dir))
    try:
        kc = km.client()
        kc.start_channels()
        kc.wait_for_ready(timeout=30)
        reply = kc.execute_interactive("import os; cwd = os.getcwd()", timeout=30,
                                       user_expressions={"cwd": "cwd"})
        assert reply["content"]["user_expressions"]["cwd"]["data"]["text/plain"] == repr(str(notebook_dir))
        kc.stop_channels()
    finally:
        km.shutdown_kernel(now=True)
    sockets = [f"{km.ip}-{port}" for port in km.ports]
    assert not [p for p in sockets + [km.connection_file] if os.path.exists(p)]
    assert not list(notebook_dir.iterdir()) and not list(build_dir.iterdir())


def test_a_missed_wakeup_costs_one_slice_not_the_timeout():
    """A channel whose first poll misses the message (as asyncio's zmq poll can) still returns it
    within one POLL_SLICE, long before the cell's timeout."""

    class Socket:
        def __init__(self):
            self.polls = 0

        async def poll(self, timeout_ms):
            self.polls += 1
            if self.polls == 1:  # the missed edge: sleep out the whole wait, then see nothing new
                await asyncio.sleep(timeout_ms / 1000)
                return 0
            return 1

    channel = ipc_kernels.SlicedChannel.__new__(ipc_kernels.SlicedChannel)
    channel.socket = Socket()

    async def recv():
        return {"msg_type": "execute_reply"}

    channel._recv = recv
    start = time.monotonic()
    message = asyncio.run(channel.get_msg(timeout=300))
    assert message["msg_type"] == "execute_reply"
    assert time.monotonic() - start < ipc_kernels.POLL_SLICE + 0.5


def test_sliced_wait_still_times_out():
    """With no message at all, the wait ends with Empty after the timeout asked for, not before."""

    class Silent:
        async def poll(self, timeout_ms):
            await asyncio.sleep(timeout_ms / 1000)
            return 0

    channel = ipc_kernels.SlicedChannel.__new__(ipc_kernels.SlicedChannel)
    channel.socket = Silent()
    start = time.monotonic()
    with pytest.raises(Exception) as raised:
        asyncio.run(channel.get_msg(timeout=1.5))
    assert raised.type.__name__ == "Empty"
    assert 1.4 < time.monotonic() - start < 2.5


def _notebook(path: Path) -> Path:
    nb = nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell(TRANSPORT_CELL)])
    nbformat.write(nb, path)
    return path


def test_nbval_route_uses_ipc(tmp_path):
    """`make test`'s notebook run (course.py's nbval arguments) gives its kernels the IPC transport."""
    sys.path.insert(0, str(ROOT))
    import course

    notebook = _notebook(tmp_path / "transport.ipynb")
    env = {**os.environ, "PYTHONPATH": os.pathsep.join([str(ROOT / "tools"), str(ROOT)])}
    done = subprocess.run([sys.executable, "-m", "pytest", *course.NBVAL_ARGS, "-q", str(notebook)],
                          cwd=ROOT, env=env, capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stdout[-2000:] + done.stderr[-2000:]


def test_nbconvert_route_uses_ipc(tmp_path):
    """`python course.py execute` (`make book-instructor`): nbconvert with course.NBCONVERT_ARGS."""
    sys.path.insert(0, str(ROOT))
    import course

    notebook = _notebook(tmp_path / "transport.ipynb")
    env = {**os.environ, "PYTHONPATH": str(ROOT / "tools")}
    subprocess.run([sys.executable, "-m", "jupyter", "nbconvert", "--to", "notebook", "--execute",
                    *course.NBCONVERT_ARGS, "--output", "run.ipynb", str(notebook)],
                   cwd=tmp_path, env=env, check=True, capture_output=True, timeout=120)
    outputs = nbformat.read(tmp_path / "run.ipynb", 4).cells[0].outputs
    assert [o.get("text") for o in outputs] == ["ipc\n"]


def test_book_route_uses_ipc():
    """book/conf.py, as Sphinx reads it, makes myst-nb's client start IPC kernels; a cell may run 60 s."""
    probe = ("import runpy, nbformat\n"
             "conf = runpy.run_path('book/conf.py')\n"
             "from nbclient import NotebookClient\n"
             "print(NotebookClient(nbformat.v4.new_notebook()).kernel_manager_class.__name__,"
             " conf['nb_execution_timeout'])")
    done = subprocess.run([sys.executable, "-c", probe], cwd=ROOT, capture_output=True, text=True,
                          check=True, timeout=60)
    name, timeout = done.stdout.split()
    assert name == "IPCKernelManager" and int(timeout) <= 60


def _kernel_clients_without_ipc(source: str) -> list[int]:
    """Lines of ``source`` that make a NotebookClient without naming its kernel manager class."""
    import ast

    calls = [node for node in ast.walk(ast.parse(source)) if isinstance(node, ast.Call)]
    return [call.lineno for call in calls
            if getattr(call.func, "id", getattr(call.func, "attr", None)) == "NotebookClient"
            and "kernel_manager_class" not in {k.arg for k in call.keywords}]


def test_every_notebook_client_of_the_project_starts_ipc_kernels():
    """A test that executes a notebook itself names the IPC kernel manager too: one that did not
    (tests_browser/test_book_helpers.py) waited out its 120 s cell timeout on a missed reply in CI."""
    assert _kernel_clients_without_ipc("NotebookClient(nb, timeout=5)") == [1]   # the check sees a plain one
    assert _kernel_clients_without_ipc("NotebookClient(nb, kernel_manager_class=K)") == []
    found = {str(path.relative_to(ROOT)): lines for folder in ("tests", "tests_browser", "tests_hub", "tools",
                                                               "mechlab", "book", "assignments")
             for path in (ROOT / folder).rglob("*.py") if ".nbgrader-deps" not in path.parts
             and (lines := _kernel_clients_without_ipc(path.read_text(encoding="utf-8")))}
    assert not found, found
