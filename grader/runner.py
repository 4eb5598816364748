"""Runs each test case of a chapter in its own sandboxed process and decides pass or fail.

A test case passes only when its process exited with status 0 within the limits AND the XML
report file it wrote names exactly that test case as passed. The report is read from a file,
never from stdout, so text the student prints (even an imitation of a report) counts for
nothing; stdout is kept only to show the student what their code printed."""
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass
import os
import signal as signals

from build import limits_for
import catch_xml
from sandbox import Limits

SIGNAL_NAMES = {
    signals.SIGSEGV: "segmentation fault: a bad pointer or an out-of-range index?",
    signals.SIGABRT: "abort: std::abort, a failed assert or std::terminate",
    signals.SIGFPE: "arithmetic error, such as an integer division by zero",
    signals.SIGBUS: "bus error",
    signals.SIGILL: "illegal instruction",
    signals.SIGKILL: "killed, probably for using too much memory or CPU time",
    signals.SIGXCPU: "CPU time limit exceeded",
    signals.SIGXFSZ: "file size limit exceeded",
}
KEEP_FAILURES = 2
KEEP_FAILURE_CHARS = 1500
KEEP_PRINTED_CHARS = 1000
# Characters Catch2's test-spec parser treats specially; a backslash makes them literal.
SPEC_SPECIAL = set('\\,[]"*~^&#')


@dataclass
class Outcome:
    passed: bool
    feedback: str = ""


def escape_test_name(name):
    return "".join("\\" + c if c in SPEC_SPECIAL else c for c in name)


def run_chapter(kit, sandbox, chapter, binary, scratch_root, seed, limits, jobs):
    """{test case name: Outcome} for every test case of the chapter."""
    limits = limits_for(kit, limits)
    folder = os.path.dirname(binary)

    def one(index_case):
        index, case = index_case
        scratch = os.path.join(scratch_root, f"{chapter.id}-{index}")
        os.makedirs(scratch)
        sandbox.prepare_writable(scratch)
        try:
            return case.name, run_case(sandbox, binary, folder, case, scratch, seed, limits)
        except Exception as error:  # a grader bug must cost this case, not the batch
            return case.name, Outcome(False, f"the grader could not run this test: {error}")

    with ThreadPoolExecutor(max_workers=max(1, jobs)) as pool:
        return dict(pool.map(one, enumerate(chapter.cases)))


def run_case(sandbox, binary, folder, case, scratch, seed, limits):
    report = os.path.join(scratch, "report.xml")
    argv = [binary, escape_test_name(case.name), "-r", "xml", "-o", report, "--rng-seed", str(seed)]
    run = sandbox.run(argv, readable=[folder], writable=scratch, limits=limits)
    printed = _printed(run.output, run.output_total)
    return Outcome(*judge(run, _read_report(report, case.name), limits, printed))


def judge(run, case, limits, printed):
    """(passed, feedback) from how the process ended and what its report says."""
    if run.error:
        return False, f"the test could not be started: {run.error}"
    if run.timed_out:
        return False, (f"timed out after {limits.wall_seconds:g} s: an endless loop, or code that waits "
                       f"for something?{printed}")
    if run.flooded:
        return False, (f"your code printed more than {limits.output_bytes // 1024} KiB of output, so the test "
                       f"was stopped{printed}")
    if run.signal is not None:
        reason = SIGNAL_NAMES.get(run.signal, "")
        name = _signal_name(run.signal)
        detail = _failures(case) if case is not None and case.failures else ""
        return False, (f"your code crashed with signal {run.signal} ({name}{': ' + reason if reason else ''})"
                       f"{detail}{printed}")
    if case is None:
        if run.returncode == 0:
            return False, ("your program exited early with status 0 before the test finished (does your code call "
                           f"exit()?){printed}")
        return False, f"your program ended with status {run.returncode} before the test finished{printed}"
    if case.passed and run.returncode == 0:
        return True, ""
    if case.passed:
        return False, f"the test passed but your program then ended with status {run.returncode}{printed}"
    return False, _failures(case).lstrip("\n") + printed


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


def default_limits(time_limit, memory_mb):
    return Limits(wall_seconds=time_limit, memory_bytes=memory_mb << 20)
