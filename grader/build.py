"""Compiles one student file and links it with the kit into one test binary per chapter.

Both run in the sandbox: the compiler sees only the header folders and the student's file,
so `#include "../solutions/..."` or an absolute path into tests/hidden finds nothing."""
import dataclasses
from dataclasses import dataclass
import os
import re

from sandbox import Limits

COMPILE_LIMITS = Limits(wall_seconds=120, memory_bytes=4 << 30, file_bytes=512 << 20, processes=64,
                        output_bytes=4 << 20)
MAX_ERROR_LINES = 25


@dataclass
class Built:
    binary: str | None
    problem: str | None = None      # "did not compile" / "did not link", for the gradebook
    feedback: str | None = None     # the compiler's first errors


def build_chapter(kit, sandbox, chapter, source, folder):
    """`source` is the student's file already copied into `folder` (a fresh folder)."""
    obj = os.path.join(folder, chapter.id + ".o")
    binary = os.path.join(folder, chapter.id + "-tests")
    limits = limits_for(kit, COMPILE_LIMITS)
    compile_cmd = [kit.compiler, *kit.compile_flags, *(f"-I{d}" for d in kit.include_dirs), "-c", source, "-o", obj]
    run = sandbox.run(compile_cmd, readable=kit.include_dirs, writable=folder, limits=limits)
    if not run.ok or not os.path.isfile(obj):
        return Built(None, "did not compile", _first_errors(run, kit, folder, "compiling"))
    link_cmd = [kit.compiler, *kit.link_flags, "-o", binary, obj, *chapter.test_objects, *kit.link_libraries]
    run = sandbox.run(link_cmd, readable=[str(kit.files_dir)], writable=folder, limits=limits)
    if not run.ok or not os.path.isfile(binary):
        return Built(None, "did not link", _first_errors(run, kit, folder, "linking"))
    os.chmod(binary, 0o755)
    return Built(binary)


def limits_for(kit, limits):
    """AddressSanitizer reserves terabytes of address space, so a sanitizer kit cannot have
    RLIMIT_AS."""
    return dataclasses.replace(limits, address_space_limit=False) if kit.sanitize else limits


def _first_errors(run, kit, folder, what):
    if run.timed_out:
        return f"{what} took longer than {COMPILE_LIMITS.wall_seconds:g} s and was stopped"
    if run.flooded:
        return f"{what} printed too many errors and was stopped"
    if run.error:
        return run.error
    text = run.output.decode("utf-8", "replace").replace(folder + "/", "")
    # The linker names the kit's object files; they are the tests, nothing the student needs.
    text = re.sub(r"\S*/objects/\d+-\S+\.o\b", "(the tests)", text)
    text = text.replace(str(kit.files_dir) + "/", "")
    text = re.sub(r"\S*tests/\w+/[\w.-]+:\d+:?", "(the tests)", text)
    missing = sorted(set(re.findall(r"undefined reference to `([^']+)'", text)))
    if missing:
        # The raw lines name test files and lines (hidden ones too); the functions are what matters.
        return ("your file does not define these functions, which the tests call (check the name, the "
                "namespace and the parameter types against the chapter's header):\n  " + "\n  ".join(missing))
    lines = text.splitlines()
    # Start at the first error; the "In function ..." line before it gives the context.
    # ld's "multiple definition" carries no "error".
    first = next((i for i, line in enumerate(lines) if re.search(r"\berror\b|multiple definition", line)), 0)
    start = first - 1 if first > 0 and lines[first - 1].endswith(":") else first
    shown = lines[start:start + MAX_ERROR_LINES]
    if len(lines) > start + MAX_ERROR_LINES:
        shown.append(f"... ({len(lines) - start - MAX_ERROR_LINES} more lines)")
    if run.signal:
        shown.append(f"(the {'compiler' if what == 'compiling' else 'linker'} was stopped by signal {run.signal})")
    return "\n".join(shown) or f"{what} failed with status {run.returncode}"
