#!/usr/bin/env python3
"""`./workbook bench speed`: the 2D gas of elastic discs in the workbook and in its peers, one run.

For every engine (workbook, chipmunk, box2d, bullet) and every N it runs
`workbook-gas ENGINE N STEPS` REPEAT times in its own process, and keeps the fastest time
per step (the median and the slowest go into the CSV beside it), the peak resident memory
(each run reports its own, Linux's VmHWM, minus the same engine's N = 1 run, divided by N)
and the relative drift of kinetic energy. It writes

    OUT/speed.csv      one row per engine and N
    OUT/speed.md       the same as a Markdown table, with the machine and the date
    OUT/performance.md the site's Performance page (docs/CMakeLists.txt reads it from here)
    FIGURES/speed.{svg,pdf,png}  time per step against N, log-log, in the shared style

With --record it also copies them (the figure as SVG only) into bench/results/: the recorded run that the
site shows when its build has not run the bench itself (docs/CMakeLists.txt), and that
tests/bench/recorded_speed.py holds to the speed goals (10^5 bodies, the peers' pace).

Times are processor time of the timed steps (std::clock; every engine runs on one thread),
which waiting for a core on a shared machine does not inflate. Other work on the machine still
slows a run down through the caches and memory they share, and never speeds one up: so the
fastest of the runs is the best estimate of what the engine itself costs, as in the accuracy
bench (on this machine one run of the workbook at N = 100,000 took 23.8 ms per step beside
runs of 15.4 and 17.8 ms). Compare engines only within one run. Runs are interleaved (each
repetition runs every N and every engine once) so that a burst of load from elsewhere hits
all sizes and engines alike.
"""

import argparse
import csv
import datetime
import math
import os
import platform
import shutil
import statistics
import subprocess
import sys
import time
from pathlib import Path

BENCH = Path(__file__).resolve().parent
STYLE = BENCH.parent / "plots" / "style.gp"
RESULTS = BENCH / "results"
ENGINES = ["workbook", "chipmunk", "box2d", "bullet"]
TITLES = {"workbook": "workbook", "chipmunk": "Chipmunk 7", "box2d": "Box2D 2.4.1", "bullet": "Bullet 3.24"}
STYLES = {"workbook": 2, "chipmunk": 3, "box2d": 4, "bullet": 12}  # line styles of plots/style.gp
SIZES = [1000, 3000, 10000, 30000, 100000]
PEERS_UP_TO = [10**9]  # set from --peers-up-to; the table says "not run" above it
COLUMNS = ["engine", "n", "steps", "repeats", "ms_per_step", "ms_per_step_median", "ms_per_step_max",
           "bytes_per_body", "energy_drift", "escaped"]


def steps_for(n, steps):
    """600 steps (10 s of gas) up to N = 10,000; fewer above, where one run already takes long."""
    return steps if steps else (600 if n <= 10000 else 60)


def run_once(gas, engine, n, steps, timeout):
    """(fields of the printed line, peak RSS in bytes), or None when the run failed."""
    process = subprocess.Popen([str(gas), engine, str(n), str(steps)], stdout=subprocess.PIPE,
                               stderr=subprocess.PIPE, text=True)
    deadline = time.monotonic() + timeout
    while True:
        pid, status, _ = os.wait4(process.pid, os.WNOHANG)
        if pid:
            break
        if time.monotonic() > deadline:
            process.kill()
            os.wait4(process.pid, 0)
            print(f"  {engine} N={n}: stopped after {timeout} s", file=sys.stderr)
            return None
        time.sleep(0.02)
    out, err = process.stdout.read(), process.stderr.read()
    process.returncode = os.WEXITSTATUS(status) if os.WIFEXITED(status) else -os.WTERMSIG(status)
    lines = [line for line in out.splitlines() if line.startswith(engine + ",")]
    if process.returncode != 0 or not lines:
        print(f"  {engine} N={n}: failed ({err.strip().splitlines()[-1] if err.strip() else process.returncode})",
              file=sys.stderr)
        return None
    fields = lines[-1].split(",")
    return fields, int(fields[8]) * 1024


def available_engines(gas):
    """The engines this workbook-gas was built with (a peer whose package is missing is absent)."""
    found = []
    for engine in ENGINES:
        result = subprocess.run([str(gas), engine, "1", "0"], capture_output=True, text=True)
        if result.returncode == 0:
            found.append(engine)
    return found


def skipped_row(engine, n, steps):
    """The row of an engine that failed, timed out or was not run at N: every measurement NaN."""
    return {**{column: "nan" for column in COLUMNS}, "engine": engine, "n": n, "steps": steps, "repeats": 0}


def measure(gas, engines, sizes, repeat, steps, timeout, peers_up_to):
    """Every repetition runs every N and every engine once, so that a change of load on the
    shared machine while the bench runs (others compiling) falls on all sizes and engines alike:
    the growth with N compares runs made side by side, not the quiet start with a busy end."""
    rows = []
    baseline = {}
    for engine in engines:
        base = run_once(gas, engine, 1, 0, timeout)
        baseline[engine] = base[1] if base else 0
    times = {(e, n): [] for e in engines for n in sizes}
    failed = set()
    for rep in range(repeat):
        for n in sizes:
            for engine in engines:
                if (engine, n) in failed:
                    continue  # failed or timed out once at this N: do not wait again
                if engine != "workbook" and n > peers_up_to:
                    continue
                result = run_once(gas, engine, n, steps_for(n, steps), timeout)
                if result:
                    times[(engine, n)].append((float(result[0][3]), result))
                    print(f"  run {rep + 1}/{repeat}: {engine:9} N={n:6}: {float(result[0][3]):.4g} ms/step", file=sys.stderr)
                else:
                    failed.add((engine, n))
    for n in sizes:
        s = steps_for(n, steps)
        for engine in engines:
            runs = times[(engine, n)]
            if not runs:
                rows.append(skipped_row(engine, n, s))
                continue
            ms = [t for t, _ in runs]
            fields, rss = runs[-1][1]
            peak = max(r[1] for _, r in runs)
            rows.append({"engine": engine, "n": n, "steps": s, "repeats": len(ms),
                         "ms_per_step": f"{min(ms):.6g}", "ms_per_step_median": f"{statistics.median(ms):.6g}",
                         "ms_per_step_max": f"{max(ms):.6g}",
                         "bytes_per_body": f"{max(peak - baseline[engine], 0) / n:.0f}",
                         "energy_drift": fields[6], "escaped": fields[7]})
            print(f"  {engine:9} N={n:6}: {rows[-1]['ms_per_step']} ms/step (fastest of {len(ms)}), "
                  f"{rows[-1]['bytes_per_body']} B/body, drift {fields[6]}", file=sys.stderr)
    return rows


def growth(rows, engine):
    """Exponent k of time ~ N^k between the smallest and the largest N the engine ran."""
    points = [(r["n"], float(r["ms_per_step"])) for r in rows if r["engine"] == engine and r["repeats"]]
    if len(points) < 2:
        return float("nan")
    (n0, t0), (n1, t1) = points[0], points[-1]
    return math.log(t1 / t0) / math.log(n1 / n0)


def machine():
    model = platform.processor() or platform.machine()
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                model = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    return f"{model}, {os.cpu_count()} logical cores, {platform.system()} {platform.release()}"


def load_average():
    """The 1-minute load average as text, or "unknown" off Linux and the BSDs."""
    try:
        return f"{os.getloadavg()[0]:.1f}"
    except (AttributeError, OSError):
        return "unknown"


def measured_line(repeat, when, load):
    """The table's first line: when, where and how the run was made."""
    return (f"Measured {when} on {machine()}, load average {load[0]} at the start and {load[1]} at the end; "
            f"each time is the fastest of {repeat} runs "
            "(processor time, each run in its own process; the machine is shared, so compare engines within this table only).")


def three_digits(x):
    """x to 3 significant digits, keeping trailing zeros (0.100, not 0.1) but no bare point (128)."""
    return f"{x:#.3g}".rstrip(".") if abs(x) < 1e3 else f"{x:.3g}"


def markdown(rows, engines, sizes, measured, not_built=()):
    """The table; a peer this build has not got (its package missing) is a column that says so."""
    measured_engines = engines
    engines = [e for e in ENGINES if e in engines or e in not_built]
    lines = [measured, ""]
    head = "| N | steps |" + "".join(f" {TITLES[e]} ms/step |" for e in engines)
    lines += [head, "|" + "---|" * (2 + len(engines))]
    by = {(r["engine"], r["n"]): r for r in rows}
    for n in sizes:
        cells = [f"{n:,}", str(by[(measured_engines[0], n)]["steps"])]
        for e in engines:
            r = by.get((e, n))
            if r is None:
                cells.append("not built")
                continue
            cells.append(("not run" if e != "workbook" and n > PEERS_UP_TO[0] else "no result") if not r["repeats"]
                         else three_digits(float(r["ms_per_step"])))
        lines.append("| " + " | ".join(cells) + " |")
    growths = [growth(rows, e) for e in engines]
    lines.append("| growth with N (smallest to largest N run) | |" +
                 "".join(f" N^{g:.2f} |" if math.isfinite(g) else " - |" for g in growths))
    def largest_run(e):
        done = [r for r in rows if r["engine"] == e and r["repeats"]]
        return f"{done[-1]['bytes_per_body']} (N = {done[-1]['n']:,})" if done else "-"
    lines.append("| memory, bytes/body, at the largest N run | |" + "".join(f" {largest_run(e)} |" for e in engines))
    first = sizes[0]
    lines.append(f"| energy drift at N = {first:,}, {by[(measured_engines[0], first)]['steps']} steps | |" + "".join(
        f" {float(by[(e, first)]['energy_drift']):.1e} |" if by.get((e, first), {}).get("repeats") else " - |"
        for e in engines))
    return "\n".join(lines) + "\n"


def figure(rows, figures, engines):
    figures.mkdir(parents=True, exist_ok=True)
    # One inline data block per engine, so that each engine's points join into one line.
    blocks, plots = [], []
    for e in engines:
        points = [f"{r['n']},{r['ms_per_step']}" for r in rows if r["engine"] == e and r["repeats"]]
        if not points:
            continue  # nothing to draw (the table says why); an empty block would stop gnuplot
        # A peer without a result at some N (it failed or ran out of time) says so in the key,
        # rather than leaving its line to end without a word.
        missing = [f"{r['n']:,}" for r in rows
                   if r["engine"] == e and not r["repeats"] and (e == "workbook" or r["n"] <= PEERS_UP_TO[0])]
        title = TITLES[e] + (f" (no result at N = {', '.join(missing)})" if missing else "")
        blocks += [f"${e} << EOD", *points, "EOD"]
        plots.append(f"${e} using 1:2 with linespoints ls {STYLES[e]} pt 7 ps 0.8 title '{title}'")
    # Ranges with room around the points: gnuplot's own log ranges run to whole decades, which
    # left the smallest N far from the left edge and the fastest time on the bottom axis.
    measured = [(r["n"], float(r["ms_per_step"])) for r in rows if r["repeats"]]
    if not measured:
        print("bench: no engine produced a result, so there is no figure (the table says why)", file=sys.stderr)
        return
    n_low, n_high = min(n for n, _ in measured), max(n for n, _ in measured)
    t_low, t_high = min(t for _, t in measured), max(t for _, t in measured)
    body = "\n".join([
        "set logscale xy", "set format x '10^{%T}'", "set format y '10^{%T}'",
        f"set xrange [{n_low / 1.25:g}:{n_high * 1.25:g}]", f"set yrange [{t_low / 2:g}:{t_high * 2:g}]",
        "set xlabel 'N / bodies' font label_font", "set ylabel 'time per step / ms' font label_font",
        "set title 'A 2D gas of elastic discs: time per step against N' font title_font",
        "set key inside top left vertical Left reverse",
        "plot " + ", ".join(plots)])
    script = blocks[:]
    for ext in ["svg", "pdf", "png"]:
        script += ["reset", f"load '{STYLE}'", f"eval use_{ext}", "set datafile separator ','",
                   f"set output '{figures / ('speed.' + ext)}'", body, "unset output"]
    result = subprocess.run(["gnuplot"], input="\n".join(script) + "\n", capture_output=True, text=True)
    if result.returncode != 0 or result.stderr.strip():
        raise RuntimeError(f"gnuplot:\n{result.stderr.strip()}")


def read_rows(csv_path):
    """The rows of a speed.csv, with N and the number of runs as numbers again."""
    with open(csv_path, newline="") as f:
        return [{**r, "n": int(r["n"]), "repeats": int(r["repeats"])} for r in csv.DictReader(f)]


PAGE = """# Performance {{#performance}}

How fast the workbook's engine steps, side by side with the engines people would pick
instead, on one machine in one run. The scene is a 2D gas of elastic discs: N discs of radius
0.05 m and mass 1 kg in a square box of side \\f$L = 10\\sqrt{{N/1000}}\\f$ m with four walls,
velocities uniform in [-5, 5] m/s, \\f$e = 1\\f$, no gravity, time step 1/60 s, started on a
grid (`bench/gas.cpp`; each peer's set-up is in `bench/gas_<engine>.cpp`). Reproduce with
`./workbook bench speed`.

{table}
Each workbook step here does all it does in a scene: one pass over the bodies moves them,
checks that every number is finite and copies what the broad phase reads into 72-byte
proxies; a uniform grid, walked cell by cell, finds both the pairs that may overlap and the
pairs whose paths may cross within the step; the narrow phase writes the contacts; the swept
test traces every disc that moved further than its radius (most of them: 5 m/s is 0.083 m a
step) against the candidates the grid found, so that none passes through another unseen; and
the elastic impulse answers each contact. The peers run with their own defaults
(`bench/gas_<engine>.cpp` says which). `./workbook bench stages` times each stage on its own.

Resting bodies are never put to sleep. Every shortcut the workbook takes leaves the result
bit for bit what it would be without it (`tests/engine/shortcuts.cpp` holds each to that),
and sleep cannot: under gravity a body resting on the ground gets its gravity kick every
step and has it taken back by the contact's answer to rounding, not exactly, so freezing it
would move it differently. Where a body is exactly still and untouched, without gravity,
a step already costs it one pass of arithmetic that leaves it as it was.

Memory is the peak resident size of the run minus that of the same engine with one body,
divided by N. Energy drift is \\f$|E_\\text{{end}} - E_\\text{{start}}| / E_\\text{{start}}\\f$ of
the kinetic energy: the workbook's elastic impulse keeps it at rounding level, the peers'
iterative solvers (in single precision for Box2D and Bullet) do not. A cell reads *no result*
where a peer's runs failed or did not finish within the bench's limit (`--timeout`, 300 s a run
by default), *not run* where the bench was told to leave the peers out at that N
(`--peers-up-to`), and *not built* where this build has not got the peer (its package was
missing when it was configured).

\\image html bench/speed.svg "Time per step against the number of bodies N, log-log: a slope of 1 is linear cost."
"""


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--gas", required=True, help="the workbook-gas executable")
    parser.add_argument("--out", required=True, type=Path, help="folder for speed.csv, speed.md, performance.md")
    parser.add_argument("--figures", type=Path, help="folder for speed.svg/pdf/png (default: OUT)")
    parser.add_argument("--sizes", type=lambda s: [int(x) for x in s.split(",")], default=SIZES)
    parser.add_argument("--engines", type=lambda s: s.split(","), default=None)
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--steps", type=int, default=0, help="steps per run (default 600 up to N = 10,000, then 60)")
    parser.add_argument("--timeout", type=float, default=300.0, help="seconds before one run is stopped")
    parser.add_argument("--peers-up-to", type=int, default=10**9,
                        help="run the peers only up to this N (on a busy machine they take minutes beyond)")
    parser.add_argument("--no-figure", action="store_true")
    parser.add_argument("--record", action="store_true", help=f"also copy the results into {RESULTS}")
    parser.add_argument("--rewrite", action="store_true",
                        help="run nothing: write the table, the page and the figure again from OUT/speed.csv and the "
                             "first line of OUT/speed.md (when and where the run was made), after a change to how "
                             "they are written (give it the run's --peers-up-to, which the CSV does not keep); with "
                             "--record, copy them too")
    args = parser.parse_args()
    PEERS_UP_TO[0] = args.peers_up_to
    if args.rewrite:
        rows = read_rows(args.out / "speed.csv")
        table = (args.out / "speed.md").read_text().splitlines()
        measured = table[0]
        ran = [e for e in ENGINES if any(r["engine"] == e for r in rows)]
        # The peers the run had not got: columns of its table, without rows in its CSV.
        header = next((line for line in table if line.startswith("| N |")), "")
        not_built = [e for e in ENGINES if e not in ran and f" {TITLES[e]} ms/step |" in header]
        write_results(rows, ran, sorted({r["n"] for r in rows}), measured, args, not_built=not_built)
        return

    engines = args.engines or available_engines(args.gas)
    missing = [e for e in ENGINES if e not in engines]
    if missing and not args.engines:
        print(f"bench: not built with {', '.join(missing)} (their Debian packages are missing)", file=sys.stderr)
    when = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
    load_before = load_average()
    rows = measure(args.gas, engines, args.sizes, args.repeat, args.steps, args.timeout, args.peers_up_to)
    load = (load_before, load_average())

    args.out.mkdir(parents=True, exist_ok=True)
    csv_path = args.out / "speed.csv"
    with open(csv_path, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=COLUMNS)
        writer.writeheader()
        writer.writerows(rows)
    write_results(rows, engines, args.sizes, measured_line(args.repeat, when, load), args,
                  not_built=[] if args.engines else missing)


def write_results(rows, engines, sizes, measured, args, not_built=()):
    """The table, the page and the figure of `rows`; with --record, copies into bench/results/."""
    table = markdown(rows, engines, sizes, measured, not_built)
    (args.out / "speed.md").write_text(table)
    (args.out / "performance.md").write_text(PAGE.format(table=table))
    if not args.no_figure:
        figure(rows, args.figures or args.out, engines)
    if args.record:
        RESULTS.mkdir(exist_ok=True)
        for name in ["speed.csv", "speed.md", "performance.md"]:
            shutil.copyfile(args.out / name, RESULTS / name)
        if not args.no_figure:  # the site's figure; the PDF and PNG stay in the build
            shutil.copyfile((args.figures or args.out) / "speed.svg", RESULTS / "speed.svg")
        print(f"recorded in {RESULTS}", file=sys.stderr)
    print(table)


if __name__ == "__main__":
    main()
