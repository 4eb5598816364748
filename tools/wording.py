"""How the workbook words a test that did not end normally: a crash, a time limit, NaN.

One place for these sentences, so that a student reads the same words from
`./workbook check` (tools/check.py) and from the grader (grader/runner.py). Each function
returns a sentence fragment; the caller adds where it happened ("in step 3") and what the
code printed."""
import re
import signal

# How a signal that ended a program reads to a student: (signal name, what happened, the usual cause).
_SIGNALS = [
    ("SIGSEGV", "a segmentation fault", "a bad pointer or reference, or an index out of range?"),
    ("SIGABRT", "an abort", "std::abort, a failed assert, or an exception thrown where none may be"),
    ("SIGFPE", "an arithmetic error", "an integer division by zero?"),
    ("SIGBUS", "a bus error", "a bad pointer?"),
    ("SIGILL", "an illegal instruction", "a function that should return a value ended without return?"),
    ("SIGKILL", "the process killed from outside", "too much memory or CPU time?"),
    ("SIGXCPU", "the CPU time limit exceeded", "an endless loop?"),
    ("SIGXFSZ", "the file size limit exceeded", "writing far too much to a file?"),
]
SIGNAL_WORDS = {getattr(signal, name): (what, why) for name, what, why in _SIGNALS if hasattr(signal, name)}
# The same crashes as Windows reports them: exit statuses (NTSTATUS codes), not signals.
WINDOWS_CRASHES = {0xC0000005: SIGNAL_WORDS.get(getattr(signal, "SIGSEGV", 11),
                                                ("a segmentation fault", "a bad pointer or reference, "
                                                                         "or an index out of range?")),
                   0xC0000094: ("an arithmetic error", "an integer division by zero?"),
                   0xC00000FD: ("a stack overflow", "a function that calls itself without end?"),
                   0xC0000409: ("an abort", "std::abort, a failed assert, or an exception thrown where none may be")}

# "nan", "-nan", "inf" as printed numbers, not inside words such as "infinite" or "financial".
NAN = re.compile(r"(?<![A-Za-z])-?(nan|inf)(?![A-Za-z])", re.IGNORECASE)


def crash_words(returncode=None, signal_number=None):
    """(what happened, the usual cause or None) when a program crashed, else None.

    returncode: as subprocess reports it (a negative number is a signal on POSIX; a large
    one a Windows crash code); signal_number: when the caller already knows the signal."""
    if signal_number is None and returncode is not None and returncode < 0:
        signal_number = -returncode
    if signal_number is not None:
        return SIGNAL_WORDS.get(signal_number, (f"signal {signal_number}", None))
    if returncode is None:
        return None
    return WINDOWS_CRASHES.get(returncode & 0xFFFFFFFF)


def _at(where):
    return f" {where}" if where else ""


def crashed(returncode=None, signal_number=None, where=""):
    """'crashed with a segmentation fault in step 3 (a bad pointer ...?)', or None when the
    program did not crash. where: "in step 3", or empty."""
    words = crash_words(returncode, signal_number)
    if words is None:
        return None
    what, why = words
    return f"crashed with {what}{_at(where)}" + (f" ({why})" if why else "")


def timed_out(seconds, where=""):
    """The words for a test stopped at its time limit."""
    return (f"did not finish within {seconds:g} s{_at(where)} and was stopped: an endless loop, or a loop "
            f"whose condition never changes?")


def not_a_number(value, where=""):
    """The words for a NaN or an infinity among the results; value is the printed number ('-nan')."""
    words = "NaN (not a number)" if value.lower().lstrip("-") == "nan" else "an infinite value"
    return f"produced {words}{_at(where)}: a division by zero, or a value used before it was set?"


def first_nan(text):
    """The first printed NaN or infinity in text ('nan', '-inf'), or None."""
    match = NAN.search(text)
    return match.group(0) if match else None
