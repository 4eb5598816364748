#!/usr/bin/env python3
"""Pareto figures of the accuracy bench: error against run time, log-log, one per family.

Reads the CSV files `workbook-accuracy bench --out DIR` wrote (pareto-<family>.csv, beside which
the figures go) and draws DIR/pareto-<family>.svg, .pdf and .png in the shared style (plots/style.gp):
every configuration of the workbook's sweep as a filled point, coloured by contact timing and
shaped by integrator; the Pareto front of those points (no faster configuration is more
accurate) as a staircase; and each peer engine of the same run (CSV column `engine`) as open
points of its own shape and colour, one per frame step.

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
    "head-on-inelastic": "Head-on pair, 1 and 3 kg, perfectly inelastic: state after 1 s",
    "resting-stack": "Three balls stacked at rest: deepest sink in 1 s, over the radius",
    "bouncing-ball": "Bouncing ball, e = 0.8: apexes of 10 bounces against e^{2k} h_0",
    "head-on": "Head-on pair, 1 and 3 kg, e = 0.5: state after 1 s",
    "cradle": "Newton's cradle, five balls, e = 1: state after 1 s",
    "stacked-drop": "Stacked-ball drop, 0.1 kg on 1 kg, e = 1: the small ball's apex",
    "tilted-rod": "Tilted rod, 30°, lands at 3 m/s, e = 0.5: velocity and spin after the impact",
    "torque-free-box": "Box spinning freely near its middle axis, 10 s: drift of L and E",
    "incline": "Block on a 30° incline, μ = 0.3 (slides) and 0.8 (sticks): slide and speed after 1 s",
    "thrown-ball": "Ball thrown at 3 m/s without spin, μ = 0.2: slides, then rolls at 5/7 v_0; state after 1 s",
}

# (integrator, timing, key title, colour variable of style.gp, point type): the workbook.
SERIES = [("semi-implicit-euler", "discrete", "semi-implicit Euler, discrete", "c_blue", 7),
          ("exact-under-gravity", "discrete", "exact under gravity, discrete", "c_sky", 9),
          ("semi-implicit-euler", "event", "semi-implicit Euler, event timing", "c_vermillion", 5),
          ("exact-under-gravity", "event", "exact under gravity, event timing", "c_orange", 11)]

# Families without gravity sweep one integrator, whose name then says nothing.
NO_GRAVITY_TITLES = {"discrete": "workbook, discrete", "event": "workbook, event timing"}

# Peers, by the start of their name in the CSV: (colour, open point type).
PEERS = [("Chipmunk", "c_green", 4), ("Box2D", "c_purple", 6), ("Bullet", "'#303030'", 12)]

# The families the peers run (tools/accuracy/peers.cpp); a figure of one of them drawn without
# peers says why, so that no caption promises points the figure lacks.
PEER_FAMILIES = {"bouncing-ball", "head-on", "cradle", "incline", "thrown-ball"}


def quote(text):
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"') + '"'


def rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def block(name, points):
    lines = [f"${name} << EOD"] + [f"{x:.6g},{y:.6g}" for x, y in points] + ["EOD"]
    return "\n".join(lines)


def point(row):
    return float(row["seconds"]), max(float(row["error"]), FLOOR)


def script_for(family, data):
    ours = [r for r in data if r.get("engine", "workbook") == "workbook"]
    integrators = {r["integrator"] for r in ours}
    blocks, plots = [], []
    for i, (integrator, timing, title, colour, point_type) in enumerate(SERIES):
        points = [point(r) for r in ours if r["integrator"] == integrator and r["timing"] == timing]
        if not points:
            continue
        if len(integrators) == 1:
            title = NO_GRAVITY_TITLES[timing]
        blocks.append(block(f"s{i}", points))
        plots.append(f"$s{i} using 1:2 with points pt {point_type} ps 1.6 lc rgb {colour} title {quote(title)}")
    peers = sorted({r["engine"] for r in data} - {"workbook"})
    for k, engine in enumerate(peers):
        colour, point_type = next(((c, p) for name, c, p in PEERS if engine.startswith(name)), ("c_note", 8))
        blocks.append(block(f"p{k}", sorted(point(r) for r in data if r["engine"] == engine)))
        plots.append(f"$p{k} using 1:2 with linespoints dt 3 lw 1.2 pt {point_type} ps 1.8 lc rgb {colour} "
                     f"title {quote(engine + ', 1/30 to 1/3840 s')}")
    if family in PEER_FAMILIES and not peers:
        plots.append("1/0 with points pt -1 title 'no peers in this build (./workbook bench accuracy installs them)'")
    front = sorted(point(r) for r in ours if r["pareto"] == "1")
    # The front holds from its last point to the slowest configuration: drawn that far, it
    # shows even when the fastest point is already the most accurate.
    slowest = max(point(r)[0] for r in ours)
    if front and front[-1][0] < slowest:
        front.append((slowest, front[-1][1]))
    blocks.append(block("front", front))
    plots.insert(0, "$front using 1:2 with steps lw 2.5 lc rgb c_total title 'Pareto front (workbook)'")
    return "\n".join(blocks + [
        f"set title {quote(TITLES.get(family, family))} font title_font",
        "set logscale xy",
        "set format x '10^{%L}'", "set format y '10^{%L}'",
        "set xlabel 't_{run} / s (processor time of one run)' font label_font",
        "set ylabel 'relative error (≤ 10^{-16} drawn at 10^{-16})' font label_font",
        f"set key maxrows {3 if len(plots) > 4 else 2}",
        "plot " + ", \\\n     ".join(plots),
    ])


def draw(csv_path):
    data = rows(csv_path)
    family = csv_path.stem[len("pareto-"):]
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
    families = [p for p in sorted(args.folder.glob("pareto-*.csv")) if p.stem[len("pareto-"):] in TITLES]
    if not families:
        sys.exit(f"accuracy.py: no family CSV in {args.folder} (run workbook-accuracy bench --out {args.folder})")
    for path in families:
        draw(path)
        print(f"{path.with_suffix('.svg')}")


if __name__ == "__main__":
    main()
