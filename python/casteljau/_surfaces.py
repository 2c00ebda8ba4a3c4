"""The library's surface classes and commands, generated from the compiled registry like
the curves' (docs/python.md, "Surfaces").

Every surface type of the registry (``_casteljau.surface_types()``: its surface-JSON name
and fields) becomes a subclass of :class:`Surface` named after the curve type it extends
(``bezier_surface``: ``BezierSurface``, ``nurbs_surface``: ``NurbsSurface``); every
command with a surface form (``_casteljau.surface_forms()``: eval, split, elevate,
insert_knot, to_bezier, bounds, area, ...) and every command whose first field is a
surface (isocurve, ...) becomes a method; the constructions of the ``surface`` command are
functions of ``casteljau.surface`` (``casteljau.surface.revolve(curve=, axis=, angle=)``,
keywords only).
Evaluation ``s(u, v)`` is written by hand (arrays of parameters, a grid or scattered pairs).
"""

from __future__ import annotations

import re
from typing import Any

import numpy as np

from . import _casteljau
from ._casteljau import Error
from ._curves import _CLASSES, _SURFACE_CLASSES, _doc, _json_object, _simplify, functions

__all__ = ["Surface", "surface_classes"]


class Surface:
    """A surface of the library. Construct one of the registry's classes
    (``BezierSurface(points)``, ``BSplineSurface(points=, degree=, knots=)``, ...) or read
    surface JSON with ``Surface.from_json``. ``s(u, v)`` evaluates: u and v numbers or
    arrays broadcast together (scattered pairs), shape ``broadcast.shape + (d,)``; with
    ``grid=True`` every u with every v, shape ``(len(u), len(v), d)``.

    >>> import numpy as np, casteljau
    >>> s = casteljau.BezierSurface([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]])
    >>> s(0.5, 0.5)
    array([0.5 , 0.5 , 0.25])
    >>> s(np.linspace(0, 1, 3), np.linspace(0, 1, 4), grid=True).shape
    (3, 4, 3)
    """

    _type = ""
    _fields: tuple[str, ...] = ()
    __slots__ = ("_s", "_json")

    def __init__(self, *args: Any, **fields: Any) -> None:
        if type(self) is Surface:
            raise TypeError("Surface is abstract: construct one of its subclasses or use Surface.from_json")
        obj = _json_object(self, args, fields)
        self._s = _casteljau.Surface(obj)
        self._json = None

    @classmethod
    def _wrap(cls, core: Any) -> "Surface":
        s = object.__new__(_SURFACE_CLASSES[core.type])
        s._s = core
        s._json = None
        return s

    @classmethod
    def from_json(cls, obj: dict | str) -> "Surface":
        """The surface of a surface-JSON object (a dict or its text); on a subclass, the
        object must be of that type."""
        s = cls._wrap(_casteljau.Surface(obj))
        if cls is not Surface and not isinstance(s, cls):
            raise Error(f"type: {cls.__name__}.from_json needs a {cls._type!r} surface, got {s._s.type!r}")
        return s

    def to_json(self) -> dict:
        """The surface JSON as the library writes it (a dict)."""
        if self._json is None:
            self._json = self._s.to_data()
        return self._json

    def __reduce__(self) -> tuple:
        return (Surface.from_json, (self._s.to_json(),))

    def __repr__(self) -> str:
        return f"{type(self).__name__}.from_json({self._s.to_json()})"

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Surface) and self._s.to_json() == other._s.to_json()

    __hash__ = None  # type: ignore[assignment]

    @property
    def dim(self) -> int:
        """The dimension d of the surface's points."""
        return self._s.dim

    @property
    def domain(self) -> tuple[tuple[float, float], tuple[float, float]]:
        """((u0, u1), (v0, v1))."""
        return self._s.domain

    def __call__(self, u: Any, v: Any, grid: bool = False) -> np.ndarray:
        """The points at (u, v): scattered pairs (u and v broadcast together; shape
        broadcast.shape + (d,)) or, with grid, every u with every v (1-D u and v; shape
        (len(u), len(v), d)). Outside the domain the end patches continue. A NaN
        parameter raises Error naming u[j] or v[j] (j: the flat index)."""
        u = np.asarray(u, dtype=np.float64)
        v = np.asarray(v, dtype=np.float64)
        if grid:
            if u.ndim > 1 or v.ndim > 1:
                raise Error(f"u, v: grid=True takes 1-D arrays, got shapes {u.shape} and {v.shape}")
            u, v = np.meshgrid(u.reshape(-1), v.reshape(-1), indexing="ij")
        else:
            u, v = np.broadcast_arrays(u, v)
        return self._s.evaluate(u, v)  # copied to C order by the module when broadcast

    def limit_normal(self, u: float, v: float) -> np.ndarray | None:
        """The unit normal at (u, v) of a 3-D surface, also where S_u x S_v vanishes on a
        degenerate edge (a sphere's pole) if the normals about the point have a limit
        there; None where they have none (a cone's apex: they turn about the axis) or at an
        isolated singular point. Where the normal is defined, the eval command's
        ``normals``. The limit comes from the first Taylor coefficient of S_u x S_v across
        the edge that does not vanish (S_u x S_uv at a pole), checked to be the same all
        along the edge (docs/python.md, "Surfaces").

        >>> import casteljau
        >>> half = casteljau.Nurbs(degree=2, knots=[0, 0, 0, 0.5, 0.5, 1, 1, 1],
        ...     points=[[0, 0, -1], [1, 0, -1], [1, 0, 0], [1, 0, 1], [0, 0, 1]],
        ...     weights=[1, 0.5 ** 0.5, 1, 0.5 ** 0.5, 1])
        >>> sphere = casteljau.surface.revolve(curve=half, axis={"point": [0, 0, 0], "direction": [0, 0, 1]})
        >>> sphere.eval([[0, 0]], normal=True).normals  # the south pole: S_u x S_v = 0
        [None]
        >>> sphere.eval([[0.5, 0]], normal=True).normals.round(15) + 0  # inward on this sphere
        array([[-1.,  0.,  0.]])
        >>> sphere.limit_normal(0, 0).round(15) + 0  # the limit at the pole: inward too
        array([0., 0., 1.])
        >>> cone = casteljau.surface.revolve(curve=casteljau.Bezier([[0, 0, 1], [1, 0, 0]]),
        ...     axis={"point": [0, 0, 0], "direction": [0, 0, 1]})
        >>> cone.limit_normal(0, 0) is None  # the apex
        True
        """
        return self._s.limit_normal(float(u), float(v))


def _class_name(json_name: str) -> str:
    """bezier_surface -> BezierSurface: the curve type's class name (the registry's) and
    "Surface"."""
    base = json_name.removesuffix("_surface")
    if base in _CLASSES:
        return _CLASSES[base].__name__ + "Surface"
    return "".join(w.capitalize() for w in json_name.split("_"))


def _method(name: str, summary: str, fields: list, field: str) -> Any:
    params = [f[0] for f in fields if f[0] != field]

    def method(self: Surface, *args: Any, **kw: Any) -> Any:
        if len(args) > len(params):
            raise TypeError(f"{name}() takes at most {len(params)} arguments ({', '.join(params)}), got {len(args)}")
        req = dict(zip(params, args))
        for k, v in kw.items():
            if k.endswith("_") and k[:-1] in params:
                k = k[:-1]
            if k not in params:
                raise TypeError(f"{name}() got an unexpected keyword argument {k!r} (fields: {', '.join(params)})")
            req[k] = v
        return _simplify(self._s.run(name, req, field))

    method.__name__ = name
    method.__qualname__ = f"Surface.{name}"
    method.__doc__ = _doc(name, summary, [f for f in fields if f[0] != field], example=False)
    return method


for _name, _summary, _fields in _casteljau.surface_forms():
    setattr(Surface, _name, _method(_name, _summary, _fields, "surface"))
for _name, _summary, _fields in _casteljau.commands():
    if _fields and _fields[0][1] == "surface" and not hasattr(Surface, _name):
        setattr(Surface, _name, _method(_name, _summary, _fields, _fields[0][0]))


def _eval_method(command: Any) -> Any:
    """eval on arrays: pairs uv given as a finite (n, 2) array (or what numpy makes one of)
    are evaluated by the compiled module without the command's JSON (the same values:
    the library's partials and geometry); anything else goes to the command (its errors)."""

    def eval(self: Surface, uv: Any, derivatives: int = 0, normal: bool = False, curvature: bool = False) -> Any:
        try:
            a = np.asarray(uv, dtype=np.float64)
        except (TypeError, ValueError):
            a = None
        direct = (a is not None and a.ndim == 2 and a.shape[0] > 0 and a.shape[1] == 2 and bool(np.isfinite(a).all())
                  and type(derivatives) is int and type(normal) is bool and type(curvature) is bool)
        if not direct:
            return command(self, uv, derivatives, normal, curvature)
        return _simplify(self._s.eval(np.ascontiguousarray(a), derivatives, normal, curvature))

    eval.__doc__ = command.__doc__
    eval.__qualname__ = "Surface.eval"
    return eval


Surface.eval = _eval_method(Surface.eval)  # type: ignore[method-assign]


def _make_class(json_name: str, fields: list) -> type:
    names = tuple(f for f in fields if f != "type")
    class_name = _class_name(json_name)
    doc = (f"The registry's {json_name!r} surface: {class_name}({', '.join(names)}), each a keyword or in this "
           f"order; the fields of surface JSON (docs/cli.md).")
    cls = type(class_name, (Surface,), {"_type": json_name, "_fields": names, "__slots__": (), "__doc__": doc,
                                        "__module__": "casteljau"})
    for f in names:
        if hasattr(Surface, f):
            continue
        setattr(cls, f, property(lambda self, f=f: _arrays_of(self.to_json().get(f)), doc=f"The surface JSON's {f!r}."))
    return cls


def _arrays_of(value: Any) -> Any:
    if isinstance(value, list):
        try:
            return np.array(value, dtype=np.float64)
        except (ValueError, TypeError):
            return value
    return value


surface_classes: dict[str, type] = {}
for _json_name, _type_fields in _casteljau.surface_types():
    _cls = _make_class(_json_name, _type_fields)
    _SURFACE_CLASSES[_json_name] = _cls
    surface_classes[_cls.__name__] = _cls


# The constructions of the `surface` command as functions of casteljau.surface: their
# names from the registry's help of its `construct` field ("extrude, ruled, ... or fit").
def _constructions() -> list[str]:
    for name, _, fields in _casteljau.commands():
        if name == "surface":
            for fname, _, _, _, help_ in fields:
                if fname == "construct":
                    return [w for w in re.split(r",\s*|\s+or\s+", help_) if re.fullmatch(r"[a-z_]+", w)]
    return []


def _construction(build: Any, construct: str) -> Any:
    def function(**kw: Any) -> Any:
        return build(construct, **kw)

    function.__name__ = construct
    function.__qualname__ = f"surface.{construct}"
    function.__doc__ = (f"casteljau.surface({construct!r}, **fields), the fields as keywords: see "
                        "help(casteljau.surface).")
    return function


if "surface" in functions:
    _build = functions["surface"]
    for _c in _constructions():
        setattr(_build, _c, _construction(_build, _c))
