"""Exercises of notebook 05_dwell_curved_slot (dwell synthesis with a curved slot, seed 000 §3)."""

import numpy as np

from ...synthesis.dwell_slot import curved_slot_dwell, two_branch_slot
from . import exercise

_D = np.radians

exercise(
    "05.1",
    "The link's dwell angle ψ_B, in degrees, of the cubic design with λ = 0.4 and dwell [70°, 140°] "
    "(link frame chosen so that ψ(0) = 0).",
    lambda: float(np.degrees(curved_slot_dwell(0.4, _D(70), _D(140)).motion(_D(105)).psi)),
    rtol=1e-6, unit="deg",
    hint="From (21) and (24): ψ(0) = ψ_B + a1·φ1³ = 0 with a1 = -λ/(3(λ+1)φ1²) — mind the sign.",
)

exercise(
    "05.2",
    "Pressure angle, in degrees, at the start of the dwell (φ = φ1 = 70°) of the design λ = 0.4, [70°, 140°].",
    lambda: float(np.degrees(curved_slot_dwell(0.4, _D(70), _D(140)).motion(_D(70)).pressure_angle)),
    rtol=1e-6, unit="deg",
    hint="On the dwell arc the pin pushes along OA; the link point moves perpendicular to BA: "
         "θ = |90° - (φ - ψ_K(φ))| with tan ψ_K = λ sin φ/(1 + λ cos φ).",
)

exercise(
    "05.3",
    "Two-branch slot with λ = 0.6 (dwell from φ1 = 0): the jump ψ'(0-) - ψ'(0+) of the velocity analog when the "
    "pin comes back along the branch it arrived on.",
    lambda: float(two_branch_slot(0.6, _D(100)).velocity_jump),
    rtol=1e-9,
    hint="Table 2: ψ'(-φ) = 2ψ_K'(φ) - ψ'(φ); on the dwell ψ'(0+) = 0, and ψ_K'(0) = λ/(λ+1).",
)
