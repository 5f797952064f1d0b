"""Exceptions in one module and one tree: every exception class of mechlab is defined in mechlab.errors and
derives from MechanismError (a ValueError), the one type a widget catches; the modules that raised them
before still export them under their old names."""

import importlib
import inspect
import pkgutil

import pytest

import mechlab
from mechlab import errors

# defined elsewhere on purpose, with the reason; a stale entry fails
ELSEWHERE = {
    "mechlab.course.exercises.feedback.NotYet": "an AssertionError: nbgrader's signal that a check failed, not an "
                                                "error of the library",
}

OLD_HOMES = {
    "mechlab.design.spec": ["SpecificationError"],
    "mechlab.design.families": ["Unsuitable"],
    "mechlab.design": ["Unsuitable"],
    "mechlab.kinetostatics.model": ["MassError", "FrictionError", "LoadError", "StructureError", "SelfLockingError"],
    "mechlab.kinetostatics.drive": ["DriveError"],
    "mechlab.mechanisms.spherical_geneva": ["SpatialMechanismError"],
    "mechlab.mechanisms.cam": ["CamUndercutError"],
    "mechlab.mechanisms.geneva": ["SlotCountError", "OffsetError"],
    "mechlab.synthesis.slot_export": ["SlotUndercutError"],
    "mechlab.synthesis.dwell_slot": ["DwellError", "DwellIntervalError", "DwellRatioError"],
    "mechlab.analysis.centres.homogeneous": ["CentreAtInfinity", "IndeterminateCentre"],
}


def exception_classes():
    """Every exception class defined in a module of mechlab, as {"module.Class": class}."""
    found = {}
    for info in pkgutil.walk_packages(mechlab.__path__, "mechlab."):
        module = importlib.import_module(info.name)
        for name, obj in vars(module).items():
            if inspect.isclass(obj) and issubclass(obj, BaseException) and obj.__module__ == info.name:
                found[f"{info.name}.{name}"] = obj
    return found


def test_every_exception_is_defined_in_errors():
    found = exception_classes()
    outside = sorted(k for k in found if not k.startswith("mechlab.errors.") and k not in ELSEWHERE)
    assert not outside, f"exception classes outside mechlab/errors.py: {outside}"
    assert not set(ELSEWHERE) - set(found), "a stale exemption"
    assert len([k for k in found if k.startswith("mechlab.errors.")]) >= 25


def test_every_exception_derives_from_the_root():
    classes = [c for c in vars(errors).values() if inspect.isclass(c) and issubclass(c, BaseException)]
    assert all(issubclass(c, errors.MechanismError) for c in classes), \
        [c.__name__ for c in classes if not issubclass(c, errors.MechanismError)]
    assert issubclass(errors.MechanismError, ValueError)


@pytest.mark.parametrize("module", sorted(OLD_HOMES))
def test_old_homes_still_export_them(module):
    mod = importlib.import_module(module)
    for name in OLD_HOMES[module]:
        assert getattr(mod, name) is getattr(errors, name)


def test_a_design_refusal_is_a_mechanism_error():
    from mechlab.design import Unsuitable

    with pytest.raises(mechlab.MechanismError):
        raise Unsuitable("the family cannot meet it")
