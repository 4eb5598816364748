#!/usr/bin/env python3
"""`./workbook bench pile`: chapter 5's pile in the workbook and in its peers, one run.

The pile (bench/pile.hpp): N frictionless discs of radius 0.05 m and 1 kg, e = 0, dropped from
a loose grid into a box of ground and two walls of inner width sqrt(N) x 0.1 m, g = 9.81 m/s^2,
time step 1/60 s, 10 s. For every N and every engine (workbook, chipmunk, box2d, bullet; the
peers each on their own defaults, bench/pile_<engine>.cpp) it runs
`workbook-pile ENGINE N SECONDS --budget B` in its own process and writes

    OUT/pile.csv      one row per engine and N: time per step, and at the end the deepest
                      overlap, the kinetic energy, the mean height of the centres and the
                      number of discs outside the box
    OUT/pile.md       the same as a Markdown table, with the machine and the date, and the
                      goals the workbook is held to, each met or not met
    FIGURES/pile.{svg,pdf,png}  time per step against N (log-log) and the deepest overlap
                      against N with the 5 mm goal, every engine, in the shared style

A run whose steps take more than the budget (processor time, --budget) is stopped and its
cell reads "skipped: over budget"; so is every larger N of that engine, and any N at which
even a linear growth from the engine's last result would take more than the budget, which is
then not started. With --record it also copies the table, the CSV and the SVG into
bench/results/; --rewrite runs nothing and writes the table and the figure again from a run's
CSV. --quick is the small run the tests make (16 and 100 discs, 3 s). `--engines` picks engines;
it may also name workbook-soft, the workbook's other scheme (the soft step of chapter 5's page,
16 substeps of 240 Hz with one relax pass and a slop of 0.4 mm), run like the workbook to the
largest N and drawn dashed; the table then checks the goals for it too, in a table of its own.

Times are processor time of the timed steps (std::clock; every engine runs on one thread);
with --repeat R each is the fastest of R runs (the state at the end is the same every run).
Compare engines only within one run: the machine may be shared.
"""

import argparse
import csv
import datetime
import math
import shutil
import subprocess
import sys
from pathlib import Path

from bench.speed import ENGINES, RESULTS, STYLE, STYLES, TITLES, load_average, machine, three_digits

# The workbook's soft step (`workbook-pile workbook-soft`, bench/pile.hpp's soft_step_knobs()): an
# engine of this bench only, run when --engines names it, beside the solver's defaults.
SOFT = "workbook-soft"
ENGINES_HERE = ENGINES + [SOFT]
TITLES = {**TITLES, SOFT: "workbook, soft step"}
STYLES = {**STYLES, SOFT: 11}  # the workbook's colour; drawn dashed (SOFT_DASH)
SOFT_DASH = " dt 2"

SIZES = [400, 1000, 2000, 5000, 10000, 20000, 50000, 100000]
PEERS_UP_TO = 10000
QUICK_SIZES = [16, 100]
QUICK_SECONDS = 3.0
COLUMNS = ["engine", "n", "steps", "status", "ms_per_step", "deepest_m", "kinetic_J", "mean_height_m", "outside"]
OVER_BUDGET = "skipped: over budget"

# The goals the workbook is held to (the table prints each as met or not met).
GOAL_DEPTH = 0.005          # m, deepest overlap at the end, at every N
GOAL_KINETIC_PER_DISC = 1e-6  # J per disc at the end, at every N
GOAL_AGAINST = ("chipmunk", 2000)  # time per step at most this peer's at this N
GOAL_GROWTH = 1.2           # time per step growing at most as N^1.2


def run_once(binary, engine, n, seconds, budget):
    """The printed fields as a dict ("status" ok or over budget), or None when the run failed."""
    argv = [str(binary), engine, str(n), f"{seconds:g}", "--budget", f"{budget:g}"]
    try:
        # The binary stops itself at the budget (processor time); the wall-clock limit is only a
        # back-stop for a run that hangs or waits for a core on a busy machine.
        done = subprocess.run(argv, capture_output=True, text=True, timeout=3 * budget + 60)
    except subprocess.TimeoutExpired:
        print(f"  {engine} N={n}: stopped after {3 * budget + 60:g} s of wall time", file=sys.stderr)
        return {"status": OVER_BUDGET}
    lines = [line for line in done.stdout.splitlines() if line.startswith(engine + ",")]  # Chipmunk prints a banner
    if done.returncode != 0 or not lines:
        last = done.stderr.strip().splitlines()[-1] if done.stderr.strip() else f"exit status {done.returncode}"
        print(f"  {engine} N={n}: failed ({last})", file=sys.stderr)
        return None
    fields = lines[-1].split(",")
    if fields[2] == "over budget":
        return {"status": OVER_BUDGET}
    return {"status": "ok", "ms_per_step": float(fields[2]), "deepest_m": fields[3], "kinetic_J": fields[4],
            "mean_height_m": fields[5], "outside": fields[6]}


def available_engines(binary):
    """The engines this workbook-pile was built with (a peer whose package is missing is absent)."""
    return [e for e in ENGINES if subprocess.run([str(binary), e, "1", "0"], capture_output=True).returncode == 0]


def measure(binary, engines, sizes, seconds, budget, repeat, peers_up_to):
    steps = int(seconds * 60 + 0.5)
    rows = []
    last = {}      # engine -> (N, ms per step) of its last result
    over = set()   # engines over budget at some N: not run at a larger one
    for n in sizes:
        for engine in engines:
            row = {**{column: "" for column in COLUMNS}, "engine": engine, "n": n, "steps": steps}
            rows.append(row)
            if engine not in ("workbook", SOFT) and n > peers_up_to:
                row["status"] = "not run"
                continue
            if engine in over:
                row["status"] = OVER_BUDGET
                continue
            if engine in last:
                n0, ms0 = last[engine]
                estimate = ms0 * n / n0 * steps / 1e3  # linear growth: the least it could take
                if estimate > budget:
                    print(f"  {engine} N={n}: not started, at least {estimate:.0f} s at linear growth "
                          f"(budget {budget:g} s)", file=sys.stderr)
                    row["status"] = OVER_BUDGET
                    over.add(engine)
                    continue
            results = []
            for _ in range(repeat):
                result = run_once(binary, engine, n, seconds, budget)
                if result is None or result["status"] != "ok":
                    results = [result]
                    break
                results.append(result)
            if results[0] is None:
                row["status"] = "failed"
                continue
            if results[0]["status"] != "ok":
                row["status"] = OVER_BUDGET
                over.add(engine)
                print(f"  {engine} N={n}: over budget ({budget:g} s)", file=sys.stderr)
                continue
            best = min(results, key=lambda r: r["ms_per_step"])
            row.update(best)
            row["ms_per_step"] = f"{best['ms_per_step']:.4g}"
            last[engine] = (n, best["ms_per_step"])
            print(f"  {engine:9} N={n:6}: {row['ms_per_step']} ms/step, deepest {float(row['deepest_m']) * 1e3:.3g} mm, "
                  f"kinetic {row['kinetic_J']} J, outside {row['outside']}", file=sys.stderr)
    return rows


def done(rows, engine):
    return [r for r in rows if r["engine"] == engine and r["status"] == "ok"]


def growth(rows, engine):
    """(k, N0, N1): time ~ N^k between the smallest and the largest N the engine finished."""
    points = done(rows, engine)
    if len(points) < 2:
        return float("nan"), None, None
    a, b = points[0], points[-1]
    return math.log(float(b["ms_per_step"]) / float(a["ms_per_step"])) / math.log(b["n"] / a["n"]), a["n"], b["n"]


def goals(rows, engine="workbook"):
    """[(goal, met, what was measured)] for the workbook (or its soft step, `engine`): met True or
    False, or None where this run could not tell (the peer or the N it is compared at not run). A
    goal over every N is not met when the engine has no result at some N (over budget)."""
    mine = [r for r in rows if r["engine"] == engine]
    ran = [r for r in mine if r["status"] == "ok"]
    missing = [f"{r['n']:,}" for r in mine if r["status"] != "ok"]
    lacking = f"; no result at N = {', '.join(missing)}" if missing else ""
    out = []
    if ran:
        worst = max(ran, key=lambda r: float(r["deepest_m"]))
        out.append(("deepest overlap at the end <= 5 mm at every N",
                    not missing and all(float(r["deepest_m"]) <= GOAL_DEPTH for r in ran),
                    f"deepest {float(worst['deepest_m']) * 1e3:.3g} mm (N = {worst['n']:,}){lacking}"))
        worst = max(ran, key=lambda r: float(r["kinetic_J"]) / r["n"])
        out.append(("kinetic energy at the end <= 1e-6 J per disc at every N",
                    not missing and all(float(r["kinetic_J"]) / r["n"] <= GOAL_KINETIC_PER_DISC for r in ran),
                    f"largest {float(worst['kinetic_J']) / worst['n']:.2g} J per disc (N = {worst['n']:,}){lacking}"))
        outside = sum(int(r["outside"]) for r in ran)
        out.append(("no disc outside the box at any N", not missing and outside == 0,
                    f"{outside} outside, all N together{lacking}"))
    else:
        out += [(g, None, "no result") for g in ("deepest overlap at the end <= 5 mm at every N",
                                                  "kinetic energy at the end <= 1e-6 J per disc at every N",
                                                  "no disc outside the box at any N")]
    peer, n = GOAL_AGAINST
    by = {(r["engine"], r["n"]): r for r in rows}
    a, b = by.get((engine, n)), by.get((peer, n))
    goal = f"time per step <= {TITLES[peer]}'s at N = {n:,}"
    if a and b and a["status"] == "ok" and b["status"] == "ok":
        ratio = float(a["ms_per_step"]) / float(b["ms_per_step"])
        out.append((goal, ratio <= 1, f"{a['ms_per_step']} ms against {b['ms_per_step']} ms ({ratio:.2f} times)"))
    else:
        out.append((goal, None, f"N = {n:,} not run by both"))
    k, n0, n1 = growth(rows, engine)
    out.append((f"time per step growing at most as N^{GOAL_GROWTH}",
                (k <= GOAL_GROWTH and not missing) if math.isfinite(k) else None,
                f"N^{k:.2f} from N = {n0:,} to {n1:,}{lacking}" if math.isfinite(k) else "fewer than two results"))
    return out


def cell(row, key, scale=1.0, digits=True):
    if row["status"] != "ok":
        return row["status"]
    value = float(row[key]) * scale
    return three_digits(value) if digits else f"{value:.2g}"


def markdown(rows, engines, sizes, measured, not_built=()):
    lines = [measured, "",
             "| engine | N | ms/step | deepest overlap at the end, mm | kinetic energy at the end, J | "
             "mean height, m | discs outside the box |",
             "|---|---|---|---|---|---|---|"]
    for n in sizes:
        for r in rows:
            if r["n"] != n:
                continue
            if r["status"] != "ok":
                lines.append(f"| {TITLES[r['engine']]} | {n:,} | {r['status']} | | | | |")
                continue
            lines.append(f"| {TITLES[r['engine']]} | {n:,} | {cell(r, 'ms_per_step')} | {cell(r, 'deepest_m', 1e3)} | "
                         f"{cell(r, 'kinetic_J', digits=False)} | {cell(r, 'mean_height_m')} | {r['outside']} |")
        for e in not_built:
            lines.append(f"| {TITLES[e]} | {n:,} | not built | | | | |")
    lines += ["", "Growth of the time per step with N (smallest to largest N each engine finished): " + "; ".join(
        f"{TITLES[e]} N^{k:.2f} ({n0:,} to {n1:,})" if math.isfinite(k) else f"{TITLES[e]} -"
        for e in engines for k, n0, n1 in [growth(rows, e)]) + ".", "",
              "| goal for the workbook | | measured |", "|---|---|---|"]
    verdict = {True: "met", False: "not met", None: "not measured"}
    lines += [f"| {goal} | {verdict[met]} | {what} |" for goal, met, what in goals(rows)]
    if any(r["engine"] == SOFT for r in rows):
        lines += ["", "The same goals, measured on the workbook's soft step:", "",
                  "| goal for the workbook's soft step | | measured |", "|---|---|---|"]
        lines += [f"| {goal} | {verdict[met]} | {what} |" for goal, met, what in goals(rows, SOFT)]
    return "\n".join(lines) + "\n"


def figure(rows, figures, engines, seconds):
    """Two panels: time per step against N (log-log), deepest overlap against N with the goal."""
    figures.mkdir(parents=True, exist_ok=True)
    blocks, times, depths = [], [], []
    for e in engines:
        points = done(rows, e)
        if not points:
            continue
        skipped = [f"{r['n']:,}" for r in rows if r["engine"] == e and r["status"] in (OVER_BUDGET, "failed")]
        title = TITLES[e] + (f" (over budget from N = {skipped[0]})" if skipped else "")
        block = "$" + e.replace("-", "_")  # a gnuplot data block's name has no '-'
        blocks += [f"{block} << EOD", *[f"{r['n']},{r['ms_per_step']},{float(r['deepest_m']) * 1e3:.6g}" for r in points], "EOD"]
        dash = SOFT_DASH if e == SOFT else ""
        times.append(f"{block} using 1:2 with linespoints ls {STYLES[e]}{dash} pt 7 ps 0.8 title '{title}'")
        depths.append(f"{block} using 1:($3 > 0.1 ? $3 : 0.1) with linespoints ls {STYLES[e]}{dash} pt 7 ps 0.8 notitle")
    measured = [r for e in engines for r in done(rows, e)]
    if not measured:
        print("bench: no engine produced a result, so there is no figure (the table says why)", file=sys.stderr)
        return
    n_low, n_high = min(r["n"] for r in measured), max(r["n"] for r in measured)
    t = [float(r["ms_per_step"]) for r in measured]
    d = [max(float(r["deepest_m"]) * 1e3, 0.1) for r in measured] + [GOAL_DEPTH * 1e3]
    common = ["set logscale xy", "set format x '10^{%T}'", f"set xrange [{n_low / 1.3:g}:{n_high * 1.3:g}]",
              "set xlabel 'N / discs' font label_font"]
    body = "\n".join([
        "set multiplot layout 1,2 title "
        f"'A pile of N frictionless discs dropped into a box, {seconds:g} s: every engine on its defaults"
        f"{', and the workbook' + chr(39) * 2 + 's soft step' if SOFT in engines else ''}' font title_font",
        *common, "set format y '10^{%T}'", f"set yrange [{min(t) / 2:g}:{max(t) * 30:g}]",  # room above the lines for the key
        "set ylabel 'time per step / ms' font label_font",
        "set key inside top left vertical Left reverse font note_font",
        "plot " + ", ".join(times),
        "set format y '%g'", "set ytics (0.1, 0.2, 0.5, 1, 2, 5, 10, 20, 50, 100, 200, 500, 1000)",
        f"set yrange [{min(d) / 1.6:g}:{max(d) * 1.6:g}]",
        "set ylabel 'deepest overlap at the end / mm' font label_font offset 0, 0",
        "set key inside top left vertical Left reverse font note_font",
        f"plot {GOAL_DEPTH * 1e3:g} with lines dt 2 lw 2 lc rgb '#303030' title 'goal: at most 5 mm', " + ", ".join(depths),
        "unset multiplot"])
    script = blocks[:]
    for ext in ["svg", "pdf", "png"]:
        script += ["reset", f"load '{STYLE}'", f"eval use_{ext}", "set datafile separator ','",
                   f"set output '{figures / ('pile.' + ext)}'", body, "unset output"]
    result = subprocess.run(["gnuplot"], input="\n".join(script) + "\n", capture_output=True, text=True)
    if result.returncode != 0 or result.stderr.strip():
        raise RuntimeError(f"gnuplot:\n{result.stderr.strip()}")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--binary", default="build/dev/bench/workbook-pile", help="the workbook-pile executable")
    parser.add_argument("--out", type=Path, default=Path("build/dev/book/bench"), help="folder for pile.csv and pile.md")
    parser.add_argument("--figures", type=Path, help="folder for pile.svg/pdf/png (default: OUT)")
    parser.add_argument("--sizes", "--counts", nargs="+", default=None,
                        help=f"numbers of discs, comma- or space-separated (default {','.join(map(str, SIZES))})")
    parser.add_argument("--peers-up-to", type=int, default=None,
                        help=f"run the peers only up to this N (default {PEERS_UP_TO:,}); the table says 'not run' above")
    parser.add_argument("--engines", type=lambda s: s.split(","), default=None)
    parser.add_argument("--seconds", type=float, default=None, help="simulated time, s (default 10)")
    parser.add_argument("--budget", type=float, default=300.0,
                        help="processor seconds one run's steps may take before it is stopped (default 300)")
    parser.add_argument("--repeat", type=int, default=1, help="runs of each engine and N; the fastest time is kept")
    parser.add_argument("--quick", action="store_true",
                        help=f"the tests' run: N = {', '.join(map(str, QUICK_SIZES))}, {QUICK_SECONDS:g} s, every engine")
    parser.add_argument("--no-figure", action="store_true")
    parser.add_argument("--record", action="store_true", help=f"also copy pile.csv, pile.md and pile.svg into {RESULTS}")
    parser.add_argument("--rewrite", action="store_true",
                        help="run nothing: write the table and the figure again from OUT/pile.csv and the first line of "
                             "OUT/pile.md (when and where the run was made), after a change to how they are written")
    args = parser.parse_args()
    if args.rewrite:
        with open(args.out / "pile.csv", newline="") as f:
            rows = [{**r, "n": int(r["n"])} for r in csv.DictReader(f)]
        engines = [e for e in ENGINES_HERE if any(r["engine"] == e for r in rows)]
        sizes = sorted({r["n"] for r in rows})
        measured = (args.out / "pile.md").read_text().splitlines()[0]
        seconds = int(rows[0]["steps"]) / 60
        write(rows, engines, sizes, measured, [], seconds, args)
        return 0
    sizes = [int(x) for item in args.sizes for x in item.split(",") if x] if args.sizes else (
        QUICK_SIZES if args.quick else SIZES)
    seconds = args.seconds or (QUICK_SECONDS if args.quick else 10.0)
    peers_up_to = args.peers_up_to if args.peers_up_to is not None else (max(sizes) if args.quick else PEERS_UP_TO)

    engines = args.engines or available_engines(args.binary)
    not_built = [] if args.engines else [e for e in ENGINES if e not in engines]
    if not_built:
        print(f"bench: not built with {', '.join(not_built)} (their Debian packages are missing)", file=sys.stderr)
    when = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
    load_before = load_average()
    rows = measure(args.binary, engines, sizes, seconds, args.budget, args.repeat, peers_up_to)
    measured = (f"Measured {when} on {machine()}, load average {load_before} at the start and {load_average()} at the "
                f"end; {seconds:g} s of pile ({int(seconds * 60 + 0.5)} steps of 1/60 s) each, "
                f"{'the fastest of ' + str(args.repeat) + ' runs' if args.repeat > 1 else 'one run'} "
                f"(processor time, each run in its own process), budget {args.budget:g} s a run; "
                "the machine is shared, so compare engines within this table only.")

    args.out.mkdir(parents=True, exist_ok=True)
    with open(args.out / "pile.csv", "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=COLUMNS)
        writer.writeheader()
        writer.writerows(rows)
    write(rows, engines, sizes, measured, not_built, seconds, args)
    return 0


def write(rows, engines, sizes, measured, not_built, seconds, args):
    """The table and the figure of `rows`; with --record, copies into bench/results/."""
    table = markdown(rows, engines, sizes, measured, not_built)
    (args.out / "pile.md").write_text(table)
    figures = args.figures or args.out
    if not args.no_figure:
        figure(rows, figures, engines, seconds)
    if args.record:
        RESULTS.mkdir(exist_ok=True)
        for name in ["pile.csv", "pile.md"]:
            shutil.copyfile(args.out / name, RESULTS / name)
        if not args.no_figure:
            shutil.copyfile(figures / "pile.svg", RESULTS / "pile.svg")
        print(f"recorded in {RESULTS}", file=sys.stderr)
    print(table)


if __name__ == "__main__":
    sys.exit(main())
