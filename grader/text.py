"""Text from a submission made safe for where the instructor reads it.

Archive member names, compiler output, what the student's code printed and exception
texts reach the instructor's terminal, results.json and the gradebook a spreadsheet opens.
`plain` keeps them text in a terminal (no escape sequence can set the clipboard, clear the
screen or reorder what is shown); `cell` also keeps a spreadsheet from reading a cell as
a formula."""
import re

# ESC sequences: CSI (ESC [ ... final), OSC (ESC ] ... BEL or ESC \), DCS/SOS/PM/APC
# (ESC P/X/^/_ ... ESC \), and two-character ones; C1 CSI (0x9b) and OSC (0x9d) likewise.
ANSI = re.compile(r"(?:\x1b\[|\x9b)[0-?]*[ -/]*[@-~]"
                  r"|(?:\x1b\]|\x9d)[^\x07\x1b\x9c]*(?:\x07|\x1b\\|\x9c)?"
                  r"|\x1b[PX^_][^\x1b\x9c]*(?:\x1b\\|\x9c)?"
                  r"|\x1b[ -~]?")
# Control characters other than newline and tab, C1 controls, and the invisible characters
# that reorder or hide text (bidirectional overrides, as in "Trojan source").
CONTROL = re.compile("[\x00-\x08\x0b-\x1f\x7f-\x9f\u200b-\u200f\u202a-\u202e\u2060-\u2064\u2066-\u2069\ufeff]")
FORMULA_START = ("=", "+", "-", "@", "\t", "\r")


def plain(text):
    """`text` without terminal escape sequences and control characters (newlines and tabs
    kept); each removed control shows as '?', so nothing vanishes silently."""
    if text is None:
        return None
    return CONTROL.sub("?", ANSI.sub("?", str(text)))


def cell(text):
    """A gradebook cell: plain, on one line, and never a formula (a leading = + - @ gets a
    quote, as spreadsheets themselves write it), except a plain number."""
    value = plain(text).replace("\r", " ").replace("\n", " ").replace("\t", " ")
    if value.startswith(FORMULA_START) and not _number(value):
        value = "'" + value
    return value


def _number(value):
    try:
        float(value)
        return True
    except ValueError:
        return False


def plain_json(data):
    """`data` (results.json) with every string made plain."""
    if isinstance(data, str):
        return plain(data)
    if isinstance(data, list):
        return [plain_json(v) for v in data]
    if isinstance(data, dict):
        return {plain(k): plain_json(v) for k, v in data.items()}
    return data
