#!/usr/bin/env python3
"""The site's motion player without building the site: one chapter's figures, strobe data and
player bundled as the docs target does (plots/figures.py, plots/strobe.py,
plots/site_motion.py) into a page with the player alone, checked in headless Chromium by the
same check the site's browser test runs on every chapter page
(tests/site/motion_player_check.py: loads, plays, pauses, scrubs, changes speed, cursor in
step, nothing fetched).

It also checks what that check takes on trust: that <scene>.panels.json, from which the
cursor is placed, says where the figure's axes really are. Every tic of every time axis in
the SVG must stand where the panel's recorded plot area and range put its value.

    player_test.py --sim build/dev/tools/workbook-sim --source . --chromium /usr/bin/chromium
"""

import argparse
import json
import re
import subprocess
import sys
import tempfile
from pathlib import Path

CHAPTER = "inelastic"
# A tic mark of a time axis and its label, as gnuplot's SVG terminal writes them.
TIC = re.compile(r"d='M([0-9.]+),([0-9.]+) L\1,[0-9.]+  '/>\s*<g transform=\"translate\(\1,[0-9.]+\)\"[^>]*"
                 r"text-anchor=\"middle\">\s*<text><tspan[^>]*>([-0-9.]+)</tspan>")

failures = []


def check(condition, message):
    if not condition:
        failures.append(message)


def check_panels(figures):
    """Each time-axis tic of each figure lies where its panel record maps the tic's value."""
    for record in sorted(figures.glob("*.panels.json")):
        panels = json.loads(record.read_text())
        svg = (figures / panels["figure"]).read_text()
        tics = 0
        for x, y, value in TIC.findall(svg):
            x, y, value = float(x), float(y), float(value)
            panel = next((p for p in panels["panels"] if abs(p["bottom"] - y) < 0.01 and p["left"] - 0.01 <= x <= p["right"] + 0.01),
                         None)
            if panel is None:
                continue  # a tic of another axis
            tics += 1
            want = panel["left"] + (value - panel["x0"]) / (panel["x1"] - panel["x0"]) * (panel["right"] - panel["left"])
            # The SVG rounds coordinates to 0.01 px.
            check(abs(x - want) <= 0.011, f"{record.name}: the tic {value} stands at x = {x}, the record puts it at {want}")
        check(tics >= 2 * len(panels["panels"]), f"{record.name}: only {tics} time-axis tics found in {panels['figure']}")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--sim", type=Path, required=True)
    parser.add_argument("--source", type=Path, required=True)
    parser.add_argument("--chromium", required=True)
    args = parser.parse_args()
    from tests.site import browser, motion_player_check  # run from the workbook's folder (ctest does)

    scenes = sorted((args.source / "chapters" / CHAPTER / "scenes").glob("*.json"))
    titles = [json.loads(scene.read_text())["title"] for scene in scenes]
    with tempfile.TemporaryDirectory() as scratch:
        scratch = Path(scratch)
        figures, html = scratch / "figures", scratch / "html"
        for module in ("plots.figures", "plots.strobe"):
            subprocess.run([sys.executable, "-m", module, CHAPTER, str(figures / CHAPTER),
                            "--sim", str(args.sim)], check=True, capture_output=True)
        subprocess.run([sys.executable, "-m", "plots.site_motion", "--figures", str(figures),
                        "--html", str(html), CHAPTER], check=True, capture_output=True)
        check_panels(figures / CHAPTER)
        page = html / "player.html"
        page.write_text("<!DOCTYPE html><html><head><meta charset='utf-8'></head><body>"
                        f"<div class='wb-motion' data-chapter='{CHAPTER}'></div>"
                        f"<script src='motion/{CHAPTER}.js'></script><script src='motion/motion-player.js'></script>"
                        "</body></html>")
        chromium = browser.Browser(args.chromium)
        try:
            problems = chromium.open(page.as_uri())
            problems += motion_player_check.check(chromium, titles)
        finally:
            chromium.close()
        for problem in problems:
            check(False, problem)
    for f in failures:
        print("FAIL:", f)
    print(f"{len(failures)} failures")
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
