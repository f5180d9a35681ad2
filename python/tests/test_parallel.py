"""`classify_many` runs without the GIL and gives the same answers on any number of threads."""

from __future__ import annotations

import os
import threading
import time
from pathlib import Path

import numpy as np
import pytest

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


def cpu_ticks_per_thread() -> dict:
    """CPU time (user + system, in clock ticks) of each thread of this process, from /proc."""
    ticks = {}
    for tid in os.listdir("/proc/self/task"):
        fields = Path(f"/proc/self/task/{tid}/stat").read_text().rsplit(")", 1)[1].split()
        ticks[tid] = int(fields[11]) + int(fields[12])
    return ticks


@pytest.mark.skipif(not Path("/proc/self/task").exists(), reason="per-thread CPU time from Linux /proc")
def test_both_cores_do_work():
    """With the default pool (one thread per core), at least two threads other than this one
    spend CPU time on the batch."""
    A, B = random_pairs(48, seed=4)
    qsic.classify_many(A[:2], B[:2])  # the pool exists before the count starts
    before = cpu_ticks_per_thread()
    qsic.classify_many(A, B, affine=True)
    after = cpu_ticks_per_thread()
    me = str(threading.get_native_id())
    busy = [t for t in after if t != me and after[t] - before.get(t, 0) > 0]
    assert len(busy) >= min(2, os.cpu_count() or 1), (before, after)


def test_thread_counts_agree():
    A, B = random_pairs(500, seed=5)
    one = qsic.classify_many(A, B, threads=1)
    for threads in (None, 2, 3):
        other = qsic.classify_many(A, B, threads=threads)
        for key in (*qsic.FIELDS, "error"):
            assert list(other[key]) == list(one[key]), (threads, key)
