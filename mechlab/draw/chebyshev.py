"""Drawings of the lambda mechanism (with its band) and of the six-bars built on it (Kinitsky, 1994).

Every drawing follows :class:`mechlab.draw.LinkageDrawing`: artists created once, moved by
``set_frame``. Extras: the symmetry axis; for a guided lambda the two circles R0, R1 of the
band and the dwell part of D's path; for the six-bars the dwell part of D's path and the
output link re-drawn in a highlight colour while the crank is inside the dwell.
"""

from __future__ import annotations

import numpy as np

from ..mechanisms.lambda_mechanism import GuidedLambda, LambdaMechanism
from ..mechanisms.lambda_sixbars import LambdaRockerSixBar, LambdaSlottedSixBar
from . import HIGHLIGHT_STYLE, OUTPUT_STYLE, LinkageDrawing, register

_CIRCLE = np.linspace(0.0, 2 * np.pi, 241)


def _in_dwell(phi: float, dwell: float) -> bool:
    return dwell > 0 and abs((phi - np.pi + np.pi) % (2 * np.pi) - np.pi) <= dwell / 2


def _dwell_path(mech, dwell: float) -> np.ndarray:
    if dwell <= 0:
        return np.full((1, 2), np.nan)
    t = np.pi + np.linspace(-dwell / 2, dwell / 2, 121) + 1e-6
    return mech.base.coupler_point(t) if hasattr(mech, "base") else mech.coupler_point(t)


@register(LambdaMechanism)
class LambdaDrawing(LinkageDrawing):
    """Links O-A, A-B-D, C-B; extra: the symmetry axis of the coupler curve through C."""

    n_extras = 1

    def axis_segment(self, m: LambdaMechanism) -> np.ndarray:
        return np.array([m.C - 0.3 * m.axis, m.C + 2.2 * m.axis])

    def extras(self, i):
        return [self.axis_segment(self.mechanism)]


@register(GuidedLambda)
class GuidedLambdaDrawing(LambdaDrawing):
    """Adds the band: circles R0 and R1 about Q and the dwell part of D's path."""

    n_extras = 4

    def extras(self, i):
        m = self.mechanism
        q = np.array([m.qx, m.qy])
        # only the arcs near the dwell part, so the picture stays readable
        e = m.axis
        th0 = np.arctan2(-e[1], -e[0]) if m.R0 > 0 else 0.0
        span = np.linspace(th0 - 0.9, th0 + 0.9, 121)
        arc = lambda R: q + R * np.stack([np.cos(span), np.sin(span)], axis=-1)
        return [self.axis_segment(m), arc(m.R0), arc(m.R1), _dwell_path(m, m.dwell)]


@register(LambdaRockerSixBar)
class RockerSixBarDrawing(LinkageDrawing):
    """МЧВ1: the dwell part of D's path and the output rocker highlighted during the dwell."""

    n_extras = 2
    extra_styles = {1: HIGHLIGHT_STYLE}

    def extras(self, i):
        m, mo = self.mechanism, self.motion
        seg = np.full((2, 2), np.nan)
        if _in_dwell(mo.phi[i], m.dwell):
            seg = np.array([mo.points["F"].p[i], mo.points["E"].p[i]])
        return [_dwell_path(m, m.dwell), seg]


@register(LambdaSlottedSixBar)
class SlottedSixBarDrawing(LinkageDrawing):
    """МЧВ3: the slotted link (a bar through the pivot along the slot), highlighted in the dwell."""

    n_extras = 3
    extra_styles = {0: OUTPUT_STYLE, 2: HIGHLIGHT_STYLE}
    numbered_extras = (0,)

    def extras(self, i):
        m, mo = self.mechanism, self.motion
        P = mo.points["P"].p[i]
        u = np.array([np.cos(mo.psi[i]), np.sin(mo.psi[i])])
        base = P + m.offset * np.array([-u[1], u[0]])  # the slot is on the left of P for offset > 0
        reach = 1.2 * np.max(np.hypot(*(mo.points["D"].p - P).T))
        bar = np.array([P, base, base + reach * u]) if m.offset else np.array([P - reach * u, P + reach * u])
        hl = bar if _in_dwell(mo.phi[i], m.dwell) else np.full((2, 2), np.nan)
        return [bar, _dwell_path(m, m.dwell), hl]
