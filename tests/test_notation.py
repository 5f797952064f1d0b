"""One notation: what a student reads in a chapter uses the glossary's symbols and no Cyrillic.

Student-facing is every Markdown cell and every code cell not tagged ``check`` (its strings, comments
and labels are what the student sees and prints). Three rules, each with its scan below:

- no Cyrillic character: the sources' terms reach students in English (the glossary keeps the originals);
- every symbol of the policed families — a Greek letter used as a quantity (π is a number, not one), and
  the subscripted $C_x$ (invariants) and $k_x$ (factors) — appears in the glossary's symbol table;
- no subscript transliterated from a source (``cp`` for ср, ``KP`` for кривошип, ``MX`` for мальтійський
  хрест): the glossary maps them to the course's $\\bar M$, $\\bar N$, $\\omega_1$, $\\omega_2$.
"""

import json
import re
from pathlib import Path

import pytest

ROOT = Path(__file__).parent.parent
CHAPTERS = sorted((ROOT / "notebooks").glob("[0-9]*.ipynb"))
GLOSSARY = ROOT / "book" / "glossary.md"

CYRILLIC = re.compile(r"[\u0400-\u04FF\u0500-\u052F]+")
GREEK_COMMANDS = {
    "alpha": "α", "beta": "β", "gamma": "γ", "delta": "δ", "epsilon": "ε", "varepsilon": "ε", "zeta": "ζ",
    "eta": "η", "theta": "θ", "vartheta": "θ", "iota": "ι", "kappa": "κ", "lambda": "λ", "mu": "μ", "nu": "ν",
    "xi": "ξ", "rho": "ρ", "varrho": "ρ", "sigma": "σ", "varsigma": "σ", "tau": "τ", "upsilon": "υ",
    "phi": "φ", "varphi": "φ", "chi": "χ", "psi": "ψ", "omega": "ω", "Gamma": "Γ", "Delta": "Δ",
    "Theta": "Θ", "Lambda": "Λ", "Xi": "Ξ", "Sigma": "Σ", "Upsilon": "Υ", "Phi": "Φ", "Psi": "Ψ",
    "Omega": "Ω"}
GREEK_COMMAND = re.compile(r"\\(" + "|".join(sorted(GREEK_COMMANDS, key=len, reverse=True)) + r")(?![A-Za-z])")
# one letter for each glyph variant: ϕ and φ, ϵ and ε, ϑ and θ, ϱ and ρ, ς and σ
VARIANTS = str.maketrans({"ϕ": "φ", "ϵ": "ε", "ϑ": "θ", "ϱ": "ρ", "ς": "σ"})
NOT_QUANTITIES = {"π"}   # π, \pi: a number
GREEK = re.compile(r"[\u0370-\u03FF\u1F00-\u1FFF]")
SUBSCRIPTED = re.compile(r"(?<![A-Za-z0-9_\\.])([Ck])_\{?([A-Za-z]+)\}?")
SOURCE_SUBSCRIPTS = re.compile(r"_\{?(cp|KP|MX)\}?(?![A-Za-z])")


def cells(path):
    return json.loads(path.read_text())["cells"]


def student_facing(cs) -> list[tuple[int, str]]:
    """(index, text) of the cells a student reads: Markdown, and code not tagged ``check``."""
    return [(i, "".join(c["source"])) for i, c in enumerate(cs)
            if c["cell_type"] == "markdown"
            or (c["cell_type"] == "code" and "check" not in c.get("metadata", {}).get("tags", []))]


def greek_letters(text: str) -> set[str]:
    """The Greek letters of a text, LaTeX commands read as their letters, glyph variants as one."""
    letters = {GREEK_COMMANDS[m] for m in GREEK_COMMAND.findall(text)} | set(GREEK.findall(text))
    return {c.translate(VARIANTS) for c in letters} - NOT_QUANTITIES


def subscripted(text: str) -> set[str]:
    """The C_x and k_x symbols of a text, as "C_v", "k_ov"."""
    return {f"{base}_{sub}" for base, sub in SUBSCRIPTED.findall(text)}


def glossary_symbols(markdown: str) -> set[str]:
    """Everything the glossary's symbol table defines: its first column's Greek letters and C_x, k_x."""
    section = markdown.partition("## Symbols")[2].partition("\n## ")[0]
    column = "\n".join(row.split("|")[1] for row in re.findall(r"^\|.*\|$", section, re.M))
    return greek_letters(column) | subscripted(column)


def problems(cs, known: set[str]) -> list[str]:
    """What breaks the notation in a chapter's cells, as 'cell i: …' lines."""
    found = []
    for i, text in student_facing(cs):
        found += [f"cell {i}: Cyrillic {w!r}" for w in sorted(set(CYRILLIC.findall(text)))]
        found += [f"cell {i}: {s} is not in the glossary's symbol table"
                  for s in sorted((greek_letters(text) | subscripted(text)) - known)]
        found += [f"cell {i}: the source's subscript {m!r} (see the glossary's table of the sources' symbols)"
                  for m in sorted(set(SOURCE_SUBSCRIPTS.findall(text)))]
    return found


KNOWN = glossary_symbols(GLOSSARY.read_text())


def test_the_glossary_defines_the_course_symbols():
    assert {"φ", "ψ", "μ", "λ", "Δ", "C_v", "C_a", "C_p", "C_j", "k_c"} <= KNOWN, KNOWN


@pytest.mark.parametrize("path", CHAPTERS, ids=lambda p: p.name)
def test_chapter_uses_the_glossarys_notation(path):
    found = problems(cells(path), KNOWN)
    assert not found, f"{path.name}:\n" + "\n".join(found)


def md(source, tags=()):
    return {"cell_type": "markdown", "metadata": {"tags": list(tags)}, "source": source}


def code(source, tags=()):
    return {"cell_type": "code", "metadata": {"tags": list(tags)}, "source": source}


def test_the_scan_sees_a_planted_cyrillic_word_and_an_unknown_symbol():
    known = glossary_symbols("## Symbols\n\n| symbol | meaning |\n|---|---|\n"
                             "| $\\varphi$, $C_v$ | crank angle; an invariant |\n| $k_{ov}$ | overload |\n")
    assert known == {"φ", "C_v", "k_ov"}
    clean = [md("The crank angle $\\varphi$ and $C_v$; $k_{ov} = 2$, $2\\pi$."), code('print(f"φ = {phi:.1f}°")')]
    assert problems(clean, known) == []
    planted = [md("The six-bar МЧВ1 turns."), code('ax.set_title("C_q of the law")'), md("$\\chi^2$ and ϕ"),
               code("# омега\nx = 1"), md("$N_{cp} = M_{cp}\\omega$")]
    assert problems(planted, known) == [
        "cell 0: Cyrillic 'МЧВ'", "cell 1: C_q is not in the glossary's symbol table",
        "cell 2: χ is not in the glossary's symbol table", "cell 3: Cyrillic 'омега'",
        "cell 4: ω is not in the glossary's symbol table",
        "cell 4: the source's subscript 'cp' (see the glossary's table of the sources' symbols)"]
    # a check cell is not student-facing; a variable named like a symbol is no symbol
    assert problems([code("assert 'МЧВ' and C_q", tags=["check"]), code("mask_a = check_k = 1")], known) == []
