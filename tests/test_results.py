"""One result convention (frozen dataclasses, no dict or named tuple in the public API) and scalar in,
scalar out for every public function and method that takes crank angles φ."""

from __future__ import annotations

import dataclasses
import inspect
import numbers

import numpy as np
import pytest
from test_fuzz import CASES, PHI

import mechlab as ml
from mechlab.analysis.centres.instant import CentreModel
from mechlab.geometry import PointPath

DEG = np.pi / 180


def _takes_phi(f) -> bool:
    return "phi" in inspect.signature(inspect.unwrap(f)).parameters


def _leaves(value, path="result"):
    """(path, value) of every number and array a result holds, through its paths, motions and dataclass
    fields; a mechanism or structure the result only carries along is left out."""
    if isinstance(value, (ml.Mechanism, CentreModel)) or value is None or isinstance(value, str):
        return
    if isinstance(value, (numbers.Number, np.ndarray, np.generic)):
        yield path, value
    elif isinstance(value, PointPath):
        yield from ((f"{path}.{k}", v) for k, v in zip(("p", "d", "dd"), value, strict=False))
    elif isinstance(value, dict):
        for k, v in value.items():
            yield from _leaves(v, f"{path}[{k!r}]")
    elif isinstance(value, (list, tuple)):
        for i, v in enumerate(value):
            yield from _leaves(v, f"{path}[{i}]")
    elif dataclasses.is_dataclass(value):
        for f in dataclasses.fields(value):
            if f.name.startswith("_"):   # a cache, filled on first use
                continue
            yield from _leaves(getattr(value, f.name), f"{path}.{f.name}")


def _assert_scalar_version(one, many, k):
    """``one`` (at the scalar PHI[k]) is ``many`` (over PHI) at row k, one dimension down."""
    a, b = dict(_leaves(one)), dict(_leaves(many))
    assert a.keys() == b.keys()
    for key, v in a.items():
        w = b[key]
        if np.ndim(w) >= 1 and len(w) == len(PHI):
            assert np.ndim(v) == np.ndim(w) - 1, f"{key}: shape {np.shape(v)} at a scalar φ"
            assert np.allclose(v, w[k], atol=1e-9, equal_nan=True), key
        else:   # a summary over the angles (a residual, a count): no row of one
            assert np.ndim(v) == np.ndim(w), key


def _phi_per_angle(name) -> bool:
    # a function of crank angles φ, not one that takes samples of a turn to integrate (drive)
    f, args, kwargs = CASES[name]()
    return _takes_phi(f) and any(a is PHI for a in (*args, *kwargs.values()))


PHI_CASES = sorted(n for n in CASES if _phi_per_angle(n))


def test_the_functions_taking_phi_are_found():
    assert {"relative_path", "other_half", "instant_centres", "base_law", "formula_18", "DwellLaw.curvature",
            "FourBar.motion"} <= set(PHI_CASES)


@pytest.mark.parametrize("name", PHI_CASES)
def test_every_public_function_taking_phi_gives_scalars_for_a_scalar(name):
    f, args, kwargs = CASES[name]()
    where = "args" if any(a is PHI for a in args) else "kwargs"
    if where == "args":
        i = next(i for i, a in enumerate(args) if a is PHI)
        def call(phi):
            return f(*args[:i], phi, *args[i + 1:], **kwargs)
    else:
        def call(phi):
            return f(*args, **{**kwargs, "phi": phi})
    many = call(PHI)
    for k in (0, 3):
        _assert_scalar_version(call(float(PHI[k])), many, k)


DWELL_LAW_METHODS = ("half", "__call__", "in_dwell", "S", "beta", "slot_points", "pressure_angle", "curvature")


@pytest.mark.parametrize("method", DWELL_LAW_METHODS)
def test_dwell_law_methods_give_scalars_for_a_scalar(method):
    law = ml.DwellLaw(0.5, 60 * DEG, 150 * DEG)
    phi = np.linspace(0.2, 3.0, len(PHI))   # the designed half [0, π], which half() and beta() take
    f = getattr(law, method)
    many = f(phi)
    for k in (0, 3, 6):
        one = f(float(phi[k]))
        for (key, v), (_, w) in zip(_leaves(one), _leaves(many), strict=False):
            assert np.ndim(v) == np.ndim(w) - 1, f"{method}: {key} has shape {np.shape(v)} at a scalar φ"
            assert np.allclose(v, w[k], atol=1e-12), key


def test_instant_centres_at_a_scalar_phi():
    """The coupler's pole P24 of the four-bar (1, 3, 3, 4) at φ = 60°: OA ∩ BE, and ψ' read from the centres."""
    fb = ml.FourBar(1.0, 3.0, 3.0, 4.0)
    ic, ics = ml.instant_centres(fb, 60 * DEG), ml.instant_centres(fb, [60 * DEG])
    assert np.ndim(ic.phi) == 0 and ic("coupler", "frame").xy.shape == (2,)
    assert np.allclose(ic("coupler", "frame").xy, ics("coupler", "frame").xy[0], atol=1e-12)
    assert np.ndim(ic.output_analog()) == 0 and ic.output_analog() == pytest.approx(fb.motion(60 * DEG).dpsi, abs=1e-12)
    assert ic.velocity_analog("coupler", (1.0, 0.0)).shape == (2,) and len(ic("crank", "frame")) == 1


# ----------------------------------------------------------------------------------------------
# one result convention
# ----------------------------------------------------------------------------------------------
def _is_loose(value) -> bool:
    """A dict or a named tuple: what the public API no longer returns (frozen dataclasses and ml.Table do)."""
    return isinstance(value, dict) or (isinstance(value, tuple) and hasattr(value, "_fields"))


def _annotation_is_loose(f) -> bool:
    ann = inspect.signature(f).return_annotation
    text = ann if isinstance(ann, str) else getattr(ann, "__name__", str(ann))
    return text.startswith(("dict", "Dict", "Mapping", "NamedTuple")) or (
        inspect.isclass(ann) and issubclass(ann, tuple) and hasattr(ann, "_fields"))


@pytest.mark.parametrize("name", sorted(CASES))
def test_no_public_callable_returns_a_dict_or_a_named_tuple(name):
    f, args, kwargs = CASES[name]()
    assert not _is_loose(f(*args, **kwargs)), f"{name} returns a {type(f(*args, **kwargs)).__name__}"


def test_no_public_name_is_or_is_annotated_as_a_dict_or_a_named_tuple():
    loose = []
    for name in ml.__all__:
        obj = getattr(ml, name)
        if inspect.ismodule(obj):
            continue
        named_tuple = inspect.isclass(obj) and issubclass(obj, tuple) and hasattr(obj, "_fields")
        if _is_loose(obj) or named_tuple or (callable(obj) and not inspect.isclass(obj) and _annotation_is_loose(obj)):
            loose.append(name)
    assert loose == []
    # the results named in the issue, as they are now
    assert isinstance(ml.TABLE1_PRINTED, ml.Table) and ml.TABLE1_PRINTED.by("z")[6].alpha0 == 53.15
    assert isinstance(ml.motion_laws.thesis_cam_rows(), ml.Table)
    assert dataclasses.is_dataclass(ml.motion_laws.rise_invariants(np.linspace(0, 1, 5), np.linspace(0, 1, 5),
                                                                   np.ones(5), np.zeros(5)))
    from mechlab.geometry import AnglePath
    assert dataclasses.is_dataclass(AnglePath) and not issubclass(AnglePath, tuple)
    theta, d, dd = ml.base_law(ml.FourBar(1, 3, 3, 4), 0.3)     # unpacks like (θ, θ', θ'')
    assert np.ndim(theta) == np.ndim(d) == np.ndim(dd) == 0


def test_read_csv_gives_named_columns():
    cols = ml.read_csv("x,y\n1,2\n3,4\n")
    assert dataclasses.is_dataclass(cols) and cols.names == ("x", "y")
    assert np.array_equal(cols["y"], [2.0, 4.0])
    with pytest.raises(KeyError, match="no column 'z'; the file has x, y"):
        cols["z"]


def test_no_named_tuple_class_in_the_library():
    """Results of methods too (Undercut, AnglePath were named tuples): no class of mechlab is one."""
    import importlib
    import pkgutil
    found = []
    for info in pkgutil.walk_packages(ml.__path__, "mechlab."):
        if info.name.startswith(("mechlab.widgets", "mechlab.draw")):
            continue   # they import the plotting stack; they define no results
        module = importlib.import_module(info.name)
        found += [f"{info.name}.{k}" for k, v in vars(module).items()
                  if inspect.isclass(v) and v.__module__ == info.name and issubclass(v, tuple)
                  and hasattr(v, "_fields")]
    assert found == []


def _method_objects():
    from test_textbook import FAMILIES
    objects = {name: make() for name, make in FAMILIES.items()}
    programme = ml.CamProgramme(20.0, 120 * DEG, 100 * DEG, 40 * DEG, law="cycloidal (sine)")
    objects["CamProgramme"] = programme
    objects["TranslatingRollerCam"] = ml.TranslatingRollerCam(programme, 40.0, 10.0, offset=8.0)
    objects["OscillatingRollerCam"] = ml.OscillatingRollerCam(
        ml.CamProgramme(20 * DEG, 120 * DEG, 100 * DEG, 40 * DEG), 40.0, 8.0, pivot_distance=90.0, arm=70.0)
    return objects


def _phi_methods():
    for name, obj in _method_objects().items():
        for attr in dir(obj):
            if attr.startswith("_") and attr != "__call__":
                continue
            f = getattr(type(obj), attr, None)
            if not callable(f) or isinstance(f, type):
                continue
            params = list(inspect.signature(inspect.unwrap(f)).parameters.values())[1:]
            required = [p.name for p in params if p.default is p.empty and p.kind is p.POSITIONAL_OR_KEYWORD]
            if required == ["phi"]:
                yield f"{name}.{attr}"


PHI_METHODS = sorted(set(_phi_methods()))


def test_the_methods_taking_phi_are_found():
    assert {"FourBar.motion", "ExternalGeneva.engaged", "CurvedSlotLink.beta", "TranslatingRollerCam.pressure_angle",
            "CamProgramme.__call__"} <= set(PHI_METHODS)


@pytest.mark.parametrize("name", PHI_METHODS)
def test_every_public_method_taking_phi_gives_scalars_for_a_scalar(name):
    obj_name, attr = name.split(".")
    obj = _method_objects()[obj_name]
    f = getattr(obj, attr)
    phi = obj.cycle(9)[1:-1] if hasattr(obj, "cycle") else np.linspace(0.3, 6.0, 7)
    if inspect.signature(inspect.unwrap(f)).parameters["phi"].annotation == "float":   # one angle only
        assert not isinstance(f(float(phi[1])), np.ndarray)
        return
    many = f(phi)
    for k in (1, 4):
        one = f(float(phi[k]))
        for (key, v), (_, w) in zip(_leaves(one), _leaves(many), strict=False):
            if np.ndim(w) >= 1 and len(w) == len(phi):
                assert np.ndim(v) == np.ndim(w) - 1, f"{name}: {key} has shape {np.shape(v)} at a scalar φ"
                assert np.allclose(v, w[k], atol=1e-9), key
