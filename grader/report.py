"""Scores and writes them out: results.json in Gradescope's format, the terminal summary and
the gradebook CSV. Knows nothing about compiling or running."""
from __future__ import annotations  # `X | None` annotations on Python 3.8 and 3.9
from dataclasses import dataclass, field
import csv
import json
import os

from grader import text as safe

VISIBILITIES = ("hidden", "after_due_date", "after_published", "visible")


@dataclass
class ChapterResult:
    chapter: object                    # kit.Chapter
    outcomes: dict | None = None       # {test case name: runner.Outcome}; None when not run
    problem: str | None = None         # "did not compile", "did not link", ...
    feedback: str | None = None        # the compiler's first errors
    source: str = "submitted"          # or "missing: graded as the untouched skeleton"

    def passed(self, case):
        outcome = (self.outcomes or {}).get(case.name)
        return outcome is not None and outcome.passed

    def case_score(self, case):
        return case.points if self.passed(case) else 0.0

    @property
    def score(self):
        return sum(self.case_score(c) for c in self.chapter.cases)

    def step_scores(self):
        """[(step, score, max_score, cases)] in step order."""
        return [(step, sum(self.case_score(c) for c in cases), sum(c.points for c in cases), cases)
                for step, cases in self.chapter.steps().items()]


@dataclass
class SubmissionResult:
    name: str
    path: str
    chapters: list = field(default_factory=list)
    error: str | None = None           # the whole submission could not be graded
    notes: list = field(default_factory=list)
    seconds: float = 0.0

    @property
    def score(self):
        return sum(c.score for c in self.chapters)

    @property
    def max_score(self):
        return sum(c.chapter.max_score for c in self.chapters)


def fmt_points(value):
    return f"{value:g}"


def case_title(chapter, step, case):
    hidden = " (hidden test)" if case.hidden else ""
    return f"{chapter.title} · Step {step[0]} {step[1].replace('-', ' ')} · {case.name}{hidden}"


def results_json(result, seed, sandbox_description, hidden_visibility):
    tests = []
    for ch in result.chapters:
        for step, cases in ch.chapter.steps().items():
            for case_index, case in enumerate(cases, start=1):
                tests.append({
                    "name": case_title(ch.chapter, step, case),
                    "number": f"{ch.chapter.number}.{step[0]}.{case_index}",
                    "score": ch.case_score(case),
                    "max_score": case.points,
                    "status": "passed" if ch.passed(case) else "failed",
                    "output": _case_output(result, ch, case),
                    "visibility": hidden_visibility if case.hidden else "visible",
                })
    return safe.plain_json({
        "score": result.score,
        "execution_time": round(result.seconds, 2),
        "output": _overall_output(result, seed, sandbox_description),
        "output_format": "text",
        "tests": tests,
        "extra_data": {
            "seed": seed,
            "max_score": result.max_score,
            "chapters": {ch.chapter.id: {"score": ch.score, "max_score": ch.chapter.max_score, "problem": ch.problem,
                                         "steps": {str(step[0]): {"name": step[1], "score": score, "max_score": top}
                                                   for step, score, top, _ in ch.step_scores()}}
                         for ch in result.chapters},
            "error": result.error,
        },
    })


def _case_output(result, ch, case):
    if result.error:
        return f"not run: {result.error}"
    if ch.outcomes is None:
        text = f"not run: your {ch.chapter.source} {ch.problem}."
        if case.hidden:  # the compiler's errors are shown once, with the visible tests
            return text
        return text + ("\n" + ch.feedback if ch.feedback else "")
    outcome = ch.outcomes.get(case.name)
    if outcome is None:
        return "not run"
    if outcome.passed:
        return "passed"
    return outcome.feedback.strip() or "failed"


def _overall_output(result, seed, sandbox_description):
    lines = [f"Random seed {seed} (Catch2 --rng-seed): regrading gives the same test cases.",
             f"Student code ran in a {sandbox_description}."]
    if result.error:
        lines.append(f"This submission could not be graded: {result.error}")
    for ch in result.chapters:
        line = f"{ch.chapter.title}: {fmt_points(ch.score)} / {fmt_points(ch.chapter.max_score)}"
        if ch.source != "submitted":
            line += f" ({ch.source})"
        if ch.problem:
            line += f": your {ch.chapter.source} {ch.problem}"
        lines.append(line)
        if ch.feedback:
            lines.append("    " + ch.feedback.replace("\n", "\n    "))
    lines += [f"Note: {n}" for n in result.notes]
    lines.append(f"Total: {fmt_points(result.score)} / {fmt_points(result.max_score)}")
    return "\n".join(lines)


def summary(result):
    """The readable terminal summary of one submission."""
    lines = [f"{result.name}: {fmt_points(result.score)} / {fmt_points(result.max_score)}"]
    if result.error:
        lines.append(f"  ERROR {result.error}")
    for ch in result.chapters:
        extra = f"  ({ch.source})" if ch.source != "submitted" else ""
        lines.append(f"  {ch.chapter.title}: {fmt_points(ch.score)} / {fmt_points(ch.chapter.max_score)}{extra}")
        if ch.problem:
            lines.append(f"    {ch.chapter.source} {ch.problem}:")
            lines += ["      " + line for line in (ch.feedback or "").splitlines()[:8]]
            continue
        if ch.outcomes is None:
            continue
        for step, score, max_score, cases in ch.step_scores():
            mark = "PASS" if score == max_score else "FAIL"
            lines.append(f"    {mark}  Step {step[0]} {step[1].replace('-', ' ')}: "
                         f"{fmt_points(score)} / {fmt_points(max_score)}")
            failed = [c for c in cases if not ch.passed(c)]
            for case in failed[:2]:
                first = ch.outcomes[case.name].feedback.strip().splitlines()[:1] if case.name in ch.outcomes else []
                hidden = " (hidden)" if case.hidden else ""
                lines.append(f"          {case.name}{hidden}: {first[0] if first else 'failed'}")
    lines += [f"  note: {n}" for n in result.notes]
    return safe.plain("\n".join(lines))


def progress_line(index, count, result):
    status = f"ERROR {result.error}" if result.error else f"{fmt_points(result.score)}/{fmt_points(result.max_score)}"
    problems = [f"{c.chapter.id} {c.problem}" for c in result.chapters if c.problem]
    tail = f"  ({'; '.join(problems)})" if problems else ""
    return safe.plain(f"[{index}/{count}] {result.name} {status}{tail}  {result.seconds:.1f} s")


def step_column(chapter, step):
    return f"{chapter.id} step {step[0]}"


def gradebook_columns(chapters):
    steps = [step_column(c, step) for c in chapters for step in c.steps()]
    return ["submission", *[c.id for c in chapters], *steps, "total", "max", "status", "notes"]


def gradebook_row(result, chapters):
    by_id = {c.chapter.id: c for c in result.chapters}
    row = {"submission": result.name}
    for chapter in chapters:
        ch = by_id.get(chapter.id)
        row[chapter.id] = fmt_points(ch.score if ch else 0.0)
        scores = {step: score for step, score, _, _ in ch.step_scores()} if ch else {}
        for step in chapter.steps():
            row[step_column(chapter, step)] = fmt_points(scores.get(step, 0.0))
    row["total"] = fmt_points(result.score)
    row["max"] = fmt_points(sum(c.max_score for c in chapters))
    row["status"] = "error" if result.error else "graded"
    notes = [result.error] if result.error else []
    notes += [f"{c.chapter.id}: {c.problem}" for c in result.chapters if c.problem]
    notes += result.notes
    row["notes"] = "; ".join(n for n in notes if n)
    return row


def write_gradebook(path, rows, chapters):
    """Rewritten after every submission, atomically, so an interrupted batch keeps every
    finished row. `rows` are gradebook_row() dicts (kept beside each results.json as row.json,
    which is how --resume takes over a finished submission)."""
    temporary = f"{path}.tmp"
    with open(temporary, "w", newline="", encoding="utf-8") as file:
        writer = csv.DictWriter(file, fieldnames=gradebook_columns(chapters), extrasaction="ignore")
        writer.writeheader()
        for row in rows:
            writer.writerow({key: safe.cell(value) for key, value in row.items()})
    os.replace(temporary, path)


def write_json(path, data):
    temporary = f"{path}.tmp"
    with open(temporary, "w", encoding="utf-8") as file:
        json.dump(data, file, indent=2, ensure_ascii=False)
        file.write("\n")
    os.replace(temporary, path)
