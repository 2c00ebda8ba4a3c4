"""The surface classes: generated from the registry, evaluation on arrays (scattered and
grids), JSON and pickling, the commands as methods, the constructions. Expected values are
closed forms computed here."""

import math
import pickle

import numpy as np
import pytest

import casteljau
from casteljau import _casteljau

# Round-off of a few operations on numbers of size 1.
EPS = 1e-14

# The bilinear patch S(u, v) = (u, v, u v) (corners (0,0,0), (0,1,0), (1,0,0), (1,1,1)).
SADDLE = [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]]


def saddle(u, v):
    u, v = np.broadcast_arrays(np.asarray(u, float), np.asarray(v, float))
    return np.stack([u, v, u * v], axis=-1)


def test_one_class_per_registry_type():
    names = {name for name, _ in _casteljau.surface_types()}
    assert names == {"bezier_surface", "rational_bezier_surface", "bspline_surface", "nurbs_surface"}
    for json_name, fields in _casteljau.surface_types():
        cls = next(c for c in casteljau.surface_classes.values() if c._type == json_name)
        assert issubclass(cls, casteljau.Surface)
        assert cls._fields == tuple(f for f in fields if f != "type")
    assert {"BezierSurface", "RationalBezierSurface", "BSplineSurface", "NurbsSurface"} == set(casteljau.surface_classes)
    # The reader refuses a field outside the listed ones, naming them.
    with pytest.raises(casteljau.Error, match="knots"):
        casteljau.BezierSurface.from_json({"type": "bezier_surface", "points": SADDLE, "knots": [[0, 1], [0, 1]]})


def test_evaluate_scattered_and_grid():
    s = casteljau.BezierSurface(SADDLE)
    assert s.dim == 3 and s.domain == ((0.0, 1.0), (0.0, 1.0))
    np.testing.assert_allclose(s(0.25, 0.5), saddle(0.25, 0.5), rtol=0, atol=EPS)
    assert s(0.25, 0.5).shape == (3,)
    u = np.random.default_rng(1).random((4, 5))
    v = np.random.default_rng(2).random((4, 5))
    out = s(u, v)
    assert out.shape == (4, 5, 3) and out.flags.c_contiguous
    np.testing.assert_allclose(out, saddle(u, v), rtol=0, atol=4 * EPS)
    np.testing.assert_allclose(s(u, 0.5), saddle(u, 0.5), rtol=0, atol=4 * EPS)  # broadcast
    gu, gv = np.linspace(0, 1, 3), np.linspace(-0.5, 1.5, 4)  # outside the domain: the patch continues
    g = s(gu, gv, grid=True)
    assert g.shape == (3, 4, 3)
    U, V = np.meshgrid(gu, gv, indexing="ij")
    np.testing.assert_allclose(g, saddle(U, V), rtol=0, atol=8 * EPS)
    with pytest.raises(casteljau.Error, match=r"^u\[1\]: must be a finite number, got nan"):
        s(np.array([0.1, np.nan]), 0.5)


def test_json_pickle_and_classes_of_every_type():
    b = casteljau.BSplineSurface(points=SADDLE, degree=[1, 1], knots=[[0, 0, 1, 1], [0, 0, 1, 1]])
    assert isinstance(b, casteljau.BSplineSurface)
    again = casteljau.Surface.from_json(b.to_json())
    assert again == b and type(again) is casteljau.BSplineSurface
    p = pickle.loads(pickle.dumps(b))
    assert p == b
    np.testing.assert_allclose(p(0.3, 0.6), saddle(0.3, 0.6), rtol=0, atol=EPS)
    np.testing.assert_array_equal(b.degree, [1, 1])
    # Weights all 2: the same points as the polynomial patch (w P / w).
    r = casteljau.RationalBezierSurface(points=SADDLE, weights=[[2, 2], [2, 2]])
    np.testing.assert_allclose(r(0.3, 0.6), saddle(0.3, 0.6), rtol=0, atol=EPS)
    n = casteljau.NurbsSurface(points=SADDLE, weights=[[1, 1], [1, 1]], degree=[1, 1],
                               knots=[[0, 0, 1, 1], [0, 0, 1, 1]])
    np.testing.assert_allclose(n(0.7, 0.2), saddle(0.7, 0.2), rtol=0, atol=EPS)
    with pytest.raises(casteljau.Error, match=r"^type: BezierSurface.from_json needs a 'bezier_surface'"):
        casteljau.BezierSurface.from_json(b.to_json())
    with pytest.raises(casteljau.Error, match=r"^points\[1\]\[1\]\[2\]: must be a finite number"):
        casteljau.BezierSurface([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, np.nan]]])


def test_surface_commands():
    s = casteljau.BezierSurface(SADDLE)
    uv = np.array([[0.25, 0.5], [1.0, 0.0]])
    r = s.eval(uv, derivatives=1, normal=True)
    np.testing.assert_allclose(r.points, saddle(uv[:, 0], uv[:, 1]), rtol=0, atol=EPS)
    # S_u = (1, 0, v), S_v = (0, 1, u); the unit normal (-v, -u, 1) / sqrt(1 + u^2 + v^2).
    np.testing.assert_allclose(r.partials.u, [[1, 0, 0.5], [1, 0, 0]], rtol=0, atol=EPS)
    np.testing.assert_allclose(r.partials.v, [[0, 1, 0.25], [0, 1, 1]], rtol=0, atol=EPS)
    n = np.array([[-0.5, -0.25, 1], [0, -1, 1]])
    np.testing.assert_allclose(r.normals, n / np.linalg.norm(n, axis=1, keepdims=True), rtol=0, atol=4 * EPS)
    # Gaussian curvature of z = u v at the origin: -1 (K = -1 / (1 + u^2 + v^2)^2).
    k = s.eval([[0.0, 0.0]], curvature=True)
    assert k.gaussian[0] == pytest.approx(-1, abs=4 * EPS)
    first, second = s.split("u", 0.5)
    assert isinstance(first, casteljau.BezierSurface)
    np.testing.assert_allclose(first(1.0, 0.5), saddle(0.5, 0.5), rtol=0, atol=EPS)
    e = s.elevate("v", 2)
    assert np.asarray(e.points).shape == (2, 4, 3)
    np.testing.assert_allclose(e(0.3, 0.8), saddle(0.3, 0.8), rtol=0, atol=4 * EPS)
    b = casteljau.BSplineSurface(points=SADDLE, degree=[1, 1], knots=[[0, 0, 1, 1], [0, 0, 1, 1]])
    k2 = b.insert_knot("u", 0.5)
    assert len(k2.knots[0]) == 5
    np.testing.assert_allclose(k2(0.3, 0.8), saddle(0.3, 0.8), rtol=0, atol=4 * EPS)
    iso = s.isocurve("u", 0.5)  # v -> S(0.5, v) = (0.5, v, v / 2)
    assert isinstance(iso, casteljau.Bezier)
    np.testing.assert_allclose(iso(0.4), [0.5, 0.4, 0.2], rtol=0, atol=EPS)
    patches = k2.to_bezier()
    assert len(patches.patches) == 2 and isinstance(patches.patches[0][0], casteljau.BezierSurface)
    box = s.bounds()
    np.testing.assert_allclose(box.min, [0, 0, 0], atol=1e-9)  # bounds: within 1e-9 of the size
    np.testing.assert_allclose(box.max, [1, 1, 1], atol=1e-9)
    # The unit square, flat: area 1 (the command's accuracy is 1e-10 relative).
    flat = casteljau.BezierSurface([[[0, 0], [0, 1]], [[1, 0], [1, 1]]])
    assert flat.area() == pytest.approx(1, rel=1e-10)


def test_constructions():
    # The unit sphere: a half circle in the xz plane turned about the z axis.
    half = casteljau.Nurbs(degree=2, knots=[0, 0, 0, 0.5, 0.5, 1, 1, 1],
                           points=[[0, 0, -1], [1, 0, -1], [1, 0, 0], [1, 0, 1], [0, 0, 1]],
                           weights=[1, math.sqrt(0.5), 1, math.sqrt(0.5), 1])
    sphere = casteljau.surface.revolve(curve=half, axis={"point": [0, 0, 0], "direction": [0, 0, 1]})
    assert isinstance(sphere, casteljau.NurbsSurface)
    (u0, u1), (v0, v1) = sphere.domain
    g = sphere(np.linspace(u0, u1, 7), np.linspace(v0, v1, 9), grid=True)
    # Every point at distance 1 from the centre (rational arcs: rounding only).
    np.testing.assert_allclose(np.linalg.norm(g, axis=-1), 1, rtol=0, atol=1e-14)
    # 4 pi, to the area command's 1e-10 relative.
    assert sphere.area() == pytest.approx(4 * math.pi, rel=1e-10)
    line = casteljau.Bezier([[0, 0, 0], [1, 0, 0]])
    wall = casteljau.surface.extrude(curve=line, vector=[0, 0, 2])
    np.testing.assert_allclose(wall(0.5, 0.5), [0.5, 0, 1], rtol=0, atol=EPS)
    assert casteljau.surface("extrude", curve=line, vector=[0, 0, 2]) == wall
    with pytest.raises(TypeError):
        casteljau.surface.revolve(half)  # keywords only


def _bezier_patch_normal_mp(P, u, v):
    """The unit normal S_u x S_v / |S_u x S_v| of the Bézier patch with control grid P at
    (u, v), in mpmath at 60 digits (Bernstein polynomials and their derivatives by their
    definitions)."""
    import mpmath as mp
    mp.mp.dps = 60
    n, m = len(P) - 1, len(P[0]) - 1

    def b(k, i, t):
        return mp.binomial(k, i) * t ** i * (1 - t) ** (k - i) if 0 <= i <= k else mp.mpf(0)

    def db(k, i, t):
        return k * (b(k - 1, i - 1, t) - b(k - 1, i, t))

    u, v = mp.mpf(u), mp.mpf(v)
    Su = [mp.fsum(db(n, i, u) * b(m, j, v) * P[i][j][c] for i in range(n + 1) for j in range(m + 1)) for c in range(3)]
    Sv = [mp.fsum(b(n, i, u) * db(m, j, v) * P[i][j][c] for i in range(n + 1) for j in range(m + 1)) for c in range(3)]
    N = [Su[1] * Sv[2] - Su[2] * Sv[1], Su[2] * Sv[0] - Su[0] * Sv[2], Su[0] * Sv[1] - Su[1] * Sv[0]]
    L = mp.sqrt(mp.fsum(x * x for x in N))
    return np.array([float(x / L) for x in N])


def test_limit_normal_at_degenerate_edges():
    """s.limit_normal (the library's limit normal): the normal where S_u x S_v vanishes on
    a degenerate edge, against closed forms and mpmath's normals at 10^-30 from the edge;
    None where the normals have no limit (a cone's apex, a collapsed side whose fan is not
    planar)."""
    h = math.sqrt(0.5)
    # A sphere of radius 2 about c, on an oblique axis d: the poles c -+ r d (4 rational
    # spans along each pole). Closed form: the normal is sigma (P - c) / r with one sign
    # sigma for the whole sphere (the side S_u x S_v points to, read off interior points).
    c, r = np.array([0.5, -1.0, 2.0]), 2.0
    d = np.array([1.0, 2.0, 2.0]) / 3
    e = np.array([2.0, -2.0, 1.0]) / 3  # perpendicular to d
    prof = [c - r * d, c - r * d + r * e, c + r * e, c + r * d + r * e, c + r * d]
    half = casteljau.Nurbs(degree=2, knots=[0, 0, 0, 0.5, 0.5, 1, 1, 1], points=[list(p) for p in prof],
                           weights=[1, h, 1, h, 1])
    sphere = casteljau.surface.revolve(curve=half, axis={"point": list(c), "direction": list(d)})
    (u0, u1), (v0, v1) = sphere.domain
    inner = [[u, v] for u in (0.1, 0.5, 0.9) for v in np.linspace(v0, v1, 7)]
    normals = np.array(sphere.eval(inner, normal=True).normals)
    sigma = np.sign(np.einsum("ij,ij->i", normals, (sphere(*np.array(inner).T) - c) / r))
    assert np.all(sigma == sigma[0])
    for v in (v0, 0.3, 1.7, math.pi, 5.9, v1):
        assert sphere.eval([[u0, v]], normal=True).normals == [None]  # the contract's null
        np.testing.assert_allclose(sphere.limit_normal(u0, v), -sigma[0] * d, rtol=0, atol=1e-13)
        np.testing.assert_allclose(sphere.limit_normal(u1, v), sigma[0] * d, rtol=0, atol=1e-13)
    # Where the normal is defined: the eval command's.
    np.testing.assert_allclose(sphere.limit_normal(0.3, 1.1), sphere.eval([[0.3, 1.1]], normal=True).normals[0], rtol=0, atol=0)
    # A paraboloid z = x^2 + y^2 (the profile x = u, z = u^2 turned about z): at its vertex
    # the closed form +-(0, 0, 1), the sign of sigma (-2x, -2y, 1) at interior points.
    para = casteljau.surface.revolve(curve=casteljau.Bezier([[0, 0, 0], [0.5, 0, 0], [1, 0, 1]]),
                                     axis={"point": [0, 0, 0], "direction": [0, 0, 1]})
    X = para(*np.array(inner).T)
    closed = np.stack([-2 * X[:, 0], -2 * X[:, 1], np.ones(len(X))], axis=1)
    sigma = np.sign(np.einsum("ij,ij->i", np.array(para.eval(inner, normal=True).normals), closed))
    assert np.all(sigma == sigma[0])
    for v in (0, 1, 2.5, 2 * math.pi):
        np.testing.assert_allclose(para.limit_normal(0, v), [0, 0, sigma[0]], rtol=0, atol=1e-13)
    # A cone's apex: the normals at (u, v) tend to (cos v, sin v, 1) / sqrt 2 (up to sign),
    # which turns with v: no limit.
    cone = casteljau.surface.revolve(curve=casteljau.Bezier([[0, 0, 1], [1, 0, 0]]),
                                     axis={"point": [0, 0, 0], "direction": [0, 0, 1]})
    for v in (0, 1, 4):
        assert cone.limit_normal(0, v) is None
    # Bilinear patches with a collapsed side (flat triangles A, B, C): the normal is the
    # triangle's everywhere, (B - A) x (C - B) for the row u = 0 collapsed, (C - B) x (B - A)
    # for the column v = 0 (S_u x S_v = u (B - A) x (C - B), resp. v (C - B) x (B - A)).
    A, B, C = np.array([0.2, 0.1, 0.3]), np.array([1.5, -0.2, 0.9]), np.array([0.7, 1.3, -0.4])
    unit = lambda x: x / np.linalg.norm(x)
    row = casteljau.BezierSurface([[list(A), list(A)], [list(B), list(C)]])
    col = casteljau.BezierSurface([[list(A), list(B)], [list(A), list(C)]])
    for t in (0, 0.3, 1):
        np.testing.assert_allclose(row.limit_normal(0, t), unit(np.cross(B - A, C - B)), rtol=0, atol=1e-14)
        np.testing.assert_allclose(col.limit_normal(t, 0), unit(np.cross(C - B, B - A)), rtol=0, atol=1e-14)
    # Bicubic patches with the row u = 0 collapsed to O: where the next row lies in a plane
    # through O (a planar fan), mpmath's normals at u = 10^-30 are one vector along the
    # edge (the limit); where it does not, they turn with v and there is no limit.
    rng = np.random.default_rng(19)
    O = [0.0, 0.0, 0.0]
    fan = [[1, 0, 0], [1, 1, 0], [0, 1.5, 0], [-1, 1, 0]]
    tail = rng.uniform(-1, 1, (2, 4, 3)).tolist()
    for row1, exists in ((fan, True), ([[1, 0, 0.2], [1, 1, -0.3], [0, 1.5, 0.1], [-1, 1, 0.4]], False)):
        P = [[O] * 4, row1] + tail
        patch = casteljau.BezierSurface(P)
        limits = [_bezier_patch_normal_mp(P, "1e-30", v) for v in (0, 0.25, 0.6, 1)]
        assert exists == all(np.allclose(x, limits[0], rtol=0, atol=1e-12) for x in limits)
        for v, lim in zip((0, 0.25, 0.6, 1), limits):
            got = patch.limit_normal(0, v)
            if exists:
                np.testing.assert_allclose(got, lim, rtol=0, atol=1e-13)
            else:
                assert got is None
    # Bad input: the normal needs 3-D, the parameters finite.
    with pytest.raises(casteljau.Error, match="^normal: "):
        casteljau.BezierSurface([[[0, 0], [0, 1]], [[1, 0], [1, 1]]]).limit_normal(0, 0)
    with pytest.raises(casteljau.Error, match="^u: "):
        cone.limit_normal(math.nan, 0)


def test_eval_on_arrays_equals_the_command():
    """s.eval on an (n, 2) array (the compiled module's partials and geometry, no JSON)
    gives the eval command's values exactly; lists, NaN and wrong types go to the command
    (its errors)."""
    rng = np.random.default_rng(12)
    nurbs = casteljau.NurbsSurface(points=rng.random((4, 5, 3)), weights=rng.random((4, 5)) + 0.5, degree=[2, 3],
                                   knots=[[0, 0, 0, 0.5, 1, 1, 1], [0, 0, 0, 0, 0.5, 1, 1, 1, 1]])
    uv = np.column_stack([rng.random(20), rng.random(20)])
    for s in (nurbs, casteljau.BezierSurface(SADDLE)):
        for k, normal, curvature in ((0, False, False), (2, False, False), (1, True, False), (3, True, True)):
            ours = s.eval(uv, derivatives=k, normal=normal, curvature=curvature)
            theirs = casteljau.run("eval", surface=s, uv=uv.tolist(), derivatives=k, normal=normal, curvature=curvature)
            if isinstance(theirs, np.ndarray):
                np.testing.assert_array_equal(ours, theirs)
                continue
            assert ours._fields() == theirs._fields()
            for name in theirs._fields():
                a, b = getattr(ours, name), getattr(theirs, name)
                if name == "partials":
                    assert a._fields() == b._fields()
                    for p in b._fields():
                        np.testing.assert_array_equal(getattr(a, p), getattr(b, p))
                else:
                    np.testing.assert_array_equal(np.asarray(a), np.asarray(b))
    # A pole-free undefined normal: at a corner of a degenerate patch (a triangle) the
    # normal is None in both.
    tri = casteljau.BezierSurface([[[0, 0, 0], [0, 0, 0]], [[1, 0, 0], [0, 1, 0]]])
    a = tri.eval([[0.0, 0.0], [0.5, 0.5]], normal=True).normals
    b = casteljau.run("eval", surface=tri, uv=[[0.0, 0.0], [0.5, 0.5]], normal=True).normals
    assert a[0] is None and b[0] is None
    np.testing.assert_array_equal(a[1], b[1])
    with pytest.raises(casteljau.Error, match=r"^uv\[1\]\[0\]: "):
        nurbs.eval([[0.5, 0.5], [np.nan, 0.5]])
    with pytest.raises(casteljau.Error, match=r"^derivatives: derivative count must be <= 64"):
        nurbs.eval(uv, derivatives=65)
    with pytest.raises(casteljau.Error, match=r"^normal: normals need a 3-D surface"):
        casteljau.BezierSurface([[[0, 0], [0, 1]], [[1, 0], [1, 1]]]).eval(uv, normal=True)
