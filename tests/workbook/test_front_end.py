#!/usr/bin/env python3
"""The front end's parts, without building anything: every command's help and refusals come
from its one definition; the help names the real defaults and no internal tickets; the same
commands start without bash (workbook.py, python -m tools.cli, ./workbook under a plain sh);
Windows paths, programs and consoles (with os and platform mocked); and the bench's and the
figures' bookkeeping (stale NOTFOUND peers, the site's copies of the figures).

    python3 -m tests.workbook.test_front_end   (from the workbook's folder; ctest runs it)"""
import argparse
import contextlib
import io
import os
import pathlib
import re
import shutil
import subprocess
import sys
import tempfile
import unittest
from unittest import mock

from tools import check
from tools.cli import building, commands, console, edition, host, prerequisites

ROOT = edition.ROOT
LISTED = [c for c in commands.COMMANDS if c.listed()]


def help_of(entry):
    """A command's --help, its words joined by single spaces (wherever the lines break)."""
    return " ".join(commands.command_parser(entry).format_help().split())


def entry(name):
    return next(c for c in commands.COMMANDS if c.name == name)


class OneDefinition(unittest.TestCase):
    def test_help_lists_each_command_as_its_parser_defines_it(self):
        text = commands.overview()
        for command in LISTED:
            with self.subTest(command=command.name):
                self.assertIn(commands.synopsis(command, commands.command_parser(command)), text)
                self.assertIn(command.summary, text)

    def test_every_option_a_command_takes_is_in_its_help(self):
        for command in commands.COMMANDS:
            parser = commands.command_parser(command)
            text = parser.format_help()
            for action in parser._actions:
                for option in action.option_strings:
                    if action.help != argparse.SUPPRESS:
                        self.assertIn(option, text, f"{command.name}: {option}")

    def test_check_help_names_the_real_time_limit(self):
        self.assertIn(f"stopped after {check.DEFAULT_TIME_LIMIT:g} s", help_of(entry("check")))
        with mock.patch.dict(os.environ, {"WORKBOOK_CHECK_TIME_LIMIT": "7.5"}):
            self.assertIn("stopped after 7.5 s", help_of(entry("check")))
        self.assertNotIn("${", help_of(entry("check")))

    @unittest.skipUnless(edition.have_grader(), "the student edition has no grader")
    def test_grade_takes_every_option_its_help_lists(self):
        from grader import grade
        parser = commands.command_parser(entry("grade"))
        args = parser.parse_args(["alice.zip", "-j", "2", "--case-jobs", "1", "--time-limit", "3"])
        self.assertEqual((args.jobs, args.case_jobs, args.time_limit), (2, 1, 3.0))
        grader_options = {o for a in grade.build_parser()._actions for o in a.option_strings}
        ours = {o for a in parser._actions for o in a.option_strings}
        self.assertEqual(grader_options, ours)

    def test_student_is_accepted_in_both_editions_and_listed_in_the_help(self):
        for full in (True, False):
            with mock.patch.object(commands, "full", lambda full=full: full):
                for name in ("run", "figures", "animations"):
                    with self.subTest(full=full, command=name):
                        parser = commands.command_parser(entry(name))
                        self.assertIn("--student", parser.format_help())
                        argv = ["scene.json", "--student"] if name == "run" else ["--student"]
                        self.assertTrue(parser.parse_args(argv).student)

    def test_no_ticket_numbers_in_any_help(self):
        texts = [commands.overview()] + [help_of(c) for c in commands.COMMANDS]
        for text in texts:
            self.assertIsNone(re.search(r"(?i)\b(issue|ticket)s? #?\d+", text), text[:200])

    def test_refusals_say_what_is_wrong_then_the_usage_and_exit_2(self):
        for argv, words in ((["check", "no-such-chapter"], "unknown chapter 'no-such-chapter'"),
                            (["no-such-command"], "unknown command 'no-such-command'"),
                            (["help", "extra"], "help takes no arguments"),
                            (["bench", "nonsense"], "unknown choice 'nonsense'")):
            if argv[0] == "bench" and not edition.have_solutions():
                continue
            with self.subTest(argv=argv):
                err = io.StringIO()
                with contextlib.redirect_stderr(err), mock.patch.object(building, "build") as build:
                    try:
                        status = commands.main(argv)
                    except SystemExit as end:
                        status = end.code
                self.assertEqual(status, 2)
                self.assertIn(words, err.getvalue())
                self.assertRegex(err.getvalue(), "(?i)usage:")
                build.assert_not_called()


class WithoutBash(unittest.TestCase):
    """The same commands with no bash anywhere: PATH holds only a Python (and, for ./workbook, a plain sh)."""

    def setUp(self):
        self.bin = pathlib.Path(tempfile.mkdtemp(prefix="no-bash-"))
        self.addCleanup(shutil.rmtree, self.bin)
        for name in ("python3", "python"):
            (self.bin / name).symlink_to(sys.executable)
        self.env = dict(os.environ, PATH=str(self.bin))

    def run_help(self, argv, cwd=ROOT):
        run = subprocess.run(argv, cwd=cwd, env=self.env, capture_output=True, text=True, timeout=60)
        self.assertEqual(run.returncode, 0, run.stderr)
        self.assertIn("check CHAPTER", run.stdout)
        return run

    def test_workbook_py_from_anywhere(self):
        self.run_help([sys.executable, str(ROOT / "workbook.py"), "help"], cwd=self.bin)

    def test_python_m_tools_cli(self):
        self.run_help([sys.executable, "-m", "tools.cli", "help"])

    @unittest.skipUnless(shutil.which("dash") or shutil.which("sh"), "no POSIX sh")
    def test_the_launcher_is_plain_sh(self):
        sh = shutil.which("dash") or shutil.which("sh")
        (self.bin / "sh").symlink_to(sh)
        for tool in ("dirname",):  # what the launcher itself calls
            (self.bin / tool).symlink_to(shutil.which(tool))
        self.run_help([sh, str(ROOT / "workbook"), "help"], cwd=self.bin)
        self.assertTrue((ROOT / "workbook").read_text().startswith("#!/bin/sh\n"))

    def test_the_launcher_is_a_few_lines(self):
        code = [line for line in (ROOT / "workbook").read_text().splitlines() if line.strip() and
                not line.lstrip().startswith("#")]
        self.assertLess(len(code), 25)
        self.assertNotRegex("\n".join(code), r"\[\[|\$\{[A-Za-z_]+\[|local |declare |<<<|\bfunction\b")


class Windows(unittest.TestCase):
    """Windows as the front end sees it, mocked: ';'-separated path lists, .exe programs,
    packages from vcpkg, a cp1252 console."""

    def windows(self):
        stack = contextlib.ExitStack()
        stack.enter_context(mock.patch.object(host, "windows", lambda: True))
        stack.enter_context(mock.patch.object(host.os, "pathsep", ";"))
        return stack

    def test_path_lists_split_at_semicolons_not_at_drive_colons(self):
        with self.windows():
            self.assertEqual(host.path_list(r"C:\vcpkg\installed\x64-windows;D:\libs"),
                             [r"C:\vcpkg\installed\x64-windows", r"D:\libs"])
        with mock.patch.object(host.os, "pathsep", ":"):
            self.assertEqual(host.path_list("/opt/a:/opt/b:"), ["/opt/a", "/opt/b"])

    def test_programs_have_exe_and_may_sit_in_a_configuration_folder(self):
        with self.windows(), tempfile.TemporaryDirectory() as folder:
            folder = pathlib.Path(folder)
            self.assertEqual(host.program_name("workbook-sim"), "workbook-sim.exe")
            self.assertEqual(host.built_program(folder, "workbook-sim"), folder / "workbook-sim.exe")
            (folder / "Debug").mkdir()
            (folder / "Debug" / "workbook-sim.exe").write_bytes(b"")
            self.assertEqual(host.built_program(folder, "workbook-sim"), folder / "Debug" / "workbook-sim.exe")
        self.assertEqual(host.program_name("workbook-sim"), "workbook-sim" if os.name != "nt" else "workbook-sim.exe")

    def test_packages_are_found_in_vcpkg(self):
        with self.windows(), tempfile.TemporaryDirectory() as vcpkg:
            config = pathlib.Path(vcpkg, "installed", "x64-windows", "share", "fmt")
            config.mkdir(parents=True)
            (config / "fmt-config.cmake").write_text("")
            environ = {"VCPKG_ROOT": vcpkg, "CMAKE_PREFIX_PATH": ""}
            self.assertEqual(host.cmake_package_dir("fmt", environ), str(config))
            self.assertIsNone(host.cmake_package_dir("CLI11", environ))

    def test_the_libraries_come_from_vcpkg_and_setup_points_at_the_readme(self):
        with self.windows(), mock.patch.dict(os.environ, {"VCPKG_ROOT": "C:/vcpkg"}):
            self.assertTrue(prerequisites.tool_found("catch2-3"))
            wanted = {tool_id for tool_id, _ in prerequisites.wanted_tools()}
            self.assertNotIn("bubblewrap", wanted)
            self.assertNotIn("clang", wanted)
        advice = prerequisites.install_advice([("cmake", "every command")])
        self.assertIn("Windows:", advice)
        name, heading = prerequisites.windows_guide()
        self.assertIn(f"## {heading}", (ROOT / name).read_text(encoding="utf-8").replace("### ", "## "))
        self.assertIn("Windows", heading)
        for text in (advice, help_of(entry("setup"))):
            self.assertIn(f"{name}, section '{heading}'", " ".join(text.split()))

    def test_windows_builds_with_the_windows_twin_of_a_preset_where_there_is_one(self):
        with tempfile.TemporaryDirectory() as root:
            pathlib.Path(root, "CMakePresets.json").write_text(
                '{"configurePresets": [{"name": "dev"}, {"name": "student"}, {"name": "windows-student"}]}')
            with mock.patch.object(edition, "ROOT", pathlib.Path(root)):
                with self.windows():
                    self.assertEqual(building.cmake_preset("student"), "windows-student")
                    self.assertEqual(building.cmake_preset("dev"), "dev")  # no twin: the preset itself
                with mock.patch.object(host, "windows", lambda: False):
                    self.assertEqual(building.cmake_preset("student"), "student")

    def test_a_cp1252_or_ascii_console_gets_readable_ascii(self):
        for encoding in ("cp1252", "ascii"):
            raw = io.BytesIO()
            stream = io.TextIOWrapper(raw, encoding=encoding, errors="strict")
            console.make_streams_safe([stream])
            stream.write("Step 1 \u00b7 energy \u0394E \u2264 0 \u2192 ok \u2603\n")
            stream.flush()
            text = raw.getvalue().decode(encoding)
            self.assertIn("\u0394E" if encoding == "utf-8" else "dE <= 0 -> ok ?", text)
        utf8 = io.TextIOWrapper(io.BytesIO(), encoding="utf-8")
        console.make_streams_safe([utf8])
        self.assertEqual(utf8.errors, "strict")

    def test_the_windows_help_names_the_py_launcher(self):
        self.assertIn("py workbook.py", commands.overview() if not host.windows() else commands.PROG)


class Apt(unittest.TestCase):
    """What the front end asks apt for, with apt itself mocked: sudo when not root, Catch2 3 from
    bookworm-backports on bookworm."""

    def test_missing_packages_are_installed_with_sudo_and_catch2_from_backports(self):
        ran = []
        with mock.patch.object(prerequisites, "missing_packages", lambda: ["gnuplot-nox", "catch2"]), \
                mock.patch.object(prerequisites, "ensure_backports"), \
                mock.patch.object(prerequisites, "_bookworm", lambda: True), \
                mock.patch.object(prerequisites.os, "geteuid", lambda: 1000, create=True), \
                mock.patch.object(prerequisites.host, "which", lambda *names: "/usr/bin/sudo"), \
                mock.patch.object(prerequisites.subprocess, "run",
                                  lambda argv, **kw: ran.append(argv) or subprocess.CompletedProcess(argv, 0)), \
                contextlib.redirect_stderr(io.StringIO()):
            prerequisites.install_with_apt()
        self.assertEqual(ran, [
            ["sudo", "apt-get", "update", "-qq"],
            ["sudo", "env", "DEBIAN_FRONTEND=noninteractive", "apt-get", "install", "-y", "-qq",
             "--no-install-recommends", "gnuplot-nox"],
            ["sudo", "env", "DEBIAN_FRONTEND=noninteractive", "apt-get", "install", "-y", "-qq",
             "-t", "bookworm-backports", "catch2"]])

    def test_without_sudo_and_not_root_it_says_so(self):
        with mock.patch.object(prerequisites.os, "geteuid", lambda: 1000, create=True), \
                mock.patch.object(prerequisites.host, "which", lambda *names: None):
            with self.assertRaisesRegex(console.Failure, "need root to run: apt-get update"):
                prerequisites.as_root(["apt-get", "update"])


class Bench(unittest.TestCase):
    def test_peers_a_configure_did_not_find_are_forgotten(self):
        with tempfile.TemporaryDirectory() as folder:
            (pathlib.Path(folder) / "CMakeCache.txt").write_text(
                "WORKBOOK_CHIPMUNK_INCLUDE:PATH=WORKBOOK_CHIPMUNK_INCLUDE-NOTFOUND\n"
                "WORKBOOK_CHIPMUNK_LIBRARY:FILEPATH=/usr/lib/libchipmunk.so\n"
                "box2d_DIR:PATH=box2d_DIR-NOTFOUND\n"
                "benchmark_DIR:PATH=/usr/lib/x86_64-linux-gnu/cmake/benchmark\n"
                "WORKBOOK_PEER_CHIPMUNK_INCLUDE:PATH=WORKBOOK_PEER_CHIPMUNK_INCLUDE-NOTFOUND\n"
                "fmt_DIR:PATH=fmt_DIR-NOTFOUND\n")
            with mock.patch.object(edition, "build_dir", lambda preset: pathlib.Path(folder)):
                self.assertEqual(building.forget_missing_peers(),
                                 ["WORKBOOK_CHIPMUNK_INCLUDE", "box2d_DIR", "WORKBOOK_PEER_CHIPMUNK_INCLUDE"])

    def test_a_stale_configure_is_run_again_without_its_notfound_entries(self):
        with mock.patch.object(prerequisites, "install_bench_packages", lambda: False), \
                mock.patch.object(building, "forget_missing_peers", lambda preset="dev": ["box2d_DIR"]), \
                mock.patch.object(building, "configured", lambda preset: True), \
                mock.patch.object(building, "_packages_changed_since", lambda preset: True), \
                mock.patch.object(prerequisites, "setup_tools"), \
                mock.patch.object(building, "configure") as configure:
            building.prepare_bench()
        configure.assert_called_once_with("dev", ["-U", "box2d_DIR"], again=True)


    def test_a_missing_peer_is_a_column_that_says_so_never_a_traceback(self):
        from bench import speed
        row = {"steps": 60, "repeats": 1, "ms_per_step": "0.5", "bytes_per_body": 500, "energy_drift": "0"}
        rows = [{**row, "engine": "workbook", "n": n} for n in (1000, 3000)] + \
               [{**row, "engine": "chipmunk", "n": n, "repeats": 0} for n in (1000, 3000)]  # ran, no result
        table = speed.markdown(rows, ["workbook", "chipmunk"], [1000, 3000], "Measured now.", not_built=["box2d"])
        header = next(line for line in table.splitlines() if line.startswith("| N |"))
        self.assertIn("Box2D 2.4.1 ms/step", header)
        self.assertEqual(table.count("not built"), 2)
        self.assertEqual(table.count("no result"), 2)
        if shutil.which("gnuplot"):
            with tempfile.TemporaryDirectory() as out:
                speed.figure(rows, pathlib.Path(out), ["workbook", "chipmunk"])  # chipmunk has no point to draw
                self.assertTrue((pathlib.Path(out) / "speed.svg").is_file())
                err = io.StringIO()
                with contextlib.redirect_stderr(err):
                    speed.figure(rows[2:], pathlib.Path(out), ["chipmunk"])
                self.assertIn("no figure", err.getvalue())


class TestCommand(unittest.TestCase):
    """./workbook test (which CI runs): its counts and exit status from ctest's summary, with
    a stand-in ctest and nothing built."""

    def run_test(self, summary, status, *argv):
        with tempfile.TemporaryDirectory() as bin_dir:
            ctest = pathlib.Path(bin_dir, "ctest")
            ctest.write_text(f"#!/bin/sh\necho 'Test project'\necho '{summary}'\nexit {status}\n")
            ctest.chmod(0o755)
            out, err = io.StringIO(), io.StringIO()
            with mock.patch.dict(os.environ, {"PATH": bin_dir + os.pathsep + os.environ["PATH"]}), \
                    mock.patch.object(building, "build") as build, \
                    contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
                code = commands.main(["test", *argv])
        return code, out.getvalue(), [c.args for c in build.call_args_list]

    @unittest.skipIf(os.name == "nt", "a shell script stands in for ctest")
    def test_both_halves_pass(self):
        code, out, built = self.run_test("100% tests passed, 0 tests failed out of 42", 0)
        self.assertEqual((code, built), (0, [("dev",), ("sanitize",)]))
        self.assertIn("tests: 84 passed, 0 failed", out)

    @unittest.skipIf(os.name == "nt", "a shell script stands in for ctest")
    def test_a_failure_fails_and_the_sanitizers_can_be_left_out(self):
        code, out, built = self.run_test("90% tests passed, 1 tests failed out of 10", 8, "--without-sanitizers")
        self.assertEqual((code, built), (1, [("dev",)]))
        self.assertIn("tests: 9 passed, 1 failed", out)

    @unittest.skipIf(os.name == "nt", "a shell script stands in for ctest")
    def test_no_summary_is_a_failure(self):
        code, out, _ = self.run_test("No tests were found!!!", 0, "--without-sanitizers")
        self.assertEqual(code, 1)


class OneWording(unittest.TestCase):
    """A crash and a time limit read the same from ./workbook check and from the grader (tools/wording.py)."""

    def test_check_and_the_grader_say_the_same(self):
        import signal
        from tools import wording
        segv = getattr(signal, "SIGSEGV", 11)
        crash = wording.crashed(signal_number=segv)
        self.assertIn("a segmentation fault", crash)
        self.assertIn(wording.crashed(-segv, where="in step 3"), check.judge("c", 3, -segv, False, "", "", 10).message)
        self.assertIn(wording.timed_out(2.5, "in step 4"), check.judge("c", 4, 0, True, "", "", 2.5).message)
        self.assertEqual(wording.crashed(0xC0000005), crash)  # Windows' access violation is the same crash
        self.assertIsNone(wording.crashed(1))
        if not edition.have_grader() or os.name == "nt":
            return
        from types import SimpleNamespace
        from grader import runner
        limits = SimpleNamespace(wall_seconds=2.5)
        ended = dict(timed_out=False, flooded=False, disk_full=False, memory_full=False, signal=None, error=None, returncode=None)
        passed, said = runner.judge((1, None), None, SimpleNamespace(**{**ended, "timed_out": True}), limits, "")
        self.assertEqual((passed, said), (False, wording.timed_out(2.5)))
        passed, said = runner.judge((1, None), None, SimpleNamespace(**{**ended, "signal": segv}), limits, "")
        self.assertIn(f"your code {crash}", said)


class Figures(unittest.TestCase):
    def test_the_site_gets_the_figures_just_drawn(self):
        with tempfile.TemporaryDirectory() as scratch:
            scratch = pathlib.Path(scratch)
            drawn, html = scratch / "figures" / "inelastic", scratch / "html"
            drawn.mkdir(parents=True)
            html.mkdir()
            (drawn / "carts.svg").write_text("new")
            (drawn / "carts.csv").write_text("data")  # the site has no copy of it: left alone
            (drawn / "same.svg").write_text("same")
            (html / "carts.svg").write_text("old")
            (html / "same.svg").write_text("same")
            self.assertEqual(commands.update_site_copies([drawn], html), 1)
            self.assertEqual((html / "carts.svg").read_text(), "new")
            self.assertFalse((html / "carts.csv").exists())
            self.assertEqual(commands.update_site_copies([drawn], scratch / "no-site"), 0)


if __name__ == "__main__":
    unittest.main(verbosity=2)
