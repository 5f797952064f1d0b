"""The four-bar linkage O-A-B-E in both assemblies.

Frame: crank pivot O at the origin, output pivot E at (ground, 0). The crank angle φ
and the output angle ψ (of the rocker E→B) are measured counter-clockwise from the
ray O→E. Lengths are dimensionless or in mm, as long as they agree.

Assembly (Zinchenko et al., 2013, §1, the text after Fig. 6): ``assembly = +1`` is
kc = +1, the points A, B, E traversed clockwise, i.e. B lies on the left of the directed
line A→E (above the frame line in the usual drawing of a crank-rocker); ``assembly = -1``
(kc = -1) is the other, counter-clockwise assembly. In the textbook names (Norton's
"open" and "crossed" circuits) ``"open"`` = +1 and ``"crossed"`` = -1: while the crank is
above the frame line (0 < φ < π) the +1 branch has B and O on opposite sides of the
diagonal AE, the quadrilateral O-A-B-E drawn uncrossed. A name labels a branch for every
φ; below the frame line the open branch's drawing may look crossed. The two are mirror images:
``FourBar(..., -1).motion(phi)`` equals ``FourBar(..., +1).motion(-phi)`` reflected
in the frame line, so ψ₋(φ) = -ψ₊(-φ), ψ'₋(φ) = ψ'₊(-φ), ψ''₋(φ) = -ψ''₊(-φ).
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property
from typing import Annotated

import numpy as np

from ..errors import AssemblyError, RotationError
from ..geometry import _re_conj, as_angles, as_complex, circle_circle, crank_point, fixed_point, rocker_dyad
from ..motion import AngularMotion, Extremes, limit_positions
from ..validate import Length, Spec, check_value
from .base import FRAME, Link, Mechanism, Pair, Structure, arc_set, branch_references, fmt_ranges, lift_on_ranges
from .curved_slot import CircleSlot, CurvedSlotLink

# Relative tolerance for Grashof's equality s + l = p + q (a change-point linkage).
_CHANGE_POINT_TOL = 1e-12
# The textbook names of the two assemblies (see the module docstring).
ASSEMBLY_NAMES = {"open": 1, "crossed": -1}


# an assembly: +1, -1 or a name in ASSEMBLY_NAMES
Assembly = Annotated[int | str, Spec("sign", options=tuple(ASSEMBLY_NAMES.items()))]


def assembly_sign(value) -> int:
    """The assembly sign from +1, -1 or a name in ``ASSEMBLY_NAMES`` ("open" = +1, "crossed" = -1)."""
    return check_value("assembly", value, Assembly.__metadata__[0])


def circle_pair(r1: float, centre2, r2: float) -> tuple[np.ndarray, np.ndarray]:
    """Both intersections of the circle of radius r1 about the origin with the circle of radius r2
    about ``centre2``, as two points (mirror images in the line of the centres)."""
    c = np.asarray(centre2, dtype=float)
    d = float(np.hypot(*c))
    along = (r1 * r1 - r2 * r2 + d * d) / (2 * d)
    across = np.sqrt(max(r1 * r1 - along * along, 0.0))
    u = c / d
    v = np.array([-u[1], u[0]])
    return along * u + across * v, along * u - across * v


@dataclass(frozen=True)
class Grashof:
    """Grashof classification of a four-bar with the numbers behind it (from :meth:`FourBar.grashof`).

    Parameters
    ----------
    kind : str
        The linkage by its crank and rocker (Norton's table): ``"crank-rocker"``, ``"double-crank"``,
        ``"rocker-crank"``, ``"double-rocker"``, ``"change-point"`` or ``"triple-rocker"``.
    s, l : float
        The shortest and the longest link (length).
    p, q : float
        The other two links (length).
    shortest : str
        The name of the shortest link (``"crank"``, ``"coupler"``, ``"rocker"`` or ``"ground"``).

    Examples
    --------
    >>> from mechlab import FourBar
    >>> FourBar(1, 3, 3.5, 4).grashof()
    Grashof(kind='crank-rocker', s=1.0, l=4.0, p=3.0, q=3.5, shortest='crank')
    """

    kind: str            # crank-rocker, double-crank, rocker-crank, double-rocker, change-point, triple-rocker
    s: float             # shortest link
    l: float             # longest link
    p: float             # the other two
    q: float
    shortest: str        # name of the shortest link

    @property
    def inequality(self) -> str:
        """Grashof's inequality with its numbers, e.g. ``"s + l = 5.00 < p + q = 6.50"``.

        Returns
        -------
        str
            The comparison of s + l with p + q (``<``, ``=`` within 1e-12 relative, or ``>``).
        """
        lhs, rhs = self.s + self.l, self.p + self.q
        rel = "=" if abs(lhs - rhs) <= _CHANGE_POINT_TOL * rhs else ("<" if lhs < rhs else ">")
        return f"s + l = {lhs:.2f} {rel} p + q = {rhs:.2f}"

    @property
    def grashof_class(self) -> str:
        """Whether Grashof's condition s + l ≤ p + q holds.

        Returns
        -------
        str
            ``"Grashof"``, ``"non-Grashof"`` (every triple-rocker) or ``"change-point"`` (equality).
        """
        return {"change-point": "change-point", "triple-rocker": "non-Grashof"}.get(self.kind, "Grashof")

    def __str__(self) -> str:
        name = "triple-rocker, non-Grashof" if self.kind == "triple-rocker" else self.kind
        return f"{name} ({self.inequality}, shortest link: {self.shortest} = {self.s:g})"


@dataclass(frozen=True)
class FourBar(Mechanism):
    """Crank O-A, coupler A-B, rocker B-E, frame O-E; output ψ = angle of E→B.

    The crank pivot O is at the origin, the output pivot E at (ground, 0); φ and ψ are measured
    counter-clockwise from the ray O→E (radians).

    Parameters
    ----------
    crank, coupler, rocker, ground : float
        Link lengths (positive; dimensionless or mm, in one unit).
    assembly : {1, -1, "open", "crossed"}, optional
        The assembly branch: +1 or ``"open"`` (B on the left of A→E), -1 or ``"crossed"``; stored as the sign.

    Raises
    ------
    DimensionError
        If a length is not positive and finite, or ``assembly`` is not one of the four values.
    AssemblyError
        If the linkage closes at no crank angle.

    Examples
    --------
    >>> from mechlab import FourBar
    >>> m = FourBar(1, 3, 3.5, 4)
    >>> round(float(m.motion(0.3).psi), 4)
    2.1036
    >>> m.grashof().kind
    'crank-rocker'
    """

    title = "four-bar"

    @classmethod
    def example(cls) -> FourBar:
        """A crank-rocker (crank 1, coupler 3, rocker 3, ground 4).

        Returns
        -------
        FourBar
            A valid instance of the family, the one the services that find the families use.
        """
        return cls(1.0, 3.0, 3.0, 4.0)

    crank: Length
    coupler: Length
    rocker: Length
    ground: Length
    assembly: Assembly = 1

    pivots = ("O", "E")
    output = "angle"

    def __post_init__(self):
        super().__post_init__()
        if not self.crank_ranges():
            a, c, r, g = self.crank, self.coupler, self.rocker, self.ground
            raise AssemblyError(
                f"the four-bar cannot be assembled at any crank angle: |AE| ranges over "
                f"[|ground - crank|, ground + crank] = [{abs(g - a):.4g}, {g + a:.4g}], "
                f"which misses the open interval [|coupler - rocker|, coupler + rocker] = "
                f"[{abs(c - r):.4g}, {c + r:.4g}]")

    # -- structure ------------------------------------------------------------------
    def grashof(self) -> Grashof:
        """Grashof's classification with respect to the crank (input) link.

        Returns
        -------
        Grashof
            The kind of linkage, the sorted lengths s, l, p, q and the shortest link's name.

        Examples
        --------
        >>> from mechlab import FourBar
        >>> str(FourBar(3, 2, 4, 4).grashof())
        'double-rocker (s + l = 6.00 < p + q = 7.00, shortest link: coupler = 2)'
        """
        named = {"crank": self.crank, "coupler": self.coupler, "rocker": self.rocker, "ground": self.ground}
        order = sorted(named, key=named.get)
        s, p, q, l = (named[k] for k in order)
        lhs, rhs = s + l, p + q
        shortest = order[0]
        if abs(lhs - rhs) <= _CHANGE_POINT_TOL * rhs:
            kind = "change-point"
        elif lhs > rhs:
            kind = "triple-rocker"
        else:
            kind = {"ground": "double-crank", "crank": "crank-rocker",
                    "rocker": "rocker-crank", "coupler": "double-rocker"}[shortest]
        return Grashof(kind, s, l, p, q, shortest)

    def extremes(self) -> Extremes:
        """The rocker's limit positions, its swing and the time ratio of a crank-rocker.

        B is at a limit when O, A, B lie in line: |OB| = coupler + crank (extended) or coupler - crank
        (folded), and |EB| = rocker (the law of cosines in triangle O-B-E).

        Returns
        -------
        Extremes
            Crank angles and rocker angles of both limits (radians), the swing and the time ratio.

        Raises
        ------
        RotationError
            Unless the linkage is a crank-rocker.

        Examples
        --------
        >>> from mechlab import FourBar
        >>> round(FourBar(1, 3, 3.5, 4).extremes().time_ratio, 6)
        1.106982
        """
        kind = self.grashof().kind
        if kind != "crank-rocker":
            raise RotationError(f"limit positions and a time ratio belong to a crank-rocker (a turning crank, a "
                                f"rocking output); this four-bar is a {kind}: {self.grashof().inequality}")
        a, c, r, g = self.crank, self.coupler, self.rocker, self.ground
        return limit_positions(self, "B", circle_pair(c + a, (g, 0.0), r), circle_pair(c - a, (g, 0.0), r))

    def crank_ranges(self):
        # |AE|² = a² + g² - 2ag·cos φ must lie strictly between (c - r)² and (c + r)².
        a, c, r, g = self.crank, self.coupler, self.rocker, self.ground
        return arc_set((a * a + g * g - (c + r) ** 2) / (2 * a * g),
                       (a * a + g * g - (c - r) ** 2) / (2 * a * g))

    def rotation_failure(self) -> str:
        info = self.grashof()
        if info.kind == "change-point":
            why = f"{info.inequality} (Grashof: a change-point linkage folds flat at a dead point)"
        elif info.kind == "triple-rocker":
            why = f"{info.inequality} (non-Grashof, a triple-rocker: no link turns fully)"
        else:
            why = (f"{info.inequality} (Grashof), but the shortest link is the {info.shortest} "
                   f"({info.s:g}), not the crank or the ground")
        return f"crank cannot turn fully: {why}; it reaches only φ ∈ {fmt_ranges(self.crank_ranges())}"

    def assembly_failure(self, phi: float) -> str:
        a, c, r, g = self.crank, self.coupler, self.rocker, self.ground
        d = float(np.sqrt(a * a + g * g - 2 * a * g * np.cos(phi)))
        if d >= c + r:
            return f"|AE| = {d:.4g} ≥ coupler + rocker = {c + r:.4g}"
        return f"|AE| = {d:.4g} ≤ |coupler - rocker| = {abs(c - r):.4g}"

    def structure(self) -> Structure:
        """Crank O→A, coupler A→B, rocker E→B; revolute pairs O, A, B, E; one RRR group.

        Returns
        -------
        Structure
            Links, pairs and structural groups, from which the drawing, centres, force model and counts derive.

        Examples
        --------
        >>> from mechlab import FourBar
        >>> FourBar(1, 3, 3.5, 4).structure().numbers()
        {'crank': 1, 'coupler': 2, 'rocker': 3, 'frame': 4}
        """
        return Structure(
            (Link("crank", "O", ("O", "A"), self.crank, joints=("O", "A")),
             Link("coupler", "A", ("A", "B"), self.coupler, joints=("A", "B")),
             Link("rocker", "E", ("E", "B"), self.rocker, joints=("B", "E"))),
            (Pair("revolute", "O", FRAME, "crank", "O"), Pair("revolute", "A", "crank", "coupler", "A"),
             Pair("revolute", "B", "coupler", "rocker", "B"), Pair("revolute", "E", FRAME, "rocker", "E")),
            (("coupler", "rocker"),), "rocker", scale=max(self.crank, self.coupler, self.rocker, self.ground))

    def curved_slot_twin(self):
        """Zinchenko et al. (2013) Fig. 2: a link pivoted at E whose slot is the circle of radius l_AB about B.

        The arc is chosen by the assembly; the twin is in Zinchenko et al.'s (2013) frame (crank angle φ − π).
        Kept over the default (the same slot, sampled from the motion) for its closed form and for a crank that
        only rocks.

        Returns
        -------
        tuple of (Mechanism, float)
            The curved-slot twin and the crank-angle shift ``phase`` (radians) from this mechanism's frame to it.

        Examples
        --------
        >>> from mechlab import FourBar
        >>> twin, phase = FourBar(1, 3, 3.5, 4).curved_slot_twin()
        >>> type(twin).__name__, round(phase, 4)
        ('CurvedSlotLink', 3.1416)
        """
        slot = CircleSlot((self.rocker, 0.0), self.coupler)
        return CurvedSlotLink(self.crank, self.ground, slot, start=self.assembly * np.pi / 2), np.pi

    # -- kinematics -------------------------------------------------------------------
    @cached_property
    def _psi_reference(self):
        return branch_references(self.crank_ranges(), self._raw_psi)

    def _raw_psi(self, phi):
        A = crank_point(self.crank, phi).p
        E = fixed_point((self.ground, 0.0), len(phi)).p
        B = circle_circle(A, self.coupler, E, self.rocker, self.assembly)
        return np.arctan2(B[:, 1], B[:, 0] - self.ground)

    def motion(self, phi) -> AngularMotion:
        """Joint paths of O, A, B, E and the output law ψ, ψ', ψ'' at crank angles φ.

        Parameters
        ----------
        phi : float or array_like
            Crank angles φ (radians); a scalar gives a motion of scalars.

        Returns
        -------
        AngularMotion
            Joint paths and the output angle ψ with ψ', ψ''.

        Raises
        ------
        DimensionError
            If φ is not a finite real number or array.
        AssemblyError
            Where the loop cannot close (the message names the reachable range).

        Examples
        --------
        >>> from mechlab import FourBar
        >>> FourBar(1, 3, 3.5, 4).motion(0.3).output
        Law(ψ = 2.10358 rad = 120.526°, ψ′ = -0.256937, ψ″ = 0.348417)
        """
        phi = as_angles(phi)
        self.check_reachable(phi)
        n = len(phi)
        A = crank_point(self.crank, phi)
        refs = self._psi_reference
        (_, _, mid, turns), = refs if len(refs) == 1 else ((0, 0, 0.0, 0),)
        B, psi = rocker_dyad(A, (self.ground, 0.0), self.coupler, self.rocker, self.assembly, phi,
                             "the coupler-rocker dyad", reference=mid + turns * phi if turns else mid)
        theta = psi.theta if len(refs) == 1 else lift_on_ranges(psi.theta, phi, refs)
        points = {"O": fixed_point((0.0, 0.0), n), "A": A, "B": B, "E": fixed_point((self.ground, 0.0), n)}
        return AngularMotion(phi, points, self._transmission, theta, psi.d, psi.dd)

    def _transmission(self, motion) -> np.ndarray:
        """Transmission angle μ at B between B→A and B→E, from cos μ = (BA·BE)/(l_AB·l_BE)."""
        zb = as_complex(motion.points["B"].p)
        cos_mu = _re_conj(zb - as_complex(motion.points["A"].p), zb - self.ground) / (self.coupler * self.rocker)
        return np.arccos(np.clip(cos_mu, -1.0, 1.0))
