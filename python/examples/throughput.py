"""Throughput of ``qsic.classify_many`` against ``qsic classify --batch`` on the same random
integer pairs (symmetric matrices, entries in [-10, 10]), per pair, wall clock.

    python throughput.py --pairs 100000 --qsic target/release/qsic [--affine]

Both run on all cores. The CLI reads JSON Lines of 4×4 integer arrays and writes JSON
(``--projective`` unless ``--affine``); ``classify_many`` reads an ``int64`` array and returns
columns. The answers are compared field by field.
"""

from __future__ import annotations

import argparse
import resource
import json
import subprocess
import time

import numpy as np

import qsic


def random_pairs(n: int, seed: int = 7):
    rng = np.random.default_rng(seed)
    tri = np.triu_indices(4)

    def symmetric():
        m = np.zeros((n, 4, 4), dtype=np.int64)
        v = rng.integers(-10, 11, size=(n, 10))
        m[:, tri[0], tri[1]] = v
        m[:, tri[1], tri[0]] = v
        return m

    return symmetric(), symmetric()


def main() -> None:
    p = argparse.ArgumentParser(description=__doc__)
    p.add_argument("--pairs", type=int, default=100_000)
    p.add_argument("--qsic", default="target/release/qsic", help="the qsic binary")
    p.add_argument("--affine", action="store_true", help="with the affine view")
    args = p.parse_args()
    A, B = random_pairs(args.pairs)
    lines = "".join(
        json.dumps({"id": k, "A": A[k].tolist(), "B": B[k].tolist()}, separators=(",", ":")) + "\n"
        for k in range(args.pairs)
    ).encode()
    flags = [] if args.affine else ["--projective"]

    children = lambda: resource.getrusage(resource.RUSAGE_CHILDREN)  # noqa: E731
    c0 = children()
    t = time.perf_counter()
    out = subprocess.run(
        [args.qsic, "classify", *flags, "--batch", "-"], input=lines, capture_output=True
    )
    cli = time.perf_counter() - t
    c1 = children()
    cli_cpu = c1.ru_utime + c1.ru_stime - c0.ru_utime - c0.ru_stime

    t, c = time.perf_counter(), time.process_time()
    cols = qsic.classify_many(A, B, affine=args.affine)
    py, py_cpu = time.perf_counter() - t, time.process_time() - c

    answers = [json.loads(line) for line in out.stdout.decode().splitlines()]
    assert len(answers) == args.pairs
    for k, ans in enumerate(answers):
        for key in qsic.FIELDS:
            got = cols[key][k]
            if key == "case":
                got = None if got == 0 else int(got)
            assert got == ans[key], (k, key, got, ans[key])
        if args.affine:
            assert cols["affine"][k] == ans["affine"], k
    per = lambda s: s / args.pairs * 1e6  # noqa: E731
    print(
        f"{args.pairs} pairs{' with the affine view' if args.affine else ''}: "
        f"CLI batch {cli:.2f} s ({per(cli):.2f} µs/pair; CPU {per(cli_cpu):.2f} µs/pair), "
        f"classify_many {py:.2f} s ({per(py):.2f} µs/pair; CPU {per(py_cpu):.2f} µs/pair), "
        f"ratio {py / cli:.2f}; answers equal"
    )


if __name__ == "__main__":
    main()
