"""What the class got wrong: the class report ``make grade`` writes next to grades.csv.

Read by a lecturer in a minute before the next class: per assignment and graded answer, the share of the
class right, the named slips most made (degrees for radians, the other assembly, …) and how many gave
nothing; per design check the distribution of outcomes (every specification met, which one missed); and
the flagged submissions — numbers that are another student's (a copied notebook), answers that are right
for another student's variant and not for the student's own (copied answers), variant numbers edited by
hand; and the submissions with a cell stopped at the time limit (a loop): their answers without a verdict
read "stopped: ran over 60 s", not as a wrong or missing answer. Written as ``class_report.csv`` (one row
per assignment, answer and outcome) and ``class_report.html``.
"""

from __future__ import annotations

import csv
import html
from collections import Counter, defaultdict
from dataclasses import dataclass, field
from pathlib import Path

from mechlab.course.exercises.selfcheck import candidates, classify

OUTCOMES = {"correct": "right", "close": "close (too few digits)", "units": "unit slip", "sign": "sign slip",
            "alternative": "named slip", "wrong": "wrong", "missing": "no answer", "form": "not a number",
            "choice": "wrong choice", "design": "design", "unfinished": "no verdict (cell did not finish)"}


@dataclass
class Submission:
    """One graded notebook: its verdicts (from the grade log, in order), nbgrader's score, the flags, and the
    cells stopped at the time limit of ``timeout`` seconds."""

    student: str
    assignment: str
    verdicts: list[dict] = field(default_factory=list)
    score: float = 0.0
    max_score: float = 0.0
    flags: list[str] = field(default_factory=list)
    stopped: list[str] = field(default_factory=list)
    timeout: int | None = None

    @property
    def stop(self) -> str:
        """What an answer without a verdict reads as: stopped at the limit, or a check that did not finish."""
        if not self.stopped:
            return OUTCOMES["unfinished"]
        return f"stopped: ran over {self.timeout} s" if self.timeout else "stopped at the time limit"


def copied_answers(sub: Submission, expected: dict[str, dict[str, dict]]) -> list[str]:
    """Answers of ``sub`` that are right for another student's variant and not for the student's own.

    ``expected`` maps student → answer name → the hidden test's recorded call for that student's variant.
    """
    own = expected.get(sub.student, {})
    out = []
    for v in sub.verdicts:
        call = own.get(v["name"])
        if call is None or not isinstance(v.get("answer"), (int, float)) or v.get("kind") == "correct":
            continue
        for other, calls in expected.items():
            theirs = calls.get(v["name"])
            if other == sub.student or theirs is None or theirs["expected"] == call["expected"]:
                continue
            table = candidates(theirs["expected"], [], {}, theirs["significant"])[:1]
            if classify(float(v["answer"]), table, theirs["significant"]):
                out.append(f"{v['name']} is {other}'s answer")
                break
    return out


def _label(v: dict) -> str:
    kind = v.get("kind", "")
    if kind == "design":
        return v.get("outcome", "design")
    if v.get("check") == "choice" and kind in ("choice", "form"):     # which distractor, not "not a number"
        key = str(v.get("answer", "")).strip().lower()
        return f"chose ({key})" if kind == "choice" else f"chose {v.get('answer')!r}, not one of the options"
    return v.get("slip") or OUTCOMES.get(kind, kind)


def rows(subs: list[Submission], expected_names: dict[str, list[str]]) -> list[dict]:
    """One row per (assignment, answer, outcome): count and share of the submissions of that assignment."""
    by = defaultdict(list)
    for s in subs:
        by[s.assignment].append(s)
    out = []
    for aid in sorted(by):
        group = by[aid]
        for name in expected_names.get(aid, []):
            counts = Counter()
            for s in group:
                mine = [v for v in s.verdicts if v["name"] == name]
                counts[_label(mine[0]) if mine else s.stop] += 1
            for outcome, n in counts.most_common():
                out.append({"assignment": aid, "answer": name, "outcome": outcome, "students": n,
                            "share": round(n / len(group), 3)})
    return out


def write(subs: list[Submission], expected_names: dict[str, list[str]], folder: Path) -> tuple[Path, Path]:
    """class_report.csv and class_report.html in ``folder``."""
    table = rows(subs, expected_names)
    csv_path, html_path = folder / "class_report.csv", folder / "class_report.html"
    with open(csv_path, "w", newline="", encoding="utf-8") as f:
        w = csv.DictWriter(f, fieldnames=["assignment", "answer", "outcome", "students", "share"])
        w.writeheader()
        w.writerows(table)
        for s in subs:
            for flag in s.flags:
                w.writerow({"assignment": s.assignment, "answer": "", "outcome": f"flag: {s.student}: {flag}",
                            "students": 1, "share": ""})
            if s.stopped:
                w.writerow({"assignment": s.assignment, "answer": "", "students": 1, "share": "",
                            "outcome": f"stopped: {s.student}: ran over {s.timeout} s in {', '.join(s.stopped)}"})
    html_path.write_text(_html(subs, table), encoding="utf-8")
    return csv_path, html_path


def _html(subs: list[Submission], table: list[dict]) -> str:
    esc = html.escape
    parts = ["<!doctype html><html lang='en'><head><meta charset='utf-8'><title>What the class got wrong</title>",
             "<style>body{font:15px/1.4 system-ui,sans-serif;margin:2em;max-width:70em}td,th{padding:.2em .6em;"
             "text-align:left;border-bottom:1px solid #ddd}.bar{display:inline-block;height:.8em;background:#3b7}"
             ".miss{background:#c63}.flag{color:#a00}h2{margin-top:1.6em}</style></head><body>",
             "<h1>What the class got wrong</h1>"]
    by = defaultdict(list)
    for r in table:
        by[(r["assignment"], r["answer"])].append(r)
    for aid in sorted({s.assignment for s in subs}):
        group = [s for s in subs if s.assignment == aid]
        mean = sum(s.score for s in group) / len(group)
        top = max((s.max_score for s in group), default=0)
        parts.append(f"<h2>{esc(aid)}</h2><p>{len(group)} submissions, mean score {mean:.1f} / {top:g}.</p>")
        parts.append("<table><tr><th>answer</th><th>right</th><th>most frequent outcomes besides right</th></tr>")
        for (a, name), rs in by.items():
            if a != aid:
                continue
            right = sum(r["share"] for r in rs if r["outcome"] in ("right", "every specification met"))
            others = "; ".join(f"{esc(r['outcome'])} {r['share']:.0%}" for r in rs
                               if r["outcome"] not in ("right", "every specification met"))[:400]
            parts.append(f"<tr><td>{esc(name)}</td><td><span class='bar' style='width:{right * 8:.1f}em'></span> "
                         f"{right:.0%}</td><td>{others or '—'}</td></tr>")
        parts.append("</table>")
        flagged = [(s.student, f) for s in group for f in s.flags]
        if flagged:
            parts.append("<h3 class='flag'>Flagged</h3><ul>" + "".join(
                f"<li class='flag'>{esc(who)}: {esc(f)}</li>" for who, f in flagged) + "</ul>")
        looped = [s for s in group if s.stopped]
        if looped:
            parts.append("<h3>Stopped at the time limit (a loop?)</h3><ul>" + "".join(
                f"<li>{esc(s.student)}: {esc(s.stop)} in {esc(', '.join(s.stopped))}</li>" for s in looped) + "</ul>")
    parts.append("</body></html>")
    return "\n".join(parts)
