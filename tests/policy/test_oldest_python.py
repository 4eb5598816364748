#!/usr/bin/env python3
"""The README promises Python 3.8 or newer for ./workbook and everything it runs in Python
(the check runner, the grader, the figures, the packers, the benches' scripts); macOS's own
python3 is 3.9. Held two ways:

  - with each Python older than this one that is found (python3.8 or python3.9 on PATH, or
    under pyenv), every module of tools/, grader/, plots/ and bench/ is imported and
    `workbook.py help` and each command's --help are run: an annotation `str | None` or a
    dict `|` fails there at import;
  - whatever Python runs this, no source calls a function or passes an argument that
    Python 3.8 does not have (the list below): those fail only when their line runs.

    test_oldest_python.py     exit status 1 and each problem, when any"""
import ast
import glob
import os
import pathlib
import re
import shutil
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]
PACKAGES = ("tools", "grader", "plots", "bench")
OLDEST = ("3.8", "3.9")

# Attributes and keyword arguments added to the standard library after Python 3.8.
NEWER_ATTRIBUTES = {
    "removeprefix": "3.9", "removesuffix": "3.9", "is_relative_to": "3.9", "with_stem": "3.9",
    "waitstatus_to_exitcode": "3.9", "pidfd_open": "3.9", "unparse": "3.9", "randbytes": "3.9",
    "BooleanOptionalAction": "3.9", "lcm": "3.9", "ulp": "3.9", "nextafter": "3.9",
    "bit_count": "3.10", "pairwise": "3.10", "aiter": "3.10", "file_digest": "3.11", "chdir": None,
}
NEWER_KEYWORDS = {"umask": "3.9", "user": "3.9", "group": "3.9", "extra_groups": "3.9", "strict": "3.10",
                  "root_dir": "3.10", "process_group": "3.11"}
# The standard library's calls that took those keywords later: module.function, or a builtin.
KEYWORD_CALLS = {"subprocess.Popen", "subprocess.run", "subprocess.call", "subprocess.check_call",
                 "subprocess.check_output", "glob.glob", "glob.iglob", "zip"}


def tracked_python_files():
    listed = subprocess.run(["git", "-C", str(ROOT), "ls-files", "*.py"], capture_output=True, text=True)
    if listed.returncode == 0:
        return [ROOT / line for line in listed.stdout.splitlines()]
    return sorted(p for p in ROOT.rglob("*.py") if "build" not in p.relative_to(ROOT).parts[:1])


def call_name(call):
    """`module.function` or `builtin` for a call written that way; "" for any other."""
    if isinstance(call.func, ast.Attribute) and isinstance(call.func.value, ast.Name):
        return f"{call.func.value.id}.{call.func.attr}"
    return call.func.id if isinstance(call.func, ast.Name) else ""


def newer_library_uses(path):
    problems = []
    tree = ast.parse(path.read_text(encoding="utf-8"))
    for node in ast.walk(tree):
        if isinstance(node, ast.Attribute) and NEWER_ATTRIBUTES.get(node.attr):
            problems.append(f"{node.lineno}: .{node.attr} (Python {NEWER_ATTRIBUTES[node.attr]})")
        elif isinstance(node, ast.Call) and call_name(node) in KEYWORD_CALLS:
            for keyword in node.keywords:
                if keyword.arg in NEWER_KEYWORDS:
                    problems.append(f"{node.lineno}: {call_name(node)}({keyword.arg}=...) (Python {NEWER_KEYWORDS[keyword.arg]})")
    # `X | None` in an annotation Python evaluates (a class's or module's field, a function's
    # argument or result) needs 3.10, unless annotations are left unevaluated.
    lazy = any(isinstance(n, ast.ImportFrom) and n.module == "__future__" and any(a.name == "annotations" for a in n.names)
               for n in tree.body)
    if not lazy:
        for node in ast.walk(tree):
            annotations = []
            if isinstance(node, ast.AnnAssign):
                annotations.append(node.annotation)
            elif isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
                annotations += [a.annotation for a in node.args.args + node.args.kwonlyargs + node.args.posonlyargs]
                annotations.append(node.returns)
            for annotation in filter(None, annotations):
                if any(isinstance(n, ast.BinOp) and isinstance(n.op, ast.BitOr) for n in ast.walk(annotation)):
                    problems.append(f"{annotation.lineno}: an annotation with | (Python 3.10; or "
                                    f"from __future__ import annotations)")
    return [f"{path.relative_to(ROOT)}:{p}" for p in problems]


def older_pythons():
    """{version: interpreter} of each of OLDEST found that runs and says it is that version (a
    pyenv shim on PATH may name a version it will not run)."""
    found = {}
    for version in OLDEST:
        candidates = sorted(glob.glob(os.path.expanduser(f"~/.pyenv/versions/{version}*/bin/python{version}")))
        candidates.append(shutil.which(f"python{version}"))
        for candidate in filter(None, candidates):
            try:
                said = subprocess.run([candidate, "-c", "import sys; print('%d.%d' % sys.version_info[:2])"],
                                      capture_output=True, text=True, timeout=60).stdout.strip()
            except OSError:
                continue
            if said == version:
                found[version] = candidate
                break
    return found


def modules():
    names = []
    for package in PACKAGES:
        for path in sorted((ROOT / package).rglob("*.py")):
            if path.name == "__main__.py":  # runs the command line when imported
                continue
            parts = path.relative_to(ROOT).with_suffix("").parts
            names.append(".".join(parts[:-1] if parts[-1] == "__init__" else parts))
    return names


def run_with(python, *args):
    return subprocess.run([python, *args], cwd=ROOT, capture_output=True, text=True, timeout=300,
                          env={**os.environ, "PYTHONDONTWRITEBYTECODE": "1"})


def problems_with(version, python):
    problems = []
    script = ("import importlib, sys, traceback\nfailed = 0\nfor name in sys.argv[1:]:\n"
              "    try:\n        importlib.import_module(name)\n"
              "    except BaseException as error:\n"
              "        failed += 1\n        print(f'{name}: {type(error).__name__}: {error}')\n"
              "sys.exit(1 if failed else 0)\n")
    imported = run_with(python, "-c", script, *modules())
    if imported.returncode != 0:
        problems += [f"Python {version}: import {line}" for line in (imported.stdout + imported.stderr).splitlines()]
    helped = run_with(python, "workbook.py", "help")
    if helped.returncode != 0:
        problems.append(f"Python {version}: workbook.py help failed:\n{helped.stderr[-2000:]}")
    # A command's line starts two spaces in; its description's next lines start further in.
    commands = [line.split()[0] for line in helped.stdout.splitlines() if re.match(r"  [a-z]", line)]
    for command in commands:
        shown = run_with(python, "workbook.py", command, "--help")
        if shown.returncode != 0:
            problems.append(f"Python {version}: workbook.py {command} --help failed:\n{shown.stderr[-2000:]}")
    if not commands:
        problems.append(f"Python {version}: workbook.py help listed no command")
    return problems


def main():
    problems = []
    for path in tracked_python_files():
        problems += newer_library_uses(path)
    found = older_pythons()
    for version, python in found.items():
        problems += problems_with(version, python)
    for problem in problems:
        print(problem)
    if not found:
        print(f"no Python {' or '.join(OLDEST)} found: only the sources were read")
    else:
        print(f"imported and ran the commands' help with {', '.join(f'{v} ({p})' for v, p in found.items())}")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
