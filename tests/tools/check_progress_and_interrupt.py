#!/usr/bin/env python3
"""A long run of workbook-sim shows a progress line on standard error after two seconds, and
Ctrl-C (SIGINT) ends it with exit status 130 and the CSV of the steps done so far, whole."""

import argparse
import json
import signal
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path


def long_scene():
    """A 2D gas of 4,900 discs for 20 simulated seconds at 600 steps/s: a minute or more."""
    bodies = []
    k = 70
    for i in range(k * k):
        bodies.append({"name": f"disc {i}", "shape": {"type": "sphere", "radius": 0.05}, "mass": 1.0,
                       "position": [-17 + 0.5 * (i % k), -17 + 0.5 * (i // k), 0],
                       "velocity": [((i * 7919) % 100) / 10 - 5, ((i * 104729) % 100) / 10 - 5, 0]})
    return {"title": "A long run", "description": "Many discs for long enough to need a progress line.",
            "responder": "none", "time_step": 1 / 600, "duration": 20.0, "gravity": [0, 0, 0], "bodies": bodies}


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--sim", required=True)
    args = parser.parse_args()
    failures = []
    with tempfile.TemporaryDirectory() as folder:
        scene, csv_path = Path(folder) / "long.json", Path(folder) / "long.csv"
        scene.write_text(json.dumps(long_scene()))
        process = subprocess.Popen([args.sim, "run", str(scene), "--csv", str(csv_path)],
                                   stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        # Ctrl-C once the progress line shows (the run has stepped for two seconds by then;
        # a sanitizer build may take seconds just to read the scene), within 120 s.
        err_chunks = []
        reader = threading.Thread(target=lambda: err_chunks.extend(iter(lambda: process.stderr.read(1), "")))
        reader.start()
        deadline = time.monotonic() + 120
        while "(Ctrl-C stops" not in "".join(err_chunks) and process.poll() is None and time.monotonic() < deadline:
            time.sleep(0.1)
        if process.poll() is not None:
            sys.exit(f"the run ended by itself before Ctrl-C (status {process.returncode}); the scene is too short for this machine")
        process.send_signal(signal.SIGINT)
        out = process.stdout.read()
        process.wait(timeout=60)
        reader.join(timeout=60)
        err = "".join(err_chunks)
        if process.returncode != 130:
            failures.append(f"exit status {process.returncode} after Ctrl-C, expected 130")
        if "step " not in err or "(Ctrl-C stops" not in err:
            failures.append(f"no progress line on standard error; it read: {err[:300]!r}")
        if "interrupted at t = " not in err:
            failures.append(f"no message saying the run was interrupted; standard error: {err[-300:]!r}")
        lines = csv_path.read_text().splitlines() if csv_path.exists() else []
        if len(lines) < 3:
            failures.append(f"the partial CSV has {len(lines)} lines, expected the header and the steps done")
        else:
            columns = len(lines[0].split(","))
            if any(len(line.split(",")) != columns for line in lines):
                failures.append("a line of the partial CSV is cut short")
            steps = len(lines) - 2
            if steps >= 12000:
                failures.append("the CSV holds every step: the run was not stopped")
            print(f"stopped after {steps} of 12000 steps; CSV of {len(lines)} lines kept")
        if "steps)" not in out:
            failures.append("no summary of the partial run on standard output")
    for failure in failures:
        print("FAIL:", failure)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
