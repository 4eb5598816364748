"""How the front end speaks: progress lines on stderr, refusals (exit 2) and failures (exit 1),
and output that a Windows console can show."""
import codecs
import os
import sys

# Characters the workbook prints (step reports, help) and what they become on a console whose
# code page cannot show them (cp1252, cp437): readable ASCII rather than '?' or garbage.
ASCII_FALLBACK = {"\u00b7": "-", "\u2013": "-", "\u2014": "--", "\u2212": "-", "\u00d7": "x", "\u0394": "d",
                  "\u2264": "<=", "\u2265": ">=", "\u2248": "~", "\u2026": "...", "\u00b2": "^2", "\u00b3": "^3",
                  "\u2018": "'", "\u2019": "'", "\u201c": '"', "\u201d": '"', "\u2192": "->", "\u00b1": "+/-",
                  "\u03c9": "w", "\u03b8": "theta", "\u00b5": "u", "\u221a": "sqrt"}


def _to_ascii(error):
    if not isinstance(error, UnicodeEncodeError):
        raise error
    text = error.object[error.start:error.end]
    return "".join(ASCII_FALLBACK.get(c, "?") for c in text), error.end


codecs.register_error("workbook-ascii", _to_ascii)


def make_streams_safe(streams=None):
    """Lets every character the workbook prints through a console that cannot encode it: a
    stream that is not UTF-8 (a Windows console on cp1252, output redirected on Windows) keeps
    its encoding, and what it cannot encode becomes readable ASCII (· becomes -, Δ becomes d)."""
    for stream in streams if streams is not None else (sys.stdout, sys.stderr):
        encoding = (getattr(stream, "encoding", None) or "ascii").lower().replace("-", "").replace("_", "")
        if encoding in ("utf8", "utf8sig") or not hasattr(stream, "reconfigure"):
            continue
        try:
            stream.reconfigure(errors="workbook-ascii")
        except (ValueError, OSError):
            pass


class Refusal(Exception):
    """Wrong arguments: the front end says what is wrong, prints the command's usage, exits 2."""


class Failure(Exception):
    """A command could not do its job (a tool missing, a build failing): exit status 1 or the
    failing program's."""

    def __init__(self, message="", status=1):
        super().__init__(message)
        self.status = status


def _bold(text):
    if os.name != "nt" and getattr(sys.stderr, "isatty", lambda: False)():
        return f"\033[1m{text}\033[0m"
    return text


def say(message):
    """A progress line: what the workbook is doing now."""
    sys.stdout.flush()
    print(_bold(f"==> {message}"), file=sys.stderr, flush=True)


def warn(message):
    print(f"workbook: {message}", file=sys.stderr, flush=True)
