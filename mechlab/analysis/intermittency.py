"""Intermittency of any output law: dwell fraction, impacts, and comparison of drives.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Annotated

import numpy as np

from ..errors import DimensionError
from ..mechanisms.base import Mechanism
from ..mechanisms.geneva import TWO_PI
from ..motion import STILL, Table
from ..validate import MAX_SAMPLES, Angle, check_value, count, number, validated
from ..validate import mechanism as mechanism_of
from .motion_laws import invariants


# ----------------------------------------------------------------------------------
# comparison of intermittent-motion mechanisms
# ----------------------------------------------------------------------------------
def _max_jump(mechanism, n: int, phase: float = 0.0):
    phi = phase + np.linspace(0.0, TWO_PI, n + 1)
    mo = mechanism.motion(phi)
    return float(np.max(np.abs(np.diff(mo.dpsi)))), float(np.max(np.abs(np.diff(mo.ddpsi))))


@validated
def detect_impacts(mechanism: Annotated[Mechanism, mechanism_of(Mechanism)],
                   n: Annotated[int, count(3, MAX_SAMPLES // 2)] = 4096, phase: Angle = 0.0) -> str:
    """The impacts of an angular output, found numerically: 'hard', 'soft' or 'none'.

    The largest change of ψ′ (ψ″) between neighbouring samples halves when the grid is
    refined if ψ′ (ψ″) is continuous, and stays put where it jumps.

    Parameters
    ----------
    mechanism : Mechanism
        A mechanism whose motion has an angular output (``dpsi``, ``ddpsi``).
    n : int
        Samples of the turn (the check also uses 2n); default 4096.
    phase : float
        Where the grid starts (rad), to avoid a crank angle where the mechanism cannot be evaluated.

    Returns
    -------
    str
        "hard" (ψ′ jumps), "soft" (ψ″ jumps) or "none".

    Raises
    ------
    TypeError
        ``mechanism`` is not a Mechanism.
    DimensionError
        ``n`` or ``phase`` out of range.

    Examples
    --------
    >>> import mechlab as ml
    >>> from mechlab.analysis.intermittency import detect_impacts
    >>> detect_impacts(ml.ExternalGeneva(4, 1.0))
    'soft'
    """
    v1, a1 = _max_jump(mechanism, n, phase)
    v2, a2 = _max_jump(mechanism, 2 * n, phase)
    if v2 > 0.75 * v1 and v1 > 1e-12:
        return "hard"
    if a2 > 0.75 * a1 and a1 > 1e-12:
        return "soft"
    return "none"


@dataclass(frozen=True)
class Intermittency:
    """The invariants of one crank turn (:func:`intermittency`); ``dwell_fraction`` is the share where the
    output stands exactly still (the course's one dwell), ``standstill_fraction`` the share where it stays
    within the tolerance asked for (a linkage's approximate dwell; equal to the dwell at the default);
    ``index_deg`` = |Δψ| in degrees; B, C, D are the motion-law invariants
    (:class:`~mechlab.analysis.motion_laws.Invariants`, the glossary's C_v, C_a, C_p) of the motion part of
    the turn, outside the near-standstill."""

    name: str
    dwell_fraction: float = field(metadata={"label": "dwell", "format": ".3f"})
    standstill_fraction: float = field(metadata={"label": "near-standstill", "format": ".3f"})
    index_deg: float = field(metadata={"label": "Δψ per turn, °", "format": ".0f"})
    max_dpsi: float = field(metadata={"label": "max ψ′", "format": ".3f"})
    max_ddpsi: float = field(metadata={"label": "max ψ″, 1/rad", "format": ".3f"})
    B: float = field(metadata={"label": "C_v", "format": ".3f"})
    C: float = field(metadata={"label": "C_a", "format": ".3f"})
    D: float = field(metadata={"label": "C_p", "format": ".3f"})
    impact: str = field(metadata={"label": "impact"})


# the default near-standstill tolerance is the exact dwell's own threshold (mechlab.motion.STILL)
DWELL_TOL = STILL
# a dwell tolerance: a share of the peak |ψ'|, in (0, 1)
DWELL_TOL_RANGE = number(0.0, 1.0, open=True)
DwellTol = Annotated[float, DWELL_TOL_RANGE]


@validated
def intermittency(mechanism: Annotated[Mechanism, mechanism_of(Mechanism)], *,
                  n: Annotated[int, count(3, MAX_SAMPLES // 2)] = 7201,
                  dwell_tol: DwellTol = DWELL_TOL, phase: Angle = 0.0,
                  name: str | None = None) -> Intermittency:
    """Invariants of one crank turn: dwell fraction (share of φ where the output stands still: |ψ'| within
    1e-9 of its peak, a numerical zero), near-standstill fraction (share with |ψ'| ≤ dwell_tol·max|ψ'|),
    output turn Δψ per crank turn, max |ψ'| and |ψ''|, and the motion-law invariants B, C, D
    (:func:`~mechlab.analysis.motion_laws.invariants`) with h = Δψ over Φ = (1 - near-standstill)·2π, the
    crank angle of the motion (cycloidal law: B = 2, C = 2π; Kinitsky, 1994, chapter 2).
    An approximate dwell (a linkage's) has no exact dwell and needs a larger ``dwell_tol`` (in (0, 1)) for
    its near-standstill.

    Parameters
    ----------
    mechanism : Mechanism
        A mechanism with an angular output that advances over a turn.
    n : int
        Samples of the turn (default 7201).
    dwell_tol : float
        Share of the peak |ψ′| in (0, 1) below which the output is nearly still (default 1e-9).
    phase : float
        Where the samples start (rad).
    name : str, optional
        Labels the row; by default the mechanism's class name.

    Returns
    -------
    Intermittency
        Dwell and near-standstill fractions, Δψ per turn (deg), max |ψ′| and |ψ″|, B, C, D and the impact.

    Raises
    ------
    TypeError
        ``mechanism`` is not a Mechanism.
    DimensionError
        The output is not an angle, it does not advance over a turn (a rocker: B undefined), or
        ``n``, ``dwell_tol`` or ``phase`` is out of range.

    Examples
    --------
    >>> import mechlab as ml
    >>> from mechlab.analysis.intermittency import intermittency
    >>> row = intermittency(ml.ExternalGeneva(4, 1.0))
    >>> round(row.dwell_fraction, 3), round(row.index_deg, 1), row.impact
    (0.75, 90.0, 'soft')
    """
    if mechanism.output != "angle":
        raise DimensionError(f"mechanism must have an angular output (ψ), got a {type(mechanism).__name__}")
    phi = phase + np.linspace(0.0, TWO_PI, n)
    mo = mechanism.motion(phi)
    vmax = float(np.max(np.abs(mo.dpsi)))
    speed = np.abs(mo.dpsi[:-1])
    dwell = float(np.mean(speed <= STILL * vmax))
    standstill = float(np.mean(speed <= max(dwell_tol, STILL) * vmax))
    dpsi_turn = float(mo.psi[-1] - mo.psi[0])
    if abs(dpsi_turn) <= 1e-9:
        raise DimensionError(f"the output does not advance over a crank turn (Δψ = {dpsi_turn:.3g} rad): "
                             f"B and C are defined for an indexing output, not a rocker")
    inv = invariants((1.0 - standstill) * TWO_PI, dpsi_turn, mo.dpsi, mo.ddpsi)
    return Intermittency(type(mechanism).__name__ if name is None else name, dwell, standstill,
                         float(np.degrees(abs(dpsi_turn))), vmax, float(np.max(np.abs(mo.ddpsi))), *inv.values,
                         detect_impacts(mechanism, phase=phase))


def compare(mechanisms: dict, *, dwell_tol: float | dict = DWELL_TOL, **kw) -> Table:
    """:func:`intermittency` of each named mechanism, one row each.

    Parameters
    ----------
    mechanisms : dict
        Name → mechanism; the name labels its row.
    dwell_tol : float or dict, optional
        The share of the peak |ψ'| below which the output counts as nearly still (the near-standstill
        column; the dwell column is always the exact standstill), in (0, 1): one for every mechanism, or a
        dict name → tolerance (a mechanism it does not name keeps the default 1e-9). A linkage's approximate
        dwell needs a larger one than a Geneva's exact dwell.
    **kw
        Passed on to :func:`intermittency` (``n``, ``phase``).

    Returns
    -------
    Table
        One :class:`Intermittency` per mechanism, in the dict's order.

    Raises
    ------
    TypeError
        ``mechanisms`` is not a dict, or one of its values is not a Mechanism.
    DimensionError
        ``dwell_tol`` names a mechanism not compared or lies outside (0, 1), or a mechanism's
        output does not advance over a turn.

    Examples
    --------
    >>> import mechlab as ml
    >>> from mechlab.analysis.intermittency import compare
    >>> table = compare({"Geneva 4": ml.ExternalGeneva(4, 1.0), "Geneva 6": ml.ExternalGeneva(6, 1.0)})
    >>> [round(row.dwell_fraction, 3) for row in table]
    [0.75, 0.667]
    """
    if not isinstance(mechanisms, dict):
        raise TypeError(f"mechanisms must be a dict of name → mechanism, got {type(mechanisms).__name__}")
    if isinstance(dwell_tol, dict):
        unknown = [repr(k) for k in dwell_tol if k not in mechanisms]
        if unknown:
            raise DimensionError(f"dwell_tol names no mechanism compared: {', '.join(unknown)} "
                                 f"(the mechanisms: {', '.join(map(repr, mechanisms))})")
        tols = {name: check_value(f"dwell_tol[{name!r}]", dwell_tol.get(name, DWELL_TOL), DWELL_TOL_RANGE)
                for name in mechanisms}
    else:
        tols = dict.fromkeys(mechanisms, check_value("dwell_tol", dwell_tol, DWELL_TOL_RANGE))
    return Table(intermittency(m, name=name, dwell_tol=tols[name], **kw) for name, m in mechanisms.items())

