#!/usr/bin/env python3
"""Puts the motion player into the built site: html/motion/motion-player.js and, per chapter,
html/motion/<chapter>.js with the data of every scene (the <scene>[.student].player.js files
plots/strobe.py wrote beside the figures) and where the panels of each scene's energy and
momentum figure lie (<scene>[.student].panels.json, from plots/figures.py), with that figure
itself copied to html/motion/<chapter>/, so that the player shows the chapter's own figure
with a cursor on it. A chapter page shows the player with the Doxygen alias
\\motionplayer{<chapter>} (docs/Doxyfile.in).

    site_motion.py --figures build/dev/book/figures --html build/dev/book/site/html --suffix "" inelastic
"""

import argparse
import json
import shutil
from pathlib import Path

PLOTS = Path(__file__).resolve().parent
SOURCE = PLOTS.parent


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--figures", type=Path, required=True)
    parser.add_argument("--html", type=Path, required=True)
    parser.add_argument("--suffix", default="", help="'' for the reference's motion, '.student' for the student edition")
    parser.add_argument("chapters", nargs="*")
    args = parser.parse_args()
    out = args.html / "motion"
    out.mkdir(parents=True, exist_ok=True)
    shutil.copyfile(PLOTS / "motion-player.js", out / "motion-player.js")
    for chapter in args.chapters:
        files = sorted(p for p in (args.figures / chapter).glob(f"*{args.suffix}.player.js")
                       if p.name.count(".") == args.suffix.count(".") + 2)
        # A build folder keeps what it once drew: a scene renamed or removed since would show
        # in the player twice, or after it was gone. Only the chapter's scenes of today count.
        scenes = SOURCE / "chapters" / chapter / "scenes"
        stale = [p for p in files if not (scenes / (p.name[:-len(args.suffix + ".player.js")] + ".json")).is_file()]
        for p in stale:
            print(f"site: left out {p.name}: no scene {chapter}/{p.name[:-len(args.suffix + '.player.js')]} any more")
        files = [p for p in files if p not in stale]
        text, figures = "".join(p.read_text() for p in files), 0
        for p in files:
            scene = p.name[:-len(args.suffix + ".player.js")]
            panels = args.figures / chapter / f"{scene}{args.suffix}.panels.json"
            if not panels.is_file():
                continue
            figure = json.loads(panels.read_text())
            (out / chapter).mkdir(exist_ok=True)
            shutil.copyfile(panels.parent / figure["figure"], out / chapter / figure["figure"])
            figure["src"] = f"motion/{chapter}/{figure.pop('figure')}"
            text += ("(window.WorkbookMotionFigures = window.WorkbookMotionFigures || {})"
                     f"[{json.dumps(chapter + '/' + scene)}] = {json.dumps(figure, separators=(',', ':'))};\n")
            figures += 1
        (out / f"{chapter}.js").write_text(text)
        print(f"site: motion player data for {chapter}: {len(files)} scenes, {figures} with their figure")


if __name__ == "__main__":
    main()
