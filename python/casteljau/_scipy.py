"""scipy.interpolate's names and conventions over the library's curves (docs/python.md,
"Coming from scipy"): ``CubicSpline(x, y, bc_type=...)``, ``BSpline(t, c, k)``,
``make_interp_spline(x, y, k)``, ``PchipInterpolator``, ``Akima1DInterpolator``,
``BarycentricInterpolator``. Data y of shape (n, ...) along ``axis`` is the library's
curve of dimension m = prod(y.shape[1:]) over the parameters x (above the library's 4
coordinates, one curve per group of at most 4 columns: interpolation is coordinate-wise,
see _Columns); calls return scipy's shapes (x.shape + y.shape[1:], a 0-d array for 1-D
data and a number). Errors name the arguments as scipy's callers write them (``x[3]``,
``y[2]``, ``t[3]``, ``c``, ``k``).
"""

from __future__ import annotations

import math
import re
from typing import Any

import numpy as np

from . import _casteljau
from ._casteljau import Error
from ._curves import _CLASSES, Curve, curve_classes

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


def _axis(y: Any, axis: Any) -> int:
    """scipy's axis, normalised to [0, ndim) (checked by _data)."""
    return int(axis) % max(np.ndim(y), 1)


def _data(y: Any, axis: int, name: str) -> tuple[np.ndarray, tuple]:
    """y as (n, m) points along axis, and the trailing shape of one value."""
    y = np.asarray(y, dtype=np.float64)
    if y.ndim == 0:
        raise Error(f"{name}: must be an array of at least one dimension, got a scalar")
    if isinstance(axis, bool) or not isinstance(axis, (int, np.integer)) or not -y.ndim <= axis < y.ndim:
        raise Error(f"axis: must be an integer in [{-y.ndim}, {y.ndim - 1}] for {name} of shape {y.shape}, got {axis!r}")
    y = np.moveaxis(y, axis, 0)
    tail = y.shape[1:]
    m = math.prod(tail)
    if m == 0:
        raise Error(f"{name}: values of shape {tail} have no numbers")
    return y.reshape(len(y), m), tail


_MAX_DIM = _casteljau.max_dimension


class _Columns:
    """Values of more than the library's 4 numbers per point (scipy accepts any trailing
    shape of y): the interpolation of each coordinate depends on that coordinate's data
    alone (one matrix for all columns in a spline, per-column slopes in PCHIP and Akima,
    per-column sums in the barycentric formula), so the m columns are split into groups of
    at most 4, one library curve each, and the answers joined column-wise. The part of a
    PPoly's curve that it calls: evaluation, derivative, domain (and _bezier_pieces,
    _integral, _hermite_ends below)."""

    def __init__(self, parts: list) -> None:
        self.parts = list(parts)

    @property
    def dim(self) -> int:
        return sum(p.dim for p in self.parts)

    @property
    def domain(self) -> tuple[float, float]:
        return self.parts[0].domain

    def __call__(self, t: Any, nu: int = 0) -> np.ndarray:
        return np.concatenate([p(t, nu) for p in self.parts], axis=-1)

    def derivative(self, k: int = 1) -> "_Columns":
        return _Columns([p.derivative(k) for p in self.parts])


def _columns(make: Any, pts: np.ndarray) -> Any:
    """make(points, first column) for the data (n, m): one curve when m <= 4, else a
    _Columns of one curve per group of at most 4 columns (an error's column index,
    "points[2][1]", made the data's: "points[2][5]" in the second group)."""
    m = pts.shape[1]
    if m <= _MAX_DIM:
        return make(pts, 0)
    parts = []
    for j in range(0, m, _MAX_DIM):
        try:
            parts.append(make(np.ascontiguousarray(pts[:, j:j + _MAX_DIM]), j))
        except Error as e:
            raise Error(re.sub(r"^(\w+\[\d+\])\[(\d+)\]", lambda g: f"{g.group(1)}[{int(g.group(2)) + j}]",
                               str(e), count=1)) from None
    return _Columns(parts)


class _TooWide:
    """The library curve under a CubicSpline or BSpline made scipy's way from more than 4
    numbers per point: there is none (the values are a _Columns of curves), so the
    library's own methods (length, bounds, to_json, ...) raise, naming the data, where
    they would otherwise answer for the first 4 columns only."""

    def __init__(self, name: str, field: str, tail: tuple) -> None:
        self.name, self.field, self.tail = name, field, tail

    def __getattr__(self, attr: str) -> Any:
        if attr.startswith("__"):
            raise AttributeError(attr)
        raise Error(f"{self.field}: values of shape {self.tail} ({math.prod(self.tail)} numbers per point): this "
                    f"{self.name} answers scipy's calls (evaluation, derivative, antiderivative, integrate, "
                    f"roots), not the library's curve methods, whose curves have 1 to {_MAX_DIM} coordinates")


def _set_core(self: Any, curve: Any, name: str, field: str, tail: tuple) -> Any:
    """Makes self (a CubicSpline or BSpline made scipy's way) the curve built by _columns;
    the curve to put under its PPoly."""
    self._json = None
    if isinstance(curve, _Columns):
        self._c = _TooWide(name, field, tail)
        return curve
    self._c = curve._c
    return Curve._wrap(self._c)


class PPoly:
    """A scipy-shaped piecewise polynomial over a library curve (what derivative() and
    antiderivative() return, in place of scipy's PPoly or BSpline): callable with scipy's
    shapes, with derivative, antiderivative, integrate and roots."""

    def __init__(self, curve: Curve, tail: tuple, extrapolate: Any = True, axis: int = 0,
                 ends: tuple | None = None) -> None:
        if isinstance(curve, (np.ndarray, list, tuple)):  # scipy's PPoly(c, x): not a constructor here
            raise TypeError("PPoly(c, x) is not supported (scipy's coefficient form); PPoly objects come from "
                            "derivative() and antiderivative() of the scipy-named classes")
        self._curve = curve
        self._tail = tail
        self.extrapolate = extrapolate
        self.axis = axis  # scipy's: the interpolation axis of y, where x's axes go in the answer
        lo, hi = curve.domain
        self._lo, self._hi = lo, hi
        self._clip_integral = False  # True under a BSpline (scipy's BSpline.integrate clips)
        # How scipy continues the function outside [lo, hi] (see _outside): ("power",
        # (x0, c0), (x1, c1)) the end pieces' power coefficients (highest first, shape
        # (k + 1, m)) about their left breaks, or ("bspline", t, c, k); None: the curve's own.
        # A callable gives them at the first call outside (a spline's slopes come from the
        # eval command, which writes the curve's JSON).
        self._ends = ends

    def _ends_now(self) -> tuple | None:
        if callable(self._ends):
            self._ends = self._ends()
        return self._ends

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
        if ext is True and self._ends is not None and x.size:
            # Outside the domain scipy's own continuation of the end pieces (the curve's
            # extrapolation is exact too, but far out the two round differently).
            xf = x.reshape(-1)
            if x.size == 1:
                beyond = not self._lo <= float(xf[0]) <= self._hi  # the per-call path: no array masks
            else:
                beyond = bool(xf.min() < self._lo or xf.max() > self._hi)
            if beyond and self._ends_now() is not None:
                flat = out.reshape(-1, out.shape[-1])
                outside = (xf < self._lo) | (xf > self._hi)
                flat[outside] = _outside(self._ends_now(), xf[outside], self._lo, int(nu))
        out = out.reshape(x.shape + self._tail)
        if ext is False or ext is None:
            outside = (x < self._lo) | (x > self._hi)
            if outside.any():
                out[outside] = np.nan
        if self.axis and out.ndim > x.ndim:
            # scipy's order: y's axes before the interpolation axis, then x's, then the rest.
            ax = list(range(out.ndim))
            out = out.transpose(ax[x.ndim:x.ndim + self.axis] + ax[:x.ndim] + ax[x.ndim + self.axis:])
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

    def _column(self, j: int) -> "PPoly":
        """The 1-D PPoly of the flat column j of the values (from the exact Bezier pieces)."""
        breaks, pieces = _bezier_pieces(self._curve)
        segs = [{"type": "bezier", "points": P[:, j:j + 1]} for P in pieces]
        curve = Curve.from_json({"type": "path", "segments": segs, "breaks": breaks})
        out = PPoly(curve, (), self.extrapolate, 0, _column_ends(self._ends_now(), j))
        out._lo, out._hi, out._clip_integral = self._lo, self._hi, self._clip_integral
        return out

    def derivative(self, nu: int = 1) -> "PPoly":
        ends = None
        own = self._ends
        if own is not None and nu >= 0:
            # scipy's PPoly.derivative: the coefficients of the powers >= nu times the
            # falling factorials.
            ends = _LazyEnds("derivative", own, nu)
        return PPoly(self._curve.derivative(nu), self._tail, self.extrapolate, self.axis, ends)

    def antiderivative(self, nu: int = 1) -> "PPoly":
        c = self._curve
        for _ in range(nu):
            c = _integral(c)
        ends = None
        own = self._ends
        if own is not None and nu >= 1:
            # scipy's PPoly.antiderivative: the coefficients over the rising factorials, the
            # powers below nu 0 on the first piece and, on the last, the Taylor
            # coefficients of the antiderivative at its left break (continuity).
            ends = _LazyEnds("antiderivative", own, nu, c)
        # extrapolate='periodic' becomes False (the integral is not periodic), as scipy's.
        ext = False if self.extrapolate == "periodic" else self.extrapolate
        return PPoly(c, self._tail, ext, self.axis, ends)

    def integrate(self, a: float, b: float, extrapolate: Any = None) -> np.ndarray:
        ext = self.extrapolate if extrapolate is None else extrapolate
        if ext is False:
            if self._clip_integral:  # scipy's BSpline: the integral over [a, b] clipped to the base interval
                a, b = (min(max(v, self._lo), self._hi) for v in (a, b))
            elif not (self._lo <= a <= self._hi and self._lo <= b <= self._hi):
                return np.full(self._tail, np.nan)  # scipy's PPoly: NaN once a or b leaves [x[0], x[-1]]
        F = _integral(self._curve)
        if ext == "periodic":
            return _periodic_integral(F, self._lo, self._hi, a, b).reshape(self._tail)
        return (F(b) - F(a)).reshape(self._tail)

    def roots(self, discontinuity: bool = True, extrapolate: Any = None) -> np.ndarray:
        """The zeros of 1-D data, ascending: solve(0)."""
        return self.solve(0.0, discontinuity, extrapolate)

    def solve(self, y: float = 0.0, discontinuity: bool = True, extrapolate: Any = None) -> np.ndarray:
        """scipy's PPoly.solve: the x where the function equals y, ascending (the registry's
        solve command on the domain; with extrapolate=True, also those of the end pieces
        continued beyond it); for data of several values per point, scipy's object array
        of y's trailing shape holding each value's roots."""
        y = float(y)
        if not math.isfinite(y):
            raise Error(f"y: must be a finite number, got {y}")
        if self._tail != ():
            out = np.empty(self._tail, dtype=object)
            for j in range(out.size):
                out.flat[j] = self._column(j).solve(y, discontinuity, extrapolate)
            return out
        ext = self.extrapolate if extrapolate is None else extrapolate
        r = self._curve.solve(y, 0)
        roots = list(np.asarray(getattr(r, "t"), dtype=np.float64))
        if ext is True:
            roots += _end_roots(self._curve, y)
        # A stretch where the function is identically y: scipy's "start point followed by
        # nan" (the registry's solve reports it as an interval, not in t).
        starts = [float(a) for a, _ in np.asarray(getattr(r, "intervals", np.zeros((0, 2))), dtype=np.float64).reshape(-1, 2)]
        out = []
        for v, stretch in sorted([(v, False) for v in roots] + [(a, True) for a in starts]):
            out += [v, math.nan] if stretch else [v]
        return np.array(out, dtype=np.float64)


def _column_ends(ends: tuple | None, j: int) -> tuple | None:
    """PPoly._ends for the column j alone."""
    if ends is None:
        return None
    if ends[0] == "power":
        return ("power",) + tuple((x0, c[:, j:j + 1]) for x0, c in ends[1:])
    _, t, c, k = ends
    return ("bspline", t, c[:, j:j + 1], k)


class _LazyEnds:
    """The ends of a PPoly (see PPoly._ends) made at the first call outside the domain,
    picklable: "hermite" from a C^1 cubic's slopes (_hermite_ends), "derivative" and
    "antiderivative" from another PPoly's ends (scipy's PPoly.derivative and
    antiderivative on the power coefficients)."""

    def __init__(self, kind: str, *args: Any) -> None:
        self.kind, self.args = kind, args

    def __call__(self) -> tuple | None:
        if self.kind == "hermite":
            return _hermite_ends(*self.args)
        own, nu = self.args[:2]
        e = own() if callable(own) else own
        if e is None or e[0] != "power":
            return None
        if self.kind == "derivative":
            return ("power",) + tuple((x0, _power_derivative(c, nu)) for x0, c in e[1:])
        curve = self.args[2]
        (x0, c0), (x1, c1) = e[1:]
        low = np.array([curve(x1, nu=j).reshape(-1) / math.factorial(j) for j in range(nu - 1, -1, -1)])
        return ("power", (x0, np.vstack([_power_integral(c0, nu), np.zeros((nu, c0.shape[1]))])),
                (x1, np.vstack([_power_integral(c1, nu), low])))


def _power_derivative(c: np.ndarray, nu: int) -> np.ndarray:
    """scipy's PPoly.derivative on one piece's power coefficients (highest first)."""
    k = c.shape[0] - 1
    if nu > k:
        return np.zeros((1, c.shape[1]))
    out = c[: k + 1 - nu].copy()
    for i in range(len(out)):
        out[i] *= float(math.prod(range(k - i - nu + 1, k - i + 1)))
    return out


def _power_integral(c: np.ndarray, nu: int) -> np.ndarray:
    """scipy's PPoly.antiderivative on one piece's power coefficients (highest first),
    without the nu new lowest ones."""
    k = c.shape[0] - 1
    out = c.copy()
    for i in range(len(out)):
        out[i] /= float(math.prod(range(k - i + 1, k - i + nu + 1)))
    return out


def _outside(ends: tuple, x: np.ndarray, lo: float, nu: int) -> np.ndarray:
    """The values (order nu) at x, outside the domain [lo, ...], as scipy continues the end
    pieces: a PPoly's power form about the piece's left break, summed from the lowest
    power up with the powers of s = x - x0 accumulated by products (scipy's
    evaluate_poly1), or a BSpline's basis functions of the end span by the Cox-de Boor
    recursion (derivatives by differentiating its last nu steps), times the coefficients."""
    left = x < lo
    if ends[0] == "power":
        (x0, c0), (x1, c1) = ends[1:]
        out = np.empty((len(x), c0.shape[1]))
        for sel, xa, c in ((left, x0, c0), (~left, x1, c1)):
            if sel.any():
                s = (x[sel] - xa)[:, None]
                k = c.shape[0] - 1
                res = np.zeros((len(s), c.shape[1]))
                z = np.ones_like(s)
                for p in range(nu, k + 1):
                    res = res + c[k - p] * z * float(math.prod(range(p - nu + 1, p + 1)))
                    if p < k:
                        z = z * s
                out[sel] = res
        return out
    _, t, c, k = ends
    n = len(t) - k - 1
    out = np.zeros((len(x), c.shape[1]))
    if nu > k:
        return out
    for sel, ell in ((left, k), (~left, n - 1)):
        if not sel.any():
            continue
        xs = x[sel]
        h = [np.ones_like(xs)] + [np.zeros_like(xs) for _ in range(k)]
        for j in range(1, k + 1):
            hh = h[:j]
            h = [np.zeros_like(xs)] + h[1:]
            for m in range(1, j + 1):
                xb, xa = t[ell + m], t[ell + m - j]
                if xb == xa:
                    h[m] = np.zeros_like(xs)
                    continue
                if j <= k - nu:
                    w = hh[m - 1] / (xb - xa)
                    h[m - 1] = h[m - 1] + w * (xb - xs)
                    h[m] = w * (xs - xa)
                else:
                    w = j * hh[m - 1] / (xb - xa)
                    h[m - 1] = h[m - 1] - w
                    h[m] = w
        res = np.zeros((len(xs), c.shape[1]))
        for a in range(k + 1):
            res = res + c[ell - k + a] * h[a][:, None]
        out[sel] = res
    return out


def _hermite_ends(curve: Curve, x: np.ndarray, y: np.ndarray) -> tuple:
    """scipy's CubicHermiteSpline coefficients of the first and last pieces of a C^1
    piecewise cubic (cubic_spline or hermite curve) through y (n, m) at x: from the values
    and the first derivatives at their ends (the eval command's derivatives, the curve's
    own slopes at the params), as scipy computes them."""
    n = len(x)
    idx = [0, 1, n - 2, n - 1]
    parts = curve.parts if isinstance(curve, _Columns) else [curve]
    d = np.concatenate([np.asarray(_casteljau.run("eval", {"curve": c, "t": x[idx], "derivatives": 1})["derivatives"],
                                   dtype=np.float64).reshape(4, -1) for c in parts], axis=1)

    def coef(i: int, d0: np.ndarray, d1: np.ndarray) -> tuple:
        dx = x[i + 1] - x[i]
        slope = (y[i + 1] - y[i]) / dx
        t = (d0 + d1 - 2 * slope) / dx
        return float(x[i]), np.array([t / dx, (slope - d0) / dx - t, d0, y[i]])

    return ("power", coef(0, d[0], d[1]), coef(n - 2, d[2], d[3]))


def _bezier_pieces(c: Any) -> tuple[list, list]:
    if isinstance(c, _Columns):
        # The groups of columns share the breaks and the pieces' degrees (the same x, knots
        # and construction): their pieces side by side.
        each = [_bezier_pieces(p) for p in c.parts]
        breaks = each[0][0]
        if any(len(b) != len(breaks) or any(len(P) != len(Q) for P, Q in zip(ps, each[0][1])) for b, ps in each):
            raise Error("curve: the groups of columns have different pieces")
        return breaks, [np.hstack(group) for group in zip(*(ps for _, ps in each))]
    j = c.to_bezier().to_json()
    for s in j["segments"]:
        if s["type"] != "bezier":
            raise Error("curve: needs a polynomial curve (this one has rational pieces)")
    return j["breaks"], [np.array(s["points"], dtype=np.float64) for s in j["segments"]]


def _integral(c: Any) -> Any:
    """The antiderivative that is 0 at the domain's start, as a path of Bezier pieces: on
    the break interval of width h a degree-n piece b_0..b_n integrates to the degree n + 1
    piece A_0 = F(start), A_(j+1) = A_j + h b_j / (n + 1)."""
    if isinstance(c, _Columns):
        return _Columns([_integral(p) for p in c.parts])
    breaks, pieces = _bezier_pieces(c)
    segs = []
    start = np.zeros(pieces[0].shape[1])
    for i, P in enumerate(pieces):
        h = breaks[i + 1] - breaks[i]
        A = np.vstack([start, start + np.cumsum(P, axis=0) * (h / len(P))])
        segs.append({"type": "bezier", "points": A})
        start = A[-1]
    return Curve.from_json({"type": "path", "segments": segs, "breaks": breaks})


def _periodic_integral(F: Curve, lo: float, hi: float, a: float, b: float) -> np.ndarray:
    """The integral from a to b of the function of period hi - lo whose antiderivative on
    [lo, hi] is F: whole periods, then the rest from a mapped into [lo, hi] (wrapping
    past hi at most once)."""
    sign = 1.0
    if b < a:
        a, b, sign = b, a, -1.0
    period = hi - lo
    periods, rest = divmod(b - a, period)
    whole = F(hi) - F(lo)
    a = lo + (a - lo) % period
    b = a + rest
    part = F(b) - F(a) if b <= hi else (F(hi) - F(a)) + (F(lo + (b - hi)) - F(lo))
    return sign * (periods * whole + part)


def _end_roots(c: Curve, y: float = 0.0) -> list:
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
        coef[0] -= y
        # A leading coefficient of rounding size (linear data through a cubic spline leaves
        # about 1e-15 on s^3 and s^2) is no degree: kept, it adds a root of size 1 / it
        # (CubicSpline([0, 1, 2, 3], [0, 1, 2, 3]).roots() had one at 3.4e7). In s, every
        # term is at most |coef| on the piece, so one below 1e-13 of the largest is noise.
        nz = np.flatnonzero(np.abs(coef) > 1e-13 * np.max(np.abs(coef)))
        if len(nz) == 0 or nz[-1] == 0:
            continue
        for s in np.roots(coef[: nz[-1] + 1][::-1]):
            # A real root comes out of the companion matrix with an imaginary part of
            # rounding size (1e-12 relative: far above it, far below a true complex pair's).
            real = abs(s.imag) <= 1e-12 * max(1.0, abs(s.real))
            # Beyond the end by more than rounding: a root at the end itself comes from the
            # domain's solve (kept here too, it was reported twice: 1 + 2e-16).
            if real and ((side < 0 and s.real < -1e-12) or (side > 0 and s.real > 1 + 1e-12)):
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
        if isinstance(self._c, _TooWide):  # more than 4 numbers per point: scipy's state alone
            return (_restore_wide, (type(self), vars(self._c), self.__dict__))
        return (_restore, (self._c.to_json(), self.__dict__))

    def __repr__(self) -> str:
        if isinstance(self._c, _TooWide):
            return f"<casteljau.{type(self).__name__} made scipy's way, values of shape {self._c.tail}>"
        return Curve.__repr__(self)

    def __eq__(self, other: object) -> bool:
        if isinstance(self._c, _TooWide) or isinstance(getattr(other, "_c", None), _TooWide):
            return self is other
        return Curve.__eq__(self, other)

    __hash__ = None  # type: ignore[assignment]

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

    def solve(self, *args: Any, **kw: Any) -> Any:
        """Made scipy's way: scipy's PPoly.solve(y, discontinuity=True, extrapolate=None);
        otherwise the registry's solve(value, axis)."""
        if self._sp is None:
            return super().solve(*args, **kw)
        return self._sp.solve(*args, **kw)


def _restore_wide(cls: type, core: dict, state: dict) -> Any:
    c = object.__new__(cls)
    c._c = _TooWide(**core)
    c._json = None
    c.__dict__.update(state)
    return c


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
        if isinstance(bc_type[0], str) and isinstance(bc_type[1], str) and bc_type[0] == bc_type[1]:
            return _bc(bc_type[0], m)
        ends = {}
        for side, b in zip(("start", "end"), bc_type):
            if b == "natural":
                b = (2, 0.0)
            elif b == "clamped":
                b = (1, 0.0)
            elif isinstance(b, str):
                raise Error(f"bc_type: {b!r} at one end only is not supported (natural, clamped, not-a-knot or "
                            "(order, value))")
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
    x = np.asarray(a["x"], dtype=np.float64)
    m = pts.shape[1]
    one_not_a_knot = isinstance(bc, (tuple, list)) and len(bc) == 2 and sum(
        isinstance(b, str) and b == "not-a-knot" for b in bc) == 1

    def make(p: np.ndarray, j: int) -> Curve:
        # The end values of bc_type for these columns of the data (all of them when m <= 4).
        b = _bc_columns(bc, m, slice(j, j + p.shape[1])) if m > _MAX_DIM else bc
        if one_not_a_knot:
            b = _one_not_a_knot(x, p, b)
        return _CUBIC_BASE(params=x, points=p, **_bc(b, p.shape[1]))

    try:
        curve = _set_core(self, _columns(make, pts), "CubicSpline", "y", tail)
    except Error as e:
        raise _renamed(e, {"params": "x", "points": "y", "boundary": "bc_type", "start_derivative": "bc_type",
                           "end_derivative": "bc_type"}, tail == ()) from None
    self.axis = _axis(a["y"], a.get("axis", 0))
    self._sp = PPoly(curve, tail, extrapolate, self.axis, _LazyEnds("hermite", curve, x, pts))
    self.x = np.asarray(a["x"], dtype=np.float64)


def _bc_columns(bc_type: Any, m: int, cols: slice) -> Any:
    """scipy's bc_type for the columns cols of data with m numbers per point: each
    (order, value) end's value (a number or y's trailing shape) flattened as the data
    and cut to those columns; strings as they are."""
    if not isinstance(bc_type, (tuple, list)) or len(bc_type) != 2:
        return bc_type
    out = []
    for b in bc_type:
        if isinstance(b, str) or not isinstance(b, (tuple, list)) or len(b) != 2:
            out.append(b)
            continue
        v = np.asarray(b[1], dtype=np.float64).reshape(-1)
        if v.size not in (1, m):
            raise Error(f"bc_type: an end's value must be a number or have y's {m} numbers per point, got {v.size}")
        out.append((b[0], np.broadcast_to(v, (m,))[cols]))
    return tuple(out)


def _one_not_a_knot(x: np.ndarray, pts: np.ndarray, bc: Any) -> tuple:
    """scipy's bc_type with 'not-a-knot' at one end only, as a pair without it: that end's
    first derivative s. The spline is affine in s, and so is the jump of its third
    derivative at the knot next to that end, which not-a-knot sets to 0: two splines (s = 0
    and s = 1, the other end as given) give the jump's two values, and s the root of the
    line through them (per coordinate: they do not mix). Two points: the chord's slope
    (scipy's rule)."""
    side = 0 if bc[0] == "not-a-knot" else 1
    other = bc[1 - side]
    m = pts.shape[1]
    if len(x) < 2 or len(pts) != len(x):
        return bc  # the library's own error names the arguments
    if len(x) == 2:
        slope = (pts[1] - pts[0]) / (x[1] - x[0])
        ends = [(1, slope), other] if side == 0 else [other, (1, slope)]
        return tuple(ends)
    jumps = []
    for s in (np.zeros(m), np.ones(m)):
        ends = [(1, s), other] if side == 0 else [other, (1, s)]
        trial = _CUBIC_BASE(params=x, points=pts, **_bc(tuple(ends), m))
        c = PPoly(Curve._wrap(trial._c), (m,)).c  # (4, pieces, m): c[0] the cubic coefficients
        jumps.append(c[0, 1] - c[0, 0] if side == 0 else c[0, -1] - c[0, -2])
    j0, j1 = jumps
    slope = -j0 / (j1 - j0)
    ends = [(1, slope), other] if side == 0 else [other, (1, slope)]
    return tuple(ends)


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
    if k >= 0 and len(pts) < int(k) + 1:
        raise Error(f"c: needs at least k + 1 = {int(k) + 1} coefficients, got {len(pts)}")
    if n >= 1 and len(pts) > n:
        pts = pts[:n]  # scipy ignores the coefficients beyond len(t) - k - 1
    try:
        curve = _set_core(self, _columns(lambda p, j: _BSPLINE_BASE(degree=int(k), knots=t, points=p), pts),
                          "BSpline", "c", tail)
    except Error as e:
        raise _renamed(e, {"knots": "t", "points": "c", "degree": "k"}, tail == ()) from None
    ext = a.get("extrapolate", True)
    self.axis = _axis(a["c"], a.get("axis", 0))
    self._sp = PPoly(curve, tail, ext, self.axis, ("bspline", t, pts, int(k)))
    self._sp._clip_integral = True
    # scipy's attributes: c with the interpolation axis first.
    self.t, self.c, self.k = t, np.moveaxis(np.asarray(a["c"], dtype=np.float64), self.axis, 0), int(k)
    self.extrapolate = ext


def _bspline_derivative(self: Any, nu: int = 1) -> Any:
    """scipy's BSpline.derivative: a BSpline of degree k - nu on t[nu:-nu] (made the
    library's way: the derivative curve). The coefficients by the B-spline derivative
    formula [PT97, (3.4)]: c'_i = k (c_(i+1) - c_i) / (t_(i+k+1) - t_(i+1)), 0 where the
    knots coincide (that basis function is 0)."""
    if self._sp is None:
        return Curve.derivative(self, nu)
    if isinstance(nu, bool) or not isinstance(nu, (int, np.integer)) or nu < 0:
        raise Error(f"nu: must be an integer >= 0, got {nu!r}")
    if nu > self.k:
        raise Error(f"nu: the order of the derivative must be <= k = {self.k}, got {nu}")
    t, k = self.t, self.k
    n = len(t) - k - 1
    c = self.c[:n]
    for _ in range(nu):
        dt = t[k + 1 : k + len(c)] - t[1 : len(c)]
        dt = dt.reshape((-1,) + (1,) * (c.ndim - 1))
        safe = np.where(dt > 0, dt, 1.0)
        c = np.where(dt > 0, k * (c[1:] - c[:-1]) / safe, 0.0)
        t, k = t[1:-1], k - 1
    return BSpline(t, np.moveaxis(c, 0, self.axis), k, extrapolate=self.extrapolate, axis=self.axis)


def _bspline_antiderivative(self: Any, nu: int = 1) -> Any:
    """scipy's BSpline.antiderivative: a BSpline of degree k + nu, each end knot once more
    per order (made the library's way: a PPoly over the integral's Bezier pieces). The
    coefficients by the B-spline integral [deBoor78]: the integral of sum c_i
    B_(i,k) from t_0 is sum d_i B_(i,k+1) on the knots (t_0, t, t_last), d_0 = 0 and
    d_(i+1) = d_i + c_i (t_(i+k+1) - t_i) / (k + 1). extrapolate='periodic' becomes False
    (the integral is not periodic), as scipy's."""
    if self._sp is None:
        return _ScipyCurve.antiderivative(self, nu)
    if isinstance(nu, bool) or not isinstance(nu, (int, np.integer)) or nu < 0:
        raise Error(f"nu: must be an integer >= 0, got {nu!r}")
    t, k = self.t, self.k
    n = len(t) - k - 1
    c = self.c[:n]
    for _ in range(nu):
        dt = (t[k + 1 : k + 1 + len(c)] - t[: len(c)]).reshape((-1,) + (1,) * (c.ndim - 1))
        c = np.concatenate([np.zeros((1,) + c.shape[1:]), np.cumsum(c * dt, axis=0) / (k + 1)])
        t, k = np.r_[t[0], t, t[-1]], k + 1
    # An end knot repeated more than k + 1 times (make_interp_spline's k = 0 knots end with
    # x[-1] twice) spans basis functions that vanish: dropped with their coefficients, the
    # function on the base interval is the same (from its end on scipy's zero-length last
    # span gives 0, ours continues the last piece).
    while len(t) > k + 2 and np.count_nonzero(t == t[-1]) > k + 1:
        t, c = t[:-1], c[:-1]
    while len(t) > k + 2 and np.count_nonzero(t == t[0]) > k + 1:
        t, c = t[1:], c[1:]
    return BSpline(t, np.moveaxis(c[: len(t) - k - 1], 0, self.axis), k,
                   extrapolate=False if self.extrapolate == "periodic" else self.extrapolate, axis=self.axis)


BSpline = _subclass("bspline", _ScipyCurve, _bspline_init, """A B-spline.

scipy's form ``BSpline(t, c, k, extrapolate=True, axis=0)`` returns scipy's shapes; the
library's ``BSpline(degree=, knots=, points=)`` returns points of shape (..., d).

>>> import casteljau
>>> b = casteljau.BSpline([0, 0, 0, 1, 1, 1], [0.0, 1.0, 0.0], 2)
>>> float(b(0.5))
0.5
>>> type(b.derivative()).__name__, b.derivative().k  # a BSpline, as scipy's
('BSpline', 1)
""", {"derivative": _bspline_derivative, "antiderivative": _bspline_antiderivative})


def _end_derivatives(b: Any, m: int, side: str) -> list:
    """One end of make_interp_spline's bc_type as [(order, value (m,)), ...]."""
    if b is None:
        return []
    if isinstance(b, str):
        if b == "clamped":
            return [(1, np.zeros(m))]
        if b == "natural":
            return [(2, np.zeros(m))]
        raise Error(f"bc_type: unknown end condition {b!r} at the {side} ('clamped', 'natural', None or "
                    "[(order, value), ...])")
    out = []
    for item in b:
        order, value = item
        if not isinstance(order, (int, np.integer)) or order < 1:
            raise Error(f"bc_type: the derivative order at the {side} must be an integer >= 1, got {order!r}")
        v = np.broadcast_to(np.asarray(value, dtype=np.float64).reshape(-1), (m,))
        if not np.isfinite(v).all():
            raise Error(f"bc_type: the derivative value at the {side} must be finite, got {value!r}")
        out.append((int(order), v))
    return out


def make_interp_spline(x: Any, y: Any, k: int = 3, t: Any = None, bc_type: Any = None, axis: int = 0) -> Any:
    """scipy's interpolating B-spline of degree k (without t: the knots scipy chooses; with
    bc_type: scipy's (deriv_l, deriv_r) end derivatives, 'clamped' or 'natural'), the
    collocation matrix (and the end rows) from the registry's basis command, solved by
    numpy.

    >>> import numpy as np, casteljau
    >>> b = casteljau.make_interp_spline(np.arange(6.0), np.arange(6.0) ** 2, k=3, bc_type="natural")
    >>> type(b).__name__, b.k
    ('BSpline', 3)
    """
    x = np.asarray(x, dtype=np.float64)
    pts, tail = _data(y, axis, "y")
    if isinstance(k, bool) or not isinstance(k, (int, np.integer)) or k < 0:
        raise Error(f"k: must be an integer >= 0, got {k!r}")
    k = int(k)
    if len(x) != len(pts):
        raise Error(f"x: {len(x)} values but y has {len(pts)}")
    # scipy: "Expect x to be a 1D strictly increasing sequence." (and finite data).
    if x.ndim != 1:
        raise Error(f"x: must be a 1-D array, got shape {x.shape}")
    for i in range(len(x)):
        if not np.isfinite(x[i]):
            raise Error(f"x[{i}]: must be a finite number, got {x[i]}")
        if i and not x[i] > x[i - 1]:
            raise Error(f"x[{i}]: x must be strictly increasing, got x[{i - 1}] = {x[i - 1]:g} then {x[i]:g}")
    bad, m_tail = np.flatnonzero(~np.isfinite(pts).all(axis=1)), tail != ()
    if len(bad):
        raise Error(f"y[{bad[0]}]: must be a finite number, got {pts[bad[0]] if m_tail else pts[bad[0]][0]}")
    m = pts.shape[1]
    periodic = isinstance(bc_type, str) and bc_type == "periodic"
    if periodic and len(pts) and not np.allclose(pts[0], pts[-1], atol=1e-15):
        raise Error("y: the first and last values must be equal for bc_type='periodic'")
    if bc_type is None or bc_type == "not-a-knot" or periodic:
        deriv_l, deriv_r = [], []
    elif isinstance(bc_type, str):
        deriv_l = _end_derivatives(bc_type, m, "start")
        deriv_r = _end_derivatives(bc_type, m, "end")
    else:
        if len(bc_type) != 2:
            raise Error(f"bc_type: must be a string or a pair (start, end), got {bc_type!r}")
        deriv_l = _end_derivatives(bc_type[0], m, "start")
        deriv_r = _end_derivatives(bc_type[1], m, "end")
    if k == 0:
        # scipy's knots are x and x[-1] again: the value y[i] on [x[i], x[i + 1]) and y[-1]
        # from x[-1] on. The library refuses an end knot repeated past degree + 1, so the
        # same function is made on the knots x and one more beyond x[-1] (the domain's end
        # kept at x[-1] for extrapolate=False), then given scipy's t and c.
        if t is not None or deriv_l or deriv_r:
            raise Error("k: 0 takes neither t nor bc_type (scipy's rule)")
        if len(x) < 2:
            raise Error("x: needs at least 2 points")
        last = x[-1] + (x[-1] - x[-2]) if x[-1] > x[-2] else x[-1] + 1.0
        y0 = np.asarray(y, dtype=np.float64)
        b = BSpline(np.r_[x, last], y0, 0, axis=axis)
        b._sp._hi = float(x[-1])
        b.t = np.r_[x, x[-1]]
        b._sp._ends = ("bspline", b.t, pts, 0)
        return b
    if periodic and k > 1:
        if t is not None:
            raise Error("t: bc_type='periodic' makes its own knots (scipy's rule)")
        return _periodic_interp_spline(x, pts, tail, k, _axis(y, axis))
    if t is None:
        if deriv_l or deriv_r:
            # scipy's knots with end derivatives: x with k more copies of each end.
            t = np.r_[(x[0],) * k, x, (x[-1],) * k]
        elif k == 2:
            # scipy's choices: k = 2 the midpoints without the first and last, odd k
            # not-a-knot (the data's sites without (k - 1) / 2 at each end).
            mid = (x[1:] + x[:-1]) / 2
            t = np.r_[(x[0],) * 3, mid[1:-1], (x[-1],) * 3]
        elif k % 2 == 1:
            h = (k - 1) // 2
            t = np.r_[(x[0],) * (k + 1), x[h + 1 : len(x) - h - 1], (x[-1],) * (k + 1)]
        else:
            # scipy 1.10 refuses these too (its not-a-knot knots are for odd degrees).
            raise Error(f"k: even degrees above 2 need t or bc_type (odd degree for not-a-knot knots), got {k}")
    if len(deriv_l) + len(deriv_r) != len(np.asarray(t)) - k - 1 - len(x):
        raise Error(f"bc_type: {len(deriv_l)} + {len(deriv_r)} end derivatives given, the knots need "
                    f"{len(np.asarray(t)) - k - 1 - len(x)}")
    t = np.asarray(t, dtype=np.float64)
    nt = len(t) - k - 1
    rows, rhs = [], []
    order = max([0] + [o for o, _ in deriv_l + deriv_r])
    try:
        b = _casteljau.run("basis", {"kind": "bspline", "degree": int(k), "knots": t, "t": np.r_[x[:1], x, x[-1:]],
                                     "derivatives": order})
    except Error as e:
        raise _renamed(e, {"knots": "t", "t": "x", "degree": "k"}, False) from None
    tables = [np.atleast_2d(b["values"])] + [np.atleast_2d(d) for d in b.get("derivatives", [])]
    # The rows of scipy's system: derivatives at x[0], the data, derivatives at x[-1].
    for o, v in deriv_l:
        rows.append(tables[o][0])
        rhs.append(v)
    rows.extend(tables[0][1:-1])
    rhs.extend(pts)
    for o, v in deriv_r:
        rows.append(tables[o][-1])
        rhs.append(v)
    A = np.array(rows, dtype=np.float64)
    if A.shape != (nt, nt):
        raise Error(f"t: {len(t)} knots give {nt} basis functions for {len(x)} points and "
                    f"{len(deriv_l) + len(deriv_r)} end conditions")
    c = np.linalg.solve(A, np.array(rhs, dtype=np.float64).reshape(nt, -1))
    ax = _axis(y, axis)
    return BSpline(t, np.moveaxis(c.reshape((nt,) + tail), 0, ax), int(k), axis=ax)


def _periodic_interp_spline(x: np.ndarray, pts: np.ndarray, tail: tuple, k: int, axis: int = 0) -> Any:
    """make_interp_spline(x, y, k, bc_type='periodic'), k >= 2: scipy's knots on a circle
    (the sites x, for even k the interior ones moved to the midpoints of their left
    intervals, and k more at each end continuing the intervals of the other end), and the
    periodic spline through the points: with these knots a spline of period x[-1] - x[0]
    has coefficients of period n - 1 (c[j] = c[j mod (n - 1)], n points), so the unknowns
    are n - 1 coefficients and the conditions the values at x[:-1] (the last equals the
    first); the collocation matrix's columns folded modulo n - 1, solved by numpy."""
    n = len(x)
    if n < 2:
        raise Error("x: needs at least 2 points")
    bad = np.flatnonzero(~(np.diff(x) > 0))
    if len(bad):
        raise Error(f"x[{bad[0] + 1}]: x must be strictly increasing")
    xc = x.copy()
    dx = np.diff(x)
    if k % 2 == 0:
        xc[1:-1] -= dx[:-1] / 2
    dx = np.diff(xc)
    t = np.empty(n + 2 * k)
    t[k:-k] = xc
    for i in range(k):
        t[k - i - 1] = t[k - i] - dx[-(i % (n - 1)) - 1]
        t[n + k + i] = t[n + k + i - 1] + dx[i % (n - 1)]
    nt = n + k - 1
    try:
        b = _casteljau.run("basis", {"kind": "bspline", "degree": k, "knots": t, "t": x[:-1]})
    except Error as e:
        raise _renamed(e, {"t": "x", "degree": "k"}, False) from None
    B = np.atleast_2d(b["values"])
    A = np.zeros((n - 1, n - 1))
    for j in range(nt):
        A[:, j % (n - 1)] += B[:, j]
    c = np.linalg.solve(A, pts[:-1])[np.arange(nt) % (n - 1)]
    return BSpline(t, np.moveaxis(c.reshape((nt,) + tail), 0, axis), k, extrapolate="periodic", axis=axis)


def _hermite_interpolator(rule: str, default_extrapolate: bool, name: str) -> type:
    def __init__(self: Any, x: Any, y: Any, axis: int = 0, extrapolate: Any = None) -> None:
        pts, tail = _data(y, axis, "y")
        xa = np.asarray(x, dtype=np.float64)
        try:
            curve = _columns(lambda p, j: _CLASSES["hermite"](params=xa, points=p, tangent_rule=rule), pts)
        except Error as e:
            raise _renamed(e, {"params": "x", "points": "y"}, tail == ()) from None
        PPoly.__init__(self, curve, tail, default_extrapolate if extrapolate is None else extrapolate, _axis(y, axis),
                       _LazyEnds("hermite", curve, xa, pts))

    return type(name, (PPoly,), {"__init__": __init__, "__module__": "casteljau",
                                 "__doc__": f"scipy's {name}: the library's hermite curve with tangent_rule {rule!r}."})


PchipInterpolator = _hermite_interpolator("monotone", True, "PchipInterpolator")
Akima1DInterpolator = _hermite_interpolator("akima", False, "Akima1DInterpolator")


class BarycentricInterpolator(PPoly):
    """scipy's BarycentricInterpolator(xi, yi=None, axis=0, *, wi=None, random_state=None):
    the library's lagrange curve, the polynomial through the points at any number of them,
    evaluated by the second barycentric formula with weights computed once (as scipy's;
    stable on well-spread nodes such as Chebyshev points, where the equispaced interpolant
    itself is not). scipy's ``set_yi``, ``add_xi`` and (scipy 1.11's) ``derivative(x,
    der=1)``, ``derivatives(x, der=None)`` (der a count, or a list of orders) and ``wi``;
    the attributes ``xi``, ``yi`` (the values as (n, r)), ``n``, ``r`` and ``wi``.

    >>> import numpy as np, casteljau
    >>> x = np.cos(np.linspace(0, np.pi, 40))  # 40 Chebyshev points
    >>> p = casteljau.BarycentricInterpolator(x, np.exp(x))
    >>> bool(abs(p(0.3) - np.exp(0.3)) < 1e-13)
    True
    >>> p.derivatives(0.0, der=3)  # exp and its derivatives at 0
    array([1., 1., 1.])
    >>> p.derivatives(0.0, der=[2, 0])  # the orders listed
    array([1., 1.])
    >>> w = (-1.0) ** np.arange(40); w[[0, -1]] /= 2  # these nodes' weights, in closed form
    >>> q = casteljau.BarycentricInterpolator(x, np.exp(x), wi=w)
    >>> bool(abs(q(0.3) - np.exp(0.3)) < 1e-13)
    True
    """

    def __init__(self, xi: Any, yi: Any = None, axis: int = 0, *, wi: Any = None, random_state: Any = None,
                 rng: Any = None) -> None:
        # random_state / rng: scipy's permutation of the weights' product (its rounding
        # only); the library's weights need none, so they are accepted and unused.
        xi = np.asarray(xi, dtype=np.float64)
        if xi.ndim != 1:
            raise Error(f"xi: must be a 1-D array, got shape {xi.shape}")
        self.xi = xi
        self.n, self.r = len(xi), None
        self.yi = None
        self.axis = axis
        self._curve = None
        self._given = wi is not None
        self._wi: np.ndarray | None = None
        self._diff: list[np.ndarray] = []  # the given weights' D^k yi, k = 0, 1, ...
        if self._given:
            w = np.asarray(wi, dtype=np.float64)
            if w.shape != xi.shape:
                raise Error(f"wi: must have one weight per node, shape {xi.shape}, got shape {w.shape}")
            for i, v in enumerate(w):
                if not np.isfinite(v) or v == 0:
                    raise Error(f"wi[{i}]: must be a finite nonzero number, got {v}")
            self._wi = w.copy()
        self.set_yi(yi, axis)

    @property
    def wi(self) -> np.ndarray:
        """The barycentric weights: the given ones, else scipy's formula 1 / prod_(j != i)
        (4 (x_i - x_j) / (max xi - min xi)) (the product in node order; scipy permutes
        its factors at random, which changes only their rounding)."""
        if self._wi is None:
            x = self.xi
            if len(x) == 1:
                return np.ones(1)
            scale = 4.0 / (np.max(x) - np.min(x))
            d = scale * (x[:, None] - x[None, :])
            np.fill_diagonal(d, 1.0)
            self._wi = 1.0 / np.prod(d, axis=1)
        return self._wi

    def set_yi(self, yi: Any, axis: Any = None) -> None:
        """New values yi at the same nodes (None: none until given again); axis: the
        interpolation axis of yi (None: the one given before)."""
        self._diff = []
        if yi is None:
            self.yi, self.r, self._curve = None, None, None
            return
        if axis is None:
            axis = self.axis
        pts, tail = _data(yi, axis, "yi")
        if len(pts) != len(self.xi):
            raise Error(f"yi: {len(pts)} values along axis {axis} but xi has {len(self.xi)}")
        self._set(self.xi, pts, tail, _axis(yi, axis))

    def _set(self, xi: np.ndarray, pts: np.ndarray, tail: tuple, axis: int) -> None:
        try:
            curve = _columns(lambda p, j: _CLASSES["lagrange"](params=xi, points=p), pts)
        except Error as e:
            raise _renamed(e, {"params": "xi", "points": "yi"}, tail == ()) from None
        PPoly.__init__(self, curve, tail, True, axis)
        if not self._given:
            self._wi = None  # the nodes' weights, made again when asked
        self.xi, self.yi = xi, pts
        self.n, self.r = pts.shape
        self._diff = []

    def add_xi(self, xi: Any, yi: Any = None) -> None:
        """More nodes xi (1-D) with their values yi (the interpolation axis where the
        constructor's was, the same other axes), given if and only if the interpolator has
        values (scipy's rule)."""
        if self._given:
            raise Error("wi: the interpolator was given its weights, which add_xi cannot extend (make a new "
                        "BarycentricInterpolator on all the nodes)")
        xi = np.asarray(xi, dtype=np.float64).reshape(-1)
        if yi is None:
            if self.yi is not None:
                raise Error("yi: required: the interpolator has values, give those of the new nodes (scipy's rule)")
            self.xi = np.concatenate([self.xi, xi])
            self.n = len(self.xi)
            self._wi = None
            return
        if self.yi is None:
            raise Error("yi: the interpolator has no values to add to (give them with set_yi first)")
        y = np.asarray(yi, dtype=np.float64)
        if y.ndim != len(self._tail) + 1:
            raise Error(f"yi: must have {len(self._tail) + 1} axes (values of shape {self._tail} along axis "
                        f"{self.axis}), got shape {y.shape}")
        y = np.moveaxis(y, self.axis, 0)
        if y.shape[1:] != self._tail:
            raise Error(f"yi: values of shape {y.shape[1:]} along axis {self.axis}, the interpolator's are "
                        f"{self._tail}")
        if len(y) != len(xi):
            raise Error(f"yi: {len(y)} values along axis {self.axis} but xi has {len(xi)}")
        self._set(np.concatenate([self.xi, xi]), np.vstack([self.yi, y.reshape(len(y), -1)]), self._tail, self.axis)

    def _check(self) -> None:
        if self._curve is None:
            raise Error("yi: not set (give the values to the constructor or to set_yi)")

    def _with_weights(self, x: Any, der: int) -> np.ndarray:
        """Given weights: the order-der derivative at x as scipy 1.11 computes it, the second
        barycentric formula with the weights wi on the values D^der yi, D the
        differentiation matrix of the weights (D_ij = (w_j / w_i) / (x_i - x_j), D_ii =
        -sum_(j != i) D_ij [BerrutTrefethen04, (9.4), (9.5)]); exact at the nodes. In the
        shape of a call."""
        x = np.asarray(x, dtype=np.float64)
        xf = x.reshape(-1)
        bad = ~np.isfinite(xf)
        if bad.any():
            j = int(np.argmax(bad))
            raise Error(f"x[{j}]: must be a finite number, got {xf[j]}")
        if der >= self.n:
            y = np.zeros_like(self.yi)
        else:
            if not self._diff:
                self._diff.append(self.yi)
            if len(self._diff) <= der:
                w, xi = self.wi, self.xi
                c = xi[:, None] - xi[None, :]
                np.fill_diagonal(c, 1.0)
                c = w[None, :] / (c * w[:, None])
                np.fill_diagonal(c, 0.0)
                np.fill_diagonal(c, -c.sum(axis=1))
                while len(self._diff) <= der:
                    self._diff.append(c @ self._diff[-1])
            y = self._diff[der]
        c = xf[:, None] - self.xi[None, :]
        at = c == 0
        c[at] = 1.0
        c = self.wi / c
        with np.errstate(divide="ignore", invalid="ignore"):
            out = (c @ y) / c.sum(axis=1)[:, None]
        rows, cols = np.nonzero(at)
        out[rows] = y[cols]
        out = out.reshape(x.shape + self._tail)
        if self.axis and out.ndim > x.ndim:  # scipy's order, as PPoly.__call__
            ax = list(range(out.ndim))
            out = out.transpose(ax[x.ndim:x.ndim + self.axis] + ax[:x.ndim] + ax[x.ndim + self.axis:])
        return out

    def __call__(self, x: Any) -> np.ndarray:  # type: ignore[override]
        self._check()
        if self._given:
            return self._with_weights(x, 0)
        return super().__call__(x)

    def derivative(self, x: Any, der: int = 1) -> np.ndarray:  # type: ignore[override]
        """The order-der derivative at x, in the shape of a call (scipy 1.11's)."""
        self._check()
        if isinstance(der, bool) or not isinstance(der, (int, np.integer)) or der < 0:
            raise Error(f"der: must be an integer >= 0, got {der!r}")
        if self._given:
            return self._with_weights(x, int(der))
        if der >= self.n:  # above the polynomial's degree
            return np.zeros_like(super().__call__(x))
        return super().__call__(x, nu=int(der))

    def derivatives(self, x: Any, der: Any = None) -> np.ndarray:
        """The derivatives of orders 0 to der - 1 at x (der None: n of them, all that can be
        nonzero), stacked first: shape (der,) + the shape of a call; der a list of orders:
        those orders, in its order (d[j] the order der[j]: scipy's documented form, as its
        barycentric_interpolate computes it, derivatives(x, max(der) + 1)[der])."""
        self._check()
        if der is None:
            der = self.n
        if isinstance(der, (list, tuple, np.ndarray)):
            orders = list(np.asarray(der).reshape(-1)) if not isinstance(der, (list, tuple)) else list(der)
            if not orders:
                raise Error("der: an empty list of orders")
            for j, k in enumerate(orders):
                if isinstance(k, (bool, np.bool_)) or not isinstance(k, (int, np.integer)) or k < 0:
                    raise Error(f"der[{j}]: must be an integer >= 0, got {k!r}")
            return self.derivatives(x, int(max(orders)) + 1)[[int(k) for k in orders]]
        if isinstance(der, bool) or not isinstance(der, (int, np.integer)) or der < 0:
            raise Error(f"der: must be an integer >= 0, a list of them, or None, got {der!r}")
        first = self(x)
        out = np.zeros((int(der),) + first.shape)
        for k in range(min(int(der), self.n)):
            out[k] = first if k == 0 else self.derivative(x, k)
        return out

    def antiderivative(self, nu: int = 1) -> PPoly:  # not scipy's (none there): the library's
        self._check()
        return super().antiderivative(nu)
