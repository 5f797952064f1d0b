"""The map of where circle_guiding designs (chapter 6's figure): each cell is what circle_guiding says there."""

import matplotlib

matplotlib.use("Agg")

import numpy as np
import pytest

from mechlab.errors import DimensionError, MechanismError, NoDesignError, SynthesisError
from mechlab.synthesis import lambda_guiding
from mechlab.synthesis.lambda_guiding import OUTCOMES, circle_guiding, design_outcomes

DEG = np.pi / 180
REFUSALS = set(OUTCOMES) - {"design", "unresolved"}  # the kinds a NoDesignError names


def test_each_cell_is_what_circle_guiding_says():
    m = design_outcomes(150 * DEG, fractions=(0.0, 0.5, 1.0), dwells=(60 * DEG, 180 * DEG, 2 * np.pi))
    lo, hi = m.span
    assert m.a[0] == lo and np.isclose(m.a[-1], hi) and 0 <= lo < hi
    # a = 0 and the span's far end are no frames; mid-span designs exist up to 2α = 180°, but a whole turn
    # needs a on the whole-turn line (Fig. 2a)
    assert m.kind.tolist() == [["frame"] * 3, ["design", "design", "whole turn"], ["frame"] * 3]
    # each cell against circle_guiding's own answer there: the design it returns or the error's evidence
    for i, a in enumerate(m.a):
        for j, dw in enumerate(m.dwell):
            try:
                g = circle_guiding(150 * DEG, a, dw, minimax=False)
            except NoDesignError as err:
                assert m.kind[i, j] == err.kind and err.kind in REFUSALS, (a, dw)
                if "span" in err.evidence:  # a frame or whole-turn refusal: a lies outside what it names
                    assert not err.evidence["span"][0] < a < err.evidence["span"][1], (a, dw, err.evidence)
            except MechanismError as err:  # no refusal: "frame" only where the error is about a itself
                assert m.kind[i, j] == ("frame" if str(err).startswith("a must be") else "unresolved"), (a, dw)
            else:
                assert m.kind[i, j] == "design" and np.isclose(g.a, a) and np.isclose(g.dwell, dw), (a, dw)


def test_each_outcome_of_a_request_gets_its_kind(monkeypatch):
    """The classification on requests whose outcomes are set here, one per dwell: a design, two refusals,
    an error that is no refusal (at a = 0: no frame; elsewhere: unresolved), and a bug, which is not hidden."""
    outcomes = {1.0: None, 2.0: NoDesignError("no design", "fold"), 3.0: NoDesignError("no design", "rotation"),
                4.0: SynthesisError("the solve did not converge"), 5.0: ValueError("a bug")}

    def request(delta, a, dwell, minimax=True):
        if outcomes[dwell] is not None:
            raise outcomes[dwell]
        return "a design"

    monkeypatch.setattr(lambda_guiding, "circle_guiding", request)
    m = design_outcomes(150 * DEG, fractions=(0.0, 0.5), dwells=(1.0, 2.0, 3.0, 4.0))
    assert m.a[0] == 0 < m.a[1]
    assert m.kind.tolist() == [["design", "fold", "rotation", "frame"], ["design", "fold", "rotation", "unresolved"]]
    with pytest.raises(ValueError, match="a bug"):
        design_outcomes(150 * DEG, fractions=(0.5,), dwells=(5.0,))


def test_bad_requests_are_named():
    with pytest.raises(DimensionError, match=r"fractions must be ≤ 1, got 1.5"):
        design_outcomes(150 * DEG, fractions=(1.5,))
    with pytest.raises(DimensionError, match="dwells must be ≥ 0 rad"):
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


def test_stored_maps_are_design_outcomes_of_today():
    """The companion's three stored maps: the default grid at each stored δ, their spans as the code has them,
    and in each map one request of every kind it holds, plus two designs, drawn at random, recomputed here
    (a change of circle_guiding that alters an outcome fails this until the file is rebuilt)."""
    maps = lambda_guiding.load_design_outcomes()
    assert [m.delta for m in maps] == list(lambda_guiding.STORED_OUTCOME_DELTAS)
    rng = np.random.default_rng(6)
    for m in maps:
        assert np.array_equal(m.fraction, lambda_guiding.OUTCOME_FRACTIONS)
        assert np.array_equal(m.dwell, lambda_guiding.OUTCOME_DWELLS)
        lo, hi = lambda_guiding._frame_span(m.delta)
        # the span's upper end for δ < 120° comes from a continuation: equal to rounding, which differs between CPUs
        assert np.allclose(m.span, (lo, hi), rtol=0, atol=1e-12)
        assert np.allclose(m.a, lo + (hi - lo) * m.fraction, rtol=0, atol=1e-12)
        kinds = set(m.kind.ravel())
        assert "design" in kinds and "unresolved" not in kinds and len(kinds) >= 3
        picks = [tuple(rng.choice(np.argwhere(m.kind == kind))) for kind in sorted(kinds)]
        picks += [tuple(ij) for ij in rng.choice(np.argwhere(m.kind == "design"), 2, replace=False)]
        for i, j in picks:
            fresh = design_outcomes(m.delta, fractions=(m.fraction[i],), dwells=(m.dwell[j],))
            assert fresh.kind[0, 0] == m.kind[i, j], (np.degrees(m.delta), m.fraction[i], np.degrees(m.dwell[j]))


def test_maps_are_read_back_as_written(tmp_path):
    small = design_outcomes(150 * DEG, fractions=(0.0, 0.5, 1.0), dwells=(60 * DEG, 2 * np.pi))
    path = lambda_guiding.save_design_outcomes([small, small], tmp_path / "maps.npz")
    back = lambda_guiding.load_design_outcomes(path)
    assert len(back) == 2
    for m in back:
        assert m.delta == small.delta and m.span == small.span and m.kind.tolist() == small.kind.tolist()
        assert all(np.array_equal(getattr(m, f), getattr(small, f)) for f in ("fraction", "a", "dwell"))
    with pytest.raises(DimensionError, match="is no file"):
        lambda_guiding.load_design_outcomes(tmp_path / "none.npz")
    (tmp_path / "other.npz").write_bytes(b"not a map")
    with pytest.raises(DimensionError, match="holds no maps"):
        lambda_guiding.load_design_outcomes(tmp_path / "other.npz")
    with pytest.raises(DimensionError, match="at least one"):
        lambda_guiding.save_design_outcomes([], tmp_path / "empty.npz")
    with pytest.raises(TypeError, match="maps"):
        lambda_guiding.save_design_outcomes([small.kind], tmp_path / "bad.npz")
