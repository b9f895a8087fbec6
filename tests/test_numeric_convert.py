"""Exact objects ↔ float64 arrays, both ways, and the light import of the numeric path."""

from __future__ import annotations

import subprocess
import sys

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from strategies import integers

import pgsym.numeric as pn
from pgsym.errors import DimensionError, NonFiniteError, NonNumericError, ObjectTypeError, ZeroVectorError

small = integers(20)


@settings(max_examples=25, deadline=None)
@given(st.lists(st.tuples(small, small, small).filter(any), min_size=1, max_size=5))
def test_points_and_lines_round_trip_exactly(rows):
    from pgsym.projective_plane import Line, Point

    for cls, kind in ((Point, "point"), (Line, "line")):
        objects = [cls(*r) for r in rows]
        array = pn.to_array(objects)
        assert array.shape == (len(rows), 3) and array.dtype == np.float64
        assert array.tolist() == [list(r) for r in rows]
        back = pn.from_array(array, kind)
        assert back == objects and pn.from_array(array, cls) == objects
        assert all(b.coords == o.coords for b, o in zip(back, objects, strict=True))  # the same numbers


def test_every_kind_round_trips():
    from pgsym.conics import Conic, DualConic
    from pgsym.plucker import Line3
    from pgsym.projective_line import Point1
    from pgsym.quadrics import Quadric
    from pgsym.space import Plane, Point3
    from pgsym.transformations import Transformation

    samples = {
        "point1": Point1(3, 1),
        "point3": Point3(1, 2, 3, 0),
        "plane": Plane(1, -1, 2, 5),
        "line3": Line3.join(Point3(1, 2, 3), Point3(0, 1, 0, 0)),
        "conic": Conic([[1, 0, 0], [0, 1, 0], [0, 0, -1]]),
        "dual_conic": DualConic([[1, 0, 0], [0, 1, 0], [0, 0, 0]]),
        "quadric": Quadric([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, -4]]),
        "transformation": Transformation([[1, 2, 0], [0, 1, 0], [0, 0, 1]]),
    }
    for kind, obj in samples.items():
        array = pn.to_array(obj)
        back = pn.from_array(array, kind)
        assert type(back) is type(obj) and back == obj, kind
        assert pn.from_array(np.stack([array, 2 * array]), kind) == [obj, obj]
    # nested batches keep their shape; fractions come back as the decimals they print as
    from pgsym.projective_plane import Point

    grid = pn.from_array(np.arange(1.0, 13.0).reshape(2, 2, 3), "point")
    assert grid[1][0] == Point(7, 8, 9)
    assert pn.from_array([0.5, 0.25, 1], "point") == Point(2, 1, 4)
    assert pn.to_array(pn.from_array([0.1, 0.2, 1.0], "point")).tolist() == [0.1, 0.2, 1.0]


def test_conversion_errors_are_named():
    import sympy

    from pgsym.projective_plane import Point

    with pytest.raises(NonNumericError, match="symbolic"):
        pn.to_array(Point(sympy.Symbol("a"), 1))
    with pytest.raises(ObjectTypeError):
        pn.to_array([1.0, 2.0])
    with pytest.raises(DimensionError, match="different sizes"):
        pn.to_array([Point(1, 2), Point(1, 2).dual(), a_point_of_space()])
    with pytest.raises(ObjectTypeError, match="unknown kind"):
        pn.from_array([1.0, 2, 3], "ellipse")
    with pytest.raises(DimensionError, match="trailing shape"):
        pn.from_array([1.0, 2, 3, 4], "point")
    with pytest.raises(ZeroVectorError):
        pn.from_array([[1.0, 2, 3], [0, 0, 0]], "line")
    with pytest.raises(NonFiniteError, match="NaN"):
        pn.from_array([np.nan, 1.0, 1.0], "point")


def a_point_of_space():
    from pgsym.space import Point3

    return Point3(1, 2, 3)


def test_numeric_path_imports_no_sympy_and_no_heavy_optional_library():
    code = (
        "import sys, numpy as np\n"
        "import pgsym\n"
        "import pgsym.numeric as pn\n"
        "x = pn.meet(pn.join(np.eye(3), np.ones(3)), [1.0, 0, -2])\n"
        "pn.dehomogenize(pn.transform_points(np.eye(3), pn.homogenize(np.ones((4, 2)))))\n"
        "pn.plane_through(np.eye(4), np.ones(4), [0.0, 0, 1, 1])\n"
        "pn.cross_ratio([0.0, 1], [1.0, 1], [2.0, 1], [3.0, 1])\n"
        "pn.plucker_join(np.eye(4), np.ones(4)); pn.transform_conics(np.eye(3), np.eye(3))\n"
        "print(sorted(m for m in ('sympy', 'matplotlib', 'scipy', 'cv2', 'skimage') if m in sys.modules))\n"
    )
    result = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert result.stdout.strip() == "[]"


def test_import_pgsym_alone_imports_no_sympy():
    code = "import sys, pgsym; print('sympy' in sys.modules, 'numpy' in sys.modules)"
    result = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert result.stdout.strip() == "False False"
