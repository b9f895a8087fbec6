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

from typing import Any

import numpy as np

from ..errors import DimensionError, NonFiniteError, NonNumericError, ObjectTypeError
from ._arrays import as_float_array

__all__ = ["from_array", "kinds", "to_array"]

def _shape(cls: type) -> tuple[int, ...]:
    """The shape of one object's array, read off its class: a vector of ``size`` coordinates, a
    ``size``×``size`` symmetric form, or a square matrix of any size (0, 0) for a transformation."""
    from ..homogeneous import HomogeneousVector  # noqa: PLC0415 — numeric → core by design: exact objects on request; numeric loads without SymPy
    from ..symmetric_form import SymmetricForm  # noqa: PLC0415 — numeric → core by design: exact objects on request; numeric loads without SymPy

    if issubclass(cls, HomogeneousVector):
        return (cls.size,)
    if issubclass(cls, SymmetricForm):
        return (cls.size, cls.size)
    return (0, 0)


def kinds() -> dict[str, tuple[str, str, tuple[int, ...]]]:
    """The kinds :func:`from_array` builds, derived from the classes (:func:`pgsym.kinds.object_classes`):
    name → (module of pgsym, class, shape of one object's array). Imports the exact core.

    >>> kinds()["conic"]
    ('conics', 'Conic', (3, 3))
    """
    from ..kinds import object_classes  # noqa: PLC0415 — numeric → core by design: exact objects on request; numeric loads without SymPy

    return {kind: (cls.__module__.removeprefix("pgsym."), cls.__name__, _shape(cls))
            for kind, cls in object_classes().items()}


def __getattr__(name: str) -> Any:
    if name == "KINDS":  # the table of earlier versions, now derived from the classes on first use
        return kinds()
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


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
    :func:`kinds`. Zero rows raise :class:`~pgsym.errors.ZeroVectorError` and rows off the
    Klein quadric :class:`~pgsym.errors.NotOnKleinQuadricError`, as the constructors do.

    >>> from_array([0.5, 0.25, 1], "point")
    Point(S(1)/2, S(1)/4, 1)
    >>> from_array(np.eye(3), "transformation").dim
    2
    """
    from ..kinds import object_classes  # noqa: PLC0415 — numeric → core by design: exact objects on request; numeric loads without SymPy

    classes = object_classes()
    name = kind.__name__ if isinstance(kind, type) else kind
    key = {cls.__name__: key for key, cls in classes.items()}.get(name, name)
    if key not in classes:
        raise ObjectTypeError(f"from_array: unknown kind {kind!r}; use one of {', '.join(classes)} or their classes")
    cls = classes[key]
    cls_name, shape = cls.__name__, _shape(cls)
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
