"""The library's classes: generated from the registry, evaluation on arrays, the commands
as methods and functions, errors. Expected values are closed forms computed here."""

import math
import pickle
import threading

import numpy as np
import pytest

import casteljau
from casteljau import _casteljau

# Round-off of a few operations on numbers of size 1: the library's evaluation (de
# Casteljau, knot spans) against the closed forms written below.
EPS = 1e-14

PARABOLA = [[0.0, 0.0], [1.0, 2.0], [2.0, 0.0]]


def parabola(t):
    """The quadratic Bezier on PARABOLA in power form: (2t, 4t(1 - t))."""
    t = np.asarray(t, dtype=float)
    return np.stack([2 * t, 4 * t * (1 - t)], axis=-1)


def test_one_class_per_registry_type():
    names = {cls for _, cls, _ in _casteljau.curve_types()}
    assert {"Bezier", "RationalBezier", "BSpline", "Nurbs", "Polyline", "Path", "Lagrange", "CubicSpline",
            "Hermite", "CatmullRom"} <= names
    for json_name, cls_name, fields in _casteljau.curve_types():
        cls = getattr(casteljau, cls_name)
        assert issubclass(cls, casteljau.Curve)
        assert cls._type == json_name
        assert cls._fields == tuple(f for f in fields if f != "type")


def test_constructor_fields_are_what_the_reader_accepts():
    # The reader's own message for an unknown field lists the fields it accepts: the
    # classes' arguments must be exactly those (in the same order).
    for json_name, cls_name, _ in _casteljau.curve_types():
        with pytest.raises(casteljau.Error) as err:
            casteljau.Curve.from_json({"type": json_name, "zzz": 1})
        listed = str(err.value).split(" has: ")[1].rstrip(")").split(", ")
        assert tuple(listed) == ("type",) + getattr(casteljau, cls_name)._fields, cls_name


def test_commands_become_methods_and_functions():
    for name, _, fields in _casteljau.commands():
        if name == "eval":  # the call itself
            assert not hasattr(casteljau, "eval") and not hasattr(casteljau.Curve, "eval")
        elif fields and fields[0][0] == "curve":
            assert callable(getattr(casteljau.Curve, name)), name
        else:
            assert callable(getattr(casteljau, name)), name
    for name in ("intersect", "distance", "fit", "subdivide"):
        assert callable(getattr(casteljau, name))


def test_evaluate_shapes_and_values():
    c = casteljau.Bezier(PARABOLA)
    assert c.dim == 2 and c.domain == (0.0, 1.0)
    p = c(0.25)
    assert p.shape == (2,) and p.dtype == np.float64
    np.testing.assert_allclose(p, parabola(0.25), rtol=0, atol=EPS)
    t = np.linspace(-0.5, 1.5, 24).reshape(2, 3, 4)  # outside the domain too: the piece continues
    out = c(t)
    assert out.shape == (2, 3, 4, 2) and out.flags.c_contiguous and out.dtype == np.float64
    np.testing.assert_allclose(out, parabola(t), rtol=0, atol=4 * EPS)
    # A non-contiguous view and integer input are accepted.
    np.testing.assert_allclose(c(t[:, ::2, 1]), parabola(t[:, ::2, 1]), rtol=0, atol=4 * EPS)
    np.testing.assert_allclose(c([0, 1]), [[0, 0], [2, 0]], rtol=0, atol=0)


def test_derivatives():
    c = casteljau.Bezier(np.array(PARABOLA))
    t = np.linspace(0, 1, 7)
    # d/dt (2t, 4t - 4t^2) = (2, 4 - 8t); second derivative (0, -8).
    np.testing.assert_allclose(c(t, nu=1), np.stack([np.full_like(t, 2), 4 - 8 * t], -1), rtol=0, atol=8 * EPS)
    np.testing.assert_allclose(c(t, nu=2), np.tile([0.0, -8.0], (7, 1)), rtol=0, atol=16 * EPS)
    d = c.derivative()
    assert isinstance(d, casteljau.Path)
    np.testing.assert_allclose(d(t), c(t, nu=1), rtol=0, atol=8 * EPS)
    np.testing.assert_allclose(c.derivative(2)(t), c(t, nu=2), rtol=0, atol=16 * EPS)


def test_constructors_from_fields():
    b = casteljau.BSpline(degree=2, knots=[0, 0, 0, 1, 2, 2, 2], points=[[0], [1], [3], [4]])
    # Keyword and positional forms agree (positional: the registry's field order).
    assert casteljau.Nurbs(2, [0, 0, 0, 1, 1, 1], [[1, 0], [1, 1], [0, 1]], [1, math.sqrt(0.5), 1]) == casteljau.Nurbs(
        degree=2, knots=[0, 0, 0, 1, 1, 1], points=[[1, 0], [1, 1], [0, 1]], weights=[1, math.sqrt(0.5), 1])
    assert b.domain == (0.0, 2.0)
    np.testing.assert_array_equal(b.knots, [0, 0, 0, 1, 2, 2, 2])
    r = casteljau.RationalBezier([[1, 0], [1, 1], [0, 1]], [1, math.sqrt(0.5), 1])
    # The rational quadratic with middle weight cos(45 deg) is the quarter of the unit circle.
    u = np.linspace(0, 1, 11)
    np.testing.assert_allclose(np.linalg.norm(r(u), axis=1), 1, rtol=0, atol=4 * EPS)
    with pytest.raises(TypeError, match="unexpected keyword argument 'knotz'"):
        casteljau.BSpline(degree=1, knotz=[0, 1])


def test_json_round_trip_and_pickle():
    c = casteljau.Curve.from_json({"type": "circle", "center": [1, 2], "radius": 3})
    assert isinstance(c, casteljau.Nurbs)
    again = casteljau.Curve.from_json(c.to_json())
    assert again == c
    p = pickle.loads(pickle.dumps(c))
    assert p == c and type(p) is casteljau.Nurbs
    t = np.linspace(*c.domain, 9)
    np.testing.assert_allclose(np.linalg.norm(p(t) - [1, 2], axis=1), 3, rtol=0, atol=16 * EPS)
    with pytest.raises(casteljau.Error, match="type: Bezier.from_json needs a 'bezier' curve"):
        casteljau.Bezier.from_json(c.to_json())


def test_operations():
    c = casteljau.Bezier(PARABOLA)
    left, right = c.split(0.5)
    assert isinstance(left, casteljau.Bezier)
    np.testing.assert_allclose(left(1.0), parabola(0.5), rtol=0, atol=EPS)
    e = c.elevate(2)
    assert len(e.points) == 5
    t = np.linspace(0, 1, 9)
    np.testing.assert_allclose(e(t), c(t), rtol=0, atol=4 * EPS)
    b = casteljau.BSpline(degree=2, knots=[0, 0, 0, 1, 1, 1], points=PARABOLA)
    k = b.insert_knot(0.5)
    assert len(k.knots) == 7
    np.testing.assert_allclose(k(t), c(t), rtol=0, atol=4 * EPS)
    pieces = k.pieces()
    np.testing.assert_array_equal(pieces.breaks, [0, 0.5, 1])
    assert [type(s) for s in pieces.segments] == [casteljau.Bezier, casteljau.Bezier]
    assert isinstance(k.to_bezier(), casteljau.Path)


def test_queries_closed_forms():
    c = casteljau.Bezier(PARABOLA)
    box = c.bounds()
    np.testing.assert_allclose(box.min, [0, 0], atol=EPS)
    np.testing.assert_allclose(box.max, [2, 1], atol=EPS)  # apex at t = 1/2
    # Length of the parabola y = 2x - x^2 on [0, 2]: integral of sqrt(1 + (2 - 2x)^2),
    # closed form sqrt(5) + asinh(2) / 2.
    # 1e-12: the accuracy the length command guarantees (docs/cli.md).
    assert c.length() == pytest.approx(math.sqrt(5) + math.asinh(2) / 2, rel=1e-12)
    line = casteljau.Polyline([[0, 0], [3, 4]])
    np.testing.assert_allclose(line.param_at_length([0, 2.5, 5]), [0, 0.5, 1], atol=EPS)
    # Curvature of the parabola at its apex: |x'y'' - y'x''| / |v|^3 = 2 * 8 / 8 = 2 (turning right: -2).
    assert c.curvature(0.5) == pytest.approx(-2, rel=1e-13)  # a few roundings on exact inputs
    assert c.curvature(np.array([[0.5]])).shape == (1, 1)
    f = c.features()
    np.testing.assert_allclose(f.extrema[1], [0.5], atol=EPS)
    circle = casteljau.Curve.from_json({"type": "circle", "center": [0, 0], "radius": 2})
    # Exact up to rounding for the circle's rational pieces integrated by quadrature (docs/cli.md).
    assert circle.area() == pytest.approx(4 * math.pi, rel=1e-12)
    poly = circle.flatten(1e-3)
    assert poly.shape[1] == 2 and len(poly) > 10
    # Every vertex lies on the circle (evaluated points: rounding only, 1e-12 of the radius
    # is generous) and every chord's midpoint, its farthest point from an arc of the circle
    # of radius 2, within the tolerance (1e-9 relative slack: the rounding of the vertices).
    np.testing.assert_allclose(np.linalg.norm(poly, axis=1), 2, atol=1e-12)
    mid = (poly[1:] + poly[:-1]) / 2
    assert np.all(2 - np.linalg.norm(mid, axis=1) <= 1e-3 * (1 + 1e-9))
    assert len(circle.flatten(1e-3, method="uniform")) >= 3


def test_project_vectorised():
    seg = casteljau.Polyline([[0, 0], [4, 0]])
    pts = np.array([[1, 1], [3, -2], [5, 1], [-1, 0]], dtype=float)
    r = seg.project(pts)
    # Nearest point on the segment [0, 4] x {0}: x clamped to [0, 4].
    np.testing.assert_allclose(r.point, [[1, 0], [3, 0], [4, 0], [0, 0]], atol=EPS)
    np.testing.assert_allclose(r.distance, [1, 2, math.sqrt(2), 1], atol=EPS)
    np.testing.assert_allclose(r.t, [0.25, 0.75, 1, 0], atol=EPS)
    # The unit circle's centre ties along the whole circle (the response then has all_t or
    # intervals): every row still gives t, point, distance; distance 1 from the centre, 1
    # from (2, 0) at the point (1, 0).
    circle = casteljau.Curve.from_json({"type": "circle", "center": [0, 0], "radius": 1})
    rc = circle.project(np.array([[0.0, 0.0], [2.0, 0.0]]))
    np.testing.assert_allclose(rc.distance, [1, 1], atol=EPS)
    np.testing.assert_allclose(rc.point[1], [1, 0], atol=EPS)
    empty = seg.project(np.zeros((0, 2)))
    assert empty.t.shape == (0,) and empty.point.shape == (0, 2)
    one = seg.project([1, 1])
    assert one.distance == pytest.approx(1)
    with pytest.raises(casteljau.Error, match=r"^points\[1\]\[0\]: must be a finite number"):
        seg.project(np.array([[1, 1], [np.nan, 0]]))


def test_module_functions():
    a = casteljau.Polyline([[0, 0], [2, 2]])
    b = casteljau.Polyline([[0, 2], [2, 0]])
    r = casteljau.intersect(a, b)
    assert len(r.intersections) == 1
    np.testing.assert_allclose(r.intersections[0].point, [1, 1], atol=EPS)
    d = casteljau.distance(casteljau.Polyline([[0, 0], [1, 0]]), casteljau.Polyline([[0, 3], [1, 3]]))
    assert d.distance == pytest.approx(3)
    pts = np.array([[0, 0], [1, 1], [2, 0], [3, 1]], dtype=float)
    fitted = casteljau.fit(pts, degree=3, control_points=4).curve
    assert isinstance(fitted, casteljau.BSpline)
    # Interpolation: the fitted curve passes through every point (at some parameter); 1e-9:
    # the solve of a 4 x 4 system and the projection, far below the points' spacing of 1.
    assert np.all(fitted.project(pts).distance < 1e-9)
    # Chaikin on the square (docs/cli.md's example): each edge gives its 1/4 and 3/4 points.
    s = casteljau.subdivide(points=[[0, 0], [4, 0], [4, 4], [0, 4]], scheme="chaikin", iterations=1, closed=True)
    np.testing.assert_allclose(s.points[:2], [[1, 0], [3, 0]])
    assert isinstance(s.limit, casteljau.BSpline)


def test_errors_carry_the_command_line_message():
    assert issubclass(casteljau.Error, ValueError)
    with pytest.raises(casteljau.Error, match=r"^points\[1\]\[1\]: must be a finite number, got nan$"):
        casteljau.Bezier([[0, 0], [1, np.nan]])
    with pytest.raises(casteljau.Error, match=r"^points\[1\]\[1\]: must be a finite number"):
        casteljau.Bezier([[0, 0], [1, float("inf")]])
    c = casteljau.Bezier(PARABOLA)
    with pytest.raises(casteljau.Error, match=r"^t\[4\]: "):
        c(np.array([[0, 0.1], [0.2, 0.3], [np.nan, 0.5]]))
    with pytest.raises(casteljau.Error, match=r"^tolerance: "):
        c.flatten(-1.0)
    with pytest.raises(casteljau.Error, match=r"^weights"):
        casteljau.RationalBezier([[0, 0], [1, 1]], [1, -1])
    with pytest.raises(casteljau.Error, match=r"^command: unknown command 'nope'"):
        _casteljau.run("nope", "{}")
    with pytest.raises(casteljau.Error, match=r"^curve\.type: split needs"):
        casteljau.Polyline([[0, 0], [1, 1]]).split(0.5)
    with pytest.raises(casteljau.Error):
        c.derivative(-1)


def _overlapping_calls(calls, tries=8):
    """Runs each call in its own thread and returns (their results, whether every call was
    still running when the main thread next ran Python). With a switch interval of an
    hour no thread gives up the GIL on a timer: the main thread, blocked until the last
    thread has started its call, gets the GIL back only when a thread releases it. The
    threads' only release point between their start and their `done` flag is the GIL
    release inside the compiled call, so when the main thread runs, each thread has started
    its call, has released the GIL in it, and has not finished it (its flag is still down):
    the calls overlap in time. Without the release the main thread would run only after
    the threads' flags were up, so an overlap is never seen then. With it, a thread whose
    call ends before the main thread is scheduled again (a loaded machine) can hide it:
    the experiment is repeated (up to `tries` times) until seen. No clock is read."""
    import sys

    results = [None] * len(calls)
    started, done = [], []

    def work(i):
        started[i].set()
        results[i] = calls[i]()
        done[i] = True

    old = sys.getswitchinterval()
    for _ in range(tries):
        started = [threading.Event() for _ in calls]
        done = [False] * len(calls)
        sys.setswitchinterval(3600.0)
        try:
            threads = [threading.Thread(target=work, args=(i,)) for i in range(len(calls))]
            for th in threads:
                th.start()
            for e in started:
                e.wait()
            overlapped = not any(done)  # the main thread's first Python after the last start
        finally:
            sys.setswitchinterval(old)
        for th in threads:
            th.join()
        if overlapped:
            break
    return results, overlapped


def test_two_threads_evaluate_at_once():
    c = casteljau.BSpline(degree=3, knots=np.r_[[0] * 3, np.linspace(0, 1, 50), [1] * 3],
                          points=np.random.default_rng(1).random((52, 3)))
    t = np.random.default_rng(2).random(200_000)
    expected = c(t)
    results, overlapped = _overlapping_calls([lambda: c(t), lambda: c(t)])
    assert overlapped  # both evaluations were in the library at once (the GIL released)
    for r in results:
        np.testing.assert_array_equal(r, expected)
    # Derivatives of two orders at once, on a fresh curve: each thread builds its order's
    # table (with the GIL) while the other may be evaluating.
    n = casteljau.Nurbs(degree=3, knots=c.knots, points=c.points, weights=np.linspace(1, 2, 52))
    want = [casteljau.Curve.from_json(n.to_json())(t, nu=k) for k in (1, 2)]
    got, overlapped = _overlapping_calls([lambda: n(t, nu=1), lambda: n(t, nu=2)])
    assert overlapped
    for g, w in zip(got, want):
        np.testing.assert_array_equal(g, w)
    # Projections of many points release it too.
    pts = np.random.default_rng(3).random((400, 3))
    (p1, p2), overlapped = _overlapping_calls([lambda: c.project(pts), lambda: c.project(pts[::-1])])
    assert overlapped
    np.testing.assert_array_equal(p1.t, p2.t[::-1])


def test_the_overlap_check_sees_a_call_that_holds_the_gil():
    # The check itself: a call that never releases the GIL (pure Python) is seen finished.
    _, overlapped = _overlapping_calls([lambda: sum(range(100_000)), lambda: sum(range(100_000))])
    assert not overlapped


def test_derivative_of_rational_curves():
    # The quarter circle with weights 1, 1, 2 is ((1 - t^2), 2t) / (1 + t^2) (closed forms
    # of its derivatives below); derivative(k) is a curve (a path of rational pieces).
    q = casteljau.RationalBezier([[1, 0], [1, 1], [0, 1]], [1, 1, 2])
    t = np.linspace(-0.5, 1.5, 41)  # outside the domain too
    s = 1 + t * t
    d1 = np.stack([-4 * t / s**2, 2 * (1 - t * t) / s**2], axis=-1)
    d2 = np.stack([(12 * t * t - 4) / s**3, 4 * t * (t * t - 3) / s**3], axis=-1)
    r1, r2 = q.derivative(), q.derivative(2)
    assert isinstance(r1, casteljau.Curve) and r1.domain == q.domain
    np.testing.assert_allclose(r1(t), d1, rtol=0, atol=1e-14)
    np.testing.assert_allclose(r2(t), d2, rtol=0, atol=5e-14)
    # A NURBS of several spans (the registry's circle): C . C' = 0 and C . C'' + |C'|^2 = 0
    # about its centre, and the derivative curves agree with c(t, nu=k).
    circle = casteljau.Curve.from_json({"type": "circle", "center": [0, 0], "radius": 2})
    lo, hi = circle.domain
    u = np.linspace(lo, hi, 57)
    C, D1, D2 = circle(u), circle.derivative()(u), circle.derivative(2)(u)
    scale = np.max(np.abs(D1)) ** 2
    np.testing.assert_allclose(np.sum(C * D1, axis=-1), 0, atol=1e-13 * scale)
    np.testing.assert_allclose(np.sum(C * D2, axis=-1) + np.sum(D1 * D1, axis=-1), 0, atol=1e-13 * scale)
    np.testing.assert_allclose(D1, circle(u, nu=1), rtol=0, atol=1e-13 * np.max(np.abs(D1)))
    np.testing.assert_allclose(D2, circle(u, nu=2), rtol=0, atol=1e-12 * np.max(np.abs(D2)))
    # The weights' scale does not matter (extreme weights stay in range).
    big = casteljau.RationalBezier([[1, 0], [1, 1], [0, 1]], [1e150, 1e150, 2e150])
    np.testing.assert_allclose(big.derivative()(t), d1, rtol=0, atol=1e-14)


def test_batch_evaluation_matches_point_by_point():
    # The batch path (the library's SpanTable, Hermite and NURBS members) against the same
    # curve evaluated one parameter at a time and against closed forms; sorted and
    # shuffled parameters give the same bits.
    rng = np.random.default_rng(9)
    t = np.r_[rng.random(997) * 1.4 - 0.2, 0.0, 0.5, 1.0]  # outside the domain too, and at breaks
    b = casteljau.BSpline(degree=2, knots=[0, 0, 0, 0.5, 1, 1, 1], points=[[0, 0], [0.5, 1], [1.5, 1], [2, 0]])
    c = casteljau.Bezier(PARABOLA)
    s = casteljau.CubicSpline(params=np.linspace(0, 1, 40), points=rng.random((40, 3)), boundary="natural")
    n = casteljau.Curve.from_json({"type": "circle", "center": [0, 0], "radius": 1})
    for curve in (b, c, s, n):
        u = np.linspace(*curve.domain, 1000) if curve is n else t
        many = curve(u)
        one = np.array([curve(x) for x in u[:50]])
        np.testing.assert_array_equal(many[:50], one)
        order = np.argsort(u)
        np.testing.assert_array_equal(curve(u[order]), many[order])
    # The parabola in power form (a few roundings of numbers of size 1).
    np.testing.assert_allclose(c(t), parabola(t), rtol=0, atol=8 * EPS)
    # The circle's points at distance 1 from its centre.
    np.testing.assert_allclose(np.linalg.norm(n(np.linspace(*n.domain, 1000)), axis=1), 1, rtol=0, atol=4 * EPS)
    big = np.full(500, 0.5)
    big[321] = np.inf
    with pytest.raises(casteljau.Error, match=r"^t\[321\]: "):
        s(big)


def test_project_rows_are_the_single_point_project():
    # Rows, one point (both on the curve's kept pieces) and the project command (the curve
    # read from its JSON, its pieces made anew) give the same bits.
    rng = np.random.default_rng(11)
    c = casteljau.Bezier([[0, 0], [1, 2], [3, -1], [4, 1]])
    pts = rng.random((40, 2)) * 4
    r = c.project(pts)
    for i in (0, 17, 39):
        one = c.project(pts[i])
        cmd = casteljau.run("project", curve=c, point=pts[i])
        assert r.t[i] == one.t == cmd.t and r.distance[i] == one.distance == cmd.distance
        np.testing.assert_array_equal(r.point[i], one.point)
        np.testing.assert_array_equal(one.point, cmd.point)
    # Ties: the one-point answer keeps the command's all_t and intervals.
    circle = casteljau.Curve.from_json({"type": "circle", "center": [0, 0], "radius": 1})
    for q in ([0.0, 0.0], [0.0, 0.5]):
        assert repr(circle.project(q)) == repr(casteljau.run("project", curve=circle, point=q))
    bump = casteljau.Bezier([[0, 0], [1, 2], [2, 0]])
    assert repr(bump.project([1.0, -5.0])) == repr(casteljau.run("project", curve=bump, point=[1.0, -5.0]))
    with pytest.raises(casteljau.Error, match=r"^point: needs 2 coordinates"):
        c.project([1.0, 2.0, 3.0])
    with pytest.raises(casteljau.Error, match=r"^point\[1\]: must be a finite number"):
        c.project([1.0, np.nan])
    with pytest.raises(casteljau.Error, match=r"^points: must be an array of shape \(n, 2\)"):
        c.project(np.zeros((3, 3)))


def test_requests_and_responses_are_python_data():
    import json

    c = casteljau.Bezier(np.array(PARABOLA))
    assert json.loads(json.dumps(c.to_json())) == c.to_json()  # lists and numbers, JSON-ready
    poly = c.flatten(0.01)
    assert isinstance(poly, np.ndarray) and poly.dtype == np.float64 and poly.shape[1] == 2
    with pytest.raises(TypeError, match=r"^points: a set is not JSON data"):
        casteljau.Bezier({1, 2})
    with pytest.raises(casteljau.Error, match=r"^points\[2\]\[0\]: must be a finite number, got -inf"):
        casteljau.Polyline(np.array([[0, 0], [1, 1], [-np.inf, 2]]))


def _every_type():
    """A curve of every registry type (2-D; a 3-D NURBS and a path mixing a rational piece)."""
    rng = np.random.default_rng(9)
    P = rng.random((6, 2))
    return [
        casteljau.Bezier(P[:4]),
        casteljau.RationalBezier(P[:4], [1.0, 2.5, 0.5, 1.5]),
        casteljau.BSpline(degree=3, knots=[0, 0, 0, 0, 0.3, 0.7, 1, 1, 1, 1], points=P),
        casteljau.Nurbs(degree=2, knots=[0, 0, 0, 0.25, 0.5, 0.75, 1, 1, 1], points=rng.random((6, 3)),
                        weights=[1, 0.5, 2, 1, 3, 1]),
        casteljau.Polyline(P),
        casteljau.Curve.from_json({"type": "path", "segments": [
            {"type": "bezier", "points": P[:3].tolist()},
            {"type": "rational_bezier", "points": P[2:5].tolist(), "weights": [1, 0.3, 2]}]}),
        casteljau.Lagrange(params=np.linspace(0, 1, 6), points=P),
        casteljau.CubicSpline(params=np.linspace(0, 2, 6), points=P),
        casteljau.Curve.from_json({"type": "hermite", "params": [0, 1, 2], "points": P[:3].tolist(),
                                   "tangent_rule": "monotone"}),
        casteljau.Curve.from_json({"type": "catmull_rom", "points": P.tolist()}),
    ]


def test_derivative_tables_against_the_librarys_derivatives():
    """c(t, nu=k) (the pieces' hodographs, de Casteljau, the quotient rule for rational
    pieces) against the eval command's derivatives (io::derivatives: each type's own
    derivative_at), inside the domain, at the breaks and outside it."""
    for c in _every_type():
        lo, hi = c.domain
        t = np.r_[np.linspace(lo - 0.3 * (hi - lo), hi + 0.3 * (hi - lo), 41), lo, hi, (lo + hi) / 2]
        ref = casteljau.run("eval", curve=c, t=t, derivatives=3)
        np.testing.assert_allclose(c(t), ref.points, rtol=1e-12, atol=1e-12 * np.abs(ref.points).max(), err_msg=c._c.type)
        for k in (1, 2, 3):
            want = np.asarray(ref.derivatives[k - 1])
            got = c(t, nu=k)
            assert got.shape == want.shape
            np.testing.assert_allclose(got, want, rtol=1e-10, atol=1e-10 * np.abs(want).max(),
                                       err_msg=f"{c._c.type} nu={k}")
        # One parameter or many: the same table (a point does not depend on its batch).
        np.testing.assert_array_equal(c(t[5], nu=2), c(t, nu=2)[5])


def test_second_derivative_at_extreme_weights():
    # The conic (1, 0), (1, 1), (0, 1) with weights [1, w, 1] at t = 1/2, against the
    # quotient rule in exact rational arithmetic (the plain quotient rule in double gave 0
    # from w = 1e16 on): the array path answers as the library's extreme-weight forms do.
    from fractions import Fraction as F

    def exact(w):
        t = F(1, 2)
        B = [(1 - t) ** 2, 2 * t * (1 - t), t * t]
        B1 = [-2 * (1 - t), 2 - 4 * t, 2 * t]
        B2 = [F(2), F(-4), F(2)]
        W = [F(1), F(w), F(1)]
        out = []
        for P in ([1, 1, 0], [0, 1, 1]):
            a, a1, a2 = (sum(b[i] * W[i] * P[i] for i in range(3)) for b in (B, B1, B2))
            d, d1, d2 = (sum(b[i] * W[i] for i in range(3)) for b in (B, B1, B2))
            # R = a / d: R'' = (a2 - 2 d1 R' - d2 R) / d, R' = (a1 - d1 R) / d
            r = a / d
            r1 = (a1 - d1 * r) / d
            out.append(float((a2 - 2 * d1 * r1 - d2 * r) / d))
        return out

    for w in (10**8, 10**16, 10**30, 10**100):
        c = casteljau.RationalBezier([[1, 0], [1, 1], [0, 1]], [1, float(w), 1])
        np.testing.assert_allclose(c(np.array([0.5]), nu=2)[0], exact(w), rtol=1e-14)


def test_rational_derivatives_on_the_circle():
    """The quarter circle (weights 1, cos 45 deg, 1): |C| = 1, C . C' = 0 and, differentiated
    once more, C . C'' + |C'|^2 = 0; beyond orders of the degree the table still answers."""
    c = casteljau.Nurbs(degree=2, knots=[0, 0, 0, 1, 1, 1], points=[[1, 0], [1, 1], [0, 1]], weights=[1, math.sqrt(0.5), 1])
    t = np.linspace(0, 1, 33)
    p, d1, d2 = c(t), c(t, nu=1), c(t, nu=2)
    np.testing.assert_allclose(np.linalg.norm(p, axis=1), 1, rtol=0, atol=4 * EPS)
    np.testing.assert_allclose(np.sum(p * d1, axis=1), 0, rtol=0, atol=8 * EPS)
    np.testing.assert_allclose(np.sum(p * d2, axis=1) + np.sum(d1 * d1, axis=1), 0, rtol=0, atol=32 * EPS)
    with pytest.raises(casteljau.Error, match=r"^t\[2\]: value must be finite, got nan"):
        c(np.array([0.1, 0.2, np.nan]), nu=1)
    with pytest.raises(casteljau.Error, match=r"^nu: must be >= 0"):
        c(0.5, nu=-1)
    # Orders above the tables' (16) go point by point through the library.
    np.testing.assert_allclose(c(t[:3], nu=17), casteljau.run("eval", curve=c, t=t[:3], derivatives=17).derivatives[16],
                               rtol=1e-9)


def test_project_on_a_curve_of_many_pieces_is_global():
    # The projection prunes pieces by their control boxes (algo/project.hpp): on a curve of
    # 1000 wiggling pieces every answer is still the global extremum, checked against a
    # dense sampling (no sample nearer than the nearest point, none farther than the
    # farthest) and the answer's point on the curve at its parameter.
    rng = np.random.default_rng(13)
    n = 1000
    c = casteljau.BSpline(degree=3, knots=np.r_[[0] * 3, np.linspace(0, 1, n + 1), [1] * 3], points=rng.random((n + 3, 2)))
    q = np.r_[rng.random((12, 2)), [[0.5, 0.5], [3.0, -2.0]]]
    samples = c(np.linspace(0, 1, 200_001))
    dist = np.sqrt(((q[:, None, :] - samples[None, :, :]) ** 2).sum(axis=-1))
    for farthest in (False, True):
        r = c.project(q, farthest=farthest)
        np.testing.assert_allclose(r.point, c(r.t), rtol=0, atol=1e-14)
        np.testing.assert_allclose(r.distance, np.linalg.norm(r.point - q, axis=1), rtol=1e-13, atol=1e-15)
        if farthest:
            assert np.all(r.distance >= dist.max(axis=1) - 1e-14)
        else:
            assert np.all(r.distance <= dist.min(axis=1) + 1e-14)
            assert np.all(r.distance >= dist.min(axis=1) - 1e-3)  # the sampling's own resolution
        for i in (0, 12):
            one = c.project(q[i], farthest=farthest)  # the one-point path (the project command)
            assert one.t == r.t[i] and one.distance == r.distance[i]
