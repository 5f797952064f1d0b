"""One of each: no public name (a class or function not starting with "_") is defined in two modules of mechlab,
so that ``Structure``, ``check`` or ``drive`` mean one thing wherever a reader meets them. A re-export (the same
object under its old home) is no second definition."""

import collections
import importlib
import inspect
import pkgutil

import pytest

import mechlab

# public names defined in two modules on purpose: none (issue 26 renamed the eight pairs; the old names that an
# assignment still imports stay as aliases of the new object, which is no second definition)
KNOWN: dict[str, set[str]] = {}


def public_definitions() -> dict[str, set[str]]:
    """Each public class or function name of mechlab → the modules that define it (not merely import it)."""
    homes = collections.defaultdict(set)
    for info in pkgutil.walk_packages(mechlab.__path__, "mechlab."):
        module = importlib.import_module(info.name)
        for name, obj in vars(module).items():
            if name.startswith("_") or not (inspect.isclass(obj) or inspect.isfunction(obj)):
                continue
            if getattr(obj, "__module__", None) == info.name and obj.__qualname__ == name:
                homes[name].add(info.name)
    return homes


def test_no_public_name_is_defined_twice():
    twice = {name: homes for name, homes in public_definitions().items() if len(homes) > 1}
    new = {name: sorted(homes) for name, homes in twice.items() if KNOWN.get(name) != homes}
    assert not new, f"public names defined in two modules: {new}"
    stale = sorted(set(KNOWN) - set(twice))
    assert not stale, f"defined once now, drop from KNOWN: {stale}"


def test_one_structure():
    # the design layer's counts are Counts; Structure is the mechanism's description alone
    assert public_definitions()["Structure"] == {"mechlab.mechanisms.base"}
    assert public_definitions()["Counts"] == {"mechlab.design.criteria"}


def test_the_counts_old_name_still_works_and_warns():
    from mechlab import design

    with pytest.warns(DeprecationWarning, match="now mechlab.design.Counts"):
        old = design.Structure
    assert old is design.Counts


# the eight pairs renamed (issue 26): old home, old name → the new name in the same module
RENAMED = [("mechlab.validate", "check", "check_value"), ("mechlab.course.errata", "count", "count_by_kind"),
           ("mechlab.synthesis.dwell_slot", "base_law", "slotted_link_law"),
           ("mechlab.course.exercises", "Spec", "Requirement"),
           ("mechlab.course.exercises.design", "Spec", "Requirement"),
           ("mechlab.design", "Verdict", "LimitVerdict"), ("mechlab.design", "DesignReport", "SpecificationReport"),
           ("mechlab.design.candidates", "Verdict", "LimitVerdict"),
           ("mechlab.design.candidates", "DesignReport", "SpecificationReport")]


@pytest.mark.parametrize("module, old, new", RENAMED)
def test_a_renamed_name_still_works_for_a_release_and_warns(module, old, new):
    mod = importlib.import_module(module)
    with pytest.warns(DeprecationWarning, match=f"{module}.{old} is now .*{new}"):
        assert getattr(mod, old) is getattr(mod, new)


def test_names_the_assignments_import_stay_without_a_warning():
    # the geneva assignments import kinetostatics.geneva.drive and assignments/report.py selfcheck.candidates: a
    # warning would show in a student's cell, so these stay plain aliases until the assignments move
    import warnings

    geneva = importlib.import_module("mechlab.kinetostatics.geneva")
    selfcheck = importlib.import_module("mechlab.course.exercises.selfcheck")
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert geneva.drive is geneva.geneva_drive and selfcheck.candidates is selfcheck.slip_candidates
