"""Conversions between exact pgsym objects and float64 arrays, both ways.

:func:`to_array` turns exact objects (points, lines, planes, Plücker lines, conics,
quadrics, transformations) into float64 arrays; :func:`from_array` turns arrays back
into exact objects, reading each float as the shortest decimal that prints it (as
:func:`pgsym.homogeneous.to_exact` does), so small integers come back unchanged. The
exact core (and with it SymPy) is imported only when these functions are called.

>>> from pgsym.projective_plane import Point
>>> to_array([Point(1, 2), Point(3, 4, 0)])
array([[1., 2., 1.],
       [3., 4., 0.]])
>>> from_array([[1.0, 2, 1], [3, 4, 0]], "point")
[Point(1, 2, 1), Point(3, 4, 0)]
"""

from __future__ import annotations

import importlib
from typing import Any

import numpy as np

from ..errors import DimensionError, NonFiniteError, NonNumericError, ObjectTypeError
from ._arrays import as_float_array

__all__ = ["KINDS", "from_array", "to_array"]

KINDS: dict[str, tuple[str, str, tuple[int, ...]]] = {
    "point1": ("projective_line", "Point1", (2,)),
    "point": ("projective_plane", "Point", (3,)),
    "line": ("projective_plane", "Line", (3,)),
    "point3": ("space", "Point3", (4,)),
    "plane": ("space", "Plane", (4,)),
    "line3": ("plucker", "Line3", (6,)),
    "conic": ("conics", "Conic", (3, 3)),
    "dual_conic": ("conics", "DualConic", (3, 3)),
    "quadric": ("quadrics", "Quadric", (4, 4)),
    "transformation": ("transformations", "Transformation", (0, 0)),
}
"""The kinds :func:`from_array` builds: name → (module of pgsym, class, shape of one object's array)."""


def _floats(values: Any, obj: Any) -> list[float]:
    try:
        return [float(v) for v in values]
    except TypeError as err:
        raise NonNumericError(
            f"to_array: {obj!r} has symbolic coordinates; substitute numbers first (obj.subs(...))"
        ) from err


def _finite(a: np.ndarray, obj: Any) -> np.ndarray:
    if not np.isfinite(a).all():
        raise NonFiniteError(
            f"to_array: {obj!r} has coordinates beyond the float64 range (about 1.8e308); divide them by a common "
            "factor first, which changes nothing projectively"
        )
    return a


def _one(obj: Any) -> np.ndarray:
    if hasattr(obj, "coords"):
        return _finite(np.array(_floats(obj.coords, obj)), obj)
    if hasattr(obj, "matrix"):
        m = obj.matrix
        return _finite(np.array(_floats(list(m), obj)).reshape(m.shape), obj)
    raise ObjectTypeError(
        f"to_array expects pgsym objects (points, lines, planes, Line3, conics, quadrics, transformations), "
        f"got {type(obj).__name__} {obj!r}"
    )


def to_array(objects: Any) -> np.ndarray:
    """Float64 array of one exact object, or of a (nested) sequence of objects of one kind.

    Vectors give shape ``(..., k)``; conics, quadrics and transformations give ``(..., k, k)``.

    >>> from pgsym.space import Point3
    >>> to_array(Point3(1, 2, 3)), to_array([]).shape
    (array([1., 2., 3., 1.]), (0,))
    """
    if isinstance(objects, (list, tuple)):
        parts = [to_array(o) for o in objects]
        if not parts:
            return np.empty((0,))
        if len({p.shape for p in parts}) > 1:
            raise DimensionError(
                f"to_array: the objects have different sizes {sorted({p.shape for p in parts})}; "
                "convert objects of one kind at a time"
            )
        return np.stack(parts)
    return _one(objects)


def from_array(array: Any, kind: str | type) -> Any:
    """Exact pgsym objects from an array: one object for one vector (or matrix), else nested lists.

    ``kind`` is a class (``Point``, ``Plane``, ``Conic``, …) or one of the names in
    :data:`KINDS`. Zero rows raise :class:`~pgsym.errors.ZeroVectorError` and rows off the
    Klein quadric :class:`~pgsym.errors.NotOnKleinQuadricError`, as the constructors do.

    >>> from_array([0.5, 0.25, 1], "point")
    Point(S(1)/2, S(1)/4, 1)
    >>> from_array(np.eye(3), "transformation").dim
    2
    """
    name = kind.__name__ if isinstance(kind, type) else kind
    by_class = {cls: key for key, (_, cls, _) in KINDS.items()}
    key = by_class.get(name, name)
    if key not in KINDS:
        raise ObjectTypeError(f"from_array: unknown kind {kind!r}; use one of {', '.join(KINDS)} or their classes")
    module, cls_name, shape = KINDS[key]
    cls = getattr(importlib.import_module(f"pgsym.{module}"), cls_name)
    a = as_float_array(array, "array", "from_array")
    if not np.all(np.isfinite(a)):
        raise NonFiniteError("from_array: the array holds NaN or infinity, which no exact object has")
    if shape == (0, 0):
        shape = a.shape[-2:] if a.ndim >= 2 and a.shape[-1] == a.shape[-2] else (-1, -1)
    if a.ndim < len(shape) or a.shape[a.ndim - len(shape) :] != shape:
        raise DimensionError(f"from_array: a {cls_name} needs trailing shape {shape}, got an array of shape {a.shape}")

    def build(x: np.ndarray) -> Any:
        if x.ndim > len(shape):
            return [build(row) for row in x]
        values = x.tolist()
        return cls(values) if len(shape) == 2 else cls(*values)

    return build(a)
