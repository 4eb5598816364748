#!/usr/bin/env python3
"""Chapter 5's figure of passes (plots/families.py, kind "passes") and what its page says.

The caption of resting-contact/passes-against-accuracy on chapters/resting-contact/chapter.md
states the scene, its length and the range of passes: they are the family's. Its claims are
checked on the reference's runs, the ones the figure draws:
- warm started, the column sinks less than from zero at every number of passes;
- with the fewest passes, from zero, it sinks by tens of centimetres (more than 100 mm).
The paragraph before it says that even the column at rest stays above the slop line: the
deepest overlap of the column's last second (the shipped reference run) is above the slop.

    python3 -m tests.plots.test_passes_figure --sim build/dev/tools/workbook-sim
"""
import argparse
import json
import re
import sys
import tempfile
from pathlib import Path

from plots import families, figures, reference_runs

SOURCE = Path(__file__).resolve().parents[2]
failures = []


def check(condition, message):
    if not condition:
        failures.append(message)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--sim", type=Path, required=True)
    args = parser.parse_args()
    family = next(f for f in families.FAMILIES["resting-contact"] if f["kind"] == "passes")
    page = (SOURCE / "chapters/resting-contact/chapter.md").read_text()
    caption = re.search(r'figurefile\{resting-contact/' + family["name"] + r'\} "([^"]*)"', page)
    check(caption is not None, f"chapter.md shows no {family['name']} figure")
    spec = json.loads(families.scene_path(SOURCE, family["scene"]).read_text())
    if caption:
        text = caption.group(1)
        balls = sum(1 for b in spec["bodies"] if not b.get("immovable"))
        check(balls == 15 and "fifteen balls" in text, f"the caption's column is not the scene's {balls} balls")
        check(f"for {family['seconds']:g} s" in text, f"the caption does not say the runs last {family['seconds']:g} s")
        check(f"at most {min(family['passes'])} to {max(family['passes'])} velocity passes" in text,
              f"the caption's range of passes is not {min(family['passes'])} to {max(family['passes'])}")

    with tempfile.TemporaryDirectory() as scratch:
        rows = families.run_passes(family, SOURCE, [("reference", args.sim)], figures.run_scene, scratch)
    sunk = {(warm, n): s for _, warm, n, _, s in rows}
    for n in family["passes"]:
        check(sunk[(True, n)] < sunk[(False, n)],
              f"{n} passes: warm started the column sank {sunk[(True, n)]:.4g} mm, from zero {sunk[(False, n)]:.4g} mm")
    fewest = min(family["passes"])
    check(sunk[(False, fewest)] > 100.0, f"{fewest} pass from zero: the column sank {sunk[(False, fewest)]:.4g} mm, "
                                         "not tens of centimetres")

    # The paragraph before the figure: the column's overlap, measured after the move and before
    # the solve, is gravity's move of one step while it is awake (the first half second) and
    # zero to rounding once asleep (the shipped run is the reference's:
    # figures.reference_runs_shipped; its 10 digits put g dt^2 within 1e-12 m).
    column = SOURCE / "chapters/resting-contact/scenes/column-of-15-balls.json"
    run = figures.read_csv(reference_runs.run_path(column))
    spec = json.loads(column.read_text())
    g_dt2 = abs(spec["gravity"][2]) * spec["time_step"] ** 2
    awake = [d for t, d in zip(run["t"], run["penetration_max"]) if 0.0 < t < 0.5]
    check(awake and all(abs(d - g_dt2) < 1e-12 for d in awake),
          f"the awake column's overlap is {max(awake)} m at most, not g dt^2 = {g_dt2} m")
    last = [d for t, d in zip(run["t"], run["penetration_max"]) if t >= spec["duration"] - 1.0]
    check(max(last) < 1e-12, f"the sleeping column's overlap is {max(last)} m, not zero to rounding")
    check("\\f$g\\,\\Delta t^2\\f$" in page and "2.7 mm" in page and round(g_dt2 * 1e4) == 27,
          "the page does not call the awake column's overlap g dt^2, 2.7 mm")

    for f in failures:
        print("FAIL:", f)
    print(f"{len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
