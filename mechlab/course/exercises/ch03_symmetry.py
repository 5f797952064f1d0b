"""Exercises of notebook 03_symmetry_of_assemblies (seed 000 §1, after Fig. 6)."""

import numpy as np

from ...analysis.equivalence import base_law
from ...mechanisms.fourbar import FourBar
from ...mechanisms.slider_crank import SliderCrank
from . import exercise

exercise(
    "03.1",
    "ψ′ of the kc = -1 assembly FourBar(1, 3, 3, 4, -1) at φ = 310°, computed from the kc = +1 assembly only "
    "(FourBar(1, 3, 3, 4, +1)).",
    lambda: float(FourBar(1.0, 3.0, 3.0, 4.0, -1).motion(np.radians(310.0)).dpsi),
    rtol=1e-6,
    hint="The two assemblies are mirror images in the frame line: ψ′₋(φ) = ψ′₊(-φ).",
)

exercise(
    "03.2",
    "(ψ″₊ + ψ″₋)/2 of FourBar(1, 3, 3, 4) at φ = 70°, both assemblies.",
    lambda: float(base_law(FourBar(1.0, 3.0, 3.0, 4.0), np.radians(70.0)).dd),
    rtol=1e-6,
    hint="The mean of the two assemblies is the base mechanism (λ = 1/4), seen from the four-bar's frame.",
)

exercise(
    "03.3",
    "s₊ + s₋ of SliderCrank(1, 3, offset=0.5) at φ = 30° (the two assemblies).",
    lambda: float(SliderCrank(1.0, 3.0, 0.5, 1).motion(np.radians(30.0)).s
                  + SliderCrank(1.0, 3.0, 0.5, -1).motion(np.radians(30.0)).s),
    hint="The two roots of the slider's quadratic add up to twice the sine mechanism's x_K.",
)
