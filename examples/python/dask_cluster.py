"""A large batch on a Dask cluster (issue 16's scale-out example; docs/python.md,
"Scale-out on Dask"): N random cubic Beziers flattened at a tolerance (the segment counts
totalled) and M noisy trajectories fitted with cubic B-splines, on the worker processes of
a cluster, checked equal to the same calls in this one process.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/dask_cluster.py            # LocalCluster, 2 workers
    PYTHONPATH=build/python /usr/bin/python3 examples/python/dask_cluster.py --cubics 1000 --trajectories 100
    /usr/bin/python3 examples/python/dask_cluster.py --scheduler tcp://scheduler:8786   # a running cluster

Without --scheduler the cluster is a `distributed.LocalCluster` of worker processes on this
machine; with it, the same code runs on the cluster of that scheduler (its workers started
with `dask worker tcp://scheduler:8786` on each machine, the casteljau package importable
there). The data are dask arrays cut into blocks; each block is one call of a plain
function on numpy arrays (below), which the workers receive pickled.

The `if __name__ == "__main__":` guard is required: distributed starts its worker
processes with multiprocessing's "spawn" method, which imports this script again in every
worker; without the guard each worker would start a cluster of its own, fail, and be
restarted by its nanny while LocalCluster waits for it (a hang, not an error).
"""

from __future__ import annotations

import argparse
import time

import dask.array as da
import numpy as np

import casteljau


def segment_counts(points: np.ndarray, tolerance: float) -> np.ndarray:
    """The number of segments of each cubic points[i] (4 control points) flattened within
    the tolerance: an integer array of shape (m,)."""
    return np.array([len(casteljau.Bezier(p).flatten(tolerance)) - 1 for p in points], dtype=np.int64)


def fitted(samples: np.ndarray, control_points: int) -> np.ndarray:
    """The cubic B-spline least-squares fit of each trajectory samples[i] (s, d): its
    control points and max_error packed as one float array of shape (m, control_points *
    d + 1)."""
    out = np.empty((len(samples), control_points * samples.shape[2] + 1))
    for i, s in enumerate(samples):
        r = casteljau.fit(s, 3, control_points=control_points)
        out[i, :-1] = np.asarray(r.curve.points, dtype=np.float64).ravel()
        out[i, -1] = r.max_error
    return out


def cubics(n: int, seed: int) -> np.ndarray:
    """n random cubics in the unit square: control points (n, 4, 2)."""
    return np.random.default_rng(seed).random((n, 4, 2))


def trajectories(m: int, samples: int, noise: float, seed: int) -> np.ndarray:
    """m noisy trajectories (m, samples, 2): a random cubic sampled at equal parameter steps
    (its Bernstein form, numpy), plus Gaussian noise."""
    rng = np.random.default_rng(seed)
    P = rng.random((m, 4, 2))
    t = np.linspace(0.0, 1.0, samples)[:, None]
    B = np.hstack([(1 - t) ** 3, 3 * t * (1 - t) ** 2, 3 * t**2 * (1 - t), t**3])  # (samples, 4)
    return np.einsum("sk,mkd->msd", B, P) + rng.normal(0.0, noise, (m, samples, 2))


def on_cluster(points: np.ndarray, paths: np.ndarray, tolerance: float, control_points: int,
               blocks: int) -> tuple[np.ndarray, np.ndarray]:
    """The segment counts and the fits, computed block by block by the current Dask client
    (one task per block)."""
    p = da.from_array(points, chunks=(max(1, -(-len(points) // blocks)), 4, 2))
    counts = p.map_blocks(segment_counts, tolerance, drop_axis=[1, 2], dtype=np.int64)
    q = da.from_array(paths, chunks=(max(1, -(-len(paths) // blocks)),) + paths.shape[1:])
    fits = q.map_blocks(fitted, control_points, drop_axis=[1, 2], new_axis=1, dtype=np.float64,
                        chunks=(q.chunks[0], (control_points * paths.shape[2] + 1,)))
    return tuple(da.compute(counts, fits))  # type: ignore[return-value]


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--cubics", type=int, default=100_000)
    ap.add_argument("--trajectories", type=int, default=10_000)
    ap.add_argument("--tolerance", type=float, default=1e-3)
    ap.add_argument("--workers", type=int, default=2, help="LocalCluster worker processes (without --scheduler)")
    ap.add_argument("--blocks", type=int, default=16, help="blocks per batch (tasks)")
    ap.add_argument("--scheduler", help="the address of a running scheduler (tcp://host:8786) instead of a LocalCluster")
    a = ap.parse_args()
    points = cubics(a.cubics, 16)
    paths = trajectories(a.trajectories, 40, 0.01, 17)
    control_points = 6

    from distributed import Client, LocalCluster

    start = time.perf_counter()
    if a.scheduler:
        client, cluster = Client(a.scheduler), None
    else:
        # Worker processes (one thread each: the library's calls hold no lock, the
        # processes give the parallelism), no dashboard (it needs bokeh).
        cluster = LocalCluster(n_workers=a.workers, threads_per_worker=1, processes=True, dashboard_address=None)
        client = Client(cluster)
    try:
        up = time.perf_counter()
        counts, fits = on_cluster(points, paths, a.tolerance, control_points, a.blocks)
        done = time.perf_counter()
        workers = len(client.scheduler_info()["workers"])
    finally:
        client.close()
        if cluster is not None:
            cluster.close()

    alone_start = time.perf_counter()
    alone_counts = segment_counts(points, a.tolerance)
    alone_fits = fitted(paths, control_points)
    alone = time.perf_counter()
    print(f"{a.cubics} cubics at tolerance {a.tolerance}: {int(counts.sum())} segments on {workers} workers, "
          f"{int(alone_counts.sum())} in one process")
    print(f"{a.trajectories} trajectories fitted ({control_points} control points): largest max_error "
          f"{fits[:, -1].max():.6f} on the workers, {alone_fits[:, -1].max():.6f} in one process")
    print(f"seconds: cluster start {up - start:.2f}, batch on the cluster {done - up:.2f}, "
          f"the same batch in one process {alone - alone_start:.2f}")
    # Equal, not close: the same compiled code on the same numbers in every process.
    assert np.array_equal(counts, alone_counts)
    assert np.array_equal(fits, alone_fits)
    print("equal to the single-process run")


if __name__ == "__main__":
    main()
