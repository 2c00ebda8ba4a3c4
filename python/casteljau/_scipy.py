"""scipy.interpolate's names and conventions over the library's curves (docs/python.md,
"Coming from scipy"): ``CubicSpline(x, y, bc_type=...)``, ``BSpline(t, c, k)``,
``make_interp_spline(x, y, k)``, ``PchipInterpolator``, ``Akima1DInterpolator``,
``BarycentricInterpolator``. Data y of shape (n, ...) along ``axis`` is the library's
curve of dimension prod(y.shape[1:]) (at most 4) over the parameters x; calls return
scipy's shapes (x.shape + y.shape[1:], a 0-d array for 1-D data and a number). Errors
name the arguments as scipy's callers write them (``x[3]``, ``y[2]``, ``t[3]``, ``c``, ``k``).
"""

from __future__ import annotations

import json
import math
import re
from typing import Any

import numpy as np

from . import _casteljau
from ._casteljau import Error
from ._curves import _CLASSES, Curve, _dumps, curve_classes

__all__ = ["PPoly", "CubicSpline", "BSpline", "make_interp_spline", "PchipInterpolator",
           "Akima1DInterpolator", "BarycentricInterpolator"]


def _renamed(e: Error, names: dict[str, str], drop_column: bool) -> Error:
    """The library's error with its field renamed to the caller's argument ("params[3]: ..."
    -> "x[3]: ..."); for 1-D data the point's coordinate index is dropped ("points[2][0]"
    -> "y[2]")."""
    msg = str(e)
    for lib, ours in names.items():
        m = re.match(rf"^{lib}(\[\d+\])?(\[\d+\])?(?=[.:\[ ])", msg)
        if m:
            first = m.group(1) or ""
            second = "" if drop_column else (m.group(2) or "")
            rest = msg[m.end():]
            for lib2, ours2 in names.items():  # "params must be strictly increasing" -> "x must ..."
                rest = re.sub(rf"\b{lib2}\b", ours2, rest)
            return Error(ours + first + second + rest)
    return e


def _data(y: Any, axis: int, name: str) -> tuple[np.ndarray, tuple]:
    """y as (n, m) points along axis, and the trailing shape of one value."""
    y = np.asarray(y, dtype=np.float64)
    if y.ndim == 0:
        raise Error(f"{name}: must be an array of at least one dimension, got a scalar")
    y = np.moveaxis(y, axis, 0)
    tail = y.shape[1:]
    m = math.prod(tail)
    if m > _casteljau.max_dimension or m == 0:
        raise Error(f"{name}: values of shape {tail} ({m} numbers per point) are not supported yet: "
                    f"at most {_casteljau.max_dimension} numbers per point")
    return y.reshape(len(y), m), tail


class PPoly:
    """A scipy-shaped piecewise polynomial over a library curve (what derivative() and
    antiderivative() return, in place of scipy's PPoly or BSpline): callable with scipy's
    shapes, with derivative, antiderivative, integrate and roots."""

    def __init__(self, curve: Curve, tail: tuple, extrapolate: Any = True) -> None:
        self._curve = curve
        self._tail = tail
        self.extrapolate = extrapolate
        lo, hi = curve.domain
        self._lo, self._hi = lo, hi

    @property
    def curve(self) -> Curve:
        """The library curve (of dimension prod(tail)) underneath."""
        return self._curve

    def __call__(self, x: Any, nu: int = 0, extrapolate: Any = None) -> np.ndarray:
        x = np.asarray(x, dtype=np.float64)
        ext = self.extrapolate if extrapolate is None else extrapolate
        xe = x
        if ext == "periodic":
            xe = self._lo + np.mod(x - self._lo, self._hi - self._lo)
        try:
            out = self._curve(xe, nu=nu)
        except Error as e:
            raise _renamed(e, {"t": "x"}, False) from None
        out = out.reshape(x.shape + self._tail)
        if ext is False or ext is None:
            outside = (x < self._lo) | (x > self._hi)
            if outside.any():
                out[outside] = np.nan
        return out

    @property
    def x(self) -> np.ndarray:
        """The breakpoints (scipy's PPoly.x)."""
        return np.asarray(_bezier_pieces(self._curve)[0], dtype=np.float64)

    @property
    def c(self) -> np.ndarray:
        """scipy's PPoly coefficients: c[m, i] multiplies (x - x[i])^(k - m) on piece i, shape
        (k + 1, pieces) + tail; from each Bezier piece's power form in s = (x - x[i]) / h,
        the coefficient of s^j divided by h^j."""
        breaks, pieces = _bezier_pieces(self._curve)
        k = max(len(P) - 1 for P in pieces)
        out = np.zeros((k + 1, len(pieces), pieces[0].shape[1]))
        for i, P in enumerate(pieces):
            n, h = len(P) - 1, breaks[i + 1] - breaks[i]
            for j in range(n + 1):
                a = sum(math.comb(n, j) * math.comb(j, r) * (-1) ** (j - r) * P[r] for r in range(j + 1))
                out[k - j, i] = a / h**j
        return out.reshape((k + 1, len(pieces)) + self._tail)

    def derivative(self, nu: int = 1) -> "PPoly":
        return PPoly(self._curve.derivative(nu), self._tail, self.extrapolate)

    def antiderivative(self, nu: int = 1) -> "PPoly":
        c = self._curve
        for _ in range(nu):
            c = _integral(c)
        return PPoly(c, self._tail, self.extrapolate)

    def integrate(self, a: float, b: float, extrapolate: Any = None) -> np.ndarray:
        ext = self.extrapolate if extrapolate is None else extrapolate
        if ext is False:
            a, b = (min(max(v, self._lo), self._hi) for v in (a, b))
        if ext == "periodic":
            raise Error("extrapolate: 'periodic' integration is not supported yet")
        F = _integral(self._curve)
        return (F(b) - F(a)).reshape(self._tail)

    def roots(self, discontinuity: bool = True, extrapolate: Any = None) -> np.ndarray:
        """The zeros of 1-D data, ascending (the registry's solve command on the domain; with
        extrapolate, also those of the end pieces continued)."""
        if self._tail not in ((), (1,)):
            raise Error("roots: needs 1-D data (y of shape (n,)), got values of shape " + str(self._tail))
        ext = self.extrapolate if extrapolate is None else extrapolate
        r = self._curve.solve(0.0, 0)
        roots = list(np.asarray(getattr(r, "t"), dtype=np.float64))
        if ext is True:
            roots += _end_roots(self._curve)
        return np.array(sorted(roots), dtype=np.float64)

    def solve(self, y: float = 0.0, discontinuity: bool = True, extrapolate: Any = None) -> np.ndarray:
        r = self._curve.solve(float(y), 0)
        return np.asarray(getattr(r, "t"), dtype=np.float64)


def _bezier_pieces(c: Curve) -> tuple[list, list]:
    j = c.to_bezier().to_json()
    for s in j["segments"]:
        if s["type"] != "bezier":
            raise Error("curve: needs a polynomial curve (this one has rational pieces)")
    return j["breaks"], [np.array(s["points"], dtype=np.float64) for s in j["segments"]]


def _integral(c: Curve) -> Curve:
    """The antiderivative that is 0 at the domain's start, as a path of Bezier pieces: on
    the break interval of width h a degree-n piece b_0..b_n integrates to the degree n + 1
    piece A_0 = F(start), A_(j+1) = A_j + h b_j / (n + 1)."""
    breaks, pieces = _bezier_pieces(c)
    segs = []
    start = np.zeros(pieces[0].shape[1])
    for i, P in enumerate(pieces):
        h = breaks[i + 1] - breaks[i]
        A = np.vstack([start, start + np.cumsum(P, axis=0) * (h / len(P))])
        segs.append({"type": "bezier", "points": A})
        start = A[-1]
    return Curve.from_json({"type": "path", "segments": segs, "breaks": breaks})


def _end_roots(c: Curve) -> list:
    """The real zeros of the first piece continued below the domain and of the last above
    it (scipy's extrapolated roots), from the pieces' power forms."""
    breaks, pieces = _bezier_pieces(c)
    out = []
    for P, (a, b), side in ((pieces[0], breaks[:2], -1), (pieces[-1], breaks[-2:], 1)):
        n = len(P) - 1
        coef = np.zeros(n + 1)  # power coefficients in s = (x - a) / (b - a), lowest first
        for k in range(n + 1):
            for i in range(k + 1):
                coef[k] += math.comb(n, k) * math.comb(k, i) * (-1) ** (k - i) * P[i, 0]
        nz = np.flatnonzero(coef)
        if len(nz) == 0 or nz[-1] == 0:
            continue
        for s in np.roots(coef[: nz[-1] + 1][::-1]):
            # A real root comes out of the companion matrix with an imaginary part of
            # rounding size (1e-12 relative: far above it, far below a true complex pair's).
            real = abs(s.imag) <= 1e-12 * max(1.0, abs(s.real))
            if real and ((side < 0 and s.real < 0) or (side > 0 and s.real > 1)):
                out.append(a + s.real * (b - a))
    return out


def _scipy_mode(self: Any, args: tuple, kw: dict, scipy_names: set) -> bool:
    return bool(args) or bool(set(kw) & scipy_names)


class _ScipyCurve:
    """scipy's call, derivative, antiderivative, integrate and roots for a library class
    constructed scipy's way (self._sp set)."""

    _sp: PPoly | None = None

    def __reduce__(self) -> tuple:
        # Pickled by the curve's JSON form and, made scipy's way, scipy's state (x, axis,
        # the PPoly view): a pickled CubicSpline(x, y) still answers in scipy's shapes.
        if self._sp is None:
            return Curve.__reduce__(self)
        return (_restore, (self._c.to_json(), self.__dict__))

    def __call__(self, x: Any, nu: int = 0, extrapolate: Any = None) -> np.ndarray:
        if self._sp is None:
            return Curve.__call__(self, x, nu)
        return self._sp(x, nu, extrapolate)

    def derivative(self, nu: int = 1) -> Any:
        if self._sp is None:
            return Curve.derivative(self, nu)
        return self._sp.derivative(nu)

    def antiderivative(self, nu: int = 1) -> PPoly:
        return (self._sp or PPoly(self, (self.dim,))).antiderivative(nu)

    def integrate(self, a: float, b: float, extrapolate: Any = None) -> np.ndarray:
        return (self._sp or PPoly(self, (self.dim,))).integrate(a, b, extrapolate)

    def roots(self, discontinuity: bool = True, extrapolate: Any = None) -> np.ndarray:
        return (self._sp or PPoly(self, (self.dim,))).roots(discontinuity, extrapolate)


def _restore(text: str, state: dict) -> Curve:
    c = Curve.from_json(text)
    c.__dict__.update(state)
    return c


def _bc(bc_type: Any, m: int) -> dict:
    """scipy's bc_type as the cubic_spline fields (docs/cli.md's table)."""
    if isinstance(bc_type, str):
        if bc_type == "clamped":
            return {"boundary": "clamped", "start_derivative": [0.0] * m, "end_derivative": [0.0] * m}
        if bc_type in ("natural", "not-a-knot", "periodic"):
            return {"boundary": bc_type}
        raise Error(f"bc_type: unknown boundary condition {bc_type!r} (not-a-knot, natural, clamped, periodic, "
                    "or a pair of them or of (order, value))")
    if isinstance(bc_type, (tuple, list)) and len(bc_type) == 2:
        if bc_type[0] == bc_type[1] and isinstance(bc_type[0], str):
            return _bc(bc_type[0], m)
        ends = {}
        for side, b in zip(("start", "end"), bc_type):
            if b == "natural":
                b = (2, 0.0)
            elif b == "clamped":
                b = (1, 0.0)
            elif isinstance(b, str):
                raise Error(f"bc_type: {b!r} at one end only is not supported yet (natural, clamped or (order, value))")
            order, value = b
            v = np.broadcast_to(np.asarray(value, dtype=np.float64).reshape(-1), (m,))
            ends[side] = {"order": order, "value": v}
        return {"boundary": ends}
    raise Error(f"bc_type: must be a string or a pair, got {bc_type!r}")


def _subclass(json_name: str, mixin: type, init: Any, doc: str, extra: dict | None = None) -> type:
    base = _CLASSES[json_name]
    cls = type(base.__name__, (mixin, base), {"__init__": init, "__doc__": doc, "__module__": "casteljau",
                                               **(extra or {})})
    _CLASSES[json_name] = cls
    curve_classes[base.__name__] = cls
    return cls


_CUBIC_BASE = _CLASSES["cubic_spline"]
_BSPLINE_BASE = _CLASSES["bspline"]


def _cubic_init(self: Any, *args: Any, **kw: Any) -> None:
    if not _scipy_mode(self, args, kw, {"x", "y", "axis", "bc_type", "extrapolate"}):
        _CUBIC_BASE.__init__(self, **kw)
        self._sp = None
        return
    names = ("x", "y", "axis", "bc_type", "extrapolate")
    a = dict(zip(names, args))
    for k, v in kw.items():
        if k not in names:
            raise TypeError(f"CubicSpline() got an unexpected keyword argument {k!r}")
        a[k] = v
    if "x" not in a or "y" not in a:
        raise TypeError("CubicSpline() needs x and y")
    pts, tail = _data(a["y"], a.get("axis", 0), "y")
    bc = a.get("bc_type", "not-a-knot")
    extrapolate = a.get("extrapolate")
    if extrapolate is None:
        extrapolate = "periodic" if bc == "periodic" else True
    try:
        _CUBIC_BASE.__init__(self, params=np.asarray(a["x"], dtype=np.float64), points=pts, **_bc(bc, pts.shape[1]))
    except Error as e:
        raise _renamed(e, {"params": "x", "points": "y", "boundary": "bc_type", "start_derivative": "bc_type",
                           "end_derivative": "bc_type"}, tail == ()) from None
    self._sp = PPoly(Curve._wrap(self._c), tail, extrapolate)
    self.x = np.asarray(a["x"], dtype=np.float64)
    self.axis = a.get("axis", 0)


def _ppoly_c(self: Any) -> np.ndarray:
    """scipy's PPoly coefficients (made scipy's way; see PPoly.c)."""
    if self._sp is None:
        raise AttributeError("c: CubicSpline made from the library's fields has no scipy coefficients")
    return self._sp.c


CubicSpline = _subclass("cubic_spline", _ScipyCurve, _cubic_init, """The C^2 cubic interpolating spline.

scipy's form ``CubicSpline(x, y, axis=0, bc_type='not-a-knot', extrapolate=None)`` returns
scipy's shapes; the library's ``CubicSpline(params=, points=, boundary=, ...)`` (keywords:
the curve-JSON fields) returns points of shape (..., d).

>>> import numpy as np, casteljau
>>> s = casteljau.CubicSpline([0, 1, 2, 3], [0, 1, 8, 27])
>>> round(float(s(1.5)), 12)  # not-a-knot on 4 points: the cubic x^3 itself
3.375
""", {"c": property(_ppoly_c)})


def _bspline_init(self: Any, *args: Any, **kw: Any) -> None:
    if not _scipy_mode(self, args, kw, {"t", "c", "k", "extrapolate", "axis"}):
        _BSPLINE_BASE.__init__(self, **kw)
        self._sp = None
        return
    names = ("t", "c", "k", "extrapolate", "axis")
    a = dict(zip(names, args))
    for key, v in kw.items():
        if key not in names:
            raise TypeError(f"BSpline() got an unexpected keyword argument {key!r}")
        a[key] = v
    if not {"t", "c", "k"} <= set(a):
        raise TypeError("BSpline() needs t, c and k")
    t = np.asarray(a["t"], dtype=np.float64)
    k = a["k"]
    if isinstance(k, float) and k.is_integer():
        k = int(k)
    if not isinstance(k, (int, np.integer)) or isinstance(k, bool):
        raise Error(f"k: must be an integer, got {k!r}")
    pts, tail = _data(a["c"], a.get("axis", 0), "c")
    n = len(t) - int(k) - 1
    if n >= 1 and len(pts) > n:
        pts = pts[:n]  # scipy ignores the coefficients beyond len(t) - k - 1
    try:
        _BSPLINE_BASE.__init__(self, degree=int(k), knots=t, points=pts)
    except Error as e:
        raise _renamed(e, {"knots": "t", "points": "c", "degree": "k"}, tail == ()) from None
    ext = a.get("extrapolate", True)
    self._sp = PPoly(Curve._wrap(self._c), tail, ext)
    self.t, self.c, self.k = t, np.asarray(a["c"], dtype=np.float64), int(k)
    self.extrapolate = ext


BSpline = _subclass("bspline", _ScipyCurve, _bspline_init, """A B-spline.

scipy's form ``BSpline(t, c, k, extrapolate=True, axis=0)`` returns scipy's shapes; the
library's ``BSpline(degree=, knots=, points=)`` returns points of shape (..., d).

>>> import casteljau
>>> b = casteljau.BSpline([0, 0, 0, 1, 1, 1], [0.0, 1.0, 0.0], 2)
>>> float(b(0.5))
0.5
""")


def make_interp_spline(x: Any, y: Any, k: int = 3, t: Any = None, bc_type: Any = None, axis: int = 0) -> Any:
    """scipy's interpolating B-spline of degree k (without t: the knots scipy chooses), the
    collocation matrix from the registry's basis command, solved by numpy."""
    if bc_type is not None:
        raise Error("bc_type: only None (scipy's default, not-a-knot) is supported yet")
    x = np.asarray(x, dtype=np.float64)
    pts, tail = _data(y, axis, "y")
    if not isinstance(k, (int, np.integer)) or k < 0:
        raise Error(f"k: must be an integer >= 0, got {k!r}")
    if t is None:
        # scipy's choices: k = 2 the midpoints without the first and last, odd k not-a-knot
        # (the data's sites without (k - 1) / 2 at each end).
        if k == 0:
            # scipy's knots x and x[-1] repeat the last knot twice, which the library's
            # bspline refuses at degree 0 (an end knot at most p + 1 times).
            raise Error("k: 0 is not supported yet (scipy's knots repeat the last point)")
        if k == 2:
            mid = (x[1:] + x[:-1]) / 2
            t = np.r_[(x[0],) * 3, mid[1:-1], (x[-1],) * 3]
        elif k % 2 == 1:
            m = (k - 1) // 2
            t = np.r_[(x[0],) * (k + 1), x[m + 1 : len(x) - m - 1], (x[-1],) * (k + 1)]
        else:
            raise Error(f"k: even degrees above 2 need t (got {k})")
    t = np.asarray(t, dtype=np.float64)
    if len(x) != len(pts):
        raise Error(f"x: {len(x)} values but y has {len(pts)}")
    try:
        A = _casteljau.run("basis", _dumps({"kind": "bspline", "degree": int(k), "knots": t, "t": x}))
    except Error as e:
        raise _renamed(e, {"knots": "t", "t": "x", "degree": "k"}, False) from None
    A = np.array(json.loads(A)["values"], dtype=np.float64)
    if A.shape != (len(x), len(x)):
        raise Error(f"t: {len(t)} knots give {A.shape[1]} basis functions for {len(x)} points")
    c = np.linalg.solve(A, pts)
    return BSpline(t, c.reshape((len(c),) + tail), int(k))


def _hermite_interpolator(rule: str, default_extrapolate: bool, name: str) -> type:
    def __init__(self: Any, x: Any, y: Any, axis: int = 0, extrapolate: Any = None) -> None:
        pts, tail = _data(y, axis, "y")
        try:
            curve = _CLASSES["hermite"](params=np.asarray(x, dtype=np.float64), points=pts, tangent_rule=rule)
        except Error as e:
            raise _renamed(e, {"params": "x", "points": "y"}, tail == ()) from None
        PPoly.__init__(self, curve, tail, default_extrapolate if extrapolate is None else extrapolate)
        self.axis = axis

    return type(name, (PPoly,), {"__init__": __init__, "__module__": "casteljau",
                                 "__doc__": f"scipy's {name}: the library's hermite curve with tangent_rule {rule!r}."})


PchipInterpolator = _hermite_interpolator("monotone", True, "PchipInterpolator")
Akima1DInterpolator = _hermite_interpolator("akima", False, "Akima1DInterpolator")


class BarycentricInterpolator(PPoly):
    """scipy's BarycentricInterpolator(xi, yi, axis=0): the library's lagrange curve (the
    polynomial through the points; at most 16 points)."""

    def __init__(self, xi: Any, yi: Any = None, axis: int = 0) -> None:
        if yi is None:
            raise Error("yi: required (set_yi is not supported yet)")
        pts, tail = _data(yi, axis, "yi")
        try:
            curve = _CLASSES["lagrange"](params=np.asarray(xi, dtype=np.float64), points=pts)
        except Error as e:
            raise _renamed(e, {"params": "xi", "points": "yi"}, tail == ()) from None
        super().__init__(curve, tail, True)
        self.xi = np.asarray(xi, dtype=np.float64)

    def __call__(self, x: Any) -> np.ndarray:  # type: ignore[override]
        return super().__call__(x)
