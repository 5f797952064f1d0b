"""Chebyshev lambda mechanisms with a dwell and the six-bars built on them (seed 001).

:mod:`.lambda_mechanism` — the symmetric lambda mechanism, circle/straight-line guiding
synthesis and the existence map; :mod:`.sixbars` — МЧВ1 (rocker) and МЧВ3 (slotted link)
six-bars; :mod:`.sliders` — МЧВ2 (rod and slider) and МЧВ5 (translating slotted link);
:mod:`.forces` — their loads, reactions and efficiency.
"""

from .lambda_mechanism import *  # noqa: F401,F403
from .lambda_mechanism import __all__ as _a
from .sixbars import *  # noqa: F401,F403
from .sixbars import __all__ as _b
from .sliders import *  # noqa: F401,F403
from .sliders import __all__ as _c

__all__ = [*_a, *_b, *_c]
