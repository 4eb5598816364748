#!/usr/bin/env python3
"""Strobe pictures: each scene's bodies drawn at evenly spaced times, earlier ones fainter.

For every chapters/<chapter>/scenes/*.json this runs the simulator once with --trajectory,
keeps <scene>.trajectory.csv and <scene>.trajectory.contacts.csv beside the figures (the
animations are drawn from them), and draws <scene>-strobe.svg, .pdf and .png: planes as
ground or walls, spheres as circles, boxes with their orientation, and at the first moment
of each touch the contact point, its normal (from body 2 towards body 1) and the size of the
impulse the responder gave. One metre is as long across as up. The view follows the rule in
plots/motion.py (choose_view). With --student the student's bodies are drawn over the
reference's, dashed, in another colour, as <scene>-strobe.student.*.

    strobe.py inelastic build/dev/book/figures/inelastic --sim build/dev/tools/workbook-sim
"""

import argparse
import sys
import tempfile
from pathlib import Path

import motion
import player_data

SNAPSHOTS = 9
ASPECT = 2.7  # width / height of the data box; the 12:5 canvas less its key and labels


def snapshot_indices(trajectory, duration, count=SNAPSHOTS):
    return [trajectory.index_at(duration * k / (count - 1)) for k in range(count)]


def data_extent(scene, runs, view, count=SNAPSHOTS):
    """(xmin, xmax, ymin, ymax) of every outline drawn and the planes' traces."""
    shapes = list(motion.plane_bounds(scene, runs[0][0], view))
    for trajectory, _ in runs:
        for k in snapshot_indices(trajectory, scene.duration, count):
            for i in motion.movable(scene):
                position, q, _ = trajectory.states[k][i]
                shapes.append(motion.outline(scene.bodies[i], position, q, view))
    return motion.extent_of([s for s in shapes if s])


def picture_box(scene, runs, view, aspect=ASPECT, count=SNAPSHOTS):
    """A data box holding every drawn outline of every run, the planes' traces and room for the
    contact arrows, at width/height = aspect."""
    box = data_extent(scene, runs, view, count)
    # Room for the normal arrows and their labels: a fifth of the picture on every side.
    room = 0.12 * max(box[1] - box[0], box[3] - box[2])
    return motion.fit_box(box[0] - room, box[1] + room, box[2] - room, box[3] + room, aspect, margin=0.02)


def draw_bodies(canvas, scene, trajectory, indices, student=False):
    """Outlines at the given frames, from faint (first) to full colour (last), with centre dots
    so that even a bullet of a few millimetres shows."""
    n = len(indices)
    for k, index in enumerate(indices):
        strength = 0.22 + 0.78 * (k / (n - 1) if n > 1 else 1.0)
        for i in motion.movable(scene):
            position, q, _ = trajectory.states[index][i]
            shape = motion.outline(scene.bodies[i], position, q, canvas.view)
            base = motion.STUDENT_COLOUR if student else motion.BODY_COLOURS[i % len(motion.BODY_COLOURS)]
            colour = motion.faded(base, strength)
            canvas.shape(shape, colour, None if student else colour, width=3.0 if student else 2.0, dashed=student,
                         opacity=0.05 + 0.12 * strength)
            canvas.point(canvas.view.project(position), colour, size=0.5)


def draw_contacts(canvas, scene, contacts, box, colour=motion.CONTACT_COLOUR, label_side=1):
    """At each touch's first step: the contact point, the normal as an arrow (from body 2
    towards body 1, into body 1), and J and t beside it."""
    for c in motion.contact_onsets(contacts):
        length = motion.normal_arrow_length(scene, c, box)
        point = canvas.view.project([c["x"], c["y"], c["z"]])
        normal = canvas.view.project([c["nx"], c["ny"], c["nz"]])
        size = (normal[0] ** 2 + normal[1] ** 2) ** 0.5 or 1.0
        end = (point[0] + length * normal[0] / size, point[1] + length * normal[1] / size)
        canvas.point(point, colour, size=1.0)
        canvas.arrow(point, end, colour, width=3.0)
        # Above the arrow's middle; near an edge of the picture, the text runs inwards from there.
        middle = ((point[0] + end[0]) / 2, max(point[1], end[1]))
        where = (middle[0] - box[0]) / (box[1] - box[0])
        align = "left" if where < 0.3 else "right" if where > 0.7 else "center"
        text = f"{motion.impulse_text(c['impulse'])} at t = {c['t']:.4g} s"
        canvas.label(text, middle, colour, align=align, offset=(0, 1.0 * label_side))


def strobe_note(scene, view, snapshots=SNAPSHOTS):
    step = scene.duration / (snapshots - 1)
    return f"{view.name}; outlines every {step:.3g} s from t = 0 to {scene.duration:.3g} s, earlier ones fainter"


def strobe_commands(scene, runs, view, box, title, key=True, snapshots=SNAPSHOTS, note=True):
    """gnuplot commands for one strobe panel. runs: [(trajectory, contacts, is_student)]."""
    canvas = motion.Canvas(view)
    motion.draw_planes(canvas, scene, runs[0][0], view, box)
    for trajectory, contacts, student in runs:
        draw_bodies(canvas, scene, trajectory, snapshot_indices(trajectory, scene.duration, snapshots), student)
    for n, (trajectory, contacts, student) in enumerate(runs):
        draw_contacts(canvas, scene, contacts, box, motion.STUDENT_COLOUR if student else motion.CONTACT_COLOUR,
                      label_side=-1 if n else 1)
    if note:
        canvas.label(strobe_note(scene, view, snapshots), (0.01, 0.965), "#404040", font="note_font", coords="graph")
    g = ["set size ratio -1", "set style textbox opaque noborder margins 1, 0.5", f"set xrange [{box[0]!r}:{box[1]!r}]", f"set yrange [{box[2]!r}:{box[3]!r}]",
         f"set xlabel {motion.quote(view.xlabel)}", f"set ylabel {motion.quote(view.ylabel)}",
         f"set title {motion.quote(title)} font title_font noenhanced", "set format x '%g'", "set format y '%g'"]
    g += canvas.lines
    plot = ["NaN notitle"]
    if key:
        for i in motion.movable(scene):
            plot.append(f"NaN with lines lc rgb '{motion.BODY_COLOURS[i % len(motion.BODY_COLOURS)]}' lw 4 "
                        f"title {motion.quote(scene.names[i])}")
        if any(student for _, _, student in runs):
            plot.append(f"NaN with lines lc rgb '{motion.STUDENT_COLOUR}' lw 3 dt 2 title 'your code'")
        if any(run[1] for run in runs):
            plot.append(f"NaN with vectors lc rgb '{motion.CONTACT_COLOUR}' lw 3 title 'contact normal, impulse J'")
    g += ["plot " + ", ".join(plot), "unset object", "unset arrow", "unset label"]
    return g


def draw(scene, out_dir, stem, runs):
    view = motion.choose_view(scene, [r[0] for r in runs])
    box = picture_box(scene, [(r[0], r[1]) for r in runs], view)
    title = scene.title + (" (your code)" if len(runs) == 1 and runs[0][2] else "")
    body = strobe_commands(scene, runs, view, box, title)
    script = []
    for ext in motion.FORMATS:
        script += ["reset", f"load {motion.quote(str(motion.STYLE))}", f"eval use_{ext}",
                   f"set output {motion.quote(str(out_dir / (stem + '.' + ext)))}"] + body + ["unset output"]
    motion.run_gnuplot("\n".join(script) + "\n", scene.path.name)
    return view, box


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("chapter", help="chapter id, as in chapters/CHAPTERS")
    parser.add_argument("out", type=Path, help="folder for the pictures and trajectories")
    parser.add_argument("--scene", type=Path, action="append",
                        help="draw only this scene file (repeatable); default: every chapters/<chapter>/scenes/*.json")
    parser.add_argument("--sim", type=Path, default=motion.SOURCE / "build/dev/tools/workbook-sim")
    parser.add_argument("--no-reference", action="store_true", help="no reference solutions: draw the student's alone")
    parser.add_argument("--student", action="store_true", help="also run the student's simulator and draw it over")
    parser.add_argument("--student-sim", type=Path, default=motion.SOURCE / "build/dev/tools/workbook-sim-student")
    args = parser.parse_args()

    scenes = args.scene or sorted((motion.SOURCE / "chapters" / args.chapter / "scenes").glob("*.json"))
    if not scenes:
        sys.exit(f"strobe.py: no scenes for chapter '{args.chapter}'")
    if args.no_reference and not args.student:
        sys.exit("strobe.py: --no-reference needs --student")
    args.out.mkdir(parents=True, exist_ok=True)
    failures = 0
    with tempfile.TemporaryDirectory() as scratch:
        for path in scenes:
            scene = motion.Scene(path)
            suffix = ".student" if args.student else ""
            print(f"strobe: {args.chapter}/{path.name} -> {args.out / (path.stem + '-strobe' + suffix)}.{{svg,pdf,png}}",
                  flush=True)
            try:
                runs = []
                stride = motion.stride_for(scene.spec)
                series = Path(scratch, f"{path.stem}.series.csv")
                if not args.no_reference:
                    where = Path(scratch) if args.student else args.out
                    t, c = motion.simulate(args.sim, path, where / f"{path.stem}.trajectory.csv", stride, series)
                    runs.append((motion.Trajectory(t), motion.read_contacts(c), False))
                if args.student:
                    t, c = motion.simulate(args.student_sim, path, args.out / f"{path.stem}.student.trajectory.csv",
                                           stride, None if runs else series)
                    runs.append((motion.Trajectory(t), motion.read_contacts(c), True))
                view, box = draw(scene, args.out, path.stem + "-strobe" + suffix, runs)
                # The site's player shows the same view, in a 16:9 box like the animations.
                player_box = picture_box(scene, [(r[0], r[1]) for r in runs], view, aspect=16 / 9, count=41)
                player_data.write(args.out / f"{path.stem}{suffix}.player.js", args.chapter, scene, runs,
                                  motion.read_series(series), view, player_box, motion.slow_motion_factor(scene.duration))
            except (RuntimeError, OSError, ValueError, KeyError) as error:
                print(f"strobe: error: {error}", file=sys.stderr)
                failures += 1
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
