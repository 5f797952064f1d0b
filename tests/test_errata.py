"""The errata registry: kinds kept apart, every claim falsifiable (issue 15)."""

from dataclasses import replace

import numpy as np
import pytest

from mechlab.course.errata import KINDS, Claim, Erratum, collect, count, table

ERRATA = collect()


def _id(e):
    return f"{e.source} {e.where}"[:60]


@pytest.fixture(scope="module")
def claims():
    """Each erratum's check run once: Claim or text."""
    return {id(e): e.check() for e in ERRATA}


def test_kinds_are_known_and_counted_separately():
    assert all(e.kind in KINDS for e in ERRATA)
    n = count(ERRATA)
    assert set(n) == set(KINDS) and sum(n.values()) == len(ERRATA)
    assert n["mistake"] >= 20 and n["remark"] >= 5 and n["unreadable"] >= 2
    with pytest.raises(ValueError, match="kind 'typo'"):
        Erratum("000", "x", "a", "b", lambda: "t", kind="typo")


@pytest.mark.parametrize("e", ERRATA, ids=_id)
def test_every_printed_mistake_evaluates_both_expressions_and_fails_if_the_printed_one_is_fed_as_correct(e, claims):
    out = claims[id(e)]
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


def test_double_harmonic_power_shows_both_extremes():
    e = next(e for e in ERRATA if "D = 7.00" in e.printed)
    c = e.check()
    assert np.isclose(c.truth, 9.8948, atol=1e-4) and "7.7516" in c.text
