"""Progress of long work on stderr: one line rewritten in place, only when stderr is a terminal."""

from __future__ import annotations

import sys
import time


class Progress:
    """``done/total what, elapsed`` on stderr while the work runs; silent when piped or ``quiet``."""

    def __init__(self, total: int, what: str, quiet: bool = False, stream=None):
        self.stream = stream or sys.stderr
        self.total, self.what = total, what
        self.show = not quiet and self.stream.isatty()
        self.start = time.perf_counter()

    def update(self, done: int) -> None:
        if self.show:
            elapsed = time.perf_counter() - self.start
            print(f"\r{done}/{self.total} {self.what}, {elapsed:.0f} s", end="", file=self.stream, flush=True)

    def close(self) -> None:
        if self.show:
            print("\r\033[K", end="", file=self.stream, flush=True)  # clear the line: the result follows
