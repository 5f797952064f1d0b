"""Kernels that talk over Unix sockets with unique absolute paths: no TCP port to race for.

Every notebook the project executes (nbval in ``make test``, myst-nb in ``make book`` and
``make pdf``, nbconvert in ``course.py execute`` and ``make book-instructor``) starts its kernels
through the classes here. Why: jupyter_client picks a kernel's five TCP ports by binding
port 0 and closing the socket, writes them into the connection file, and only then does the
kernel bind them. In that gap any other process on the machine (another build, another
kernel, any outgoing connection that gets an ephemeral port) can take one of them: the
kernel dies with ``ZMQError: Address already in use`` and its client waits out its start-up
timeout (jupyter/jupyter_client#276, #487; nteract/papermill#511). ``LocalPortCache`` only
keeps apart the kernels of one process.

A second stall has another cause: nbclient waits for a cell's reply with one
``await socket.poll(timeout)`` on the shell channel, and that asyncio poll can miss the
wake-up of a reply that has arrived (zmq's descriptor signals edges, not levels): the client
then sleeps until the cell's timeout, finds the reply in the poll that ends it, and goes on
as if nothing happened (jupyter/nbclient#312, jupyter/nbconvert#2003; the book's chapters that
took 300 s more than usual and then passed). ``SlicedAsyncKernelClient`` waits in slices of
``POLL_SLICE`` seconds, each ending in such a poll, so a missed wake-up costs at most that.

The IPC transport has no shared namespace to race in, provided the socket names are unique
and absolute. Plain ``--KernelManager.transport=ipc`` gives neither when no connection file
is named beforehand (nbval, nbclient): the sockets are then ``kernel-ipc-1`` … ``-5``
*relative to the working directory*, the same names for every kernel started there, and the
kernel (started in the notebook's folder) and its client (in the build's) look in different
folders. Here each kernel's connection file is named up front, ``kernel-<random>.json`` in
Jupyter's private runtime folder, and jupyter_client derives the socket names from it
(``kernel-<random>-ipc-1`` …); they are removed when the kernel shuts down.

Use:

* nbconvert, nbgrader: ``--NotebookClient.kernel_manager_class=ipc_kernels.IPCKernelManager``
  with this folder on ``PYTHONPATH``;
* pytest with nbval: ``-p ipc_kernels`` (this module is also a pytest plugin);
* in-process (Sphinx's conf.py): ``ipc_kernels.install()``.
"""

from __future__ import annotations

import os
import secrets
from queue import Empty
from time import monotonic

import zmq
from jupyter_client import AsyncKernelManager, KernelManager
from jupyter_client.asynchronous import AsyncKernelClient
from jupyter_client.channels import AsyncZMQSocketChannel
from jupyter_core.paths import jupyter_runtime_dir
from traitlets import CaselessStrEnum, HasTraits, Type, default

POLL_SLICE = 1.0  # seconds: the longest a reply that has arrived can go unnoticed
# A Unix socket's path holds at most 107 bytes (Linux; 103 on macOS); "-ipc-5" is appended
SOCKET_PATH_MAX = 100


def _runtime_dir() -> str:
    """Jupyter's runtime folder (private to the user), or a short one when its path is too long."""
    folder = jupyter_runtime_dir()
    if len(folder) + len("/kernel-0123456789ab-ipc-5") > SOCKET_PATH_MAX:
        folder = os.path.join("/tmp", f"jupyter-runtime-{os.getuid()}")  # POSIX: where ipc is used
    os.makedirs(folder, mode=0o700, exist_ok=True)
    return folder


class SlicedChannel(AsyncZMQSocketChannel):
    """A channel whose wait for a message never lasts more than ``POLL_SLICE`` without a fresh look."""

    async def get_msg(self, timeout: float | None = None) -> dict:
        deadline = None if timeout is None else monotonic() + timeout
        while True:
            left = None if deadline is None else max(0.0, deadline - monotonic())
            try:
                return await super().get_msg(timeout=POLL_SLICE if left is None else min(left, POLL_SLICE))
            except Empty:
                if left is not None and left <= POLL_SLICE:
                    raise


class SlicedAsyncKernelClient(AsyncKernelClient):
    """nbclient's kernel client with `SlicedChannel` for the shell, IOPub and control channels."""

    shell_channel_class = Type(SlicedChannel)
    iopub_channel_class = Type(SlicedChannel)
    control_channel_class = Type(SlicedChannel)


class _UniqueIPC(HasTraits):
    """IPC transport by default (where zmq has it: not every Windows build does); the connection file,
    hence the sockets, named before the start."""

    transport = CaselessStrEnum(["tcp", "ipc"], default_value="ipc" if zmq.has("ipc") else "tcp", config=True)

    @default("connection_file")
    def _unique_connection_file(self) -> str:
        return os.path.join(_runtime_dir(), f"kernel-{secrets.token_hex(6)}.json")


class IPCKernelManager(_UniqueIPC, AsyncKernelManager):
    """nbclient's kernel manager (nbconvert, myst-nb, nbgrader): unique Unix sockets, sliced waits.

    Examples
    --------
    >>> km = IPCKernelManager()
    >>> km.transport, os.path.isabs(km.ip), km.ip.endswith("-ipc")
    ('ipc', True, True)
    """

    @default("client_factory")
    def _sliced_client(self) -> type:
        return SlicedAsyncKernelClient


class BlockingIPCKernelManager(_UniqueIPC, KernelManager):
    """The blocking kernel manager (nbval's) over unique Unix sockets."""


def install() -> None:
    """Make nbclient and nbval in this process start their kernels through the classes above."""
    from nbclient import NotebookClient

    def ipc_default(self):
        return IPCKernelManager

    # traitlets copies a dynamic default into every subclass made so far (myst-nb's, nbconvert's)
    classes = [NotebookClient]
    while classes:
        cls = classes.pop()
        cls._kernel_manager_class_default = ipc_default
        cls._all_trait_default_generators["kernel_manager_class"] = ipc_default
        classes.extend(cls.__subclasses__())
    try:
        import nbval.kernel
    except ImportError:  # the book's part has no nbval
        return
    nbval.kernel.KernelManager = BlockingIPCKernelManager


def pytest_configure(config) -> None:
    """As a pytest plugin (``-p ipc_kernels``): nbval's kernels over unique Unix sockets."""
    install()
