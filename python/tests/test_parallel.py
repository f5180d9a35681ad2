"""`classify_many` runs without the GIL and gives the same answers on any number of threads."""

from __future__ import annotations

import threading
import time

import numpy as np

import qsic


def random_pairs(n: int, seed: int):
    rng = np.random.default_rng(seed)
    m = rng.integers(-9, 10, size=(2, n, 4, 4))
    return m + m.transpose(0, 1, 3, 2)


def test_the_gil_is_released_while_classifying():
    """While the batch runs in another thread, this thread keeps running Python: the longest
    pause between two of its steps is far below the batch's duration (holding the GIL, the
    native call would block it throughout)."""
    A, B = random_pairs(48, seed=3)
    done = threading.Event()
    spans = []

    def work():
        t = time.perf_counter()
        qsic.classify_many(A, B, affine=True)  # the affine view: milliseconds per pair
        spans.append(time.perf_counter() - t)
        done.set()

    worker = threading.Thread(target=work)
    last, longest = time.perf_counter(), 0.0
    worker.start()
    while not done.is_set():
        now = time.perf_counter()
        longest, last = max(longest, now - last), now
    worker.join()
    assert spans[0] > 0.2
    assert longest < spans[0] / 3, (longest, spans[0])


def test_thread_counts_agree():
    A, B = random_pairs(500, seed=5)
    one = qsic.classify_many(A, B, threads=1)
    for threads in (None, 2, 3):
        other = qsic.classify_many(A, B, threads=threads)
        for key in (*qsic.FIELDS, "error"):
            assert list(other[key]) == list(one[key]), (threads, key)
