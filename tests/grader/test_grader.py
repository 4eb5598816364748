#!/usr/bin/env python3
"""Trust in the grader: grades the reference, the untouched skeleton, every mutant
(tests/mutants/<chapter>/<name>/) and every hostile submission (tests/hostile/<name>/) in ONE
batch, then checks the scores against each expect.json, the output formats, that hidden
tests leak no source, that regrading is deterministic, and that the Gradescope zip works
against a simulated /autograder tree.

    python3 tests/grader/test_grader.py --build-dir build/dev   (ctest runs it: label grader)"""
import argparse
import csv
import json
import os
import pathlib
import shutil
import subprocess
import sys
import tarfile
import tempfile
import time
import unittest
import zipfile

from compose import compose

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "tools"))
import workbook_files  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[2]
GRADE = ROOT / "grader" / "grade.py"
PACK = ROOT / "grader" / "pack_gradescope.py"
BUILD_DIR = ROOT / "build" / "dev"
TIME_LIMIT = "3"
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
        started = time.monotonic()
        with subprocess.Popen([sys.executable, str(GRADE), "--build-dir", str(BUILD_DIR), "--out", str(self.out),
                               "--time-limit", TIME_LIMIT, "--quiet", *map(str, self.paths)],
                              stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True) as grader:
            # The sandbox derives its fresh uids from the grader's pid; the fork-loop check
            # looks at those alone, so another grader running on the machine cannot fail it.
            self.grader_pid = grader.pid
            stdout, stderr = grader.communicate(timeout=900)
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
        unlinked = self._folder("does-not-link", {})  # compiles, but defines none of the functions
        (unlinked / source_name(chapters[0])).write_text(f'#include "{chapters[0]}.hpp"\n')
        for mutant in sorted((ROOT / "tests" / "mutants").glob("*/*/expect.json")):
            name = f"mutant-{mutant.parent.parent.name}-{mutant.parent.name}"
            self._add_expected(name, mutant.parent, mutant.parent.parent.name)
        for hostile in sorted((ROOT / "tests" / "hostile").glob("*/expect.json")):
            self._add_expected(f"hostile-{hostile.parent.name}", hostile.parent, None)

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


BATCH = None


def batch():
    global BATCH
    if BATCH is None:
        BATCH = Batch()
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
        self.assertEqual(names[:6], ["reference", "reference-again", "skeleton", "empty", "does-not-compile", "corrupt"])
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

    def test_regrading_is_deterministic(self):
        first, again = self.b.results["reference"], self.b.results["reference-again"]
        self.assertEqual([(t["name"], t["score"], t["status"]) for t in first["tests"]],
                         [(t["name"], t["score"], t["status"]) for t in again["tests"]])
        seed = first["extra_data"]["seed"]
        self.assertIn(f"Random seed {seed}", first["output"])

    def test_each_mutant_and_hostile_loses_exactly_its_steps(self):
        sandboxed = "bubblewrap" in self.b.results["reference"]["output"]
        for name, (chapter, expect) in self.b.expect.items():
            with self.subTest(submission=name):
                lost = set(expect["loses_steps"])
                if name == "hostile-read-secrets" and not sandboxed:
                    self.skipTest("without bubblewrap the secrets are readable: that is the printed warning")
                steps = self.steps(name, chapter)
                self.assertTrue(lost <= {int(s) for s in steps}, f"unknown step in {expect}")
                for number, step in steps.items():
                    if int(number) in lost:
                        self.assertLess(step["score"], step["max_score"], f"{name} keeps step {number}")
                    else:
                        self.assertEqual(step["score"], step["max_score"], f"{name} loses step {number}: "
                                         + self._failed_output(name, chapter, number))
                if expect.get("feedback"):
                    failed = [t["output"] for t in self.b.results[name]["tests"] if t["status"] == "failed"]
                    self.assertTrue(any(expect["feedback"] in text for text in failed),
                                    f"{name}: no failed test says '{expect['feedback']}': {failed[:1]}")

    def _failed_output(self, name, chapter, step):
        index = chapter_ids().index(chapter) + 1
        return "\n".join(t["output"][:400] for t in self.b.results[name]["tests"]
                         if t["status"] == "failed" and t.get("number", "").startswith(f"{index}.{step}."))

    def test_fork_loop_is_stopped_and_leaves_no_process(self):
        if os.getuid() == 0 and "fresh unprivileged uid" in self.b.results["reference"]["output"]:
            outputs = "\n".join(t["output"] for t in self.b.results["hostile-fork-loop"]["tests"])
            self.assertIn("then fork failed", outputs, "the process limit did not stop the fork loop")
        first_uid = FRESH_UID_BASE + (self.b.grader_pid % 100_000) * 10_000
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
        self.assertEqual(left, [], "sandboxed processes outlived the batch")

    def test_planted_results_are_ignored(self):
        result = self.b.results["hostile-write-results"]
        self.assertEqual(result["score"], result["extra_data"]["max_score"])
        for path in self.b.out.rglob("*"):
            if path.is_file():
                self.assertNotIn("planted", path.read_text(errors="replace"), f"{path} was written by student code")

    def test_compile_error_and_broken_archives(self):
        chapter = chapter_ids()[0]
        result = self.b.results["does-not-compile"]
        self.assertEqual(result["extra_data"]["chapters"][chapter]["score"], 0)
        self.assertEqual(result["extra_data"]["chapters"][chapter]["problem"], "did not compile")
        self.assertIn("error", result["tests"][0]["output"])
        self.assertIn("did not compile", result["tests"][0]["output"])
        rows = {row["submission"]: row for row in self.b.rows}
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
        for path in (ROOT / "tests" / "hidden").glob("*.cpp"):
            hidden_lines |= {line.strip() for line in path.read_text().splitlines() if len(line.strip()) > 30}
        hidden_seen = 0
        for name, result in self.b.results.items():
            for test in result["tests"]:
                if "(hidden test)" not in test["name"]:
                    self.assertEqual(test["visibility"], "visible")
                    continue
                hidden_seen += 1
                self.assertEqual(test["visibility"], "after_published")
                for needle in ("TEST_CASE", "tests/hidden", "#include", "hidden/", ".cpp:", "SECTION("):
                    self.assertNotIn(needle, test["output"], f"{name}: {test['name']}")
                for line in hidden_lines:
                    self.assertNotIn(line, test["output"], f"{name}: {test['name']} shows a line of its source")
        if any((ROOT / "tests" / "hidden").glob("*.cpp")):
            self.assertGreater(hidden_seen, 0)

    def test_gradebook_csv_columns_and_sums(self):
        chapters = chapter_ids()
        self.assertEqual(self.b.columns, ["submission", *chapters, "total", "max", "status", "notes"])
        maximum = {float(row["max"]) for row in self.b.rows}
        self.assertEqual(len(maximum), 1)
        for row in self.b.rows:
            with self.subTest(row=row["submission"]):
                self.assertIn(row["status"], ("graded", "error"))
                self.assertAlmostEqual(float(row["total"]), sum(float(row[c]) for c in chapters))
                self.assertLessEqual(float(row["total"]), float(row["max"]))
                if row["submission"] in self.b.results:
                    self.assertAlmostEqual(float(row["total"]), self.b.results[row["submission"]]["score"])

    def test_gradescope_zip_against_a_simulated_autograder(self):
        root = self.b.tmp / "gradescope"
        zip_path = self.b.tmp / "autograder.zip"
        pack = subprocess.run([sys.executable, str(PACK), str(zip_path)], capture_output=True, text=True, timeout=300)
        self.assertEqual(pack.returncode, 0, pack.stderr)
        with zipfile.ZipFile(zip_path) as archive:
            names = archive.namelist()
            self.assertIn("setup.sh", names)
            self.assertIn("run_autograder", names)
            self.assertFalse(any(n.startswith("workbook/build/") or "/.git/" in n for n in names))
            self.assertTrue(any(n.startswith("workbook/solutions/") for n in names))
            for script in ("setup.sh", "run_autograder"):
                self.assertTrue((archive.getinfo(script).external_attr >> 16) & 0o111, f"{script} not executable")
            archive.extractall(root / "autograder" / "source")
        source = root / "autograder" / "source"
        for script in ("setup.sh", "run_autograder"):
            os.chmod(source / script, 0o755)
            self.assertEqual(subprocess.run(["bash", "-n", str(source / script)]).returncode, 0)
        mutant = next(name for name in self.b.expect if name.startswith("mutant-"))
        shutil.copytree(self.b.subs / mutant, root / "autograder" / "submission")
        env = {**os.environ, "AUTOGRADER_ROOT": str(root / "autograder"), "WORKBOOK_KIT_BUILD_DIR": str(BUILD_DIR)}
        run = subprocess.run([str(source / "run_autograder")], env=env, capture_output=True, text=True, timeout=300)
        self.assertEqual(run.returncode, 0, run.stderr)
        results = json.loads((root / "autograder" / "results" / "results.json").read_text())
        self.assertEqual(results["score"], self.b.results[mutant]["score"])
        self.assertEqual(len(results["tests"]), len(self.b.results[mutant]["tests"]))
        # Without a kit, the student still gets a results.json that says what went wrong.
        env["WORKBOOK_KIT_BUILD_DIR"] = str(self.b.tmp / "no-kit")
        subprocess.run([str(source / "run_autograder")], env=env, capture_output=True, timeout=120)
        broken = json.loads((root / "autograder" / "results" / "results.json").read_text())
        self.assertEqual(broken["score"], 0)
        self.assertIn("instructor", broken["output"])


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
    elif BATCH is not None:
        print(f"kept {BATCH.tmp} for inspection", file=sys.stderr)
    sys.exit(0 if program.result.wasSuccessful() else 1)


if __name__ == "__main__":
    main()
