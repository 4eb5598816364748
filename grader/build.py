"""Compiles one student file and links it into the student's process for one chapter: the
student's object, the chapter's dispatch and the server loop (grader/remote/), the engine.

Before compiling, the source's includes are checked (only the public headers and the
submission's own files); after compiling, the symbols the object defines (only the chapter
header's functions and internal helpers). Compiling, listing symbols and linking run in the
sandbox, and compiler output is shown only where it speaks of the student's file or a public
header, so no text from outside the submission reaches the student."""
from __future__ import annotations  # `X | None` annotations on Python 3.8 and 3.9
import dataclasses
from dataclasses import dataclass
import os
import re

from grader import screen
from grader.sandbox import Limits

COMPILE_LIMITS = Limits(wall_seconds=120, memory_bytes=4 << 30, file_bytes=512 << 20, processes=64,
                        output_bytes=4 << 20)
MAX_ERROR_LINES = 25
NM = "/usr/bin/nm"


@dataclass
class Built:
    binary: str | None
    problem: str | None = None      # "did not compile" / "did not link" / "was refused", for the gradebook
    feedback: str | None = None     # the compiler's first errors, or why the file was refused


def build_chapter(kit, sandbox, chapter, source, folder, group=None):
    """`source` is the student's file already copied into `folder` (a fresh folder); every
    command runs in the submission's `group` (see Sandbox.new_group)."""
    obj = os.path.join(folder, chapter.id + ".o")
    binary = os.path.join(folder, chapter.id + "-student")
    with open(source, "rb") as file:
        refused = check_source(file.read().decode("utf-8", "replace"), chapter.source)
    if refused:
        return Built(None, "was refused", refused)
    limits = limits_for(kit, COMPILE_LIMITS)
    # Preprocessed in the sandbox, where no secret exists (or none the sandbox's user may
    # read); its output is screened and is what gets compiled, so the check sees exactly
    # what the compiler reads.
    preprocessed = os.path.join(folder, chapter.id + ".ii")
    run = sandbox.run([kit.compiler, *kit.compile_flags, *(f"-I{d}" for d in kit.include_dirs), "-E", source,
                       "-o", preprocessed], readable=kit.include_dirs, writable=folder, limits=limits, group=group)
    if not run.ok or not os.path.isfile(preprocessed):
        return Built(None, "did not compile", _first_errors(run, kit, folder, "compiling", chapter.source))
    text = _read_whole(preprocessed)
    problems = [(None, TOO_LARGE)] if text is None else screen.check_preprocessed(text, source, kit.include_dirs)
    if problems:
        return Built(None, "was refused", screen.refusal(chapter.source, problems))
    # Compiled to assembly first: its text is checked before the assembler reads it.
    assembly = os.path.join(folder, chapter.id + ".s")
    compile_cmd = [kit.compiler, *kit.compile_flags, "-x", "c++-cpp-output", "-S", preprocessed, "-o", assembly]
    run = sandbox.run(compile_cmd, readable=kit.include_dirs, writable=folder, limits=limits, group=group)
    if not run.ok or not os.path.isfile(assembly):
        return Built(None, "did not compile", _first_errors(run, kit, folder, "compiling", chapter.source))
    text = _read_whole(assembly)
    problems = [(None, TOO_LARGE)] if text is None else screen.check_assembly(text)
    if problems:
        return Built(None, "was refused", screen.refusal(chapter.source, problems))
    run = sandbox.run([kit.compiler, *kit.compile_flags, "-x", "assembler", "-c", assembly, "-o", obj],
                      readable=kit.include_dirs, writable=folder, limits=limits, group=group)
    if not run.ok or not os.path.isfile(obj):
        return Built(None, "did not compile", _first_errors(run, kit, folder, "assembling", chapter.source))
    refused = _check_symbols(sandbox, chapter, obj, folder, limits, group)
    if refused:
        return Built(None, "was refused", refused)
    link_cmd = [kit.compiler, *kit.link_flags, "-o", binary, obj, *chapter.server_objects, *kit.link_libraries]
    run = sandbox.run(link_cmd, readable=[str(kit.files_dir)], writable=folder, limits=limits, group=group)
    if not run.ok or not os.path.isfile(binary):
        return Built(None, "did not link", _first_errors(run, kit, folder, "linking", chapter.source))
    os.chmod(binary, 0o750)
    return Built(binary)


# A check must read all of what it checks: a hand-written chapter file comes nowhere near.
CHECKED_BYTES = 64 << 20
TOO_LARGE = f"the compiler's output is larger than {CHECKED_BYTES >> 20} MiB, more than the grader checks"


def _read_whole(path):
    """The text of `path`, or None when it is larger than CHECKED_BYTES."""
    with open(path, "rb") as file:
        data = file.read(CHECKED_BYTES + 1)
    return None if len(data) > CHECKED_BYTES else data.decode("utf-8", "replace")


def limits_for(kit, limits):
    """AddressSanitizer reserves terabytes of address space, so a sanitizer kit cannot have
    RLIMIT_AS."""
    return dataclasses.replace(limits, address_space_limit=False) if kit.sanitize else limits


# --- Includes and assembler (see screen.py) --------------------------------------------
def check_source(text, name):
    """Why the file is refused from its text alone, before anything runs, or None."""
    problems = screen.check_text(text)
    return screen.refusal(name, problems) if problems else None


# --- Symbols ------------------------------------------------------------------------------
def _check_symbols(sandbox, chapter, obj, folder, limits, group=None):
    """Why the object is refused, or None: it may define (globally) only the functions of the
    chapter's header; helpers must be internal (static or in an anonymous namespace). Weak
    definitions of inline functions and templates are what every file has, except main and
    the allocation functions."""
    runs = [sandbox.run([NM, "--defined-only", *flags, obj], readable=[folder], writable=folder, limits=limits,
                        group=group)
            for flags in ([], ["-C"])]
    if not all(run.ok for run in runs):
        return "the grader could not list the functions your file defines (nm failed)"
    raw = runs[0].output.decode("utf-8", "replace").splitlines()
    readable = runs[1].output.decode("utf-8", "replace").splitlines()
    refused = []
    for line, nice in zip(raw, readable):
        parts, shown = line.split(maxsplit=2), nice.split(maxsplit=2)
        if len(parts) != 3 or len(shown) != 3:
            continue
        kind, mangled, name = parts[1], parts[2], shown[2]
        if kind.islower() and kind not in ("i", "u", "v", "w"):
            continue  # local: an internal helper
        if mangled in chapter.functions:
            continue
        special = mangled == "main" or name.startswith(("operator new", "operator delete"))
        if kind in ("W", "V", "u", "v", "w") and not special:
            continue  # an inline function or a template instantiation
        refused.append(name)
    if not refused:
        return None
    allowed = ", ".join(sorted({n.split("(")[0].rsplit("::", 1)[-1] for n in chapter.functions.values()}))
    return (f"your {chapter.source} was refused: it defines "
            + ", ".join(f"'{n}'" for n in refused[:5]) + (f" and {len(refused) - 5} more" if len(refused) > 5 else "")
            + f", which {'is' if len(refused) == 1 else 'are'} not among the functions of the chapter's header "
            f"({allowed}). Define only those; make your own helpers internal (static, or inside "
            "namespace { ... }), and never define main, engine or standard-library functions.")


# --- Compiler output ----------------------------------------------------------------------
LOCATED = re.compile(r"^(?:In file included from |\s+from )?([^:\s][^:]*?):\d+(?::\d+)?[:,]")


def _first_errors(run, kit, folder, what, source_name):
    if run.timed_out:
        return f"{what} took longer than {COMPILE_LIMITS.wall_seconds:g} s and was stopped"
    if run.flooded:
        return f"{what} printed too many errors and was stopped"
    if run.error:
        return run.error
    text = run.output.decode("utf-8", "replace").replace(folder + "/", "")
    # The linker names the kit's object files; they are the grader's, nothing the student needs.
    text = re.sub(r"\S*/objects/\d+-\S+\.o\b", "(the grader's part)", text)
    text = text.replace(str(kit.files_dir) + "/", "")
    missing = sorted(set(re.findall(r"undefined reference to `([^']+)'", text)))
    if missing:
        return ("your file does not define these functions, which the tests call (check the name, the "
                "namespace and the parameter types against the chapter's header):\n  " + "\n  ".join(missing))
    lines = _only_own_text(text.splitlines(), source_name, kit)
    # Start at the first error; the "In function ..." line before it gives the context.
    # ld's "multiple definition" carries no "error".
    first = next((i for i, line in enumerate(lines) if re.search(r"\berror\b|multiple definition", line)), 0)
    start = first - 1 if first > 0 and lines[first - 1].endswith(":") else first
    shown = lines[start:start + MAX_ERROR_LINES]
    if len(lines) > start + MAX_ERROR_LINES:
        shown.append(f"... ({len(lines) - start - MAX_ERROR_LINES} more lines)")
    if run.signal:
        tool = {"compiling": "compiler", "assembling": "assembler"}.get(what, "linker")
        shown.append(f"(the {tool} was stopped by signal {run.signal})")
    return "\n".join(shown) or f"{what} failed with status {run.returncode}"


def _only_own_text(lines, source_name, kit):
    """The compiler's lines, without any that speak of (and so may quote) a file outside the
    submission and the public headers: a diagnostic located elsewhere is replaced by one line."""
    public = [os.path.relpath(d, kit.files_dir) + "/" if kit.files_dir and d.startswith(str(kit.files_dir)) else d + "/"
              for d in kit.include_dirs]

    def allowed(path):
        return path == source_name or path.startswith(tuple(public)) or path.startswith("/usr/")

    kept, hiding = [], False
    for line in lines:
        located = LOCATED.match(line)
        if located or line.startswith(("{standard input}", "/tmp/")):
            hiding = not (located and allowed(located.group(1)))
            if hiding:
                if not kept or kept[-1] != HIDDEN:
                    kept.append(HIDDEN)
                continue
        elif hiding and (line.startswith(" ") or not line.strip()):
            continue  # the quoted source and caret lines of a hidden diagnostic
        else:
            hiding = False
        kept.append(line)
    return kept


HIDDEN = "(a message about a file outside your submission, not shown)"
