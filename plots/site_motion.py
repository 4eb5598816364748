#!/usr/bin/env python3
"""Puts the motion player into the built site: html/motion/motion-player.js and, per chapter,
html/motion/<chapter>.js with the data of every scene (the <scene>[.student].player.js files
plots/strobe.py wrote beside the figures). A chapter page shows the player with the Doxygen
alias \\motionplayer{<chapter>} (docs/Doxyfile.in).

    site_motion.py --figures build/dev/book/figures --html build/dev/book/site/html --suffix "" inelastic
"""

import argparse
import shutil
from pathlib import Path

PLOTS = Path(__file__).resolve().parent


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
        (out / f"{chapter}.js").write_text("".join(p.read_text() for p in files))
        print(f"site: motion player data for {chapter}: {len(files)} scenes")


if __name__ == "__main__":
    main()
