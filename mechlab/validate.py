"""One declarative validation layer for every public input of mechlab.

A parameter declares its kind once, in its annotation: ``crank: Length``,
``n: Samples = 361``, ``lam: Annotated[float, number(0, 1, open=True)]``. Two
enforcers read the declarations: :class:`Checked` (a frozen dataclass's fields, in
``__post_init__``; :class:`~mechlab.mechanisms.Mechanism` is one) and the decorator
:func:`validated` (a function's arguments). A rejected value raises
:class:`~mechlab.errors.DimensionError` (or the declared subclass) whose message names
the parameter and the violated condition with the numbers; an object of the wrong
kind where a mechanism is expected raises TypeError naming what was expected.

Numbers: Python and numpy ints, floats and bools are accepted; complex values (even
with a zero imaginary part), strings, None (unless declared ``optional``: None then
means "off" or "the documented default"), NaN and ±inf are refused; magnitudes stay
within ``MAGNITUDE`` so squares and products neither overflow nor underflow. Counts
are whole, positive and bounded by a named limit (no MemoryError, no hang).
"""

from __future__ import annotations

import dataclasses
import functools
import inspect
import numbers
import os
import sys
from dataclasses import dataclass, fields
from typing import Annotated, Any, get_args, get_origin

import numpy as np

from .errors import DimensionError, renamed

# Lengths and other magnitudes beyond these overflow or underflow in the solvers' squares and products.
MAGNITUDE = (1e-100, 1e100)
# Samples a single call may allocate: 2·10⁶ crank angles (16 MB per array; 360,000 is the benchmark).
MAX_SAMPLES = 2_000_000
# Points per side of a square grid evaluated point by point (each point a small solve).
MAX_GRID = 400
# Slots of a Geneva wheel.
MAX_SLOTS = 1000


@dataclass(frozen=True)
class Spec:
    """What a parameter may be: ``kind`` with its bounds and its None policy.

    Parameters
    ----------
    kind : str
        "number" (real), "length" (> 0, or ≥ 0 with ``zero``), "angle" (radians), "count" (whole), "sign"
        (±1), "choice" (one of ``options``), "flag" (bool), "point" (a 2-vector), "points" (an (m, width)
        array, m ≥ lo), "mechanism" (an instance of ``expected``), "items" (a sequence of instances of
        ``expected``, made a tuple), "text" (a non-empty str), "function", "samples" (a 1-D array of at least
        ``lo`` finite numbers), "path" (a str or os.PathLike), "angles" (crank angles: a scalar or a 1-D array
        of at least ``lo``, radians), "reals" (a number or an array, each value within [lo, hi]), "radians"
        (as "reals", angles: the bounds shown in degrees too).
    lo, hi : float, optional
        Bounds (for "count", "points", "samples", "angles": the least and largest number).
    open_lo, open_hi : bool, optional
        Exclude the lower or the upper bound.
    optional : bool, optional
        Whether None is accepted (and passed through).
    options : tuple, optional
        The admissible values of a "choice" (or of a "sign", as (name, value) pairs).
    expected : type or tuple of type, optional
        The class(es) of a "mechanism" or of the "items".
    error : type, optional
        The exception raised on a violation.
    why : str, optional
        Appended to a range violation's message.
    function_ok : bool, optional
        Whether a function of the motion may stand for the value (a load, an axis).
    width : int, optional
        Columns of "points": 2 for (x, y), 3 for homogeneous (x, y, w).

    Examples
    --------
    >>> Spec("length", 0.0, open_lo=True).check("rod", 3)
    3.0
    """

    kind: str
    lo: float | None = None
    hi: float | None = None
    open_lo: bool = False
    open_hi: bool = False
    optional: bool = False
    options: tuple = ()
    expected: Any = None
    error: type = DimensionError
    why: str = ""
    function_ok: bool = False  # a function of the motion may stand for the value (a load, an axis)
    width: int = 2  # columns of "points": 2 for (x, y), 3 for homogeneous (x, y, w)

    def check(self, name: str, value):
        """``value`` converted (float, int, tuple) or the declared error naming ``name``.

        Parameters
        ----------
        name : str
            The parameter's name, for the message.
        value : object
            The value to check.

        Returns
        -------
        object
            The converted value (None for an optional None; a function when ``function_ok``).

        Raises
        ------
        DimensionError
            Or the declared ``error``, naming ``name``, the condition and the value.

        Examples
        --------
        >>> length().check("rod", -1)
        Traceback (most recent call last):
        ...
        mechlab.errors.DimensionError: rod must be > 0, got -1
        """
        if value is None and self.optional:
            return None
        if self.function_ok and callable(value):
            return value
        return _CHECKERS[self.kind](self, name, value)

    def fail(self, name: str, condition: str, value, *, explain: bool = True):
        """Raise the declared error; ``why`` explains a violated range, not a value of the wrong type.

        Parameters
        ----------
        name : str
            The parameter's name.
        condition : str
            What the value must be, e.g. "> 0".
        value : object
            The value given.
        explain : bool, optional
            Whether to append ``why``.

        Raises
        ------
        DimensionError
            Or the declared ``error``: "``name`` must be ``condition``, got ``value``".

        Examples
        --------
        >>> Spec("number").fail("x", "positive", -1)
        Traceback (most recent call last):
        ...
        mechlab.errors.DimensionError: x must be positive, got -1
        """
        hint = f" ({self.why})" if self.why and explain else ""
        raise self.error(f"{name} must be {condition}, got {_show(value)}{hint}")


class _Shown(str):
    """A description shown as it is (not repr'd) in a message."""


def _show(value) -> str:
    if isinstance(value, _Shown):
        return str(value)
    if isinstance(value, float | np.floating):
        return f"{float(value):g}"
    if isinstance(value, int | np.integer) and abs(int(value)) >= 10**20:
        return f"an integer of {len(str(abs(int(value))))} digits"
    text = repr(value)
    return text if len(text) <= 60 else text[:57] + "..."


def _real(spec: Spec, name: str, value) -> float:
    """A real scalar as a finite float within MAGNITUDE, refusing by name everything else."""
    if isinstance(value, np.ndarray) and value.ndim == 0:
        value = value[()]
    if isinstance(value, complex | np.complexfloating):
        spec.fail(name, "a real number (complex values are not accepted)", value, explain=False)
    if isinstance(value, str | bytes) or value is None or not isinstance(value, numbers.Real | np.bool_):
        what = _Shown(f"an array of shape {np.shape(value)}") if isinstance(value, np.ndarray | list | tuple) \
            else value
        spec.fail(name, "a number", what, explain=False)
    try:
        x = float(value)
    except OverflowError:
        _magnitude(spec, name, _show(value))
    if not np.isfinite(x):
        spec.fail(name, "finite", x, explain=False)
    if abs(x) > MAGNITUDE[1]:
        _magnitude(spec, name, f"{x:g}")
    return x


def _magnitude(spec: Spec, name: str, shown: str):
    raise spec.error(f"{name} = {shown} lies outside the supported magnitudes [{MAGNITUDE[0]:g}, {MAGNITUDE[1]:g}] "
                     f"(use mm or lengths relative to one link)")


def _plain(v: float) -> str:
    return f"{v:g}"


def _in_radians(v: float) -> str:
    return f"{v:.6g} rad ({np.degrees(v):.6g}°)"


def _reals(spec: Spec, name: str, value, unit=_plain):
    """A real number, or an array of them (one per crank angle), each within the declared bounds."""
    if not isinstance(value, np.ndarray | list | tuple):
        x = _real(spec, name, value)
        _bounds(spec, name, x, unit)
        return x
    arr = np.asarray(value) if not isinstance(value, list | tuple) or value else np.zeros(0)
    if arr.dtype.kind not in "biuf":
        spec.fail(name, "a number or an array of real numbers", _Shown(f"an array of dtype {arr.dtype}"),
                  explain=False)
    arr = arr.astype(float)
    if not arr.size:
        return arr
    least, most = arr.min(), arr.max()  # two passes without temporaries; NaN propagates to both
    if not -MAGNITUDE[1] <= least <= most <= MAGNITUDE[1]:  # NaN compares False
        spec.fail(name, f"finite, of magnitude ≤ {MAGNITUDE[1]:g}", arr[~(np.abs(arr) <= MAGNITUDE[1])][0],
                  explain=False)
    for limit in _limits(spec):
        if _breaks(least, *limit) or _breaks(most, *limit):
            _outside(spec, name, arr, _breaks(arr, *limit), _condition(*limit, unit))
    return arr


def _radians(spec: Spec, name: str, value):
    return _reals(spec, name, value, _in_radians)


def _outside(spec: Spec, name: str, arr: np.ndarray, bad: np.ndarray, condition: str):
    """Refuse ``arr``, showing (the first four of) its values where ``bad``, which break ``condition``."""
    values = arr[bad]
    shown = ", ".join(f"{v:g}" for v in values[:4]) + (", …" if values.size > 4 else "")
    spec.fail(name, condition, _Shown(f"{shown} ({values.size} of {arr.size} values)" if arr.size > 1 else shown))


def _limits(spec: Spec) -> tuple:
    """The declared bounds as (bound, strict, lower)."""
    return (((spec.lo, spec.open_lo, True),) if spec.lo is not None else ()) + \
        (((spec.hi, spec.open_hi, False),) if spec.hi is not None else ())


def _breaks(x, bound, strict, lower):
    """Where x (a value or an array) breaks the bound."""
    if lower:
        return x <= bound if strict else x < bound
    return x >= bound if strict else x > bound


def _condition(bound, strict, lower, unit) -> str:
    return f"{('>' if strict else '≥') if lower else ('<' if strict else '≤')} {unit(bound)}"


def _bounds(spec: Spec, name: str, x: float, unit=_plain) -> None:
    for limit in _limits(spec):
        if _breaks(x, *limit):
            spec.fail(name, _condition(*limit, unit), x)


def _number(spec, name, value):
    x = _real(spec, name, value)
    _bounds(spec, name, x)
    return x


def _length(spec, name, value):
    x = _real(spec, name, value)
    _bounds(spec, name, x)
    if 0 < x < MAGNITUDE[0] and spec.open_lo:  # a positive length divides somewhere; one that may be 0 never does
        _magnitude(spec, name, f"{x:g}")
    return x


def _angle(spec, name, value):
    x = _real(spec, name, value)
    _bounds(spec, name, x, unit=_in_radians)
    return x


def _count(spec, name, value):
    whole = f"a whole number ≥ {spec.lo}"
    if isinstance(value, bool | np.bool_) or not isinstance(value, numbers.Real):
        spec.fail(name, whole, value, explain=False)
    if isinstance(value, numbers.Integral):
        k = int(value)
    else:
        x = _real(spec, name, value)
        if x != round(x):
            spec.fail(name, whole, x)
        k = int(x)
    if k < spec.lo:
        spec.fail(name, whole, k)
    if k > spec.hi:
        spec.fail(name, f"≤ {spec.hi:,} (mechlab's limit for one call)", k, explain=False)
    return k


def _sign(spec, name, value):
    """+1 or -1, or one of the names in ``options`` ((name, sign) pairs, e.g. ("open", 1))."""
    names = dict(spec.options)
    if isinstance(value, str) and value in names:
        return names[value]
    if not isinstance(value, numbers.Real | np.bool_) or isinstance(value, bool | np.bool_) or value not in (1, -1):
        spec.fail(name, " or ".join(["+1", "-1"] + [f"{k!r} (= {v:+d})" for k, v in names.items()]), value)
    return int(value)


def _choice(spec, name, value):
    if not isinstance(value, str | int) or isinstance(value, bool) or value not in spec.options:
        spec.fail(name, "one of " + ", ".join(repr(o) for o in spec.options), value)
    return value


def _flag(spec, name, value):
    if not isinstance(value, bool | np.bool_):
        spec.fail(name, "True or False", value)
    return bool(value)


def _point(spec, name, value):
    if isinstance(value, str | bytes) or np.ndim(value) != 1 or len(value) != 2:
        spec.fail(name, "a point (x, y)", value)
    return tuple(_real(spec, f"{name}[{i}]", v) for i, v in enumerate(value))


def _points(spec, name, value):
    arr = np.asarray(value) if not isinstance(value, str | bytes) and value is not None else np.asarray(0.0)
    if arr.dtype.kind not in "biuf" or arr.ndim != 2 or arr.shape[1] != spec.width or len(arr) < spec.lo:
        spec.fail(name, f"an (m, {spec.width}) array of real coordinates with m ≥ {spec.lo}",
                  f"shape {arr.shape}, dtype {arr.dtype}" if isinstance(value, np.ndarray | list | tuple) else value)
    arr = arr.astype(float)
    if not np.all(np.abs(arr) <= MAGNITUDE[1]):  # NaN compares False
        spec.fail(name, f"finite, of magnitude ≤ {MAGNITUDE[1]:g}", arr[~(np.abs(arr) <= MAGNITUDE[1])][0])
    return arr


def _text(spec, name, value):
    if not isinstance(value, str) or not value:
        spec.fail(name, "a non-empty name (str)", value, explain=False)
    return value


def _function(spec, name, value):
    if not callable(value):
        raise TypeError(f"{name} must be a function, got {type(value).__name__} {_show(value)}")
    return value


def _items(spec, name, value):
    if isinstance(value, str | bytes | np.ndarray) or not isinstance(value, tuple | list):
        raise TypeError(f"{name} must be a tuple of {_names(spec.expected)}, got {type(value).__name__} "
                        f"{_show(value)}")
    for i, item in enumerate(value):
        if not isinstance(item, spec.expected):
            raise TypeError(f"{name}[{i}] must be a {_names(spec.expected)}, got {type(item).__name__} {_show(item)}")
    return tuple(value)


def _names(expected) -> str:
    if isinstance(expected, type):
        return expected.__name__
    names = [t.__name__ for t in expected]
    return ", ".join(names[:-1]) + " or " + names[-1]


def _angles(spec, name, value) -> np.ndarray:
    """Crank angles (radians) as a 1-D float array of at least ``lo`` angles; a scalar becomes an array of one."""
    arr = value if isinstance(value, np.ndarray) else np.asarray(value if value is not None else "None")
    if arr.dtype.kind not in "biuf":
        if arr.dtype.kind != "O":
            raise spec.error(f"crank angles must be real numbers (radians): {name} = {_show(value)}"
                             + (" (complex values are not accepted)" if arr.dtype.kind == "c" else ""))
        arr = np.array([_real(spec, name, v) for v in arr.ravel()]).reshape(arr.shape)
    arr = np.atleast_1d(np.asarray(arr, dtype=float))
    if arr.ndim != 1:
        raise spec.error(f"crank angles must be a scalar or a 1-D array: {name} has shape {arr.shape}")
    if len(arr) < spec.lo:
        raise spec.error(f"{name} must hold at least {spec.lo:g} crank angle(s), got {len(arr)}")
    if not np.all(np.abs(arr) <= MAGNITUDE[1]):  # one pass: NaN compares False, so this also catches NaN
        bad = arr[~(np.abs(arr) <= MAGNITUDE[1])][0]
        raise spec.error(f"crank angles must be finite, of magnitude ≤ {MAGNITUDE[1]:g}: {name} holds {bad:g}")
    return arr


def _path(spec, name, value):
    if not isinstance(value, str | os.PathLike):
        raise TypeError(f"{name} must be a file path (str or pathlib.Path), got {type(value).__name__} {_show(value)}")
    return value


def _samples(spec, name, value):
    arr = np.asarray(value) if not isinstance(value, str | bytes) and value is not None else np.asarray("x")
    if arr.dtype.kind not in "biuf" or arr.ndim != 1 or len(arr) < spec.lo:
        spec.fail(name, f"a 1-D array of at least {spec.lo} real numbers",
                  f"shape {arr.shape}, dtype {arr.dtype}" if isinstance(value, np.ndarray | list | tuple) else value,
                  explain=False)
    if spec.hi is not None and len(arr) > spec.hi:
        spec.fail(name, f"at most {spec.hi:,} values (mechlab's limit for one call)", _Shown(f"{len(arr):,}"),
                  explain=False)
    arr = arr.astype(float)
    if not np.all(np.isfinite(arr)):  # samples of a result (a torque), not sizes: any finite magnitude
        spec.fail(name, "finite (got NaN or inf)", arr[~np.isfinite(arr)][0], explain=False)
    return arr


def _mechanism(spec, name, value):
    if not isinstance(value, spec.expected):
        hint = f" ({spec.why})" if spec.why else ""
        raise spec.error(f"{name} must be a {_names(spec.expected)}, got {type(value).__name__} {_show(value)}{hint}")
    return value


_CHECKERS = {"number": _number, "length": _length, "angle": _angle, "count": _count, "sign": _sign,
             "choice": _choice, "flag": _flag, "point": _point, "points": _points, "mechanism": _mechanism,
             "items": _items, "text": _text, "function": _function, "samples": _samples,
             "path": _path, "angles": _angles, "reals": _reals, "radians": _radians}


# -- declarations ------------------------------------------------------------------------------------------
def number(lo=None, hi=None, *, open: bool = False, optional: bool = False, error=DimensionError, why=""):
    """A real number, within [lo, hi] (or (lo, hi) with ``open``).

    Parameters
    ----------
    lo, hi : float, optional
        The bounds (None: unbounded).
    open : bool, optional
        Exclude the bounds.
    optional : bool, optional
        Whether None is accepted (and passed through).
    error : type, optional
        The exception raised on a violation (a mechlab.errors class).
    why : str, optional
        Appended to a range violation's message, to say why the range holds.

    Returns
    -------
    Spec
        The declaration, for ``Annotated[type, spec]`` or :func:`check_value`.

    Examples
    --------
    >>> number(0, 1, why="a fraction").check("f", 2)
    Traceback (most recent call last):
    ...
    mechlab.errors.DimensionError: f must be ≤ 1, got 2 (a fraction)
    """
    return Spec("number", lo, hi, open, open, optional, error=error, why=why)


def length(*, zero: bool = False, hi=None, optional: bool = False, error=DimensionError, why=""):
    """A length: > 0 (≥ 0 with ``zero``), at least 1e-100 unless 0.

    Parameters
    ----------
    zero : bool, optional
        Accept 0.
    hi : float, optional
        The largest length (None: unbounded).
    optional : bool, optional
        Whether None is accepted (and passed through).
    error : type, optional
        The exception raised on a violation (a mechlab.errors class).
    why : str, optional
        Appended to a range violation's message, to say why the range holds.

    Returns
    -------
    Spec
        The declaration, for ``Annotated[type, spec]`` or :func:`check_value`.

    Examples
    --------
    >>> length().check("rod", 3)
    3.0
    """
    return Spec("length", 0.0, hi, not zero, False, optional, error=error, why=why)


def angle(lo=None, hi=None, *, open: bool = False, optional: bool = False, error=DimensionError, why=""):
    """An angle in radians, within [lo, hi] (or (lo, hi) with ``open``).

    Parameters
    ----------
    lo, hi : float, optional
        The bounds (None: unbounded).
    open : bool, optional
        Exclude the bounds.
    optional : bool, optional
        Whether None is accepted (and passed through).
    error : type, optional
        The exception raised on a violation (a mechlab.errors class).
    why : str, optional
        Appended to a range violation's message, to say why the range holds.

    Returns
    -------
    Spec
        The declaration, for ``Annotated[type, spec]`` or :func:`check_value`.

    Examples
    --------
    >>> angle(0, 3.2).check("beta", 1)
    1.0
    """
    return Spec("angle", lo, hi, open, open, optional, error=error, why=why)


def count(lo: int = 1, limit: int = MAX_SAMPLES, *, optional: bool = False, error=DimensionError, why=""):
    """A whole number in [lo, limit].

    Parameters
    ----------
    lo : int, optional
        The least value.
    limit : int, optional
        The largest value.
    optional : bool, optional
        Whether None is accepted (and passed through).
    error : type, optional
        The exception raised on a violation (a mechlab.errors class).
    why : str, optional
        Appended to a range violation's message, to say why the range holds.

    Returns
    -------
    Spec
        The declaration, for ``Annotated[type, spec]`` or :func:`check_value`.

    Examples
    --------
    >>> count(3).check("z", 4.0)
    4
    """
    return Spec("count", lo, limit, optional=optional, error=error, why=why)


def choice(*options, optional: bool = False, error=DimensionError):
    """One of ``options`` (strings or ints).

    Parameters
    ----------
    *options
        The admissible values.
    optional : bool, optional
        Whether None is accepted (and passed through).
    error : type, optional
        The exception raised on a violation.

    Returns
    -------
    Spec
        The declaration.

    Examples
    --------
    >>> choice("open", "crossed").check("assembly", "x")
    Traceback (most recent call last):
    ...
    mechlab.errors.DimensionError: assembly must be one of 'open', 'crossed', got 'x'
    """
    return Spec("choice", options=options, optional=optional, error=error)


def mechanism(expected, *, optional: bool = False, error=TypeError, why=""):
    """An instance of ``expected`` (a class, a tuple of classes or a runtime-checkable protocol).

    Parameters
    ----------
    expected : type or tuple of type
        The admissible class(es).
    optional : bool, optional
        Whether None is accepted (and passed through).
    error : type, optional
        The exception raised on a violation (TypeError by default).
    why : str, optional
        Appended to a range violation's message, to say why the range holds.

    Returns
    -------
    Spec
        The declaration, for ``Annotated[type, spec]`` or :func:`check_value`.

    Examples
    --------
    >>> mechanism(int).check("m", "x")
    Traceback (most recent call last):
    ...
    TypeError: m must be a int, got str 'x'
    """
    return Spec("mechanism", expected=expected, optional=optional, error=error, why=why)


Length = Annotated[float, length()]
Distance = Annotated[float, length(zero=True)]          # a length that may be 0
Coordinate = Annotated[float, number()]                 # a signed length or a position
Real = Annotated[float, number()]
Reals = Annotated[float | np.ndarray, Spec("reals")]  # a number, or one per crank angle
Angle = Annotated[float, angle()]
OptionalAngle = Annotated[float | None, angle(optional=True)]
Sign = Annotated[int, Spec("sign")]
Flag = Annotated[bool, Spec("flag")]
Point = Annotated[tuple, Spec("point")]
Samples = Annotated[int, count(1)]
Name = Annotated[str, Spec("text")]
Function = Annotated[Any, Spec("function")]
FilePath = Annotated[Any, Spec("path")]
# crank angles for a result that needs at least one (optional: None means the mechanism's cycle)
Angles = Annotated[np.ndarray, Spec("angles", lo=1)]
OptionalAngles = Annotated[np.ndarray | None, Spec("angles", lo=1, optional=True)]


def or_function(spec: Spec) -> Spec:
    """``spec``, or a function of the motion that gives such values.

    Parameters
    ----------
    spec : Spec
        The declaration of a value.

    Returns
    -------
    Spec
        The same declaration, accepting a callable as well.

    Examples
    --------
    >>> or_function(number()).check("load", abs) is abs
    True
    """
    return dataclasses.replace(spec, function_ok=True)


# -- enforcement -------------------------------------------------------------------------------------------
def _spec_of(annotation, namespace) -> Spec | None:
    """The Spec declared by an annotation (a string under ``from __future__ import annotations``)."""
    if isinstance(annotation, str):
        if "Annotated" not in annotation and not annotation[:1].isupper():  # float, np.ndarray, …: no Spec
            return None
        try:
            annotation = eval(annotation, namespace)
        except NameError:  # a name imported only for type checking: not a declaration
            return None
    if get_origin(annotation) is Annotated:
        return next((m for m in get_args(annotation)[1:] if isinstance(m, Spec)), None)
    return None


_FIELD_SPECS: dict[type, tuple[tuple[str, Spec], ...]] = {}


def _field_specs(cls) -> tuple[tuple[str, Spec], ...]:
    specs = _FIELD_SPECS.get(cls)
    if specs is None:
        found = []
        for f in fields(cls):
            owner = next(k for k in cls.__mro__ if f.name in inspect.get_annotations(k))
            spec = _spec_of(f.type, vars(sys.modules[owner.__module__]))
            if spec is not None:
                found.append((f.name, spec))
        specs = _FIELD_SPECS[cls] = tuple(found)
    return specs


def check_fields(obj) -> None:
    """Check and convert, in place, every declared field of a frozen dataclass instance.

    An instance may name its parameters in messages by ``_label(name)`` (e.g. "mass of coupler").

    Parameters
    ----------
    obj : object
        A dataclass instance whose fields are annotated with ``Annotated[type, Spec]``.

    Raises
    ------
    DimensionError
        Or a field's declared error, for the first field that violates its declaration.

    Examples
    --------
    >>> from mechlab import FourBar
    >>> check_fields(FourBar(1, 3, 3.5, 4))  # its lengths pass (and stay converted to floats)
    """
    label = getattr(obj, "_label", None)
    for name, spec in _field_specs(type(obj)):
        object.__setattr__(obj, name, spec.check(label(name) if label else name, getattr(obj, name)))


class Checked:
    """Base of the frozen dataclasses whose fields carry declarations: checked before any other use.

    A subclass with its own ``__post_init__`` calls ``super().__post_init__()`` first.

    Examples
    --------
    >>> from dataclasses import dataclass
    >>> @dataclass(frozen=True)
    ... class Bar(Checked):
    ...     length: Length
    >>> Bar(2)
    Bar(length=2.0)
    >>> Bar(0)
    Traceback (most recent call last):
    ...
    mechlab.errors.DimensionError: length must be > 0, got 0
    """

    def __post_init__(self):
        check_fields(self)


def validated(fn):
    """Check the declared arguments of ``fn`` (its annotations with a Spec) on every call.

    Defaults are not checked (they are valid by construction); a converted value replaces the argument,
    so the body sees floats and ints.

    Parameters
    ----------
    fn : callable
        A function whose parameters are annotated with ``Annotated[type, Spec]``.

    Returns
    -------
    callable
        The checking wrapper, with ``fn``'s signature.

    Examples
    --------
    >>> @validated
    ... def scale(x: Length, k: Real = 2.0):
    ...     return x * k
    >>> scale(3)
    6.0
    >>> scale(-3)
    Traceback (most recent call last):
    ...
    mechlab.errors.DimensionError: x must be > 0, got -3
    """
    signature = inspect.signature(fn)
    specs = None

    @functools.wraps(fn)
    def wrapper(*args, **kwargs):
        nonlocal specs
        if specs is None:  # resolved on first call: the annotations may name classes defined further down
            specs = {name: s for name, p in signature.parameters.items()
                     if (s := _spec_of(p.annotation, fn.__globals__)) is not None}
        bound = signature.bind(*args, **kwargs)
        arguments = bound.arguments
        for name, spec in specs.items():
            if name in arguments:
                arguments[name] = spec.check(name, arguments[name])
        return fn(*bound.args, **bound.kwargs)

    wrapper.__signature__ = signature
    return wrapper


def check_value(name: str, value, spec: Spec):
    """One value against a Spec (for values that are not parameters, e.g. a derived default).

    Parameters
    ----------
    name : str
        The value's name, for the message.
    value : object
        The value.
    spec : Spec
        Its declaration.

    Returns
    -------
    object
        The converted value.

    Raises
    ------
    DimensionError
        Or the declared error, naming ``name``.

    Examples
    --------
    >>> check_value("n", 5, count(1))
    5
    """
    return spec.check(name, value)


# the old name (feedback.check is the students' check; this one validates a value)
__getattr__ = renamed(__name__, check=(check_value, "mechlab.validate.check_value"))
