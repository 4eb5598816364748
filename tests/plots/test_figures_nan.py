#!/usr/bin/env python3
"""A student's NaN must not break the figures (plots/figures.py): the finite part is drawn,
the place where values stop being finite is marked on the figure and said in words, and
the run succeeds. The student's simulator is stood in for by nan_after_impact_sim.py.

    test_figures_nan.py --sim build/dev/tools/workbook-sim"""
import argparse
import csv
import os
import pathlib
import subprocess
import sys
import tempfile
import unittest

HERE = pathlib.Path(__file__).resolve().parent
ROOT = HERE.parents[1]
FAKE = HERE / "nan_after_impact_sim.py"
SCENE = ROOT / "chapters" / "inelastic" / "scenes" / "head-on-carts.json"
SIM = None


def first_contact_time(csv_path):
    with open(csv_path, newline="") as f:
        rows = list(csv.DictReader(f))
    return next(float(r["t"]) for r in rows if float(r["contacts"]) != 0.0)


class NanInFigures(unittest.TestCase):
    def draw(self, *mode):
        scratch = tempfile.mkdtemp(prefix="figures-nan-")
        env = dict(os.environ, WORKBOOK_REAL_SIM=str(SIM))
        run = subprocess.run([sys.executable, "-m", "plots.figures", "inelastic", scratch, "--scene", str(SCENE),
                              "--student", "--student-sim", str(FAKE), *mode],
                             capture_output=True, text=True, env=env, timeout=300)
        return run, pathlib.Path(scratch)

    def check(self, run, out, label):
        self.assertEqual(run.returncode, 0, run.stdout + run.stderr)
        for ext in ("svg", "pdf", "png", "csv"):
            self.assertTrue((out / f"head-on-carts.student.{ext}").stat().st_size > 0, ext)
        t_stop = first_contact_time(SIM_CSV)
        self.assertIn(f"the values of your code stop being finite (NaN or infinite) at t = {t_stop:.6g} s", run.stdout)
        svg = (out / "head-on-carts.student.svg").read_text()
        self.assertIn(f"{label}: not finite (NaN)", svg)
        self.assertIn(f"from t = {t_stop:.4g} s on", svg)
        # The CSV beside the figure is the data as it came, NaN included.
        self.assertIn("nan", (out / "head-on-carts.student.csv").read_text())

    def test_over_the_reference(self):
        run, out = self.draw("--sim", str(SIM))
        self.check(run, out, "your code")
        self.assertIn("your code: ΔE not finite (NaN)", (out / "head-on-carts.student.svg").read_text())

    def test_alone_as_in_the_student_edition(self):
        run, out = self.draw("--no-reference")
        self.check(run, out, "your code")


if __name__ == "__main__":
    parser = argparse.ArgumentParser()
    parser.add_argument("--sim", required=True, type=pathlib.Path)
    args, rest = parser.parse_known_args()
    SIM = args.sim.resolve()
    SIM_CSV = pathlib.Path(tempfile.mkdtemp(prefix="figures-nan-ref-")) / "reference.csv"
    subprocess.run([str(SIM), "run", str(SCENE), "--csv", str(SIM_CSV), "--quiet"], check=True)
    unittest.main(argv=[sys.argv[0]] + rest, verbosity=2)
