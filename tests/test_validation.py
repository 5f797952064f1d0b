"""The validation layer (mechlab.validate) and every case of issue 16 that was seen to fail.

Each test states the input that used to pass silently, raise a raw numpy/Python error, hang or
return NaN, and asserts the named error (parameter and condition with the numbers) or a finite
result at the edge of what is accepted.
"""

from __future__ import annotations

import dataclasses
import functools
import math
import time
from typing import Annotated

import numpy as np
import pytest
from examples import designs, example_of, families, guides

import mechlab as ml
from mechlab import DimensionError, MechanismError
from mechlab.mechanisms.sixbar_iv import example as sixbar_example
from mechlab.synthesis.dwell_slot import LAMBDA_RANGE, LAMBDA_TOL, MIN_TRANSITION, DwellError
from mechlab.validate import MAX_SAMPLES, Checked, Length, Sign, Spec, check_value, count, validated

DEG = np.pi / 180


@functools.cache
def mechanisms():
    """One of every mechanism family (found, with its example: tests/examples.py), the lambda six-bars designed."""
    return [example_of(c) for c in families() if c.__module__.startswith("mechlab.")] + list(designs())


def init_fields(obj) -> dict:
    return {f.name: getattr(obj, f.name) for f in dataclasses.fields(obj) if f.init}


# -- the layer itself ---------------------------------------------------------------------------------------
def test_a_declaration_checks_converts_and_names():
    @validated
    def f(crank: Length, assembly: Sign = 1):
        return crank, assembly

    assert f(np.int64(2), np.float64(-1.0)) == (2.0, -1)
    assert type(f(2)[0]) is float and type(f(2, -1.0)[1]) is int
    for bad, msg in ((np.complex128(1 + 1j), r"crank must be a real number \(complex values are not accepted\)"),
                     ("2", "crank must be a number, got '2'"), (None, "crank must be a number, got None"),
                     (math.nan, "crank must be finite, got nan"), (-1, "crank must be > 0, got -1"),
                     (10**400, r"crank = an integer of 401 digits lies outside the supported magnitudes"),
                     (1e-300, r"crank = 1e-300 lies outside the supported magnitudes \[1e-100, 1e\+100\]")):
        with pytest.raises(DimensionError, match=msg):
            f(bad)
    with pytest.raises(DimensionError, match=r"assembly must be \+1 or -1, got True"):
        f(1.0, True)


def test_a_dataclass_declares_its_fields_once():
    from dataclasses import dataclass

    @dataclass(frozen=True)
    class Link(Checked):
        length: Length
        turns: Annotated[int, count(1, 5)] = 1

    assert Link(np.float32(0.5), 5.0).turns == 5 and type(Link(1).length) is float
    with pytest.raises(DimensionError, match=r"turns must be ≤ 5 \(mechlab's limit for one call\), got 6"):
        Link(1.0, 6)
    with pytest.raises(DimensionError, match=r"turns must be a whole number ≥ 1, got 2.5"):
        Link(1.0, 2.5)


def test_a_count_past_its_limit_is_refused_before_any_work():
    t0 = time.perf_counter()
    with pytest.raises(DimensionError, match=rf"n must be ≤ {MAX_SAMPLES:,}"):
        ml.FourBar(1, 3, 3, 4).turn(10**12)
    with pytest.raises(DimensionError, match=r"n must be ≤"):
        ml.FourBar(1, 3, 3, 4).turn(10**400)
    assert time.perf_counter() - t0 < 1.0


def test_one_spec_per_kind_refuses_by_name():
    assert check_value("p", (1, np.float32(2)), Spec("point")) == (1.0, 2.0)
    with pytest.raises(DimensionError, match=r"p\[1\] must be a number, got 'x'"):
        check_value("p", (1, "x"), Spec("point"))
    with pytest.raises(TypeError, match="guide must be a CircleGuide, got str"):
        ml.mchv1("circle", 1.0, 20 * DEG)
    with pytest.raises(TypeError, match="mechanism must be a Mechanism, got float"):
        ml.instant_centres(1.0)


def test_an_array_spec_bounds_every_value_and_shows_those_outside():
    fractions = Spec("reals", 0.0, 1.0, why="fractions of the span")
    inside = check_value("fractions", [0, 0.25, 1], fractions)
    assert isinstance(inside, np.ndarray) and inside.tolist() == [0.0, 0.25, 1.0]
    assert check_value("fractions", np.int64(1), fractions) == 1.0  # a scalar stays a scalar
    with pytest.raises(DimensionError, match=r"^fractions must be ≤ 1, got 1.5, 2 \(2 of 4 values\) "
                                             r"\(fractions of the span\)$"):
        check_value("fractions", np.array([0.5, 1.5, 1.0, 2.0]), fractions)
    with pytest.raises(DimensionError, match=r"^fractions must be ≥ 0, got -0.25 \(fractions"):
        check_value("fractions", [-0.25], fractions)
    with pytest.raises(DimensionError, match=r"^fractions must be ≥ 0, got -1 \(fractions"):
        check_value("fractions", -1, fractions)
    with pytest.raises(DimensionError, match=r"fractions must be finite, of magnitude ≤ 1e\+100, got nan"):
        check_value("fractions", np.array([0.5, np.nan]), fractions)  # NaN compares False with both bounds
    with pytest.raises(DimensionError, match=r"x must be > 0, got 0 \(1 of 2 values\)"):
        check_value("x", [0, 1], Spec("reals", 0.0, open_lo=True))
    # angles: the bounds also in degrees; a long list of offenders is cut
    with pytest.raises(DimensionError, match=r"dwells must be ≤ 6.28319 rad \(360°\), got 7, 8, 9, 10, … "
                                             r"\(6 of 7 values\)"):
        check_value("dwells", np.arange(6.0, 13.0), Spec("radians", 0.0, 2 * np.pi))


def test_array_bounds_declared_by_the_library():
    with pytest.raises(DimensionError, match=r"fractions must be ≤ 1, got 1.5 "):
        ml.design_outcomes(150 * DEG, fractions=(0.5, 1.5))
    with pytest.raises(DimensionError, match=r"dwells must be ≥ 0 rad \(0°\), got -1 \(1 of 2 values\)"):
        ml.design_outcomes(150 * DEG, dwells=(1.0, -1.0))
    with pytest.raises(DimensionError, match=r"dwells must be finite"):
        ml.design_outcomes(150 * DEG, dwells=(1.0, np.nan))
    law = ml.curved_slot_dwell(0.5, 60 * DEG, 150 * DEG).law
    assert np.all(np.isfinite(law.half(np.array([0.0, np.pi])).psi))
    with pytest.raises(DwellError, match=r"phi must be ≤ 3.14159 rad \(180°\), got 4 \(1 of 2 values\) "
                                         r"\(half\(\) takes the designed half; use __call__ for any φ\)"):
        law.half(np.array([1.0, 4.0]))


# -- issue 16, seen cases -------------------------------------------------------------------------------
def test_complex_values_are_refused_not_truncated():
    with pytest.raises(DimensionError, match="crank must be a real number"):
        ml.FourBar(np.complex128(1 + 1j), 3, 3, 4)
    with pytest.raises(DimensionError, match="crank must be a real number"):
        ml.FourBar(1 + 1j, 3, 3, 4)
    with pytest.raises(DimensionError, match=r"complex values are not accepted"):
        ml.FourBar(1, 3, 3, 4).motion(np.array([1 + 1j]))
    with pytest.raises(DimensionError, match=r"complex values are not accepted"):
        ml.FourBar(1, 3, 3, 4).motion(np.array([1 + 0j]))  # even with a zero imaginary part


def test_nan_no_longer_switches_a_check_off():
    circle, straight = guides()
    with pytest.raises(MechanismError, match="below the allowed 30°"):
        ml.mchv2(circle, 1.25)                                     # refused at 30°…
    with pytest.raises(DimensionError, match="mu_min must be finite, got nan"):
        ml.mchv2(circle, 1.25, mu_min=math.nan)                    # …and NaN no longer lets it through
    with pytest.raises(DimensionError, match="max_pressure must be finite"):
        ml.mchv5(straight, max_pressure=math.nan)
    with pytest.raises(DimensionError, match="max_speed must be finite"):
        ml.mchv3_full_turn_best(straight, max_speed=math.nan)
    with pytest.raises(DimensionError, match="theta_max must be finite"):
        ml.dwell_limit(0.5, math.nan)
    for tol in (math.nan, -1):
        with pytest.raises(DimensionError, match="dwell_tol must be"):
            ml.intermittency(ml.ExternalGeneva(4, 1.0), dwell_tol=tol)
    for start in (math.nan, math.inf, -math.inf):
        with pytest.raises(DimensionError, match="start must be finite"):
            ml.CurvedSlotLink(1, 4, ml.CircleSlot((3, 0), 3), start=start)
        with pytest.raises(DimensionError, match="start must be finite"):
            ml.SixBarIV(**{**init_fields(sixbar_example()), "start": start})


def test_none_means_off_only_where_documented():
    circle, _ = guides()
    relaxed = ml.mchv2(circle, 1.25, mu_min=None)
    assert np.all(np.isfinite(relaxed.motion(relaxed.turn(73)).s))
    with pytest.raises(ml.InfeasibleDesignError, match="K must be a number, got None"):
        ml.mchv2(circle, None)


@pytest.mark.parametrize("dwell", [math.nan, "120", None, np.array([1.0, 2.0]), -3.0])
def test_the_lambda_six_bars_check_their_dwell(dwell):
    for mech in designs():
        with pytest.raises(DimensionError, match="dwell must be"):
            type(mech)(**{**init_fields(mech), "dwell": dwell})


def test_secondary_parameters_raise_named_errors():
    for call, msg in ((lambda: ml.EllipticTrammel(1, "abc"), "beta must be a number, got 'abc'"),
                      (lambda: ml.CurvedSlotLink(1, 4, ml.CircleSlot((3, 0), 3), start="abc"), "start must be"),
                      (lambda: ml.two_branch_slot(0.5, None), "phi2 must be a number, got None"),
                      (lambda: ml.forces.press(work_fraction=None), "work_fraction must be a number, got None"),
                      (lambda: ml.Kinetostatics(ml.FourBar(1, 3, 3, 4), omega1="abc"),
                       "omega1 must be a number, got 'abc'")):
        with pytest.raises(DimensionError, match=msg):
            call()


@pytest.mark.parametrize("n", [1.5, -1, None, 0, "361", 10**12])
def test_sample_counts_are_whole_positive_and_bounded(n):
    with pytest.raises(DimensionError, match="n must be"):
        ml.FourBar(1, 3, 3, 4).turn(n)


def test_huge_integers_are_named_not_overflow():
    with pytest.raises(DimensionError, match="crank = an integer of 401 digits lies outside"):
        ml.FourBar(10**400, 3, 3, 4)
    with pytest.raises(DimensionError, match="phi = an integer of 401 digits lies outside"):
        ml.FourBar(1, 3, 3, 4).motion(10**400)
    with pytest.raises(ml.SlotCountError, match=r"z must be ≤ 1,000"):
        ml.ExternalGeneva(10**400, 1)


def test_velocity_and_acceleration_of_nan_are_refused_for_every_mechanism():
    assert {type(m) for m in mechanisms()} >= {ml.FourBar, ml.SphericalGeneva, ml.Linkage, ml.TranslatingRollerCam}
    for mech in mechanisms():
        mo = mech.motion(mech.cycle(9))
        assert np.all(np.isfinite(mo.velocity(3.0))) and np.all(np.isfinite(mo.acceleration(3.0, 1.0)))
        with pytest.raises(DimensionError, match="omega1 must be finite, got nan"):
            mo.velocity(math.nan)
        with pytest.raises(DimensionError, match="eps1 must be finite, got inf"):
            mo.acceleration(1.0, math.inf)


def test_results_are_finite_up_to_the_limits_and_refused_past_them():
    lo, hi = LAMBDA_RANGE
    for lam in (lo, hi):
        v, a = ml.base_peaks(lam)
        assert np.isfinite(v) and np.isfinite(a)
        law = ml.DwellLaw(lam, 60 * DEG, 150 * DEG)
        assert np.all(np.isfinite(law.curvature(np.linspace(0, 2 * np.pi, 181))))
    with pytest.raises(DimensionError, match=r"lam = 1e\+160 lies outside the supported magnitudes"):
        ml.base_peaks(1e160)                                       # was (1.0, nan)
    with pytest.raises(DimensionError, match=r"lam must be ≤ 1e\+06, got 1e\+07"):
        ml.base_peaks(1e7)
    with pytest.raises(ml.DwellRatioError, match=r"lam must be ≥ 1e-06, got 1e-300"):
        ml.DwellLaw(1e-300, 60 * DEG, 150 * DEG)                  # its curvature was -inf everywhere
    with pytest.raises(DimensionError, match=r"rpm = 1e\+300 lies outside"):
        ml.forces.press(rpm=1e300)                                 # was "SVD did not converge"
    with pytest.raises(DimensionError, match=r"rpm must be ≤"):
        ml.forces.rocker_drive(rpm=1e10)                           # 1e300 gave a NaN torque
    with pytest.raises(ml.forces.LoadError, match=r"value\[0\] must be finite, got nan"):
        ml.Force("slider", "B", (math.nan, 1.0))                   # gave NaN reactions
    fast = ml.forces.press(rpm=9e6).forces(np.linspace(0, 2 * np.pi, 13))
    assert np.all(np.isfinite(fast.torque))


def test_degenerate_dwell_designs_are_refused_by_name():
    with pytest.raises(ml.DwellIntervalError, match=r"each transition needs at least 0.0005 rad .* φ1 = 1e-300"):
        ml.curved_slot_dwell(0.5, 1e-300, 60 * DEG)                # was LinAlgError "Singular matrix"
    with pytest.raises(ml.DwellRatioError, match=r"λ ≠ 1 is needed \(\|λ - 1\| > 0.0001\)"):
        ml.curved_slot_dwell(1 + 1e-8, 60 * DEG, 150 * DEG)        # built, then motion() failed without λ
    with pytest.raises(ml.DwellIntervalError, match=r"π - φ2 = 4.44e-16 rad"):
        ml.curved_slot_dwell(0.5, 60 * DEG, np.nextafter(np.pi, 0))  # |ψ''| ≈ 4.5e15, θ = 90°
    # the edges that are accepted move with finite analogs
    for mech in (ml.curved_slot_dwell(0.5, MIN_TRANSITION, np.pi - MIN_TRANSITION),
                 ml.curved_slot_dwell(1 + 1.01 * LAMBDA_TOL, 60 * DEG, 150 * DEG)):
        mo = mech.motion(mech.turn(721))
        assert np.all(np.isfinite(mo.dpsi)) and np.all(np.isfinite(mo.ddpsi))


def test_an_indexing_measure_of_a_rocker_is_refused_not_infinite():
    with pytest.raises(DimensionError, match=r"does not advance over a crank turn"):
        ml.intermittency(ml.FourBar(1, 3, 3, 4))                   # C_v = max|ψ'|·Φ/|Δψ| with Δψ = 0


@pytest.mark.parametrize("call, error, match", [
    (lambda: ml.existence_map(np.radians(150), n=10**6), ml.DimensionError, r"n = 1e\+06 must lie in \[2, 400\]"),
    (lambda: ml.existence_map(np.radians(150), dwells=[np.nan]), ml.DimensionError, "dwells must be finite"),
    (lambda: ml.existence_map(np.radians(150), dwells="abc"), ml.DimensionError, "dwells must be a number"),
    (lambda: ml.whole_turn_line(np.radians(120), ds=0), ml.DimensionError, "ds = 0 must lie in"),
    (lambda: ml.whole_turn_line(np.radians(120), ds=1e-6), ml.DimensionError, "ds = 1e-06 must lie in"),
    (lambda: ml.circle_guiding(np.radians(150), 0.9, 1.0, minimax=np.nan), ml.DimensionError, "minimax must be True"),
    (lambda: ml.whole_turn_guiding(np.radians(150), 0.9, line=3), TypeError, "line must be a WholeTurnLine"),
    (lambda: ml.existence_region(np.radians(150), line=3), TypeError, "line must be a WholeTurnLine"),
])
def test_lambda_guiding_inputs_are_refused_by_name(call, error, match):
    with pytest.raises(error, match=match):
        call()


# -- the exports the fuzz did not reach before (issue 16, item 1), and what its explore mode found ------------
@pytest.mark.parametrize("call, error, match", [
    (lambda: ml.centre_count(1.5), DimensionError, "n_links must be a whole number ≥ 2"),
    (lambda: ml.law_difference(ml.FourBar(1, 3, 3, 4).motion([1.0, 2.0]), 3), TypeError, "m2 must be a Motion"),
    (lambda: ml.law_difference(*(ml.FourBar(1, 3, 3, 4).motion(np.zeros(k)) for k in (2, 3))), DimensionError,
     "over the same"),                                                     # was a broadcasting ValueError
    (lambda: ml.rolling_speeds(ml.FourBar(1, 3, 3, 4), "coupler", reference="coupler"), MechanismError,
     "two different links"),                                               # was CentreAtInfinity "translates"
    (lambda: ml.nearest_assembly(ml.FourBar(1, 3, 3, 4), math.nan, B=(2.8, 2.7)), DimensionError, "phi must be"),
    (lambda: ml.five_link_higher_pair(*np.array([[[1, 0]], [[-1, 0]], [[2, -2]], [[-1, 2]], [[-1, 1]], [[-1, 2]],
                                                 [[0, 2]]], float)), ml.SingularityError,
     "singular in snapshot 0"),                                            # was LinAlgError "Singular matrix"
    (lambda: ml.read_csv("no such file"), DimensionError, "neither a file nor CSV text"),  # was FileNotFoundError
    (lambda: ml.read_csv("a,b\n1,x\n"), DimensionError, "path_or_text holds no table"),  # was ValueError
    (lambda: ml.read_csv(3), TypeError, "path_or_text must be a file path"),
    (lambda: ml.time_ratio_far_angle(1.0, math.nan), DimensionError, "dwell must be finite"),
    (lambda: ml.dwell_extent(ml.FourBar(1, 3, 3, 4)), TypeError, "mech must be a LambdaRockerSixBar"),
    (lambda: ml.rise_law(ml.mchv1(guides()[0], 1.0, 20 * DEG), 2 * np.pi), DimensionError, "dwell must be <"),
    (lambda: ml.TranslatingRollerCam(ml.CamProgramme(10, 1, 1), 40, 8, samples=10**12), DimensionError,
     "samples must be ≤"),                                                 # was MemoryError
    (lambda: ml.CamProgramme(10, 1, 1, return_law=math.nan), DimensionError, "return_law must be one of"),
    (lambda: ml.CamProgramme(10, 1, 1, law=np.array([1.0])), DimensionError, "law must be one of"),  # unhashable
    (lambda: ml.write_cam_csv(ml.FourBar(1, 3, 3, 4)), TypeError, "cam must be a TranslatingRollerCam"),
    (lambda: ml.forces.motor_torque(np.array([1.0]), 2.0, efficiency=0), ml.DriveError, "efficiency must be >"),
    (lambda: ml.forces.cycle_mean(np.ones(3), np.zeros(3)), DimensionError, "samples of one interval"),  # was nan
    (lambda: ml.forces.solve(ml.model_for(ml.FourBar(1, 3, 3, 4)), ml.FourBar(1, 3, 3, 4).motion([1.0]),
                             maxiter=0), DimensionError, "maxiter must be a whole number ≥ 1"),
    (lambda: ml.forces.output_axis(ml.SliderCrank(1, 3).motion([1.0])), TypeError, "motion must be a AngularMotion"),
    (lambda: ml.motion_laws.law_invariants(math.nan), DimensionError, "law must be one of"),  # was a TypeError
    (lambda: ml.band_touches(np.ones(3), None), DimensionError, "E must be a number, got None"),  # was a TypeError
    (lambda: ml.circle_guiding(150 * DEG, 0.9, 120 * DEG, guess=(1 + 1j, 1, 1, 1)), DimensionError,
     r"guess\[0\] must be a real number"),                                  # was a TypeError from float()
    (lambda: ml.transmission_lines(math.nan), DimensionError, "mu_min must be finite"),  # gave NaN lines
    (lambda: ml.transmission_lines(n=math.nan), DimensionError, "n must be"),             # was a TypeError
    (lambda: ml.thesis_iteration(1e-300, 0.9, 60 * DEG), ml.SynthesisError, "did not converge"),  # was LinAlgError
    (lambda: ml.motion_laws.law_invariants(dataclasses.replace(ml.motion_laws.LAWS["cosine"], dy=lambda x: x / 0)),
     DimensionError, "gives NaN or inf"),                                  # was nan invariants
    (lambda: ml.motion_laws.rise_invariants(np.array([0.0, 1e90]), np.array([0.0, 1e-90]), np.ones(2),
                                            np.ones(2)), DimensionError, "the invariants overflow"),  # was inf
])
def test_newly_fuzzed_exports_refuse_by_name(call, error, match):
    with np.errstate(divide="ignore", invalid="ignore"), pytest.raises(error, match=match):
        call()


def test_a_centre_refuses_rows_that_are_not_normalised():
    ok = ml.Centre(np.array([[1.0, 2.0, 1.0], [0.6, 0.8, 0.0]]), "P13")
    assert ok.xy[0].tolist() == [1.0, 2.0] if ok.finite.all() else ok.direction[1].tolist() == [0.6, 0.8]
    for h, match in (([[2.0, 4.0, 2.0]], r"h\[0\] = \[2.0, 4.0, 2.0\] of centre P must be normalised"),
                     ([[3.0, 4.0, 0.0]], "unit direction"), ([[np.nan, 0.0, 1.0]], "h must be finite"),
                     ([[1.0, 2.0]], r"h must be an \(m, 3\) array"), ("abc", r"h must be an \(m, 3\) array")):
        with pytest.raises(DimensionError, match=match):
            ml.Centre(np.array(h) if not isinstance(h, str) else h)
    with pytest.raises(DimensionError, match="name must be a non-empty name"):
        ml.Centre(np.array([[1.0, 2.0, 1.0]]), name=None)


def test_design_inputs_go_through_the_layer():
    D = ml.design
    spec = D.Specification("index", 0.75, stations=4)
    with pytest.raises(D.SpecificationError, match="overload must be finite, got nan"):
        D.Specification("index", 0.75, stations=4, overload=math.nan)
    with pytest.raises(D.SpecificationError, match=r"inertia must be a real number \(complex"):
        D.Specification("index", 0.75, stations=4, inertia=np.complex128(1 + 1j))
    with pytest.raises(D.SpecificationError, match="amplitude must be ≤ π"):
        D.Specification("swing", 0.3, amplitude=4.0)
    with pytest.raises(DimensionError, match="parts must be a whole number ≥ 0"):
        D.Counts(-1, 2, 2)
    with pytest.raises(TypeError, match="families must be a tuple of str"):
        D.candidates(spec, "external Geneva")
    with pytest.raises(DimensionError, match="phase must be ≤"):
        D.check_design(spec, ml.ExternalGeneva(4, 1.0), phase=10.0)
    with pytest.raises(DimensionError, match=r"circles\[0\] radius must be > 0"):
        D.evaluate(ml.ExternalGeneva(4, 1.0), spec, scale=1.0, structure=D.Counts(2, 2, 2), circles=(((0, 0), -1),))
    comparison = D.candidates(spec, ["external Geneva"])
    with pytest.raises(DimensionError, match="by must be one of"):
        comparison.ranked(np.array([1.0, 2.0]))                   # explore mode: a raw ValueError ("truth value")
    with pytest.raises(TypeError, match="path must be a file path"):
        comparison.to_csv(3)                                      # explore mode: wrote to file descriptor 3


# -- widgets: every explorer's controls driven to their ends ------------------------------------------------
def _widget_modules():
    import importlib
    import pkgutil

    from mechlab import widgets
    return [widgets] + [importlib.import_module(f"mechlab.widgets.{m.name}")
                        for m in pkgutil.iter_modules(widgets.__path__)]


def _explorer_factories() -> dict:
    """Every public function of mechlab.widgets that makes an explorer (named …_explorer or …_equivalence)."""
    return {f"{mod.__name__}.{name}": fn for mod in _widget_modules() for name, fn in vars(mod).items()
            if callable(fn) and not name.startswith("_") and getattr(fn, "__module__", "") == mod.__name__
            and not isinstance(fn, type) and name.endswith(("_explorer", "_equivalence"))}


# the factories that need an argument; each gets a specification its explorer starts from
FACTORY_ARGS = {"choosing_explorer": lambda: (ml.design.Specification("index", 0.75, stations=4, inertia=1.0),)}


def _ends(widget) -> list:
    """The values a control can be driven to at its ends: a slider's min and max, every option of a choice."""
    if hasattr(widget, "min"):
        return [widget.min, widget.max]
    return [option[1] if isinstance(option, tuple) else option for option in widget.options]


@pytest.mark.parametrize("name", sorted(_explorer_factories()))
def test_every_explorer_survives_its_controls_at_their_ends(name):
    """Each slider to its minimum and its maximum (each choice to every option), one at a time, then back:
    no exception escapes a control (an impossible geometry is shown as the explorer's message), and the
    explorer recovers its first state."""
    import matplotlib.pyplot as plt

    fn = _explorer_factories()[name]
    ex = fn(*FACTORY_ARGS.get(name.rsplit(".", 1)[1], tuple)())
    first = ex.message
    controls = dict(ex.sliders)
    for extra in ("angle", "rank"):  # the crank angle; the choosing explorer's ranking
        if hasattr(ex, extra):
            controls[extra] = getattr(ex, extra)
    assert controls, f"{name} has no controls"
    for key, w in controls.items():
        start = w.value
        for value in _ends(w):
            w.value = value  # an exception here escaped the explorer's rebuild
            assert isinstance(ex.message, str), (key, value)
        w.value = start
        assert ex.message == first, f"{name}: {key} back at {start} leaves {ex.message!r}"
    plt.close("all")


def test_every_explorer_class_is_driven_to_its_ends():
    """Every explorer class mechlab.widgets defines is made by a factory the test above drives."""
    classes = {cls for mod in _widget_modules() for n, cls in vars(mod).items()
               if isinstance(cls, type) and n.endswith("Explorer") and cls.__module__ == mod.__name__
               and n != "Explorer"}  # the base of the others, never made alone
    made = set()
    for name, fn in _explorer_factories().items():
        made.add(type(fn(*FACTORY_ARGS.get(name.rsplit(".", 1)[1], tuple)())))
    import matplotlib.pyplot as plt
    plt.close("all")
    assert len(_explorer_factories()) >= 17
    assert classes <= made, f"explorer classes no factory makes: {classes - made}"
