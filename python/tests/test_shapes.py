"""`Quadric` constructors: polynomial strings, arrays and the shapes of `qsic::shapes`, each
against the equation the shape states."""

from __future__ import annotations

from fractions import Fraction

import numpy as np
import pytest

import qsic
from qsic import Quadric

SHAPES = [
    (Quadric.sphere, ([1, 2, 3], 4), "(x-1)^2+(y-2)^2+(z-3)^2-4"),
    (Quadric.ellipsoid, ([0, 0, 1], [1, 4, 9]), "x^2+y^2/4+(z-1)^2/9-1"),
    (Quadric.cylinder, ([0, 0, 0], [0, 0, 2], Fraction(1, 4)), "4*(x^2+y^2)-4*(1/4)"),
    (Quadric.elliptic_cylinder, ([1, 0], [4, 1]), "(x-1)^2/4+y^2-1"),
    (Quadric.cone, ([0, 0, 0], [0, 0, 1], Fraction(1, 2)), "z^2-(1/2)*(x^2+y^2+z^2)"),
    (Quadric.elliptic_cone, ([0, 0, 0], [1, 4]), "x^2+y^2/4-z^2"),
    (Quadric.elliptic_paraboloid, ([0, 0, 0], [1, 1]), "x^2+y^2-z"),
    (Quadric.hyperbolic_paraboloid, ([0, 0, 0], [1, 1]), "x^2-y^2-z"),
    (Quadric.hyperboloid_one_sheet, ([0, 0, 0], [1, 1, 1]), "x^2+y^2-z^2-1"),
    (Quadric.hyperboloid_two_sheets, ([0, 0, 0], [1, 1, 1]), "z^2-x^2-y^2-1"),
    (Quadric.plane_pair, ([1, 0, 0], -1, [0, 1, 0], 2), "(x-1)*(y+2)"),
]


@pytest.mark.parametrize("make,args,equation", SHAPES, ids=lambda v: getattr(v, "__name__", None))
def test_shapes_equal_their_equations(make, args, equation):
    assert make(*args) == Quadric(equation)


def test_array_string_and_matrix_round_trip():
    q = Quadric("x^2 + y^2 + z^2 - w^2")
    assert q == Quadric([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, -1]])
    assert q == Quadric(np.diag([1, 1, 1, -1]))
    assert q == Quadric(q.polynomial) == Quadric(q.matrix) == Quadric(q)
    assert q != Quadric("2*x^2 + 2*y^2 + 2*z^2 - 2*w^2")  # same surface, other matrix
    assert repr(q) == "Quadric('x^2 + y^2 + z^2 - w^2')" and str(q) == q.polynomial
    assert Quadric("z - 1").is_plane and not q.is_plane


def test_shapes_classify_as_their_geometry():
    """Two unit spheres with centres 2 apart touch at one point (externally)."""
    a = Quadric.sphere([0, 0, 0], 1)
    b = Quadric.sphere([2, 0, 0], 1)
    r = qsic.classify(a, b)
    assert r.affine["solids"] == "touching_externally"
    assert r.affine["surfaces"] == ["sphere", "sphere"]
    assert "pencil:" in str(r) and "in R^3" in str(r)
