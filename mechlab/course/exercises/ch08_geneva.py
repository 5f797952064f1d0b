"""Exercises of notebook 08_geneva (planar and spherical Geneva drives)."""

import numpy as np

from ...mechanisms.geneva import ExternalGeneva, InternalGeneva
from ...mechanisms.spherical_geneva import SphericalGeneva
from . import exercise

exercise(
    "08.1",
    "Crank radius a (mm) of an external Geneva drive with z = 6 slots and centre distance C = 120 mm (radial entry).",
    lambda: ExternalGeneva(6, 120.0).crank_radius,
    rtol=1e-4, unit="mm",
    hint="At entry the crank O-A is perpendicular to the slot W-A: a right triangle with the angle π/z at W.",
)

exercise(
    "08.2",
    "Dwell fraction (share of the crank turn with the wheel locked) of an external Geneva with z = 5; "
    "and of an internal one with z = 5. Answer as a pair (external, internal).",
    lambda: (ExternalGeneva(5, 1.0).dwell_fraction, InternalGeneva(5, 1.0).dwell_fraction),
    rtol=1e-4,
    hint="The pin is in a slot while the crank turns through π - 2π/z (external) or π + 2π/z (internal).",
)

exercise(
    "08.3",
    "Largest angular velocity (rad/s) of the wheel of ExternalGeneva(z=6, C=100) when the crank turns at 10 rad/s.",
    lambda: float(ExternalGeneva(6, 100.0).max_velocity() * 10.0),
    rtol=1e-4, unit="rad/s",
    hint="On the line of centres the pin is C - a from W: ψ' = a/(C - a) = λ/(1 - λ), λ = sin(π/z).",
)

exercise(
    "08.4",
    "Crank angle α0 (degrees) at which the pin enters a slot of the spherical Geneva with R = 50 mm, e = 20 mm, z = 6.",
    lambda: float(np.degrees(SphericalGeneva(50.0, 20.0, 6).alpha0)),
    rtol=1e-4, unit="deg",
    hint="ρ0 = sqrt(e² + R² sin²(π/z)) and cos α0 = e/ρ0 (Vainer & Shatokhina, formulas (1)-(2)).",
)

exercise(
    "08.5",
    "Angular velocity analog ψ' of the wheel of SphericalGeneva(R=40, e=15, z=4) just after the pin enters the slot.",
    lambda: SphericalGeneva(40.0, 15.0, 4).entry_velocity(),
    rtol=1e-4,
    hint="tan β = tan ψ sin α: differentiate and evaluate at α = α0.",
)

exercise(
    "08.6",
    "Kind of impact ('hard', 'soft' or 'none') at the start of the wheel's motion of the spherical Geneva "
    "without offset, SphericalGeneva(R=40, e=0, z=4).",
    lambda: SphericalGeneva(40.0, 0.0, 4).impacts().kind,
    hint="With e = 0, α0 = 90°: is ψ' zero at entry? Is ψ''?",
)
