"""`classify_many`: a bad row is that row's `error` entry whatever it holds (None, objects that
cannot be read, bytes, complex numbers, non-finite numbers, rows of the wrong shape, integers
beyond the limits, strings that are not Unicode); the other rows are answered as if alone.
Only arguments that make the whole call meaningless raise."""

from __future__ import annotations

from decimal import Decimal
from fractions import Fraction
from typing import Any, List

import numpy as np
import pytest

import qsic

SPHERE = [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, -1]]
CYLINDER = [[2, 0, 0, 0], [0, 4, 0, 0], [0, 0, 0, 0], [0, 0, 0, -1]]


class Unprintable:
    """An object whose str() and repr() raise."""

    def __str__(self) -> str:
        raise RuntimeError("no str")

    __repr__ = __str__


class BadRatio:
    """A number-like object whose as_integer_ratio raises something unexpected."""

    def as_integer_ratio(self) -> Any:
        raise RuntimeError("no ratio")


def with_entry(value: Any, at: tuple = (0, 1)) -> List[List[Any]]:
    """SPHERE with `value` at `at` and at its mirror (so only the value can be wrong)."""
    m = [list(r) for r in SPHERE]
    i, j = at
    m[i][j] = value
    m[j][i] = value
    return m


# (what the bad row holds, words its message must contain)
BAD_ROWS = [
    (with_entry(None), ["entry (0,1)", "None"]),
    (with_entry(Unprintable()), ["entry (0,1)", "Unprintable"]),
    (with_entry(BadRatio()), ["entry (0,1)", "BadRatio", "no ratio"]),
    (with_entry(b"1"), ["entry (0,1)", "bytes"]),
    (with_entry(1 + 2j), ["entry (0,1)", "complex"]),
    (with_entry(0j), ["entry (0,1)", "complex"]),
    (with_entry(True), ["entry (0,1)", "bool"]),
    (with_entry({"x": 1}), ["entry (0,1)", "dict"]),
    (with_entry([1, 2]), ["entry (0,1)", "list"]),
    (with_entry(float("nan")), ["entry (0,1) is not a finite number"]),
    (with_entry(float("-inf")), ["entry (0,1) is not a finite number"]),
    (with_entry(Decimal("NaN")), ["entry (0,1) is not a finite number"]),
    (with_entry(Decimal("sNaN")), ["entry (0,1) is not a finite number"]),
    (with_entry(Decimal("-Infinity")), ["entry (0,1) is not a finite number"]),
    (with_entry(np.datetime64("2020-01-01")), ["entry (0,1)", "datetime64"]),
    (with_entry(10**20000), ["entry (0,1)", "limit"]),
    (with_entry(Fraction(1, 10**20000)), ["entry (0,1)", "limit"]),
    (with_entry(Decimal("1e999999999")), ["entry (0,1)", "limit"]),
    (with_entry("\ud800"), ["entry (0,1)", "Unicode"]),
    (with_entry("1/0"), ["entry (0,1)", "zero denominator"]),
    ([[1, 0], [0, 1]], ["4x4", "(2, 2)"]),
    ([[1, 0, 0, 0]] * 3 + [[0, 0, 0]], ["4x4"]),
    (None, ["4x4", "None"]),
    ({"a": 1}, ["4x4", "dict"]),
    ("x^2+y^2+z^2-1", ["4x4", "str"]),
    (7, ["4x4", "int"]),
]


@pytest.mark.parametrize("bad, words", BAD_ROWS, ids=[str(k) for k in range(len(BAD_ROWS))])
@pytest.mark.parametrize("side", ["A", "B"])
def test_one_bad_row_is_its_error_the_others_are_answered(bad, words, side):
    rows = [SPHERE, bad, SPHERE]
    others = [CYLINDER] * 3
    A, B = (rows, others) if side == "A" else (others, rows)
    alone = qsic.classify_many(np.array([A[0]]), np.array([B[0]]))  # a good row by itself
    cols = qsic.classify_many(A, B)
    message = cols["error"][1]
    assert isinstance(message, str) and message.startswith(f"{side}: "), message
    for w in words:
        assert w in message, (w, message)
    for key in qsic.FIELDS:
        assert cols[key][0] == alone[key][0] and cols[key][2] == alone[key][0], key
    assert cols["error"][0] is None and cols["error"][2] is None
    # the error entry has the shape of every other error entry
    assert cols["pencil"][1] is None and cols["case"][1] == 0
    assert cols["components"][1] is None and cols["singular_points"][1] is None


def test_bad_rows_in_object_arrays_and_on_both_sides():
    A = np.empty(4, dtype=object)  # a 1-d object array of rows
    for k, row in enumerate([SPHERE, with_entry(None), with_entry(Unprintable()), np.array(SPHERE)]):
        A[k] = row
    B = np.empty(4, dtype=object)
    for k, row in enumerate([CYLINDER, CYLINDER, with_entry(1j), with_entry(1j)]):
        B[k] = row
    cols = qsic.classify_many(A, B)
    assert cols["error"][0] is None and cols["case"][0] == 1
    assert cols["error"][1].startswith("A: entry (0,1) is None")
    assert cols["error"][2].startswith("A: entry (0,1)")  # A is read first, as in the CLI
    assert cols["error"][3].startswith("B: entry (0,1)") and "complex" in cols["error"][3]
    # a regular object array with one bad entry
    A = np.array([SPHERE, with_entry(None), SPHERE], dtype=object)
    cols = qsic.classify_many(A, np.array([CYLINDER] * 3))
    assert [e is None for e in cols["error"]] == [True, False, True]


def test_mixed_entries_keep_their_exact_values():
    """A list mixing ints, floats, strings and Fractions is read entry by entry: the float
    0.5 is exact, the string "0.1" one tenth, and no int passes through a float."""
    big = 2**60 + 1  # not a float
    a = [[big, 0, 0, 0], [0, big, 0, 0], [0, 0, big, 0], [0, 0, 0, -big]]
    b = [[0.5, 0, 0, 0], [0, "0.1", 0, 0], [0, 0, 0, 0], [0, 0, 0, Fraction(-1, 3)]]
    cols = qsic.classify_many([a, SPHERE], [b, b])
    single = qsic.classify(a, b, affine=False)
    assert cols["error"][0] is None
    for key in qsic.FIELDS:
        got = cols[key][0]
        assert (None if key == "case" and got == 0 else got) == getattr(single, key), key
    # a bytes row among mixed rows is that row's error, the int row is not turned into bytes
    cols = qsic.classify_many([SPHERE, with_entry(b"1")], [CYLINDER, CYLINDER])
    assert cols["error"][0] is None and "bytes" in cols["error"][1]


def test_whole_arrays_of_unreadable_types_are_errors_row_by_row():
    for dtype in (complex, "S4", "datetime64[s]", "timedelta64[s]", "timedelta64[ns]", "datetime64[ns]", "V8"):
        A = np.zeros((3, 4, 4), dtype=dtype)
        cols = qsic.classify_many(A, np.array([CYLINDER] * 3))
        assert len(cols["error"]) == 3, dtype
        for message in cols["error"]:
            assert message is not None and message.startswith("A: entry (0,0)"), (dtype, message)


def test_long_double_arrays_are_read_exactly():
    """np.longdouble holds more bits than float64: it must not be rounded to it. The sphere
    of squared radius 1 + 2⁻⁶⁰ is not the unit sphere, which float64 would make it."""
    if np.finfo(np.longdouble).nmant < 60:
        pytest.skip("long double has no 61 bits here")
    r2 = np.longdouble(1) + np.longdouble(2) ** -60
    A = np.array([SPHERE], dtype=np.longdouble)
    A[0, 3, 3] = -r2
    B = np.array([SPHERE])
    exact = qsic.classify_many(
        np.vectorize(lambda x: Fraction(*x.as_integer_ratio()), otypes=[object])(A), B
    )
    rounded = qsic.classify_many(A.astype(np.float64), B)
    assert exact["segre"][0] != rounded["segre"][0]  # the test can tell them apart
    cols = qsic.classify_many(A, B)
    for key in qsic.FIELDS:
        assert cols[key][0] == exact[key][0], key
    assert qsic.Quadric(A[0]).matrix[3, 3] == -Fraction(*r2.as_integer_ratio())


def test_big_integers_beyond_python_str_limit_are_read():
    """Integers of more than 4300 digits (Python's str() limit) but within the library's
    10 000 digits are read exactly."""
    big = 10**5000 + 1
    m = [[big, 0, 0, 0], [0, big, 0, 0], [0, 0, big, 0], [0, 0, 0, -big]]
    cols = qsic.classify_many([m], [CYLINDER])
    assert cols["error"][0] is None
    assert cols["case"][0] == qsic.classify_many(np.array([SPHERE]), np.array([CYLINDER]))["case"][0]
    assert qsic.Quadric(m).matrix[0, 0] == big


@pytest.mark.parametrize(
    "A, B, error",
    [
        ([SPHERE, SPHERE], [CYLINDER], qsic.QsicError),  # lengths differ
        (np.array([SPHERE] * 2), np.array([CYLINDER] * 3), qsic.QsicError),
        (5, [CYLINDER], TypeError),  # not a sequence
        (None, [CYLINDER], TypeError),
        ("x^2", [CYLINDER], TypeError),
        ({"A": SPHERE}, [CYLINDER], TypeError),
        (np.float64(1.0), [CYLINDER], TypeError),
        (np.zeros((4, 4)), np.zeros((4, 4)), qsic.QsicError),  # one matrix, not a batch
        (np.zeros((2, 4, 3)), np.zeros((2, 4, 3)), qsic.QsicError),
    ],
)
def test_meaningless_arguments_raise(A, B, error):
    with pytest.raises(error) as e:
        qsic.classify_many(A, B)
    assert str(e.value)  # a message, naming what is wrong
    assert str(e.value).startswith(("A", "B")) or "length" in str(e.value)


def test_empty_batches_give_empty_columns():
    for empty in ([], np.zeros((0, 4, 4)), np.zeros((0, 4, 4), dtype=object)):
        cols = qsic.classify_many(empty, empty)
        assert all(len(cols[key]) == 0 for key in (*qsic.FIELDS, "error"))
