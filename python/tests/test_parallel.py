"""`classify_many` gives the same answers on any number of threads.

That it releases the GIL and keeps both cores busy is measured (README, "Python"), not
asserted here: a test timing threads on this shared machine would be flaky."""

from __future__ import annotations

import numpy as np

import qsic


def random_pairs(n: int, seed: int):
    rng = np.random.default_rng(seed)
    m = rng.integers(-9, 10, size=(2, n, 4, 4))
    return m + m.transpose(0, 1, 3, 2)


def test_thread_counts_agree():
    A, B = random_pairs(500, seed=5)
    one = qsic.classify_many(A, B, threads=1)
    for threads in (None, 2, 3):
        other = qsic.classify_many(A, B, threads=threads)
        for key in (*qsic.FIELDS, "error"):
            assert list(other[key]) == list(one[key]), (threads, key)
