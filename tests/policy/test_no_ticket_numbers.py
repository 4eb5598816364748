#!/usr/bin/env python3
"""Product text names what a thing is, never the ticket that asked for it: no "issue 12" in
the pages, the help, the figures, the code or its comments (a reader outside the project's
tracker learns nothing from the number).

    test_no_ticket_numbers.py [ROOT]     exit status 1 and each place when any"""
import pathlib
import re
import subprocess
import sys

ROOT = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parents[2]
TICKET = re.compile(r"\b(?:issue|ticket)s? #?\d+", re.IGNORECASE)
THIS_FILE = pathlib.Path(__file__).resolve()


def files():
    listed = subprocess.run(["git", "-C", str(ROOT), "ls-files"], capture_output=True, text=True)
    if listed.returncode == 0:
        return [ROOT / line for line in listed.stdout.splitlines()]
    return [p for p in ROOT.rglob("*") if p.is_file() and "build" not in p.relative_to(ROOT).parts[:1]]


def replaced_front_end(path):
    """The bash ./workbook, which a Python front end replaces (its help is checked there)."""
    return path == ROOT / "workbook" and path.read_text(errors="replace").startswith("#!/usr/bin/env bash")


def main():
    problems = []
    for path in files():
        if path.resolve() == THIS_FILE or not path.is_file() or replaced_front_end(path):
            continue
        try:
            text = path.read_text()
        except (UnicodeDecodeError, OSError):
            continue
        for number, line in enumerate(text.splitlines(), 1):
            if TICKET.search(line):
                problems.append(f"{path.relative_to(ROOT)}:{number}: {line.strip()[:140]}")
    for problem in problems:
        print("a ticket number in product text:", problem)
    print(f"{len(problems)} lines name a ticket")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
