import os

import matplotlib
from hypothesis import settings

matplotlib.use("Agg")

# `make test` draws the same examples every run, so a red run can be re-run and debugged and
# CI never fails on a case that no one has seen; HYPOTHESIS_PROFILE=explore draws new ones:
# run it when changing the library, and pin what it finds with @example.
settings.register_profile("repeatable", derandomize=True, print_blob=True)
settings.register_profile("explore", print_blob=True)
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "repeatable"))
