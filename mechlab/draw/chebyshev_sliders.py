"""Drawings of the translating-output lambda six-bars МЧВ2 and МЧВ5 (Kinitsky, 1994, Fig. 1 в, д).

Protocol of :class:`mechlab.draw.LinkageDrawing` (artists made once, moved by ``set_frame``).
Extras: the fixed guide line (and, for МЧВ2, the slider block on it; for МЧВ5 the output link:
its slot through D and its bar along the guide), the dwell part of D's path, and the output
re-drawn in the highlight colour while the crank is inside the designed dwell.
"""

from __future__ import annotations

import numpy as np

from ..mechanisms.lambda_sliders import LambdaSliderSixBar, LambdaTranslatingSlot
from . import GUIDE_STYLE, HIGHLIGHT_STYLE, OUTPUT_STYLE, LinkageDrawing, register
from .chebyshev import _dwell_path, _in_dwell

_NAN = np.full((2, 2), np.nan)


def _block(centre, u, size):
    """A square slider block of side ``size`` centred on ``centre``, aligned with u (closed polyline)."""
    n = np.array([-u[1], u[0]])
    h = size / 2
    return np.array([centre + h * (a * u + b * n) for a, b in ((-1, -1), (1, -1), (1, 1), (-1, 1), (-1, -1))])


@register(LambdaSliderSixBar)
class SliderSixBarDrawing(LinkageDrawing):
    """МЧВ2: the guide through Q, the slider block at E (highlighted in the dwell), D's dwell path."""

    n_extras = 4
    extra_styles = {0: GUIDE_STYLE, 1: OUTPUT_STYLE, 3: HIGHLIGHT_STYLE}
    numbered_extras = (1,)

    def extras(self, i):
        m, mo = self.mechanism, self.motion
        u = m.u
        s = mo.s
        size = 0.2 * m.rod
        guide = np.array([m.Q + (s.min() - 2 * size) * u, m.Q + (s.max() + 2 * size) * u])
        block = _block(mo.points["E"].p[i], u, size)
        hl = block if _in_dwell(mo.phi[i], m.dwell) else _NAN
        return [guide, block, _dwell_path(m, m.dwell), hl]


@register(LambdaTranslatingSlot)
class TranslatingSlotDrawing(LinkageDrawing):
    """МЧВ5: the fixed guide, the output link (slot through D and a bar along the guide, highlighted
    in the dwell), the block at D and D's dwell path."""

    n_extras = 5
    extra_styles = {0: GUIDE_STYLE, 1: OUTPUT_STYLE, 2: OUTPUT_STYLE, 4: HIGHLIGHT_STYLE}
    numbered_extras = (1,)

    def extras(self, i):
        m, mo = self.mechanism, self.motion
        v, w = np.array([np.cos(m.slot), np.sin(m.slot)]), np.array([np.cos(m.guide), np.sin(m.guide)])
        E, D = mo.points["E"].p[i], mo.points["D"].p[i]
        D_all = mo.points["D"].p
        # the slot spans D's whole sweep along it, the bar reaches back along the guide past the curve
        along = (D_all - E) @ v
        reach = float(np.ptp(D_all @ w)) + 0.3
        slot = np.array([E + (along.min() - 0.1) * v, E + (along.max() + 0.1) * v])
        link = np.array([slot[0], slot[1], E, E + reach * w])
        # the fixed guide: a bushing (two short rails either side of the bar) beyond the bar's travel
        s, n, g = mo.s, np.array([-w[1], w[0]]), 0.04
        lo, hi = m.P + (s.max() + 0.4 * reach) * w, m.P + (s.max() + 0.8 * reach) * w
        guide = np.array([lo + g * n, hi + g * n, [np.nan, np.nan], lo - g * n, hi - g * n])
        size = 0.08
        block = _block(D, v, size)
        hl = link if _in_dwell(mo.phi[i], m.dwell) else np.full((4, 2), np.nan)
        return [guide, link, block, _dwell_path(m, m.dwell), hl]
