"""Evaluating and projecting over Dask arrays (docs/python.md, "Scale-out on Dask").

Each block is handed to the compiled library in one call (``map_blocks``); the curve
travels to the workers pickled by its JSON form. The same code runs on a laptop
(threads: the library releases the GIL), with ``dask.config.set(scheduler="processes")``
or on a cluster (``distributed.Client(address)``): nothing here depends on the scheduler.

>>> import dask.array as da, numpy as np, casteljau, casteljau.dask
>>> c = casteljau.Bezier([[0, 0], [1, 2], [2, 0]])
>>> t = da.linspace(0, 1, 5, chunks=2)
>>> casteljau.dask.evaluate(c, t).compute(scheduler="synchronous")[2]
array([1., 1.])
"""

from __future__ import annotations

from typing import Any

import dask.array as da
import numpy as np

from ._curves import Curve, Result

__all__ = ["evaluate", "project"]


def evaluate(curve: Curve, t: Any, nu: int = 0) -> da.Array:
    """curve(t, nu) over a Dask array of parameters (any shape and chunks): a Dask array
    of shape t.shape + (d,), chunked as t along its axes and whole along the last."""
    t = da.asarray(t).astype(np.float64)
    d = curve.dim
    return t.map_blocks(lambda block: curve(block, nu=nu), dtype=np.float64, new_axis=t.ndim,
                        chunks=t.chunks + ((d,),), meta=np.empty((0,) * (t.ndim + 1), dtype=np.float64))


def project(curve: Curve, points: Any, farthest: bool = False) -> Result:
    """curve.project(points) over a Dask array of points (n, d), chunked along its rows:
    Result(t (n,), point (n, d), distance (n,)) of Dask arrays (one pass over the blocks:
    the three are slices of one array)."""
    points = da.asarray(points).astype(np.float64)
    d = curve.dim
    if points.ndim != 2 or points.shape[1] != d:
        raise ValueError(f"points: must be an array of shape (n, {d}), got {points.shape}")
    points = points.rechunk({1: d})

    def block(p: np.ndarray) -> np.ndarray:
        r = curve.project(p, farthest=farthest)
        return np.column_stack([r.t, r.distance, r.point])

    packed = points.map_blocks(block, dtype=np.float64, chunks=(points.chunks[0], (d + 2,)),
                               meta=np.empty((0, 0), dtype=np.float64))
    return Result(t=packed[:, 0], distance=packed[:, 1], point=packed[:, 2:])
