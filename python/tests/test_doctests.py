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
        # A surface method named as a curve command (split, elevate, bounds, ...) does not
        # carry the curve's example.
        from casteljau._curves import _EXAMPLES

        assert not any(t.name.startswith("casteljau.Surface.") and t.name.split(".")[-1] in _EXAMPLES
                       and _EXAMPLES[t.name.split(".")[-1]].strip() in t.docstring for t in tests)


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


def test_stub_result_fields_match_answers():
    """The stub's result classes (casteljau._stubs._RESULT_CLASSES: a Result at run time)
    name fields every answer has, of the declared kinds, and _RETURNS' plain annotations
    (float, an array, a curve class) are what the commands answer."""
    import numpy as np

    from casteljau import _stubs

    C = casteljau
    cubic = C.Bezier([[0, 0], [0, 2], [2, 2], [2, 0]])
    bs = C.BSpline(degree=2, knots=[0, 0, 0, 1, 2, 2, 2], points=[[0, 0], [2, 0], [2, 2], [0, 2]])
    patch = C.BezierSurface([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]])
    answers = {
        "_Bounds": cubic.bounds(),
        "_Pieces": bs.pieces(),
        "_Projection": cubic.project([1, 3]),
        "_Features": cubic.features(),
        "_Intersection": C.intersect(C.Bezier([[0, 0], [2, 2]]), C.Bezier([[0, 2], [2, 0]])).intersections[0],
        "_Intersections": C.intersect(C.Bezier([[0, 0], [2, 2]]), C.Bezier([[0, 2], [2, 0]])),
        "_Distance": C.distance(C.Bezier([[0, 0], [2, 0]]), C.Bezier([[3, 1], [4, 2]])),
        "_Fit": C.fit([[0, 0], [1, 1], [2, 0]], degree=2, control_points=3),
        "_Subdivision": C.subdivide([[0, 0], [4, 0], [4, 4]], scheme="chaikin", iterations=1),
        "_RemovedKnot": bs.insert_knot(0.5).remove_knot(0.5, 1, 1e-9),
        "_Solution": cubic.solve(1.0, 0),
        "_Reduction": cubic.elevate(1).reduce(1, 1e-9),
        "_Frames": C.Bezier([[0, 0, 0], [1, 1, 0], [2, 0, 1]]).frames([0, 0.5]),
        "_SvgPath": cubic.to_svg_path(),
        "_Patches": patch.to_bezier(),
        "_SurfaceProjection": patch.project([0.5, 0.5, 1]),
        "_CurveSurfaceIntersections": patch.intersect(C.Bezier([[0.5, 0.5, -1], [0.5, 0.5, 2]])),
        "_Mesh": patch.tessellate(0.1),
    }
    kinds = {"float": (float,), "int": (int,), "str": (str,), "bool": (bool,), _stubs._F64: (np.ndarray,),
             f"float | {_stubs._F64}": (float, np.ndarray), f"list[{_stubs._F64}]": (list,),
             "Sequence[_Intersection]": (list, np.ndarray), "BSpline": (C.BSpline,), "Curve": (C.Curve,),
             "list[Bezier | RationalBezier]": (list,), "list[list[Surface]]": (list,), "list[Result]": (list,)}
    assert {name for name, _ in _stubs._RESULT_CLASSES} == set(answers)
    for name, fields in _stubs._RESULT_CLASSES:
        r = answers[name]
        assert isinstance(r, C.Result), name
        for field, ftype in fields:
            assert isinstance(getattr(r, field), kinds[ftype]), (name, field, ftype)
            if ftype == _stubs._F64:
                assert getattr(r, field).dtype == np.float64, (name, field)
    plain = {"length": cubic.length(), "area": C.Polyline([[0, 0], [1, 0], [1, 1], [0, 0]]).area(),
             "flatten": cubic.flatten(0.1), "param_at_length": cubic.param_at_length([0.5]),
             "to_bezier": cubic.to_bezier(), "to_quadratic": cubic.to_quadratic(0.01),
             "elevate": cubic.elevate(1), "insert_knot": bs.insert_knot(0.5), "refine": bs.refine([0.5]),
             "to_bspline": cubic.to_bspline()}
    for command, value in plain.items():
        annotation = _stubs._RETURNS[command]
        expected = {"float": float, _stubs._F64: np.ndarray, "Path": C.Path, "Curve": C.Curve,
                    "BSpline | Nurbs": (C.BSpline, C.Nurbs)}[annotation]
        assert isinstance(value, expected), (command, annotation, type(value))
    a, b = cubic.split(0.5)
    assert type(a) is type(b) is C.Bezier  # tuple[_C, _C]
    surface = {"area": (patch.area(), float), "isocurve": (patch.isocurve("u", 0.5), C.Curve),
               "elevate": (patch.elevate("u", 1), C.Surface), "split": (patch.split("u", 0.5), list),
               "tessellate": (patch.tessellate(0.1, format="obj"), str), "eval": (patch.eval([[0.5, 0.5]]), np.ndarray)}
    for command, (value, kind) in surface.items():
        assert command in _stubs._SURFACE_RETURNS and isinstance(value, kind), (command, type(value))
