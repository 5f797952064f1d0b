"""Errata of the source texts, each with the computation that shows it.

Each chapter adds a module to this package defining ``ERRATA``, a list of
:class:`Erratum` of three kinds (:data:`KINDS`): *printed mistakes*, *remarks* (rounding,
notation, incomplete or misleading statements) and *unreadable* passages. A mistake's
``check`` returns a :class:`Claim`: the printed and the corrected expression evaluated on
the same numbers, next to the truth computed independently (simulation or derivation).
:meth:`Claim.judge` raises (AssertionError) unless the correction matches the truth and the
printed expression misses it, so a listed mistake fails the tests when it stops being one,
and feeding the printed expression in as the correction makes the check fail. Remarks may
return a Claim too (rounding: the printed digits against the value); unreadable passages
return their evidence as text. :func:`collect` gathers every chapter's list for the book.
"""

from __future__ import annotations

import importlib
import pkgutil
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from ...errors import renamed

SOURCES = {
    "000": "Zinchenko et al. (2013), slotted-link mechanisms with a curved slot",
    "001": "Kinitsky (1994), Chebyshev hinged mechanisms with a dwell (thesis abstract)",
    "002": "Kozhevnikov, Theory of mechanisms and machines, §7.1-7.2",
    "003": "SibSIU conference proceedings, kinetostatic analysis",
    "004": "Vainer & Shatokhina, offset spherical Geneva mechanism",
}

KINDS = {
    "mistake": "printed mistakes",
    "remark": "remarks: rounding, notation, incomplete or misleading statements",
    "unreadable": "unreadable: what the scan does not let us check",
}


@dataclass(frozen=True)
class Claim:
    """A printed expression and its correction evaluated on the same numbers, against the truth.

    ``truth`` is computed independently of both; the correction must match it within ``tol``
    and the printed expression must miss it by more than ``printed_tol`` (default ``tol``; e.g.
    half a unit of the printed last digit where the correction is exact); both may be one value per
    entry. Arrays: with ``each`` every printed entry must be wrong, else the worst point counts.
    ``text`` says what was evaluated, on which numbers. Making a Claim judges it: it raises
    AssertionError when it does not hold, so ``Erratum.check()`` fails like an assert.
    """

    truth: object
    printed: object
    correct: object
    tol: object
    text: str
    each: bool = True
    printed_tol: object = None

    def __post_init__(self):
        self.judge()  # a claim that does not hold cannot be made

    def __str__(self) -> str:
        return self.judge()

    def judge(self) -> str:
        """The evidence, with both errors; raises AssertionError if the printed expression is right
        (with ``each``, at any of the compared points: every printed entry must be wrong) or the
        correction wrong."""
        t, p, c = (np.asarray(v, dtype=float) for v in (self.truth, self.printed, self.correct))
        tol = np.broadcast_to(np.asarray(self.tol, dtype=float), t.shape)
        ptol = tol if self.printed_tol is None else np.broadcast_to(np.asarray(self.printed_tol, dtype=float), t.shape)
        miss_c = float(np.max(np.abs(c - t)))
        miss_p = float((np.min if self.each else np.max)(np.abs(p - t)))
        if not np.all(np.abs(c - t) <= tol):
            raise AssertionError(f"{self.text}: the correction misses the truth by {miss_c:.3g} > {_show(tol)}")
        margin = np.abs(p - t) - ptol
        if not (np.min if self.each else np.max)(margin) > 0:
            raise AssertionError(f"{self.text}: the printed expression agrees with the truth ({miss_p:.3g} ≤ "
                                 f"{_show(ptol)}); it is not a mistake")
        return (f"{self.text} (printed off by {miss_p:.3g}; corrected within {miss_c:.1g}, tolerance {_show(tol)}"
                + ("" if self.printed_tol is None else f", printed beyond {_show(ptol)}") + ")")


def _show(tol) -> str:
    """A tolerance as one number, or its range when it differs per entry."""
    lo, hi = float(np.min(tol)), float(np.max(tol))
    return f"{hi:.3g}" if lo == hi else f"{lo:.3g}…{hi:.3g}"


@dataclass(frozen=True)
class Erratum:
    """One place in a source: where, what is printed, what is correct, and the evidence.

    ``source`` is a key of :data:`SOURCES`; ``where`` names the formula, table or page;
    ``printed`` and ``correct`` are short texts (LaTeX allowed between $…$); ``notebook`` is the
    chapter notebook that demonstrates it; ``kind`` a key of :data:`KINDS`. ``check`` returns a
    :class:`Claim` (required for a mistake) or, for a remark or an unreadable passage, text.
    """

    source: str
    where: str
    printed: str
    correct: str
    check: Callable[[], Claim | str]
    notebook: str = ""
    kind: str = "mistake"

    def __post_init__(self):
        if self.kind not in KINDS:
            raise ValueError(f"erratum kind {self.kind!r} is not one of {', '.join(KINDS)}")

    def evidence(self) -> str:
        """Recompute the evidence (raises if the claim no longer holds)."""
        out = self.check()
        if isinstance(out, Claim):
            return out.judge()
        if self.kind == "mistake":
            raise TypeError(f"{self.source} {self.where}: a printed mistake's check must return a Claim, "
                            f"evaluating the printed and the corrected expression")
        return out


def count_by_kind(errata: list[Erratum] | None = None) -> dict[str, int]:
    """How many errata of each kind (all of :data:`KINDS`, zeros included)."""
    rows = collect() if errata is None else errata
    return {k: sum(e.kind == k for e in rows) for k in KINDS}


def collect() -> list[Erratum]:
    """Every chapter's errata, in module-name order."""
    found: list[Erratum] = []
    for info in sorted(pkgutil.iter_modules(__path__), key=lambda m: m.name):
        module = importlib.import_module(f"{__name__}.{info.name}")
        found.extend(getattr(module, "ERRATA", []))
    return found


def table(errata: list[Erratum] | None = None, *, notebook: str | None = None) -> str:
    """A Markdown table of errata with their evidence recomputed now."""
    rows = errata if errata is not None else collect()
    if notebook is not None:
        rows = [e for e in rows if e.notebook == notebook]
    lines = ["| source | kind | where | printed | correct | evidence |", "|---|---|---|---|---|---|"]
    for e in rows:
        cells = (f"{e.source}", e.kind, e.where, e.printed, e.correct, e.evidence())
        lines.append("| " + " | ".join(c.replace("|", "\\|").replace("\n", " ") for c in cells) + " |")
    return "\n".join(lines)


# the old name (validate.count is the whole-number spec)
__getattr__ = renamed(__name__, count=(count_by_kind, "mechlab.course.errata.count_by_kind"))
