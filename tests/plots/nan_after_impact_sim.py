#!/usr/bin/env python3
"""A stand-in for workbook-sim-student whose responder returns NaN: it runs the real
simulator named by $WORKBOOK_REAL_SIM, then turns every value from the first contact on
into NaN, as a student's division by zero at impact would. Same command line as workbook-sim:
    nan_after_impact_sim.py run SCENE.json --csv OUT.csv --quiet"""
import csv
import os
import subprocess
import sys

args = sys.argv[1:]
out = args[args.index("--csv") + 1]
subprocess.run([os.environ["WORKBOOK_REAL_SIM"], *args], check=True)
with open(out, newline="") as f:
    rows = list(csv.reader(f))
contacts = rows[0].index("contacts")
hit = next(i for i, row in enumerate(rows[1:], 1) if float(row[contacts]) != 0.0)
for row in rows[hit:]:
    row[1:] = ["-nan" if i % 2 else "nan" for i in range(len(row) - 1)]
with open(out, "w", newline="") as f:
    csv.writer(f).writerows(rows)
