"""Design and code checks: run a student's design (or function) through mechlab and report each
specification met or missed, with the numbers ("pressure angle 52.3° > 45° at φ = 12°").

Every checker returns a :class:`DesignReport` (truthy when every specification is met; ``require``
raises :class:`~mechlab.course.exercises.feedback.NotYet` with the whole report). Angles are asked and
reported in degrees; lengths in the design's own unit.
"""

from __future__ import annotations

import os
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ...errors import MechanismError, renamed
from . import feedback
from .feedback import NotYet
from .selfcheck import record, value_bin

_TEST = {"<": np.less, "≤": np.less_equal, ">": np.greater, "≥": np.greater_equal}
_NEGATION = {"<": "≥", "≤": ">", ">": "≤", "≥": "<"}


@dataclass(frozen=True)
class Requirement:
    """One specification: ``value op limit`` (op one of < ≤ > ≥), or ``|value − limit| ≤ tol`` when ``op``
    is "≈"; ``where`` says where the value was measured (e.g. "φ = 12°")."""

    name: str
    value: float
    op: str
    limit: float
    unit: str = ""
    where: str = ""
    tol: float = 0.0

    @property
    def met(self) -> bool:
        if not np.isfinite(self.value):
            return False
        if self.op == "≈":
            return abs(self.value - self.limit) <= self.tol
        return bool(_TEST[self.op](self.value, self.limit))

    def __str__(self) -> str:
        u = self.unit
        at = f" at {self.where}" if self.where else ""
        if self.op == "≈":
            rel = "within" if self.met else "outside"
            return (f"{'✓' if self.met else '✗'} {self.name} {self.value:.4g}{u}{at}: {rel} "
                    f"{self.limit:.4g}{u} ± {self.tol:.2g}{u}")
        op = self.op if self.met else _NEGATION[self.op]
        return f"{'✓' if self.met else '✗'} {self.name} {self.value:.4g}{u} {op} {self.limit:.4g}{u}{at}"


@dataclass(frozen=True)
class DesignReport:
    """The specifications of one design, each met or missed; ``problem`` is set when the design could
    not be examined at all (wrong type, not buildable, a function that raised)."""

    title: str
    specs: tuple[Requirement, ...] = ()
    problem: str = ""

    @property
    def ok(self) -> bool:
        return not self.problem and all(s.met for s in self.specs)

    def __bool__(self) -> bool:
        return self.ok

    def __repr__(self) -> str:
        head = f"{self.title}: {'every specification met ✓' if self.ok else 'not yet ✗'}"
        lines = [f"  {s}" for s in self.specs] + ([f"  ✗ {self.problem}"] if self.problem else [])
        return "\n".join([head, *lines])

    def require(self) -> None:
        """Print the report if every specification is met, else raise NotYet with it (and log the outcome
        for the class report while ``make grade`` runs)."""
        missed = [s.name for s in self.specs if not s.met] + (["could not be examined"] if self.problem else [])
        record({"name": self.title, "kind": "design", "ok": self.ok,
                "outcome": "every specification met" if self.ok else "missed: " + ", ".join(missed)})
        if not self.ok:
            raise NotYet(repr(self))
        print(repr(self))


def _deg(x) -> float:
    return float(np.degrees(x))


def _kind(obj, cls, title: str, what: str) -> DesignReport | None:
    if obj is None or obj is Ellipsis:
        return DesignReport(title, problem=f"no design yet: build {what}")
    if not isinstance(obj, cls):
        return DesignReport(title, problem=f"expected {what}, got {type(obj).__name__}")
    return None


def _full_turn(mech, cls, title: str, what: str):
    """The motion over one crank turn, or the report of why there is none (no design, wrong type, no full turn)."""
    if (bad := _kind(mech, cls, title, what)) is not None:
        return bad
    try:
        return mech.motion(mech.turn(3601))
    except MechanismError as err:
        return DesignReport(title, problem=f"the crank does not turn fully: {err}")


def _turn(n: int = 3601) -> np.ndarray:
    return np.linspace(0.0, 2 * np.pi, n)


def time_ratio(psi: np.ndarray, phi: np.ndarray) -> float:
    """K = (crank angle of the slower stroke)/(of the faster) between the output's extremes over one turn."""
    i, j = int(np.argmin(psi)), int(np.argmax(psi))
    forward = (phi[j] - phi[i]) % (2 * np.pi)
    return float(max(forward, 2 * np.pi - forward) / min(forward, 2 * np.pi - forward))


def fourbar_design(fb, *, swing: float | None = None, swing_tol: float = 0.5, min_transmission: float | None = None,
                   time_ratio_at_least: float | None = None) -> DesignReport:
    """A crank-rocker four-bar: the crank turns fully; rocker swing ``swing`` ± ``swing_tol`` (degrees);
    transmission angle μ within [min_transmission, 180° − min_transmission] over the turn; time ratio
    K ≥ ``time_ratio_at_least``."""
    from ...mechanisms.fourbar import FourBar

    mo = _full_turn(fb, FourBar, "four-bar design", "a mechlab FourBar(crank, coupler, rocker, ground)")
    if isinstance(mo, DesignReport):
        return mo
    specs = []
    if swing is not None:
        specs.append(Requirement("rocker swing", _deg(np.ptp(mo.psi)), "≈", swing, "°", tol=swing_tol))
    if min_transmission is not None:
        dev = np.minimum(mo.transmission, np.pi - mo.transmission)
        k = int(np.argmin(dev))
        specs.append(Requirement("smallest transmission angle min(μ, 180° − μ)", _deg(dev[k]), "≥",
                                 min_transmission, "°", f"φ = {_deg(mo.phi[k]):.0f}°"))
    if time_ratio_at_least is not None:
        specs.append(Requirement("time ratio K", time_ratio(mo.psi, mo.phi), "≥", time_ratio_at_least))
    return DesignReport("four-bar design", tuple(specs))


def output_design(mech, *, min_swing: float | None = None, max_velocity: float | None = None) -> DesignReport:
    """Any mechanism whose crank turns fully and whose output is an angle (a slotted link, a four-bar, …):
    swing of the output over a turn ≥ ``min_swing`` (degrees); largest |ψ′| ≤ ``max_velocity``."""
    from ...mechanisms.base import Mechanism

    mo = _full_turn(mech, Mechanism, "output design", "a mechlab mechanism")
    if isinstance(mo, DesignReport):
        return mo
    specs = []
    if min_swing is not None:
        specs.append(Requirement("output swing", _deg(np.ptp(mo.psi)), "≥", min_swing, "°"))
    if max_velocity is not None:
        k = int(np.argmax(np.abs(mo.dpsi)))
        specs.append(Requirement("largest |ψ′|", float(abs(mo.dpsi[k])), "≤", max_velocity, "",
                          f"φ = {_deg(mo.phi[k]):.0f}°"))
    return DesignReport("output design", tuple(specs))


def guide_design(guide, *, min_dwell: float, max_band: float, min_crank: float) -> DesignReport:
    """A lambda mechanism's circle-guiding design (``circle_guiding``, Kinitsky, 1994): dwell 2α ≥ ``min_dwell``
    (degrees), half-width E of the band around the arc ≤ ``max_band``, crank r ≥ ``min_crank`` (units of l)."""
    from ...synthesis.lambda_guiding import CircleGuide

    title = "circle-guiding design"
    if (bad := _kind(guide, CircleGuide, title, "circle_guiding(delta, a, dwell)")) is not None:
        return bad
    return DesignReport(title, (Requirement("dwell 2α", _deg(guide.dwell), "≥", min_dwell, "°"),
                                Requirement("band half-width E", guide.E, "≤", max_band, " l"),
                                Requirement("crank r", guide.r, "≥", min_crank, " l")))


def cam_design(cam, *, max_pressure: float, max_base_radius: float | None = None,
               motion: tuple[float, float, float, float] | None = None) -> DesignReport:
    """A disc cam with a roller follower (``mechlab.TranslatingRollerCam`` or ``OscillatingRollerCam``): the
    profile is not undercut, the largest |pressure angle| over the turn is < ``max_pressure`` (degrees), the
    base radius ≤ ``max_base_radius`` (the cam's size), and — when ``motion`` = (stroke, rise, outer dwell,
    return) is given (the stroke in the cam's length unit, angles in degrees) — the follower's programme is
    that motion (stroke to 0.05, angles to 0.5°), so that a cam for an easier motion does not pass."""
    title = "cam design"
    if cam is None or cam is Ellipsis:
        return DesignReport(title, problem="no design yet: build a TranslatingRollerCam or OscillatingRollerCam")
    if not all(hasattr(cam, name) for name in ("undercut", "pressure_angle")):
        return DesignReport(title, problem=f"expected a mechlab roller cam, got {type(cam).__name__}")
    phi = np.linspace(0.0, 2 * np.pi, 2881)
    alpha = np.abs(cam.pressure_angle(phi))
    k = int(np.argmax(alpha))
    specs = [Requirement("pressure angle", _deg(alpha[k]), "<", max_pressure, "°", f"φ = {_deg(phi[k]):.0f}°")]
    if max_base_radius is not None:
        specs.append(Requirement("base radius", float(cam.base_radius), "≤", max_base_radius))
    if motion is not None:
        prog = cam.programme
        got = (float(prog.stroke), _deg(prog.rise), _deg(prog.outer_dwell), _deg(prog.ret))
        specs += [Requirement(name, value, "≈", want, unit, tol=tol) for name, value, want, unit, tol in
                  zip(("stroke", "rise", "outer dwell", "return"), got, motion, ("", "°", "°", "°"),
                      (0.05, 0.5, 0.5, 0.5), strict=False)]
    cut = cam.undercut()
    return DesignReport(title, tuple(specs), "" if cut is None else f"the profile is undercut: {cut}")


def dwell_slot_design(mech, *, min_dwell: float, max_pressure: float, dxf: str | os.PathLike | None = None,
                      n: int = 721) -> DesignReport:
    """A curved-slot dwell mechanism (Zinchenko et al., 2013, §3): dwell φ2 − φ1 ≥ ``min_dwell`` (degrees),
    the largest pressure angle over the turn < ``max_pressure`` (degrees), and — when ``dxf`` is given — that
    file, which must lie in the working folder (the notebook's own, a submission's own when graded), a
    readable DXF whose centre line (layer CENTRE) lies within 1e-3 pivot distances of the designed slot's
    centre line."""
    from ...synthesis.dwell_slot import DwellSlotMechanism

    title = "curved-slot dwell design"
    if (bad := _kind(mech, DwellSlotMechanism, title, "curved_slot_dwell(lam, phi1, phi2, ...)")) is not None:
        return bad
    theta, at = mech.max_pressure_angle(n)
    specs = [Requirement("dwell φ2 − φ1", _deg(mech.phi2 - mech.phi1), "≥", min_dwell, "°"),
             Requirement("pressure angle", _deg(theta), "<", max_pressure, "°", f"φ = {_deg(at):.0f}°")]
    problem = ""
    if dxf is not None:
        gap, problem = _dxf_gap(mech, dxf)
        if not problem:
            specs.append(Requirement("DXF centre line's distance from the designed slot", gap, "≤",
                              1e-3 * mech.pivot_distance))
    return DesignReport(title, tuple(specs), problem)


def _dxf_gap(mech, path) -> tuple[float, str]:
    """Largest distance from the designed slot's centre line to the DXF's (layer CENTRE), or why none."""
    import ezdxf

    where = repr(os.fspath(path))
    here = Path.cwd().resolve()
    if here not in Path(path).resolve().parents:
        # a file outside the notebook's own folder may be another student's: grading reads only the submission's
        return np.inf, (f"write the DXF beside this notebook (a plain file name such as 'slot.dxf'), not to {where}: "
                        "the check reads only files in the notebook's own folder")
    if not os.path.isfile(path):
        return np.inf, f"no DXF file at {where}: write it with mechlab.synthesis.slot_export.write_dxf"
    try:
        doc = ezdxf.readfile(path)
    except (OSError, ezdxf.DXFError) as err:
        return np.inf, f"{where} is not a readable DXF: {err}"
    pts = [np.asarray(list(e.vertices()))[:, :2] for e in doc.modelspace().query("LWPOLYLINE POLYLINE")
           if e.dxf.layer == "CENTRE"]
    if not pts:
        return np.inf, f"{where} has no polyline on layer CENTRE"
    got, want = np.concatenate(pts), mech.slot_points(401)
    gap = float(np.min(np.hypot(*(want[:, None, :] - got[None, :, :]).transpose(2, 0, 1)), axis=1).max())
    if gap > 1e-3 * mech.pivot_distance:
        return gap, f"the DXF's centre line is {gap:.3g} away from this design's slot: export the design you checked"
    return gap, ""


def sixbar_design(mech, dwell: float, *, time_ratio: float, swing: float, time_ratio_tol: float = 0.02,
                  swing_tol: float = 0.5, max_residual: float = 0.5) -> DesignReport:
    """A dwell six-bar (Kinitsky, 1994) simulated over a turn (``lambda_sixbars.report``): time ratio K
    ± ``time_ratio_tol``, swing ± ``swing_tol`` (degrees), residual motion over the dwell
    ``dwell`` (degrees, centred on φ = 180°) ≤ ``max_residual`` degrees."""
    from ...mechanisms.lambda_sixbars import LambdaRockerSixBar
    from ...synthesis.lambda_sixbars import report

    title = "dwell six-bar design"
    if (bad := _kind(mech, LambdaRockerSixBar, title, "a six-bar from mchv1(guide, K, swing)")) is not None:
        return bad
    rep = report(mech, np.radians(dwell))
    return DesignReport(title, (
        Requirement("time ratio K", rep.K, "≈", time_ratio, tol=time_ratio_tol),
        Requirement("swing", _deg(rep.swing), "≈", swing, "°", tol=swing_tol),
        Requirement(f"residual motion over the {dwell:g}° dwell", _deg(rep.residual), "≤", max_residual, "°"),
    ))


def motor_specs(motor_power: float, drive, catalogue: Sequence[float] | None = None) -> tuple[Requirement, ...]:
    """The chosen motor (W) against a :class:`~mechlab.kinetostatics.drive.Drive`: it covers the nominal power,
    and — with a ``catalogue`` — it is the smallest catalogue size that does."""
    specs = [Requirement(f"motor power vs the nominal power ({drive.governing} governs)", float(motor_power), "≥",
                  drive.nominal_power, " W")]
    if catalogue is not None:  # counted, not named: the check must not hand out the answer
        smaller = [p for p in catalogue if drive.nominal_power <= p < float(motor_power)]
        specs.append(Requirement("smaller catalogue motors that would also do", len(smaller), "≤", 0))
    return tuple(specs)


def geneva_design(geneva, *, rpm: float, inertia: float, index_time: float, motor_power: float,
                  min_rpm: float | None = None, min_dwell_fraction: float | None = None,
                  catalogue: Sequence[float] | None = None, overload: float = 2.0,
                  impacts: Sequence[str] | None = None) -> DesignReport:
    """A Geneva drive (planar or spherical) at ``rpm`` indexing ``inertia`` (kg·m²): at least ``min_rpm``
    cycles a minute; a share ≥ ``min_dwell_fraction`` of the turn at rest; the wheel's motion takes at most
    ``index_time`` seconds; the motor of ``motor_power`` W covers the nominal power of
    :func:`mechlab.kinetostatics.geneva.geneva_drive` (rms torque, peak/overload) and is the smallest of
    ``catalogue`` that does (:func:`motor_specs`); ``impacts`` lists the admissible kinds at entry ("none",
    "soft", "hard")."""
    from ...kinetostatics.geneva import geneva_drive
    from ...mechanisms.geneva import PlanarGeneva
    from ...mechanisms.spherical_geneva import SphericalGeneva

    title = "Geneva drive design"
    if (bad := _kind(geneva, (PlanarGeneva, SphericalGeneva), title, "an ExternalGeneva, InternalGeneva or "
                     "SphericalGeneva")) is not None:
        return bad
    omega1 = float(rpm) * 2 * np.pi / 60
    d = geneva_drive(geneva, inertia=inertia, omega1=omega1, overload=overload, n=2001)
    specs = [Requirement("cycles per minute", float(rpm), "≥", min_rpm)] if min_rpm is not None else []
    if min_dwell_fraction is not None:
        specs.append(Requirement("dwell fraction", geneva.dwell_fraction, "≥", min_dwell_fraction))
    specs += [Requirement("index time", 2 * geneva.engagement_half_angle / omega1, "≤", index_time, " s"),
              *motor_specs(motor_power, d, catalogue)]
    problem = ""
    if impacts is not None and (kind := geneva.impacts().kind) not in impacts:
        problem = f"impact at entry is {kind!r}, admissible: {', '.join(impacts)}"
    return DesignReport(title, tuple(specs), problem)


def press_design(k, motor_power: float, *, stroke: float, stroke_tol: float, max_pressure: float,
                 catalogue: Sequence[float] | None = None, overload: float = 2.0) -> DesignReport:
    """A press (``mechlab.kinetostatics.press``, metres): slider stroke ``stroke`` ± ``stroke_tol``; largest
    pressure angle at the slider < ``max_pressure`` (degrees); ``motor_power`` (W) covers the nominal power
    of the course's drive rule (:func:`motor_specs`)."""
    from ...kinetostatics.drive import drive
    from ...kinetostatics.machines import Kinetostatics

    title = "press design"
    if (bad := _kind(k, Kinetostatics, title, "a press from mechlab.forces.press(crank, rod, ...)")) is not None:
        return bad
    mo = k.mechanism.motion(_turn())
    r = k.forces(k.turn(721))
    d = drive(r.torque, r.phi, r.omega1, overload=overload)
    i = int(np.argmax(mo.pressure_angle))
    return DesignReport(title, (
        Requirement("stroke", float(np.ptp(mo.s)), "≈", stroke, " m", tol=stroke_tol),
        Requirement("pressure angle", _deg(mo.pressure_angle[i]), "<", max_pressure, "°",
                    f"φ = {_deg(mo.phi[i]):.0f}°"),
        *motor_specs(motor_power, d, catalogue),
    ))


def function_check(fn: Callable, reference: Callable, cases: Iterable[tuple], *, name: str,
                   rtol: float = 1e-6, atol: float = 1e-9, hint: str = "") -> DesignReport:
    """Call the student's ``fn(*case)`` and the grader's ``reference(*case)`` (mechlab, or better an
    independent formula) on every case (e.g. random geometries); report how many agree and the first that
    does not, with its inputs (never the reference's value).

    An output agrees when each element lies in the reference element's bin, or a neighbouring one, of a
    logarithmic grid of step ``rtol`` (|x| ≤ ``atol`` is one bin): the rule of
    :func:`.selfcheck.first_disagreement`, which the student edition's :func:`.self_check` applies to keyed
    digests of the same bins, so the notebook's verdict is the grader's. While :func:`.recording`, the
    call records the cases and the reference's bins (for ``make student`` to seal) and passes. ``hint`` is
    added to the message on a case that disagrees.

    Examples
    --------
    >>> function_check(lambda x: 2 * x, lambda x: x + x, [(1.0,), (2.5,)], name="double").ok
    True
    """
    cases = list(cases)
    outputs = []
    for case in cases:
        want = np.asarray(reference(*case), dtype=float)
        outputs.append((want.shape, [value_bin(float(x), rtol, atol) for x in want.ravel()]))
    if feedback._RECORDING is not None:
        feedback._RECORDING.append(dict(kind="function", name=name, cases=cases, outputs=outputs, rtol=rtol,
                                        atol=atol, hint=hint))
        return DesignReport(f"function {name}", problem="")
    verdict, agreed = feedback.function_outcome(fn, name, cases, outputs, rtol=rtol, atol=atol, hint=hint)
    title = f"function {name}"
    if verdict.ok:
        return DesignReport(title, (Requirement(f"cases that agree with the reference (rtol {rtol:g})",
                                                len(cases), "≥", len(cases)),))
    agree = ((Requirement("cases that agree with the reference", agreed, "≥", len(cases)),)
             if verdict.kind == "wrong" else ())
    return DesignReport(title, agree, problem=verdict.message.removeprefix("✗ "))


# the old name (validate.Spec is what a parameter may be)
__getattr__ = renamed(__name__, Spec=(Requirement, "mechlab.course.exercises.Requirement"))
