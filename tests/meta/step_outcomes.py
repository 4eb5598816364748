#!/usr/bin/env python3
"""Test of the tests: runs a step-test binary for one chapter and asserts that every step
passes (the reference) or that every step fails with feedback naming a broken law (the
untouched skeleton). A step that an untouched skeleton passes would give students free
points and tell them nothing, so it is a bug in the tests."""
import argparse
import subprocess
import sys

from tools import catch_xml


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--binary", required=True)
    parser.add_argument("--chapter", required=True)
    parser.add_argument("--expect", choices=["pass", "fail"], required=True)
    parser.add_argument("--seed", required=True)
    args = parser.parse_args()

    run = subprocess.run([args.binary, f"[{args.chapter}]", "--reporter", "xml", "--rng-seed", str(args.seed)],
                         capture_output=True, text=True, timeout=600)
    steps = {}
    for case in catch_xml.parse(run.stdout):
        if case.step is None:
            print(f"PROBLEM test case '{case.name}' has no [step:N:name] tag")
            return 1
        steps.setdefault(case.step, []).append(case)
    if not steps:
        print(f"no step tests found for chapter {args.chapter}")
        return 1

    problems = []
    for (number, name), cases in sorted(steps.items()):
        label = f"step {number} ({name})"
        step_passed = all(c.passed for c in cases)
        if args.expect == "pass" and not step_passed:
            problems.append(f"{label}: the reference fails it: {[c.failures[:1] for c in cases if not c.passed]}")
        if args.expect == "fail":
            if step_passed:
                problems.append(f"{label}: the untouched skeleton passes it")
            for case in cases:
                if not case.passed and not any("Law broken:" in f for f in case.failures):
                    problems.append(f"{label}: '{case.name}' fails without naming a law: {case.failures[:1]}")
    for line in problems:
        print("PROBLEM", line)
    print(f"{len(steps)} steps of {args.chapter} checked, expecting every one to {args.expect}: {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
