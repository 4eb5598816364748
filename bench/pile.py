#!/usr/bin/env python3
"""The pile bench: runs bench/pile.hpp's pile (N frictionless discs dropped into a box, 10 s)
in the workbook for each N and writes a CSV and a Markdown table of time per step, deepest
overlap, kinetic energy, mean height and discs outside the box.

Usage: python3 -m bench.pile --binary build/dev/bench/workbook-pile [--counts 400 1000 2000] [--out bench/results]

The workbook alone for now: the peers (Chipmunk, Box2D, Bullet, as bench/speed.py runs them
for the gas) are still to be added to workbook-pile.
"""
import argparse
import csv
import pathlib
import subprocess
import sys

FIELDS = ["engine", "N", "ms_per_step", "deepest_m", "kinetic_J", "mean_height_m", "outside"]


def run(binary: str, count: int, seconds: float) -> dict:
    out = subprocess.run([binary, str(count), str(seconds)], check=True, capture_output=True, text=True).stdout
    return dict(zip(FIELDS, out.strip().split(",")))


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--binary", default="build/dev/bench/workbook-pile", help="the workbook-pile executable")
    parser.add_argument("--counts", type=int, nargs="+", default=[400, 1000, 2000, 5000, 10000], help="numbers of discs")
    parser.add_argument("--seconds", type=float, default=10.0, help="simulated time, s")
    parser.add_argument("--out", default="bench/results", help="folder for pile.csv and pile.md")
    args = parser.parse_args()
    rows = []
    for count in args.counts:
        row = run(args.binary, count, args.seconds)
        print(",".join(row[f] for f in FIELDS), flush=True)
        rows.append(row)
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    with open(out / "pile.csv", "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=FIELDS)
        writer.writeheader()
        writer.writerows(rows)
    lines = ["| engine | N | ms/step | deepest overlap at the end, m | kinetic energy, J | mean height, m | outside |",
             "|---|---|---|---|---|---|---|"]
    lines += ["| " + " | ".join(r[f] for f in FIELDS) + " |" for r in rows]
    (out / "pile.md").write_text("\n".join(lines) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
