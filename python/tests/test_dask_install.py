"""The Dask helpers (synchronous scheduler: the same graph any scheduler runs) and the
package installed by `cmake --install` into a temporary prefix."""

import os
import pathlib
import subprocess
import sys

import numpy as np
import pytest

import casteljau


def test_dask_evaluate_and_project():
    da = pytest.importorskip("dask.array")
    import casteljau.dask as cd

    c = casteljau.BSpline(degree=3, knots=np.r_[[0] * 3, np.linspace(0, 1, 8), [1] * 3],
                          points=np.random.default_rng(3).random((10, 2)))
    t = np.random.default_rng(4).random((300, 4))
    lazy = cd.evaluate(c, da.from_array(t, chunks=(70, 3)))
    assert lazy.shape == (300, 4, 2)
    # Equal to the single-process call (the same code per block).
    np.testing.assert_array_equal(lazy.compute(scheduler="synchronous"), c(t))
    pts = np.random.default_rng(5).random((50, 2))
    r = cd.project(c, da.from_array(pts, chunks=(16, 2)))
    whole = c.project(pts)
    np.testing.assert_array_equal(r.t.compute(scheduler="synchronous"), whole.t)
    np.testing.assert_array_equal(r.point.compute(scheduler="synchronous"), whole.point)
    np.testing.assert_array_equal(r.distance.compute(scheduler="synchronous"), whole.distance)


def test_installed_package(tmp_path):
    build = os.environ.get("CASTELJAU_BUILD_DIR")
    if not build:
        pytest.skip("CASTELJAU_BUILD_DIR not set (ctest sets it)")
    cmake = os.environ.get("CASTELJAU_CMAKE", "cmake")
    subprocess.run([cmake, "--install", build, "--component", "python", "--prefix", str(tmp_path)], check=True,
                   capture_output=True)
    site = next(tmp_path.glob("lib/python3/dist-packages"))
    assert (site / "casteljau" / "__init__.py").exists()
    code = ("import casteljau, numpy as np; c = casteljau.Bezier([[0, 0], [1, 2], [2, 0]]); "
            "print(casteljau.__file__); print(c(np.array([0.5])).tolist())")
    env = dict(os.environ, PYTHONPATH=str(site))
    out = subprocess.run([sys.executable, "-c", code], check=True, capture_output=True, text=True, env=env,
                         cwd=tmp_path).stdout.split("\n")
    assert pathlib.Path(out[0]).is_relative_to(tmp_path)
    assert out[1] == "[[1.0, 1.0]]"


def test_dask_local_cluster_example():
    """examples/python/dask_cluster.py on a distributed.LocalCluster of 2 worker processes
    (the curves and data travel pickled): its segment counts and fits equal the
    single-process run's (the example asserts it, exactly). 400 cubics and 40
    trajectories: about 3 s of wall time, most of it the cluster's start."""
    pytest.importorskip("distributed")
    example = pathlib.Path(__file__).parents[2] / "examples" / "python" / "dask_cluster.py"
    out = subprocess.run([sys.executable, str(example), "--cubics", "400", "--trajectories", "40", "--blocks", "4"],
                         check=True, capture_output=True, text=True, env=dict(os.environ), timeout=100).stdout
    assert "400 cubics" in out and "on 2 workers" in out and "equal to the single-process run" in out
