"""Figures that compare several runs, for plots/figures.py --families.

A chapter lists its families in FAMILIES below; each entry is one figure, drawn from scenes of
the chapter (and of earlier chapters, for overlays) in the shared style of plots/style.gp.
Kinds:

  staircase  kinetic energy over time for several scenes on one axis, one colour each, with
             optional overlays from other chapters drawn dashed on top;
  apexes     for a ball bouncing on the ground: the height of each apex after a bounce next to
             the closed form e^(2k) h0, and the relative error of each apex beside it.
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
}


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

