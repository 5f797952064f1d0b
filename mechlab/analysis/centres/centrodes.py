"""Fixed and moving centrodes of one link relative to another (Kozhevnikov, §7.2).

The fixed centrode is the path of the relative centre P in the reference link's frame;
the moving centrode is the same point seen from the moving link. They touch at P at
every instant and roll on each other without slipping (Kozhevnikov, after formula
(7.9)). :func:`rolling_speeds` checks this with the seed's complex-number formulas,
derived anew: for two points A, B of the link (|AB| = l) written as complex numbers
z_A, z_B in the reference frame and primes for d/dφ,

    ξ_P = l·z_A' / (z_A' - z_B')                          (7.6)  P in the link's frame (x₁ along AB)
    z_P = (z_B z_A' - z_A z_B') / (z_A' - z_B')           (7.7)  P in the reference frame
    z_P' = (z_B - z_A)(z_A' z_B'' - z_A'' z_B') / (z_A' - z_B')²   (7.8)
    ξ_P' = l (z_A' z_B'' - z_A'' z_B') / (z_A' - z_B')²           (7.9)

so |z_P'| = |ξ_P'|: equal arc lengths on both centrodes.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ...errors import MechanismError
from ...geometry import AnglePath, PointPath, perp, unit
from ...mechanisms.base import AnyMechanism
from ...motion import scalar_law
from ...validate import Name, OptionalAngles, validated
from .homogeneous import Centre, CentreAtInfinity, in_frame
from .instant import InstantCentres, instant_centres


def point_in_frame(p: PointPath, origin: PointPath, angle: AnglePath) -> PointPath:
    """A moving point seen from a moving frame, with analogs:
    q = R(-θ)r, q' = R(-θ)(r' - θ'Jr), q'' = R(-θ)(r'' - θ''Jr - 2θ'Jr' - θ'²r), r = p - o."""
    th, d1, d2 = angle
    r, r1, r2 = p.p - origin.p, p.d - origin.d, p.dd - origin.dd
    c, s = np.cos(th)[:, None], np.sin(th)[:, None]

    def rot(v):
        return np.stack([c[:, 0] * v[:, 0] + s[:, 0] * v[:, 1], -s[:, 0] * v[:, 0] + c[:, 0] * v[:, 1]], -1)

    q1 = r1 - d1[:, None] * perp(r)
    q2 = r2 - d2[:, None] * perp(r) - 2.0 * d1[:, None] * perp(r1) - (d1**2)[:, None] * r
    return PointPath(rot(r), rot(q1), rot(q2))


def pole_from_two_points(zA, zB, dzA, dzB, phi=None):
    """Kozhevnikov formulas (7.6) and (7.7): (ξ_P, z_P) as complex arrays from two points of a link.

    Raises CentreAtInfinity where z_A' = z_B' (the link translates: the pole is at infinity).
    """
    den = dzA - dzB
    scale = np.maximum(np.abs(dzA), np.abs(dzB))
    bad = np.abs(den) <= 1e-13 * np.where(scale > 0, scale, 1.0)
    if np.any(bad):
        i = int(np.argmax(bad))
        at = "" if phi is None else f" at φ = {np.degrees(phi[i]):.4g}°"
        raise CentreAtInfinity(f"z_A' = z_B'{at}: the link translates, its pole is at infinity")
    l = np.abs(zB - zA)
    return l * dzA / den, (zB * dzA - zA * dzB) / den


@dataclass(frozen=True, eq=False)
class Centrodes:
    """Centrodes of ``link`` relative to ``reference`` over the crank angles ``phi``.

    ``centre``: the relative centre in world coordinates; ``fixed``: in the reference
    link's frame; ``moving``: in the moving link's frame (all :class:`Centre`, so points
    at infinity are explicit). ``poses`` holds both links' frames to place the curves
    in the world at any frame i (:meth:`fixed_at`, :meth:`moving_at`).
    """

    centres: InstantCentres
    link: str
    reference: str
    centre: Centre
    fixed: Centre
    moving: Centre

    @property
    def phi(self):
        return self.centres.phi

    def _place(self, c: Centre, name: str, i: int) -> Centre:
        o, th = self.centres.structure.poses[name]
        cs, sn = np.cos(th.theta[i]), np.sin(th.theta[i])
        x, y, w = c.h.T
        X = cs * x - sn * y + np.where(w != 0, o.p[i, 0], 0.0)
        Y = sn * x + cs * y + np.where(w != 0, o.p[i, 1], 0.0)
        return Centre(np.column_stack([X, Y, w]), c.name)

    def fixed_at(self, i: int) -> Centre:
        """The fixed centrode placed in world coordinates at frame i (it moves if the reference does)."""
        return self._place(self.fixed, self.reference, i)

    def moving_at(self, i: int) -> Centre:
        """The moving centrode carried by the link to its position at frame i, in world coordinates."""
        return self._place(self.moving, self.link, i)


def _two_links(ic: InstantCentres, link: str, reference: str) -> None:
    """``link`` and ``reference`` name two different links of the mechanism, else MechanismError naming them."""
    for param, name in (("link", link), ("reference", reference)):
        if name not in ic.links:
            raise MechanismError(f"{param} must be one of the links {', '.join(ic.links)}, got {name!r}")
    if link == reference:
        raise MechanismError(f"link and reference must be two different links, got {link!r} twice")


@scalar_law
@validated
def centrodes(mechanism: AnyMechanism, link: Name, reference: Name = "frame", phi: OptionalAngles = None,
              method: str = "kennedy") -> Centrodes:
    """Fixed and moving centrodes of ``link`` relative to ``reference``.

    Parameters
    ----------
    mechanism : Mechanism
        Any planar mechanism that describes its ``structure()``.
    link, reference : str
        Link names of :func:`instant_centres`, e.g. "coupler" and "frame" of a four-bar.
    phi : float or array_like, optional
        Crank angles (rad); by default the mechanism's cycle.
    method : {"kennedy", "velocity"}
        How the centres are found (see :func:`instant_centres`).

    Returns
    -------
    Centrodes
        ``centre`` (world), ``fixed`` (in the reference's frame) and ``moving`` (in the link's
        frame), each a :class:`Centre`.

    Raises
    ------
    TypeError
        ``mechanism`` is not a Mechanism.
    MechanismError
        ``link`` or ``reference`` is not a link, or both name the same link.
    SpatialMechanismError
        A spatial mechanism (it has no planar centres).
    IndeterminateCentre
        Kennedy's construction degenerates at a crank angle (use ``method="velocity"``).

    Examples
    --------
    >>> import numpy as np
    >>> import mechlab as ml
    >>> c = ml.centrodes(ml.FourBar(1, 3, 3, 4), "coupler", phi=np.array([0.0, 0.5]))
    >>> np.round(c.fixed.xy, 4)
    array([[4.    , 0.    ],
           [3.2458, 1.7732]])
    """
    ic = instant_centres(mechanism, phi, method)
    _two_links(ic, link, reference)
    P = ic(link, reference)
    poses = ic.structure.poses
    o_r, th_r = poses[ic.links[ic.index(reference)]]
    o_l, th_l = poses[ic.links[ic.index(link)]]
    return Centrodes(ic, link, reference, P, in_frame(P, o_r.p, th_r.theta), in_frame(P, o_l.p, th_l.theta))


@scalar_law
@validated
def rolling_speeds(mechanism: AnyMechanism, link: Name, reference: Name = "frame", phi: OptionalAngles = None):
    """Arc-length rates |dP/dφ| along the fixed and the moving centrode (formulas (7.8), (7.9)).

    Uses the link's origin and the point at one unit of length along its x-axis as A and B,
    both seen from the reference link.

    Parameters
    ----------
    mechanism : Mechanism
        Any planar mechanism that describes its ``structure()``.
    link, reference : str
        Link names of :func:`instant_centres`.
    phi : float or array_like, optional
        Crank angles (rad); by default the mechanism's cycle.

    Returns
    -------
    fixed_speed, moving_speed : numpy.ndarray
        |dP/dφ| along the fixed and the moving centrode (equal: rolling without slipping).
    xi, z : numpy.ndarray of complex
        The pole from (7.6) and (7.7), in the link's and in the reference's frame.

    Raises
    ------
    TypeError
        ``mechanism`` is not a Mechanism.
    MechanismError
        ``link`` or ``reference`` is not a link, or both name the same link.
    CentreAtInfinity
        The link translates relative to the reference at a crank angle.

    Examples
    --------
    >>> import numpy as np
    >>> import mechlab as ml
    >>> fixed, moving, xi, z = ml.rolling_speeds(ml.FourBar(1, 3, 3, 4), "coupler", phi=np.array([0.1, 1.0]))
    >>> np.round(fixed, 4), bool(np.allclose(fixed, moving))
    (array([4.0755, 5.1648]), True)
    """
    phi = mechanism.cycle() if phi is None else phi
    ic = instant_centres(mechanism, phi, method="velocity")
    _two_links(ic, link, reference)
    poses = ic.structure.poses
    o_r, th_r = poses[ic.links[ic.index(reference)]]
    o_l, th_l = poses[ic.links[ic.index(link)]]
    l = ic.structure.scale
    u = unit(th_l.theta)
    B = PointPath(o_l.p + l * u, o_l.d + l * th_l.d[:, None] * perp(u),
                  o_l.dd + l * (th_l.dd[:, None] * perp(u) - (th_l.d**2)[:, None] * u))
    a, b = point_in_frame(o_l, o_r, th_r), point_in_frame(B, o_r, th_r)
    z = lambda v: v[:, 0] + 1j * v[:, 1]  # noqa: E731
    zA, zB, dzA, dzB, ddzA, ddzB = z(a.p), z(b.p), z(a.d), z(b.d), z(a.dd), z(b.dd)
    xi, zP = pole_from_two_points(zA, zB, dzA, dzB, phi)
    num = dzA * ddzB - ddzA * dzB
    den2 = (dzA - dzB) ** 2
    dz = (zB - zA) * num / den2          # (7.8)
    dxi = l * num / den2                 # (7.9)
    return np.abs(dz), np.abs(dxi), xi, zP
