"""Sliders for the lambda mechanism and its six-bars (Kinitsky, 1994): δ, a, 2α, K, β_m in degrees.

Each explorer rebuilds the design through the synthesis (circle_guiding, mchv1), so a request
outside the existence map shows its SynthesisError message in place of the drawing.
"""

from __future__ import annotations

from ..synthesis.lambda_guiding import circle_guiding
from ..synthesis.lambda_sixbars import mchv1
from . import Control, MechanismExplorer


def _guided(delta, a, dwell):
    return circle_guiding(delta, a, dwell).guided


def lambda_explorer(delta=150.0, a=0.9, dwell=120.0, n=121, *, live: bool | None = None,
                    question: str | None = None) -> MechanismExplorer:
    """Circle-guiding lambda mechanism from δ, a and the dwell 2α, with its band and axis."""
    controls = {
        "delta": Control("break δ", 90.0, 180.0, 1.0, delta, "deg"),
        "a": Control("frame a = OC/l", 0.2, 1.6, 0.01, a),
        "dwell": Control("dwell 2α", 20.0, 300.0, 2.0, dwell, "deg"),
    }
    return MechanismExplorer(_guided, controls, trace="D", n=n, title="Chebyshev lambda mechanism, circle guiding",
                             live=live, question=question)


def _mchv1(delta, a, dwell, K, swing, mu_min):
    return mchv1(circle_guiding(delta, a, dwell), K, swing, mu_min=mu_min if mu_min > 0 else None)


def mchv1_explorer(delta=150.0, a=0.9, dwell=120.0, K=1.0, swing=20.0, mu_min=30.0, n=121, *,
                   live: bool | None = None, question: str | None = None) -> MechanismExplorer:
    """МЧВ1 six-bar synthesised from δ, a, 2α, the time ratio K and the swing β_m; a design whose
    dyad transmission angle leaves [μ_min, 180° − μ_min] shows the reason instead (μ_min = 0: no limit)."""
    controls = {
        "delta": Control("break δ", 90.0, 180.0, 1.0, delta, "deg"),
        "a": Control("frame a = OC/l", 0.2, 1.6, 0.01, a),
        "dwell": Control("dwell 2α", 20.0, 300.0, 2.0, dwell, "deg"),
        "K": Control("time ratio K", 0.5, 2.0, 0.05, K),
        "swing": Control("swing β_m", 5.0, 90.0, 1.0, swing, "deg"),
        "mu_min": Control("least μ, 0 = any", 0.0, 45.0, 1.0, mu_min, "deg"),
    }
    return MechanismExplorer(_mchv1, controls, trace="D", n=n, title="Lambda six-bar with rocker output (type 1)",
                             live=live, question=question)


__all__ = ["lambda_explorer", "mchv1_explorer"]
