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


def test_a_machine_array_reads_as_its_entries_do():
    """A 4×4 int, unsigned or float NumPy array goes to the library as bytes (the
    route of a classify_many row); its quadric, its errors and its classification equal
    those of the same entries read one by one (an object array), for every reading of
    floats — an asymmetric matrix catches a transposed read, 0.1 and 2⁻⁶⁰ a rounded one."""
    def entries(m):  # an object array of the NumPy scalars themselves (float32 stays float32)
        out = np.empty((4, 4), dtype=object)
        for i in range(4):
            for j in range(4):
                out[i, j] = m[i, j]
        return out

    rng = np.random.default_rng(3)
    base = rng.integers(-9, 10, (4, 4))
    sym = base + base.T
    arrays = [
        sym.astype(np.int64),
        sym.astype(np.int16),
        (sym + 10).astype(np.uint64),
        sym.astype(np.float64) * 0.1 + 2.0**-60,
        sym.astype(np.float32) / 3,
    ]
    for m in arrays:
        for floats in ("binary", "shortest"):
            fast = qsic.Quadric(m, floats=floats)
            slow = qsic.Quadric(entries(m), floats=floats)
            assert (fast.matrix == slow.matrix).all(), (m.dtype, floats)
    big = np.array([[2**63 + 1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]], dtype=np.uint64)
    assert qsic.Quadric(big).matrix[0, 0] == 2**63 + 1
    asym = sym.astype(np.float64)
    asym[0, 1] += 0.5
    for m in (asym, asym.astype(np.int64)):
        with pytest.raises(qsic.QsicError) as fast:
            qsic.Quadric(m)
        with pytest.raises(qsic.QsicError) as slow:
            qsic.Quadric(entries(m))
        assert str(fast.value) == str(slow.value) and "not symmetric" in str(fast.value)
    with pytest.raises(qsic.QsicError, match="is a bool"):
        qsic.Quadric(sym > 0)  # as its entries: a bool is not a number
    nan = sym.astype(np.float64)
    nan[2, 2] = np.nan
    with pytest.raises(qsic.QsicError, match=r"entry \(2,2\)"):
        qsic.Quadric(nan)
    a = np.diag([1.0, 1.0, 1.0, -4.0])
    b = np.array([[1.0, 0, 0, -3], [0, 1, 0, 0], [0, 0, 1, 0], [-3, 0, 0, 8]])
    assert qsic.classify(a, b).to_dict() == qsic.classify(entries(a), entries(b)).to_dict()
