"""The method comparison: `compare_methods` and `Motion.compare_methods` return the table of
`screwbender compare --json` (the same numbers, the same field names), and refuse unknown
methods naming them.

Only the table's frame (method names, row count, `pose_count`, `closed`) is asserted here: the
metrics themselves are the core's, tested there, and their fields may change with it; the CLI
parity compares whatever fields the core writes."""

import json
import math

import numpy as np
import pytest

import screwbender as sb
from test_inputs import P


def test_the_named_methods_in_their_order():
    t = sb.compare_methods(P, closed=True, methods=["slerp", "polyscrew"])
    assert [row["method"] for row in t["rows"]] == ["slerp", "polyscrew"]
    assert t["pose_count"] == 6 and t["closed"] is True
    assert t["skipped"] == []
    # As the CLI's `--methods`: one comma-separated string, any case, a method named once.
    t = sb.compare_methods(P, closed=False, methods="polyscrew, SLERP,polyscrew")
    assert [row["method"] for row in t["rows"]] == ["polyscrew", "slerp"]
    assert t["pose_count"] == 6 and t["closed"] is False
    assert sb.compare_methods(P, methods=[])["rows"] == []


def test_every_applicable_method_by_default():
    closed = sb.compare_methods(P)
    names = [row["method"] for row in closed["rows"]] + [s.split(":")[0] for s in closed["skipped"]]
    assert "cc1" not in names and "barr" not in names  # C¹ C–C is open only; barr only named
    assert {"polyscrew", "bspline", "fourpoint", "jarek"} <= set(names)
    opened = sb.compare_methods(P, closed=False)
    assert len(opened["rows"]) + len(opened["skipped"]) == len(names) + 1  # and cc1
    assert opened["closed"] is False and opened["pose_count"] == 6


def test_a_motion_compares_its_control_poses():
    m = sb.Motion(P, closed=False, scheme="bspline", levels=2)
    got = m.compare_methods(["polyscrew", "bspline"], body_points=[[0, 0, 0]])
    want = sb.compare_methods(P, closed=False, methods=["polyscrew", "bspline"], body_points=[[0, 0, 0]])
    assert got == want
    assert got["body_points"] == [[0.0, 0.0, 0.0]]
    # Keyword arguments as the JS API's `compareMethods(methods, bodyPoints)`.
    assert m.compare_methods(methods="polyscrew")["rows"][0]["method"] == "polyscrew"


def test_unknown_methods_are_refused_naming_methods():
    with pytest.raises(ValueError, match=r"methods\[1\]: unknown value 'nope' \(expected polyscrew, "):
        sb.compare_methods(P, methods=["polyscrew", "nope"])
    # A comma-separated text is a list, as the CLI's --methods: the same words.
    with pytest.raises(ValueError, match=r"^methods\[1\]: unknown value 'nope'"):
        sb.Motion(P).compare_methods("polyscrew,nope")
    with pytest.raises(TypeError, match=r"methods\[0\]: expected a method name \(str\)"):
        sb.compare_methods(P, methods=[1])
    with pytest.raises(TypeError, match=r"methods: expected a method name"):
        sb.compare_methods(P, methods=3)


def test_other_bad_input_is_refused_and_named():
    # A method that does not apply: its name first (as the CLI).
    with pytest.raises(ValueError, match=r"^cc1"):
        sb.compare_methods(P, closed=True, methods=["cc1"])
    with pytest.raises(ValueError, match=r"body_points: shape \(3,\) is not \(k, 3\)"):
        sb.compare_methods(P, methods=["polyscrew"], body_points=[1, 2, 3])
    with pytest.raises(ValueError, match=r"body_points\[4\]: not a finite number"):
        sb.compare_methods(P, methods=["polyscrew"], body_points=[[0, 0, 0], [1, math.inf, 0]])
    with pytest.raises(ValueError, match=r"poses\[3\]\.rotation: zero quaternion"):
        bad = P.copy()
        bad[3, 3:] = 0
        sb.compare_methods(bad)


def close(a, b, path="table"):
    """`a` equals `b` (parsed JSON): the same keys, lists and strings, numbers to 1e-12."""
    if isinstance(a, dict):
        assert isinstance(b, dict) and set(a) == set(b), path
        for k in a:
            close(a[k], b[k], f"{path}.{k}")
    elif isinstance(a, list):
        assert isinstance(b, list) and len(a) == len(b), path
        for i, (x, y) in enumerate(zip(a, b)):
            close(x, y, f"{path}[{i}]")
    elif isinstance(a, float) or isinstance(b, float):
        assert isinstance(a, (int, float)) and isinstance(b, (int, float)), path
        assert abs(a - b) <= 1e-12 * max(1.0, abs(a), abs(b)), f"{path}: {a} != {b}"
    else:
        assert a == b, path


@pytest.mark.parametrize("methods", [None, "polyscrew,bspline,kks,cc0"])
def test_the_table_is_the_clis(cli, methods):
    doc = cli(["preset", "l_cycle_rotated"])
    args = ["compare", "--json"] + ([] if methods is None else ["--methods", methods])
    want = json.loads(cli(args, doc))
    # From the document the CLI reads (the same numbers: see test_cli_parity.py).
    m = sb.Motion.from_json(doc)
    close(m.compare_methods(methods), want)
    close(sb.compare_methods(m.poses, m.closed, methods), want)
    assert want["rows"]  # the comparison compared something
