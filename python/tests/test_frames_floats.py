"""Frames of the curve's lines and conics as a CAD kernel takes them, the report in the user's
words, and the two readings of floats (``floats="binary"``, the default, and
``floats="shortest"``)."""

from __future__ import annotations

import math

import numpy as np
import pytest

import qsic
from qsic import Quadric, QsicError


def frames(a, b):
    return [c["frame"] for c in qsic.param(a, b)["components"] if "frame" in c]


def test_steinmetz_ellipses_have_exact_frames():
    fs = frames("x^2+y^2-1", "x^2+z^2-1")
    assert [f["type"] for f in fs] == ["ellipse", "ellipse"]
    for f in fs:
        assert f["location"] == ["0", "0", "0"]
        assert f["major_radius"] == {"exact": "sqrt(2)", "square": "2"}
        assert f["minor_radius"]["exact"] == "1"
        assert f["x_direction"]["vector"] in (["0", "1", "1"], ["0", "1", "-1"])
        assert f["x_direction"]["norm2"] == "2"


def test_a_circle_drawn_from_its_frame_lies_on_both_surfaces():
    # the sphere x² + y² + z² = 3 and the plane x + y + z = 1: a circle about (1/3, 1/3, 1/3)
    # of radius² 8/3, drawn as gp_Circ draws it: location + r(cos t·X + sin t·Y)
    (f,) = frames("x^2+y^2+z^2-3", "x+y+z-1")
    assert f["type"] == "circle" and f["location"] == ["1/3", "1/3", "1/3"]
    assert f["radius"]["square"] == "8/3"
    a = f["approx"]
    p, x, y, r = (np.array(a[k]) for k in ("location", "x_direction", "y_direction", "radius"))
    for t in np.linspace(0, 2 * math.pi, 13):
        q = p + r * (math.cos(t) * x + math.sin(t) * y)
        assert abs(q @ q - 3) < 1e-12 and abs(q.sum() - 1) < 1e-12


def test_the_report_leads_with_r3():
    text = str(qsic.classify("x^2+y^2-z^2", "z-1-2*x"))
    assert text.startswith("in R^3:           a hyperbola: 2 unbounded curves")
    assert "projective class" in text and "pencil:" in text


def test_a_sphere_of_typed_floats_touches_the_plane_only_read_as_typed():
    # centre (0.1, 0.2, 0.3), radius² 0.3**2 (which prints as 0.09): the plane z = 0.6 touches
    # the sphere of the decimals, not the sphere of the floats' binary values
    plane = "z - 0.6"

    def touches(q):
        return qsic.classify(q, plane).affine["isolated_points"] == 1

    assert not touches(Quadric.sphere([0.1, 0.2, 0.3], 0.3**2))
    assert touches(Quadric.sphere([0.1, 0.2, 0.3], 0.3**2, floats="shortest"))
    assert touches(Quadric.sphere(["0.1", "0.2", "0.3"], "0.09"))
    # the same sphere as a matrix of floats, in every entry point
    m = [[1, 0, 0, -0.1], [0, 1, 0, -0.2], [0, 0, 1, -0.3], [-0.1, -0.2, -0.3, 0.05]]
    assert qsic.classify(m, plane).real_type != "point"
    assert qsic.classify(m, plane, floats="shortest").real_type == "point"
    assert Quadric(m, floats="shortest") == Quadric([[str(v) for v in r] for r in m])
    assert qsic.param(m, plane, floats="shortest")["real_type"] == "point"
    # a batch: float64 arrays (read in Rust) and float32 ones (read through their texts)
    A = np.array([m, m], dtype=np.float64)
    # the double plane (z − 3/5)², exact, beside each
    plane2 = [["0"] * 4, ["0"] * 4, ["0", "0", "1", "-3/5"], ["0", "0", "-3/5", "9/25"]]
    B = [plane2, plane2]
    binary = qsic.classify_many(A, B)
    shortest = qsic.classify_many(A, B, floats="shortest")
    texts = qsic.classify_many([[[str(v) for v in r] for r in m]] * 2, B)
    assert list(texts["real_type"]) == ["point", "point"]
    assert list(shortest["real_type"]) == list(texts["real_type"])
    assert list(binary["real_type"]) != list(shortest["real_type"])
    f32 = qsic.classify_many(A.astype(np.float32), B, floats="shortest")
    assert list(f32["real_type"]) == list(shortest["real_type"])


def test_floats_is_checked_and_non_floats_are_unchanged():
    with pytest.raises(QsicError, match="floats must be 'binary' or 'shortest'"):
        Quadric("x^2-1", floats="decimal")
    with pytest.raises(QsicError, match="not a finite number"):
        Quadric.sphere([float("nan"), 0, 0], 1, floats="shortest")
    exact = Quadric.sphere([1, "1/3", 0], 2)
    assert Quadric.sphere([1, "1/3", 0], 2, floats="shortest") == exact
    # a float that is an integer, or a dyadic fraction, reads the same either way
    assert Quadric.sphere([0.5, 2.0, 0], 0.25) == Quadric.sphere([0.5, 2.0, 0], 0.25, floats="shortest")
