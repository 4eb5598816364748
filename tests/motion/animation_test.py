#!/usr/bin/env python3
"""Makes one animation (the head-on carts) and checks it with ffprobe: the stated size, frame
rate, frame count and length, and the slow-motion factor written beside it.

    animation_test.py --sim build/dev/tools/workbook-sim --source .
"""

import argparse
import json
import subprocess
import sys
import tempfile
from pathlib import Path

failures = []


def check(condition, message):
    if not condition:
        failures.append(message)


def probe(path):
    result = subprocess.run(["ffprobe", "-v", "error", "-count_frames", "-show_entries",
                             "stream=codec_name,width,height,r_frame_rate,nb_read_frames:format=duration", "-of", "json",
                             str(path)], capture_output=True, text=True, check=True)
    info = json.loads(result.stdout)
    return info["streams"][0], float(info["format"]["duration"])


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--sim", type=Path, required=True)
    parser.add_argument("--source", type=Path, required=True)
    args = parser.parse_args()
    from plots import animate, motion  # run from the workbook's folder (ctest does)

    # The slow-motion rule: the smallest round factor giving at least four seconds of film.
    for duration, factor in ((0.4, 10), (0.9, 5), (2.0, 2), (0.01, 500), (6.0, 1), (0.5, 10)):
        check(animate.slow_motion_factor(duration) == factor,
              f"slow motion for {duration} s is {animate.slow_motion_factor(duration)}, expected {factor}")

    # Long titles are broken after a colon or comma so that they fit across the frame.
    title = "Car crash at a junction: 1500 kg east at 20 m/s, 1000 kg north at 15 m/s"
    lines = animate.wrapped(title).split("\n")
    check(lines == ["Car crash at a junction: 1500 kg east at 20 m/s,", "1000 kg north at 15 m/s"], f"wrapped: {lines}")
    check(animate.wrapped("Head-on carts") == "Head-on carts", "a short title was broken")

    scene = args.source / "chapters/inelastic/scenes/head-on-carts.json"
    with tempfile.TemporaryDirectory() as out:
        out = Path(out)
        motion.simulate(args.sim, scene, out / "head-on-carts.trajectory.csv")
        result = subprocess.run([sys.executable, "-m", "plots.animate", str(scene), str(out)],
                                capture_output=True, text=True)
        check(result.returncode == 0, f"animate.py failed: {result.stderr}")
        stated = json.loads((out / "head-on-carts.video.json").read_text())
        # 0.4 s at ten times slower, 25 frames a second: 100 intervals, 101 frames, 4.04 s.
        check(stated == {"frames": 101, "fps": 25, "seconds": 4.04, "slow_motion": 10, "width": 1280, "height": 720,
                         "gif_width": 640}, f"stated {stated}")
        check("slow motion ×10" in result.stdout, f"animate.py said {result.stdout!r}")
        video, length = probe(out / "head-on-carts.mp4")
        check((video["codec_name"], video["width"], video["height"], video["r_frame_rate"]) == ("h264", 1280, 720, "25/1"),
              f"mp4 stream {video}")
        check(int(video["nb_read_frames"]) == 101, f"mp4 has {video['nb_read_frames']} frames, expected 101")
        check(abs(length - 4.04) < 0.5 / 25, f"mp4 lasts {length} s, expected 4.04 s")
        gif, gif_length = probe(out / "head-on-carts.gif")
        check((gif["codec_name"], gif["width"], gif["height"]) == ("gif", 640, 360), f"gif stream {gif}")
        check(int(gif["nb_read_frames"]) == 101, f"gif has {gif['nb_read_frames']} frames, expected 101")
        check(abs(gif_length - 4.04) < 0.5 / 25, f"gif lasts {gif_length} s, expected 4.04 s")

    for f in failures:
        print("FAIL:", f)
    print(f"{len(failures)} failures")
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
