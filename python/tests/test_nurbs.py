"""``qsic.nurbs``: the CLI's JSON, and exact NURBS checked in exact arithmetic — every rational
curve evaluated in ``Fraction``s at many parameters lies on both quadrics (residual zero)."""

from __future__ import annotations

import json
from fractions import Fraction

import pytest

import qsic
from qsic import QsicError

from conftest import run_cli

# (A, B, the two surfaces as exact functions of (x, y, z), the number of curves)
RATIONAL = [
    ("x^2+y^2+z^2-4", "x^2+y^2-2*x",
     (lambda x, y, z: x * x + y * y + z * z - 4, lambda x, y, z: x * x + y * y - 2 * x), 2),
    ("x^2+y^2-1", "x^2+z^2-1",
     (lambda x, y, z: x * x + y * y - 1, lambda x, y, z: x * x + z * z - 1), 4),
    ("x^2+y^2-1", "z-x", (lambda x, y, z: x * x + y * y - 1, lambda x, y, z: z - x), 1),
    ("x^2+y^2-z^2", "y-1", (lambda x, y, z: x * x + y * y - z * z, lambda x, y, z: y - 1), 2),
    ("x^2+y^2-z^2", "z-x-1", (lambda x, y, z: x * x + y * y - z * z, lambda x, y, z: z - x - 1), 1),
    ("x^2+y^2-z^2", "x", (lambda x, y, z: x * x + y * y - z * z, lambda x, y, z: x), 4),
]


def de_casteljau(points, weights, t):
    """The point of one rational Bézier segment at ``t``, exactly (homogeneous, then divided)."""
    work = [(w * p[0], w * p[1], w * p[2], w) for p, w in zip(points, weights)]
    while len(work) > 1:
        work = [tuple((1 - t) * a + t * b for a, b in zip(u, v)) for u, v in zip(work, work[1:])]
    x, y, z, w = work[0]
    return x / w, y / w, z / w


@pytest.mark.parametrize("a,b,surfaces,count", RATIONAL, ids=[f"{a} & {b}" for a, b, _, _ in RATIONAL])
def test_rational_nurbs_lie_exactly_on_both_surfaces(a, b, surfaces, count):
    n = qsic.nurbs(a, b)
    assert len(n["curves"]) == count, n["left"]
    for c in n["curves"]:
        assert c["exact"] and c["bound"] == 0
        d = c["degree"]
        mults = c["multiplicities"]
        assert mults[0] == mults[-1] == d + 1 and all(m == d for m in mults[1:-1])
        assert len(c["control_points"]) == sum(mults) - d - 1
        points = [tuple(Fraction(v) for v in p) for p in c["control_points"]]
        weights = [Fraction(w) for w in c["weights"]]
        assert all(w > 0 for w in weights)
        for k in range(len(c["knots"]) - 1):
            seg = slice(k * d, k * d + d + 1)
            for t in (Fraction(i, 17) for i in range(18)):
                p = de_casteljau(points[seg], weights[seg], t)
                assert [f(*p) for f in surfaces] == [0, 0], (a, b, k, t)


def test_the_python_dict_equals_the_cli_json(cli):
    for a, b, _, _ in RATIONAL:
        out = run_cli(cli, "nurbs", "--json", a, b)
        assert out.returncode == 0, out.stderr.decode()
        assert json.loads(out.stdout) == qsic.nurbs(a, b)
        step = run_cli(cli, "nurbs", "--format", "step", a, b)
        assert step.stdout.decode() == qsic.nurbs(a, b, step=True)


def test_a_box_of_the_users_clips_the_hyperbola():
    n = qsic.nurbs("x^2+y^2-z^2", "y-1", bounds=(-3, -3, -3, 3, 3, 3))
    assert n["bounds"] == {"lo": ["-3", "-3", "-3"], "hi": ["3", "3", "3"]}
    for c in n["curves"]:
        assert c["clipped"] == [True, True]
        for end in (c["approx"]["control_points"][0], c["approx"]["control_points"][-1]):
            assert max(abs(v) for v in end) == pytest.approx(3, abs=1e-6)
    with pytest.raises(QsicError, match="six numbers"):
        qsic.nurbs("x^2+y^2-z^2", "y-1", bounds=(1, 2, 3))


def test_quartic_branches_are_approximated_within_the_tolerance():
    """Every control point's curve within the bound of both surfaces, checked at the decimals
    (the residual over the gradient, a first-order distance) and the tolerance honoured."""
    a, b = "x^2+y^2+z^2-4", "x^2+y^2-2*x+1/2"
    for tolerance in (None, 1e-6):
        n = qsic.nurbs(a, b, tolerance=tolerance)
        assert [c["exact"] for c in n["curves"]] == [False, False], n["left"]
        assert n["left"] == []
        for c in n["curves"]:
            assert c["u"] is None and c["degree"] == 7
            assert 0 < c["bound"] <= (tolerance or 1e-8)
    with pytest.raises(QsicError, match="tolerance"):
        qsic.nurbs(a, b, tolerance=-1.0)
