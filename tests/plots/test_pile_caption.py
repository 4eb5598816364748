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

    landing = max(r["penetration_max"] for r in rows if r["t"] < 1.5)
    lowest = min(rows, key=lambda r: r["potential"])
    rise = rows[-1]["potential"] - lowest["potential"]
    later = max(r["penetration_max"] for r in rows if 1.5 <= r["t"] < 2.5)
    end = rows[-1]
    claims = {
        "A hundred passes a step": passes == 100,
        "no more than 5 mm a step": round(max_push * 1000) == 5,
        "the deepest overlap reaches 10 cm": round(landing * 100) == 10,
        f"climbs {rise / 1000:.1f} kJ": rise > 0 and f"climbs {rise / 1000:.1f} kJ" in text,
        # kinetic energy "near zero" while the pile is lifted (until the shift near 2 s): below 1 % of the rise
        "while kinetic energy stays near zero": all(r["kinetic_linear"] < 0.01 * rise for r in rows if lowest["t"] + 0.25 < r["t"] < 1.5),
        "overlaps by 8 cm again": round(later * 100) == 8,
        "After 3 s the deepest overlap is 5 mm": abs(end["t"] - 3.0) < 1e-6 and round(end["penetration_max"] * 1000) == 5,
        "0.01 J of kinetic energy is left": round(end["kinetic_linear"], 2) == 0.01,
    }
    failures = [claim for claim, holds in claims.items() if not holds or claim.split(":")[0] not in text]
    for claim in failures:
        print(f"{SCENE}: the caption's \"{claim}\" is not what the reference run shows", file=sys.stderr)
    if failures:
        sys.exit(1)
    print(f"{SCENE}: the caption's {len(claims)} claims hold (landing {landing * 1000:.1f} mm, lift {rise:.0f} J, "
          f"later {later * 1000:.1f} mm, end {end['penetration_max'] * 1000:.2f} mm and {end['kinetic_linear']:.3g} J)")


if __name__ == "__main__":
    main()
