"""Numbers are read exactly: a float is the binary fraction it holds, a string its decimal."""

from __future__ import annotations

from decimal import Decimal
from fractions import Fraction

import numpy as np
import pytest

import qsic


def test_float_entries_are_converted_exactly():
    q = qsic.Quadric([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 0.1]])
    assert q.matrix[3, 3] == Fraction(0.1) == Fraction(3602879701896397, 2**55)
    assert q.matrix[3, 3] != Fraction(1, 10)
    assert qsic.Quadric([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, "0.1"]]).matrix[3, 3] == Fraction(1, 10)
    for exact in (Fraction(1, 3), Decimal("0.25"), np.float32(0.1), 2**80, np.int64(-7)):
        m = qsic.Quadric([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, exact]]).matrix
        assert m[3, 3] == Fraction(*exact.as_integer_ratio()) if isinstance(exact, np.floating) else Fraction(exact)


def test_tangent_spheres_are_tangent_only_with_exact_decimals():
    """Spheres of radii 1/10 and 2/10 whose centres are 3/10 apart touch at one point; the
    floats 0.3, 0.05, 0.01 are not those decimals, and the float spheres do not touch."""
    a_text = [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, "-1/100"]]
    b_text = [[1, 0, 0, "-3/10"], [0, 1, 0, 0], [0, 0, 1, 0], ["-3/10", 0, 0, "1/20"]]
    a_float = [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, -0.01]]
    b_float = [[1, 0, 0, -0.3], [0, 1, 0, 0], [0, 0, 1, 0], [-0.3, 0, 0, 0.05]]
    exact = qsic.classify(a_text, b_text, affine=False)
    floats = qsic.classify(a_float, b_float, affine=False)
    assert exact.to_dict() == qsic.classify(
        "x^2+y^2+z^2-0.01", "(x-0.3)^2+y^2+z^2-0.04", affine=False
    ).to_dict()
    assert exact.real_type != floats.real_type
    # the same float pair through every batch route: float64, object floats, Fractions
    A = np.array([a_float] * 3, dtype=np.float64)
    B = np.array([b_float] * 3, dtype=np.float64)
    routes = [
        qsic.classify_many(A, B),
        qsic.classify_many(A.astype(object), B.astype(object)),
        qsic.classify_many(
            np.vectorize(Fraction, otypes=[object])(A), np.vectorize(Fraction, otypes=[object])(B)
        ),
    ]
    for cols in routes:
        assert list(cols["real_type"]) == [floats.real_type] * 3
        assert list(cols["case"]) == [floats.case] * 3
    texts = qsic.classify_many(np.array([a_text], dtype=object), np.array([b_text], dtype=object))
    assert texts["real_type"][0] == exact.real_type and texts["case"][0] == exact.case


def test_big_integers_and_unsigned_arrays():
    big = 2**70
    A = np.array([[[big, 0, 0, 0], [0, big, 0, 0], [0, 0, big, 0], [0, 0, 0, -big]]], dtype=object)
    B = np.array([[[2, 0, 0, 0], [0, 4, 0, 0], [0, 0, 0, 0], [0, 0, 0, -1]]], dtype=np.int16)
    cols = qsic.classify_many(A, B)
    assert cols["error"][0] is None
    assert (cols["case"][0], cols["real_type"][0]) == (1, "two_finite_components")
    # uint64 beyond the range of int64 goes through exact integers
    huge = np.array([[[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 2**64 - 1, 0], [0, 0, 0, 0]]], dtype=np.uint64)
    got = qsic.classify_many(huge, B)
    assert got["error"][0] is None and got["pencil"][0] == "regular"
    for key in qsic.FIELDS:
        assert got[key][0] == qsic.classify_many(huge.astype(object), B)[key][0], key


@pytest.mark.parametrize("bad", [np.zeros((2, 4, 3)), np.zeros((4, 4)), np.zeros(5), np.zeros((2, 16))])
def test_bad_array_shapes_and_types_raise(bad):
    with pytest.raises(qsic.QsicError):
        qsic.classify_many(bad, bad)
