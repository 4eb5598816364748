#!/usr/bin/env python3
"""Animations of a scene for lectures: <scene>.mp4 (H.264) and <scene>.gif.

Drawn from the trajectory files the strobe pictures left beside the figures
(<scene>.trajectory.csv and .contacts.csv; plots/strobe.py), never by running the
simulation again. Frames are rendered by gnuplot (pngcairo, 1280x720, plots/style.gp's
use_video) and joined by ffmpeg at 25 frames per second. Short scenes are slowed down by a
round factor (2, 5, 10, 20, 50, ...) so that every video lasts at least four seconds; the
factor is written in the picture ("slow motion ×10", or "real time"), with the simulated time.
The GIF is the same film at 640x360.

With --student the student's bodies (<scene>.student.trajectory.csv) are drawn over the
reference's, dashed, in another colour, as <scene>.student.mp4 and .gif; with
--no-reference (the student edition) over the reference's motion shipped in
chapters/<chapter>/reference-runs/, or alone where none is shipped.

    animate.py chapters/inelastic/scenes/head-on-carts.json build/dev/book/figures/inelastic
"""

import argparse
import json
import subprocess
import sys
import tempfile
from pathlib import Path

from plots import motion
from plots import reference_runs
from plots import strobe

FPS = 25
SIZE = (1280, 720)
GIF_WIDTH = 640
ASPECT = 2.25   # width / height of the data box in a 16:9 frame with title and key
TEXT_SIZE = (0.014, 0.066)  # one character of label_font, as fractions of the data box (strobe.TEXT_SIZE)


slow_motion_factor = motion.slow_motion_factor


def frame_times(duration, factor):
    """Simulated time of each frame: 1/(FPS factor) apart, from 0 to the end of the run."""
    count = round(duration * factor * FPS)
    return [duration * k / count for k in range(count + 1)]


LONGEST_TITLE_LINE = 60  # characters that fit across a 1280 px frame at title_font, with room


def wrapped(title, width=LONGEST_TITLE_LINE):
    """The title on two lines when it is too long for one, broken after a colon or comma."""
    if len(title) <= width:
        return title
    breaks = [i + 1 for i, c in enumerate(title[:width]) if c in ":," and title[i + 1:i + 2] == " "]
    cut = breaks[-1] if breaks else title.rfind(" ", 0, width)
    return title[:cut].rstrip() + "\n" + title[cut:].lstrip() if cut > 0 else title


def speed_text(factor):
    return "real time" if factor == 1 else f"slow motion ×{factor}"


def trail_blocks(scene, runs, view):
    """The paths of the bodies' centres, as gnuplot datablocks: for each run and each colour of
    its trails, a block of rows (x, y) for each body of that colour, one row for each frame of
    the trajectory, the blocks apart by a blank line. Each frame draws them up to its own row
    (`every`), so the film's script holds each path once, not once a frame (a pile of 1,000
    discs had a script of hundreds of MB). One colour a datablock, not a colour column: a
    dashed line keeps its dashes only when drawn as one line.
    Returns (datablocks, [(name, run, colour)])."""
    blocks, trails = [], []
    for n, (trajectory, _, student) in enumerate(runs):
        by_colour = {}
        for i in motion.movable(scene):
            colour = motion.faded(motion.STUDENT_COLOUR if student else motion.body_colour(scene, i), 0.45)
            by_colour.setdefault(colour, []).append("\n".join(
                f"{x!r},{y!r}" for x, y in (view.project(states[i][0]) for states in trajectory.states)))
        for k, (colour, paths) in enumerate(by_colour.items()):
            name = f"$trail{n}_{k}"
            blocks.append(f"{name} << EOD\n" + "\n\n".join(paths) + "\nEOD")
            trails.append((name, n, colour))
    return blocks, trails


def frame_commands(scene, runs, view, box, t, factor, trails):
    """One frame: planes, each body's path so far (`trails` of trail_blocks), the bodies at
    time t, the touches so far."""
    canvas = motion.Canvas(view, box, TEXT_SIZE)
    motion.draw_planes(canvas, scene, runs[0][0], view, box)
    plot = ["NaN notitle"]
    for n, (trajectory, contacts, student) in enumerate(runs):
        index = trajectory.index_at(t)
        plot += [f"{name} every ::0::{index} using 1:2 with lines lc rgb '{colour}' lw 1.5{' dt 2' if student else ''} "
                 "notitle" for name, run, colour in trails if run == n]
        for i in motion.movable(scene):
            colour = motion.STUDENT_COLOUR if student else motion.body_colour(scene, i)
            position, axes, _ = trajectory.states[index][i]
            shape = motion.outline(scene.bodies[i], position, axes, view)
            canvas.shape(shape, colour, None if student else colour, width=3.5 if student else 2.5, dashed=student,
                         opacity=0.25, hands=motion.box_hands(scene.bodies[i], position, axes, view))
            canvas.point(view.project(position), colour, size=0.5)
        between = (t - motion.touch_window(scene.duration), t + 1e-12)
        strobe.draw_contacts(canvas, scene, contacts, box, student, label_side=-1 if n else 1, between=between)
    canvas.label(f"t = {t:.4f} s", (0.01, 0.95), "#202020", coords="graph")
    canvas.label(f"{view.name} · {speed_text(factor)}", (0.99, 0.95), "#202020", align="right", coords="graph")
    for name, colour in motion.key_entries(scene):
        plot.append(f"NaN with lines lc rgb '{colour}' lw 4 title {motion.quote(name)}")
    if any(student for _, _, student in runs):
        plot.append(f"NaN with lines lc rgb '{motion.STUDENT_COLOUR}' lw 3 dt 2 title 'your code'")
    return canvas.panel(plot)


def render(scene, runs, out_stem, frames_dir):
    view = motion.choose_view(scene, [r[0] for r in runs])
    box = strobe.picture_box(scene, [(r[0], r[1]) for r in runs], view, aspect=ASPECT, count=41)
    factor = slow_motion_factor(scene.duration)
    times = frame_times(scene.duration, factor)
    script = ["reset", f"load {motion.quote(str(motion.STYLE))}", "eval use_video", "set size ratio -1",
              "set style textbox opaque noborder margins 1, 0.5",
              f"set xrange [{box[0]!r}:{box[1]!r}]", f"set yrange [{box[2]!r}:{box[3]!r}]",
              f"set xlabel {motion.quote(view.xlabel)}", f"set ylabel {motion.quote(view.ylabel)}",
              f"set title {motion.quote(wrapped(strobe.strobe_title(scene)))} font title_font noenhanced",
              "set format x '%g'", "set format y '%g'", "set key outside bottom center horizontal"]
    blocks, trails = trail_blocks(scene, runs, view)
    script += blocks
    for k, t in enumerate(times):
        script.append(f"set output {motion.quote(str(frames_dir / f'frame{k:05d}.png'))}")
        script += frame_commands(scene, runs, view, box, t, factor, trails)
        script.append("unset output")
    motion.run_gnuplot("\n".join(script) + "\n", scene.path.name)
    pattern = str(frames_dir / "frame%05d.png")
    ffmpeg = ["ffmpeg", "-loglevel", "error", "-y", "-framerate", str(FPS), "-i", pattern]
    subprocess.run(ffmpeg + ["-c:v", "libx264", "-pix_fmt", "yuv420p", "-crf", "20", "-movflags", "+faststart",
                             "-r", str(FPS), f"{out_stem}.mp4"], check=True)
    subprocess.run(ffmpeg + ["-vf", f"scale={GIF_WIDTH}:-1:flags=lanczos,split[a][b];[a]palettegen[p];[b][p]paletteuse",
                             "-r", str(FPS), f"{out_stem}.gif"], check=True)
    return factor, len(times)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("scene", type=Path, help="the scene file")
    parser.add_argument("out", type=Path, help="the chapter's figures folder, holding the trajectories")
    parser.add_argument("--student", action="store_true", help="draw the student's bodies over the reference's")
    parser.add_argument("--no-reference", action="store_true", help="no reference solutions: the student's alone")
    args = parser.parse_args()
    scene = motion.Scene(args.scene)
    stem = args.scene.stem
    runs = []
    try:
        if not args.no_reference:
            t = args.out / f"{stem}.trajectory.csv"
            runs.append((motion.Trajectory(t), motion.read_contacts(motion.contacts_path(t)), False))
        elif reference_runs.trajectory_path(args.scene).is_file():  # the student edition: the shipped motion
            t = reference_runs.trajectory_path(args.scene)
            runs.append((motion.Trajectory(t), motion.read_contacts(motion.contacts_path(t)), False))
        if args.student or args.no_reference:
            t = args.out / f"{stem}.student.trajectory.csv"
            # Alone (no reference motion at all) the bodies keep their own colours, as the key lists them.
            runs.append((motion.Trajectory(t), motion.read_contacts(motion.contacts_path(t)), bool(runs)))
        out_stem = args.out / (stem + (".student" if args.student or args.no_reference else ""))
        with tempfile.TemporaryDirectory() as frames:
            factor, count = render(scene, runs, out_stem, Path(frames))
        print(f"animate: {args.scene.name} -> {out_stem}.{{mp4,gif}}: {count} frames at {FPS} fps, "
              f"{count / FPS:.2f} s, {speed_text(factor)}")
        (args.out / f"{out_stem.name}.video.json").write_text(json.dumps(
            {"frames": count, "fps": FPS, "seconds": count / FPS, "slow_motion": factor,
             "width": SIZE[0], "height": SIZE[1], "gif_width": GIF_WIDTH}) + "\n")
    except (RuntimeError, OSError, ValueError, KeyError, subprocess.CalledProcessError) as error:
        sys.exit(f"animate: error: {error}")


if __name__ == "__main__":
    main()
