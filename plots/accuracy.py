#!/usr/bin/env python3
"""Pareto figures of the accuracy bench: error against run time, log-log, one per family.

Reads the CSV files `workbook-accuracy bench --out DIR` wrote (one per family, beside which the
figures go) and draws DIR/<family>.svg, .pdf and .png in the shared style (plots/style.gp):
every configuration of the sweep as a point, coloured by contact timing and shaped by
integrator, and the Pareto front (no faster configuration is more accurate) as a staircase.

    accuracy.py build/dev/book/accuracy
"""

import argparse
import csv
import subprocess
import sys
from pathlib import Path

PLOTS = Path(__file__).resolve().parent
STYLE = PLOTS / "style.gp"
FORMATS = ["svg", "pdf", "png"]

# Errors at or below this are drawn on it: a log axis has no zero, and event timing reaches
# rounding (about 1e-16 relative).
FLOOR = 1e-16

TITLES = {
    "bouncing-ball": "Bouncing ball, e = 0.8: apexes of 10 bounces against e^{2k} h_0",
    "head-on": "Head-on pair, 1 and 3 kg, e = 0.5: state after 1 s",
    "cradle": "Newton's cradle, five balls, e = 1: state after 1 s",
    "stacked-drop": "Stacked-ball drop, 0.1 kg on 1 kg, e = 1: the small ball's apex",
}

# (integrator, timing, key title, colour variable of style.gp, point type)
SERIES = [("semi-implicit-euler", "discrete", "semi-implicit Euler, discrete", "c_blue", 7),
          ("exact-under-gravity", "discrete", "exact under gravity, discrete", "c_sky", 9),
          ("semi-implicit-euler", "event", "semi-implicit Euler, event timing", "c_vermillion", 5),
          ("exact-under-gravity", "event", "exact under gravity, event timing", "c_orange", 11)]


def quote(text):
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"') + '"'


def rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def block(name, points):
    lines = [f"${name} << EOD"] + [f"{x:.6g},{y:.6g}" for x, y in points] + ["EOD"]
    return "\n".join(lines)


def script_for(family, data):
    blocks, plots = [], []
    for i, (integrator, timing, title, colour, point) in enumerate(SERIES):
        points = [(float(r["seconds"]), max(float(r["error"]), FLOOR)) for r in data
                  if r["integrator"] == integrator and r["timing"] == timing]
        blocks.append(block(f"s{i}", points))
        plots.append(f"$s{i} using 1:2 with points pt {point} ps 1.6 lc rgb {colour} title {quote(title)}")
    front = sorted((float(r["seconds"]), max(float(r["error"]), FLOOR)) for r in data if r["pareto"] == "1")
    blocks.append(block("front", front))
    plots.insert(0, f"$front using 1:2 with steps lw 2.5 lc rgb c_total title 'Pareto front'")
    return "\n".join(blocks + [
        f"set title {quote(TITLES.get(family, family))} font title_font",
        "set logscale xy",
        "set format x '10^{%L}'", "set format y '10^{%L}'",
        "set xlabel 't_{run} / s (processor time of one run)' font label_font",
        "set ylabel 'relative error (≤ 10^{-16} drawn at 10^{-16})' font label_font",
        "set key maxrows 2",
        "plot " + ", \\\n     ".join(plots),
    ])


def draw(csv_path):
    data = rows(csv_path)
    family = csv_path.stem
    body = script_for(family, data)
    script = []
    for ext in FORMATS:
        script += ["reset", f"load {quote(str(STYLE))}", f"eval use_{ext}",
                   f"set output {quote(str(csv_path.with_suffix('.' + ext)))}", body, "unset output"]
    result = subprocess.run(["gnuplot"], input="\n".join(script) + "\n", capture_output=True, text=True)
    if result.returncode != 0 or result.stderr.strip():
        raise RuntimeError(f"gnuplot on {csv_path}:\n{result.stderr.strip()}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("folder", type=Path, help="where workbook-accuracy bench wrote its CSV files")
    args = parser.parse_args()
    families = [p for p in sorted(args.folder.glob("*.csv")) if p.stem in TITLES]
    if not families:
        sys.exit(f"accuracy.py: no family CSV in {args.folder} (run workbook-accuracy bench --out {args.folder})")
    for path in families:
        draw(path)
        print(f"{path.with_suffix('.svg')}")


if __name__ == "__main__":
    main()
