#!/usr/bin/env python3
"""Checks plots/compare.py: every responder the simulator lists is run and drawn, whatever
chapters exist, and the runs obey the laws every responder must.

- One energy figure and one strip per comparison scene, in SVG, PDF and PNG.
- A time series per responder: the simulator's own list, not a fixed one.
- Two carts meeting: momentum (2 kg * 3 m/s - 1 kg * 1 m/s = 5 kg m/s) is kept to rounding
  under every responder; with `none` the energy stays 9.5 J; with `inelastic` it ends at
  1/2 * 3 kg * (5/3 m/s)^2 = 4.1667 J.
- The strip marks each touch where it begins, with the impulse the responder gave it: the
  carts' one touch under every responder that answers it with restitution carries
  J = mu (1 + e) |v1 - v2| = 2/3 kg * 1.6 * 4 m/s = 4.2667 N s, the contact solver's too,
  whose first row of the pair is a point still apart that gets no impulse (a speculative
  point); and no marked touch of a responder that changes velocities has J = 0.
- The strip names the carts (its panels have no key).

    comparison_test.py --sim build/dev/tools/workbook-sim --source .
"""

import argparse
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
    args = parser.parse_args()
    from plots import motion  # run from the workbook's folder (ctest does)

    listed = subprocess.run([str(args.sim), "responders"], capture_output=True, text=True, check=True).stdout.split()
    check("none" in listed and "inelastic" in listed, f"responders: {listed}")
    with tempfile.TemporaryDirectory() as out:
        out = Path(out)
        result = subprocess.run([sys.executable, "-m", "plots.compare", str(out), "--sim", str(args.sim)],
                                capture_output=True, text=True)
        check(result.returncode == 0, f"compare.py failed: {result.stderr}")
        for scene in ("ball-drop", "carts-meet"):
            for kind in ("energy", "strip"):
                for ext in ("svg", "pdf", "png"):
                    path = out / f"{scene}-{kind}.{ext}"
                    check(path.exists() and path.stat().st_size > 1000, f"missing or empty: {path.name}")
            for name in listed:
                check((out / f"{scene}.{name}.trajectory.csv").exists(), f"{scene} was not run under {name}")
        for name in listed:
            series = motion.read_series(out / f"carts-meet.{name}.csv")
            for px in series["momentum_x"]:
                if abs(px - 5.0) > 1e-12 * 5.0:
                    check(False, f"carts under {name}: momentum {px!r}, expected 5 kg m/s")
                    break
        for scene in ("ball-drop", "carts-meet"):
            for name in listed:
                touches = motion.contact_onsets(motion.read_contacts(out / f"{scene}.{name}.trajectory.contacts.csv"))
                check(bool(touches), f"{scene} under {name}: no touch marked")
                if name not in ("none", "projection"):  # the two that change no velocity
                    check(all(c["impulse"] > 0.0 for c in touches),
                          f"{scene} under {name}: a touch marked with J = 0: {[(c['t'], c['impulse']) for c in touches]}")
        # The strip's panels have no key: its first panel names each cart above its first outline.
        strip = (out / "carts-meet-strip.svg").read_text()
        check(all(f">{name}<" in strip for name in ("cart A", "cart B")), "the carts' strip does not name the carts")
        expected = 2.0 / 3.0 * 1.6 * 4.0
        for name in set(listed) - {"none", "projection", "inelastic"}:
            touches = motion.contact_onsets(motion.read_contacts(out / f"carts-meet.{name}.trajectory.contacts.csv"))
            check(len(touches) == 1 and abs(touches[0]["impulse"] - expected) <= 1e-12 * expected,
                  f"carts under {name}: touches marked {[(c['t'], c['impulse']) for c in touches]}, "
                  f"expected one with J = {expected:.5g} N s")
        none = motion.read_series(out / "carts-meet.none.csv")["total"]
        check(all(abs(e - 9.5) <= 1e-12 * 9.5 for e in none), "carts under none: energy is not 9.5 J throughout")
        inelastic = motion.read_series(out / "carts-meet.inelastic.csv")["total"][-1]
        check(abs(inelastic - 1.5 * 25 / 9) <= 1e-12 * 9.5, f"carts under inelastic end at {inelastic!r} J, expected 4.1667 J")
    for f in failures:
        print("FAIL:", f)
    print(f"{len(listed)} responders, {len(failures)} failures")
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
