"""The figure of a box turning freely, for plots/figures.py: its spin in its own frame.

A free body's angular momentum L is constant in the world frame, so the probes' curves of a
box spinning alone are flat lines, and the tennis-racket effect (a box spun about its middle
axis turns over and over) cannot be seen in them. It shows in the body frame: the angular
velocity as the box itself sees it, R^T w, swings from +w to -w at every flip. This module
draws that from the simulator's trajectory file (orientation and world angular velocity per
step), beside the kinetic energy and |L| from its time series, which stay constant.

A scene gets this figure instead of the energy and momentum panels when nothing responds
(responder "none") and its one movable body is a box that spins: see watched_body().
"""

import csv
import math
from pathlib import Path

from plots import figure_render
from plots import motion

AXES = "xyz"
RANKS = ["smallest", "middle", "largest"]


quote = figure_render.quote


def watched_body(description):
    """Index of the body whose spin the figure follows, or None for an ordinary scene: the
    scene has no responder and exactly one movable body, a box with an angular velocity."""
    if description.get("responder") != "none":
        return None
    bodies = description.get("bodies", [])
    movable = [i for i, b in enumerate(bodies) if not b.get("immovable") and not b.get("kinematic")]
    if len(movable) != 1:
        return None
    body = bodies[movable[0]]
    spinning = any(v != 0 for v in body.get("angular_velocity", [0, 0, 0]))
    return movable[0] if body.get("shape", {}).get("type") == "box" and spinning else None


def moment_ranks(half_extents):
    """For each body axis, whether its moment of inertia is the smallest, middle or largest
    (a box's moment about x goes with b^2 + c^2, the squares of the other two half extents)."""
    squares = [h * h for h in half_extents]
    moments = [sum(squares) - s for s in squares]
    order = sorted(range(3), key=lambda a: moments[a])
    return {axis: RANKS[order.index(axis)] for axis in range(3)}


def body_spin(trajectory_path, body):
    """[(t, (wx, wy, wz) in the body frame)] of one body, from a `workbook-sim run --trajectory` file."""
    series = []
    with open(trajectory_path, newline="") as f:
        for row in csv.DictReader(f):
            if int(row["body"]) != body:
                continue
            # Along each of the body's own axes, as the simulator wrote them (R^T w).
            w = [float(row[c]) for c in ("wx", "wy", "wz")]
            series.append((float(row["t"]), tuple(sum(a * b for a, b in zip(axis, w)) for axis in motion.axes_of(row))))
    return series


def sign_changes(times, values):
    """Times at which `values` changes sign, each found by linear interpolation within its step."""
    found = []
    for i in range(1, len(values)):
        a, b = values[i - 1], values[i]
        if (a > 0.0) != (b > 0.0):
            found.append(times[i - 1] + (times[i] - times[i - 1]) * a / (a - b))
    return found


def largest_relative_change(values):
    return max(abs(v - values[0]) for v in values) / abs(values[0]) if values and values[0] != 0.0 else 0.0


def exponent_text(value):
    """1.4e-14 as gnuplot's enhanced 1.4·10^{-14}; 0 as 0."""
    if value == 0.0:
        return "0"
    power = math.floor(math.log10(value))
    return f"{value / 10.0 ** power:.1f}·10^{{{power}}}"


def series_of(trajectory_path, data, body):
    """The drawn series of one run: time, body-frame spin, kinetic energy and |L| per step.
    The trajectory has one frame per step (stride 1), as the time series has one row."""
    spin = body_spin(trajectory_path, body)
    if len(spin) != len(data["t"]):
        raise RuntimeError(f"{trajectory_path}: {len(spin)} frames of body {body}, but {len(data['t'])} samples")
    columns = {
        "t": data["t"],
        "spin_x": [w[0] for _, w in spin], "spin_y": [w[1] for _, w in spin], "spin_z": [w[2] for _, w in spin],
        "kinetic_energy": [a + b for a, b in zip(data["kinetic_linear"], data["kinetic_rotational"])],
        "angular_momentum_magnitude": [math.sqrt(x * x + y * y + z * z) for x, y, z in
                                       zip(data["angular_momentum_x"], data["angular_momentum_y"], data["angular_momentum_z"])],
    }
    for name, values in columns.items():
        if not all(math.isfinite(v) for v in values):
            t = next(t for t, v in zip(data["t"], values) if not math.isfinite(v))
            raise RuntimeError(f"{trajectory_path}: {name} stops being finite at t = {t:g} s")
    return columns


def write_csv(path, runs):
    """One CSV of what is drawn: every run's columns, the second run's (the student's over the
    reference) with the suffix _yours."""
    header, columns = ["t"], [runs[0][1]["t"]]
    for n, (_, series) in enumerate(runs):
        for name, values in series.items():
            if name != "t":
                header.append(name + ("_yours" if n else ""))
                columns.append(values)
    with open(path, "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(header)
        for row in zip(*columns):
            writer.writerow([repr(v) for v in row])
    return header


def gnuplot_body(title, description, body, runs, csv_path, header):
    """The multiplot (everything after `set output`): body-frame spin on the left, kinetic
    energy and |L| on the right. `runs` is [(who, series)], the first one solid."""
    shape = description["bodies"][body]["shape"]
    ranks = moment_ranks(shape["half_extents"])
    main = runs[0][1]
    t_end = main["t"][-1]
    spins = [main["spin_" + a] for a in AXES]
    watched = max(range(3), key=lambda a: abs(spins[a][0]))  # the axis it was spun about
    flips = sign_changes(main["t"], spins[watched])
    top = max(abs(v) for values in spins for v in values)
    energy, momentum = main["kinetic_energy"], main["angular_momentum_magnitude"]

    def column(name, n):
        return header.index(name + ("_yours" if n else "")) + 1

    def style(n):
        return " dt student_dash" if n else ""

    overlay = len(runs) > 1
    flip_text = f"ω_{AXES[watched]} changes sign {len(flips)} time{'s' if len(flips) != 1 else ''}"
    if len(flips) >= 2:
        flip_text += f", every {(flips[-1] - flips[0]) / (len(flips) - 1):.2f} s"
    flip_text += " (reference)" if overlay else ""
    g = [f"set multiplot layout 1,2 title {quote(title)} font title_font noenhanced",
         f"set xrange [0:{t_end!r}]", "set xlabel 't / s'",
         # Left: the spin as the box sees it.
         "set title 'Angular velocity in the body frame'", "set ylabel 'ω / (rad/s)'",
         f"set yrange [{-1.2 * top!r}:{1.45 * top!r}]",
         f"set label 1 {quote(flip_text)} at graph 0.02, graph 0.93 left font label_font tc rgb c_drop"]
    plot = []
    for n, (who, _) in enumerate(runs):
        for a, axis in enumerate(AXES):
            name = f"ω_{axis}, body {axis} axis ({ranks[a]} moment)" if n == 0 else ""
            plot.append(f"'{csv_path}' skip 1 using 1:{column('spin_' + axis, n)} with lines ls {51 + a}{style(n)}"
                        + (f" title {quote(name)}" if name else " notitle"))
    if overlay:
        plot += ["NaN with lines ls 90 title 'reference'", "NaN with lines ls 90 dt student_dash title 'your code'"]
    g += ["plot " + ", \\\n     ".join(plot), figure_render.RECORD_PANEL, "unset label"]

    # Right: what stays constant, each on its own axis, with its largest relative change
    # written in the free space below the two lines.
    changes = (f"E: {exponent_text(largest_relative_change(energy))},   "
               f"|L|: {exponent_text(largest_relative_change(momentum))}")
    g += ["set title 'Kinetic energy and angular momentum'", "set ylabel 'E / J'",
          f"set yrange [0:{1.6 * max(energy)!r}]",
          "set y2label '|L| / (kg m^2/s), right axis'", f"set y2range [0:{1.25 * max(momentum)!r}]",
          "set y2tics", "set my2tics 2", "set border 11",
          f"set label 1 {quote('largest relative change' + (' (reference)' if overlay else ''))} "
          "at graph 0.5, graph 0.36 center font label_font tc rgb c_drop",
          f"set label 2 {quote(changes)} at graph 0.5, graph 0.26 center font label_font tc rgb c_drop"]
    plot = []
    for n, _ in enumerate(runs):
        plot.append(f"'{csv_path}' skip 1 using 1:{column('kinetic_energy', n)} with lines ls 3{style(n)}"
                    + (" title 'E, kinetic'" if n == 0 else " notitle"))
        plot.append(f"'{csv_path}' skip 1 using 1:{column('angular_momentum_magnitude', n)} axes x1y2 with lines ls 22{style(n)}"
                    + (" title '|L| (right)'" if n == 0 else " notitle"))
    if overlay:
        plot += ["NaN with lines ls 90 title 'reference'", "NaN with lines ls 90 dt student_dash title 'your code'"]
    g += ["plot " + ", \\\n     ".join(plot), figure_render.RECORD_PANEL, "unset multiplot"]
    return "\n".join(g)


def draw(scene, description, body, runs, out_dir, stem):
    """Writes stem.{svg,pdf,png} and stem.csv. `runs` is [(who, (time-series path, data), trajectory
    path)], the reference (or the student's code alone) first."""
    series = [(who, series_of(trajectory, data, body)) for who, (_, data), trajectory in runs]
    csv_path = Path(out_dir, stem + ".csv")
    header = write_csv(csv_path, series)
    title = description.get("title", scene.stem) + ("" if runs[0][0] == "reference" else " (your code)")
    body_text = gnuplot_body(title, description, body, series, csv_path, header)
    figure_render.render(body_text, Path(out_dir), stem, scene.name)
