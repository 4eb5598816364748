"""What a submission's file may make the compiler read, checked twice.

1. `check_text` reads the file as the preprocessor tokenises it (lines spliced, comments and
   literals skipped), before anything runs. Every rule here depends on the file's bytes only,
   never on which files exist, so a refusal tells the student nothing about the instructor's
   machine:
   - #include / #include_next / #import / #embed must name a literal file that is not an
     absolute path and does not leave the submission (..);
   - __has_include(...) likewise, and it must be written out (not built by a macro);
   - token pasting (##) and _Pragma are refused: they are the only ways to build the
     tokens above (or a pragma) out of pieces that the first rules cannot see;
   - line directives (#line, # 12 "file") are refused: they would let the file pose as a
     system header in the preprocessed output that the second check reads;
   - #pragma ... dependency (it stats a file by name).
2. `check_preprocessed` reads the compiler's own output (`-E`, run in the sandbox, where no
   secret exists): every file the preprocessor entered must be the submission's file, a
   public header or a system header under /usr, and the submission's own lines may not hold
   `asm` in any spelling (so no .incbin however its string is assembled). That output is
   what is then compiled, so what was checked is exactly what is built.
3. `check_assembly` reads the assembly the compiler wrote from it, before it is assembled:
   no directive that reads a file (GCC copies a section attribute's string into it verbatim,
   so `section("x\n.incbin \"/etc/passwd\"")` would be one without any `asm`).
"""
import os
import re

# Preprocessing tokens the checks care about; everything else is one character of "other".
TOKEN = re.compile(r"""
    (?P<raw>(?:u8|u|U|L)?R"(?P<delim>[^()\\\s"]{0,16})\()       # raw string: skipped to its end below
  | (?P<string>(?:u8|u|U|L)?"(?:[^"\\\n]|\\.)*"?)
  | (?P<char>(?:u8|u|U|L)?'(?:[^'\\\n]|\\.)*'?)
  | (?P<line_comment>//[^\n]*)
  | (?P<block_comment>/\*.*?(?:\*/|\Z))
  | (?P<paste>\#\#|%:%:)
  | (?P<hash>\#|%:|\?\?=)
  | (?P<ident>[A-Za-z_]\w*)
  | (?P<number>\.?\d(?:[eEpP][+-]|[\w.'])*)
  | (?P<newline>\n)
  | (?P<space>[ \t\f\v\r]+)
  | (?P<other>.)
""", re.VERBOSE | re.DOTALL)

DIRECTIVES_READING_FILES = {"include", "include_next", "import", "embed"}
HAS_INCLUDE = {"__has_include", "__has_include_next", "__has_embed"}
ASM = {"asm", "__asm", "__asm__"}


def _tokens(text):
    """(kind, text, line number) of each token, as the preprocessor sees them: lines spliced
    first, a comment is one space (so `#/**/include` is a directive and `__has_include/**/(`
    a call)."""
    text = re.sub(r"\\[ \t]*\r?\n", "", text)
    position, line = 0, 1
    while position < len(text):
        match = TOKEN.match(text, position)
        kind = "raw" if match.group("raw") else match.lastgroup
        end = match.end()
        if kind == "raw":
            close = text.find(")" + match.group("delim") + '"', end)
            end = len(text) if close < 0 else close + len(match.group("delim")) + 2
            kind = "string"
        token = text[position:end]
        if kind in ("block_comment", "line_comment"):
            kind = "space"
        yield kind, token, line
        line += token.count("\n")
        position = end


def _logical_lines(text):
    """[(line number, [(kind, token)])] without spaces, one entry per logical line."""
    lines, current, number = [], [], 1
    for kind, token, line in _tokens(text):
        if kind == "newline":
            if current:
                lines.append((number, current))
            current = []
        elif kind != "space":
            if not current:
                number = line
            current.append((kind, token))
    if current:
        lines.append((number, current))
    return lines


def _outside(path):
    normal = path.replace("\\", "/")
    if normal.startswith("/") or re.match(r"^[A-Za-z]:", normal) or normal.startswith("~"):
        return "is an absolute path"
    if ".." in normal.split("/"):
        return "leaves your submission (..)"
    return None


def _file_name(tokens, start):
    """(path, index after it) of a "file" or <file> name at tokens[start], or (None, start)."""
    if start >= len(tokens):
        return None, start
    kind, token = tokens[start]
    if kind == "string" and token.startswith('"') and token.endswith('"') and len(token) >= 2:
        return token[1:-1], start + 1
    if token == "<":
        for end in range(start + 1, len(tokens)):
            if tokens[end][1] == ">":
                return "".join(t for _, t in tokens[start + 1:end]), end + 1
    return None, start


def check_text(text):
    """[(line, problem)] the file is refused for, from its text alone."""
    problems = []
    for number, tokens in _logical_lines(text):
        words = [t for _, t in tokens]
        if tokens[0][0] == "hash" and len(tokens) > 1:
            directive = words[1]
            if directive in DIRECTIVES_READING_FILES:
                path, _ = _file_name(tokens, 2)
                if path is None:
                    problems.append((number, f"an #{directive} whose file name is not written out cannot be checked"))
                elif _outside(path):
                    problems.append((number, f"{path!r} {_outside(path)}"))
                if directive == "embed":
                    problems.append((number, "#embed reads a file into the program, which the grader does not allow"))
                continue
            if directive == "line" or tokens[1][0] == "number":
                problems.append((number, "line directives (#line) are not allowed in a submission"))
                continue
            if directive == "pragma" and "dependency" in words:
                problems.append((number, "#pragma ... dependency reads a file, which the grader does not allow"))
                continue
        defining = tokens[0][0] == "hash" and words[1:2] == ["define"]
        for index, (kind, token) in enumerate(tokens):
            if kind == "hash" and index > 0 and not (defining and index > 2 and tokens[index + 1:index + 2]
                                                      and tokens[index + 1][0] == "ident"):
                # A '#' that is not a directive's could reach the preprocessed output as a line
                # marker (# 1 "/usr/include/..." 3) and pose as a system header there.
                problems.append((number, "a '#' may only start a directive or stringize a macro parameter"))
            elif kind == "paste":
                problems.append((number, "token pasting (##) is not allowed in a submission"))
            elif kind == "ident" and token == "_Pragma":
                problems.append((number, "_Pragma is not allowed in a submission"))
            elif kind == "ident" and token in HAS_INCLUDE:
                path, after = _file_name(tokens, index + 2) if words[index + 1:index + 2] == ["("] else (None, 0)
                if path is None or words[after:after + 1] != [")"]:
                    problems.append((number, f"{token}(...) must name its file as a literal"))
                elif _outside(path):
                    problems.append((number, f"{path!r} {_outside(path)}"))
            elif kind == "ident" and token in ASM:
                problems.append((number, f"'{token}' (inline assembler) is not allowed"))
    return problems


# --- The preprocessor's output -------------------------------------------------------------
LINEMARKER = re.compile(r'^#\s+(\d+)\s+"((?:[^"\\]|\\.)*)"((?:\s+\d+)*)\s*$')


def check_preprocessed(text, source, allowed_dirs):
    """[(line, problem)] for the preprocessed `text` of `source`: files entered that are not
    the source, under `allowed_dirs` or a system header under /usr, and `asm` on the
    source's own lines. The line markers are the compiler's own: check_text refused any
    that the source could have written itself."""
    roots = [os.path.realpath(d) + os.sep for d in allowed_dirs] + ["/usr/"]
    source_real = os.path.realpath(source)
    problems = []
    stack = [None]                  # the real file of each include level (None: not yet known)
    line = [0]                      # the line number the next text line has, per level
    for raw in text.splitlines():
        marker = LINEMARKER.match(raw)
        if marker:
            number, name, flags = int(marker.group(1)), _unescape(marker.group(2)), marker.group(3).split()
            if "1" in flags:        # entering an included file
                including = line[-1] if stack[-1] == source_real else None
                stack.append(_real(name))
                line.append(number)
                if not _allowed(stack[-1], source_real, roots):
                    problems.append((including, "includes a file that is not part of the standard library, the "
                                                "workbook's public headers or your submission"))
            elif "2" in flags and len(stack) > 1:  # back in the including file
                stack.pop()
                line.pop()
                line[-1] = number
            else:
                if stack[-1] is None:
                    stack[-1] = _real(name)
                line[-1] = number
            continue
        if stack[-1] == source_real:
            if raw.lstrip().startswith("#pragma") and "dependency" in raw:
                problems.append((line[-1], "#pragma ... dependency reads a file, which the grader does not allow"))
            for kind, token, _ in _tokens(raw):
                if kind == "ident" and token in ASM:
                    problems.append((line[-1], f"'{token}' (inline assembler) is not allowed"))
                    break
        line[-1] += 1
    return problems


# Assembler directives that read a file (.incbin, .include) and those that could build one
# out of pieces (macros, repetition). The compiler never writes any of them for C++; they
# reach its assembly only through a string it copies verbatim, such as GCC's
# __attribute__((section("...\n.incbin \"/etc/passwd\""))).
ASSEMBLER_READS = re.compile(r"\.(incbin|include|macro|irpc?|rept|altmacro|purgem)\b", re.IGNORECASE)


def check_assembly(text):
    """[(None, problem)] for the compiler's assembly output: checked as text, strings
    included, so that no quoting can hide a directive from the check (a string of the
    program that spells '.incbin' is refused too)."""
    found = sorted({match.group(0).lower() for match in ASSEMBLER_READS.finditer(text)})
    if not found:
        return []
    return [(None, f"the compiled program would make the assembler read a file or run an assembler macro "
                   f"({', '.join(found)}): a string in an attribute (section, alias...) or in inline assembler "
                   "that the compiler copies into its assembly")]


def _unescape(name):
    return re.sub(r"\\(.)", r"\1", name)


def _real(name):
    if name.startswith("<") and name.endswith(">"):  # <built-in>, <command-line>
        return name
    return os.path.realpath(name)


def _allowed(path, source_real, roots):
    return path.startswith("<") or path == source_real or path.startswith(tuple(roots))


def refusal(name, problems):
    """The text a refused file gets: the rules, then the first problems by line."""
    shown = [f"line {line}: {problem}" if line else problem for line, problem in problems[:5]]
    return (f"your {name} was not compiled: it may include only the standard library, the workbook's public "
            "headers and files of your own submission, and may not use inline assembler.\n  " + "\n  ".join(shown))
