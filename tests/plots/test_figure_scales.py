#!/usr/bin/env python3
"""What a figure shows of a scene at rest, and what the motion player lists, without a build:

- a resting scene's momentum (rounding, 1e-9 kg m/s beside 100 J) is drawn flat at zero on the
  scale of the momentum the scene's energy could give its mass, sqrt(2 M E), with every
  component in the key; angular momentum of that size is left out; real momentum keeps its
  own scale;
- the player's data (plots/site_motion.py) leave out what a build folder kept of a scene that
  no longer exists, and keep every scene of today.

    python3 -m tests.plots.test_figure_scales"""
import math
import pathlib
import re
import shutil
import subprocess
import sys
import tempfile
import unittest

ROOT = pathlib.Path(__file__).resolve().parents[2]

from plots import figures  # noqa: E402  (run from the workbook's folder: ctest does)


def run(noise, energy=98.1, mass=10.0):
    """gnuplot_panels for three samples of a resting-contact scene whose momenta are `noise`."""
    columns = ["t", "kinetic_linear", "kinetic_rotational", "potential", "total", "momentum_x", "momentum_y",
               "momentum_z", "angular_momentum_x", "angular_momentum_y", "angular_momentum_z",
               "response_energy_change", "contacts", "penetration_max"]
    data = {c: [0.0, 0.0, 0.0] for c in columns}
    data["t"] = [0.0, 0.5, 1.0]
    data["potential"] = data["total"] = [energy] * 3
    data["momentum_z"] = [0.0, -noise, noise]
    data["angular_momentum_x"] = [0.0, 2 * noise, -noise]
    return figures.gnuplot_panels("t", "resting-contact", [("r.csv", data, False, True)], ("r.csv", data), None, 1.0,
                                  moving_mass=mass)


def momentum_range(body):
    match = re.search(r"set title 'Momentum'\n.*\nset yrange \[([^:]+):([^\]]+)\]", body)
    return float(match.group(1)), float(match.group(2))


class RestingMomentum(unittest.TestCase):
    def test_rounding_is_drawn_flat_on_the_scenes_scale(self):
        body = run(9e-9)
        scale = math.sqrt(2 * 10.0 * 98.1)
        lo, hi = momentum_range(body)
        self.assertLessEqual(lo, -scale)
        self.assertGreaterEqual(hi, scale)
        self.assertLess(hi, 2 * scale)
        for title in ("p_x", "p_y", "p_z"):
            self.assertIn(f'title "{title}"', body)
        self.assertNotIn("L_x", body)
        self.assertNotRegex(body, r"(?m)^set y2tics")

    def test_real_momentum_keeps_its_own_scale(self):
        lo, hi = momentum_range(run(0.4))
        self.assertLess(hi, 1.0)
        self.assertGreater(hi, 0.4)
        self.assertIn("L_x", run(0.4))


class PlayerLeavesOutOldScenes(unittest.TestCase):
    def test_only_todays_scenes(self):
        figures_dir = pathlib.Path(tempfile.mkdtemp(prefix="player-scenes-"))
        try:
            chapter = figures_dir / "resting-contact"
            chapter.mkdir()
            scenes = sorted(p.stem for p in (ROOT / "chapters" / "resting-contact" / "scenes").glob("*.json"))
            for name in scenes + ["a-scene-renamed-since"]:
                (chapter / f"{name}.player.js").write_text(f"// {name}\n")
            html = figures_dir / "html"
            result = subprocess.run([sys.executable, "-m", "plots.site_motion", "--figures", str(figures_dir), "--html",
                                     str(html), "resting-contact"], capture_output=True, text=True, cwd=ROOT, timeout=60)
            self.assertEqual(result.returncode, 0, result.stderr)
            data = (html / "motion" / "resting-contact.js").read_text()
            self.assertNotIn("a-scene-renamed-since", data)
            for name in scenes:
                self.assertIn(f"// {name}\n", data)
            self.assertIn("left out a-scene-renamed-since.player.js", result.stdout)
        finally:
            shutil.rmtree(figures_dir)


if __name__ == "__main__":
    unittest.main()
