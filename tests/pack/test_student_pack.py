#!/usr/bin/env python3
"""The student edition: written into a temporary folder and proved free of solution and
hidden-test text by its file list and its content. (test_off_debian.py runs a pack's quick
start and checks every chapter from scratch, with Clang alone: one build of the pack for the
whole suite, since the same sources are built with GCC in this tree's own build.)"""
import pathlib
import subprocess
import tempfile
import unittest

from grader import pack_student

ROOT = pathlib.Path(__file__).resolve().parents[2]

# Answers live in C++: the reference, hidden tests and mutants. (The grader and the hostile
# submissions are kept out of the pack by the file-list test; they hold no answer, and their
# boilerplate lines, such as a catch clause, prove nothing here.)
SECRET_FOLDERS = ["solutions", "tests/hidden", "tests/mutants"]
SECRET_CODE = {".cpp", ".hpp"}
PUBLIC_FOLDERS = ["skeleton", "tests/steps", "tests/engine", "tests/support", "engine", "chapters", "tools"]


def text_files(folder):
    return [p for p in folder.rglob("*") if p.is_file() and p.suffix in {".cpp", ".hpp", ".py", ".md", ".json", ".txt", ".sh", ""}]


def significant_lines(path):
    """Lines long enough to identify their file (short lines like '}' are everywhere)."""
    try:
        lines = path.read_text(errors="replace").splitlines()
    except OSError:
        return set()
    return {" ".join(line.split()) for line in lines if len(line.strip()) >= 24}


class StudentPackTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.scratch = tempfile.TemporaryDirectory(prefix="student-pack-")
        cls.pack = pathlib.Path(cls.scratch.name) / "workbook-student"
        pack_student.write_pack(cls.pack)

    @classmethod
    def tearDownClass(cls):
        cls.scratch.cleanup()

    def pack_files(self):
        return [p.relative_to(self.pack).as_posix() for p in self.pack.rglob("*") if p.is_file()]

    def test_no_secret_file_is_in_the_pack(self):
        for relative in self.pack_files():
            for secret in pack_student.EXCLUDED:
                self.assertFalse(relative == secret or relative.startswith(secret + "/"), relative)

    def test_no_line_of_a_secret_file_is_in_the_pack(self):
        public = set()
        for folder in PUBLIC_FOLDERS:
            for path in text_files(ROOT / folder):
                public |= significant_lines(path)
        secret = set()
        for folder in SECRET_FOLDERS:
            if (ROOT / folder).exists():
                for path in text_files(ROOT / folder):
                    if path.suffix in SECRET_CODE:
                        secret |= significant_lines(path)
        secret -= public  # lines the student already has (includes, signatures) give nothing away
        self.assertGreater(len(secret), 40, "too few secret lines found: is the test reading the right folders?")
        for path in text_files(self.pack):
            leaked = significant_lines(path) & secret
            self.assertFalse(leaked, f"{path.relative_to(self.pack)} holds secret lines: {sorted(leaked)[:3]}")

    def test_the_reference_runs_of_every_scene_are_in_the_pack_as_numbers_only(self):
        # The student's figures draw over them (plots/reference_runs.py); numbers and a header.
        from plots import reference_runs
        shipped = 0
        for scene in reference_runs.scenes():
            for fraction, _ in reference_runs.runs_of(scene):
                relative = reference_runs.run_path(scene, fraction).relative_to(ROOT)
                self.assertTrue((self.pack / relative).is_file(), f"{relative} is not in the pack")
                header, *rows = (self.pack / relative).read_text().splitlines()
                self.assertTrue(header.startswith("t,"), relative)
                for row in rows:
                    [float(value) for value in row.split(",")]
                shipped += 1
            if reference_runs.has_trajectory(scene):  # the strobe pictures and the player draw over it
                trajectory = reference_runs.trajectory_path(scene).relative_to(ROOT)
                self.assertTrue((self.pack / trajectory).is_file(), f"{trajectory} is not in the pack")
        self.assertGreater(shipped, 20)

    def test_help_and_readme_speak_only_of_what_the_pack_has(self):
        help_text = subprocess.run(["./workbook", "help"], cwd=self.pack, capture_output=True, text=True).stdout
        readme = (self.pack / "README.md").read_text()
        for text, where in ((help_text, "./workbook help"), (readme, "README.md")):
            for absent in ("--solutions", "--student", "workbook grade", "workbook pack", "  grade ", "  pack "):
                self.assertNotIn(absent, text, f"{where} of the student edition mentions {absent!r}")
        self.assertIn("check CHAPTER", help_text)


if __name__ == "__main__":
    unittest.main(verbosity=2)
