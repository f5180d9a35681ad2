"""`classify_many` gives the same answers on any number of threads.

That it releases the GIL and keeps both cores busy is measured (README, "Python"), not
asserted here: a test timing threads on this shared machine would be flaky."""

from __future__ import annotations

import time
from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest

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


def test_the_most_threads_documented_are_accepted_and_agree():
    A, B = random_pairs(40, seed=6)
    one = qsic.classify_many(A, B, threads=1)
    for threads in (qsic.MAX_THREADS, np.int64(2)):
        other = qsic.classify_many(A, B, threads=threads)
        for key in (*qsic.FIELDS, "error"):
            assert list(other[key]) == list(one[key]), (threads, key)
    doc = qsic.classify_many.__doc__
    assert f"from 1 to :data:`MAX_THREADS` ({qsic.MAX_THREADS})" in doc
    readme = (Path(__file__).resolve().parents[2] / "README.md").read_text()
    assert f"`threads` from 1 to {qsic.MAX_THREADS}" in readme


@pytest.mark.parametrize(
    "threads", [0, -1, 257, 2**31, 2**70, 2.0, 2.5, "2", True, [2], Fraction(2)]
)
def test_thread_counts_out_of_range_or_not_integers_raise_before_any_work(threads):
    A, B = random_pairs(3, seed=7)
    start = time.monotonic()
    with pytest.raises(qsic.QsicError, match=rf"^threads must be an integer from 1 to {qsic.MAX_THREADS}, got "):
        qsic.classify_many(A, B, threads=threads)
    assert time.monotonic() - start < 5


@pytest.mark.parametrize("threads", [0, -1, 257])
def test_the_native_module_checks_threads_too(threads):
    data = np.zeros((1, 4, 4), dtype=np.int64).tobytes()
    with pytest.raises(qsic.QsicError, match=rf"^threads must be an integer from 1 to {qsic.MAX_THREADS}, got "):
        qsic._qsic.classify_many("int64", data, "int64", data, threads=threads)
