"""What a machine asks of its dwell mechanism: the motion programme, the load and the limits."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import DimensionError

MOTIONS = ("index", "swing", "stroke")
IMPACTS = ("none", "soft", "hard")  # in order of severity


class SpecificationError(DimensionError):
    """A specification that no mechanism can be asked for (its message names the field)."""


def _number(name: str, value, lo: float = -np.inf, hi: float = np.inf, *, open_lo=False) -> float:
    if isinstance(value, (str, bytes, complex)) or value is None:
        raise SpecificationError(f"{name} must be a real number, got {value!r}")
    try:
        x = float(value)
    except (TypeError, ValueError, OverflowError):
        raise SpecificationError(f"{name} must be a real number, got {value!r}") from None
    if not np.isfinite(x) or x < lo or x > hi or (open_lo and x == lo):
        bound = f"({lo:g}, {hi:g}]" if open_lo else f"[{lo:g}, {hi:g}]"
        raise SpecificationError(f"{name} must lie in {bound}, got {x:g}")
    return x


@dataclass(frozen=True)
class Specification:
    """One machine's requirement on a dwell mechanism (angles in radians, lengths in mm, SI loads).

    Parameters
    ----------
    motion : {"index", "swing", "stroke"}
        ``"index"``: the output turns one way by ``2π/stations`` per crank turn (an indexing
        table); ``"swing"``: it rocks through ``amplitude`` (rad) and back; ``"stroke"``: it
        translates through ``amplitude`` (mm) and back.
    dwell_fraction : float
        Share of the crank turn during which the output stands still, in (0, 1).
    amplitude : float, optional
        Swing (rad) or stroke (mm); for ``"index"`` it follows from ``stations``.
    stations : int, optional
        Stations of the indexing table (``"index"`` only), ≥ 2.
    rpm : float
        Crank speed (cycles per minute).
    inertia, mass : float
        The output's load: moment of inertia (kg·m²) of a rotating output, mass (kg) of a
        translating one.
    resisting : float
        A constant torque (N·m) or force (N) that opposes the output's motion.
    max_pressure_angle : float
        Largest admitted pressure angle (rad); for a linkage, 90° − the least transmission angle.
    max_size : float
        Largest admitted dimension of the mechanism's footprint (mm).
    impacts : {"none", "soft", "hard"}
        The worst impact admitted: "none" (velocity and acceleration continuous), "soft"
        (acceleration may jump), "hard" (velocity may jump).
    dwell_tolerance : float
        How far the achieved dwell fraction may fall short of, or exceed, the asked one.
    dwell_precision : float
        The output "stands still" while it stays within this fraction of its amplitude.
    crank_radius : float
        The crank radius (mm) that sizes a design whose output is an angle (its kinematics do
        not fix a scale); a stroke fixes the scale itself.
    overload : float
        Motor overload factor of the course's motor rule (:func:`mechlab.kinetostatics.drive`).
    """

    motion: str
    dwell_fraction: float
    amplitude: float | None = None
    stations: int | None = None
    rpm: float = 60.0
    inertia: float = 0.0
    mass: float = 0.0
    resisting: float = 0.0
    max_pressure_angle: float = np.radians(45.0)
    max_size: float = 1000.0
    impacts: str = "hard"
    dwell_tolerance: float = 0.03
    dwell_precision: float = 0.001
    crank_radius: float = 50.0
    overload: float = 2.0

    def __post_init__(self):
        if self.motion not in MOTIONS:
            raise SpecificationError(f"motion must be one of {MOTIONS}, got {self.motion!r}")
        if self.impacts not in IMPACTS:
            raise SpecificationError(f"impacts must be one of {IMPACTS}, got {self.impacts!r}")
        fields = dict(dwell_fraction=_number("dwell_fraction", self.dwell_fraction, 0.0, 0.95, open_lo=True),
                      rpm=_number("rpm", self.rpm, 0.0, 1e5, open_lo=True),
                      inertia=_number("inertia", self.inertia, 0.0, 1e6),
                      mass=_number("mass", self.mass, 0.0, 1e6),
                      resisting=_number("resisting", self.resisting, 0.0, 1e9),
                      max_pressure_angle=_number("max_pressure_angle", self.max_pressure_angle, 0.0, np.pi / 2,
                                                 open_lo=True),
                      max_size=_number("max_size", self.max_size, 0.0, 1e5, open_lo=True),
                      dwell_tolerance=_number("dwell_tolerance", self.dwell_tolerance, 0.0, 0.5, open_lo=True),
                      dwell_precision=_number("dwell_precision", self.dwell_precision, 0.0, 0.2, open_lo=True),
                      crank_radius=_number("crank_radius", self.crank_radius, 0.0, 1e4, open_lo=True),
                      overload=_number("overload", self.overload, 1.0, 100.0))
        if self.motion == "index":
            if self.stations is None:
                raise SpecificationError("an index motion needs the number of stations")
            z = _number("stations", self.stations, 2, 360)
            if z != int(z) or isinstance(self.stations, bool):
                raise SpecificationError(f"stations must be a whole number, got {self.stations!r}")
            fields["stations"] = int(z)
            fields["amplitude"] = 2 * np.pi / int(z)
        else:
            if self.stations is not None:
                raise SpecificationError(f"stations belong to an index motion, not to a {self.motion}")
            if self.amplitude is None:
                raise SpecificationError(f"a {self.motion} needs its amplitude "
                                         f"({'swing angle, rad' if self.motion == 'swing' else 'stroke, mm'})")
            hi = np.pi if self.motion == "swing" else self.max_size
            fields["amplitude"] = _number("amplitude", self.amplitude, 0.0, hi, open_lo=True)
        for k, v in fields.items():
            object.__setattr__(self, k, v)

    @property
    def omega1(self) -> float:
        """Crank speed (rad/s)."""
        return self.rpm * 2 * np.pi / 60.0

    @property
    def dwell_angle(self) -> float:
        """Crank angle of the dwell (rad)."""
        return 2 * np.pi * self.dwell_fraction

    @property
    def rotary(self) -> bool:
        return self.motion != "stroke"

    def describe(self) -> str:
        """One line, in the units a machine designer reads."""
        if self.motion == "index":
            what = f"index {np.degrees(self.amplitude):.4g}° ({self.stations} stations)"
        elif self.motion == "swing":
            what = f"swing {np.degrees(self.amplitude):.4g}°"
        else:
            what = f"stroke {self.amplitude:.4g} mm"
        load = (f"J = {self.inertia:.4g} kg·m²" if self.rotary else f"m = {self.mass:.4g} kg")
        return (f"{what}, dwell {self.dwell_fraction:.3f} of the turn ({np.degrees(self.dwell_angle):.4g}°), "
                f"{self.rpm:.4g} rpm, {load}, pressure angle ≤ {np.degrees(self.max_pressure_angle):.4g}°, "
                f"size ≤ {self.max_size:.4g} mm, impacts: {self.impacts} at worst")
