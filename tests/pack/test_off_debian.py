#!/usr/bin/env python3
"""Off Debian: ./workbook looks for its tools before it thinks of apt. With every tool there
and neither apt nor dpkg, it goes on; with a tool missing it prints what to install on
Fedora, Arch and macOS (Homebrew), goes on when only optional tools are missing and stops
when a tool every command needs is. And the student edition, written from scratch, runs its
README's quick start (the book, a chapter's figures, the test command) and checks every
chapter with Clang alone: PATH without apt-get, dpkg, gcc or g++, and CXX=clang++. This is the
suite's one build of a pack (test_student_pack.py checks what a pack holds): the sources are
the ones this tree builds with GCC, so a second build with GCC would prove little more.

The "system without apt" is this machine seen through a PATH of links to every program on
it except those hidden, so no container is needed."""
import os
import pathlib
import re
import subprocess
import sys
import tempfile
import time
import unittest

from grader import pack_student
from tools import workbook_files

ROOT = pathlib.Path(__file__).resolve().parents[2]

PACKAGE_MANAGERS = {"apt", "apt-get", "apt-cache", "apt-mark", "apt-config", "dpkg", "dpkg-query", "dpkg-deb"}
GCC = {"gcc", "g++", "cc", "c++", "cpp"}


def hidden_by_name(name, hidden):
    return name in hidden or any(name.startswith(h + "-") for h in hidden if h in GCC) or \
        name.startswith(("x86_64-linux-gnu-gcc", "x86_64-linux-gnu-g++", "aarch64-linux-gnu-gcc", "aarch64-linux-gnu-g++"))


def path_without(folder, hidden):
    """A folder of links to every program on PATH but the hidden ones; returns it as a PATH."""
    folder.mkdir(parents=True, exist_ok=True)
    for directory in os.environ["PATH"].split(os.pathsep):
        if not os.path.isdir(directory):
            continue
        for entry in os.scandir(directory):
            link = folder / entry.name
            if link.exists() or hidden_by_name(entry.name, hidden):
                continue
            if entry.is_file() and os.access(entry.path, os.X_OK):
                link.symlink_to(entry.path)
    return str(folder)


class OffDebian(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.scratch = tempfile.TemporaryDirectory(prefix="off-debian-")
        cls.root = pathlib.Path(cls.scratch.name)

    @classmethod
    def tearDownClass(cls):
        cls.scratch.cleanup()

    def env(self, name, hidden, **extra):
        return dict(os.environ, PATH=path_without(self.root / name, PACKAGE_MANAGERS | set(hidden)), **extra)

    def workbook(self, folder, env, *args, timeout=120):
        started = time.monotonic()
        run = subprocess.run([str(folder / "workbook"), *args], cwd=folder, env=env, capture_output=True, text=True,
                             timeout=timeout)
        print(f"./workbook {' '.join(args)}: {time.monotonic() - started:.0f} s", file=sys.stderr, flush=True)
        return run

    def test_all_tools_there_and_no_apt_goes_on_quietly(self):
        run = self.workbook(ROOT, self.env("all", set()), "setup")
        self.assertEqual(run.returncode, 0, run.stderr)
        self.assertEqual(run.stderr, "")

    def test_optional_tools_missing_prints_what_to_install_and_goes_on(self):
        run = self.workbook(ROOT, self.env("no-gnuplot", {"gnuplot", "doxygen"}), "setup")
        self.assertEqual(run.returncode, 0, run.stderr)
        for line in ("gnuplot              needed by figures", "doxygen              needed by docs (the site)",
                     "Fedora:           sudo dnf install gnuplot doxygen",
                     "Arch:             sudo pacman -S --needed gnuplot doxygen",
                     "macOS (Homebrew): brew install gnuplot doxygen", "going on"):
            self.assertIn(line, run.stderr)
        self.assertNotIn("apt-get", run.stderr)

    def test_a_tool_every_command_needs_missing_stops(self):
        run = self.workbook(ROOT, self.env("no-cmake", {"cmake", "ninja"}), "setup")
        self.assertEqual(run.returncode, 1, run.stderr)
        self.assertIn("cmake                needed by every command", run.stderr)
        self.assertIn("sudo dnf install cmake ninja-build", run.stderr)
        self.assertIn("brew install cmake ninja", run.stderr)

    def test_the_student_edition_runs_its_quick_start_and_checks_with_clang_alone(self):
        pack = self.root / "workbook-student"
        pack_student.write_pack(pack)
        env = self.env("clang-alone", GCC, CXX="clang++")
        first_chapter = workbook_files.chapters(pack)[0]
        # The quick start of the pack's README. The test command's sanitizer half builds and
        # runs the same sources as this tree's own sanitizer half, so here it would only double
        # the suite's time.
        for command in (["book"], ["figures", first_chapter], ["test", "--without-sanitizers"]):
            run = self.workbook(pack, env, *command, timeout=1800)
            self.assertEqual(run.returncode, 0, f"{' '.join(command)} failed in the pack:\n{(run.stdout + run.stderr)[-3000:]}")
            if command == ["book"]:
                self.assertIn("g++ not found: build/dev uses clang++", run.stderr)
        self.assertIn("tests: ", run.stdout)
        self.assertIn(" 0 failed", run.stdout)
        html = pack / "build/dev/book/site/html"
        self.assertTrue((html / "chapter_inelastic.html").is_file(), "the site has no chapter 1 page")
        self.assert_site_cites_only_what_the_pack_has(html)
        self.assertTrue((pack / "build/dev/book/figures/inelastic/head-on-carts.student.svg").is_file(),
                        "the pack draws its figures from the student's code")
        for chapter in workbook_files.chapters(pack):
            run = self.workbook(pack, env, "check", chapter, timeout=1500)
            output = run.stdout + run.stderr
            self.assertEqual(run.returncode, 1, output[-3000:])
            self.assertIn("FAIL  Step 1", run.stdout, output[-3000:])
            self.assertIn("0 of", run.stdout, output[-3000:])
            self.assertNotIn("PASS  Step", run.stdout, output[-3000:])
            self.assertIn("Law broken:", run.stdout)
            self.assertIn(" steps pass.", run.stdout)
            self.assertNotIn("apt-get", run.stderr)
        cache = (pack / "build/student/CMakeCache.txt").read_text()
        self.assertRegex(cache, r"CMAKE_CXX_COMPILER:\w+=\S*clang\+\+")
        # Its ctest registers the chapter steps, one test per step, under the student preset,
        # and they fail on the untouched skeleton as check does.
        listing = subprocess.run(["ctest", "--preset", "student", "-N"], cwd=pack, env=env, capture_output=True,
                                 text=True, timeout=120)
        for chapter in workbook_files.chapters(pack):
            self.assertIn(f"{chapter}.step1.", listing.stdout, listing.stdout + listing.stderr)
        steps = subprocess.run(["ctest", "--preset", "student", "-L", "your-steps"], cwd=pack, env=env,
                               capture_output=True, text=True, timeout=600)
        self.assertNotEqual(steps.returncode, 0, "the untouched skeleton's steps must fail under ctest too")
        # Every step fails; the tests that pass build each chapter's step program first (ctest
        # builds nothing), one a chapter.
        counts = re.search(r"tests passed, (\d+) tests failed out of (\d+)", steps.stdout)
        self.assertIsNotNone(counts, steps.stdout[-2000:])
        chapters = workbook_files.chapters(pack)
        self.assertEqual(int(counts[1]), int(counts[2]) - len(chapters), steps.stdout[-2000:])
        for chapter in chapters:
            self.assertRegex(steps.stdout, rf"{re.escape(chapter)}\.build \.+ +Passed")
        solutions = self.workbook(pack, env, "check", "inelastic", "--solutions")
        self.assertNotEqual(solutions.returncode, 0)
        self.assertIn("no solutions", solutions.stderr)
        scene = next((pack / "chapters").glob("*/scenes/*.json"))
        run = self.workbook(pack, env, "run", str(scene), timeout=1500)
        self.assertEqual(run.returncode, 0, (run.stdout + run.stderr)[-3000:])
        self.assertIn("total energy", run.stdout)

    def assert_site_cites_only_what_the_pack_has(self, html):
        """No page of the pack's site names a file, folder or option the pack does not have."""
        absent = [prefix + "/" for prefix in pack_student.EXCLUDED] + ["--solutions", "--student", "adding_a_chapter"]
        for page in html.glob("*.html"):
            text = re.sub(r"<[^>]+>", "", page.read_text(errors="replace"))
            for name in absent:
                self.assertNotIn(name, text, f"{page.name} of the student edition's site cites {name}")


if __name__ == "__main__":
    unittest.main(verbosity=2)
