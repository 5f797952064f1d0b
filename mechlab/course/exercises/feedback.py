"""Feedback on a computed answer: textbook tolerance, "give more digits", and the usual slips named.

The expected value is passed in by whoever grades (an nbgrader hidden test); this module stores
no answer. A :class:`Verdict` shows as one line and is truthy when the answer is right;
:meth:`Verdict.require` raises :class:`NotYet`, whose notebook traceback is the message alone, so a
grader's feedback never shows the test's source (where the expected value is computed).
"""

from __future__ import annotations

import base64
import contextlib
import math
import textwrap
from dataclasses import dataclass
from numbers import Real

import numpy as np

from . import selfcheck

#: While not None, :func:`check` and :func:`check_choice` append their call here instead of judging
#: (see :func:`recording`: how a student edition's tokens are made from the hidden tests).
_RECORDING: list | None = None

#: A textbook answer: three significant figures.
SIGNIFICANT = 3
#: Within this relative error an answer is "close": the method is right, the digits are too few.
CLOSE = 0.01

# unit asked -> (factor the slip multiplies the right value by, what the student gave, how to fix it)
UNIT_SLIPS = {
    "deg": [(math.pi / 180, "radians", "the answer is asked in degrees: convert with np.degrees")],
    "rad": [(180 / math.pi, "degrees", "the answer is asked in radians: convert with np.radians")],
    "rad/s": [(180 / math.pi, "deg/s", "the answer is asked in rad/s: convert with np.radians"),
              (30 / math.pi, "rpm", "the answer is asked in rad/s: ω = 2π·n/60")],
    "mm": [(1e-3, "metres", "the answer is asked in mm: multiply by 1000")],
    "m/s": [(1e3, "mm/s", "the answer is asked in m/s: divide by 1000")],
    "m": [(1e3, "millimetres", "the answer is asked in metres: divide by 1000")],
    "N·m": [(1e3, "N·mm", "the answer is asked in N·m: divide by 1000")],
    "W": [(1e-3, "kW", "the answer is asked in watts: multiply by 1000")],
    "s": [(1e3, "ms", "the answer is asked in seconds: divide by 1000")],
}


@dataclass(frozen=True)
class Verdict:
    """The outcome of a check: ``ok``, a ``kind`` ("correct", "close", "units", "sign", "alternative",
    "choice", "wrong", "missing", "form") and the one-line ``message`` a student reads."""

    ok: bool
    kind: str
    message: str

    def __bool__(self) -> bool:
        return self.ok

    def __repr__(self) -> str:
        return self.message

    def require(self) -> None:
        """Print the message if the answer is right, else raise :class:`NotYet` with it (for graded cells)."""
        if not self.ok:
            raise NotYet(self.message)
        print("\n".join(_wrapped(self.message)))


class NotYet(AssertionError):
    """A graded check that failed. In a notebook its traceback is the message alone (IPython's
    ``_render_traceback_``), so the test's source — the expected value — is not shown."""

    def _render_traceback_(self) -> list[str]:
        return _wrapped(str(self))


def _wrapped(message: str, width: int = 100) -> list[str]:
    """The message's lines wrapped to ``width`` columns (feedback pages do not wrap code output)."""
    return [part for line in message.splitlines() for part in textwrap.wrap(line, width, subsequent_indent="    ")
            or [""]]


def tolerance(expected: float, significant: int = SIGNIFICANT) -> float:
    """Half a unit in the last of ``significant`` figures of ``expected``: a correctly rounded answer passes."""
    if expected == 0:
        return 0.5 * 10.0 ** (-significant)
    return 0.5 * 10.0 ** (math.floor(math.log10(abs(expected))) - significant + 1)


def _parsed(answer, name: str, unit: str) -> float | Verdict:
    """The answer as a float, or the verdict on why it is none (no answer yet, not one finite number)."""
    if answer is None or answer is Ellipsis:
        return Verdict(False, "missing", f"✗ {name}: no answer yet — replace ... with your value"
                                         f"{' in ' + unit if unit else ''}.")
    a = _number(answer)
    if a is None:
        return Verdict(False, "form", f"✗ {name}: expected one finite number{' in ' + unit if unit else ''}, "
                                      f"got {answer!r} ({type(answer).__name__}).")
    return a


def _number(answer) -> float | None:
    if isinstance(answer, bool) or (not isinstance(answer, (Real, np.number)) and not (
            isinstance(answer, np.ndarray) and answer.size == 1)):
        return None
    x = float(np.asarray(answer).reshape(()))
    return x if math.isfinite(x) else None


def _near(a: float, b: float, rel: float = CLOSE) -> bool:
    return abs(a - b) <= rel * abs(b) + 1e-12


def check(answer, expected: float, *, name: str = "answer", unit: str = "", significant: int = SIGNIFICANT,
          alternatives: dict[str, float] | None = None, hint: str = "") -> Verdict:
    """Compare a numeric ``answer`` with ``expected`` to ``significant`` figures and name the slip if any.

    Tried in order: right to the textbook tolerance (:func:`tolerance`, on the grid of
    :func:`.selfcheck.windows`); within 1 % ("close — give more digits"); the right value in another unit
    (``UNIT_SLIPS[unit]``: degrees for radians and back, m for mm, rpm for rad/s, …); the right magnitude
    with the sign flipped; one of ``alternatives`` (name → the value that slip gives, e.g.
    ``{"the other assembly (kc = −1)": …}``). Otherwise "not yet" and ``hint``. No message contains
    ``expected``. The student edition's :func:`self_check` gives the same verdict from a token.
    """
    call = dict(kind="number", expected=float(expected), name=name, unit=unit, significant=significant,
                alternatives={k: float(v) for k, v in (alternatives or {}).items()}, hint=hint,
                unit_slips=UNIT_SLIPS.get(unit, []))
    if _RECORDING is not None:
        _RECORDING.append(call)
        return Verdict(True, "recorded", f"{name}: recorded")
    a = _parsed(answer, name, unit)
    slip = ""
    if isinstance(a, Verdict):
        verdict = a
    else:
        table = selfcheck.slip_candidates(call["expected"], call["unit_slips"], call["alternatives"], significant)
        found = selfcheck.classify(a, table, significant)
        verdict = _number_verdict(a, found, call)
        slip = {"units": f"{found[1]} for {unit}", "alternative": found[1]}.get(found[0], "") if found else ""
    _log(call, verdict, answer, slip)
    return verdict


def _number_verdict(a: float, found, call: dict) -> Verdict:
    """The one-line verdict on answer ``a`` from the row :func:`.selfcheck.classify` found (None: wrong)."""
    name, unit, hint, significant = call["name"], call["unit"], call["hint"], call["significant"]
    u = f" {unit}" if unit else ""
    kind, label, fix = found or ("wrong", "", "")
    if kind == "correct":
        return Verdict(True, kind, f"✓ {name} = {a:.4g}{u}: right to {significant} significant figures.")
    if kind == "close":
        return Verdict(False, kind, f"≈ {name} = {a:.4g}{u} is within 1 % but not within {significant} "
                                    f"significant figures: close — give more digits.")
    if kind == "units":
        return Verdict(False, kind, f"✗ {name} = {a:.4g} is the right value in {label}: {fix}.")
    if kind == "sign":
        return Verdict(False, kind, f"✗ {name} = {a:.4g}{u}: the size is right, the sign is flipped — check the "
                                    f"sign convention (which sense is positive).")
    if kind == "alternative":
        return Verdict(False, kind, f"✗ {name} = {a:.4g}{u} is what {label} gives: {hint or 'reread the question'}.")
    more = f" Hint: {hint}" if hint else ""
    return Verdict(False, "wrong", f"✗ {name} = {a:.4g}{u}: not yet (more than 1 % off, and not a unit or sign "
                                   f"slip).{more}")


def check_choice(answer, expected: str, options: dict[str, str], *, name: str = "choice",
                 hints: dict[str, str] | None = None) -> Verdict:
    """Check a multiple-choice ``answer`` (a key of ``options``, case and spaces ignored); a wrong key gets
    its own hint from ``hints`` when there is one."""
    call = dict(kind="choice", expected=expected, options=dict(options), name=name, hints=dict(hints or {}))
    if _RECORDING is not None:
        _RECORDING.append(call)
        return Verdict(True, "recorded", f"{name}: recorded")
    verdict = _choice_verdict(answer, expected, options, name, hints)
    _log(call, verdict, answer)
    return verdict


def _choice_verdict(answer, expected, options, name, hints) -> Verdict:
    if answer is None or answer is Ellipsis:
        return Verdict(False, "missing", f"✗ {name}: no choice yet — one of {', '.join(map(repr, options))}.")
    key = str(answer).strip().lower()
    if key not in options:
        return Verdict(False, "form", f"✗ {name}: {answer!r} is not one of {', '.join(map(repr, options))}.")
    if key == expected:
        return Verdict(True, "correct", f"✓ {name}: ({key}) {options[key]}.")
    why = (hints or {}).get(key, "reread the question and test your reasoning with the explorer")
    return Verdict(False, "choice", f"✗ {name}: ({key}) is not it — {why}.")


def check_form(answer, *, name: str = "answer", unit: str = "") -> Verdict:
    """What a student can be told before grading: is ``answer`` one finite number? (No expected value.)"""
    a = _parsed(answer, name, unit)
    if isinstance(a, Verdict):
        return a
    return Verdict(True, "form", f"{name} = {a:.6g}{' ' + unit if unit else ''} — a number; it is graded to "
                                 f"{SIGNIFICANT} significant figures when you submit.")


@contextlib.contextmanager
def recording():
    """Within the block, :func:`check` and :func:`check_choice` record their calls (expected value, slips,
    name, unit, hint) in the list this yields and pass; ``make student`` runs the hidden tests so to seal
    each one into a :func:`self_check` token."""
    global _RECORDING
    calls, previous = [], _RECORDING
    _RECORDING = calls
    try:
        yield calls
    finally:
        _RECORDING = previous


def _log(call: dict, verdict: Verdict, answer, slip: str = "") -> None:
    """The grader's verdict, for the class report (only while ``make grade`` names a log file)."""
    number = _number(answer) if call["kind"] == "number" else None
    selfcheck.record({"name": call["name"], "check": call["kind"], "kind": verdict.kind, "ok": verdict.ok, "slip": slip,
                      "answer": number if number is not None else (None if answer in (None, Ellipsis)
                                                                      else str(answer)[:40])})


def self_check(token: str, answer) -> Verdict:
    """The grader's verdict on ``answer`` (a number, a choice or, for a code exercise, the function), at once,
    from the ``token`` the student edition holds.

    The token (made by ``make student`` from the hidden test's own call, see :mod:`.selfcheck`) holds the
    right value and each named slip only as keyed digests of the bins the grader accepts, so the same
    verdict — right, close, the unit or sign slip, the named alternative, or not yet with the hint — is
    shown without the expected value being anywhere in the notebook. A code exercise's token holds the
    hidden cases' inputs and the digests of the bins of the reference's outputs (:func:`function_verdict`).
    Prints the verdict and returns it;
    inside nbgrader's autograde it returns quietly (the hidden test prints the grade's own verdict).

    Examples
    --------
    >>> from mechlab.course.exercises.selfcheck import seal
    >>> token = seal(dict(kind="number", expected=2.5, name="x", unit="mm", significant=3,
    ...                   alternatives={}, hint="", unit_slips=UNIT_SLIPS["mm"]), salt="demo")
    >>> self_check(token, 0.0025).kind
    ✗ x = 0.0025 is the right value in metres: the answer is asked in mm: multiply by 1000.
    'units'
    """
    body = selfcheck.unseal(token)
    name, unit, hint = body["name"], body["unit"], body["hint"]
    if body["t"] == "f":
        salt = body["s"].encode()
        expected = [(shape, [raw[i:i + selfcheck.DIGEST] for i in range(0, len(raw), selfcheck.DIGEST)])
                    for shape, raw in ((s, base64.b64decode(p)) for s, p in body["rows"])]
        verdict = function_verdict(answer, name, [selfcheck.decode_case(c) for c in body["cases"]], expected,
                                   rtol=body["rtol"], atol=body["atol"], hint=hint,
                                   hashed=lambda b: selfcheck.digest(salt, b))
    elif body["t"] == "c":
        opts = body["options"]
        if answer is None or answer is Ellipsis or str(answer).strip().lower() not in opts:
            verdict = _choice_verdict(answer, None, opts, name, None)
        else:
            key = str(answer).strip().lower()
            right, why = selfcheck.choice_verdict(body, key)
            verdict = _choice_verdict(key, key if right else None, opts, name, {key: why} if why else None)
    else:
        a = _parsed(answer, name, unit)
        if isinstance(a, Verdict):
            verdict = a
        else:
            salt = body["s"].encode()
            found = selfcheck.classify(a, selfcheck.digest_table(body), body["sig"],
                                       hashed=lambda b: selfcheck.digest(salt, b))
            verdict = _number_verdict(a, found, dict(name=name, unit=unit, hint=hint, significant=body["sig"]))
    if not selfcheck.grading():
        print("\n".join(_wrapped(verdict.message)))
    return verdict


def function_verdict(fn, name: str, cases: list, expected: list, *, rtol: float, atol: float, hint: str = "",
                     hashed=None) -> Verdict:
    """The verdict on a student's function ``fn`` over ``cases``, the grader's and the self-check's alike.

    ``expected[n]`` is (shape, stored bins) of the reference's output on case n: its element bins
    (:func:`.selfcheck.value_bin`) in clear for the grader, or their keyed digests with ``hashed`` the
    keyed hash for a token. The first case whose call raises, whose shape differs or which has an element
    in no bin near the reference's is named, with its inputs and never the reference's value.
    """
    return function_outcome(fn, name, cases, expected, rtol=rtol, atol=atol, hint=hint, hashed=hashed)[0]


def function_outcome(fn, name: str, cases: list, expected: list, *, rtol: float, atol: float, hint: str = "",
                     hashed=None) -> tuple[Verdict, int]:
    """:func:`function_verdict` and the number of cases that agree before the first that does not."""
    n = len(cases)
    if fn is None or fn is Ellipsis:
        return Verdict(False, "missing", f"✗ {name}: no answer yet — define the function {name}."), 0
    if not callable(fn):
        return Verdict(False, "form", f"✗ {name}: expected a function, got {type(fn).__name__}."), 0
    for k, (case, (shape, stored)) in enumerate(zip(cases, expected, strict=False)):
        where = f"case {k + 1} of {n}: {name}{_args(case)}"
        try:
            out = fn(*case)
        except NotImplementedError:
            return Verdict(False, "missing", f"✗ {name}: no answer yet — replace `raise NotImplementedError` "
                                             f"with your code."), k
        except Exception as err:  # the student's code: any failure is reported, not raised
            return Verdict(False, "raised", f"✗ {where} raised {type(err).__name__}: {err}."), k
        if out is None or out is Ellipsis:
            return Verdict(False, "missing", f"✗ {where} returned {out!r}: no answer yet — write its body."), k
        try:
            got = np.asarray(out, dtype=float)
        except (TypeError, ValueError):
            return Verdict(False, "form", f"✗ {where} returned {type(out).__name__}, not numbers."), k
        if got.shape != tuple(shape):
            return Verdict(False, "shape", f"✗ {where} returned shape {got.shape}, expected {tuple(shape)}."), k
        i = selfcheck.first_disagreement(got, k, stored, rtol, atol, hashed)
        if i is not None:
            element = f"element {i + 1} of {got.size} of its output differs" if got.size > 1 else "it differs"
            before = f"; the {k} case{'s' if k != 1 else ''} before it agree" if k else ""
            more = f" Hint: {hint}" if hint else ""
            return Verdict(False, "wrong", f"✗ {where} is not what the reference gives ({element} by more than "
                                           f"rtol {rtol:g}){before}.{more}"), k
    return Verdict(True, "correct", f"✓ {name} passes all {n} cases (it agrees with the reference to rtol "
                                    f"{rtol:g})."), n


def _args(case: tuple) -> str:
    return "(" + ", ".join(f"{c:.4g}" if isinstance(c, float) else repr(c) for c in case) + ")"
