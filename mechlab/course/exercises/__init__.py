"""Exercises with a ``check`` that tells the student whether an answer is right.

Each chapter adds a module to this package that registers its exercises with
:func:`exercise`; the expected value is computed by mechlab when ``check`` is
called, never typed in. ``check("00.1", answer)`` prints a one-line verdict (with a
hint when wrong) and returns True or False, so a notebook can also assert it.
"""

from __future__ import annotations

import importlib
import pkgutil
from dataclasses import dataclass
from typing import Callable

import numpy as np

_REGISTRY: dict[str, "Exercise"] = {}


@dataclass(frozen=True)
class Exercise:
    key: str
    question: str
    expected: Callable[[], object]
    rtol: float = 1e-6
    atol: float = 1e-9
    hint: str = ""
    unit: str = ""


def exercise(key: str, question: str, expected: Callable[[], object], *, rtol: float = 1e-6,
             atol: float = 1e-9, hint: str = "", unit: str = "") -> Exercise:
    """Register an exercise (called at import time by the chapter modules)."""
    ex = Exercise(key, question, expected, rtol, atol, hint, unit)
    _REGISTRY[key] = ex
    return ex


def _load_all() -> None:
    for info in pkgutil.iter_modules(__path__):
        importlib.import_module(f"{__name__}.{info.name}")


def get(key: str) -> Exercise:
    """The registered exercise ``key`` (KeyError names the known keys)."""
    if key not in _REGISTRY:
        _load_all()
    try:
        return _REGISTRY[key]
    except KeyError:
        raise KeyError(f"no exercise {key!r}; known: {', '.join(sorted(_REGISTRY))}") from None


def _matches(answer, expected, rtol, atol) -> bool:
    if isinstance(expected, str):
        return isinstance(answer, str) and answer.strip().lower() == expected.strip().lower()
    try:
        a = np.asarray(answer, dtype=float)
        e = np.asarray(expected, dtype=float)
    except (TypeError, ValueError):
        return False
    return a.shape == e.shape and bool(np.allclose(a, e, rtol=rtol, atol=atol))


def check(key: str, answer, *, quiet: bool = False) -> bool:
    """Compare ``answer`` with the exercise's expected value; print a verdict, return it."""
    ex = get(key)
    if answer is None or answer is Ellipsis:
        if not quiet:
            print(f"Exercise {key}: no answer yet — replace ... with your value.")
        return False
    ok = _matches(answer, ex.expected(), ex.rtol, ex.atol)
    if not quiet:
        if ok:
            print(f"Exercise {key}: correct ✓")
        else:
            print(f"Exercise {key}: not yet ✗ — {ex.hint or 'check your computation'}")
    return ok


def solution(key: str):
    """The expected answer (for lecturers and for the tests)."""
    return get(key).expected()
