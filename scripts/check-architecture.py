#!/usr/bin/env python3
"""ARCHITECTURE.md's trees of each crate's src/ name exactly the files that are there.

Every `.rs` and `.wgsl` file under crates/<crate>/src/ is named (by its file name) in the tree
block of ARCHITECTURE.md that starts with `crates/<crate>/src/`, and every file name such a
block names exists in that crate. A prose tree cannot be generated without losing its
explanations, so it is checked instead: a new file or a rename fails here until the tree says
where it went.

    python3 scripts/check-architecture.py
"""
import pathlib
import re
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
text = (ROOT / "ARCHITECTURE.md").read_text(encoding="utf-8")
blocks = re.findall(r"```text\n(crates/([\w-]+)/src/\n.*?)```", text, flags=re.S)
if not blocks:
    sys.exit("ARCHITECTURE.md: no ```text block starting with crates/<crate>/src/")

problems = []
for body, crate in blocks:
    src = ROOT / "crates" / crate / "src"
    named = set(re.findall(r"[\w-]+\.(?:rs|wgsl)\b", body))
    present = {p.name for p in src.rglob("*") if p.suffix in (".rs", ".wgsl")}
    for name in sorted(present - named):
        problems.append(f"crates/{crate}/src: {name} is not in ARCHITECTURE.md's tree")
    for name in sorted(named - present):
        problems.append(f"ARCHITECTURE.md names {name} under crates/{crate}/src/, which has no such file")

if problems:
    print("\n".join(problems), file=sys.stderr)
    sys.exit(1)
print(f"ARCHITECTURE.md: the trees of {', '.join(c for _, c in blocks)} match their files")
