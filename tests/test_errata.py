"""The errata registry: kinds kept apart, every claim falsifiable (issue 15)."""

import re
from dataclasses import replace

import numpy as np
import pytest

from mechlab.course.errata import Claim, Erratum, collect, table

ERRATA = collect()


def _id(e):
    return f"{e.source} {e.where}"[:60]


def _mutations(claim):
    """The claim with its correction moved a tenth of the way toward the printed value (a boolean entry:
    flipped), one entry at a time, at each entry that carries the mistake (the printed value misses there)."""
    t = np.asarray(claim.truth, dtype=float)
    p, c = (np.broadcast_to(np.asarray(v, dtype=float), t.shape).copy() for v in (claim.printed, claim.correct))
    tol = claim.tol if claim.printed_tol is None else claim.printed_tol
    ptol = np.broadcast_to(np.asarray(tol, dtype=float), t.shape)
    boolean = np.asarray(claim.truth).dtype == bool
    for i in np.ndindex(t.shape):
        if abs(p[i] - t[i]) > ptol[i]:
            m = c.copy()
            m[i] = 1 - m[i] if boolean else c[i] + 0.1 * (p[i] - c[i])
            yield i, (m if t.shape else float(m))


# each erratum's check runs in its own test: one that fails names itself, the others still pass
@pytest.mark.parametrize("e", ERRATA, ids=_id)
def test_every_printed_mistake_evaluates_both_expressions_and_fails_if_the_printed_one_is_fed_as_correct(e):
    out = e.check()
    if e.kind == "mistake":
        assert isinstance(out, Claim), "a printed mistake must evaluate the printed and the corrected expression"
    if not isinstance(out, Claim):
        assert isinstance(out, str) and out
        return
    assert out.judge()
    # the printed expression, fed in as if it were the correction, must fail the check
    with pytest.raises(AssertionError, match="misses the truth"):
        replace(out, correct=out.printed).judge()
    # and a check that called the corrected expression "printed" would not list a mistake
    with pytest.raises(AssertionError, match="not a mistake"):
        replace(out, printed=out.correct).judge()


@pytest.mark.parametrize("e", ERRATA, ids=_id)
def test_every_check_fails_when_the_value_it_guards_is_perturbed(e):
    """A check whose tolerance is looser than the mistake it lists cannot fail: moving the correction a
    tenth of the way toward the printed value (each entry alone) must be refused."""
    out = e.check()
    if not isinstance(out, Claim):
        # a remark or an unreadable passage prints no value to move: it must not be a mistake, and its
        # evidence (asserted inside its check) is computed numbers, not words alone
        assert e.kind != "mistake" and re.search(r"\d(\.\d|e-\d)", out), out
        return
    mutations = list(_mutations(out))
    assert mutations, "no entry of the printed expression misses the truth"
    for _i, m in mutations:
        with pytest.raises(AssertionError, match="misses the truth"):
            replace(out, correct=m)


def test_claim_judges_on_the_numbers():
    ok = Claim(1.0, 1.5, 1.0 + 1e-12, 1e-9, "x")
    assert "printed off by 0.5" in ok.judge() == str(ok)
    with pytest.raises(AssertionError, match="not a mistake"):
        Claim([1.0, 2.0], [1.5, 2.0], [1.0, 2.0], 1e-9, "one printed entry is right").judge()
    assert Claim([1.0, 2.0], [1.5, 2.0], [1.0, 2.0], 1e-9, "the worst", each=False).judge()
    with pytest.raises(AssertionError, match="misses"):
        Claim(1.0, 2.0, 1.1, 0.05, "x").judge()


def test_a_mistake_without_a_claim_is_refused():
    with pytest.raises(TypeError, match="must return a Claim"):
        Erratum("000", "x", "a", "b", lambda: "only words").evidence()
    assert Erratum("000", "x", "a", "b", lambda: "only words", kind="remark").evidence() == "only words"


def test_the_table_shows_the_kind():
    rows = [e for e in ERRATA if e.source == "001" and e.kind != "unreadable"][:2]
    md = table(rows)
    assert md.splitlines()[0] == "| source | kind | where | printed | correct | evidence |"
    assert all(f"| 001 | {e.kind} |" in md for e in rows)


def test_claim_tolerances_per_entry_and_for_the_printed_side():
    # an exact correction, a printed value rounded to two decimals: the printed side needs its own margin
    assert Claim(np.pi**2 / 2, 4.94, np.pi**2 / 2, 1e-9, "rounded", printed_tol=0.005).judge()
    with pytest.raises(AssertionError, match="not a mistake"):
        Claim(np.pi**2 / 2, 4.935, np.pi**2 / 2, 1e-9, "rounded right", printed_tol=0.005)
    with pytest.raises(AssertionError, match="misses the truth"):
        Claim([0.4530, 45.58], [0.46, 52.93], [0.4578, 45.58], [0.0005, 0.005], "per entry")


def test_reclassified_entries():
    """The crank-moment equation is exact under the source's uniform rotation: a remark; the two
    Kozhevnikov entries rest on one guessed reading of a garbled line: unreadable; the middle piece of β
    (the source's (23)) is listed."""
    by = {(e.source, e.where): e for e in ERRATA}
    crank = [e for (src, where), e in by.items() if src == "003" and "moment equation about B" in where]
    assert len(crank) == 1 and crank[0].kind == "remark"
    assert [e.kind for e in ERRATA if e.source == "002"] == ["unreadable", "unreadable"]
    middle = [e for e in ERRATA if e.source == "000" and "[φ1, φ2]" in e.where]
    assert len(middle) == 1 and middle[0].kind == "mistake" and isinstance(middle[0].check(), Claim)


def test_double_harmonic_power_shows_both_extremes():
    e = next(e for e in ERRATA if "D = 7.00" in e.printed)
    c = e.check()
    assert np.isclose(c.truth, 9.8948, atol=1e-4) and "7.7516" in c.text
