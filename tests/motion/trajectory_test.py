#!/usr/bin/env python3
"""Checks `workbook-sim run SCENE --trajectory OUT.csv [--stride K]` on every scene of every chapter.

- Both headers are the documented ones (docs/scene-format.md), character for character.
- The first frame is the scene file's initial state; the last frame is the final state: its
  time, momentum and kinetic energy equal the last row of the --csv time series and the
  summary's final numbers.
- With --stride K the frames are 0, K, 2K, ... and the last, each row equal to the same
  frame's row of the stride-1 run.
- Each contact's impulse equals body 1's change of momentum along the normal in that step,
  less what gravity added (the position corrector moves positions only).

- In the sanitizer build (--sanitized) a heavy scene (plots/motion.py: is_heavy) runs its
  first half second only, from a copy of its file: the dev build's run checks every scene whole.

    python3 -m tests.motion.trajectory_test --sim build/dev/tools/workbook-sim --source . [--sanitized]
"""

import argparse
import csv
import json
import math
import re
import subprocess
import sys
import tempfile
from pathlib import Path

from plots import motion  # run from the workbook's folder (ctest does)

TRAJECTORY_HEADER = "frame,t,body,name,x,y,z,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz,ex_x,ex_y,ex_z,ey_x,ey_y,ey_z,ez_x,ez_y,ez_z"
CONTACTS_HEADER = "frame,t,body1,body2,point,x,y,z,nx,ny,nz,depth,impulse"
STRIDE = 7

failures = []


def check(condition, message):
    if not condition:
        failures.append(message)


def close(a, b, scale, rel=1e-12):
    """Equal to rounding: within `rel` of the magnitudes in play."""
    return abs(a - b) <= rel * max(abs(a), abs(b), scale)


def chapters(source):
    text = (source / "chapters" / "CHAPTERS").read_text()
    return [line.split("#")[0].strip() for line in text.splitlines() if line.split("#")[0].strip()]


def run(sim, scene, out, stride=None):
    command = [str(sim), "run", str(scene), "--trajectory", str(out / "traj.csv"), "--csv", str(out / "series.csv")]
    if stride:
        command += ["--stride", str(stride)]
    result = subprocess.run(command, capture_output=True, text=True, timeout=300)
    if result.returncode != 0:
        raise RuntimeError(f"{' '.join(command)} failed: {result.stderr}")
    lines = {name: (out / name).read_text().splitlines() for name in ("traj.csv", "traj.contacts.csv", "series.csv")}
    return result.stdout, lines


def rows(lines):
    return list(csv.DictReader(lines))


def initial_orientation(spec):
    """The unit quaternion (w, x, y, z) a scene's "orientation" stands for (docs/scene-format.md)."""
    if spec is None:
        return [1.0, 0.0, 0.0, 0.0]
    if "quaternion" in spec:
        q = [float(v) for v in spec["quaternion"]]
        size = math.sqrt(sum(v * v for v in q))
        return [v / size for v in q]
    axis = [float(v) for v in spec["axis"]]
    size = math.sqrt(sum(v * v for v in axis))
    half = math.radians(float(spec["angle_degrees"])) / 2
    return [math.cos(half)] + [math.sin(half) * v / size for v in axis]


def check_scene(sim, scene, scratch, sanitized=False):
    name = f"{scene.parent.parent.name}/{scene.name}"
    spec = json.loads(scene.read_text())
    if sanitized and motion.is_heavy(spec):
        spec = motion.for_sanitizers(spec)
        scene = scratch / f"sanitized-{scene.name}"
        scene.write_text(json.dumps(spec))
        name += f" (its first {spec['duration']:g} s)"
    summary, one = run(sim, scene, scratch)
    check(one["traj.csv"][0] == TRAJECTORY_HEADER, f"{name}: trajectory header is {one['traj.csv'][0]!r}")
    check(one["traj.contacts.csv"][0] == CONTACTS_HEADER, f"{name}: contacts header is {one['traj.contacts.csv'][0]!r}")
    bodies = rows(one["traj.csv"])
    series = rows(one["series.csv"])
    steps = len(series) - 1
    count = len(spec["bodies"])
    frames = sorted({int(r["frame"]) for r in bodies})
    check(frames == list(range(steps + 1)), f"{name}: stride 1 should record frames 0..{steps}")
    check(len(bodies) == count * (steps + 1), f"{name}: {len(bodies)} rows, expected {count * (steps + 1)}")

    # The body's own axes (what the pictures draw with): unit, at right angles, right-handed
    # (x cross y is z), to rounding, in every row.
    for row in bodies[:: max(1, len(bodies) // 200)]:
        ex, ey, ez = ([float(row[f"e{a}_{c}"]) for c in "xyz"] for a in "xyz")
        cross = [ex[1] * ey[2] - ex[2] * ey[1], ex[2] * ey[0] - ex[0] * ey[2], ex[0] * ey[1] - ex[1] * ey[0]]
        dots = [sum(a * b for a, b in zip(u, v)) for u, v in ((ex, ex), (ey, ey), (ez, ez), (ex, ey), (ey, ez), (ez, ex))]
        check(all(abs(d - (1.0 if k < 3 else 0.0)) <= 1e-12 for k, d in enumerate(dots)) and
              all(abs(a - b) <= 1e-12 for a, b in zip(cross, ez)),
              f"{name}: body {row['body']} at frame {row['frame']}: axes {ex}, {ey}, {ez} are not a rotation")

    # First frame: the scene file.
    for i, body in enumerate(spec["bodies"]):
        row = bodies[i]
        check(int(row["frame"]) == 0 and int(row["body"]) == i, f"{name}: row {i} should be body {i} at frame 0")
        check(row["name"] == body.get("name", f"bodies[{i}]"), f"{name}: body {i} is named {row['name']!r}")
        for key, columns in (("position", "xyz"), ("velocity", ("vx", "vy", "vz")),
                             ("angular_velocity", ("wx", "wy", "wz"))):
            expected = body.get(key, [0, 0, 0])
            actual = [float(row[c]) for c in columns]
            check(actual == [float(v) for v in expected], f"{name}: body {i} {key} starts at {actual}, scene says {expected}")
        q = [float(row[c]) for c in ("qw", "qx", "qy", "qz")]
        expected_q = initial_orientation(body.get("orientation"))
        check(all(abs(a - b) <= 1e-15 for a, b in zip(q, expected_q)),
              f"{name}: body {i} orientation starts at {q}, scene says {expected_q}")

    # Last frame: the time series' and the summary's final state.
    last = bodies[-count:]
    final = series[-1]
    check(all(int(r["frame"]) == steps for r in last), f"{name}: the last rows are not frame {steps}")
    check(float(last[0]["t"]) == float(final["t"]), f"{name}: last frame at t = {last[0]['t']}, series ends at {final['t']}")
    masses = [b.get("mass") if not b.get("immovable") else None for b in spec["bodies"]]
    momentum = [sum(m * float(r[c]) for m, r in zip(masses, last) if m) for c in ("vx", "vy", "vz")]
    kinetic = sum(0.5 * m * sum(float(r[c]) ** 2 for c in ("vx", "vy", "vz")) for m, r in zip(masses, last) if m)
    scale = max(abs(float(final[c])) for c in ("momentum_x", "momentum_y", "momentum_z")) or 1.0
    for axis, value in zip("xyz", momentum):
        check(close(value, float(final[f"momentum_{axis}"]), scale),
              f"{name}: final momentum_{axis} from the trajectory {value!r}, series {final[f'momentum_{axis}']}")
    check(close(kinetic, float(final["kinetic_linear"]), float(final["total"]) or 1.0),
          f"{name}: final kinetic energy from the trajectory {kinetic!r}, series {final['kinetic_linear']}")
    reported = re.search(r"total energy\s+\S+ J -> (\S+) J", summary)
    check(reported is not None and f"{kinetic + float(final['kinetic_rotational']) + float(final['potential']):.6f}" == reported.group(1),
          f"{name}: the summary's final energy {reported and reported.group(1)} is not the trajectory's")

    # Impulses: J = m1 ((v1' - v1) . n - dt g . n), in steps with one contact.
    gravity = spec.get("gravity", [0, 0, 0])
    dt = spec["time_step"]
    velocity = {(int(r["frame"]), int(r["body"])): [float(r[c]) for c in ("vx", "vy", "vz")] for r in bodies}
    contacts = rows(one["traj.contacts.csv"])
    per_step = {}
    for c in contacts:
        per_step.setdefault(int(c["frame"]), []).append(c)
    checked = 0
    for step, found in per_step.items():
        if len(found) != 1 or spec["responder"] == "none":
            continue
        c = found[0]
        b1 = int(c["body1"])
        if not masses[b1]:
            continue
        n = [float(c[k]) for k in ("nx", "ny", "nz")]
        dv = [a - b for a, b in zip(velocity[(step, b1)], velocity[(step - 1, b1)])]
        expected = masses[b1] * (sum(x * y for x, y in zip(dv, n)) - dt * sum(g * y for g, y in zip(gravity, n)))
        size = masses[b1] * math.sqrt(sum(v * v for v in velocity[(step - 1, b1)])) or 1.0
        check(close(float(c["impulse"]), expected, size, 1e-9),
              f"{name}: step {step}: impulse {c['impulse']}, body 1's momentum change says {expected!r}")
        checked += 1
    # A scene whose contacts always come several at a time (a ball between two others) has no
    # step in which one contact alone explains the momentum change.
    single = any(len(found) == 1 for found in per_step.values())
    check(checked > 0 or spec["responder"] == "none" or not single, f"{name}: no contact with an impulse to check")

    # Stride: frames 0, K, 2K, ... and the last, each identical to the stride-1 row.
    _, strided = run(sim, scene, scratch, STRIDE)
    by_frame = {}
    for line in one["traj.csv"][1:]:
        by_frame.setdefault(int(line.split(",", 1)[0]), []).append(line)
    expected_frames = sorted(set(range(0, steps + 1, STRIDE)) | {steps})
    got = {}
    for line in strided["traj.csv"][1:]:
        got.setdefault(int(line.split(",", 1)[0]), []).append(line)
    check(sorted(got) == expected_frames, f"{name}: stride {STRIDE} recorded frames {sorted(got)[:5]}..., expected {expected_frames[:5]}...")
    check(all(got[f] == by_frame[f] for f in got if f in by_frame), f"{name}: stride {STRIDE} rows differ from stride 1")
    check(strided["traj.contacts.csv"] == one["traj.contacts.csv"], f"{name}: the stride changed the contacts file")
    return steps, len(contacts)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--sim", type=Path, required=True)
    parser.add_argument("--source", type=Path, required=True)
    parser.add_argument("--sanitized", action="store_true", help="the sanitizer build: heavy scenes' first half second")
    args = parser.parse_args()
    scenes = [s for c in chapters(args.source) for s in sorted((args.source / "chapters" / c / "scenes").glob("*.json"))]
    check(len(scenes) > 0, "no scenes found")
    with tempfile.TemporaryDirectory() as scratch:
        for scene in scenes:
            steps, contacts = check_scene(args.sim, scene, Path(scratch), args.sanitized)
            print(f"{scene.parent.parent.name}/{scene.name}: {steps} steps, {contacts} contact rows")

    # A bad stride is refused.
    bad = subprocess.run([str(args.sim), "run", str(scenes[0]), "--trajectory", "/dev/null", "--stride", "0"],
                         capture_output=True, text=True)
    check(bad.returncode != 0 and "stride" in bad.stderr, f"--stride 0 was accepted: {bad.returncode} {bad.stderr!r}")

    # An unwritable trajectory is an error that names the file.
    missing = "/nonexistent-folder/out.csv"
    bad = subprocess.run([str(args.sim), "run", str(scenes[0]), "--trajectory", missing], capture_output=True, text=True)
    check(bad.returncode == 1 and missing in bad.stderr, f"an unwritable trajectory gave {bad.returncode} {bad.stderr!r}")

    for f in failures:
        print("FAIL:", f)
    print(f"{len(scenes)} scenes, {len(failures)} failures")
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
