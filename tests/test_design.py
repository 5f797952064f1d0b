"""Choosing a dwell mechanism: every candidate meets its specification when simulated anew; refusals
say why; the comparison criteria agree with closed forms (Geneva, cam laws, the limit theorem)."""

from dataclasses import replace

import numpy as np
import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st
from scipy.optimize import brentq

import mechlab as ml
from mechlab import design as D
from mechlab.analysis.half_turn import base_peaks
from mechlab.analysis.motion_laws import law_invariants
from mechlab.geometry import PointPath
from mechlab.mechanisms.cam import CamAngularMotion
from mechlab.motion import AngularMotion

SEEN: set[str] = set()  # families that produced a candidate in the property test


def _law(mo):
    return (mo.psi, mo.dpsi, mo.ddpsi) if hasattr(mo, "psi") else (mo.s, mo.ds, mo.dds)


def _resimulate(cand, spec, n=5001):
    """The candidate's motion on a grid of its own (not evaluate's), in mm for a stroke."""
    d = cand.design
    phi = d.phase + np.linspace(0.0, 2 * np.pi, n)
    x, d1, _ = _law(d.mechanism.motion(phi))
    return phi, (x if spec.rotary else x * d.scale), d1


def _longest_near(x, spec, n=1441):
    """Longest share of the turn over which the output stays within dwell_precision·h of one of its values
    (brute force over every sample as the reference, on the unwrapped output of two turns)."""
    idx = np.linspace(0, len(x) - 1, n).round().astype(int)
    one = x[idx][:-1]
    shift = x[-1] - x[0] if spec.motion == "index" else 0.0
    ext = np.concatenate([one, one + shift])
    best = 0
    for i in range(n - 1):
        near = np.abs(ext - ext[i]) <= spec.dwell_precision * spec.amplitude
        # the run of True through i (and through i + n - 1, its copy one turn later)
        for j in (i, i + n - 1):
            lo = j - np.argmin(near[j::-1]) if not near[j::-1].all() else 0
            hi = j + np.argmin(near[j:]) if not near[j:].all() else len(ext)
            best = max(best, hi - lo - 1 if not near[j::-1].all() else hi - lo)
    return min(best, n - 1) / (n - 1)


specs = st.one_of(
    st.builds(lambda z, extra, rpm: D.Specification("index", min(0.9, (z + 2) / (2 * z) + extra), stations=z,
                                                    rpm=rpm, inertia=1.0),
              st.integers(3, 10), st.sampled_from([-0.1, -0.02, 0.0, 0.02, 0.1]), st.floats(10, 120)),
    st.builds(lambda dw, sw, pa: D.Specification("swing", dw / 360, amplitude=np.radians(sw),
                                                 max_pressure_angle=np.radians(pa), inertia=0.2),
              st.sampled_from([30, 40, 60, 120]), st.floats(15, 60), st.sampled_from([45, 60, 70])),
    st.builds(lambda dw, h: D.Specification("stroke", dw / 360, amplitude=h, mass=3.0,
                                            max_pressure_angle=np.radians(60)),
              st.sampled_from([60, 120]), st.floats(20, 150)),
)


@settings(max_examples=12, deadline=None)
@given(specs)
@example(D.Specification("index", 2 / 3, stations=6, inertia=2.4, rpm=40))
@example(D.Specification("swing", 40 / 360, amplitude=np.radians(40), max_pressure_angle=np.radians(60)))
@example(D.Specification("stroke", 1 / 3, amplitude=60.0, mass=2.0, max_pressure_angle=np.radians(60)))
def test_every_candidate_meets_its_specification_when_simulated_anew(spec):
    comp = D.candidates(spec)
    SEEN.update(c.family for c in comp.candidates)
    assert len(comp.candidates) + len(comp.refusals) == len(D.FAMILIES)
    for cand in comp.candidates:
        _phi, x, _d1 = _resimulate(cand, spec)
        h = spec.amplitude
        if spec.motion == "index":
            assert abs(abs(x[-1] - x[0]) - h) < 1e-6 * h  # one index per crank turn
        else:
            assert np.ptp(x) == pytest.approx(h, rel=2e-3)  # the swing or stroke asked
        # the output stands still (within the precision band) for at least the asked dwell less the tolerance
        assert _longest_near(x, spec) >= spec.dwell_fraction - spec.dwell_tolerance - 2e-3
        c = cand.criteria
        assert c.pressure_angle <= spec.max_pressure_angle + 1e-9
        assert 0 < c.size <= spec.max_size
        assert D.spec.IMPACTS.index(c.impact) <= D.spec.IMPACTS.index(spec.impacts)
        for v in (c.B, c.C, c.peak_torque, c.rms_torque, c.motor_power, c.dwell_residual):
            assert np.isfinite(v) and v >= 0
    for r in comp.refusals:
        assert r.reason and r.family in D.FAMILIES


def test_the_property_test_saw_candidates_of_several_families():
    # runs after the property test (file order): it must not have passed on refusals alone
    assert {"external Geneva", "spherical Geneva", "curved slot", "lambda six-bar, type 1 (rocker dwell)",
            "lambda six-bar, type 2 (slider dwell)", "disc cam"} <= SEEN


def test_refusals_name_their_reason_with_numbers():
    spec = D.Specification("index", 0.60, stations=4)
    comp = D.candidates(spec)
    refused = {r.family: r.reason for r in comp.refusals}
    assert refused["external Geneva"] == "4 stations give a dwell fraction of 0.750; 0.600 was asked (± 0.030)"
    assert "0.250" in refused["internal Geneva"]
    assert refused["curved slot"].startswith("rocks its output")
    assert refused["disc cam"].startswith("lifts or rocks its follower")
    assert refused["disc cam"].endswith("; an index was asked")
    assert "180°" in refused["lambda six-bar, type 3 (half-turn index)"]
    assert "4 stations" in refused["lambda six-bar, type 3 (half-turn index)"]
    tight = D.candidates(D.Specification("swing", 50 / 360, amplitude=np.radians(40),
                                         max_pressure_angle=np.radians(55)), ["curved slot"])
    assert not tight.candidates and "> 55.0°" in tight.refusals[0].reason


def test_a_limit_missed_in_simulation_is_a_refusal_with_its_numbers():
    small = D.Specification("index", 0.75, stations=4, max_size=100.0)
    comp = D.candidates(small, ["external Geneva"])
    assert not comp.candidates
    assert "size" in comp.refusals[0].reason and "> 100 mm" in comp.refusals[0].reason
    none = D.Specification("index", 0.75, stations=4, impacts="none")
    refusal = D.candidates(none, ["external Geneva"]).refusals[0]
    assert "impacts: soft where none at worst are admitted" in refusal.reason


@pytest.mark.parametrize("z", [3, 4, 6, 8])
def test_geneva_criteria_agree_with_its_closed_form(z):
    spec = D.Specification("index", (z + 2) / (2 * z), stations=z, inertia=1.0)
    cand = D.candidates(spec, ["external Geneva"]).candidates[0]
    g, c = cand.design.mechanism, cand.criteria
    # the index is one rise, from the end of the exact dwell to the start of the next: the rest of the turn
    assert c.dwell_fraction == pytest.approx(g.dwell_fraction, abs=1e-7)
    motion_angle, h = 2 * np.pi * (1 - c.dwell_fraction), 2 * np.pi / z
    assert c.B == pytest.approx(g.max_velocity() * motion_angle / h, rel=2.5e-3)
    assert c.C == pytest.approx(g.max_acceleration() * motion_angle**2 / h, rel=3e-3)
    assert c.impact == "soft" and c.acceleration_jump > 0.01 and c.velocity_jump == 0.0
    assert c.dwell_residual < 1e-3


class _CycloidalRiseReturn:
    """A stand-in whose output is a cycloidal rise over Φ/2, a cycloidal return over Φ/2, then a dwell."""

    def __init__(self, motion_angle, h):
        object.__setattr__(self, "Phi", motion_angle)
        object.__setattr__(self, "h", h)

    def motion(self, phi):
        phi = np.asarray(phi, float)
        half = self.Phi / 2
        t = np.mod(phi, 2 * np.pi)
        u = np.clip(np.where(t < half, t, self.Phi - t) / half, 0.0, 1.0)
        sgn = np.where(t < half, 1.0, -1.0) * (t < self.Phi)
        x = self.h * (u - np.sin(2 * np.pi * u) / (2 * np.pi))
        d1 = sgn * self.h / half * (1 - np.cos(2 * np.pi * u))
        d2 = (t < self.Phi) * self.h / half**2 * 2 * np.pi * np.sin(2 * np.pi * u)
        zero = np.zeros((len(phi), 2))
        return AngularMotion(phi, {"O": PointPath(zero, zero, zero)}, np.full(len(phi), np.pi / 2), x, d1, d2)


def test_criteria_reproduce_the_cycloidal_invariants():
    # over its rise (Φ/2) the output is the cycloidal law: B, C, D are the law's own, and its jerk peaks at 4π²
    spec = D.Specification("swing", 1 / 3, amplitude=0.5)
    mech = _CycloidalRiseReturn(2 * np.pi * (1 - spec.dwell_fraction), 0.5)
    c = D.evaluate(mech, spec, scale=1.0, structure=D.Counts(1, 1, 1))
    law = law_invariants("cycloidal (sine)")
    assert (law.B, law.C) == (pytest.approx(2.0), pytest.approx(2 * np.pi))
    # the rise is measured from where the exact dwell ends (its end refined between samples) up to the top
    assert (c.B, c.C, c.D) == pytest.approx((law.B, law.C, law.D), rel=1e-3)
    # no closed-form jerk in this motion: a central difference of x″
    assert c.J == pytest.approx(4 * np.pi**2, rel=3e-3)
    assert c.impact == "none"
    # the exact dwell is the stand-in's: a third of the turn
    assert c.dwell_fraction == pytest.approx(1 / 3, abs=1e-6)
    # the near-standstill is longer: the output stays within 0.001 h of rest also where the cycloid leaves
    # and joins it (y = ε at u*)
    u = brentq(lambda u: u - np.sin(2 * np.pi * u) / (2 * np.pi) - spec.dwell_precision, 1e-6, 0.5)
    assert c.standstill_fraction == pytest.approx(1 / 3 + 2 * u * (mech.Phi / 2) / (2 * np.pi), abs=1e-3)
    assert c.standstill_fraction > c.dwell_fraction + 0.01
    assert c.dwell_residual == pytest.approx(0.0, abs=1e-6)


class _CycloidalWithJerk(_CycloidalRiseReturn):
    """The same stand-in whose motion carries a closed-form ``jerk`` (as a cam's does), times ``factor``."""

    factor = 1.0

    def motion(self, phi):
        mo = super().motion(phi)
        half, t = self.Phi / 2, np.mod(np.asarray(phi, float), 2 * np.pi)
        u = np.clip(np.where(t < half, t, self.Phi - t) / half, 0.0, 1.0)
        sgn = np.where(t < half, 1.0, -1.0) * (t < self.Phi)
        jerk = self.factor * sgn * self.h / half**3 * 4 * np.pi**2 * np.cos(2 * np.pi * u)
        return CamAngularMotion(mo.phi, mo.points, mo._transmission, mo.psi, mo.dpsi, mo.ddpsi, jerk)


def test_criteria_take_the_jerk_from_the_motions_closed_form():
    # the capstone's J is the law's closed-form jerk where the motion has one: exact to the sampling of Φ,
    # and it is that jerk (scaling it scales J; a central difference of x″ would not follow)
    spec = D.Specification("swing", 1 / 3, amplitude=0.5)
    mech = _CycloidalWithJerk(2 * np.pi * (1 - spec.dwell_fraction), 0.5)
    assert D.evaluate(mech, spec, scale=1.0, structure=D.Counts(1, 1, 1)).J == pytest.approx(4 * np.pi**2,
                                                                                                 rel=1e-5)
    mech.factor = 1.5
    assert D.evaluate(mech, spec, scale=1.0, structure=D.Counts(1, 1, 1)).J == pytest.approx(6 * np.pi**2,
                                                                                                 rel=1e-5)


def test_curved_slot_candidate_respects_the_limit_theorem():
    # Zinchenko et al. (2013): no linkage's peak ψ' is below its base mechanism's
    spec = D.Specification("swing", 40 / 360, amplitude=np.radians(40), max_pressure_angle=np.radians(60))
    cand = D.candidates(spec, ["curved slot"]).candidates[0]
    lam = cand.design.mechanism.lam
    _phi, _x, d1 = _resimulate(cand, spec)
    assert np.max(np.abs(d1)) >= base_peaks(lam)[0] * (1 - 1e-9)


def test_the_table_shows_and_exports(tmp_path):
    comp = D.candidates(D.Specification("index", 2 / 3, stations=6, inertia=2.4, rpm=40))
    assert {c.family for c in comp.candidates} >= {"external Geneva", "spherical Geneva"}
    text = comp.to_csv(tmp_path / "t.csv")
    assert (tmp_path / "t.csv").read_text(encoding="utf-8") == text
    assert text.splitlines()[0].startswith("family,dwell_fraction,standstill_fraction,dwell_residual,B,C,D,J,impact")
    assert "external Geneva" in comp._repr_html_() and "Refused" in comp._repr_html_()
    by_power = comp.ranked("motor_power")
    powers = [c.criteria.motor_power for c in by_power.candidates]
    assert powers == sorted(powers)
    with pytest.raises(ml.MechanismError, match="by must be one of"):
        comp.ranked("colour")


def test_the_chosen_curved_slot_exports_its_slot(tmp_path):
    spec = D.Specification("swing", 40 / 360, amplitude=np.radians(40), max_pressure_angle=np.radians(60))
    cand = D.candidates(spec, ["curved slot"]).candidates[0]
    path = cand.design.export(tmp_path / "slot.dxf")
    assert (tmp_path / "slot.dxf").stat().st_size > 1000 and (tmp_path / "slot.csv").exists()
    assert path == tmp_path / "slot.dxf"


@pytest.mark.parametrize("bad, match", [
    (dict(motion="jump"), "motion must be one of"),
    (dict(dwell_fraction=float("nan")), "dwell_fraction"),
    (dict(dwell_fraction=1.2), "dwell_fraction must be ≤ 0.95"),
    (dict(stations=None), "needs the number of stations"),
    (dict(stations=4.5), "whole number"),
    (dict(rpm=0), "rpm"),
    (dict(rpm="fast"), "rpm must be a number"),
    (dict(max_pressure_angle=2.0), "max_pressure_angle"),
    (dict(impacts="some"), "impacts must be one of"),
    (dict(inertia=1 + 1j), "inertia must be a real number"),
])
def test_a_bad_specification_names_its_field(bad, match):
    kw = dict(motion="index", dwell_fraction=0.75, stations=4) | bad
    with pytest.raises(D.SpecificationError, match=match):
        D.Specification(**kw)
    with pytest.raises(TypeError, match="Specification"):
        D.candidates({"motion": "index"})


def test_the_explorer_recovers_from_an_impossible_specification():
    from mechlab.widgets.design import ChoosingExplorer
    ex = ChoosingExplorer(D.Specification("index", 0.75, stations=4, inertia=1.0), live=False)
    assert "external Geneva" in ex.table.value and not ex.message
    ex.sliders["dwell_fraction"].value = 0.40  # no Geneva dwells 0.40 with 4 stations
    assert ex.message == "No family meets this specification."
    assert "4 stations give a dwell fraction of 0.750; 0.400 was asked" in ex.table.value
    assert not any(line.get_visible() for line in ex.figure.curves.values())
    ex.sliders["dwell_fraction"].value = 0.75
    assert not ex.message and ex.figure.curves["external Geneva"].get_visible()
    ex.rank.value = "size"
    sizes = [c.criteria.size for c in ex.comparison.candidates]
    assert sizes == sorted(sizes)


def test_check_design_reports_each_limit_with_numbers():
    spec = D.Specification("stroke", 1 / 3, amplitude=120.0, mass=6.0, max_pressure_angle=np.radians(60))
    six = ml.mchv2(ml.circle_guiding(np.radians(150), 0.9, spec.dwell_angle), 1.0)
    stroke = np.ptp(six.motion(np.linspace(0, 2 * np.pi, 2881)).s)
    good = D.check_design(spec, six, scale=120.0 / stroke)
    assert good.met, str(good)
    bad = D.check_design(spec, six, scale=100.0 / stroke)  # a stroke of 100 mm, 120 asked
    assert not bad.met
    amp = next(v for v in bad.verdicts if v.criterion == "amplitude")
    assert not amp.met and amp.text.startswith("100 mm reached, 120 mm asked")
    tight = D.check_design(replace(spec, max_pressure_angle=np.radians(20)), six, scale=120.0 / stroke)
    pa = next(v for v in tight.verdicts if v.criterion == "pressure angle")
    assert not pa.met and "> 20.0°" in pa.text
    with pytest.raises(TypeError, match="mechanism"):
        D.check_design(spec, "МЧВ2")
    with pytest.raises(ml.MechanismError, match="scale"):
        D.check_design(spec, six, scale=-1)


@pytest.mark.parametrize("z", [4, 6])
def test_geneva_torque_and_motor_agree_with_the_geneva_chapter(z):
    # the comparison samples the turn uniformly; kinetostatics.geneva.geneva_drive resolves the engagement ends
    from mechlab.kinetostatics.geneva import geneva_drive
    spec = D.Specification("index", (z + 2) / (2 * z), stations=z, inertia=2.4, rpm=40)
    cand = D.candidates(spec, ["external Geneva"]).candidates[0]
    ref = geneva_drive(cand.design.mechanism, inertia=2.4, omega1=spec.omega1)
    assert cand.criteria.peak_torque == pytest.approx(ref.peak_torque, rel=2e-3)
    assert cand.criteria.rms_torque == pytest.approx(ref.rms_torque, rel=2e-3)
    assert cand.criteria.motor_power == pytest.approx(ref.nominal_power, rel=2e-3)


@pytest.mark.parametrize("motion, amplitude", [("stroke", 80.0), ("swing", np.radians(30))])
def test_the_cam_candidate_carries_its_law_and_exports_its_profile(motion, amplitude, tmp_path):
    # the cam's rise is the cycloidal law solved through the profile: from the end of its exact dwell, its
    # invariants are the law's, and its jerk the law's closed form, C_j = 4π²
    spec = D.Specification(motion, 0.3, amplitude=amplitude, max_pressure_angle=np.radians(35), impacts="none")
    cand = D.candidates(spec, ["disc cam"]).candidates[0]
    law = law_invariants("cycloidal (sine)")
    c = cand.criteria
    assert (c.B, c.C, c.J) == pytest.approx((law.B, law.C, 4 * np.pi**2), rel=1e-5)
    assert c.dwell_fraction == pytest.approx(0.3, abs=1e-6)
    assert c.pressure_angle <= spec.max_pressure_angle and c.impact == "none"
    # the base circle is the smallest within the limit: 2 % smaller breaks it
    cam = cand.design.mechanism
    phi = np.linspace(0, 2 * np.pi, 1441)
    assert np.max(np.abs(cam.pressure_angle(phi))) == pytest.approx(spec.max_pressure_angle, rel=1e-3)
    assert cam.undercut() is None
    cand.design.export(tmp_path / "cam.dxf")
    assert (tmp_path / "cam.dxf").stat().st_size > 1000 and (tmp_path / "cam.csv").exists()


@settings(max_examples=300, deadline=None)
@given(st.lists(st.floats(-3, 3), min_size=1, max_size=40), st.sampled_from([0.0, 0.5, 7.0]),
       st.sampled_from([0.0, 0.1, 0.5, 2.0, 100.0]))
def test_longest_still_is_the_first_longest_run_in_the_band(values, shift, band):
    # against brute force over every start and length of the periodic samples (one turn at most)
    from mechlab.design.criteria import longest_still

    x = np.array(values)
    n, ext = len(x), np.concatenate([x, x + shift])
    best = max((length, -s) for s in range(2 * n) for length in range(1, min(n, 2 * n - s) + 1)
               if np.ptp(ext[s:s + length]) <= band)
    assert longest_still(x, shift, band) == (-best[1] % n, best[0])
