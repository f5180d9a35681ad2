"""Errors: one bad row is an `error` entry with the CLI's message, never an exception for the
batch; single calls raise `QsicError`, a `ValueError` with the library's message."""

from __future__ import annotations

import numpy as np
import pytest
from conftest import cli_batch, run_cli

import qsic

SPHERE = [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, -1]]
CYLINDER = [[2, 0, 0, 0], [0, 4, 0, 0], [0, 0, 0, 0], [0, 0, 0, -1]]
NOT_SYMMETRIC = [[1, 2, 0, 0], [3, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, -1]]
ZERO = [[0] * 4] * 4
BAD_NUMBER = [["1/0", 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, -1]]


def test_bad_rows_are_errors_with_the_cli_messages(cli):
    pairs = [
        (SPHERE, CYLINDER),
        (NOT_SYMMETRIC, CYLINDER),
        (SPHERE, NOT_SYMMETRIC),
        (ZERO, ZERO),
        (ZERO, CYLINDER),
        (BAD_NUMBER, SPHERE),
        (SPHERE, CYLINDER),
    ]
    A = np.array([a for a, _ in pairs], dtype=object)
    B = np.array([b for _, b in pairs], dtype=object)
    cols = qsic.classify_many(A, B)
    answers = cli_batch(cli, [{"id": k, "A": a, "B": b} for k, (a, b) in enumerate(pairs)], "--projective")
    bad = [1, 2, 3, 5]
    for k, answer in enumerate(answers):
        if k in bad:
            assert cols["error"][k] == answer["error"]["message"], k
            assert cols["pencil"][k] is None and cols["case"][k] == 0 and cols["components"][k] is None
        else:
            assert cols["error"][k] is None and "error" not in answer
            assert cols["pencil"][k] == answer["pencil"]
    assert cols["error"][1].startswith("A: matrix is not symmetric: entry (0,1) = 2 but (1,0) = 3")
    assert cols["error"][2].startswith("B: ")
    assert cols["error"][3].startswith("A and B: both are zero")
    assert cols["pencil"][4] == "single"  # one zero form: the other quadric alone
    # the same through the int64 route
    ints = qsic.classify_many(np.array([p[0] for p in pairs[:5]]), np.array([p[1] for p in pairs[:5]]))
    assert list(ints["error"]) == list(cols["error"][:5])


def test_non_finite_floats_are_row_errors():
    A = np.array([SPHERE, SPHERE, SPHERE], dtype=np.float64)
    A[1, 3, 3] = np.nan
    A[2, 0, 0] = np.inf
    B = np.array([CYLINDER] * 3, dtype=np.float64)
    cols = qsic.classify_many(A, B)
    assert cols["error"][0] is None
    assert cols["error"][1] == "A: entry (3,3) is not a finite number"
    assert cols["error"][2] == "A: entry (0,0) is not a finite number"
    # the same messages when the floats are read one by one
    for objects in (A.astype(object), [m.tolist() for m in A]):
        assert list(qsic.classify_many(objects, B)["error"]) == list(cols["error"])


def test_exceptions_are_value_errors_with_the_library_message(cli):
    assert issubclass(qsic.QsicError, ValueError)
    out = run_cli(cli, "classify", "x^2+*y", "y^2")
    assert out.returncode == 1
    with pytest.raises(ValueError) as e:
        qsic.classify("x^2+*y", "y^2")
    assert isinstance(e.value, qsic.QsicError)
    assert out.stderr.decode().strip() == f"error: {e.value}"
    with pytest.raises(qsic.QsicError, match=r"^A and B: both are zero"):
        qsic.classify("0", "0")
    with pytest.raises(qsic.QsicError, match=r"not symmetric: entry \(0,1\)"):
        qsic.Quadric(NOT_SYMMETRIC)
    with pytest.raises(qsic.QsicError, match="zero form"):
        qsic.Quadric(ZERO)
    with pytest.raises(qsic.QsicError, match="4x4"):
        qsic.Quadric([[1, 0], [0, 1]])
    with pytest.raises(qsic.QsicError, match="must be positive"):
        qsic.Quadric.sphere([0, 0, 0], -1)
