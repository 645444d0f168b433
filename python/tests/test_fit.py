"""`fit` gives the numbers of `screwbender fit --json` (the same core on the same file): the
fitted control poses and the residual report to 1e-12."""

import json
import math

import numpy as np
import pytest

import screwbender as sb


@pytest.fixture(scope="module")
def samples(tmp_path_factory):
    """300 samples of a helix-like motion with a deterministic wobble, one every 0.05 s."""
    poses, times = [], []
    for i in range(300):
        t = 0.05 * i
        a = 0.4 * t
        wobble = 0.01 * math.sin(1.7 * i)
        poses.append(
            {
                "origin": [2.0 * math.cos(a), 2.0 * math.sin(a) + wobble, 0.3 * a],
                "rotation": [math.cos(a / 2), 0.0, 0.0, math.sin(a / 2)],
            }
        )
        times.append(t)
    path = tmp_path_factory.mktemp("fit") / "samples.json"
    path.write_text(json.dumps({"closed": False, "poses": poses, "times": times}))
    return path


def test_fit_matches_the_cli(cli, samples, tmp_path):
    out = tmp_path / "fitted.json"
    args = ["--method", "se3bspline", "--controls", "8", "--robust", "huber"]
    report = json.loads(cli(["fit", str(samples), *args, "--json", "-o", str(out)]))
    motion, got = sb.fit(samples, method="se3bspline", controls=8, robust="huber")
    assert set(got) == set(report)
    for key, value in report.items():
        if isinstance(value, float):
            assert got[key] == pytest.approx(value, rel=0, abs=1e-12), key
        else:
            assert got[key] == value, key
    doc = json.loads(out.read_text())
    want = np.array([p["origin"] + p["rotation"] for p in doc["poses"]])
    have = np.array([motion.pose(i) for i in range(len(motion))])
    np.testing.assert_allclose(have, want, rtol=0, atol=1e-12)
    # The wobble (0.01) is what remains.
    assert got["max_position"] < 0.012


def test_fit_refuses_bad_options(samples):
    with pytest.raises(ValueError, match="exactly one of controls and tolerance"):
        sb.fit(samples)
    with pytest.raises(ValueError, match="method"):
        sb.fit(samples, method="kks", controls=4)
    with pytest.raises(ValueError, match="poses"):
        sb.fit(samples, controls=301)


def test_measure_fit_of_a_fit_is_its_report(cli, samples, tmp_path):
    """A fit's own motion measured against its samples gives the fit's report, and the numbers
    of `screwbender fit --measure`; a motion that covers half the path is far, and bad input is
    named."""
    for method in ("screwbender", "se3bspline"):
        motion, report = sb.fit(samples, method=method, controls=10)
        got = sb.measure_fit(motion, samples, method=method)
        saved = tmp_path / f"{method}.json"
        saved.write_text(motion.to_json())
        by_cli = json.loads(cli(["fit", str(samples), "--method", method, "--measure", str(saved), "--json"]))
        assert set(got) == set(by_cli)
        for key, value in by_cli.items():
            assert got[key] == (pytest.approx(value, rel=0, abs=1e-12) if isinstance(value, float) else value), key
        assert got["iterations"] == 0
        for key in ("controls", "samples"):
            assert got[key] == report[key], key
        for key in ("rms_position", "max_position", "rms_angle", "max_angle", "rms_deviation", "max_deviation"):
            assert got[key] == pytest.approx(report[key], rel=0, abs=1e-12), (method, key)
    # Half of the path stretched over the whole time span is far from the samples.
    half = sb.Motion(sb.Motion.load(samples).poses[[0, 75, 150]], closed=False, times=[0.0, 7.5, 14.95])
    fitted, report = sb.fit(samples, controls=10)
    assert sb.measure_fit(half, samples)["rms_position"] > 10 * report["rms_position"]
    with pytest.raises(ValueError, match="radius"):
        sb.measure_fit(fitted, samples, radius=0.0)
    with pytest.raises(ValueError, match="method"):
        sb.measure_fit(fitted, samples, method="kks")
