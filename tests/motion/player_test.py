#!/usr/bin/env python3
"""The site's motion player in headless Chromium: it loads every scene of a chapter, plays,
and the cursor on the energy and momentum charts moves in step with the time shown.

A page with the player and the chapter's data (written by plots/strobe.py, bundled by
plots/site_motion.py as the docs target does) is opened with #autoplay; after a few seconds
of virtual time the DOM is dumped and read.

    player_test.py --sim build/dev/tools/workbook-sim --source . --chromium /usr/bin/chromium
"""

import argparse
import re
import subprocess
import sys
import tempfile
from pathlib import Path

failures = []


def check(condition, message):
    if not condition:
        failures.append(message)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--sim", type=Path, required=True)
    parser.add_argument("--source", type=Path, required=True)
    parser.add_argument("--chromium", required=True)
    args = parser.parse_args()
    scenes = sorted((args.source / "chapters/inelastic/scenes").glob("*.json"))
    with tempfile.TemporaryDirectory() as scratch:
        scratch = Path(scratch)
        figures, html = scratch / "figures", scratch / "html"
        subprocess.run([sys.executable, str(args.source / "plots/strobe.py"), "inelastic", str(figures / "inelastic"),
                        "--sim", str(args.sim)], check=True, capture_output=True)
        subprocess.run([sys.executable, str(args.source / "plots/site_motion.py"), "--figures", str(figures),
                        "--html", str(html), "inelastic"], check=True, capture_output=True)
        page = html / "player.html"
        page.write_text("<!DOCTYPE html><html><head><meta charset='utf-8'></head><body>"
                        "<div class='wb-motion' data-chapter='inelastic'></div>"
                        "<script src='motion/inelastic.js'></script><script src='motion/motion-player.js'></script>"
                        "</body></html>")
        dom = subprocess.run([args.chromium, "--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
                              "--disable-component-update", "--disable-sync", "--no-first-run",
                              f"--user-data-dir={scratch / 'profile'}", "--virtual-time-budget=3000", "--dump-dom",
                              page.as_uri() + "#autoplay"], capture_output=True, text=True, timeout=120).stdout

    options = re.findall(r"<option value=\"\d+\">", dom)
    check(len(options) >= len(scenes), f"the scene menu has {len(options)} entries, expected at least {len(scenes)}")
    player = re.search(r'class="wb-motion"[^>]*data-playing="(\w+)" data-time="([0-9.]+)"', dom)
    check(player is not None, "no player in the page")
    if player:
        t = float(player.group(2))
        # The first scene (bullet-block) runs 10 ms at 500 times slower: 3 s of play is 6 ms.
        check(0.004 < t < 0.0085, f"after 3 s of playing the player shows t = {t} s, expected about 0.006 s")
        cursors = re.findall(r'class="wb-cursor" x1="([0-9.e+-]+)"', dom)
        check(len(cursors) == 2, f"{len(cursors)} cursors, expected 2 (energy, momentum)")
        # The charts span t = 0..0.01 s over x = 70..458.
        for x in cursors:
            check(abs(float(x) - (70 + t / 0.01 * 388)) < 1e-6 * 458, f"cursor at x = {x}, the time {t} s says "
                  f"{70 + t / 0.01 * 388}")
    for f in failures:
        print("FAIL:", f)
    print(f"{len(failures)} failures")
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
