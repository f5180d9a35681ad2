#!/usr/bin/env python3
"""Disguise every pair of a JSON Lines corpus by a random invertible integer map.

    disguise_pairs.py FILE SEED DIGITS proj|affine > OUT.jsonl

Each line's quadrics become PᵀAP and PᵀBP for one random integer matrix P per line whose
entries have DIGITS decimal digits (random sign). `proj`: any invertible P. `affine`: P keeps
the plane at infinity, last row (0, 0, 0, k), so affine labels (bounded, unbounded, points at
infinity) stay true. Every other field is kept as it is (labels are invariant under a
projective map for `proj`, under an affine one for `affine`); `source` gets the disguise
appended and `id` a suffix. Deterministic in SEED (Python's `random.Random`, seeded by SEED
and the line number). A and B may be 4×4 arrays of integer or "p/q" strings or polynomial
strings in x, y, z, w (read with sympy); the output is always 4×4 arrays of strings.
Lines without A and B (or with non-constant entries, as in moving pairs) are copied as they
are.
"""

import json
import random
import sys
from fractions import Fraction


def parse_matrix(m):
    """A 4×4 Fraction matrix from an array of strings or a polynomial string; None if not."""
    if isinstance(m, list):
        try:
            return [[Fraction(str(e)) for e in row] for row in m]
        except (ValueError, ZeroDivisionError):
            return None
    if isinstance(m, str):
        import sympy

        x, y, z, w = sympy.symbols("x y z w")
        expr = sympy.expand(sympy.sympify(m.replace("^", "**")))
        vs = [x, y, z, w]
        poly = sympy.Poly(expr, *vs)
        if poly.total_degree() > 2 or any(sum(mon) != 2 for mon in poly.monoms()):
            return None
        out = [[Fraction(0)] * 4 for _ in range(4)]
        for i in range(4):
            for j in range(4):
                mon = [0] * 4
                mon[i] += 1
                mon[j] += 1
                c = Fraction(str(poly.coeff_monomial(tuple(mon))))
                out[i][j] = c if i == j else c / 2
        return out
    return None


def det(m):
    """The determinant of a square Fraction matrix by elimination."""
    a = [row[:] for row in m]
    n = len(a)
    d = Fraction(1)
    for c in range(n):
        p = next((r for r in range(c, n) if a[r][c] != 0), None)
        if p is None:
            return Fraction(0)
        if p != c:
            a[c], a[p] = a[p], a[c]
            d = -d
        d *= a[c][c]
        for r in range(c + 1, n):
            f = a[r][c] / a[c][c]
            for k in range(c, n):
                a[r][k] -= f * a[c][k]
    return d


def random_entry(rng, digits):
    lo, hi = 10 ** (digits - 1), 10**digits - 1
    return rng.choice((-1, 1)) * rng.randint(lo, hi)


def random_map(rng, digits, affine):
    """A random invertible 4×4 integer matrix (last row (0,0,0,k) when affine)."""
    while True:
        p = [[random_entry(rng, digits) for _ in range(4)] for _ in range(4)]
        if affine:
            p[3] = [0, 0, 0, random_entry(rng, digits)]
        if det([[Fraction(e) for e in row] for row in p]) != 0:
            return p


def congruence(p, m):
    """PᵀMP."""
    mp = [[sum(m[i][k] * p[k][j] for k in range(4)) for j in range(4)] for i in range(4)]
    return [[sum(p[k][i] * mp[k][j] for k in range(4)) for j in range(4)] for i in range(4)]


def text(f):
    return str(f.numerator) if f.denominator == 1 else f"{f.numerator}/{f.denominator}"


def main(argv):
    if len(argv) != 5 or argv[4] not in ("proj", "affine"):
        sys.stderr.write(__doc__)
        return 2
    path, seed, digits, mode = argv[1], argv[2], int(argv[3]), argv[4]
    if digits < 1:
        sys.stderr.write("DIGITS must be at least 1\n")
        return 2
    with open(path) as f:
        for number, line in enumerate(f):
            if not line.strip():
                continue
            record = json.loads(line)
            a = parse_matrix(record.get("A"))
            b = parse_matrix(record.get("B"))
            if a is None or b is None:
                print(json.dumps(record))
                continue
            rng = random.Random(f"{seed}:{number}")
            p = random_map(rng, digits, mode == "affine")
            record["A"] = [[text(e) for e in row] for row in congruence(p, a)]
            record["B"] = [[text(e) for e in row] for row in congruence(p, b)]
            tag = f"disguise_pairs.py seed {seed}, {digits}-digit {mode} P"
            record["source"] = f"{record.get('source', '')}; {tag}".lstrip("; ")
            if "id" in record:
                record["id"] = f"{record['id']}-d{digits}{mode[0]}"
            print(json.dumps(record))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
