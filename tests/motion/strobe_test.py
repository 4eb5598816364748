#!/usr/bin/env python3
"""Checks the strobe pictures (plots/strobe.py) against the trajectories they are drawn from.

- The view rule: a scene with gravity is seen from the side with up against gravity, across
  the axis they move along or, when they move along none, the one they turn about least;
  one without gravity is seen across the two axes the bodies move along, from the side when
  the ground faces up in it.
- Nothing is cut off: every outline drawn lies inside the picture's box, and the box has the
  aspect asked for (with `set size ratio -1`, one metre across equals one metre up); the
  outlines are set side by side in time exactly where nothing moves across.
- Boxes turn truthfully: the spinning cube's +x hand stands at 5 t radians before it hits.
- Labels of touches at one place do not cover one another.
- The marked contacts are the touches' first steps, with the impulse of the trajectory file:
  in the head-on carts, one touch at t = 0.2 s with J = mu |v1 - v2| = 2/3 kg * 3 m/s = 2 N s;
  chapter 5's resting contacts are not marked.
- Every scene of every chapter gets an SVG, a PDF and a PNG of the stated size. In the
  sanitizer build (--sanitized) the heavy scenes (plots/motion.py: is_heavy) are left out:
  drawing them is Python and gnuplot, the same in both builds, and a thousand discs take the
  most of a minute; the dev build's run draws every scene, and motion.trajectory runs the
  heavy scenes under the sanitizers.

    strobe_test.py --sim build/dev/tools/workbook-sim --source .
"""

import argparse
import json
import math
import struct
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
    parser.add_argument("--student-sim", type=Path, required=True)
    parser.add_argument("--sanitized", action="store_true", help="the sanitizer build: heavy scenes left out")
    args = parser.parse_args()
    from plots import motion, strobe  # run from the workbook's folder (ctest does)

    scenes_dir = args.source / "chapters" / "inelastic" / "scenes"
    with tempfile.TemporaryDirectory() as scratch:
        scratch = Path(scratch)
        loaded = {}
        for path in sorted(scenes_dir.glob("*.json")):
            scene = motion.Scene(path)
            t, c = motion.simulate(args.sim, path, scratch / f"{path.stem}.trajectory.csv", motion.stride_for(scene.spec))
            loaded[path.stem] = (scene, motion.Trajectory(t), motion.read_contacts(c))

        # The view rule.
        scene, trajectory, _ = loaded["clay-drop"]
        view = motion.choose_view(scene, [trajectory])
        check((view.h, view.v, view.name, view.sign_v) == (0, 1, "side view", 1.0), f"clay-drop view {vars(view)}")
        scene, trajectory, _ = loaded["car-crash"]
        view = motion.choose_view(scene, [trajectory])
        check((view.h, view.v, view.name) == (0, 1, "top view"), f"car-crash view {vars(view)}")
        spec = dict(loaded["clay-drop"][0].spec, gravity=[0, 0, 9.81])
        upside = motion.choose_view(motion.Scene(scenes_dir / "clay-drop.json", spec), [loaded["clay-drop"][1]])
        check((upside.v, upside.sign_v) == (2, -1.0), f"gravity +z should give up = -z, got {vars(upside)}")

        # Boxes (chapter 4) are drawn by their axes (as the simulator writes them): the outline of
        # the projected corners. A box turned by `angle` about z has these axes.
        box_body = {"shape": {"type": "box", "half_extents": [1.0, 0.5, 0.25]}}
        top = motion.View(0, 1, "top view")
        for angle, half_x, half_y in ((0.0, 1.0, 0.5), (90.0, 0.5, 1.0), (45.0, 1.5 / math.sqrt(2), 1.5 / math.sqrt(2))):
            c, s = math.cos(math.radians(angle)), math.sin(math.radians(angle))
            shape = motion.outline(box_body, [2.0, 3.0, 0.0], [[c, s, 0.0], [-s, c, 0.0], [0.0, 0.0, 1.0]], top)
            x0, x1, y0, y1 = motion.extent_of([shape])
            corners = len(shape[1])
            check(shape[0] == "polygon" and corners == 4, f"box at {angle} degrees: {corners} corners, expected 4")
            for got, want in ((x0, 2 - half_x), (x1, 2 + half_x), (y0, 3 - half_y), (y1, 3 + half_y)):
                check(abs(got - want) < 1e-12, f"box at {angle} degrees spans {x0}..{x1}, {y0}..{y1}")

        # Nothing cut off, aspect kept; outlines set side by side in time where nothing moves across.
        for path in ("angular-impulse/long-box-drop", "angular-impulse/box-lands-flat-one-by-one",
                     "angular-impulse/tennis-racket", "angular-impulse/spinning-box-hits-box", "linear-impulse/bouncing-ball"):
            chapter, stem = path.split("/")
            scene = motion.Scene(args.source / "chapters" / chapter / "scenes" / f"{stem}.json")
            t, c = motion.simulate(args.sim, scene.path, scratch / f"{stem}.trajectory.csv", motion.stride_for(scene.spec))
            loaded[stem] = (scene, motion.Trajectory(t), motion.read_contacts(c))
        spread = {"clay-drop", "bouncing-ball", "box-lands-flat-one-by-one", "tennis-racket"}
        for name, (scene, trajectory, contacts) in loaded.items():
            view = motion.choose_view(scene, [trajectory])
            pitch, count = strobe.strobe_layout(scene, [(trajectory, contacts)], view)
            check((pitch is not None) == (name in spread), f"{name}: outlines {'' if pitch else 'not '}set side by side")
            box = strobe.picture_box(scene, [(trajectory, contacts)], view, count=count, pitch=pitch)
            aspect = (box[1] - box[0]) / (box[3] - box[2])
            check(abs(aspect - strobe.ASPECT) < 1e-9 * strobe.ASPECT, f"{name}: box aspect {aspect}")
            for t in strobe.snapshot_times(scene.duration, count):
                k = trajectory.index_at(t)
                where = strobe.view_at(view, pitch, scene.duration, t, count)
                for i in motion.movable(scene):
                    position, axes, _ = trajectory.states[k][i]
                    x0, x1, y0, y1 = motion.extent_of([motion.outline(scene.bodies[i], position, axes, where)])
                    check(box[0] < x0 and x1 < box[1] and box[2] < y0 and y1 < box[3],
                          f"{name}: body {i} at frame {k} ({x0}..{x1}, {y0}..{y1}) leaves the box {box}")

        # The view shows how boxes turn: a box tipping about x is seen across y, a long box
        # dropped on the ground without gravity is seen from the side, ground down.
        for name, want in (("box-lands-flat-one-by-one", (1, 2, "side view", 1.0)), ("long-box-drop", (0, 2, "side view", 1.0)),
                           ("tennis-racket", (0, 1, "top view", 1.0)), ("clay-drop", (0, 1, "side view", 1.0))):
            scene, trajectory, _ = loaded[name]
            view = motion.choose_view(scene, [trajectory])
            check((view.h, view.v, view.name, view.sign_v) == want, f"{name}: view {vars(view)}, expected {want}")

        # A box's hands turn with it, the right way: the spinning cube (5 rad/s about +z, seen
        # from above) has turned its +x hand 5 t radians anticlockwise before the impact.
        scene, trajectory, _ = loaded["spinning-box-hits-box"]
        view = motion.choose_view(scene, [trajectory])
        for t in (0.02, 0.05, 0.08):
            k = trajectory.index_at(t)
            position, axes, _ = trajectory.states[k][0]
            (cx, cy), (hx, hy) = motion.box_hands(scene.bodies[0], position, axes, view)[0]
            turned = math.atan2(hy - cy, hx - cx)
            check(abs(turned - 5.0 * trajectory.times[k]) < 1e-9 * 5.0 * trajectory.times[k] + 1e-12,
                  f"spinning cube at t = {trajectory.times[k]} s: +x hand at {turned} rad, expected {5.0 * trajectory.times[k]}")
            check(abs(math.hypot(hx - cx, hy - cy) - 0.2) < 1e-12, "the +x hand is not as long as the half extent")

        # Labels of touches at one place are kept apart, inside the picture.
        canvas = motion.Canvas(motion.View(0, 1, "top view"), (0.0, 10.0, 0.0, 4.0), strobe.TEXT_SIZE)
        for n in range(4):
            canvas.free_label(f"J = {n} N s at t = 0.2 s", (5.0, 1.0), "#000000")
        ys = sorted(y for _, _, y in canvas.taken)
        line = strobe.TEXT_SIZE[1] * 4.0
        check(all(b - a >= 1.2 * line for a, b in zip(ys, ys[1:])), f"labels at one place overlap: {ys}")
        check(all(0.0 < y < 4.0 for y in ys), f"labels leave the picture: {ys}")

        # The marked contact of the head-on carts.
        onsets = motion.contact_onsets(loaded["head-on-carts"][2])
        check(len(onsets) == 1, f"head-on carts: {len(onsets)} touches marked, expected 1")
        if onsets:
            check(abs(onsets[0]["t"] - 0.2) < 1e-9, f"head-on carts: touch at t = {onsets[0]['t']}")
            check(abs(onsets[0]["impulse"] - 2.0) < 1e-12, f"head-on carts: J = {onsets[0]['impulse']}, expected 2 N s")
        # Chapter 5's contacts rest: a touch's first impulse is a step's share of the weight, not
        # an impact's answer, and its pictures mark none (a chapter 1 scene's touch is marked).
        knocked = args.source / "chapters/resting-contact/scenes/stack-knocked-over.json"
        resting = motion.Scene(knocked)
        t, c = motion.simulate(args.sim, knocked, scratch / "stack-knocked-over.trajectory.csv", motion.stride_for(resting.spec))
        check(len(motion.contact_onsets(motion.read_contacts(c))) > 0, "the knocked-over stack has no touch at all")
        check(motion.marked_touches(resting, motion.read_contacts(c)) == [], "a resting-contact scene's touches are marked")
        check(len(motion.marked_touches(loaded["head-on-carts"][0], loaded["head-on-carts"][2])) == 1,
              "head-on carts: marked_touches() should keep its one touch")
        drop = motion.contact_onsets(loaded["clay-drop"][2])
        check(len(drop) == 1, f"clay drop: resting contact should be marked once, got {len(drop)}")

        # The chapter page's strobe captions state when each touch began: the marked onsets' times.
        import re
        page = (args.source / "chapters/inelastic/chapter.md").read_text()
        captions = re.findall(r'figurefile\{inelastic/([a-z-]+)-strobe\} "([^"]*)"', page)
        chapter_one = len(list(scenes_dir.glob("*.json")))
        check(len(captions) == chapter_one, f"chapter.md shows {len(captions)} strobe pictures, there are {chapter_one} scenes")
        for stem, caption in captions:
            stated = [float(t) for t in re.findall(r"t = ([0-9.]+) s", caption)]
            marked = [c["t"] for c in motion.contact_onsets(loaded[stem][2])]
            check(all(any(abs(s - m) <= 0.5 * 10 ** -len(f"{s}".split(".")[-1]) + 1e-12 for m in marked) for s in stated),
                  f"chapter.md: the caption of {stem}-strobe states t = {stated}, the touches begin at {marked}")

        # Every scene of every chapter drawn, in three formats.
        chapters = [line.split("#")[0].strip() for line in (args.source / "chapters/CHAPTERS").read_text().splitlines()]
        for chapter in filter(None, chapters):
            out = scratch / chapter
            command = [sys.executable, "-m", "plots.strobe", chapter, str(out), "--sim", str(args.sim)]
            drawn = sorted((args.source / "chapters" / chapter / "scenes").glob("*.json"))
            if args.sanitized:  # the heavy scenes are drawn by the dev build's run only
                drawn = [path for path in drawn if not motion.is_heavy(json.loads(path.read_text()))]
                if not drawn:
                    continue
                command += [arg for path in drawn for arg in ("--scene", str(path))]
            result = subprocess.run(command, capture_output=True, text=True)
            check(result.returncode == 0, f"strobe.py {chapter} failed: {result.stderr}")
            for path in drawn:
                for ext in ("svg", "pdf", "png"):
                    check((out / f"{path.stem}-strobe.{ext}").stat().st_size > 1000 if (out / f"{path.stem}-strobe.{ext}").exists()
                          else False, f"{chapter}: no {path.stem}-strobe.{ext}")
                png = out / f"{path.stem}-strobe.png"
                if png.exists():
                    width, height = struct.unpack(">II", png.read_bytes()[16:24])
                    check((width, height) == (1800, 750), f"{png.name} is {width}x{height}, expected 1800x750")

    # --student: the student's run drawn over the reference's, from the student's simulator.
    with tempfile.TemporaryDirectory() as out:
        out = Path(out)
        scene = scenes_dir / "head-on-carts.json"
        result = subprocess.run([sys.executable, "-m", "plots.strobe", "inelastic", str(out), "--scene",
                                 str(scene), "--sim", str(args.sim), "--student", "--student-sim", str(args.student_sim)],
                                capture_output=True, text=True)
        check(result.returncode == 0, f"strobe.py --student failed: {result.stderr}")
        for ext in ("svg", "pdf", "png"):
            check((out / f"head-on-carts-strobe.student.{ext}").exists(), f"no head-on-carts-strobe.student.{ext}")
        check(not (out / "head-on-carts-strobe.svg").exists(), "--student overwrote the reference's picture")
        direct = out / "direct.csv"
        motion.simulate(args.student_sim, scene, direct)
        check((out / "head-on-carts.student.trajectory.csv").read_text() == direct.read_text(),
              "the student's trajectory is not the student simulator's")
        svg = (out / "head-on-carts-strobe.student.svg").read_text()
        rgb = ", ".join(f"{int(motion.STUDENT_COLOUR[i:i + 2], 16):3d}" for i in (1, 3, 5))
        check(svg.count(f"stroke='rgb({rgb})' stroke-dasharray") >= 3,
              f"the student's bodies are not drawn dashed in rgb({rgb}) (the key and at least one outline)")
        data = (out / "head-on-carts.student.player.js").read_text()
        check('"student":true' in data and '"student":false' in data, "the player data lacks one of the two runs")

    for f in failures:
        print("FAIL:", f)
    print(f"{len(failures)} failures")
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
