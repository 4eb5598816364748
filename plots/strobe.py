#!/usr/bin/env python3
"""Strobe pictures: each scene's bodies drawn at evenly spaced times, earlier ones fainter.

For every chapters/<chapter>/scenes/*.json this runs the simulator once with --trajectory,
keeps <scene>.trajectory.csv and <scene>.trajectory.contacts.csv beside the figures (the
animations are drawn from them), and draws <scene>-strobe.svg, .pdf and .png: planes as
ground or walls, spheres as circles, boxes with their orientation, and at the first moment
of each touch the contact point, its normal (from body 2 towards body 1) and the size of the
impulse the responder gave. One metre is as long across as up. The view follows the rule in
plots/motion.py (choose_view). With --student the student's bodies are drawn over the
reference's, dashed, in another colour, as <scene>-strobe.student.*; with --no-reference (the
student edition) over the reference's motion shipped in chapters/<chapter>/reference-runs/
(plots/reference_runs.py), or alone, in the bodies' own colours, where none is shipped.

    strobe.py inelastic build/dev/book/figures/inelastic --sim build/dev/tools/workbook-sim
"""

import argparse
import sys
import tempfile
from pathlib import Path

from plots import motion
from plots import player_data
from plots import reference_runs

SNAPSHOTS = 9
ASPECT = 2.7  # width / height of the data box; the 12:5 canvas less its key and labels
# One character of label_font as fractions of the data box's width and height, on the
# strobe picture's canvas (style.gp's use_svg; the PNG and PDF are the same picture scaled).
TEXT_SIZE = (0.0105, 0.062)


def snapshot_times(duration, count=SNAPSHOTS):
    return [duration * k / (count - 1) for k in range(count)]


def snapshot_indices(trajectory, duration, count=SNAPSHOTS):
    return [trajectory.index_at(t) for t in snapshot_times(duration, count)]


FEWEST_SPREAD = 5  # outlines, when fewer make each larger (strobe_layout)


def strobe_layout(scene, runs, view, aspect=ASPECT, count=SNAPSHOTS):
    """(pitch, count): how far apart outlines are set side by side in time order (None: drawn
    where they are) and how many there are.

    Outlines are spread when no body moves across the picture (a ball dropped, a box landing
    or spinning in place), where they would otherwise lie on top of one another: the
    horizontal axis then counts time, the vertical one stays in metres, and every outline
    keeps the scale of the vertical axis. The pitch fills the picture's width and is at least
    a quarter more than the widest outline; when `count` outlines that far apart would not
    fit beside the motion's height, fewer (down to FEWEST_SPREAD) are drawn, larger."""
    moving = motion.movable(scene)
    size = max(motion.body_size(scene.bodies[i]) for i in moving)
    for trajectory, _ in runs:
        for i in moving:
            across = [states[i][0][view.h] for states in trajectory.states]
            if max(across) - min(across) > 0.01 * size:
                return None, count
    _, _, ymin, ymax = data_extent(scene, runs, view, count)
    widest = 0.0
    for trajectory, _ in runs:
        for k in range(len(trajectory.times)):
            shapes = [motion.outline(scene.bodies[i], *trajectory.states[k][i][:2], view) for i in moving]
            x0, x1, _, _ = motion.extent_of([s for s in shapes if s])
            widest = max(widest, x1 - x0)
    width = 0.9 * aspect * (ymax - ymin) * 1.3
    fit = int((width - widest) / (1.25 * widest)) + 1
    spread = max(FEWEST_SPREAD, min(count, fit))
    pitch = max(1.25 * widest, (width - widest) / (spread - 1))
    # A touch's arrow stands where it happened: at its time, moved across by the contact
    # point's own offset from the body. A wide body touching at both ends (a long box) can
    # bring two touches to one place that stand apart where they are: those stay in place.
    in_place = picture_box(scene, runs, view, aspect, count)
    spread_box = picture_box(scene, runs, view, aspect, spread, pitch)
    spread_clashes = clashes(scene, runs, view, pitch, spread, spread_box[1] - spread_box[0])
    if spread_clashes and spread_clashes >= clashes(scene, runs, view, None, count, in_place[1] - in_place[0]):
        return None, count
    return pitch, spread


def clashes(scene, runs, view, pitch, count, width):
    """How many pairs of a run's marked touches would stand within 4 % of the picture's
    width of each other (and so have their arrows on top of one another)."""
    found = 0
    for _, contacts in runs:
        marks = sorted(view_at(view, pitch, scene.duration, c["t"], count).project([c["x"], c["y"], c["z"]])[0]
                       for c in motion.marked_touches(scene, contacts))
        found += sum(1 for i, a in enumerate(marks) for b in marks[i + 1:] if b - a < 0.04 * width)
    return found


def view_at(view, pitch, duration, t, count):
    """The view in which the bodies at time t are drawn: moved across in proportion to t
    when the outlines are spread in time, the view itself otherwise."""
    if pitch is None:
        return view
    return motion.Shifted(view, pitch * t * (count - 1) / duration)


def data_extent(scene, runs, view, count=SNAPSHOTS, pitch=None):
    """(xmin, xmax, ymin, ymax) of every outline drawn and the planes' traces."""
    shapes = list(motion.plane_bounds(scene, runs[0][0], view))
    for trajectory, _ in runs:
        for t, k in zip(snapshot_times(scene.duration, count), snapshot_indices(trajectory, scene.duration, count)):
            where = view_at(view, pitch, scene.duration, t, count)
            for i in motion.movable(scene):
                position, axes, _ = trajectory.states[k][i]
                shapes.append(motion.outline(scene.bodies[i], position, axes, where))
    return motion.extent_of([s for s in shapes if s])


def picture_box(scene, runs, view, aspect=ASPECT, count=SNAPSHOTS, pitch=None):
    """A data box holding every drawn outline of every run, the planes' traces and room for the
    contact arrows, at width/height = aspect."""
    box = data_extent(scene, runs, view, count, pitch)
    # Room for the normal arrows and their labels: an eighth of the picture on every side
    # where there are touches to mark, a little otherwise.
    touches = any(contacts for _, contacts in runs)
    room = (0.12 if touches else 0.03) * max(box[1] - box[0], box[3] - box[2])
    return motion.fit_box(box[0] - room, box[1] + room, box[2] - room, box[3] + room, aspect, margin=0.02)


def draw_bodies(canvas, scene, trajectory, times, student=False, pitch=None):
    """Outlines at the given times, from faint (first) to full colour (last), with centre dots
    so that even a bullet of a few millimetres shows, and a box's own axes (motion.box_hands)."""
    n = len(times)
    for k, t in enumerate(times):
        index = trajectory.index_at(t)
        where = view_at(canvas.view, pitch, scene.duration, t, n)
        strength = 0.22 + 0.78 * (k / (n - 1) if n > 1 else 1.0)
        for i in motion.movable(scene):
            position, axes, _ = trajectory.states[index][i]
            shape = motion.outline(scene.bodies[i], position, axes, where)
            base = motion.STUDENT_COLOUR if student else motion.body_colour(scene, i)
            colour = motion.faded(base, strength)
            canvas.shape(shape, colour, None if student else colour, width=3.0 if student else 2.0, dashed=student,
                         opacity=0.05 + 0.12 * strength, hands=motion.box_hands(scene.bodies[i], position, axes, where))
            canvas.point(where.project(position), colour, size=0.5)


def draw_paths(scene, trajectory, view, pitch, count, student=False, name="path"):
    """With the outlines spread in time, each body's centre drawn as a thin line through them
    (its height against time): gnuplot datablocks and plot clauses."""
    if pitch is None:
        return [], []
    blocks, clauses = [], []
    for i in motion.movable(scene):
        heights = [view.project(states[i][0])[1] for states in trajectory.states]
        if max(heights) - min(heights) <= 0.01 * motion.body_size(scene.bodies[i]):
            continue  # a body that stays put has no path worth a line (it would hide a box's hands)
        points = [view_at(view, pitch, scene.duration, t, count).project(states[i][0])
                  for t, states in zip(trajectory.times, trajectory.states)]
        block = f"${name}{i}"
        blocks.append(f"{block} << EOD\n" + "\n".join(f"{x!r},{y!r}" for x, y in points) + "\nEOD")
        colour = motion.STUDENT_COLOUR if student else motion.body_colour(scene, i)
        clauses.append(f"{block} using 1:2 with lines lc rgb '{motion.faded(colour, 0.5)}' lw 1.2"
                       f"{' dt 2' if student else ''} notitle")
    return blocks, clauses


def draw_contacts(canvas, scene, contacts, box, student=False, label_side=1, pitch=None,
                  count=SNAPSHOTS, between=None, font="label_font", with_time=True):
    """At each touch's first step: the contact point, the normal as an arrow (from body 2
    towards body 1, into body 1), and J and t beside it (J alone without `with_time`), clear
    of the other labels. With `between` = (t0, t1), only the touches that began in that time
    (a film's frame). The student's touches are in their colour, their arrows dashed as their
    outlines are, with an open head, so that the reference's arrow at the same touch shows."""
    colour = motion.STUDENT_COLOUR if student else motion.CONTACT_COLOUR
    for c in motion.marked_touches(scene, contacts):
        if between and not between[0] <= c["t"] <= between[1]:
            continue
        where = view_at(canvas.view, pitch, scene.duration, c["t"], count)
        length = motion.normal_arrow_length(scene, c, box)
        point = where.project([c["x"], c["y"], c["z"]])
        normal = canvas.view.project([c["nx"], c["ny"], c["nz"]])
        size = (normal[0] ** 2 + normal[1] ** 2) ** 0.5 or 1.0
        end = (point[0] + length * normal[0] / size, point[1] + length * normal[1] / size)
        canvas.point(point, colour, size=1.0)
        canvas.arrow(point, end, colour, width=2.0 if student else 3.0, dashed=student)
        # Above the arrow (below for a student's, so the two do not meet); near an edge of the
        # picture the text runs inwards from there.
        middle = ((point[0] + end[0]) / 2, max(point[1], end[1]) if label_side > 0 else min(point[1], end[1]))
        where_x = (middle[0] - box[0]) / (box[1] - box[0])
        align = "left" if where_x < 0.3 else "right" if where_x > 0.7 else "center"
        text = motion.impulse_text(c["impulse"]) + (f" at t = {c['t']:.4g} s" if with_time else "")
        canvas.free_label(text, middle, colour, align, label_side, font)


def strobe_note(scene, view, snapshots=SNAPSHOTS, spread=False):
    step = scene.duration / (snapshots - 1)
    where = ", set side by side in time order" if spread else ""
    return f"{view.name}; outlines every {step:.4g} s from t = 0 to {scene.duration:.4g} s{where}, earlier ones fainter"


def strobe_title(scene):
    """The scene's title; for a sweep (a figure of several runs) the one run that is drawn."""
    if "sweep" in scene.spec:
        fraction = scene.spec.get("position_correction", {}).get("fraction")
        return f"{scene.title}: the motion at β = {fraction:g}" if fraction is not None else scene.title
    return scene.title


def strobe_commands(scene, runs, view, box, title, key=True, snapshots=SNAPSHOTS, note=True, pitch=None,
                    text_size=TEXT_SIZE, ytics=None):
    """gnuplot commands for one strobe panel. runs: [(trajectory, contacts, is_student)].
    `ytics`: the step between the vertical axis's tics (gnuplot's choice without it). A panel
    of a strip (not `key`) whose outlines are set side by side in time labels its touches
    with J alone, since its horizontal axis tells the time."""
    canvas = motion.Canvas(view, box, text_size)
    motion.draw_planes(canvas, scene, runs[0][0], view, box)
    blocks, paths = [], []
    for n, (trajectory, contacts, student) in enumerate(runs):
        draw_bodies(canvas, scene, trajectory, snapshot_times(scene.duration, snapshots), student, pitch)
        b, c = draw_paths(scene, trajectory, view, pitch, snapshots, student, f"path{n}_")
        blocks += b
        paths += c
    for n, (trajectory, contacts, student) in enumerate(runs):
        draw_contacts(canvas, scene, contacts, box, student, label_side=-1 if n else 1, pitch=pitch, count=snapshots,
                      font="label_font" if key else "note_font", with_time=key or pitch is None)
    if note:
        canvas.label(strobe_note(scene, view, snapshots, pitch is not None), (0.01, 0.965), "#404040",
                     font="note_font", coords="graph")
    g = ["set size ratio -1", "set style textbox opaque noborder margins 1, 0.5", f"set xrange [{box[0]!r}:{box[1]!r}]",
         f"set yrange [{box[2]!r}:{box[3]!r}]", f"set xlabel {motion.quote(view.xlabel)}", f"set ylabel {motion.quote(view.ylabel)}",
         f"set title {motion.quote(title)} font {'title_font' if key else 'label_font'} noenhanced",
         "set format x '%g'", "set format y '%g'"]
    if ytics:
        g += [f"set ytics {ytics!r}"]
    if pitch is not None:
        # The horizontal axis counts time: a tic under each outline, at its body's centre.
        centre = view.project(runs[0][0].states[0][motion.movable(scene)[0]][0])[0]
        times = snapshot_times(scene.duration, snapshots)
        names = [f"{t:.4g}" for t in times]
        if sum(len(n) + 2 for n in names) * text_size[0] > 0.6:  # crowded: every other tic is named
            names = [n if k % 2 == 0 else "" for k, n in enumerate(names)]
        tics = ", ".join(f"{motion.quote(n)} {view_at(view, pitch, scene.duration, t, snapshots).dx + centre!r}"
                         for n, t in zip(names, times))
        # A lone picture says how to read the axis; a strip's panels have their title for that.
        meaning = " (outlines side by side in time order, to the scale of the vertical axis)" if key else ""
        g += [f"set xtics ({tics})", "unset mxtics", f"set xlabel 't / s{meaning}'"]
    plot = ["NaN notitle"] + paths
    if key:
        for name, colour in motion.key_entries(scene):
            plot.append(f"NaN with lines lc rgb '{colour}' lw 4 title {motion.quote(name)}")
        if any(student for _, _, student in runs):
            plot.append(f"NaN with lines lc rgb '{motion.STUDENT_COLOUR}' lw 3 dt 2 title 'your code'")
        if any(motion.marked_touches(scene, run[1]) for run in runs):
            plot.append(f"NaN with vectors lc rgb '{motion.CONTACT_COLOUR}' lw 3 title 'contact normal, impulse J'")
    return g + canvas.panel(plot, blocks)


def draw(scene, out_dir, stem, runs):
    view = motion.choose_view(scene, [r[0] for r in runs])
    pitch, count = strobe_layout(scene, [(r[0], r[1]) for r in runs], view)
    box = picture_box(scene, [(r[0], r[1]) for r in runs], view, count=count, pitch=pitch)
    title = strobe_title(scene) + (" (your code)" if len(runs) == 1 and runs[0][2] else "")
    body = strobe_commands(scene, runs, view, box, title, snapshots=count, pitch=pitch)
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
                if not args.no_reference:
                    where = Path(scratch) if args.student else args.out
                    t, c = motion.simulate(args.sim, path, where / f"{path.stem}.trajectory.csv", stride)
                    runs.append((motion.Trajectory(t), motion.read_contacts(c), False))
                elif reference_runs.trajectory_path(path).is_file():  # the student edition: the shipped motion
                    t = reference_runs.trajectory_path(path)
                    runs.append((motion.Trajectory(t), motion.read_contacts(motion.contacts_path(t)), False))
                if args.student:
                    t, c = motion.simulate(args.student_sim, path, args.out / f"{path.stem}.student.trajectory.csv",
                                           stride)
                    # Dashed in the student's colour over the reference's; alone (a scene without
                    # a shipped reference) in the bodies' own colours, as the key lists them.
                    runs.append((motion.Trajectory(t), motion.read_contacts(c), bool(runs)))
                view, box = draw(scene, args.out, path.stem + "-strobe" + suffix, runs)
                # The site's player shows the same view, in a 16:9 box like the animations.
                player_box = picture_box(scene, [(r[0], r[1]) for r in runs], view, aspect=16 / 9, count=41)
                player_data.write(args.out / f"{path.stem}{suffix}.player.js", args.chapter, scene, runs, view,
                                  player_box, motion.slow_motion_factor(scene.duration))
            except (RuntimeError, OSError, ValueError, KeyError) as error:
                print(f"strobe: error: {error}", file=sys.stderr)
                failures += 1
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
