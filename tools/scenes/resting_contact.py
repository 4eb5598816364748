#!/usr/bin/env python3
"""Writes the scenes of chapter 5 (chapters/resting-contact/scenes/*.json).

The pile has a thousand bodies, too many to write by hand; the other scenes are written here
too so that every number of the chapter's scenes has one source. Run it again after a change:

    python3 tools/scenes/resting_contact.py
"""
import json
import math
import pathlib

OUT = pathlib.Path(__file__).resolve().parents[2] / "chapters" / "resting-contact" / "scenes"
GROUND = {"name": "ground", "shape": {"type": "plane", "normal": [0, 0, 1]}, "immovable": True, "position": [0, 0, 0],
          "restitution": 0.0}


def wall(name, normal, x):
    return {"name": name, "shape": {"type": "plane", "normal": normal}, "immovable": True, "position": [x, 0, 0],
            "restitution": 0.0}


def ball(name, x, z, radius=0.05, vx=0.0, vz=0.0, restitution=0.0, mass=1.0):
    return {"name": name, "shape": {"type": "sphere", "radius": radius}, "mass": mass, "position": [x, 0, z],
            "velocity": [vx, 0, vz], "restitution": restitution}


def box(name, x, z, half=0.1):
    return {"name": name, "shape": {"type": "box", "half_extents": [half, half, half]}, "mass": 1.0,
            "position": [x, 0, z], "restitution": 0.0}


def scene(title, description, bodies, duration, time_step=1 / 60, solver=None, correction=(0.5, 0.002)):
    result = {"title": title, "description": description, "responder": "resting-contact", "time_step": time_step,
              "duration": duration, "gravity": [0, 0, -9.81],
              "position_correction": {"fraction": correction[0], "slop": correction[1]}}
    if solver:
        result["contact_solver"] = solver
    result["bodies"] = bodies
    return result


def pile(count):
    """The pile of bench/pile.hpp: discs 2.4 radii apart on a loose grid, jittered sideways."""
    width = math.sqrt(count) * 0.1
    columns = max(1, int(width / 0.12))
    pitch = width / columns
    state = 23
    bodies = []
    for i in range(count):
        state = (state * 6364136223846793005 + 1442695040888963407) % 2**64
        jitter = ((state >> 11) / 9007199254740992.0 - 0.5) * 0.2 * 0.05
        column, row = i % columns, i // columns
        bodies.append(ball(f"disc {i + 1}", -width / 2 + pitch * (column + 0.5) + jitter, 0.06 + 0.12 * row))
    return bodies + [GROUND, wall("left wall", [1, 0, 0], -width / 2), wall("right wall", [-1, 0, 0], width / 2)]


def main():
    scenes = {
        "stack-of-10-boxes": scene(
            "A frictionless stack of ten 20 cm boxes, 60 s",
            "Ten boxes of 1 kg, 20 cm a side, stand on each other on the ground, frictionless. Each contact has "
            "four points, one under each corner, and the weight of the nine boxes above has to reach the ground "
            "in every step. Every normal is vertical, so nothing pushes a box sideways, and the stack stands "
            "for the whole minute: no box moves by more than a few nanometres. The first step has no impulses "
            "of the last one to start from and takes some 800 passes to carry the weight down.",
            [box(f"box {i + 1}", 0.0, 0.1 + 0.2 * i) for i in range(10)] + [GROUND], 60.0,
            solver={"velocity_iterations": 1000}),
        "column-of-15-balls": scene(
            "A column of fifteen balls resting for 60 s",
            "Fifteen balls of 1 kg and 5 cm radius stand on each other in a line on the ground, frictionless. "
            "One pass of impulses would leave the lower ones sinking; the solver's passes carry the weight of "
            "each ball down to the ground.",
            [ball(f"ball {i + 1}", 0.0, 0.05 + 0.1 * i) for i in range(15)] + [GROUND], 60.0),
        "pyramid-of-balls": scene(
            "A pyramid of 21 balls between two walls",
            "Six balls on the ground between two walls, five on them, and so on up to one: each ball rests on "
            "two below it and pushes them apart, which the walls hold.",
            [ball(f"ball {row + 1}.{k + 1}", -0.25 + 0.05 * row + 0.1 * k, 0.05 + row * 0.1 * math.sqrt(3) / 2)
             for row in range(6) for k in range(6 - row)]
            + [GROUND, wall("left wall", [1, 0, 0], -0.3), wall("right wall", [-1, 0, 0], 0.3)], 10.0),
        "pile-of-1000-discs": scene(
            "A pile of 1,000 discs dropped into a box",
            "A thousand frictionless discs of 5 cm radius and 1 kg (e = 0) fall from a loose grid into a box "
            "3.16 m wide and settle into a pile: the benchmark of the chapter, where every disc touches up to six.",
            pile(1000), 3.0),
        "stack-knocked-over": scene(
            "A stack of five boxes knocked over by a ball",
            "A stack of five boxes stands on the ground for half a second; then a 2 kg ball at 6 m/s hits the "
            "fourth box. The stack comes apart, and without friction the boxes slide on along the ground.",
            [box(f"box {i + 1}", 0.0, 0.1 + 0.2 * i) for i in range(5)] + [GROUND]
            + [ball("ball", -1.5, 0.93, radius=0.1, vx=6.0, vz=0.0, mass=2.0)], 4.0,
            solver={"velocity_iterations": 300}),
    }
    OUT.mkdir(parents=True, exist_ok=True)
    for name, content in scenes.items():
        text = json.dumps(content, indent=1) if name != "pile-of-1000-discs" else json.dumps(content)
        (OUT / f"{name}.json").write_text(text + "\n")


if __name__ == "__main__":
    main()
