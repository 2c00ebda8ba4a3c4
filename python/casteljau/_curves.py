"""The library's curve classes and commands, generated from the compiled registry.

Every curve type of the registry (``_casteljau.curve_types()``: its curve-JSON name, class
name and fields) becomes a subclass of :class:`Curve` whose constructor takes the type's
fields, positionally in the registry's order or as keywords. Every command of the registry
(``_casteljau.commands()``) with a ``curve`` field becomes a method of :class:`Curve` named
after the command, and every other command a module function: a type or a command added
to the library reaches Python with no change here. A few methods are written by hand on
top (evaluation, ``derivative``, ``curvature``, ``pieces``, ``project`` over many points).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from . import _casteljau
from ._casteljau import Error


__all__ = ["Curve", "Result", "Error", "curve_classes", "run"]


def _json_object(obj: Any, args: tuple, fields: dict[str, Any]) -> dict[str, Any]:
    """The JSON object of a generated class's constructor call (curves and surfaces): its
    `_type`, the positional arguments in the order of its `_fields`, then the keywords;
    Python's own TypeErrors for too many, unknown or repeated arguments."""
    name, names = type(obj).__name__, obj._fields
    if len(args) > len(names):
        raise TypeError(f"{name}() takes at most {len(names)} positional arguments "
                        f"({', '.join(names)}), got {len(args)}")
    out: dict[str, Any] = {"type": obj._type}
    out.update(zip(names, args))
    for k, v in fields.items():
        if k not in names:
            raise TypeError(f"{name}() got an unexpected keyword argument {k!r} (fields: {', '.join(names)})")
        if k in out:
            raise TypeError(f"{name}() got multiple values for argument {k!r}")
        out[k] = v
    return out


# ---------------------------------------------------------------------------------------
# Python values <-> request JSON: requests go to the compiled module as Python data (dicts,
# lists, numbers, numpy arrays, curves), converted to the library's JSON values in C++
# (a NaN or infinity refused there, naming its path); responses come back as Python data
# with arrays of numbers as numpy arrays.


def _dumps(obj: Any) -> str:
    """obj as JSON text (numpy arrays, curves and surfaces included)."""
    return _casteljau.to_json_text(obj)


def _arrays(value: Any) -> Any:
    """Response data as Python: curve and surface objects as curves and surfaces, other
    objects as Result (arrays of numbers already numpy arrays)."""
    if isinstance(value, dict):
        kind = value.get("type")
        if kind in _CLASSES:
            return Curve.from_json(value)
        if kind in _SURFACE_CLASSES:
            return _SURFACE_CLASSES[kind].from_json(value)
        return Result(**{k: _arrays(v) for k, v in value.items()})
    if isinstance(value, list):
        return [_arrays(v) for v in value]
    return value


class Result:
    """A command's answer: its fields as attributes (arrays as numpy arrays)."""

    def __init__(self, **fields: Any) -> None:
        self.__dict__.update(fields)

    def __repr__(self) -> str:
        inner = ", ".join(f"{k}={v!r}" for k, v in self.__dict__.items())
        return f"Result({inner})"

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Result) or self.__dict__.keys() != other.__dict__.keys():
            return False
        return all(np.array_equal(a, b) if isinstance(a, np.ndarray) else a == b
                   for a, b in zip(self.__dict__.values(), other.__dict__.values()))

    def _fields(self) -> tuple:
        return tuple(self.__dict__)


def _simplify(response: dict) -> Any:
    """A response of one field answers with that field's value (length -> a float, flatten
    -> its points, split -> its two curves); otherwise a Result of every field."""
    out = _arrays(response)
    fields = out._fields() if isinstance(out, Result) else ()
    if len(fields) == 1:
        v = getattr(out, fields[0])
        return tuple(v) if fields[0] == "curves" else v
    return out


def run(command: str, **request: Any) -> Any:
    """Runs a command of the registry on a request given as keywords (curves, arrays and
    numbers as they come); the response as Python (see Result)."""
    return _simplify(_casteljau.run(command, request))


# ---------------------------------------------------------------------------------------
# The curve classes

_CLASSES: dict[str, type] = {}
_SURFACE_CLASSES: dict[str, type] = {}  # filled by _surfaces.py


class Curve:
    """A curve of the library. Construct one of the registry's classes (``Bezier(points)``,
    ``Nurbs(degree=, knots=, points=, weights=)``, ...) or read curve JSON with
    ``Curve.from_json``. Calling a curve evaluates it: ``c(t)`` for a number or an array of
    any shape gives float64 points of shape ``t.shape + (d,)``; ``c(t, nu=k)`` the order-k
    derivative."""

    _type = ""  # the curve-JSON name (set on each generated class)
    _fields: tuple[str, ...] = ()
    __slots__ = ("_c", "_json")

    def __init__(self, *args: Any, **fields: Any) -> None:
        if type(self) is Curve:
            raise TypeError("Curve is abstract: construct one of its subclasses or use Curve.from_json")
        obj = _json_object(self, args, fields)
        self._c = _casteljau.Curve(obj)
        self._json = None

    @classmethod
    def _wrap(cls, core: Any) -> "Curve":
        c = object.__new__(_CLASSES[core.type])
        c._c = core
        c._json = None
        return c

    @classmethod
    def from_json(cls, obj: dict | str) -> "Curve":
        """The curve of a curve-JSON object (a dict or its text); on a subclass, the object
        must be of that type."""
        c = cls._wrap(_casteljau.Curve(obj))
        if cls is not Curve and not isinstance(c, cls):
            raise Error(f"type: {cls.__name__}.from_json needs a {cls._type!r} curve, got {c._c.type!r}")
        return c

    def to_json(self) -> dict:
        """The curve JSON as the library writes it (a dict)."""
        if self._json is None:
            self._json = self._c.to_data()
        return self._json

    def __reduce__(self) -> tuple:
        # Pickled by its JSON form (multiprocessing, Dask).
        return (Curve.from_json, (self._c.to_json(),))

    def __repr__(self) -> str:
        return f"{type(self).__name__}.from_json({self._c.to_json()})"

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Curve) and self._c.to_json() == other._c.to_json()

    __hash__ = None  # type: ignore[assignment]

    @property
    def dim(self) -> int:
        """The dimension d of the curve's points."""
        return self._c.dim

    @property
    def domain(self) -> tuple[float, float]:
        """The parameter domain (lo, hi)."""
        return self._c.domain

    def __call__(self, t: Any, nu: int = 0) -> np.ndarray:
        """Points (nu = 0) or order-nu derivatives at t (a number or an array of any shape):
        float64, C-contiguous, shape t.shape + (d,). Outside the domain the end pieces
        continue. A NaN parameter raises Error naming t[j] (j: the flat index).

        >>> import casteljau
        >>> c = casteljau.Bezier([[0, 0], [0, 2], [2, 2], [2, 0]])
        >>> c(0.5)  # de Casteljau: (P0 + 3 P1 + 3 P2 + P3) / 8
        array([1. , 1.5])
        >>> c([0, 0.5, 1])
        array([[0. , 0. ],
               [1. , 1.5],
               [2. , 0. ]])
        >>> c(0.5, nu=1), c(0.5, nu=2)  # x = 6 t^2 - 4 t^3, y = 6 t - 6 t^2
        (array([3., 0.]), array([  0., -12.]))
        """
        return self._c.evaluate(np.asarray(t, dtype=np.float64), int(nu))

    def derivative(self, k: int = 1) -> "Curve":
        """The order-k derivative curve as a Path with the curve's parametrisation:
        c.derivative(k)(t) == c(t, nu=k) (to rounding). A polynomial piece's derivative is
        its hodograph (a Bezier segment); a rational piece's R = N / W is the rational
        segment (N' W - N W') / W^2, of twice the degree (each order doubles it again).

        >>> import casteljau
        >>> d = casteljau.Bezier([[0, 0], [0, 2], [2, 2], [2, 0]]).derivative()
        >>> type(d).__name__, d.segments[0].points  # the hodograph: 3 (P[j+1] - P[j])
        ('Path', [[0.0, 6.0], [6.0, 0.0], [0.0, -6.0]])
        >>> d(0.5)
        array([3., 0.])
        >>> arc = casteljau.RationalBezier([[1, 0], [1, 1], [0, 1]], [1, 1, 2])  # ((1 - t^2), 2 t) / (1 + t^2)
        >>> arc.derivative()(0.5).round(12)  # (-4 t, 2 (1 - t^2)) / (1 + t^2)^2
        array([-1.28,  0.96])
        """
        if k < 0:
            raise Error(f"k: must be >= 0, got {k}")
        c: Curve = self
        for _ in range(k):
            c = _hodograph(c)
        return c

    def curvature(self, t: Any) -> np.ndarray | float:
        """The curvature at t (signed in 2-D): the shape of t.

        >>> import casteljau
        >>> c = casteljau.Bezier([[0, 0], [0, 2], [2, 2], [2, 0]])
        >>> round(c.curvature(0.5), 12)  # (x' y'' - y' x'') / |c'|^3 = 3 (-12) / 27: turning clockwise
        -1.333333333333
        >>> arc = casteljau.RationalBezier([[1, 0], [1, 1], [0, 1]], [1, 1, 2])  # on the unit circle
        >>> arc.curvature([0, 0.5, 1]).round(12)
        array([1., 1., 1.])
        """
        k = self._c.curvature(np.asarray(t, dtype=np.float64))
        return float(k) if k.ndim == 0 else k

    def pieces(self) -> Result:
        """The exact Bezier pieces: Result(breaks (n + 1,), segments [Bezier or
        RationalBezier on [0, 1]]).

        >>> import casteljau
        >>> b = casteljau.BSpline(degree=2, knots=[0, 0, 0, 1, 2, 2, 2], points=[[0, 0], [2, 0], [2, 2], [0, 2]])
        >>> p = b.pieces()  # the pieces meet at the midpoint of the middle leg
        >>> p.breaks, [s.points for s in p.segments]
        (array([0., 1., 2.]), [[[0.0, 0.0], [2.0, 0.0], [2.0, 1.0]], [[2.0, 1.0], [2.0, 2.0], [0.0, 2.0]]])
        """
        p = self.to_bezier()
        j = p.to_json()
        return Result(breaks=np.array(j["breaks"], dtype=np.float64),
                      segments=[Curve.from_json(s) for s in j["segments"]])

    def project(self, point: Any, farthest: bool = False) -> Result:
        """The nearest (farthest) point of the curve to point (d,), or to each row of points
        (n, d): Result(t, point, distance) with arrays of shape (n,), (n, d), (n,) (one
        point: a number, (d,), a number, and all_t / intervals on ties, as the project
        command answers). The rows run in C++ without the GIL, each a direct call of the
        library's project (no JSON), on the curve's exact pieces made at its first
        projection and kept.

        >>> import casteljau
        >>> r = casteljau.Bezier([[0, 0], [0, 2], [2, 2], [2, 0]]).project([1, 3])  # above the top (1, 1.5)
        >>> round(r.t, 12), r.point.round(12), round(r.distance, 12)
        (0.5, array([1. , 1.5]), 1.5)
        >>> r = casteljau.Bezier([[0, 0], [4, 0]]).project([[1, 1], [3, -2], [5, 0]])  # rows: arrays
        >>> r.t, r.distance  # the feet of the perpendiculars; past the end, the end
        (array([0.25, 0.75, 1.  ]), array([1., 2., 1.]))
        """
        pts = np.asarray(point, dtype=np.float64)
        if pts.ndim == 1:
            return _simplify(self._c.project_point(pts, bool(farthest)))
        if pts.ndim != 2:
            raise Error(f"points: must be one point (d,) or an array of points (n, d), got shape {pts.shape}")
        # t, point and distance per row, by the library's project called on each row (all_t
        # and intervals, present on ties only, are left out here: project one point to see
        # them).
        t, p, d = self._c.project_rows(pts, bool(farthest))
        return Result(t=t, point=p, distance=d)


def _hodograph(c: Curve) -> Curve:
    """The first derivative of a polynomial curve as a path of Bezier segments: on the
    break interval [a, b] a degree-n piece with points P has derivative points
    n (P[j+1] - P[j]) / (b - a)."""
    j = c.to_bezier().to_json()
    breaks = j["breaks"]
    segs = []
    for i, s in enumerate(j["segments"]):
        P = np.array(s["points"], dtype=np.float64)
        n = len(P) - 1
        h = breaks[i + 1] - breaks[i]
        if s["type"] == "rational_bezier":
            segs.append(_rational_derivative(P, np.array(s["weights"], dtype=np.float64), h))
            continue
        D = n * np.diff(P, axis=0) / h if n > 0 else np.zeros_like(P)
        segs.append({"type": "bezier", "points": D})
    return Curve.from_json({"type": "path", "segments": segs, "breaks": breaks})


def _bernstein_product(f: np.ndarray, g: np.ndarray) -> np.ndarray:
    """The Bernstein coefficients of f g (degrees m and n, rows of coefficients, columns of
    coordinates): (f g)_k = sum over i + j = k of C(m, i) C(n, j) / C(m + n, k) f_i g_j."""
    m, n = len(f) - 1, len(g) - 1
    out = np.zeros((m + n + 1,) + np.broadcast_shapes(f.shape[1:], g.shape[1:]))
    for i in range(m + 1):
        for j in range(n + 1):
            out[i + j] += (math.comb(m, i) * math.comb(n, j) / math.comb(m + n, i + j)) * f[i] * g[j]
    return out


def _rational_derivative(P: np.ndarray, w: np.ndarray, h: float) -> dict:
    """The derivative, over a break interval of width h, of the rational Bezier piece with
    points P (n + 1, d) and weights w, as a rational_bezier segment of degree 2n: with
    N = sum w_i P_i B_i and W = sum w_i B_i, R' = (N' W - N W') / (h W^2), the numerator
    (degree 2n - 1) raised once to 2n, the weights the coefficients of W^2 (positive where
    w is) and the points the numerator's homogeneous coefficients over them."""
    n = len(P) - 1
    w = w / np.max(np.abs(w))  # the same curve; keeps W^2 in range
    N = P * w[:, None]
    if n == 0:
        return {"type": "bezier", "points": np.zeros_like(P)}
    dN, dW = n * np.diff(N, axis=0), n * np.diff(w)[:, None]
    A = _bernstein_product(dN, w[:, None]) - _bernstein_product(N, dW)  # degree 2n - 1
    m = len(A) - 1
    k = np.arange(m + 2)[:, None] / (m + 1)
    A = k * np.vstack([np.zeros_like(A[:1]), A]) + (1 - k) * np.vstack([A, np.zeros_like(A[:1])])  # degree 2n
    W2 = _bernstein_product(w[:, None], w[:, None])[:, 0]
    return {"type": "rational_bezier", "points": A / (W2[:, None] * h), "weights": W2}


# ---------------------------------------------------------------------------------------
# Generation from the registry


def _registry_commands() -> list:
    return _casteljau.commands()


def _command_method(name: str, summary: str, fields: list) -> Any:
    params = [f[0] for f in fields if f[0] != "curve"]

    def method(self: Curve, *args: Any, **kw: Any) -> Any:
        if len(args) > len(params):
            raise TypeError(f"{name}() takes at most {len(params)} arguments ({', '.join(params)}), got {len(args)}")
        req = dict(zip(params, args))
        for k, v in kw.items():
            if k.endswith("_") and k[:-1] in params:  # from_: "from" is a Python keyword
                k = k[:-1]
            if k not in params:
                raise TypeError(f"{name}() got an unexpected keyword argument {k!r} (fields: {', '.join(params)})")
            req[k] = v
        return _simplify(self._c.run(name, req, "curve"))

    method.__name__ = name
    method.__qualname__ = f"Curve.{name}"
    method.__doc__ = _doc(name, summary, [f for f in fields if f[0] != "curve"])
    return method


def _command_function(name: str, summary: str, fields: list) -> Any:
    params = [f[0] for f in fields]
    gathers = bool(fields) and fields[0][1] == "curve[]"

    def function(*args: Any, **kw: Any) -> Any:
        req: dict[str, Any] = {}
        if gathers and args and isinstance(args[0], Curve):
            # intersect(a, b), distance(a, b): the curves array from the leading curves.
            n = 0
            while n < len(args) and isinstance(args[n], Curve):
                n += 1
            req[params[0]] = list(args[:n])
            rest, names = args[n:], params[1:]
        else:
            rest, names = args, params
        if len(rest) > len(names):
            raise TypeError(f"{name}() takes at most {len(params)} arguments ({', '.join(params)})")
        req.update(zip(names, rest))
        for k, v in kw.items():
            if k not in params:
                raise TypeError(f"{name}() got an unexpected keyword argument {k!r} (fields: {', '.join(params)})")
            req[k] = v
        return _simplify(_casteljau.run(name, req))

    function.__name__ = name
    function.__qualname__ = name
    function.__doc__ = _doc(name, summary, fields)
    return function


def _doc(name: str, summary: str, fields: list, example: bool = True) -> str:
    """A generated method's or function's docstring: the registry's summary and fields, and
    the command's example from _EXAMPLES (curve methods and module functions only: a
    surface method of the same name passes example=False)."""
    lines = [summary + ".", "", f"The registry's command {name!r} (docs/cli.md). Arguments:"]
    for fname, ftype, required, default, help_ in fields:
        state = "required" if required else (f"default {default}" if default else "optional")
        lines.append(f"    {fname} ({ftype}, {state}): {help_}")
    if example and name in _EXAMPLES:
        lines += ["", "Example (run as a doctest; the values checkable by hand):", "", _EXAMPLES[name].strip("\n")]
    return "\n".join(lines)


# The docstring examples of the generated methods and functions, by command (a command
# without one here has none). Each expected value is a textbook one, worked out in the
# comment beside it; values from an iteration or a quadrature are rounded.
_EXAMPLES: dict[str, str] = {
    "split": """
>>> import casteljau
>>> a, b = casteljau.Bezier([[0, 0], [0, 2], [2, 2], [2, 0]]).split(0.5)
>>> a.points  # de Casteljau at 1/2: P0, the first midpoints' first, ..., the point
[[0.0, 0.0], [0.0, 1.0], [0.5, 1.5], [1.0, 1.5]]
>>> b.points  # ... and the other side of the triangle
[[1.0, 1.5], [1.5, 1.5], [2.0, 1.0], [2.0, 0.0]]
""",
    "elevate": """
>>> import casteljau
>>> casteljau.Bezier([[0, 0], [0, 2], [2, 2], [2, 0]]).elevate(1).points  # Q_i = i/4 P_(i-1) + (1 - i/4) P_i
[[0.0, 0.0], [0.0, 1.5], [1.0, 2.0], [2.0, 1.5], [2.0, 0.0]]
""",
    "insert_knot": """
>>> import casteljau
>>> b = casteljau.BSpline(degree=2, knots=[0, 0, 0, 1, 1, 1], points=[[0, 0], [1, 2], [2, 0]])
>>> c = b.insert_knot(0.5)  # Boehm: the new points are the affected legs' midpoints
>>> c.knots, c.points
([0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0], [[0.0, 0.0], [0.5, 1.0], [1.5, 1.0], [2.0, 0.0]])
""",
    "to_bezier": """
>>> import casteljau
>>> b = casteljau.BSpline(degree=2, knots=[0, 0, 0, 1, 2, 2, 2], points=[[0, 0], [2, 0], [2, 2], [0, 2]])
>>> p = b.to_bezier()  # a Path; the pieces meet at the midpoint of the middle leg
>>> p.breaks, [s.points for s in p.segments]
([0.0, 1.0, 2.0], [[[0.0, 0.0], [2.0, 0.0], [2.0, 1.0]], [[2.0, 1.0], [2.0, 2.0], [0.0, 2.0]]])
""",
    "bounds": """
>>> import casteljau
>>> b = casteljau.Bezier([[0, 0], [0, 2], [2, 2], [2, 0]]).bounds()  # y(t) = 6 t (1 - t): 1.5 at t = 1/2
>>> b.min, b.max
(array([0., 0.]), array([2. , 1.5]))
""",
    "length": """
>>> import casteljau
>>> s = casteljau.Bezier([[0, 0], [3, 4]])
>>> round(s.length(), 12), round(s.length(from_=0.5), 12)  # a 3-4-5 segment, and its second half
(5.0, 2.5)
""",
    "param_at_length": """
>>> import casteljau
>>> casteljau.Bezier([[0, 0], [3, 4]]).param_at_length([0, 2.5, 5]).round(12)  # arc length 5 t
array([0. , 0.5, 1. ])
""",
    "features": """
>>> import casteljau
>>> f = casteljau.Bezier([[0, 0], [1, 1], [2, -1], [3, 0]]).features()  # y = 3 t (1 - t) (1 - 2 t)
>>> f.inflections  # the point of symmetry
array([0.5])
>>> [e.round(6) for e in f.extrema]  # x = 3 t has none; y' = 0 at t = (3 -+ sqrt(3)) / 6
[array([], dtype=float64), array([0.211325, 0.788675])]
""",
    "flatten": """
>>> import casteljau
>>> q = casteljau.Bezier([[0, 0], [1, 1], [2, 0]])  # a chord over dt misses the parabola by dt^2 / 2
>>> q.flatten(0.2)  # dt = 1/2: 1/8 <= 0.2
array([[0. , 0. ],
       [1. , 0.5],
       [2. , 0. ]])
>>> len(q.flatten(0.03, method="uniform"))  # dt = 1/5: 0.02 <= 0.03 (dt = 1/4: 0.03125)
6
""",
    "area": """
>>> import math, casteljau
>>> casteljau.Polyline([[0, 0], [1, 0], [1, 1], [0, 1], [0, 0]]).area()  # counterclockwise: +
1.0
>>> casteljau.Polyline([[0, 0], [0, 1], [1, 1], [1, 0], [0, 0]]).area()  # clockwise: -
-1.0
>>> arc = casteljau.RationalBezier([[1, 0], [1, 1], [0, 1]], [1, 1, 2])  # ((1 - t^2), 2 t) / (1 + t^2)
>>> quarter = casteljau.Path(segments=[arc, casteljau.Bezier([[0, 1], [0, 0]]), casteljau.Bezier([[0, 0], [1, 0]])])
>>> round(quarter.area() - math.pi / 4, 12)  # the quarter disc
0.0
""",
    "intersect": """
>>> import casteljau
>>> r = casteljau.intersect(casteljau.Bezier([[0, 0], [2, 2]]), casteljau.Bezier([[0, 2], [2, 0]]))
>>> x = r.intersections[0]  # the diagonals of a square cross at its centre
>>> x.t.round(12), x.point.round(12), x.kind, len(r.overlaps)
(array([0.5, 0.5]), array([1., 1.]), 'crossing', 0)
""",
    "distance": """
>>> import casteljau
>>> r = casteljau.distance(casteljau.Bezier([[0, 0], [2, 0]]), casteljau.Bezier([[3, 1], [4, 2]]))
>>> round(r.distance, 12), r.t, r.points  # from the end (2, 0) to the start (3, 1): sqrt(2)
(1.414213562373, array([1., 0.]), array([[2., 0.],
       [3., 1.]]))
""",
    "fit": """
>>> import numpy as np, casteljau
>>> r = casteljau.fit([[0, 0], [1, 1], [2, 0]], degree=2, control_points=3)  # interpolation
>>> np.round(r.curve.points, 12) + 0  # B(1/2) = P0/4 + P1/2 + P2/4 = (1, 1): P1 = (1, 2)
array([[0., 0.],
       [1., 2.],
       [2., 0.]])
>>> round(r.max_error, 12)
0.0
""",
    "remove_knot": """
>>> import casteljau
>>> b = casteljau.BSpline(degree=2, knots=[0, 0, 0, 1, 1, 1], points=[[0, 0], [1, 2], [2, 0]])
>>> r = b.insert_knot(0.5).remove_knot(0.5, 1, 1e-12)  # an inserted knot comes out again
>>> r.removed, r.curve.knots, r.curve.points
(1, [0.0, 0.0, 0.0, 1.0, 1.0, 1.0], [[0.0, 0.0], [1.0, 2.0], [2.0, 0.0]])
""",
    "solve": """
>>> import casteljau
>>> c = casteljau.Bezier([[0, 0], [0, 2], [2, 2], [2, 0]])  # x = 6 t^2 - 4 t^3
>>> c.solve(1.0, 0).t.round(12)  # x = 1 at the point of symmetry
array([0.5])
""",
    "refine": """
>>> import casteljau
>>> b = casteljau.BSpline(degree=1, knots=[0, 0, 1, 1], points=[[0, 0], [2, 0]])
>>> b.refine([0.25, 0.5, 0.75]).points  # a line's new points: on it, at 2 u
[[0.0, 0.0], [0.5, 0.0], [1.0, 0.0], [1.5, 0.0], [2.0, 0.0]]
""",
    "reduce": """
>>> import numpy as np, casteljau
>>> cubic = casteljau.Bezier([[0, 0], [1, 2], [2, 0]]).elevate(1)  # a parabola written as a cubic
>>> r = cubic.reduce(1, 1e-9)
>>> np.round(r.curve.points, 12) + 0, round(r.max_error, 12)
(array([[0., 0.],
       [1., 2.],
       [2., 0.]]), 0.0)
""",
    "to_quadratic": """
>>> import casteljau
>>> cubic = casteljau.Bezier([[0, 0], [1, 2], [2, 0]]).elevate(1)  # a parabola written as a cubic
>>> [s.points for s in cubic.to_quadratic(1e-9).segments]  # one quadratic: the parabola's own
[[[0.0, 0.0], [1.0, 2.0], [2.0, 0.0]]]
""",
    "frames": """
>>> import casteljau
>>> arc = casteljau.RationalBezier([[1, 0, 0], [1, 1, 0], [0, 1, 0]], [1, 1, 2])  # a quarter of the unit circle
>>> f = arc.frames([0, 1])  # at (1, 0, 0) and (0, 1, 0): the tangent turns, the normal points to the centre
>>> f.tangents.round(12) + 0, f.normals.round(12) + 0, f.binormals.round(12) + 0
(array([[ 0.,  1.,  0.],
       [-1.,  0.,  0.]]), array([[-1.,  0.,  0.],
       [ 0., -1.,  0.]]), array([[0., 0., 1.],
       [0., 0., 1.]]))
""",
    "offset": """
>>> import casteljau
>>> o = casteljau.Bezier([[0, 0], [2, 0]]).offset(1, 1e-6)  # positive: to the left of the direction
>>> o([0, 0.5, 1]).round(12) + 0
array([[0., 1.],
       [1., 1.],
       [2., 1.]])
""",
    "to_svg_path": """
>>> import casteljau
>>> r = casteljau.Bezier([[0, 0], [0, 2], [2, 2], [2, 0]]).to_svg_path()  # SVG holds a cubic exactly
>>> r.d, r.exact
('M 0 0 C 0 2 2 2 2 0', True)
""",
    "basis": """
>>> import casteljau
>>> casteljau.basis("bernstein", degree=2, t=[0.5])  # (1 - t)^2, 2 t (1 - t), t^2
array([[0.25, 0.5 , 0.25]])
""",
    "subdivide": """
>>> import casteljau
>>> r = casteljau.subdivide([[0, 0], [4, 0], [4, 4], [0, 4]], scheme="chaikin", iterations=1, closed=True)
>>> r.points  # Chaikin: each edge's points at 1/4 and 3/4
array([[1., 0.],
       [3., 0.],
       [4., 1.],
       [4., 3.],
       [3., 4.],
       [1., 4.],
       [0., 3.],
       [0., 1.]])
""",
}


# Methods written above by hand take precedence over a generated one of the same name.
_HAND_WRITTEN = {"project"}
# Commands that are not methods: eval is the call (and curvature), render and the readers
# are module functions.
_NOT_METHODS = {"eval"}

functions: dict[str, Any] = {}
for _name, _summary, _fields in _registry_commands():
    _field_names = [f[0] for f in _fields]
    if _name in _NOT_METHODS:
        continue  # casteljau.run("eval", ...) still reaches it
    if _fields and _fields[0][0] == "curve":
        if _name not in _HAND_WRITTEN:
            setattr(Curve, _name, _command_method(_name, _summary, _fields))
    else:
        functions[_name] = _command_function(_name, _summary, _fields)


def _make_class(json_name: str, class_name: str, fields: list) -> type:
    names = tuple(f for f in fields if f != "type")
    doc = (f"The registry's {json_name!r} curve: {class_name}({', '.join(names)}), each a keyword or in this "
           f"order; the fields of curve JSON (docs/cli.md).")
    cls = type(class_name, (Curve,), {"_type": json_name, "_fields": names, "__slots__": (), "__doc__": doc,
                                      "__module__": "casteljau"})
    for f in names:
        if hasattr(Curve, f):  # dim: the property of every curve
            continue
        setattr(cls, f, property(lambda self, f=f: _arrays(self.to_json().get(f)), doc=f"The curve JSON's {f!r}."))
    return cls


curve_classes: dict[str, type] = {}
for _json_name, _class_name, _type_fields in _casteljau.curve_types():
    _cls = _make_class(_json_name, _class_name, _type_fields)
    _CLASSES[_json_name] = _cls
    curve_classes[_class_name] = _cls
