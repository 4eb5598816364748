#!/usr/bin/env python3
"""Keeps `./workbook bench pile` from rotting without timing anything: runs bench/pile.py --quick
(16 and 100 discs, 3 s) with every engine workbook-pile was built with, and checks what it writes:

- every engine's pile of 16 discs (and the workbook's soft step's, run on its own with
  --engines workbook-soft) ends at rest inside the box: in a box exactly four diameters wide
  the 16 lie lowest as a square stack of four rows, each a diameter above the last, mean
  height 0.2 m; every engine lands within 1 cm of it (each lets contacts overlap by its own slop,
  2 mm to 5 mm, and Box2D's edges carry a 1 cm skin), with a kinetic energy of at most 1e-6 J per
  disc, no overlap deeper than a fifth of a radius and no disc outside;
- every number of the table is produced (finite) and pile.md prints each row and each goal,
  its verdict the one the CSV's numbers give;
- a run over its budget is stopped and reads "skipped: over budget", and so does the larger N.
"""

import argparse
import csv
import math
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

SOURCE = Path(__file__).resolve().parents[2]
FIGURE = [] if shutil.which("gnuplot") else ["--no-figure"]
TITLES = {"workbook": "workbook", "workbook-soft": "workbook, soft step", "chipmunk": "Chipmunk 7", "box2d": "Box2D 2.4.1",
          "bullet": "Bullet 3.24"}


def run_bench(binary, out, *options):
    result = subprocess.run([sys.executable, "-m", "bench.pile", "--binary", binary, "--out", str(out), *options],
                            cwd=SOURCE, capture_output=True, text=True, timeout=120)
    if result.returncode != 0:
        sys.exit(f"bench/pile.py {' '.join(options)} failed:\n{result.stderr}")
    with open(out / "pile.csv", newline="") as f:
        return list(csv.DictReader(f)), (out / "pile.md").read_text()


def check_rows(rows, table, failures):
    """Each row's numbers produced, its 16 discs at rest in the square stack, its row in the table."""
    for r in rows:
        where = f"{r['engine']} at N = {r['n']}"
        if r["status"] != "ok":
            failures.append(f"{where}: status {r['status']!r}, expected ok")
            continue
        n = int(r["n"])
        ms, deepest, kinetic, height = (float(r[k]) for k in ["ms_per_step", "deepest_m", "kinetic_J", "mean_height_m"])
        if not all(math.isfinite(x) for x in (ms, deepest, kinetic, height)) or ms <= 0:
            failures.append(f"{where}: numbers not all produced: {r}")
            continue
        if r["outside"] != "0":
            failures.append(f"{where}: {r['outside']} discs outside the box")
        if n == 16:
            if not kinetic <= 1e-6 * n:
                failures.append(f"{where}: kinetic energy {kinetic:.3g} J after 3 s, expected at rest (<= {1e-6 * n:g} J)")
            if not abs(height - 0.2) <= 0.01:
                failures.append(f"{where}: mean height {height:.4g} m, expected the square stack's 0.2 m within 1 cm")
            if not deepest <= 0.01:
                failures.append(f"{where}: deepest overlap {deepest * 1e3:.3g} mm, expected at most 10 mm")
        title = TITLES[r["engine"]]
        if f"| {title} | {n:,} | " not in table:
            failures.append(f"pile.md has no row for {title} at N = {n:,}")


def check_goals(mine, table, whose, failures):
    """Each goal over every N is printed in `table` as met or not met as the rows' numbers say."""
    expected = {
        "deepest overlap at the end <= 5 mm at every N": all(float(r["deepest_m"]) <= 0.005 for r in mine),
        "kinetic energy at the end <= 1e-6 J per disc at every N":
            all(float(r["kinetic_J"]) <= 1e-6 * int(r["n"]) for r in mine),
        "no disc outside the box at any N": all(r["outside"] == "0" for r in mine),
    }
    for goal, met in expected.items():
        if f"| {goal} | {'met' if met else 'not met'} |" not in table:
            failures.append(f"pile.md does not say {whose}goal '{goal}' is {'met' if met else 'not met'}")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--binary", required=True, help="the workbook-pile executable")
    args = parser.parse_args()
    failures = []
    with tempfile.TemporaryDirectory() as out:
        out = Path(out)
        rows, table = run_bench(args.binary, out / "quick", "--quick", *FIGURE)
        engines = sorted({r["engine"] for r in rows})
        print(f"engines built: {', '.join(engines)}")
        if "workbook" not in engines:
            failures.append("the workbook is missing from pile.csv")
        if len(rows) != 2 * len(engines):
            failures.append(f"{len(rows)} rows, expected one per engine and N (2 x {len(engines)})")
        check_rows(rows, table, failures)
        # The goals' verdicts, from the CSV's numbers.
        check_goals([r for r in rows if r["engine"] == "workbook" and r["status"] == "ok"], table, "", failures)
        for goal in ["time per step <= Chipmunk 7's at N = 2,000 | not measured", "time per step growing at most as N^1.2 |"]:
            if goal not in table:
                failures.append(f"pile.md lacks '{goal}'")
        if not FIGURE:
            svg = (out / "quick" / "pile.svg").read_text() if (out / "quick" / "pile.svg").is_file() else ""
            for label in ["time per step / ms", "deepest overlap at the end / mm", "goal: at most 5 mm"]:
                if label not in svg:
                    failures.append(f"pile.svg lacks '{label}'")

        # The workbook's soft step, an engine the bench runs when asked: the same checks.
        rows, table = run_bench(args.binary, out / "soft", "--quick", "--engines", "workbook-soft", "--no-figure")
        if sorted({r["engine"] for r in rows}) != ["workbook-soft"] or len(rows) != 2:
            failures.append(f"--engines workbook-soft gave rows {[(r['engine'], r['n']) for r in rows]}")
        check_rows(rows, table, failures)
        # Its goals, in a table of their own after the defaults' (which ran nothing here).
        heading = "| goal for the workbook's soft step | | measured |"
        soft_goals = table.split(heading, 1)[1] if heading in table else ""
        if not soft_goals:
            failures.append(f"pile.md lacks the soft step's goals ('{heading}')")
        if soft_goals:
            check_goals(rows, soft_goals, "the soft step's ", failures)

        # A budget (1 microsecond) far below what the steps take: the run is stopped, and the larger N not started.
        rows, table = run_bench(args.binary, out / "budget", "--engines", "workbook", "--sizes", "100,400",
                                "--seconds", "3", "--budget", "1e-6", "--no-figure")
        if [r["status"] for r in rows] != ["skipped: over budget"] * 2:
            failures.append(f"with a budget of 1 microsecond, statuses {[r['status'] for r in rows]}, expected both over budget")
        if table.count("| skipped: over budget |") != 2:
            failures.append("pile.md does not say 'skipped: over budget' for both N")
    for failure in failures:
        print("FAIL:", failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
