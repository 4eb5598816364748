"""Runs each test case of a chapter as two processes and decides pass or fail.

The trusted checker (the chapter's tests linked with stand-ins, see grader/remote/) runs
the test case; every call of a chapter function goes through a pipe to the student's
process (the student's object and a server loop), which runs sandboxed and only computes.
A test case passes only when the checker exited with status 0 and the XML report it wrote
(into a folder the student's process cannot write) names exactly that test case as passed.
The student's process can change that only through the numbers it answers; what it prints
is shown to the student, and how it ended (crash, exit, time or output limit) explains a
failure."""
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass
import os
import shutil
import signal as signals
import subprocess
import tempfile
import threading

from grader import sandbox as sandboxes
from grader.build import limits_for
from grader.sandbox import Limits
from tools import catch_xml, wording

KEEP_FAILURES = 2
KEEP_FAILURE_CHARS = 1500
KEEP_PRINTED_CHARS = 1000


@dataclass
class Outcome:
    passed: bool
    feedback: str = ""


# The checker itself is trusted and quick; this only bounds a grader bug or a wedged pipe.
CHECKER_EXTRA_SECONDS = 30
MAX_REPORT_BYTES = 8 << 20


def run_chapter(kit, sandbox, chapter, binary, scratch_root, seed, limits, jobs, group=None):
    """{test case name: Outcome} for every test case of the chapter. Each case's student
    process runs as its own uid (where the grader is root) in a private, empty folder that
    is removed after the case."""
    limits = limits_for(kit, limits)
    folder = os.path.dirname(binary)

    def one(index_case):
        index, case = index_case
        if sandboxes.stopping.is_set():  # an interrupted batch records nothing of this chapter
            return case.name, Outcome(False, "not run: the grader was interrupted")
        scratch = os.path.join(scratch_root, f"{chapter.id}-{index}")
        os.makedirs(scratch)
        try:
            return case.name, run_case(sandbox, chapter, binary, folder, case, scratch, seed, limits, group)
        except Exception as error:  # a grader bug must cost this case, not the batch
            return case.name, Outcome(False, f"the grader could not run this test: {error}")
        finally:
            shutil.rmtree(scratch, ignore_errors=True)

    cases = list(enumerate(chapter.cases))
    # Without a private /tmp, cases running side by side could pass data through the shared
    # folders: the visible cases run first, and every hidden case after they have all ended
    # (and what they left is removed), so no hidden input can reach a visible case's output.
    phases = [[c for c in cases if not c[1].hidden], [c for c in cases if c[1].hidden]] if sandbox.shares_tmp \
        else [cases]
    outcomes = {}
    with ThreadPoolExecutor(max_workers=max(1, jobs)) as pool:
        for phase in phases:
            outcomes.update(pool.map(one, phase))
    return outcomes


def run_case(sandbox, chapter, binary, folder, case, scratch, seed, limits, group=None):
    calls_read, calls_write = os.pipe()
    answers_read, answers_write = os.pipe()
    # Anonymous pipes cannot be reached by name; the mode lets the student's fresh uid reopen
    # its own end as /dev/fd/N (a pipe belongs to the uid that made it).
    os.fchmod(answers_write, 0o666)
    student = {}

    def serve():
        student["run"] = sandbox.run([binary, f"/dev/fd/{answers_write}"], readable=[folder], writable=scratch,
                                     limits=limits, stdin_fd=calls_read, pass_fds=(answers_write,), group=group)

    # The grader keeps a reader of the answers until the end, so that the student's process
    # can always open its end, even when the checker is already gone.
    keep_answers_open = os.dup(answers_read)
    server = threading.Thread(target=serve, daemon=True)
    server.start()
    try:
        with tempfile.TemporaryDirectory(prefix="checker-") as private:  # 0700: the student cannot write the report
            report = os.path.join(private, "report.xml")
            checker = _run_checker(chapter, case, private, report, seed, limits, calls_write, answers_read)
            verdict = _read_report(report, case.name)
        server.join()
    finally:
        os.close(keep_answers_open)
    run = student.get("run")
    # The student's file is compiled in this folder; its path means nothing to the student.
    printed = _printed(run.output, run.output_total).replace(folder + "/", "") if run else ""
    return Outcome(*judge(checker, verdict, run, limits, printed))


def _run_checker(chapter, case, private, report, seed, limits, calls_write, answers_read):
    """Runs the trusted checker on one test case; its standard output carries the calls and
    its standard input the answers. Returns (returncode or None, problem text or None).

    The case is selected by the chapter's tag and its name together (two chapters may hold a
    test of the same name), and the name is read from a file in the grader's private folder: a
    command line can be read by every process on the machine, and a hidden test's name says
    what it tests. Catch2 reads each line of that file as one quoted test name."""
    spec = os.path.join(private, "case")
    with open(spec, "w", encoding="utf-8") as file:
        file.write(catch_xml.escape_test_name(case.name) + "\n")
    argv = [str(chapter.checker), f"[{chapter.id}]", "--input-file", spec, "-r", "xml", "-o", report,
            "--rng-seed", str(seed)]
    env = {"PATH": "/usr/bin:/bin", "LANG": "C.UTF-8", "WORKBOOK_REMOTE_CHANNEL": "stdio"}
    try:
        # restore_signals=False keeps SIGPIPE ignored: a write to a dead student process is an
        # error the stand-in reports, not the checker's death. A session of its own: a Ctrl-C
        # in the grader's terminal must not end a case as if the student's code had failed.
        process = subprocess.Popen(argv, stdin=answers_read, stdout=calls_write, stderr=subprocess.DEVNULL,
                                   env=env, restore_signals=False, close_fds=True, start_new_session=True)
    except OSError as error:
        return None, f"could not start the checker: {error}"
    finally:
        os.close(answers_read)
        os.close(calls_write)
    try:
        return process.wait(timeout=limits.wall_seconds + CHECKER_EXTRA_SECONDS), None
    except subprocess.TimeoutExpired:
        process.kill()
        process.wait()
        return None, "the grader's checker did not finish"


def judge(checker, case, student, limits, printed):
    """(passed, feedback): the verdict is the checker's alone; how the student's process
    ended only explains a failure."""
    returncode, problem = checker
    if case is not None and case.passed and returncode == 0:
        return True, ""
    run = student
    if run is None:
        return False, f"the grader could not run this test: {problem or 'the student process did not run'}"
    gone = case is None or any(remote_gone_marker in f for f in case.failures)
    if not gone and not (run.timed_out or run.flooded or run.disk_full or run.memory_full or run.signal is not None
                         or run.error):
        if run.returncode not in (0, None):
            gone = True
    if not gone:
        if problem:
            return False, f"the grader could not finish this test ({problem}){printed}"
        return False, _failures(case).lstrip("\n") + printed
    if run.error:
        return False, f"the test could not be started: {run.error}"
    if run.timed_out:
        return False, wording.timed_out(limits.wall_seconds) + printed
    if run.flooded:
        return False, (f"your code printed more than {limits.output_bytes // 1024} KiB of output, so the test "
                       f"was stopped{printed}")
    if run.memory_full:
        return False, (f"your code used more than {limits.memory_bytes >> 20} MiB of memory (all its processes "
                       f"together), so the test was stopped{printed}")
    if run.disk_full:
        return False, (f"your code wrote more than {limits.disk_bytes >> 20} MiB to disk, so the test was "
                       f"stopped{printed}")
    if run.signal is not None:
        return False, (f"your code {wording.crashed(signal_number=run.signal)} [{_signal_name(run.signal)}, "
                       f"signal {run.signal}]{printed}")
    if run.returncode == 0:
        return False, ("your program exited early with status 0 before the test finished (does your code call "
                       f"exit()?){printed}")
    if "Sanitizer" in printed:  # sanitizer kits (the workbook's own CI) stop at the first bad access
        return False, f"your code crashed: the sanitizer found undefined behaviour or a bad memory access{printed}"
    return False, f"your program ended with status {run.returncode} before the test finished{printed}"


remote_gone_marker = "[workbook-remote: your code's process ended]"


def _read_report(path, name):
    """The CaseResult, or None unless the report is complete and names only this case."""
    try:
        with open(path, "rb") as file:
            cases = catch_xml.parse(file.read(8 << 20))
    except (OSError, ValueError):
        return None
    return cases[0] if len(cases) == 1 and cases[0].name == name else None


def _failures(case):
    shown = [f[:KEEP_FAILURE_CHARS] for f in case.failures[:KEEP_FAILURES]]
    more = len(case.failures) - len(shown)
    text = "\n".join(shown) if shown else "the test failed"
    if more > 0:
        text += f"\n(and {more} more failed check{'s' if more > 1 else ''})"
    return "\n" + text


def _printed(output, total):
    if not output:
        return ""
    text = output.decode("utf-8", "replace")
    text = "".join(c for c in text if c in "\n\t" or c.isprintable())
    tail = text[-KEEP_PRINTED_CHARS:]
    cut = " (last part)" if len(tail) < len(text) or total > len(output) else ""
    return f"\nyour code printed{cut}:\n{tail.rstrip()}"


def _signal_name(number):
    try:
        return signals.Signals(number).name
    except ValueError:
        return f"signal {number}"


# The student's process needs one process and no thread; bubblewrap adds its own (the
# namespace's init) to the count. The rest is slack for a sanitizer kit's helper thread.
STUDENT_PROCESSES = 4


def default_limits(time_limit, memory_mb, disk_mb=64):
    return Limits(wall_seconds=time_limit, memory_bytes=memory_mb << 20, disk_bytes=disk_mb << 20,
                  processes=STUDENT_PROCESSES)
