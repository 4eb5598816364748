#!/usr/bin/env python3
"""One scene under every responder, for the lecture that explains why the later chapters exist.

For each scene in plots/comparison/ (a ball dropped onto the ground, two carts meeting) this
asks the simulator which responders it has (`workbook-sim responders`: `none` and every
chapter's, in the order of chapters/response_models.cpp, so a new chapter joins by itself),
runs the scene under each with --trajectory and --csv, and draws:

- <scene>-energy.{svg,pdf,png}: the total energy over time, one curve per responder;
- <scene>-strip.{svg,pdf,png}: one strobe picture per responder (plots/strobe.py), all in
  the same box and scale, stacked (wide scenes) or side by side (tall ones).

The CSV files drawn from stay beside them: <scene>.<responder>.csv, .trajectory.csv and
.trajectory.contacts.csv.

    compare.py build/dev/book/figures/comparison --sim build/dev/tools/workbook-sim
"""

import argparse
import json
import math
import subprocess
import sys
from pathlib import Path

from plots import figure_render
from plots import motion
from plots import strobe

SCENES = sorted((motion.PLOTS / "comparison").glob("*.json"))
# One colour a responder (Okabe-Ito, style.gp's, with its darker yellow): eight, as many as
# there are responders; past them the colours come round again with dashes.
RESPONDER_COLOURS = ["#303030", "#0072B2", "#D55E00", "#009E73", "#E69F00", "#CC79A7", "#56B4E9", "#B8A000"]


def responders(simulator):
    result = subprocess.run([str(simulator), "responders"], capture_output=True, text=True, check=True)
    return [line.strip() for line in result.stdout.splitlines() if line.strip()]


def run_all(simulator, path, out):
    """{responder: (Trajectory, contacts, series csv path)} for every responder."""
    spec = json.loads(path.read_text())
    runs = {}
    for name in responders(simulator):
        scene_file = out / f"{path.stem}.{name}.scene.json"
        scene_file.write_text(json.dumps(dict(spec, responder=name), indent=1))
        series = out / f"{path.stem}.{name}.csv"
        t, c = motion.simulate(simulator, scene_file, out / f"{path.stem}.{name}.trajectory.csv",
                               motion.stride_for(spec), series)
        scene_file.unlink()
        runs[name] = (motion.Trajectory(t), motion.read_contacts(c), series)
    return runs


def energy_commands(scene, runs):
    totals = [v for _, _, series in runs.values() for v in motion.read_series(series)["total"]]
    lo, hi = min(totals + [0.0]), max(totals + [0.0])
    span = hi - lo or 1.0
    g = [f"set title {motion.quote(scene.title + ': total energy under each responder')} font title_font noenhanced",
         "set xlabel 't / s'", "set ylabel 'E / J'", f"set xrange [0:{scene.duration!r}]", "set format x '%g'",
         f"set yrange [{lo - (0.05 * span if lo < 0 else 0)!r}:{hi + 0.1 * span!r}]"]
    # Several responders give the same curve (a ball meets the ground at one point, which
    # chapters 3 to 6 answer alike): each is drawn narrower than the one before, over it, so
    # that curves which coincide show as bands of their colours instead of the last alone.
    plot, n_runs = [], len(runs)
    for n, (name, (_, _, series)) in enumerate(runs.items()):
        colour = RESPONDER_COLOURS[n % len(RESPONDER_COLOURS)]
        width = 1.5 + 6.5 * (n_runs - 1 - n) / max(n_runs - 1, 1)
        dashes = f" dt {1 + n // len(RESPONDER_COLOURS)}" if n >= len(RESPONDER_COLOURS) else ""
        plot.append(f"{motion.quote(str(series))} skip 1 using 1:5 with lines lc rgb '{colour}' lw {width:.2f}{dashes} "
                    f"title {motion.quote(name)}")
    return g + ["plot " + ", ".join(plot)]


def leaving(scene, trajectory, view, box):
    """A note for each body whose last position lies outside the picture: where it went."""
    notes = []
    for i in motion.movable(scene):
        x, y = view.project(trajectory.states[-1][i][0])
        if not (box[0] <= x <= box[1] and box[2] <= y <= box[3]):
            axis, value = (view.ylabel, y) if not box[2] <= y <= box[3] else (view.xlabel, x)
            notes.append(f"{scene.names[i]} leaves the picture:\n{axis.split(' /')[0]} = {motion.number(value)} m "
                         f"at t = {trajectory.times[-1]:.4g} s")
    return notes


# One character of note_font (the labels of a strip's touches) on the strip's PNG terminal, in
# pixels: DejaVu Sans at 18 pt, measured over labels such as "J = 3.551 N s at t = 0.4525 s".
# The SVG and PDF strips hold the same text at the same or a smaller share of their width.
NOTE_CHAR_PX = 12.0


def nice_step(least):
    """The smallest step of 1, 2, 2.5, 4 or 5 times a power of ten that is at least `least`."""
    power = 10.0 ** math.floor(math.log10(least))
    return next(m * power for m in (1.0, 2.0, 2.5, 4.0, 5.0, 10.0) if m * power >= least * (1 - 1e-12))


def names(scene, trajectory, view, pitch, count):
    """Each body's name above its first outline, in its colour: the strip's key, in its first
    panel, where a scene has bodies of more than one colour (the panels have no key of their own)."""
    entries = motion.key_entries(scene)
    if len(entries) < 2 or len(entries) != len(motion.movable(scene)):
        return []
    where = strobe.view_at(view, pitch, scene.duration, 0.0, count)
    labels = []
    for k, (i, (name, colour)) in enumerate(zip(motion.movable(scene), entries)):
        x, y = where.project(trajectory.states[0][i][0])
        top = y + motion.body_size(scene.bodies[i])
        labels.append(f"set label {2000 + k} {motion.quote(name)} at first {x!r}, first {top!r} center offset character 0, 0.8 "
                      f"front font note_font tc rgb '{colour}' noenhanced boxed")
    return labels


def strip_commands(scene, runs):
    trajectories = [(t, c) for t, c, _ in runs.values()]
    view = motion.choose_view(scene, [t for t, _ in trajectories])
    # One box and scale for every panel, fitted to the runs that stay near the others: a run
    # whose bodies go more than three times as far as the middle one (a ball falling through
    # the ground with no responder) leaves the picture, with a note saying where it went.
    spans = [max(e[1] - e[0], e[3] - e[2]) for e in (strobe.data_extent(scene, [run], view) for run in trajectories)]
    middle = sorted(spans)[len(spans) // 2]
    kept = [run for run, span in zip(trajectories, spans) if span <= 3 * middle]
    extent = strobe.data_extent(scene, kept, view)
    n = len(runs)
    # Wide scenes stack their panels; tall ones stand them side by side. Past three responders
    # the panels wrap into a grid (two columns of wide panels, three of tall ones), so that
    # each stays large enough to read as more chapters add responders.
    across = (extent[1] - extent[0]) < 1.5 * (extent[3] - extent[2])
    if n <= 3:
        rows, columns = (1, n) if across else (n, 1)
    else:
        columns = 3 if across else 2
        rows = -(-n // columns)
    aspect = (4.0 / columns) / (3.0 * 0.85 / rows)
    pitch, count = strobe.strobe_layout(scene, kept, view, aspect)
    box = strobe.picture_box(scene, kept, view, aspect=aspect, count=count, pitch=pitch)
    title = f"{scene.title} under each responder\n{strobe.strobe_note(scene, view, count, pitch is not None)}"
    g = [f"set multiplot layout {rows},{columns} "
         f"title {motion.quote(title)} font title_font noenhanced", "set key off"]
    # One character of the labels in a panel, as fractions of its data box, and tics on the
    # vertical axis no closer than one and a half lines of their text.
    first, (trajectory, contacts, _) = next(iter(runs.items()))
    sketch = strobe.strobe_commands(scene, [(trajectory, contacts, False)], view, box, first, key=False, note=False,
                                    snapshots=count, pitch=pitch)
    # gnuplot decides a multiplot panel's margins, and with `set size ratio -1` its box is as
    # wide as the panel's height allows, not as its column is: so it is asked.
    width, height, line = figure_render.panel_area(g + sketch, "use_strip_png")
    text_size = (NOTE_CHAR_PX / width, line / height)
    ytics = nice_step((box[3] - box[2]) * 1.5 * line / height)
    for n, (name, (trajectory, contacts, _)) in enumerate(runs.items()):
        panel = strobe.strobe_commands(scene, [(trajectory, contacts, False)], view, box, name, key=False, note=False,
                                       snapshots=count, pitch=pitch, text_size=text_size, ytics=ytics)
        notes = [f"set label {1000 + k} {motion.quote(text)} at graph 0.62, graph {0.85 - 0.15 * k!r} center front "
                 f"font note_font tc rgb '{motion.CONTACT_COLOUR}' noenhanced boxed"
                 for k, text in enumerate(leaving(scene, trajectory, view, box))]
        if n == 0:
            notes += names(scene, trajectory, view, pitch, count)
        g += panel[:-4] + notes + panel[-4:]
    return g + ["unset multiplot"]


def draw(commands, out_stem, strip):
    script = []
    for ext in motion.FORMATS:
        script += ["reset", f"load {motion.quote(str(motion.STYLE))}", f"eval use_{'strip_' if strip else ''}{ext}",
                   f"set output {motion.quote(str(out_stem) + '.' + ext)}"] + commands + ["unset output"]
    motion.run_gnuplot("\n".join(script) + "\n", out_stem.name)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("out", type=Path, help="folder for the figures and their CSV files")
    parser.add_argument("--sim", type=Path, default=motion.SOURCE / "build/dev/tools/workbook-sim")
    args = parser.parse_args()
    args.out.mkdir(parents=True, exist_ok=True)
    failures = 0
    for path in SCENES:
        try:
            runs = run_all(args.sim, path, args.out)
            scene = motion.Scene(path)
            print(f"compare: {path.name} under {', '.join(runs)} -> {args.out / path.stem}-{{energy,strip}}.*", flush=True)
            draw(energy_commands(scene, runs), args.out / f"{path.stem}-energy", strip=False)
            draw(strip_commands(scene, runs), args.out / f"{path.stem}-strip", strip=True)
        except (RuntimeError, OSError, ValueError, KeyError, subprocess.CalledProcessError) as error:
            print(f"compare: error: {error}", file=sys.stderr)
            failures += 1
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
