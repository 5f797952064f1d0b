"""Instantaneous centres and centrodes (Kozhevnikov, §7.1-7.2).

* :func:`instant_centres` — every relative centre of any mechanism that describes its
  ``structure()`` (every planar family: linkages, the lambda six-bars, the class-IV six-bar,
  curved slots, Geneva wheels, cams; the spherical Geneva refuses by name), by Kennedy's theorem
  (or, as a check, from the links' velocity twists), vectorised over φ; centres at
  infinity are explicit (homogeneous coordinates, :class:`Centre`).
* :func:`centrodes` — fixed and moving centrodes of any link relative to any other.
* :class:`EllipticTrammel`, :class:`Antiparallelogram` — the mechanisms of §7.2.
"""

from ...mechanisms.antiparallelogram import Antiparallelogram
from ...mechanisms.trammel import EllipticTrammel
from .centrodes import Centrodes, centrodes, pole_from_two_points, rolling_speeds
from .homogeneous import Centre, CentreAtInfinity, IndeterminateCentre, segments, separation
from .instant import InstantCentres, instant_centres
from .kennedy import centre_count, centres_from_twists, kennedy

__all__ = [
    "Antiparallelogram",
    "Centre",
    "CentreAtInfinity",
    "Centrodes",
    "EllipticTrammel",
    "IndeterminateCentre",
    "InstantCentres",
    "centre_count",
    "centres_from_twists",
    "centrodes",
    "instant_centres",
    "kennedy",
    "pole_from_two_points",
    "rolling_speeds",
    "segments",
    "separation",
]
