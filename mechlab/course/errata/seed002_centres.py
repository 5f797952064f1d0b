"""Kozhevnikov (§7.1-7.2): two passages we could only read by guessing an OCR-garbled line, each
recomputed by mechlab.analysis.centres under that reading.

Both rest on one reading of the line that names the angle α (and the points B, C) on the trammel's
and the antiparallelogram's drawings. Under our reading (7.11) and the text are wrong; a
self-consistent reading, with α measured from the other guide, makes (7.11) right. The scan does not
settle which, so they are listed as unreadable passages, with the computation for our reading."""

import numpy as np

from ...analysis.centres import centrodes
from ...analysis.centres.instant import instant_centres
from ...mechanisms.antiparallelogram import Antiparallelogram
from ...mechanisms.trammel import EllipticTrammel
from . import Claim, Erratum

NOTEBOOK = "01_instant_centres.ipynb"


def _trammel_y_coordinate() -> str:
    """(7.11): the pole's second coordinate uses cos(β - α) where (7.10), (7.13), (7.14) need cos α."""
    l, beta = 1.0, np.radians(60.0)
    m = EllipticTrammel(l, beta)
    phi = np.radians(np.arange(0.5, 360.0, 7.0))
    cd = centrodes(m, "rod", phi=phi)
    P = cd.fixed.xy                      # the rod's pole P14 in the guides' frame (A's guide = x axis)
    x1, y1 = cd.moving.xy.T              # P14 in the rod's frame x₁Ay₁ (x₁ along AB)
    # (7.13)-(7.14) hold exactly with α = β - θ, θ the rod's inclination to A's guide:
    alpha = beta - m.rod_angle(phi)
    assert np.allclose(x1, l * np.cos(alpha) * np.sin(beta - alpha) / np.sin(beta), atol=1e-12)
    assert np.allclose(y1, l * np.cos(alpha) * np.cos(beta - alpha) / np.sin(beta), atol=1e-12)
    # with this α, (7.10) is right (up to the sense of the x axis) and the true y is l cos α / sin β
    assert np.allclose(np.abs(P[:, 0]), np.abs(l * np.sin(np.pi - alpha) / np.sin(beta)), atol=1e-12)
    assert np.allclose(np.abs(P[:, 1]), np.abs(l * np.cos(alpha) / np.sin(beta)), atol=1e-12)
    printed_y = l * np.cos(beta - alpha) / np.sin(beta)
    r2 = (l * np.sin(np.pi - alpha) / np.sin(beta)) ** 2 + printed_y**2   # (7.10)² + (7.11)² as printed
    assert np.ptp(r2) > 1.0 * l**2 and np.allclose(np.hypot(*P.T), l / np.sin(beta), atol=1e-12)
    i = int(np.argmin(np.abs(np.degrees(alpha) - 10.0)))
    # away from α = β/2, where cos(β − α) = cos α and the printed y happens to be right
    far = np.abs(alpha - beta / 2) > 0.2
    return Claim(np.abs(P[far, 1]), np.abs(printed_y[far]), np.abs(l * np.cos(alpha[far]) / np.sin(beta)), 1e-9,
                 text=(f"l = 1, β = 60°, α = {np.degrees(alpha[i]):.1f}°: pole P14 = ({P[i, 0]:.4f}, {P[i, 1]:.4f}) "
                       f"(Kennedy), "
            f"|y| = l cos α / sin β = {abs(np.cos(alpha[i])) / np.sin(beta):.4f}; printed l cos(β-α)/sin β = "
            f"{printed_y[i]:.4f}; printed x² + y² ranges over [{r2.min():.3f}, {r2.max():.3f}] l² instead of "
            f"the constant l²/sin²β = {1 / np.sin(beta) ** 2:.4f} l² of (7.12); |y| compared at {far.sum()} "
            f"positions with |α − β/2| > 0.2"))


def _antiparallelogram_pole() -> str:
    """Fig. 7.7: P24 of the two opposite links is where the lines of links 1 and 3 meet, not AB ∩ BC."""
    m = Antiparallelogram(1.0, 2.0)
    phi = np.radians([30.0, 45.0, 120.0])    # (at φ = 60° P24 is at infinity: OA ∥ EB)
    ic = instant_centres(m, phi)
    iv = instant_centres(m, phi, method="velocity")
    p24 = ic("coupler", "frame")            # links 2 and 4 of O-A-B-E: coupler AB and frame OE
    assert p24.finite.all() and np.allclose(p24.xy, iv("coupler", "frame").xy, atol=1e-12)
    O, A, B, E = (ic.motion.points[k].p for k in "OABE")
    # it lies on the lines of links 1 (OA) and 3 (EB) ...
    on = lambda P, Q, R: np.abs((Q - P)[:, 0] * (R - P)[:, 1] - (Q - P)[:, 1] * (R - P)[:, 0])  # noqa: E731
    assert on(p24.xy, O, A).max() < 1e-12 and on(p24.xy, E, B).max() < 1e-12
    # ... while two adjacent links' lines (AB and BE here) meet at their joint B, which moves
    gap = np.hypot(*(p24.xy - B).T)
    vB = np.hypot(*ic.motion.points["B"].d.T)
    assert vB.min() > 0.1
    # the printed rule (lines AB and BE meet at the joint B) and the corrected one (OA ∩ EB), by their own
    # line intersections, against Kennedy's P24
    meet = np.array([_meet(O[i], A[i], E[i], B[i]) for i in range(len(phi))])
    return Claim(p24.xy, B, meet, 1e-9,
                 text=(f"antiparallelogram crank = rocker = 1, coupler = frame = 2, φ = 45°: P24 = "
                       f"({p24.xy[1, 0]:.4f}, "
            f"{p24.xy[1, 1]:.4f}) = OA ∩ EB (Kennedy and twists agree to 1e-12); the joint B = "
            f"({B[1, 0]:.4f}, {B[1, 1]:.4f}) where adjacent lines meet is {gap[1]:.4f} away and moves with "
            f"velocity analog {vB[1]:.4f} ≠ 0"))


def _meet(P, Q, R, S):
    """Intersection of the lines PQ and RS."""
    d1, d2 = Q - P, S - R
    t = ((R - P)[0] * d2[1] - (R - P)[1] * d2[0]) / (d1[0] * d2[1] - d1[1] * d2[0])
    return P + t * d1


ERRATA = [
    Erratum(
        source="002", where="§7.2, formula (7.11) (the elliptic trammel's drawing)",
        printed=r"$y = \frac{BC}{\sin\beta} = \frac{l_{AB}\cos(\beta-\alpha)}{\sin\beta}$",
        correct=r"if α is the angle of (7.10), (7.13), (7.14) as we read the garbled line: "
                r"$y = \frac{l_{AB}\cos\alpha}{\sin\beta}$, and only then (7.10)² + (7.11)² gives (7.12); "
                r"with α measured from the other guide the printed (7.11) is right",
        check=_trammel_y_coordinate, notebook=NOTEBOOK, kind="unreadable"),
    Erratum(
        source="002", where="§7.2, text on the antiparallelogram's drawing",
        printed="the centre of links 2 and 4 lies at the intersection of lines AB and BC",
        correct="as we read the garbled letters: … of the lines of links 1 and 3 (AB and CD for the loop "
                "A-B-C-D), since lines AB and BC only meet at the joint B; the letters rest on the same guessed "
                "reading as (7.11)",
        check=_antiparallelogram_pole, notebook=NOTEBOOK, kind="unreadable"),
]
