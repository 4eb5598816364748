#!/usr/bin/env python3
"""Random cases are the same on every compiler: one draw per statement.

C++ leaves the order in which a function's arguments (and the operands of `*`, `+`, ...)
are evaluated unspecified, so `make_box(random.uniform(...), random.vector(...))` draws the
same numbers in another order on GCC and on Clang: a student on one compiler and the grader
on another would see different cases from the same seed. The order is fixed between
statements, between the elements of a braced list (`Vector3{r(), r(), r()}`) and between
the condition and the branch of `c ? a : b`, so this test allows a statement to draw more
than once only there. A draw is a call of a generator named `random` or `engine` (random.uniform(...),
engine()), or the generator handed to a helper (random_box(random, ...)).

    test_random_draws.py [ROOT]     exit status 1 and the offending statements when any"""
import pathlib
import re
import sys

ROOT = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parents[2]
FOLDERS = ["tests", "tools", "bench", "engine"]
DRAW = re.compile(r"\b(?:random\s*\.\s*(?:uniform|log_uniform|vector|direction)\s*\(|(?:random|engine)\s*\(\s*\))|\w\s*\(\s*random\s*[,)]")
COMMENT = re.compile(r"//[^\n]*|/\*.*?\*/", re.DOTALL)
STRING = re.compile(r'"(?:\\.|[^"\\])*"')


def statements(text):
    """The text of each statement: the pieces between ';', cut after the last block brace
    (a crude split, enough for the tests' plain code)."""
    text = STRING.sub('""', COMMENT.sub("", text))
    for piece in text.split(";"):
        cut = max(piece.rfind("{\n"), piece.rfind("}\n"), piece.rfind(") {"), piece.rfind("else {"))
        yield piece[cut + 1:] if cut >= 0 else piece


def top_level_elements(braced):
    """The comma-separated elements of the text inside one braced list."""
    depth, start, elements = 0, 0, []
    for i, c in enumerate(braced):
        if c in "([{":
            depth += 1
        elif c in ")]}":
            depth -= 1
        elif c == "," and depth == 0:
            elements.append(braced[start:i])
            start = i + 1
    elements.append(braced[start:])
    return elements


def branches(statement):
    """The condition and branches of a top-level `c ? a : b` (the condition is evaluated
    first, then one branch only), or [statement] when there is none."""
    depth, parts, start = 0, [], 0
    for i, c in enumerate(statement):
        if c in "([{":
            depth += 1
        elif c in ")]}":
            depth -= 1
        elif depth == 0 and (c == "?" or (c == ":" and statement[i - 1] != ":" and statement[i + 1:i + 2] != ":")):
            parts.append(statement[start:i])
            start = i + 1
    return parts + [statement[start:]] if parts and "?" in statement else [statement]


def ordered(statement):
    """True when the statement's draws happen in an order the language fixes."""
    draws = list(DRAW.finditer(statement))
    if len(draws) <= 1:
        return True
    parts = branches(statement)
    if len(parts) > 1:
        return all(ordered(part) for part in parts)
    # A braced list holding every draw, one draw an element, and no draw outside it.
    open_at = statement.find("{")
    if open_at < 0:
        return False
    depth = 0
    for i in range(open_at, len(statement)):
        depth += {"{": 1, "}": -1}.get(statement[i], 0)
        if depth == 0:
            break
    inside = statement[open_at + 1:i]
    if len(DRAW.findall(inside)) != len(draws):
        return False
    return all(len(DRAW.findall(element)) <= 1 for element in top_level_elements(inside))


def main():
    # The rule itself, on statements whose order is known.
    assert not ordered("make_box(random.uniform(0, 1), half, random.vector(1))")
    assert not ordered("v = random.direction() * random.uniform(0, 1)")
    assert ordered("const Vector3 half{random.uniform(0, 1), random.uniform(0, 1), random.uniform(0, 1)}")
    assert ordered("e = random.uniform(0, 1) < 0.5 ? 1.0 : random.uniform(0, 1)")
    assert not ordered("x = {make_sphere(random.uniform(0, 1), random.uniform(0, 1))}")
    problems = []
    for folder in FOLDERS:
        for path in sorted((ROOT / folder).rglob("*")):
            if path.suffix not in (".cpp", ".hpp") or "build" in path.relative_to(ROOT).parts[:1]:
                continue
            text = path.read_text(errors="replace")
            if not DRAW.search(text):
                continue
            for statement in statements(text):
                if not ordered(statement):
                    shown = " ".join(statement.split())
                    problems.append(f"{path.relative_to(ROOT)}: {shown[:160]}")
    for problem in problems:
        print("more than one random draw in one statement (order unspecified):", problem)
    print(f"{len(problems)} statements draw in an order the compiler chooses")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
