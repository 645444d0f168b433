"""Benchmarks of the Python package (not timed tests: they print numbers, they assert nothing).

1. ``Motion.subdivide()`` at 10^5 and 10^6 refined poses against the Rust core doing the same
   work natively (``Subdivision::apply_into`` on the same control poses plus the ``(N, 7)`` rows
   in a fresh array), run interleaved (one Python run, one Rust run, ...) so that both see the
   same machine load, each side warm in one process; min / median / max of each and the ratios.
2. ``sb.screw`` on 10^6 pairs against a Python loop over ``modern_robotics``
   (``X0 @ MatrixExp6(MatrixLog6(TransInv(X0) @ X1) * t)``, timed on a sample of pairs and scaled)
   and against pytransform3d's batched ``dual_quaternions_sclerp`` (its native dual
   quaternions in, so its conversions are not counted).

    .venv/bin/python benches/python/bench.py [--rounds 9] [--quick]

Needs the Rust example ``core_timing`` (built here with cargo, release). Unset
OPENBLAS_CORETYPE / OPENBLAS_L2_SIZE for this command alone if they are set (they slow numpy).
"""

import argparse
import os
import pathlib
import re
import statistics
import subprocess
import time

import numpy as np

import screwbender as sb

ROOT = pathlib.Path(__file__).resolve().parents[2]


def cpu() -> str:
    text = subprocess.run(["lscpu"], capture_output=True, text=True).stdout
    model = re.search(r"Model name:\s*(.+)", text)
    flags = re.search(r"Flags:\s*(.+)", text)
    f = set(flags.group(1).split()) if flags else set()
    width = "AVX-512" if "avx512f" in f else "AVX2" if "avx2" in f else "no AVX2"
    return f"{model.group(1).strip() if model else '?'}, {os.cpu_count()} CPUs, {width}"


def core_binary() -> pathlib.Path:
    subprocess.run(
        ["cargo", "build", "--release", "-q", "-p", "screwbender-py", "--example", "core_timing"],
        cwd=ROOT, check=True,
    )
    target = pathlib.Path(os.environ.get("CARGO_TARGET_DIR", ROOT / "target"))
    return target / "release" / "examples" / "core_timing"


def run_core(binary, *args) -> list:
    out = subprocess.run([str(binary), *map(str, args)], capture_output=True, text=True, check=True).stdout
    return out


def spread(ts) -> str:
    return f"min {min(ts) * 1e3:8.2f} ms  median {statistics.median(ts) * 1e3:8.2f} ms  max {max(ts) * 1e3:8.2f} ms"


def bench_subdivide(binary, refined: int, rounds: int) -> None:
    """Interleaved, one Python run and one Rust run per round (alternating which goes first), both
    sides warm in one long-lived process each: Python in this one, Rust in ``core_timing serve``
    (one subdivision per line it reads). Both do the same work: subdivide in working memory kept
    from the run before, then write the ``(N, 7)`` rows into a fresh array, which Python returns
    and this loop drops before the next round, as the Rust side drops its own."""
    levels = 5
    n = refined // 2**levels
    rows = np.array([[float(v) for v in line.split()] for line in run_core(binary, "poses", n, 1).splitlines()])
    m = sb.Motion(rows, closed=True, scheme="fourpoint", levels=levels, rules="direct")
    rust_process = subprocess.Popen([str(binary), "serve"], stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True)

    def rust_run() -> float:
        rust_process.stdin.write(f"subdivide {n} {levels}\n")
        rust_process.stdin.flush()
        return float(rust_process.stdout.readline())

    def python_run() -> float:
        m.levels = levels  # a change: the next subdivide() computes afresh
        start = time.perf_counter()
        out = m.subdivide()
        elapsed = time.perf_counter() - start
        assert out.shape == (n * 2**levels, 7)
        return elapsed

    py, rust = [], []
    try:
        for _ in range(2):  # both sides grow their working memory once, untimed
            python_run(), rust_run()
        for i in range(rounds):
            if i % 2:
                rust.append(rust_run())
                py.append(python_run())
            else:
                py.append(python_run())
                rust.append(rust_run())
    finally:
        rust_process.stdin.close()
        rust_process.wait()
    ratios = sorted(a / b for a, b in zip(py, rust))
    print(f"Motion.subdivide() {n * 2**levels:>8} poses  python {spread(py)}")
    print(f"{'':>26} rust   {spread(rust)}")
    print(f"{'':>26} ratio python/rust: of medians {statistics.median(py) / statistics.median(rust):.3f}, "
          f"of minima {min(py) / min(rust):.3f}, per round min {ratios[0]:.3f} median {statistics.median(ratios):.3f} max {ratios[-1]:.3f}")


def random_pairs(count: int, seed: int):
    rng = np.random.default_rng(seed)
    q = rng.normal(size=(2, count, 4))
    q /= np.linalg.norm(q, axis=2, keepdims=True)
    o = rng.uniform(-2, 2, size=(2, count, 3))
    return np.concatenate([o[0], q[0]], 1), np.concatenate([o[1], q[1]], 1), rng.uniform(0, 1, count)


def matrices(rows):
    w, x, y, z = rows[:, 3:].T
    m = np.zeros((len(rows), 4, 4))
    m[:, 0] = np.stack([1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y), rows[:, 0]], 1)
    m[:, 1] = np.stack([2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x), rows[:, 1]], 1)
    m[:, 2] = np.stack([2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y), rows[:, 2]], 1)
    m[:, 3, 3] = 1
    return m


def bench_screw(binary, pairs: int, rounds: int, loop_sample: int) -> None:
    import modern_robotics as mr
    import pytransform3d.trajectories as ptr

    a, b, t = random_pairs(pairs, 11)
    ma, mb = matrices(a), matrices(b)
    sb_rows, sb_mats = [], []
    for _ in range(rounds):
        start = time.perf_counter()
        sb.screw(a, t, b)
        sb_rows.append(time.perf_counter() - start)
        start = time.perf_counter()
        sb.screw(ma, t, mb)
        sb_mats.append(time.perf_counter() - start)
    rust = [float(v) for v in run_core(binary, "screw", pairs, rounds).split()]
    da, db = ptr.dual_quaternions_from_transforms(ma), ptr.dual_quaternions_from_transforms(mb)
    pt = []
    for _ in range(max(1, rounds // 3)):
        start = time.perf_counter()
        ptr.dual_quaternions_sclerp(da, db, t)
        pt.append(time.perf_counter() - start)
    k = loop_sample
    start = time.perf_counter()
    for i in range(k):
        x0 = ma[i]
        ma[i] @ mr.MatrixExp6(mr.MatrixLog6(mr.TransInv(x0) @ mb[i]) * t[i])
    mr_total = (time.perf_counter() - start) / k * pairs
    best = statistics.median(sb_rows)
    print(f"sb.screw {pairs} pairs (n,7)    {spread(sb_rows)}")
    print(f"sb.screw {pairs} pairs (n,4,4)  {spread(sb_mats)}")
    print(f"Rust core Pose::blends + rows  {spread(rust)}")
    print(f"pytransform3d dual_quaternions_sclerp (batched)  {spread(pt)}")
    print(f"modern_robotics Python loop: {mr_total:.1f} s for {pairs} pairs (timed on {k})")
    print(f"ratios: modern_robotics loop / sb.screw = {mr_total / best:.0f}x, "
          f"pytransform3d batched / sb.screw = {statistics.median(pt) / best:.1f}x, "
          f"sb.screw / Rust core = {best / statistics.median(rust):.2f}x, "
          f"matrices in / rows in = {statistics.median(sb_mats) / best:.2f}x")


def main() -> None:
    p = argparse.ArgumentParser()
    p.add_argument("--rounds", type=int, default=15)
    p.add_argument("--quick", action="store_true", help="10^5 only, fewer pairs")
    p.add_argument("--subdivide-only", action="store_true", help="only Motion.subdivide()")
    args = p.parse_args()
    print(f"CPU: {cpu()}; numpy {np.__version__}; screwbender {sb.__version__}")
    binary = core_binary()
    # numpy asks the kernel for huge pages for its large arrays (where transparent huge pages are
    # "madvise"), which makes the first touches of a fresh result cheaper than those of the Rust
    # side's Vec: timed both ways, the second with the same page size on both sides.
    for hugepages in (True, False):
        np.core.multiarray._set_madvise_hugepage(hugepages)
        print(f"numpy huge pages for large arrays: {'on (its default)' if hugepages else 'off (as the Rust side)'}")
        for refined in [100_000] if args.quick else [100_000, 1_000_000]:
            bench_subdivide(binary, refined, args.rounds)
    np.core.multiarray._set_madvise_hugepage(True)
    if not args.subdivide_only:
        bench_screw(binary, 100_000 if args.quick else 1_000_000, args.rounds, 2_000 if args.quick else 20_000)


if __name__ == "__main__":
    main()
