#!/usr/bin/env python3
"""Grades submissions against the instructor's engine, public and hidden tests.

    python3 grader/grade.py --build-dir build/dev [options] SUBMISSION...

A submission is a folder, .zip or .tar.gz holding the student's copies of skeleton/ files.
Writes OUT/<submission>/results.json (Gradescope's format) and summary.txt, and
OUT/gradebook.csv with one row per submission. See grader/README.md."""
import argparse
import os
import pathlib
import shutil
import sys
import tempfile
import time
import traceback

HERE = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
sys.path.insert(0, str(HERE.parent / "tools"))

import build  # noqa: E402
import kit as kits  # noqa: E402
import report  # noqa: E402
import runner  # noqa: E402
import sandbox as sandboxes  # noqa: E402
import submission as submissions  # noqa: E402


def parse_args(argv):
    parser = argparse.ArgumentParser(description="Grade workbook submissions with the public and hidden tests.")
    parser.add_argument("submissions", nargs="+", metavar="SUBMISSION", help="folder, .zip or .tar.gz")
    parser.add_argument("--build-dir", default="build/dev", help="the instructor's build holding grader/kit.json")
    parser.add_argument("--out", default="grading-results", help="folder for results.json files and gradebook.csv")
    parser.add_argument("--seed", type=int, default=None, help="Catch2 --rng-seed (default: the workbook's seed)")
    parser.add_argument("--time-limit", type=float, default=10.0, help="seconds per test case (default 10)")
    parser.add_argument("--memory-mb", type=int, default=1024, help="address-space limit per test case (default 1024)")
    parser.add_argument("--hidden-visibility", choices=report.VISIBILITIES, default="after_published",
                        help="Gradescope visibility of hidden tests (default after_published)")
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 1, help="test cases run in parallel")
    parser.add_argument("--no-bwrap", action="store_true", help="do not use bubblewrap (weaker isolation)")
    parser.add_argument("--results-json", help="also copy the (single) submission's results.json here (Gradescope)")
    parser.add_argument("--keep-work", action="store_true", help="keep the build folders (printed) for debugging")
    parser.add_argument("--quiet", action="store_true", help="only the progress lines, no per-submission summary")
    return parser.parse_args(argv)


class Grader:
    def __init__(self, kit, sandbox, args):
        self.kit, self.sandbox, self.args = kit, sandbox, args
        self.seed = args.seed if args.seed is not None else kit.default_seed
        self.limits = runner.default_limits(args.time_limit, args.memory_mb)
        self.work_root = tempfile.mkdtemp(prefix="workbook-grade-")
        os.chmod(self.work_root, 0o755)  # the sandboxed user must reach its own folders
        self.kit = kits.snapshot(kit, self.work_root)

    def grade(self, path, name):
        started = time.monotonic()
        result = report.SubmissionResult(name, str(path))
        work = tempfile.mkdtemp(prefix=f"{_safe(name)}-", dir=self.work_root)
        os.chmod(work, 0o755)
        try:
            self._grade_into(result, path, work)
        except submissions.SubmissionError as error:
            result.error = str(error)
        except Exception as error:  # a grader bug costs this submission only, and is reported
            traceback.print_exc(file=sys.stderr)
            result.error = f"internal grader error: {type(error).__name__}: {error}"
        finally:
            if self.args.keep_work:  # printed, not a note: notes reach the student's results.json
                print(f"{name}: build folder kept: {work}", file=sys.stderr, flush=True)
            else:
                shutil.rmtree(work, ignore_errors=True)
        if result.error:
            result.chapters = [report.ChapterResult(c, None, "was not graded") for c in self.kit.chapters]
        result.seconds = time.monotonic() - started
        return result

    def _grade_into(self, result, path, work):
        found, notes = submissions.chapter_files(path, [c.source for c in self.kit.chapters])
        result.notes += notes
        for chapter in self.kit.chapters:
            folder = os.path.join(work, chapter.id)
            os.mkdir(folder)
            source = os.path.join(folder, chapter.source)
            if chapter.source in found:
                data, where = found[chapter.source]
                origin = "submitted" if where == chapter.source else f"submitted as {where}"
            else:
                data, origin = chapter.skeleton.read_bytes(), "missing: graded as the untouched skeleton"
            pathlib.Path(source).write_bytes(data)
            os.chmod(source, 0o644)
            self.sandbox.prepare_writable(folder)
            built = build.build_chapter(self.kit, self.sandbox, chapter, source, folder)
            if built.binary is None:
                result.chapters.append(report.ChapterResult(chapter, None, built.problem, built.feedback, origin))
                continue
            scratch = os.path.join(work, "runs")
            os.makedirs(scratch, exist_ok=True)
            outcomes = runner.run_chapter(self.kit, self.sandbox, chapter, built.binary, scratch, self.seed,
                                          self.limits, self.args.jobs)
            result.chapters.append(report.ChapterResult(chapter, outcomes, source=origin))

    def close(self):
        if not self.args.keep_work:
            shutil.rmtree(self.work_root, ignore_errors=True)


def _safe(name):
    return "".join(c if c.isalnum() or c in "-_." else "_" for c in name)[:60] or "submission"


def unique_names(paths):
    """Folder names under --out: distinct even when a name plus a suffix is itself submitted
    (x, x, x-2), and never '..' or the gradebook."""
    names, taken = [], {"gradebook.csv", "gradebook.csv.tmp"}
    for path in paths:
        base = _safe(submissions.display_name(path)).strip(".") or "submission"
        name, count = base, 1
        while name in taken:
            count += 1
            name = f"{base}-{count}"
        taken.add(name)
        names.append(name)
    return names


def main(argv=None):
    args = parse_args(argv if argv is not None else sys.argv[1:])
    try:
        kit = kits.load(args.build_dir)
    except kits.KitError as error:
        print(f"grade: {error}", file=sys.stderr)
        return 2
    sandbox = sandboxes.detect(allow_bwrap=not args.no_bwrap)
    grader = Grader(kit, sandbox, args)
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    print(f"Grading {len(args.submissions)} submission(s): chapters {', '.join(c.id for c in kit.chapters)} "
          f"({report.fmt_points(sum(c.max_score for c in kit.chapters))} points), random seed {grader.seed}, "
          f"time limit {args.time_limit:g} s per test case.", flush=True)
    print(f"Isolation: {sandbox.description}.", flush=True)
    for warning in ([sandbox.warning] if sandbox.warning else []) + kit.warnings:
        print(f"WARNING: {warning}" if not warning.startswith("WARNING") else warning, file=sys.stderr, flush=True)

    results = []
    names = unique_names(args.submissions)
    gradebook = out / "gradebook.csv"
    try:
        for index, (path, name) in enumerate(zip(args.submissions, names), start=1):
            result = grader.grade(path, name)
            results.append(result)
            _write(out / name, result, grader, sandbox, args)
            report.write_gradebook(gradebook, results, kit.chapters)
            print(report.progress_line(index, len(names), result), flush=True)
            if not args.quiet and len(names) == 1:
                print(report.summary(result), flush=True)
    finally:
        grader.close()
    if args.results_json and results:
        os.makedirs(os.path.dirname(os.path.abspath(args.results_json)), exist_ok=True)
        shutil.copyfile(out / names[0] / "results.json", args.results_json)
    print(f"Gradebook: {gradebook}  (results.json per submission in {out}/<name>/)", flush=True)
    return 0


def _write(folder, result, grader, sandbox, args):
    try:
        folder.mkdir(parents=True, exist_ok=True)
        data = report.results_json(result, grader.seed, sandbox.description, args.hidden_visibility)
        report.write_json(folder / "results.json", data)
        (folder / "summary.txt").write_text(report.summary(result) + "\n", encoding="utf-8")
    except OSError as error:
        result.notes.append(f"could not write results: {error}")
        print(f"grade: cannot write the results of {result.name}: {error}", file=sys.stderr, flush=True)


if __name__ == "__main__":
    sys.exit(main())
