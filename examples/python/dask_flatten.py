"""Flatten many random cubic Beziers on Dask worker processes and total the segment counts
(issue 16's scale-out example; docs/python.md, "Scale-out on Dask").

    PYTHONPATH=build/python /usr/bin/python3 examples/python/dask_flatten.py [N] [TOLERANCE]

The cubics' control points are one (N, 4, 2) array cut into chunks; each chunk is flattened
on a worker (a separate process: dask's multiprocessing scheduler) and the counts summed.
The total equals the single-process run's. On a cluster, the same graph runs with
`distributed.Client("tcp://scheduler:8786")` in place of the scheduler argument, the
package importable on every worker.
"""

import sys

import dask
import numpy as np

import casteljau


def segments(points: np.ndarray, tolerance: float) -> int:
    """The total of the segment counts of the cubics points[i] (4 control points each)."""
    return sum(len(casteljau.Bezier(p).flatten(tolerance)) - 1 for p in points)


def total(points: np.ndarray, tolerance: float, chunk: int, **compute) -> int:
    parts = [dask.delayed(segments)(points[i : i + chunk], tolerance) for i in range(0, len(points), chunk)]
    return int(dask.delayed(sum)(parts).compute(**compute))


def main() -> None:
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 100_000
    tolerance = float(sys.argv[2]) if len(sys.argv) > 2 else 1e-3
    points = np.random.default_rng(16).random((n, 4, 2))
    on_workers = total(points, tolerance, max(1, n // 16), scheduler="processes", num_workers=2)
    alone = segments(points, tolerance)
    print(f"{n} cubics at tolerance {tolerance}: {on_workers} segments on 2 worker processes, {alone} in one")
    assert on_workers == alone


if __name__ == "__main__":
    main()
