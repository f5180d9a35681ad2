"""Equal or proportional quadrics, and quadrics sharing a plane, name what they share in
Python as in the CLI: the affine view of `classify`, the components of `sample` and
`param`, and the rows of `classify_many`."""

from __future__ import annotations

import json

import numpy as np
from conftest import run_cli

import qsic

SPHERES = ("x^2+y^2+z^2-1", "2*x^2+2*y^2+2*z^2-2")


def test_classify_names_the_common_sphere(cli):
    d = qsic.classify(*SPHERES).to_dict()
    (c,) = d["affine"]["components"]
    assert (c["kind"], c["name"], c["bounded"]) == ("quadric", "sphere", True)
    assert "the two are the same sphere" in d["affine"]["summary"]
    assert "no common point" not in d["affine"]["summary"]
    out = run_cli(cli, "classify", "--json", *SPHERES)
    assert d == json.loads(out.stdout)


def test_sample_and_param_list_the_common_surface():
    s = qsic.sample(*SPHERES)
    (c,) = s["components"]
    assert (c["kind"], c["name"], c["branches"]) == ("quadric", "sphere", [])
    p = qsic.param("z-1", "2*z-2")
    (plane,) = p["components"]
    assert (plane["kind"], plane["name"]) == ("plane", "plane")
    assert plane["plane"][:2] == ["0", "0"]
    # beside a curve: the common plane x = 0 and the line y = z = 0
    s = qsic.sample("x*y", "x*z")
    assert [c["kind"] for c in s["components"]] == ["line", "plane"]


def test_classify_many_rows_of_equal_quadrics():
    eye = np.diag([1, 1, 1, -1]).astype(np.int64)
    a = np.stack([eye, eye])
    b = np.stack([3 * eye, np.diag([1, 1, 1, -4]).astype(np.int64)])
    rows = qsic.classify_many(a, b)
    assert list(rows["pencil"]) == ["single", "regular"]
