"""The work budget (``budget=``): a call over it raises the budget error, a row over it is an
error row among answered rows, the default answers, and a bad budget is refused at once."""

import numpy as np
import pytest

import qsic
from qsic import QsicError

SPHERES = ("x^2+y^2+z^2-1", "(x-2)^2+y^2+z^2-1")  # tangent: the exact path
CLOSE = ("x^2+y^2+z^2-w^2", "x^2+(1+1e-1600)*y^2+2*z^2+3*w^2")  # roots 1e-1600 apart


def test_a_call_over_its_budget_raises_and_a_larger_one_answers():
    with pytest.raises(QsicError, match="over the work budget: 1000 units"):
        qsic.classify(*SPHERES, budget=1000, affine=False)
    c = qsic.classify(*SPHERES, budget=10**9, affine=False)
    assert c.case == qsic.classify(*SPHERES).case
    # the affine view builds the curve here (real points at infinity): its units count
    # against the same budget
    hyperboloids = ("x^2+y^2-z^2-1", "x^2-3*y^2+z^2-2")
    assert qsic.classify(*hyperboloids, budget=20_000, affine=False).case == 1
    with pytest.raises(QsicError, match="over the work budget"):
        qsic.classify(*hyperboloids, budget=20_000)


def test_curve_and_points_take_the_budget():
    viviani = ("x^2+y^2+z^2-4", "(x-1)^2+y^2-1")
    with pytest.raises(QsicError, match="over the work budget"):
        qsic.param(*viviani, budget=10)
    assert qsic.param(*viviani, budget=10**9)["case"] == qsic.param(*viviani)["case"]
    with pytest.raises(QsicError, match="over the work budget"):
        qsic.sample(*viviani, points=100_000, budget=10**6)
    s = qsic.sample(*viviani, points=100, budget=10**9)
    assert len(s["components"]) == 1


def test_a_row_over_its_budget_is_an_error_row_and_the_others_are_answered():
    def matrices(texts):
        return [qsic.Quadric(t).matrix for t in texts]

    a = matrices([SPHERES[0], CLOSE[0], SPHERES[0]])
    b = matrices(["x^2+2*y^2-1", CLOSE[1], "x^2+2*y^2-2"])
    out = qsic.classify_many(a, b, budget=10**5)
    assert out["error"][0] is None and out["error"][2] is None
    assert "over the work budget: 100000 units" in out["error"][1]
    assert out["case"][1] == 0
    full = qsic.classify_many(a, b)
    assert list(full["error"]) == [None, None, None]
    assert out["case"][0] == full["case"][0] and out["case"][2] == full["case"][2]


@pytest.mark.parametrize("bad", [0, -1, 2**64, 1.5, "1e9", True, np.bool_(True)])
def test_a_bad_budget_is_refused(bad):
    with pytest.raises(QsicError, match="budget must be a positive integer"):
        qsic.classify(*SPHERES, budget=bad)
    with pytest.raises(QsicError, match="budget must be a positive integer"):
        qsic.classify_many(np.zeros((1, 4, 4)), np.zeros((1, 4, 4)), budget=bad)


def test_the_default_is_the_cli_default():
    assert qsic.DEFAULT_BUDGET == 10**12
    assert qsic.classify(*SPHERES, budget=np.int64(10**12)).case == qsic.classify(*SPHERES).case


# a sphere moving along the x axis through a fixed one: instants ±3, ±1 and 0 (concentric)
MOVING = ("(x-t)^2+y^2+z^2-4", "x^2+y^2+z^2-1")


def test_motion_and_first_contact_take_the_budget():
    full = qsic.motion(*MOVING)
    assert [i["t"] for i in full["instants"]] == ["-3", "-1", "0", "1", "3"]
    with pytest.raises(QsicError, match="over the work budget: 100 units"):
        qsic.motion(*MOVING, budget=100)
    assert qsic.motion(*MOVING, budget=10**9) == full
    contact = qsic.first_contact(*MOVING)
    assert contact["first_contact"] == "-3"
    with pytest.raises(QsicError, match="over the work budget: 100 units"):
        qsic.first_contact(*MOVING, budget=100)
    assert qsic.first_contact(*MOVING, budget=10**9) == contact


@pytest.mark.parametrize("bad", [0, -5, 2**64, 2.5])
def test_a_bad_motion_budget_is_refused(bad):
    with pytest.raises(QsicError, match="budget must be a positive integer"):
        qsic.motion(*MOVING, budget=bad)
    with pytest.raises(QsicError, match="budget must be a positive integer"):
        qsic.first_contact(*MOVING, budget=bad)
