"""mechlab.course.exercises: the feedback of `check` (each slip recognised with its slip), the design and code
checks (each with a passing and a failing design), and the assignments' shape (no answer in the package)."""

from __future__ import annotations

import functools
import json
import re
from pathlib import Path

import numpy as np
import pytest

import mechlab as ml
from mechlab.course import exercises as ex
from mechlab.course.exercises import (
    NotYet,
    cam_design,
    check,
    check_choice,
    check_form,
    dwell_slot_design,
    fourbar_design,
    function_check,
    geneva_design,
    guide_design,
    output_design,
    press_design,
    sixbar_design,
    tolerance,
)
from mechlab.synthesis.slot_export import write_dxf

SOURCE = Path(__file__).resolve().parents[1] / "assignments" / "source"
CAT = [90, 120, 180, 250, 370, 550, 750, 1100, 1500, 2200]


# -- check: tolerance, close, slips -----------------------------------------------------------------------
def test_textbook_tolerance_is_three_significant_figures_and_said():
    assert tolerance(2 / 3) == pytest.approx(5e-4) and tolerance(57.4) == pytest.approx(0.05)
    v = check(0.667, 2 / 3)
    assert v and v.kind == "correct" and "3 significant figures" in repr(v)
    assert check(57.40, 150 * np.sin(np.pi / 8), unit="mm")          # 57.4025 rounded
    assert not check(0.6685, 2 / 3)                                   # beyond half a unit in the 3rd figure


def test_close_answers_are_asked_for_more_digits():
    v = check(0.67, 2 / 3)
    assert not v and v.kind == "close" and "give more digits" in v.message and "0.0005" not in v.message
    assert check(0.6617, 2 / 3).kind == "close" and check(0.6567, 2 / 3).kind == "wrong"   # 0.75 %, 1.5 % off


@pytest.mark.parametrize("unit, right, slipped, words", [
    ("rad", 0.6, np.degrees(0.6), "degrees"),
    ("deg", 34.38, np.radians(34.38), "radians"),
    ("mm", 57.4, 0.0574, "metres"),
    ("m", 0.25, 250.0, "millimetres"),
    ("rad/s", 9.42, 9.42 * 30 / np.pi, "rpm"),
    ("rad/s", 9.42, np.degrees(9.42), "deg/s"),
    ("N·m", 85.7, 85700.0, "N·mm"),
    ("W", 225.0, 0.225, "kW"),
])
def test_unit_slips_are_named(unit, right, slipped, words):
    v = check(slipped, right, unit=unit)
    assert not v and v.kind == "units" and words in v.message
    assert check(right, right, unit=unit)


def test_flipped_sign_and_other_assembly_are_named_without_the_answer():
    v = check(10.0, -10.0)
    assert v.kind == "sign" and "sign" in v.message and "-10" not in v.message
    other = ml.FourBar(1, 3, 3, 4, -1).motion(np.pi / 2).dpsi
    right = ml.FourBar(1, 3, 3, 4, 1).motion(np.pi / 2).dpsi
    v = check(other, right, alternatives={"the other assembly (−1)": other}, hint="use assembly=+1")
    assert v.kind == "alternative" and "the other assembly" in v.message and "use assembly=+1" in v.message
    assert f"{right:.3g}" not in v.message
    assert check(123.0, 1.0, hint="look at Table 2").message.endswith("Hint: look at Table 2")


def test_missing_and_malformed_answers():
    assert check(..., 1.0).kind == "missing" and check(None, 1.0).kind == "missing"
    for bad in ("12", [1.0, 2.0], np.nan, True):
        assert check(bad, 1.0).kind == "form"
    assert check(np.float64(1.0), 1.0) and check(np.array([1.0]), 1.0) and check(0.0004, 0.0)


def test_a_verdict_is_one_line_and_can_be_asserted():
    v = check(0.6, 0.6, name="λ")
    assert "\n" not in repr(v) and bool(v) is True
    with pytest.raises(NotYet, match="give more digits") as err:
        check(0.67, 2 / 3).require()
    assert " ".join(err.value._render_traceback_()).split() == str(err.value).split()   # the message alone
    long = check(1e6, 1.0, hint="x " * 80)
    with pytest.raises(NotYet) as err:
        long.require()
    assert len(err.value._render_traceback_()) > 1 and max(map(len, err.value._render_traceback_())) <= 100
    assert isinstance(err.value, AssertionError)


def test_choice_and_form():
    opts = {"a": "grows", "b": "stays", "c": "shrinks"}
    assert check_choice(" A ", "a", opts)
    v = check_choice("c", "a", opts, hints={"c": "a longer crank moves A further"})
    assert v.kind == "choice" and "a longer crank" in v.message
    assert check_choice("d", "a", opts).kind == "form" and check_choice(..., "a", opts).kind == "missing"
    assert check_form(1.5, unit="mm") and not check_form("x") and not check_form(...)


def test_the_package_holds_no_answer():
    assert not hasattr(ex, "solution") and not hasattr(ex, "get")
    names = {p.stem for p in Path(ex.__file__).parent.glob("*.py")}
    # lab_model: the +1 assembly only; coupler: chapter 8a's dwell six-bar, measured from its joints
    assert names == {"__init__", "feedback", "design", "selfcheck", "lab_model", "coupler"}


# -- design and code checks: one passing, one failing design each --------------------------------------------
def test_fourbar_design():
    good = fourbar_design(ml.FourBar(1.12, 3.5, 3.0, 4.0), swing=45, min_transmission=40)
    assert good and "✓ rocker swing 44.9" in repr(good)
    bad = fourbar_design(ml.FourBar(1.0, 3.5, 3.0, 4.0), swing=45, min_transmission=56, time_ratio_at_least=1.1)
    assert not bad and [s.met for s in bad.specs] == [False, False, False]
    assert "✗ smallest transmission angle min(μ, 180° − μ) 54.31° < 56° at φ = 0°" in repr(bad)
    assert "does not turn fully" in fourbar_design(ml.FourBar(2, 4, 3.5, 1.5)).problem
    assert not fourbar_design(...) and "expected a mechlab FourBar" in fourbar_design(1.0).problem


def test_output_design():
    assert output_design(ml.SlottedLink(0.45, 1.0), min_swing=50, max_velocity=1.0)
    bad = output_design(ml.SlottedLink(0.6, 1.0), min_swing=50, max_velocity=1.0)
    assert not bad and "largest |ψ′| 1.5 > 1" in repr(bad)          # λ/(1 − λ) = 1.5


def test_guide_design():
    good = ml.circle_guiding(np.radians(150), 0.9, np.radians(110))
    assert guide_design(good, min_dwell=110, max_band=5e-5, min_crank=0.2)
    bad = guide_design(ml.circle_guiding(np.radians(150), 0.9, np.radians(120)), min_dwell=110, max_band=5e-5,
                       min_crank=0.2)
    assert not bad and "✗ band half-width E" in repr(bad)


def test_dwell_slot_design_with_its_dxf(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)                                # the check reads only the notebook's own folder
    design = ml.curved_slot_dwell(0.3, np.radians(59), np.radians(149.5), transition="quintic")
    path = Path("slot.dxf")
    report = dwell_slot_design(design, min_dwell=90, max_pressure=70, dxf=path)
    assert not report and "no DXF file" in report.problem
    write_dxf(design, path)
    assert dwell_slot_design(design, min_dwell=90, max_pressure=70, dxf=path)
    bad = dwell_slot_design(design, min_dwell=90, max_pressure=45, dxf=path)
    assert not bad and "✗ pressure angle 67.92° ≥ 45° at φ = 180°" in repr(bad)
    other = ml.curved_slot_dwell(0.5, np.radians(40), np.radians(140))
    assert "export the design you checked" in dwell_slot_design(other, min_dwell=90, max_pressure=90, dxf=path).problem


def test_sixbar_design():
    guide = ml.circle_guiding(np.radians(150), 0.9, np.radians(120))
    assert sixbar_design(ml.mchv1(guide, 1.25, np.radians(30), side=-1), 120, time_ratio=1.25, swing=30)
    bad = sixbar_design(ml.mchv1(guide, 1.0, np.radians(20)), 120, time_ratio=1.25, swing=30)
    assert not bad and [s.met for s in bad.specs] == [False, False, True]


def _lambda_sixbar(pivot_angle: float, rocker: float):
    """Chapter 6's lambda design (δ = 150°, a = 0.9, 2α = 120°) with a rod of the band's radius R at D and an output
    rocker pivoted at F, R·``rocker`` from the band's centre in the direction ``pivot_angle`` (degrees): built by hand
    with the structure builder, as a student may."""
    deg = np.pi / 180
    g = ml.circle_guiding(150 * deg, 0.9, 120 * deg)
    F = g.centre + rocker * g.R * np.array([np.cos(pivot_angle * deg), np.sin(pivot_angle * deg)])
    return (ml.Linkage({"O": (0, 0), "C": (0.9, 0), "F": tuple(F)}, ml.Crank("O", "A", g.r))
            .rrr("A", "C", "B", 1.0, 1.0, links=("coupler", "rocker"))
            .point("D", "coupler", (1 - np.cos(150 * deg), -np.sin(150 * deg)))
            .rrr("D", "F", "E", g.R, rocker * g.R, links=("rod", "output")))


def test_dwell_sixbar_design():
    from mechlab.course.exercises import dwell_sixbar_design

    good = dwell_sixbar_design(_lambda_sixbar(0, 1.2), min_dwell=150, max_residual=0.5, min_swing=25)
    assert good and [s.name for s in good.specs][2:] == ["transmission angle at B, min(μ, 180° − μ)",
                                                         "transmission angle at E, min(μ, 180° − μ)"]
    # a pivot beside the arc: the dyad folds, the output creeps through the dwell
    bad = dwell_sixbar_design(_lambda_sixbar(90, 0.8), min_dwell=150, max_residual=0.5, min_swing=25)
    assert not bad and [s.met for s in bad.specs] == [False, True, True, False]
    assert "✗ transmission angle at E, min(μ, 180° − μ) 1.1" in repr(bad)
    # a stricter band gives a shorter still interval, measured, not assumed
    strict = dwell_sixbar_design(_lambda_sixbar(0, 1.2), min_dwell=150, max_residual=0.05, min_swing=25)
    assert good.specs[0].value > strict.specs[0].value > 60
    assert "turn fully" in dwell_sixbar_design(_lambda_sixbar(270, 0.8), min_dwell=90, max_residual=0.5,
                                               min_swing=10).problem
    assert "no design yet" in dwell_sixbar_design(..., min_dwell=90, max_residual=0.5, min_swing=10).problem
    assert "expected a mechlab Linkage" in dwell_sixbar_design(ml.FourBar(1, 3, 3, 4), min_dwell=90, max_residual=0.5,
                                                               min_swing=10).problem
    slider = ml.Linkage({"O": (0, 0), "G": (0, 0)}, ml.Crank("O", "A", 1.0)).rrp("A", "B", 3.0, ml.Guide("G"))
    assert "slides" in dwell_sixbar_design(slider, min_dwell=90, max_residual=0.5, min_swing=10).problem


def test_the_longest_still_interval_is_the_brute_force_one():
    from mechlab.course.exercises.coupler import longest_still_interval

    rng = np.random.default_rng(8)
    for _ in range(60):
        psi, band = rng.normal(size=rng.integers(5, 30)).cumsum(), rng.uniform(0.2, 3.0)
        n = len(psi)
        best = max((length for start in range(n) for length in range(1, n + 1)
                    if np.ptp(np.take(psi, range(start, start + length), mode="wrap")) <= band), default=0)
        length, start = longest_still_interval(psi, band)
        assert length == best and np.ptp(np.take(psi, range(start, start + length), mode="wrap")) <= band
    assert longest_still_interval(np.zeros(7), 0.0) == (7, 0)


def test_geneva_design():
    from mechlab.kinetostatics.geneva import geneva_drive

    g = ml.ExternalGeneva(6, 0.2)
    need = geneva_drive(g, inertia=0.8, omega1=85 * np.pi / 30, n=2001).nominal_power
    motor = min(p for p in CAT if p >= need)
    assert geneva_design(g, rpm=85, inertia=0.8, index_time=0.25, motor_power=motor, min_rpm=60, catalogue=CAT)
    slow = geneva_design(g, rpm=70, inertia=0.8, index_time=0.25, motor_power=max(CAT), min_rpm=60, catalogue=CAT)
    assert not slow and "✗ index time 0.2857 s > 0.25 s" in repr(slow)
    assert "✗ smaller catalogue motors that would also do 7 > 0" in repr(slow)   # 2200 W: far more than needed
    sph = geneva_design(ml.SphericalGeneva(40.0, 5.0, 4), rpm=60, inertia=0.02, index_time=0.45, motor_power=2200,
                        min_dwell_fraction=0.6, impacts=("soft", "none"))
    assert not sph and "✗ dwell fraction 0.5557 < 0.6" in repr(sph) and "impact at entry is 'hard'" in sph.problem


def test_press_design():
    k = ml.forces.press(0.125, 0.5)
    r = k.forces(k.turn(721))
    motor = min(p for p in CAT if p >= ml.forces.drive(r.torque, r.phi, r.omega1).nominal_power)
    assert press_design(k, motor, stroke=0.25, stroke_tol=0.002, max_pressure=15, catalogue=CAT)
    bad = press_design(ml.forces.press(0.125, 0.4), motor, stroke=0.25, stroke_tol=0.002, max_pressure=15)
    assert not bad and "✗ pressure angle 18.21° ≥ 15° at φ = 90°" in repr(bad)


@pytest.mark.skipif(not hasattr(ml, "TranslatingRollerCam"), reason="the cams are not in this mechlab yet")
def test_cam_design():
    deg = np.pi / 180
    pusher = ml.CamProgramme(stroke=20.0, rise=120 * deg, ret=100 * deg, outer_dwell=40 * deg)
    assert cam_design(ml.TranslatingRollerCam(pusher, 40.0, 10.0, offset=8.0), max_pressure=30, max_base_radius=40)
    assert "✗ base radius 40 > 35" in repr(cam_design(ml.TranslatingRollerCam(pusher, 40.0, 10.0), max_pressure=30,
                                                      max_base_radius=35))
    nose = ml.CamProgramme(stroke=30.0, rise=40 * deg, ret=40 * deg)
    bad = cam_design(ml.TranslatingRollerCam(nose, base_radius=15.0, roller_radius=11.0), max_pressure=30)
    assert not bad and "✗ pressure angle 65.76° ≥ 30° at φ = 17°" in repr(bad) and "undercut" in bad.problem
    assert "expected a mechlab roller cam" in cam_design(ml.FourBar(1, 3, 3, 4), max_pressure=30).problem
    cam = ml.TranslatingRollerCam(pusher, 40.0, 10.0, offset=8.0)
    assert cam_design(cam, max_pressure=30, motion=(20, 120, 40, 100))
    easier = cam_design(cam, max_pressure=30, motion=(25, 120, 40, 90))    # a smaller stroke, a slower return
    assert not easier and [s.met for s in easier.specs][-4:] == [False, True, True, False]
    assert "✗ stroke 20: outside 25 ± 0.05" in repr(easier)


def test_function_check():
    def ref(z):
        return ml.ExternalGeneva(z, 1.0).max_velocity()

    cases = [(z,) for z in range(3, 10)]

    def good(z):
        return np.sin(np.pi / z) / (1 - np.sin(np.pi / z))

    assert function_check(good, ref, cases, name="peak", rtol=1e-9)
    wrong = function_check(lambda z: np.sin(np.pi / z), ref, cases, name="peak")
    assert not wrong and "peak(3) is not what the reference gives" in repr(wrong) and "6.464" not in repr(wrong)
    assert "raised ZeroDivisionError" in function_check(lambda z: 1 / 0, ref, cases, name="peak").problem
    assert "returned shape (2,)" in function_check(lambda z: (1, 2), ref, cases, name="peak").problem


# -- the assignments ------------------------------------------------------------------------------------------
def _notebooks():
    return sorted(SOURCE.glob("*/*.ipynb"))


# issue 25's kinds; a "code" exercise (write a function) is allowed but does not count among the four
COUNTED = {"predict", "compute", "explain", "debug", "design", "graphical"}
KINDS = COUNTED | {"code"}


def _kinds(path) -> list[str]:
    nb = json.loads(path.read_text())
    heads = [c["source"] if isinstance(c["source"], str) else "".join(c["source"]) for c in nb["cells"]
             if c["cell_type"] == "markdown" and "".join(c["source"]).startswith("## Exercise")]
    return [" ".join(h.split()).split("·")[1].split("(")[0].strip() for h in heads]


def test_every_chapter_has_an_assignment():
    ids = {p.stem for p in _notebooks()}
    pointed = {m for nb in (SOURCE.parents[1] / "notebooks").glob("*.ipynb")
               for m in re.findall(r"assignments/release/(\w+)/", nb.read_text())}
    assert pointed <= ids and len(ids) >= 11, pointed - ids      # every chapter's pointer has its assignment


@pytest.mark.parametrize("path", _notebooks(), ids=lambda p: p.stem)
def test_an_assignment_has_five_exercises_of_four_kinds(path):
    kinds = _kinds(path)
    assert set(kinds) <= KINDS, (path.stem, kinds)
    assert len(kinds) >= 5 and len(set(kinds) & COUNTED) >= 4, (path.stem, kinds)


@pytest.mark.parametrize("path", _notebooks(), ids=lambda p: p.stem)
def test_an_assignment_states_units_and_points(path):
    nb = json.loads(path.read_text())
    kinds = _kinds(path)
    assert len(kinds) >= 4 and len(set(kinds)) >= 3 and set(kinds) <= KINDS, (path.stem, kinds)
    assert {"design", "code", "debug"} & set(kinds), path.stem
    for c in nb["cells"]:
        text = " ".join("".join(c["source"]).split())
        if c["cell_type"] == "markdown" and text.startswith("## Exercise") and "· compute" in text:
            assert "3 significant figures" in text or "in mm" in text.lower() or "**in" in text, (path.stem, text)
        meta = c["metadata"].get("nbgrader", {})
        if meta.get("grade") and c["cell_type"] == "markdown":
            assert meta.get("solution") and "explain" in kinds      # a hand-graded answer is an explanation
        elif meta.get("grade"):
            assert meta["points"] >= 0 and c["cell_type"] == "code"
        assert not c.get("outputs") and c.get("execution_count") is None


# -- no graded answer one public call away (tools/one_call_audit.py) -----------------------------------------
@functools.cache   # one module for every assignment's audit: it keeps the calls already made (_MADE)
def _audit():
    import importlib.util
    spec = importlib.util.spec_from_file_location("one_call_audit", SOURCE.parents[1] / "tools" / "one_call_audit.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def test_the_audit_finds_a_one_call_answer():
    audit = _audit()
    found = audit.sweep([8.0, 150.0], {"ExternalGeneva": ml.ExternalGeneva, "FourBar": ml.FourBar})
    assert audit.answered_by(ml.ExternalGeneva(8, 150.0).crank_radius, found).startswith("ExternalGeneva(8, 150)")
    assert audit.answered_by(np.degrees(ml.ExternalGeneva(8, 150.0).index_angle), found).endswith("in degrees")
    assert audit.answered_by(ml.ExternalGeneva(8, 150.0).crank_radius * 1.001, found) is None


@pytest.mark.parametrize("aid", sorted(p.stem for p in _notebooks()))
def test_no_graded_answer_is_one_public_call_away(aid):
    audit = _audit()
    rows = audit.audit(aid, audit.public_callables())
    assert len(rows) >= 3 and not [r for r in rows if r[2]], rows


# -- a design to each student's own specification ---------------------------------------------------------------
def _design_cells(nb):
    """(answer cell, check cell) of each design exercise: the two code cells after its heading."""
    out = []
    for k, c in enumerate(nb.cells):
        if c.cell_type == "markdown" and c.source.startswith("## Exercise") and "· design" in c.source.split("\n")[0]:
            answer, checker = [d for d in nb.cells[k + 1:k + 3] if d.cell_type == "code"]
            out.append((answer, checker))
    return out


def _corners(path):
    """Each corner of the variant ranges of the numbers a design exercise reads (the other numbers: the source's)."""
    import itertools

    import nbformat
    nb = nbformat.read(path, as_version=4)
    cell = next(c for c in nb.cells if "variant" in c.metadata.get("mechlab", {}))
    ranges = cell.metadata["mechlab"]["variant"]
    base = {}
    exec(cell.source, {}, base)
    for answer, checker in _design_cells(nb):
        used = sorted(set(re.findall(r"V\[\"(\w+)\"\]", answer.source + checker.source)) & set(ranges))
        for corner in itertools.product(*[(ranges[k][0], ranges[k][1]) for k in used]):
            yield nb, answer, checker, {**base["V"], **dict(zip(used, corner, strict=False))}


@pytest.mark.parametrize("path", [p for p in _notebooks() if any(True for _ in _corners(p))], ids=lambda p: p.stem)
def test_a_per_student_design_exists_at_every_corner_and_is_checked_against_its_own_numbers(path, tmp_path,
                                                                                            monkeypatch):
    """The worked solution, built from the student's numbers, meets the check at every corner of the ranges the
    design's specification is drawn from; the check reads ``V``, so another student's numbers give another spec."""
    import contextlib
    import io
    monkeypatch.chdir(tmp_path)                        # a design may write its DXF
    setup = None
    for nb, answer, checker, values in _corners(path):
        setup = setup or next(c.source for c in nb.cells if c.cell_type == "code")
        env = {"V": values}
        with contextlib.redirect_stdout(io.StringIO()):
            exec(setup, env)
            exec(answer.source, env)                   # the given lines, then the worked solution
            try:
                exec(checker.source, env)
            except NotYet as err:
                pytest.fail(f"{path.stem} at {values}: {err}")


def test_the_lab_model_is_the_plus_one_assembly_and_nothing_else():
    """symmetry's ``plus``: ψ′ of FourBar(..., +1), from its own closure; no way to ask it for the other assembly."""
    from mechlab.course.exercises.lab_model import PlusAssemblyRate
    from mechlab.errors import AssemblyError
    rng = np.random.default_rng(5)
    for crank in rng.uniform(0.3, 1.5, 5):
        phi = rng.uniform(0, 2 * np.pi, 7)
        plus = PlusAssemblyRate(crank, 3.0, 3.0, 4.0)
        assert np.allclose(plus(phi), ml.FourBar(crank, 3.0, 3.0, 4.0, 1).motion(phi).dpsi, rtol=1e-10)
        assert not np.allclose(plus(phi), ml.FourBar(crank, 3.0, 3.0, 4.0, -1).motion(phi).dpsi, rtol=1e-3)
    assert set(vars(plus)) == {"crank", "coupler", "rocker", "ground"}
    assert not [n for n in dir(plus) if not n.startswith("_") and callable(getattr(plus, n))]   # no method to call
    with pytest.raises(AssemblyError, match="does not close"):
        PlusAssemblyRate(0.3, 1.0, 1.0, 4.0)(0.0)
