"""The capstone's (chapter 12's) check cells verify whatever design the student leaves: they pass for the
committed first attempt (which misses its stroke), for the intended fix and for another family, and fail when
the report does not describe the design in the cell; no check cell moves the student's explorer, which opens
on exactly the specification the text states.

The cells are taken from the notebook by their ids and run in one namespace, as the kernel would run them.
"""

import json
import re
from pathlib import Path

import matplotlib
import numpy as np
import pytest

matplotlib.use("Agg")

NOTEBOOK = Path(__file__).parent.parent / "notebooks" / "12_choosing_a_mechanism.ipynb"
CELLS = {c["id"]: "".join(c["source"]) for c in json.loads(NOTEBOOK.read_text())["cells"]}
IMPORTS, SPEC, EXPLORER, EXPLORER_CHECK = "fcde75aa", "dbea240e", "8f437d6c", "47eb75d1"
DESIGN, DESIGN_CHECK = "254f406b", "b16b774f"


def run(ns: dict, *ids: str) -> dict:
    for cid in ids:
        exec(compile(CELLS[cid], f"cell {cid}", "exec"), ns)
    return ns


def student(edit=None) -> dict:
    """The design cell as a student leaves it: ``edit`` rewrites its source (None: as committed)."""
    ns = run({}, IMPORTS)
    code = CELLS[DESIGN] if edit is None else edit(CELLS[DESIGN])
    exec(compile(code, "the student's design cell", "exec"), ns)
    return ns


def check(ns: dict) -> None:
    exec(compile(CELLS[DESIGN_CHECK], f"cell {DESIGN_CHECK}", "exec"), ns)


def with_scale(expr: str):
    return lambda code: re.sub(r"^my_scale = .*$", f"my_scale = {expr}", code, flags=re.M)


def test_the_cells_are_where_the_test_looks():
    assert "my_scale = 250.0" in CELLS[DESIGN] and "report = design.check_design" in CELLS[DESIGN]
    assert "choosing_explorer(table" in CELLS[EXPLORER]


def test_the_first_attempt_misses_and_its_check_passes():
    ns = student()
    check(ns)
    assert not ns["report"].met and [v.criterion for v in ns["report"].verdicts if not v.met] == ["amplitude"]


def test_the_intended_fix_meets_the_specification_and_its_check_passes():
    stroke = "np.ptp(my_design.motion(np.linspace(0, 2 * np.pi, 2881)).output.value)"
    ns = student(with_scale(f"120 / {stroke}"))
    check(ns)
    assert ns["report"].met


def test_another_family_is_checked_too():
    def cam(code):
        return code.replace("my_design = ml.mchv2(guide, 1.0)", "my_design = design.candidates(printer).candidates[-1]"
                            ".design.mechanism").replace("my_scale = 250.0", "my_scale = 1.0")
    ns = student(cam)
    check(ns)
    assert ns["report"].verdicts[0].met     # the candidate was scaled to the stroke by the comparison


def test_a_report_left_from_an_earlier_design_fails_the_check():
    ns = student()
    ns["my_scale"] = 300.0               # changed, but the cell that makes the report not run again
    with pytest.raises(AssertionError, match="run that cell again"):
        check(ns)


def test_a_report_for_another_specification_fails_the_check():
    ns = student()
    ns["report"] = ns["design"].check_design(ns["design"].Specification(
        "stroke", 1 / 4, amplitude=80.0, mass=6.0), ns["my_design"], scale=ns["my_scale"])
    with pytest.raises(AssertionError, match="another specification"):
        check(ns)


def test_a_verdict_that_contradicts_its_lines_fails_the_check():
    from dataclasses import replace
    ns = student()
    first = replace(ns["report"].verdicts[0], met=True)   # "met" although the stroke is 80 mm of 120
    ns["report"] = replace(ns["report"], verdicts=(first,) + ns["report"].verdicts[1:])
    with pytest.raises(AssertionError):
        check(ns)


def test_the_check_cell_does_not_show_the_fix():
    assert "120" not in CELLS[DESIGN_CHECK] and "/ stroke" not in CELLS[DESIGN_CHECK]
    assert "scale=" not in CELLS[DESIGN_CHECK]


@pytest.fixture(scope="module")
def explorer_ns():
    return run({}, IMPORTS, SPEC, EXPLORER)


def test_the_explorer_opens_on_the_stated_specification(explorer_ns):
    ex, table = explorer_ns["explorer"], explorer_ns["table"]
    assert table.dwell_fraction == 1.0 / 1.5 and table.stations == 6 and table.rpm == 40
    assert ex.spec() == table and ex.comparison.spec == table
    refused = {r.family: r.reason for r in ex.comparison.refusals}
    assert refused["internal Geneva"].endswith("0.667 was asked (± 0.030)")
    # a slider moved away and back stands for the text's value again, not for the slider's rounding
    ex.sliders["dwell_fraction"].value = 0.5
    assert ex.spec().dwell_fraction == 0.5
    ex.sliders["dwell_fraction"].value = round(1.0 / 1.5, 2)
    assert ex.spec() == table


def test_no_check_cell_moves_the_students_explorer(explorer_ns):
    ex = explorer_ns["explorer"]
    ex.sliders["rpm"].value = 60.0       # where a student left it
    before, spec = {k: w.value for k, w in ex.sliders.items()}, ex.spec()
    with pytest.raises(AssertionError):  # the check sees the moved explorer, and only looks
        run(explorer_ns, EXPLORER_CHECK)
    assert {k: w.value for k, w in ex.sliders.items()} == before and ex.spec() == spec


def test_check_cells_assign_no_widget_state():
    cells = json.loads(NOTEBOOK.read_text())["cells"]
    checks = ["".join(c["source"]) for c in cells if "check" in c.get("metadata", {}).get("tags", [])]
    assert len(checks) >= 4
    for code in checks:
        assert not re.search(r"\bexplorer\.\w+(\[[^]]*\])?\.value\s*=", code), code
    assert re.search(r"\bexplorer\.\w+(\[[^]]*\])?\.value\s*=", 'explorer.sliders["x"].value = 4')


def _pixels(png: bytes) -> np.ndarray:
    import io

    from PIL import Image
    return np.asarray(Image.open(io.BytesIO(png)).convert("RGB")).astype(int)


def test_a_release_redraws_only_the_data_and_the_picture_is_the_full_drawing():
    import io
    import time

    from mechlab import design
    from mechlab.widgets.design import ChoosingExplorer
    ns = run({}, IMPORTS, SPEC)
    ex = ChoosingExplorer(ns["table"], live=False)
    cpu = []
    for v in (0.60, 0.70, 0.40, 0.75, 0.67):   # 0.40 refuses every family: the lines hide, the axes stay
        start = time.process_time()
        ex.sliders["dwell_fraction"].value = v
        cpu.append(time.process_time() - start)
    assert sorted(cpu)[2] < 0.15, cpu           # the median release: comparison and picture, CPU seconds
    full = io.BytesIO()
    ex.figure.fig.savefig(full, format="png")
    differ = np.abs(_pixels(ex.output.value) - _pixels(full.getvalue())).max(axis=2) > 40
    assert differ.mean() < 1e-3                 # the same picture, up to a few antialiased pixels
    swing = ChoosingExplorer(design.Specification("swing", 40 / 360, amplitude=np.radians(40), impacts="none",
                                                  max_pressure_angle=np.radians(60)), live=False)
    swing.sliders["amplitude"].value = 60.0
    full = io.BytesIO()
    swing.figure.fig.savefig(full, format="png")
    assert (np.abs(_pixels(swing.output.value) - _pixels(full.getvalue())).max(axis=2) > 40).mean() < 1e-3
    swing.figure.laws.set_ylim(-0.5, 2.0)        # new limits, new tick labels: the axes are drawn again
    swing._redraw()
    full = io.BytesIO()
    swing.figure.fig.savefig(full, format="png")
    assert (np.abs(_pixels(swing.output.value) - _pixels(full.getvalue())).max(axis=2) > 40).mean() < 1e-3
