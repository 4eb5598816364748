#!/usr/bin/env python3
"""Keeps `./workbook bench speed` from rotting without timing anything: runs bench/speed.py
on a small gas (N = 100 and 300, 60 steps, one repetition; the peers at N = 100 alone, so that
the rows of runs not made are written too) with every engine workbook-gas was built with, and
checks the shape of what it writes and that each engine's gas keeps
what it should: every disc inside the box, the energy finite, and the workbook's energy
to rounding (the peers' iterative solvers are not held to that; their drift is reported)."""

import argparse
import csv
import math
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

SOURCE = Path(__file__).resolve().parents[2]
SIZES = [100, 300]
# The figure too where gnuplot is installed (./workbook setup installs it; the tests that need
# it elsewhere are left out without it).
FIGURE = [] if shutil.which("gnuplot") else ["--no-figure"]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--gas", required=True)
    args = parser.parse_args()
    failures = []
    with tempfile.TemporaryDirectory() as out:
        out = Path(out)
        result = subprocess.run([sys.executable, str(SOURCE / "bench" / "speed.py"), "--gas", args.gas, "--out", str(out),
                                 "--sizes", ",".join(map(str, SIZES)), "--repeat", "1", "--steps", "60", *FIGURE,
                                 # the peers only at the smaller N: the rows of runs not made are written too
                                 "--peers-up-to", str(SIZES[0])],
                                capture_output=True, text=True, timeout=120)
        if result.returncode != 0:
            sys.exit(f"bench/speed.py failed:\n{result.stderr}")
        with open(out / "speed.csv", newline="") as f:
            rows = list(csv.DictReader(f))
        engines = sorted({r["engine"] for r in rows})
        print(f"engines built: {', '.join(engines)}")
        if "workbook" not in engines:
            failures.append("the workbook's own engine is missing from speed.csv")
        expected = ["engine", "n", "steps", "repeats", "ms_per_step", "ms_per_step_median", "ms_per_step_max",
                    "bytes_per_body", "energy_drift", "escaped"]
        if list(rows[0].keys()) != expected:
            failures.append(f"speed.csv columns {list(rows[0].keys())}, expected {expected}")
        if len(rows) != len(engines) * len(SIZES):
            failures.append(f"{len(rows)} rows, expected one per engine and N ({len(engines)} x {len(SIZES)})")
        for r in rows:
            where = f"{r['engine']} at N = {r['n']}"
            if r["engine"] != "workbook" and int(r["n"]) > SIZES[0]:
                if r["repeats"] != "0" or r["ms_per_step"] != "nan":
                    failures.append(f"{where}: above --peers-up-to, expected a row of a run not made, got {r}")
                continue
            if r["repeats"] != "1" or r["steps"] != "60":
                failures.append(f"{where}: ran {r['repeats']} times {r['steps']} steps, expected once, 60 steps")
                continue
            ms, drift = float(r["ms_per_step"]), float(r["energy_drift"])
            if not (math.isfinite(ms) and ms > 0):
                failures.append(f"{where}: time per step {r['ms_per_step']}, expected a positive number")
            # The headline is the fastest run; the median and the slowest are never below it.
            if not ms <= float(r["ms_per_step_median"]) <= float(r["ms_per_step_max"]):
                failures.append(f"{where}: fastest {ms}, median {r['ms_per_step_median']}, slowest {r['ms_per_step_max']} out of order")
            if not math.isfinite(drift):
                failures.append(f"{where}: energy drift {r['energy_drift']} is not finite")
            if r["escaped"] != "0":
                failures.append(f"{where}: {r['escaped']} discs left the box through its walls")
            if r["engine"] == "workbook" and drift > 1e-12:
                failures.append(f"{where}: energy drift {drift:.3e} over 60 elastic steps, expected rounding (<= 1e-12)")
        table = (out / "speed.md").read_text()
        svg = (out / "speed.svg").read_text() if (out / "speed.svg").is_file() else ""
        if not FIGURE and "time per step / ms" not in svg:
            failures.append("speed.svg is missing or has no labelled time axis")
        if "no result" in svg:
            failures.append("speed.svg says a run has no result, but runs left out by --peers-up-to were not made at all")
        if len(engines) > 1 and "not run" not in table:
            failures.append("speed.md does not say which peers were not run at the larger N")
        page = (out / "performance.md").read_text()
        # --rewrite writes the same table again from the CSV and the table's first line.
        rewrite = subprocess.run([sys.executable, str(SOURCE / "bench" / "speed.py"), "--gas", args.gas, "--out", str(out),
                                  "--peers-up-to", str(SIZES[0]), "--rewrite", *FIGURE],
                                 capture_output=True, text=True, timeout=120)
        if rewrite.returncode != 0 or (out / "speed.md").read_text() != table:
            failures.append(f"--rewrite did not write the same table again:\n{rewrite.stderr[-2000:]}")
        for needle, text, name in [("| N | steps |", table, "speed.md"), ("growth with N", table, "speed.md"),
                                   ("the fastest of 1 runs", table, "speed.md"),
                                   ("{#performance}", page, "performance.md"), ("Measured ", page, "performance.md")]:
            if needle not in text:
                failures.append(f"{name} lacks '{needle}'")
    for failure in failures:
        print("FAIL:", failure)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
