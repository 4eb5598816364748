#!/usr/bin/env python3
"""No two chapters have a scene of the same name. The site's pages load every figure from one
folder by its file name (Doxygen copies the images of every chapter's figure folder side by
side), so two scenes of one name would show one chapter's figure under the other's caption.

    test_unique_scene_names.py [ROOT]     exit status 1 and each shared name when any"""
import collections
import pathlib
import sys

ROOT = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parents[2]


def main():
    chapters = collections.defaultdict(list)
    for scene in sorted((ROOT / "chapters").glob("*/scenes/*.json")):
        chapters[scene.stem].append(scene.parent.parent.name)
    shared = {name: where for name, where in chapters.items() if len(where) > 1}
    for name, where in sorted(shared.items()):
        print(f"scene name '{name}' is used by the chapters {', '.join(where)}: the site would show one "
              f"chapter's figure for both; rename one of them")
    if not chapters:
        print(f"no scene found under {ROOT / 'chapters'}")
        return 1
    print(f"{len(chapters)} scene names, each in one chapter" if not shared else f"{len(shared)} shared")
    return 1 if shared else 0


if __name__ == "__main__":
    sys.exit(main())
