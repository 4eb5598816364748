"""What the motion pictures share: reading trajectories, choosing the view, and drawing bodies.

The strobe pictures (strobe.py), the animations (animate.py) and the cross-chapter comparison
(compare.py) all draw from the files `workbook-sim run --trajectory` writes (columns in
docs/scene-format.md); nothing here runs the simulation except `simulate`, which asks the
simulator for those files. Shapes (radius, plane normal, box half extents) come from the
scene file, positions and orientations from the trajectory.

Drawing is gnuplot commands in the plot's own coordinates (Canvas), with `set size ratio -1`
so that one metre is as long across as up and circles stay circles.
"""

import csv
import json
import math
import subprocess
from pathlib import Path

PLOTS = Path(__file__).resolve().parent
SOURCE = PLOTS.parent
STYLE = PLOTS / "style.gp"
FORMATS = ["svg", "pdf", "png"]
AXES = "xyz"

# One colour per body, in scene order (style.gp's Okabe-Ito palette); the student's bodies in
# an overlay are all drawn in STUDENT_COLOUR, dashed.
BODY_COLOURS = ["#0072B2", "#D55E00", "#009E73", "#E69F00", "#56B4E9", "#B8A000"]
STUDENT_COLOUR = "#CC79A7"
GROUND_FILL = "#E4E4E4"
GROUND_LINE = "#505050"
CONTACT_COLOUR = "#B2182B"  # style.gp's c_drop: what the response did

# A scene runs in well under a second; a student's endless loop must not hang the figures.
SCENE_TIME_LIMIT = 120

# A heavy scene: more than this many body-seconds (bodies x duration), chapter 5's pile, column,
# pyramid and minute-long stacks; the scenes of chapters 1 to 4 have at most 28.
HEAVY_BODY_SECONDS = 100
# The sanitizer build (build/sanitize) runs the tests again, some 20 times slower, to catch
# memory and undefined-behaviour errors, which a short stretch of a scene shows as well as the
# whole: there the tests run a heavy scene's first half second only (the pile's discs have
# landed, the stacks stand). The dev build's tests run every scene whole.
SANITIZED_SECONDS = 0.5


def is_heavy(spec):
    """True for a scene of more than HEAVY_BODY_SECONDS body-seconds."""
    return len(spec.get("bodies", [])) * float(spec.get("duration", 0)) > HEAVY_BODY_SECONDS


def for_sanitizers(spec):
    """The scene description as the sanitizer build's tests run it: a heavy one cut to its
    first SANITIZED_SECONDS, any other as it is."""
    if not is_heavy(spec):
        return spec
    return dict(spec, duration=min(float(spec["duration"]), SANITIZED_SECONDS))


def quote(text):
    """A gnuplot double-quoted string; a newline becomes gnuplot's own \\n (a line break)."""
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"').replace("\n", "\\n") + '"'


def simulate(simulator, scene, trajectory, stride=1, csv_path=None):
    """Runs `simulator run scene --trajectory trajectory`; returns (trajectory, contacts) paths."""
    command = [str(simulator), "run", str(scene), "--trajectory", str(trajectory), "--stride", str(stride), "--quiet"]
    if csv_path:
        command += ["--csv", str(csv_path)]
    try:
        result = subprocess.run(command, capture_output=True, text=True, timeout=SCENE_TIME_LIMIT)
    except subprocess.TimeoutExpired:
        raise RuntimeError(f"{simulator} ran {scene} for more than {SCENE_TIME_LIMIT} s and was stopped "
                           "(an endless loop in the responder?)") from None
    if result.returncode != 0:
        raise RuntimeError(f"{simulator} failed on {scene}:\n{result.stderr.strip()}")
    return Path(trajectory), contacts_path(trajectory)


def contacts_path(trajectory):
    trajectory = Path(trajectory)
    stem = trajectory.name[:-4] if trajectory.name.endswith(".csv") else trajectory.name
    return trajectory.with_name(stem + ".contacts.csv")


SLOW_MOTION = [1, 2, 5, 10, 20, 50, 100, 200, 500, 1000, 2000, 5000, 10000]
SHORTEST_FILM = 4.0  # s


def slow_motion_factor(duration):
    """How much slower than real time a scene is filmed (and played in the site): the smallest
    round factor that makes the film last at least SHORTEST_FILM seconds."""
    return next((f for f in SLOW_MOTION if duration * f >= SHORTEST_FILM - 1e-9), SLOW_MOTION[-1])


# A touch is marked in a film (and the site's player) while it happens and for this long of
# the film after, so that the picture does not fill with the arrows of touches long past.
TOUCH_FILM_SECONDS = 1.5


def touch_window(duration):
    """How long, in simulated seconds, a film shows a touch after it began."""
    return TOUCH_FILM_SECONDS / slow_motion_factor(duration)


def stride_for(scene_spec, frames=1500):
    """A stride keeping about `frames` recorded frames (every step for short runs)."""
    steps = round(scene_spec["duration"] / scene_spec["time_step"])
    return max(1, math.ceil(steps / frames))


class Scene:
    """The scene file's static part: names, shapes, which bodies are immovable, gravity."""

    def __init__(self, path, spec=None):
        self.path = Path(path)
        spec = spec if spec is not None else json.loads(self.path.read_text())
        self.spec = spec
        self.title = spec["title"]
        self.responder = spec["responder"]
        self.duration = spec["duration"]
        self.gravity = [float(g) for g in spec.get("gravity", [0, 0, 0])]
        self.bodies = spec["bodies"]
        self.names = [b.get("name", f"bodies[{i}]") for i, b in enumerate(self.bodies)]
        self.movable = [i for i, b in enumerate(self.bodies) if b["shape"]["type"] != "plane"]


class Trajectory:
    """The frames of a trajectory file: times, per frame per body (position, axes, velocity)
    in `states`, and per frame per body the angular velocity in `spins`. `axes` are the body's
    own x, y and z axes in the world frame, as the simulator writes them (columns ex_x ... ez_z):
    the pictures draw boxes and planes from them and hold no rotation code of their own."""

    def __init__(self, path):
        frames = {}
        with open(path, newline="") as f:
            # Rows as lists, read by column number: a pile's trajectory has a million values.
            reader = csv.reader(f)
            column = {name: i for i, name in enumerate(next(reader, []))}
            frame_at, t_at = column["frame"], column["t"]
            position_at, velocity_at, spin_at = ([column[c] for c in names] for names in ("xyz", VELOCITY, SPIN))
            axes_at = [[column[c] for c in axis] for axis in AXIS_COLUMNS]
            for row in reader:
                frame = frames.setdefault(int(row[frame_at]), (float(row[t_at]), [], []))
                frame[1].append(([float(row[i]) for i in position_at], [[float(row[i]) for i in axis] for axis in axes_at],
                                 [float(row[i]) for i in velocity_at]))
                frame[2].append([float(row[i]) for i in spin_at])
        self.steps = sorted(frames)
        self.times = [frames[s][0] for s in self.steps]
        self.states = [frames[s][1] for s in self.steps]
        self.spins = [frames[s][2] for s in self.steps]
        for t, states in zip(self.times, self.states):
            for position, axes, v in states:
                if not all(math.isfinite(x) for x in position + [c for axis in axes for c in axis] + v):
                    raise ValueError(f"{path}: a body's state is not finite at t = {t} s (NaN or infinity)")

    def index_at(self, t):
        """The recorded frame nearest to time t."""
        lo, hi = 0, len(self.times) - 1
        while lo < hi:
            mid = (lo + hi) // 2
            if self.times[mid] < t:
                lo = mid + 1
            else:
                hi = mid
        if lo > 0 and abs(self.times[lo - 1] - t) <= abs(self.times[lo] - t):
            lo -= 1
        return lo


def read_series(path):
    """A --csv time series as {column: [float, ...]}."""
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    return {name: [float(row[i]) for row in rows[1:]] for i, name in enumerate(rows[0])}


def read_contacts(path):
    """Contact rows grouped by step: {step: [row dict with floats]}."""
    steps = {}
    with open(path, newline="") as f:
        reader = csv.reader(f)
        names = next(reader, [])
        for row in reader:
            values = dict(zip(names, map(float, row)))
            steps.setdefault(int(values["frame"]), []).append(values)
    return steps


# Responders whose contacts rest (chapter 5's stacks, columns, pyramids and piles, chapter 6's
# blocks and balls on the ground): a touch's
# first impulse is a step's share of the weight the solver passes down, found again every step,
# not the answer to an impact; the pictures of their scenes mark no touches.
RESTING_RESPONDERS = {"resting-contact", "friction"}


def marked_touches(scene, contacts, limit=4):
    """The touches a picture of `scene` marks: contact_onsets(), none for a responder of
    RESTING_RESPONDERS."""
    return [] if scene.responder in RESTING_RESPONDERS else contact_onsets(contacts, limit)


def touching(contact):
    """Whether a contact row is a touch: the bodies overlap, or the responder gave the point an
    impulse. A speculative point (a pair still apart, which the contact solver watches in case
    it closes within the step) that got no impulse is no touch yet: marking it would date the
    touch a step early with J = 0."""
    return contact["depth"] >= 0.0 or contact["impulse"] > 0.0


def contact_onsets(contacts, limit=4):
    """The first step of each touch: a pair touching in this step and not in the one before.
    Resting contact (a ball on the ground touches every step) counts once. Returns the first
    touching point's row of up to `limit` touches, in time order."""
    def pairs(step):
        first = {}
        for c in contacts.get(step, []):
            if touching(c):
                first.setdefault((int(c["body1"]), int(c["body2"])), c)
        return first
    onsets = []
    for step in sorted(contacts):
        before = pairs(step - 1)
        onsets += [c for pair, c in pairs(step).items() if pair not in before]
    return onsets[:limit]


# ---- The view ---------------------------------------------------------------------------------

class View:
    """Which two world axes the picture shows: h across, v up, and what to call the view."""

    def __init__(self, h, v, name):
        self.h, self.v, self.name = h, v, name
        self.sign_v = 1.0

    def project(self, p):
        return (p[self.h], self.sign_v * p[self.v])

    def label(self, axis):
        return f"{AXES[axis]} / m"

    @property
    def xlabel(self):
        return self.label(self.h)

    @property
    def ylabel(self):
        return ("−" if self.sign_v < 0 else "") + self.label(self.v)


class Shifted:
    """A view whose pictures are moved across by `dx`: where a strobe picture sets its
    outlines side by side in time order (strobe.py, spread_pitch)."""

    def __init__(self, view, dx):
        self.view, self.dx = view, dx
        self.h, self.v, self.name, self.sign_v = view.h, view.v, view.name, view.sign_v
        self.xlabel, self.ylabel = view.xlabel, view.ylabel

    def project(self, p):
        x, y = self.view.project(p)
        return (x + self.dx, y)


def choose_view(scene, trajectories):
    """The rule (plots/README.md, "Motion pictures"): with gravity, a side view with up
    against gravity and across the axis along which the bodies move furthest; where they move
    equally far (within a hundredth of the largest body), across the axis they turn about
    least, so that a box tipping over is seen turning. Without gravity, the two axes along
    which the bodies move furthest (x before y before z on ties), so a scene in the plane
    z = 0 is seen as the x-y plane; it is a side view when a plane (the ground) faces along
    the picture's vertical axis, drawn below the bodies, and a top view otherwise."""
    extent, turn = [0.0, 0.0, 0.0], [0.0, 0.0, 0.0]
    moving = [i for i in movable(scene) if not scene.bodies[i].get("immovable")]
    for trajectory in trajectories:
        for axis in range(3):
            values = [states[i][0][axis] for states in trajectory.states for i in moving]
            if values:
                extent[axis] = max(extent[axis], max(values) - min(values))
            turn[axis] += sum(abs(spins[i][axis]) for spins in trajectory.spins for i in moving)
    tie = 0.01 * max([body_size(scene.bodies[i]) for i in moving], default=0.0)
    if any(scene.gravity):
        up = max(range(3), key=lambda a: abs(scene.gravity[a]))
        others = [a for a in range(3) if a != up]
        furthest = max(extent[a] for a in others)
        across = min((a for a in others if extent[a] >= furthest - tie), key=lambda a: (turn[a], a))
        view = View(across, up, "side view")
        view.sign_v = -1.0 if scene.gravity[up] > 0 else 1.0
        return view
    first, second = sorted(sorted(range(3), key=lambda a: (-round(extent[a], 12), a))[:2])
    view = View(first, second, "top view")
    for body in scene.bodies:
        if body["shape"]["type"] == "plane":
            normal = [float(n) for n in body["shape"]["normal"]]
            if abs(normal[second]) > 0.99 * math.sqrt(sum(n * n for n in normal)):
                view.name = "side view"
                view.sign_v = 1.0 if normal[second] > 0 else -1.0
                break
    return view


# ---- Geometry ---------------------------------------------------------------------------------

AXIS_COLUMNS = [[f"e{axis}_{c}" for c in "xyz"] for axis in "xyz"]
VELOCITY = ("vx", "vy", "vz")
SPIN = ("wx", "wy", "wz")


def axes_of(row):
    """A body's own x, y and z axes in the world frame, from a trajectory row."""
    return [[float(row[c]) for c in columns] for columns in AXIS_COLUMNS]


def to_world(axes, local):
    """A vector given in a body's frame (components along its axes), in the world frame."""
    return [sum(local[k] * axes[k][i] for k in range(3)) for i in range(3)]


def convex_hull(points):
    pts = sorted(set(points))
    if len(pts) <= 2:
        return pts

    def cross(o, a, b):
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])

    lower, upper = [], []
    for p in pts:
        while len(lower) >= 2 and cross(lower[-2], lower[-1], p) <= 0:
            lower.pop()
        lower.append(p)
    for p in reversed(pts):
        while len(upper) >= 2 and cross(upper[-2], upper[-1], p) <= 0:
            upper.pop()
        upper.append(p)
    return lower[:-1] + upper[:-1]


def outline(body, position, axes, view):
    """('circle', (cx, cy), r) or ('polygon', [points]) of a movable body in the view, or None."""
    shape = body["shape"]
    if shape["type"] == "sphere":
        return ("circle", view.project(position), float(shape["radius"]))
    if shape["type"] == "box":
        h = [float(e) for e in shape["half_extents"]]
        corners = []
        for sx in (-1, 1):
            for sy in (-1, 1):
                for sz in (-1, 1):
                    local = to_world(axes, [sx * h[0], sy * h[1], sz * h[2]])
                    corners.append(view.project([position[i] + local[i] for i in range(3)]))
        return ("polygon", convex_hull(corners))
    return None


def box_hands(body, position, axes, view):
    """For a box, three segments from its centre to the middles of its +x, +y and +z faces,
    in the view: the box's own axes, so that its turning shows even where its outline looks
    the same (a cube turned a quarter, a box flipped end over end). None for other shapes."""
    shape = body["shape"]
    if shape["type"] != "box":
        return None
    h = [float(e) for e in shape["half_extents"]]
    centre = view.project(position)
    hands = []
    for axis in range(3):
        hands.append((centre, view.project([position[k] + h[axis] * axes[axis][k] for k in range(3)])))
    return hands


def body_colour(scene, i):
    """Each movable body its own colour; with more bodies than colours (a billiard rack) the
    first keeps the first colour and all the others share the second, as the key says."""
    bodies = movable(scene)
    if len(bodies) > len(BODY_COLOURS):
        return BODY_COLOURS[0] if i == bodies[0] else BODY_COLOURS[1]
    return BODY_COLOURS[bodies.index(i) if i in bodies else i % len(BODY_COLOURS)]


def key_entries(scene):
    """(title, colour) of the key: one per body, or two for a crowd (see body_colour)."""
    bodies = movable(scene)
    if len(bodies) > len(BODY_COLOURS):
        return [(scene.names[bodies[0]], BODY_COLOURS[0]),
                (f"{scene.names[bodies[1]]} … {scene.names[bodies[-1]]}", BODY_COLOURS[1])]
    return [(scene.names[i], body_colour(scene, i)) for i in bodies]


def body_size(body):
    """A movable body's largest half-width, m (0 for a plane)."""
    shape = body["shape"]
    if shape["type"] == "sphere":
        return float(shape["radius"])
    if shape["type"] == "box":
        return max(float(e) for e in shape["half_extents"])
    return 0.0


def normal_arrow_length(scene, contact, box):
    """Three times the larger body of the pair, at most a tenth of the picture: long enough to
    see, short enough not to hide the bodies it points at."""
    size = max(body_size(scene.bodies[int(contact["body1"])]), body_size(scene.bodies[int(contact["body2"])]))
    return min(3.0 * size, 0.1 * max(box[1] - box[0], box[3] - box[2]))


def plane_line(body, position, axes, view):
    """(point, unit normal) of a plane's trace in the view, or None when the plane lies in the
    picture's own plane (its normal points at the viewer)."""
    normal = to_world(axes, [float(n) for n in body["shape"]["normal"]])
    n2 = view.project(normal)
    length = math.hypot(*n2)
    if length < 1e-9:
        return None
    return view.project(position), (n2[0] / length, n2[1] / length)


def extent_of(shapes):
    """(xmin, xmax, ymin, ymax) over outlines."""
    xs, ys = [], []
    for shape in shapes:
        if shape[0] == "circle":
            (cx, cy), r = shape[1], shape[2]
            xs += [cx - r, cx + r]
            ys += [cy - r, cy + r]
        else:
            xs += [p[0] for p in shape[1]]
            ys += [p[1] for p in shape[1]]
    return min(xs), max(xs), min(ys), max(ys)


def clip_polygon(polygon, box):
    """Sutherland-Hodgman: the part of a convex polygon inside box (xmin, xmax, ymin, ymax)."""
    xmin, xmax, ymin, ymax = box
    edges = [(0, xmin, 1), (0, xmax, -1), (1, ymin, 1), (1, ymax, -1)]
    for axis, limit, side in edges:
        inside = lambda p: side * (p[axis] - limit) >= 0  # noqa: E731
        out = []
        for i, p in enumerate(polygon):
            prev = polygon[i - 1]
            if inside(p):
                if not inside(prev):
                    out.append(intersect(prev, p, axis, limit))
                out.append(p)
            elif inside(prev):
                out.append(intersect(prev, p, axis, limit))
        polygon = out
        if not polygon:
            return []
    return polygon


def clip_line(point, direction, box):
    """The two ends of the infinite line point + s direction inside box, or None."""
    lo, hi = -math.inf, math.inf
    for axis, (low, high) in enumerate(((box[0], box[1]), (box[2], box[3]))):
        if abs(direction[axis]) < 1e-15:
            if not low <= point[axis] <= high:
                return None
            continue
        s1, s2 = (low - point[axis]) / direction[axis], (high - point[axis]) / direction[axis]
        lo, hi = max(lo, min(s1, s2)), min(hi, max(s1, s2))
    if lo > hi:
        return None
    return [(point[0] + s * direction[0], point[1] + s * direction[1]) for s in (lo, hi)]


def intersect(a, b, axis, limit):
    s = (limit - a[axis]) / (b[axis] - a[axis])
    return (a[0] + s * (b[0] - a[0]), a[1] + s * (b[1] - a[1]))


def fit_box(xmin, xmax, ymin, ymax, aspect, margin=0.08):
    """The data box grown by `margin` and then to width/height = `aspect`, centred."""
    w, h = xmax - xmin, ymax - ymin
    size = max(w, h, 1e-9)
    w, h = max(w, 1e-3 * size), max(h, 1e-3 * size)
    cx, cy = (xmin + xmax) / 2, (ymin + ymax) / 2
    w, h = w * (1 + 2 * margin), h * (1 + 2 * margin)
    if w / h < aspect:
        w = h * aspect
    else:
        h = w / aspect
    return cx - w / 2, cx + w / 2, cy - h / 2, cy + h / 2


def faded(colour, strength):
    """`colour` mixed with white: strength 1 is the colour, 0 is white."""
    rgb = [int(colour[i:i + 2], 16) for i in (1, 3, 5)]
    return "#" + "".join(f"{round(255 - strength * (255 - c)):02X}" for c in rgb)


def number(value, digits=3):
    return f"{value:.{digits}g}".replace("-", "\u2212")


def impulse_text(j):
    """J in N s, or kN s from 10^4 N s on, with four significant digits."""
    j = abs(j)
    return f"J = {j / 1000:.4g} kN s" if j >= 1e4 else f"J = {j:.4g} N s"


class Canvas:
    """Collects what one panel draws, for one view: polygons, arrows and labels as gnuplot
    commands with their own numbering (`lines`), circles and dots as rows of datablocks, one
    for each style, that the panel's plot command draws (`panel`). gnuplot looks through all
    the objects it holds each time one is set, so the thousand discs of a pile at ten moments
    took it seconds to read as objects; from a datablock it reads them at once.

    `text_size` is the size of one character of label_font as fractions of the plot's width
    and height (it depends on the terminal and the layout), so that labels placed with
    `free_label` can be kept from covering one another."""

    def __init__(self, view=None, box=None, text_size=(0.0082, 0.05)):
        self.view = view
        self.box = box
        self.text_size = text_size
        self.taken = []
        self.lines = []
        self.objects = 0
        self.arrows = 0
        self.labels = 0
        self.circles = {}  # plot style -> rows "x,y,radius,colour" (style.gp reads commas)
        self.dots = {}     # plot style -> rows "x,y,colour"

    def panel(self, plot, datablocks=()):
        """The panel's commands: `datablocks`, the canvas's own and its lines, then one plot
        command of the clauses `plot` (first, so drawn first) and the circles and dots (dots
        last, over everything the plot draws; polygons, arrows and labels are drawn over the
        plot, as gnuplot draws front objects)."""
        blocks, clauses = list(datablocks), list(plot)
        for n, (style, rows) in enumerate([*self.circles.items(), *self.dots.items()]):
            name = f"$canvas{n}"
            blocks.append(f"{name} << EOD\n" + "\n".join(rows) + "\nEOD")
            clauses.append(f"{name} using {'1:2:3:4' if style.startswith('with circles') else '1:2:3'} {style} notitle")
        return blocks + self.lines + ["plot " + ", ".join(clauses), "unset object", "unset arrow", "unset label"]

    def keep_clear(self, text, at, align="center"):
        """Marks where a label placed by other means (a plane's name) stands, so that labels
        placed by free_label stay off it."""
        width = len(text) * self.text_size[0] * (self.box[1] - self.box[0])
        x0 = at[0] - {"left": 0.0, "center": 0.5, "right": 1.0}[align] * width
        self.taken.append((x0, x0 + width, at[1]))

    def free_label(self, text, at, colour, align="center", side=1, font="label_font"):
        """A label_font label beside the point `at` (above it for side 1, below for -1), moved
        a line further out for as long as it would cover a label placed before it."""
        box = self.box
        width = len(text) * self.text_size[0] * (box[1] - box[0])
        line = self.text_size[1] * (box[3] - box[2])
        x0 = at[0] - {"left": 0.0, "center": 0.5, "right": 1.0}[align] * width
        # Inside the picture: a label that would run over its left or right edge starts (ends)
        # there, its opaque box too (a character's margin: strobe.py's textbox style), so that
        # the box does not cover the axis.
        inset = 0.01 * (box[1] - box[0]) + self.text_size[0] * (box[1] - box[0])
        if x0 < box[0] + inset or x0 + width > box[1] - inset:
            x0 = box[0] + inset if x0 < box[0] + inset else box[1] - inset - width
            at, align = (x0, at[1]), "left"
        # Lines out from the point while they stay inside the picture, then the other way.
        slots = [side * (1.0 + 1.3 * n) for n in range(40)]
        # The picture's top line is its note's (strobe.py).
        slots = [s for s in slots if box[2] + line < at[1] + s * line < box[3] - 2.0 * line] + [-s for s in slots]
        for offset in slots:
            y = at[1] + offset * line
            if not any(x0 < b[1] and b[0] < x0 + width and abs(y - b[2]) < 1.1 * line for b in self.taken):
                break
        self.taken.append((x0, x0 + width, y))
        # On a white ground, so that outlines behind the text do not cross it.
        self.label(text, at, colour, align=align, font=font, offset=(0, offset), boxed=True)

    def circle(self, centre, radius, colour, fill, width=2.0, dashed=False, opacity=0.15):
        """An outline in `colour`, filled with it at `opacity` when `fill` (which is then the
        same colour) is given."""
        if fill and fill != colour:
            raise ValueError("a circle is filled with its outline's colour")
        style = (f"with circles lc rgb variable lw {width}{' dt 2' if dashed else ''} "
                 f"fs {f'transparent solid {opacity}' if fill else 'empty'} border")
        self.circles.setdefault(style, []).append(f"{centre[0]!r},{centre[1]!r},{radius!r},{int(colour[1:], 16)}")

    def polygon(self, points, colour, fill, width=2.0, dashed=False, opacity=0.15, layer="front"):
        if len(points) < 3:
            return
        self.objects += 1
        path = " to ".join(f"{p[0]!r},{p[1]!r}" for p in points + [points[0]])
        fs = f"fs transparent solid {opacity} border lc rgb '{colour}'" if fill else f"fs empty border lc rgb '{colour}'"
        self.lines.append(f"set object {self.objects} polygon from {path} {layer} fc rgb '{fill or colour}' {fs} "
                          f"lw {width}{' dt 2' if dashed else ''}")

    def shape(self, shape, colour, fill, width=2.0, dashed=False, opacity=0.15, hands=None):
        if shape[0] == "circle":
            self.circle(shape[1], shape[2], colour, fill, width, dashed, opacity)
        else:
            self.polygon(shape[1], colour, fill, width, dashed, opacity)
        for start, end in hands or []:
            if math.dist(start, end) > 0:
                self.arrow(start, end, colour, width=0.75 * width, head=False)

    def arrow(self, start, end, colour, width=3.0, head=True, dashed=False):
        """An arrow; a dashed one has an open head, so that one drawn over a solid arrow (the
        student's normal over the reference's, at the same touch) leaves the other in sight."""
        self.arrows += 1
        tip = ("empty head size screen 0.015,25" if dashed else "filled head size screen 0.012,25") if head else "nohead"
        self.lines.append(f"set arrow {self.arrows} from {start[0]!r},{start[1]!r} to {end[0]!r},{end[1]!r} front "
                          f"lc rgb '{colour}' lw {width}{' dt 2' if dashed else ''} {tip}")

    def label(self, text, at, colour="#202020", align="left", font="label_font", coords="first", offset=None,
              rotate=0, boxed=False):
        self.labels += 1
        where = f"{coords} {at[0]!r}, {coords} {at[1]!r}" if coords == "first" else f"{coords} {at[0]!r}, {at[1]!r}"
        off = f" offset character {offset[0]}, {offset[1]}" if offset else ""
        turn = f" rotate by {rotate:.1f}" if rotate else ""
        self.lines.append(f"set label {self.labels} {quote(text)} at {where} {align}{turn}{off} front font {font} "
                          f"tc rgb '{colour}' noenhanced{' boxed' if boxed else ''}")

    def point(self, at, colour, size=0.6):
        """A dot; one outside the box is left out."""
        if self.box and not (self.box[0] <= at[0] <= self.box[1] and self.box[2] <= at[1] <= self.box[3]):
            return
        self.dots.setdefault(f"with points pt 7 ps {size} lc rgb variable", []).append(
            f"{at[0]!r},{at[1]!r},{int(colour[1:], 16)}")


def draw_planes(canvas, scene, trajectory, view, box):
    """Immovable planes as a surface line with a grey band on their solid side, clipped to the box."""
    xmin, xmax, ymin, ymax = box
    depth = 0.035 * max(xmax - xmin, ymax - ymin)
    far = 4 * math.hypot(xmax - xmin, ymax - ymin)
    for i, body in enumerate(scene.bodies):
        if body["shape"]["type"] != "plane":
            continue
        position, axes, _ = trajectory.states[0][i]
        trace = plane_line(body, position, axes, view)
        if trace is None:
            continue
        (px, py), (nx, ny) = trace
        dx, dy = -ny, nx
        a, b = (px - far * dx, py - far * dy), (px + far * dx, py + far * dy)
        band = [a, b, (b[0] - depth * nx, b[1] - depth * ny), (a[0] - depth * nx, a[1] - depth * ny)]
        canvas.polygon(clip_polygon(band, box), GROUND_FILL, GROUND_FILL, width=0.5, opacity=1.0, layer="back")
        ends = clip_line((px, py), (dx, dy), box)
        if ends:
            canvas.arrow(ends[0], ends[1], GROUND_LINE, width=2.5, head=False)
        inside = clip_polygon(band, box)
        if inside:
            cx = sum(p[0] for p in inside) / len(inside)
            cy = sum(p[1] for p in inside) / len(inside)
            # The name runs along the surface, inside the band.
            turn = math.degrees(math.atan2(dy, dx)) if abs(dx) < 0.5 else 0
            canvas.label(scene.names[i], (cx, cy), GROUND_LINE, align="center", font="note_font", rotate=turn)
            if not turn:
                canvas.keep_clear(scene.names[i], (cx, cy))


def plane_bounds(scene, trajectory, view):
    """Points a picture must include for its planes: where each plane crosses the view."""
    points = []
    for i, body in enumerate(scene.bodies):
        if body["shape"]["type"] == "plane":
            position, axes, _ = trajectory.states[0][i]
            trace = plane_line(body, position, axes, view)
            if trace:
                points.append(("polygon", [trace[0]]))
    return points


def movable(scene):
    """The bodies that are not planes, by index (a list the scene keeps: do not change it)."""
    return scene.movable


def run_gnuplot(script, what):
    result = subprocess.run(["gnuplot"], input=script, capture_output=True, text=True)
    if result.returncode != 0 or result.stderr.strip():
        raise RuntimeError(f"gnuplot on {what}:\n{result.stderr.strip()[:2000]}")
