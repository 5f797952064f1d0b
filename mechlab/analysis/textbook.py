"""What textbooks read off a linkage: the branch of a sketch, the transmission angle's
extremes, the crank angles of zero output acceleration, crank ranges in degrees.

The limit positions and the time ratio are methods of the mechanisms that have them
(``FourBar.extremes()``, ``SliderCrank.extremes()``).
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass
from typing import Annotated

import numpy as np
from scipy.optimize import brentq, minimize_scalar

from ..errors import DimensionError
from ..mechanisms.base import AnyMechanism
from ..validate import Angle, Spec, check_value, count, validated


@validated
def nearest_assembly(mechanism: AnyMechanism, phi: Angle, **joints):
    """The assembly of ``mechanism`` whose joints at crank angle ``phi`` lie nearest the given points.

    Picks a branch from a sketch: both assemblies (+1 and -1) are solved at φ and the one
    with the smaller sum of distances from the named joints to their points is returned.

    Parameters
    ----------
    mechanism : Mechanism
        A mechanism with an ``assembly`` field (+1 or −1).
    phi : float
        Crank angle of the sketch (rad).
    **joints : (float, float)
        Joint name → its sketched point, in the mechanism's length units, e.g. ``B=(2.8, 2.7)``.

    Returns
    -------
    Mechanism
        A copy of ``mechanism`` with the nearer assembly.

    Raises
    ------
    DimensionError
        The mechanism has no assembly, no joint is given, a name is not one of its joints, or a
        point is not a finite (x, y) pair.
    AssemblyError
        The linkage cannot be assembled at ``phi``.

    Examples
    --------
    >>> import numpy as np
    >>> import mechlab as ml
    >>> from mechlab.analysis.textbook import nearest_assembly
    >>> nearest_assembly(ml.FourBar(1, 3, 3, 4), np.radians(60), B=(1.7, -1.9)).assembly
    -1
    """
    if not any(f.name == "assembly" for f in dataclasses.fields(mechanism)):
        raise DimensionError(f"{type(mechanism).__name__} has no assembly to choose")
    if not joints:
        raise DimensionError("nearest_assembly needs at least one joint and its sketched point, e.g. B=(x, y)")
    points = {name: np.array(check_value(f"the sketched point {name}", xy, Spec("point")))
              for name, xy in joints.items()}
    best = None
    for sign in (1, -1):
        candidate = dataclasses.replace(mechanism, assembly=sign)
        mo = candidate.motion(phi)
        missing = sorted(set(points) - set(mo.points))
        if missing:
            raise DimensionError(f"{missing} are not joints of {type(mechanism).__name__}; its joints are "
                                 f"{sorted(mo.points)}")
        gap = sum(float(np.hypot(*(mo.points[k].p - xy))) for k, xy in points.items())
        if best is None or gap < best[0]:
            best = (gap, candidate)
    return best[1]


@dataclass(frozen=True)
class TransmissionExtremes:
    """The least and greatest transmission angle μ over the crank's range and where they occur (radians).

    Parameters
    ----------
    mu_min : float
        Least transmission angle (rad).
    phi_min : float
        Crank angle where it occurs (rad, in [0, 2π)).
    mu_max : float
        Greatest transmission angle (rad).
    phi_max : float
        Crank angle where it occurs (rad, in [0, 2π)).

    Examples
    --------
    >>> import mechlab as ml
    >>> from mechlab.analysis.textbook import transmission_extremes
    >>> t = transmission_extremes(ml.FourBar(1, 3, 3, 4))
    >>> round(float(t.mu_min), 4), round(float(t.phi_max), 4)
    (1.0472, 3.1416)
    """

    mu_min: float
    phi_min: float
    mu_max: float
    phi_max: float

    @property
    def worst_deviation(self) -> float:
        """max |μ − 90°| over the cycle: the largest pressure angle.

        Returns
        -------
        float
            The largest deviation of μ from π/2 (rad).

        Examples
        --------
        >>> from mechlab.analysis.textbook import TransmissionExtremes
        >>> round(float(TransmissionExtremes(1.0, 0.0, 2.0, 3.14).worst_deviation), 4)
        0.5708
        """
        return max(np.pi / 2 - self.mu_min, self.mu_max - np.pi / 2)

    def __repr__(self) -> str:
        d = np.degrees
        return (f"TransmissionExtremes(μ_min = {d(self.mu_min):.4f}° at φ = {d(self.phi_min):.4f}°, "
                f"μ_max = {d(self.mu_max):.4f}° at φ = {d(self.phi_max):.4f}°; "
                f"worst |μ - 90°| = {d(self.worst_deviation):.4f}°)")


def _refine(f, phi, i):
    """The extremum of ``f`` near sample ``i`` of the grid ``phi``, by a bounded 1-D search."""
    lo, hi = phi[max(i - 1, 0)], phi[min(i + 1, len(phi) - 1)]
    res = minimize_scalar(f, bounds=(lo, hi), method="bounded", options={"xatol": 1e-12})
    return (float(res.x), float(res.fun)) if res.fun < f(phi[i]) else (float(phi[i]), float(f(phi[i])))


@validated
def transmission_extremes(mechanism: AnyMechanism, n: Annotated[int, count(3)] = 3601) -> TransmissionExtremes:
    """Least and greatest transmission angle over the crank's cycle and the crank angles of both.

    Sampled on ``mechanism.cycle(n)`` and refined by a bounded search between the grid's
    neighbours of each extreme. For a four-bar, μ is extreme where the crank lies along the
    frame line (φ = 0 and π, from cos μ = (c² + r² - |AE|²)/(2cr)).

    Parameters
    ----------
    mechanism : Mechanism
        A mechanism whose motion carries a transmission angle.
    n : int
        Samples of the crank's cycle (≥ 3; default 3601).

    Returns
    -------
    TransmissionExtremes
        μ_min, μ_max (rad) and the crank angles (rad) where they occur.

    Raises
    ------
    TypeError
        ``mechanism`` is not a Mechanism.
    DimensionError
        ``n`` is not an integer ≥ 3.

    Examples
    --------
    >>> import mechlab as ml
    >>> from mechlab.analysis.textbook import transmission_extremes
    >>> t = transmission_extremes(ml.FourBar(1, 3, 3, 4))
    >>> round(float(t.mu_min), 4), round(float(t.phi_min), 4)
    (1.0472, 0.0)
    """
    phi = mechanism.cycle(n)
    mu = mechanism.motion(phi).transmission

    def mu_at(x):
        return float(mechanism.motion(float(x)).transmission)

    phi_min, mu_min = _refine(mu_at, phi, int(np.argmin(mu)))
    phi_max, neg_max = _refine(lambda x: -mu_at(x), phi, int(np.argmax(mu)))
    return TransmissionExtremes(mu_min, float(np.mod(phi_min, 2 * np.pi)), -neg_max, float(np.mod(phi_max, 2 * np.pi)))


@validated
def zero_acceleration(mechanism: AnyMechanism, n: Annotated[int, count(3)] = 3601) -> np.ndarray:
    """Crank angles (radians, ascending in the cycle) where the output's second analog changes sign.

    There the output acceleration at a constant crank speed vanishes and its velocity is
    extreme, e.g. the slider-crank's s″ = 0. Each sign change of s″ (or ψ″) on
    ``mechanism.cycle(n)`` is polished by Brent's method on the exact analog.

    Parameters
    ----------
    mechanism : Mechanism
        Any mechlab mechanism.
    n : int
        Samples of the crank's cycle (≥ 3; default 3601).

    Returns
    -------
    numpy.ndarray
        The crank angles (rad) where the output's second analog is zero.

    Raises
    ------
    TypeError
        ``mechanism`` is not a Mechanism.
    DimensionError
        ``n`` is not an integer ≥ 3.

    Examples
    --------
    >>> import mechlab as ml
    >>> from mechlab.analysis.textbook import zero_acceleration
    >>> [round(float(p), 4) for p in zero_acceleration(ml.SliderCrank(1, 3))]
    [1.2771, 5.006]
    """
    phi = mechanism.cycle(n)
    dd = mechanism.motion(phi).output.dd
    change = np.flatnonzero(np.sign(dd[:-1]) * np.sign(dd[1:]) < 0)

    def dd_at(x):
        return float(mechanism.motion(float(x)).output.dd)

    return np.array([brentq(dd_at, phi[i], phi[i + 1], xtol=1e-14) for i in change])


@validated
def crank_ranges_degrees(mechanism: AnyMechanism) -> tuple[tuple[float, float], ...]:
    """``mechanism.crank_ranges()`` in degrees: ((0.0, 360.0),) for a crank that turns fully.

    Parameters
    ----------
    mechanism : Mechanism
        Any mechlab mechanism.

    Returns
    -------
    tuple of (float, float)
        Each range of crank angles (start, end) in degrees.

    Raises
    ------
    TypeError
        ``mechanism`` is not a Mechanism.

    Examples
    --------
    >>> import mechlab as ml
    >>> from mechlab.analysis.textbook import crank_ranges_degrees
    >>> crank_ranges_degrees(ml.FourBar(1, 3, 3, 4))
    ((0.0, 360.0),)
    """
    return tuple((float(np.degrees(s)), float(np.degrees(e))) for s, e in mechanism.crank_ranges())
