"""Each family's synthesis to one :class:`~mechlab.design.spec.Specification`, through the course's own synthesis.

A designer returns a :class:`Design` (the mechanism, its scale to mm, its structure) or
raises :class:`Unsuitable` with the reason and the numbers.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from scipy.optimize import brentq

from ..errors import MechanismError, Unsuitable
from ..mechanisms import ExternalGeneva, InternalGeneva, SphericalGeneva
from ..mechanisms.cam import OscillatingRollerCam, TranslatingRollerCam
from ..synthesis.atlas import load_atlas
from ..synthesis.cam_design import CamProgramme
from ..synthesis.coupler_dwell import arc_dwell_sixbar
from ..synthesis.dwell_slot import DwellLaw, best_placement, curved_slot_dwell
from ..synthesis.lambda_guiding import circle_guiding, straight_guiding
from ..synthesis.lambda_sixbars import mchv1, mchv3_half_turn
from ..synthesis.lambda_sliders import mchv2, mchv5
from ..synthesis.slot_export import write_cam_csv, write_cam_dxf, write_csv, write_dxf
from .criteria import SAMPLES, Counts, counted
from .spec import Specification

# lambda mechanisms tried, (δ, a): inside the existence region of Kinitsky (1994), Fig. 2a
LAMBDA_FRAMES = ((np.radians(150.0), 0.9), (np.radians(180.0), 0.8), (np.radians(120.0), 0.75))


@dataclass(frozen=True)
class Design:
    """One family's design for a specification.

    ``mechanism`` is in its own units; its lengths × ``scale`` are mm. ``circles`` are
    (centre, radius) of parts the joints do not trace (a wheel, a sphere), for the footprint.
    ``pressure_angle`` replaces the motion's own where the family knows it better.
    ``export(path)`` writes the part that must be manufactured to a profile (DXF), or is
    None where the family has none. ``phase`` shifts the sampled crank angles off a point
    where the family's solver cannot be evaluated.

    Parameters
    ----------
    family : str
        The family's name, a key of :data:`~mechlab.design.FAMILIES`.
    mechanism : Mechanism
        The synthesised mechanism, in its own units.
    scale : float
        Its lengths × ``scale`` are mm.
    structure : Counts
        Its moving parts, lower and higher pairs.
    circles : tuple of ((x, y), r), optional
        Parts the joints do not trace, for the footprint (mechanism's units).
    pressure_angle : float, optional
        Worst pressure angle (rad) replacing the motion's own.
    phase : float, optional
        Shift of the sampled crank angles (rad).
    export : callable, optional
        ``export(path)`` writes the part to manufacture (DXF); None where there is none.
    note : str, optional
        A line on what sets the design.

    Examples
    --------
    >>> from mechlab.design import FAMILIES, Specification
    >>> design = FAMILIES["external Geneva"](Specification("index", 0.75, stations=4))
    >>> design.family, str(design.structure), round(design.scale, 3)
    ('external Geneva', '2 parts, 2 lower + 2 higher pairs', 70.711)
    """

    family: str
    mechanism: object
    scale: float
    structure: Counts
    circles: tuple = ()
    pressure_angle: float | None = None
    phase: float = 0.0
    export: Callable | None = None
    note: str = ""


def _needs(spec: Specification, *motions: str, what: str) -> None:
    if spec.motion not in motions:
        article = "an" if spec.motion == "index" else "a"
        raise Unsuitable(f"{what}; {article} {spec.motion} was asked")


def _dwell_matches(spec: Specification, dwell: float, how: str) -> None:
    if abs(dwell - spec.dwell_fraction) > spec.dwell_tolerance:
        raise Unsuitable(f"{how} give a dwell fraction of {dwell:.3f}; {spec.dwell_fraction:.3f} was asked "
                         f"(± {spec.dwell_tolerance:.3f})")


def _geneva(cls, family: str, spec: Specification) -> Design:
    _needs(spec, "index", what="indexes a rotating table one way")
    z = spec.stations
    g = cls(z, 1.0)
    _dwell_matches(spec, g.dwell_fraction, f"{z} stations")
    wheel = ((g.centre_distance, 0.0), g.outer_radius)
    crank = ((0.0, 0.0), g.crank_radius + g.roller_radius)
    # parts: crank with pin and locking disc, wheel; pairs: two pivots, pin in slot, and the locking arcs (locks)
    return Design(family, g, spec.crank_radius / g.crank_radius, counted(g), circles=(wheel, crank),
                  pressure_angle=0.0, note="radial slot: the pin pushes along the wheel's tangent")


def external_geneva(spec: Specification) -> Design:
    return _geneva(ExternalGeneva, "external Geneva", spec)


def internal_geneva(spec: Specification) -> Design:
    return _geneva(InternalGeneva, "internal Geneva", spec)


def spherical_geneva(spec: Specification) -> Design:
    """The offset spherical Geneva (Vainer & Shatokhina): the offset e sets the dwell for z stations."""
    _needs(spec, "index", what="indexes a rotating table one way")
    # in mm: the drive's pin and slot have sizes of their own (pin_diameter, mm)
    z, R = spec.stations, spec.crank_radius
    # the dwell grows with e from 1/2 at e = 0; the largest admissible e is where the drive still assembles
    lo, hi = 0.0, R
    for _ in range(40):
        mid = 0.5 * (lo + hi)
        try:
            SphericalGeneva(R, mid, z)
            lo = mid
        except MechanismError:
            hi = mid
    e_max = lo * (1 - 1e-6)
    d_min, d_max = SphericalGeneva(R, 0.0, z).dwell_fraction, SphericalGeneva(R, e_max, z).dwell_fraction
    want = spec.dwell_fraction
    if not d_min - spec.dwell_tolerance <= want <= d_max + spec.dwell_tolerance:
        raise Unsuitable(f"with {z} stations its dwell fraction lies in [{d_min:.3f}, {d_max:.3f}] "
                         f"(offset 0 to {e_max:.4g} mm); {want:.3f} was asked")
    e = brentq(lambda e: SphericalGeneva(R, e, z).dwell_fraction - np.clip(want, d_min, d_max), 0.0, e_max,
               xtol=1e-9) if d_min < want < d_max else (0.0 if want <= d_min else e_max)
    g = SphericalGeneva(R, e, z)
    # the crank's locking disc and the wheel's arcs: a second, passive higher pair
    return Design("spherical Geneva", g, 1.0, counted(g),
                  circles=(((0.0, 0.0), R),), note=f"offset e = {e:.4g} mm sets the dwell (sphere R = {R:g} mm)")


def curved_slot(spec: Specification) -> Design:
    """The slotted link with a curved slot (Zinchenko et al., 2013): λ from the swing, the dwell placed
    where its largest pressure angle is least."""
    _needs(spec, "swing", what="rocks its output (λ < 1)")
    length = spec.dwell_angle
    if length >= np.pi - 0.1:
        raise Unsuitable(f"its dwell lies within one half-turn with room for both transitions: "
                         f"{np.degrees(length):.1f}° asked, less than {np.degrees(np.pi - 0.1):.1f}° possible")

    def design(lam):
        theta, phi1 = best_placement(lam, length)
        return theta, phi1, DwellLaw(lam, phi1, phi1 + length)

    phi = np.linspace(-np.pi, np.pi, 721)

    def swing(lam):
        return float(np.ptp(design(lam)[2](phi).psi))

    lo, hi = 0.05, 0.95
    s_lo, s_hi = swing(lo), swing(hi)
    if not s_lo <= spec.amplitude <= s_hi:
        raise Unsuitable(f"its swing lies in [{np.degrees(s_lo):.1f}°, {np.degrees(s_hi):.1f}°] for this dwell "
                         f"(λ from {lo} to {hi}); {np.degrees(spec.amplitude):.1f}° was asked")
    lam = brentq(lambda x: swing(x) - spec.amplitude, lo, hi, xtol=1e-6)
    theta, phi1, _ = design(lam)
    if theta > spec.max_pressure_angle:
        raise Unsuitable(f"its least worst pressure angle for a {np.degrees(length):.1f}° dwell is "
                         f"{np.degrees(theta):.1f}° > {np.degrees(spec.max_pressure_angle):.1f}° (λ = {lam:.3f})")
    m = curved_slot_dwell(lam, phi1, phi1 + length)
    scale = spec.crank_radius / m.crank

    def export(path):
        """The slot in mm: DXF at ``path`` and CSV beside it."""
        from ..synthesis.dwell_slot import curved_slot_dwell as build
        mm = build(lam, phi1, phi1 + length, pivot_distance=scale)
        write_dxf(mm, path)
        write_csv(mm, str(path).rsplit(".", 1)[0] + ".csv")
        return path

    return Design("curved slot", m, scale, counted(m),
                  pressure_angle=theta, export=export, note=f"λ = {lam:.4f}, dwell from φ = {np.degrees(phi1):.1f}°")


def _lambda_designs(spec: Specification, build, what: str) -> list:
    """Try the lambda frames of :data:`LAMBDA_FRAMES`; the designs that build, or Unsuitable with every reason."""
    designs, reasons = [], []
    for delta, a in LAMBDA_FRAMES:
        try:
            designs.append(build(delta, a))
        except MechanismError as err:
            reasons.append(f"δ = {np.degrees(delta):.0f}°, a = {a}: {err}")
    if not designs:
        raise Unsuitable(f"no {what} for this dwell: " + "; ".join(reasons))
    return designs


def mchv1_rocker(spec: Specification) -> Design:
    """Kinitsky's lambda six-bar, type 1 (МЧВ1): circle-guiding lambda mechanism and a rocker dyad, time ratio 1."""
    _needs(spec, "swing", what="rocks its output")
    mu_min = np.pi / 2 - spec.max_pressure_angle
    designs = _lambda_designs(
        spec, lambda d, a: mchv1(circle_guiding(d, a, spec.dwell_angle), 1.0, spec.amplitude, mu_min=mu_min),
        "lambda six-bar, type 1")
    six = min(designs, key=lambda m: m.r)  # the smallest crank for a given coupler: the slowest coupler
    return Design("lambda six-bar, type 1 (rocker dwell)", six, spec.crank_radius / six.r, counted(six))


def mchv3_half(spec: Specification) -> Design:
    """Kinitsky's lambda six-bar, type 3, half turn (МЧВ3-2М): a straight-line lambda mechanism drives a slotted
    link through 180°."""
    _needs(spec, "index", what="indexes 180° (2 stations)")
    if spec.stations != 2:
        raise Unsuitable(f"indexes 180° per crank turn (2 stations); {spec.stations} stations were asked")
    six = _lambda_designs(spec, lambda d, a: mchv3_half_turn(straight_guiding(d, a, spec.dwell_angle)),
                          "straight-line lambda mechanism")[0]
    return Design("lambda six-bar, type 3 (half-turn index)", six, spec.crank_radius / six.r, counted(six),
                  phase=1e-3)


def _stroke_design(spec, six, family):
    phi = np.linspace(0.0, 2 * np.pi, 721)
    stroke = float(np.ptp(six.motion(phi).s))
    return Design(family, six, spec.amplitude / stroke, counted(six))


def mchv2_slider(spec: Specification) -> Design:
    """Kinitsky's lambda six-bar, type 2 (МЧВ2): circle-guiding lambda mechanism, rod and slider, scaled to the
    stroke."""
    _needs(spec, "stroke", what="translates its output")
    six = _lambda_designs(spec, lambda d, a: mchv2(circle_guiding(d, a, spec.dwell_angle), 1.0,
                                                   mu_min=np.pi / 2 - spec.max_pressure_angle), "lambda six-bar, type "
                                                                                                "2")[0]
    return _stroke_design(spec, six, "lambda six-bar, type 2 (slider dwell)")


def mchv5_slotted(spec: Specification) -> Design:
    """Kinitsky's lambda six-bar, type 5 (МЧВ5): straight-line lambda mechanism and a translating slotted link,
    scaled to the stroke."""
    _needs(spec, "stroke", what="translates its output")
    six = _lambda_designs(spec, lambda d, a: mchv5(straight_guiding(d, a, spec.dwell_angle)),
                          "straight-line lambda mechanism")[0]
    return _stroke_design(spec, six, "lambda six-bar, type 5 (translating-slot dwell)")


def _rocker_swing(path: np.ndarray, rod: float, pivot: np.ndarray, rocker: float, sign: int) -> np.ndarray:
    """The output rocker's angle over the sampled coupler-point ``path`` (n, 2) for an RRR dyad (rod from the
    point, rocker from ``pivot``); NaN where the dyad does not close."""
    d = pivot - path
    dist = np.hypot(*d.T)
    with np.errstate(invalid="ignore", divide="ignore"):
        along = (rod * rod - rocker * rocker + dist * dist) / (2 * dist)
        h = np.sqrt(rod * rod - along * along)
        joint = path + (along[:, None] * d + sign * h[:, None] * np.column_stack([-d[:, 1], d[:, 0]])) / dist[:, None]
    return np.unwrap(np.arctan2(joint[:, 1] - pivot[1], joint[:, 0] - pivot[0]))


def _rocker_for_swing(path, rod: float, centre, direction, sign: int, amplitude: float) -> float | None:
    """The rocker length b (its pivot at ``centre`` + b·``direction``) whose swing over ``path`` is ``amplitude``:
    the first sign change on a geometric grid of b from 0.3 to 30 rods, refined by Brent's method; None if none."""

    def excess(b):
        psi = _rocker_swing(path, rod, centre + b * direction, b, sign)
        return float(np.ptp(psi)) - amplitude if np.all(np.isfinite(psi)) else np.nan

    grid = rod * np.geomspace(0.3, 30.0, 25)
    values = np.array([excess(b) for b in grid])
    bracket = np.flatnonzero(np.isfinite(values[:-1]) & np.isfinite(values[1:])
                             & (np.sign(values[:-1]) != np.sign(values[1:])))
    if not bracket.size:
        return None
    return brentq(excess, grid[bracket[0]], grid[bracket[0] + 1], xtol=1e-12 * rod)


ATLAS_TRIED = 12  # atlas designs tried per specification, best ripple first


def atlas_sixbar(spec: Specification) -> Design:
    """A six-bar from the coupler-curve atlas (:mod:`mechlab.synthesis.atlas`): a crank-rocker whose coupler point
    runs along a near-circular arc over the dwell, and a rod of the arc's radius to an output rocker whose joint
    rests at the arc's centre. Of the atlas's designs for the dwell (best ripple first), the first whose output
    rocker, pivoted square to the rod at mid-dwell at the distance that gives the asked swing, stands still
    within the specification's precision and transmits within its pressure angle."""
    _needs(spec, "swing", what="rocks its output (a rocker dwells while the coupler point runs along an arc)")
    atlas = load_atlas()
    widest = max(atlas.settings["arc_widths"])
    if spec.dwell_angle > widest:
        raise Unsuitable(f"the atlas holds arcs of up to {np.degrees(widest):.0f}° of crank; "
                         f"{np.degrees(spec.dwell_angle):.1f}° was asked")
    mu_min = np.pi / 2 - spec.max_pressure_angle
    found = atlas.query(spec.dwell_angle, spec.dwell_precision, mu_min, spec.max_size / spec.crank_radius,
                        count=ATLAS_TRIED)
    if not found:
        raise Unsuitable(f"no design of the atlas has a {np.degrees(spec.dwell_angle):.1f}° arc with a ripple under "
                         f"{spec.dwell_precision:g} of its radius, transmission ≥ {np.degrees(mu_min):.1f}° and size "
                         f"≤ {spec.max_size:g} mm")
    phi = np.linspace(0.0, 2 * np.pi, SAMPLES, endpoint=False)
    reasons = []
    for design in found:
        arc = design.arc
        path = design.path(phi)  # in closed form: the structure builder builds the chosen design only
        inside = ((phi - arc.crank_interval[0]) % (2 * np.pi)) <= arc.dwell
        centre = np.asarray(arc.centre)
        mid = design.path(0.5 * sum(arc.crank_interval))[0]
        to_mid = np.arctan2(*(mid - centre)[::-1])
        for side in (1, -1):
            direction = np.array([np.cos(to_mid + side * np.pi / 2), np.sin(to_mid + side * np.pi / 2)])
            # D at the centre at mid-dwell: on the left (+1) or right of the line P → F, as arc_dwell_sixbar builds
            to_centre = centre - mid
            sign = 1 if direction[0] * to_centre[1] - direction[1] * to_centre[0] > 0 else -1

            b = _rocker_for_swing(path, arc.radius, centre, direction, sign, spec.amplitude)
            if b is None:
                continue
            pivot = centre + b * direction
            psi = _rocker_swing(path, arc.radius, pivot, b, sign)
            still = float(np.ptp(psi[inside])) / spec.amplitude
            if still > spec.dwell_precision:
                reasons.append(f"design {design.index}: output moves {still:.2g} of its swing in the dwell")
                continue
            try:
                six = arc_dwell_sixbar(design.linkage(), "P", arc, output_pivot=tuple(pivot))
            except MechanismError as err:
                reasons.append(f"design {design.index}: {err}")
                continue
            pa = float(np.max(six.motion(phi).pressure_angle))
            if pa > spec.max_pressure_angle:
                reasons.append(f"design {design.index}: pressure angle {np.degrees(pa):.1f}°")
                continue
            return Design("atlas six-bar (coupler-curve arc)", six, spec.crank_radius, counted(six),
                          note=f"atlas design {design.index}: crank 1, coupler {design.coupler:g}, rocker "
                               f"{design.rocker:g}, frame {design.frame:g}, point {design.point}; arc R = "
                               f"{arc.radius:.4g}, ripple {arc.ripple / arc.radius:.2g} R")
    raise Unsuitable(f"none of the atlas's {len(found)} best designs for this dwell meets it: "
                     + "; ".join(reasons[:3]) + ("…" if len(reasons) > 3 else ""))


CAM_LAW = "cycloidal (sine)"  # continuous acceleration: no impact
ROLLER_FRACTIONS = (0.3, 0.2, 0.1)  # roller radius / base radius, tried until the profile is not undercut


def disc_cam(spec: Specification) -> Design:
    """A disc cam with a roller follower (translating for a stroke, oscillating for a swing): rise and
    return by the cycloidal law over the motion, the base circle the smallest that keeps the pressure
    angle within the limit, the roller the largest that does not undercut the profile."""
    _needs(spec, "swing", "stroke", what="lifts or rocks its follower (an index needs a barrel or globoidal cam)")
    motion = 2 * np.pi - spec.dwell_angle
    programme = CamProgramme(spec.amplitude, motion / 2, motion / 2, 0.0, law=CAM_LAW)
    phi = np.linspace(0.0, 2 * np.pi, 2 * SAMPLES + 1)  # finer than the judge's grid: its peak is not missed
    arm = 2 * spec.crank_radius

    def build(rb, roller):
        if spec.motion == "stroke":
            return TranslatingRollerCam(programme, rb, roller * rb)
        prime = rb * (1 + roller)
        return OscillatingRollerCam(programme, rb, roller * rb, float(np.hypot(arm, prime)), arm)

    def excess(rb, roller):
        try:
            return float(np.max(np.abs(build(rb, roller).pressure_angle(phi)))) - spec.max_pressure_angle
        except MechanismError:
            return np.pi  # the follower cannot be assembled: as bad as it gets

    lo, hi = (0.2 * spec.amplitude, 20 * spec.amplitude) if spec.motion == "stroke" else (0.1 * arm, 3 * arm)
    reasons = []
    for roller in ROLLER_FRACTIONS:
        if excess(hi, roller) > 0:
            reasons.append(f"roller {roller:g} r_b: even r_b = {hi:.4g} mm leaves the pressure angle above "
                           f"{np.degrees(spec.max_pressure_angle):.1f}°")
            continue
        rb = (lo if excess(lo, roller) <= 0
              else brentq(lambda r, roller=roller: excess(r, roller), lo, hi, xtol=1e-6 * hi))
        rb *= 1 + 1e-4  # just inside the limit
        cam = build(rb, roller)
        cut = cam.undercut()
        if cut is not None:
            reasons.append(f"roller {roller:g} r_b: {cut}")
            continue

        def export(path, cam=cam):
            """The profile in mm: DXF at ``path`` and CSV beside it."""
            write_cam_dxf(cam, path)
            write_cam_csv(cam, str(path).rsplit(".", 1)[0] + ".csv")
            return path

        follower = "translating" if spec.motion == "stroke" else "oscillating"
        return Design("disc cam", cam, 1.0, counted(cam),
                      circles=(((0.0, 0.0), float(np.max(np.hypot(*cam.profile().surface.T)))),), export=export,
                      note=f"{follower} roller follower, base radius {rb:.4g} mm, roller {roller * rb:.3g} mm, "
                           f"{CAM_LAW} law")
    raise Unsuitable("; ".join(reasons))


FAMILIES: dict[str, Callable[[Specification], Design]] = {
    "external Geneva": external_geneva,
    "internal Geneva": internal_geneva,
    "spherical Geneva": spherical_geneva,
    "curved slot": curved_slot,
    "lambda six-bar, type 1 (rocker dwell)": mchv1_rocker,
    "lambda six-bar, type 3 (half-turn index)": mchv3_half,
    "lambda six-bar, type 2 (slider dwell)": mchv2_slider,
    "lambda six-bar, type 5 (translating-slot dwell)": mchv5_slotted,
    "disc cam": disc_cam,
    "atlas six-bar (coupler-curve arc)": atlas_sixbar,
}
