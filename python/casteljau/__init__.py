"""casteljau: Bezier, rational Bezier, B-spline, NURBS and interpolating curves on numpy
arrays (docs/python.md).

The library's classes, one per curve type of its registry (``Bezier``, ``RationalBezier``,
``BSpline``, ``Nurbs``, ``Polyline``, ``Path``, ``Lagrange``, ``CubicSpline``, ``Hermite``,
``CatmullRom``), take the fields of curve JSON (docs/cli.md) and evaluate on arrays:

>>> import numpy as np, casteljau
>>> c = casteljau.Bezier([[0, 0], [1, 2], [2, 0]])
>>> c(0.5)
array([1., 1.])
>>> c(np.linspace(0, 1, 3)).shape
(3, 2)
>>> round(c.length(), 6)  # sqrt(5) + asinh(2) / 2
2.957886

Every command of the registry is a method of a curve (``split``, ``flatten``, ``bounds``,
``project``, ...) or a module function (``intersect``, ``distance``, ``fit``,
``subdivide``, ...). scipy.interpolate's names (``CubicSpline(x, y, bc_type=...)``,
``BSpline(t, c, k)``, ``make_interp_spline``, ``PchipInterpolator``,
``Akima1DInterpolator``, ``BarycentricInterpolator``) take scipy's arguments and return
scipy's shapes. Errors raise ``casteljau.Error``, a ValueError, with the command line's
"<where>: <what>" message.
"""

from ._casteljau import Error

Error.__module__ = "casteljau"
from ._curves import Curve, Result, curve_classes, functions, run
from . import _scipy
from ._surfaces import Surface, surface_classes
from ._scipy import (PPoly, CubicSpline, BSpline, make_interp_spline, PchipInterpolator, Akima1DInterpolator,
                     BarycentricInterpolator)

globals().update(curve_classes)  # Bezier, RationalBezier, ..., from the registry
globals().update(functions)  # intersect, distance, fit, subdivide, basis, render, surface, ...
globals().update(surface_classes)  # BezierSurface, RationalBezierSurface, BSplineSurface, NurbsSurface

__all__ = (["Curve", "Surface", "Result", "Error", "run", "PPoly", "make_interp_spline", "PchipInterpolator",
            "Akima1DInterpolator", "BarycentricInterpolator"] + sorted(curve_classes) + sorted(surface_classes)
           + sorted(functions))
