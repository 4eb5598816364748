#!/usr/bin/env python3
"""Every mutant and correct variant of tests/mutants/ at many seeds: each must lose exactly
the steps its expect.json names (a correct variant: none), at every seed.

    python3 tests/mutants/check_seeds.py --build-dir build/dev [--seeds 1-10] [--chapter ID] [NAME ...]

The grader's own test (tests/grader/test_grader.py) grades the corpus once, at the workbook's
seed, as the grader does (one sandboxed process pair per test case). This check is opt-in and
faster, so that it can afford ten seeds: per mutant it compiles the composed submission once
with the kit's recipe, links it with the chapter's server objects, and runs the chapter's
trusted checker over all of the chapter's test cases in one process pair per seed, without
the sandbox (the mutants are the workbook's own code). A step is lost when any of its test
cases fails; a mutant whose expect.json names a "feedback" must show it in a failure.
Prints one line per mutant and exits 1 when any mutant misses at any seed."""
import argparse
import json
import os
import pathlib
import re
import subprocess
import sys
import tempfile
from concurrent.futures import ThreadPoolExecutor

ROOT = pathlib.Path(__file__).resolve().parents[2]
from tests.grader.compose import compose  # noqa: E402
from tools import catch_xml  # noqa: E402

STEP_TAG = re.compile(r"step:(\d+):")  # a step's tag, [step:3:prepare]


def seeds_from(text):
    seeds = []
    for part in text.split(","):
        low, _, high = part.partition("-")
        seeds.extend(range(int(low), int(high or low) + 1))
    return seeds


def build(kit, chapter, source_text, folder):
    """The student's process for `source_text`: compiled and linked as the grader does."""
    source = folder / chapter["source"]
    source.write_text(source_text)
    obj, binary = folder / "student.o", folder / "student"
    subprocess.run([kit["compiler"], *kit["compile_flags"], *(f"-I{d}" for d in kit["include_dirs"]), "-c", str(source),
                    "-o", str(obj)], check=True, capture_output=True, text=True)
    subprocess.run([kit["compiler"], *kit["link_flags"], "-o", str(binary), str(obj), *chapter["server_objects"],
                    *kit["link_libraries"]], check=True, capture_output=True, text=True)
    return binary


def lost_steps(chapter, binary, seed, folder):
    """At `seed`: {step with a failing test case: that case and its text}, and the text of
    every failing case as the grader shows it (tools/catch_xml.py reads both)."""
    report = folder / f"report-{seed}.xml"
    calls_read, calls_write = os.pipe()
    answers_read, answers_write = os.pipe()
    student = subprocess.Popen([str(binary), f"/dev/fd/{answers_write}"], stdin=calls_read, pass_fds=(answers_write,),
                               stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    os.close(calls_read)
    os.close(answers_write)
    checker = subprocess.Popen([chapter["checker"], "-r", "xml", "-o", str(report), "--rng-seed", str(seed)],
                               stdin=answers_read, stdout=calls_write, stderr=subprocess.DEVNULL,
                               env={"PATH": "/usr/bin:/bin", "WORKBOOK_REMOTE_CHANNEL": "stdio"}, restore_signals=False)
    os.close(answers_read)
    os.close(calls_write)
    try:
        checker.wait(timeout=600)
    finally:
        student.kill()
        student.wait()
    lost, shown = {}, []
    for case in catch_xml.parse(report.read_bytes()):
        if case.passed:
            continue
        step = next(int(m.group(1)) for m in map(STEP_TAG.match, case.tags) if m)
        text = "\n".join(case.failures)
        lost.setdefault(step, f"{case.name}: {' '.join(text.split())[:600]}")
        shown.append(text)
    return lost, shown


def check(kit, chapters, mutant, seeds):
    chapter_id = mutant.parent.name
    chapter = chapters[chapter_id]
    expect = json.loads((mutant / "expect.json").read_text())
    wanted = set(expect["loses_steps"])
    reference = ROOT / "solutions" / chapter["source"]
    text = compose(reference.read_text(), (mutant / chapter["source"]).read_text(), f"solutions/{chapter['source']}")
    misses = []
    with tempfile.TemporaryDirectory(prefix="mutant-seeds-") as tmp:
        folder = pathlib.Path(tmp)
        binary = build(kit, chapter, text, folder)
        for seed in seeds:
            lost, shown = lost_steps(chapter, binary, seed, folder)
            if set(lost) != wanted:
                extra = {s: lost[s] for s in set(lost) - wanted}
                misses.append((seed, sorted(lost), extra))
            elif expect.get("feedback") and not any(expect["feedback"] in text for text in shown):
                misses.append((seed, sorted(lost), {0: f"no failure says '{expect['feedback']}'"}))
    return f"{chapter_id}/{mutant.name}", wanted, misses


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--build-dir", default=str(ROOT / "build" / "dev"))
    parser.add_argument("--seeds", default="1-10", help="e.g. 1-10 or 3,7 (default 1-10)")
    parser.add_argument("--chapter", help="only this chapter's mutants")
    parser.add_argument("-j", "--jobs", type=int, default=2)
    parser.add_argument("names", nargs="*", help="only these mutants (folder names)")
    args = parser.parse_args()
    kit = json.loads((pathlib.Path(args.build_dir) / "grader" / "kit.json").read_text())
    chapters = {c["id"]: c for c in kit["chapters"]}
    seeds = seeds_from(args.seeds)
    mutants = sorted(p.parent for p in (ROOT / "tests" / "mutants").glob("*/*/expect.json"))
    if args.chapter:
        mutants = [m for m in mutants if m.parent.name == args.chapter]
    if args.names:
        mutants = [m for m in mutants if m.name in args.names]
    failed = 0
    counts = {}
    with ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
        for name, wanted, misses in pool.map(lambda m: check(kit, chapters, m, seeds), mutants):
            chapter = name.split("/")[0]
            counts.setdefault(chapter, [0, 0])
            counts[chapter][0] += 1
            if misses:
                failed += 1
                counts[chapter][1] += 1
                print(f"MISS  {name}: expected to lose {sorted(wanted)}", flush=True)
                for seed, lost, extra in misses:
                    print(f"        seed {seed}: lost {lost}", flush=True)
                    for step, text in extra.items():
                        print(f"          {f'step {step}' if step else 'feedback'}: {text}", flush=True)
            else:
                print(f"ok    {name}: loses {sorted(wanted)} at seeds {args.seeds}", flush=True)
    for chapter, (total, bad) in sorted(counts.items()):
        print(f"{chapter}: {total} mutants and variants, {total - bad} as expected at every seed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
