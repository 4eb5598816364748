#!/usr/bin/env python3
"""Grades submissions against the instructor's engine, public and hidden tests.

    python3 -m grader.grade --build-dir build/dev [options] SUBMISSION...   (from the workbook's folder)

A submission is a folder, .zip or .tar.gz holding the student's copies of skeleton/ files.
Writes OUT/<submission>/results.json (Gradescope's format) and summary.txt, and
OUT/gradebook.csv with one row per submission. See grader/README.md."""
import argparse
from concurrent.futures import ThreadPoolExecutor
import hashlib
import json
import os
import pathlib
import shutil
import signal
import sys
import tempfile
import threading
import time
import traceback

from grader import build
from grader import kit as kits
from grader import report
from grader import runner
from grader import sandbox as sandboxes
from grader import submission as submissions


def build_parser(add_help=True):
    """The options of grade; ./workbook grade takes the same (one definition for both)."""
    parser = argparse.ArgumentParser(description="Grade workbook submissions with the public and hidden tests.",
                                     add_help=add_help)
    parser.add_argument("submissions", nargs="+", metavar="SUBMISSION", help="folder, .zip or .tar.gz")
    parser.add_argument("--build-dir", default="build/dev", help="the instructor's build holding grader/kit.json")
    parser.add_argument("--out", default="grading-results", help="folder for results.json files and gradebook.csv")
    parser.add_argument("--seed", type=int, default=None, help="Catch2 --rng-seed (default: the workbook's seed)")
    parser.add_argument("--time-limit", type=float, default=10.0, help="seconds per test case (default 10)")
    parser.add_argument("--memory-mb", type=int, default=1024, help="address-space limit per test case (default 1024)")
    parser.add_argument("--hidden-visibility", choices=report.VISIBILITIES, default="after_published",
                        help="Gradescope visibility of hidden tests (default after_published)")
    parser.add_argument("-j", "--jobs", type=int, default=1, help="submissions graded at once (default 1)")
    parser.add_argument("--case-jobs", type=int, default=os.cpu_count() or 1,
                        help="test cases of one submission run at once (default: the number of CPUs)")
    parser.add_argument("--resume", action="store_true",
                        help="keep the results of submissions already graded into --out (after an interruption)")
    parser.add_argument("--no-bwrap", action="store_true", help="do not use bubblewrap (weaker isolation)")
    parser.add_argument("--results-json", help="also copy the (single) submission's results.json here (Gradescope)")
    parser.add_argument("--keep-work", action="store_true", help="keep the build folders (printed) for debugging")
    parser.add_argument("--quiet", action="store_true", help="only the progress lines, no per-submission summary")
    return parser


def parse_args(argv):
    return build_parser().parse_args(argv)


class Grader:
    def __init__(self, kit, sandbox, args):
        self.kit, self.sandbox, self.args = kit, sandbox, args
        self.seed = args.seed if args.seed is not None else kit.default_seed
        self.limits = runner.default_limits(args.time_limit, args.memory_mb)
        self.work_root = tempfile.mkdtemp(prefix="workbook-grade-")
        # The sandboxed users must reach the kit and their own submission's folder, but not
        # list the root: each submission's folder is open to that submission's group only.
        os.chmod(self.work_root, 0o711)
        self.stopping = threading.Event()   # set on Ctrl-C: nothing graded after it is recorded
        self.kit = kits.snapshot(kit, self.work_root)
        # A chapter's build and runs depend only on the bytes of its one source file (it is
        # built alone in its own folder) and on the kit and seed, which a batch shares. So a
        # file graded once is not graded again in this batch: the untouched skeleton a
        # student has not started yet, above all, costs one run per chapter, not one per
        # student (about three quarters of the grader's own test batch).
        self.graded_sources = {}
        self.graded_sources_lock = threading.Lock()

    def grade(self, path, name):
        started = time.monotonic()
        result = report.SubmissionResult(name, str(path))
        work = tempfile.mkdtemp(prefix=f"{_safe(name)}-", dir=self.work_root)
        group = self.sandbox.new_group()
        self.sandbox.private_folder(work, group)
        try:
            self._grade_into(result, path, work, group)
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

    def _grade_into(self, result, path, work, group):
        found, notes = submissions.chapter_files(path, [c.source for c in self.kit.chapters])
        result.notes += notes
        for chapter in self.kit.chapters:
            folder = os.path.join(work, chapter.id)
            os.mkdir(folder)
            self.sandbox.private_folder(folder, group)
            if chapter.source in found:
                data, where = found[chapter.source]
                origin = "submitted" if where == chapter.source else f"submitted as {where}"
            else:
                data, origin = chapter.skeleton.read_bytes(), "missing: graded as the untouched skeleton"
            outcomes, problem, feedback = self._graded_once(chapter, data, lambda: self._build_and_run(
                chapter, data, folder, work, group))
            result.chapters.append(report.ChapterResult(chapter, outcomes, problem, feedback, origin))

    def _graded_once(self, chapter, data, grade):
        """grade()'s (outcomes, problem, feedback) for these bytes of this chapter's file,
        computed once per batch; a submission graded at the same time waits for it."""
        key = (chapter.id, hashlib.sha256(data).hexdigest())
        with self.graded_sources_lock:
            entry = self.graded_sources.setdefault(key, {"lock": threading.Lock(), "result": None})
        with entry["lock"]:
            if entry["result"] is None:
                entry["result"] = grade()
            return entry["result"]

    def _build_and_run(self, chapter, data, folder, work, group):
        source = os.path.join(folder, chapter.source)
        pathlib.Path(source).write_bytes(data)
        if group is not None:
            os.chown(source, os.getuid(), group)
        os.chmod(source, 0o640)
        built = build.build_chapter(self.kit, self.sandbox, chapter, source, folder, group)
        if built.binary is None:
            return None, built.problem, built.feedback
        runs = os.path.join(work, "runs")
        scratch = os.path.join(runs, chapter.id)
        for level in (runs, scratch):
            os.makedirs(level, exist_ok=True)
            self.sandbox.private_folder(level, group)
        outcomes = runner.run_chapter(self.kit, self.sandbox, chapter, built.binary, scratch, self.seed,
                                      self.limits, self.args.case_jobs, group)
        return outcomes, None, None

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


def expand(paths):
    """The submissions the command line names: a folder holding no chapter file of its own but
    only folders and archives (an LMS export unpacked, say) is a folder of submissions. A
    missing path, or an empty folder given alone, is refused before anything is graded."""
    found = []
    for given in paths:
        path = pathlib.Path(given)
        if not path.exists():
            raise submissions.SubmissionError(f"{given}: no such file or folder")
        if path.is_dir():
            entries = sorted(p for p in path.iterdir() if not p.name.startswith(".") and p.name != "__MACOSX")
            if not entries and len(paths) == 1:
                # Alone it is a mistake on the command line; in a batch, a student's empty hand-in (a row of zeros).
                raise submissions.SubmissionError(f"{given}: the folder is empty, there is nothing to grade")
            holds_sources = any(p.is_file() and p.suffix in (".cpp", ".hpp", ".h") for p in entries)
            if not holds_sources and len(entries) > 1 and all(
                    p.is_dir() or p.name.lower().endswith(submissions.SUFFIXES) for p in entries):
                found += [str(p) for p in entries]
                continue
        found.append(given)
    return found


class Interrupted(Exception):
    """Ctrl-C (or SIGTERM) stopped the batch."""


def _interrupt(signum, frame):
    raise KeyboardInterrupt


def main(argv=None):
    args = parse_args(argv if argv is not None else sys.argv[1:])
    # Everything the grader writes (results, gradebook, work folders) is the grader's only,
    # unless it opens a folder on purpose (the sandboxed runs' own folders).
    os.umask(0o077)
    signal.signal(signal.SIGTERM, _interrupt)
    try:
        args.submissions = expand(args.submissions)
    except submissions.SubmissionError as error:
        print(f"grade: {error}", file=sys.stderr)
        return 2
    try:
        kit = kits.load(args.build_dir)
    except kits.KitError as error:
        print(f"grade: {error}", file=sys.stderr)
        return 2
    # WORKBOOK_NO_BWRAP=1 is --no-bwrap for scripts that cannot pass options (the Gradescope test).
    sandbox = sandboxes.detect(allow_bwrap=not args.no_bwrap and os.environ.get("WORKBOOK_NO_BWRAP") != "1")
    grader = Grader(kit, sandbox, args)
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    out.chmod(0o700)  # results hold hidden tests' feedback: never readable by student code
    print(f"Grading {len(args.submissions)} submission(s): chapters {', '.join(c.id for c in kit.chapters)} "
          f"({report.fmt_points(sum(c.max_score for c in kit.chapters))} points), random seed {grader.seed}, "
          f"time limit {args.time_limit:g} s per test case.", flush=True)
    print(f"Isolation: {sandbox.description}.", flush=True)
    exposed = kits.exposed_secrets(kit) if sandbox.mode != "bwrap" else []
    if exposed:
        kit.warnings.append(f"student code can read {', '.join(exposed)} (readable by every user): make the tree "
                            f"unreadable to others (chmod -R go-rwx {kit.source_dir}), as setup.sh does on Gradescope")
    for warning in ([sandbox.warning] if sandbox.warning else []) + kit.warnings:
        print(f"WARNING: {warning}" if not warning.startswith("WARNING") else warning, file=sys.stderr, flush=True)

    names = unique_names(args.submissions)
    gradebook = out / "gradebook.csv"
    rows = {}  # by name; written in the order given, whatever order they finish in
    if args.resume:
        for name in names:
            try:
                rows[name] = json.loads((out / name / "row.json").read_text())
            except (OSError, ValueError):
                continue
        if rows:
            print(f"Resuming: {len(rows)} submission(s) already graded in {out}.", flush=True)
    todo = [(path, name) for path, name in zip(args.submissions, names) if name not in rows]
    done = len(rows)
    lock = threading.Lock()

    def one(path_name):
        nonlocal done
        path, name = path_name
        if grader.stopping.is_set():
            return
        result = grader.grade(path, name)
        with lock:
            if grader.stopping.is_set():
                return  # some of its commands may have been stopped: graded again with --resume
            _write(out / name, result, grader, sandbox, args)
            rows[name] = report.gradebook_row(result, kit.chapters)
            report.write_json(out / name / "row.json", rows[name])
            report.write_gradebook(gradebook, [rows[n] for n in names if n in rows], kit.chapters)
            done += 1
            print(report.progress_line(done, len(names), result), flush=True)
            if not args.quiet and len(names) == 1:
                print(report.summary(result), flush=True)

    pool = ThreadPoolExecutor(max_workers=max(1, args.jobs))
    try:
        futures = [pool.submit(one, item) for item in todo]
        for future in futures:
            future.result()
        pool.shutdown()
        report.write_gradebook(gradebook, [rows[n] for n in names if n in rows], kit.chapters)
    except KeyboardInterrupt:
        _stop(grader, pool)
        with lock:
            report.write_gradebook(gradebook, [rows[n] for n in names if n in rows], kit.chapters)
            print(f"Interrupted: {done} of {len(names)} submission(s) graded and recorded in {out}; the others "
                  f"are not. Run the same command with --resume to grade them.", file=sys.stderr, flush=True)
        grader.close()
        return 130
    finally:
        grader.close()
    if args.results_json and rows:
        os.makedirs(os.path.dirname(os.path.abspath(args.results_json)), exist_ok=True)
        shutil.copyfile(out / names[0] / "results.json", args.results_json)
    print(f"Gradebook: {gradebook}  (results.json per submission in {out}/<name>/)", flush=True)
    return 0


def _stop(grader, pool):
    """Stops a batch: no new command starts, the running ones are killed, and no submission
    graded meanwhile is recorded (a case whose process was killed would read as a crash)."""
    grader.stopping.set()
    sandboxes.stopping.set()
    pool.shutdown(wait=False, cancel_futures=True)
    while True:
        sandboxes.stop_all()
        pool.shutdown(wait=False)
        if not any(t.is_alive() for t in getattr(pool, "_threads", ())):
            return
        time.sleep(0.05)


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
    try:
        sys.exit(main())
    except KeyboardInterrupt:  # before the batch started: nothing was graded or recorded
        print("Interrupted before grading started: nothing recorded.", file=sys.stderr)
        sys.exit(130)
