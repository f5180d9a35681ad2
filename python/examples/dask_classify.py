"""Classify a partitioned data set of quadric pairs on a Dask cluster.

The data set is CSV (or Parquet) with a column ``id`` and the 32 columns ``a00 … a33``,
``b00 … b33``: the entries of A and B, row by row (integers, floats, or number strings such as
``"3/4"``). Each partition is classified by ``qsic.classify_many`` (with ``threads`` threads
per task), and the result is one row per pair: ``id``, ``pencil``, ``case`` (0: none),
``complex_type``, ``real_type``, ``error``.

    python dask_classify.py pairs.csv out.csv                  # a LocalCluster of 2 processes
    python dask_classify.py pairs.csv out.csv --workers 4
    python dask_classify.py 's3://bucket/pairs/*.parquet' s3://bucket/out/ --scheduler tcp://host:8786

With ``--scheduler`` the script connects to a running cluster instead of starting one; every
worker needs ``qsic`` installed (the same wheel), and the paths must be readable by the
workers (a shared file system or object storage). The script sends itself to the workers
(``Client.upload_file``), so nothing else needs installing.
"""

from __future__ import annotations

import argparse
import os
from typing import Optional

import numpy as np
import pandas as pd

import qsic

A_COLUMNS = [f"a{i}{j}" for i in range(4) for j in range(4)]
B_COLUMNS = [f"b{i}{j}" for i in range(4) for j in range(4)]
OUTPUT = ["id", "pencil", "case", "complex_type", "real_type", "error"]


def classify_partition(df: pd.DataFrame, threads: Optional[int] = 1) -> pd.DataFrame:
    """One partition of pairs → one row of answers per pair, the index kept."""
    n = len(df)
    A = _matrices(df[A_COLUMNS], n)
    B = _matrices(df[B_COLUMNS], n)
    cols = qsic.classify_many(A, B, threads=threads)
    out = {"id": df["id"].to_numpy()}
    for key in OUTPUT[1:]:
        # explicit dtypes: the same for the empty meta partition and for every real one
        out[key] = pd.Series(cols[key], index=df.index, dtype=np.int8 if key == "case" else object)
    return pd.DataFrame(out, index=df.index)


def _matrices(block: pd.DataFrame, n: int) -> np.ndarray:
    """Integer columns as int64, float columns as float64, anything else as objects."""
    kinds = {dt.kind for dt in block.dtypes}
    if kinds <= {"i", "u"}:
        values = block.to_numpy(dtype=np.int64)
    elif kinds <= {"i", "u", "f"}:
        values = block.to_numpy(dtype=np.float64)
    else:
        values = block.to_numpy(dtype=object)
    return values.reshape(n, 4, 4)


def classify_dataset(path: str, blocksize: Optional[str] = "16MB"):
    """A lazy Dask DataFrame of the answers for the pairs at ``path`` (CSV or Parquet)."""
    import dask.dataframe as dd

    if path.endswith(".parquet") or path.endswith("/"):
        pairs = dd.read_parquet(path)
    else:
        pairs = dd.read_csv(path, blocksize=blocksize)
    meta = classify_partition(pairs._meta)  # the answers' columns, from an empty partition
    return pairs.map_partitions(classify_partition, meta=meta)


def run(path: str, client, blocksize: Optional[str] = "16MB") -> pd.DataFrame:
    """Classifies the data set at ``path`` on ``client``'s cluster and gathers the answers."""
    client.upload_file(os.path.abspath(__file__))
    return classify_dataset(path, blocksize).compute()


def main() -> None:
    from dask.distributed import Client, LocalCluster

    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("pairs", help="CSV file(s) or a Parquet data set of pairs")
    p.add_argument("out", help="the answers: a CSV file, or a directory for Parquet")
    p.add_argument("--scheduler", help="address of a running scheduler (default: a LocalCluster)")
    p.add_argument("--workers", type=int, default=2, help="LocalCluster worker processes")
    args = p.parse_args()
    if args.scheduler:
        client = Client(args.scheduler)
    else:
        client = Client(LocalCluster(n_workers=args.workers, threads_per_worker=1, processes=True))
    with client:
        client.upload_file(os.path.abspath(__file__))
        answers = classify_dataset(args.pairs)
        if args.out.endswith("/"):
            answers.to_parquet(args.out)
        else:
            answers.to_csv(args.out, single_file=True, index=False)
    print(f"answers written to {args.out}")


if __name__ == "__main__":
    main()
