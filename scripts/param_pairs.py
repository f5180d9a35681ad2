#!/usr/bin/env python3
"""Random pairs for the cost of `qsic param` (README, "Speed"): JSON lines for `qsic param --batch -`.

    scripts/param_pairs.py N [SEED]   # two symmetric 4x4 integer matrices a line, entries in [-10, 10]

Deterministic for a given N and seed (default 2026); the first k lines do not depend on N.
"""
import json
import random
import sys


def random_matrix(rng):
    while True:
        m = [[0] * 4 for _ in range(4)]
        for i in range(4):
            for j in range(i, 4):
                m[i][j] = m[j][i] = rng.randint(-10, 10)
        if any(v != 0 for row in m for v in row):
            return m


def main():
    n = int(sys.argv[1])
    rng = random.Random(int(sys.argv[2]) if len(sys.argv) > 2 else 2026)
    for i in range(1, n + 1):
        print(json.dumps({"id": i, "A": random_matrix(rng), "B": random_matrix(rng)}))


main()
