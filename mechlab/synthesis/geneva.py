"""Design tables of the spherical Geneva drive (Vainer & Shatokhina, Table 1).
"""

from __future__ import annotations

from dataclasses import dataclass, field, fields
from typing import Annotated

import numpy as np

from ..mechanisms.spherical_geneva import SphericalGeneva
from ..motion import Table
from ..validate import Spec, validated


@dataclass(frozen=True)
class SphericalRow:
    """One row of Table 1 (Vainer & Shatokhina): angles in degrees, ω_max/ω1 and |ε|max/ω1²."""

    z: int
    alpha0: float = field(metadata={"label": "α0, °"})
    beta0: float = field(metadata={"label": "β0, °"})
    omega_max: float = field(metadata={"label": "ω_max/ω1"})
    eps_max: float = field(metadata={"label": "|ε|max/ω1²"})
    alpha1: float = field(metadata={"label": "α1, °"})
    beta1: float = field(metadata={"label": "β1, °"})


@validated
def spherical_table(R: float, e: float, z_values: Annotated[np.ndarray, Spec("samples", lo=1)],
                    pin_diameter: float = 10.0) -> Table:
    """Table 1 of Vainer & Shatokhina, recomputed: per z, α0 and β0 (deg), ω_max/ω1, the largest
    |ε|/ω1² while the wheel moves (|α| ≤ α0), and α1, β1 (deg) where it is reached.

    Parameters
    ----------
    R : float
        Sphere radius (mm).
    e : float
        Offset (mm), 0 ≤ e < R.
    z_values : array_like of int
        Slot counts, each ≥ 3.
    pin_diameter : float
        Pin diameter (mm), default 10.

    Returns
    -------
    Table
        One ``SphericalRow`` per z.

    Raises
    ------
    SlotCountError
        A z that is not a whole number ≥ 3.
    OffsetError
        ``e`` outside [0, R).
    DimensionError
        ``R`` or ``pin_diameter`` not a positive length, or ``z_values`` empty.

    Examples
    --------
    >>> import mechlab as ml
    >>> row = list(ml.spherical_table(40.0, 15.0, [4]))[0]
    >>> round(row.alpha0, 2), round(row.omega_max, 2)
    (62.06, 1.13)
    """
    rows = []
    for z in z_values:
        g = SphericalGeneva(R, e, z, pin_diameter)
        eps, al = g.max_acceleration()
        rows.append(SphericalRow(g.z, float(np.degrees(g.alpha0)), float(np.degrees(g.beta0)), g.max_velocity(),
                                 eps, float(np.degrees(al)), float(np.degrees(g.position(al).theta))))
    return Table(rows)


# Vainer & Shatokhina, Table 1 as printed (R = 40 mm, e = 15 mm, d = 10 mm).
TABLE1_PRINTED = Table(SphericalRow(*row) for row in (
    (3, 66.60, 60.0, 1.89, 2.51, 16.40, 27.80),
    (4, 62.06, 45.0, 1.13, 1.06, 27.26, 27.56),
    (5, 57.46, 36.0, 0.86, 0.71, 34.96, 26.22),
    (6, 53.15, 30.0, 0.72, 0.57, 41.60, 25.38),
    (8, 45.58, 22.5, 0.58, 0.46, 52.93, 24.85),
))


TABLE1_COLUMNS = tuple(f.name for f in fields(SphericalRow) if f.name != "z")


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
    against :func:`spherical_table`.

    Parameters
    ----------
    R : float
        Sphere radius (mm), default 40 (the printed table's).
    e : float
        Offset (mm), default 15.

    Returns
    -------
    Table
        One ``Cell`` per (z, column): printed, computed and "agrees", "last digit" or "differs".

    Raises
    ------
    OffsetError
        ``e`` outside [0, R).
    DimensionError
        ``R`` is not a positive length.

    Examples
    --------
    >>> import mechlab as ml
    >>> cells = ml.table1_comparison()
    >>> len(cells), sum(cell.agrees for cell in cells)
    (30, 15)
    """
    rows = spherical_table(R, e, TABLE1_PRINTED.column("z")).by("z")
    out = []
    for printed in TABLE1_PRINTED:
        z = printed.z
        for col in TABLE1_COLUMNS:
            p, c = getattr(printed, col), float(getattr(rows[z], col))
            diff = abs(p - c)
            status = "agrees" if diff <= 0.005 + 1e-12 else "last digit" if diff <= 0.015 else "differs"
            out.append(Cell(z, col, p, c, status))
    return Table(out)



_MARK = {"agrees": "", "last digit": " ·", "differs": " ✗"}


def _labelled_as_table1(name: str):
    """A field with the label (and so the units) of :class:`SphericalRow`'s column ``name``."""
    return field(metadata=SphericalRow.__dataclass_fields__[name].metadata)


@dataclass(frozen=True)
class ReviewRow:
    """One z of Table 1 (Vainer & Shatokhina), each cell "printed / computed" and marked
    "·" (last digit) or "✗" (differs); the columns carry :class:`SphericalRow`'s units."""

    z: int
    alpha0: str = _labelled_as_table1("alpha0")
    beta0: str = _labelled_as_table1("beta0")
    omega_max: str = _labelled_as_table1("omega_max")
    eps_max: str = _labelled_as_table1("eps_max")
    alpha1: str = _labelled_as_table1("alpha1")
    beta1: str = _labelled_as_table1("beta1")


def table1_review(comparison: Table | None = None) -> Table:
    """Table 1 as the reader checks it: per z, every cell as "printed / computed", marked.

    Parameters
    ----------
    comparison : Table, optional
        The cells of :func:`table1_comparison`; by default computed for R = 40 mm, e = 15 mm.

    Returns
    -------
    Table
        One ``ReviewRow`` per z; a cell is marked "·" (last digit) or "✗" (differs).

    Examples
    --------
    >>> import mechlab as ml
    >>> list(ml.table1_review())[1].alpha0
    '62.06 / 62.06'
    """
    cells = {(c.z, c.column): c for c in (table1_comparison() if comparison is None else comparison)}
    return Table(ReviewRow(z, *(f"{cells[z, col].printed:.2f} / {cells[z, col].computed:.2f}"
                                f"{_MARK[cells[z, col].status]}" for col in TABLE1_COLUMNS))
                 for z in sorted({z for z, _ in cells}))
