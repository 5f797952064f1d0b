"""The result of ``mechanism.motion(phi)``: joint paths and the output law.

Analogs are derivatives with respect to the crank angle φ; physical values at a
crank speed ω1 and crank acceleration ε1 follow from the chain rule:
ω2 = ψ'·ω1 and ε2 = ψ''·ω1² + ψ'·ε1 (likewise v = s'·ω1, a = s''·ω1² + s'·ε1).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Callable, Mapping

import numpy as np

from .geometry import PointPath


@dataclass(frozen=True, eq=False)
class Motion:
    """Joint paths over the crank angles ``phi`` (radians).

    ``points`` maps joint names to :class:`~mechlab.geometry.PointPath` (positions
    and analogs, each ``(n, 2)``). ``transmission`` is the transmission angle μ in
    [0, π] at every φ (π/2 is ideal); ``pressure_angle`` is |π/2 - μ|. A mechanism may
    pass a function of the motion instead of the array: it is evaluated on first use.
    """

    phi: np.ndarray
    points: Mapping[str, PointPath]
    _transmission: np.ndarray | Callable[["Motion"], np.ndarray] = field(repr=False)

    @property
    def transmission(self) -> np.ndarray:
        if callable(self._transmission):
            object.__setattr__(self, "_transmission", self._transmission(self))
        return self._transmission

    @property
    def pressure_angle(self) -> np.ndarray:
        return np.abs(np.pi / 2 - self.transmission)

    def _law(self):
        raise NotImplementedError

    def velocity(self, omega1: float) -> np.ndarray:
        """Output velocity (rad/s or length/s) at crank speed ω1 (rad/s)."""
        return self._law()[1] * omega1

    def acceleration(self, omega1: float, eps1: float = 0.0) -> np.ndarray:
        """Output acceleration at crank speed ω1 and crank acceleration ε1."""
        _, d1, d2 = self._law()
        return d2 * omega1**2 + d1 * eps1

    def __len__(self) -> int:
        return len(self.phi)


@dataclass(frozen=True, eq=False)
class AngularMotion(Motion):
    """Motion whose output is an angle ψ (radians) with analogs ψ' and ψ''."""

    psi: np.ndarray
    dpsi: np.ndarray
    ddpsi: np.ndarray

    def _law(self):
        return self.psi, self.dpsi, self.ddpsi


@dataclass(frozen=True, eq=False)
class LinearMotion(Motion):
    """Motion whose output is a displacement s (length) with analogs s' and s''."""

    s: np.ndarray
    ds: np.ndarray
    dds: np.ndarray

    def _law(self):
        return self.s, self.ds, self.dds
