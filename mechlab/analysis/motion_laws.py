"""Classic cam motion laws over a rise and their dimensionless invariants (Kinitsky, 1994, chapter 2 table).

A rise law is written on the normalised time x ∈ [0, 1] (crank angle over the rise / its
duration Φ) with the normalised stroke y ∈ [0, 1] (output displacement / stroke h).
Kinitsky (1994) compares linkages with cams by three invariants of the rise:

* B = max |y'| — velocity, the physical peak is B·h·ω/Φ;
* C = max |y''| — acceleration, the peak is C·h·ω²/Φ²;
* D = max |y'·y''| — "kinetic power" (velocity × acceleration), the peak of the inertia
  power is D·J·h²·ω³/Φ³.

C and D are **absolute** extremes by default: the thesis' МЧВ1 rows are reproduced only with
them. ``signed=True`` gives the signed maxima max y'' and max y'y'' instead (the driving phase
only). They differ where the law is not odd about mid-rise: for the double harmonic law
D = 9.8948 (absolute) against 7.7516 (signed), and the thesis prints 7.00, neither.

:func:`invariants` (:func:`rise_invariants` over one sampled rise) measures the same numbers on any
output law ψ(φ) sampled by a mechanism, so linkages and cams go in one table. Norton (*Design of
Machinery*, ch. 8) calls B, C the factors C_v, C_a; the jerk factor C_j = max |y‴| is :func:`law_jerk`.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from typing import Annotated, Any

import numpy as np
from scipy.optimize import minimize_scalar

from ..errors import DimensionError, MechanismError
from ..motion import Table
from ..validate import (
    MAX_SAMPLES,
    Checked,
    Flag,
    Function,
    Name,
    Real,
    Spec,
    check_value,
    choice,
    count,
    number,
    validated,
)

OptionalFunction = Annotated[Any, Spec("function", optional=True)]
Sampled = Annotated[np.ndarray, Spec("samples", lo=2, hi=MAX_SAMPLES)]  # one value a crank angle
Analogs = Annotated[np.ndarray, Spec("samples", lo=1, hi=MAX_SAMPLES)]

__all__ = [
    "ALIASES",
    "LAWS",
    "Invariants",
    "LawRow",
    "PrintedInvariants",
    "RiseLaw",
    "invariants",
    "law_invariants",
    "law_jerk",
    "law_table",
    "named_law",
    "rise_invariants",
    "thesis_cam_rows",
    "thesis_mchv1_rows",
]


@dataclass(frozen=True)
class Invariants:
    """The rise's invariants B (velocity), C (acceleration) and D (kinetic power)."""

    B: float
    C: float
    D: float

    def __post_init__(self):
        for name in ("B", "C", "D"):
            object.__setattr__(self, name, float(getattr(self, name)))

    @property
    def values(self) -> tuple[float, float, float]:
        """(B, C, D)."""
        return self.B, self.C, self.D

    def __repr__(self):
        return f"Invariants(B={self.B:.4f}, C={self.C:.4f}, D={self.D:.4f})"


@dataclass(frozen=True)
class RiseLaw(Checked):
    """A rise law y(x) with y'(x), y''(x) (vectorised) and its closed-form invariants
    (B, C, D, and optionally C_j = max|y‴|; None where no closed form is known).

    ``dddy`` is the jerk analog y‴(x) between the points where y'' jumps (None: not given);
    calling the law gives (y, y', y''), :meth:`jerk` gives y‴. ``knots``: the x in (0, 1) where the
    law changes its formula (a derivative jumps there); a cam's profile is splined piecewise between them.
    """

    name: Name
    y: Function
    dy: Function
    ddy: Function
    closed: tuple
    dddy: OptionalFunction = None
    knots: tuple = ()

    def __post_init__(self):
        super().__post_init__()
        if isinstance(self.knots, str) or np.ndim(self.knots) != 1:
            raise DimensionError(f"knots must be a sequence of x in (0, 1), got {self.knots!r:.60}")
        object.__setattr__(self, "knots", tuple(check_value(f"knots[{i}]", v, number(0.0, 1.0, open=True))
                                                for i, v in enumerate(self.knots)))
        if isinstance(self.closed, str) or np.ndim(self.closed) != 1 or len(self.closed) not in (3, 4):
            raise DimensionError(f"closed must be the closed forms (B, C, D) or (B, C, D, C_j), "
                                 f"got {self.closed!r:.60}")
        object.__setattr__(self, "closed", tuple(None if v is None else check_value(f"closed[{i}]", v, number())
                                                 for i, v in enumerate(self.closed)))

    def __call__(self, x):
        x = np.asarray(x, dtype=float)
        return self.y(x), self.dy(x), self.ddy(x)

    def jerk(self, x):
        """y‴(x), the jerk analog (between jumps of y''); MechanismError if the law does not give it."""
        if self.dddy is None:
            raise MechanismError(f"law {self.name!r} gives no jerk analog (dddy)")
        x = np.asarray(x, dtype=float)
        return np.broadcast_to(np.asarray(self.dddy(x), dtype=float), x.shape) + 0.0


PI = np.pi
_S3 = np.sqrt(3.0)


def _piecewise(x, lo, hi):
    return np.where(x < 0.5, lo(x), hi(x))


def _dh_dd_max():
    # double harmonic: y'y'' = (π³/4)(sin πx − ½ sin 2πx)(cos πx − cos 2πx); its largest magnitude is
    # in the deceleration (x > 2/3, where y'' < 0), found by a bounded search on [2/3, 1]
    def f(x):
        return (PI**3 / 4) * (np.sin(PI * x) - 0.5 * np.sin(2 * PI * x)) * (np.cos(PI * x) - np.cos(2 * PI * x))
    return -minimize_scalar(f, bounds=(2 / 3, 1.0), method="bounded", options=dict(xatol=1e-12)).fun


# -- the two laws built from sine and constant pieces of acceleration (Norton, Design of Machinery, ch. 8) --
# Both start with y'' = C sin 4πx on [0, 1/8] and are odd about mid-rise, y(x) = 1 − y(1 − x): the rise
# is written on its first half u ∈ [0, ½] as (y, y', y'', y‴) and mirrored by _odd. C follows from y(½) = ½.
_W = 4 * PI
_C_MT = 8 * PI / (PI + 2)          # modified trapezoid: y(½) = C(π + 2)/(16π)
_C_MS = 4 * PI**2 / (PI + 4)       # modified sine: y(½) = C(π + 4)/(8π²)
_W_MS = 4 * PI / 3                 # the modified sine's second quarter-wave spans [1/8, 1/2]


def _sine_start(u, C):
    """y, y', y'', y‴ of the first piece y'' = C sin 4πu, u ∈ [0, 1/8]."""
    s, c = np.sin(_W * u), np.cos(_W * u)
    return C / _W * (u - s / _W), C / _W * (1 - c), C * s, C * _W * c


def _trapezoid_half(u):
    C = _C_MT
    y1 = C / _W * (1 / 8 - 1 / _W)                       # y at u = 1/8
    v2, y2 = C / _W + C / 4, y1 + C / (4 * _W) + C / 32   # y', y at u = 3/8
    t, r = u - 1 / 8, u - 3 / 8
    s, c = np.sin(_W * r), np.cos(_W * r)
    flat = (y1 + C / _W * t + C * t**2 / 2, C / _W + C * t, C + 0 * u, 0 * u)
    fall = (y2 + v2 * r + C / _W**2 * (1 - c), v2 + C / _W * s, C * c, -C * _W * s)
    return [np.select([u <= 1 / 8, u <= 3 / 8], [a, b], f)
            for a, b, f in zip(_sine_start(u, C), flat, fall, strict=False)]


def _sine_half(u):
    C = _C_MS
    y1 = C / _W * (1 / 8 - 1 / _W)
    t = u - 1 / 8
    s, c = np.sin(_W_MS * t), np.cos(_W_MS * t)
    fall = (y1 + C / _W * t + C / _W_MS**2 * (1 - c), C / _W + C / _W_MS * s, C * c, -C * _W_MS * s)
    return [np.where(u <= 1 / 8, a, f) for a, f in zip(_sine_start(u, C), fall, strict=False)]


def _odd(half, k):
    """The k-th derivative of the rise whose first half is ``half``, mirrored: y(x) = 1 − y(1 − x)."""
    def f(x):
        x = np.asarray(x, dtype=float)
        v = half(np.minimum(x, 1 - x))[k]
        return np.where(x <= 0.5, v, (k == 0) + (-1) ** (k + 1) * v)
    return f


def _power_peak(p, q):
    """max over θ ∈ [0, π/2] of (p + q sin θ) cos θ (p, q > 0), at the root of 2q sin²θ + p sin θ − q = 0:
    the kinetic power where a sine piece of y'' starts at its crest."""
    s = (-p + np.sqrt(p * p + 8 * q * q)) / (4 * q)
    return (p + q * s) * np.sqrt(1 - s * s)


LAWS = {
    "constant acceleration": RiseLaw(
        "constant acceleration",
        lambda x: _piecewise(x, lambda x: 2 * x**2, lambda x: 1 - 2 * (1 - x) ** 2),
        lambda x: _piecewise(x, lambda x: 4 * x, lambda x: 4 * (1 - x)),
        lambda x: _piecewise(x, lambda x: 4 + 0 * x, lambda x: -4 + 0 * x),
        (2.0, 4.0, 8.0), lambda x: 0 * x, (0.5,)),  # y'y'' = 16x peaks at x → ½; y'' jumps at 0, ½, 1
    "linearly falling acceleration": RiseLaw(
        "linearly falling acceleration",
        lambda x: 3 * x**2 - 2 * x**3, lambda x: 6 * x - 6 * x**2, lambda x: 6 - 12 * x,
        (1.5, 6.0, 2 * _S3), lambda x: -12 + 0 * x),  # 36x(1−x)(1−2x) peaks at x = (3 − √3)/6: 2√3
    "cosine": RiseLaw(  # the simple harmonic law
        "cosine",
        lambda x: 0.5 * (1 - np.cos(PI * x)), lambda x: PI / 2 * np.sin(PI * x), lambda x: PI**2 / 2 * np.cos(PI * x),
        (PI / 2, PI**2 / 2, PI**3 / 8), lambda x: -PI**3 / 2 * np.sin(PI * x)),
    "cycloidal (sine)": RiseLaw(
        "cycloidal (sine)",
        lambda x: x - np.sin(2 * PI * x) / (2 * PI), lambda x: 1 - np.cos(2 * PI * x),
        lambda x: 2 * PI * np.sin(2 * PI * x),
        (2.0, 2 * PI, 3 * _S3 * PI / 2, 4 * PI**2),  # (1 − cos θ)·2π sin θ peaks at cos θ = −½
        lambda x: 4 * PI**2 * np.cos(2 * PI * x)),
    "3-4-5 polynomial": RiseLaw(
        "3-4-5 polynomial",
        lambda x: 10 * x**3 - 15 * x**4 + 6 * x**5, lambda x: 30 * x**2 - 60 * x**3 + 30 * x**4,
        lambda x: 60 * x - 180 * x**2 + 120 * x**3,
        (15 / 8, 10 / _S3, None, 60.0),  # D: _closed_345 below; y‴ = 60(1 − 6x + 6x²) peaks at the ends
        lambda x: 60 - 360 * x + 360 * x**2),
    "double harmonic": RiseLaw(
        "double harmonic",
        lambda x: 0.5 * ((1 - np.cos(PI * x)) - 0.25 * (1 - np.cos(2 * PI * x))),
        lambda x: PI / 2 * (np.sin(PI * x) - 0.5 * np.sin(2 * PI * x)),
        lambda x: PI**2 / 2 * (np.cos(PI * x) - np.cos(2 * PI * x)),
        (None, PI**2, None),  # |y''| peaks at x = 1: π² (a jump to the dwell's 0); B, D below
        lambda x: PI**3 / 2 * (2 * np.sin(2 * PI * x) - np.sin(PI * x))),
    "4-5-6-7 polynomial": RiseLaw(
        "4-5-6-7 polynomial",
        lambda x: 35 * x**4 - 84 * x**5 + 70 * x**6 - 20 * x**7,
        lambda x: 140 * x**3 - 420 * x**4 + 420 * x**5 - 140 * x**6,
        lambda x: 420 * x**2 - 1680 * x**3 + 2100 * x**4 - 840 * x**5,
        (35 / 16, None, None, 52.5),  # y‴ = 840x(1−x)(1 − 5x + 5x²) peaks in magnitude at x = ½: −52.5
        lambda x: 840 * x - 5040 * x**2 + 8400 * x**3 - 4200 * x**4),
    "modified trapezoid": RiseLaw(
        "modified trapezoid", *(_odd(_trapezoid_half, k) for k in range(3)),
        # y' peaks at ½: C(1/(2π) + 1/4) = 2; y'y'' peaks in the falling sine piece after 3/8; y‴ at the ends
        (2.0, _C_MT, _C_MT * _power_peak(_C_MT / _W + _C_MT / 4, _C_MT / _W), _C_MT * _W),
        _odd(_trapezoid_half, 3), (1 / 8, 3 / 8, 5 / 8, 7 / 8)),
    "modified sine": RiseLaw(
        "modified sine", *(_odd(_sine_half, k) for k in range(3)),
        # y' peaks at ½: C/π; y'y'' peaks in the long sine piece after 1/8; y‴ peaks at the ends: 4πC
        (_C_MS / PI, _C_MS, _C_MS * _power_peak(_C_MS / _W, _C_MS / _W_MS), _C_MS * _W),
        _odd(_sine_half, 3), (1 / 8, 7 / 8)),
}

# other names of the same laws (textbooks differ): a name of ALIASES selects the law it names
ALIASES = {"simple harmonic": "cosine", "harmonic": "cosine", "cycloidal": "cycloidal (sine)",
           "parabolic": "constant acceleration", "3-4-5": "3-4-5 polynomial", "4-5-6-7": "4-5-6-7 polynomial"}


def named_law(law, name: str = "law") -> RiseLaw:
    """A :class:`RiseLaw` itself, or the one of :data:`LAWS` that ``law`` names (or one of its
    :data:`ALIASES`).

    Parameters
    ----------
    law : a RiseLaw, or a name of LAWS or ALIASES.
    name : the parameter's name in the error message.

    Returns
    -------
    RiseLaw

    Raises
    ------
    DimensionError
        ``law`` names no law.

    Examples
    --------
    >>> named_law("simple harmonic").name
    'cosine'
    """
    if isinstance(law, RiseLaw):
        return law
    law = check_value(name, law, choice(*LAWS, *ALIASES))
    return LAWS[ALIASES.get(law, law)]


def _closed_345():
    # y'y'' = 30x²(1−x)² · 60x(1−x)(1−2x) = 1800 x³(1−x)³(1−2x); d/dx = 0 → with u = x(1−x):
    # 3u²u'(1−2x) − 2u³ = 0 → 3(1−2x)² = 2u = 2x(1−x) → 14x² − 14x + 3 = 0
    x = (14 - np.sqrt(196 - 168)) / 28
    return 1800 * x**3 * (1 - x) ** 3 * (1 - 2 * x)


def _closed_dh_B():
    # y' ∝ sin πx − ½ sin 2πx, zero derivative: cos πx = cos 2πx → πx = 2π/3
    x = 2 / 3
    return PI / 2 * (np.sin(PI * x) - 0.5 * np.sin(2 * PI * x))


def _closed_4567():
    # y'' = 420x²(1−x)²(1−2x) = 420u²(1−2x), u = x(1−x): d/dx = 0 → (1−2x)² = u → 5x² − 5x + 1 = 0
    x = (5 - np.sqrt(5)) / 10
    return 420 * x**2 * (1 - x) ** 2 * (1 - 2 * x)


def _with_closed(name, *closed):
    LAWS[name] = replace(LAWS[name], closed=closed)


_with_closed("3-4-5 polynomial", 15 / 8, 10 / _S3, _closed_345(), 60.0)
_with_closed("double harmonic", _closed_dh_B(), PI**2, _dh_dd_max())
_with_closed("4-5-6-7 polynomial", 35 / 16, _closed_4567(), None, 52.5)


def _peak(law, f, x):
    """max f over the samples x of [0, 1], polished by a bounded scalar search around the best sample."""
    v = np.broadcast_to(np.asarray(f(x), dtype=float), x.shape)
    if not np.all(np.isfinite(v)):
        raise DimensionError(f"law {law.name!r} gives NaN or inf at x = {x[~np.isfinite(v)][0]:g}")
    i, n = int(np.argmax(v)), len(x)
    lo, hi = x[max(i - 1, 0)], x[min(i + 1, n - 1)]
    if hi - lo <= 0:
        return float(v[i])
    res = minimize_scalar(lambda s: -float(f(np.array([s]))[0]), bounds=(lo, hi), method="bounded",
                          options=dict(xatol=1e-12))
    return max(float(v[i]), -res.fun)


@validated
def law_invariants(law: RiseLaw | str, n: Annotated[int, count(3)] = 20001, *, signed: Flag = False) -> Invariants:
    """B, C, D of a rise law (one of :data:`LAWS` or its name), measured on n samples of x ∈ [0, 1] and
    polished by a bounded scalar search around the best sample (independent of the closed forms). C and D
    are the absolute extremes, or with ``signed`` the signed maxima (module docstring)."""
    law = named_law(law)
    size = (lambda v: v) if signed else np.abs
    x = np.linspace(0.0, 1.0, n)
    return Invariants(_peak(law, lambda s: np.abs(law.dy(s)), x), _peak(law, lambda s: size(law.ddy(s)), x),
                      _peak(law, lambda s: size(law.dy(s) * law.ddy(s)), x))


@validated
def law_jerk(law: RiseLaw | str, n: Annotated[int, count(3)] = 20001) -> float:
    """The jerk factor C_j = max|y‴| of a rise law, measured like :func:`law_invariants`; ``inf`` where
    y'' jumps (at the rise's ends from the dwells' zero, or inside): the jerk there is an impulse.

    A jump is found exactly on the samples: without one, neighbouring values of y'' differ by at most
    the sample step times max|y‴| (mean value theorem).

    Parameters
    ----------
    law : a RiseLaw with its jerk analog ``dddy``, or a name of :data:`LAWS` (or :data:`ALIASES`).
    n : number of samples of x ∈ [0, 1] before polishing.

    Returns
    -------
    float
        C_j (the physical peak jerk is C_j·h·ω³/Φ³), or ``inf``.

    Raises
    ------
    MechanismError
        The law gives no jerk analog.

    Examples
    --------
    >>> round(law_jerk("cycloidal (sine)"), 4), law_jerk("simple harmonic")
    (39.4784, inf)
    """
    law = named_law(law)
    x = np.linspace(0.0, 1.0, n)
    top = _peak(law, lambda s: np.abs(law.jerk(s)), x)
    ddy = np.broadcast_to(np.asarray(law.ddy(x), dtype=float), x.shape)
    step = np.abs(np.diff(np.concatenate([[0.0], ddy, [0.0]])))   # the dwells on both sides: y'' = 0
    allowed = np.concatenate([[1e-12], np.full(n - 1, 1.5 * top * (x[1] - x[0]) + 1e-12), [1e-12]])
    return float("inf") if np.any(step > allowed) else top


@validated
def invariants(Phi: Real, h: Real, dpsi: Analogs, ddpsi: Analogs, *, signed: Flag = False) -> Invariants:
    """B, C, D of an output law that moves by ``h`` over the crank angle ``Phi``, from its analogs.

    B = max|ψ'|·Φ/|h|, C = max|ψ''|·Φ²/|h|, D = max|ψ'ψ''|·Φ³/h² (Kinitsky, 1994, chapter 2:
    invariants of velocity, acceleration and kinetic power); with ``signed`` C and D are the signed
    maxima in the direction of the rise. Raises MechanismError if the output does not move.
    """
    if len(dpsi) != len(ddpsi):
        raise DimensionError(f"dpsi and ddpsi must be samples at the same angles, got {len(dpsi)} and "
                             f"{len(ddpsi)} values")
    Phi, h = np.float64(Phi), np.float64(h)  # numpy floats: an overflow gives inf, refused below
    if not abs(h) > 0 or not Phi > 0:
        raise MechanismError(f"no rise to normalise: stroke h = {h:.3g}, duration Φ = {Phi:.3g}")
    acc, power = np.asarray(ddpsi) * np.sign(h), np.asarray(dpsi) * np.asarray(ddpsi)  # along the rise
    if not signed:
        acc, power = np.abs(acc), np.abs(power)
    with np.errstate(over="ignore"):
        inv = Invariants(np.max(np.abs(dpsi)) * Phi / abs(h), np.max(acc) * Phi**2 / abs(h),
                         np.max(power) * Phi**3 / h**2)
    if not np.all(np.isfinite(inv.values)):
        raise DimensionError(f"the invariants overflow: duration Φ = {Phi:.3g} and stroke h = {h:.3g} with "
                             f"max|dpsi| = {np.max(np.abs(dpsi)):.3g}, max|ddpsi| = {np.max(np.abs(ddpsi)):.3g}")
    return inv


@validated
def rise_invariants(phi: Sampled, psi: Sampled, dpsi: Sampled, ddpsi: Sampled, *, signed: Flag = False) -> Invariants:
    """:func:`invariants` of an output law sampled over one rise (φ from its start to its end):
    Φ = φ_end − φ_start and h = ψ_end − ψ_start."""
    if not len(phi) == len(psi) == len(dpsi) == len(ddpsi):
        raise DimensionError(f"phi, psi, dpsi and ddpsi must be samples at the same angles, got {len(phi)}, "
                             f"{len(psi)}, {len(dpsi)} and {len(ddpsi)} values")
    return invariants(phi[-1] - phi[0], psi[-1] - psi[0], dpsi, ddpsi, signed=signed)


@dataclass(frozen=True)
class PrintedInvariants:
    """One cam row of Kinitsky's (1994) table as printed: the law and its B, C, D (None: not readable)."""

    law: str
    B: float | None
    C: float | None
    D: float | None

    @property
    def values(self) -> tuple:
        """(B, C, D)."""
        return self.B, self.C, self.D


def thesis_cam_rows() -> Table:
    """The cam rows of the table on page 21 of Kinitsky (1994) as printed (B, C, D), where the OCR is
    readable; the laws are those of :data:`LAWS`. The rows "Stoddart", "Kurd" and the power law
    with sine-type acceleration are not decodable reliably and are left out."""
    return Table(PrintedInvariants(*row) for row in (
        ("constant acceleration", 2.00, 4.00, 8.00),
        ("linearly falling acceleration", 1.50, 6.00, 3.46),
        ("cosine", 1.57, 4.94, 3.88),
        ("cycloidal (sine)", 2.00, 6.28, 8.15),
        ("3-4-5 polynomial", 1.875, 5.77, None),  # printed D is garbled ("6.ВЭ")
        ("double harmonic", 2.04, 9.88, 7.00),
    ))


def thesis_mchv1_rows() -> list:
    """МЧВ1 rows of the same table (K = 1, β_m = 20°) as printed: (δ°, α°, a, B, C, D).
    The dwell is 2α; a is printed to one decimal only."""
    return [
        (120, 25, 0.7, 2.58, 17.11, 22.79), (120, 50, 0.8, 2.23, 11.69, 14.02), (120, 75, 0.8, 1.98, 9.11, 9.74),
        (180, 25, 0.9, 2.51, 18.25, 22.47), (180, 50, 1.0, 2.16, 12.32, 16.67), (180, 100, 1.0, 1.70, 7.77, 6.71),
        (180, 125, 1.1, 1.43, 4.70, 3.58), (240, 25, 1.2, 2.26, 13.94, 15.20), (240, 50, 1.5, 1.97, 8.22, 8.86),
        (240, 100, 1.4, 1.52, 5.17, 4.13), (240, 125, 1.4, 1.30, 3.50, 2.43), (270, 25, 1.5, 2.16, 11.76, 12.52),
        (270, 50, 1.7, 1.92, 7.23, 7.89), (270, 100, 1.6, 1.45, 4.95, 3.51),
    ]


@dataclass(frozen=True)
class LawRow:
    """One law of :func:`law_table`: its invariants (dimensionless: B, C, D are the textbooks' C_v, C_a
    and the kinetic-power factor C_p), its jerk factor C_j (None where Y″ jumps: the jerk is an impulse, the
    textbooks' "infinite") and Y″ at the rise's two ends."""

    law: str
    B: float = field(metadata={"label": "C_v = max|Y′|"})
    C: float = field(metadata={"label": "C_a = max|Y″|"})
    D: float = field(metadata={"label": "C_p = max|Y′Y″|"})
    start: float = field(metadata={"label": "Y″ at x = 0"})
    end: float = field(metadata={"label": "Y″ at x = 1"})
    # last, with a default: a positional LawRow(law, B, C, D, start, end) keeps working
    J: float | None = field(default=None, metadata={"label": "C_j = max|Y‴| (None: Y″ jumps)"})


def law_table(names=None, n: Annotated[int, count(3)] = 20001) -> Table:
    """The cam laws side by side (Kinitsky, 1994, chapter 2): per law of :data:`LAWS` (all, or those
    named), B, C, D of :func:`law_invariants`, C_j of :func:`law_jerk` and the acceleration analog Y″ at
    both ends of the rise —
    a jump there from the dwell's 0 is a soft impact."""
    if names is not None and (not isinstance(names, list | tuple) or not names):
        raise DimensionError(f"names must be a non-empty list of law names (or None: all), got {names!r}")
    names = list(LAWS) if names is None else [named_law(name, "names").name for name in names]
    n = check_value("n", n, count(3))
    rows = []
    for name in names:
        inv = law_invariants(name, n)
        ends = np.round(LAWS[name](np.array([0.0, 1.0]))[2], 9) + 0.0   # rounding noise and "-0" away
        jerk = law_jerk(name, n)
        rows.append(LawRow(name, inv.B, inv.C, inv.D, float(ends[0]), float(ends[1]),
                           jerk if np.isfinite(jerk) else None))
    return Table(rows)
