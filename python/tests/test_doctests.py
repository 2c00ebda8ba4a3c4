"""The examples in the package's docstrings run as written."""

import doctest

import pytest

import casteljau


def _examples(module):
    """Every docstring example reachable from the module's public names: doctest.testmod
    collects only objects whose __module__ is the module itself, which left out the
    classes and functions defined in casteljau._scipy and _surfaces (make_interp_spline,
    Surface, ...). module=False turns that filter off; each docstring is run once."""
    finder = doctest.DocTestFinder(exclude_empty=True)
    tests, seen = [], set()
    names = getattr(module, "__all__", None) or [n for n in vars(module) if not n.startswith("_")]
    for name, obj in [(module.__name__, module)] + [(f"{module.__name__}.{n}", getattr(module, n)) for n in names]:
        if not (isinstance(obj, type) or callable(obj) or obj is module):
            continue
        found = finder.find(obj, name, module=False, globs={}) if obj is not module else finder.find(obj, name)
        for t in found:
            if t.examples and (t.filename, t.lineno, t.docstring) not in seen:
                seen.add((t.filename, t.lineno, t.docstring))
                tests.append(t)
    return tests


@pytest.mark.parametrize("module", ["casteljau", "casteljau.dask"])
def test_docstring_examples(module):
    if module == "casteljau.dask":
        pytest.importorskip("dask.array")
    mod = __import__(module, fromlist=["_"])
    tests = _examples(mod)
    runner = doctest.DocTestRunner(optionflags=doctest.NORMALIZE_WHITESPACE)
    for t in tests:
        runner.run(t)
    results = runner.summarize(verbose=False)
    assert results.attempted > 0 and results.failed == 0
    if module == "casteljau":
        # The examples the old collection missed run now.
        names = {t.name.split(".")[-1] for t in tests}
        assert {"make_interp_spline", "Surface", "BSpline", "CubicSpline", "BarycentricInterpolator"} <= names, names
        # Every method and module function the issue names has an example (the generated
        # ones from _curves._EXAMPLES, keyed by command).
        issue = {"__call__", "derivative", "pieces", "split", "elevate", "insert_knot", "to_bezier", "bounds",
                 "length", "param_at_length", "project", "features", "curvature", "flatten", "area", "intersect",
                 "distance", "fit", "subdivide"}
        assert issue <= names, issue - names
        assert {n for n in issue if callable(getattr(casteljau.Curve, n, None))} <= {
            t.name.split(".")[-1] for t in tests if t.name.startswith("casteljau.Curve.")}


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
