"""Runs a gnuplot body for every output format of the figures (SVG for the web, PDF for
slides, PNG to look at) with the shared style, and records where each panel's plot area lies,
so the site's motion player can move a cursor across the very figure the page shows. Shared by
figures.py and spin.py, which draw different figures of the same kind."""
import json
import subprocess
import tempfile
from pathlib import Path

PLOTS = Path(__file__).resolve().parent
STYLE = PLOTS / "style.gp"
FORMATS = ["svg", "pdf", "png"]

# After each panel's plot, gnuplot prints where the panel's plot area lies on the canvas and
# the range of its horizontal axis. From the SVG's lines figures.py writes <stem>.panels.json,
# which the site's motion player reads to move a cursor across the chapter's own figure in
# step with the scene (plots/motion-player.js).
RECORD_PANEL = ('print sprintf("%.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g", GPVAL_TERM_XMIN, '
                'GPVAL_TERM_XMAX, GPVAL_TERM_YMIN, GPVAL_TERM_YMAX, GPVAL_X_MIN, GPVAL_X_MAX, GPVAL_TERM_XSIZE, '
                'GPVAL_TERM_YSIZE, GPVAL_TERM_SCALE)')


def panel_area(commands, terminal):
    """(width, height, line) of the plot area of the first panel `commands` draw on `terminal`
    (a use_* string of style.gp), in pixels, line being gnuplot's character height there (the
    unit a label's offset counts in): what gnuplot decided, margins and `set size ratio`
    included, asked of it by drawing the panel once into a scratch file."""
    with tempfile.TemporaryDirectory() as scratch:
        script = [f"load {quote(str(STYLE))}", f"eval {terminal}", f"set output {quote(str(Path(scratch, 'sketch')))}",
                  f"set print {quote(str(Path(scratch, 'panels')))}"]
        for command in commands:
            script.append(command)
            if command.startswith("plot "):
                script += [RECORD_PANEL, "print GPVAL_TERM_VCHAR / GPVAL_TERM_SCALE"]
                break
        result = subprocess.run(["gnuplot"], input="\n".join(script + ["unset print"]) + "\n", capture_output=True,
                                text=True)
        if result.returncode != 0 or result.stderr.strip():
            raise RuntimeError(f"gnuplot on a panel's size:\n{result.stderr.strip()[:2000]}")
        record, line = Path(scratch, "panels").read_text().split("\n")[:2]
    left, right, low, high = (float(v) for v in record.split()[:4])
    return right - left, high - low, float(line)


def quote(text):
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"') + '"'


def render(body, out_dir, stem, what, x_per_second=1.0):
    """Draws `body` as stem.svg, .pdf and .png, and writes stem.panels.json: where each
    panel's plot area lies in the SVG (pixels from its top left corner) and the range of its
    horizontal axis, which is x_per_second times the time."""
    with tempfile.TemporaryDirectory() as scratch:
        script = []
        for ext in FORMATS:
            script += ["reset", f"load {quote(str(STYLE))}", f"eval use_{ext}",
                       f"set output {quote(str(out_dir / (stem + '.' + ext)))}",
                       f"set print {quote(str(Path(scratch, ext + '.panels')))}", body, "unset output", "unset print"]
        result = subprocess.run(["gnuplot"], input="\n".join(script) + "\n", capture_output=True, text=True)
        if result.returncode != 0 or result.stderr.strip():
            raise RuntimeError(f"gnuplot on {what}:\n{result.stderr.strip()}")
        panels, width, height = [], None, None
        for line in Path(scratch, "svg.panels").read_text().split("\n"):
            if not line.strip():
                continue
            left, right, low, high, x0, x1, xsize, ysize, scale = (float(v) for v in line.split())
            width, height = xsize / scale, ysize / scale
            panels.append({"left": left, "right": right, "top": height - high, "bottom": height - low, "x0": x0, "x1": x1})
    (out_dir / (stem + ".panels.json")).write_text(json.dumps(
        {"figure": stem + ".svg", "width": width, "height": height, "x_per_second": x_per_second, "panels": panels},
        indent=1) + "\n")
