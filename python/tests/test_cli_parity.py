"""The package gives the command-line tool's poses bit for bit: every preset × scheme × rule set
at level 3 (`screwbender preset ID | screwbender subdivide …`), evaluation (`eval`) and the screw
between two poses (`screw`).

Bit for bit means from the same input numbers: the CLI reads its documents with serde_json,
whose default float parser may land one unit in the last place away from the correctly rounded
value that Python's `json` (and so a numpy array of the same text) gives. The bit-for-bit
checks therefore read the CLI's document with `Motion.from_json` (the same parser); the same
motion built from a numpy array of the document's numbers is checked to 1e-13."""

import json

import numpy as np
import pytest

import screwbender as sb
from conftest import cli_poses

SCHEMES = ["bspline", "fourpoint", "jarek"]
# The package, files, the JS API and the CLI name the rule sets alike.
RULES = ["direct", "split"]


def same_bits(a, b):
    a, b = np.asarray(a, dtype=np.float64), np.asarray(b, dtype=np.float64)
    assert a.shape == b.shape
    # Bit patterns, not values: -0.0 and 0.0 differ, and so would any last-bit change.
    np.testing.assert_array_equal(a.view(np.uint64), b.view(np.uint64))


@pytest.fixture(scope="module")
def preset_docs(cli):
    return {name: cli(["preset", name]) for name in sb.presets()}


def test_presets_are_the_clis(cli):
    listed = [line.split()[0] for line in cli(["preset"]).splitlines() if line.strip()]
    assert sb.presets() == listed
    assert [d[0] for d in sb.preset_descriptions()] == listed
    # Each by the same name in words (the core's table, as the page's chooser shows it).
    for line in cli(["preset"]).splitlines():
        if line.strip():
            assert f" {sb.preset_display(line.split()[0])['name']}: " in line, line


@pytest.mark.parametrize("scheme", SCHEMES)
@pytest.mark.parametrize("rules", RULES)
def test_every_preset_subdivides_as_the_cli(cli, preset_docs, scheme, rules):
    for name, doc in preset_docs.items():
        out = cli(["subdivide", "--scheme", scheme, "--rules", rules, "--levels", "3"], doc)
        # The CLI reads the preset's document: the same numbers, from JSON or from an array.
        m = sb.Motion.from_json(doc)
        m.scheme, m.rules, m.levels = scheme, rules, 3
        same_bits(m.subdivide(), cli_poses(out))
        closed = json.loads(doc).get("closed", True)
        rows = sb.Motion(np.array(cli_poses(doc)), closed=closed, scheme=scheme, rules=rules, levels=3)
        assert np.abs(rows.subdivide() - np.array(cli_poses(out))).max() <= 1e-13
        # The preset itself (not through the document's shortest decimal digits).
        preset = sb.Motion.from_preset(name, scheme=scheme, rules=rules, levels=3)
        assert preset.closed == closed
        assert np.abs(preset.subdivide() - m.subdivide()).max() <= 1e-13


@pytest.mark.parametrize("s", [0.0, 0.3, 1.0, -0.5])
def test_the_js_family_subdivides_as_the_cli(cli, preset_docs, s):
    for name, doc in preset_docs.items():
        out = cli(["subdivide", "--s", str(s), "--levels", "3"], doc)
        m = sb.Motion.from_json(doc)
        m.s, m.levels = s, 3
        same_bits(m.subdivide(), cli_poses(out))


def test_open_sequences_subdivide_as_the_cli(cli, preset_docs):
    for name in ["l_cycle_rotated", "circle4"]:
        for scheme in SCHEMES:
            out = cli(["subdivide", "--open", "--scheme", scheme, "--levels", "4"], preset_docs[name])
            m = sb.Motion.from_json(preset_docs[name])
            m.closed, m.scheme, m.levels = False, scheme, 4
            same_bits(m.subdivide(), cli_poses(out))


@pytest.mark.parametrize("levels", [0, 3])
def test_poses_at_evaluates_as_the_cli(cli, preset_docs, levels):
    us = [0.0, 0.37, 1.5, 2.999, 3.25, -0.4, 7.1]
    args = ["eval", "--levels", str(levels), "--scheme", "jarek"]
    for u in us:
        args += ["--u", repr(u)]
    for name in ["l_cycle_rotated", "circle4"]:
        out = cli(args, preset_docs[name])
        m = sb.Motion.from_json(preset_docs[name])
        m.scheme, m.levels = "jarek", levels
        same_bits(m.poses_at(np.array(us)), cli_poses(out))
        same_bits(m.poses_at(us[1]), cli_poses(out)[1])


def test_screw_is_the_clis(cli):
    rng = np.random.default_rng(7)
    for _ in range(20):
        q = rng.normal(size=(2, 4))
        q /= np.linalg.norm(q, axis=1, keepdims=True)
        a = np.concatenate([rng.normal(size=3), q[0]])
        b = np.concatenate([rng.normal(size=3), q[1]])
        doc = json.dumps(
            {"poses": [{"origin": list(p[:3]), "rotation": list(p[3:])} for p in (a, b)]}
        )
        ts = [0.0, 0.25, 0.5, 1.0, 1.7, -0.3]
        args = ["screw"]
        for t in ts:
            args += ["--t", repr(t)]
        want = cli_poses(cli(args, doc))
        # Read as the CLI reads them, then: one t, many t, batches of pairs.
        a, b = sb.Motion.from_json(doc).poses
        same_bits(sb.screw(a, np.array(ts), b), want)
        same_bits(sb.screw(a, ts[3], b), want[3])
        pairs = sb.screw(np.stack([a] * len(ts)), np.array(ts), np.stack([b] * len(ts)))
        same_bits(pairs, want)
