"""The `Motion` API beyond the CLI's outputs: shapes, kinematics, files, copies, the GIL."""

import threading
import time

import numpy as np
import pytest

import screwbender as sb
from test_inputs import P


def test_the_issues_example_runs():
    m = sb.Motion(P, closed=True, scheme="fourpoint", levels=5, rules="direct")
    assert m.subdivide().shape == (6 * 32, 7)
    assert m.refined_matrices().shape == (6 * 32, 4, 4)
    u = np.linspace(0, 6, 13)
    assert m.poses_at(u).shape == (13, 7)
    k = m.kinematics_at(u, point=[2, 0, 0])
    assert set(k) == {"position", "velocity", "acceleration", "angular_velocity", "angular_acceleration"}
    assert all(v.shape == (13, 3) for v in k.values())
    assert sb.screw(P[0], 0.5, P[1]).shape == (7,)
    assert sb.screw(P[0], u, P[1]).shape == (13, 7)
    assert "l_cycle_rotated" in sb.presets()
    assert sb.Motion.from_preset("l_cycle_rotated").name == "l_cycle_rotated"


def test_interpolating_scheme_passes_through_the_control_poses():
    m = sb.Motion(P, scheme="fourpoint", levels=5)
    got = m.poses_at(np.arange(6.0))
    sign = np.sign(np.sum(got[:, 3:] * P[:, 3:], axis=1))[:, None]
    assert np.abs(got[:, :3] - P[:, :3]).max() <= 1e-12
    assert np.abs(got[:, 3:] * sign - P[:, 3:]).max() <= 1e-12


def test_kinematics_are_the_derivatives_of_the_motion():
    m = sb.Motion(P, scheme="jarek", levels=4)
    point = np.array([0.5, -0.2, 0.3])
    h = 1e-6
    # Midpoints of refined spans (a refined knot has a one-sided derivative).
    u = (np.arange(40) + 0.5) / 16 + 0.01

    def position(u):
        poses = m.poses_at(u)
        w, x, y, z = poses[:, 3:].T
        r = np.stack(
            [
                np.stack([1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)], -1),
                np.stack([2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)], -1),
                np.stack([2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)], -1),
            ],
            1,
        )
        return poses[:, :3] + r @ point

    k = m.kinematics_at(u, point=point)
    assert np.abs(k["position"] - position(u)).max() <= 1e-12
    velocity = (position(u + h) - position(u - h)) / (2 * h)
    assert np.abs(k["velocity"] - velocity).max() <= 1e-6 * max(1, np.abs(velocity).max())
    acc = (k["velocity"] - m.kinematics_at(u - h, point=point)["velocity"]) / h
    assert np.abs(k["acceleration"] - acc).max() <= 1e-4 * max(1, np.abs(acc).max())
    scalar = m.kinematics_at(float(u[3]), point=point)
    assert scalar["velocity"].shape == (3,)
    assert np.array_equal(scalar["velocity"], k["velocity"][3])


def test_level_zero_is_the_plain_polyscrew():
    m = sb.Motion(P, levels=0)
    assert np.array_equal(m.subdivide(), m.poses)
    half = m.poses_at(np.array([1.5]))[0]
    assert np.array_equal(half, sb.screw(m.poses[1], 0.5, m.poses[2]))


def test_shapes_follow_the_parameters():
    m = sb.Motion(P, levels=3)
    assert m.poses_at(np.zeros((2, 3))).shape == (2, 3, 7)
    assert m.poses_at(1.25).shape == (7,)
    assert m.poses_at([]).shape == (0, 7)
    assert m.sample(10).shape == (10, 7)
    assert m.domain == (0.0, 6.0)
    assert len(m) == 6
    assert sb.Motion(P, closed=False).domain == (0.0, 5.0)


def test_options_round_trip_and_invalidate():
    m = sb.Motion(P, levels=3)
    first = m.subdivide()
    m.scheme = "bspline"
    assert m.scheme == "bspline" and m.s == 1.0
    assert not np.array_equal(m.subdivide(), first)
    m.s = 0.25
    assert m.scheme == "j" and m.s == 0.25
    m.scheme = "fourpoint"
    m.rules = "split"
    assert m.rules == "split"
    # The core's former id is accepted and reported as the one id.
    m.rules = "split-then-tweak"
    assert m.rules == "split" and "rules='split'" in repr(m)
    m.rules = "direct"
    assert np.array_equal(m.subdivide(), first)
    m.set_pose(-1, P[0])
    assert np.array_equal(m.pose(5), P[0])
    c = m.copy()
    c.levels = 1
    assert m.levels == 3 and c.levels == 1
    assert "Motion(6 poses, closed=True, scheme='fourpoint', levels=3, rules='direct')" == repr(m)


def test_files_round_trip_and_match_the_cli(tmp_path, cli):
    m = sb.Motion.from_preset("l_cycle_rotated", levels=3)
    for name in ["walk.json", "walk.csv", "walk.glb", "walk.gltf"]:
        path = tmp_path / name
        count = m.export(path)
        assert count > 0 and path.exists()
    back = sb.Motion.load(tmp_path / "walk.json")
    assert np.abs(back.poses - m.poses).max() <= 1e-15 and back.closed == m.closed
    glb = sb.Motion.load(tmp_path / "walk.glb")
    assert np.abs(glb.poses - m.poses).max() <= 1e-6  # glTF stores float32
    assert (tmp_path / "walk.bin").exists()
    # The same bytes as `screwbender export` (from the document the CLI reads).
    doc = cli(["preset", "l_cycle_rotated"])
    m = sb.Motion.from_json(doc)
    m.levels = 3
    m.export(tmp_path / "walk.glb")
    out = tmp_path / "cli.glb"
    cli(["export", "--format", "glb", "--levels", "3", "-o", str(out)], doc)
    assert out.read_bytes() == (tmp_path / "walk.glb").read_bytes()
    csv = cli(["export", "--format", "csv", "--levels", "3", "--point", "1,0,0"], doc)
    m.export(tmp_path / "p.csv", point=[1, 0, 0])
    assert (tmp_path / "p.csv").read_text() == csv
    with pytest.raises(ValueError, match="cannot tell the format"):
        m.export(tmp_path / "walk.txt")
    with pytest.raises(ValueError, match="not both"):
        m.export(tmp_path / "x.glb", fps=30, tolerance=1e-3)


def test_large_work_releases_the_gil():
    m = sb.Motion(np.tile(P, (1, 1)), levels=17)  # 786 432 refined poses
    ticks = []
    done = threading.Event()

    def work():
        m.subdivide()
        done.set()

    worker = threading.Thread(target=work)
    start = time.perf_counter()
    worker.start()
    while not done.is_set():
        ticks.append(time.perf_counter())
        time.sleep(0.001)
    worker.join()
    elapsed = time.perf_counter() - start
    # The main thread kept running Python while the subdivision ran.
    assert elapsed > 0.005
    assert len(ticks) >= 3


# ---- former names: they still work for one release, and warn ---------------------------------


def test_matrices_is_the_former_name_of_refined_matrices():
    m = sb.Motion(P, levels=2)
    with pytest.warns(DeprecationWarning, match=r"use Motion\.refined_matrices\(\)") as seen:
        got = m.matrices()
    assert np.array_equal(got, m.refined_matrices())
    # Attributed to the caller's line, as `stacklevel=2` in Python.
    assert seen[0].filename == __file__


def test_kinematics_is_the_former_name_of_kinematics_at():
    m = sb.Motion(P, levels=2)
    u = np.linspace(0, 6, 7)
    with pytest.warns(DeprecationWarning, match=r"use Motion\.kinematics_at\(\)") as seen:
        got = m.kinematics(u, point=[1, 0, 0])
    want = m.kinematics_at(u, point=[1, 0, 0])
    assert set(got) == set(want) and all(np.array_equal(got[k], want[k]) for k in want)
    assert seen[0].filename == __file__


def test_split_then_tweak_is_accepted_and_reported_as_split():
    m = sb.Motion(P, rules="split-then-tweak", levels=2)
    assert m.rules == "split"
    assert np.array_equal(m.subdivide(), sb.Motion(P, rules="split", levels=2).subdivide())
    assert sb.Motion.from_preset("circle4", rules="split-then-tweak").rules == "split"
    m.rules = "direct"
    m.rules = "split-then-tweak"
    assert m.rules == "split" and "rules='split'" in repr(m)


def test_pose_count_is_the_number_of_control_poses():
    m = sb.Motion(P)
    assert m.pose_count == len(m) == 6


def test_insert_and_remove_pose_as_the_js_api_does():
    m = sb.Motion(P, closed=True)
    before = m.poses.copy()
    assert m.insert_pose(5) == 6  # after a cycle's last pose: the screw midpoint to the first
    assert len(m) == 7
    np.testing.assert_allclose(m.pose(6), sb.screw(before[5], 0.5, before[0]), rtol=0, atol=1e-15)
    m.remove_pose(-1)
    assert np.array_equal(m.poses, before)
    given = before[2] + np.array([0.5, 0, 0, 0, 0, 0, 0])
    assert m.insert_pose(1, given) == 2
    np.testing.assert_array_equal(m.pose(2), given)
    # Bad input: the element named, nothing changed.
    m = sb.Motion(P[:2], closed=False)
    kept = m.poses.copy()
    with pytest.raises(ValueError, match="index"):
        m.insert_pose(1)  # an open motion's last pose has no successor
    with pytest.raises(ValueError):
        m.remove_pose(0)  # two poses at least
    with pytest.raises(IndexError, match="index"):
        m.remove_pose(2)
    with pytest.raises(ValueError, match="pose"):
        m.insert_pose(0, [1, 2, 3])
    assert np.array_equal(m.poses, kept)
