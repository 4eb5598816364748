#!/usr/bin/env python3
"""What `./workbook check CHAPTER` runs: a chapter's public step tests, each test case in
its own process with a time limit, reported step by step.

One process per test case means that a crash, an endless loop or an exception in one step
costs that step only: every other step is still run and reported, and the summary line is
always printed. The look and the wording are those of the "steps" reporter
(tests/support/step_reporter.cpp), which a student without Python can still use by hand.

    python3 -m tools.check --binary build/student/tests/public_steps_student --chapter inelastic --seed 20261122

(from the workbook's folder: the workbook's Python code is one tree of packages, tools/ among them).

Exit status: 0 when every step passes, 1 otherwise, 2 for wrong arguments."""
import argparse
import concurrent.futures
import os
import pathlib
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


def run_case(binary, name, step, seed, time_limit, scratch):
    report = os.path.join(scratch, "report.xml")
    output = os.path.join(scratch, "printed.txt")
    argv = [binary, catch_xml.escape_test_name(name), "--reporter", "xml", "--out", report, "--rng-seed", str(seed)]
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
    return judge(name, step, returncode, timed_out, report_text, printed, time_limit)


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


def run_chapter(binary, chapter, seed, time_limit, jobs):
    """Every step of the chapter, with the result of each of its test cases."""
    cases = list_cases(binary, chapter)
    steps = {}
    for name, tags in cases:
        number, title = step_of(tags)
        steps.setdefault(number, Step(number, title)).cases.append(name)
    with tempfile.TemporaryDirectory(prefix="workbook-check-") as scratch_root:
        def one(indexed):
            index, (name, tags) = indexed
            scratch = os.path.join(scratch_root, str(index))
            os.mkdir(scratch)
            return name, run_case(binary, name, step_of(tags)[0], seed, time_limit, scratch)

        with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, jobs)) as pool:
            results = dict(pool.map(one, enumerate(cases)))
    for step in steps.values():
        step.cases = [(name, results[name]) for name in step.cases]
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
    parser.add_argument("--binary", required=True, help="the step-test program (Catch2)")
    parser.add_argument("--chapter", required=True, help="chapter id, as in chapters/CHAPTERS")
    parser.add_argument("--seed", required=True, type=int, help="Catch2 --rng-seed (tests/RANDOM_SEED)")
    parser.add_argument("--time-limit", type=float, default=DEFAULT_TIME_LIMIT,
                        help="seconds each test case may take (default: %(default)s)")
    parser.add_argument("--jobs", type=int, default=min(4, os.cpu_count() or 1),
                        help="test cases run at once (default: %(default)s)")
    args = parser.parse_args(argv)
    if not os.path.isfile(args.binary):
        parser.error(f"no test program at {args.binary}")
    if args.time_limit <= 0:
        parser.error("--time-limit must be positive")

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
