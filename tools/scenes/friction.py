#!/usr/bin/env python3
"""Writes the scenes of chapter 6, friction (chapters/friction/scenes/*.json).

Each scene has a closed form the chapter's tests check (tests/chapters/friction_scenes.cpp);
their numbers have one source, here. Run it again after a change:

    python3 tools/scenes/friction.py
"""
import json
import math
import pathlib

OUT = pathlib.Path(__file__).resolve().parents[2] / "chapters" / "friction" / "scenes"
G = 9.81
HALF = 0.1  # the blocks' half extent, m
RADIUS = 0.1  # the balls' radius, m
# Every body starts just touching the ground; the first step's fall of g dt^2 makes the contact.
# A step of 1/240 s keeps that fall small (0.17 mm): the contact point lies halfway into it,
# g dt^2 / 2 above a ball's lowest point, which shortens the lever arm of its friction by
# 0.09 % of the radius (tests/chapters/friction_scenes.cpp predicts the motion with it).
TIME_STEP = 1 / 240


def ground(normal=(0, 0, 1), friction=0.0, static=None, restitution=0.0):
    body = {"name": "ground", "shape": {"type": "plane", "normal": list(normal)}, "immovable": True,
            "position": [0, 0, 0], "restitution": restitution, "friction": friction}
    if static is not None:
        body["static_friction"] = static
    return body


def block(friction, static=None, angle_degrees=0.0, velocity=(0, 0, 0)):
    """A 1 kg cube of 20 cm standing on a plane tilted by `angle_degrees` about y (downhill +x)."""
    a = math.radians(angle_degrees)
    normal = (math.sin(a), 0.0, math.cos(a))
    body = {"name": "block", "shape": {"type": "box", "half_extents": [HALF, HALF, HALF]}, "mass": 1.0,
            "position": [HALF * c for c in normal], "velocity": list(velocity), "restitution": 0.0,
            "friction": friction}
    if static is not None:
        body["static_friction"] = static
    if angle_degrees:
        body["orientation"] = {"axis": [0, 1, 0], "angle_degrees": angle_degrees}
    return body


def rod():
    """The page's rod (its energy example): 1 kg, 1 m x 10 cm x 10 cm, tilted 45 degrees about y
    with its end at +x lowest, just above the ground, at (-1, 0, -2) m/s; e = 1, friction 0.5."""
    a = math.radians(45.0)
    height = 0.5 * math.sin(a) + 0.05 * math.cos(a) + 0.01
    return {"name": "rod", "shape": {"type": "box", "half_extents": [0.5, 0.05, 0.05]}, "mass": 1.0,
            "position": [0, 0, height], "velocity": [-1.0, 0, -2.0], "restitution": 1.0, "friction": 0.5,
            "orientation": {"axis": [0, 1, 0], "angle_degrees": 45.0}}


def ball(friction, speed, spin=0.0):
    """A solid 1 kg ball of 10 cm radius on the ground moving along +x; `spin` about +y, rad/s
    (positive: the way it turns when rolling forward)."""
    return {"name": "ball", "shape": {"type": "sphere", "radius": RADIUS}, "mass": 1.0,
            "position": [0, 0, RADIUS], "velocity": [speed, 0, 0], "angular_velocity": [0, spin, 0],
            "restitution": 0.0, "friction": friction}


def scene(title, description, bodies, duration):
    return {"title": title, "description": description, "responder": "friction", "time_step": TIME_STEP,
            "duration": duration, "gravity": [0, 0, -G],
            "position_correction": {"fraction": 1.0, "slop": 0.0}, "bodies": bodies}


def box_stack(count, friction):
    """Chapter 5's stack: `count` 1 kg boxes of 20 cm standing on each other on the ground, each
    body (the ground too) with friction `friction`; one step of 1/60 s, as games run, with chapter
    5's correction (half the overlap beyond a 2 mm slop each step) and up to 300 velocity passes."""
    boxes = [{"name": f"box {i + 1}", "shape": {"type": "box", "half_extents": [HALF, HALF, HALF]}, "mass": 1.0,
              "position": [0.0, 0, HALF + 2 * HALF * i], "restitution": 0.0, "friction": friction}
             for i in range(count)]
    return boxes + [ground(friction=friction)]


def incline_normal(angle_degrees):
    a = math.radians(angle_degrees)
    return (math.sin(a), 0.0, math.cos(a))


def main():
    scenes = {
        "block-on-incline-sticks": scene(
            "A block on a 30° incline that sticks",
            "A 1 kg block rests on a 30° slope with static friction 0.7 and sliding friction 0.5. "
            "tan 30° = 0.577 is above the sliding coefficient but below the static one, so the block never "
            "starts to slide: friction holds it with m g sin 30° = 4.905 N, less than 0.7 m g cos 30° = 5.947 N.",
            [block(0.5, 0.7, 30.0), ground(incline_normal(30.0), 0.5, 0.7)], 2.0),
        "block-on-incline-slides": scene(
            "A block sliding down a 30° incline",
            "A 1 kg block starts at rest on a 30° slope with friction 0.3. tan 30° = 0.577 is above 0.3, so it "
            "slides, accelerating at g (sin 30° - 0.3 cos 30°) = 2.356 m/s^2 down the slope.",
            [block(0.3, None, 30.0), ground(incline_normal(30.0), 0.3)], 2.0),
        "box-sliding-to-rest": scene(
            "A box sliding to rest",
            "A 1 kg box slides at 3 m/s on flat ground with friction 0.5. Friction decelerates it at "
            "0.5 g = 4.905 m/s^2: it stops after 0.612 s and v^2 / (2 mu g) = 0.917 m, and stays.",
            [block(0.5, velocity=(3.0, 0, 0)), ground(friction=0.5)], 1.5),
        "ball-starts-rolling": scene(
            "A ball thrown without spin starts to roll",
            "A solid 1 kg ball of 10 cm radius is thrown along the ground at 3.5 m/s without spin, friction 0.2. "
            "It slides while friction slows it and spins it up, and rolls from t = 2 v0 / (7 mu g) = 0.51 s at "
            "5/7 of its speed, 2.5 m/s, for good.",
            [ball(0.2, 3.5), ground(friction=0.2)], 2.0),
        "ball-with-backspin": scene(
            "A ball with backspin comes back",
            "The same ball at 2 m/s with 60 rad/s of backspin (its surface turns at 6 m/s against its motion), "
            "friction 0.2. Friction slows it, stops it and brings it back: it rolls back at "
            "(5 v0 - 2 r w0) / 7 = -2/7 m/s from t = 2 (v0 + r w0) / (7 mu g) = 1.165 s.",
            [ball(0.2, 2.0, -60.0), ground(friction=0.2)], 3.0),
        "rod-lands-on-its-end": scene(
            "A rod lands on its end, e = 1 and friction 0.5",
            "A 1 kg rod, 1 m long and 10 cm thick, tilted 45°, falls at 2 m/s and drifts at 1 m/s, without "
            "spin, and lands on its lower end: restitution 1 and friction 0.5. Solved together with friction, "
            "Newton's restitution would send it off with more energy than it brought; the solver's two phases "
            "(the approach stopped with friction, then the bounce alone) never add any.",
            [rod(), ground(friction=0.5, restitution=1.0)], 1.5),
    }
    stack = scene(
        "A stack of ten 20 cm boxes resting for 60 s, friction 0.5",
        "Chapter 5's stack of ten 1 kg boxes, 20 cm a side, now with friction 0.5 on every box and the ground. "
        "Friction holds each box where it stands, and the stack rests for the whole minute (as chapter 5's "
        "does without friction).",
        box_stack(10, 0.5), 60.0)
    stack.update({"time_step": 1 / 60, "position_correction": {"fraction": 0.5, "slop": 0.002}})
    stack["contact_solver"] = {"velocity_iterations": 300}
    stack["bodies"] = stack.pop("bodies")  # the bodies last, as in every scene file
    scenes["stack-of-10-boxes-with-friction"] = stack
    OUT.mkdir(parents=True, exist_ok=True)
    for name, content in scenes.items():
        (OUT / f"{name}.json").write_text(json.dumps(content, indent=1) + "\n")


if __name__ == "__main__":
    main()
