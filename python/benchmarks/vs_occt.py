#!/usr/bin/env python3
"""qsic against OpenCASCADE on natural-quadric pairs, side by side in one Python process.

    python3 python/benchmarks/vs_occt.py [--pairs N] [--json OUT] [--write-inputs PATH]

For the same configurations of planes, spheres, circular cylinders and circular cones, in
families (plane–quadric, sphere–sphere, cylinder–cylinder, cone–X, sphere–cylinder, and
near-degenerate ones at 10⁻⁹–10⁻¹²), it times per pair

* OpenCASCADE: its surfaces (`gp_Pln`, `gp_Sphere`, `gp_Cylinder`, `gp_Cone`) built from
  the configuration and the closed-form intersector `IntAna_QuadQuadGeo` (tolerances
  `Precision::Confusion` 1e-7 and `Precision::Angular` 1e-12), its type and count read;
* qsic: `qsic.classify_many(A, B, affine=True)` on the same pairs as `(N, 4, 4)` float64
  arrays (one thread, and all cores), and `qsic.classify(a, b)` per pair;

and reports the time per pair of each and the ratio on the configurations OpenCASCADE
answers (qsic's time alone on the others), and every configuration where
OpenCASCADE's answer differs from the exact one (qsic's, on the exact values of the same
floats) or where it has none (`IntAna_NoGeometricSolution`: the quartics).

Every matrix entry is a dyadic rational, so the float64 arrays hold the configuration
exactly; OpenCASCADE gets the same centres, radii and (normalized) axes. The tangent and
near-degenerate configurations use axis-parallel axes, which OpenCASCADE holds exactly too.

Environment: run with a Python that has `qsic`, NumPy and `OCP` (cadquery-ocp-novtk), or
with any Python 3: the script then makes its own virtual environment in
`target/bench-venv` (NumPy and maturin from PyPI, the qsic wheel built from this checkout
in release mode), puts OpenCASCADE on its path from the venv that scripts/test-python keeps
(`$QSIC_OCCT_VENV`, default `~/.cache/qsic/occt-venv`, made and filled once if missing),
and runs itself there.

`--write-inputs PATH` writes the configurations as JSON lines (family, name, the two
matrices as float rows) — the file the criterion bench `natural` reads
(crates/qsic/benches/inputs/natural.jsonl).
"""

from __future__ import annotations

import argparse
import json
import math
import os
import subprocess
import sys
import time
from collections import Counter
from fractions import Fraction as F
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


# ---------------------------------------------------------------------------------------------
# the environment


def have_modules() -> bool:
    try:
        import numpy  # noqa: F401
        import OCP.IntAna  # noqa: F401
        import qsic  # noqa: F401
    except ImportError:
        return False
    return True


def bootstrap(argv: list[str]) -> None:
    """Make target/bench-venv with NumPy, maturin, the qsic wheel and OpenCASCADE on its path,
    then run this script there (once: a second failure is an error, not a loop)."""
    if os.environ.get("QSIC_VS_OCCT_BOOTSTRAPPED"):
        sys.exit("vs_occt.py: qsic, numpy or OCP still missing in the bench venv")
    target = Path(os.environ.get("CARGO_TARGET_DIR", ROOT / "target"))
    venv = target / "bench-venv"
    py = venv / "bin" / "python"
    cache = Path(os.environ.get("XDG_CACHE_HOME", Path.home() / ".cache"))
    occt = Path(os.environ.get("QSIC_OCCT_VENV", cache / "qsic" / "occt-venv"))
    run = lambda *cmd: subprocess.run([str(c) for c in cmd], check=True)  # noqa: E731
    quiet = ["-m", "pip", "--disable-pip-version-check", "install", "--quiet"]
    if not py.exists():
        run(sys.executable, "-m", "venv", venv)
        run(py, *quiet, "maturin>=1.9.4,<2", "numpy>=1.23")
    occt_py = occt / "bin" / "python"
    if subprocess.run([str(occt_py), "-c", "import OCP.IntAna"], capture_output=True).returncode:
        occt.parent.mkdir(parents=True, exist_ok=True)
        run(sys.executable, "-m", "venv", "--clear", occt)
        run(occt_py, *quiet, "cadquery-ocp-novtk")
    purelib = lambda p: subprocess.run(  # noqa: E731
        [str(p), "-c", "import sysconfig; print(sysconfig.get_paths()['purelib'])"],
        check=True, capture_output=True, text=True).stdout.strip()
    Path(purelib(py), "occt.pth").write_text(purelib(occt_py) + "\n")
    wheels = target / "bench-wheels"
    env = dict(os.environ, CARGO_TARGET_DIR=str(target))
    subprocess.run([str(venv / "bin" / "maturin"), "build", "--quiet", "--release",
                    "--manifest-path", str(ROOT / "python" / "Cargo.toml"),
                    "--interpreter", str(py), "--out", str(wheels)], check=True, env=env)
    wheel = max(wheels.glob("qsic-*.whl"), key=lambda p: p.stat().st_mtime)
    run(py, *quiet, "--force-reinstall", "--no-deps", wheel)
    os.execve(str(py), [str(py), __file__, *argv],
              dict(os.environ, QSIC_VS_OCCT_BOOTSTRAPPED="1"))


# ---------------------------------------------------------------------------------------------
# natural quadrics: exact matrices and OpenCASCADE's surfaces


def plane(n, e):
    """n·x = e."""
    return {"kind": "plane", "n": [F(v) for v in n], "e": F(e)}


def sphere(c, r, r2=None):
    """Centre c, radius r (or r2 = r² when r is irrational)."""
    r2 = F(r) ** 2 if r2 is None else F(r2)
    return {"kind": "sphere", "c": [F(v) for v in c], "r2": r2}


def cylinder(p, d, r, r2=None):
    """Axis through p along the integer direction d, radius r (or r2 = r²)."""
    r2 = F(r) ** 2 if r2 is None else F(r2)
    return {"kind": "cylinder", "p": [F(v) for v in p], "d": [F(v) for v in d], "r2": r2}


def cone(p, d, t):
    """Apex p, axis along d, tan(half angle) = t."""
    return {"kind": "cone", "p": [F(v) for v in p], "d": [F(v) for v in d], "t": F(t)}


def dot(u, v):
    return sum(a * b for a, b in zip(u, v))


def quadric_block(k3, p, const):
    """The 4×4 matrix of (x − p)ᵀK(x − p) + const."""
    kp = [dot(row, p) for row in k3]
    m = [[k3[i][j] for j in range(3)] + [-kp[i]] for i in range(3)]
    m.append([-kp[0], -kp[1], -kp[2], dot(p, kp) + const])
    return m


def matrix(s):
    """The exact symmetric matrix of the quadric (x, y, z, w); a plane as its double plane."""
    eye = [[F(int(i == j)) for j in range(3)] for i in range(3)]
    if s["kind"] == "plane":
        h = s["n"] + [-s["e"]]
        return [[a * b for b in h] for a in h]
    if s["kind"] == "sphere":
        return quadric_block(eye, s["c"], -s["r2"])
    d = s["d"]
    dd = dot(d, d)
    if s["kind"] == "cylinder":
        k3 = [[dd * eye[i][j] - d[i] * d[j] for j in range(3)] for i in range(3)]
        return quadric_block(k3, s["p"], -s["r2"] * dd)
    t2 = s["t"] ** 2
    k3 = [[dd * eye[i][j] - (1 + t2) * d[i] * d[j] for j in range(3)] for i in range(3)]
    return quadric_block(k3, s["p"], F(0))


def float_matrix(s):
    m = matrix(s)
    out = [[float(v) for v in row] for row in m]
    for row, exact in zip(out, m):
        for f, v in zip(row, exact):
            if F(f) != v:
                raise ValueError(f"{s}: the entry {v} is not a float64")
    return out


def occ_args(s):
    """The floats OpenCASCADE's surface of `s` is built from: (kind, args)."""
    f = lambda v: tuple(float(x) for x in v)  # noqa: E731
    if s["kind"] == "plane":
        return ("plane", (*f(s["n"]), -float(s["e"])))
    if s["kind"] == "sphere":
        return ("sphere", (*f(s["c"]), math.sqrt(s["r2"])))
    if s["kind"] == "cylinder":
        return ("cylinder", (*f(s["p"]), *f(s["d"]), math.sqrt(s["r2"])))
    return ("cone", (*f(s["p"]), *f(s["d"]), math.atan(float(s["t"]))))


def occ_surface(kind, v):
    from OCP.gp import gp_Ax3, gp_Cone, gp_Cylinder, gp_Dir, gp_Pln, gp_Pnt, gp_Sphere

    if kind == "plane":
        return gp_Pln(*v)
    if kind == "sphere":
        return gp_Sphere(gp_Ax3(gp_Pnt(v[0], v[1], v[2]), gp_Dir(0, 0, 1)), v[3])
    ax = gp_Ax3(gp_Pnt(v[0], v[1], v[2]), gp_Dir(v[3], v[4], v[5]))
    if kind == "cylinder":
        return gp_Cylinder(ax, v[6])
    return gp_Cone(ax, v[6], 0.0)


RANK = {"plane": 0, "cylinder": 1, "sphere": 2, "cone": 3}
TOL, TOL_ANG = 1e-7, 1e-12  # Precision::Confusion(), Precision::Angular()


def occ_pair(a, b):
    """The pair's surfaces as floats, in the argument order IntAna_QuadQuadGeo has
    constructors for, and whether it takes the angular tolerance."""
    if RANK[a["kind"]] > RANK[b["kind"]]:
        a, b = b, a
    angular = a["kind"] == "plane" and b["kind"] in ("plane", "cylinder", "cone")
    return occ_args(a), occ_args(b), angular


def occ_intersect(pair):
    """IntAna_QuadQuadGeo on a pair of occ_pair: the surfaces built, then intersected."""
    from OCP.IntAna import IntAna_QuadQuadGeo

    (ka, va), (kb, vb), angular = pair
    sa, sb = occ_surface(ka, va), occ_surface(kb, vb)
    if angular:
        return IntAna_QuadQuadGeo(sa, sb, TOL_ANG, TOL)
    if ka == "plane":
        return IntAna_QuadQuadGeo(sa, sb)
    return IntAna_QuadQuadGeo(sa, sb, TOL)


OCC_NAMES = {
    "IntAna_Point": ["point"], "IntAna_Line": ["line"], "IntAna_Circle": ["circle"],
    "IntAna_Ellipse": ["ellipse"], "IntAna_Parabola": ["parabola"],
    "IntAna_Hyperbola": ["hyperbola"], "IntAna_Empty": [], "IntAna_Same": ["same"],
}


def occ_answer(q):
    """The multiset of OpenCASCADE's curves by name; None when it gives no answer."""
    if not q.IsDone():
        return None
    kind = q.TypeInter().name
    if kind == "IntAna_NoGeometricSolution":
        return None
    if kind == "IntAna_PointAndCircle":
        return Counter(["point", "circle"])
    names = OCC_NAMES[kind]
    n = q.NbSolutions() if names and names != ["same"] else 1
    if kind == "IntAna_Hyperbola":
        n = (n + 1) // 2  # a gp_Hypr is one branch: both branches are one hyperbola
    return Counter(names * n)


def exact_answer(affine):
    """The multiset of the real curves in ℝ³ by name, from qsic's affine object (curves at
    infinity left out: OpenCASCADE's surfaces have no points at infinity)."""
    out = Counter()
    for c in affine["components"]:
        if c["kind"] in ("quadric", "plane"):
            out["same"] += 1
        elif c.get("name") and not c.get("at_infinity"):
            out[c["name"]] += 1
    out["point"] += affine["isolated_points"]
    return +out


# ---------------------------------------------------------------------------------------------
# the configurations

Z, X, Y = (0, 0, 1), (1, 0, 0), (0, 1, 0)
DELTAS = [F(1, 2**30), F(1, 2**33), F(1, 2**37), F(1, 2**40)]  # ≈ 9e-10, 1e-10, 7e-12, 9e-13


def configurations():
    """(family, name, A, B), deterministic."""
    out = []
    add = lambda fam, name, a, b: out.append((fam, name, a, b))  # noqa: E731
    offsets = [(0, 0, 0), (F(3, 4), F(-5, 8), F(1, 2)), (-2, F(7, 4), F(-3, 8))]
    dirs = [(1, 2, 2), (2, 3, 6), (1, 4, 8), (2, 6, 9)]  # integer lengths 3, 7, 9, 11
    for k, o in enumerate(offsets):
        sh = lambda v: [F(a) + F(b) for a, b in zip(v, o)]  # noqa: E731
        e3 = dot(o, Z)
        # plane–quadric
        add("plane-quadric", f"plane crossing a sphere #{k}", plane(Z, e3 + F(1, 2)), sphere(o, 2))
        add("plane-quadric", f"plane tangent to a sphere #{k}", plane(Z, e3 + 2), sphere(o, 2))
        add("plane-quadric", f"plane missing a sphere #{k}", plane(Z, e3 + 3), sphere(o, 2))
        add("plane-quadric", f"plane across a cylinder #{k}", plane(Z, e3 + 1), cylinder(o, Z, 1))
        add("plane-quadric", f"oblique plane, cylinder #{k}",
            plane((1, 0, 2), dot((1, 0, 2), o)), cylinder(o, Z, 1))
        add("plane-quadric", f"plane along a cylinder: two lines #{k}",
            plane(X, dot(X, o) + F(1, 2)), cylinder(o, Z, 1))
        add("plane-quadric", f"plane tangent to a cylinder #{k}",
            plane(X, dot(X, o) + 1), cylinder(o, Z, 1))
        add("plane-quadric", f"plane through a cone's apex #{k}", plane(X, dot(X, o)), cone(o, Z, 1))
        add("plane-quadric", f"plane tangent to a cone #{k}",
            plane((1, 0, -1), dot((1, 0, -1), o)), cone(o, Z, 1))
        add("plane-quadric", f"cone section: ellipse #{k}",
            plane((-1, 0, 2), dot((-1, 0, 2), o) + 2), cone(o, Z, 1))
        add("plane-quadric", f"cone section: parabola #{k}",
            plane((-1, 0, 1), dot((-1, 0, 1), o) + 1), cone(o, Z, 1))
        add("plane-quadric", f"cone section: hyperbola #{k}",
            plane(Y, dot(Y, o) + 1), cone(o, Z, 1))
        # sphere–sphere
        add("sphere-sphere", f"crossing #{k}", sphere(o, 2), sphere(sh((1, 1, 0)), F(3, 2)))
        add("sphere-sphere", f"tangent outside #{k}", sphere(o, 2), sphere(sh((3, 0, 0)), 1))
        add("sphere-sphere", f"tangent inside #{k}", sphere(o, 2), sphere(sh((0, 0, 1)), 1))
        add("sphere-sphere", f"apart #{k}", sphere(o, 1), sphere(sh((2, 2, 2)), 1))
        add("sphere-sphere", f"nested #{k}", sphere(o, 3), sphere(sh((F(1, 2), 0, 0)), 1))
        add("sphere-sphere", f"concentric #{k}", sphere(o, 3), sphere(o, 1))
        add("sphere-sphere", f"the same #{k}", sphere(o, F(5, 4)), sphere(o, F(5, 4)))
        # cylinder–cylinder
        add("cylinder-cylinder", f"parallel crossing #{k}", cylinder(o, Z, 1), cylinder(sh(X), Z, 1))
        add("cylinder-cylinder", f"parallel tangent #{k}", cylinder(o, Z, 1), cylinder(sh((2, 0, 0)), Z, 1))
        add("cylinder-cylinder", f"parallel apart #{k}", cylinder(o, Z, 1), cylinder(sh((3, 0, 0)), Z, 1))
        add("cylinder-cylinder", f"coaxial #{k}", cylinder(o, Z, 1), cylinder(o, Z, 2))
        add("cylinder-cylinder", f"Steinmetz #{k}", cylinder(o, Z, 1), cylinder(o, Y, 1))
        add("cylinder-cylinder", f"perpendicular, radii 1 and 2 #{k}", cylinder(o, Z, 1), cylinder(o, Y, 2))
        add("cylinder-cylinder", f"skew axes #{k}", cylinder(o, dirs[k], 1), cylinder(sh(X), Z, F(3, 2)))
        add("cylinder-cylinder", f"internally tangent, parallel #{k}",
            cylinder(o, Z, 2), cylinder(sh(X), Z, 1))
        # sphere–cylinder
        add("sphere-cylinder", f"coaxial: two circles #{k}", sphere(o, 2), cylinder(o, Z, 1))
        add("sphere-cylinder", f"tangent along a circle #{k}", sphere(o, 1), cylinder(o, Z, 1))
        add("sphere-cylinder", f"Viviani #{k}", sphere(o, 2), cylinder(sh(X), Z, 1))
        add("sphere-cylinder", f"off axis #{k}", sphere(o, 2), cylinder(sh((F(1, 2), 0, 0)), dirs[k], 1))
        add("sphere-cylinder", f"apart #{k}", sphere(sh((5, 0, 0)), 1), cylinder(o, Z, 1))
        # cone–X
        add("cone-x", f"cone and coaxial sphere #{k}", cone(o, Z, 1), sphere(sh((0, 0, 2)), 1))
        add("cone-x", f"cone and coaxial cylinder #{k}", cone(o, Z, 1), cylinder(o, Z, 1))
        add("cone-x", f"cone and sphere at the apex #{k}", cone(o, Z, 1), sphere(o, 1))
        add("cone-x", f"cone and sphere tangent along a circle #{k}", cone(o, Z, F(3, 4)),
            sphere(sh((0, 0, 5)), 3))
        add("cone-x", f"coaxial cones, common apex #{k}", cone(o, Z, 1), cone(o, Z, F(1, 2)))
        add("cone-x", f"coaxial cones, apart apexes #{k}", cone(o, Z, 1), cone(sh((0, 0, 2)), Z, F(1, 2)))
        add("cone-x", f"cone and cylinder, generic #{k}", cone(o, dirs[k], 1), cylinder(sh(X), Z, F(1, 2)))
        add("cone-x", f"cone and sphere, generic #{k}", cone(o, dirs[k], F(1, 2)), sphere(sh((1, 0, 3)), 2))
    # near-degenerate: tangencies moved by δ on a squared radius (the gap about δ/(2r))
    for d in DELTAS:
        g = f"{float(d):.0e}"
        add("near-degenerate", f"plane and sphere, r² = 4 − {g}: no point",
            plane(Z, 2), sphere((0, 0, 0), None, 4 - d))
        add("near-degenerate", f"plane and sphere, r² = 4 + {g}: a small circle",
            plane(Z, 2), sphere((0, 0, 0), None, 4 + d))
        add("near-degenerate", f"spheres at 2, r² = 1 + {g}: a small circle",
            sphere((0, 0, 0), 1), sphere((2, 0, 0), None, 1 + d))
        add("near-degenerate", f"spheres at 2, r² = 1 − {g}: apart",
            sphere((0, 0, 0), 1), sphere((2, 0, 0), None, 1 - d))
        add("near-degenerate", f"parallel cylinders at 2, r² = 1 + {g}: two lines",
            cylinder((0, 0, 0), Z, 1), cylinder((2, 0, 0), Z, None, 1 + d))
        add("near-degenerate", f"parallel cylinders at 2, r² = 1 − {g}: apart",
            cylinder((0, 0, 0), Z, 1), cylinder((2, 0, 0), Z, None, 1 - d))
        add("near-degenerate", f"plane x = {float(d):.0e}, off a cone's apex: a hyperbola",
            plane(X, d), cone((0, 0, 0), Z, 1))
        add("near-degenerate", f"sphere r² = 1 + {g} and cylinder r = 1: two close circles",
            sphere((0, 0, 0), None, 1 + d), cylinder((0, 0, 0), Z, 1))
    return out


# ---------------------------------------------------------------------------------------------
# the run


def per_pair_seconds(fn, n, repeat):
    best = math.inf
    for _ in range(repeat):
        t = time.perf_counter()
        fn()
        best = min(best, time.perf_counter() - t)
    return best / n


def main(argv: list[str]) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--pairs", type=int, default=2000, help="pairs timed per family (repeats)")
    ap.add_argument("--repeat", type=int, default=3, help="timed runs; the best is kept")
    ap.add_argument("--json", help="write the results as JSON to this file")
    ap.add_argument("--write-inputs", help="write the configurations as JSON lines and stop")
    args = ap.parse_args(argv)
    configs = configurations()
    if args.write_inputs:
        with open(args.write_inputs, "w") as f:
            for fam, name, a, b in configs:
                f.write(json.dumps({"family": fam, "name": name,
                                    "a": float_matrix(a), "b": float_matrix(b)}) + "\n")
        print(f"{len(configs)} configurations written to {args.write_inputs}")
        return 0
    if not have_modules():
        bootstrap(argv)
    import numpy as np
    import qsic

    # answers, one pair at a time
    differ, missing, answered = [], [], set()
    for fam, name, a, b in configs:
        r = qsic.classify(np.array(float_matrix(a)), np.array(float_matrix(b)))
        exact = exact_answer(r.affine)
        occ = occ_answer(occ_intersect(occ_pair(a, b)))
        if occ is None:
            missing.append((fam, name, dict(exact)))
        else:
            answered.add(name)
            if occ != exact:
                differ.append((fam, name, dict(occ), dict(exact)))

    def qsic_times(chosen):
        pairs = [chosen[i % len(chosen)] for i in range(args.pairs)]
        A = np.array([float_matrix(c[2]) for c in pairs])
        B = np.array([float_matrix(c[3]) for c in pairs])

        def many(threads):
            def go():
                out = qsic.classify_many(A, B, affine=True, threads=threads)
                assert all(e is None for e in out["error"])
            return go

        def single():
            for i in range(len(pairs)):
                qsic.classify(A[i], B[i])

        return (per_pair_seconds(many(1), len(pairs), args.repeat),
                per_pair_seconds(many(None), len(pairs), args.repeat),
                per_pair_seconds(single, len(pairs), 1))

    # timing, family by family: the configurations OpenCASCADE answers side by side, then
    # qsic alone on those it has no answer for
    rows = []
    families = sorted({c[0] for c in configs}, key=[c[0] for c in configs].index)
    for fam in families:
        both = [c for c in configs if c[0] == fam and c[1] in answered]
        alone = [c for c in configs if c[0] == fam and c[1] not in answered]
        row = {"family": fam, "answered": len(both), "no_answer": len(alone)}
        if both:
            pairs = [both[i % len(both)] for i in range(args.pairs)]
            occ_pairs = [occ_pair(c[2], c[3]) for c in pairs]

            def occ_run():
                for pair in occ_pairs:
                    q = occ_intersect(pair)
                    if q.IsDone():
                        q.TypeInter()
                        q.NbSolutions()

            row["occt_us"] = per_pair_seconds(occ_run, len(pairs), args.repeat) * 1e6
            one, many_, single = qsic_times(both)
            row.update(classify_many_1_us=one * 1e6, classify_many_all_us=many_ * 1e6,
                       classify_us=single * 1e6)
        if alone:
            row["no_answer_classify_many_1_us"] = qsic_times(alone)[0] * 1e6
        rows.append(row)
    print(f"{len(configs)} configurations; per pair, best of {args.repeat} runs "
          f"(OpenCASCADE: surfaces + IntAna_QuadQuadGeo; qsic: affine view)\n")
    print(f"{'family':<18} {'both':>4} {'OCCT µs':>8} {'many/1 µs':>9} {'many µs':>8} "
          f"{'classify µs':>11} {'OCCT/many1':>10} {'none':>4} {'many/1 µs':>9}")
    for r in rows:
        side = (f"{r['occt_us']:>8.2f} {r['classify_many_1_us']:>9.2f} "
                f"{r['classify_many_all_us']:>8.2f} {r['classify_us']:>11.2f} "
                f"{r['occt_us'] / r['classify_many_1_us']:>10.2f}") if r["answered"] else " " * 51
        rest = f"{r['no_answer_classify_many_1_us']:>9.2f}" if r["no_answer"] else ""
        print(f"{r['family']:<18} {r['answered']:>4} {side} {r['no_answer']:>4} {rest}")
    print(f"\nOpenCASCADE differs from the exact answer on {len(differ)} of {len(configs)}:")
    for fam, name, occ, exact in differ:
        print(f"  {fam}: {name}: OpenCASCADE {occ or 'nothing'}, exact {exact or 'nothing'}")
    print(f"OpenCASCADE has no answer on {len(missing)}:")
    for fam, name, exact in missing:
        print(f"  {fam}: {name}: exact {exact or 'nothing'}")
    if args.json:
        Path(args.json).write_text(json.dumps({
            "rows": rows,
            "differ": [{"family": f, "name": n, "occt": o, "exact": e} for f, n, o, e in differ],
            "no_answer": [{"family": f, "name": n, "exact": e} for f, n, e in missing],
        }, indent=1))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
