#!/usr/bin/env python3
"""Trust in the grader: grades the reference, the untouched skeleton, every correct variant
and two mistakes a chapter (tests/mutants/<chapter>/<name>/) and every hostile submission
(tests/hostile/<name>/) in ONE batch, then checks the scores against each expect.json, the
output formats, that hidden tests leak no source, that regrading is deterministic, and that
the Gradescope zip works against a simulated /autograder tree.

    python3 -m tests.grader.test_grader --build-dir build/dev   (from the workbook's folder; ctest runs it: label grader)"""
import argparse
import csv
import gzip
import io
import json
import os
import pathlib
import re
import shutil
import signal
import subprocess
import sys
import tarfile
import tempfile
import threading
import time
import unittest
import zipfile

from tests.grader.compose import compose
from tools import workbook_files

ROOT = pathlib.Path(__file__).resolve().parents[2]


def module(name, root=ROOT):
    """argv and environment that run one of the workbook's Python programs (grader.grade) from root."""
    return [sys.executable, "-m", name], dict(os.environ, PYTHONPATH=str(root))


GRADE, GRADE_ENV = module("grader.grade")
PACK, PACK_ENV = module("grader.pack_gradescope")
BUILD_DIR = ROOT / "build" / "dev"
TIME_LIMIT = "3"
# Per test case: small enough that the memory-in-children submission crosses it in well under
# the time limit, large enough for any honest submission (the reference runs in 24 MiB). A
# first touch of memory costs about 3 ms a MiB on this project's virtual machines, so 320 MiB
# under a limit of 256 left too little margin: in one CI run the cases ended otherwise.
MEMORY_MB = "96"
FRESH_UID_BASE = 1_600_000_000
GRADESCOPE_TEST_KEYS = {"name": str, "score": (int, float), "max_score": (int, float), "status": str,
                        "output": str, "visibility": str}
VISIBILITIES = {"hidden", "after_due_date", "after_published", "visible"}


def chapter_ids():
    return workbook_files.chapters(ROOT)


def source_name(chapter):
    return chapter.replace("-", "_") + ".cpp"


class Batch:
    """Builds the submissions, grades them once, and keeps what came out."""

    def __init__(self):
        self.tmp = pathlib.Path(tempfile.mkdtemp(prefix="grader-test-"))
        self.subs = self.tmp / "submissions"
        self.out = self.tmp / "out"
        self.subs.mkdir()
        self.paths, self.expect = [], {}
        self._make()

    def grade(self):
        started = time.monotonic()
        with subprocess.Popen([*GRADE, "--build-dir", str(BUILD_DIR), "--out", str(self.out),
                               "--time-limit", TIME_LIMIT, "--memory-mb", MEMORY_MB, "--quiet",
                               *map(str, self.paths)],
                              stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=GRADE_ENV) as grader:
            # The sandbox derives its fresh uids from the grader's pid; the fork-loop check
            # looks at those alone, so another grader running on the machine cannot fail it.
            self.grader_pid = grader.pid
            stdout, stderr = grader.communicate(timeout=1700)
        self.run = subprocess.CompletedProcess(grader.args, grader.returncode, stdout, stderr)
        self.seconds = time.monotonic() - started
        with open(self.out / "gradebook.csv", newline="") as file:
            reader = csv.DictReader(file)
            self.columns = reader.fieldnames
            self.rows = list(reader)
        self.results = {}
        for row in self.rows:
            path = self.out / row["submission"] / "results.json"
            if path.is_file():
                self.results[row["submission"]] = json.loads(path.read_text())

    def _folder(self, name, files):
        folder = self.subs / name
        folder.mkdir()
        for file_name, source in files.items():
            shutil.copyfile(source, folder / file_name)
        self.paths.append(folder)
        return folder

    def _make(self):
        chapters = chapter_ids()
        reference = {source_name(c): ROOT / "solutions" / source_name(c) for c in chapters}
        self._folder("reference", reference)
        # The same reference again, as a zip with the files inside a folder: determinism and archives.
        with zipfile.ZipFile(self.subs / "reference-again.zip", "w") as archive:
            for name, path in reference.items():
                archive.write(path, f"my-work/{name}")
            archive.writestr("my-work/notes.txt", "not a source file")
        self.paths.append(self.subs / "reference-again.zip")
        with tarfile.open(self.subs / "skeleton.tar.gz", "w:gz") as archive:
            for c in chapters:
                archive.add(ROOT / "skeleton" / source_name(c), source_name(c))
        self.paths.append(self.subs / "skeleton.tar.gz")
        self._folder("empty", {})
        broken = self._folder("does-not-compile", {})
        (broken / source_name(chapters[0])).write_text("#include <vector>\nint broken( {\n")
        (self.subs / "corrupt.zip").write_bytes(b"PK\x03\x04 this is not really a zip")
        self.paths.append(self.subs / "corrupt.zip")
        self._archive_bomb(self.subs / "archive-bomb.tar.gz")
        self.paths.append(self.subs / "archive-bomb.tar.gz")
        unlinked = self._folder("does-not-link", {})  # compiles, but defines none of the functions
        (unlinked / source_name(chapters[0])).write_text(f'#include "{chapters[0]}.hpp"\n')
        # Through the whole grader: every correct variant and, per chapter, two mistakes (one
        # that loses one step, one that loses several), the others marked "through_grader":
        # false. Every mutant's steps and feedback, at two seeds, are checked by
        # grader.mutants_at_two_seeds (tests/mutants/check_seeds.py), much faster than one
        # sandboxed process pair per test case; here the question is whether the grader's
        # wire, scoring and feedback give the same verdicts.
        mistakes = {}
        for mutant in sorted((ROOT / "tests" / "mutants").glob("*/*/expect.json")):
            expect = json.loads(mutant.read_text())
            if not expect.get("through_grader", True):
                continue
            chapter = mutant.parent.parent.name
            if expect["loses_steps"]:
                mistakes.setdefault(chapter, []).append(len(expect["loses_steps"]))
            self._add_expected(f"mutant-{chapter}-{mutant.parent.name}", mutant.parent, chapter)
        for chapter in chapters:
            lost = sorted(mistakes.get(chapter, []))
            assert lost and lost[0] == 1 and lost[-1] > 1, \
                f"{chapter}: the grader's batch needs a mistake that loses one step and one that loses several"
        for hostile in sorted((ROOT / "tests" / "hostile").glob("*/expect.json")):
            self._add_expected(f"hostile-{hostile.parent.name}", hostile.parent, None)
        self._names_archive(self.subs / f"{NAMES_ARCHIVE}.zip")
        self.paths.append(self.subs / f"{NAMES_ARCHIVE}.zip")

    @staticmethod
    def _names_archive(path):
        """A zip whose only chapter file lies in a folder named with terminal escapes (write
        the clipboard, clear the screen) and a spreadsheet formula, and is too large to grade:
        the name reaches the notes, the summary and results.json."""
        with zipfile.ZipFile(path, "w") as archive:
            archive.writestr(f"{HOSTILE_NAME}/{source_name(chapter_ids()[0])}", "// too large\n" * 90_000)

    @staticmethod
    def _archive_bomb(path, size=96 << 20):
        """A tar.gz of about 100 KiB that expands to 96 MiB of zeros, past the grader's limit."""
        class Zeros(io.RawIOBase):
            def __init__(self):
                self.left = size

            def readable(self):
                return True

            def readinto(self, buffer):
                count = min(len(buffer), self.left)
                buffer[:count] = bytes(count)
                self.left -= count
                return count

        with gzip.open(path, "wb", compresslevel=1) as packed, tarfile.open(fileobj=packed, mode="w|") as archive:
            info = tarfile.TarInfo("padding.bin")
            info.size = size
            archive.addfile(info, io.BufferedReader(Zeros(), 1 << 20))
            source = (ROOT / "solutions" / source_name(chapter_ids()[0])).read_bytes()
            info = tarfile.TarInfo(source_name(chapter_ids()[0]))
            info.size = len(source)
            archive.addfile(info, io.BytesIO(source))

    def _add_expected(self, name, folder, chapter):
        expect = json.loads((folder / "expect.json").read_text())
        chapter = chapter or expect.get("chapter") or next(
            c for c in chapter_ids() if (folder / source_name(c)).exists())
        # Cases hold only what differs from the reference; the submission is the composition.
        source = source_name(chapter)
        reference = ROOT / "solutions" / source
        composed = compose(reference.read_text(), (folder / source).read_text(), f"solutions/{source}")
        submission = self._folder(name, {})
        (submission / source).write_text(composed)
        self.expect[name] = (chapter, expect)


NAMES_ARCHIVE = "hostile-names"
HOSTILE_NAME = '=HYPERLINK("http://example.invalid")\x1b]52;c;aGVsbG8=\x07\x1b[2J\x9b31m\u202e'
BATCH = None
GRADESCOPE_THREAD = None


def batch():
    """The submissions, graded once; the Gradescope run (the slow part: setup.sh builds a
    kit) goes on beside it in a thread, since both mostly wait."""
    global BATCH, GRADESCOPE_THREAD
    if BATCH is None:
        made = Batch()
        GRADESCOPE_THREAD = threading.Thread(target=gradescope, args=(made,), daemon=True)
        GRADESCOPE_THREAD.start()
        made.grade()
        BATCH = made
    return BATCH


class GraderTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.b = batch()
        print(f"\ngraded {len(cls.b.paths)} submissions in {cls.b.seconds:.1f} s "
              f"({cls.b.seconds / len(cls.b.paths):.2f} s each)", file=sys.stderr)

    def steps(self, name, chapter):
        return self.b.results[name]["extra_data"]["chapters"][chapter]["steps"]

    def test_batch_finishes_with_every_row(self):
        self.assertEqual(self.b.run.returncode, 0, self.b.run.stderr[-3000:])
        names = [row["submission"] for row in self.b.rows]
        self.assertEqual(len(names), len(self.b.paths))
        self.assertEqual(names[:7], ["reference", "reference-again", "skeleton", "empty", "does-not-compile", "corrupt",
                                     "archive-bomb"])
        progress = [line for line in self.b.run.stdout.splitlines() if line.startswith("[")]
        self.assertEqual(len(progress), len(self.b.paths), self.b.run.stdout)
        self.assertTrue(progress[-1].startswith(f"[{len(self.b.paths)}/{len(self.b.paths)}]"))
        for name in names:
            self.assertIn(name, self.b.results, f"no results.json for {name}")

    def test_reference_scores_full_marks_and_skeleton_zero(self):
        for name in ("reference", "reference-again"):
            result = self.b.results[name]
            self.assertGreater(result["score"], 0)
            self.assertEqual(result["score"], result["extra_data"]["max_score"], result["output"])
            self.assertTrue(all(t["status"] == "passed" for t in result["tests"]))
        # A test name with a comma must be selected exactly (Catch2 test-spec escaping).
        self.assertTrue(any("," in t["name"] for t in self.b.results["reference"]["tests"]))
        for name in ("skeleton", "empty"):
            self.assertEqual(self.b.results[name]["score"], 0)
        self.assertIn("untouched skeleton", self.b.results["empty"]["output"])

    def test_the_same_files_in_an_archive_score_the_same(self):
        # (Within a batch, identical files are graded once; that a second, separate run gives
        # the same results is checked against the Gradescope run below.)
        first, again = self.b.results["reference"], self.b.results["reference-again"]
        self.assertEqual([(t["name"], t["score"], t["status"]) for t in first["tests"]],
                         [(t["name"], t["score"], t["status"]) for t in again["tests"]])
        seed = first["extra_data"]["seed"]
        self.assertIn(f"Random seed {seed}", first["output"])

    def test_each_mutant_and_hostile_loses_exactly_its_steps(self):
        sandboxed = "bubblewrap" in self.b.results["reference"]["output"]
        for name, (chapter, expect) in self.b.expect.items():
            with self.subTest(submission=name):
                if name == "hostile-read-secrets" and not sandboxed:
                    self.skipTest("this tree is readable by every user; GradescopeTest checks the protected one")
                check_expectation(self, name, chapter, expect, self.b.results[name],
                                  (self.b.out / name / "summary.txt").read_text())

    def test_fork_loop_is_stopped_and_leaves_no_process(self):
        if os.getuid() == 0 and "fresh unprivileged uid" in self.b.results["reference"]["output"]:
            outputs = "\n".join(t["output"] for t in self.b.results["hostile-fork-loop"]["tests"])
            self.assertIn("then fork failed", outputs, "the process limit did not stop the fork loop")
        self.assertEqual(processes_left(self.b.grader_pid), [], "sandboxed processes outlived the batch")

    def test_no_hostile_submission_spies_escapes_or_outgrows_its_case(self):
        check_isolation(self, self.b.out, self.b.results, self.b.run.stdout,
                        "fresh unprivileged uid" in self.b.results["reference"]["output"])

    def test_interrupt_records_nothing_half_graded_and_resume_grades_it(self):
        """Ctrl-C in a terminal sends SIGINT to the whole process group: the batch stops, no
        submission graded meanwhile is recorded, and --resume grades them all."""
        out = self.b.tmp / "interrupted"
        paths = [str(self.b.subs / "reference"), str(self.b.subs / "hostile-segfault")]
        command = [*GRADE, "--build-dir", str(BUILD_DIR), "--out", str(out), "--time-limit",
                   TIME_LIMIT, "--quiet", *paths]
        with subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                              start_new_session=True, env=GRADE_ENV) as grader:
            # Grading starts right after this line; on a busy machine the grader may take
            # seconds to get there (Python's start, the kit, the sandbox's probe).
            header = ""
            while not header.startswith("Isolation:") and grader.poll() is None:
                header = grader.stdout.readline()
            time.sleep(3)
            os.killpg(grader.pid, signal.SIGINT)
            stdout, stderr = grader.communicate(timeout=60)
        if grader.returncode == 0:
            self.skipTest("the batch finished before the interrupt")
        self.assertEqual(grader.returncode, 130, stderr[-2000:])
        self.assertIn("--resume", stderr)
        self.assertEqual(processes_left(grader.pid), [])
        resumed = subprocess.run(command + ["--resume"], capture_output=True, text=True, timeout=300)
        self.assertEqual(resumed.returncode, 0, resumed.stderr[-2000:])
        with open(out / "gradebook.csv", newline="") as file:
            rows = {row["submission"]: row for row in csv.DictReader(file)}
        self.assertEqual(set(rows), {"reference", "hostile-segfault"})
        self.assertEqual(rows["reference"]["total"], rows["reference"]["max"])
        batch_rows = {row["submission"]: row for row in self.b.rows}
        self.assertEqual(rows["hostile-segfault"]["total"], batch_rows["hostile-segfault"]["total"])
        for name in rows:
            self.assertNotIn("SIGINT", (out / name / "results.json").read_text())

    def test_planted_results_are_ignored(self):
        # The planted file claims full marks; the hostile case is a chapter-1 submission, so
        # its own chapter must be graded on what its functions return: full marks, no more.
        result = self.b.results["hostile-write-results"]
        chapter = self.b.expect["hostile-write-results"][0]
        graded = result["extra_data"]["chapters"][chapter]
        self.assertEqual(graded["score"], graded["max_score"])
        self.assertEqual(result["score"], sum(c["score"] for c in result["extra_data"]["chapters"].values()))
        for path in self.b.out.rglob("*"):
            if path.is_file():
                self.assertNotIn("planted", path.read_text(errors="replace"), f"{path} was written by student code")

    def test_missing_or_empty_paths_are_refused(self):
        empty = self.b.tmp / "nothing-here"
        empty.mkdir(exist_ok=True)
        for path in (self.b.tmp / "no-such-submission", empty):
            run = subprocess.run([*GRADE, "--build-dir", str(BUILD_DIR), "--out",
                                  str(self.b.tmp / "refused"), str(path)], capture_output=True, text=True, timeout=60,
                                 env=GRADE_ENV)
            self.assertEqual(run.returncode, 2, run.stdout)
            self.assertIn(str(path), run.stderr)
            self.assertFalse((self.b.tmp / "refused" / "gradebook.csv").exists())

    def test_resume_keeps_finished_rows(self):
        """A second run with --resume over the same --out grades nothing again."""
        run = subprocess.run([*GRADE, "--build-dir", str(BUILD_DIR), "--out", str(self.b.out),
                              "--resume", "--quiet", *map(str, self.b.paths)], capture_output=True, text=True,
                             timeout=120, env=GRADE_ENV)
        self.assertEqual(run.returncode, 0, run.stderr[-2000:])
        self.assertIn(f"Resuming: {len(self.b.paths)} submission(s)", run.stdout)
        self.assertFalse([line for line in run.stdout.splitlines() if line.startswith("[")])
        with open(self.b.out / "gradebook.csv", newline="") as file:
            self.assertEqual(list(csv.DictReader(file)), self.b.rows)

    def test_compile_error_and_broken_archives(self):
        chapter = chapter_ids()[0]
        result = self.b.results["does-not-compile"]
        self.assertEqual(result["extra_data"]["chapters"][chapter]["score"], 0)
        self.assertEqual(result["extra_data"]["chapters"][chapter]["problem"], "did not compile")
        self.assertIn("error", result["tests"][0]["output"])
        self.assertIn("did not compile", result["tests"][0]["output"])
        rows = {row["submission"]: row for row in self.b.rows}
        self.assertEqual(rows["archive-bomb"]["status"], "error")
        self.assertIn("64 MiB", rows["archive-bomb"]["notes"])
        self.assertLess(self.b.results["archive-bomb"]["execution_time"], 10)
        self.assertEqual(rows["corrupt"]["status"], "error")
        self.assertIn("archive", rows["corrupt"]["notes"])
        self.assertEqual(rows["does-not-compile"]["status"], "graded")
        self.assertIn("did not compile", rows["does-not-compile"]["notes"])

    def test_link_errors_name_the_missing_functions_and_no_test_file(self):
        chapter = chapter_ids()[0]
        result = self.b.results["does-not-link"]
        self.assertEqual(result["extra_data"]["chapters"][chapter]["problem"], "did not link")
        output = result["tests"][0]["output"]
        self.assertIn("does not define these functions", output)
        self.assertIn(f"workbook::{chapter.replace('-', '_')}::", output)
        self.assertNotIn("tests/", output)

    def test_results_json_has_gradescope_fields(self):
        for name, result in self.b.results.items():
            with self.subTest(submission=name):
                self.assertIsInstance(result["score"], (int, float))
                self.assertIsInstance(result["execution_time"], (int, float))
                self.assertIsInstance(result["output"], str)
                self.assertIsInstance(result["tests"], list)
                self.assertTrue(result["tests"])
                for test in result["tests"]:
                    for key, kind in GRADESCOPE_TEST_KEYS.items():
                        self.assertIsInstance(test[key], kind, f"{key} in {test}")
                    self.assertIn(test["status"], ("passed", "failed"))
                    self.assertIn(test["visibility"], VISIBILITIES)
                    self.assertTrue(0 <= test["score"] <= test["max_score"])
                    if test["max_score"] > 0:
                        self.assertEqual(test["status"] == "passed", test["score"] == test["max_score"])
                self.assertAlmostEqual(result["score"], sum(t["score"] for t in result["tests"]))
                chapters = result["extra_data"]["chapters"]
                self.assertAlmostEqual(result["extra_data"]["max_score"], sum(t["max_score"] for t in result["tests"]))
                self.assertAlmostEqual(result["score"], sum(c["score"] for c in chapters.values()))
                for chapter in chapters.values():
                    self.assertAlmostEqual(chapter["score"], sum(s["score"] for s in chapter["steps"].values()))
                    self.assertAlmostEqual(chapter["max_score"], sum(s["max_score"] for s in chapter["steps"].values()))

    def test_hidden_tests_show_no_source(self):
        hidden_lines = set()
        for path in (ROOT / "tests" / "hidden").rglob("*.[ch]pp"):
            hidden_lines |= {line.strip() for line in path.read_text().splitlines() if len(line.strip()) > 30}
        hidden_seen = 0
        for name, result in self.b.results.items():
            for test in result["tests"]:
                if "(hidden test)" not in test["name"]:
                    self.assertEqual(test["visibility"], "visible")
                    continue
                hidden_seen += 1
                self.assertEqual(test["visibility"], "after_published")
                for needle in ("TEST_CASE", "tests/hidden", "#include", "hidden/", "SECTION("):
                    self.assertNotIn(needle, test["output"], f"{name}: {test['name']}")
                # A file and line may be named only when it is the student's own file.
                own = {source_name(c) for c in chapter_ids()}
                for named in re.findall(r"([\w./-]+\.cpp):", test["output"]):
                    self.assertIn(named, own, f"{name}: {test['name']} names {named}")
                for line in hidden_lines:
                    self.assertNotIn(line, test["output"], f"{name}: {test['name']} shows a line of its source")
        if any((ROOT / "tests" / "hidden").glob("*.cpp")):
            self.assertGreater(hidden_seen, 0)

    def test_gradebook_csv_columns_and_sums(self):
        chapters = chapter_ids()
        steps = [c for c in self.b.columns if " step " in c]
        self.assertEqual(self.b.columns, ["submission", *chapters, *steps, "total", "max", "status", "notes"])
        self.assertEqual(len(steps), sum(len(self.steps("reference", c)) for c in chapters))
        maximum = {float(row["max"]) for row in self.b.rows}
        self.assertEqual(len(maximum), 1)
        for row in self.b.rows:
            with self.subTest(row=row["submission"]):
                self.assertIn(row["status"], ("graded", "error"))
                self.assertAlmostEqual(float(row["total"]), sum(float(row[c]) for c in chapters))
                self.assertAlmostEqual(float(row["total"]), sum(float(row[s]) for s in steps))
                self.assertLessEqual(float(row["total"]), float(row["max"]))
                if row["submission"] in self.b.results:
                    self.assertAlmostEqual(float(row["total"]), self.b.results[row["submission"]]["score"])



CRASH_AT_START = """
// Crashes while the program starts, before any function is called.
namespace {
volatile int* volatile nowhere = nullptr;
volatile int crash = *nowhere;
}  // namespace
"""


class Gradescope:
    """The Gradescope autograder exactly as Gradescope runs it, in a temporary <root>: unzip to
    <root>/source, run setup.sh from there, copy run_autograder to <root>/run_autograder and run
    it from <root> with the submission in <root>/submission, read <root>/results/results.json.
    Bubblewrap is hidden (WORKBOOK_NO_BWRAP=1), as in Gradescope's containers. The root lives
    under the build folder so that the shared compiler cache recognises setup.sh's build."""

    def __init__(self, made):
        self.root = BUILD_DIR / "gradescope-test"
        shutil.rmtree(self.root, ignore_errors=True)
        self.root.mkdir(parents=True)
        zip_path = self.root / "autograder.zip"
        self.pack = subprocess.run([*PACK, str(zip_path)], capture_output=True, text=True, timeout=300,
                                   env=PACK_ENV)
        if self.pack.returncode != 0:
            return
        with zipfile.ZipFile(zip_path) as archive:
            self.names = archive.namelist()
            self.modes = {n: archive.getinfo(n).external_attr >> 16 for n in ("setup.sh", "run_autograder")}
        self.sources_before = self._apt_sources()
        subprocess.run(["unzip", "-q", str(zip_path), "-d", str(self.root / "source")], check=True)
        # As Gradescope runs it: no compiler cache (a fresh machine has none), whatever the
        # caller's environment says.
        env = {k: v for k, v in os.environ.items() if k != "CMAKE_CXX_COMPILER_LAUNCHER"}
        self.setup = subprocess.run(["./setup.sh"], cwd=self.root / "source", env=env, capture_output=True, text=True,
                                    timeout=900)
        self.sources_after = self._apt_sources()
        shutil.copy2(self.root / "source" / "run_autograder", self.root / "run_autograder")
        self.results = {}
        chapters = chapter_ids()
        reference = {source_name(c): (ROOT / "solutions" / source_name(c)).read_text() for c in chapters}
        skeleton = {source_name(c): (ROOT / "skeleton" / source_name(c)).read_text() for c in chapters}
        crashing = {**skeleton, source_name(chapters[0]): skeleton[source_name(chapters[0])] + CRASH_AT_START}
        for label, files in (("reference", reference), ("skeleton", skeleton), ("crashing", crashing)):
            self.grade(label, files)
        # Every hostile case again, graded by the kit setup.sh built, as root without bubblewrap:
        # fresh unprivileged uids and the permissions setup.sh set are all that protect. Two
        # submissions at a time, so that one can look for the other's files.
        self.hostile = {n: e for n, e in made.expect.items() if n.startswith("hostile-")}
        self.hostile_out = self.root / "hostile-out"
        grade, grade_env = module("grader.grade", self.root / "source" / "workbook")
        with subprocess.Popen(
                [*grade, "--build-dir", str(self.root / "source" / "workbook" / "build" / "grader"),
                 "--out", str(self.hostile_out), "--time-limit", TIME_LIMIT, "--memory-mb", MEMORY_MB, "--quiet",
                 "--no-bwrap", "-j", "2", "--case-jobs", "1",
                 *(str(made.subs / n) for n in self.hostile), str(made.subs / f"{NAMES_ARCHIVE}.zip")],
                stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=grade_env) as grader:
            self.hostile_pid = grader.pid
            stdout, stderr = grader.communicate(timeout=600)
        self.hostile_run = subprocess.CompletedProcess(grader.args, grader.returncode, stdout, stderr)

    @staticmethod
    def _apt_sources():
        listing = {}
        for folder in ("/etc/apt/sources.list.d",):
            if os.path.isdir(folder):
                listing.update({name: pathlib.Path(folder, name).read_bytes() for name in os.listdir(folder)})
        if os.path.isfile("/etc/apt/sources.list"):
            listing["sources.list"] = pathlib.Path("/etc/apt/sources.list").read_bytes()
        return listing

    def grade(self, label, files):
        submission = self.root / "submission"
        shutil.rmtree(submission, ignore_errors=True)
        submission.mkdir()
        for name, text in files.items():
            (submission / name).write_text(text)
        env = {**os.environ, "AUTOGRADER_ROOT": str(self.root), "WORKBOOK_NO_BWRAP": "1"}
        env.pop("WORKBOOK_KIT_BUILD_DIR", None)
        run = subprocess.run([str(self.root / "run_autograder")], cwd=self.root, env=env, capture_output=True,
                             text=True, timeout=300)
        results = json.loads((self.root / "results" / "results.json").read_text())
        self.results[label] = (run, results)
        return run, results


GRADESCOPE = None


def gradescope(made=None):
    """Built once, in the thread batch() starts; a test asking for it waits for that thread."""
    global GRADESCOPE
    if made is not None:
        GRADESCOPE = Gradescope(made)
        return GRADESCOPE
    batch()
    GRADESCOPE_THREAD.join()
    return GRADESCOPE


class GradescopeTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.b = batch()
        cls.g = gradescope()

    def test_zip_layout(self):
        self.assertEqual(self.g.pack.returncode, 0, self.g.pack.stderr)
        self.assertIn("setup.sh", self.g.names)
        self.assertIn("run_autograder", self.g.names)
        self.assertFalse(any(n.startswith("workbook/build/") or "/.git/" in n for n in self.g.names))
        self.assertTrue(any(n.startswith("workbook/solutions/") for n in self.g.names))
        for script, mode in self.g.modes.items():
            self.assertTrue(mode & 0o111, f"{script} not executable")

    def test_setup_builds_the_kit_leaves_apt_sources_alone_and_hides_the_tree(self):
        self.assertEqual(self.g.setup.returncode, 0, self.g.setup.stdout[-2000:] + self.g.setup.stderr[-2000:])
        self.assertEqual(self.g.sources_before, self.g.sources_after, "setup.sh changed the package sources")
        source = self.g.root / "source"
        for path in (source, source / "workbook" / "solutions", source / "workbook" / "tests" / "hidden"):
            self.assertEqual(path.stat().st_mode & 0o077, 0, f"{path} is readable by other users")

    def test_reference_full_marks_skeleton_and_crash_zero(self):
        run, results = self.g.results["reference"]
        self.assertEqual(run.returncode, 0, run.stderr)
        self.assertGreater(results["score"], 0)
        self.assertEqual(results["score"], results["extra_data"]["max_score"], results["output"])
        self.assertIn("resource limits only", results["output"])
        # Regrading is deterministic: another run, with its own kit, gives every case the same
        # score and status as the batch did.
        self.assertEqual([(t["name"], t["score"], t["status"]) for t in results["tests"]],
                         [(t["name"], t["score"], t["status"]) for t in self.b.results["reference"]["tests"]])
        for label in ("skeleton", "crashing"):
            run, results = self.g.results[label]
            self.assertEqual(run.returncode, 0, run.stderr)
            self.assertEqual(results["score"], 0, results["output"])
            self.assertTrue(results["tests"])
            self.assertTrue(all(t["status"] == "failed" for t in results["tests"]))
        self.assertTrue(any("crashed with a segmentation fault" in t["output"] for t in self.g.results["crashing"][1]["tests"]),
                        self.g.results["crashing"][1]["tests"][0]["output"])

    def test_hostile_submissions_without_bubblewrap(self):
        self.assertEqual(self.g.hostile_run.returncode, 0, self.g.hostile_run.stderr[-3000:])
        self.assertNotIn("student code can read", self.g.hostile_run.stderr)
        for name, (chapter, expect) in self.g.hostile.items():
            with self.subTest(submission=name):
                results = json.loads((self.g.hostile_out / name / "results.json").read_text())
                self.assertIn("resource limits only", results["output"])
                summary = (self.g.hostile_out / name / "summary.txt").read_text()
                if name == "hostile-read-secrets":
                    # Other trees on this machine (this repository, say) may be readable; the
                    # Gradescope tree must not be.
                    self.assertNotIn(str(self.g.root), json.dumps(results))
                    continue
                check_expectation(self, name, chapter, expect, results, summary)

    def test_hostile_submissions_without_bubblewrap_neither_spy_nor_outlive_their_case(self):
        results = {}
        for folder in self.g.hostile_out.iterdir():
            if (folder / "results.json").is_file():
                results[folder.name] = json.loads((folder / "results.json").read_text())
        check_isolation(self, self.g.hostile_out, results, self.g.hostile_run.stdout, os.getuid() == 0)
        self.assertEqual(processes_left(self.g.hostile_pid), [], "processes outlived the batch")
        # The hopping daemon moves to a new pid faster than /proc can be listed; its sign of
        # life is a file it creates again and again.
        alive = pathlib.Path("/tmp/workbook-hopper-alive")
        alive.unlink(missing_ok=True)
        time.sleep(0.5)
        self.assertFalse(alive.exists(), "the hopping daemon outlived its test case")
        if os.getuid() == 0:  # fresh uids: what they left in the machine's shared folders is removed
            for folder in ("/tmp", "/dev/shm", "/var/tmp"):
                left = [n for n in os.listdir(folder) if n.startswith(("workbook-tmp-fill-", "workbook-spy"))]
                self.assertEqual(left, [], f"left in {folder}")
        out_mode = self.g.hostile_out.stat().st_mode & 0o777
        self.assertEqual(out_mode, 0o700)
        for path in self.g.hostile_out.rglob("*"):
            self.assertEqual(path.stat().st_mode & 0o077, 0, f"{path} is readable by other users")


def processes_left(grader_pid):
    """Live processes of the fresh uids a grader with this pid used."""
    first_uid = FRESH_UID_BASE + (grader_pid % 100_000) * 10_000
    own_uids = range(first_uid, first_uid + 10_000)
    left = []
    for entry in os.listdir("/proc"):
        try:
            if entry.isdigit() and os.stat(f"/proc/{entry}").st_uid in own_uids:
                state = pathlib.Path(f"/proc/{entry}/stat").read_text().rsplit(")", 1)[1].split()[0]
                if state != "Z":
                    left.append(entry)
        except (FileNotFoundError, ProcessLookupError, IndexError):
            continue
    return left


def failed_outputs(results, visible=None):
    return [t["output"] for t in results["tests"] if t["status"] == "failed"
            and (visible is None or (t["visibility"] == "visible") == visible)]


def check_isolation(test, out, results, stdout, fresh_uids):
    """What the hostile submissions that spy, fill /tmp or hold memory in children must
    not achieve, in either mode; and that names from an archive reach no output raw."""
    spy = results["hostile-spy-on-cases"]
    hidden_names = [t["name"].split(" · ")[-1][:-len(" (hidden test)")] for t in spy["tests"]
                    if t["name"].endswith("(hidden test)")]
    visible = "\n".join(failed_outputs(spy, visible=True))
    test.assertIn("inputs", visible, "the spy did not run")
    for name in hidden_names:
        test.assertNotIn(name, visible, "a visible test's output names a hidden test")
    own_inputs = lambda outputs: set(re.findall(r"my inputs (inputs [^;]*;)", "\n".join(outputs)))
    hidden_only = own_inputs(failed_outputs(spy, visible=False)) - own_inputs(failed_outputs(spy, visible=True))
    for inputs in hidden_only:
        test.assertNotIn(inputs, visible, "a visible test's output holds a hidden test's inputs")
    fill = "\n".join(failed_outputs(results["hostile-tmp-fill"]))
    written = [int(n) for n in re.findall(r"wrote (\d+) MiB", fill)]
    test.assertTrue(written or "MiB to disk" in fill, fill[:500])
    test.assertLessEqual(max(written, default=0), 128, "/tmp or /dev/shm held more than their size")
    if fresh_uids:
        held = failed_outputs(results["hostile-memory-in-children"])
        test.assertTrue(any("MiB of memory" in output for output in held),
                        "the memory held in children was not named:\n" + "\n".join(o[:300] for o in held))
    # Names with terminal escapes and formulas: plain text everywhere.
    names = results[NAMES_ARCHIVE]
    raw = (out / NAMES_ARCHIVE / "results.json").read_text(encoding="utf-8") + stdout
    raw += (out / NAMES_ARCHIVE / "summary.txt").read_text(encoding="utf-8")
    test.assertIn("HYPERLINK", json.dumps(names))
    for bad in ("\x1b", "\x07", "\x9b", "\u202e", "\\u001b"):
        test.assertNotIn(bad, raw)
    with open(out / "gradebook.csv", newline="", encoding="utf-8") as file:
        for row in csv.DictReader(file):
            for value in row.values():
                test.assertFalse(value.startswith(("=", "+", "@")) or value.startswith("-") and not
                                 re.fullmatch(r"-[\d.]+", value), f"a formula in the gradebook: {value!r}")
                test.assertNotIn("\x1b", value)


def check_expectation(test, name, chapter, expect, results, summary):
    lost = set(expect["loses_steps"])
    steps = results["extra_data"]["chapters"][chapter]["steps"]
    test.assertTrue(lost <= {int(s) for s in steps}, f"unknown step in {expect}")
    for number, step in steps.items():
        if int(number) in lost:
            test.assertLess(step["score"], step["max_score"], f"{name} keeps step {number}")
        else:
            failed = "\n".join(t["output"][:400] for t in results["tests"] if t["status"] == "failed")
            test.assertEqual(step["score"], step["max_score"], f"{name} loses step {number}: {failed[:1500]}")
    if expect.get("feedback"):
        failed = [t["output"] for t in results["tests"] if t["status"] == "failed"]
        test.assertTrue(any(expect["feedback"] in text for text in failed),
                        f"{name}: no failed test says '{expect['feedback']}': {failed[:1]}")
    everything = json.dumps(results) + summary
    for secret in expect.get("must_not_show", []):
        test.assertNotIn(secret, everything, f"{name} shows '{secret}'")
    for line in hidden_source_lines():
        test.assertNotIn(line, everything, f"{name} shows a line of a hidden test")
    for line in solution_lines():
        test.assertNotIn(line, everything, f"{name} shows a line of a reference solution")


def hidden_source_lines():
    lines = set()
    for path in (ROOT / "tests" / "hidden").rglob("*.[ch]pp"):
        lines |= {line.strip() for line in path.read_text().splitlines() if len(line.strip()) > 30}
    return lines


def solution_lines():
    lines = set()
    for path in (ROOT / "solutions").glob("*.cpp"):
        lines |= {line.strip() for line in path.read_text().splitlines()
                  if len(line.strip()) > 30 and not line.strip().startswith(("//", "#include"))}
    return lines


def main():
    global BUILD_DIR
    parser = argparse.ArgumentParser()
    parser.add_argument("--build-dir", default=str(BUILD_DIR))
    args, rest = parser.parse_known_args()
    BUILD_DIR = pathlib.Path(args.build_dir).resolve()
    started = time.monotonic()
    program = unittest.main(argv=[sys.argv[0], *rest], exit=False, verbosity=2)
    print(f"grader test took {time.monotonic() - started:.1f} s", file=sys.stderr)
    if BATCH is not None and program.result.wasSuccessful():
        shutil.rmtree(BATCH.tmp, ignore_errors=True)
        if GRADESCOPE is not None:
            shutil.rmtree(GRADESCOPE.root, ignore_errors=True)
    elif BATCH is not None:
        print(f"kept {BATCH.tmp} for inspection", file=sys.stderr)
    sys.exit(0 if program.result.wasSuccessful() else 1)


if __name__ == "__main__":
    main()
