"""Feedback at once for code and debug exercises: ``self_check(token, fn)`` in the student edition.

For every code or debug exercise (a hidden ``function_check``) of every assignment, the worked solution
(right), the given code (broken, or an empty body) and a function that raises are planted; the verdict
the notebook prints must be the grader's, must hold no output of the reference, and the edition must
hold neither the reference's code nor its outputs.
"""

from __future__ import annotations

import base64
import contextlib
import io
import json
import re
import sys
import tempfile
from pathlib import Path

import nbformat
import numpy as np
import pytest

from mechlab.course.exercises import NotYet, function_check, self_check
from mechlab.course.exercises.feedback import _args
from mechlab.course.exercises.selfcheck import decode_case, encode_case, near_bins, value_bin

ROOT = Path(__file__).resolve().parents[1]
SOURCE = ROOT / "assignments" / "source"
sys.path.insert(0, str(ROOT / "assignments"))
import variants  # noqa: E402  (assignments/ is a folder of scripts, not a package)

IDS = sorted(p.name for p in SOURCE.iterdir() if (p / f"{p.name}.ipynb").is_file()
             and "function_check(" in (p / f"{p.name}.ipynb").read_text(encoding="utf-8"))
DECIMAL = re.compile(r"-?\d+\.\d+(?:e[-+]?\d+)?")


def _exercises(aid):
    """(rendered master, [(cell, hidden test, token or None if the cell has none)]) of each function check
    of ``aid``."""
    nb = variants.render(nbformat.read(SOURCE / aid / f"{aid}.ipynb", as_version=4), aid, "ada")
    sealed = next(c for c in nb.cells if c.get("id") == "sealed-checks")
    env: dict = {}
    exec(sealed.source, env)
    found = []
    for c in nb.cells:
        hidden = "".join(variants.HIDDEN.findall(c.source))
        if "function_check(" in hidden:
            m = re.search(r'self_check\(CHECKS\["([^"]+)"\], (\w+)\);', c.source)
            found.append((c, hidden, env["CHECKS"][m.group(1)] if m else None))
    return nb, found


def _setup(nb) -> dict:
    env: dict = {}
    for c in nb.cells:
        role = c.metadata.get("nbgrader", {})
        if c.cell_type == "code" and role.get("locked") and not role.get("points") and "HIDDEN" not in c.source:
            with contextlib.redirect_stdout(io.StringIO()):
                exec(c.source, env)
    return env


def _plants(nb, name: str, env: dict) -> dict:
    """right: the worked solution; given: the code the student starts from; raises: a TypeError."""
    cell = next(c for c in nb.cells if re.search(rf"def {name}\(", c.source) and "BEGIN SOLUTION" in c.source)
    env = dict(env)
    with tempfile.TemporaryDirectory() as tmp, contextlib.chdir(tmp):   # a design may write its DXF
        for c in nb.cells[:nb.cells.index(cell)]:       # the worked solutions before it (helpers it may use)
            if "### BEGIN SOLUTION" in c.source:
                with contextlib.redirect_stdout(io.StringIO()), contextlib.suppress(Exception):
                    exec(c.source.split("### BEGIN SOLUTION\n")[1].split("### END SOLUTION")[0], env)
    given, solution = cell.source.split("### BEGIN SOLUTION\n")
    out = {}
    for label, code in (("given", given), ("right", given + solution.split("### END SOLUTION")[0])):
        scope = dict(env)
        exec(code, scope)
        out[label] = scope[name]

    def raises(*args):
        raise TypeError("planted failure")
    out["raises"] = raises
    return out


def _graded(hidden: str, env: dict, name: str, fn):
    """The grader's report on ``fn`` (the hidden test run as nbgrader runs it) and the reference's outputs."""
    seen = {}

    def spy(f, reference, cases, **kw):
        cases = list(cases)
        seen["outputs"] = [np.asarray(reference(*c), dtype=float) for c in cases]
        seen["cases"] = cases
        seen["report"] = function_check(f, reference, cases, **kw)
        return seen["report"]
    scope = {**env, "function_check": spy, name: fn}
    with contextlib.redirect_stdout(io.StringIO()), contextlib.suppress(NotYet):
        exec(hidden, scope)
    return seen


@pytest.mark.parametrize("aid", IDS)
def test_self_check_of_a_function_is_the_graders_verdict_and_shows_no_output(aid):
    nb, exercises = _exercises(aid)
    env = _setup(nb)
    assert exercises
    for cell, hidden, token in exercises:
        name = re.search(r'name="(\w+)"', hidden).group(1)
        assert token is not None and "checked when you submit" not in cell.source, (aid, name)
        for label, fn in _plants(nb, name, env).items():          # the whole cell, as autograde runs it
            scope = {**env, name: fn}
            with contextlib.redirect_stdout(io.StringIO()):
                try:
                    exec(cell.source, scope)
                    passed = True
                except NotYet:
                    passed = False
            assert passed == (label == "right"), (aid, name, label)
        kinds = {}
        for label, fn in _plants(nb, name, env).items():
            seen = _graded(hidden, env, name, fn)
            out = io.StringIO()
            with contextlib.redirect_stdout(out):
                mine = self_check(token, fn)
            report = seen["report"]
            assert mine.ok == report.ok, (aid, name, label, mine.message, repr(report))
            if not report.ok:
                assert mine.message == "✗ " + report.problem, (aid, name, label)
            kinds[label] = mine.kind
            printed = out.getvalue()
            for case in seen["cases"]:
                printed = printed.replace(_args(case), "")             # the inputs are the student's to see
            for s in DECIMAL.findall(printed):
                assert not any(np.any(np.abs(float(s) - o) <= 1e-3 * np.abs(o) + 1e-9) for o in seen["outputs"]), \
                    (aid, name, label, printed)
        assert kinds["right"] == "correct", (aid, name)
        assert kinds["given"] in ("wrong", "shape", "missing", "raised"), (aid, name, kinds)
        assert kinds["raises"] == "raised"
        assert self_check(token, None).kind == "missing" and self_check(token, 3.0).kind == "form"


@pytest.mark.parametrize("aid", IDS)
def test_the_edition_holds_neither_the_reference_nor_its_outputs(aid):
    nb, exercises = _exercises(aid)
    env = _setup(nb)
    edition = "\n".join(variants.SOLUTION.sub("", variants.HIDDEN.sub("", c.source)) for c in nb.cells)
    tokens = "\n".join(json.dumps(json.loads(base64.b64decode(t))) for _, _, t in exercises)
    for _cell, hidden, _token in exercises:
        assert "_reference" not in edition
        body = [line.strip() for line in hidden.splitlines() if line.strip().startswith("return ")]
        assert body and not any(line in edition for line in body), (aid, body)
        name = re.search(r'name="(\w+)"', hidden).group(1)
        seen = _graded(hidden, env, name, None)
        inputs = {float(s) for case in seen["cases"] for s in DECIMAL.findall(json.dumps(encode_case(case)))}
        for text in (edition, tokens):                  # an output may equal an input (the student's to see)
            numbers = [float(s) for s in DECIMAL.findall(text) if len(s.strip("-0.").split("e")[0]) >= 5
                       and float(s) not in inputs]
            for o in seen["outputs"]:
                assert not [x for x in numbers if np.any(np.abs(x - o) <= 1e-6 * np.abs(o) + 1e-12)], (aid, name)


def test_bins_agree_as_the_grader_says_and_cases_round_trip():
    """Within rtol/2 always the same or a neighbouring bin, beyond 2·rtol never; zero and NaN are own bins."""
    rng = np.random.default_rng(0)
    rtol = 1e-6
    for x in rng.uniform(-1e3, 1e3, 200):
        near = near_bins(value_bin(x, rtol, 1e-9))
        assert value_bin(x * (1 + rtol / 2), rtol, 1e-9) in near
        assert value_bin(x * (1 + 2.5 * rtol), rtol, 1e-9) not in near
        assert value_bin(-x, rtol, 1e-9) not in near
    assert value_bin(1e-12, rtol, 1e-9) == value_bin(-1e-12, rtol, 1e-9) == "z"
    assert value_bin(float("nan"), rtol, 1e-9) == "n"
    case = (1.5, 3, True, np.arange(3.0) / 7, [2, (0.1,)])
    back = decode_case(json.loads(json.dumps(encode_case(case))))
    assert back[:3] == case[:3] and type(back[1]) is int and back[4] == [2, (0.1,)]
    assert np.array_equal(back[3], case[3])
    with pytest.raises(TypeError):
        encode_case(type("Local", (), {"__module__": "__nowhere__"})())
