"""The two plain-text facts every tool of the workbook reads, read one way for all of them.

chapters/CHAPTERS: chapter ids in teaching order, one a line; '#' starts a comment.
tests/RANDOM_SEED: the Catch2 --rng-seed of every test run, check and grade, so that random
cases are the same everywhere and regrading gives the same scores."""
import pathlib


def chapters(root):
    text = (pathlib.Path(root) / "chapters" / "CHAPTERS").read_text()
    return [line.split("#", 1)[0].strip() for line in text.splitlines() if line.split("#", 1)[0].strip()]


def random_seed(root):
    return int((pathlib.Path(root) / "tests" / "RANDOM_SEED").read_text().strip())
