"""The learning path as a picture: which chapter needs which, read from the chapters themselves.

    python tools/learning_path.py          # writes book/figures/learning_path.svg

A chapter's needs are the chapters that its "Prerequisites" section links to; a link after
"Looking ahead" points forward and is no need. Titles and times come from the path's table in
book/intro.md. An arrow joins a chapter to the one that needs it, left out where a longer chain
of arrows already leads there. At most LANES boxes stand side by side, so that the labels stay
readable where the book shows the picture (its 752 px column). The times in that table are the time
model's (tools/lesson_time.py, whose ``--write`` rewrites the table and redraws this picture).
tests/test_course_frame.py checks that every need comes earlier in the path, that the committed picture
is the one this script draws, that no arrow runs through a box and that every label is at least 11 px
high in that column.
"""

from __future__ import annotations

import io
import itertools
import json
import re
import sys
import textwrap
from dataclasses import dataclass
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
from matplotlib.patches import FancyArrowPatch, FancyBboxPatch

ROOT = Path(__file__).resolve().parent.parent
FIGURE = ROOT / "book" / "figures" / "learning_path.svg"
AHEAD = "Looking ahead"
LINK = re.compile(r"\]\((\d+[a-z]?)_\w+\.ipynb[)#]")
# chapter, "you learn to", time, the exercises' time (optional), needs
ROW = re.compile(r"^\| \[(\d+[a-z]?) · ([^\]]+)\]\(notebooks/(\w+)\.ipynb\) \|[^|\n]*\| (\d+) min \|"
                 r"(?: (?:\d+ min|—) \|)? ([^|\n]*) \|$", re.M)


@dataclass(frozen=True)
class Chapter:
    number: str   # as the heading writes it: "8", or "8a" for a chapter inserted after 8 without renumbering
    stem: str
    title: str
    minutes: int
    needs: frozenset[str]


def label(prefix: str) -> str:
    """A file name's number as a chapter's heading writes it: "08a" → "8a", "12" → "12"."""
    digits, letter = re.fullmatch(r"(\d+)([a-z]?)", prefix).groups()
    return f"{int(digits)}{letter}"


def prerequisites(notebook: Path) -> frozenset[int]:
    """The chapter numbers linked in the notebook's "## Prerequisites" section, before "Looking ahead"."""
    cells = json.loads(notebook.read_text())["cells"]
    frame = "".join(cells[0]["source"])
    section = frame.partition("## Prerequisites\n")[2].partition("\n## ")[0]
    return frozenset(label(n) for n in LINK.findall(section.partition(AHEAD)[0]))


def chapters(root: Path = ROOT) -> list[Chapter]:
    """The path's chapters in order: title and time from book/intro.md, needs from the notebooks."""
    rows = ROW.findall((root / "book" / "intro.md").read_text())
    return [Chapter(n, stem, title, int(minutes), prerequisites(root / "notebooks" / f"{stem}.ipynb"))
            for n, title, stem, minutes, _ in rows]


def arrows(path: list[Chapter]) -> set[tuple[str, str]]:
    """(need, chapter) pairs without those that a longer chain implies (the transitive reduction)."""
    needs = {c.number: set(c.needs) for c in path}

    def reachable(start: str) -> set[str]:  # every chapter that `start` builds on, directly or not
        seen, todo = set(), list(needs.get(start, ()))
        while todo:
            n = todo.pop()
            if n not in seen:
                seen.add(n)
                todo.extend(needs.get(n, ()))
        return seen
    return {(n, c) for c, ns in needs.items() for n in ns
            if not any(n in reachable(m) for m in ns - {n})}


W, H = 0.92, 0.66  # a chapter's box, in lanes (one lane = one box width and its gap) and rows
# at most this many lanes side by side, so that the labels stay ≥ 11 px in the book's 752 px column
LANES = 5
SLOTS = [i / 2 for i in range(2 * LANES - 1)]  # the x a box may take, in half lanes


def segment(where, edge):
    (x0, r0), (x1, r1) = where[edge[0]], where[edge[1]]
    return (x0, r0 + H / 2), (x1, r1 - H / 2)


def crosses(a, b) -> bool:
    """Whether two segments cross (touching ends do not count)."""
    def side(p, q, r):
        return (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0])
    return (side(*a, b[0]) * side(*a, b[1]) < 0) and (side(*b, a[0]) * side(*b, a[1]) < 0)


def through_boxes(where, edges) -> int:
    """How often an arrow passes a box's top or bottom edge inside the box (or within 0.1 lane of it)."""
    hits = 0
    for e in edges:
        (x0, y0), (x1, y1) = segment(where, e)
        for m, (xb, rb) in where.items():
            if m not in e and y0 < rb < y1:
                for y in (rb - H / 2, rb + H / 2):
                    x = x0 + (x1 - x0) * (y - y0) / (y1 - y0)
                    hits += abs(x - xb) < W / 2 + 0.1
    return hits


def cost(where, edges) -> float:
    """Arrows through boxes count most, then crossing arrows, then slanted arrows and the width."""
    segments = [segment(where, e) for e in edges]
    crossings = sum(not set(e) & set(f) and crosses(a, b)
                    for i, (e, a) in enumerate(zip(edges, segments, strict=False))
                    for f, b in zip(edges[i + 1:], segments[i + 1:], strict=False))
    xs = [x for x, _ in where.values()]
    return (100 * through_boxes(where, edges) + 10 * crossings + sum(abs(b[0] - a[0]) for a, b in segments)
            + 4 * (max(xs) - min(xs)))


def improve(where, earliest, needed_by, edges):
    """Move a box to a free slot of a row it may take (from its earliest row down to just above the first
    chapter that needs it), or swap two boxes of a row, while that lowers `cost`; the layout and its cost."""
    order = sorted(where, key=lambda m: (earliest[m], m))
    last = max(earliest.values())
    best = cost(where, edges)
    improved = True
    while improved:
        improved = False
        for m in order:
            trials = []
            for r in range(earliest[m], min((where[d][1] for d in needed_by[m]), default=last + 1)):
                taken = [x for n, (x, rn) in where.items() if rn == r and n != m]
                trials += [{**where, m: (x, r)} for x in SLOTS if all(abs(x - t) >= 1 for t in taken)]
            trials += [{**where, m: where[n], n: where[m]} for n in order if where[n][1] == where[m][1] and n > m]
            for trial in trials:
                c = cost(trial, edges)
                if c < best - 1e-9:
                    where, best, improved = trial, c, True
    return where, best


def layout(path: list[Chapter], edges: set[tuple[str, str]]) -> dict[str, tuple[float, int]]:
    """(x, row): a chapter starts in the row after its latest need (the longest chain of needs below it),
    side by side in path order, and :func:`improve` moves it; tried from every order of the widest row
    (the branches), the lowest `cost` wins. Worked on the chapters' places in the path (8a sorts after 8)."""
    place = {c.number: i for i, c in enumerate(path)}
    needs = {place[c.number]: {place[n] for n in c.needs} for c in path}
    earliest: dict[int, int] = {}
    for i in range(len(path)):  # in path order, so every need has its row already
        earliest[i] = 1 + max((earliest[n] for n in needs[i]), default=-1)
    needed_by = {i: [d for d in needs if i in needs[d]] for i in needs}
    rows: dict[int, list[int]] = {}
    for m in sorted(earliest, key=lambda m: (earliest[m], m)):
        rows.setdefault(earliest[m], []).append(m)
    widest = max(rows, key=lambda r: (len(rows[r]), -r))
    starts = ({m: (float(i), r) for r, ms in {**rows, widest: list(order)}.items() for i, m in enumerate(ms)}
              for order in itertools.permutations(rows[widest]))
    placed = sorted((place[n], place[c]) for n, c in edges)
    where = min((improve(start, earliest, needed_by, placed) for start in starts), key=lambda wc: wc[1])[0]
    return {path[i].number: xy for i, xy in where.items()}


def draw(path: list[Chapter]):
    edges = arrows(path)
    where = layout(path, edges)
    xs = [x for x, _ in where.values()]
    rows = max(r for _, r in where.values()) + 1
    fig, ax = plt.subplots(figsize=(1.75 * (max(xs) - min(xs) + 1.1), 1.05 * rows + 0.3))
    ax.set_xlim(min(xs) - 0.55, max(xs) + 0.55)
    ax.set_ylim(rows - 0.5, -0.6)
    ax.axis("off")
    w, h = W, H
    for c in path:
        x, r = where[c.number]
        ax.add_patch(FancyBboxPatch((x - w / 2, r - h / 2), w, h, boxstyle="round,pad=0,rounding_size=0.08",
                                    facecolor="#e8f0fa", edgecolor="#1f4e8c", linewidth=1.2, zorder=2))
        title = textwrap.fill(f"{c.number} · {c.title}", 17)
        ax.text(x, r - 0.07, title, ha="center", va="center", fontsize=11, zorder=3)
        ax.text(x, r + h / 2 - 0.1, f"{c.minutes} min", ha="center", va="center", fontsize=10,
                color="#555555", zorder=3)
    place = {c.number: i for i, c in enumerate(path)}
    for n, c in sorted(edges, key=lambda e: (place[e[0]], place[e[1]])):
        (x0, r0), (x1, r1) = where[n], where[c]
        ax.add_patch(FancyArrowPatch((x0, r0 + h / 2), (x1, r1 - h / 2), arrowstyle="-|>", mutation_scale=12,
                                     color="#1f4e8c", linewidth=1.0, shrinkA=1, shrinkB=1, zorder=1))
    total = sum(c.minutes for c in path)
    ax.set_title(f"The learning path ({total} min): each arrow leads from a chapter to one that builds on it",
                 fontsize=12)
    fig.tight_layout()
    return fig


def svg(path: list[Chapter]) -> bytes:
    """The picture as SVG bytes, the same on every run (no date, fixed ids)."""
    fig = draw(path)
    out = io.BytesIO()
    with plt.rc_context({"svg.hashsalt": "learning-path"}):
        fig.savefig(out, format="svg", metadata={"Date": None})
    plt.close(fig)
    return out.getvalue()


def main(argv: list[str]) -> None:
    target = Path(argv[0]) if argv else FIGURE
    target.parent.mkdir(parents=True, exist_ok=True)
    target.write_bytes(svg(chapters()))
    print(f"wrote {target}")


if __name__ == "__main__":
    main(sys.argv[1:])
