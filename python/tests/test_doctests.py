"""The examples in the package's docstrings run as written."""

import doctest

import pytest

import casteljau

import casteljau


@pytest.mark.parametrize("module", ["casteljau", "casteljau.dask"])
def test_docstring_examples(module):
    if module == "casteljau.dask":
        pytest.importorskip("dask.array")
    mod = __import__(module, fromlist=["_"])
    failures, tried = doctest.testmod(mod, optionflags=doctest.NORMALIZE_WHITESPACE)
    assert tried > 0 and failures == 0


def test_type_stubs_are_current():
    import ast
    import pathlib

    from casteljau import _casteljau, _stubs

    stub = pathlib.Path(casteljau.__file__).with_name("__init__.pyi")
    text = stub.read_text()
    assert text == _stubs.stub_text()  # written by the build from this registry
    compile(text, str(stub), "exec")  # valid Python (once: "duplicate argument 'curves'")
    names = {n.name for n in ast.parse(text).body if isinstance(n, (ast.ClassDef, ast.FunctionDef))}
    assert {cls for _, cls, _ in _casteljau.curve_types()} <= names
    assert {"intersect", "distance", "fit", "subdivide", "make_interp_spline"} <= names
