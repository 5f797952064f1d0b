"""Feedback at once: the grader's verdict in the student's notebook, without the expected value in it.

Why keyed hashes of quantised candidates (and not a salted hash of the rounded answer, nor a compiled model): the
grader must be able to say *which* slip an answer is (degrees for radians, the other assembly, …), so the notebook
needs one test per candidate value — the right one and every named slip — and it must agree with the grader to the
last bin. Each candidate is replaced by the set of grid bins that the grader accepts for it (:func:`windows`: the
textbook tolerance on a grid ten times finer than the third significant figure for the right value, a 1 % window on a
logarithmic grid of 0.2 % steps for "close" and the slips). A bin is written ``"<grid>|<decade or sign>|<index>"`` and
stored only as the first 4 bytes of HMAC-SHA256(salt, bin). The self-check hashes the few bins the student's answer
falls in (its own decade and the two next to it on the fine grid, one logarithmic bin) and looks them up, kind by
kind, in the grader's order. The grader (:func:`mechlab.course.exercises.check`) runs the same :func:`classify` on the
bins in clear, so the two verdicts are the same function of the answer; they could differ only on a 32-bit hash
collision (≈ 1e-7 per check). A recompiled model would carry the answer in code a student can run on other numbers;
the hashes carry no number: reading a token gives the salt, the slips' names and bin digests. Limits, said plainly: a
check that answers "right" at once is an oracle, so a student who loops over the ~9000 bins of a decade can find the
right bin (as with any immediate feedback; the hidden tests still decide the grade, and a variant per student makes
the value useless to anyone else). The token reveals how many bins each slip window has, hence roughly the slip's
decade; it reveals neither the value nor its sign. Code exercises (a function checked on hidden cases) are sealed the
same way, per case and output element: see :func:`seal_function`."""

from __future__ import annotations

import base64
import hashlib
import hmac
import importlib
import json
import math
import os
from collections.abc import Iterable

import numpy as np

#: bytes of each digest kept (false match ≈ bins looked up × bins stored / 2³²)
DIGEST = 4
#: relative window of a slip and of "close": the grader's 1 %
WINDOW = 0.01
#: the logarithmic grid of the slip windows: 0.2 % steps
_LOG_STEP = math.log1p(0.002)


def _decade(x: float) -> int:
    return math.floor(math.log10(abs(x))) if x else -1


def windows(value: float, *, right: bool, significant: int = 3) -> set[str]:
    """The bins the grader accepts around ``value``.

    ``right``: the textbook tolerance — half a unit in the ``significant``-th figure — on a grid ten
    times finer (``"f"`` bins, ±5 of them; a zero value lives in decade −1, which every look-up includes).
    Otherwise a ±1 % window on a logarithmic grid of 0.2 % steps (``"c"`` bins, sign apart: 11 of them).
    """
    if right:
        d = _decade(value)
        step = 10.0 ** (d - significant)
        centre = round(value / step)
        return {f"f{significant}|{d}|{centre + k}" for k in range(-5, 6)}
    if not value:
        return {"c|0"}
    sign = "+" if value > 0 else "-"
    lo, hi = (round(math.log(abs(value) * (1 + s * WINDOW)) / _LOG_STEP) for s in (-1, 1))
    return {f"c|{sign}|{k}" for k in range(lo, hi + 1)}


def lookups(answer: float, significant: int = 3) -> set[str]:
    """The bins an answer falls in: on the fine grid in its own decade, the two next to it and decade −1
    (zero); on the logarithmic grid its one bin."""
    out = {f"f{significant}|{d}|{round(answer / 10.0 ** (d - significant))}"
           for d in {_decade(answer) - 1, _decade(answer), _decade(answer) + 1, -1}}
    if abs(answer) < 1e-12:
        out.add("c|0")
    else:
        out.add(f"c|{'+' if answer > 0 else '-'}|{round(math.log(abs(answer)) / _LOG_STEP)}")
    return out


def slip_candidates(expected: float, unit_slips: Iterable[tuple[float, str, str]], alternatives: dict[str, float],
                    significant: int = 3) -> list[tuple[str, str, str, set[str]]]:
    """The grader's table in its order: (kind, label, fix, bins) for right, close, each unit slip, the
    flipped sign and each named alternative (see :func:`mechlab.course.exercises.check`)."""
    e = float(expected)
    rows = [("correct", "", "", windows(e, right=True, significant=significant)),
            ("close", "", "", windows(e, right=False))]
    rows += [("units", gave, fix, windows(e * factor, right=False)) for factor, gave, fix in unit_slips]
    if e:
        rows.append(("sign", "", "", windows(-e, right=False)))
    rows += [("alternative", slip, "", windows(float(v), right=False)) for slip, v in alternatives.items()
             if math.isfinite(float(v))]
    return rows


# the old name, for assignments/report.py (renamed: design.candidates is the design layer's)
candidates = slip_candidates


def classify(answer: float, table, significant: int = 3, hashed=None) -> tuple[str, str, str] | None:
    """The first row of ``table`` whose bins hold one of the answer's :func:`lookups` (the rule the grader
    and the self-check share): (kind, label, fix), or None. ``hashed`` maps a bin to what the table
    stores (none for the grader: bins in clear; a keyed digest for a token); "close" never wins over "correct"
    because the right value's fine window comes first."""
    look = {hashed(b) if hashed else b for b in lookups(answer, significant)}
    for kind, label, fix, bins in table:
        if look & set(bins):
            return kind, label, fix
    return None


def digest(salt: bytes, item: str) -> bytes:
    return hmac.new(salt, item.encode(), hashlib.sha256).digest()[:DIGEST]


def seal(check: dict, salt: str) -> str:
    """A check recorded from the grader's call (``{"kind": "number"|"choice", …}``) as an opaque token."""
    key = salt.encode()
    if check["kind"] == "function":
        return seal_function(check, salt)
    if check["kind"] == "number":
        rows = slip_candidates(check["expected"], check["unit_slips"], check["alternatives"], check["significant"])
        body = {"t": "n", "sig": check["significant"], "rows": [
            [kind, label, fix, base64.b64encode(b"".join(sorted(digest(key, b) for b in bins))).decode()]
            for kind, label, fix, bins in rows]}
    else:
        body = {"t": "c", "options": check["options"], "rows": [
            [base64.b64encode(digest(key, f"choice|{o}")).decode(), _encrypt(key, o, check["hints"].get(o, ""),
                                                                               o == check["expected"])]
            for o in sorted(check["options"])]}
    body.update(s=salt, name=check["name"], unit=check.get("unit", ""), hint=check.get("hint", ""))
    return base64.b64encode(json.dumps(body, ensure_ascii=False, separators=(",", ":")).encode()).decode()


def _stream(key: bytes, option: str, n: int) -> bytes:
    out, k = b"", 0
    while len(out) < n:
        out += hashlib.sha256(key + f"|stream|{option}|{k}".encode()).digest()
        k += 1
    return out[:n]


def _encrypt(key: bytes, option: str, hint: str, right: bool) -> str:
    """A choice's verdict readable only by whoever types that option: ("1" if right else "0") + its hint."""
    plain = (("1" if right else "0") + hint).encode()
    stream = _stream(key, option, len(plain))
    return base64.b64encode(bytes(a ^ b for a, b in zip(plain, stream, strict=True))).decode()


def _decrypt(key: bytes, option: str, sealed: str) -> tuple[bool, str]:
    raw = base64.b64decode(sealed)
    plain = bytes(a ^ b for a, b in zip(raw, _stream(key, option, len(raw)), strict=False)).decode()
    return plain[0] == "1", plain[1:]


def unseal(token: str) -> dict:
    """The body of a token (salt, names, bin digests); raises ValueError on a damaged one."""
    try:
        return json.loads(base64.b64decode(token.encode()))
    except (ValueError, UnicodeDecodeError) as err:
        raise ValueError("this check cell's token is damaged: restore the cell from the student edition") from err


def digest_table(body: dict):
    """A number token's rows as (kind, label, fix, set of digests) for :func:`classify`."""
    rows = []
    for kind, label, fix, packed in body["rows"]:
        raw = base64.b64decode(packed)
        rows.append((kind, label, fix, {raw[i:i + DIGEST] for i in range(0, len(raw), DIGEST)}))
    return rows


def choice_verdict(body: dict, option: str) -> tuple[bool, str] | None:
    """(right, hint) for a choice the token lists, None for one it does not."""
    key = body["s"].encode()
    mine = base64.b64encode(digest(key, f"choice|{option}")).decode()
    for stored, sealed in body["rows"]:
        if stored == mine:
            return _decrypt(key, option, sealed)
    return None


def grading() -> bool:
    """True inside nbgrader's autograde (it sets NBGRADER_EXECUTION): the hidden tests speak then."""
    return os.environ.get("NBGRADER_EXECUTION") == "autograde"


def record(entry: dict) -> None:
    """Append one verdict to the file MECHLAB_GRADE_LOG names (set by ``make grade`` for the class report)."""
    path = os.environ.get("MECHLAB_GRADE_LOG")
    if path:
        with open(path, "a", encoding="utf-8") as f:
            f.write(json.dumps(entry, ensure_ascii=False) + "\n")



# --- code exercises: the reference's outputs as keyed digests of bins, per case and element -------------------
#
# A function check (:func:`mechlab.course.exercises.function_check`) agrees with the reference when every
# element of every case's output lies in the reference's bin or a neighbouring one on a logarithmic grid of
# step ``rtol`` (sign apart; |x| ≤ atol is the one bin "z"). The grader applies this rule in clear, the
# token holds only digest(salt, "case|element|bin") of the reference's bins, and the self-check hashes
# the student's three candidate bins: the same verdict, and no output value in the notebook.

def value_bin(x: float, rtol: float, atol: float) -> str:
    """The bin of one output value on a function check's grid: "z" for |x| ≤ atol, "n" for a non-finite x,
    else ``±k`` with k = round(ln|x| / ln(1 + rtol))."""
    if not math.isfinite(x):
        return "n"
    if abs(x) <= atol:
        return "z"
    return f"{'+' if x > 0 else '-'}{round(math.log(abs(x)) / math.log1p(rtol))}"


def near_bins(b: str) -> set[str]:
    """The bins a value in bin ``b`` agrees with: itself and, off zero, the two next to it."""
    if b in ("z", "n"):
        return {b}
    k = int(b[1:])
    return {f"{b[0]}{k + d}" for d in (-1, 0, 1)}


def first_disagreement(got, case: int, stored, rtol: float, atol: float, hashed=None) -> int | None:
    """The first element of ``got`` (flattened) that is in no bin near the stored one, or None when all agree.
    ``stored[i]`` is the reference element's bin (in clear for the grader) or its digest under ``hashed``."""
    for i, x in enumerate(np.asarray(got, dtype=float).ravel()):
        near = near_bins(value_bin(float(x), rtol, atol))
        if not any((hashed(f"{case}|{i}|{b}") if hashed else b) == stored[i] for b in near):
            return i
    return None


def encode_case(x):
    """A case's inputs as JSON (floats exactly): numbers, strings, tuples, lists, arrays and objects of an
    importable class (their attributes). Raises TypeError for anything else (a class the hidden test defines)."""
    if x is None or isinstance(x, (bool, int, float, str)):
        return x
    if isinstance(x, np.generic):
        return x.item()
    if isinstance(x, (tuple, list)):
        return {"t" if isinstance(x, tuple) else "l": [encode_case(v) for v in x]}
    if isinstance(x, np.ndarray):
        return {"a": x.tolist(), "dt": x.dtype.str}
    cls = type(x)
    if hasattr(x, "__dict__") and _importable(cls.__module__):
        return {"o": [cls.__module__, cls.__qualname__], "d": {k: encode_case(v) for k, v in vars(x).items()}}
    raise TypeError(f"a case input of type {cls.__qualname__} cannot be carried in a token")


def _importable(module: str) -> bool:
    try:
        importlib.import_module(module)
    except ImportError:
        return False
    return True


def decode_case(x):
    """The inverse of :func:`encode_case`."""
    if not isinstance(x, dict):
        return x
    if "t" in x or "l" in x:
        items = [decode_case(v) for v in x.get("t", x.get("l"))]
        return tuple(items) if "t" in x else items
    if "a" in x:
        return np.array(x["a"], dtype=x["dt"])
    module, qualname = x["o"]
    cls = importlib.import_module(module)
    for part in qualname.split("."):
        cls = getattr(cls, part)
    obj = cls.__new__(cls)
    obj.__dict__.update({k: decode_case(v) for k, v in x["d"].items()})
    return obj


def seal_function(check: dict, salt: str) -> str:
    """A recorded function check (cases, each reference output's shape and element bins) as a token."""
    key = salt.encode()
    rows = [[list(shape), base64.b64encode(b"".join(digest(key, f"{n}|{i}|{b}") for i, b in enumerate(bins)))
             .decode()] for n, (shape, bins) in enumerate(check["outputs"])]
    body = {"t": "f", "rtol": check["rtol"], "atol": check["atol"], "cases": [encode_case(c) for c in check["cases"]],
            "rows": rows, "s": salt, "name": check["name"], "unit": "", "hint": check.get("hint", "")}
    return base64.b64encode(json.dumps(body, ensure_ascii=False, separators=(",", ":")).encode()).decode()
