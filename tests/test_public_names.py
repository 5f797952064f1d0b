"""One of each: no public name (a class or function not starting with "_") is defined in two modules of mechlab,
so that ``Structure``, ``check`` or ``drive`` mean one thing wherever a reader meets them. A re-export (the same
object under its old home) is no second definition."""

import collections
import importlib
import inspect
import pkgutil

import pytest

import mechlab

# defined twice today, each awaiting its rename or merge (issue 26); a stale entry fails, a new pair fails
KNOWN = {
    "DesignReport": {"mechlab.course.exercises.design", "mechlab.design.candidates"},   # two spec checkers: one to go
    "Verdict": {"mechlab.course.exercises.feedback", "mechlab.design.candidates"},
    "Spec": {"mechlab.course.exercises.design", "mechlab.validate"},
    "candidates": {"mechlab.course.exercises.selfcheck", "mechlab.design.candidates"},
    "base_law": {"mechlab.analysis.equivalence", "mechlab.synthesis.dwell_slot"},   # two signatures; chapters 2-3 import one
    "check": {"mechlab.course.exercises.feedback", "mechlab.validate"},
    "count": {"mechlab.course.errata", "mechlab.validate"},
    "drive": {"mechlab.kinetostatics.drive", "mechlab.kinetostatics.geneva"},
}


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
