#!/usr/bin/env python3
"""Random moving pencils with fixed seeds, for measuring `qsic motion` and `qsic contact`.

Each matrix is symmetric 4x4 with entries polynomials in t of degree DEG whose integer
coefficients are uniform in [-(2^BITS - 1), 2^BITS - 1]. Writes JSON Lines {"id", "A", "B"}
(A, B as 4x4 arrays of strings), the format of `qsic motion --batch`.

usage: random_moving.py DEG BITS COUNT [SEED]
"""
import json
import random
import sys


def poly(rng, deg, bits):
    m = (1 << bits) - 1
    terms = []
    for k in range(deg + 1):
        c = rng.randint(-m, m)
        if c:
            terms.append(f"({c})*t^{k}" if k else f"({c})")
    return " + ".join(terms) if terms else "0"


def matrix(rng, deg, bits):
    m = [[None] * 4 for _ in range(4)]
    for i in range(4):
        for j in range(i, 4):
            m[i][j] = m[j][i] = poly(rng, deg, bits)
    return m


def main():
    deg, bits, count = (int(a) for a in sys.argv[1:4])
    seed = int(sys.argv[4]) if len(sys.argv) > 4 else 1
    for n in range(count):
        rng = random.Random(f"{seed}-{deg}-{bits}-{n}")
        line = {"id": f"random_d{deg}_b{bits}_s{seed}_{n}",
                "A": matrix(rng, deg, bits), "B": matrix(rng, deg, bits)}
        print(json.dumps(line))


if __name__ == "__main__":
    main()
