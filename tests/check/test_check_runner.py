#!/usr/bin/env python3
"""Test of ./workbook check's runner (tools/check.py).

Against check/misbehaving/ (step 1 returns NaN, step 2 is right, step 3 crashes, step 4
never returns, step 5 throws) every step must still be reported, each misbehaviour in plain
words on its own step, the summary printed and the exit status 1. Against the untouched
skeleton the runner must print exactly what the steps reporter prints (the look students
know), and against the reference every step passes with exit status 0.

Against a program with the reference of odd chapters and the skeleton of even ones, each
finished chapter passes whole: a test case is run by its tags and its name, never by a name
another chapter also uses. A chapter's own program holds that chapter's tests only, and a
compile error reads as the file and line it is in."""
import argparse
import pathlib
import subprocess
import sys
import time
import unittest

ROOT = pathlib.Path(__file__).resolve().parents[2]
CHECK = [sys.executable, "-m", "tools.check"]  # run from the workbook's folder (cwd=ROOT)

from tools import catch_xml  # noqa: E402
from tools import check  # noqa: E402

ARGS = None
TIME_LIMIT = 2.0


def run_check(binary, *extra, chapter="inelastic"):
    started = time.monotonic()
    run = subprocess.run([*CHECK, "--binary", binary, "--chapter", chapter,
                          "--seed", ARGS.seed, *extra], capture_output=True, text=True, timeout=120, cwd=ROOT)
    return run, time.monotonic() - started


def step_block(output, number):
    """The lines of one step, from its PASS/FAIL line to the next step or the summary."""
    lines = output.splitlines()
    start = next(i for i, line in enumerate(lines) if line[2:].startswith(("PASS  Step %d " % number,
                                                                            "FAIL  Step %d " % number)))
    end = next((i for i in range(start + 1, len(lines)) if lines[i].startswith("  ") and lines[i][2:6] in ("PASS", "FAIL")
                or lines[i].endswith("steps pass.")), len(lines))
    return "\n".join(lines[start:end])


class MisbehavingCode(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.result, cls.seconds = run_check(ARGS.misbehaving, "--time-limit", str(TIME_LIMIT))
        cls.out = cls.result.stdout

    def test_exit_status_is_1_not_the_crash_signal(self):
        self.assertEqual(self.result.returncode, 1, self.out + self.result.stderr)

    def test_every_step_and_the_summary_are_printed(self):
        for number in range(1, 6):
            self.assertIn(f"Step {number} \u00b7", self.out)
        self.assertIn("  1 of 5 steps pass.", self.out)

    def test_nan_is_named_on_step_1(self):
        block = step_block(self.out, 1)
        self.assertIn("FAIL  Step 1", block)
        self.assertIn("your code produced NaN (not a number) in step 1", block)
        self.assertIn("Law broken: conservation of linear momentum", block)

    def test_the_right_step_still_passes(self):
        self.assertIn("PASS  Step 2 \u00b7 stick together  (2 of 2 tests pass)", self.out)

    def test_a_crash_is_named_on_step_3(self):
        block = step_block(self.out, 3)
        self.assertIn("FAIL  Step 3", block)
        self.assertIn("crashed with a segmentation fault in step 3", block)

    def test_an_endless_loop_is_stopped_on_step_4(self):
        block = step_block(self.out, 4)
        self.assertIn(f"did not finish within {TIME_LIMIT:g} s in step 4 and was stopped", block)
        self.assertLess(self.seconds, 30 * TIME_LIMIT, "the time limit was not applied")

    def test_an_exception_is_named_on_step_5(self):
        block = step_block(self.out, 5)
        self.assertIn("your code threw an exception in step 5: energy_lost is not written yet", block)


class OrdinaryCode(unittest.TestCase):
    def test_the_skeleton_reads_exactly_as_the_steps_reporter_prints_it(self):
        run, _ = run_check(ARGS.skeleton)
        reporter = subprocess.run([ARGS.skeleton, "[inelastic]", "--reporter", "steps", "--rng-seed", ARGS.seed],
                                  capture_output=True, text=True, timeout=120)
        self.assertEqual(run.returncode, 1)
        self.assertEqual(run.stdout, reporter.stdout)

    def test_the_reference_passes_with_exit_status_0(self):
        run, _ = run_check(ARGS.reference)
        self.assertEqual(run.returncode, 0, run.stdout + run.stderr)
        self.assertIn("  5 of 5 steps pass.", run.stdout)
        self.assertNotIn("FAIL", run.stdout)

    def test_wrong_arguments_exit_2(self):
        run = subprocess.run([*CHECK, "--chapter", "inelastic"], capture_output=True, text=True, cwd=ROOT)
        self.assertEqual(run.returncode, 2)
        self.assertIn("usage:", run.stderr)


class ChaptersApart(unittest.TestCase):
    def chapters(self):
        text = (ROOT / "chapters" / "CHAPTERS").read_text()
        return [line.split("#")[0].strip() for line in text.splitlines() if line.split("#")[0].strip()]

    def test_a_finished_chapter_passes_whole_beside_an_unfinished_one(self):
        finished = self.chapters()[0::2]  # the mixed program holds the reference of chapters 1, 3, ...
        shared = "an immovable body on either side, and two immovable bodies"
        listing = catch_xml.parse_listing(subprocess.run([ARGS.mixed, catch_xml.escape_test_name(shared), "--list-tests", "-r", "xml"],
                                                         capture_output=True, text=True).stdout)
        self.assertGreaterEqual(len({tuple(tags) for _, tags in listing}), 2, "the name is no longer shared")
        for chapter in finished:
            run, _ = run_check(ARGS.mixed, chapter=chapter)
            self.assertEqual(run.returncode, 0, run.stdout + run.stderr)
            self.assertNotIn("FAIL", run.stdout)

    def test_every_case_is_run_alone(self):
        cases = catch_xml.parse_listing(subprocess.run([ARGS.mixed, "--list-tests", "-r", "xml"],
                                                       capture_output=True, text=True).stdout)
        self.assertGreater(len(cases), 20)
        for name, tags in cases:
            spec = catch_xml.case_spec(name, tags)
            picked = catch_xml.parse_listing(subprocess.run([ARGS.mixed, spec, "--list-tests", "-r", "xml"],
                                                            capture_output=True, text=True).stdout)
            self.assertEqual(picked, [(name, tags)], spec)

    def test_a_chapter_program_holds_that_chapter_only(self):
        cases = catch_xml.parse_listing(subprocess.run([ARGS.chapter_program, "--list-tests", "-r", "xml"],
                                                       capture_output=True, text=True).stdout)
        self.assertTrue(cases)
        self.assertTrue(all("projection" in tags for _, tags in cases), cases)


class CompileErrors(unittest.TestCase):
    """The first error of a build, as a student reads it: file and line."""

    def problem(self, output):
        return check.compile_problem(output, "projection", pathlib.Path("/home/s/workbook"))

    def test_gcc_and_clang(self):
        output = ("FAILED: chapters/x.o\n/usr/bin/g++ -I/home/s/workbook/chapters -c /home/s/workbook/skeleton/projection.cpp\n"
                  "/home/s/workbook/skeleton/projection.cpp:42:17: error: 'depth' was not declared in this scope\n")
        text = self.problem(output)
        self.assertIn("in skeleton/projection.cpp, line 42:", text)
        self.assertIn("'depth' was not declared in this scope", text)

    def test_msvc(self):
        text = self.problem("C:\\w\\skeleton\\projection.cpp(12,5): error C2065: 'x': undeclared identifier\n")
        self.assertIn("projection.cpp, line 12:", text)
        self.assertIn("'x': undeclared identifier", text)

    def test_a_missing_function(self):
        text = self.problem("/usr/bin/ld: a.o: in function `f':\na.cpp:(.text+0x1): "
                            "undefined reference to `workbook::projection::correct(double)'\n")
        self.assertIn("a function the tests call is missing: workbook::projection::correct(double)", text)


class Judging(unittest.TestCase):
    """How a process's end reads, without building anything."""

    def test_an_exit_without_a_report(self):
        result = check.judge("case", 2, 3, False, "", "", 10)
        self.assertFalse(result.passed)
        self.assertIn("stopped in step 2 with exit status 3", result.message)

    def test_an_abort_and_a_floating_point_error(self):
        self.assertIn("crashed with an abort in step 1", check.judge("c", 1, -6, False, "", "", 10).message)
        self.assertIn("crashed with an arithmetic error in step 4", check.judge("c", 4, -8, False, "", "", 10).message)

    def test_an_infinite_actual_value(self):
        report = ('<Catch2TestRun><TestCase name="c" tags="[step:1:x]"><Failure>Law broken: x (y).\n'
                  '  actual:   (inf, 0, 0) m/s</Failure><OverallResult success="false"/></TestCase></Catch2TestRun>')
        self.assertIn("produced an infinite value in step 1", check.judge("c", 1, 1, False, report, "", 10).message)


def main():
    global ARGS
    parser = argparse.ArgumentParser()
    parser.add_argument("--misbehaving", required=True)
    parser.add_argument("--mixed", required=True, help="reference of chapters 1, 3, ...; skeleton of 2, 4, ...")
    parser.add_argument("--chapter-program", required=True, help="public_steps_student_projection")
    parser.add_argument("--skeleton", required=True)
    parser.add_argument("--reference", required=True)
    parser.add_argument("--seed", required=True)
    ARGS, rest = parser.parse_known_args()
    unittest.main(argv=[sys.argv[0]] + rest, verbosity=2)


if __name__ == "__main__":
    main()
