"""The two-pose screw is the screw of the libraries a robotics course already uses: the
*Modern Robotics* library's `ScrewTrajectory` (`X0 · exp(s · log(X0⁻¹ X1))`) and pytransform3d's
`dual_quaternion_sclerp`, within 1e-12 on random well-conditioned pairs."""

import modern_robotics as mr
import numpy as np
import pytest
from pytransform3d import transformations as pt

import screwbender as sb

TOL = 1e-12


def random_pairs(count, seed):
    """Pairs of 4×4 poses whose relative rotation is between 0.2 and 2.8 rad (away from the
    identity, where log(X) loses digits in `acos`, and from the half turn, where its axis is
    ill-conditioned), with translations of order 1."""
    rng = np.random.default_rng(seed)
    pairs = []
    while len(pairs) < count:
        q = rng.normal(size=(2, 4))
        q /= np.linalg.norm(q, axis=1, keepdims=True)
        a = np.concatenate([rng.uniform(-2, 2, 3), q[0]])
        b = np.concatenate([rng.uniform(-2, 2, 3), q[1]])
        angle = 2 * np.arccos(min(1.0, abs(float(np.dot(q[0], q[1])))))
        if 0.2 < angle < 2.8:
            pairs.append((pose_matrix(a), pose_matrix(b)))
    return pairs


def pose_matrix(p):
    w, x, y, z = p[3:]
    m = np.eye(4)
    m[:3, :3] = [
        [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
        [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
        [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)],
    ]
    m[:3, 3] = p[:3]
    return m


def matrices_of(rows):
    return np.array([pose_matrix(r) for r in np.atleast_2d(rows)])


def test_screw_trajectory_of_modern_robotics():
    for x0, x1 in random_pairs(200, seed=1):
        tf, n = 2.0, 9
        for method in (3, 5):
            frames = mr.ScrewTrajectory(x0, x1, tf, n, method)
            scaling = mr.CubicTimeScaling if method == 3 else mr.QuinticTimeScaling
            s = np.array([scaling(tf, tf * i / (n - 1)) for i in range(n)])
            ours = matrices_of(sb.screw(x0, s, x1))
            assert np.abs(ours - np.array(frames)).max() <= TOL


def test_the_exponential_formula_beyond_the_ends():
    for x0, x1 in random_pairs(100, seed=2):
        log = mr.MatrixLog6(mr.TransInv(x0) @ x1)
        for s in (-0.5, 0.3, 1.4):
            want = x0 @ mr.MatrixExp6(log * s)
            assert np.abs(matrices_of(sb.screw(x0, s, x1))[0] - want).max() <= TOL


def test_dual_quaternion_sclerp_of_pytransform3d():
    for x0, x1 in random_pairs(200, seed=3):
        d0, d1 = pt.dual_quaternion_from_transform(x0), pt.dual_quaternion_from_transform(x1)
        for t in (0.0, 0.1, 0.5, 0.77, 1.0):
            want = pt.transform_from_dual_quaternion(pt.dual_quaternion_sclerp(d0, d1, t))
            assert np.abs(matrices_of(sb.screw(x0, t, x1))[0] - want).max() <= TOL


def test_batches_of_pairs_match_modern_robotics():
    pairs = random_pairs(300, seed=4)
    a = np.array([p[0] for p in pairs])
    b = np.array([p[1] for p in pairs])
    t = np.linspace(-0.2, 1.2, len(pairs))
    ours = matrices_of(sb.screw(a, t, b))
    for k, (x0, x1) in enumerate(pairs):
        want = x0 @ mr.MatrixExp6(mr.MatrixLog6(mr.TransInv(x0) @ x1) * t[k])
        assert np.abs(ours[k] - want).max() <= TOL


@pytest.mark.parametrize("seed", [5, 6])
def test_spatialmath_style_matrices_pass_straight_in(seed):
    # (n, 4, 4) matrices as `SE3(...).A` gives them, in a Motion: its refined control poses at
    # u = i are the given poses for the interpolating 4-point scheme.
    pairs = random_pairs(3, seed)
    mats = np.array([m for pair in pairs for m in pair])
    m = sb.Motion(mats, closed=True, scheme="fourpoint", levels=4)
    got = matrices_of(m.poses_at(np.arange(len(mats), dtype=float)))
    assert np.abs(got - mats).max() <= 1e-12
