#!/usr/bin/env python3
"""The tennis-racket figure (plots/spin.py, through plots/figures.py) draws what the simulation
did: the angular velocity it draws in the body frame, times the box's principal moments, has
the |L| and the kinetic energy the simulator's probes measured, row by row; the middle-axis
component changes sign several times at a steady interval; |L| and E stay constant. The
overlay and the student edition's drawing work too. Only free spinning boxes get this figure.

    test_spin_figure.py --sim build/dev/tools/workbook-sim"""
import argparse
import csv
import json
import pathlib
import subprocess
import sys
import tempfile
import unittest

HERE = pathlib.Path(__file__).resolve().parent
ROOT = HERE.parents[1]
SCENE = ROOT / "chapters" / "angular-impulse" / "scenes" / "tennis-racket.json"
SIM = None

from plots import spin  # noqa: E402  (run from the workbook's folder: ctest does)


def read(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    return {name: [float(r[name]) for r in rows] for name in rows[0]}


def relative(a, b):
    return abs(a - b) / abs(b)


class SpinFigure(unittest.TestCase):
    def draw(self, *mode):
        out = pathlib.Path(tempfile.mkdtemp(prefix="spin-figure-"))
        run = subprocess.run([sys.executable, "-m", "plots.figures", "angular-impulse", str(out), "--scene", str(SCENE), *mode],
                             capture_output=True, text=True, timeout=300)
        self.assertEqual(run.returncode, 0, run.stdout + run.stderr)
        return out

    def test_only_free_spinning_boxes_get_it(self):
        chosen = [path.relative_to(ROOT).as_posix() for path in sorted(ROOT.glob("chapters/*/scenes/*.json"))
                  if spin.watched_body(json.loads(path.read_text())) is not None]
        self.assertEqual(chosen, ["chapters/angular-impulse/scenes/tennis-racket.json"])

    def test_the_drawn_spin_is_the_simulated_one(self):
        out = self.draw("--sim", str(SIM))
        for ext in ("svg", "pdf", "png", "csv"):
            self.assertGreater((out / f"tennis-racket.{ext}").stat().st_size, 0, ext)
        data = read(out / "tennis-racket.csv")
        box = json.loads(SCENE.read_text())["bodies"][0]
        a, b, c = (2 * h for h in box["shape"]["half_extents"])
        moments = [box["mass"] / 12 * (b * b + c * c), box["mass"] / 12 * (a * a + c * c), box["mass"] / 12 * (a * a + b * b)]
        for i in range(len(data["t"])):
            w = [data["spin_" + axis][i] for axis in "xyz"]
            momentum = sum((m * x) ** 2 for m, x in zip(moments, w)) ** 0.5
            energy = 0.5 * sum(m * x * x for m, x in zip(moments, w))
            # A wrong frame (R w instead of R^T w) would give another |I w| for this box.
            self.assertLess(relative(momentum, data["angular_momentum_magnitude"][i]), 1e-12, data["t"][i])
            self.assertLess(relative(energy, data["kinetic_energy"][i]), 1e-12, data["t"][i])
        for name in ("kinetic_energy", "angular_momentum_magnitude"):
            self.assertLess(spin.largest_relative_change(data[name]), 1e-13, name)
        flips = spin.sign_changes(data["t"], data["spin_y"])
        self.assertGreaterEqual(len(flips), 4)
        intervals = [later - earlier for earlier, later in zip(flips, flips[1:])]
        for interval in intervals:
            self.assertLess(relative(interval, intervals[0]), 1e-3, intervals)
        self.assertLess(min(data["spin_y"]), -0.99 * data["spin_y"][0])
        svg = (out / "tennis-racket.svg").read_text()
        self.assertIn(f"changes sign {len(flips)} times, every {sum(intervals) / len(intervals):.2f} s", svg)

    def test_over_the_reference_and_alone(self):
        # The scene has no responder, so the reference simulator can stand in for the student's.
        out = self.draw("--sim", str(SIM), "--student", "--student-sim", str(SIM))
        data = read(out / "tennis-racket.student.csv")
        self.assertEqual(data["spin_y"], data["spin_y_yours"])
        svg = (out / "tennis-racket.student.svg").read_text()
        self.assertIn("your code", svg)
        out = self.draw("--no-reference", "--student", "--student-sim", str(SIM))
        self.assertIn("(your code)", (out / "tennis-racket.student.svg").read_text())
        self.assertNotIn("spin_y_yours", (out / "tennis-racket.student.csv").read_text())


if __name__ == "__main__":
    parser = argparse.ArgumentParser()
    parser.add_argument("--sim", required=True)
    args, rest = parser.parse_known_args()
    SIM = pathlib.Path(args.sim)
    unittest.main(argv=[sys.argv[0], *rest])
