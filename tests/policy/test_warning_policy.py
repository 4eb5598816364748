#!/usr/bin/env python3
"""One warning policy for the student's code (cmake/Warnings.cmake), proved on a configured
build's compile_commands.json: every compilation of a file in skeleton/ shows warnings and
never makes them errors, whichever command (check, run, figures, book, test) builds it,
while the workbook's own code (engine/) keeps warnings as errors in the dev build, and the
student presets make no warning an error at all. Only the test target that
holds the shipped skeleton warning-free (workbook_skeleton_strict) may use -Werror on it.

    test_warning_policy.py build/dev/compile_commands.json"""
import json
import pathlib
import shlex
import sys
import unittest

ROOT = pathlib.Path(__file__).resolve().parents[2]
COMMANDS = None
STRICT_TARGET = "workbook_skeleton_strict"


def arguments(entry):
    return entry["arguments"] if "arguments" in entry else shlex.split(entry["command"])


def under(entry, folder):
    path = pathlib.Path(entry["file"])
    if not path.is_absolute():
        path = pathlib.Path(entry["directory"]) / path
    return folder in pathlib.Path(path).resolve().parents


class WarningPolicy(unittest.TestCase):
    def test_student_code_shows_warnings_and_never_fails_on_them(self):
        student = [e for e in COMMANDS if under(e, ROOT / "skeleton") and STRICT_TARGET not in e.get("output", "")
                   and STRICT_TARGET not in " ".join(arguments(e))]
        self.assertTrue(student, "no compilation of skeleton/ in the build")
        for entry in student:
            flags = arguments(entry)
            self.assertTrue("-Wall" in flags or "/W4" in flags, f"warnings not shown for {entry['file']}")
            self.assertFalse("-Werror" in flags or "/WX" in flags, f"warnings are errors for {entry['file']}: {flags}")

    def test_the_workbooks_own_code_keeps_warnings_as_errors(self):
        own = [e for e in COMMANDS if under(e, ROOT / "engine")]
        self.assertTrue(own)
        for entry in own:
            flags = arguments(entry)
            self.assertTrue("-Werror" in flags or "/WX" in flags, f"no warnings as errors for {entry['file']}")

    def test_no_preset_makes_student_warnings_fatal(self):
        presets = (ROOT / "CMakePresets.json").read_text()
        self.assertNotIn("STUDENT_WARNINGS_AS_ERRORS", presets)
        self.assertNotIn("-Werror", presets)

    def test_the_student_presets_make_no_warning_fatal_in_anything_they_build(self):
        """The engine and the tests are built by the student presets too: there, on a compiler
        the workbook's CI never ran (Apple Clang, MSVC), a new warning must not stop a student."""
        presets = {p["name"]: p for p in json.loads((ROOT / "CMakePresets.json").read_text())["configurePresets"]}
        students = [name for name in presets if name.endswith("student")]
        self.assertIn("student", students)
        self.assertIn("windows-student", students)
        for name in students:
            self.assertEqual(presets[name]["cacheVariables"].get("WORKBOOK_WARNINGS_AS_ERRORS"), "OFF",
                             f"preset {name} keeps warnings as errors in the engine and tests")


if __name__ == "__main__":
    COMMANDS = json.loads(pathlib.Path(sys.argv.pop(1)).read_text())
    unittest.main(verbosity=2)
