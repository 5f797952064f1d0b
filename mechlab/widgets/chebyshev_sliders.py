"""Sliders for the translating-output lambda six-bars МЧВ2 and МЧВ5 (Kinitsky, 1994, Fig. 1 в, д).

Each move re-runs the synthesis (circle_guiding + mchv2, straight_guiding + mchv5), so an
infeasible request shows its InfeasibleDesignError / SynthesisError message in place of the drawing.
"""

from __future__ import annotations

from ..synthesis.lambda_guiding import circle_guiding, straight_guiding
from ..synthesis.lambda_sliders import mchv2, mchv5
from . import Control, MechanismExplorer


def _mchv2(delta, a, dwell, K, mu_min):
    return mchv2(circle_guiding(delta, a, dwell, minimax=False), K, mu_min=mu_min if mu_min > 0 else None)


def mchv2_explorer(delta=150.0, a=0.9, dwell=120.0, K=1.0, mu_min=30.0, n=121, *, live: bool | None = None,
                   question: str | None = None) -> MechanismExplorer:
    """МЧВ2 from δ, a, the dwell 2α, the time ratio K (the guide through Q and E1) and the least
    transmission angle μ2′ accepted (degrees; 0 = any), as :func:`mchv1_explorer` does for МЧВ1."""
    controls = {
        "delta": Control("break δ", 90.0, 180.0, 1.0, delta, "deg"),
        "a": Control("frame a = OC/l", 0.2, 1.6, 0.01, a),
        "dwell": Control("dwell 2α", 20.0, 200.0, 2.0, dwell, "deg"),
        "K": Control("time ratio K", 0.5, 2.0, 0.05, K),
        "mu_min": Control("least μ2′, 0 = any", 0.0, 45.0, 1.0, mu_min, "deg"),
    }
    return MechanismExplorer(_mchv2, controls, trace="D", n=n, title="Lambda six-bar with slider output (type 2)",
                             live=live, question=question)


def _mchv5(delta, a, dwell, gamma):
    return mchv5(straight_guiding(delta, a, dwell), guide_angle=gamma)


def mchv5_explorer(delta=180.0, a=0.8, dwell=180.0, gamma=0.0, n=121, *, live: bool | None = None,
                   question: str | None = None) -> MechanismExplorer:
    """МЧВ5 from δ, a, the straight part's 2α and the guide's angle γ to the slot normal."""
    controls = {
        "delta": Control("break δ", 90.0, 180.0, 1.0, delta, "deg"),
        "a": Control("frame a = OC/l", 0.2, 1.6, 0.01, a),
        "dwell": Control("dwell 2α", 20.0, 200.0, 2.0, dwell, "deg"),
        "gamma": Control("guide angle γ", -60.0, 60.0, 1.0, gamma, "deg"),
    }
    return MechanismExplorer(_mchv5, controls, trace="D", n=n, title="Lambda six-bar with translating slotted output "
                                                                     "(type 5)",
                             live=live, question=question)


__all__ = ["mchv2_explorer", "mchv5_explorer"]
