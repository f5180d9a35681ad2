"""The curve and motion APIs equal the CLI's JSON (`qsic param --json`, `qsic sample`,
`qsic motion --json`, `qsic contact --json`); sampled points lie on both quadrics."""

from __future__ import annotations

import json
from decimal import Decimal
from fractions import Fraction

import numpy as np
import pytest
from conftest import CORPUS, read_jsonl, run_cli

import qsic

PAIRS = [
    ("x^2+y^2+z^2-w^2", "2*x^2+4*y^2-w^2"),  # case 1: two closed quartic branches
    ("x^2+y^2+z^2-1", "x^2+y^2-z^2"),  # two circles
    ("x^2+y^2-1", "x^2+z^2-1"),  # Steinmetz: two crossing ellipses
]


def cli_json(cli, *args):
    out = run_cli(cli, *args)
    assert out.returncode == 0, out.stderr.decode()
    return json.loads(out.stdout)


@pytest.mark.parametrize("a,b", PAIRS)
def test_param_equals_cli(cli, a, b):
    assert qsic.param(a, b) == cli_json(cli, "param", "--json", a, b)


@pytest.mark.parametrize("a,b", PAIRS)
def test_param_options_equal_the_cli_flags(cli, a, b):
    projective = qsic.param(a, b, affine=False)
    assert projective == cli_json(cli, "param", "--json", "--projective", a, b)
    assert "affine" not in projective
    charted = qsic.param(a, b, chart="z")
    assert charted == cli_json(cli, "param", "--json", "--chart", "z", a, b)
    assert charted["affine"]["chart"] == "z"


@pytest.mark.parametrize("a,b", PAIRS)
def test_sample_equals_cli_and_lies_on_both_quadrics(cli, a, b):
    got = qsic.sample(a, b, points=16)
    want = cli_json(cli, "sample", "--points", "16", a, b)
    qa, qb = (np.array(qsic.Quadric(q).matrix, dtype=float) for q in (a, b))
    assert len(got["components"]) == len(want["components"]) > 0
    for piece, expected in zip(got["components"], want["components"]):
        assert len(piece["branches"]) == len(expected["branches"])
        for branch, exp in zip(piece["branches"], expected["branches"]):
            assert branch.shape == (len(exp), 4) and branch.shape[0] >= 16
            assert np.array_equal(branch, np.array(exp))  # floats round-trip exactly
            assert np.allclose(np.linalg.norm(branch, axis=1), 1)
            for q in (qa, qb):
                assert np.abs(np.einsum("ni,ij,nj->n", branch, q, branch)).max() < 1e-9
        for branch, exp in zip(piece["affine"]["branches"], expected["affine"]["branches"]):
            assert branch.shape == (len(exp), 3) and np.array_equal(branch, np.array(exp))
        assert piece["affine"]["points_at_infinity"].shape[1] == 4
    assert got["connected_components"] == want["connected_components"]


def test_not_yet_and_zero_are_errors():
    with pytest.raises(qsic.QsicError, match="^not yet: the curve of a single quadric"):
        qsic.param("0", "x^2+y^2-z^2")


@pytest.mark.parametrize("line", read_jsonl(CORPUS / "moving.jsonl"), ids=lambda r: r["id"])
def test_motion_on_the_moving_corpus_equals_cli(cli, line):
    got = qsic.motion(line["A"], line["B"])
    assert got == cli_json(cli, "motion", "--json", json.dumps(line["A"]), json.dumps(line["B"]))
    def value(t):
        return float(Fraction(t)) if isinstance(t, str) else float(t["approx"])

    instants = [value(i["t"]) for i in got["instants"]]
    assert instants == pytest.approx([value(t) for t in line["critical_instants"]], abs=1e-12)


def test_motion_with_a_range_and_first_contact_equal_cli(cli):
    a, b = "x^2+y^2+z^2-4", "(x-t)^2+y^2+z^2-1"
    got = qsic.motion(a, b, range=(-1, 2))
    assert got == cli_json(cli, "motion", "--json", "--range", "-1", "2", a, b)
    assert [i["t"] for i in got["instants"]] == ["-1", "0", "1"]
    contact = qsic.first_contact(a, b)
    assert contact == cli_json(cli, "contact", "--json", a, b)
    assert contact["first_contact"] == "-3"  # |t| = 2 + 1
    later = qsic.first_contact(a, b, range=(0, None))
    assert later == cli_json(cli, "contact", "--json", "--range", "0", "oo", a, b)
    assert later["first_contact"] == "1"  # inside (no common point) until |t| = 2 − 1
    # the documented key order, the solids on the range only
    assert list(later) == ["range", "first_contact", "contact", "solids"]
    # the instant alone: the same instant, the same object as the CLI's, nothing else
    only = qsic.first_contact(a, b, range=(0, None), first_only=True)
    assert only == cli_json(
        cli, "contact", "--json", "--first-only", "--range", "0", "oo", a, b
    )
    assert only == {"range": ["0", None], "first_contact": "1"}
    assert later["contact"]["points"][0]["point"] == ["2", "0", "0", "1"]  # the inner touching
    assert list(later["solids"]) == ["first_meeting", "intervals", "instants"]
    assert later["solids"]["intervals"][0]["from"] == "0"


def test_inputs_are_read_as_by_the_cli(cli):
    # a plane is its double plane in motion as in classify; a common factor is cleared
    planes = qsic.motion("z-1", "x^2+y^2-z^2")
    assert planes == cli_json(cli, "motion", "--json", "z-1", "x^2+y^2-z^2")
    assert planes["intervals"][0]["case"] == qsic.classify("z-1", "x^2+y^2-z^2").case == 19
    sphere = qsic.first_contact("t*x^2+t*y^2+t*z^2-t", "x^2+y^2+z^2-4")
    assert sphere["solids"]["instants"] == []
    # one range reader: an empty range is refused with the CLI's message
    for empty in [(float("inf"), float("-inf")), (2, 1)]:
        for f in (qsic.motion, qsic.first_contact):
            with pytest.raises(qsic.QsicError, match="range: invalid time range: .* the range is empty"):
                f("x^2+y^2+z^2-4", "(x-t)^2+y^2+z^2-1", range=empty)
    # an infinite float or Decimal is an open side, NaN an error
    pair = ("x^2+y^2+z^2-4", "(x-t)^2+y^2+z^2-1")
    open_start = qsic.motion(*pair, range=(None, 1))
    assert qsic.motion(*pair, range=(Decimal("-Infinity"), 1)) == open_start
    assert qsic.motion(*pair, range=(float("-inf"), 1)) == open_start
    with pytest.raises(qsic.QsicError, match="range start is not a finite number"):
        qsic.motion(*pair, range=(float("nan"), 1))


def test_rigid_motions_as_dicts_equal_cli(cli):
    # the ellipsoid x²/4 + y² + z² = 1 turning about z (t = tan(θ/2)) first touches the
    # sphere of radius 3 about (3, 4, 0) with a tip, at (6/5, 8/5, 0), at t = −2
    turning = {"quadric": "x^2/4 + y^2 + z^2 - 1", "rotate": {"axis": [0, 0, 1]}}
    sphere = "(x - 3)^2 + (y - 4)^2 + z^2 - 9"
    got = qsic.first_contact(turning, sphere)
    assert got == cli_json(cli, "contact", "--json", json.dumps(turning), sphere)
    assert got["first_contact"] == "-2"
    assert got["contact"]["points"][0]["point"] == ["6/5", "8/5", "0", "1"]
    assert got["contact"]["at_start"] is False
    # a quaternion path with exact numbers, a screw rise, numpy and Fraction entries
    screw = {
        "quadric": np.diag([1, 1, 1, -1]).tolist(),
        "rotate": {"quaternion": [1, 0, 0, "t"], "center": [Fraction(0), 0, 0]},
        "translate": [0, 0, "t"],
    }
    m = qsic.motion(screw, "x^2 + y^2 + (z - 5)^2 - 1")
    # a unit sphere about the origin rising along z: touches at t = 3, leaves at t = 7
    assert [i["t"] for i in m["instants"]][:1] == ["3"]
    with pytest.raises(qsic.QsicError, match="^A: invalid rigid motion: the rotation axis is zero"):
        qsic.motion({"quadric": "x^2 - 1", "rotate": {"axis": [0, 0, 0]}}, sphere)
