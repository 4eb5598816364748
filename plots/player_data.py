"""The site's motion player data: one scene's motion, energy and momentum as a JavaScript file.

plots/strobe.py writes <scene>[.student].player.js beside the figures; the docs target copies
them, with plots/motion-player.js, into the site (plots/site_motion.py). A <script> file and
not JSON, because browsers refuse to fetch JSON from file:// pages and the site must work
offline from a folder. Everything is already in the picture's coordinates (metres in the
chosen view), so the player only scales and draws.
"""

import json
import math

import motion

MOST_FRAMES = 400   # the player interpolates nothing: it shows the nearest stored frame
MOST_SAMPLES = 600  # points per energy or momentum curve


def evenly(count, most):
    """Up to `most` indices from 0 to count - 1, evenly spread, both ends included."""
    if count <= most:
        return list(range(count))
    return sorted({round(k * (count - 1) / (most - 1)) for k in range(most)})


def shape_data(shape):
    if shape[0] == "circle":
        return {"c": [round(shape[1][0], 6), round(shape[1][1], 6), round(shape[2], 6)]}
    return {"p": [[round(x, 6), round(y, 6)] for x, y in shape[1]]}


def series_data(series):
    """Energy and momentum curves from the time series ({column: [values]}), thinned evenly.
    Each step is kept as a step: the thinning keeps the samples on both sides of a response."""
    t = series["t"]
    keep = set(evenly(len(t), MOST_SAMPLES))
    for i, change in enumerate(series["response_energy_change"]):
        if change != 0.0 and len(keep) < 2 * MOST_SAMPLES:
            keep |= {max(i - 1, 0), i}
    index = sorted(keep)
    pick = lambda column: [series[column][i] for i in index]  # noqa: E731
    energy = [("total", "total", "#9A9A9A"), ("kinetic", "kinetic", "#0072B2"), ("potential", "potential", "#009E73")]
    kinetic = [a + b for a, b in zip(series["kinetic_linear"], series["kinetic_rotational"])]
    columns = dict(series, kinetic=kinetic)
    scale = max((abs(v) for v in columns["total"] + kinetic), default=0.0) or 1.0
    e = [{"name": title, "colour": colour, "v": [columns[c][i] for i in index]} for c, title, colour in energy
         if c != "potential" or max(abs(v) for v in columns[c]) > 1e-9 * scale]
    p_columns = [("momentum_x", "p_x", "#0072B2"), ("momentum_y", "p_y", "#D55E00"), ("momentum_z", "p_z", "#009E73")]
    p_scale = max((abs(v) for c, _, _ in p_columns for v in series[c]), default=0.0)
    p = [{"name": title, "colour": colour, "v": pick(c)} for c, title, colour in p_columns
         if max(abs(v) for v in series[c]) > 1e-9 * p_scale] or [{"name": "p_x", "colour": "#0072B2", "v": pick("momentum_x")}]
    return {"t": [t[i] for i in index], "energy": e, "momentum": p}


def write(path, chapter, scene, runs, series, view, box, slow_motion):
    """runs: [(Trajectory, contacts, is_student)]; series: the first run's time series."""
    bodies = [{"name": scene.names[i], "colour": motion.BODY_COLOURS[i % len(motion.BODY_COLOURS)]}
              for i in motion.movable(scene)]
    planes = []
    depth = 0.035 * max(box[1] - box[0], box[3] - box[2])
    for i, body in enumerate(scene.bodies):
        if body["shape"]["type"] != "plane":
            continue
        position, q, _ = runs[0][0].states[0][i]
        trace = motion.plane_line(body, position, q, view)
        if trace is None:
            continue
        (px, py), (nx, ny) = trace
        ends = motion.clip_line((px, py), (-ny, nx), box)
        if ends:
            a, b = ends
            band = motion.clip_polygon([a, b, (b[0] - depth * nx, b[1] - depth * ny), (a[0] - depth * nx, a[1] - depth * ny)], box)
            planes.append({"name": scene.names[i], "line": [list(a), list(b)], "band": [list(p) for p in band]})
    run_data = []
    for trajectory, contacts, student in runs:
        frames = evenly(len(trajectory.times), MOST_FRAMES)
        shapes = [[shape_data(motion.outline(scene.bodies[i], *trajectory.states[k][i][:2], view))
                   for i in motion.movable(scene)] for k in frames]
        touches = []
        for c in motion.contact_onsets(contacts):
            length = motion.normal_arrow_length(scene, c, box)
            point = view.project([c["x"], c["y"], c["z"]])
            normal = view.project([c["nx"], c["ny"], c["nz"]])
            size = math.hypot(*normal) or 1.0
            touches.append({"t": c["t"], "from": list(point),
                            "to": [point[0] + length * normal[0] / size, point[1] + length * normal[1] / size],
                            "text": motion.impulse_text(c["impulse"])})
        run_data.append({"student": student, "t": [trajectory.times[k] for k in frames], "shapes": shapes,
                         "touches": touches})
    data = {"chapter": chapter, "scene": scene.path.stem, "title": scene.title, "duration": scene.duration,
            "slow_motion": slow_motion, "view": {"name": view.name, "x": view.xlabel, "y": view.ylabel},
            "box": list(box), "bodies": bodies, "planes": planes, "runs": run_data, "series": series_data(series)}
    text = "(window.WorkbookMotion = window.WorkbookMotion || []).push(" + json.dumps(data, separators=(",", ":")) + ");\n"
    path.write_text(text)
