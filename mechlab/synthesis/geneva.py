"""Design tables of the spherical Geneva drive (Vainer & Shatokhina, Table 1).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Annotated

import numpy as np

from ..mechanisms.spherical_geneva import SphericalGeneva
from ..motion import Table
from ..validate import Spec, validated


@dataclass(frozen=True)
class SphericalRow:
    """One row of Table 1 (Vainer & Shatokhina): angles in degrees, ω_max/ω1 and |ε|max/ω1²."""

    z: int
    alpha0: float
    beta0: float
    omega_max: float
    eps_max: float
    alpha1: float
    beta1: float


@validated
def spherical_table(R: float, e: float, z_values: Annotated[np.ndarray, Spec("samples", lo=1)],
                    pin_diameter: float = 10.0) -> Table:
    """Table 1 of Vainer & Shatokhina, recomputed: per z, α0 and β0 (deg), ω_max/ω1, the largest
    |ε|/ω1² while the wheel moves (|α| ≤ α0), and α1, β1 (deg) where it is reached."""
    rows = []
    for z in z_values:
        g = SphericalGeneva(R, e, z, pin_diameter)
        eps, al = g.max_acceleration()
        rows.append(SphericalRow(g.z, float(np.degrees(g.alpha0)), float(np.degrees(g.beta0)), g.max_velocity(),
                                 eps, float(np.degrees(al)), float(np.degrees(g.position(al).theta))))
    return Table(rows)


# Vainer & Shatokhina, Table 1 as printed (R = 40 mm, e = 15 mm, d = 10 mm).
TABLE1_PRINTED = {
    3: {"alpha0": 66.60, "beta0": 60.0, "omega_max": 1.89, "eps_max": 2.51, "alpha1": 16.40, "beta1": 27.80},
    4: {"alpha0": 62.06, "beta0": 45.0, "omega_max": 1.13, "eps_max": 1.06, "alpha1": 27.26, "beta1": 27.56},
    5: {"alpha0": 57.46, "beta0": 36.0, "omega_max": 0.86, "eps_max": 0.71, "alpha1": 34.96, "beta1": 26.22},
    6: {"alpha0": 53.15, "beta0": 30.0, "omega_max": 0.72, "eps_max": 0.57, "alpha1": 41.60, "beta1": 25.38},
    8: {"alpha0": 45.58, "beta0": 22.5, "omega_max": 0.58, "eps_max": 0.46, "alpha1": 52.93, "beta1": 24.85},
}


TABLE1_COLUMNS = ("alpha0", "beta0", "omega_max", "eps_max", "alpha1", "beta1")


@dataclass(frozen=True)
class Cell:
    """One cell of Table 1: ``status`` is "agrees" (the computed value rounds to the
    printed one), "last digit" (off by at most 1.5 units of the printed last digit,
    0.01) or "differs"."""

    z: int
    column: str
    printed: float
    computed: float
    status: str

    @property
    def agrees(self) -> bool:
        return self.status == "agrees"


def table1_comparison(R: float = 40.0, e: float = 15.0) -> Table:
    """Every cell of Vainer & Shatokhina's Table 1 (:data:`TABLE1_PRINTED`, two decimals printed)
    against :func:`spherical_table`."""
    rows = spherical_table(R, e, sorted(TABLE1_PRINTED)).by("z")
    out = []
    for z, printed in TABLE1_PRINTED.items():
        for col in TABLE1_COLUMNS:
            p, c = printed[col], float(getattr(rows[z], col))
            diff = abs(p - c)
            status = "agrees" if diff <= 0.005 + 1e-12 else "last digit" if diff <= 0.015 else "differs"
            out.append(Cell(z, col, p, c, status))
    return Table(out)

