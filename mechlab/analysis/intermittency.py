"""Intermittency of any output law: dwell fraction, impacts, and comparison of drives.
"""

from __future__ import annotations

import numpy as np
from ..mechanisms.geneva import TWO_PI


# ----------------------------------------------------------------------------------
# comparison of intermittent-motion mechanisms
# ----------------------------------------------------------------------------------
def _max_jump(mechanism, n: int, phase: float = 0.0):
    phi = phase + np.linspace(0.0, TWO_PI, n + 1)
    mo = mechanism.motion(phi)
    return float(np.max(np.abs(np.diff(mo.dpsi)))), float(np.max(np.abs(np.diff(mo.ddpsi))))


def detect_impacts(mechanism, n: int = 4096, phase: float = 0.0) -> str:
    """'hard', 'soft' or 'none', found numerically for any angular-output mechanism:
    the largest change of ψ' (ψ'') between neighbouring samples halves when the grid is
    refined if ψ' (ψ'') is continuous, and stays put where it jumps. The grid starts at
    ``phase`` (to avoid a crank angle where a mechanism cannot be evaluated)."""
    v1, a1 = _max_jump(mechanism, n, phase)
    v2, a2 = _max_jump(mechanism, 2 * n, phase)
    if v2 > 0.75 * v1 and v1 > 1e-12:
        return "hard"
    if a2 > 0.75 * a1 and a1 > 1e-12:
        return "soft"
    return "none"


def intermittency(mechanism, *, n: int = 7201, dwell_tol: float = 1e-9, phase: float = 0.0) -> dict:
    """Invariants of one crank turn: dwell fraction (share of φ with |ψ'| ≤ dwell_tol·max|ψ'|),
    output turn Δψ per crank turn, max |ψ'| and |ψ''|, and the dimensionless invariants
    C_v = max|ψ'|·Φ/|Δψ| and C_a = max|ψ''|·Φ²/|Δψ| with Φ = (1 - dwell)·2π the crank
    angle of the motion: the cam-law coefficients (cycloidal law: C_v = 2, C_a = 2π).
    An approximate dwell (a linkage's) needs a larger ``dwell_tol``; the samples start at
    ``phase``."""
    phi = phase + np.linspace(0.0, TWO_PI, n)
    mo = mechanism.motion(phi)
    vmax = float(np.max(np.abs(mo.dpsi)))
    still = np.abs(mo.dpsi) <= dwell_tol * vmax
    dwell = float(np.mean(still[:-1]))
    dpsi_turn = float(mo.psi[-1] - mo.psi[0])
    amax = float(np.max(np.abs(mo.ddpsi)))
    Phi = (1.0 - dwell) * TWO_PI
    return {"dwell_fraction": dwell, "index_deg": float(np.degrees(abs(dpsi_turn))), "max_dpsi": vmax,
            "max_ddpsi": amax, "Cv": vmax * Phi / abs(dpsi_turn), "Ca": amax * Phi**2 / abs(dpsi_turn),
            "impact": detect_impacts(mechanism, phase=phase)}


def compare(mechanisms: dict, **kw) -> list[dict]:
    """:func:`intermittency` of each named mechanism, one row each."""
    return [{"name": name, **intermittency(m, **kw)} for name, m in mechanisms.items()]

