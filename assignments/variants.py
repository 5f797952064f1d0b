"""A variant per student: each student's numbers, drawn from the student id and the assignment, written into that
student's copy of the assignment's source before nbgrader sees it.

How (after PrairieLearn's split of a question into the parameters a student sees and the answers the server keeps, and
what nbgrader's maintainers say of its design in nbgrader issues #1153 and #1433: one source, one release, the hidden
tests re-inserted from the master at autograde): the source notebook is a template. Its cell tagged
``metadata.mechlab.variant`` (``{"R": [40, 80, 5], …}``: low, high, step) holds the shared numbers as ``V = {...}``;
markdown cells say ``{{R}}`` where a number goes. :func:`render` writes one student's master: that cell with the
student's numbers and id, the placeholders filled, every check cell's visible line replaced by
``self_check(CHECKS[key], answer);`` (for a code exercise ``self_check(CHECKS[key], the_function);``, its token
holding the hidden cases' inputs and the digests of the reference's outputs) and a cell ``CHECKS = {key: token}``
(source hidden in JupyterLab) after the numbers, each token sealed (:mod:`mechlab.course.exercises.selfcheck`) from
the very call its hidden test makes (run here with :func:`~mechlab.course.exercises.recording`). ``make student``
releases each student's master; ``make grade`` releases the master of the student id nbgrader files the submission
under, so nbgrader's own OverwriteCells puts that student's numbers back in the locked cells and the hidden tests
grade against them, whatever the submitted notebook says (a hand-edited or another student's ``V`` is flagged by
:func:`whose`).

Numbers are ``low + k·step`` with k from SHA-256 of (assignment, student id, draw): the same on every machine and run.
A draw whose checks give a non-finite expected value is drawn again (``draw`` 1, 2, …)."""

from __future__ import annotations

import ast
import builtins
import contextlib
import copy
import hashlib
import io
import math
import re

import nbformat

from mechlab.course.exercises import feedback, function_check
from mechlab.course.exercises.selfcheck import seal

HIDDEN = re.compile(r"### BEGIN HIDDEN TESTS\n(.*?)### END HIDDEN TESTS\n?", re.S)
SOLUTION = re.compile(r"### BEGIN SOLUTION\n.*?### END SOLUTION\n?", re.S)
SHARED = ""   # the student id of the shared edition (no class list)
CHECKERS = ("check", "check_choice", "function_check")   # the calls a hidden test grades with
CALL = re.compile(r"\b(?:check|check_choice|function_check)\(")


def variant_cell(nb):
    """The cell holding ``V = {...}`` (tagged ``metadata.mechlab.variant``), or None."""
    return next((c for c in nb.cells if "variant" in c.metadata.get("mechlab", {})), None)


def defaults(nb) -> dict:
    """The source's shared numbers (the dict literal of its variant cell)."""
    cell = variant_cell(nb)
    if cell is None:
        return {}
    tree = ast.parse(cell.source)
    for node in tree.body:
        if isinstance(node, ast.Assign) and getattr(node.targets[0], "id", "") == "V":
            return ast.literal_eval(node.value)
    raise ValueError(f"variant cell {cell.get('id')}: no `V = {{...}}` literal")


def draw(ranges: dict, aid: str, student: str, attempt: int = 0) -> dict:
    """The student's numbers: each ``low + k·step`` (k uniform on the grid) from SHA-256 of the ids."""
    out = {}
    for name, (low, high, step) in sorted(ranges.items()):
        n = round((high - low) / step) + 1
        h = int.from_bytes(hashlib.sha256(f"{aid}|{student}|{attempt}|{name}".encode()).digest()[:8], "big")
        value = low + (h % n) * step
        out[name] = int(value) if all(float(x).is_integer() for x in (low, step)) else round(value, 10)
    return out


def _literal(values: dict) -> str:
    return "{" + ", ".join(f"{k!r}: {v!r}" for k, v in values.items()) + "}"


def _fill(text: str, values: dict) -> str:
    return re.sub(r"\{\{(\w+)\}\}", lambda m: f"{values[m.group(1)]:g}" if m.group(1) in values else m.group(0),
                  text)


class _Unanswered(dict):
    """Exec locals in which an answer the student has not given yet reads as None (globals still win)."""

    def __init__(self, known):
        super().__init__()
        self.known = known

    def __missing__(self, key):
        if key in self.known or hasattr(builtins, key):
            raise KeyError(key)
        return None


def _checks(nb) -> list[tuple[int, list[dict]]]:
    """Run the set-up cells and every check cell's hidden test with the checks recording: for each check
    cell, the calls it makes (expected values in clear: only the lecturer's side ever holds them)."""
    env: dict = {"__name__": "__variant__"}
    found = []
    for k, cell in enumerate(nb.cells):
        if cell.cell_type != "code":
            continue
        role = cell.metadata.get("nbgrader", {})
        if role.get("locked") and not role.get("points") and not HIDDEN.search(cell.source):
            with contextlib.redirect_stdout(io.StringIO()):                     # set-up, variant
                exec(compile(cell.source, f"<cell {cell.get('id')}>", "exec"), env)
            continue
        hidden = "".join(HIDDEN.findall(cell.source))
        if not re.search(CALL, hidden):
            continue
        with feedback.recording() as calls, contextlib.redirect_stdout(io.StringIO()):
            code = compile(hidden, f"<hidden {cell.get('id')}>", "exec")
            if "function_check(" in hidden:
                # one namespace, so the test's comprehensions see its own names; the student's function
                # (not defined here) reads as None, and the test's names stay out of ``env``
                exec(code, {**env, "function_check": function_check,
                            **{name: None for name in _answers(hidden) if name.isidentifier()}})
            else:
                exec(code, env, _Unanswered(env))
        found.append((k, calls))
    return found


def _answers(hidden: str) -> list[str]:
    """The answer expressions (first argument) of the hidden test's check calls, in order."""
    calls = [node for node in ast.walk(ast.parse(hidden)) if isinstance(node, ast.Call)
             and getattr(node.func, "id", "") in CHECKERS]
    calls.sort(key=lambda c: (c.lineno, c.col_offset))
    return [ast.unparse(c.args[0]) for c in calls]


def _answer(hidden: str, n: int) -> list[str]:
    """:func:`_answers`, which must be one per recorded call."""
    found = _answers(hidden)
    if len(found) != n:
        raise ValueError(f"{len(found)} check calls in the hidden test, {n} recorded")
    return found


def _wrapped(token: str, width: int = 88) -> str:
    """A token as adjacent string literals in parentheses, one short line each (Python joins them): the
    sealed cell stays within the notebook's width."""
    chunks = [token[i:i + width] for i in range(0, len(token), width)] or [""]
    return "(\n" + "".join(f"        {c!r}\n" for c in chunks) + "    )"


def salt(aid: str, student: str, cell_id: str, k: int) -> str:
    return hashlib.sha256(f"mechlab|{aid}|{student}|{cell_id}|{k}".encode()).hexdigest()[:16]


def render(src, aid: str, student: str = SHARED, values: dict | None = None):
    """One student's master of ``aid``: numbers, placeholders and self-check tokens filled (see the module).

    ``values`` overrides the draw (tests); without a class (``student`` empty) the source's own numbers.
    Raises ValueError when no draw in 20 gives finite expected values.
    """
    base = defaults(src)
    cell = variant_cell(src)
    for attempt in range(20):
        nb = copy.deepcopy(src)
        if cell is not None:
            mine = values or (base if student == SHARED else draw(cell.metadata["mechlab"]["variant"], aid, student,
                                                                attempt))
            mine = {k: mine.get(k, v) for k, v in base.items()}
            vc = variant_cell(nb)
            vc.source = (f"V = {_literal(mine)}  # your numbers"
                         + (f" (variant of student {student!r})" if student else "") + "\n")
        else:
            mine = {}
        for c in nb.cells:
            if c.cell_type == "markdown":
                c.source = _fill(c.source, mine)
        checks = _checks(nb)
        if all(math.isfinite(call["expected"]) for _, calls in checks for call in calls if call["kind"] == "number"):
            break
        if values or student == SHARED:
            raise ValueError(f"{aid}: the numbers {mine} give a non-finite expected value")
    else:
        raise ValueError(f"{aid}: no variant of {student!r} in 20 draws gives finite expected values")
    sealed = {}
    for k, calls in checks:
        c = nb.cells[k]
        hidden = "".join(HIDDEN.findall(c.source))
        gid = c.metadata.get("nbgrader", {}).get("grade_id", c.get("id", str(k)))
        lines = []
        for j, (call, answer) in enumerate(zip(calls, _answer(hidden, len(calls)), strict=False)):
            try:
                sealed[f"{gid}:{j}"] = seal(call, salt(aid, student, gid, j))
            except TypeError as err:     # every auto-graded answer is checked in the notebook: no exception
                raise ValueError(f"{aid}: {gid}: {err} (give the hidden test's cases as objects of an importable "
                                 "class, e.g. one in mechlab.course.exercises)") from err
            lines.append(f'self_check(CHECKS["{gid}:{j}"], {answer});')
        if any(call["kind"] == "function" for call in calls):     # the hidden test's own check, for autograde
            lines.insert(0, "from mechlab.course.exercises import function_check")
        c.source = "\n".join(lines) + "\n" + HIDDEN.search(c.source).group(0)
    if sealed:
        at = nb.cells.index(variant_cell(nb) or next(c for c in nb.cells if c.cell_type == "code")) + 1
        cell = nbformat.v4.new_code_cell(
            "# what the check cells compare your answers with, sealed (no number in it): run it, do not edit it\n"
            "from mechlab.course.exercises import self_check\n\nCHECKS = {\n"
            + "".join(f"    {k!r}: {_wrapped(v)},\n" for k, v in sealed.items()) + "}\n")
        cell["id"] = "sealed-checks"
        cell.metadata.update({"jupyter": {"source_hidden": True}, "nbgrader": {
            "grade": False, "grade_id": "sealed_checks", "locked": True, "schema_version": 3, "solution": False,
            "task": False}})
        nb.cells.insert(at, cell)
    return nb


def numbers(nb) -> tuple[dict, str | None]:
    """The numbers a (submitted) notebook's variant cell holds and the student it names (None if absent)."""
    cell = variant_cell(nb)
    if cell is None:
        return {}, None
    try:
        values = defaults(nb)
    except (ValueError, SyntaxError):
        values = {}
    m = re.search(r"variant of student '([^']*)'", cell.source)
    return values, (m.group(1) if m else None)


def whose(nb, aid: str, student: str, masters: dict[str, nbformat.NotebookNode]) -> str:
    """"" when the submission's numbers are the student's own; else a flag naming what is wrong: another
    student's numbers (``masters`` maps ids to their rendered masters), or numbers edited by hand."""
    got, named = numbers(nb)
    own, _ = numbers(masters[student]) if student in masters else ({}, None)
    if got == own and named in (student, None):
        return ""
    for other, master in masters.items():
        if other != student and numbers(master)[0] == got:
            return f"carries the numbers of {other}"
    return "variant numbers edited by hand" if got != own else f"variant cell names student {named!r}"
