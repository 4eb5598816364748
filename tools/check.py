#!/usr/bin/env python3
"""What `./workbook check CHAPTER` runs: a chapter's public step tests, each test case in
its own process with a time limit, reported step by step.

One process per test case means that a crash, an endless loop or an exception in one step
costs that step only: every other step is still run and reported, and the summary line is
always printed. The look and the wording are those of the "steps" reporter
(tests/support/step_reporter.cpp), which a student without Python can still use by hand.

    python3 -m tools.check --build-dir build/student --chapter inelastic --seed 20261122
    python3 -m tools.check --binary build/student/tests/public_steps_student --chapter inelastic --seed 20261122

(from the workbook's folder: the workbook's Python code is one tree of packages, tools/ among them).

With --build-dir it first builds the chapter's own step-test program,
public_steps_student_<file> (tests/CMakeLists.txt), which holds only that chapter's tests and
the student's file of that chapter: an unfinished file of another chapter does not stop the
check, and a compile error is reported with the file and line it is in. With --binary it runs
a program that is already built (it may hold every chapter; only CHAPTER's cases are run).

Exit status: 0 when every step passes, 1 otherwise, 2 for wrong arguments."""
import argparse
import concurrent.futures
import os
import pathlib
import re
import signal
import subprocess
import sys
import tempfile
from dataclasses import dataclass, field

from tools import catch_xml, wording

DEFAULT_TIME_LIMIT = 10.0  # seconds per test case; each takes milliseconds when the code is right
SHOWN_CASES_PER_STEP = 2
SHOWN_PRINTED_CHARS = 600


@dataclass
class CaseResult:
    name: str
    passed: bool
    message: str = ""  # what the student reads under the case when it fails


@dataclass
class Step:
    number: int
    title: str
    cases: list = field(default_factory=list)  # [(name, CaseResult or None)]

    @property
    def passed(self):
        return all(result.passed for _, result in self.cases)


def step_of(tags):
    """(number, title) of the [step:N:name] tag, (0, "untagged tests") without one, as the
    steps reporter groups them."""
    for tag in tags:
        parts = tag.split(":", 2)
        if len(parts) == 3 and parts[0] == "step" and parts[1].isdigit():
            return int(parts[1]), parts[2].replace("-", " ")
    return 0, "untagged tests"


def judge(name, step, returncode, timed_out, report_text, printed, time_limit):
    """The CaseResult of one test case, from how its process ended and its XML report."""
    where = f"in step {step}"
    if timed_out:
        return CaseResult(name, False, wording.timed_out(time_limit, where) + printed)
    crash = wording.crashed(returncode, where=where)
    if crash is not None:
        return CaseResult(name, False, crash + printed)
    case = None
    try:
        case = next((c for c in catch_xml.parse(report_text) if c.name == name), None)
    except ValueError:
        pass
    if case is None:
        if returncode == 0:
            return CaseResult(name, False, f"the test did not run {where} (is the test program up to date?)")
        return CaseResult(name, False, f"the test program stopped {where} with exit status {returncode} before the "
                                       f"test could finish: std::exit, or an error it could not report?{printed}")
    if case.passed and returncode == 0:
        return CaseResult(name, True)
    first = case.failures[0] if case.failures else "failed"
    if first.startswith("your code threw an exception: "):
        first = f"your code threw an exception {where}: " + first[len("your code threw an exception: "):]
    elif first.startswith("your code crashed: "):
        first = f"your code crashed {where}: " + first[len("your code crashed: "):]
    elif wording.first_nan(_actual_line(first)):
        first = f"your code {wording.not_a_number(wording.first_nan(_actual_line(first)), where)}\n{first}"
    return CaseResult(name, False, first + printed)


def _actual_line(text):
    return next((line for line in text.splitlines() if line.strip().startswith("actual:")), "")


def run_case(binary, name, tags, seed, time_limit, scratch):
    report = os.path.join(scratch, "report.xml")
    output = os.path.join(scratch, "printed.txt")
    # Name and tags (the chapter's among them): another chapter may have a test of this name.
    argv = [binary, catch_xml.case_spec(name, tags), "--reporter", "xml", "--out", report, "--rng-seed", str(seed)]
    timed_out = False
    with open(output, "wb") as printed_file:
        process = subprocess.Popen(argv, stdin=subprocess.DEVNULL, stdout=printed_file, stderr=subprocess.STDOUT,
                                   start_new_session=(os.name == "posix"))
        try:
            returncode = process.wait(timeout=time_limit)
        except subprocess.TimeoutExpired:
            timed_out = True
            _stop(process)
            returncode = process.wait()
    report_text = pathlib.Path(report).read_text(errors="replace") if os.path.exists(report) else ""
    printed = pathlib.Path(output).read_bytes()[:SHOWN_PRINTED_CHARS].decode(errors="replace").strip()
    printed = f"\nyour code printed:\n{printed}" if printed else ""
    return judge(name, step_of(tags)[0], returncode, timed_out, report_text, printed, time_limit)


def _stop(process):
    """Ends a test program that ran out of time, with anything it started."""
    try:
        if os.name == "posix":
            os.killpg(process.pid, signal.SIGKILL)
        else:
            process.kill()
    except (ProcessLookupError, PermissionError):
        pass


def list_cases(binary, chapter):
    """[(name, tags)] of the chapter's test cases; raises RuntimeError when the program cannot list them."""
    try:
        run = subprocess.run([binary, f"[{chapter}]", "--list-tests", "--reporter", "xml"],
                             capture_output=True, text=True, timeout=60)
    except (OSError, subprocess.TimeoutExpired) as error:
        raise RuntimeError(f"{binary} could not list its tests: {error}") from None
    try:
        return catch_xml.parse_listing(run.stdout)
    except ValueError:
        how = wording.crashed(run.returncode) or f"stopped with exit status {run.returncode}"
        raise RuntimeError(f"the test program {how} before any test could run "
                           f"(code that runs at start-up, such as a global variable's initialiser?)\n"
                           f"{run.stderr.strip()[:SHOWN_PRINTED_CHARS]}") from None


# The first error of a compiler's output: GCC and Clang "file:line:col: error: text", MSVC
# "file(line,col): error C1234: text"; and a linker's missing function.
_COMPILE_ERROR = re.compile(r"^(?P<file>[A-Za-z]:[^:(\n]+?|[^\s:(][^:(\n]*?)(?::(?P<line>\d+)(?::\d+)?:|\((?P<mline>\d+)(?:,\d+)?\)\s*:)"
                            r"\s*(?:fatal )?error(?: [A-Z]+\d+)?:\s*(?P<text>.*)$", re.MULTILINE)
_MISSING_FUNCTION = re.compile(r"undefined reference to [`'](?P<name>[^'`]+)'|unresolved external symbol.*?\((?P<msvc>[^)]*\))\)"
                               r"|Undefined symbols? .*?\n\s*\"(?P<apple>[^\"]+)\"")


def program_name(chapter, solutions):
    """The chapter's own step-test program (student) or the reference's program of every chapter."""
    return "public_steps_reference" if solutions else "public_steps_student_" + chapter.replace("-", "_")


def find_program(build_dir, name):
    """The built program in build_dir (tests/, or tests/<config>/ for a multi-config generator)."""
    for folder in [build_dir / "tests", *sorted((build_dir / "tests").glob("*/"))]:
        for candidate in (folder / name, folder / (name + ".exe")):
            if candidate.is_file():
                return candidate
    return None


def compile_problem(output, chapter, root):
    """What to tell a student whose chapter does not build: the file and line of the first error."""
    def shown(path):
        try:
            return pathlib.Path(path).resolve().relative_to(root).as_posix()
        except ValueError:
            return path
    first = _COMPILE_ERROR.search(output)
    if first:
        where = f"{shown(first['file'].strip())}, line {first['line'] or first['mline']}"
        return (f"Your code for chapter {chapter} does not compile yet. The first error is in {where}:\n"
                f"    {first['text'].strip()}\n"
                f"Fix it (the compiler's full message is above) and run the check again. Only this chapter's "
                f"file has to compile to check this chapter.")
    missing = _MISSING_FUNCTION.search(output)
    if missing:
        name = next(group for group in missing.groups() if group)
        return (f"Your code for chapter {chapter} compiles, but a function the tests call is missing: {name}\n"
                f"Is it still defined in your file, with the same name, parameters and namespace as in the header?")
    return (f"Chapter {chapter}'s tests could not be built; the build's own messages are above.")


def build_program(build_dir, chapter, solutions, root, out):
    """Builds the chapter's step-test program; returns its path, or None after saying why not."""
    name = program_name(chapter, solutions)
    run = subprocess.run(["cmake", "--build", str(build_dir), "--target", name],
                         capture_output=True, text=True, errors="replace")
    if run.returncode != 0:
        out.write(run.stdout + run.stderr)
        out.write("\n" + compile_problem(run.stdout + run.stderr, chapter, root) + "\n")
        return None
    program = find_program(build_dir, name)
    if program is None:
        out.write(f"the build made no program {name} in {build_dir}/tests (configure {build_dir} again?)\n")
    return program


def run_chapter(binary, chapter, seed, time_limit, jobs):
    """Every step of the chapter, with the result of each of its test cases."""
    cases = list_cases(binary, chapter)
    steps = {}
    for name, tags in cases:
        number, title = step_of(tags)
        steps.setdefault(number, Step(number, title))
    with tempfile.TemporaryDirectory(prefix="workbook-check-") as scratch_root:
        def one(indexed):
            index, (name, tags) = indexed
            scratch = os.path.join(scratch_root, str(index))
            os.mkdir(scratch)
            return run_case(binary, name, tags, seed, time_limit, scratch)

        with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, jobs)) as pool:
            results = list(pool.map(one, enumerate(cases)))
    for step in steps.values():
        step.cases = []
    for (name, tags), result in zip(cases, results):
        steps[step_of(tags)[0]].cases.append((name, result))
    return [steps[number] for number in sorted(steps)]


def indent(text, prefix="          "):
    return prefix + text.replace("\n", "\n" + prefix)


def report(steps, out):
    """Prints the steps as the steps reporter does; returns the number of steps that pass."""
    passed_steps = 0
    for step in steps:
        ok = step.passed
        passed_steps += ok
        cases_passed = sum(result.passed for _, result in step.cases)
        out.write(f"  {'PASS' if ok else 'FAIL'}  Step {step.number} \u00b7 {step.title}  "
                  f"({cases_passed} of {len(step.cases)} tests pass)\n")
        if ok:
            continue
        failing = [(name, result) for name, result in step.cases if not result.passed]
        for name, result in failing[:SHOWN_CASES_PER_STEP]:
            out.write(f"        test: {name}\n")
            out.write(indent(result.message) + "\n")
    out.write(f"  {passed_steps} of {len(steps)} steps pass.\n")
    out.flush()
    return passed_steps


def main(argv=None):
    parser = argparse.ArgumentParser(description="Runs a chapter's step tests, each test case in its own process "
                                                 "with a time limit, and reports them step by step.")
    program = parser.add_mutually_exclusive_group(required=True)
    program.add_argument("--binary", help="a step-test program (Catch2) that is already built")
    program.add_argument("--build-dir", type=pathlib.Path,
                         help="a configured build folder: build the chapter's own step-test program there first")
    parser.add_argument("--solutions", action="store_true",
                        help="with --build-dir: check the reference solutions instead of the student's code")
    parser.add_argument("--chapter", required=True, help="chapter id, as in chapters/CHAPTERS")
    parser.add_argument("--seed", required=True, type=int, help="Catch2 --rng-seed (tests/RANDOM_SEED)")
    parser.add_argument("--time-limit", type=float, default=DEFAULT_TIME_LIMIT,
                        help="seconds each test case may take (default: %(default)s)")
    parser.add_argument("--jobs", type=int, default=min(4, os.cpu_count() or 1),
                        help="test cases run at once (default: %(default)s)")
    args = parser.parse_args(argv)
    if args.time_limit <= 0:
        parser.error("--time-limit must be positive")
    if args.solutions and not args.build_dir:
        parser.error("--solutions goes with --build-dir")
    if args.build_dir:
        if not (args.build_dir / "CMakeCache.txt").is_file():
            parser.error(f"{args.build_dir} is not a configured build folder")
        root = pathlib.Path(__file__).resolve().parents[1]
        program = build_program(args.build_dir, args.chapter, args.solutions, root, sys.stdout)
        if program is None:
            return 1
        args.binary = str(program)
    if not os.path.isfile(args.binary):
        parser.error(f"no test program at {args.binary}")

    try:
        steps = run_chapter(os.path.abspath(args.binary), args.chapter, args.seed, args.time_limit, args.jobs)
    except RuntimeError as error:
        print(indent(str(error), "  "))
        print("  0 steps could be checked.")
        return 1
    if not steps:
        print(f"  no step tests for chapter {args.chapter}")
        print("  0 steps could be checked.")
        return 1
    passed = report(steps, sys.stdout)
    return 0 if passed == len(steps) else 1


if __name__ == "__main__":
    sys.exit(main())
