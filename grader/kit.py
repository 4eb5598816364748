"""The grader kit: what the instructor's build left in <build>/grader/kit.json, and the
test cases of each chapter, listed once from a trusted binary (the untouched skeleton
linked with the public and hidden tests)."""
from dataclasses import dataclass, field, replace
import itertools
import json
import os
import pathlib
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ElementTree

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1] / "tools"))
import catch_xml  # noqa: E402
import workbook_files  # noqa: E402


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
    lister: pathlib.Path
    test_objects: list
    cases: list = field(default_factory=list)

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
    chapters = [Chapter(number, entry["id"], entry["source"], pathlib.Path(entry["skeleton"]),
                        pathlib.Path(entry["lister"]), entry["test_objects"])
                for number, entry in enumerate(data["chapters"], start=1)]
    kit = Kit(path, pathlib.Path(data["source_dir"]), pathlib.Path(data["build_dir"]), data["compiler"],
              data["compile_flags"], data["link_flags"], data["include_dirs"], data["link_libraries"],
              bool(data.get("sanitize")), int(data["default_seed"]), chapters)
    missing = [str(p) for p in [kit.compiler, *kit.link_libraries, *kit.include_dirs]
               + [p for c in chapters for p in (c.lister, c.skeleton, *c.test_objects)] if not pathlib.Path(p).exists()]
    if missing:
        raise KitError(f"the grader kit in {path.parent} is incomplete (missing {missing[0]}"
                       f"{f' and {len(missing) - 1} more' if len(missing) > 1 else ''}): rebuild it")
    _check_chapter_list(kit)
    for chapter in chapters:
        chapter.cases = _list_cases(kit, chapter)
    return kit


def snapshot(kit, root):
    """A copy of what compiling and linking a submission reads (headers, objects, libraries
    not under /usr), world-readable, under `root`; and the kit that points at it.

    The sandboxed compiler and linker then see this copy and nothing of the instructor's
    tree: no build folder (whose reference objects hold the solution), and no dependence on
    the tree's permissions. Without namespaces the sandbox runs as a fresh uid, which could
    not read a tree under a private home folder at all."""
    root = pathlib.Path(root) / "kit"
    include_dirs = []
    for index, folder in enumerate(kit.include_dirs):
        # At their place in the tree, so that a compiler error names engine/include/...
        inside = pathlib.Path(folder).is_relative_to(kit.source_dir)
        target = root / (pathlib.Path(folder).relative_to(kit.source_dir) if inside else f"include{index}")
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
    chapters = [replace(c, test_objects=[copied(p, next(counter)) for p in c.test_objects]) for c in kit.chapters]
    for folder, dirs, files in os.walk(root):
        os.chmod(folder, 0o755)
        for name in files:
            os.chmod(os.path.join(folder, name), 0o644)
    os.chmod(root.parent, 0o755)
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
        run = subprocess.run([str(chapter.lister), f"[{chapter.id}]", "--list-tests", "-r", "xml"],
                             capture_output=True, timeout=60, stdin=subprocess.DEVNULL)
        root = ElementTree.fromstring(run.stdout)
    except (OSError, subprocess.TimeoutExpired, ElementTree.ParseError) as error:
        raise KitError(f"cannot list the test cases of {chapter.id} from {chapter.lister}: {error}") from None
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
