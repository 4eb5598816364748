#!/usr/bin/env python3
"""Every command of ./workbook, as `./workbook help` lists them: `--help` exits 0 and prints
the command's usage; a wrong argument exits 2 and prints what is wrong and the usage on
stderr, before anything is built or installed; a command that needs an argument refuses to
run without one. Also: several scenes for `run` either all run or are refused.

    test_cli.py [ROOT]   (default: the workbook this file is in; the student edition too)"""
import pathlib
import re
import subprocess
import sys
import unittest

ROOT = pathlib.Path(__file__).resolve().parents[2]
NEEDS_AN_ARGUMENT = {"check", "run", "grade", "pack"}


def workbook(*args):
    return subprocess.run([str(ROOT / "workbook"), *args], capture_output=True, text=True, timeout=120, cwd=ROOT)


def listed_commands():
    """The command names `./workbook help` lists: the first word of each indented line."""
    text = workbook("help").stdout
    return sorted({m.group(1) for m in re.finditer(r"^  ([a-z]+)\b", text, re.MULTILINE)})


class EveryCommand(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.commands = listed_commands()

    def test_help_lists_the_commands(self):
        self.assertIn("check", self.commands)
        self.assertIn("setup", self.commands)
        self.assertEqual(workbook("help").returncode, 0)
        self.assertEqual(workbook("--help").returncode, 0)

    def test_help_of_every_command_exits_0(self):
        for command in self.commands:
            with self.subTest(command=command):
                run = workbook(command, "--help")
                self.assertEqual(run.returncode, 0, f"{command} --help: {run.stderr}")
                self.assertRegex(run.stdout, r"(?i)usage:", command)

    def test_a_wrong_argument_exits_2_with_the_usage(self):
        for command in self.commands:
            with self.subTest(command=command):
                run = workbook(command, "--no-such-option")
                self.assertEqual(run.returncode, 2, f"{command} --no-such-option: {run.stdout}{run.stderr}")
                self.assertRegex(run.stderr, r"(?i)usage:", command)
                self.assertNotIn("==> Building", run.stderr, f"{command} built before refusing")

    def test_a_missing_argument_exits_2_with_the_usage(self):
        for command in NEEDS_AN_ARGUMENT & set(self.commands):
            with self.subTest(command=command):
                run = workbook(command)
                self.assertEqual(run.returncode, 2, f"{command}: {run.stdout}{run.stderr}")
                self.assertRegex(run.stderr, r"(?i)usage:", command)

    def test_an_unknown_command_exits_2(self):
        run = workbook("no-such-command")
        self.assertEqual(run.returncode, 2)
        self.assertIn("unknown command", run.stderr)

    def test_several_scenes_all_run_or_are_refused(self):
        scene = next((ROOT / "chapters").glob("*/scenes/*.json"))
        run = workbook("run", str(scene), "no-such-scene.json")
        self.assertEqual(run.returncode, 2)
        self.assertIn("no scene file", run.stderr)
        run = workbook("run", str(scene), str(scene), "--csv", "out.csv")
        self.assertEqual(run.returncode, 2)
        self.assertIn("--csv takes one scene", run.stderr)

    def test_an_unknown_chapter_is_refused(self):
        for command in ("check", "figures"):
            run = workbook(command, "no-such-chapter")
            self.assertEqual(run.returncode, 2)
            self.assertIn("unknown chapter 'no-such-chapter'", run.stderr)


if __name__ == "__main__":
    if len(sys.argv) > 1 and not sys.argv[1].startswith("-"):
        ROOT = pathlib.Path(sys.argv.pop(1)).resolve()
    unittest.main(verbosity=2)
