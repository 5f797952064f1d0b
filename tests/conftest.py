import atexit
import gc
import os

import matplotlib
import pytest
from hypothesis import settings

matplotlib.use("Agg")

# `make test` draws the same examples every run, so a red run can be re-run and debugged and
# CI never fails on a case that no one has seen; HYPOTHESIS_PROFILE=explore draws new ones:
# run it when changing the library, and pin what it finds with @example.
settings.register_profile("repeatable", derandomize=True, print_blob=True)
settings.register_profile("explore", print_blob=True)
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "repeatable"))

# When pytest is done (its last garbage collection included), everything left lives until the process ends: frozen,
# it is not scanned again by each of the garbage collections of the interpreter's shutdown, which took seconds per
# thousand tests (the heap of a whole run is large), on the critical path of `make test`
atexit.register(gc.freeze)


@pytest.fixture(autouse=True)
def _no_ipython_shell_left_behind():
    """A test that makes IPython's InteractiveShell (the alt-text tests, docstring examples) leaves none behind: while
    one lives, every static explorer's redraw goes through its display formatter and prints a PNG (0.2–1 s a
    control), which made the widget tests after tests/test_a11y.py 5–40× slower (135 s instead of 23)."""
    yield
    from IPython.core.interactiveshell import InteractiveShell

    if InteractiveShell.initialized():
        InteractiveShell.clear_instance()
