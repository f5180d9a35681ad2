"""The Dask example end to end: a CSV of pairs in several partitions, classified on a
LocalCluster of two worker processes, equals `classify_many` on the whole set."""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pandas as pd
import distributed

import qsic

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
sys.path.insert(0, str(EXAMPLES))
import dask_classify  # noqa: E402


def random_pairs(n: int, seed: int) -> tuple:
    rng = np.random.default_rng(seed)
    m = rng.integers(-6, 7, size=(2, n, 4, 4))
    m = m + m.transpose(0, 1, 3, 2)
    m[0, 5, 0, 1] += 1  # not symmetric: an error row
    m[1, 9] = 0  # the zero form on one side: a single quadric
    return m[0], m[1]


def test_dask_example_on_two_local_workers_equals_classify_many(tmp_path):
    A, B = random_pairs(600, seed=11)
    frame = pd.DataFrame(A.reshape(-1, 16), columns=dask_classify.A_COLUMNS)
    frame[dask_classify.B_COLUMNS] = B.reshape(-1, 16)
    frame.insert(0, "id", np.arange(len(frame)) * 7)
    csv = tmp_path / "pairs.csv"
    frame.to_csv(csv, index=False)

    cluster = distributed.LocalCluster(
        n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None
    )
    with cluster, distributed.Client(cluster) as client:
        assert len(client.scheduler_info()["workers"]) == 2
        lazy = dask_classify.classify_dataset(str(csv), blocksize="16KB")
        assert lazy.npartitions >= 3
        answers = dask_classify.run(str(csv), client, blocksize="16KB")

    expected = qsic.classify_many(A, B)
    answers = answers.sort_values("id")
    assert list(answers["id"]) == list(frame["id"])
    assert list(answers.columns) == dask_classify.OUTPUT
    for key in dask_classify.OUTPUT[1:]:
        assert list(answers[key]) == list(expected[key]), key
    assert answers["error"].iloc[5].startswith("A: matrix is not symmetric")
    assert answers["pencil"].iloc[9] == "single"
    assert answers["error"].notna().sum() == 1
