#!/usr/bin/env python3
"""Writes the student edition of the workbook: `./workbook pack student OUT`.

The edition is the instructor's tree as git tracks it, less everything that would give
answers away or is of no use to a student: the reference solutions, the hidden tests, the
grader and its mutants and hostile submissions, the checks that need the reference, and
CI. Its README is the student README in grader/student-README.md.

Folders are dropped whole, by role, so a new chapter's solution or hidden test cannot slip
through. The pack test (tests/pack) then proves it by content, not by name."""
import argparse
import pathlib
import shutil
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parents[1]

# Paths (relative to the root, '/'-separated) left out of the student edition, with why.
EXCLUDED = {
    "solutions": "the reference responders",
    "tests/hidden": "hidden tests",
    "tests/mutants": "wrong implementations, each one a near-solution",
    "tests/hostile": "the grader's hostile submissions",
    "tests/grader": "the grader's own tests",
    "tests/pack": "this test of the pack, which reads the solutions",
    "tests/chapters": "checks of the texts and figures against the reference",
    "tests/check": "the test of ./workbook check's runner, with a deliberately broken responder",
    "tests/site": "the browser test of the instructor's site",
    "grader": "the instructor's grader",
    ".ci": "the workbook's own CI",
    "docs/adding-a-chapter.md": "the authors' guide, which quotes the grader's wire and describes the solutions",
}


def is_excluded(relative):
    return any(relative == prefix or relative.startswith(prefix + "/") for prefix in EXCLUDED)


def tracked_files(root):
    """Every file git tracks, plus new files it does not ignore: an instructor's uncommitted
    hidden test must not silently go missing from a pack. The new ones are named on stderr,
    so that a stray folder (build-asan/, notes) is noticed before the pack is handed out."""
    def listing(*options):
        run = subprocess.run(["git", "-C", str(root), "ls-files", "-z", *options], capture_output=True, check=True)
        return {p for p in run.stdout.decode().split("\0") if p}

    untracked = listing("--others", "--exclude-standard")
    if untracked:
        shown = ", ".join(sorted(untracked)[:8]) + (f" and {len(untracked) - 8} more" if len(untracked) > 8 else "")
        print(f"note: also packing {len(untracked)} file(s) git does not track yet: {shown}", file=sys.stderr)
    return sorted(listing("--cached") | untracked)


def write_pack(out, root=ROOT):
    out = pathlib.Path(out).resolve()
    if out.exists() and any(out.iterdir()):
        raise SystemExit(f"pack student: {out} exists and is not empty; choose a new folder")
    out.mkdir(parents=True, exist_ok=True)
    kept = 0
    for relative in tracked_files(root):
        source = root / relative
        if is_excluded(relative) or not source.is_file():
            continue
        target = out / relative
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(source, target)
        kept += 1
    shutil.copy2(root / "grader" / "student-README.md", out / "README.md")
    return kept


def main():
    parser = argparse.ArgumentParser(description="Write the student edition of the workbook into a new folder.")
    parser.add_argument("out", help="folder to create (must be new or empty)")
    args = parser.parse_args()
    kept = write_pack(args.out)
    print(f"Student edition written to {pathlib.Path(args.out).resolve()} ({kept} files).")
    print("Left out: " + "; ".join(f"{path}{'' if '.' in pathlib.PurePath(path).name[1:] else '/'} ({why})"
                                  for path, why in EXCLUDED.items()))
    print("Hand the folder (or an archive of it) to students; they start with its README.md.")
    return 0


if __name__ == "__main__":
    sys.exit(main())
