"""The grader kit: what the instructor's build left in <build>/grader/kit.json, and the
test cases of each chapter, listed once from its trusted checker (the public and hidden
tests linked with stand-ins that forward each call to the student's process)."""
from __future__ import annotations  # `X | None` annotations on Python 3.8 and 3.9
from dataclasses import dataclass, field, replace
import itertools
import json
import os
import pathlib
import shutil
import subprocess
import xml.etree.ElementTree as ElementTree

from tools import catch_xml, workbook_files


class KitError(Exception):
    """The kit is missing or broken: an instructor problem, reported before any grading."""


@dataclass
class TestCase:
    name: str
    tags: list
    hidden: bool
    order: int

    def _record(self):
        return catch_xml.CaseResult(self.name, self.tags, False)

    @property
    def step(self):
        return self._record().step or (0, "untagged")

    @property
    def points(self):
        return self._record().points


@dataclass
class Chapter:
    number: int
    id: str
    source: str            # the student's file name, e.g. linear_impulse.cpp
    skeleton: pathlib.Path
    checker: pathlib.Path     # trusted: tests + stand-ins, never loads student code
    server_objects: list      # linked with the student's object into the student's process
    cases: list = field(default_factory=list)
    functions: dict = field(default_factory=dict)  # {mangled symbol: readable name} of the header's functions

    @property
    def namespace(self):
        return "workbook::" + (self.source[:-len(".cpp")] if self.source.endswith(".cpp") else self.source)

    @property
    def title(self):
        return f"Chapter {self.number} {self.id}"

    @property
    def max_score(self):
        return sum(case.points for case in self.cases)

    def steps(self):
        """{(number, name): [cases]} in step order."""
        steps = {}
        for case in sorted(self.cases, key=lambda c: (c.step[0], c.hidden, c.order)):
            steps.setdefault(case.step, []).append(case)
        return steps


@dataclass
class Kit:
    path: pathlib.Path
    source_dir: pathlib.Path
    build_dir: pathlib.Path
    compiler: str
    compile_flags: list
    link_flags: list
    include_dirs: list
    link_libraries: list
    sanitize: bool
    default_seed: int
    chapters: list
    warnings: list = field(default_factory=list)
    files_dir: pathlib.Path | None = None  # the snapshot the sandbox reads; see snapshot()


def load(build_dir):
    path = pathlib.Path(build_dir) / "grader" / "kit.json"
    if not path.is_file():
        raise KitError(f"no grader kit at {path}: build it first (cmake --preset dev && cmake --build --preset dev)")
    try:
        data = json.loads(path.read_text())
    except (OSError, ValueError) as error:
        raise KitError(f"cannot read {path}: {error}") from None
    if data.get("format") != 2:
        raise KitError(f"{path} is from an older grader: rebuild the kit (cmake --build --preset dev --target grader_kit)")
    chapters = [Chapter(number, entry["id"], entry["source"], pathlib.Path(entry["skeleton"]),
                        pathlib.Path(entry["checker"]), entry["server_objects"])
                for number, entry in enumerate(data["chapters"], start=1)]
    kit = Kit(path, pathlib.Path(data["source_dir"]), pathlib.Path(data["build_dir"]), data["compiler"],
              data["compile_flags"], data["link_flags"], data["include_dirs"], data["link_libraries"],
              bool(data.get("sanitize")), int(data["default_seed"]), chapters)
    missing = [str(p) for p in [kit.compiler, *kit.link_libraries, *kit.include_dirs]
               + [p for c in chapters for p in (c.checker, c.skeleton, *c.server_objects)] if not pathlib.Path(p).exists()]
    if missing:
        raise KitError(f"the grader kit in {path.parent} is incomplete (missing {missing[0]}"
                       f"{f' and {len(missing) - 1} more' if len(missing) > 1 else ''}): rebuild it")
    _check_chapter_list(kit)
    for chapter in chapters:
        chapter.cases = _list_cases(kit, chapter)
        chapter.functions = _chapter_functions(chapter)
    return kit


def defined_symbols(path, nm="nm"):
    """[(type letter, mangled, readable)] of the symbols an object or binary defines."""
    runs = [subprocess.run([nm, "--defined-only", *flags, str(path)], capture_output=True, text=True, timeout=60,
                           stdin=subprocess.DEVNULL) for flags in ([], ["-C"])]
    if any(run.returncode != 0 for run in runs):
        raise OSError(f"nm cannot read {path}: {runs[0].stderr.strip()[:300]}")
    rows = []
    for raw, readable in zip(runs[0].stdout.splitlines(), runs[1].stdout.splitlines()):
        parts = raw.split(maxsplit=2)
        nice = readable.split(maxsplit=2)
        if len(parts) == 3 and len(nice) == 3:
            rows.append((parts[1], parts[2], nice[2]))
    return rows


def _chapter_functions(chapter):
    """The functions a submission may define: the stand-ins the checker defines, which are
    exactly the chapter header's functions (grader/remote/<file>.cpp)."""
    try:
        rows = defined_symbols(chapter.checker)
    except (OSError, subprocess.TimeoutExpired) as error:
        raise KitError(f"cannot list the functions of {chapter.id}: {error}") from None
    functions = {mangled: readable for kind, mangled, readable in rows
                 if kind == "T" and readable.startswith(chapter.namespace + "::")}
    if not functions:
        raise KitError(f"the checker of {chapter.id} defines no function of {chapter.namespace}: "
                       f"see grader/remote/{chapter.source}")
    return functions


def exposed_secrets(kit):
    """The secret folders (solutions, hidden tests, the kit's build) a user other than the
    grader's could read: without bubblewrap only permissions keep them from student code."""
    def readable_by_others(path):
        path = pathlib.Path(path)
        if not path.exists():
            return False
        for folder in [*reversed(path.parents), path]:
            mode = folder.stat().st_mode
            if folder != path and not mode & 0o001:
                return False
        return bool(path.stat().st_mode & 0o004)
    candidates = [kit.source_dir / "solutions", kit.source_dir / "tests" / "hidden", kit.build_dir]
    return [str(p) for p in candidates if readable_by_others(p)]


def _relative_to(path, folder):
    """`path` relative to `folder`, or None when it is not inside (Path.is_relative_to, which
    Python 3.8 lacks)."""
    try:
        return pathlib.Path(path).relative_to(folder)
    except ValueError:
        return None


def snapshot(kit, root):
    """A copy of what compiling and linking a submission reads (headers, objects, libraries
    not under /usr), world-readable, under `root`; and the kit that points at it.

    The sandboxed compiler and linker then see this copy and nothing of the instructor's
    tree: no build folder (whose reference objects hold the solution), no test objects (the
    student's process links only the engine and the server loop), and no dependence on the
    tree's permissions. Without namespaces the sandbox runs as a fresh uid, which could
    not read a tree under a private home folder at all."""
    root = pathlib.Path(root) / "kit"
    include_dirs = []
    for index, folder in enumerate(kit.include_dirs):
        # At their place in the tree, so that a compiler error names engine/include/...
        target = root / (_relative_to(folder, kit.source_dir) or f"include{index}")
        shutil.copytree(folder, target, ignore=_not_headers)
        include_dirs.append(str(target))

    def copied(path, index):
        if path.startswith("/usr/"):
            return path
        target = root / "objects" / f"{index}-{os.path.basename(path)}"
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(path, target)
        return str(target)

    counter = itertools.count()
    libraries = [copied(p, next(counter)) for p in kit.link_libraries]
    chapters = [replace(c, server_objects=[copied(p, next(counter)) for p in c.server_objects]) for c in kit.chapters]
    for folder, dirs, files in os.walk(root):
        os.chmod(folder, 0o755)
        for name in files:
            os.chmod(os.path.join(folder, name), 0o644)
    os.chmod(root.parent, 0o711)  # reachable, not listable: it also holds the submissions' folders
    return replace(kit, files_dir=root, include_dirs=include_dirs, link_libraries=libraries, chapters=chapters)


def _not_headers(folder, names):
    return [n for n in names if not os.path.isdir(os.path.join(folder, n)) and not n.endswith((".hpp", ".h"))]


def _check_chapter_list(kit):
    listed = kit.source_dir / "chapters" / "CHAPTERS"
    if not listed.is_file():
        return
    ids = workbook_files.chapters(kit.source_dir)
    in_kit = [c.id for c in kit.chapters]
    if ids != in_kit:
        kit.warnings.append(f"chapters/CHAPTERS lists {ids} but the kit was built for {in_kit}: rebuild the kit")


def _list_cases(kit, chapter):
    try:
        run = subprocess.run([str(chapter.checker), f"[{chapter.id}]", "--list-tests", "-r", "xml"],
                             capture_output=True, timeout=60, stdin=subprocess.DEVNULL)
        root = ElementTree.fromstring(run.stdout)
    except (OSError, subprocess.TimeoutExpired, ElementTree.ParseError) as error:
        raise KitError(f"cannot list the test cases of {chapter.id} from {chapter.checker}: {error}") from None
    cases = []
    hidden_dir = "/tests/hidden/"
    for order, node in enumerate(root.iter("TestCase")):
        name = node.findtext("Name", "")
        tags = catch_xml.parse_tags(node.findtext("Tags", ""))
        source = node.findtext("SourceInfo/File", "")
        case = TestCase(name, tags, hidden_dir in source.replace("\\", "/"), order)
        if case.step[0] == 0:
            kit.warnings.append(f"{chapter.id}: test case '{name}' has no [step:N:name] tag")
        if not any(t.startswith("points:") for t in tags):
            kit.warnings.append(f"{chapter.id}: test case '{name}' has no [points:P] tag and counts 0 points")
        cases.append(case)
    if not cases:
        raise KitError(f"chapter {chapter.id} has no test cases tagged [{chapter.id}]")
    return cases
