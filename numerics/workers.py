"""Forked worker processes for CPU-bound work: the claims checked (`paper.verification`) and the benchmark's
high-precision references (`numerics.bench_set`)."""

from __future__ import annotations

import multiprocessing
import signal


def _signals() -> None:
    """In each worker: Ctrl-C is the parent's to answer (in one line; workers that took it too would each print a
    traceback, ``Process ForkPoolWorker-2: ...``), and SIGTERM, which the pool ends its workers with, ends one
    quietly (the command line's handler, which the fork copies, would raise in it)."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    signal.signal(signal.SIGTERM, signal.SIG_DFL)


def fork_pool(workers: int) -> multiprocessing.pool.Pool:
    """``workers`` forked processes that leave Ctrl-C and SIGTERM to the parent (`_signals`)."""
    return multiprocessing.get_context("fork").Pool(workers, _signals)
