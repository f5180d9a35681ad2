"""Throughput of ``qsic.classify_many`` against ``qsic classify --batch`` on the same random
integer pairs (symmetric matrices, entries in [-10, 10]), per pair, wall clock.

    python throughput.py --pairs 100000 --qsic target/release/qsic [--affine] [--dask]

Both run on all cores. The CLI reads JSON Lines of 4×4 integer arrays and writes JSON
(``--projective`` unless ``--affine``); ``classify_many`` reads an ``int64`` array and returns
columns. The answers are compared field by field. With ``--dask``, also the Dask example
(``dask_classify.py``: the pairs as a CSV file, read and classified by ``map_partitions`` on a
LocalCluster of two worker processes, one thread each), cluster start-up not counted.
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
    p.add_argument("--dask", action="store_true", help="also the Dask example on 2 local workers")
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
    if args.dask:
        dask_seconds = run_dask(A, B, cols)
        print(f"{args.pairs} pairs through Dask: {dask_seconds:.2f} s ({per(dask_seconds):.2f} µs/pair)")
    print(
        f"{args.pairs} pairs{' with the affine view' if args.affine else ''}: "
        f"CLI batch {cli:.2f} s ({per(cli):.2f} µs/pair; CPU {per(cli_cpu):.2f} µs/pair), "
        f"classify_many {py:.2f} s ({per(py):.2f} µs/pair; CPU {per(py_cpu):.2f} µs/pair), "
        f"ratio {py / cli:.2f}; answers equal"
    )


def run_dask(A, B, cols) -> float:
    """Seconds for the Dask example on the pairs (written to a CSV file first)."""
    import os
    import sys
    import tempfile

    import pandas as pd
    from dask.distributed import Client, LocalCluster

    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    import dask_classify

    with tempfile.TemporaryDirectory() as tmp:
        frame = pd.DataFrame(A.reshape(-1, 16), columns=dask_classify.A_COLUMNS)
        frame[dask_classify.B_COLUMNS] = B.reshape(-1, 16)
        frame.insert(0, "id", range(len(frame)))
        path = os.path.join(tmp, "pairs.csv")
        frame.to_csv(path, index=False)
        cluster = LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None)
        with cluster, Client(cluster) as client:
            client.upload_file(dask_classify.__file__)
            t = time.perf_counter()
            answers = dask_classify.classify_dataset(path, blocksize="1MB").compute()
            seconds = time.perf_counter() - t
    answers = answers.sort_values("id")
    for key in ("pencil", "case", "complex_type", "real_type", "error"):
        assert list(answers[key]) == list(cols[key]), key
    return seconds


if __name__ == "__main__":
    main()
