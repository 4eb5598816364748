#!/usr/bin/env python3
"""Energy and momentum figures for the scenes of one workbook chapter.

For every chapters/<chapter>/scenes/*.json this runs the simulator into a CSV and draws one
figure with two panels, energy over time and momentum over time, as SVG, PDF and PNG beside
the CSV. The kinetic energy the impact removes is marked with its measured value (the CSV's
response_energy_change column). With --student the student's simulator is run as well and
its curves are drawn dashed over the reference's. With --no-reference (the student edition,
which has no reference solutions) the reference's curves come from the runs shipped in
chapters/<chapter>/reference-runs/ (plots/reference_runs.py), and the student's are drawn
dashed over them as in the full edition; a scene without a shipped run shows the student's
curves alone. All looks come from plots/style.gp.

    figures.py inelastic build/dev/book/figures/inelastic --sim build/dev/tools/workbook-sim
    figures.py inelastic OUT --student --student-sim build/dev/tools/workbook-sim-student
"""

import argparse
import csv
import json
import math
import subprocess
import sys
import tempfile
from pathlib import Path

from plots import families
from plots import figure_render
from plots import reference_runs
from plots import spin

PLOTS = Path(__file__).resolve().parent
SOURCE = PLOTS.parent
STYLE = figure_render.STYLE

# (CSV column, key title, line style in style.gp, always drawn?)
ENERGY = [("total", "total", 1, True), ("kinetic_linear", "kinetic, linear", 2, True),
          ("kinetic_rotational", "kinetic, rotational", 3, False), ("potential", "potential", 4, False)]
MOMENTUM = [("momentum_x", "p_x", 11), ("momentum_y", "p_y", 12), ("momentum_z", "p_z", 13)]
ANGULAR = [("angular_momentum_x", "L_x", 21), ("angular_momentum_y", "L_y", 22), ("angular_momentum_z", "L_z", 23)]

# What the measured energy change at impact should equal, per responder; the figure states it
# next to the measured value. A responder missing here gets the measured value alone.
LOSS_LAW = {"inelastic": "−½ μ |v₁ − v₂|²", "projection": "0: positions only",
            "linear-impulse": "−½ μ (1 − e²) (v₁₂·n)²"}
LOSS_LAW["angular-impulse"] = "½ (1 − e) Σ Jᵢ uᵢ"  # u_i < 0: each pushing point i approached at u_i

# Responders whose figures get a third panel, the deepest penetration per step (the CSV's
# penetration_max), because what they change is positions (projection), or because keeping
# overlap within the slop is half of what they do (resting contact: the slop drawn).
DEPTH_PANEL = {"projection", "resting-contact"}
DEPTH = ("penetration_max", "deepest penetration", 41)

# Responders whose contacts rest rather than hit (chapter 5's stacks and piles, chapter 6's
# blocks and balls on the ground): no single impact to mark. What the energy panel states
# instead is the kinetic energy left at the end: zero for bodies come to rest.
RESTING = {"resting-contact", "friction"}


def final_kinetic(data):
    """Kinetic energy (linear and rotational) of the last sample, J."""
    return data["kinetic_linear"][-1] + data["kinetic_rotational"][-1]

FORMATS = figure_render.FORMATS

RECORD_PANEL = figure_render.RECORD_PANEL


def read_csv(path):
    """The CSV as {column: [float, ...]}."""
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    return {name: [float(row[i]) for row in rows[1:]] for i, name in enumerate(rows[0])}


# A scene runs in well under a second; a student's endless loop must not hang the figures.
SCENE_TIME_LIMIT = 120


def run_scene(simulator, scene, csv_path, trajectory=None):
    """Runs the scene into `csv_path` (and every body's state per step into `trajectory`, if
    given); returns the time series as read_csv() does."""
    extra = ["--trajectory", str(trajectory)] if trajectory else []
    try:
        result = subprocess.run([str(simulator), "run", str(scene), "--csv", str(csv_path), "--quiet", *extra],
                                capture_output=True, text=True, timeout=SCENE_TIME_LIMIT)
    except subprocess.TimeoutExpired:
        raise RuntimeError(f"{simulator} ran {scene} for more than {SCENE_TIME_LIMIT} s and was stopped "
                           "(an endless loop in the responder?)") from None
    # Status 3: the world stopped on a NaN or an infinity (workbook/guards.hpp) and wrote the
    # samples up to there; the figure draws what is finite and marks where it stopped.
    if result.returncode == 3 and Path(csv_path).is_file():
        print(f"figures: note: {Path(scene).name}: {result.stderr.strip()}", flush=True)
    elif result.returncode != 0:
        raise RuntimeError(f"{simulator} failed on {scene}:\n{result.stderr.strip()}")
    return read_csv(csv_path)


def first_nonfinite(data):
    """Index of the first sample holding a value that is not finite (NaN, infinite), or None.
    A student's responder can produce one; everything before it is still worth drawing."""
    columns = list(data.values())
    for i in range(len(columns[0])):
        if any(not math.isfinite(column[i]) for column in columns):
            return i
    return None


def finite_prefix(csv_path, data, stop, scratch):
    """(path, data) of the samples before `stop`, for gnuplot, which cannot read 'nan'; the
    CSV written beside the figure keeps every sample, the non-finite ones too."""
    lines = Path(csv_path).read_text().splitlines(keepends=True)
    path = Path(scratch, Path(csv_path).stem + ".finite.csv")
    path.write_text("".join(lines[:1 + stop]))
    return path, {name: column[:stop] for name, column in data.items()}


def largest(datasets, columns):
    return max((abs(v) for d in datasets for c in columns for v in d[c] if math.isfinite(v)), default=0.0)


def significant(datasets, column, scale):
    """True when the column rises above rounding noise: above 1e-9 of `scale`, the largest
    related quantity (a curve of 1e-13 J next to 800 J is noise, not physics)."""
    return largest(datasets, [column]) > 1e-9 * scale


def impact(data):
    """Index of the first sample whose step changed kinetic energy in a response, else of the
    first step with a contact, else None."""
    for column in ("response_energy_change", "contacts"):
        for i, v in enumerate(data[column]):
            if v != 0.0:
                return i
    return None


def unit_scale(values, units):
    """(factor, unit) keeping tick labels below 10^4: units[k] is the unit for factor 1000^-k."""
    biggest = max((abs(v) for v in values if math.isfinite(v)), default=0.0)
    k = 0
    while k + 1 < len(units) and biggest >= 1e4 * 1000.0 ** k:
        k += 1
    return 1000.0 ** -k, units[k]


def axis_range(values, top_room=0.14):
    """A range that includes zero, with room above the data for the annotations."""
    finite = [v for v in values if math.isfinite(v)]
    lo, hi = min(finite + [0.0]), max(finite + [0.0])
    span = hi - lo or 1.0
    return lo - (0.06 * span if lo < 0 else 0.0), hi + top_room * span


def tick_step(span, ticks=5):
    """A round tick spacing (1, 2, 2.5 or 5 times a power of ten) giving about `ticks` intervals."""
    raw = span / ticks
    power = 10.0 ** math.floor(math.log10(raw))
    return next(m * power for m in (1, 2, 2.5, 5, 10) if m * power >= raw * 0.999)


quote = figure_render.quote


def number(value, unit):
    """Three decimals with a true minus sign; a value that rounds to zero is 0.000, never −0.000
    (an energy change of -1e-16 J at e = 1 is rounding, not a loss)."""
    text = f"{value:.3f}"
    return (text if text.strip("-0.") else "0.000").replace("-", "\u2212") + " " + unit


def curves(datasets, series, factor, axes=""):
    """Plot clauses: every series for every (csv path, data, dashed, titled) dataset."""
    clauses = []
    for path, data, dashed, titled in datasets:
        header = list(data)
        for column, title, style in series:
            clause = f"'{path}' skip 1 using 1:(${header.index(column) + 1}*{factor!r}) {axes}with lines ls {style}"
            clause += " dt student_dash" if dashed else ""
            clause += f" title {quote(title)}" if titled else " notitle"
            clauses.append(clause)
    return clauses


def gnuplot_panels(title, responder, datasets, reference, student, t_end, stops=(), slop=None, moving_mass=None):
    """The multiplot body (everything after `set output`) for one scene. `stops` lists
    (whose curves, time) where a run's values stopped being finite: marked on both panels.
    `slop` (m): drawn across the penetration panel, where there is one. `moving_mass` (kg, the
    movable bodies' total) gives momentum its scale: the momentum the scene's largest energy
    would be if it were all kinetic, sqrt(2 M E)."""
    main = (reference or student)[1]
    everything = [d for _, d, _, _ in datasets]
    hit = None if responder in RESTING else impact(main)
    stop_marks = []
    for n, (who, t_stop) in enumerate(stops):
        stop_marks += [f"set arrow {5 + n} from {t_stop!r}, graph 0 to {t_stop!r}, graph 1 nohead dt 2 lw 2 lc rgb c_drop",
                       f"set label {5 + n} \"{who}: not finite (NaN)\\nfrom t = {t_stop:.4g} s on\" at {t_stop!r}, "
                       f"graph {0.25 - 0.08 * n!r} "
                       f"{'left offset character 0.6' if t_stop < 0.6 * t_end else 'right offset character -0.6'}, 0 "
                       "font note_font tc rgb c_drop noenhanced"]

    e_scale = largest(everything, [c for c, _, _, _ in ENERGY])
    # A resting scene's momentum is rounding (1e-9 kg m/s under 100 J): judged against its own
    # largest value it would fill the panel with noise, so it is judged against the momentum
    # the scene's energy could give its mass.
    p_scale = max(largest(everything, [c for c, _, _ in MOMENTUM]), math.sqrt(2.0 * moving_mass * e_scale) if moving_mass else 0.0)
    energy = [(c, t, s) for c, t, s, always in ENERGY if always or significant(everything, c, e_scale)]
    momentum = [(c, t, s) for c, t, s in MOMENTUM if significant(everything, c, p_scale)]
    # Nothing above rounding: every component is drawn, flat at zero on the scene's own scale.
    p_range = [-p_scale, p_scale] if not momentum and p_scale > 0.0 else []
    momentum = momentum or MOMENTUM
    # Angular momentum is compared with |p| times one metre (or with zero when nothing moves).
    angular = [(c, t, s) for c, t, s in ANGULAR if significant(everything, c, p_scale * 1.0)]

    e_factor, e_unit = unit_scale([v for d in everything for c, _, _ in energy for v in d[c]], ["J", "kJ", "MJ"])
    p_factor, p_unit = unit_scale([v for d in everything for c, _, _ in momentum for v in d[c]] + p_range,
                                  ["kg m/s", "10^3 kg m/s", "10^6 kg m/s"])
    e_lo, e_hi = axis_range([e_factor * v for d in everything for c, _, _ in energy for v in d[c]], top_room=0.55)
    p_lo, p_hi = axis_range([p_factor * v for d in everything for c, _, _ in momentum for v in d[c]] + [p_factor * v for v in p_range])

    depth_panel = responder in DEPTH_PANEL
    g = [f"set multiplot layout 1,{3 if depth_panel else 2} title {quote(title)} font title_font noenhanced",
         f"set xrange [0:{t_end!r}]", f"set xtics 0, {tick_step(t_end)!r}", "set format x '%g'",
         "set xlabel 't / s'"]
    if hit is not None:
        t_hit = main["t"][hit]
        impact_label = f"set label 1 'impact' at {t_hit!r}, graph 0.97 offset character 0.6, 0 left font note_font tc rgb c_note"
        g += [f"set arrow 1 from {t_hit!r}, graph 0 to {t_hit!r}, graph 1 @impact_style", impact_label]

    g += stop_marks
    # Energy panel, with the drop at impact marked and labelled by its measured value.
    g += ["set title 'Energy'", f"set ylabel 'E / {e_unit}'", f"set yrange [{e_lo!r}:{e_hi!r}]"]
    if hit is not None:
        drop = main["response_energy_change"][hit]
        before = main["total"][hit - 1] * e_factor
        after = before + drop * e_factor
        t_arrow = t_hit + 0.012 * t_end  # just right of the step, so that the curve does not hide it
        if drop != 0.0 and math.isfinite(before) and math.isfinite(after):
            g.append(f"set arrow 2 from {t_arrow!r}, {before!r} to {t_arrow!r}, {after!r} @drop_style")
        if reference:
            law = LOSS_LAW.get(responder)
            lines = [f"ΔE = {number(drop * e_factor, e_unit)}"] + ([f"    = {law}"] if law else [])
        else:
            lines = [f"your code: ΔE = {number(drop * e_factor, e_unit)}"]
        if reference and student:
            s_hit = impact(student[1])
            s_drop = student[1]["response_energy_change"][s_hit] if s_hit is not None else 0.0
            if any(who == "your code" for who, _ in stops) and s_hit is None:
                lines.append("your code: ΔE not finite (NaN)")
            else:
                lines.append(f"your code: ΔE = {number(s_drop * e_factor, e_unit)}")
        # In the free strip above the curves, beside the impact line on the side with more room.
        right = t_hit < 0.6 * t_end
        for n, text in enumerate(lines):
            g.append(f"set label {10 + n} {quote(text)} at first {t_arrow if right else t_hit!r}, graph {0.87 - 0.07 * n!r} "
                     f"{'left offset character 0.8' if right else 'right offset character -0.8'}, 0 "
                     "font label_font tc rgb c_drop noenhanced")
    if responder in RESTING:
        # Resting contact: no impact; the kinetic energy left at the end, run by run.
        lines = [f"{'' if own else who + ': '}kinetic at the end: {number(final_kinetic(d) * e_factor, e_unit)}"
                 for who, d, own in (("reference", reference[1] if reference else None, not student),
                                     ("your code", student[1] if student else None, not reference)) if d is not None]
        for n, text in enumerate(lines):
            g.append(f"set label {10 + n} {quote(text)} at graph 0.03, graph {0.87 - 0.07 * n!r} left "
                     "font label_font tc rgb c_drop noenhanced")
    plot = curves(datasets, energy, e_factor)
    if reference and student:
        plot += ["NaN with lines ls 90 title 'reference'", "NaN with lines ls 90 dt student_dash title 'your code'"]
    g += ["plot " + ", \\\n     ".join(plot), RECORD_PANEL, "unset arrow 2", "unset label"]
    if hit is not None:
        g.append(impact_label)  # the energy labels are gone, the impact keeps its own
    g += [line for line in stop_marks if line.startswith("set label")]

    # Momentum panel: linear momentum on the left axis, angular momentum (if any) on the right.
    g += ["set title 'Momentum'", f"set ylabel 'p / ({p_unit})'", f"set yrange [{p_lo!r}:{p_hi!r}]"]
    plot = curves(datasets, momentum, p_factor)
    if angular:
        l_factor, l_unit = unit_scale([v for d in everything for c, _, _ in angular for v in d[c]],
                                      ["kg m^2/s", "10^3 kg m^2/s", "10^6 kg m^2/s"])
        l_lo, l_hi = axis_range([l_factor * v for d in everything for c, _, _ in angular for v in d[c]])
        g += [f"set y2label 'L / ({l_unit}), right axis'", f"set y2range [{l_lo!r}:{l_hi!r}]", "set y2tics",
              "set my2tics 2", "set border 11"]
        plot += curves(datasets, [(c, t + " (right)", s) for c, t, s in angular], l_factor, "axes x1y2 ")
    if reference and student:
        plot += ["NaN with lines ls 90 title 'reference'", "NaN with lines ls 90 dt student_dash title 'your code'"]
    g += ["plot " + ", \\\n     ".join(plot), RECORD_PANEL]

    # Penetration panel: the deepest contact of each step as detected, before correction.
    if depth_panel:
        d_lo, d_hi = axis_range([1000.0 * v for d in everything for v in d[DEPTH[0]]] + ([1000.0 * slop] if slop else []))
        g += ["unset y2label", "unset y2tics", "unset my2tics", "set border 3", "set title 'Penetration'",
              "set ylabel 'depth / mm'", f"set yrange [{d_lo!r}:{d_hi!r}]"]
        if slop:
            g += [f"set arrow 3 from graph 0, first {1000.0 * slop!r} to graph 1, first {1000.0 * slop!r} nohead dt 2 lw 1.5 lc rgb c_note",
                  f"set label 3 {quote(f'slop {slop * 1000.0:g} mm')} at graph 0.97, first {1000.0 * slop!r} right "
                  "offset 0, character 0.7 font note_font tc rgb c_note"]
        plot = curves(datasets, [DEPTH[:3]], 1000.0)
        if reference and student:
            plot += ["NaN with lines ls 90 title 'reference'", "NaN with lines ls 90 dt student_dash title 'your code'"]
        g += ["plot " + ", \\\n     ".join(plot), RECORD_PANEL]
    g.append("unset multiplot")
    return "\n".join(g)


def sweep_panel(title, runs, dt):
    """One panel: the deepest penetration against the step number, one curve per fraction.
    `runs` is a list of (fraction, csv path, data, dashed, titled)."""
    everything = [d for _, _, d, _, _ in runs]
    steps = len(everything[0]["t"]) - 1
    d_lo, d_hi = axis_range([1000.0 * v for d in everything for v in d[DEPTH[0]]], top_room=0.06)
    g = [f"set title {quote(title)} font title_font noenhanced", f"set xrange [0:{steps}]",
         f"set xtics 0, {tick_step(steps)!r}", "set format x '%g'", "set xlabel 'step k'",
         "set ylabel 'deepest penetration / mm'", f"set yrange [{d_lo!r}:{d_hi!r}]",
         "set key outside right center vertical Left reverse"]
    plot = []
    for n, (fraction, path, data, dashed, titled) in enumerate(runs):
        column = list(data).index(DEPTH[0]) + 1
        clause = f"'{path}' skip 1 using ($1/{dt!r}):(${column}*1000.0) with linespoints ls {31 + n % 6} pt 7 ps 0.5"
        clause += " dt student_dash" if dashed else ""
        clause += f" title {quote(f'β = {fraction:g}')}" if titled else " notitle"
        plot.append(clause)
    if any(run[3] for run in runs):
        plot += ["NaN with lines ls 90 title 'reference'", "NaN with lines ls 90 dt student_dash title 'your code'"]
    g += ["plot " + ", \\\n     ".join(plot), RECORD_PANEL]
    return "\n".join(g)


def run_sweep(simulator, scene, fractions, out_dir, stem):
    """Runs `scene` once per fraction of its sweep; returns [(fraction, csv path, data)]."""
    description = json.loads(scene.read_text())
    runs = []
    for n, fraction in enumerate(fractions):
        variant = dict(description)
        variant.pop("sweep")
        variant["position_correction"] = dict(description.get("position_correction", {}), fraction=fraction)
        scene_path = Path(out_dir, f"{stem}.run-{n}.json")
        csv_path = Path(out_dir, f"{stem}.run-{n}.csv")
        scene_path.write_text(json.dumps(variant))
        try:
            runs.append((fraction, csv_path, run_scene(simulator, scene_path, csv_path)))
        finally:
            scene_path.unlink()
    return runs


render = figure_render.render


def shipped_sweep(scene, fractions):
    """[(fraction, csv path, data)] of the reference's runs shipped for a swept scene, or []
    when any is missing."""
    paths = [reference_runs.run_path(scene, f) for f in fractions]
    if not all(p.is_file() for p in paths):
        return []
    return [(f, p, read_csv(p)) for f, p in zip(fractions, paths)]


def draw_sweep(scene, out_dir, stem, reference_sim, student_sim):
    """A scene with a "sweep": one figure of depth against step, one curve per fraction, and
    one CSV beside it (the step and every run's deepest penetration, m). Without a reference
    simulator the reference's runs shipped with the workbook are drawn, when there are any."""
    description = json.loads(scene.read_text())
    fractions, dt = description["sweep"]["fraction"], description["time_step"]
    runs, made = [], []
    if reference_sim:
        made += run_sweep(reference_sim, scene, fractions, out_dir, stem)
        runs += [(f, p, d, False, True) for f, p, d in made]
    elif student_sim:
        runs += [(f, p, d, False, True) for f, p, d in shipped_sweep(scene, fractions)]
    have_reference = bool(runs)
    if student_sim:
        mine = run_sweep(student_sim, scene, fractions, out_dir, stem + ".yours")
        made += mine
        runs += [(f, p, d, have_reference, not have_reference) for f, p, d in mine]
    title = description["title"] + ("" if have_reference else " (your code)")
    body = sweep_panel(title, runs, dt)
    try:
        # The horizontal axis counts steps: a time t lies at step t / dt.
        render(body, out_dir, stem, scene.name, x_per_second=1.0 / dt)
        with open(out_dir / (stem + ".csv"), "w", newline="") as f:
            writer = csv.writer(f)
            writer.writerow(["step"] + [f"penetration_max_beta_{fr:g}" + ("_yours" if dashed or not have_reference else "")
                                        for fr, _, _, dashed, _ in runs])
            for k in range(len(runs[0][2]["t"])):
                writer.writerow([k] + [repr(d[DEPTH[0]][k]) for _, _, d, _, _ in runs])
    finally:
        for _, path, _ in made:  # the runs made here; never the shipped ones
            path.unlink()


def draw(scene, out_dir, stem, reference, student, scratch):
    """Writes stem.svg, stem.pdf and stem.png for one scene. Values that stop being finite
    end their curves, with a mark on the figure and a note on stdout; returns those notes."""
    description = json.loads(scene.read_text())
    title, responder = description.get("title", scene.stem), description.get("responder", "")
    if student and not reference:
        title += " (your code)"
    t_end = (reference or student)[1]["t"][-1]
    stops, notes = [], []
    runs = {"reference": reference, "your code": student}
    for who, run in list(runs.items()):
        stop = first_nonfinite(run[1]) if run else None
        if stop is None:
            continue
        t_stop = run[1]["t"][stop]
        stops.append((who, t_stop))
        notes.append(f"{scene.name}: the values of {who} stop being finite (NaN or infinite) at t = {t_stop:.6g} s; "
                     f"the curves end there, marked on the figure (the CSV keeps every sample)")
        runs[who] = finite_prefix(run[0], run[1], max(stop, 1), scratch)
    reference, student = runs["reference"], runs["your code"]
    datasets = ([(reference[0], reference[1], False, True)] if reference else []) + \
               ([(student[0], student[1], bool(reference), not reference)] if student else [])
    slop = description.get("position_correction", {}).get("slop") if responder in RESTING else None
    moving_mass = sum(b.get("mass", 0.0) for b in description.get("bodies", [])
                      if not b.get("immovable") and not b.get("kinematic"))
    body = gnuplot_panels(title, responder, datasets, reference, student, t_end, stops, slop, moving_mass)
    render(body, out_dir, stem, scene.name)
    return notes


def draw_families(args, have_reference, scratch):
    """The chapter's family figures (plots/families.py); returns the number of failures."""
    failures = 0
    for family in families.FAMILIES.get(args.chapter, []):
        stem = family["name"] + (".student" if args.student else "")
        print(f"figures: {args.chapter}/{family['name']} (family) -> {args.out / stem}.{{svg,pdf,png,csv}}", flush=True)
        try:
            if family["kind"] == "passes":  # one scene run again and again with other solver settings
                sims = ([("reference", args.sim)] if have_reference else []) + \
                       ([("your code", args.student_sim)] if args.student else [])
                rows = families.run_passes(family, SOURCE, sims, run_scene, scratch)
                body = families.passes(family, rows, scratch)
                families.write_csv(family, rows, {}, scratch, args.out / (stem + ".csv"))
            runs, student_runs = {}, {}
            for member in (families.members(family) if family["kind"] != "passes" else []):
                scene = families.scene_path(SOURCE, member)
                name = member.replace("/", "--")
                if have_reference:
                    path = Path(scratch, name + ".csv")
                    runs[member] = (path, run_scene(args.sim, scene, path))
                elif reference_runs.run_path(scene).is_file():  # the student edition: the shipped run
                    runs[member] = (reference_runs.run_path(scene), read_csv(reference_runs.run_path(scene)))
                # Other chapters' overlays are the reference's alone.
                if args.student and member.split("/")[0] == args.chapter:
                    path = Path(scratch, name + ".student.csv")
                    student_runs[member] = (path, run_scene(args.student_sim, scene, path))
            if family["kind"] != "passes":
                body = families.body(family, runs, student_runs, SOURCE, scratch)
                families.write_csv(family, runs, student_runs, scratch, args.out / (stem + ".csv"))
            script = []
            for ext in FORMATS:
                script += ["reset", f"load {quote(str(STYLE))}", f"eval use_{ext}",
                           f"set output {quote(str(args.out / (stem + '.' + ext)))}", body, "unset output"]
            result = subprocess.run(["gnuplot"], input="\n".join(script) + "\n", capture_output=True, text=True)
            if result.returncode != 0 or result.stderr.strip():
                raise RuntimeError(f"gnuplot on {family['name']}:\n{result.stderr.strip()}")
        except (RuntimeError, OSError, ValueError, KeyError, StopIteration) as error:
            print(f"figures: error: {error}", file=sys.stderr)
            failures += 1
    return failures


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("chapter", help="chapter id, as in chapters/CHAPTERS")
    parser.add_argument("out", type=Path, help="folder for the figures and CSV files")
    parser.add_argument("--scene", type=Path, action="append",
                        help="draw only this scene file (repeatable); default: every chapters/<chapter>/scenes/*.json")
    parser.add_argument("--sim", type=Path, default=SOURCE / "build/dev/tools/workbook-sim",
                        help="reference simulator (default: %(default)s)")
    parser.add_argument("--no-reference", action="store_true",
                        help="there are no reference solutions (the student edition): draw the student's curves alone")
    parser.add_argument("--student", action="store_true", help="also run the student's simulator and overlay it")
    parser.add_argument("--families", action="store_true",
                        help="draw the chapter's family figures (plots/families.py) instead of one figure per scene")
    parser.add_argument("--student-sim", type=Path, default=SOURCE / "build/dev/tools/workbook-sim-student",
                        help="the student's simulator (default: %(default)s)")
    args = parser.parse_args()

    scenes = args.scene or sorted((SOURCE / "chapters" / args.chapter / "scenes").glob("*.json"))
    if not scenes and not args.families:
        sys.exit(f"figures.py: no scenes for chapter '{args.chapter}'")
    have_reference = not args.no_reference
    if args.no_reference and not args.student:
        sys.exit("figures.py: --no-reference needs --student: without the reference there is only your code to draw")
    if have_reference and not args.sim.is_file():
        sys.exit(f"figures.py: no reference simulator at {args.sim} (build it, or pass --no-reference --student)")
    if args.student and not args.student_sim.is_file():
        sys.exit(f"figures.py: no student simulator at {args.student_sim}")
    args.out.mkdir(parents=True, exist_ok=True)

    failures = 0
    with tempfile.TemporaryDirectory() as scratch:
        if args.families:
            sys.exit(1 if draw_families(args, have_reference, scratch) else 0)
        for scene in scenes:
            stem = scene.stem + (".student" if args.student else "")
            overlay = have_reference or reference_runs.shipped(scene)
            what = ("your code over the reference" if overlay else "your code") if args.student else "reference"
            print(f"figures: {args.chapter}/{scene.name} ({what}) -> {args.out / stem}.{{svg,pdf,png,csv}}", flush=True)
            try:
                description = json.loads(scene.read_text())
                if "sweep" in description:
                    draw_sweep(scene, args.out, stem, args.sim if have_reference else None,
                               args.student_sim if args.student else None)
                    continue
                watched = spin.watched_body(description)
                if watched is not None:  # a box turning freely: its spin in its own frame
                    sims = ([("reference", args.sim)] if have_reference else []) + \
                           ([("your code", args.student_sim)] if args.student else [])
                    runs = []
                    for n, (who, sim) in enumerate(sims):
                        path, trajectory = Path(scratch, f"{stem}.{n}.csv"), Path(scratch, f"{stem}.{n}.trajectory.csv")
                        runs.append((who, (path, run_scene(sim, scene, path, trajectory)), trajectory))
                    spin.draw(scene, description, watched, runs, args.out, stem)
                    continue
                reference = student = None
                if have_reference:
                    path = Path(scratch, scene.stem + ".csv") if args.student else args.out / (stem + ".csv")
                    reference = (path, run_scene(args.sim, scene, path))
                elif reference_runs.run_path(scene).is_file():  # the student edition: the shipped run
                    path = reference_runs.run_path(scene)
                    reference = (path, read_csv(path))
                if args.student:
                    path = args.out / (stem + ".csv")
                    student = (path, run_scene(args.student_sim, scene, path))
                for note in draw(scene, args.out, stem, reference, student, scratch):
                    print(f"figures: note: {note}", flush=True)
            except (RuntimeError, OSError, ValueError, KeyError) as error:
                print(f"figures: error: {error}", file=sys.stderr)
                failures += 1
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
