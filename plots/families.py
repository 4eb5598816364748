"""Figures that compare several runs, for plots/figures.py --families.

A chapter lists its families in FAMILIES below; each entry is one figure, drawn from scenes of
the chapter (and of earlier chapters, for overlays) in the shared style of plots/style.gp.
Kinds:

  staircase  kinetic energy over time for several scenes on one axis, one colour each, with
             optional overlays from other chapters drawn dashed on top;
  apexes     for a ball bouncing on the ground: the height of each apex after a bounce next to
             the closed form e^(2k) h0, and the relative error of each apex beside it;
  passes     for a scene with a contact solver: the scene run again for each most number of
             velocity passes per step, warm started and not, and what each run leaves: the
             deepest overlap of its last second and how far the bodies sank (plots/figures.py
             runs them: run_passes below).
"""

import json
from pathlib import Path

FAMILIES = {
    "linear-impulse": [
        {"name": "energy-staircase", "kind": "staircase",
         "title": "Head-on carts, 2 kg at 3 m/s into 1 kg at rest: kinetic energy for four e",
         "members": [("linear-impulse/head-on-carts-e0", "e = 0"), ("linear-impulse/head-on-carts-e05", "e = 0.5"),
                     ("linear-impulse/head-on-carts-e08", "e = 0.8"), ("linear-impulse/head-on-carts-e1", "e = 1")],
         "overlays": [("inelastic/head-on-carts", "chapter 1, inelastic")]},
        {"name": "bouncing-ball-apexes", "kind": "apexes", "scene": "linear-impulse/bouncing-ball",
         "title": "Ball bouncing at e = 0.8: apex height after each bounce"},
    ],
    "resting-contact": [
        {"name": "passes-against-accuracy", "kind": "passes", "scene": "resting-contact/column-of-15-balls",
         "seconds": 5.0, "passes": [1, 2, 4, 8, 16, 32, 64, 128, 256],
         "title": "Fifteen balls standing for 5 s: what the velocity passes of a step leave"},
    ],
}

PASSES_COLUMNS = ["who", "warm_start", "passes", "overlap_mm", "sunk_mm"]


def passes_variant(spec, passes, warm_start, seconds):
    """The scene description run for one point of a passes figure."""
    # The passes alone: a shock sweep, or speculative contacts, would hold the column up at
    # any number of passes and hide what the figure measures.
    solver = dict(spec.get("contact_solver", {}), velocity_iterations=passes, warm_start=warm_start, shock_sweeps=0,
                  speculative_distance=0.0)
    return dict(spec, duration=seconds, contact_solver=solver)


def passes_measures(spec, data, seconds):
    """(deepest overlap of the last second in mm, how far the bodies' mean height fell in mm)."""
    last = [d for t, d in zip(data["t"], data["penetration_max"]) if t >= seconds - 1.0 - 1e-9]
    mass = sum(b.get("mass", 0.0) for b in spec["bodies"] if not b.get("immovable"))
    g = sum(v * v for v in spec.get("gravity", [0, 0, 0])) ** 0.5
    sunk = (data["potential"][0] - data["potential"][-1]) / (mass * g)
    return 1000.0 * max(last), 1000.0 * sunk


def run_passes(family, source, sims, run_scene, scratch):
    """Rows of PASSES_COLUMNS: the family's scene for each of its pass counts, warm started and
    not, with each (name, simulator) of `sims`; run_scene(sim, scene, csv) as plots/figures.py's."""
    spec = json.loads(scene_path(source, family["scene"]).read_text())
    rows = []
    for who, sim in sims:
        for warm in (True, False):
            for n in family["passes"]:
                variant = Path(scratch, f"passes-{who.replace(' ', '-')}-{int(warm)}-{n}.json")
                variant.write_text(json.dumps(passes_variant(spec, n, warm, family["seconds"])))
                data = run_scene(sim, variant, variant.with_suffix(".csv"))
                rows.append([who, warm, n, *passes_measures(spec, data, family["seconds"])])
    return rows


SOURCE = Path(__file__).resolve().parent.parent


def passes(family, rows, scratch):
    """gnuplot body: the overlap left and the sinking against the passes per step (log scale)."""
    table = Path(scratch, family["name"] + ".dat")
    series = []
    with open(table, "w") as out:
        for who in dict.fromkeys(r[0] for r in rows):
            for warm in (True, False):
                chosen = [r for r in rows if r[0] == who and r[1] == warm]
                series.append((who, warm, len(series)))
                out.write("".join(f"{r[2]},{r[3]!r},{r[4]!r}\n" for r in chosen) + "\n\n")
    most = max(r[2] for r in rows)
    g = [f"set multiplot layout 1,2 title {quote(family['title'])} font title_font noenhanced",
         "set logscale x 2", f"set xrange [0.8:{most * 1.25!r}]", "set xlabel 'velocity passes per step, at most'",
         "set format x '%g'", "set key outside below center horizontal Left reverse"]
    slop = 1000.0 * json.loads(scene_path(SOURCE, family["scene"]).read_text()).get("position_correction", {}).get("slop", 0.0)
    for column, title, ylabel in ((2, "Deepest overlap, last second", "depth / mm"), (3, "How far the balls sank", "mean height lost / mm")):
        top = max(r[column + 1] for r in rows)
        low = min([r[column + 1] for r in rows] + ([slop] if column == 2 and slop > 0 else []))
        g += [f"set title {quote(title)}", f"set ylabel {quote(ylabel)}", "set logscale y 10", "set format y '%g'",
              f"set yrange [{max(low, 1e-3) * 0.5!r}:{top * 2.0!r}]", "unset arrow", "unset label"]
        if column == 2 and slop > 0:  # the overlap the position pass leaves alone
            g += [f"set arrow 1 from graph 0, first {slop!r} to graph 1, first {slop!r} nohead dt 2 lw 1.5 lc rgb c_note",
                  f"set label 1 {quote(f'slop {slop:g} mm')} at graph 0.97, first {slop!r} right offset 0, character 0.7 "
                  "font note_font tc rgb c_note"]
        plot = []
        for who, warm, index in series:
            style = 61 if warm else 62
            dashed = " dt student_dash" if who == "your code" and len(series) > 2 else ""
            label = ("warm started" if warm else "from zero") + ("" if who == "reference" else f" ({who})")
            plot.append(f"'{table}' index {index} using 1:{column} with linespoints ls {style}{dashed} title {quote(label)}")
        g.append("plot " + ", \\\n     ".join(plot))
    g.append("unset multiplot")
    return "\n".join(g)


def scene_path(source, member):
    chapter, stem = member.split("/")
    return source / "chapters" / chapter / "scenes" / (stem + ".json")


def quote(text):
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"') + '"'


def staircase(family, runs, student_runs):
    """gnuplot body: kinetic energy against time, one curve per member (dashed: the student's)."""
    g = [f"set title {quote(family['title'])} font title_font noenhanced", "set xlabel 't / s'", "set ylabel 'E_{kin} / J'",
         "set key outside right center vertical Left reverse samplen 3"]
    top = max(max(data["kinetic_linear"]) for _, data in runs.values()) if runs else \
        max(max(data["kinetic_linear"]) for _, data in student_runs.values())
    t_end = max(data["t"][-1] for source in (runs, student_runs) for _, data in source.values())
    g += [f"set yrange [0:{top * 1.1!r}]", f"set xrange [0:{t_end!r}]"]
    clauses = []
    for i, (member, label) in enumerate(family["members"]):
        for source, dashed, suffix in ((runs, False, ""), (student_runs, bool(runs), " (your code)")):
            if member not in source:
                continue
            path, data = source[member]
            column = list(data).index("kinetic_linear") + 1
            clause = f"'{path}' skip 1 using 1:{column} with lines ls {61 + i}"
            clause += (" dt student_dash" if dashed else "") + f" title {quote(label + (suffix if dashed else ''))}"
            clauses.append(clause)
    for member, label in family.get("overlays", []):
        if member in runs:
            path, data = runs[member]
            clauses.append(f"'{path}' skip 1 using 1:{list(data).index('kinetic_linear') + 1} with lines ls 65 title {quote(label)}")
    g.append("plot " + ", \\\n     ".join(clauses))
    return "\n".join(g)


def apexes_of(data, mass, radius, g):
    """Heights of the ball's lowest point at each apex after a bounce, from the potential energy
    (one movable body: potential = m g y)."""
    heights = [p / (mass * g) - radius for p in data["potential"]]
    found, bounced = [], False
    for i in range(1, len(heights) - 1):
        if data["response_energy_change"][i] != 0.0:
            bounced = True
        # The apex: the first local maximum of the height after a bounce.
        if bounced and heights[i] >= heights[i - 1] and heights[i] > heights[i + 1]:
            found.append(heights[i])
            bounced = False
    return found


def apexes(family, runs, student_runs, source, scratch):
    """gnuplot body: two panels, apex heights against the closed form, and their relative error."""
    scene = json.loads(scene_path(source, family["scene"]).read_text())
    ball = next(b for b in scene["bodies"] if not b.get("immovable"))
    ground = next(b for b in scene["bodies"] if b.get("immovable"))
    e = min(ball.get("restitution", 1.0), ground.get("restitution", 1.0))
    g_value = -scene["gravity"][1]
    radius = ball["shape"]["radius"]
    h0 = ball["position"][1] - radius
    series = []
    for source_runs, label, style in ((runs, "simulation", 71), (student_runs, "your code", 73)):
        if family["scene"] in source_runs:
            series.append((label, style, apexes_of(source_runs[family["scene"]][1], ball["mass"], radius, g_value)))
    # A run without a single bounce (an unfinished responder) has no apexes: it is named in a
    # note instead of drawn, and the closed form is shown for six bounces.
    count = max([len(s[2]) for s in series] + [0]) or 6
    missing = [label for label, _, values in series if not values]
    table = Path(scratch) / (family["name"] + ".dat")
    with open(table, "w") as out:
        out.write(",".join(["k", "closed_form_m"] + [f"{label.replace(' ', '_')}_{c}" for label, _, _ in series
                                                      for c in ("m", "error_percent")]) + "\n")
        for k in range(1, count + 1):
            ideal = e ** (2 * k) * h0
            row = [str(k), repr(ideal)]
            for _, _, values in series:
                row += [repr(values[k - 1]), repr(100.0 * (values[k - 1] - ideal) / ideal)] if k <= len(values) else ["NaN", "NaN"]
            out.write(",".join(row) + "\n")
    fine = Path(scratch) / (family["name"] + ".curve.dat")
    with open(fine, "w") as out:
        for i in range(0, 10 * count + 1):
            k = 0.5 + i / 10.0
            out.write(f"{k!r},{e ** (2 * k) * h0!r}\n")
    g = [f"set multiplot layout 1,2 title {quote(family['title'])} font title_font noenhanced",
         f"set xrange [0.5:{count + 0.5!r}]", "set xtics 1", "set mxtics 1", "set xlabel 'bounce k'",
         "set title 'Apex height'", "set ylabel 'h / m'", "set key inside top right vertical Left reverse", f"set yrange [0:{h0 * e * e * 1.1!r}]"]
    plot = [f"'{fine}' using 1:2 with lines ls 72 title {quote('closed form e^{2k} h_0, e = ' + repr(e))}"]
    for n, (label, style, values) in enumerate(series):
        if values:
            plot.append(f"'{table}' skip 1 using 1:{3 + 2 * n} with linespoints ls {style} title {quote(label)}")
    for n, label in enumerate(missing):
        g.append(f"set label {20 + n} {quote(label + ': no bounce')} at graph 0.05, graph {0.1 + 0.08 * n!r} "
                 "font label_font tc rgb c_drop noenhanced")
    g.append("plot " + ", \\\n     ".join(plot))
    worst = max((abs(100.0 * (v - e ** (2 * k) * h0) / (e ** (2 * k) * h0))
                 for _, _, values in series for k, v in enumerate(values, 1)), default=1.0)
    g += ["set title 'Error against the closed form'", "set ylabel '(h_k - e^{2k} h_0) / e^{2k} h_0 / %'",
          f"set yrange [{-1.15 * worst!r}:{1.15 * worst!r}]", "set arrow 5 from graph 0, first 0 to graph 1, first 0 nohead lw 1 lc rgb c_note"]
    plot = []
    for n, (label, style, values) in enumerate(series):
        if values:
            plot.append(f"'{table}' skip 1 using 1:{4 + 2 * n} with linespoints ls {style} title {quote(label)}")
    g += ["plot " + (", \\\n     ".join(plot) or "0 with lines ls 72 notitle"), "unset multiplot"]
    return "\n".join(g)


def write_csv(family, runs, student_runs, scratch, path):
    """The numbers a family figure draws, as CSV beside it."""
    if family["kind"] == "apexes":
        path.write_text((Path(scratch) / (family["name"] + ".dat")).read_text())
        return
    if family["kind"] == "passes":  # runs: the rows of run_passes()
        path.write_text(",".join(PASSES_COLUMNS) + "\n" + "".join(",".join(str(v) for v in row) + "\n" for row in runs))
        return
    columns = []
    for source, suffix in ((runs, ""), (student_runs, "_your_code")):
        for member, data in source.items():
            columns.append((member.replace("/", "_").replace("-", "_") + suffix + "_kinetic_J", data[1]["kinetic_linear"], data[1]["t"]))
    times = columns[0][2]
    with open(path, "w") as out:
        out.write(",".join(["t"] + [name for name, _, _ in columns]) + "\n")
        for i, t in enumerate(times):
            out.write(",".join([repr(t)] + [repr(values[i]) if i < len(values) else "" for _, values, _ in columns]) + "\n")


def members(family):
    """Every scene a family runs, as 'chapter/stem'."""
    if family["kind"] == "staircase":
        return [m for m, _ in family["members"]] + [m for m, _ in family.get("overlays", [])]
    return [family["scene"]]


def body(family, runs, student_runs, source, scratch):
    if family["kind"] == "staircase":
        return staircase(family, runs, student_runs)
    if family["kind"] == "apexes":
        return apexes(family, runs, student_runs, source, scratch)
    raise ValueError(f"unknown family kind {family['kind']}")

