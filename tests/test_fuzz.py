"""Every exported callable of mechlab, fed valid and adversarial inputs (hypothesis).

Each case is a valid call; hypothesis replaces one of its parameters by a nearby valid value or
by an adversarial one (NaN, ±inf, 0, negatives, 1e-300, 1e300, 10**400, bools, strings, None,
complex, wrong-shaped and empty arrays) and the outcome must be one of:

* a result whose every number is finite (a mechanism is also moved over its cycle);
* a MechanismError subclass whose message names the replaced parameter; a real finite number of the
  right type may instead make the design impossible, and the error then names the violated condition;
* a TypeError naming what was expected, where a mechanism (or another object of a kind) is expected.

The same examples every run (tests/conftest.py); the whole file runs in about 30 s.
"""

from __future__ import annotations

import atexit
import contextlib
import dataclasses
import functools
import inspect
import math
import numbers
import re
import shutil
import tempfile
from pathlib import Path

import numpy as np
import pytest
from examples import designs, example_of, families, guides
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import mechlab as ml
from mechlab import design as D
from mechlab import forces as F
from mechlab import motion_laws as ML
from mechlab.kinetostatics import drive as force_drive
from mechlab.validate import _spec_of

DEG = np.pi / 180

ADVERSARIAL = [math.nan, math.inf, -math.inf, 0, 0.0, -1, -2.5, 1e-300, 1e300, 10**400, True, False, "abc", None,
               1 + 1j, np.complex128(2 + 0.5j), np.array([1.0, 2.0]), np.array([]), np.array([[1.0]]),
               np.float32(0.5), np.int64(3), np.nan, [1.0, "x"]]

# a parameter's name as the messages may spell it
ALIASES = {"delta": ("δ",), "lam": ("λ",), "phi1": ("φ1",), "phi2": ("φ2",), "swing": ("β_m",),
           "theta_max": ("θ",), "K": ("time ratio",), "stroke": ("stroke h",), "com": ("centre of mass",)}


@functools.cache
def scratch() -> Path:
    """A temporary folder for the files the export functions write, removed at exit."""
    folder = Path(tempfile.mkdtemp(prefix="mechlab-fuzz-"))
    atexit.register(shutil.rmtree, folder, ignore_errors=True)
    return folder


@functools.cache
def cams():
    """A translating and an oscillating roller cam (mm, rad) with their programmes."""
    lift, swing = ml.CamProgramme(10.0, 100 * DEG, 100 * DEG, 40 * DEG), ml.CamProgramme(20 * DEG, 100 * DEG, 100 * DEG)
    return (lift, ml.TranslatingRollerCam(lift, 40.0, 8.0, offset=2.0, samples=720),
            swing, ml.OscillatingRollerCam(swing, 40.0, 8.0, float(np.hypot(100.0, 48.0)), 100.0, samples=720))


@functools.cache
def slot_csv() -> str:
    return ml.write_csv(ml.curved_slot_dwell(0.5, 60 * DEG, 150 * DEG, transition="quintic"), n=41)


@functools.cache
def slot_dxf() -> Path:
    path = scratch() / "read.dxf"
    ml.write_dxf(ml.curved_slot_dwell(0.5, 60 * DEG, 150 * DEG, transition="quintic"), path, roller_radius=0.01, n=41)
    return path


@functools.cache
def specs():
    """An index and a swing specification (the fast families: a call of candidates() takes 0.02 s)."""
    return (D.Specification("index", 0.75, stations=4, inertia=1.0),
            D.Specification("swing", 50 / 360, amplitude=40 * DEG, max_pressure_angle=60 * DEG))


@functools.cache
def small_atlas() -> Path:
    """A small coupler-curve atlas saved in the scratch folder."""
    return ml.build_atlas((2.0, 3.0), u=(1.0,), v=(0.5,), samples=72, workers=1).save(scratch() / "atlas.npz")


def small_outcomes():
    """A one-frame, one-dwell map of the lambda mechanism's designs."""
    return ml.design_outcomes(150 * DEG, fractions=(0.5,), dwells=(60 * DEG,))


def snapshots():
    """One snapshot of the five-link mechanism with a higher pair (Kozhevnikov, Fig. 7.3)."""
    return tuple(np.array([p]) for p in ((0.0, 0.0), (1.0, 0.2), (1.8, 1.5), (0.7, 2.2), (-0.5, 1.4), (0.9, 1.1),
                                          (0.3, 1.0)))


@functools.cache
def coupler():
    """A crank-rocker with a coupler point P whose curve has a nearly circular arc and a nearly straight run."""
    return ml.coupler_fourbar(1.0, 3.0, 3.0, 4.0, point=(1.5, 1.0))


@functools.cache
def coupler_arc():
    return ml.coupler_arcs(coupler(), dwell=1.2, n=240, count=1)[0]


@functools.cache
def coupler_run():
    return ml.coupler_runs(coupler(), dwell=1.2, n=240, count=1)[0]


def wavy():
    return ml.ParametricSlot(lambda t: np.stack([1.0 + 0 * t, t], -1), lambda t: np.stack([0 * t, 1 + 0 * t], -1),
                             lambda t: np.zeros((len(t), 2)), -0.8, 0.8)


def fields_of(obj):
    return [getattr(obj, f.name) for f in dataclasses.fields(obj) if f.init]


fb = ml.FourBar(1.0, 3.0, 3.0, 4.0)
PHI = np.linspace(0.1, 6.0, 7)
TURN = np.linspace(0.0, 2 * np.pi, 9)


def family_case(cls):
    """A family's case, found not listed: its class called with the fields of its example, each replaced in turn."""
    return lambda: (cls, tuple(fields_of(example_of(cls))), {})


def case_name(cls) -> str:
    """A family's case name: its class name (with its module for one defined outside mechlab)."""
    return cls.__name__ if cls.__module__.startswith("mechlab.") else f"{cls.__module__}.{cls.__qualname__}"


# name: (callable, args, kwargs); every family of mechlab (tests/examples.families) first
CASES = {
    **{case_name(cls): family_case(cls) for cls in families() if cls.__module__.startswith("mechlab.")},
    "CircleSlot": lambda: (ml.CircleSlot, ((1.0, 0.0), 3.0), {}),
    "ParametricSlot": lambda: (ml.ParametricSlot, tuple(fields_of(wavy())[:5]), {"periodic": False}),
    "SampledSlot": lambda: (ml.SampledSlot, (np.c_[np.ones(9), np.linspace(-0.8, 0.8, 9)],), {"closed": False}),
    # build your own linkage: the pieces (the whole linkage is a family, its example a shaper)
    "Crank": lambda: (ml.Crank, ("O", "A", 1.0), {"name": "crank"}),
    "RRR": lambda: (ml.RRR, ("A", "E", "B", 3.0, 3.0), {"assembly": -1, "links": ("coupler", "rocker")}),
    "RRP": lambda: (ml.RRP, ("A", "B", 3.0, ml.Guide("G", 0.2)), {"assembly": 1, "links": ("rod", "slider")}),
    "RPR": lambda: (ml.RPR, ("A", "P"), {"length": 2.0, "links": ("block", "lever")}),
    "PRP": lambda: (ml.PRP, (ml.Guide("G"), ml.Guide("P", 0.0, "lever"), "B"), {"links": ("slider", "block")}),
    "RPP": lambda: (ml.RPP, ("A", "K", ml.Guide("G", 0.2)), {"slot": 1.2, "links": ("block", "yoke")}),
    "Tetrad": lambda: (ml.Tetrad, ("A", "E", ("Q", "P", "R", "T"), ((-0.2, 0.55), (0.7, 0.55)),
                                   ((0.55, 0.45), (1.35, 0.15)), (0.25, 0.85), (3.67, 3.04)),
                       {"at": 3.14, "links": ("coupler", "link 3", "link 5", "output")}),
    "CurvedSlot": lambda: (ml.CurvedSlot, ("A", ml.CircleSlot((3.0, 0.0), 3.0), "K"),
                           {"pivot": "B", "guide": None, "start": 1.0, "at": 0.0, "link": "lever"}),
    "CamFollower": lambda: (ml.CamFollower, (ml.CircleSlot((0.5, 0.0), 2.0), "cam", "C"),
                            {"pivot": "B", "arm": 2.0, "guide": None, "start": 1.3, "at": 0.0, "link": "arm"}),
    "Guide": lambda: (ml.Guide, ("G",), {"angle": 0.3, "on": "lever"}),
    "Point": lambda: (ml.Point, ("C", "AB"), {"at": (1.5, 0.8)}),
    "build_atlas": lambda: (ml.build_atlas, ((2.0, 3.0),), {"u": (1.0,), "v": (0.5,), "samples": 72, "chunk": 4,
                                                           "workers": 1}),
    "load_atlas": lambda: (ml.load_atlas, (small_atlas(),), {}),
    "FourBar.motion": lambda: (fb.motion, (PHI,), {}),
    "FourBar.turn": lambda: (fb.turn, (9,), {}),
    "FourBar.cycle": lambda: (fb.cycle, (9,), {}),
    "Motion.velocity": lambda: (fb.motion(PHI).velocity, (2.0,), {}),
    "Motion.acceleration": lambda: (fb.motion(PHI).acceleration, (2.0,), {"eps1": 0.5}),
    "relative_path": lambda: (ml.relative_path, (fb, PHI), {}),
    "equivalent_slot": lambda: (ml.equivalent_slot, (fb,), {}),
    "base_law": lambda: (ml.base_law, (fb, PHI), {}),
    "base_mechanism": lambda: (ml.base_mechanism, (fb,), {}),
    "assembly_symmetry": lambda: (ml.assembly_symmetry, (fb, PHI), {}),
    "other_half": lambda: (ml.other_half, (fb, PHI), {}),
    "limit_theorem": lambda: (ml.limit_theorem, (fb,), {"n": 73}),
    "base_peaks": lambda: (ml.base_peaks, (0.5,), {}),
    "slotted_link_law": lambda: (ml.slotted_link_law, (0.5, PHI), {}),
    "instant_centres": lambda: (ml.instant_centres, (fb, PHI), {"method": "kennedy"}),
    "centrodes": lambda: (ml.centrodes, (fb, "coupler"), {"reference": "frame", "phi": PHI, "method": "kennedy"}),
    "curved_slot_dwell": lambda: (ml.curved_slot_dwell, (0.5, 60 * DEG, 150 * DEG),
                                  {"pivot_distance": 1.0, "transition": "quintic", "roller_radius": 0.0}),
    "DwellLaw": lambda: (ml.DwellLaw, (0.5, 60 * DEG, 150 * DEG), {"transition": "cubic", "pivot_distance": 1.0}),
    "DwellLaw.curvature": lambda: (ml.DwellLaw(0.5, 60 * DEG, 150 * DEG).curvature, (PHI,), {}),
    "two_branch_slot": lambda: (ml.two_branch_slot, (0.5, 60 * DEG), {"pivot_distance": 1.0}),
    "dwell_limit": lambda: (ml.dwell_limit, (0.5, 75 * DEG), {"transition": "cubic", "pivot_distance": 1.0}),
    "cubic_dwell_window": lambda: (ml.cubic_dwell_window, (0.5, 60 * DEG), {}),
    "compare_transitions": lambda: (ml.compare_transitions, (0.5, 60 * DEG, 150 * DEG), {"n": 73}),
    "slot_profile": lambda: (ml.slot_profile, (ml.curved_slot_dwell(0.5, 60 * DEG, 150 * DEG, transition="quintic"),),
                             {"roller_radius": 0.01, "n": 41}),
    "write_csv": lambda: (ml.write_csv, (ml.curved_slot_dwell(0.5, 60 * DEG, 150 * DEG, transition="quintic"),),
                          {"roller_radius": 0.01, "n": 41}),
    "mchv1": lambda: (ml.mchv1, (guides()[0], 1.0, 20 * DEG), {"side": 1, "mu_min": 30 * DEG}),
    "mchv2": lambda: (ml.mchv2, (guides()[0], 1.0), {"normal": 1, "mu_min": 30 * DEG}),
    "mchv2_stroke": lambda: (ml.mchv2_stroke, (guides()[0], 0.35), {"side": 1, "mu_min": None}),
    "mchv3_full_turn": lambda: (ml.mchv3_full_turn, (guides()[1],), {"beyond": 0.06, "depth": 0.05, "side": 1}),
    "mchv3_full_turn_best": lambda: (ml.mchv3_full_turn_best, (guides()[1],),
                                     {"side": 1, "max_speed": 15.0, "beyonds": np.array([0.06]),
                                      "depths": np.array([0.04, 0.05])}),
    "mchv3_pivot_table": lambda: (ml.mchv3_pivot_table, (guides()[1],),
                                  {"beyonds": np.array([0.06]), "depth": 0.05, "n": 61}),
    "mchv3_best_table": lambda: (ml.mchv3_best_table, (np.array([np.pi]),),
                                 {"delta": np.pi, "a": 0.8, "beyonds": np.array([0.06]),
                                  "depths": np.array([0.04, 0.05])}),
    "mchv5": lambda: (ml.mchv5, (guides()[1],), {"stroke": None, "side": 1, "max_pressure": 60 * DEG}),
    "slot_residual_first_order": lambda: (ml.slot_residual_first_order, (designs()[2], guides()[1], PHI), {}),
    "slider_report": lambda: (ml.slider_report, (designs()[1],), {"dwell": 120 * DEG}),
    "slider_invariants": lambda: (ml.slider_invariants, (designs()[3],), {"dwell": np.pi}),
    "spherical_table": lambda: (ml.spherical_table, (40.0, 15.0, [3, 4]), {"pin_diameter": 10.0}),
    "intermittency": lambda: (ml.intermittency, (ml.ExternalGeneva(4, 1.0),),
                              {"n": 721, "dwell_tol": 1e-9, "phase": 0.1}),
    "compare": lambda: (ml.compare, ({"g": ml.ExternalGeneva(4, 1.0)},), {"n": 361}),
    "Kinetostatics": lambda: (ml.Kinetostatics, (fb,), {"omega1": 2.0, "eps1": 0.0, "gravity": (0.0, -9.81)}),
    "Kinetostatics.forces": lambda: (ml.forces.press().forces, (PHI,), {}),
    "press": lambda: (ml.forces.press, (), {"crank": 0.1, "rod": 0.4, "rpm": 120.0, "P": 2000.0,
                                             "work_fraction": 0.3, "f": 0.1, "radius": 0.01}),
    "rocker_drive": lambda: (ml.forces.rocker_drive, (), {"crank": 0.1, "rpm": 120.0, "T": 40.0, "f": 0.05}),
    "class_iv_drive": lambda: (ml.forces.class_iv_drive, (), {"omega1": 10.0, "T": 20.0, "f": 0.1, "radius": 0.02}),
    "drive": lambda: (force_drive, (np.cos(np.linspace(0, 2 * np.pi, 73)) + 2, np.linspace(0, 2 * np.pi, 73),
                                    10.0), {"overload": 2.0, "efficiency": 0.9}),
    "Body": lambda: (ml.Body, ("rod", "A"), {"axis": 0.0, "mass": 1.0, "inertia": 0.1, "com": (0.1, 0.0),
                                               "length": 0.3}),
    "Revolute": lambda: (ml.Revolute, ("A", "crank", "rod", "A"), {"friction": 0.1, "radius": 0.01}),
    "Prismatic": lambda: (ml.Prismatic, ("B", "slider", "frame", "B"), {"angle": 0.0, "friction": 0.1}),
    "HigherPair": lambda: (ml.HigherPair, ("K", "a", "b", "K"), {"normal": 0.5, "friction": 0.1}),
    "Force": lambda: (ml.Force, ("slider", "B", (0.0, -100.0)), {}),
    "Torque": lambda: (ml.Torque, ("rocker", 5.0), {}),
    "model_for": lambda: (ml.model_for, (fb,), {}),
    "ForceModel": lambda: (ml.ForceModel, tuple(fields_of(ml.model_for(fb))), {}),
    "formula_18": lambda: (ml.formula_18, (0.5, PHI), {}),
    "best_placement": lambda: (ml.best_placement, (0.5, 60 * DEG), {"transition": "cubic", "n_grid": 7}),
    "mchv2_far_position": lambda: (ml.mchv2_far_position, (guides()[0], 1.0), {"normal": 1}),
    "mchv3_oscillating": lambda: (ml.mchv3_oscillating, (guides()[1], 0.1), {}),
    "classic_lambda": lambda: (ml.classic_lambda, (), {}),
    "detect_impacts": lambda: (ml.detect_impacts, (ml.ExternalGeneva(4, 1.0),), {"n": 512, "phase": 0.1}),
    "transmission_extremes": lambda: (ml.transmission_extremes, (fb,), {"n": 361}),
    "zero_acceleration": lambda: (ml.zero_acceleration, (fb,), {"n": 361}),
    "crank_ranges_degrees": lambda: (ml.crank_ranges_degrees, (fb,), {}),
    "table1_comparison": lambda: (ml.table1_comparison, (), {"R": 40.0, "e": 15.0}),
    "table1_review": lambda: (ml.table1_review, (), {}),
    "write_dxf": lambda: (ml.write_dxf, (ml.curved_slot_dwell(0.5, 60 * DEG, 150 * DEG, transition="quintic"),
                                         scratch() / "slot.dxf"),
                          {"roller_radius": 0.01, "n": 41}),
    "read_csv": lambda: (ml.read_csv, (slot_csv(),), {}),
    "read_dxf": lambda: (ml.read_dxf, (slot_dxf(),), {}),
    "nearest_assembly": lambda: (ml.nearest_assembly, (fb, 1.0), {"B": (2.8, 2.7)}),
    "law_difference": lambda: (ml.law_difference, (fb.motion(PHI), ml.FourBar(1.0, 3.0, 3.0, 4.0, -1).motion(PHI)),
                               {}),
    "centre_count": lambda: (ml.centre_count, (6,), {}),
    "rolling_speeds": lambda: (ml.rolling_speeds, (fb, "coupler"), {"reference": "frame", "phi": PHI}),
    "five_link_higher_pair": lambda: (ml.five_link_higher_pair, snapshots(), {"scale": 3.0}),
    "Centre": lambda: (ml.Centre, (np.array([[1.0, 2.0, 1.0], [0.6, 0.8, 0.0]]),), {"name": "P13"}),
    "mchv3_half_turn": lambda: (ml.mchv3_half_turn, (guides()[1],), {}),
    "dwell_extent": lambda: (ml.dwell_extent, (designs()[2],), {"tol": 0.02, "n": 361}),
    "rise_law": lambda: (ml.rise_law, (designs()[0], 120 * DEG), {"n": 101}),
    "time_ratio_far_angle": lambda: (ml.time_ratio_far_angle, (1.2, 120 * DEG), {}),
    "CamProgramme": lambda: (ml.CamProgramme, (10.0, 100 * DEG, 100 * DEG),
                             {"outer_dwell": 40 * DEG, "law": "cycloidal (sine)", "return_law": "3-4-5 polynomial"}),
    "write_cam_csv": lambda: (ml.write_cam_csv, (cams()[1],), {"path": None, "n": 73}),
    "write_cam_dxf": lambda: (ml.write_cam_dxf, (cams()[3], scratch() / "cam.dxf"), {"n": 73}),
    # the Chebyshev guiding solvers
    "circle_guiding": lambda: (ml.circle_guiding, (150 * DEG, 0.9, 120 * DEG), {"guess": None, "minimax": True}),
    "band_touches": lambda: (ml.band_touches, (np.sin(np.linspace(0, 6 * np.pi, 121)), 1.0), {"rtol": 1e-3}),
    "fifth_order_line": lambda: (ml.fifth_order_line, (150 * DEG,), {"n": 20}),
    "thesis_iteration": lambda: (ml.thesis_iteration, (150 * DEG, 0.9, 60 * DEG), {"tol": 1e-6, "maxiter": 50}),
    "transmission_lines": lambda: (ml.transmission_lines, (30 * DEG, 150 * DEG), {"n": 11}),
    "straight_guiding": lambda: (ml.straight_guiding, (np.pi, 0.8, np.pi), {}),
    "whole_turn_line": lambda: (ml.whole_turn_line, (120 * DEG,), {"ds": 0.05, "r_start": 0.005}),
    "whole_turn_guiding": lambda: (ml.whole_turn_guiding, (240 * DEG, 1.6), {"line": None}),
    "existence_map": lambda: (ml.existence_map, (150 * DEG,), {"dwells": (120 * DEG,), "n": 3}),
    "existence_region": lambda: (ml.existence_region, (240 * DEG,), {"line": None}),
    "design_outcomes": lambda: (ml.design_outcomes, (150 * DEG,), {"fractions": (0.5,), "dwells": (120 * DEG,)}),
    "save_design_outcomes": lambda: (ml.save_design_outcomes, ([small_outcomes()], scratch() / "maps.npz"), {}),
    "load_design_outcomes": lambda: (ml.load_design_outcomes, (ml.save_design_outcomes([small_outcomes()],
                                                                                      scratch() / "maps.npz"),), {}),
    # mechlab.forces
    "forces.solve": lambda: (F.solve, (ml.model_for(fb), fb.motion(PHI)),
                             {"loads": (ml.Torque("rocker", 5.0),), "omega1": 2.0, "eps1": 0.5,
                              "gravity": (0.0, -9.81), "maxiter": 50, "tol": 1e-10}),
    "forces.balanced_load": lambda: (F.balanced_load, (fb, 5.0, PHI),
                                     {"loads": (ml.Torque("coupler", 1.0),), "omega1": 2.0, "eps1": 0.5,
                                      "gravity": (0.0, -9.81)}),
    "forces.torque_for_load": lambda: (F.torque_for_load, (fb, -3.0, PHI), {"omega1": 2.0, "eps1": 0.5}),
    "forces.virtual_work_torque": lambda: (F.virtual_work_torque, (ml.model_for(fb), fb.motion(PHI)),
                                           {"loads": (ml.Torque("rocker", 5.0),), "omega1": 2.0, "eps1": 0.5,
                                            "gravity": (0.0, -9.81)}),
    "forces.output_axis": lambda: (F.output_axis, (fb.motion(PHI),), {}),
    "forces.slender_bar": lambda: (F.slender_bar, (2.0, 0.3), {}),
    "forces.motor_torque": lambda: (F.motor_torque, (np.array([1.0, -2.0, 3.0]), 4.0), {"efficiency": 0.8}),
    "forces.cycle_mean": lambda: (F.cycle_mean, (np.cos(TURN) + 2, TURN), {}),  # a mean over an interval
    "forces.rpm_to_rad": lambda: (F.rpm_to_rad, (120.0,), {}),
    "forces.press_load": lambda: (F.press_load, (2000.0,), {"work_fraction": 0.3}),
    # mechlab.motion_laws
    "motion_laws.RiseLaw": lambda: (ML.RiseLaw, tuple(fields_of(ML.LAWS["cycloidal (sine)"])), {}),
    "motion_laws.law_invariants": lambda: (ML.law_invariants, ("cycloidal (sine)",), {"n": 2001, "signed": True}),
    "motion_laws.law_table": lambda: (ML.law_table, (["cosine", "cycloidal (sine)"],), {"n": 2001}),
    "motion_laws.law_jerk": lambda: (ML.law_jerk, ("modified sine",), {"n": 2001}),
    "motion_laws.named_law": lambda: (ML.named_law, ("simple harmonic",), {}),
    "motion_laws.invariants": lambda: (ML.invariants, (2.0, 0.5, np.sin(PHI), np.cos(PHI)), {"signed": True}),
    "motion_laws.rise_invariants": lambda: (ML.rise_invariants, ml.rise_law(designs()[0], 120 * DEG, n=101),
                                            {"signed": False}),
    "motion_laws.thesis_cam_rows": lambda: (ML.thesis_cam_rows, (), {}),
    "motion_laws.thesis_mchv1_rows": lambda: (ML.thesis_mchv1_rows, (), {}),
    # mechlab.design: every field of a specification replaced in turn
    "design.Specification": lambda: (D.Specification, ("index", 0.75),
                                     {"stations": 4, "rpm": 60.0, "inertia": 1.0, "mass": 0.0, "resisting": 2.0,
                                      "max_pressure_angle": 45 * DEG, "max_size": 1000.0, "impacts": "hard",
                                      "dwell_tolerance": 0.03, "dwell_precision": 0.001, "crank_radius": 50.0,
                                      "overload": 2.0}),
    "design.Specification (stroke)": lambda: (D.Specification, ("stroke", 1 / 3),
                                              {"amplitude": 120.0, "mass": 6.0, "max_size": 2000.0}),
    "design.candidates": lambda: (D.candidates, (specs()[0],), {"families": ["external Geneva", "internal Geneva"]}),
    "design.check_design": lambda: (D.check_design, (specs()[0], ml.ExternalGeneva(4, 1.0)),
                                    {"scale": 50.0, "phase": 0.0}),
    "design.evaluate": lambda: (D.evaluate, (ml.ExternalGeneva(4, 1.0), specs()[0]),
                                {"scale": 50.0, "structure": D.Counts(2, 2, 2), "circles": (((1.4, 0.0), 1.0),),
                                 "pressure_angle": 0.0, "phase": 0.1}),
    "design.Counts": lambda: (D.Counts, (2, 2, 1), {}),
    "design.Comparison.ranked": lambda: (D.candidates(specs()[0], ["external Geneva"]).ranked, ("size",), {}),
    "design.Comparison.to_csv": lambda: (D.candidates(specs()[0], ["external Geneva"]).to_csv,
                                         (scratch() / "table.csv",), {}),
    # dwells from coupler curves: the fits and the six-bars on them
    "coupler_fourbar": lambda: (ml.coupler_fourbar, (1.0, 3.0, 3.0, 4.0), {"point": (1.5, 1.0), "assembly": 1}),
    "coupler_arcs": lambda: (ml.coupler_arcs, (coupler(), "P"), {"dwell": 1.2, "n": 240, "count": 2,
                                                                 "max_ripple": 1e-3, "max_radius": None}),
    "coupler_runs": lambda: (ml.coupler_runs, (coupler(), "P"), {"dwell": 1.2, "n": 240, "count": 2,
                                                                 "max_ripple": 1e-3}),
    "fit_arc": lambda: (ml.fit_arc, (coupler(), "P", coupler_arc().crank_interval), {"n": 240}),
    "fit_run": lambda: (ml.fit_run, (coupler(), "P", coupler_run().crank_interval), {"n": 240}),
    "arc_dwell_sixbar": lambda: (ml.arc_dwell_sixbar, (coupler(), "P", coupler_arc()), {"output_pivot": None}),
    "run_dwell_sixbar": lambda: (ml.run_dwell_sixbar, (coupler(), "P", coupler_run()), {"pivot": None}),
    "check_dwell": lambda: (ml.check_dwell, (ml.arc_dwell_sixbar(coupler(), "P", coupler_arc()),
                                            coupler_arc().crank_interval), {"n": 240}),
}

# the slow ones get fewer examples
BUDGET = {"whole_turn_guiding": 3, "existence_region": 3, "design_outcomes": 3, "existence_map": 3,
          "whole_turn_line": 4, "design.candidates": 8, "design.check_design": 8, "design.evaluate": 10,
          "design.Comparison.ranked": 4,
          "design.Comparison.to_csv": 4, "rise_law": 8, "dwell_extent": 8, "mchv3_half_turn": 4,
          "dwell_limit": 4, "mchv3_full_turn_best": 6, "mchv3_best_table": 4, "mchv3_pivot_table": 6,
          "compare_transitions": 4, "mchv2_stroke": 6, "mchv1": 8, "mchv2": 8,
          "slider_invariants": 6, "slider_report": 6, "compare": 6, "intermittency": 8, "SixBarIV": 8,
          "LambdaSlottedSixBar": 8, "mchv3_full_turn": 8, "Kinetostatics.forces": 8,
          "coupler_arcs": 12, "coupler_runs": 12, "fit_arc": 12, "fit_run": 12, "arc_dwell_sixbar": 10,
          "run_dwell_sixbar": 10, "check_dwell": 10}


def finite(value, depth=0) -> bool:
    """Every number reachable in a result is finite (arrays of numbers, containers, dataclasses)."""
    if depth > 4 or value is None or isinstance(value, str | bytes | type) or (callable(value) and not \
            dataclasses.is_dataclass(value)):
        return True
    if isinstance(value, numbers.Number):
        return bool(np.isfinite(value)) if not isinstance(value, complex) else bool(np.isfinite(value.real))
    if isinstance(value, np.ndarray):
        return value.dtype.kind not in "fc" or bool(np.all(np.isfinite(value)))
    if isinstance(value, dict):
        return all(finite(v, depth + 1) for v in value.values())
    if isinstance(value, list | tuple):
        return all(finite(v, depth + 1) for v in value[:50])
    if dataclasses.is_dataclass(value):
        return all(finite(getattr(value, f.name, None), depth + 1) for f in dataclasses.fields(value)
                   if not f.name.startswith("_"))
    return True


def check_result(result):
    assert finite(result), f"non-finite numbers in {result!r:.300}"
    if isinstance(result, ml.Mechanism):
        mo = result.motion(result.cycle(16))
        law = mo.output
        assert all(np.all(np.isfinite(x)) for x in (law.value, law.d, law.dd)), f"{result!r:.200} moves with NaN or inf"


def parameters(fn, args, kwargs):
    """(name, index or None) of every parameter of the valid call."""
    sig = inspect.signature(fn)
    names = list(sig.parameters)
    return [(names[i], i) for i in range(len(args))] + [(k, None) for k in kwargs]


def expects_object(fn, name) -> bool:
    """Whether ``name`` expects an object of a kind (a mechanism, a guide, a slot) rather than a number."""
    target = getattr(fn, "__wrapped__", fn)
    if inspect.isclass(target):
        field = {f.name: f for f in dataclasses.fields(target)}.get(name)
        spec = field and _spec_of(field.type, vars(inspect.getmodule(target)))
    else:
        annotation = inspect.signature(target).parameters[name].annotation
        spec = _spec_of(annotation, getattr(target, "__globals__", {}))
        if spec is None and isinstance(annotation, str) and re.fullmatch(r"[A-Z]\w*( \| None)?", annotation):
            return True  # annotated with a class of mechlab (a WholeTurnLine): an object of that kind
    return (spec is not None and spec.kind in ("mechanism", "items", "function", "path")) or \
        name in ("mechanism", "mech", "guide", "slot", "groups", "mechanisms")


def well_typed(value) -> bool:
    """A real finite number: it may be refused by a condition of the design rather than by its name."""
    if isinstance(value, bool | np.bool_):
        return True
    if isinstance(value, numbers.Integral):
        return abs(int(value)) < 2**63
    if isinstance(value, np.ndarray):  # a point (x, y) or samples: a value of the right type
        return value.ndim == 1 and len(value) > 0 and bool(np.all(np.isfinite(value)))
    return isinstance(value, numbers.Real) and bool(np.isfinite(value))


def run_case(name, replace, case=None):
    fn, args, kwargs = (case or CASES[name])()
    args, kwargs = list(args), dict(kwargs)
    param, index, bad = replace(parameters(fn, args, kwargs), args, kwargs)
    if index is None:
        kwargs[param] = bad
    else:
        args[index] = bad
    try:
        with contextlib.chdir(scratch()):  # a file name drawn as a value ("abc") is written there
            result = fn(*args, **kwargs)
    except ml.MechanismError as err:
        names = (param, param.replace("_", " ")) + ALIASES.get(param, ())
        assert well_typed(bad) or any(n in str(err) for n in names), \
            f"{name}({param}={bad!r}): {type(err).__name__}: {err}"
        return
    except TypeError as err:
        assert expects_object(fn, param), f"{name}({param}={bad!r}) raised TypeError: {err}"
        assert "must be" in str(err) or "needs" in str(err), f"{name}({param}={bad!r}): TypeError {err}"
        return
    check_result(result)


@pytest.mark.parametrize("name", sorted(CASES))
def test_valid_call(name):
    fn, args, kwargs = CASES[name]()
    check_result(fn(*args, **kwargs))


def fuzz(name, case, examples: int) -> None:
    """``examples`` calls of ``case`` with one parameter replaced by a nearby valid or an adversarial value."""
    @settings(max_examples=examples, deadline=None, database=None, suppress_health_check=list(HealthCheck))
    @given(st.data())
    def replaced(data):
        def replace(params, args, kwargs):
            param, index = data.draw(st.sampled_from(params), label="parameter")
            valid = args[index] if index is not None else kwargs[param]
            choices = list(ADVERSARIAL)
            if isinstance(valid, float) and not isinstance(valid, bool):
                choices.append(valid * data.draw(st.floats(0.5, 2.0), label="scale"))
            return param, index, data.draw(st.sampled_from(choices), label="value")
        run_case(name, replace, case)

    replaced()


@pytest.mark.parametrize("name", sorted(n for n in CASES if CASES[n]()[1] or CASES[n]()[2]))  # with parameters
def test_every_parameter_replaced(name):
    fuzz(name, CASES[name], BUDGET.get(name, 40))


def fuzz_family(cls, examples: int = 20) -> None:
    """Fuzz a family found at run time (e.g. one a test module defines) as the cases above: its example's
    fields each replaced in turn."""
    case = family_case(cls)
    fn, args, kwargs = case()
    check_result(fn(*args, **kwargs))
    fuzz(case_name(cls), case, examples)


def test_every_family_found_is_fuzzed():
    """Each family found at run time has its case: mechlab's above, one defined elsewhere (a test module's) here."""
    found = families()
    assert {ml.FourBar, ml.Linkage, ml.TranslatingRollerCam} <= set(found)
    for cls in found:
        if case_name(cls) in CASES:
            assert CASES[case_name(cls)]()[0] is cls
        else:
            fuzz_family(cls, examples=10)


# Exported classes whose instances are results, built by the library and never from user input (a Motion is
# made by motion(), a Criteria by evaluate()); every other exported callable needs a case above.
RESULTS = {"DesignOutcomes", "Mechanism", "Grashof", "Motion", "AngularMotion", "LinearMotion", "Law", "Extremes",
           "Table", "Quantity", "TransmissionExtremes", "forces.Reaction", "forces.ForceResult", "forces.Drive",
           "motion_laws.Invariants", "motion_laws.PrintedInvariants", "motion_laws.LawRow",
           "design.Comparison", "design.Candidate", "design.Refusal",
           "design.SpecificationReport", "design.LimitVerdict", "design.Criteria", "design.Design",
           "ArcFit", "RunFit", "DwellCheck", "Atlas", "AtlasDesign"}
def exported_callables() -> dict[str, object]:
    """Every callable that ``mechlab.__all__`` exports, and those of the modules it exports (``mechlab.forces``,
    ``mechlab.design``, …) as "module.name": functions and classes, not exceptions, constants or modules."""
    out = {}
    for name in ml.__all__:
        obj = getattr(ml, name)
        if inspect.ismodule(obj):
            out.update({f"{name}.{n}": getattr(obj, n) for n in obj.__all__})
        else:
            out[name] = obj
    return {k: v for k, v in out.items() if callable(v) and not inspect.ismodule(v)
            and not (inspect.isclass(v) and issubclass(v, BaseException))}


def test_every_export_is_covered():
    """A new export, at the top or in an exported module, fails here until it has a case in CASES."""
    exports = exported_callables()
    assert {"design.Specification", "design.candidates", "forces.solve", "motion_laws.law_invariants",
            "FourBar"} <= set(exports)
    assert not RESULTS - set(exports), "an exemption names no export"
    covered = {id(CASES[name]()[0]) for name in CASES}
    missing = sorted(name for name, obj in exports.items()
                     if id(obj) not in covered and name not in RESULTS)
    assert not missing, f"exports without a fuzz case: {missing}"
