"""A round trip through OpenCASCADE (``cadquery-ocp-novtk``, installed by scripts/test-python):
the STEP text of ``qsic nurbs`` read by ``STEPControl_Reader``, as many edges as our curves,
every edge within the stated bound of OpenCASCADE's own surfaces of both quadrics
(``GeomAPI_ProjectPointOnSurf``), and the frames of ``qsic param`` built into ``gp_Circ`` /
``gp_Elips`` / ``gp_Hypr`` / ``gp_Parab`` / ``gp_Lin`` passing through the same points.

OpenCASCADE is imported at the top: where it is missing the module fails to import and the
run fails — never a silent skip (the test script installs it)."""

from __future__ import annotations

import math
import tempfile
from pathlib import Path

import pytest

from OCP.BRep import BRep_Tool
from OCP.Geom import (
    Geom_Circle,
    Geom_ConicalSurface,
    Geom_CylindricalSurface,
    Geom_Ellipse,
    Geom_Hyperbola,
    Geom_Line,
    Geom_Parabola,
    Geom_Plane,
    Geom_SphericalSurface,
)
from OCP.GeomAPI import GeomAPI_ProjectPointOnCurve, GeomAPI_ProjectPointOnSurf
from OCP.IFSelect import IFSelect_RetDone
from OCP.STEPControl import STEPControl_Reader
from OCP.TopAbs import TopAbs_EDGE
from OCP.TopExp import TopExp_Explorer
from OCP.TopoDS import TopoDS
from OCP.gp import gp_Ax2, gp_Ax3, gp_Circ, gp_Dir, gp_Elips, gp_Hypr, gp_Lin, gp_Parab, gp_Pnt

import qsic


def plane(a, b, c, d):
    return Geom_Plane(float(a), float(b), float(c), float(d))


def sphere(centre, r):
    return Geom_SphericalSurface(gp_Ax3(gp_Pnt(*centre), gp_Dir(0, 0, 1)), r)


def cylinder(point, axis, r):
    return Geom_CylindricalSurface(gp_Ax3(gp_Pnt(*point), gp_Dir(*axis)), r)


def cone(apex, axis, half_angle):
    return Geom_ConicalSurface(gp_Ax3(gp_Pnt(*apex), gp_Dir(*axis)), half_angle, 0.0)


# (name, A, B, OpenCASCADE's A, OpenCASCADE's B, our curve count)
CASES = [
    ("sphere and plane crossing", "x^2+y^2+z^2-4", "z-1",
     lambda: sphere((0, 0, 0), 2.0), lambda: plane(0, 0, 1, -1), 1),
    ("Viviani", "x^2+y^2+z^2-4", "x^2+y^2-2*x",
     lambda: sphere((0, 0, 0), 2.0), lambda: cylinder((1, 0, 0), (0, 0, 1), 1.0), 2),
    ("two cylinders crossing (Steinmetz)", "x^2+y^2-1", "x^2+z^2-1",
     lambda: cylinder((0, 0, 0), (0, 0, 1), 1.0), lambda: cylinder((0, 0, 0), (0, 1, 0), 1.0), 4),
    ("cylinder and oblique plane", "x^2+y^2-1", "z-x",
     lambda: cylinder((0, 0, 0), (0, 0, 1), 1.0), lambda: plane(-1, 0, 1, 0), 1),
    ("cone and plane: hyperbola", "x^2+y^2-z^2", "y-1",
     lambda: cone((0, 0, 0), (0, 0, 1), math.pi / 4), lambda: plane(0, 1, 0, -1), 2),
    ("cone and plane: parabola", "x^2+y^2-z^2", "z-x-1",
     lambda: cone((0, 0, 0), (0, 0, 1), math.pi / 4), lambda: plane(-1, 0, 1, -1), 1),
    ("cone and plane: ellipse", "x^2+y^2-z^2", "z-x/2-1",
     lambda: cone((0, 0, 0), (0, 0, 1), math.pi / 4), lambda: plane(-0.5, 0, 1, -1), 1),
    ("plane through the apex", "x^2+y^2-z^2", "x",
     lambda: cone((0, 0, 0), (0, 0, 1), math.pi / 4), lambda: plane(1, 0, 0, 0), 4),
    ("plane tangent to a cone", "x^2+y^2-z^2", "x-z",
     lambda: cone((0, 0, 0), (0, 0, 1), math.pi / 4), lambda: plane(1, 0, -1, 0), 1),
    ("sphere and cylinder tangent", "x^2+y^2+z^2-1", "x^2+y^2-1",
     lambda: sphere((0, 0, 0), 1.0), lambda: cylinder((0, 0, 0), (0, 0, 1), 1.0), 1),
    ("sphere and cylinder coaxial", "x^2+y^2+z^2-4", "x^2+y^2-1",
     lambda: sphere((0, 0, 0), 2.0), lambda: cylinder((0, 0, 0), (0, 0, 1), 1.0), 2),
    ("cone and sphere coaxial", "x^2+y^2-z^2", "x^2+y^2+z^2-2",
     lambda: cone((0, 0, 0), (0, 0, 1), math.pi / 4), lambda: sphere((0, 0, 0), math.sqrt(2)), 2),
]

# smooth quartics (Levin's form): B-spline approximations of degree 7 within their bound
QUARTICS = [
    ("two cylinders of radii 1 and 0.8 crossing", "x^2+y^2-1", "x^2+z^2-16/25",
     lambda: cylinder((0, 0, 0), (0, 0, 1), 1.0), lambda: cylinder((0, 0, 0), (0, 1, 0), 0.8), 2),
    ("sphere and an offset cylinder", "x^2+y^2+z^2-4", "(x-3/2)^2+y^2-1",
     lambda: sphere((0, 0, 0), 2.0), lambda: cylinder((1.5, 0, 0), (0, 0, 1), 1.0), 1),
    ("cone and a crossing cylinder", "x^2+y^2-z^2", "(x-2)^2+z^2-9/4",
     lambda: cone((0, 0, 0), (0, 0, 1), math.pi / 4), lambda: cylinder((2, 0, 0), (0, 1, 0), 1.5), 2),
]


def edges_of_step(text: str):
    with tempfile.TemporaryDirectory() as d:
        path = Path(d) / "curve.stp"
        path.write_text(text)
        reader = STEPControl_Reader()
        assert reader.ReadFile(str(path)) == IFSelect_RetDone
        reader.TransferRoots()
        shape = reader.OneShape()
    out = []
    ex = TopExp_Explorer(shape, TopAbs_EDGE)
    while ex.More():
        out.append(BRep_Tool.Curve_s(TopoDS.Edge(ex.Current()), 0.0, 0.0))
        ex.Next()
    return out


def samples(curve, n=41):
    f, l = curve.FirstParameter(), curve.LastParameter()
    return [curve.Value(f + (l - f) * k / (n - 1)) for k in range(n)]


def box_size(n):
    lo = [float(eval(v)) for v in n["bounds"]["lo"]]
    hi = [float(eval(v)) for v in n["bounds"]["hi"]]
    return math.dist(lo, hi)


@pytest.mark.parametrize(
    "name,a,b,surf_a,surf_b,count", CASES + QUARTICS, ids=[c[0] for c in CASES + QUARTICS]
)
def test_step_curves_lie_on_opencascades_surfaces(name, a, b, surf_a, surf_b, count):
    n = qsic.nurbs(a, b)
    assert len(n["curves"]) == count, n["left"]
    curves = edges_of_step(qsic.nurbs(a, b, step=True))
    assert len(curves) == len(n["curves"])
    # exact curves (bound 0) written as doubles: the bound plus the rounding of the file;
    # approximations within their proved bound, of 1e-9 of their size
    bound = max(c["bound"] for c in n["curves"]) + 1e-9 * box_size(n)
    assert all(c["exact"] == (c["bound"] == 0) for c in n["curves"])
    if (name, a, b, surf_a, surf_b, count) in QUARTICS:
        assert all(not c["exact"] and 0 < c["bound"] < 1e-8 for c in n["curves"])
    for k, (curve, ours) in enumerate(zip(curves, n["curves"])):
        assert curve.Degree() == ours["degree"]
        assert curve.NbPoles() == len(ours["control_points"])
        for p in samples(curve):
            for s in (surf_a(), surf_b()):
                d = GeomAPI_ProjectPointOnSurf(p, s).LowerDistance()
                assert d <= bound, f"{name}: edge {k} at {p.Coord()} is {d} off {s}"


def frame_curves(frame):
    """The frame as OpenCASCADE's curves: one, or a hyperbola's two branches."""
    a = frame["approx"]
    if frame["type"] == "line":
        return [Geom_Line(gp_Lin(gp_Pnt(*a["location"]), gp_Dir(*a["direction"])))]
    ax = gp_Ax2(gp_Pnt(*a["location"]), gp_Dir(*a["normal"]), gp_Dir(*a["x_direction"]))
    if frame["type"] == "circle":
        return [Geom_Circle(gp_Circ(ax, a["radius"]))]
    if frame["type"] == "ellipse":
        return [Geom_Ellipse(gp_Elips(ax, a["major_radius"], a["minor_radius"]))]
    if frame["type"] == "hyperbola":
        h = gp_Hypr(ax, a["major_radius"], a["minor_radius"])
        return [Geom_Hyperbola(h), Geom_Hyperbola(h.OtherBranch())]
    if frame["type"] == "parabola":
        return [Geom_Parabola(gp_Parab(ax, a["focal"]))]
    return []


@pytest.mark.parametrize("name,a,b,surf_a,surf_b,count", CASES, ids=[c[0] for c in CASES])
def test_frames_in_gp_curves_pass_through_the_nurbs_points(name, a, b, surf_a, surf_b, count):
    components = qsic.param(a, b)["components"]
    n = qsic.nurbs(a, b)
    curves = edges_of_step(qsic.nurbs(a, b, step=True))
    checked = 0
    for curve, ours in zip(curves, n["curves"]):
        frame = components[ours["component"]].get("frame")
        gs = frame_curves(frame) if frame else []
        if not gs:
            continue
        for p in samples(curve, 17):
            d = min(GeomAPI_ProjectPointOnCurve(p, g).LowerDistance() for g in gs)
            assert d <= 1e-9 * box_size(n), f"{name}: {p.Coord()} is {d} off the {frame['type']}"
        checked += 1
    # every curve here is a line or a conic with a frame (the tangent plane's double line too)
    assert checked == len(n["curves"]) or name == "Viviani", (name, checked)
