#!/usr/bin/env python3
"""Near-degenerate pairs at several scales, for `qsic sample --batch -` and the checks in
`../shared/checks/` (README, "Sampling at every scale"): JSON lines with `id`, `A`, `B` (4x4
rational matrices as strings) and the labels `check_sample.py` reads.

    scripts/near_degenerate.py > near.jsonl

Each family is an exact configuration with a singular point or a tangency, moved off it by
`e = 10^-k`: Steinmetz's cylinders with axes `e` apart or radii `1` and `1 + e`, Viviani's
sphere and cylinder with the cylinder's radius off by `e`, two spheres whose circle has radius
about `sqrt(e)`. Every pair is also scaled by `10^5` and `10^-5`. Deterministic.
"""
import json
from fractions import Fraction as F


def matrix(quad, lin, const):
    """the symmetric matrix of sum quad[i][j] x_i x_j + 2 sum lin[i] x_i w + const w^2"""
    m = [[F(0)] * 4 for _ in range(4)]
    for i in range(3):
        for j in range(3):
            m[i][j] = F(quad[i][j])
        m[i][3] = m[3][i] = F(lin[i])
    m[3][3] = F(const)
    return m


def cylinder(axis, centre, r2):
    """points at squared distance r2 from the line through centre along coordinate axis"""
    q = [[F(int(i == j and i != axis)) for j in range(3)] for i in range(3)]
    lin = [-centre[i] if i != axis else F(0) for i in range(3)]
    const = sum(centre[i] ** 2 for i in range(3) if i != axis) - r2
    return matrix(q, lin, const)


def sphere(centre, r2):
    q = [[F(int(i == j)) for j in range(3)] for i in range(3)]
    return matrix(q, [-c for c in centre], sum(c * c for c in centre) - r2)


def scaled(m, k):
    """the quadric of the points scaled by k: x -> x/k"""
    out = [row[:] for row in m]
    for i in range(3):
        for j in range(3):
            out[i][j] = m[i][j] / (k * k)
        out[i][3] = out[3][i] = m[i][3] / k
    return out


def text(m):
    return [[str(v) for v in row] for row in m]


def families(e):
    z = F(0)
    yield "steinmetz-offset", cylinder(2, [z, z, z], F(1)), cylinder(1, [e, z, z], F(1)), (1, 0)
    yield "steinmetz-radii", cylinder(2, [z, z, z], F(1)), cylinder(1, [z, z, z], (1 + e) ** 2), (2, 0)
    yield "viviani", sphere([z, z, z], F(1)), cylinder(2, [F(1, 2), z, z], (F(1, 2) + e) ** 2), (1, 0)
    yield "spheres", sphere([z, z, z], F(1)), sphere([2 - e, z, z], F(1)), (1, 0)


def main():
    for k in (3, 5, 8, 10, 15, 20):
        e = F(1, 10 ** k)
        for name, a, b, want in families(e):
            for scale in (0, 5, -5):
                f = F(10) ** scale
                line = {
                    "id": "%s-e%d-s%d" % (name, k, scale),
                    "A": text(scaled(a, f)),
                    "B": text(scaled(b, f)),
                    "pencil": "regular",
                }
                print(json.dumps(line))


main()
