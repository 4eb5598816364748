#!/usr/bin/env python3
"""The recorded run of `./workbook bench speed` (bench/results/, written with --record) meets
its speed goals, and its page says what its table says. Nothing is timed here: this reads
the numbers the bench measured on the machine and date the page names.

Goals: at N = 1,000 at most one third of Chipmunk's time per step in the same run; cost growth
with N at most N^1.1 from 1,000 to 100,000, and N = 100,000 ran; at most 1 KB per body at
N = 100,000; kinetic energy drift of the gas at rounding level (<= 1e-12 relative) at every N."""

import csv
import math
import sys
from pathlib import Path

RESULTS = Path(__file__).resolve().parents[2] / "bench" / "results"


def main():
    failures = []
    with open(RESULTS / "speed.csv", newline="") as f:
        rows = {(r["engine"], int(r["n"])): r for r in csv.DictReader(f)}
    ms = lambda engine, n: float(rows[(engine, n)]["ms_per_step"])
    workbook = sorted(n for (e, n), r in rows.items() if e == "workbook" and r["repeats"] not in ("0", ""))
    if 1000 not in workbook or 100000 not in workbook:
        sys.exit(f"the recorded run lacks the workbook at N = 1,000 or 100,000 (has {workbook})")
    ratio = ms("workbook", 1000) / ms("chipmunk", 1000)
    growth = math.log(ms("workbook", 100000) / ms("workbook", 1000)) / math.log(100)
    memory = float(rows[("workbook", 100000)]["bytes_per_body"])
    print(f"N = 1,000: {ms('workbook', 1000):.4g} ms/step, {ratio:.3f} of Chipmunk's {ms('chipmunk', 1000):.4g}")
    print(f"growth from 1,000 to 100,000: N^{growth:.3f}; memory at 100,000: {memory:.0f} B/body")
    if not ratio <= 1 / 3:
        failures.append(f"N = 1,000 takes {ratio:.3f} of Chipmunk's time, goal at most 1/3")
    if not growth <= 1.1:
        failures.append(f"cost grows as N^{growth:.3f}, goal at most N^1.1")
    if not memory <= 1024:
        failures.append(f"{memory:.0f} bytes per body at N = 100,000, goal at most 1 KB")
    for n in workbook:
        drift = float(rows[("workbook", n)]["energy_drift"])
        if not drift <= 1e-12:
            failures.append(f"energy drift {drift:.3e} at N = {n:,}, goal at most 1e-12")
        if rows[("workbook", n)]["escaped"] != "0":
            failures.append(f"{rows[('workbook', n)]['escaped']} discs left the box at N = {n:,}")
    # The page shows the table of this run, with its machine and date.
    page = (RESULTS / "performance.md").read_text()
    table = (RESULTS / "speed.md").read_text()
    if table not in page:
        failures.append("performance.md does not hold speed.md's table")
    if f"N^{growth:.2f}" not in table:
        failures.append(f"speed.md's growth row does not say N^{growth:.2f}")
    for needle in ["Measured ", "load average", "logical cores", "the fastest of"]:
        if needle not in table:
            failures.append(f"speed.md lacks '{needle}'")
    for failure in failures:
        print("FAIL:", failure)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
