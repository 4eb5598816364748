"""The site's motion player data: one scene's motion as a JavaScript file.

plots/strobe.py writes <scene>[.student].player.js beside the figures; the docs target copies
them, with plots/motion-player.js, into the site (plots/site_motion.py). A <script> file and
not JSON, because browsers refuse to fetch JSON from file:// pages and the site must work
offline from a folder. Everything is already in the picture's coordinates (metres in the
chosen view), so the player only scales and draws.
"""

import json
import math

from plots import motion

# The player interpolates nothing: it shows the nearest stored frame. It stores as many as the
# film has (25 per second of film), within these bounds, so a turning box turns as smoothly.
FILM_FPS = 25
FEWEST_FRAMES, MOST_FRAMES = 100, 1000


def evenly(count, most):
    """Up to `most` indices from 0 to count - 1, evenly spread, both ends included."""
    if count <= most:
        return list(range(count))
    return sorted({round(k * (count - 1) / (most - 1)) for k in range(most)})


def shape_data(shape, hands=None):
    """A circle {"c": [x, y, r]} or a polygon {"p": [[x, y], ...]}, with a box's own axes
    {"a": [[x0, y0, x1, y1], ...]} (motion.box_hands)."""
    if shape[0] == "circle":
        data = {"c": [round(shape[1][0], 6), round(shape[1][1], 6), round(shape[2], 6)]}
    else:
        data = {"p": [[round(x, 6), round(y, 6)] for x, y in shape[1]]}
    if hands:
        data["a"] = [[round(v, 6) for v in start + end] for start, end in hands]
    return data


def write(path, chapter, scene, runs, view, box, slow_motion):
    """runs: [(Trajectory, contacts, is_student)]. The scene's energy and momentum are not
    here: the player shows the chapter's own figure (plots/site_motion.py)."""
    bodies = [{"name": scene.names[i], "colour": motion.body_colour(scene, i)} for i in motion.movable(scene)]
    planes = []
    depth = 0.035 * max(box[1] - box[0], box[3] - box[2])
    for i, body in enumerate(scene.bodies):
        if body["shape"]["type"] != "plane":
            continue
        position, axes, _ = runs[0][0].states[0][i]
        trace = motion.plane_line(body, position, axes, view)
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
        film = round(scene.duration * slow_motion * FILM_FPS) + 1
        frames = evenly(len(trajectory.times), max(FEWEST_FRAMES, min(MOST_FRAMES, film)))
        shapes = [[shape_data(motion.outline(scene.bodies[i], *trajectory.states[k][i][:2], view),
                              motion.box_hands(scene.bodies[i], *trajectory.states[k][i][:2], view))
                   for i in motion.movable(scene)] for k in frames]
        touches = []
        for c in motion.marked_touches(scene, contacts):
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
            "slow_motion": slow_motion, "touch_window": motion.TOUCH_FILM_SECONDS / slow_motion, "view": {"name": view.name, "x": view.xlabel, "y": view.ylabel},
            "box": list(box), "bodies": bodies, "key": [list(e) for e in motion.key_entries(scene)], "planes": planes,
            "runs": run_data}
    text = "(window.WorkbookMotion = window.WorkbookMotion || []).push(" + json.dumps(data, separators=(",", ":")) + ");\n"
    path.write_text(text)
