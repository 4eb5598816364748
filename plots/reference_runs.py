#!/usr/bin/env python3
"""The reference's time series of every chapter scene, shipped with the workbook.

The student edition has no reference solutions, but the reference's energy and momentum over
time are no secret: the chapter pages describe them. They live in
chapters/<chapter>/reference-runs/<scene>.csv (a swept scene: <scene>.fraction-<f>.csv, one per
fraction), the CSV `workbook-sim run --csv` writes, rounded to 10 significant digits, so that
plots/figures.py draws a student's curves over the reference's in the student edition too, as
it does in the full edition with the reference simulator. Beside them, <scene>.trajectory.csv
and <scene>.trajectory.contacts.csv (`--trajectory` at the stride the motion pictures use,
8 significant digits) let plots/strobe.py and plots/animate.py draw the student's bodies over
the reference's. A scene of a box turning freely (responder "none", plots/spin.py) has none:
no student code acts on it.

    reference_runs.py write --sim build/dev/tools/workbook-sim     after a change to a scene or the engine
    reference_runs.py check --sim build/dev/tools/workbook-sim     the shipped runs are the reference's (ctest)
    reference_runs.py check --sanitized --sim build/sanitize/tools/workbook-sim    heavy scenes' first half second
"""
import argparse
import csv
import io
import json
import math
import subprocess
import sys
import tempfile
from pathlib import Path

from plots import motion
from plots import spin

SOURCE = Path(__file__).resolve().parent.parent
DIGITS = 10
TRAJECTORY_DIGITS = 8  # a hundredth of a millimetre in a scene of metres: finer than any picture
# A shipped value agrees with a fresh run when it differs by less than this, relative to the
# larger of the value and its column's largest magnitude: the 10 digits kept, with room for
# another compiler's last bits.
AGREEMENT = 1e-8


def chapters():
    text = (SOURCE / "chapters" / "CHAPTERS").read_text()
    return [line.split("#")[0].strip() for line in text.splitlines() if line.split("#")[0].strip()]


def folder(chapter):
    return SOURCE / "chapters" / chapter / "reference-runs"


def run_path(scene, fraction=None):
    """Where the reference's run of a scene (of one fraction of its sweep) is shipped."""
    chapter = scene.resolve().parent.parent.name
    suffix = "" if fraction is None else f".fraction-{fraction:g}"
    return folder(chapter) / f"{scene.stem}{suffix}.csv"


def trajectory_path(scene):
    """Where the reference's trajectory of a scene is shipped (its contacts: motion.contacts_path)."""
    chapter = scene.resolve().parent.parent.name
    return folder(chapter) / f"{scene.stem}.trajectory.csv"


# The motion of a scene is shipped when it is not heavy (motion.is_heavy): the chapters' small
# scenes, not the piles and the minute-long stacks of chapter 5, whose motion would weigh tens
# of megabytes. A student's strobe picture of those has no reference under it and keeps the
# bodies' own colours.
def has_trajectory(scene):
    """True for a scene whose motion the student's code decides (not a free spin) and that is
    small enough to ship."""
    spec = json.loads(scene.read_text())
    return not motion.is_heavy(spec) and spin.watched_body(spec) is None


def rounded(path, digits):
    """The rows of a CSV with every number rounded to `digits` significant digits (names kept)."""
    def one(value):
        try:
            return f"{float(value):.{digits}g}"
        except ValueError:
            return value
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    return [rows[0]] + [[one(x) for x in row] for row in rows[1:]]


def simulate_motion(sim, scene, scratch):
    """(trajectory rows, contacts rows) of the scene at the motion pictures' stride."""
    stride = motion.stride_for(motion.Scene(scene).spec)
    trajectory, contacts = motion.simulate(sim, scene, Path(scratch, "motion.trajectory.csv"), stride)
    return rounded(trajectory, TRAJECTORY_DIGITS), rounded(contacts, TRAJECTORY_DIGITS)


def shipped(scene):
    """True when every run of the scene is shipped (a free spin has none to ship)."""
    runs = runs_of(scene)
    return bool(runs) and all(run_path(scene, fraction).is_file() for fraction, _ in runs)


def runs_of(scene):
    """[(fraction or None, scene description to run)] of one scene file; [] for a free spin."""
    description = json.loads(scene.read_text())
    if spin.watched_body(description) is not None:
        return []
    if "sweep" not in description:
        return [(None, description)]
    variants = []
    for fraction in description["sweep"]["fraction"]:
        variant = {k: v for k, v in description.items() if k != "sweep"}
        variant["position_correction"] = dict(description.get("position_correction", {}), fraction=fraction)
        variants.append((fraction, variant))
    return variants


def simulate(sim, description, scratch):
    """The rows of `workbook-sim run --csv` for one scene description, rounded to DIGITS."""
    scene = Path(scratch, "scene.json")
    out = Path(scratch, "run.csv")
    scene.write_text(json.dumps(description))
    result = subprocess.run([str(sim), "run", str(scene), "--csv", str(out), "--quiet"], capture_output=True, text=True)
    if result.returncode != 0:
        raise RuntimeError(f"{sim} failed on {description.get('title', 'a scene')}:\n{result.stderr.strip()}")
    with open(out, newline="") as f:
        rows = list(csv.reader(f))
    return [rows[0]] + [[f"{float(x):.{DIGITS}g}" for x in row] for row in rows[1:]]


def text_of(rows):
    buffer = io.StringIO()
    csv.writer(buffer, lineterminator="\n").writerows(rows)
    return buffer.getvalue()


def scenes():
    return [s for chapter in chapters() for s in sorted((SOURCE / "chapters" / chapter / "scenes").glob("*.json"))]


def write(sim):
    with tempfile.TemporaryDirectory() as scratch:
        for chapter in chapters():
            target = folder(chapter)
            target.mkdir(exist_ok=True)
            wanted = set()
            for scene in sorted((SOURCE / "chapters" / chapter / "scenes").glob("*.json")):
                for fraction, description in runs_of(scene):
                    path = run_path(scene, fraction)
                    path.write_text(text_of(simulate(sim, description, scratch)))
                    wanted.add(path.name)
                    print(f"reference-runs: {path.relative_to(SOURCE)}")
                if has_trajectory(scene):
                    trajectory, contacts = simulate_motion(sim, scene, scratch)
                    for path, rows in ((trajectory_path(scene), trajectory),
                                       (motion.contacts_path(trajectory_path(scene)), contacts)):
                        path.write_text(text_of(rows))
                        wanted.add(path.name)
                        print(f"reference-runs: {path.relative_to(SOURCE)}")
            for stale in target.glob("*.csv"):
                if stale.name not in wanted:
                    stale.unlink()
                    print(f"reference-runs: removed {stale.relative_to(SOURCE)} (no such scene)")


def number(text):
    try:
        return float(text)
    except ValueError:
        return None


def disagreement(shipped, fresh, agreement=AGREEMENT):
    """None when two tables agree, else what differs first."""
    if shipped[0] != fresh[0]:
        return f"columns {shipped[0]} instead of {fresh[0]}"
    if len(shipped) != len(fresh):
        return f"{len(shipped) - 1} samples instead of {len(fresh) - 1}"
    values = [[number(x) for x in row] for row in fresh[1:]]
    scale = [max((abs(row[i]) for row in values if row[i] is not None and math.isfinite(row[i])), default=0.0)
             for i in range(len(fresh[0]))]
    for n, (a_row, b_row, text_row) in enumerate(zip(shipped[1:], values, fresh[1:]), 1):
        for i, (a, b) in enumerate(zip(a_row, b_row)):
            if b is None:
                if a != text_row[i]:
                    return f"sample {n}, {fresh[0][i]}: {a} shipped, {text_row[i]} now"
            elif number(a) is None or abs(number(a) - b) > agreement * max(abs(b), scale[i]) + 1e-300:
                return f"sample {n}, {fresh[0][i]}: {a} shipped, {b!r} now"
    return None


def read_rows(path):
    with open(path, newline="") as f:
        return list(csv.reader(f))


def check(sim, sanitized=False):
    """The shipped runs against fresh ones. `sanitized` (the sanitizer build's run): a heavy
    scene runs its first motion.SANITIZED_SECONDS only, compared with as many shipped samples;
    the dev build's run compares every scene whole."""
    problems = []
    with tempfile.TemporaryDirectory() as scratch:
        for scene in scenes():
            for fraction, description in runs_of(scene):
                path = run_path(scene, fraction)
                if not path.is_file():
                    problems.append(f"{path.relative_to(SOURCE)} is missing")
                    continue
                shipped_rows = read_rows(path)
                if sanitized and motion.is_heavy(description):
                    fresh = simulate(sim, motion.for_sanitizers(description), scratch)
                    shipped_rows = shipped_rows[:len(fresh)]
                else:
                    fresh = simulate(sim, description, scratch)
                problem = disagreement(shipped_rows, fresh)
                if problem:
                    problems.append(f"{path.relative_to(SOURCE)} is not the reference's run: {problem}")
            if has_trajectory(scene):
                fresh = simulate_motion(sim, scene, scratch)
                for path, rows in zip((trajectory_path(scene), motion.contacts_path(trajectory_path(scene))), fresh):
                    if not path.is_file():
                        problems.append(f"{path.relative_to(SOURCE)} is missing")
                        continue
                    problem = disagreement(read_rows(path), rows, agreement=1e-6)
                    if problem:
                        problems.append(f"{path.relative_to(SOURCE)} is not the reference's motion: {problem}")
    for problem in problems:
        print("reference-runs:", problem)
    if problems:
        print("Write them again with: python3 -m plots.reference_runs write --sim build/dev/tools/workbook-sim")
    return 1 if problems else 0


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("action", choices=["write", "check"])
    parser.add_argument("--sim", type=Path, required=True, help="the reference simulator (workbook-sim)")
    parser.add_argument("--sanitized", action="store_true",
                        help="check: the simulator is the sanitizer build's; heavy scenes are compared over their first "
                             f"{motion.SANITIZED_SECONDS:g} s only")
    args = parser.parse_args()
    if args.action == "write":
        write(args.sim)
        return 0
    return check(args.sim, args.sanitized)


if __name__ == "__main__":
    sys.exit(main())
