"""One dwell fraction: the design layer, the mechanisms and chapter 12 give the same numbers.

The **dwell fraction** is the share of the turn over which the output stands exactly still; the
**near-standstill fraction** the longer share over which it stays within a band (the design layer's
``dwell_precision``). Each family's mechanism that knows its own figure is compared with the design
layer's, measured from the simulated motion; chapter 12's printed numbers are compared with both.
"""

import contextlib
import io
import re
from pathlib import Path

import nbformat
import numpy as np
import pytest

import mechlab as ml
from mechlab import design as D
from mechlab.design.candidates import limits
from mechlab.design.criteria import SAMPLES

CHAPTER = Path(__file__).resolve().parents[1] / "notebooks" / "12_choosing_a_mechanism.ipynb"
GRID = 2 / SAMPLES  # the near-standstill is measured on the judge's grid: one sample at each end


def _candidate(spec, family):
    comp = D.candidates(spec, [family])
    assert comp.candidates, comp.refusals
    return comp.candidates[0]


def _exact(cand):
    """The family's own exact dwell fraction, from its mechanism's dimensions."""
    m = cand.design.mechanism
    if hasattr(m, "dwell_fraction"):  # the Geneva drives
        return m.dwell_fraction
    if hasattr(m, "programme"):  # the cam: its dwells are the turn less rise and return (outer dwell 0 here)
        p = m.programme
        assert p.outer_dwell == 0.0
        return 1.0 - (p.rise + p.ret) / (2 * np.pi)
    return (m.phi2 - m.phi1) / (2 * np.pi)  # the curved slot: the slot's arc about the crank's centre


EXACT = [
    ("external Geneva", D.Specification("index", 3 / 4, stations=4, inertia=1.0)),
    ("external Geneva", D.Specification("index", 2 / 3, stations=6, inertia=2.4, rpm=40)),
    ("external Geneva", D.Specification("index", 5 / 8, stations=8, inertia=1.0)),
    ("internal Geneva", D.Specification("index", 1 / 3, stations=6, inertia=1.0)),
    ("spherical Geneva", D.Specification("index", 2 / 3, stations=6, inertia=2.4, rpm=40)),
    ("curved slot", D.Specification("swing", 40 / 360, amplitude=np.radians(40),
                                     max_pressure_angle=np.radians(60))),
    ("disc cam", D.Specification("stroke", 1 / 3, amplitude=120.0, mass=6.0, max_pressure_angle=np.radians(60))),
    ("disc cam", D.Specification("swing", 0.3, amplitude=np.radians(30), max_pressure_angle=np.radians(35))),
]


@pytest.mark.parametrize("family, spec", EXACT, ids=[f"{f}-{s.dwell_fraction:.3f}" for f, s in EXACT])
def test_the_design_layers_dwell_is_the_mechanisms_exact_dwell(family, spec):
    cand = _candidate(spec, family)
    c = cand.criteria
    assert c.dwell_fraction == pytest.approx(_exact(cand), abs=1e-6)
    # the near-standstill is the longer figure, and the one the specification is judged by
    assert c.standstill_fraction >= c.dwell_fraction - GRID
    assert c.standstill_fraction >= spec.dwell_fraction - spec.dwell_tolerance
    m = cand.design.mechanism
    if hasattr(m, "standstill_fraction"):  # the planar Geneva's closed form of the same band
        assert abs(c.standstill_fraction - m.standstill_fraction(spec.dwell_precision)) <= GRID


@pytest.mark.parametrize("family, spec", [
    ("lambda six-bar, type 1 (rocker dwell)", D.Specification("swing", 40 / 360, amplitude=np.radians(40),
                                                             max_pressure_angle=np.radians(60))),
    ("lambda six-bar, type 2 (slider dwell)", D.Specification("stroke", 1 / 3, amplitude=120.0, mass=6.0,
                                                             max_pressure_angle=np.radians(60))),
])
def test_an_approximate_dwell_is_only_a_near_standstill(family, spec):
    # Chebyshev's six-bars never stand exactly still: their dwell fraction is 0, and the specification's
    # dwell is met by their near-standstill
    c = _candidate(spec, family).criteria
    assert c.dwell_fraction == 0.0
    assert c.standstill_fraction >= spec.dwell_fraction - spec.dwell_tolerance
    verdict = next(v for v in limits(spec, c) if v.criterion == "dwell")
    assert verdict.met and f"near-standstill {c.standstill_fraction:.3f}" in verdict.text
    assert "exact dwell 0.000" in verdict.text


def _run_chapter(ids):
    """Execute chapter 12's code cells ``ids`` in order (in this process) and return their namespace and
    printed text: what the chapter prints, from the same library calls."""
    cells = {c.id: c for c in nbformat.read(CHAPTER, as_version=4).cells}
    ns, out = {}, io.StringIO()
    with contextlib.redirect_stdout(out):
        for i in ids:
            exec(compile(cells[i].source, f"{CHAPTER.name}:{i}", "exec"), ns)
    return ns, out.getvalue(), [c.source for c in cells.values() if c.cell_type == "markdown"]


def test_chapter_12_prints_the_mechanisms_dwell_and_near_standstill():
    ns, printed, prose = _run_chapter(["fcde75aa", "dbea240e", "6dd8084d", "046df7cf", "046df7cf-spherical"])
    comparison, table = ns["comparison"], ns["table"]
    ext = next(c for c in comparison.candidates if c.family == "external Geneva")
    sph = next(c for c in comparison.candidates if c.family == "spherical Geneva")
    g = ext.design.mechanism
    exact, near = f"{g.dwell_fraction:.3f}", f"{g.standstill_fraction(table.dwell_precision):.3f}"
    assert (exact, near) == ("0.667", "0.680")
    # the printed sentences: the exact dwell, as the prose's (1/2 + 1/z), and the near-standstill
    assert re.search(r"exactly still for (\d\.\d{3}) of the turn \(1/2 \+ 1/z\)", printed).group(1) == exact
    assert g.dwell_fraction == pytest.approx(1 / 2 + 1 / g.z)
    assert re.search(r"of its index step: (\d\.\d{3})", printed).group(1) == near
    assert re.search(r"gives the dwell, (\d\.\d{3})", printed).group(1) == f"{sph.design.mechanism.dwell_fraction:.3f}"
    # the table the chapter shows: its dwell column is the exact one, its near-standstill column the band's
    head, *rows = comparison.rows()
    row = next(r for r in rows if r[0] == "external Geneva")
    assert row[head.index("dwell (of turn)")] == exact and row[head.index("near-standstill (of turn)")] == near
    # the prose quotes no other dwell figure than these
    quoted = {q for text in prose for q in re.findall(r"\b0\.\d{3}\b", text)}
    assert quoted <= {exact, near, f"{table.dwell_precision:.3f}"}, quoted  # the band, 0.001 of the amplitude


INDEXING = EXACT[:5]   # the Geneva drives: intermittency is defined for an output that indexes, not a rocker


@pytest.mark.parametrize("family, spec", INDEXING, ids=[f"{f}-{s.dwell_fraction:.3f}" for f, s in INDEXING])
def test_the_analysis_layers_dwell_is_the_same_exact_dwell(family, spec):
    # mechlab.analysis.intermittency (chapter 10's comparison table) counts the samples where the output is
    # exactly still: the same figure as the design layer, to one sample at each end of the dwell
    cand = _candidate(spec, family)
    m, n = cand.design.mechanism, 7201
    row = ml.intermittency(m, n=n, phase=1e-3)
    assert row.dwell_fraction == pytest.approx(cand.criteria.dwell_fraction, abs=2 / (n - 1))
    # a tolerance widens only the near-standstill (the planar drives' slow ends; the spherical one enters
    # with a velocity jump), never the dwell
    loose = ml.intermittency(m, n=n, phase=1e-3, dwell_tol=0.05)
    assert loose.dwell_fraction == row.dwell_fraction <= loose.standstill_fraction
    assert (loose.standstill_fraction > row.dwell_fraction) == (m.impacts().kind != "hard")


def test_an_approximate_dwell_has_no_exact_dwell_in_the_analysis_layer():
    from mechlab.synthesis.lambda_guiding import straight_guiding
    from mechlab.synthesis.lambda_sixbars import mchv3_half_turn

    six = mchv3_half_turn(straight_guiding(np.pi, 0.8, np.pi))
    row = ml.intermittency(six, n=3601, phase=1e-3, dwell_tol=1e-2)
    assert row.dwell_fraction == 0.0 and row.standstill_fraction > 0.5


def test_one_threshold_of_still():
    """The dwell fraction, the dwell's ends (design criteria) and the still output of the inverse problem use
    the one threshold mechlab.motion.STILL: a second constant would let the table and the chart disagree."""
    import mechlab.analysis.intermittency as intermittency
    import mechlab.design.criteria as criteria
    import mechlab.kinetostatics.inverse as inverse
    from mechlab.motion import STILL

    assert criteria.STILL is STILL and inverse.STILL is STILL and intermittency.STILL is STILL
    assert intermittency.DWELL_TOL == STILL

