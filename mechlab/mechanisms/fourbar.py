"""The four-bar linkage O-A-B-E in both assemblies.

Frame: crank pivot O at the origin, output pivot E at (ground, 0). The crank angle φ
and the output angle ψ (of the rocker E→B) are measured counter-clockwise from the
ray O→E. Lengths are dimensionless or in mm, as long as they agree.

Assembly (seed 000, §1, the text after Fig. 6): ``assembly = +1`` is kc = +1, the
points A, B, E traversed clockwise, i.e. B lies on the left of the directed line
A→E (above the frame line in the usual drawing of a crank-rocker); ``assembly = -1``
(kc = -1) is the other, counter-clockwise assembly. The two are mirror images:
``FourBar(..., -1).motion(phi)`` equals ``FourBar(..., +1).motion(-phi)`` reflected
in the frame line, so ψ₋(φ) = -ψ₊(-φ), ψ'₋(φ) = ψ'₊(-φ), ψ''₋(φ) = -ψ''₊(-φ).
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property
from typing import NamedTuple

import numpy as np

from ..errors import AssemblyError
from ..geometry import _re_conj, as_angles, as_complex, check_length, check_sign, circle_circle, crank_point, fixed_point, rocker_dyad
from ..motion import AngularMotion
from .base import Mechanism, arc_set, branch_references, fmt_ranges, lift_on_ranges

# Relative tolerance for Grashof's equality s + l = p + q (a change-point linkage).
_CHANGE_POINT_TOL = 1e-12


class Grashof(NamedTuple):
    """Grashof classification of a four-bar with the numbers behind it."""

    kind: str            # crank-rocker, double-crank, rocker-crank, double-rocker, change-point, triple-rocker
    s: float             # shortest link
    l: float             # longest link
    p: float             # the other two
    q: float
    shortest: str        # name of the shortest link

    @property
    def inequality(self) -> str:
        lhs, rhs = self.s + self.l, self.p + self.q
        if abs(lhs - rhs) <= _CHANGE_POINT_TOL * rhs:
            rel = "="
        else:
            rel = "<" if lhs < rhs else ">"
        return f"s + l = {lhs:.2f} {rel} p + q = {rhs:.2f}"

    def __str__(self) -> str:
        return f"{self.kind} ({self.inequality}, shortest link: {self.shortest} = {self.s:g})"


@dataclass(frozen=True)
class FourBar(Mechanism):
    """Crank O-A, coupler A-B, rocker B-E, frame O-E; output ψ = angle of E→B.

    Raises DimensionError for a length that is not positive and finite,
    AssemblyError if the linkage closes at no crank angle.
    """

    crank: float
    coupler: float
    rocker: float
    ground: float
    assembly: int = 1

    links = (("O", "A"), ("A", "B"), ("B", "E"))
    pivots = ("O", "E")
    output = "angle"

    def __post_init__(self):
        for name in ("crank", "coupler", "rocker", "ground"):
            object.__setattr__(self, name, check_length(name, getattr(self, name)))
        object.__setattr__(self, "assembly", check_sign("assembly", self.assembly))
        if not self.crank_ranges():
            a, c, r, g = self.crank, self.coupler, self.rocker, self.ground
            raise AssemblyError(
                f"the four-bar cannot be assembled at any crank angle: |AE| ranges over "
                f"[|ground - crank|, ground + crank] = [{abs(g - a):.4g}, {g + a:.4g}], "
                f"which misses the open interval [|coupler - rocker|, coupler + rocker] = "
                f"[{abs(c - r):.4g}, {c + r:.4g}]")

    # -- structure ------------------------------------------------------------------
    def grashof(self) -> Grashof:
        """Grashof's classification with respect to the crank (input) link."""
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
            why = f"{info.inequality} (Grashof: no link turns fully)"
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
        """Joint paths of O, A, B, E and the output law ψ, ψ', ψ'' at crank angles φ (rad).

        Raises AssemblyError (with the reachable range) where the loop cannot close.
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
