"""Feedback at once (mechlab.course.exercises.self_check) and a variant per student (assignments/variants.py).

For every auto-graded exercise of every assignment, in a student's edition: the right answer, each named
slip and a wrong answer are planted; the notebook's self-check must name the same verdict as the grader's
hidden test, print no number within tolerance of the expected value (but the student's own), and the
edition must hold neither the expected value nor the hidden test.
"""

from __future__ import annotations

import base64
import contextlib
import io
import json
import re
import sys
from pathlib import Path

import nbformat
import numpy as np
import pytest

from mechlab.course.exercises import check, check_choice, self_check, tolerance
from mechlab.course.exercises.selfcheck import classify, lookups, seal, slip_candidates, windows

ROOT = Path(__file__).resolve().parents[1]
SOURCE = ROOT / "assignments" / "source"
sys.path.insert(0, str(ROOT / "assignments"))
import variants  # noqa: E402  (assignments/ is a folder of scripts, not a package)

IDS = sorted(p.name for p in SOURCE.iterdir() if (p / f"{p.name}.ipynb").is_file())
# answers that are one of the prompt's numbers on purpose: the exercise is to recognise them
GIVEN = {("equivalence", "slot radius"): "the equivalent slot's radius is the coupler's length, given in the prompt"}
NUMBER = re.compile(r"-?\d+(?:\.\d+)?(?:e[-+]?\d+)?")


def _source(aid):
    return nbformat.read(SOURCE / aid / f"{aid}.ipynb", as_version=4)


def _tokens(nb) -> list[tuple[str, str]]:
    """(token, answer expression) of every number or choice self_check line of a rendered notebook, in order
    (a code exercise's, ``self_check(token, fn)``, is tested in test_selfcheck_functions.py)."""
    sealed = next(c for c in nb.cells if c.get("id") == "sealed-checks")
    env: dict = {}
    exec(sealed.source, env)
    return [(env["CHECKS"][m.group(1)], m.group(2)) for c in nb.cells
            for m in re.finditer(r'self_check\(CHECKS\["([^"]+)"\], (.+)\);', c.source)
            if json.loads(base64.b64decode(env["CHECKS"][m.group(1)]))["t"] != "f"]


def _said(token, answer) -> tuple[object, str]:
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        verdict = self_check(token, answer)
    return verdict, out.getvalue()


def _plants(call) -> dict[str, float]:
    """The answers to plant for a number check: right, each slip it names, and a wrong one."""
    e = call["expected"]
    plants = {"correct": e}
    plants.update({f"units:{gave}": e * factor for factor, gave, _ in call["unit_slips"]})
    if e:
        plants["sign"] = -e
    plants.update({f"alternative:{k}": v for k, v in call["alternatives"].items()})
    if e:
        plants["close"] = e * 1.008
    plants["wrong"] = e * 1.37 + 0.731
    return plants


def _expected_kind(plant: str) -> str:
    return plant.split(":")[0]


def _leaks(text: str, expected: float, own: float | None) -> list[str]:
    """Numbers in ``text`` within tolerance of ``expected`` (other than the student's own answer)."""
    tol = tolerance(expected)
    found = []
    for s in NUMBER.findall(text):
        x = float(s)
        if abs(x - expected) <= tol and not (own is not None and abs(x - own) <= 1e-3 * abs(own) + 1e-12):
            found.append(s)
    return found


@pytest.mark.parametrize("aid", IDS)
@pytest.mark.parametrize("student", ["", "ada"])
def test_self_check_names_what_the_grader_names_and_reveals_nothing(aid, student):
    nb = variants.render(_source(aid), aid, student)
    checks = [call for _, calls in variants._checks(nb) for call in calls if call["kind"] != "function"]
    tokens = _tokens(nb)
    assert len(tokens) == len(checks) >= 2, aid
    for (token, _), call in zip(tokens, checks, strict=False):
        if call["kind"] == "choice":
            for option in call["options"]:
                mine, _ = _said(token, option)
                graded = check_choice(option, call["expected"], call["options"], name=call["name"],
                                      hints=call["hints"])
                assert (mine.kind, mine.ok, mine.message) == (graded.kind, graded.ok, graded.message), (aid, option)
            continue
        e = call["expected"]
        for plant, value in _plants(call).items():
            mine, printed = _said(token, value)
            graded = check(value, e, name=call["name"], unit=call["unit"], significant=call["significant"],
                           alternatives=call["alternatives"], hint=call["hint"])
            assert (mine.kind, mine.ok, mine.message) == (graded.kind, graded.ok, graded.message), (aid, plant)
            want = _expected_kind(plant)
            if want in ("units", "sign", "alternative") and _near_other(value, plant, call):
                continue                                                 # two slips give one value: the first wins
            assert mine.kind == want, (aid, call["name"], plant, mine.message)
            assert not _leaks(printed, e, value), (aid, plant, printed)
            for word in ("radians", "degrees", "metres", "millimetres", "ms", "rpm", "deg/s"):
                if plant == f"units:{word}":
                    assert word in printed
        for missing in (..., None, "twelve"):
            mine, _ = _said(token, missing)
            assert mine.kind == check(missing, e, name=call["name"], unit=call["unit"]).kind


@pytest.mark.parametrize("aid", IDS)
def test_the_editions_check_cells_run_on_their_own(aid):
    """The rendered check cells, run as the student runs them (set-up, numbers, sealed checks, then each check
    cell's visible line with the right answer bound): every one says ✓."""
    nb = variants.render(_source(aid), aid, "ada")
    calls = [call for _, cs in variants._checks(nb) for call in cs if call["kind"] != "function"]
    functions = {call["name"] for _, cs in variants._checks(nb) for call in cs if call["kind"] == "function"}
    env: dict = {}
    for c in nb.cells:
        role = c.metadata.get("nbgrader", {})
        if c.cell_type == "code" and role.get("locked") and not role.get("points") and "HIDDEN" not in c.source:
            exec(c.source, env)
    lines = [line for c in nb.cells for line in variants.HIDDEN.sub("", c.source).splitlines()
             if line.startswith("self_check(") and line.split("], ")[1].rstrip(");") not in functions]
    assert len(lines) == len(calls)
    for line, call in zip(lines, calls, strict=False):
        answer = re.search(r"\], (.+)\);$", line).group(1)
        env[answer] = call["expected"]
        out = io.StringIO()
        with contextlib.redirect_stdout(out):
            exec(line, env)
        assert out.getvalue().startswith("✓"), (aid, line[:60], out.getvalue())


def _near_other(value, plant, call) -> bool:
    """True when the planted slip also falls in the window of a row tried before it (e.g. −e = an alternative)."""
    table = slip_candidates(call["expected"], call["unit_slips"], call["alternatives"], call["significant"])
    order = [("units:" + label if kind == "units" else kind if kind != "alternative" else "alternative:" + label)
             for kind, label, _, _ in table]
    mine = plant if plant in order else None
    look = lookups(value, call["significant"])
    earlier = order[:order.index(mine)] if mine else []
    return any(look & bins for (kind, label, _, bins), name in zip(table, order, strict=False) if name in earlier)


@pytest.mark.parametrize("aid", IDS)
def test_the_edition_holds_no_expected_value(aid):
    nb = variants.render(_source(aid), aid, "ada")
    checks = [call for _, calls in variants._checks(nb) for call in calls if call["kind"] == "number"]
    tokens = [t for t, _ in _tokens(nb)]
    for token in tokens:
        body = json.loads(base64.b64decode(token))
        shown = json.dumps({k: v for k, v in body.items() if k != "rows"}) + " ".join(
            " ".join(row[:3]) for row in body["rows"] if isinstance(row[0], str) and len(row) == 4)
        for call in checks:
            assert not _leaks(shown, call["expected"], None), (aid, call["name"])
    text = "\n".join(variants.SOLUTION.sub("", variants.HIDDEN.sub("", c.source)) for c in nb.cells
                     if c.get("id") != "sealed-checks")
    for call in (c for c in checks if (aid, c["name"]) not in GIVEN):
        assert not [s for s in NUMBER.findall(text) if len(s.strip("-0.")) >= 3
                    and abs(float(s) - call["expected"]) <= tolerance(call["expected"])], (aid, call["name"])


def test_bins_agree_with_the_textbook_tolerance_up_to_a_tenth_of_it():
    rng = np.random.default_rng(1)
    for e in np.concatenate([rng.uniform(-1e3, 1e3, 200), 10.0 ** rng.uniform(-4, 4, 200), [9.996, 1.0, 0.0]]):
        tol = tolerance(e)
        table = slip_candidates(e, [], {})
        for a in (e + 0.8 * tol, e - 0.8 * tol, e):
            assert classify(a, table)[0] == "correct", (e, a)
        for a in (e + 1.3 * tol, e - 1.3 * tol):
            assert (classify(a, table) or ("wrong",))[0] != "correct", (e, a)
        if e:
            assert classify(e * 1.007, table)[0] == "close" and classify(e * 1.015, table) is None
    assert windows(0.0, right=True) & lookups(0.0004) and not windows(0.0, right=True) & lookups(0.0007)


def test_a_token_without_its_salt_reveals_no_bin_and_a_damaged_token_is_named():
    call = dict(kind="number", expected=57.4, name="r", unit="mm", significant=3, alternatives={}, hint="",
                unit_slips=[(1e-3, "metres", "multiply by 1000")])
    a, b = seal(call, "one"), seal(call, "two")
    rows_a = json.loads(base64.b64decode(a))["rows"]
    rows_b = json.loads(base64.b64decode(b))["rows"]
    assert [r[3] for r in rows_a] != [r[3] for r in rows_b]             # keyed: another salt, other digests
    assert "57" not in base64.b64decode(a).decode()
    with pytest.raises(ValueError, match="damaged"):
        self_check("not a token!", 1.0)


# -- variants -------------------------------------------------------------------------------------------------
def test_variants_are_deterministic_distinct_and_in_range():
    src = _source("geneva_spherical")
    ranges = variants.variant_cell(src).metadata["mechlab"]["variant"]
    ids = [f"s{k:03d}" for k in range(30)]
    drawn = [variants.draw(ranges, "geneva_spherical", s) for s in ids]
    assert len({json.dumps(d, sort_keys=True) for d in drawn}) == 30
    assert drawn == [variants.draw(ranges, "geneva_spherical", s) for s in ids]
    assert variants.draw(ranges, "geneva", "s000") != drawn[0]            # another assignment, other numbers
    for d in drawn:
        for name, (lo, hi, step) in ranges.items():
            assert lo <= d[name] <= hi and abs((d[name] - lo) / step - round((d[name] - lo) / step)) < 1e-9
    one = nbformat.writes(variants.render(src, "geneva_spherical", "s007"))
    assert one == nbformat.writes(variants.render(src, "geneva_spherical", "s007"))   # byte-identical
    assert one != nbformat.writes(variants.render(src, "geneva_spherical", "s008"))


def test_whose_flags_edited_and_copied_numbers():
    src = _source("geneva_spherical")
    masters = {s: variants.render(src, "geneva_spherical", s) for s in ("ann", "ben")}
    ann = masters["ann"]
    assert variants.whose(ann, "geneva_spherical", "ann", masters) == ""
    assert variants.whose(masters["ben"], "geneva_spherical", "ann", masters) == "carries the numbers of ben"
    edited = nbformat.reads(nbformat.writes(ann), as_version=4)
    cell = variants.variant_cell(edited)
    cell.source = re.sub(r"'rpm': \d+", "'rpm': 41", cell.source)
    assert variants.whose(edited, "geneva_spherical", "ann", masters) == "variant numbers edited by hand"


def test_the_class_report_names_the_choice_made(tmp_path, monkeypatch):
    """A wrong multiple-choice answer reads as the option chosen (which distractor), never as "not a number"."""
    import report
    log = tmp_path / "log.jsonl"
    monkeypatch.setenv("MECHLAB_GRADE_LOG", str(log))
    options = {"a": "faster", "b": "slower", "c": "the same"}
    subs = []
    for who, answer in (("ann", "a"), ("bob", "B "), ("cy", "b"), ("dee", "z"), ("eve", 2.5)):
        log.write_text("")
        check_choice(answer, "a", options, name="prediction")
        if answer == 2.5:
            check(answer, 2.5, name="speed")
        verdicts = [json.loads(line) for line in log.read_text().splitlines()]
        subs.append(report.Submission(who, "geneva", verdicts))
    table = {r["outcome"]: r["students"] for r in report.rows(subs, {"geneva": ["prediction"]})}
    assert table == {"right": 1, "chose (b)": 2, "chose 'z', not one of the options": 1,
                     "chose '2.5', not one of the options": 1}
    speed = report.rows(subs, {"geneva": ["speed"]})
    assert {r["outcome"] for r in speed} >= {"right"}                   # numbers keep their own labels


@pytest.mark.parametrize("student", ["", "ada", "bo", "cy"])
def test_geneva_names_degrees_fed_to_sin(student):
    """Exercise 3 of geneva: λ = np.sin(180 / z) (degrees into np.sin) is named as that slip, not "not yet"."""
    nb = variants.render(_source("geneva"), "geneva", student)
    V, _ = variants.numbers(nb)
    token = next(t for t, answer in _tokens(nb) if answer == "omega_max")
    lam = np.sin(180 / V["z"])
    verdict, printed = _said(token, lam / (1 - lam) * V["rpm"] * np.pi / 30)
    assert verdict.kind == "alternative" and "degrees where np.sin takes radians" in printed
    assert _said(token, lam)[0].kind == "wrong"                         # λ alone is not that slip
