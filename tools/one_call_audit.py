"""Which graded answers is one public mechlab call away? (issue 25: none should be.)

    python tools/one_call_audit.py [assignment ...]      # prints one line per graded answer, exit 1 if any is

Method. For each auto-graded number of each assignment (the shared variant, rendered as the student sees it) the
expected value is taken from the hidden test's own ``check`` call (recorded, as ``make student`` does). The prompt's
inputs are the numbers of the exercise's text (and those of the student's numbers ``V`` it names without stating
them), each angle given in degrees also in radians. Then every public callable of mechlab and of its sub-modules
(course, widgets and drawing left out) is tried on them:

* functions and classes with k required positional parameters: called on every ordered choice of k
  inputs for k ≤ 3, and on every run of k consecutive inputs in the prompt's order for k ≤ 6;
* on each object a class returns: every public attribute and zero-argument method;

and every finite scalar result (or one-element array) is compared with the expected value, as it is and in the usual
other units (degrees ↔ radians, ×1000, ÷1000), to a relative 1e-9 (a call that answers gives the hidden test's own
value; the grader's 3-figure window would let chance hits through). A hit names the call. A code exercise is flagged
when its hidden reference calls ``ml.`` (checked against a public function instead of an independent reference).

Limits. Keyword-only parameters keep their defaults; a result needing an index (``motion(φ).dpsi[0]``), arithmetic on
a result (× ω1) or two calls is not "one call" and is not looked for; a call running over 0.2 s is abandoned. The
search is exhaustive over what it tries, not over every program a student could write."""

from __future__ import annotations

import argparse
import functools
import importlib
import inspect
import itertools
import math
import pkgutil
import re
import signal
import sys
from pathlib import Path

import nbformat
import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path[:0] = [str(ROOT), str(ROOT / "assignments")]

import variants  # noqa: E402

import mechlab  # noqa: E402

SKIP = ("mechlab.course", "mechlab.widgets", "mechlab.draw")
NUMBER = re.compile(r"(?<![\w.])-?\d+(?:\.\d+)?(?:e[-+]?\d+)?(?![\w])")
DEGREES = re.compile(r"(?<![\w.])(-?\d+(?:\.\d+)?)\s*(?:°|deg)")
UNITS = {"as is": 1.0, "in degrees": 180 / math.pi, "in radians": math.pi / 180, "×1000": 1e3, "÷1000": 1e-3}


class _Slow(Exception):
    pass


def _alarm(signum, frame):
    raise _Slow


@functools.cache   # the same for every assignment (walking the package takes ~0.5 s)
def public_callables() -> dict[str, object]:
    """Every public function and class of mechlab and its sub-modules, by dotted name (one entry each)."""
    found, seen = {}, set()
    mods = [mechlab] + [importlib.import_module(m.name) for m in pkgutil.walk_packages(mechlab.__path__, "mechlab.")
                        if not m.name.startswith(SKIP) and not m.name.split(".")[-1].startswith("_")]
    for mod in mods:
        for name in getattr(mod, "__all__", None) or [n for n in dir(mod) if not n.startswith("_")]:
            obj = getattr(mod, name, None)
            public = (inspect.isfunction(obj) or inspect.isclass(obj)) and getattr(obj, "__module__", "").startswith(
                "mechlab") and not issubclass(obj if inspect.isclass(obj) else object, BaseException)
            if public and id(obj) not in seen:
                seen.add(id(obj))
                found[f"{mod.__name__}.{name}"] = obj
    return found


def _arity(fn) -> int | None:
    try:
        sig = inspect.signature(fn)
    except (TypeError, ValueError):
        return None
    return sum(1 for p in sig.parameters.values() if p.default is p.empty
               and p.kind in (p.POSITIONAL_ONLY, p.POSITIONAL_OR_KEYWORD))


def _scalars(value, depth=0):
    """(label, float) of a result: itself if a scalar, else its public attributes and 0-arg methods."""
    x = _scalar(value)
    if x is not None:
        yield "", x
        return
    if depth or value is None or isinstance(value, (str, bytes, dict, list, tuple, np.ndarray)):
        return
    for name in dir(value):
        if name.startswith("_"):
            continue
        try:
            attr = getattr(value, name)
            if callable(attr):
                if _arity(attr) != 0 or inspect.isclass(attr):
                    continue
                attr = attr()
        except Exception:
            continue
        x = _scalar(attr)
        if x is not None:
            yield f".{name}" + ("()" if callable(getattr(value, name, None)) else ""), x


def _scalar(value):
    try:
        if isinstance(value, (bool, np.bool_)):
            return None
        a = np.asarray(value, dtype=float)
        if a.size == 1 and np.isfinite(a).all():
            return float(a.reshape(()))
    except (TypeError, ValueError):
        pass
    return None


def _argument_lists(inputs: list[float], k: int):
    if k == 0:
        yield ()
        return
    if k <= 3:
        yield from itertools.permutations(inputs, k)
    if k <= 6:
        yield from (tuple(inputs[i:i + k]) for i in range(len(inputs) - k + 1))


# the scalars of each call already made, by (callable, arguments): the prompts of one assignment, and of different
# assignments, share many numbers, so about a quarter of the calls of a whole audit are repeats
_MADE: dict[tuple, list[tuple[str, float]]] = {}


def sweep(inputs: list[float], calls: dict[str, object]) -> tuple[np.ndarray, list[str]]:
    """Every scalar one call on ``inputs`` gives: (values, the expression of each)."""
    values, names = [], []
    old = signal.signal(signal.SIGALRM, _alarm)
    try:
        for name, fn in calls.items():
            k = _arity(fn)
            if k is None or k > 6:
                continue
            for args in dict.fromkeys(_argument_lists(inputs, k)):
                key = (name, fn, args)
                if key not in _MADE:
                    _MADE[key] = _call(fn, args)
                hits = _MADE[key]
                call = f"{name}({', '.join(f'{a:g}' for a in args)})"
                for label, x in hits:
                    values.append(x)
                    names.append(call + label)
    finally:
        signal.signal(signal.SIGALRM, old)
    return np.array(values), names


def _call(fn, args) -> list[tuple[str, float]]:
    """The scalars of ``fn(*args)`` (integral values passed as int); none if it raises or runs over 0.2 s."""
    try:
        signal.setitimer(signal.ITIMER_REAL, 0.2)
        try:
            return list(_scalars(fn(*[int(a) if float(a).is_integer() else a for a in args])))
        finally:
            signal.setitimer(signal.ITIMER_REAL, 0)
    except (Exception, _Slow):
        return []


def answered_by(expected: float, found: tuple[np.ndarray, list[str]], rtol: float = 1e-9) -> str | None:
    """The first expression of a :func:`sweep` equal to ``expected`` (to ``rtol``) in one of the usual units.

    Equal, not merely within the grader's tolerance: among a few hundred thousand results some fall in a
    3-figure window by chance, while a library call that answers gives the hidden test's own value."""
    values, names = found
    for unit, factor in UNITS.items():
        hit = np.flatnonzero(np.abs(values * factor - expected) <= rtol * max(abs(expected), 1e-12))
        if hit.size:
            return f"{names[hit[0]]} {unit}"
    return None


def _exercise_texts(nb) -> dict[int, str]:
    """For each code cell index, the text of the exercise it belongs to (the last '## Exercise' above it)."""
    text, out = "", {}
    for k, c in enumerate(nb.cells):
        if c.cell_type == "markdown" and c.source.lstrip().startswith("## Exercise"):
            text = c.source
        out[k] = text
    return out


def _inputs(text: str, values: dict) -> list[float]:
    """The prompt's numbers in order (the title, points and "3 significant figures" left out), then the
    student's numbers the prompt names (``V["a"]``) without stating them, then each angle the prompt gives in
    degrees ("60°") in radians. The student's other numbers belong to other exercises: trying them too
    multiplies the search (a cube in the number of inputs) and finds only chance hits."""
    body = re.sub(r"\d+ significant figures|\(\d+ points?[^)]*\)", "", text.split("\n", 1)[-1])
    named = [float(v) for k, v in values.items() if re.search(rf"V\[[\"']{re.escape(k)}[\"']\]", body)]
    nums = list(dict.fromkeys([float(s) for s in NUMBER.findall(body)] + named))
    degrees = {float(s) for s in DEGREES.findall(body)}
    nums += [math.radians(x) for x in nums if x in degrees and x != 0]
    return nums


def audit(aid: str, calls: dict[str, object]) -> list[tuple[str, str, str | None]]:
    """(assignment, answer name, the call that gives it or None) for each graded answer of ``aid``."""
    src = nbformat.read(ROOT / "assignments" / "source" / aid / f"{aid}.ipynb", as_version=4)
    nb = variants.render(src, aid)
    values = variants.numbers(nb)[0]
    texts = _exercise_texts(nb)
    rows, swept = [], {}
    for k, recorded in variants._checks(nb):
        inputs = tuple(_inputs(texts[k], values))
        if inputs not in swept:
            swept[inputs] = sweep(list(inputs), calls)
        for call in recorded:
            if call["kind"] == "number":
                rows.append((aid, call["name"], answered_by(call["expected"], swept[inputs])))
    for c in nb.cells:
        hidden = "".join(variants.HIDDEN.findall(c.source))
        m = re.search(r"function_check\((\w+),\s*(.*?),\s*_cases", hidden, re.S)
        if m:
            rows.append((aid, m.group(1), f"checked against {m.group(2).strip()}" if "ml." in m.group(2) else None))
    return rows


def main(argv=None) -> int:
    known = sorted(p.name for p in (ROOT / "assignments" / "source").iterdir() if (p / f"{p.name}.ipynb").is_file())
    parser = argparse.ArgumentParser(description="List, for each graded answer, whether one public mechlab call "
                                                 "returns it from the prompt's inputs (exit 1 if any does).")
    parser.add_argument("ids", nargs="*", metavar="assignment", help=f"assignment ids (default: all of {known})")
    ids = parser.parse_args(argv).ids or known
    unknown = sorted(set(ids) - set(known))
    if unknown:
        parser.error(f"no assignment {', '.join(unknown)}; known: {', '.join(known)}")
    calls = public_callables()
    found = 0
    for aid in ids:
        for _, name, hit in audit(aid, calls):
            found += hit is not None
            print(f"{aid:<20} {name:<32} {'ONE CALL: ' + hit if hit else 'no single call found'}")
    print(f"{found} graded answers one public call away ({len(calls)} public callables tried)")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
