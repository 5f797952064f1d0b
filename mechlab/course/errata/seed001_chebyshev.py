"""Errata and undecodable passages of Kinitsky (1994, thesis abstract), with evidence."""

import numpy as np

from ...analysis.motion_laws import law_invariants
from ...mechanisms.fourbar import FourBar
from ...mechanisms.lambda_mechanism import LambdaMechanism, classic_lambda
from ...synthesis.lambda_guiding import circle_guiding, straight_guiding
from . import Claim, Erratum

DEG = np.pi / 180
NB06 = "06_chebyshev_dwell_synthesis.ipynb"
NB07 = "08_chebyshev_dwell_sixbars.ipynb"


def _rotation():
    # the printed conditions against Grashof's verdict on a grid of (r, a), double cranks included
    r, a = (v.ravel() for v in np.meshgrid(np.linspace(0.05, 1.35, 27), np.linspace(0.07, 1.97, 39)))  # no r = a
    cell = (r + a < 2) & (r < 1.0)  # inside the printed conditions
    r, a = r[cell], a[cell]
    truth = np.array([FourBar(x, 1.0, 1.0, y).grashof().kind == "crank-rocker" for x, y in zip(r, a, strict=False)])
    printed = (r < 1) & (r + a < 2)
    correct = (r < a) & (r + a < 2)
    n_bad = int(np.sum(printed & ~truth))
    return Claim(truth, printed, correct, 0.5, each=False, text=
                 f"{len(r)} four-bars (r, 1, 1, a) on a grid: the printed conditions admit {n_bad} that are not "
                 f"crank-rockers (e.g. r = 0.5, a = 0.3, a double crank); with r < a added, Grashof agrees at each")


def _formulas():
    # the relations that replace (2)-(11): |CA| = 2 sin(μ/2), |CD| = 2 sin((δ − μ)/2), ∠ACD = π − δ/2
    m = LambdaMechanism(0.3, 0.9, 140 * DEG)
    phi = np.linspace(0, 2 * np.pi, 721)
    mo = m.motion(phi)
    A, C, D = (mo.points[k].p for k in "ACD")
    mu = mo.transmission
    ca, cd = np.hypot(*(A - C).T), np.hypot(*(D - C).T)
    ang = np.arccos(np.clip(((A - C) * (D - C)).sum(1) / (ca * cd), -1, 1))
    e1 = np.abs(ca - 2 * np.sin(mu / 2)).max()
    e2 = np.abs(cd - 2 * np.sin((m.delta - mu) / 2)).max()
    e3 = np.abs(ang - (np.pi - m.delta / 2)).max()
    assert max(e1, e2, e3) < 1e-12
    return (f"over a turn of (r, a, δ) = (0.3, 0.9, 140°): max errors {e1:.1e}, {e2:.1e}, {e3:.1e} "
            f"of |CA| = 2 sin(μ/2), |CD| = 2 sin((δ−μ)/2), ∠ACD = π − δ/2")


def _cam(name, k, printed, exact, formula):
    def check():
        got = law_invariants(name).values[k]
        return Claim(got, printed, exact, 1e-6,
                     f"{'BCD'[k]} of the {name} law = {got:.4f} = {formula}, printed {printed:.2f} (rounding to "
                     f"two decimals allows 0.005)", printed_tol=0.005)
    return check


def _dh_power():
    # the truth from the closed form written out here, not from the library's law functions:
    # y = ½[(1 − cos πx) − ¼(1 − cos 2πx)], y' = (π/2)(sin πx − ½ sin 2πx), y'' = (π²/2)(cos πx − cos 2πx)
    x = np.linspace(0, 1, 200001)
    power = ((np.pi**3 / 4) * (np.sin(np.pi * x) - 0.5 * np.sin(2 * np.pi * x))
             * (np.cos(np.pi * x) - np.cos(2 * np.pi * x)))
    absmax, signed = np.abs(power).max(), power.max()
    return Claim(absmax, 7.00, 9.89, 0.005,
                 f"max |y'y''| = {absmax:.4f} on 200001 points of the closed form (the definition that reproduces "
                 f"the МЧВ1 rows); the signed max y'y'' = {signed:.4f} does not give the printed 7.00 either")


def _classic():
    s = straight_guiding(np.pi, 0.8, np.pi)
    m = classic_lambda()
    x = m.axis_coordinates(np.pi + np.array([0.0, np.pi / 2]))[0]
    assert abs(s.r - 0.4) < 1e-12 and np.allclose(x, 1.6, atol=1e-14)
    return (f"Chebyshev's 1 : 2 : 2.5 : 5 lambda is the equal-ripple straight guide of 2α = 180°: "
            f"r = {s.r:.12f}, x(0) = x(90°) = 1.6, E = {s.E:.6f}")


def _mchv1_row():
    from ...analysis.motion_laws import rise_invariants
    from ...synthesis.lambda_sixbars import mchv1, rise_law

    g = circle_guiding(np.pi, 1.0, 100 * DEG)
    inv = rise_invariants(*rise_law(mchv1(g, 1.0, 20 * DEG), g.dwell))
    assert abs(inv.B - 2.16) < 0.01 and abs(inv.C / 12.32 - 1) < 0.01  # the row's B, C are reproduced
    return Claim(inv.D, 16.67, 13.67, 0.005,
                 f"δ = 180°, 2α = 100°, a = 1.0, K = 1, β_m = 20°: B = {inv.B:.2f}, C = {inv.C:.2f} as printed, "
                 f"D = {inv.D:.4f}, which rounds to the corrected 13.67")


def _row_fit(delta, alpha, a, guess=None, full_swing=False):
    """Worst relative mismatch of (B, C, D) of МЧВ1 (K = 1, β_m = 20°) against the printed row
    (and the invariants, and the circle-guiding design as a start for a neighbouring a).

    The rise is normalised as :func:`~mechlab.synthesis.lambda_sixbars.rise_law` measures it, from the
    end of the dwell to the far extreme; ``full_swing`` takes the stroke from the dwell's centre instead
    (adding the dwell's residual motion, about 0.013 rad at δ = 270°, 2α = 200°)."""
    from ...analysis.motion_laws import invariants, thesis_mchv1_rows
    from ...synthesis.lambda_sixbars import mchv1, rise_law

    row = next(r for r in thesis_mchv1_rows() if r[:2] == (delta, alpha))
    g = circle_guiding(delta * DEG, a, 2 * alpha * DEG, guess=guess) if guess else \
        circle_guiding(delta * DEG, a, 2 * alpha * DEG)
    six = mchv1(g, 1.0, 20 * DEG, mu_min=None)
    phi, psi, dpsi, ddpsi = rise_law(six, g.dwell)
    start = six.motion(np.array([np.pi])).psi[0] if full_swing else psi[0]
    inv = invariants(phi[-1] - phi[0], psi[-1] - start, dpsi, ddpsi)
    return max(abs(inv.B / row[3] - 1), abs(inv.C / row[4] - 1), abs(inv.D / row[5] - 1)), inv


def _a_claim(delta, alphas, printed_a, correct_a, tol, note, full_swing=False):
    """The a that reproduces each printed row best (:func:`_best_a`) against the printed and the
    corrected a."""
    fits = [_best_a(delta, alpha, correct_a, span=0.04, step=0.02) for alpha in alphas]
    worst = [_row_fit(delta, alpha, printed_a)[0] for alpha in alphas]
    text = "; ".join(f"δ = {delta}°, α = {alpha}°, K = 1, β_m = 20°: the printed B, C, D are reproduced best at "
                     f"a = {a:.4f} (worst {100 * w:.1f} %), at a = {printed_a} only within {100 * p:.1f} %"
                     for alpha, (w, a), p in zip(alphas, fits, worst, strict=False))
    return Claim([a for _, a in fits], printed_a, correct_a, tol, f"{text} ({note})")


def _rows_120():
    return _a_claim(120, (50, 75), 0.8, 0.75, 0.0025, "a printed rounded up to one decimal")


def _row_270_100():
    swing = _best_a(270, 100, 1.48, span=0.04, step=0.02, full_swing=True)
    return _a_claim(270, (100,), 1.6, 1.43, 0.01,
                    f"the rise normalised from the dwell's end, as rise_law does for every МЧВ1 row; normalised by "
                    f"the full swing from the dwell's centre the best fit is a = {swing[1]:.3f} (worst "
                    f"{100 * swing[0]:.1f} %): 1.6 is far either way, probably a misprint of 1.4")


def _best_a(delta, alpha, a0, span=0.2, step=0.025, full_swing=False):
    """(worst mismatch, a) minimised over a near the printed a0: a scan, then a bounded 1-D search
    (each circle-guiding solve started from the scan's best design)."""
    from scipy.optimize import minimize_scalar

    from ...errors import MechanismError

    fits = []
    for a in a0 + np.arange(-span, span + 1e-9, step):
        try:
            fits.append((_row_fit(delta, alpha, a, full_swing=full_swing)[0], a))
        except MechanismError:  # no design at this a (outside the map, or F cannot be placed)
            continue
    w, a = min(fits)
    g = circle_guiding(delta * DEG, a, 2 * alpha * DEG)
    guess = (g.r, g.k, g.t3, g.t2)

    def worst(x):
        try:
            return _row_fit(delta, alpha, x, guess, full_swing)[0]
        except MechanismError:
            return 1.0

    res = minimize_scalar(worst, bounds=(a - step, a + step), method="bounded", options=dict(xatol=1e-4))
    return (float(res.fun), float(res.x)) if res.fun < w else (w, a)


def _rows_125():
    w180, a180 = _best_a(180, 125, 1.1, step=0.1)
    w240, a240 = _best_a(240, 125, 1.4, step=0.1)
    inv = _row_fit(180, 125, a180)[1]
    assert 0.02 < w180 < 0.035 and abs(a180 - 1.12) < 0.01 and w240 > 0.07
    return (f"2α = 250°, K = 1, β_m = 20°: δ = 180° is closest at a = {a180:.3f} (B, C, D = {inv.B:.2f}, {inv.C:.2f}, "
            f"{inv.D:.2f}; worst {100 * w180:.1f} %); δ = 240° at best {100 * w240:.1f} % off (a = {a240:.3f}, "
            f"B ≈ 1.40 for every a)")


def _whole_turn():
    from ...synthesis.lambda_guiding import whole_turn_line

    wt = whole_turn_line(150 * DEG)
    g = circle_guiding(150 * DEG, 0.3, 347 * DEG)
    assert abs(wt.a[0] - 2 * np.sin(150 * DEG / 4)) < 0.01 and abs(wt.r[-1] + wt.a[-1] - 2) < 0.03
    assert g.r / 0.3 > 0.97
    return (f"δ = 150°: one 360° line from (r, a) = ({wt.r[0]:.3f}, {wt.a[0]:.4f}) ≈ (0, 2 sin(δ/4)) to "
            f"({wt.r[-1]:.3f}, {wt.a[-1]:.3f}) on r + a = 2; for a < 1 the dwell → 360° only as r → a "
            f"(a = 0.3, 2α = 347°: r = {g.r:.4f})")


ERRATA = [
    Erratum("001", "the opening, condition for the crank's full rotation", "$l_{OA} < l$ and $l_{OC} + l_{OA} < 2l$",
            "also $r < a$ (line PX of the existence map in the (r, a) plane): otherwise the frame is the "
            "shortest link and the base four-bar is a double crank", _rotation, NB06, kind="remark"),
    Erratum("001", "formulas (2)-(11)", "illegible in the OCR (only (1), (5), (11), (13)-(15) readable)",
            "re-derived: B is the circumcentre of A, C, D, so $|CA| = 2\\sin(\\mu/2)$, "
            "$|CD| = 2\\sin((\\delta-\\mu)/2)$, $\\angle ACD = \\pi - \\delta/2$; synthesis by equal ripple",
            _formulas, NB06, kind="unreadable"),
    Erratum("001", "Chebyshev's lambda (note)", "dimensions 1 : 2 : 2.5 : 5 quoted without a dwell",
            "they are exactly the straight-line synthesis for 2α = 180° (a = 0.8 → r = 0.4)", _classic, NB06,
            kind="remark"),
    Erratum("001", "table p. 21, МЧВ1 row δ = 180°, α = 50°", "D = 16.67",
            "D = 13.67 (probably a misprint of one digit)",
            _mchv1_row, NB07),
    Erratum("001", "table p. 21, cosine law", "C = 4.94", "C = π²/2 = 4.93",
            _cam("cosine", 1, 4.94, np.pi**2 / 2, "π²/2"), NB07, kind="remark"),
    Erratum("001", "table p. 21, sinusoidal (cycloidal) law", "D = 8.15", "D = 3√3π/2 = 8.16",
            _cam("cycloidal (sine)", 2, 8.15, 3 * np.sqrt(3) * np.pi / 2, "3√3π/2"), NB07, kind="remark"),
    Erratum("001", "table p. 21, double harmonic law", "C = 9.88", "C = π² = 9.87",
            _cam("double harmonic", 1, 9.88, np.pi**2, "π²"), NB07, kind="remark"),
    Erratum("001", "table p. 21, double harmonic law", "D = 7.00",
            "D = 9.89 (max |y'y''|, the definition that reproduces the МЧВ1 rows; 7.75 for the signed max)",
            _dh_power, NB07),
    Erratum("001", "table p. 21, МЧВ1 rows δ = 120°, α = 50° and 75°", "a = 0.8",
            "a = 0.75 (printed rounded up to one decimal); with 0.8 C comes out 13–15 % low", _rows_120, NB07,
            kind="remark"),
    Erratum("001", "table p. 21, МЧВ1 row δ = 270°, α = 100°", "a = 1.6",
            "a ≈ 1.43 (the row's B, C, D are those of a = 1.42–1.43 with the rise measured from the dwell's "
            "end, as for every МЧВ1 row here; ≈ 1.48 normalised by the full swing, as the thesis does; 1.6 is "
            "probably a misprint of 1.4)",
            _row_270_100, NB07),
    Erratum("001", "table p. 21, МЧВ1 rows δ = 180° and 240°, α = 125°",
            "B, C, D = 1.43, 4.70, 3.58 and 1.30, 3.50, 2.43",
            "180°: nearly, with a ≈ 1.12 (2.7 %, B 3 % high); 240°: undecodable — no a within ±0.2 comes closer "
            "than 7.6 % (a wider search over K 0.9–1.1, β_m 15–25° and both sides of F: 6.1 % at best)",
            _rows_125, NB07, kind="unreadable"),
    Erratum("001", "text before (12), boundary 2 of the existence map (its lines KU and AP)",
            "two lines where the whole coupler curve is near a circle, α = π",
            "computed: one line per δ, from A = (0, 2 sin(δ/4)) on the fifth-order line to the rotation limit; "
            "for a < 1 the 360° limit is r = a itself (which letters are which is not decodable)",
            _whole_turn, NB06, kind="unreadable"),
]
