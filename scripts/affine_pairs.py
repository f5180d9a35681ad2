#!/usr/bin/env python3
"""Random pairs for the affine view's cost (README, "Speed"): JSON lines for `qsic classify --batch -`.

    scripts/affine_pairs.py N random [SEED]      # symmetric 4x4 integer matrices, entries in [-9, 9]
    scripts/affine_pairs.py N ellipsoids [SEED]  # two ellipsoids (x-c)^T Q (x-c) = r, Q = M^T M + I

Deterministic for a given N, family and seed.
"""
import json
import random
import sys


def random_matrix(rng):
    m = [[0] * 4 for _ in range(4)]
    for i in range(4):
        for j in range(i, 4):
            m[i][j] = m[j][i] = rng.randint(-9, 9)
    if all(v == 0 for row in m for v in row):
        m[3][3] = 1
    return m


def ellipsoid(rng):
    mm = [[rng.randint(-2, 2) for _ in range(3)] for _ in range(3)]
    q = [[sum(mm[k][i] * mm[k][j] for k in range(3)) + (i == j) for j in range(3)] for i in range(3)]
    c = [rng.randint(-3, 3) for _ in range(3)]
    r = rng.randint(1, 9)
    qc = [sum(q[i][j] * c[j] for j in range(3)) for i in range(3)]
    m = [[q[i][j] for j in range(3)] + [-qc[i]] for i in range(3)]
    m.append([-qc[0], -qc[1], -qc[2], sum(c[i] * qc[i] for i in range(3)) - r])
    return m


def main():
    n = int(sys.argv[1])
    family = sys.argv[2]
    rng = random.Random(int(sys.argv[3]) if len(sys.argv) > 3 else 2026)
    make = {"random": random_matrix, "ellipsoids": ellipsoid}[family]
    for i in range(1, n + 1):
        print(json.dumps({"id": i, "A": make(rng), "B": make(rng)}))


main()
