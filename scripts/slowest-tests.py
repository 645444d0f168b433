#!/usr/bin/env python3
"""The slowest tests of the last run, for the closing table of scripts/test.sh.

Reads what the stages left in artifacts/: each e2e job's wall time (tests/e2e/run.mjs writes
artifacts/e2e-durations.json) and each pytest test's time (the Python stage's JUnit report,
artifacts/python/pytest.xml). Prints the slowest few of each; prints nothing for a stage that
did not run.
"""
import json
import os
import sys
import xml.etree.ElementTree as ET

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SHOWN = 6


def main():
    rows = []
    e2e = os.path.join(ROOT, "artifacts/e2e-durations.json")
    if os.path.exists(e2e):
        with open(e2e, encoding="utf-8") as f:
            rows += [(float(s), f"e2e {job}") for job, s in json.load(f).items()]
    junit = os.path.join(ROOT, "artifacts/python/pytest.xml")
    if os.path.exists(junit):
        for case in ET.parse(junit).getroot().iter("testcase"):
            rows.append((float(case.get("time", 0)), f"pytest {case.get('classname')}::{case.get('name')}"))
    if not rows:
        return 0
    print(f"slowest tests (of {len(rows)} timed)", file=sys.stderr)
    for seconds, name in sorted(rows, reverse=True)[:SHOWN]:
        print(f"{seconds:6.0f} s  {name}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
