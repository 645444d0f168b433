"""Input: matrices in = quaternions in; every bad input of docs/bad-input.md that applies to the
package, plus wrong shapes, dtypes and object arrays, raises `ValueError` / `TypeError` whose
message names the element; a `Motion` that refused a change is unchanged."""

import math
import os

import numpy as np
import pytest

import screwbender as sb
from test_references import matrices_of

SQ = math.sqrt(0.5)
P = np.array(
    [
        [0, 0, 0, 1, 0, 0, 0],
        [4, 0, 0, SQ, 0, 0, SQ],
        [4, 3, 0.5, 0, 0, 0, 1],
        [0, 3, 1, SQ, 0, 0, -SQ],
        [-1, 1, 0.2, SQ, SQ, 0, 0],
        [1, -1, 0, 0.5, 0.5, 0.5, 0.5],
    ]
)


def state(m):
    return (
        m.poses.tobytes(), m.closed, m.scheme, m.s, m.rules, m.levels, m.times, m.velocities,
        m.name, m.subdivide().tobytes(),
    )


def refuses(exc, match, fn, *args, **kwargs):
    with pytest.raises(exc) as e:
        fn(*args, **kwargs)
    assert match in str(e.value), str(e.value)
    return str(e.value)


# ---- matrices in = quaternions in ------------------------------------------------------------


def test_matrices_in_equal_quaternions_in():
    mats = matrices_of(P)
    for kwargs in [dict(scheme="jarek"), dict(scheme="bspline", rules="split"), dict(s=0.3)]:
        for closed in (True, False):
            q = sb.Motion(P, closed=closed, levels=4, **kwargs)
            m = sb.Motion(mats, closed=closed, levels=4, **kwargs)
            assert np.abs(m.refined_matrices() - q.refined_matrices()).max() <= 1e-12
            u = np.linspace(-0.5, 6.5, 41)
            assert np.abs(matrices_of(m.poses_at(u)) - matrices_of(q.poses_at(u))).max() <= 1e-12
    a, b = P[1], P[4]
    t = np.linspace(0, 1, 9)
    one = matrices_of(sb.screw(a, t, b))
    assert np.abs(matrices_of(sb.screw(pose_mat(a), t, pose_mat(b))) - one).max() <= 1e-12
    assert np.abs(matrices_of(sb.screw(pose_mat(a), t, b)) - one).max() <= 1e-12


def pose_mat(p):
    return matrices_of(p)[0]


def test_matrices_out_are_the_poses():
    m = sb.Motion(P, levels=3)
    assert np.abs(m.refined_matrices() - matrices_of(m.subdivide())).max() <= 1e-15
    assert m.refined_matrices().shape == (48, 4, 4)


def test_other_real_dtypes_and_layouts_are_accepted():
    ref = sb.Motion(P, levels=2).subdivide()
    ints = np.array([[0, 0, 0, 1, 0, 0, 0], [1, 0, 0, 1, 0, 0, 0], [1, 1, 0, 1, 0, 0, 0]])
    assert sb.Motion(ints, levels=1).subdivide().dtype == np.float64
    assert np.array_equal(sb.Motion(P.tolist(), levels=2).subdivide(), ref)
    assert np.array_equal(sb.Motion(np.asfortranarray(P), levels=2).subdivide(), ref)
    wide = np.zeros((6, 9))
    wide[:, ::1][:, :7] = P
    assert np.array_equal(sb.Motion(wide[:, :7], levels=2).subdivide(), ref)
    assert np.array_equal(sb.Motion(P.astype(np.float32).astype(np.float64), levels=2).subdivide().shape, ref.shape)


# ---- bad input (docs/bad-input.md) -----------------------------------------------------------


def with_pose(i, row):
    p = P.copy()
    p[i] = row
    return p


def test_nan_is_refused_and_named():
    refuses(ValueError, "poses[2].origin: not a finite number", sb.Motion, with_pose(2, [0, math.nan, 0, 1, 0, 0, 0]))
    refuses(ValueError, "poses[1].rotation", sb.Motion, with_pose(1, [0, 0, 0, 1, math.nan, 0, 0]))
    refuses(ValueError, "s: not a finite number", sb.Motion, P, s=math.nan)
    m = sb.Motion(P)
    refuses(ValueError, "u[1]: not a finite number", m.poses_at, [0.5, math.nan])
    refuses(ValueError, "t: not a finite number", sb.screw, P[0], math.nan, P[1])
    refuses(ValueError, "point[1]: not a finite number", m.kinematics_at, 0.5, point=[0, math.nan, 0])
    mats = matrices_of(P)
    mats[3, 1, 2] = math.nan
    refuses(ValueError, "poses[3].basis", sb.Motion, mats)


def test_infinity_is_refused_and_named():
    refuses(ValueError, "poses[0].origin: not a finite number", sb.Motion, with_pose(0, [math.inf, 0, 0, 1, 0, 0, 0]))
    refuses(ValueError, "u[0]: not a finite number", sb.Motion(P).poses_at, [-math.inf])
    refuses(ValueError, "b[2]", sb.screw, P[:3], 0.5, with_pose(2, [0, 0, 0, math.inf, 0, 0, 0])[:3])


def test_huge_finite_values_are_refused_and_named():
    refuses(ValueError, "poses[4].origin: 1e101 is out of range", sb.Motion, with_pose(4, [0, 0, 1e101, 1, 0, 0, 0]))
    refuses(ValueError, "s: 5 is out of range (expected -4 to 4)", sb.Motion, P, s=5.0)
    refuses(ValueError, "levels", sb.Motion, P, levels=2**40)


def test_zero_quaternion_is_refused_and_named():
    refuses(ValueError, "poses[3].rotation: zero quaternion", sb.Motion, with_pose(3, [0, 0, 0, 0, 0, 0, 0]))
    refuses(ValueError, "a.rotation: zero quaternion", sb.screw, [0, 0, 0, 0, 0, 0, 0], 0.5, P[1])


def test_non_unit_quaternion_is_refused_and_named():
    refuses(ValueError, "poses[1].rotation: quaternion norm 2 is not 1", sb.Motion, with_pose(1, [0, 0, 0, 2, 0, 0, 0]))
    # Within the tolerance it is normalised.
    m = sb.Motion(with_pose(1, [0, 0, 0, 1.0005, 0, 0, 0]))
    assert m.poses[1, 3] == 1.0


def test_non_orthonormal_and_left_handed_matrices_are_refused_and_named():
    mats = matrices_of(P)
    skew = mats.copy()
    skew[2, 0, 1] += 0.1
    refuses(ValueError, "poses[2].basis: basis is not orthonormal", sb.Motion, skew)
    mirror = mats.copy()
    mirror[4, :3, 0] *= -1
    refuses(ValueError, "poses[4].basis: basis is left-handed", sb.Motion, mirror)
    projective = mats.copy()
    projective[1, 3, 0] = 0.5
    refuses(ValueError, "poses[1].matrix[3]: bottom row", sb.Motion, projective)
    refuses(ValueError, "a.basis", sb.screw, skew[2], 0.5, mats[0])


def test_too_few_poses_are_refused():
    refuses(ValueError, "poses: 1 pose(s) given, at least 2 needed", sb.Motion, P[:1])
    refuses(ValueError, "poses: 0 pose(s) given, at least 2 needed", sb.Motion, np.zeros((0, 7)))
    refuses(ValueError, "at least 2 needed", sb.Motion, P[:1], times=[0, 1])
    one = '{"poses": [{"origin": [0, 0, 0], "rotation": [1, 0, 0, 0]}]}'
    refuses(ValueError, "at least 2 needed", sb.Motion.from_json, one)
    m = sb.Motion(P)
    before = state(m)
    refuses(ValueError, "at least 2 needed", setattr, m, "poses", P[:1])
    assert state(m) == before


def test_unknown_option_values_are_refused_and_named():
    refuses(ValueError, "scheme: unknown value 'cubic' (expected bspline, fourpoint, jarek, j)", sb.Motion, P, scheme="cubic")
    refuses(ValueError, "rules: unknown value 'v3'", sb.Motion, P, rules="v3")
    refuses(ValueError, "rules: the J_s family is defined with the direct rules only", sb.Motion, P, s=0.5, rules="split")
    # A scheme and s must agree (as in JavaScript and on the command line).
    refuses(ValueError, "s: s = 0.3 contradicts scheme 'jarek'", sb.Motion, P, scheme="jarek", s=0.3)
    assert sb.Motion(P, scheme="jarek", s=0.5).scheme == "jarek"
    refuses(ValueError, "levels: -1 is out of range", sb.Motion, P, levels=-1)
    refuses(ValueError, "levels: 2.5 is out of range (expected a whole number from 0 to 19", sb.Motion, P, levels=2.5)
    assert sb.Motion(P, levels=3.0).levels == 3
    refuses(TypeError, "levels: expected a whole number", sb.Motion, P, levels=True)
    refuses(TypeError, "unexpected keyword argument 'sheme'", sb.Motion, P, sheme="jarek")
    refuses(ValueError, "name: 'nope' is out of range (expected a preset: ", sb.Motion.from_preset, "nope")
    assert sb.Motion(P, rules="split").rules == "split"
    assert sb.Motion(P, levels=np.int64(2)).levels == 2


def test_levels_beyond_the_cap_are_refused_before_any_work():
    refuses(ValueError, "levels: the result would have 1572864 poses, more than the limit of 1048576", sb.Motion, P, levels=18)
    m = sb.Motion(P, levels=17)
    assert m.refined_count == 6 * 2**17
    before = state(m)
    refuses(ValueError, "levels: 40 is out of range (expected a whole number from 0 to 19", setattr, m, "levels", 40)
    refuses(ValueError, "levels: the result would have", setattr, m, "levels", 19)
    assert state(m) == before


def test_malformed_files_are_refused_with_their_position(tmp_path):
    bad = {
        "truncated.json": '{"closed": true, "poses": [{"origin": [0, 0, 0], "rotation": [1, 0',
        "misspelt.json": '{"poses": [{"origin": [0,0,0], "rotaton": [1,0,0,0]}, {"origin": [1,0,0], "rotation": [1,0,0,0]}]}',
        "bad.csv": "x,y,z,qw,qx,qy,qz\n0,0,0,1,0,0,0\n1,0,zero,1,0,0,0\n",
        "broken.glb": "glTF\x02\x00\x00\x00garbage",
    }
    want = {
        "truncated.json": "line 1 column",
        "misspelt.json": "rotaton",
        "bad.csv": "line 3, column z",
        "broken.glb": "broken.glb:",
    }
    for name, text in bad.items():
        path = tmp_path / name
        path.write_bytes(text.encode("latin-1"))
        refuses(ValueError, want[name], sb.Motion.load, path)
    refuses(FileNotFoundError, "missing.json", sb.Motion.load, tmp_path / "missing.json")
    refuses(ValueError, "motion document", sb.Motion.from_json, "[]")


def test_bad_key_timing_is_refused_and_named():
    refuses(ValueError, "times", sb.Motion, P, times=[0, 1, 1, 2, 3, 4, 5])
    refuses(ValueError, "times", sb.Motion, P, times=[0, 1, 2])
    refuses(ValueError, "velocities", sb.Motion, P, velocities=[None, -1, None, None, None, None])
    refuses(TypeError, "velocities[1]: expected a number or None", sb.Motion, P, velocities=[None, "fast", None, None, None, None])
    m = sb.Motion(P, times=[0, 1, 2, 3, 4, 5, 6])
    before = state(m)
    refuses(ValueError, "times", setattr, m, "times", [0, 2, 1, 3, 4, 5, 6])
    refuses(ValueError, "velocities", setattr, m, "velocities", [1, 2])
    assert state(m) == before


def test_oversized_files_are_refused_before_parsing(tmp_path):
    big = tmp_path / "big.csv"
    with open(big, "wb") as f:
        f.truncate(65 * 2**20)  # sparse: nothing is written or read
    refuses(ValueError, "larger than the limit", sb.Motion.load, big)


# ---- wrong shapes, dtypes, object arrays -----------------------------------------------------


def test_wrong_shapes_are_refused_and_named():
    refuses(ValueError, "poses: shape (6, 6) is not (n, 7)", sb.Motion, P[:, :6])
    refuses(ValueError, "poses: shape (7,) is not (n, 7)", sb.Motion, P[0])
    refuses(ValueError, "poses: shape (2, 3, 3) is not", sb.Motion, np.zeros((2, 3, 3)))
    refuses(ValueError, "poses: not a rectangular array of numbers", sb.Motion, [[0, 0, 0, 1, 0, 0, 0], [1, 0, 0, 1]])
    refuses(ValueError, "a: shape (6,) is not", sb.screw, P[0, :6], 0.5, P[1])
    refuses(ValueError, "point: shape (2,) is not (3,)", sb.Motion(P).kinematics_at, 0.5, point=[1, 2])
    refuses(ValueError, "t of shape (3,)", sb.screw, P[:2], [0.1, 0.2, 0.3], P[2:4])
    refuses(ValueError, "2 start pose(s), 3 end pose(s)", sb.screw, P[:2], 0.5, P[2:5])
    refuses(ValueError, "times: shape (2, 4) is not (n,)", sb.Motion, P, times=np.zeros((2, 4)))


def test_wrong_dtypes_are_refused_and_named():
    refuses(TypeError, "poses: expected numbers, got an object array", sb.Motion, np.array(P, dtype=object).tolist() + [[None] * 7])
    refuses(TypeError, "poses: expected numbers, got an object array", sb.Motion, P.astype(object))
    refuses(TypeError, "poses: expected numbers, got an array of booleans", sb.Motion, P > 0)
    refuses(TypeError, "poses: expected real numbers, got an array of dtype complex128", sb.Motion, P.astype(complex))
    refuses(TypeError, "poses: expected real numbers, got an array of dtype <U", sb.Motion, [["a"] * 7] * 3)
    refuses(TypeError, "poses: expected numbers, got a str", sb.Motion, "poses.json")
    refuses(TypeError, "u: expected a number, got a bool", sb.Motion(P).poses_at, True)
    refuses(TypeError, "t: expected numbers, got a str", sb.screw, P[0], "half", P[1])
    refuses(TypeError, "closed: expected True or False, got a str", sb.Motion, P, closed="yes")
    refuses(TypeError, "closed: expected True or False, got a int", setattr, sb.Motion(P), "closed", 1)
    refuses(TypeError, "scheme: expected a str, got a int", sb.Motion, P, scheme=3)
    refuses(TypeError, "s: expected a number, got a str", sb.Motion, P, s="half")
    refuses(TypeError, "rules: expected a str, got a list", setattr, sb.Motion(P), "rules", ["direct"])


# ---- a refused change changes nothing --------------------------------------------------------


def test_a_motion_that_refused_a_change_is_unchanged():
    m = sb.Motion(P, scheme="jarek", levels=4, times=[0, 1, 2, 3, 4, 5, 6], name="walk")
    before = state(m)
    attempts = [
        ("poses", with_pose(2, [0, 0, 0, 0, 0, 0, 0])),
        ("poses", P[:, :5]),
        ("poses", P[:4]),  # the times no longer match: refused as a whole
        ("scheme", "cubic"),
        ("rules", "nope"),
        ("s", math.inf),
        ("levels", -3),
        ("levels", 30),
        ("times", [0, 1]),
        ("velocities", [-1] * 6),
    ]
    for name, value in attempts:
        with pytest.raises((ValueError, TypeError)):
            setattr(m, name, value)
        assert state(m) == before, name
    m2 = sb.Motion(P, levels=4, s=0.2)
    b2 = state(m2)
    with pytest.raises(ValueError):
        m2.rules = "split"
    assert state(m2) == b2
    with pytest.raises(ValueError):
        m.set_pose(1, [0, 0, 0, 0, 0, 0, 0])
    with pytest.raises(IndexError):
        m.set_pose(6, P[0])
    assert state(m) == before
    assert m.poses_at(0.5).shape == (7,)
