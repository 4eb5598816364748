#!/usr/bin/env python3
"""Writes the Gradescope autograder zip.

    python3 -m grader.pack_gradescope OUT.zip [--hidden-visibility V] [--seed N] [--time-limit S]

Layout: setup.sh and run_autograder at the root, the instructor's tree (minus .git and
build folders) under workbook/. Gradescope unpacks it to /autograder/source, runs setup.sh
from there once to build the grader kit, copies run_autograder to /autograder/run_autograder
and runs it from /autograder per submission; it grades /autograder/submission into
/autograder/results/results.json.

For tests, run_autograder honours AUTOGRADER_ROOT (instead of /autograder) and
WORKBOOK_KIT_BUILD_DIR (an already built kit, instead of the one setup.sh builds)."""
import argparse
import os
import pathlib
import subprocess
import sys
import zipfile

from grader import report
from grader.pack_student import tracked_files
from tools import workbook_files

HERE = pathlib.Path(__file__).resolve().parent

SKIP_DIRS = {".git", "build", "out", "grading-results", "__pycache__", ".cache", ".idea", ".vscode"}
APT_PACKAGES = ("g++ cmake ninja-build python3 binutils bubblewrap util-linux libfmt-dev nlohmann-json3-dev libcli11-dev")

SETUP_SH = r"""#!/usr/bin/env bash
# Gradescope runs this once, as root, from <root>/source (normally /autograder/source) on a
# fresh image: install what is missing, build the grader kit (engine, public and hidden test
# checkers) from the packed tree, and put the tree out of reach of student code.
# Needs Catch2 3: Debian 12 bookworm (from bookworm-backports) or Ubuntu 24.04 or newer.
set -euo pipefail
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
export DEBIAN_FRONTEND=noninteractive
PACKAGES=(@APT@)
missing=()
for package in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}\n' "$package" 2>/dev/null | grep -q '^install ok installed' || missing+=("$package")
done
catch2_version="$(dpkg-query -W -f='${Version}' catch2 2>/dev/null || true)"
if [ "${#missing[@]}" -gt 0 ] || [[ "$catch2_version" != 3.* ]]; then
  catch2_from=()
  if grep -qs '^VERSION_CODENAME=bookworm' /etc/os-release; then
    # bookworm's own Catch2 is 2.13. Add bookworm-backports only where no package source names
    # it yet: a second entry for the same suite makes apt warn on every call.
    if ! grep -rqs 'bookworm-backports' /etc/apt/sources.list /etc/apt/sources.list.d/; then
      echo 'deb http://deb.debian.org/debian bookworm-backports main' > /etc/apt/sources.list.d/workbook-bookworm-backports.list
    fi
    catch2_from=(-t bookworm-backports)
  fi
  apt-get update
  if [ "${#missing[@]}" -gt 0 ]; then apt-get install -y --no-install-recommends "${missing[@]}"; fi
  if [[ "$catch2_version" != 3.* ]]; then apt-get install -y --no-install-recommends "${catch2_from[@]}" catch2; fi
fi
BUILD="$HERE/workbook/build/grader"
cmake -S "$HERE/workbook" -B "$BUILD" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=g++ \
      -DWORKBOOK_WARNINGS_AS_ERRORS=OFF
cmake --build "$BUILD" --target grader_kit
test -f "$BUILD/grader/kit.json"
# Gradescope's containers cannot run bubblewrap, so student code runs as fresh unprivileged
# uids: the tree (solutions, hidden tests, the kit's sources and build) must be unreadable
# to them. The grader copies what a student's compile needs (public headers, the engine).
chmod -R go-rwx "$HERE"
echo "grader kit ready in $BUILD"
"""

RUN_AUTOGRADER = r"""#!/usr/bin/env bash
# Gradescope copies this script to <root>/run_autograder (normally /autograder/run_autograder)
# and runs it from <root>, once per submission; the kit stays where setup.sh built it, in
# <root>/source. It must always leave <root>/results/results.json behind.
set -uo pipefail
ROOT="${AUTOGRADER_ROOT:-/autograder}"
SOURCE="$ROOT/source"
BUILD="${WORKBOOK_KIT_BUILD_DIR:-$SOURCE/workbook/build/grader}"
RESULTS="$ROOT/results/results.json"
mkdir -p "$ROOT/results"
rm -f "$RESULTS"
WORK="$(mktemp -d)"
PYTHONPATH="$SOURCE/workbook" python3 -m grader.grade --build-dir "$BUILD" --out "$WORK" --results-json "$RESULTS" \
        --seed @SEED@ --time-limit @TIME@ --hidden-visibility @VISIBILITY@ "$ROOT/submission"
status=$?
if [ ! -s "$RESULTS" ]; then
  # The grader itself failed (e.g. the kit was not built): tell the student it is not their fault.
  printf '{"score": 0, "execution_time": 0, "output": "The autograder failed (status %s) before grading your submission. Please tell your instructor.", "tests": []}\n' "$status" > "$RESULTS"
fi
rm -rf "$WORK"
exit 0
"""


def tree_files(root, exclude):
    """The files git knows of (tracked, or new and not ignored), like the student pack; a tree
    that is not a git checkout (an unpacked release) is walked instead."""
    try:
        listed = [root / relative for relative in tracked_files(root)]
    except (OSError, subprocess.CalledProcessError):
        listed = None
    if listed is not None:
        yield from (p for p in listed if p.is_file() and not p.is_symlink() and p.resolve() != exclude)
        return
    for folder, dirs, files in os.walk(root):
        dirs[:] = sorted(d for d in dirs if d not in SKIP_DIRS
                         and not (pathlib.Path(folder, d) / "CMakeCache.txt").exists())
        for name in sorted(files):
            path = pathlib.Path(folder, name)
            if path.resolve() == exclude or path.is_symlink() or name.endswith(".pyc"):
                continue
            yield path


def _add_script(archive, name, text):
    info = zipfile.ZipInfo(name, date_time=(2026, 1, 1, 0, 0, 0))
    info.external_attr = 0o100755 << 16
    info.compress_type = zipfile.ZIP_DEFLATED
    archive.writestr(info, text)


def pack(out, source_dir, seed, time_limit, visibility):
    out = pathlib.Path(out).resolve()
    source_dir = pathlib.Path(source_dir).resolve()
    out.parent.mkdir(parents=True, exist_ok=True)
    run = (RUN_AUTOGRADER.replace("@SEED@", str(seed)).replace("@TIME@", f"{time_limit:g}")
           .replace("@VISIBILITY@", visibility))
    count = 0
    with zipfile.ZipFile(out, "w", zipfile.ZIP_DEFLATED) as archive:
        _add_script(archive, "setup.sh", SETUP_SH.replace("@APT@", APT_PACKAGES))
        _add_script(archive, "run_autograder", run)
        for path in tree_files(source_dir, out):
            rel = path.relative_to(source_dir).as_posix()
            archive.write(path, f"workbook/{rel}")
            count += 1
    return count


def main(argv=None):
    parser = argparse.ArgumentParser(description="Write the Gradescope autograder zip.")
    parser.add_argument("out", metavar="OUT.zip")
    parser.add_argument("--source-dir", default=str(HERE.parent), help="the instructor's tree (default: this one)")
    parser.add_argument("--seed", type=int, default=None)
    parser.add_argument("--time-limit", type=float, default=10.0)
    parser.add_argument("--hidden-visibility", choices=report.VISIBILITIES, default="after_published")
    args = parser.parse_args(argv)
    for needed in ("solutions", "tests/hidden", "grader/grade.py"):
        if not (pathlib.Path(args.source_dir) / needed).exists():
            print(f"pack: {args.source_dir} has no {needed}: pack the instructor's tree", file=sys.stderr)
            return 2
    seed = args.seed if args.seed is not None else workbook_files.random_seed(args.source_dir)
    count = pack(args.out, args.source_dir, seed, args.time_limit, args.hidden_visibility)
    print(f"Wrote {args.out}: setup.sh, run_autograder and {count} files of the workbook "
          f"(seed {seed}, hidden tests {args.hidden_visibility}).")
    return 0


if __name__ == "__main__":
    sys.exit(main())
