"""Hypothesis strategies for random valid geometries, shared by the test modules."""

import numpy as np
from hypothesis import assume
from hypothesis import strategies as st

from mechlab import FourBar, SliderCrank

lengths = st.floats(min_value=0.2, max_value=10.0, allow_nan=False, allow_infinity=False)
signs = st.sampled_from([1, -1])


@st.composite
def revolving_fourbars(draw):
    """Four-bars whose crank turns fully (crank-rockers and double-cranks), built so:
    the crank a must satisfy g + a < c + r and |g - a| > |c - r|, kept 3 % away from
    the dead points."""
    c, r, g = draw(lengths), draw(lengths), draw(lengths)
    m = 0.03 * (c + r)
    hi = c + r - g - m
    windows = [(0.05, min(hi, g - abs(c - r) - m)), (g + abs(c - r) + m, hi)]
    windows = [(lo, up) for lo, up in windows if up - lo > 1e-3]
    assume(windows)
    lo, up = windows[draw(st.integers(0, len(windows) - 1))]
    a = lo + draw(st.floats(0.0, 1.0)) * (up - lo)
    return FourBar(a, c, r, g, draw(signs))


@st.composite
def fourbars(draw):
    """Any assemblable four-bar (its crank may only rock)."""
    a, c, r, g = draw(lengths), draw(lengths), draw(lengths), draw(lengths)
    lo, hi = (a * a + g * g - (c + r) ** 2) / (2 * a * g), (a * a + g * g - (c - r) ** 2) / (2 * a * g)
    # stay clear of the degenerate cases where a dead point sits at φ = 0 or π
    assume(lo < 0.98 and hi > -0.98 and hi - lo > 0.02 and abs(hi - 1) > 0.02 and abs(lo + 1) > 0.02)
    return FourBar(a, c, r, g, draw(signs))


@st.composite
def revolving_slider_cranks(draw):
    a, l = draw(lengths), draw(lengths)
    e = draw(st.floats(min_value=-5.0, max_value=5.0))
    assume(a + abs(e) < 0.97 * l)
    return SliderCrank(a, l, e, draw(signs))


def central_difference(f, h):
    """Second-order central difference of samples on a uniform grid (interior points)."""
    return (f[2:] - f[:-2]) / (2 * h)


def fine_grid(mechanism, n=20001):
    phi = mechanism.cycle(n)
    return phi, phi[1] - phi[0]


__all__ = ["central_difference", "fine_grid", "fourbars", "np", "revolving_fourbars", "revolving_slider_cranks"]
