"""The map of where circle_guiding designs (chapter 6's figure): each cell is what circle_guiding says there."""

import matplotlib

matplotlib.use("Agg")

import numpy as np
import pytest

from mechlab.errors import DimensionError, MechanismError, NoDesignError
from mechlab.synthesis.lambda_guiding import OUTCOMES, circle_guiding, design_outcomes

DEG = np.pi / 180


def _direct(delta, a, dwell):
    try:
        circle_guiding(delta, a, dwell, minimax=False)
        return "design"
    except NoDesignError as err:
        return err.kind
    except MechanismError:
        return "frame" if a == 0 else "unresolved"


def test_each_cell_is_what_circle_guiding_says():
    m = design_outcomes(150 * DEG, fractions=(0.0, 0.5, 1.0), dwells=(60 * DEG, 180 * DEG, 2 * np.pi))
    assert m.kind.shape == (3, 3) and set(m.kind.ravel()) <= set(OUTCOMES)
    lo, hi = m.span
    assert m.a[0] == lo and np.isclose(m.a[-1], hi) and 0 <= lo < hi
    for i, a in enumerate(m.a):
        for j, dw in enumerate(m.dwell):
            assert m.kind[i, j] == _direct(150 * DEG, a, dw), (a, dw)
    assert m.kind[1, 0] == m.kind[1, 1] == "design"  # the middle of the span, ordinary dwells
    assert m.kind[0, 0] == "frame"  # a = 0 is no frame


def test_bad_requests_are_named():
    with pytest.raises(DimensionError, match="fractions"):
        design_outcomes(150 * DEG, fractions=(1.5,))
    with pytest.raises(DimensionError, match="dwells"):
        design_outcomes(150 * DEG, dwells=(-1.0,))
    with pytest.raises(DimensionError, match="MAX_OUTCOMES"):
        design_outcomes(150 * DEG, fractions=np.linspace(0, 1, 100), dwells=np.linspace(0.1, 1, 100))
    with pytest.raises(DimensionError):
        design_outcomes(float("nan"))


def test_plot_marks_every_request():
    from mechlab.draw import OUTCOME_STYLE, plot_design_outcomes

    m = design_outcomes(180 * DEG, fractions=(0.25, 0.5), dwells=(90 * DEG, 120 * DEG))
    fig = plot_design_outcomes([m])
    ax = fig.axes[0]
    markers = [ln for ln in ax.lines if len(ln.get_xdata()) == 1]
    assert len(markers) == m.kind.size
    assert {ln.get_marker() for ln in markers} == {OUTCOME_STYLE[k][0] for k in m.kind.ravel()}
    assert ax.get_xlabel() == "frame a (units of l)" and fig.axes[0].get_ylabel() == "dwell 2α (degrees)"
    with pytest.raises(TypeError):
        plot_design_outcomes(["not a map"])
