"""What a machine asks of its dwell mechanism: the motion programme, the load and the limits."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Annotated

import numpy as np

from ..errors import SpecificationError
from ..validate import Checked, Spec, choice, count, mechanism

MOTIONS = ("index", "swing", "stroke")
IMPACTS = ("none", "soft", "hard")  # in order of severity


def _within(lo: float, hi: float, *, open_lo: bool = False, optional: bool = False) -> Spec:
    """A real number in [lo, hi] (or (lo, hi] with ``open_lo``), refused as a SpecificationError."""
    return Spec("number", lo, hi, open_lo=open_lo, optional=optional, error=SpecificationError)


Fraction = Annotated[float, _within(0.0, 0.95, open_lo=True)]


@dataclass(frozen=True)
class Specification(Checked):
    """One machine's requirement on a dwell mechanism (angles in radians, lengths in mm, SI loads).

    Parameters
    ----------
    motion : {"index", "swing", "stroke"}
        ``"index"``: the output turns one way by ``2π/stations`` per crank turn (an indexing
        table); ``"swing"``: it rocks through ``amplitude`` (rad) and back; ``"stroke"``: it
        translates through ``amplitude`` (mm) and back.
    dwell_fraction : float
        Share of the crank turn during which the output stands still, in (0, 1): still within
        ``dwell_precision`` (a near-standstill), so that an approximate dwell can meet it; a design's
        ``Criteria.standstill_fraction`` is compared with it, its exact ``dwell_fraction`` is reported beside.
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

    Raises
    ------
    SpecificationError
        A value outside its range, an index motion without ``stations``, ``stations`` given
        to a swing or a stroke, a swing or stroke without ``amplitude``, or an amplitude
        beyond π (a swing) or ``max_size`` (a stroke).

    Examples
    --------
    >>> from mechlab.design import Specification
    >>> spec = Specification("index", 0.5, stations=4)
    >>> round(float(spec.amplitude), 4)
    1.5708
    """

    motion: Annotated[str, choice(*MOTIONS, error=SpecificationError)]
    dwell_fraction: Fraction
    amplitude: Annotated[float | None, _within(0.0, 1e5, open_lo=True, optional=True)] = None
    stations: Annotated[int | None, count(2, 360, optional=True, error=SpecificationError)] = None
    rpm: Annotated[float, _within(0.0, 1e5, open_lo=True)] = 60.0
    inertia: Annotated[float, _within(0.0, 1e6)] = 0.0
    mass: Annotated[float, _within(0.0, 1e6)] = 0.0
    resisting: Annotated[float, _within(0.0, 1e9)] = 0.0
    max_pressure_angle: Annotated[float, _within(0.0, np.pi / 2, open_lo=True)] = np.radians(45.0)
    max_size: Annotated[float, _within(0.0, 1e5, open_lo=True)] = 1000.0
    impacts: Annotated[str, choice(*IMPACTS, error=SpecificationError)] = "hard"
    dwell_tolerance: Annotated[float, _within(0.0, 0.5, open_lo=True)] = 0.03
    dwell_precision: Annotated[float, _within(0.0, 0.2, open_lo=True)] = 0.001
    crank_radius: Annotated[float, _within(0.0, 1e4, open_lo=True)] = 50.0
    overload: Annotated[float, _within(1.0, 100.0)] = 2.0

    def __post_init__(self):
        super().__post_init__()
        if self.motion == "index":
            if self.stations is None:
                raise SpecificationError("an index motion needs the number of stations")
            object.__setattr__(self, "amplitude", 2 * np.pi / self.stations)
        else:
            if self.stations is not None:
                raise SpecificationError(f"stations belong to an index motion, not to a {self.motion}")
            if self.amplitude is None:
                raise SpecificationError(f"a {self.motion} needs its amplitude "
                                         f"({'swing angle, rad' if self.motion == 'swing' else 'stroke, mm'})")
            hi, what = (np.pi, "π (a swing)") if self.motion == "swing" else (self.max_size, "max_size (a stroke)")
            if self.amplitude > hi:
                raise SpecificationError(f"amplitude must be ≤ {what} = {hi:g}, got {self.amplitude:g}")

    @property
    def omega1(self) -> float:
        """Crank speed (rad/s).

        Returns
        -------
        float
            ``rpm · 2π / 60``.

        Examples
        --------
        >>> from mechlab.design import Specification
        >>> round(Specification("swing", 0.3, amplitude=0.5, rpm=60).omega1, 4)
        6.2832
        """
        return self.rpm * 2 * np.pi / 60.0

    @property
    def dwell_angle(self) -> float:
        """Crank angle of the dwell (rad).

        Returns
        -------
        float
            ``2π · dwell_fraction``.

        Examples
        --------
        >>> from mechlab.design import Specification
        >>> round(Specification("swing", 0.25, amplitude=0.5).dwell_angle, 4)
        1.5708
        """
        return 2 * np.pi * self.dwell_fraction

    @property
    def rotary(self) -> bool:
        """Whether the output rotates (an index or a swing) rather than translates (a stroke).

        Returns
        -------
        bool
            True for ``"index"`` and ``"swing"``, False for ``"stroke"``.

        Examples
        --------
        >>> from mechlab.design import Specification
        >>> Specification("stroke", 0.3, amplitude=40.0).rotary
        False
        """
        return self.motion != "stroke"

    def describe(self) -> str:
        """One line, in the units a machine designer reads (degrees, mm, rpm).

        Returns
        -------
        str
            The motion, dwell, speed, load and limits.

        Examples
        --------
        >>> from mechlab.design import Specification
        >>> Specification("index", 0.5, stations=4).describe()[:40]
        'index 90° (4 stations), dwell 0.500 of t'
        """
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


AnySpecification = Annotated[Specification, mechanism(Specification)]
