"""Exercises of notebook 02_base_mechanism (seed 000 §2, formulas (12)-(20), Tables 1-2)."""

import numpy as np

from ...analysis.half_turn import base_peaks, formula_18
from . import exercise

exercise(
    "02.1",
    "Peak |ψ′_K| of the base mechanism with λ = 0.4 (the lower bound of every linkage with this λ).",
    lambda: base_peaks(0.4)[0],
    hint="Formula (19) at φ = π.",
)

exercise(
    "02.2",
    "Peak |ψ″_K| of the base mechanism with λ = 0.4.",
    lambda: base_peaks(0.4)[1],
    rtol=1e-6,
    hint="Differentiate (20) and solve the quadratic in cos φ: 2λc² - (1 + λ²)c - 4λ = 0.",
)

exercise(
    "02.3",
    "A curved-slot link with λ = 0.3 has ψ′(40°) = 0.35. What is ψ′(320°)? (Table 2, corrected.)",
    lambda: float(2 * formula_18(0.3, np.radians(40.0)).d - 0.35),
    rtol=1e-6,
    hint="ψ′(φ) + ψ′(2π - φ) = 2ψ′_K(φ).",
)
