"""Every command of ./workbook, each defined once: its place in `./workbook help`, its options
(argparse, from which its --help and its refusals are generated) and what it does.

Every command: `--help` prints its usage and exits 0; wrong arguments print what is wrong and
the usage on stderr and exit 2, before anything is installed or built. The student edition
(no solutions/, no grader/) lists only what it has."""
import argparse
import os
import pathlib
import re
import shutil
import subprocess
import sys
import textwrap
from dataclasses import dataclass
from typing import Callable

from tools import wording
from tools.cli import building, edition, host, prerequisites
from tools.cli.console import Failure, Refusal, make_streams_safe, say, warn

PROG = "py workbook.py" if host.windows() else "./workbook"
GROUPS = ["For everyone", "Students", "Lecturers", "Speed and accuracy", "Instructors"]
BOOK = edition.ROOT / "build" / "dev" / "book"
SITE_HTML = BOOK / "site" / "html"


@dataclass
class Command:
    name: str
    group: str
    summary: str                   # its line in `./workbook help`
    description: str               # the text of its --help, above the options
    arguments: Callable            # arguments(parser): adds its options and arguments
    run: Callable                  # run(args, raw): its exit status; raw are its arguments as typed
    listed: Callable = lambda: True  # whether this edition offers it (`help` lists it)
    refusal: str = ""              # why it refuses to run when the edition does not offer it


COMMANDS = []


def command(name, group, summary, description, listed=lambda: True, refusal=""):
    """Declares a command: decorates its run function; the arguments function follows with @<name>.arguments."""
    def declare(run):
        entry = Command(name, group, summary, description, lambda parser: None, run, listed, refusal)
        COMMANDS.append(entry)

        def arguments(function):
            entry.arguments = function
            return function
        run.arguments = arguments
        return run
    return declare


def full():
    return edition.have_solutions()


def chapter_list():
    return " ".join(edition.chapters())


def from_caller(path):
    """A path the user typed, relative to where they typed the command."""
    return pathlib.Path(os.path.abspath(path))


def chapter_number(chapter):
    chapters = edition.chapters()
    if chapter not in chapters:
        raise Refusal(f"unknown chapter '{chapter}' (chapters: {' '.join(chapters)})")
    return chapters.index(chapter) + 1


def run_program(argv, cwd=None, stdout=None):
    sys.stdout.flush()
    sys.stderr.flush()
    return subprocess.run([str(a) for a in argv], cwd=cwd, stdout=stdout).returncode


def run_python(module, args, cwd=None):
    """Runs one of the workbook's Python programs (plots.figures, grader.grade) in a process of
    its own, with the workbook's folder as the root of its imports; cwd: where the user typed
    the command, unless given."""
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join([str(edition.ROOT), *host.path_list(env.get("PYTHONPATH"))])
    sys.stdout.flush()
    sys.stderr.flush()
    return subprocess.run([sys.executable, "-m", module, *[str(a) for a in args]], cwd=cwd, env=env).returncode


def tool(name):
    """A program of build/dev/tools/ (workbook-sim, workbook-accuracy), .exe on Windows."""
    return host.built_program(edition.build_dir("dev") / "tools", name)


# --- For everyone ---------------------------------------------------------------------------
@command("book", "For everyone", "build everything, run every chapter's scenes, write the figures and the site",
         "Installs what is missing, builds, runs every chapter's scenes, writes the figures and builds the site.")
def run_book(args, raw):
    building.build("dev")
    building.build("dev", "figures", "docs")
    say(f"Figures: {BOOK / 'figures'}{os.sep}")
    say(f"Site:    {SITE_HTML / 'index.html'}")
    return 0


@command("test", "For everyone", "build and run the whole test suite (GCC, then Clang with sanitizers)",
         "Builds with GCC (warnings as errors in the workbook's own code) and runs every test, then again "
         "with Clang under AddressSanitizer and UndefinedBehaviorSanitizer.")
def run_test(args, raw):
    presets = ["dev"] if args.without_sanitizers else ["dev", "sanitize"]
    passed = failed = 0
    status = 0
    for preset in presets:
        building.build(preset)
        say(f"Testing build/{preset}")
        counts, ctest_status = _ctest(preset)
        if ctest_status != 0:
            status = 1
        if counts is None:
            status = 1
            continue
        failed += counts[0]
        passed += counts[1] - counts[0]
    if failed:
        status = 1
    print(f"tests: {passed} passed, {failed} failed", flush=True)
    return status


@run_test.arguments
def _(parser):
    parser.add_argument("--without-sanitizers", action="store_true",
                        help="the GCC half only: quicker, but blind to the memory and undefined-behaviour errors "
                             "the sanitizers catch")


# ctest's summary line, "100% tests passed, 0 tests failed out of 42".
CTEST_SUMMARY = re.compile(r"tests passed, (\d+) tests? failed out of (\d+)")


def _ctest(preset):
    """Runs ctest --preset, its output shown as it comes; ((failed, total) or None, status)."""
    sys.stdout.flush()
    process = subprocess.Popen(["ctest", "--preset", building.cmake_preset(preset), "-j", "2"], cwd=edition.ROOT,
                               stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, errors="replace")
    counts = None
    for line in process.stdout:
        sys.stdout.write(line)
        sys.stdout.flush()
        match = CTEST_SUMMARY.search(line)
        if match:
            counts = (int(match.group(1)), int(match.group(2)))
    return counts, process.wait()


@command("setup", "For everyone",
         "check for the tools the workbook needs and install what is missing (run by every command)",
         "Checks for the tools the workbook needs. When something is missing it installs it with apt (Debian, "
         "Ubuntu: Catch2 3 from bookworm-backports on bookworm) or, without apt, prints what to install on Fedora, "
         "Arch, macOS or Windows. Every other command runs it first; it does nothing when all are there. "
         "On Windows: " + prerequisites.windows_advice() + ".")
def run_setup(args, raw):
    if host.windows():
        print(f"Windows: {prerequisites.windows_advice()}.")
    prerequisites.setup_tools()
    if host.windows():
        missing = prerequisites.missing_tools()
        print("All the tools are there." if not missing else
              "Missing: " + ", ".join(f"{tool_id} ({needs})" for tool_id, needs in missing))
    return 0


# --- Students -------------------------------------------------------------------------------
def check_time_limit():
    """Seconds each test case of `check` may take: WORKBOOK_CHECK_TIME_LIMIT, or check.py's default."""
    from tools import check
    given = os.environ.get("WORKBOOK_CHECK_TIME_LIMIT")
    try:
        limit = float(given) if given else check.DEFAULT_TIME_LIMIT
    except ValueError:
        limit = -1
    if not limit > 0:
        raise Refusal(f"WORKBOOK_CHECK_TIME_LIMIT must be a positive number of seconds (it is '{given}')")
    return limit


@command("check", "Students", "build your skeleton/ code and report each step of CHAPTER: pass, or which law it breaks",
         "Builds your code in skeleton/ and runs CHAPTER's public step tests, step by step, each test in its own "
         "process: a crash, an endless loop (stopped after {limit:g} s; WORKBOOK_CHECK_TIME_LIMIT=SECONDS changes "
         "it), an exception or a NaN is reported on its own step, and every other step is still checked. Exit "
         "status 0 only when every step passes.")
def run_check(args, raw):
    number = chapter_number(args.chapter)
    solutions = args.solutions
    if solutions and not full():
        raise Refusal("this edition has no solutions/ (the reference solutions are the instructor's)")
    who = "the reference solutions" if solutions else "your code in skeleton/"
    limit = check_time_limit()
    prerequisites.setup_tools()
    building.configure("student")
    say(f"Chapter {number} \u00b7 {args.chapter}: checking {who} (random seed {edition.seed()})")
    # check.py builds the chapter's own step-test program (only this chapter's file has to
    # compile; a compile error is told with its file and line), then runs each test case in its
    # own process with a time limit: a crash or an endless loop costs its own step only, and
    # every step and the summary are still reported.
    from tools import check
    argv = ["--build-dir", str(edition.build_dir("student")), "--chapter", args.chapter,
            "--seed", edition.seed(), "--time-limit", f"{limit:g}"]
    return check.main(argv + (["--solutions"] if solutions else []))


@run_check.arguments
def _(parser):
    parser.add_argument("chapter", metavar="CHAPTER", help="one of: " + chapter_list())
    # The student edition has no solutions: --solutions is refused there by name, not as unknown.
    parser.add_argument("--solutions", action="store_true",
                        help="the same checks on the reference solutions" if full() else argparse.SUPPRESS)


STUDENT_HELP_FULL = "your code in skeleton/ instead of the reference solutions"
STUDENT_HELP_STUDENT = "your code (in this edition, which has no reference, it always is)"


@command("run", "Students", "simulate scene files" + (" (--student: with your code)" if full() else " with your code"),
         "Simulates each scene file and prints a summary. Every scene file is checked first: either all of them "
         "run, or none does.")
def run_run(args, raw):
    scenes = [from_caller(s) for s in args.scenes]
    writes = args.csv or args.trajectory or args.stride is not None
    if writes and len(scenes) > 1:
        raise Refusal("--csv takes one scene, and so does --trajectory; run the scenes one at a time to write their "
                      "CSV files")
    for scene in scenes:
        if not scene.is_file():
            raise Refusal(f"no scene file {scene}")
    sim = "workbook-sim-student" if args.student or not full() else "workbook-sim"
    options = []
    if args.explain:
        options.append("--explain")
    if args.csv:
        options += ["--csv", from_caller(args.csv)]
    if args.trajectory:
        options += ["--trajectory", from_caller(args.trajectory)]
    if args.stride is not None:
        options += ["--stride", args.stride]
    building.build("dev", sim, to_stderr=True)
    # The simulator's exit status says how a run ended (workbook-sim run --help): 2 refused,
    # 3 stopped at a NaN, 4 internal error, 130 Ctrl-C. A run killed by a signal crashed: it is
    # said in words and passed on as 128 + the signal, so a crash never reads as a refusal.
    status = 0
    for scene in scenes:
        if len(scenes) > 1:
            say(str(scene))
        returncode = run_program([tool(sim), "run", scene, *options])
        crash = wording.crashed(returncode) if returncode < 0 else \
            wording.crashed(signal_number=returncode - 128) if 128 < returncode < 256 and returncode != 130 else \
            wording.crashed(returncode) if returncode > 255 else None
        if crash:
            print(f"workbook: the simulator {crash} on {scene}; this is a bug in the engine or in your "
                  f"responder, not a problem with the scene", file=sys.stderr)
            returncode = 128 - returncode if returncode < 0 else returncode
        if returncode != 0 and status <= 128:
            status = returncode
    return status


@run_run.arguments
def _(parser):
    parser.add_argument("scenes", nargs="+", metavar="SCENE.json", help="scene files (chapters/*/scenes/, or your own)")
    parser.add_argument("--csv", metavar="OUT", help="write the energy and momentum time series (one scene only)")
    parser.add_argument("--trajectory", metavar="OUT.csv",
                        help="write every body's state per frame, and OUT.contacts.csv the contacts (one scene only)")
    parser.add_argument("--stride", metavar="K", help="with --trajectory: every K-th step")
    parser.add_argument("--student", action="store_true", help=STUDENT_HELP_FULL if full() else STUDENT_HELP_STUDENT)
    parser.add_argument("--explain", action="store_true",
                        help="list the stages a scene uses and those it skips, and why, without running it")


# --- Lecturers ------------------------------------------------------------------------------
@command("figures", "Lecturers", "energy and momentum figures (SVG, PDF, PNG, CSV) of chapters or scene files",
         "Runs the scenes of each CHAPTER (default: every chapter) and writes energy and momentum figures as SVG, "
         "PDF and PNG with the CSV beside them, into build/dev/book/figures/<chapter>/, and updates the copies "
         "in the site (build/dev/book/site/html/) when it has been built. A SCENE.json (any scene file, your own "
         "too) is drawn on its own, into build/dev/book/figures/scenes/ or --out DIR.")
def run_figures(args, raw):
    chapters, scenes = [], []
    for item in args.items:
        if item.endswith(".json"):
            if not from_caller(item).is_file():
                raise Refusal(f"no scene file {item}")
            scenes.append(from_caller(item))
        else:
            chapter_number(item)
            chapters.append(item)
    if args.out and not scenes:
        raise Refusal("--out is for scene files; chapters go to build/dev/book/figures/<chapter>/")
    student = args.student and full()  # the student edition draws your code already
    if scenes:
        if full():
            sims = ["workbook-sim"] + (["workbook-sim-student"] if student else [])
        else:
            sims = ["workbook-sim-student"]
        building.build("dev", *sims)
        if full():
            options = ["--sim", tool("workbook-sim")]
            if student:
                options += ["--student", "--student-sim", tool("workbook-sim-student")]
        else:
            options = ["--no-reference", "--student", "--student-sim", tool("workbook-sim-student")]
        out = from_caller(args.out) if args.out else BOOK / "figures" / "scenes"
        scene_options = [a for scene in scenes for a in ("--scene", scene)]
        status = run_python("plots.figures", ["scenes", out, *scene_options, *options])
        if status != 0:
            return status
        say(f"Figures are in {out}{os.sep}")
    if not chapters and not scenes:
        chapters = edition.chapters()
    if chapters:
        building.build("dev", *[f"figures-{c}{'-student' if student else ''}" for c in chapters])
        say(f"Figures are in {BOOK / 'figures'}{os.sep}")
        updated = update_site_copies([BOOK / "figures" / c for c in chapters])
        if updated:
            say(f"Updated {updated} figure(s) in the site: {SITE_HTML}{os.sep}")
    return 0


@run_figures.arguments
def _(parser):
    parser.add_argument("items", nargs="*", metavar="CHAPTER|SCENE.json",
                        help="chapters (" + chapter_list() + ") or scene files; default: every chapter")
    parser.add_argument("--student", action="store_true",
                        help="overlay the curves of your code in skeleton/ on the reference's" if full()
                        else "your code's curves (in this edition they always are)")
    parser.add_argument("--out", metavar="DIR", help="where the figures of scene files go")


def update_site_copies(folders, html=SITE_HTML):
    """Copies the figures just drawn over the site's copies of them (Doxygen copies each figure
    into html/ under its own name), so that the site shows what was drawn. Returns how many."""
    if not html.is_dir():
        return 0
    updated = 0
    for folder in folders:
        if not folder.is_dir():
            continue
        for figure in folder.iterdir():
            copy = html / figure.name
            if figure.is_file() and copy.is_file() and figure.read_bytes() != copy.read_bytes():
                shutil.copyfile(figure, copy)
                updated += 1
    return updated


@command("animations", "Lecturers", "MP4 and GIF of every scene, for slides (slow: about 10 minutes)",
         "Films every scene of CHAPTER (or of every chapter) as <scene>.mp4 (1280x720, 25 fps) and <scene>.gif "
         "(640x360) into build/dev/book/figures/<chapter>/, slowed down by a stated factor when the scene is short.")
def run_animations(args, raw):
    if args.chapter:
        chapter_number(args.chapter)
    student = "-student" if args.student and full() else ""
    target = f"animations-{args.chapter}{student}" if args.chapter else f"animations{student}"
    building.build("dev", target)
    say(f"Animations are in {BOOK / 'figures'}{os.sep}")
    return 0


@run_animations.arguments
def _(parser):
    parser.add_argument("chapter", nargs="?", metavar="CHAPTER", help="one chapter (default: every chapter)")
    parser.add_argument("--student", action="store_true",
                        help="draw your code's bodies over the reference's" if full()
                        else "your code's bodies (in this edition they always are)")


@command("docs", "Lecturers", "the literate site (Doxygen), with formulas, figures and code",
         "Builds the literate site with Doxygen into build/dev/book/site/.")
def run_docs(args, raw):
    building.build("dev", "docs")
    say(f"The site is at {SITE_HTML / 'index.html'}")
    return 0


# --- Speed and accuracy ---------------------------------------------------------------------
NO_SOLUTIONS = "this edition has no reference solutions to run it with"


@command("stress", "Speed and accuracy",
         "the stress corpus: scenes that break naive engines, invariants checked every step",
         "Runs the stress corpus (tools/accuracy/stress.hpp) and prints scene, steps, worst violation and verdict. "
         "Exit status 0 only when every scene passes.", listed=full, refusal=NO_SOLUTIONS)
def run_stress(args, raw):
    options = ["--full"] if args.full else []
    if args.csv:
        options += ["--csv", from_caller(args.csv)]
    if args.responder:
        options += ["--responder", args.responder]
    building.build("dev", "workbook-accuracy", to_stderr=True)
    return run_program([tool("workbook-accuracy"), "stress", *options])


@run_stress.arguments
def _(parser):
    parser.add_argument("--full", action="store_true",
                        help="the on-demand corpus (10,000 bodies, 10^6 steps), with a progress line")
    parser.add_argument("--csv", metavar="OUT", help="also write the table as CSV")
    parser.add_argument("--responder", metavar="NAME", help="run the corpus with this responder only")


BENCH_KINDS = ("accuracy", "speed", "stages", "pile")


@command("bench", "Speed and accuracy",
         "run time against error; speed against Chipmunk, Box2D and Bullet; each stage's speed",
         "accuracy [OUT]: sweeps time step, substeps, integrator and contact timing over the scene families with "
         "a closed form, measures error and run time, and draws one Pareto figure per family (SVG, PDF, PNG, CSV) "
         "into OUT, with Chipmunk, Box2D and Bullet on the same axes. OUT defaults to the site's folder, "
         "build/dev/book/figures/accuracy, which the Performance page shows (./workbook docs rebuilds it).\n\n"
         "speed [options of bench/speed.py]: a 2D gas of equal balls bouncing in a closed box, for N = 1,000 to "
         "100,000, in the workbook and in Chipmunk, Box2D and Bullet, one run: build/dev/book/bench/speed.{csv,md}, "
         "the figure in book/figures/bench/ and the site's Performance page (./workbook docs to rebuild it). Takes "
         "about 25 minutes on 2 quiet cores, most of it Box2D and Bullet at N = 10,000 and more (--peers-up-to N "
         "leaves the peers out above N). --record also copies the results into bench/results/, the recorded run "
         "the site shows until a build runs its own; --rewrite runs nothing and writes the table, page and figure "
         "again from the last run's CSV. `./workbook bench speed --help` lists its options.\n\n"
         "stages [Google Benchmark options]: micro benchmarks of each stage of a step (integrate, detect, "
         "respond, probes).\n\n"
         "pile [options of bench/pile.py]: chapter 5's pile of frictionless discs dropped into a box, 10 s, in the "
         "workbook and in Chipmunk, Box2D and Bullet (each on its defaults) for N = 400 to 10,000, and in the workbook "
         "alone up to 100,000: time per step, deepest overlap, kinetic energy, mean height and discs outside, and the "
         "workbook's goals met or not, in build/dev/book/bench/pile.{csv,md}, the figure in book/figures/bench/. A run "
         "over its budget (--budget, 300 s) is stopped and says so. --record also copies the results into "
         "bench/results/; --quick is a seconds-long run of 16 and 100 discs.\n\n"
         "Each installs libbenchmark-dev and the peers' Debian packages first (with apt) and builds with those "
         "found; a peer that is missing is a row that says so. Never part of ./workbook test.",
         listed=full, refusal=NO_SOLUTIONS)
def run_bench(args, raw):
    rest = list(args.rest)
    if args.kind not in ("speed", "pile") and ("-h" in rest or "--help" in rest):
        parser = command_parser(next(c for c in COMMANDS if c.name == "bench"))
        parser.print_help()
        return 0
    if args.kind == "accuracy":
        if len(rest) > 1 or any(a.startswith("-") for a in rest):
            raise Refusal("bench accuracy takes at most one folder")
        out = from_caller(rest[0]) if rest else BOOK / "figures" / "accuracy"
        building.prepare_bench()
        building.build("dev", "workbook-accuracy", to_stderr=True)
        out.mkdir(parents=True, exist_ok=True)
        status = run_program([tool("workbook-accuracy"), "bench", "--out", out])
        if status == 0:
            status = run_python("plots.accuracy", [out])
        if status == 0:
            say(f"Figures and CSV in {out}")
        return status
    if args.kind == "speed":
        if "-h" in rest or "--help" in rest:
            return run_python("bench.speed", ["--help"])
        building.prepare_bench()
        building.build("dev", "workbook-gas", to_stderr=True)
        status = run_python("bench.speed", ["--gas", host.built_program(edition.build_dir("dev") / "bench",
                                                                            "workbook-gas"),
                                               "--out", BOOK / "bench", "--figures", BOOK / "figures" / "bench", *rest],
                            cwd=edition.ROOT)
        if status == 0:
            say(f"Table: {BOOK / 'bench' / 'speed.md'}; figure: {BOOK / 'figures' / 'bench' / 'speed.svg'}")
        return status
    if args.kind == "pile":
        if "-h" in rest or "--help" in rest:
            return run_python("bench.pile", ["--help"])
        building.prepare_bench()
        building.build("dev", "workbook-pile", to_stderr=True)
        status = run_python("bench.pile", ["--binary", host.built_program(edition.build_dir("dev") / "bench", "workbook-pile"),
                                           "--out", BOOK / "bench", "--figures", BOOK / "figures" / "bench", *rest],
                            cwd=edition.ROOT)
        if status == 0:
            say(f"Table: {BOOK / 'bench' / 'pile.md'}; figure: {BOOK / 'figures' / 'bench' / 'pile.svg'}")
        return status
    building.prepare_bench()
    prerequisites.setup_tools()
    building.configure("dev")
    if not _has_target("dev", "workbook-stages"):
        raise Failure("bench stages needs Google Benchmark (Debian: libbenchmark-dev), which this build did not "
                      "find; install it and run the command again")
    building.build("dev", "workbook-stages", to_stderr=True)
    return run_program([host.built_program(edition.build_dir("dev") / "bench", "workbook-stages"), *rest])


def _has_target(preset, target):
    """Whether the configured build has the target (a target left out for a missing package is not there)."""
    run = subprocess.run(["cmake", "--build", "--preset", building.cmake_preset(preset), "--target", "help"],
                         cwd=edition.ROOT,
                         capture_output=True, text=True)
    return run.returncode != 0 or re.search(rf"^{re.escape(target)}\b", run.stdout, re.MULTILINE) is not None


@run_bench.arguments
def _(parser):
    parser.add_argument("kind", choices=BENCH_KINDS, metavar="accuracy|speed|stages|pile", help="which bench")
    parser.add_argument("rest", nargs=argparse.REMAINDER, metavar="...",
                        help="accuracy: the folder OUT; speed: bench/speed.py's options; stages: Google Benchmark's; "
                             "pile: bench/pile.py's options")


# --- Instructors ----------------------------------------------------------------------------
NO_GRADER = "this edition has no grader"


def _grade_parser():
    from grader import grade
    return grade.build_parser(add_help=False)


@command("grade", "Instructors", "grade submissions (folders, .zip or .tar.gz); see grader/README.md",
         "Grades submissions (folders, .zip or .tar.gz) against the public and hidden tests: results.json and "
         "summary.txt per submission and gradebook.csv in --out. The grader kit is built first (build/dev).",
         listed=edition.have_grader, refusal=NO_GRADER)
def run_grade(args, raw):
    building.build("dev", "grader_kit", to_stderr=True)
    return run_python("grader.grade", ["--build-dir", edition.build_dir("dev"), "--seed", edition.seed(), *raw])


@command("pack", "Instructors", "gradescope OUT.zip: the Gradescope autograder; student OUT: the student edition",
         "gradescope OUT.zip [options]: the Gradescope autograder zip (`./workbook pack gradescope --help` lists "
         "its options); student OUT: the student edition (no solutions, no hidden tests, no grader), a new folder.",
         listed=edition.have_grader, refusal=NO_GRADER)
def run_pack(args, raw):
    module = {"gradescope": "grader.pack_gradescope", "student": "grader.pack_student"}[args.kind]
    return run_python(module, args.rest)


@run_pack.arguments
def _(parser):
    parser.add_argument("kind", choices=("gradescope", "student"), metavar="gradescope|student", help="which pack")
    parser.add_argument("rest", nargs=argparse.REMAINDER, metavar="OUT ...", help="where to write it, and options")


# --- The parser, made from the definitions above --------------------------------------------
class Paragraphs(argparse.HelpFormatter):
    """argparse's help, with the description's paragraphs (blank-line separated) kept apart."""

    def _fill_text(self, text, width, indent):
        return "\n\n".join(textwrap.fill(" ".join(p.split()), width, initial_indent=indent, subsequent_indent=indent)
                           for p in text.split("\n\n"))


class Parser(argparse.ArgumentParser):
    """argparse, with the workbook's refusals: what is wrong, then the usage, on stderr; exit 2."""

    def error(self, message):
        message = re.sub(r"^argument [^:]+: invalid choice: '([^']*)' \(choose from (.*)\)$",
                         lambda m: f"unknown choice '{m[1]}' (one of {m[2]})", message)
        self.exit(2, f"{self.prog}: {message}\n\n{self.format_usage()}Run {self.prog} --help for details.\n")


def _describe(entry):
    text = entry.description
    if entry.name == "check":
        try:
            text = text.format(limit=check_time_limit())
        except Refusal:  # said when the command runs; the help names the default
            from tools import check
            text = text.format(limit=check.DEFAULT_TIME_LIMIT)
    return text


def command_parser(entry):
    """The parser of one command, with its --help generated from its definition."""
    parents = [_grade_parser()] if entry.name == "grade" and edition.have_grader() else []
    parser = Parser(prog=f"{PROG} {entry.name}", description=_describe(entry), parents=parents,
                    formatter_class=Paragraphs,
                    epilog="Chapters: " + chapter_list() if entry.name in ("check", "figures", "animations") else None)
    entry.arguments(parser)
    return parser


def synopsis(entry, parser):
    """'check CHAPTER', 'run SCENE.json...': the command and its positional arguments."""
    words = [entry.name]
    for action in parser._get_positional_actions():
        name = action.metavar or action.dest
        if action.nargs == "+":
            words.append(f"{name}...")
        elif action.nargs == "*":
            words.append(f"[{name}...]")
        elif action.nargs == "?":
            words.append(f"[{name}]")
        elif action.nargs != argparse.REMAINDER:
            words.append(name)
    return " ".join(words)


def overview():
    """The text of `./workbook help`: every command this edition offers, by audience."""
    lines = [f"Usage: {PROG} COMMAND [ARGS]", ""]
    for group in GROUPS:
        entries = [e for e in COMMANDS if e.group == group and e.listed()]
        if not entries:
            continue
        lines.append(group)
        for entry in entries:
            words = synopsis(entry, command_parser(entry))
            if len(words) <= 24:
                lines.append(f"  {words:<24} {entry.summary}")
            else:
                lines += [f"  {words}", f"  {'':<24} {entry.summary}"]
        lines.append("")
    lines.append(f"Chapters: {chapter_list()}")
    lines.append(f"Run {PROG} COMMAND --help for details of one command.")
    if not host.windows():
        lines.append("Without a POSIX shell (Windows): py workbook.py COMMAND, the same commands.")
    return "\n".join(lines) + "\n"


def refuse(entry, message):
    usage = command_parser(entry).format_usage() if entry else ""
    name = f" {entry.name}" if entry else ""
    sys.stderr.write(f"workbook{name}: {message}\n\n{usage or overview()}")
    return 2


def main(argv=None):
    make_streams_safe()
    argv = list(sys.argv[1:] if argv is None else argv)
    name = argv[0] if argv else "help"
    rest = argv[1:]
    if name in ("help", "-h", "--help"):
        if rest:
            return refuse(None, "help takes no arguments")
        sys.stdout.write(overview())
        return 0
    entry = next((e for e in COMMANDS if e.name == name), None)
    if entry is None:
        return refuse(None, f"unknown command '{name}'")
    if not entry.listed() and entry.refusal and not (entry.name in ("stress", "bench") and
                                                     {"-h", "--help"} & set(rest[:1])):
        return refuse(entry, entry.refusal)
    parser = command_parser(entry)
    args = parser.parse_args(rest)  # --help and wrong arguments end here (exit 0 and 2)
    try:
        return entry.run(args, rest)
    except Refusal as refusal:
        return refuse(entry, str(refusal))
    except Failure as failure:
        if failure.args and failure.args[0]:
            warn(failure.args[0])
        return failure.status
    except KeyboardInterrupt:
        return 130
