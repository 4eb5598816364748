"""What this copy of the workbook holds. The instructor's tree has the reference solutions,
the hidden tests and the grader; the student edition (./workbook pack student) has none of
them, and the front end offers only what the edition has."""
import os
import pathlib

from tools import workbook_files

ROOT = pathlib.Path(__file__).resolve().parents[2]


def have_solutions():
    return (ROOT / "solutions").is_dir()


def have_grader():
    return (ROOT / "grader" / "grade.py").is_file()


def have_site_tests():
    return (ROOT / "tests" / "site").is_dir()


def chapters():
    """Chapter ids in teaching order (chapters/CHAPTERS)."""
    return workbook_files.chapters(ROOT)


def seed():
    """The Catch2 --rng-seed of every check, test and grade: WORKBOOK_SEED or tests/RANDOM_SEED."""
    return os.environ.get("WORKBOOK_SEED") or str(workbook_files.random_seed(ROOT))


def build_dir(preset):
    return ROOT / "build" / preset
