"""The conformance cases through the Python package: prints {options, compare, export} as JSON.

Run by tests/conformance/frontends/python.mjs with the project's venv; reads the cases and
each preset's document (as the CLI writes it) from the JSON on standard input.
"""

import hashlib
import json
import os
import sys
import tempfile

import numpy as np
import screwbender as sb


def motion(document, options):
    doc = json.loads(document)
    poses = np.array([p["origin"] + p["rotation"] for p in doc["poses"]], dtype=float)
    return sb.Motion(poses, closed=doc.get("closed", True), name=doc.get("name"), **options)


def attempt(f):
    try:
        return f()
    except (ValueError, TypeError) as e:
        return {"error": str(e)}


def main():
    given = json.load(sys.stdin)
    cases, documents = given["cases"], given["documents"]
    out = {"options": {}, "compare": {}, "export": {}}

    def options_case(c):
        m = motion(documents[c["preset"]], c["options"])
        rows = m.subdivide()
        return {
            "scheme": m.scheme,
            "s": m.s,
            "rules": m.rules,
            "levels": m.levels,
            "count": len(rows),
            "first": rows[0].tolist(),
            "last": rows[-1].tolist(),
        }

    for c in cases["options"]:
        out["options"][c["id"]] = attempt(lambda: options_case(c))
    for c in cases["compare"]:
        out["compare"][c["id"]] = attempt(
            lambda: motion(documents[c["preset"]], {}).compare_methods(c["methods"])
        )
    with tempfile.TemporaryDirectory() as d:
        for c in cases["export"]:
            path = os.path.join(d, f"{c['id']}.{c['format']}")

            def export_case():
                motion(documents[c["preset"]], {}).export(path)
                data = open(path, "rb").read()
                return {"sha256": hashlib.sha256(data).hexdigest(), "bytes": len(data)}

            out["export"][c["id"]] = attempt(export_case)
    json.dump(out, sys.stdout)


if __name__ == "__main__":
    main()
