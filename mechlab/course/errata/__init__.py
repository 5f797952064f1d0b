"""Mistakes found in the source texts, each with the computation that shows it.

Each chapter adds a module to this package defining ``ERRATA``, a list of
:class:`Erratum`. An erratum carries a ``check`` function that recomputes the
evidence and returns it as a short string; ``check`` must raise (an
AssertionError) if the printed version turned out right or the corrected one wrong,
so a claim in the errata list fails the tests when it stops being true.
:func:`collect` gathers every chapter's list for the book's Errata page.
"""

from __future__ import annotations

import importlib
import pkgutil
from dataclasses import dataclass
from typing import Callable

SOURCES = {
    "000": "Zinchenko et al. (2013), slotted-link mechanisms with a curved slot",
    "001": "Kinitsky (1994), Chebyshev hinged mechanisms with a dwell (thesis abstract)",
    "002": "Kozhevnikov, Theory of mechanisms and machines, §7.1-7.2",
    "003": "SibSIU conference proceedings, kinetostatic analysis",
    "004": "Vainer & Shatokhina, offset spherical Geneva mechanism",
}


@dataclass(frozen=True)
class Erratum:
    """One printed mistake: where, what is printed, what is correct, and the evidence.

    ``source`` is a seed key of :data:`SOURCES` ("000" … "004"); ``where`` names the
    formula, table or page; ``printed`` and ``correct`` are short texts (LaTeX allowed
    between $…$); ``notebook`` is the chapter notebook that demonstrates it.
    """

    source: str
    where: str
    printed: str
    correct: str
    check: Callable[[], str]
    notebook: str = ""

    def evidence(self) -> str:
        """Recompute the evidence (raises if the claim no longer holds)."""
        return self.check()


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
    lines = ["| source | where | printed | correct | evidence |", "|---|---|---|---|---|"]
    for e in rows:
        cells = (f"{e.source}", e.where, e.printed, e.correct, e.evidence())
        lines.append("| " + " | ".join(c.replace("|", "\\|").replace("\n", " ") for c in cells) + " |")
    return "\n".join(lines)
