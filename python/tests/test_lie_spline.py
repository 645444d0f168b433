"""The cumulative B-splines on Lie groups against the cumulative formula evaluated independently:
SE(3) with 4×4 matrices and scipy.linalg's expm/logm, R³ × SO(3) with
scipy.spatial.transform.Rotation's rotation vectors (the ``kks`` method is that motion)."""

import numpy as np
import pytest
from scipy.linalg import expm, logm
from scipy.spatial.transform import Rotation

import screwbender as sb

#: Agreement of the core with the independent evaluation (matrix entries, origins).
TOLERANCE = 1e-9


def matrix(row):
    """4×4 homogeneous matrix of a pose row ``x y z qw qx qy qz``."""
    m = np.eye(4)
    w, x, y, z = row[3:]
    m[:3, :3] = Rotation.from_quat([x, y, z, w]).as_matrix()
    m[:3, 3] = row[:3]
    return m


def se3_log(m):
    """The principal logarithm of an SE(3) matrix, as a 4×4 twist matrix."""
    return np.real(logm(m))


def cumulative_basis(f):
    """λ₁, λ₂, λ₃ of the uniform cumulative cubic B-spline at ``f ∈ [0, 1)``."""
    return (
        (5 + 3 * f - 3 * f**2 + f**3) / 6,
        (1 + 3 * f + 3 * f**2 - 2 * f**3) / 6,
        f**3 / 6,
    )


def with_ends(controls, closed, log, exp, inverse, compose):
    """The control list indexed from −1: wrapped for a cycle, phantoms reflected along the end
    spans for an open sequence."""
    if closed:
        return controls
    first = compose(controls[0], exp(-log(compose(inverse(controls[0]), controls[1]))))
    last = compose(controls[-1], exp(log(compose(inverse(controls[-2]), controls[-1]))))
    return [first, *controls, last]


def se3_reference(poses, closed, us):
    """``T(u) = C_{j−1} ∏ expm(λ_i logm(C_{k−1}⁻¹ C_k))`` with matrices (each logarithm taken
    once: scipy's logm is slow)."""
    mats = [matrix(p) for p in poses]
    n = len(mats)
    c = with_ends(mats, closed, se3_log, expm, np.linalg.inv, np.matmul)
    m = len(c)
    # logs[k] = log(c[k−1]⁻¹ c[k]) in stored indices (wrapping for a cycle).
    logs = [se3_log(np.linalg.inv(c[k - 1]) @ c[k]) for k in range(m)]
    out = []
    for u in us:
        if closed:
            u = u % n
            j = min(int(np.floor(u)), n - 1)
            at = lambda k: k % n  # noqa: E731
        else:
            j = min(int(np.floor(u)), n - 2)
            at = lambda k: k + 1  # noqa: E731
        f = u - j
        t = c[at(j - 1)]
        for i, lam in enumerate(cumulative_basis(f)):
            t = t @ expm(lam * logs[at(j + i)])
        out.append(t)
    return np.array(out)


def split_reference(poses, closed, us):
    """The same on R³ × SO(3): origins by the cubic B-spline, rotations by ``Rotation``."""
    n = len(poses)
    origins = [np.asarray(p[:3]) for p in poses]
    rots = [Rotation.from_quat([p[4], p[5], p[6], p[3]]) for p in poses]
    o = with_ends(origins, closed, lambda d: d, lambda d: d, lambda a: -a, np.add)
    r = with_ends(
        rots,
        closed,
        lambda d: d.as_rotvec(),
        Rotation.from_rotvec,
        lambda a: a.inv(),
        lambda a, b: a * b,
    )
    out = []
    for u in us:
        if closed:
            u = u % n
            j = min(int(np.floor(u)), n - 1)
            idx = lambda k: k % n  # noqa: E731
        else:
            j = min(int(np.floor(u)), n - 2)
            idx = lambda k: k + 1  # noqa: E731
        f = u - j
        origin = o[idx(j - 1)]
        rot = r[idx(j - 1)]
        for i, lam in enumerate(cumulative_basis(f)):
            k = j + i
            origin = origin + lam * (o[idx(k)] - o[idx(k - 1)])
            rot = rot * Rotation.from_rotvec(lam * (r[idx(k - 1)].inv() * r[idx(k)]).as_rotvec())
        m = np.eye(4)
        m[:3, :3] = rot.as_matrix()
        m[:3, 3] = origin
        out.append(m)
    return np.array(out)


def random_poses(seed, n, max_angle=1.0):
    """Poses with rotations well under half a turn from each other (the principal logarithm
    is then the spline's minimal one)."""
    rng = np.random.default_rng(seed)
    rows = []
    base = Rotation.from_rotvec(rng.normal(size=3))
    for _ in range(n):
        r = Rotation.from_rotvec(rng.normal(size=3) * max_angle / 3) * base
        x, y, z, w = r.as_quat()
        rows.append([*rng.uniform(-3, 3, size=3), w, x, y, z])
    return np.array(rows)


@pytest.mark.parametrize("closed", [True, False])
def test_se3_bspline_is_the_cumulative_formula(closed):
    poses = random_poses(7, 6)
    end = 6 if closed else 5
    us = np.linspace(0, end, 25)
    got = np.array([matrix(p) for p in sb.method_poses("se3bspline", poses, us, closed)])
    want = se3_reference(poses, closed, us)
    assert np.abs(got - want).max() < TOLERANCE


@pytest.mark.parametrize("closed", [True, False])
def test_split_bspline_is_kim_kim_shin(closed):
    poses = random_poses(8, 5)
    end = 5 if closed else 4
    us = np.linspace(0, end, 33)
    got = np.array([matrix(p) for p in sb.method_poses("kks", poses, us, closed)])
    want = split_reference(poses, closed, us)
    assert np.abs(got - want).max() < TOLERANCE


@pytest.mark.parametrize("method", ["se3interp", "splitinterp"])
def test_interpolating_splines_pass_through_the_poses(method):
    poses = random_poses(9, 7, max_angle=0.6)
    got = sb.method_poses(method, poses, np.arange(7.0), closed=True)
    want = np.array([matrix(p) for p in poses])
    assert np.abs(np.array([matrix(p) for p in got]) - want).max() < 1e-10
    # Between the poses it is a smooth curve, not the approximating one.
    mid = sb.method_poses(method, poses, 0.5)
    assert mid.shape == (7,)


def test_method_poses_names_bad_input():
    poses = random_poses(1, 4)
    with pytest.raises(ValueError, match="method: unknown value 'nope'"):
        sb.method_poses("nope", poses, 0.0)
    with pytest.raises(ValueError, match=r"u\[1\]"):
        sb.method_poses("se3bspline", poses, [0.0, np.nan])
    preset = sb.Motion.from_preset("l_cycle_rotated").poses
    with pytest.raises(ValueError, match="se3interp.poses: .*half a turn"):
        sb.method_poses("se3interp", preset, 0.0, closed=True)
