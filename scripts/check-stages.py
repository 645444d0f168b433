#!/usr/bin/env python3
"""The test suite's stage table (scripts/stages.txt) is whole and consistent.

Every stage script in scripts/test.d/ is run by exactly one stage; every name is unique; every
lane and way of running is one scripts/test.sh knows; a stage needs only stages declared before
it (so the table's order is one they can run in); a command's program exists. Exits non-zero
with one line per problem.
"""
import os
import shlex
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
LANES = {"setup", "rust", "web", "python", "e2e"}
RUNS = {"cpu", "beside", "alone"}


def main():
    problems = []
    seen = []
    used_scripts = {}
    with open(os.path.join(ROOT, "scripts/stages.txt"), encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            if not line.strip() or line.lstrip().startswith("#"):
                continue
            parts = line.split(None, 4)
            where = f"scripts/stages.txt:{number}"
            if len(parts) < 5:
                problems.append(f"{where}: expected name, lane, runs, after and a command")
                continue
            name, lane, runs, after, command = parts
            if name in seen:
                problems.append(f"{where}: the name {name} is declared twice")
            if lane not in LANES:
                problems.append(f"{where}: lane {lane} is not one of {', '.join(sorted(LANES))}")
            if runs not in RUNS:
                problems.append(f"{where}: runs {runs} is not one of {', '.join(sorted(RUNS))}")
            for dep in [] if after == "-" else after.split(","):
                if dep not in seen:
                    problems.append(f"{where}: {name} needs {dep}, which is not declared before it")
            program = shlex.split(command)[0]
            if "/" in program:
                if not os.access(os.path.join(ROOT, program), os.X_OK):
                    problems.append(f"{where}: {program} is not an executable file")
                if program.startswith(("scripts/test.d/", "./scripts/test.d/")):
                    used_scripts.setdefault(os.path.basename(program), []).append(name)
            seen.append(name)
    stage_dir = os.path.join(ROOT, "scripts/test.d")
    for script in sorted(os.listdir(stage_dir)):
        if not script.endswith(".sh"):
            continue
        users = used_scripts.get(script, [])
        if len(users) != 1:
            problems.append(f"scripts/test.d/{script}: run by {len(users)} stages of scripts/stages.txt (expected 1)")
        with open(os.path.join(stage_dir, script), encoding="utf-8") as f:
            if any(line.startswith("# test.sh:") for line in f):
                problems.append(f"scripts/test.d/{script}: a '# test.sh:' line; say how it runs in scripts/stages.txt")
    for problem in problems:
        print(problem, file=sys.stderr)
    if not problems:
        print(f"scripts/stages.txt: {len(seen)} stages, every stage script run once")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
