#!/usr/bin/env python3
"""The numbers of the caption of chapter 5's pile of 1,000 discs are the scene's: each is
recomputed from the reference's shipped run (chapters/resting-contact/reference-runs, which
figures.reference_runs_shipped holds to this build's simulator), the solver's settings from the
engine's header, and looked up in the caption as the page rounds it.

    python3 -m tests.plots.test_pile_caption"""
import csv
import re
import sys
from pathlib import Path

SOURCE = Path(__file__).resolve().parents[2]
SCENE = "pile-of-1000-discs"


def main():
    page = (SOURCE / "chapters/resting-contact/chapter.md").read_text()
    caption = re.search(r'figurefile\{resting-contact/' + SCENE + r'\} "([^"]*)"', page)
    if caption is None:
        sys.exit(f"chapter.md shows no {SCENE} figure")
    text = caption.group(1)
    with open(SOURCE / "chapters/resting-contact/reference-runs" / f"{SCENE}.csv", newline="") as f:
        rows = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]
    header = (SOURCE / "engine/include/workbook/contact_solver.hpp").read_text()
    passes = int(re.search(r"int velocity_iterations = (\d+);", header).group(1))
    max_push = float(re.search(r"double max_push = ([0-9.e-]+);", header).group(1))

    sweeps = int(re.search(r"int shock_sweeps = (\d+);", header).group(1))
    slop = float(re.search(r'"slop": ([0-9.e-]+)', (SOURCE / "chapters/resting-contact/scenes" / f"{SCENE}.json").read_text()).group(1))

    deepest = max((r for r in rows if r["t"] < 1.5), key=lambda r: r["penetration_max"])
    landing, landing_at = deepest["penetration_max"], deepest["t"]
    at_1s = min(rows, key=lambda r: abs(r["t"] - 1.0))
    shifting = [r for r in rows if 1.0 - 1e-9 <= r["t"] < 1.5 - 1e-9]
    shift_peak = max(shifting, key=lambda r: r["kinetic_linear"])
    creep = [r for r in rows if r["t"] >= 1.7 - 1e-9]
    quiet = [r for r in rows if r["t"] >= 2.2 - 1e-9]
    end = rows[-1]
    claims = {
        "a hundred passes": passes == 100,
        "and a shock sweep a step": sweeps == 1,
        "no more than 5 mm a step": round(max_push * 1000) == 5,
        "the deepest overlap reaches nearly 5 cm, near 0.6 s": round(landing * 100) == 5 and landing < 0.05
        and round(landing_at, 1) == 0.6,
        "by 1 s it is down to 3 mm": round(at_1s["penetration_max"] * 1000) == 3,
        "up to 7 J of kinetic energy near 1.1 s": round(shift_peak["kinetic_linear"]) == 7
        and round(shift_peak["t"], 1) == 1.1,
        "from 1.7 s on the pile moves with less than 1 J": max(r["kinetic_linear"] for r in creep) < 1.0,
        "from 2.2 s on with less than 0.01 J": max(r["kinetic_linear"] for r in quiet) < 0.01,
        "at 3 s, with 2e-6 J left, it has not yet fallen asleep": round(end["t"], 6) == 3.0
        and round(end["kinetic_linear"] * 1e6) == 2,
        "its deepest overlap the 2 mm slop": round(slop * 1000) == 2
        and all(round(r["penetration_max"] * 1000) == 2 for r in quiet),
    }
    failures = [claim for claim, holds in claims.items() if not holds or claim.split(":")[0] not in text]
    for claim in failures:
        print(f"{SCENE}: the caption's \"{claim}\" is not what the reference run shows", file=sys.stderr)
    if failures:
        sys.exit(1)
    print(f"{SCENE}: the caption's {len(claims)} claims hold (landing {landing * 1000:.1f} mm, at 1 s "
          f"{at_1s['penetration_max'] * 1000:.2f} mm, end {end['penetration_max'] * 1000:.2f} mm and {end['kinetic_linear']:.3g} J)")


if __name__ == "__main__":
    main()
